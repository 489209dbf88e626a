r"""Rating formulas of radial roller bearings: ISO 281's basic dynamic load rating and
basic rating life, and ISO 16281's lamina ratings and basic reference rating life (the
package docstring, :mod:`linecontact.bearing`, gives the method).

References
----------
.. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life.
.. [2] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for
   calculating the modified reference rating life for universally loaded rolling
   bearings.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import CombinationError, OutOfRangeError, UnknownNameError
from ..checks import check_interval, check_positive

__all__ = [
    "dynamic_load_rating",
    "basic_rating_life",
    "reference_rating_life",
    "lamina_load_ratings",
    "ISO_RING_FACTOR",
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
    Valid for Z >= 3, 0 < D_we < D_pw < inf, 0 < L_we < inf. The formula reproduces
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
    _fits(Dpw, Dwe)
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
    _fits(Dpw, Dwe)
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
    qei = np.mean(qi ** pi, axis=0) ** (1 / pi)
    qee = np.mean(qo ** po, axis=0) ** (1 / po)
    total = np.sum((qei / qci) ** 4.5) + np.sum((qee / qce) ** 4.5)
    return math.inf if total == 0 else float(total ** (-8 / 9))


def _rollers(rollers):
    z = check_interval("rollers", rollers, 3, 100000)
    if float(z) != int(z):
        raise OutOfRangeError("rollers", float(z), "a whole number >= 3")
    return int(z)


def _fits(Dpw, Dwe):
    if not Dpw > Dwe:
        raise OutOfRangeError("pitch_diameter", Dpw, f"({Dwe:.6g}, inf) m", unit="m",
                              hint="the pitch diameter must exceed the roller diameter "
                                   "(the inner raceway diameter d_m - D is positive)")
