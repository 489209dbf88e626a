r"""Operating clearance of a radial bearing: interference fits (Lame) and ring temperatures.

An interference fit presses two thick-walled cylinders together: the inner member
(bore :math:`d_1`, outside :math:`d`, modulus :math:`E_1`, Poisson :math:`\nu_1`) into
the outer member (bore d, outside :math:`d_2`; :math:`E_2`, :math:`\nu_2`). Lame's
solution (plane stress, open ends) gives the joint pressure of a diametral interference
I

.. math::

    p = \frac{I}{d\left[\dfrac{1}{E_2}\left(\dfrac{d_2^2 + d^2}{d_2^2 - d^2}
    + \nu_2\right) + \dfrac{1}{E_1}\left(\dfrac{d^2 + d_1^2}{d^2 - d_1^2}
    - \nu_1\right)\right]}

(:func:`fit_pressure`), the outer member's outside diameter grows and the inner
member's bore shrinks by

.. math::

    \Delta d_2 = \frac{2 p\,d^2 d_2}{E_2 (d_2^2 - d^2)}, \qquad
    \Delta d_1 = -\frac{2 p\,d_1 d^2}{E_1 (d^2 - d_1^2)}

For a bearing: the inner ring on the shaft is the outer member (its raceway is its
outside, :func:`inner_raceway_expansion`); the outer ring in the housing is the inner
member (its raceway is its bore, :func:`outer_raceway_contraction`). Both reduce the
radial clearance by their raceway diameter change; so does an inner ring warmer than
the outer ring (:func:`thermal_clearance_change`). :func:`operating_clearance` sums
them.

References
----------
.. [1] S. P. Timoshenko, J. N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill
   (1970), section 28 (thick-walled cylinder).
.. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Essential Concepts, chapter 3 (interference fitting and clearance;
   differential expansion).
.. [3] SKF, Rolling bearings (PUB BU/P1 17000, 2018), "Bearing internal clearance"
   (the reduction by fits and temperature, about 70-90 % of the interference, and
   alpha dT d_m for a ring temperature difference).
"""
from __future__ import annotations

import numpy as np

from .._numerics import out
from ..checks import POISSON_RATIO, check_interval, check_positive
from ..errors import CombinationError

__all__ = [
    "STEEL_EXPANSION",
    "fit_pressure",
    "inner_raceway_expansion",
    "outer_raceway_contraction",
    "thermal_clearance_change",
    "operating_clearance",
]

#: Linear thermal expansion coefficient of bearing steel (100Cr6 / AISI 52100),
#: about 12e-6 1/K between 20 and 100 C (catalogue value) [1/K].
STEEL_EXPANSION = 12e-6


def _poisson(name, v):
    return POISSON_RATIO.check(v, name=name)


def _ratio_term(inner, outer):
    """(outer^2 + inner^2)/(outer^2 - inner^2) for inner < outer (outer may be inf,
    inner may be 0): written with k = (inner/outer)^2 so that inf and 0 are exact."""
    k = (inner / outer) ** 2
    return (1.0 + k) / (1.0 - k)


def fit_pressure(interference, diameter, inner_bore, outer_diameter, inner_modulus,
                 inner_poisson, outer_modulus, outer_poisson):
    r"""Joint pressure of an interference fit of two thick-walled cylinders (Lame).

    .. math::

        p = \frac{I}{d\left[\dfrac{1}{E_2}\left(\dfrac{d_2^2 + d^2}{d_2^2 - d^2}
        + \nu_2\right) + \dfrac{1}{E_1}\left(\dfrac{d^2 + d_1^2}{d^2 - d_1^2}
        - \nu_1\right)\right]}

    Parameters
    ----------
    interference : float or array_like
        Effective diametral interference I (after smoothing of the roughness),
        0 <= I < inf [m].
    diameter : float or array_like
        Joint (nominal) diameter d, 0 < d < inf [m].
    inner_bore : float or array_like
        Bore d_1 of the inner member, 0 <= d_1 < d (0: solid shaft) [m].
    outer_diameter : float or array_like
        Outside diameter d_2 of the outer member, d < d_2 <= inf (inf: a housing
        much larger than the ring) [m].
    inner_modulus : float or array_like
        Young's modulus E_1 of the inner member, 0 < E_1 < inf [Pa].
    inner_poisson : float or array_like
        Poisson's ratio nu_1 of the inner member, 0 <= nu_1 <= 0.5 [-].
    outer_modulus : float or array_like
        Young's modulus E_2 of the outer member, 0 < E_2 < inf [Pa].
    outer_poisson : float or array_like
        Poisson's ratio nu_2 of the outer member, 0 <= nu_2 <= 0.5 [-].

    Returns
    -------
    float or ndarray
        p [Pa].

    Notes
    -----
    Linear elasticity, plane stress (free ends), uniform interference along the
    joint, no rotation (centrifugal loosening not included). A ring's flanges and
    raceway profile are ignored: the ring is the cylinder from bore to raceway.

    Examples
    --------
    A steel ring, bore 50 mm, raceway 59 mm, on a solid steel shaft, I = 20 um:

    >>> p = fit_pressure(20e-6, 50e-3, 0.0, 59e-3, 210e9, 0.3, 210e9, 0.3)
    >>> f"{p / 1e6:.2f} MPa"
    '11.84 MPa'

    References
    ----------
    .. [1] S. P. Timoshenko, J. N. Goodier, Theory of Elasticity, 3rd ed. (1970),
       section 28.
    """
    I = check_interval("interference", interference, 0.0, np.inf, high_open=True,
                       unit="m")
    d = check_positive("diameter", diameter, "m")
    d1 = check_interval("inner_bore", inner_bore, 0.0, d, high_open=True, unit="m")
    d2 = check_interval("outer_diameter", outer_diameter, d, np.inf, low_open=True,
                        unit="m")
    E1 = check_positive("inner_modulus", inner_modulus, "Pa")
    E2 = check_positive("outer_modulus", outer_modulus, "Pa")
    v1 = _poisson("inner_poisson", inner_poisson)
    v2 = _poisson("outer_poisson", outer_poisson)
    compliance = (_ratio_term(d, d2) + v2) / E2 + (_ratio_term(d1, d) - v1) / E1
    return out(I / (d * compliance))


def inner_raceway_expansion(interference, bore, raceway_diameter, ring_modulus,
                            ring_poisson, shaft_bore=0.0, shaft_modulus=None,
                            shaft_poisson=None):
    r"""Growth of the inner ring's raceway diameter from its interference fit on the shaft.

    .. math:: \Delta d_r = \frac{2 p\,d^2 d_r}{E_r (d_r^2 - d^2)}

    with p the joint pressure of :func:`fit_pressure` (shaft: inner member, bore d_s;
    ring: outer member, outside its raceway diameter d_r). For a solid shaft of the
    ring's material it reduces to :math:`\Delta d_r = I\,d/d_r`.

    Parameters
    ----------
    interference : float or array_like
        Effective diametral interference I of ring and shaft, 0 <= I < inf [m].
    bore : float or array_like
        Ring bore (shaft seat) diameter d, 0 < d < inf [m].
    raceway_diameter : float or array_like
        Inner raceway diameter d_r (d_m - D for a cylindrical roller bearing),
        d < d_r < inf [m].
    ring_modulus : float or array_like
        Young's modulus E_r of the ring, 0 < E_r < inf [Pa].
    ring_poisson : float or array_like
        Poisson's ratio of the ring, 0 <= nu_r <= 0.5 [-].
    shaft_bore : float or array_like, optional
        Bore d_s of a hollow shaft, 0 <= d_s < d (default 0: solid) [m].
    shaft_modulus : float or array_like, optional
        Young's modulus of the shaft, 0 < E_s < inf (default: the ring's) [Pa].
    shaft_poisson : float or array_like, optional
        Poisson's ratio of the shaft, 0 <= nu_s <= 0.5 (default: the ring's) [-].

    Returns
    -------
    float or ndarray
        Delta d_r >= 0 [m], the reduction of the radial (diametral) clearance.

    Notes
    -----
    See :func:`fit_pressure` for the assumptions. A hollow shaft or a thicker ring
    lowers the ratio Delta d_r / I.

    Examples
    --------
    >>> f"{inner_raceway_expansion(20e-6, 50e-3, 59e-3, 210e9, 0.3) * 1e6:.3f} um"
    '16.949 um'

    References
    ----------
    .. [1] S. P. Timoshenko, J. N. Goodier, Theory of Elasticity (1970), section 28.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 3.
    """
    Es = ring_modulus if shaft_modulus is None else shaft_modulus
    vs = ring_poisson if shaft_poisson is None else shaft_poisson
    p = np.asarray(fit_pressure(interference, bore, shaft_bore, raceway_diameter, Es, vs,
                                ring_modulus, ring_poisson))
    d = np.asarray(bore, dtype=float)
    dr = np.asarray(raceway_diameter, dtype=float)
    if np.any(np.isinf(dr)):
        raise CombinationError({"raceway_diameter": "inf"},
                               "the ring's raceway diameter must be finite")
    E = np.asarray(ring_modulus, dtype=float)
    return out(2.0 * p * d * d * dr / (E * (dr * dr - d * d)))


def outer_raceway_contraction(interference, outside_diameter, raceway_diameter,
                              ring_modulus, ring_poisson, housing_diameter=np.inf,
                              housing_modulus=None, housing_poisson=None):
    r"""Shrinkage of the outer ring's raceway diameter from its interference in the housing.

    .. math:: \Delta D_r = \frac{2 p\,D_r D^2}{E_r (D^2 - D_r^2)}

    with p the joint pressure of :func:`fit_pressure` (ring: inner member, bore its
    raceway diameter D_r; housing: outer member, outside D_h). For a housing of the
    ring's material and infinite outside diameter it reduces to
    :math:`\Delta D_r = I\,D_r/D`.

    Parameters
    ----------
    interference : float or array_like
        Effective diametral interference I of ring and housing, 0 <= I < inf [m].
    outside_diameter : float or array_like
        Ring outside (housing seat) diameter D, D_r < D < inf [m].
    raceway_diameter : float or array_like
        Outer raceway diameter D_r (d_m + D for a cylindrical roller bearing),
        0 < D_r < D [m].
    ring_modulus : float or array_like
        Young's modulus of the ring, 0 < E_r < inf [Pa].
    ring_poisson : float or array_like
        Poisson's ratio of the ring, 0 <= nu_r <= 0.5 [-].
    housing_diameter : float or array_like, optional
        Outside diameter D_h of the housing, D < D_h <= inf (default inf: a massive
        housing) [m].
    housing_modulus : float or array_like, optional
        Young's modulus of the housing, 0 < E_h < inf (default: the ring's) [Pa].
    housing_poisson : float or array_like, optional
        Poisson's ratio of the housing, 0 <= nu_h <= 0.5 (default: the ring's) [-].

    Returns
    -------
    float or ndarray
        Delta D_r >= 0 [m], the reduction of the radial (diametral) clearance.

    Notes
    -----
    See :func:`fit_pressure` for the assumptions. A housing of lower modulus (light
    alloy) or a thin housing wall lowers the ratio Delta D_r / I.

    Examples
    --------
    >>> f"{outer_raceway_contraction(20e-6, 110e-3, 81e-3, 210e9, 0.3) * 1e6:.3f} um"
    '14.727 um'

    References
    ----------
    .. [1] S. P. Timoshenko, J. N. Goodier, Theory of Elasticity (1970), section 28.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 3.
    """
    Eh = ring_modulus if housing_modulus is None else housing_modulus
    vh = ring_poisson if housing_poisson is None else housing_poisson
    p = np.asarray(fit_pressure(interference, outside_diameter, raceway_diameter,
                                housing_diameter, ring_modulus, ring_poisson, Eh, vh))
    D = np.asarray(outside_diameter, dtype=float)
    Dr = check_positive("raceway_diameter", raceway_diameter, "m")
    E = np.asarray(ring_modulus, dtype=float)
    return out(2.0 * p * Dr * D * D / (E * (D * D - Dr * Dr)))


def thermal_clearance_change(inner_raceway_diameter, outer_raceway_diameter,
                             roller_diameter, inner_temperature_rise,
                             outer_temperature_rise, roller_temperature_rise=None,
                             expansion=STEEL_EXPANSION):
    r"""Change of the radial (diametral) clearance from the temperatures of rings and rollers.

    .. math::

        \Delta P_d = \alpha\left(D_r\,\Delta T_o - d_r\,\Delta T_i
        - 2 D\,\Delta T_w\right)

    (positive: the clearance grows). With the rollers at the mean of the two rings'
    temperatures it is :math:`-\alpha\,(\Delta T_i - \Delta T_o)\,d_m`, the catalogue
    rule.

    Parameters
    ----------
    inner_raceway_diameter : float or array_like
        Inner raceway diameter d_r, 0 < d_r < inf [m].
    outer_raceway_diameter : float or array_like
        Outer raceway diameter D_r, 0 < D_r < inf [m].
    roller_diameter : float or array_like
        Roller diameter D, 0 < D < inf [m].
    inner_temperature_rise : float or array_like
        Temperature rise of the inner ring from the mounting (reference)
        temperature, -inf < dT_i < inf [K].
    outer_temperature_rise : float or array_like
        Temperature rise of the outer ring, -inf < dT_o < inf [K].
    roller_temperature_rise : float or array_like, optional
        Temperature rise of the rollers, -inf < dT_w < inf (default: the mean of the
        two rings') [K].
    expansion : float or array_like, optional
        Linear thermal expansion coefficient alpha of rings and rollers,
        0 <= alpha < inf (default 12e-6, bearing steel) [1/K].

    Returns
    -------
    float or ndarray
        Delta P_d [m]; negative when the inner ring runs warmer (the usual case).

    Notes
    -----
    Uniform temperature in each part, free thermal expansion of the rings (the
    change of a fit's interference by different shaft, ring and housing temperatures
    is a change of `interference` in :func:`inner_raceway_expansion` and
    :func:`outer_raceway_contraction`).

    Examples
    --------
    Inner ring 10 K warmer than the outer ring, d_m = 70 mm:

    >>> f"{thermal_clearance_change(59e-3, 81e-3, 11e-3, 10.0, 0.0) * 1e6:.2f} um"
    '-8.40 um'

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 3.
    .. [2] SKF, Rolling bearings (PUB BU/P1 17000, 2018), "Bearing internal
       clearance".
    """
    dr = check_positive("inner_raceway_diameter", inner_raceway_diameter, "m")
    Dr = check_positive("outer_raceway_diameter", outer_raceway_diameter, "m")
    D = check_positive("roller_diameter", roller_diameter, "m")
    Ti = check_interval("inner_temperature_rise", inner_temperature_rise, -np.inf,
                        np.inf, low_open=True, high_open=True, unit="K")
    To = check_interval("outer_temperature_rise", outer_temperature_rise, -np.inf,
                        np.inf, low_open=True, high_open=True, unit="K")
    Tw = (0.5 * (Ti + To) if roller_temperature_rise is None else
          check_interval("roller_temperature_rise", roller_temperature_rise, -np.inf,
                         np.inf, low_open=True, high_open=True, unit="K"))
    a = check_interval("expansion", expansion, 0.0, np.inf, high_open=True, unit="1/K")
    return out(a * (Dr * To - dr * Ti - 2.0 * D * Tw))


def operating_clearance(clearance, inner_expansion=0.0, outer_contraction=0.0,
                        thermal_change=0.0):
    r"""Operating radial (diametral) clearance after the fits and the temperatures.

    .. math:: P_{d,op} = P_d - \Delta d_r - \Delta D_r + \Delta P_{d,T}

    Parameters
    ----------
    clearance : float or array_like
        Radial internal clearance before mounting P_d (diametral; negative for
        preload), -inf < P_d < inf [m].
    inner_expansion : float or array_like, optional
        Inner raceway growth (:func:`inner_raceway_expansion`), 0 <= dd < inf [m].
    outer_contraction : float or array_like, optional
        Outer raceway shrinkage (:func:`outer_raceway_contraction`), 0 <= dD < inf [m].
    thermal_change : float or array_like, optional
        Thermal change (:func:`thermal_clearance_change`), -inf < dP < inf [m].

    Returns
    -------
    float or ndarray
        P_d,op [m] (negative: the bearing runs preloaded), the clearance to give to
        the load distribution (``clearance=`` of
        :class:`linecontact.bearing.RadialRollerBearing`).

    Notes
    -----
    Superposition of the small changes (linear elasticity and expansion). The
    elastic deformation of the raceways by the rollers' loads is the load
    distribution's, not part of the operating clearance.

    Examples
    --------
    >>> f"{operating_clearance(40e-6, 16.949e-6, 0.0, -8.4e-6) * 1e6:.3f} um"
    '14.651 um'

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 3.
    """
    Pd = check_interval("clearance", clearance, -np.inf, np.inf, low_open=True,
                        high_open=True, unit="m")
    di = check_interval("inner_expansion", inner_expansion, 0.0, np.inf, high_open=True,
                        unit="m")
    do = check_interval("outer_contraction", outer_contraction, 0.0, np.inf,
                        high_open=True, unit="m")
    dt = check_interval("thermal_change", thermal_change, -np.inf, np.inf, low_open=True,
                        high_open=True, unit="m")
    return out(Pd - di - do + dt)
