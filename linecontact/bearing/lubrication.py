r"""Lubrication of a roller bearing's line contacts: EHL film, film ratio, viscosity ratio.

The elastohydrodynamic (EHL) film of a line contact from Hamrock's dimensionless groups
(Hamrock, Schmid & Jacobson 2004, chapter 21), with :math:`E' = 2E^*` (E* of Li & Popov
(2017) [li-popov-2017], Eq. 3), R the contact's effective radius in the rolling
direction, u the mean entrainment speed, w' the load per unit length, eta0 the dynamic
viscosity at the inlet (operating) temperature and alpha the pressure-viscosity
coefficient:

.. math::

    U = \frac{\eta_0 u}{E' R}, \qquad G = \alpha E', \qquad W' = \frac{w'}{E' R}

- **Pan & Hamrock (1989)**, the default (:data:`DEFAULT_FILM_FORMULA`):
  :math:`h_{min}/R = 1.714\,W'^{-0.128} U^{0.694} G^{0.568}`,
  :math:`h_c/R = 2.922\,W'^{-0.166} U^{0.692} G^{0.470}`. Chosen because one
  consistent fit gives both the central and the minimum film, fitted to full numerical
  EHL solutions (the form of Hamrock's book).
- **Dowson & Higginson (1977)**, beside it: :math:`h_{min}/R = 2.65\,U^{0.70}
  G^{0.54} W'^{-0.13}` (minimum film only).

The film ratio :math:`\Lambda = h_{min}/\sqrt{R_{q1}^2 + R_{q2}^2}`
(:func:`film_ratio`), the kinematics of pure rolling (:func:`entrainment_speed`,
Harris & Kotzalas 2007), and the viscosity ratio :math:`\kappa = \nu/\nu_1` with the
rated viscosity :math:`\nu_1` in the form published in bearing catalogues for
ISO 281:2007 (:func:`rated_viscosity`, :func:`viscosity_ratio`).

All functions take SI units (speeds in rad/s, viscosities in Pa s or m^2/s) and
broadcast over arrays: a profiled roller's slices, or every roller of a bearing, in one
call.

References
----------
.. [1] H. P. Pan, B. J. Hamrock, "Simple formulas for performance parameters used in
   elastohydrodynamically lubricated line contacts", J. Tribology 111 (1989) 246-251.
.. [2] D. Dowson, G. R. Higginson, Elasto-Hydrodynamic Lubrication, SI edition,
   Pergamon Press, Oxford (1977).
.. [3] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
   Lubrication, 2nd ed., Marcel Dekker, New York (2004), chapter 21 (rectangular
   conjunctions).
.. [4] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press (2007):
   Essential Concepts, the chapter on kinematic speeds (cage and rolling
   element speeds).
.. [5] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life, the rated
   viscosity nu1 as published in bearing catalogues, e.g. SKF, Rolling bearings
   (catalogue PUB BU/P1 17000, 2018), section "Viscosity ratio kappa", or Schaeffler,
   Technical Pocket Guide STT (2014), "Reference viscosity".
"""
from __future__ import annotations

import math

import numpy as np

from .._numerics import out
from ..checks import Interval, check_interval, check_positive
from ..errors import UnknownNameError

__all__ = [
    "DEFAULT_FILM_FORMULA",
    "FILM_FORMULAS",
    "DENSITY",
    "KINEMATIC_VISCOSITY",
    "PRESSURE_VISCOSITY",
    "ehl_parameters",
    "minimum_film_pan_hamrock",
    "central_film_pan_hamrock",
    "minimum_film_dowson_higginson",
    "minimum_film_thickness",
    "film_ratio",
    "entrainment_speed",
    "cage_speed",
    "rated_viscosity",
    "viscosity_ratio",
]

#: The line-contact film formula used unless another is named.
DEFAULT_FILM_FORMULA = "pan-hamrock"

#: Film formulas by name -> (source, h_min/R = c W'^w U^u G^g as (c, w, u, g)).
FILM_FORMULAS = {
    "pan-hamrock": ("Pan & Hamrock (1989)", (1.714, -0.128, 0.694, 0.568)),
    "dowson-higginson": ("Dowson & Higginson (1977)", (2.65, -0.13, 0.70, 0.54)),
}
#: Accepted pressure-viscosity coefficients alpha [1/Pa]: lubricating oils lie near
#: 1e-8 to 4e-8 1/Pa (10 to 40 GPa^-1; Hamrock, Schmid & Jacobson 2004, the chapter on
#: lubricant viscosity); a value above 1e-7 is a unit slip (20 GPa^-1 given as the bare
#: number 20 makes the film thousands of times too thick), refused.
PRESSURE_VISCOSITY = Interval("pressure_viscosity", 0.0, 1e-7, low_open=True,
                              unit="1/Pa")
_ALPHA_HINT = ("alpha in 1/Pa: 20 GPa^-1 is 2e-8 1/Pa (lubricating oils lie near 1e-8 "
               "to 4e-8)")
#: Accepted lubricant densities [kg/m^3]: mineral and synthetic oils and greases' base
#: oils lie near 800 to 1000 kg/m^3 (perfluorinated ones near 1900); outside 500-2500 is
#: a unit slip (0.86 g/cm^3 given as the bare number 0.86 makes eta0 = rho nu a thousand
#: times too small and the film some hundred times too thin), refused.
DENSITY = Interval("density", 500.0, 2500.0, unit="kg/m^3")
_DENSITY_HINT = "density in kg/m^3: 0.86 g/cm^3 is 860 kg/m^3"
#: Accepted kinematic viscosities [m^2/s]: 1e-7 to 1e-1 m^2/s (0.1 to 1e5 mm^2/s, from
#: a thin spindle oil to a heavy gear oil near its pour point); above that is a unit slip
#: (68 mm^2/s given as the bare number 68 is 68 m^2/s), refused.
KINEMATIC_VISCOSITY = Interval("viscosity", 1e-7, 1e-1, unit="m^2/s")
_VISCOSITY_HINT = "kinematic viscosity in m^2/s: 68 mm^2/s (cSt) is 6.8e-5 m^2/s"
#: Pan & Hamrock's (1989) central film h_c/R = c W'^w U^u G^g as (c, w, u, g).
_PAN_HAMROCK_CENTRAL = (2.922, -0.166, 0.692, 0.470)

#: Inner-ring speed [r/min] at which the catalogue form of ISO 281's nu1 changes branch.
_NU1_BRANCH_RPM = 1000.0


def ehl_parameters(speed, radius, load_per_length, estar, viscosity, pressure_viscosity):
    r"""Hamrock's dimensionless speed, material and load groups U, G, W' of a line contact.

    .. math::

        U = \frac{\eta_0 u}{E' R}, \qquad G = \alpha E', \qquad
        W' = \frac{w'}{E' R}, \qquad E' = 2E^*

    Parameters
    ----------
    speed : float or array_like
        Mean entrainment speed u = (u_1 + u_2)/2, 0 < u < inf [m/s].
    radius : float or array_like
        Effective radius of the contact in the rolling direction, 0 < R < inf [m].
    load_per_length : float or array_like
        Load per unit length w' (a slice's line load), 0 <= w' < inf [N/m].
    estar : float or array_like
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    viscosity : float or array_like
        Dynamic viscosity eta0 at the operating (inlet) temperature and ambient
        pressure, 0 < eta0 < inf [Pa s].
    pressure_viscosity : float or array_like
        Pressure-viscosity coefficient alpha, 0 < alpha <= 1e-7
        (:data:`PRESSURE_VISCOSITY`) [1/Pa].

    Returns
    -------
    tuple of float or ndarray
        (U, G, W') [-], broadcast over the inputs.

    Notes
    -----
    Valid for the ranges above. E' = 2 E* is Hamrock's reduced modulus
    2 / ((1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2).

    Examples
    --------
    Steel (E* = 115.4 GPa), R = 4.7 mm, u = 2.7 m/s, 100 N/mm, ISO VG 68 near 70 C
    (eta0 = 0.02 Pa s, alpha = 2e-8 1/Pa):

    >>> U, G, W = ehl_parameters(2.7, 4.7e-3, 100e3, 115.4e9, 0.02, 2e-8)
    >>> f"U = {U:.3e}, G = {G:.0f}, W' = {W:.3e}"
    "U = 4.978e-11, G = 4616, W' = 9.219e-05"

    References
    ----------
    .. [1] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
       Lubrication, 2nd ed. (2004), chapter 21.
    """
    u = check_positive("speed", speed, "m/s")
    R = check_positive("radius", radius, "m")
    w = check_interval("load_per_length", load_per_length, 0.0, np.inf, high_open=True,
                       unit="N/m")
    E = 2.0 * check_positive("estar", estar, "Pa")
    eta = check_positive("viscosity", viscosity, "Pa s")
    alpha = PRESSURE_VISCOSITY.check(pressure_viscosity, hint=_ALPHA_HINT)
    U, G, W = np.broadcast_arrays(eta * u / (E * R), alpha * E, w / (E * R))
    return out(U), out(G), out(W)


def _film(coeffs, speed, radius, load_per_length, estar, viscosity, pressure_viscosity):
    """R c W'^w U^u G^g; inf where the load is zero (no contact: no EHL film)."""
    c, ew, eu, eg = coeffs
    U, G, W = (np.asarray(x) for x in ehl_parameters(
        speed, radius, load_per_length, estar, viscosity, pressure_viscosity))
    R = np.broadcast_to(np.asarray(radius, dtype=float), U.shape)
    with np.errstate(divide="ignore"):
        Wp = np.where(W > 0.0, W, 1.0) ** ew
    h = np.where(W > 0.0, R * c * Wp * U ** eu * G ** eg, np.inf)
    return out(h)


def minimum_film_pan_hamrock(speed, radius, load_per_length, estar, viscosity,
                             pressure_viscosity):
    r"""Minimum EHL film thickness of a line contact, Pan & Hamrock (1989).

    .. math:: \frac{h_{min}}{R} = 1.714\,W'^{-0.128}\,U^{0.694}\,G^{0.568}

    with U, G, W' of :func:`ehl_parameters`.

    Parameters
    ----------
    speed : float or array_like
        Mean entrainment speed u, 0 < u < inf [m/s].
    radius : float or array_like
        Effective radius in the rolling direction, 0 < R < inf [m].
    load_per_length : float or array_like
        Load per unit length w', 0 <= w' < inf [N/m].
    estar : float or array_like
        Effective modulus E*, 0 < E* < inf [Pa].
    viscosity : float or array_like
        Dynamic viscosity eta0 at the operating temperature, 0 < eta0 < inf [Pa s].
    pressure_viscosity : float or array_like
        Pressure-viscosity coefficient alpha, 0 < alpha <= 1e-7
        (:data:`PRESSURE_VISCOSITY`) [1/Pa].

    Returns
    -------
    float or ndarray
        h_min [m]; inf where w' = 0 (an unloaded slice has no EHL contact).

    Notes
    -----
    Isothermal, fully flooded, Newtonian, smooth surfaces, pure rolling; a curve fit to
    numerical EHL solutions over the parameter range of the source (that of steel
    rolling bearings and gears; no range is enforced here beyond the one above). Inlet
    shear heating and starvation lower the film at high speed; the fit does not
    include them.

    Examples
    --------
    >>> h = minimum_film_pan_hamrock(2.7, 4.7e-3, 100e3, 115.4e9, 0.02, 2e-8)
    >>> f"{h * 1e6:.3f} um"
    '0.226 um'

    References
    ----------
    .. [1] H. P. Pan, B. J. Hamrock, "Simple formulas for performance parameters used
       in elastohydrodynamically lubricated line contacts", J. Tribology 111 (1989)
       246-251.
    """
    return _film(FILM_FORMULAS["pan-hamrock"][1], speed, radius, load_per_length, estar,
                 viscosity, pressure_viscosity)


def central_film_pan_hamrock(speed, radius, load_per_length, estar, viscosity,
                             pressure_viscosity):
    r"""Central EHL film thickness of a line contact, Pan & Hamrock (1989).

    .. math:: \frac{h_c}{R} = 2.922\,W'^{-0.166}\,U^{0.692}\,G^{0.470}

    with U, G, W' of :func:`ehl_parameters`.

    Parameters
    ----------
    speed : float or array_like
        Mean entrainment speed u, 0 < u < inf [m/s].
    radius : float or array_like
        Effective radius in the rolling direction, 0 < R < inf [m].
    load_per_length : float or array_like
        Load per unit length w', 0 <= w' < inf [N/m].
    estar : float or array_like
        Effective modulus E*, 0 < E* < inf [Pa].
    viscosity : float or array_like
        Dynamic viscosity eta0 at the operating temperature, 0 < eta0 < inf [Pa s].
    pressure_viscosity : float or array_like
        Pressure-viscosity coefficient alpha, 0 < alpha <= 1e-7
        (:data:`PRESSURE_VISCOSITY`) [1/Pa].

    Returns
    -------
    float or ndarray
        h_c [m]; inf where w' = 0.

    Notes
    -----
    As :func:`minimum_film_pan_hamrock` (same source, same assumptions). The ratio of
    the two fits, h_c/h_min = 1.705 W'^-0.038 U^-0.002 G^-0.098, falls below 1 at
    very high loads (for steel, G = 4616 and U = 5e-11: near W' = 1.5e-3, a Hertz
    pressure of about 3.6 GPa), beyond the range the fits were made for.

    Examples
    --------
    >>> h = central_film_pan_hamrock(2.7, 4.7e-3, 100e3, 115.4e9, 0.02, 2e-8)
    >>> f"{h * 1e6:.3f} um"
    '0.251 um'

    References
    ----------
    .. [1] H. P. Pan, B. J. Hamrock, J. Tribology 111 (1989) 246-251.
    """
    return _film(_PAN_HAMROCK_CENTRAL, speed, radius, load_per_length, estar, viscosity,
                 pressure_viscosity)


def minimum_film_dowson_higginson(speed, radius, load_per_length, estar, viscosity,
                                  pressure_viscosity):
    r"""Minimum EHL film thickness of a line contact, Dowson & Higginson (1977).

    .. math:: \frac{h_{min}}{R} = 2.65\,U^{0.70}\,G^{0.54}\,W'^{-0.13}

    with U, G, W' of :func:`ehl_parameters`.

    Parameters
    ----------
    speed : float or array_like
        Mean entrainment speed u, 0 < u < inf [m/s].
    radius : float or array_like
        Effective radius in the rolling direction, 0 < R < inf [m].
    load_per_length : float or array_like
        Load per unit length w', 0 <= w' < inf [N/m].
    estar : float or array_like
        Effective modulus E*, 0 < E* < inf [Pa].
    viscosity : float or array_like
        Dynamic viscosity eta0 at the operating temperature, 0 < eta0 < inf [Pa s].
    pressure_viscosity : float or array_like
        Pressure-viscosity coefficient alpha, 0 < alpha <= 1e-7
        (:data:`PRESSURE_VISCOSITY`) [1/Pa].

    Returns
    -------
    float or ndarray
        h_min [m]; inf where w' = 0.

    Notes
    -----
    Isothermal, fully flooded, Newtonian, smooth surfaces; the classical fit of
    Dowson & Higginson's numerical solutions (it gives the minimum film only). For
    steel bearing contacts it lies about 5-10 % above Pan & Hamrock's h_min.

    Examples
    --------
    >>> h = minimum_film_dowson_higginson(2.7, 4.7e-3, 100e3, 115.4e9, 0.02, 2e-8)
    >>> f"{h * 1e6:.3f} um"
    '0.244 um'

    References
    ----------
    .. [1] D. Dowson, G. R. Higginson, Elasto-Hydrodynamic Lubrication, SI edition,
       Pergamon Press (1977).
    .. [2] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
       Lubrication, 2nd ed. (2004), chapter 21.
    """
    return _film(FILM_FORMULAS["dowson-higginson"][1], speed, radius, load_per_length,
                 estar, viscosity, pressure_viscosity)


def minimum_film_thickness(speed, radius, load_per_length, estar, viscosity,
                           pressure_viscosity, formula=DEFAULT_FILM_FORMULA):
    r"""Minimum EHL film thickness of a line contact by a named formula.

    .. math:: \frac{h_{min}}{R} = c\,W'^{\,w}\,U^{u}\,G^{g}

    with (c, w, u, g) = (1.714, -0.128, 0.694, 0.568) for ``"pan-hamrock"`` (default)
    and (2.65, -0.13, 0.70, 0.54) for ``"dowson-higginson"`` (:data:`FILM_FORMULAS`).

    Parameters
    ----------
    speed : float or array_like
        Mean entrainment speed u, 0 < u < inf [m/s].
    radius : float or array_like
        Effective radius in the rolling direction, 0 < R < inf [m].
    load_per_length : float or array_like
        Load per unit length w', 0 <= w' < inf [N/m].
    estar : float or array_like
        Effective modulus E*, 0 < E* < inf [Pa].
    viscosity : float or array_like
        Dynamic viscosity eta0 at the operating temperature, 0 < eta0 < inf [Pa s].
    pressure_viscosity : float or array_like
        Pressure-viscosity coefficient alpha, 0 < alpha <= 1e-7
        (:data:`PRESSURE_VISCOSITY`) [1/Pa].
    formula : str, optional
        ``"pan-hamrock"`` (default) or ``"dowson-higginson"``.

    Returns
    -------
    float or ndarray
        h_min [m]; inf where w' = 0.

    Raises
    ------
    UnknownNameError
        An unknown formula (the message lists the known ones).

    Notes
    -----
    See :func:`minimum_film_pan_hamrock` and :func:`minimum_film_dowson_higginson`.

    Examples
    --------
    >>> h = minimum_film_thickness(2.7, 4.7e-3, 100e3, 115.4e9, 0.02, 2e-8,
    ...                            formula="dowson-higginson")
    >>> f"{h * 1e6:.3f} um"
    '0.244 um'

    References
    ----------
    .. [1] H. P. Pan, B. J. Hamrock, J. Tribology 111 (1989) 246-251.
    .. [2] D. Dowson, G. R. Higginson, Elasto-Hydrodynamic Lubrication (1977).
    """
    if formula not in FILM_FORMULAS:
        raise UnknownNameError("formula", formula, list(FILM_FORMULAS))
    return _film(FILM_FORMULAS[formula][1], speed, radius, load_per_length, estar,
                 viscosity, pressure_viscosity)


def film_ratio(film_thickness, roughness_1, roughness_2):
    r"""Film ratio (specific film thickness) Lambda of a lubricated contact.

    .. math:: \Lambda = \frac{h_{min}}{\sqrt{R_{q1}^2 + R_{q2}^2}}

    Parameters
    ----------
    film_thickness : float or array_like
        Minimum film thickness h_min, 0 <= h_min <= inf [m].
    roughness_1 : float or array_like
        RMS roughness Rq of the first surface (roller), 0 <= Rq < inf [m].
    roughness_2 : float or array_like
        RMS roughness Rq of the second surface (raceway), 0 <= Rq < inf [m].

    Returns
    -------
    float or ndarray
        Lambda [-] (inf for two ideally smooth surfaces or an infinite film).

    Notes
    -----
    Valid for the ranges above, not both roughnesses zero with a zero film. Lambda
    below about 1 means asperity contact (boundary or mixed lubrication), above about
    3 full separation (Hamrock et al. 2004, section 3.11; Harris & Kotzalas 2007).

    Examples
    --------
    >>> f"{film_ratio(0.35e-6, 0.1e-6, 0.15e-6):.2f}"
    '1.94'

    References
    ----------
    .. [1] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals of Fluid Film
       Lubrication, 2nd ed. (2004), section 3.11 (film parameter).
    """
    h = check_interval("film_thickness", film_thickness, 0.0, np.inf, unit="m")
    r1 = check_interval("roughness_1", roughness_1, 0.0, np.inf, high_open=True, unit="m")
    r2 = check_interval("roughness_2", roughness_2, 0.0, np.inf, high_open=True, unit="m")
    s = np.hypot(r1, r2)
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = np.where(s > 0.0, h / np.where(s > 0.0, s, 1.0), np.inf)
    if np.any((s == 0.0) & (h == 0.0)):
        from ..errors import CombinationError
        raise CombinationError({"film_thickness": 0.0, "roughness_1": 0.0,
                                "roughness_2": 0.0},
                               "zero film between ideally smooth surfaces: Lambda is "
                               "undefined (0/0)")
    return out(lam)


def _gamma(pitch_diameter, roller_diameter, contact_angle):
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    D = check_positive("roller_diameter", roller_diameter, "m")
    a = check_interval("contact_angle", contact_angle, 0.0, math.pi / 2, high_open=True,
                       unit="rad")
    g = D * np.cos(a) / dm
    if np.any(g >= 1.0):
        check_interval("roller_diameter", D * np.cos(a), 0.0, dm, low_open=True,
                       high_open=True, unit="m",
                       hint="D cos(alpha) must be below the pitch diameter")
    return dm, g


def entrainment_speed(inner_ring_speed, pitch_diameter, roller_diameter,
                      outer_ring_speed=0.0, contact_angle=0.0):
    r"""Mean entrainment (rolling) speed of a roller's raceway contacts in pure rolling.

    .. math::

        u = \frac{d_m}{4}\,(1 - \gamma^2)\,|\omega_i - \omega_o|, \qquad
        \gamma = \frac{D\cos\alpha}{d_m}

    the same at the inner and the outer contact: both surfaces of a contact move at u
    relative to the cage, which turns at
    :math:`\omega_c = \tfrac12[\omega_i(1-\gamma) + \omega_o(1+\gamma)]`
    (:func:`cage_speed`).

    Parameters
    ----------
    inner_ring_speed : float or array_like
        Angular speed of the inner ring omega_i, -inf < omega_i < inf [rad/s].
    pitch_diameter : float or array_like
        Pitch diameter d_m > D cos(alpha) [m].
    roller_diameter : float or array_like
        Roller diameter D, 0 < D < inf [m].
    outer_ring_speed : float or array_like, optional
        Angular speed of the outer ring omega_o (default 0, fixed outer ring),
        -inf < omega_o < inf [rad/s].
    contact_angle : float or array_like, optional
        Contact angle alpha (0 for cylindrical roller bearings, default),
        0 <= alpha < pi/2 [rad].

    Returns
    -------
    float or ndarray
        u [m/s], the mean of the two surfaces' speeds at either contact.

    Notes
    -----
    Pure rolling (no cage slip, no gyroscopic or centrifugal effects), rigid rings.
    Inner raceway surface speed relative to the cage:
    (omega_i - omega_c)(d_m/2)(1 - gamma) = (omega_i - omega_o)(d_m/4)(1 - gamma^2);
    the outer raceway's, (omega_c - omega_o)(d_m/2)(1 + gamma), is the same.

    Examples
    --------
    Inner ring at 1500 r/min, d_m = 70 mm, D = 11 mm:

    >>> u = entrainment_speed(1500 * 2 * math.pi / 60, 70e-3, 11e-3)
    >>> f"{u:.4f} m/s"
    '2.6810 m/s'

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, the chapter on kinematic speeds (cage and rolling
       element speeds).
    """
    wi = check_interval("inner_ring_speed", inner_ring_speed, -np.inf, np.inf,
                        low_open=True, high_open=True, unit="rad/s")
    wo = check_interval("outer_ring_speed", outer_ring_speed, -np.inf, np.inf,
                        low_open=True, high_open=True, unit="rad/s")
    dm, g = _gamma(pitch_diameter, roller_diameter, contact_angle)
    return out(dm / 4.0 * (1.0 - g * g) * np.abs(wi - wo))


def cage_speed(inner_ring_speed, pitch_diameter, roller_diameter, outer_ring_speed=0.0,
               contact_angle=0.0):
    r"""Angular speed of the cage (roller set) in pure rolling.

    .. math:: \omega_c = \tfrac12\left[\omega_i(1 - \gamma) + \omega_o(1 + \gamma)\right],
              \qquad \gamma = \frac{D\cos\alpha}{d_m}

    Parameters
    ----------
    inner_ring_speed : float or array_like
        Angular speed of the inner ring omega_i, -inf < omega_i < inf [rad/s].
    pitch_diameter : float or array_like
        Pitch diameter d_m > D cos(alpha) [m].
    roller_diameter : float or array_like
        Roller diameter D, 0 < D < inf [m].
    outer_ring_speed : float or array_like, optional
        Angular speed of the outer ring (default 0), -inf < omega_o < inf [rad/s].
    contact_angle : float or array_like, optional
        Contact angle alpha (default 0), 0 <= alpha < pi/2 [rad].

    Returns
    -------
    float or ndarray
        omega_c [rad/s].

    Notes
    -----
    Pure rolling, no cage slip. A point of the inner ring is overrolled
    Z |omega_i - omega_c| / (2 pi) times a second, of the outer ring
    Z |omega_c - omega_o| / (2 pi).

    Examples
    --------
    >>> f"{cage_speed(157.08, 70e-3, 11e-3):.3f} rad/s"
    '66.198 rad/s'

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, the chapter on kinematic speeds.
    """
    wi = check_interval("inner_ring_speed", inner_ring_speed, -np.inf, np.inf,
                        low_open=True, high_open=True, unit="rad/s")
    wo = check_interval("outer_ring_speed", outer_ring_speed, -np.inf, np.inf,
                        low_open=True, high_open=True, unit="rad/s")
    _, g = _gamma(pitch_diameter, roller_diameter, contact_angle)
    return out(0.5 * (wi * (1.0 - g) + wo * (1.0 + g)))


def rated_viscosity(speed, pitch_diameter):
    r"""Rated (reference) kinematic viscosity nu1 of ISO 281:2007, catalogue form.

    .. math::

        \nu_1 = 45000\,n^{-0.83}\,d_m^{-0.5}\ (n < 1000), \qquad
        \nu_1 = 4500\,n^{-0.5}\,d_m^{-0.5}\ (n \ge 1000)

    with nu1 in mm^2/s, the speed n in r/min and d_m in mm (converted here from and to
    SI).

    Parameters
    ----------
    speed : float or array_like
        Rotational speed of the bearing (the rotating ring against the other),
        0 < omega < inf [rad/s].
    pitch_diameter : float or array_like
        Pitch (mean) diameter d_m, 0 < d_m < inf [m].

    Returns
    -------
    float or ndarray
        nu1 [m^2/s].

    Notes
    -----
    The two-branch power law is the published fit of ISO 281's nu1 diagram (the
    viscosity needed for adequate lubrication at the operating temperature; mineral
    oils); at 1000 r/min (104.72 rad/s), where the second branch takes over, the
    first gives 2.3 % more (the published fit's own step). Catalogue diagrams span
    roughly 2 to 100000 r/min and d_m of 10 to 2000 mm; no range is enforced beyond
    positivity. The catalogues' d_m is the bearing's mean diameter (d + D)/2; the
    bearing passes its pitch diameter, within a few percent of it for a cylindrical
    roller bearing (nu1 ~ d_m^-0.5: half that in nu1).

    Examples
    --------
    >>> f"{rated_viscosity(1500 * 2 * math.pi / 60, 70e-3) * 1e6:.2f} mm^2/s"
    '13.89 mm^2/s'

    References
    ----------
    .. [1] ISO 281:2007, clause on the viscosity ratio, in the form published by
       bearing makers, e.g. SKF, Rolling bearings (PUB BU/P1 17000, 2018), or
       Schaeffler, Technical Pocket Guide STT (2014).
    """
    w = check_positive("speed", speed, "rad/s")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    n = w * 60.0 / (2.0 * math.pi)
    dmm = dm * 1e3
    # the branch point with a rounding allowance: 1000 r/min given as rad/s and
    # converted back is 999.9999999999999
    nu1 = np.where(n < _NU1_BRANCH_RPM * (1.0 - 1e-12), 45000.0 * n ** -0.83, 4500.0 * n ** -0.5) \
        * dmm ** -0.5
    return out(nu1 * 1e-6)


def viscosity_ratio(viscosity, speed, pitch_diameter):
    r"""Viscosity ratio kappa = nu / nu1 of ISO 281:2007.

    .. math:: \kappa = \frac{\nu}{\nu_1(n, d_m)}

    with nu1 from :func:`rated_viscosity`.

    Parameters
    ----------
    viscosity : float or array_like
        Kinematic viscosity nu of the lubricant at the operating temperature,
        0 < nu < inf [m^2/s].
    speed : float or array_like
        Rotational speed of the bearing, 0 < omega < inf [rad/s].
    pitch_diameter : float or array_like
        Pitch diameter d_m, 0 < d_m < inf [m].

    Returns
    -------
    float or ndarray
        kappa [-].

    Notes
    -----
    The life modification factor a_ISO accepts 0.1 <= kappa; above 4 it takes 4
    (:func:`linecontact.bearing.ratings.life_modification_factor`). The dynamic viscosity of
    the film formulas is eta0 = rho nu.

    Examples
    --------
    ISO VG 68 at 70 C (about 20.7 mm^2/s), 1500 r/min, d_m = 70 mm:

    >>> f"{viscosity_ratio(20.7e-6, 1500 * 2 * math.pi / 60, 70e-3):.2f}"
    '1.49'

    References
    ----------
    .. [1] ISO 281:2007, viscosity ratio, catalogue form (see :func:`rated_viscosity`).
    """
    nu = check_positive("viscosity", viscosity, "m^2/s")
    return out(nu / np.asarray(rated_viscosity(speed, pitch_diameter)))
