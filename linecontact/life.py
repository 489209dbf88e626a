r"""Modified rating life of roller bearings: ISO 281:2007's a_ISO, the reliability factor a1.

The modified rating life

.. math:: L_{nm} = a_1\,a_{ISO}\,L_{10}

multiplies the basic rating life :math:`L_{10}`
(:func:`linecontact.bearing.basic_rating_life`) by the reliability factor
:math:`a_1` (:func:`reliability_factor`) and the life modification factor
:math:`a_{ISO}(\kappa, e_C C_u/P)` of the systems approach
(:func:`life_modification_factor`): the viscosity ratio kappa
(:func:`linecontact.lubrication.viscosity_ratio`), the contamination factor e_C and
the fatigue load limit C_u (:func:`fatigue_load_limit`). On the lamina loads of a
computed load distribution, the same modification applies to ISO 16281's basic
reference rating life :math:`L_{10r}` (:func:`modified_reference_rating_life`).

Every formula here is the form published in bearing catalogues and handbooks for
ISO 281:2007 (the standard's text is not reproduced); the module is the library layer
for roller bearings (line contact): life exponent 10/3.

References
----------
.. [1] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life, the
   systems approach (a_ISO) and the reliability factor a1, as published in e.g. SKF,
   Rolling bearings (PUB BU/P1 17000, 2018), "Selecting bearing size", or Schaeffler,
   Technical Pocket Guide STT (2014), "Rating life".
.. [2] ISO/TR 1281-2:2008, Explanatory notes on ISO 281 - Part 2: Modified rating life
   calculation, based on a systems approach to fatigue stresses.
.. [3] E. Ioannides, T. A. Harris, "A new fatigue life model for rolling bearings",
   J. Tribology 107 (1985) 367-378 (the fatigue load limit behind a_ISO).
.. [4] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Essential Concepts, chapter 11 (fatigue life, reliability).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._numerics import out
from .checks import check_interval, check_positive

__all__ = [
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
        Basic static load rating C0 (:func:`linecontact.static.static_load_rating`),
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
    from .bearing import reference_rating_life

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
