r"""Rating formulas of radial roller bearings: ISO 281's basic dynamic load rating and
basic rating life, ISO 16281's lamina ratings and basic reference rating life (the
package docstring, :mod:`linecontact.bearing`, gives the method), ISO 76's static load
rating and static safety, and ISO 281's life modification.

Static load rating (ISO 76)
---------------------------
The basic static radial load rating of a radial roller bearing

.. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
          i\,Z\,L_{we}\,D_{we}\cos\alpha \quad [\mathrm{N,\ mm}]

(:func:`static_load_rating`) is the load under which the most heavily loaded roller's
contact reaches a Hertz pressure of 4000 MPa (for contact angle 0, with the
zero-clearance Stribeck factor Q_max = 5 F_r / (i Z cos alpha) and steel's modulus:
docs/bearing_life.md checks the 44 against it). Against the static equivalent load
:math:`P_{0r}` (:func:`static_equivalent_load`) the static safety factor is
:math:`s_0 = C_{0r}/P_{0r}` (:func:`static_safety_factor`); from a computed peak
pressure, where a profile or misalignment makes the load distribution differ from the
rating's assumptions (edge stresses included), the stress-based safety
:math:`s_0 = (4000\ \mathrm{MPa}/p_{max})^2` (:func:`pressure_safety_factor`): line
contact, p ~ sqrt(Q).

Modified rating life (ISO 281:2007)
-----------------------------------
.. math:: L_{nm} = a_1\,a_{ISO}\,L_{10}

multiplies the basic rating life :math:`L_{10}` (:func:`basic_rating_life`) by the
reliability factor :math:`a_1` (:func:`reliability_factor`) and the life modification
factor :math:`a_{ISO}(\kappa, e_C C_u/P)` of the systems approach
(:func:`life_modification_factor`): the viscosity ratio kappa
(:func:`linecontact.bearing.lubrication.viscosity_ratio`), the contamination factor e_C
and the fatigue load limit C_u (:func:`fatigue_load_limit`). On the lamina loads of a
computed load distribution, the same modification applies to ISO 16281's basic
reference rating life :math:`L_{10r}` (:func:`modified_reference_rating_life`). Every
formula is the form published in bearing catalogues and handbooks (the standards' texts
are not reproduced); life exponent 10/3 (line contact).

References
----------
.. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life; its
   systems approach (a_ISO) and reliability factor a1 as published in e.g. SKF,
   Rolling bearings (PUB BU/P1 17000, 2018), "Selecting bearing size", or Schaeffler,
   Technical Pocket Guide STT (2014), "Rating life".
.. [2] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for
   calculating the modified reference rating life for universally loaded rolling
   bearings.
.. [3] ISO 76:2006, Rolling bearings - Static load ratings, as published in bearing
   catalogues (e.g. SKF, Rolling bearings, PUB BU/P1 17000, 2018, "Static load
   ratings"; Schaeffler, Technical Pocket Guide STT, 2014).
.. [4] ISO/TR 1281-2:2008, Explanatory notes on ISO 281 - Part 2: Modified rating life
   calculation, based on a systems approach to fatigue stresses.
.. [5] E. Ioannides, T. A. Harris, "A new fatigue life model for rolling bearings",
   J. Tribology 107 (1985) 367-378 (the fatigue load limit behind a_ISO).
.. [6] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Essential Concepts, chapters on static load rating (4000 MPa, permanent
   deformation 1e-4 D) and fatigue life (reliability).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._numerics import out
from ..checks import Interval, check_interval, check_positive
from ..errors import CombinationError, OutOfRangeError, UnknownNameError

__all__ = [
    "dynamic_load_rating",
    "max_rollers",
    "ROLLER_COUNT",
    "basic_rating_life",
    "reference_rating_life",
    "lamina_load_ratings",
    "roller_damage_shares",
    "ISO_RING_FACTOR",
    "PERMISSIBLE_PRESSURE",
    "static_load_rating",
    "static_equivalent_load",
    "static_safety_factor",
    "pressure_safety_factor",
    "A_ISO_CAP",
    "KAPPA_RANGE",
    "RELIABILITY_FACTORS",
    "life_modification_factor",
    "fatigue_load_limit",
    "reliability_factor",
    "modified_rating_life",
    "reference_equivalent_load",
    "ReferenceLife",
    "modified_reference_rating_life",
]

#: ISO 16281 constants relating the ring rolling-element rating Q_c to C_r:
#: Q_ci = C_i / (0.378 Z), Q_ce = C_e / (0.364 Z) (i = 1, alpha = 0). They are the
#: Lundberg-Palmgren ratios J_r/J_1 and J_r/J_2 of the zero-clearance load zone
#: (:func:`linecontact.bearing.load_zone_integral` and its analogues give 0.3764 and
#: 0.3630, see the tests).
ISO_RING_FACTOR = {"inner": 0.378, "outer": 0.364}


def dynamic_load_rating(rollers, pitch_diameter, roller_diameter, length, b_m=1.1):
    r"""Basic dynamic radial load rating C_r of a radial roller bearing (ISO 281:2007).

    .. math::

        C_r = b_m f_c\,(L_{we})^{7/9} Z^{3/4} D_{we}^{29/27}\ [\mathrm{N,\ mm}],\quad
        f_c = 207.9\,\lambda\nu\,\gamma^{2/9}\frac{(1-\gamma)^{29/27}}{(1+\gamma)^{1/4}}
        \left[1 + \left(1.04\left(\frac{1-\gamma}{1+\gamma}\right)^{143/108}
        \right)^{9/2}\right]^{-2/9}

    with :math:`\gamma = D_{we}/D_{pw}` (contact angle 0, one row) and
    :math:`\lambda\nu = 0.83`.

    Parameters
    ----------
    rollers : int
        Number of rollers Z >= 3 [-].
    pitch_diameter : float
        Pitch diameter D_pw > D_we [m].
    roller_diameter : float
        Roller diameter D_we > 0 [m].
    length : float
        Effective roller length L_we > 0 [m].
    b_m : float, optional
        Rating factor for contemporary material and manufacturing, 0 < b_m <= 2 [-]
        (ISO 281 Table: 1.1 for cylindrical and machined-ring needle roller
        bearings, default; 1.0 for drawn-cup needle roller bearings).

    Returns
    -------
    float
        C_r [N].

    Notes
    -----
    Valid for Z >= 3 rollers that fit (D_pw sin(pi/Z) > D_we), 0 < D_we < D_pw < inf,
    0 < L_we < inf. The formula reproduces
    ISO 281's Table of f_c (84.2 at gamma = 0.10, 74.1 at 0.05); a catalogue's C_r
    may differ (manufacturers' own b_m, profile and material).

    Examples
    --------
    >>> f"{dynamic_load_rating(14, 70e-3, 11e-3, 11e-3) / 1e3:.1f} kN"
    '59.7 kN'

    References
    ----------
    .. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life,
       clause 7 (radial roller bearings) and its table of f_c.
    """
    Z = _rollers(rollers)
    Dpw = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    Dwe = float(check_positive("roller_diameter", roller_diameter, "m"))
    Lwe = float(check_positive("length", length, "m"))
    bm = float(check_interval("b_m", b_m, 0.0, 2.0, low_open=True))
    _fits(Dpw, Dwe, Z)
    g = Dwe / Dpw
    fc = (207.9 * 0.83 * g ** (2 / 9) * (1 - g) ** (29 / 27) / (1 + g) ** 0.25
          * (1 + (1.04 * ((1 - g) / (1 + g)) ** (143 / 108)) ** 4.5) ** (-2 / 9))
    return bm * fc * (Lwe * 1e3) ** (7 / 9) * Z ** 0.75 * (Dwe * 1e3) ** (29 / 27)


def basic_rating_life(rating, load, exponent=10 / 3):
    r"""Basic rating life L10 = (C/P)^p of ISO 281 [10^6 revolutions].

    .. math:: L_{10} = \left(\frac{C_r}{P_r}\right)^{10/3}

    Parameters
    ----------
    rating : float
        Basic dynamic load rating C_r > 0 [N].
    load : float or array_like
        Dynamic equivalent load P_r > 0 (the radial load of a purely radially loaded
        bearing) [N].
    exponent : float, optional
        Life exponent p, 0 < p < inf [-] (10/3 for roller bearings, default).

    Returns
    -------
    float or ndarray
        L10 [-] in millions of revolutions.

    Notes
    -----
    Valid for 0 < C, P < inf (ISO 281 limits P to below about C/2 for its life
    factors; the formula itself is what is computed here).

    Examples
    --------
    >>> f"{basic_rating_life(65e3, 10e3):.1f}"
    '512.5'

    References
    ----------
    .. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life.
    """
    C = check_positive("rating", rating, "N")
    P = check_positive("load", load, "N")
    p = check_positive("exponent", exponent, "")
    r = (C / P) ** p
    return float(r) if np.ndim(r) == 0 else r


def lamina_load_ratings(rating, rollers, pitch_diameter, roller_diameter, laminae):
    r"""Rolling-element load ratings of one lamina, inner and outer ring (ISO 16281).

    .. math::

        q_{ci} = \frac{C_i}{0.378\,Z}\,n_s^{-7/9}, \quad
        q_{ce} = \frac{C_e}{0.364\,Z}\,n_s^{-7/9}, \quad
        C_i = C_r\left[1 + \left(\frac{C_i}{C_e}\right)^{9/2}\right]^{2/9},\
        \frac{C_i}{C_e} = 1.038\left(\frac{1-\gamma}{1+\gamma}\right)^{143/108}

    Parameters
    ----------
    rating : float
        Basic dynamic load rating C_r of the bearing, 0 < C_r < inf [N].
    rollers : int
        Number of rollers Z >= 3 [-].
    pitch_diameter : float
        Pitch diameter D_pw > D_we [m].
    roller_diameter : float
        Roller diameter D_we > 0 [m].
    laminae : int
        Number of laminae n_s >= 1 the roller length is divided into [-].

    Returns
    -------
    tuple of float
        (q_ci, q_ce) [N].

    Notes
    -----
    Valid for 0 < C_r < inf, Z >= 3, 0 < D_we < D_pw, n_s >= 1 (contact angle 0, one
    row). The ring split C_i/C_e and the factors 0.378, 0.364 are those of ISO/TS
    16281:2008 as reconstructed from the Lundberg-Palmgren theory (the factors are the
    ratios J_r/J_1, J_r/J_2 of the zero-clearance load zone, 0.3764 and 0.3630 by
    :func:`load_zone_integral` and its analogues); ISO 16281:2025 keeps the method
    (not checked against the 2025 text, which is not public).

    Examples
    --------
    >>> qi, qe = lamina_load_ratings(65e3, 14, 70e-3, 11e-3, 1)
    >>> f"{qi / 1e3:.1f} kN, {qe / 1e3:.1f} kN"
    '12.7 kN, 19.4 kN'

    References
    ----------
    .. [1] ISO/TS 16281:2008 (now ISO 16281:2025), section on roller bearings (lamina
       method).
    .. [2] G. Lundberg, A. Palmgren, "Dynamic capacity of roller bearings", Acta
       Polytechnica Mech. Eng. Series 2(4) (1952).
    """
    C = float(check_positive("rating", rating, "N"))
    Z = _rollers(rollers)
    Dpw = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    Dwe = float(check_positive("roller_diameter", roller_diameter, "m"))
    n = int(check_interval("laminae", laminae, 1, 1e6))
    _fits(Dpw, Dwe, Z)
    g = Dwe / Dpw
    ratio = 1.038 * ((1 - g) / (1 + g)) ** (143 / 108)  # C_i / C_e
    Ci = C * (1 + ratio ** 4.5) ** (2 / 9)
    Ce = C * (1 + ratio ** -4.5) ** (2 / 9)
    scale = n ** (-7 / 9)
    return (Ci / (ISO_RING_FACTOR["inner"] * Z) * scale,
            Ce / (ISO_RING_FACTOR["outer"] * Z) * scale)


def reference_rating_life(rating, pitch_diameter, roller_diameter, slice_loads_inner,
                          slice_loads_outer, rotating="inner"):
    r"""Basic reference rating life L10r of ISO 16281 from the rollers' lamina loads.

    .. math::

        q_{e,k} = \left(\frac1Z\sum_j q_{jk}^{\,p}\right)^{1/p}\ (p = 4\
        \text{rotating ring},\ 9/2\ \text{stationary}),\qquad
        L_{10r} = \left(\sum_k\left[\left(\frac{q_{ci}}{q_{ei,k}}\right)^{-9/2} +
        \left(\frac{q_{ce}}{q_{ee,k}}\right)^{-9/2}\right]\right)^{-8/9}

    Parameters
    ----------
    rating : float
        Basic dynamic load rating C_r, 0 < C_r < inf [N].
    pitch_diameter : float
        Pitch diameter D_pw > D_we [m].
    roller_diameter : float
        Roller diameter D_we > 0 [m].
    slice_loads_inner : array_like
        Lamina loads of the inner-ring contacts, shape (Z, n_s), >= 0 [N].
    slice_loads_outer : array_like
        Lamina loads of the outer-ring contacts, shape (Z, n_s), >= 0 [N].
    rotating : str, optional
        ``"inner"`` (default) or ``"outer"``: the ring that rotates against the load.

    Returns
    -------
    float
        L10r [-] in millions of revolutions (inf if no lamina is loaded).

    Notes
    -----
    Valid for loads >= 0, 0 < D_we < D_pw, Z >= 3 rollers (the rows), n_s >= 1 laminae
    (the columns). For an aligned bearing of zero clearance with
    uniform lamina loads the Stribeck load zone gives L10r = (C_r/F_r)^4: the line-
    contact exponent of Lundberg and Palmgren, equal to ISO 281's (C_r/P_r)^(10/3) at
    P = C_r only (ISO 281 rounds the exponent to 10/3 for all roller bearings). No
    edge-stress or life-modification factor (a_ISO) is applied: this is the basic
    reference rating life.

    Examples
    --------
    Ten of 14 rollers carrying 2 kN each, uniformly over 10 laminae:

    >>> q = np.zeros((14, 10)); q[:10] = 200.0
    >>> f"{reference_rating_life(65e3, 70e-3, 11e-3, q, q):.0f}"
    '2024'

    References
    ----------
    .. [1] ISO/TS 16281:2008 (now ISO 16281:2025), equations of the basic reference
       rating life of roller bearings (lamina method).
    """
    ti, to, _, _ = _lamina_damage(rating, pitch_diameter, roller_diameter,
                                  slice_loads_inner, slice_loads_outer, rotating)
    total = np.sum(ti) + np.sum(to)
    return math.inf if total == 0 else float(total ** (-8 / 9))


def _lamina_damage(rating, pitch_diameter, roller_diameter, slice_loads_inner,
                   slice_loads_outer, rotating):
    """ISO 16281's damage terms of each lamina of the inner and the outer ring,
    (q_e,k / q_c)^(9/2), and each roller's q_jk^p (the rollers' contributions to the
    rings' equivalent lamina loads), checked inputs: (t_inner, t_outer, qi^p, qo^p)."""
    qi = np.asarray(slice_loads_inner, dtype=float)
    qo = np.asarray(slice_loads_outer, dtype=float)
    if qi.ndim != 2 or qi.shape != qo.shape:
        raise CombinationError({"slice_loads_inner": f"shape {qi.shape}",
                                "slice_loads_outer": f"shape {qo.shape}"},
                               "give two arrays of the same shape (rollers, laminae)")
    for name, q in (("slice_loads_inner", qi), ("slice_loads_outer", qo)):
        check_interval(name, q, 0.0, np.inf, high_open=True, unit="N")
    if rotating not in ("inner", "outer"):
        raise UnknownNameError("rotating", rotating, ["inner", "outer"])
    Z, n = qi.shape
    qci, qce = lamina_load_ratings(rating, Z, pitch_diameter, roller_diameter, n)
    pi, po = (4.0, 4.5) if rotating == "inner" else (4.5, 4.0)
    wi, wo = qi ** pi, qo ** po
    qei = np.mean(wi, axis=0) ** (1 / pi)
    qee = np.mean(wo, axis=0) ** (1 / po)
    return (qei / qci) ** 4.5, (qee / qce) ** 4.5, wi, wo


def roller_damage_shares(rating, pitch_diameter, roller_diameter, slice_loads_inner,
                         slice_loads_outer, rotating="inner"):
    r"""Share of the bearing's fatigue damage (ISO 16281, lamina method) taken at each
    roller's position.

    .. math::

        d_j = \frac{1}{T}\sum_k\left[t_{i,k}\frac{q_{i,jk}^{p_i}}{\sum_l q_{i,lk}^{p_i}}
        + t_{e,k}\frac{q_{e,jk}^{p_e}}{\sum_l q_{e,lk}^{p_e}}\right],\qquad
        t_{i,k} = \left(\frac{q_{ei,k}}{q_{ci}}\right)^{9/2},\quad
        T = \sum_k (t_{i,k} + t_{e,k}) = L_{10r}^{-9/8}

    Parameters
    ----------
    rating : float
        Basic dynamic load rating C_r, 0 < C_r < inf [N].
    pitch_diameter : float
        Pitch diameter D_pw > D_we [m].
    roller_diameter : float
        Roller diameter D_we > 0 [m].
    slice_loads_inner : array_like
        Lamina loads of the inner-ring contacts, shape (Z, n_s), >= 0 [N].
    slice_loads_outer : array_like
        Lamina loads of the outer-ring contacts, shape (Z, n_s), >= 0 [N].
    rotating : str, optional
        ``"inner"`` (default) or ``"outer"``: the ring that rotates against the load.

    Returns
    -------
    ndarray
        d_j [-], one per roller, summing to 1 (all 0 if no lamina is loaded).

    Notes
    -----
    Valid as :func:`reference_rating_life`. Each lamina's damage term
    :math:`t_k` (the summand of :math:`L_{10r}^{-9/8}`) is split over the roller
    positions in proportion to their contributions :math:`q^p` to the lamina's
    equivalent load (p = 4 on the rotating ring, 9/2 on the stationary one): the
    points of a ring meet every position once a revolution, and the damage a point
    takes there grows as :math:`q^p`. A split, not a second life: the shares say
    where the bearing's L10r is spent.

    Examples
    --------
    Ten of 14 rollers carrying 2 kN each: each takes a tenth of the damage.

    >>> q = np.zeros((14, 10)); q[:10] = 200.0
    >>> d = roller_damage_shares(65e3, 70e-3, 11e-3, q, q)
    >>> f"{d.sum():.12f}", f"{d[0]:.3f}", f"{d[-1]:.0f}"
    ('1.000000000000', '0.100', '0')

    References
    ----------
    .. [1] ISO/TS 16281:2008 (now ISO 16281:2025), equations of the basic reference
       rating life of roller bearings (lamina method).
    """
    ti, to, wi, wo = _lamina_damage(rating, pitch_diameter, roller_diameter,
                                    slice_loads_inner, slice_loads_outer, rotating)
    total = np.sum(ti) + np.sum(to)
    if total == 0:
        return np.zeros(wi.shape[0])
    si, so = wi.sum(axis=0), wo.sum(axis=0)
    fi = np.divide(wi, si, out=np.zeros_like(wi), where=si > 0)
    fo = np.divide(wo, so, out=np.zeros_like(wo), where=so > 0)
    return (fi @ ti + fo @ to) / total


#: Contact pressure of roller bearings at the static load rating (ISO 76) [Pa].
PERMISSIBLE_PRESSURE = 4000e6
#: ISO 76's factor for radial roller bearings: 44 N/mm^2 [Pa].
_C0_FACTOR = 44e6


def static_load_rating(rollers, pitch_diameter, roller_diameter, length, rows=1,
                       contact_angle=0.0):
    r"""Basic static radial load rating C0r of a radial roller bearing (ISO 76).

    .. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
              i\,Z\,L_{we}\,D_{we}\cos\alpha

    with the 44 in N/mm^2 and lengths in mm (here in SI: 44e6 Pa times lengths in m,
    the same number).

    Parameters
    ----------
    rollers : int
        Number of rollers per row Z >= 1 [-].
    pitch_diameter : float
        Pitch diameter D_pw > D_we cos(alpha) [m].
    roller_diameter : float
        Roller diameter D_we, 0 < D_we < inf [m].
    length : float
        Effective roller length L_we, 0 < L_we < inf [m].
    rows : int, optional
        Number of rows i >= 1 (default 1) [-].
    contact_angle : float, optional
        Nominal contact angle alpha (0 for cylindrical and needle roller bearings,
        default), 0 <= alpha < pi/2 [rad].

    Returns
    -------
    float
        C0r [N].

    Notes
    -----
    Valid for the ranges above. The rating corresponds to 4000 MPa at the centre of
    the most heavily loaded roller contact (a permanent deformation of about 1e-4 of
    the roller diameter); a maker's catalogue C0 may differ (profile, design).

    Examples
    --------
    14 rollers 11 mm x 11 mm on d_m = 70 mm:

    >>> f"{static_load_rating(14, 70e-3, 11e-3, 11e-3) / 1e3:.2f} kN"
    '62.82 kN'

    References
    ----------
    .. [1] ISO 76:2006, basic static radial load rating of radial roller bearings, as
       published in catalogues.
    """
    Z = check_interval("rollers", rollers, 1, 1e5)
    i = check_interval("rows", rows, 1, 100)
    for name, v in (("rollers", Z), ("rows", i)):
        if float(v) != int(v):
            raise OutOfRangeError(name, float(v), "a whole number >= 1")
    Dpw = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    Dwe = float(check_positive("roller_diameter", roller_diameter, "m"))
    Lwe = float(check_positive("length", length, "m"))
    a = float(check_interval("contact_angle", contact_angle, 0.0, math.pi / 2,
                             high_open=True, unit="rad"))
    Dc = Dwe * math.cos(a)
    if not Dc < Dpw:
        raise OutOfRangeError("pitch_diameter", Dpw, f"({Dc:.6g}, inf) m", unit="m",
                              hint="the pitch diameter must exceed D_we cos(alpha)")
    return _C0_FACTOR * (1.0 - Dc / Dpw) * int(i) * int(Z) * Lwe * Dc


def static_equivalent_load(radial_load):
    r"""Static equivalent radial load P0r of a radial roller bearing with alpha = 0.

    .. math:: P_{0r} = F_r

    Parameters
    ----------
    radial_load : float or array_like
        Radial load F_r (the largest that acts, shocks included),
        0 <= F_r < inf [N].

    Returns
    -------
    float or ndarray
        P0r [N].

    Notes
    -----
    ISO 76 for radial roller bearings with contact angle 0, which carry radial load
    only by their raceways (an axial load on the flanges of NJ or NUP bearings is
    checked by the flange contacts, :mod:`linecontact.bearing.flanges`, not by P0r).

    Examples
    --------
    >>> static_equivalent_load(20e3)
    20000.0

    References
    ----------
    .. [1] ISO 76:2006, static equivalent radial load, as published in catalogues.
    """
    return out(check_interval("radial_load", radial_load, 0.0, np.inf, high_open=True,
                              unit="N"))


def static_safety_factor(static_rating, static_load):
    r"""Static safety factor s0 = C0 / P0 (ISO 76).

    .. math:: s_0 = \frac{C_{0r}}{P_{0r}}

    Parameters
    ----------
    static_rating : float or array_like
        Basic static load rating C0r, 0 < C0r < inf [N].
    static_load : float or array_like
        Static equivalent load P0r, 0 <= P0r < inf [N].

    Returns
    -------
    float or ndarray
        s0 [-] (inf for no load).

    Notes
    -----
    Catalogues ask for s0 of about 1 to 4 for roller bearings depending on the
    demands on quiet running and on shock loads.

    Examples
    --------
    >>> f"{static_safety_factor(62.82e3, 20e3):.3f}"
    '3.141'

    References
    ----------
    .. [1] ISO 76:2006, static safety factor, as published in catalogues.
    """
    C0 = check_positive("static_rating", static_rating, "N")
    P0 = check_interval("static_load", static_load, 0.0, np.inf, high_open=True, unit="N")
    with np.errstate(divide="ignore"):
        return out(np.where(P0 > 0.0, C0 / np.where(P0 > 0.0, P0, 1.0), np.inf))


def pressure_safety_factor(peak_pressure, permissible_pressure=PERMISSIBLE_PRESSURE):
    r"""Stress-based static safety of a line contact from its computed peak pressure.

    .. math:: s_0 = \left(\frac{p_{perm}}{p_{max}}\right)^2, \qquad
              p_{perm} = 4000\ \mathrm{MPa}

    Parameters
    ----------
    peak_pressure : float or array_like
        Largest contact pressure p_max of the most loaded contact (edge stresses
        included), 0 <= p_max < inf [Pa].
    permissible_pressure : float, optional
        Pressure at the static load rating, 0 < p_perm < inf (default 4000 MPa, roller
        bearings) [Pa].

    Returns
    -------
    float or ndarray
        s0 [-] (inf where p_max = 0): the factor by which the load could grow before
        p_max reaches p_perm.

    Notes
    -----
    In a line contact the peak pressure grows as the square root of the load
    (Hertz: p0 = sqrt(w' E* / (pi R))), so the load safety is the square of the
    pressure ratio; with a uniformly loaded roller it equals C0r/P0r wherever the
    rating's load distribution holds. Under a profile or misalignment, p ~ sqrt(Q)
    holds only approximately (the contact length changes with the load); the factor
    is then the pressure ratio squared as defined, not an exact load margin.

    Examples
    --------
    >>> f"{pressure_safety_factor(2000e6):.2f}"
    '4.00'

    References
    ----------
    .. [1] ISO 76:2006 (4000 MPa for roller bearings), as published in catalogues.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter on static load rating.
    """
    p = check_interval("peak_pressure", peak_pressure, 0.0, np.inf, high_open=True,
                       unit="Pa")
    pp = check_positive("permissible_pressure", permissible_pressure, "Pa")
    with np.errstate(divide="ignore"):
        return out(np.where(p > 0.0, (pp / np.where(p > 0.0, p, 1.0)) ** 2, np.inf))


#: Upper limit of a_ISO in the published form [-].
A_ISO_CAP = 50.0
#: kappa range of the published a_ISO: below 0.1 it is not defined (error), above 4
#: the value at 4 applies (the film separates the surfaces; no further gain) [-].
KAPPA_RANGE = (0.1, 4.0)
#: a_ISO for roller bearings:
#: 0.1 [1 - (c1 - c2 / kappa^c3) (e_C C_u / P)^0.4]^-9.185, (kappa from, c1, c2, c3).
_A_ISO_BRANCHES = ((0.1, 1.5859, 1.3993, 0.054381),
                   (0.4, 1.5859, 1.2348, 0.19087),
                   (1.0, 1.5859, 1.2348, 0.071739))
_A_ISO_LOAD_EXPONENT = 0.4
_A_ISO_EXPONENT = -9.185
#: ISO 281:2007's table of a1 (reliability [%] -> a1), as published in catalogues; the
#: Weibull form of :func:`reliability_factor` reproduces every entry to its digits.
RELIABILITY_FACTORS = {90: 1.0, 95: 0.64, 96: 0.55, 97: 0.47, 98: 0.37, 99: 0.25,
                       99.2: 0.22, 99.4: 0.19, 99.6: 0.16, 99.8: 0.12, 99.9: 0.093,
                       99.92: 0.087, 99.94: 0.080, 99.95: 0.077}
#: Life exponent of roller bearings (ISO 281) [-].
_P_ROLLER = 10.0 / 3.0


def life_modification_factor(kappa, contamination, fatigue_load_limit, load):
    r"""Life modification factor a_ISO of ISO 281:2007 for radial roller bearings.

    .. math::

        a_{ISO} = \min\left(50,\ 0.1\left[1 - \left(1.5859 - \frac{c_2}{\kappa^{c_3}}
        \right)\left(\frac{e_C C_u}{P}\right)^{0.4}\right]^{-9.185}\right)

    with :math:`(c_2, c_3)` = (1.3993, 0.054381) for 0.1 <= kappa < 0.4,
    (1.2348, 0.19087) for 0.4 <= kappa < 1 and (1.2348, 0.071739) for 1 <= kappa <= 4.

    Parameters
    ----------
    kappa : float or array_like
        Viscosity ratio nu/nu1, 0.1 <= kappa < inf (above 4 the value at 4 applies)
        [-].
    contamination : float or array_like
        Contamination factor e_C, 0 <= e_C <= 1 (1: extreme cleanliness) [-].
    fatigue_load_limit : float or array_like
        Fatigue load limit C_u of the bearing, 0 < C_u < inf [N].
    load : float or array_like
        Dynamic equivalent load P, 0 < P < inf [N].

    Returns
    -------
    float or ndarray
        a_ISO, 0.1 <= a_ISO <= 50 [-].

    Raises
    ------
    OutOfRangeError
        kappa below 0.1 (the published form is not defined there), or another
        input outside its range.

    Notes
    -----
    As the published form states: kappa > 4 is evaluated at kappa = 4, and a_ISO is
    limited to 50 (also where the bracket reaches zero, i.e. an infinite life in the
    formula). Not included: the rule for lubricants with effective EP additives
    (kappa < 1 and e_C >= 0.2: evaluate at kappa = 1, a_ISO <= 3), which needs a
    test of the lubricant; apply it by passing kappa = 1 and capping at 3. e_C from
    the catalogue tables (cleanliness, d_m, lubrication); C_u from the maker or
    :func:`fatigue_load_limit`.

    Examples
    --------
    kappa = 1.5, e_C = 0.5, C_u = 8 kN, P = 10 kN:

    >>> f"{life_modification_factor(1.5, 0.5, 8e3, 10e3):.3f}"
    '1.754'
    >>> life_modification_factor(2.0, 1.0, 30e3, 10e3)   # clean and lightly loaded
    50.0

    References
    ----------
    .. [1] ISO 281:2007, life modification factor for the systems approach, roller
       bearings, as published in bearing catalogues (e.g. SKF, Rolling bearings,
       PUB BU/P1 17000, 2018; Schaeffler, Technical Pocket Guide STT, 2014).
    .. [2] ISO/TR 1281-2:2008 (its derivation).
    """
    k = check_interval("kappa", kappa, KAPPA_RANGE[0], np.inf, high_open=True,
                       hint="the published a_ISO is not defined below kappa = 0.1")
    ec = check_interval("contamination", contamination, 0.0, 1.0)
    cu = check_positive("fatigue_load_limit", fatigue_load_limit, "N")
    P = check_positive("load", load, "N")
    k = np.minimum(k, KAPPA_RANGE[1])
    c1 = np.full(k.shape, _A_ISO_BRANCHES[0][1])
    c2 = np.full(k.shape, _A_ISO_BRANCHES[0][2])
    c3 = np.full(k.shape, _A_ISO_BRANCHES[0][3])
    for start, b1, b2, b3 in _A_ISO_BRANCHES[1:]:
        at = k >= start
        c1, c2, c3 = np.where(at, b1, c1), np.where(at, b2, c2), np.where(at, b3, c3)
    x = ec * cu / P
    bracket = 1.0 - (c1 - c2 / k ** c3) * x ** _A_ISO_LOAD_EXPONENT
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(bracket > 0.0,
                     0.1 * np.where(bracket > 0.0, bracket, 1.0) ** _A_ISO_EXPONENT,
                     A_ISO_CAP)
    return out(np.minimum(a, A_ISO_CAP))


def fatigue_load_limit(static_rating, pitch_diameter):
    r"""Fatigue load limit C_u of a roller bearing, the simplified estimate from C0.

    .. math::

        C_u = \frac{C_0}{8.2}\ (d_m \le 100\ \mathrm{mm}), \qquad
        C_u = \frac{C_0}{8.2}\left(\frac{100\ \mathrm{mm}}{d_m}\right)^{0.3}\
        (d_m > 100\ \mathrm{mm})

    Parameters
    ----------
    static_rating : float or array_like
        Basic static load rating C0 (:func:`static_load_rating`),
        0 < C0 < inf [N].
    pitch_diameter : float or array_like
        Pitch diameter d_m, 0 < d_m < inf [m].

    Returns
    -------
    float or ndarray
        C_u [N].

    Notes
    -----
    ISO 281:2007's simplified method for roller bearings of common steel and quality
    (its annex); a maker's C_u from the detailed method (contact stress 1500 MPa)
    takes precedence where known. The size factor accounts for the lower fatigue
    limit of larger parts.

    Examples
    --------
    >>> f"{fatigue_load_limit(82e3, 70e-3) / 1e3:.2f} kN"
    '10.00 kN'
    >>> f"{fatigue_load_limit(820e3, 400e-3) / 1e3:.1f} kN"
    '66.0 kN'

    References
    ----------
    .. [1] ISO 281:2007, annex on the fatigue load limit (simplified method for roller
       bearings), as reproduced in catalogue and handbook tables.
    """
    C0 = check_positive("static_rating", static_rating, "N")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    size = np.where(dm <= 0.1, 1.0, (0.1 / dm) ** 0.3)
    return out(C0 / 8.2 * size)


def reliability_factor(reliability):
    r"""Life modification factor a1 for a reliability above 90 % (ISO 281:2007).

    .. math::

        a_1 = 0.95\left(\frac{\ln(1/R)}{\ln(1/0.9)}\right)^{2/3} + 0.05

    the Weibull distribution of bearing lives (slope 1.5) with the minimum life
    0.05 L10 of ISO 281:2007.

    Parameters
    ----------
    reliability : float or array_like
        Reliability R (the fraction of bearings reaching the life),
        0.9 <= R <= 0.9995 [-].

    Returns
    -------
    float or ndarray
        a1 [-] (1 at 90 %, 0.077 at 99.95 %).

    Notes
    -----
    Valid for 0.9 <= R <= 0.9995, the range of ISO 281's table
    (:data:`RELIABILITY_FACTORS`), which this form reproduces to its printed digits
    at every entry (tests/test_life.py).

    Examples
    --------
    >>> f"{reliability_factor(0.99):.3f}"
    '0.248'
    >>> [round(float(a), 2) for a in reliability_factor([0.9, 0.95, 0.99])]
    [1.0, 0.64, 0.25]

    References
    ----------
    .. [1] ISO 281:2007, reliability factor a1 (table and its Weibull basis), as
       published in catalogues.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 11 (Weibull distribution of lives).
    """
    R = check_interval("reliability", reliability, 0.9, 0.9995)
    return out(0.95 * (np.log(1.0 / R) / math.log(1.0 / 0.9)) ** (2.0 / 3.0) + 0.05)


def modified_rating_life(basic_life, life_modification, reliability_factor=1.0):
    r"""Modified rating life L_nm = a1 a_ISO L10 (ISO 281:2007).

    .. math:: L_{nm} = a_1\,a_{ISO}\,L_{10}

    Parameters
    ----------
    basic_life : float or array_like
        Basic rating life L10 (or ISO 16281's L10r), 0 <= L10 <= inf [-] in 10^6
        revolutions.
    life_modification : float or array_like
        a_ISO (:func:`life_modification_factor`), 0 < a_ISO <= 50 [-].
    reliability_factor : float or array_like, optional
        a1 (:func:`reliability_factor`), 0 < a1 <= 1 (default 1: 90 %) [-].

    Returns
    -------
    float or ndarray
        L_nm [-] in 10^6 revolutions.

    Notes
    -----
    Valid for the ranges above; a_ISO above the published cap of 50 is refused
    rather than capped here (compute it with :func:`life_modification_factor`).

    Examples
    --------
    >>> f"{modified_rating_life(512.5, 1.754, 0.25):.1f}"
    '224.7'

    References
    ----------
    .. [1] ISO 281:2007, modified rating life, as published in catalogues.
    """
    L = check_interval("basic_life", basic_life, 0.0, np.inf)
    a = check_interval("life_modification", life_modification, 0.0, A_ISO_CAP,
                       low_open=True)
    a1 = check_interval("reliability_factor", reliability_factor, 0.0, 1.0,
                        low_open=True)
    return out(a1 * a * L)


def reference_equivalent_load(rating, reference_life):
    r"""Dynamic equivalent reference load P_ref that gives a life through ISO 281's law.

    .. math:: P_{ref} = C_r\,L_{10r}^{-3/10}

    (so that :math:`(C_r/P_{ref})^{10/3} = L_{10r}`).

    Parameters
    ----------
    rating : float or array_like
        Basic dynamic load rating C_r, 0 < C_r < inf [N].
    reference_life : float or array_like
        Basic reference rating life L10r, 0 < L10r <= inf [-] in 10^6 revolutions.

    Returns
    -------
    float or ndarray
        P_ref [N] (0 for an infinite life).

    Notes
    -----
    The load at which a_ISO is evaluated for a computed load distribution
    (:func:`modified_reference_rating_life`).

    Examples
    --------
    >>> f"{reference_equivalent_load(65e3, 512.5) / 1e3:.2f} kN"
    '10.00 kN'

    References
    ----------
    .. [1] ISO 16281:2025 (formerly ISO/TS 16281:2008), the dynamic equivalent
       reference load.
    """
    C = check_positive("rating", rating, "N")
    L = check_interval("reference_life", reference_life, 0.0, np.inf, low_open=True)
    return out(C * L ** (-1.0 / _P_ROLLER))


@dataclass(frozen=True)
class ReferenceLife:
    """The modified reference rating life and the factors it is made of.

    Returned by :func:`modified_reference_rating_life`.

    .. math:: L_{nmr} = a_1\\,a_{ISO}(\\kappa, e_C C_u / P_{ref})\\,L_{10r}

    Parameters
    ----------
    basic : float
        Basic reference rating life L10r [-] in 10^6 revolutions.
    reference_load : float
        Dynamic equivalent reference load P_ref = C_r L10r^(-3/10) [N].
    life_modification : float
        a_ISO at P_ref [-].
    reliability_factor : float
        a1 [-].
    life : float
        L_nmr = a1 a_ISO L10r [-] in 10^6 revolutions.

    Notes
    -----
    0 < L10r <= inf; the factors as in :func:`life_modification_factor` and
    :func:`reliability_factor`.

    Examples
    --------
    >>> r = ReferenceLife(500.0, 10e3, 2.0, 1.0, 1000.0)
    >>> r.life == r.reliability_factor * r.life_modification * r.basic
    True

    References
    ----------
    ISO 16281:2025; ISO 281:2007.
    """

    basic: float
    reference_load: float
    life_modification: float
    reliability_factor: float
    life: float


def modified_reference_rating_life(rating, pitch_diameter, roller_diameter,
                                   slice_loads_inner, slice_loads_outer, kappa,
                                   contamination, fatigue_load_limit, reliability=0.9,
                                   rotating="inner"):
    r"""Modified reference rating life L_nmr from the rollers' lamina loads (ISO 16281).

    .. math::

        L_{nmr} = a_1\,a_{ISO}\!\left(\kappa, \frac{e_C C_u}{P_{ref}}\right) L_{10r},
        \qquad P_{ref} = C_r\,L_{10r}^{-3/10}

    with L10r the basic reference rating life of the lamina loads
    (:func:`linecontact.bearing.reference_rating_life`).

    Parameters
    ----------
    rating : float
        Basic dynamic load rating C_r, 0 < C_r < inf [N].
    pitch_diameter : float
        Pitch diameter D_pw > D_we [m].
    roller_diameter : float
        Roller diameter D_we > 0 [m].
    slice_loads_inner : array_like
        Lamina loads of the inner-ring contacts, shape (Z, n_s), >= 0 [N].
    slice_loads_outer : array_like
        Lamina loads of the outer-ring contacts, shape (Z, n_s), >= 0 [N].
    kappa : float
        Viscosity ratio, 0.1 <= kappa < inf [-].
    contamination : float
        Contamination factor e_C, 0 <= e_C <= 1 [-].
    fatigue_load_limit : float
        Fatigue load limit C_u, 0 < C_u < inf [N].
    reliability : float, optional
        Reliability, 0.9 <= R <= 0.9995 (default 0.9: a1 = 1) [-].
    rotating : str, optional
        ``"inner"`` (default) or ``"outer"``: the ring that rotates against the load.

    Returns
    -------
    ReferenceLife
        L10r, P_ref, a_ISO, a1 and L_nmr.

    Notes
    -----
    One a_ISO for the bearing, evaluated at the equivalent reference load that gives
    L10r through ISO 281's life law: the bearing-level form of the life modification
    (for a uniformly loaded aligned bearing it is ISO 281's a_ISO at P). A
    lamina-by-lamina modification (each lamina's own stress against the fatigue
    limit) is not implemented; ISO 16281:2025's text was not checked for it. No edge
    factor is applied to L10r (as in :func:`linecontact.bearing.reference_rating_life`).

    Examples
    --------
    Ten of 14 rollers carrying 2 kN each over 10 laminae, kappa 1.5, e_C 0.5, C_u 8 kN:

    >>> q = np.zeros((14, 10)); q[:10] = 200.0
    >>> r = modified_reference_rating_life(65e3, 70e-3, 11e-3, q, q, 1.5, 0.5, 8e3)
    >>> f"L10r {r.basic:.0f}, P_ref {r.reference_load / 1e3:.2f} kN, " \
    ...     f"a_ISO {r.life_modification:.2f}, L_nmr {r.life:.0f}"
    'L10r 2024, P_ref 6.62 kN, a_ISO 3.27, L_nmr 6618'

    References
    ----------
    .. [1] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for
       calculating the modified reference rating life for universally loaded rolling
       bearings.
    .. [2] ISO 281:2007, life modification factor, catalogue form.
    """
    L10r = reference_rating_life(rating, pitch_diameter, roller_diameter,
                                 slice_loads_inner, slice_loads_outer, rotating=rotating)
    a1 = float(reliability_factor(reliability))
    if math.isinf(L10r):
        P = 0.0
        a = A_ISO_CAP
        check_interval("kappa", kappa, KAPPA_RANGE[0], np.inf, high_open=True)
        check_interval("contamination", contamination, 0.0, 1.0)
        check_positive("fatigue_load_limit", fatigue_load_limit, "N")
    else:
        P = float(reference_equivalent_load(rating, L10r))
        a = float(life_modification_factor(kappa, contamination, fatigue_load_limit, P))
    return ReferenceLife(basic=L10r, reference_load=P, life_modification=a,
                         reliability_factor=a1, life=a1 * a * L10r)


#: The roller counts of a bearing: an integer from 3 (the most that fit on a pitch
#: circle: :func:`max_rollers`) [-].
ROLLER_COUNT = Interval("rollers", 3, math.inf, False, True, "")


def _rollers(rollers):
    z = check_interval("rollers", rollers, 3, 100000)
    if float(z) != int(z):
        raise OutOfRangeError("rollers", float(z), "a whole number >= 3")
    return int(z)


def max_rollers(pitch_diameter, roller_diameter):
    """The most rollers of diameter D that fit on the pitch circle d_m without
    overlapping: the largest Z with d_m sin(pi/Z) > D (the chord between neighbouring
    centres longer than a roller's diameter).

    Parameters
    ----------
    pitch_diameter : float
        Pitch diameter d_m > D [m].
    roller_diameter : float
        Roller diameter D > 0 [m].

    Returns
    -------
    int
        The largest Z that fits [-] (below 3: no bearing of these sizes).

    Notes
    -----
    Valid for 0 < D < d_m; geometry only (a cage needs more room: a real bearing
    holds fewer).

    Examples
    --------
    >>> max_rollers(65e-3, 11e-3), max_rollers(70e-3, 11e-3)
    (18, 19)
    """
    ratio = roller_diameter / pitch_diameter
    z = int(math.pi / math.asin(min(ratio, 1.0)))
    while z >= 3 and not pitch_diameter * math.sin(math.pi / z) > roller_diameter:
        z -= 1
    return z


def _fits(Dpw, Dwe, Z=None):
    """Refuse a roller not smaller than the pitch diameter and, with `Z`, rollers that
    overlap on the pitch circle (:func:`max_rollers`)."""
    if not Dpw > Dwe:
        raise OutOfRangeError("pitch_diameter", Dpw, f"({Dwe:.6g}, inf) m", unit="m",
                              hint="the pitch diameter must exceed the roller diameter "
                                   "(the inner raceway diameter d_m - D is positive)")
    if Z is not None and not Dpw * math.sin(math.pi / Z) > Dwe:
        most = max_rollers(Dpw, Dwe)
        raise OutOfRangeError(
            "rollers", Z, f"[3, {most}] (for d_m = {Dpw * 1e3:.6g} mm, "
            f"D = {Dwe * 1e3:.6g} mm)", hint=f"{Z} rollers overlap: neighbouring centres "
            f"are d_m sin(pi/Z) = {Dpw * math.sin(math.pi / Z) * 1e3:.4g} mm apart, less "
            f"than the roller diameter; at most {most} fit")
