r"""Classical closed forms for a cylinder on a flat, the comparisons of Li & Popov (2017).

All functions take and return SI units (m, N, Pa) and broadcast over numpy arrays. E*
is the effective modulus of Eq. 3 (:func:`effective_modulus`); bearing texts often use
E' = 2 E* instead, which is *not* what these functions take.

Contents: effective modulus (Eq. 3), Hertz half-width (Eq. 1), Puttock & Thwaite
(Eq. 2) with its inverse and its stiffness (the paper's Eq. 13 corrected), the
Johnson-type family (Eq. 4), Kunz & de Maria's linear law, and the steel-only rolling
bearing formulas of Palmgren and ISO 16281.

References
----------
.. [1] Li & Popov (2017) [li-popov-2017].
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985).
.. [3] A. Palmgren, Ball and Roller Bearing Engineering, SKF (1959).
.. [4] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded rolling bearings.
"""
from __future__ import annotations

import math

import numpy as np

from ._numerics import out
from .checks import POISSON_RATIO, Interval, check_interval, check_positive, document
from .errors import OutOfRangeError
from .lipopov import (lipopov_depth, lipopov_force, lipopov_profile,
                      lipopov_stiffness, lipopov_stiffness_at_force)

__all__ = [
    "effective_modulus",
    "hertz_half_width",
    "hertz_peak_pressure",
    "puttock_thwaite_depth",
    "puttock_thwaite_force",
    "puttock_thwaite_stiffness",
    "puttock_thwaite_stiffness_at_depth",
    "puttock_thwaite_profile",
    "JOHNSON_CONSTANTS",
    "johnson_constant",
    "johnson_depth",
    "johnson_force",
    "johnson_stiffness",
    "johnson_equivalent_beta",
    "KUNZ_C",
    "kunz_force",
    "kunz_depth",
    "STEEL_MODULUS",
    "STEEL_POISSON",
    "STEEL_ESTAR",
    "STEEL_ESTAR_TOLERANCE",
    "STEEL_ESTAR_RANGE",
    "PALMGREN_C",
    "ISO16281_C",
    "palmgren_depth",
    "palmgren_force",
    "iso16281_depth",
    "iso16281_force",
]

MODULUS_OR_RIGID = Interval("modulus", 0.0, np.inf, low_open=True, high_open=False,
                            unit="Pa")


# --------------------------------------------------------------------------------------
# Eq. 3
# --------------------------------------------------------------------------------------
@document(E=MODULUS_OR_RIGID, NU=POISSON_RATIO)
def effective_modulus(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    r"""Effective (contact) modulus E* of two elastic bodies (Li & Popov 2017, Eq. 3).

    .. math::
        \frac{1}{E^*} = \frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2}

    Parameters
    ----------
    modulus1 : float or array_like
        Young's modulus E1 of the first body [Pa].
    poisson1 : float or array_like
        Poisson ratio nu1 of the first body [-].
    modulus2 : float or array_like, optional
        Young's modulus E2 of the second body [Pa]; ``inf`` (default) for a rigid body.
    poisson2 : float or array_like, optional
        Poisson ratio nu2 of the second body [-]; required with a finite `modulus2`
        (as on the command line: an elastic body without its Poisson ratio is refused,
        not given a default), ignored for a rigid one.

    Returns
    -------
    float or ndarray
        E* [Pa]. Bearing texts' E' is 2 E*.

    Raises
    ------
    OutOfRangeError
        A modulus outside its range, a Poisson ratio outside its range, a finite
        `modulus2` without `poisson2`, or both bodies rigid.

    Notes
    -----
    Valid for %(E)s (``inf`` = rigid) and %(NU)s for each body, not both rigid.
    nu = 0.5 (incompressible) is allowed: E* = 4 E / 3 for rubber on a rigid body.

    Examples
    --------
    Steel on steel, E = 210 GPa, nu = 0.3:

    >>> f"{effective_modulus(210e9, 0.3, 210e9, 0.3) / 1e9:.2f} GPa"
    '115.38 GPa'

    Rigid cylinder on steel:

    >>> f"{effective_modulus(210e9, 0.3) / 1e9:.2f} GPa"
    '230.77 GPa'

    Rubber (E = 5 MPa, nu = 0.5) on a rigid cylinder:

    >>> f"{effective_modulus(5e6, 0.5) / 1e6:.3f} MPa"
    '6.667 MPa'

    A second modulus needs its Poisson ratio:

    >>> effective_modulus(210e9, 0.3, 70e9)
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: poisson2 = 'missing' is outside ...

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 3.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985),
       chapter 4.
    """
    E1, nu1, E2, nu2 = two_bodies(modulus1, poisson1, modulus2, poisson2)
    compliance = (1 - nu1**2) / E1 + (1 - nu2**2) / E2
    return out(1.0 / compliance)


def two_bodies(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    """The checked elastic constants (E1, nu1, E2, nu2) of a pair of bodies.

    The one home of the input rules of every two-body modulus (E* here, G* in
    :func:`linecontact.tangential.effective_shear_modulus`): moduli in (0, inf] Pa
    (``inf`` = rigid), Poisson ratios in [0, 0.5], not both bodies rigid, and a finite
    `modulus2` only with its `poisson2` (a rigid body's nu2 does not enter: 0 is used).
    """
    E1 = MODULUS_OR_RIGID.check(modulus1, name="modulus1")
    E2 = MODULUS_OR_RIGID.check(modulus2, name="modulus2")
    nu1 = POISSON_RATIO.check(poisson1, name="poisson1")
    if poisson2 is None:
        if np.any(np.isfinite(E2)):
            raise OutOfRangeError(
                "poisson2", "missing", str(POISSON_RATIO),
                hint="modulus2 is given (an elastic second body), so its Poisson ratio "
                     "is needed too; leave modulus2 out for a rigid second body")
        poisson2 = 0.0   # rigid second body: its Poisson ratio does not enter
    nu2 = POISSON_RATIO.check(poisson2, name="poisson2")
    if np.any(np.isinf(E1) & np.isinf(E2)):
        raise OutOfRangeError("modulus1", math.inf, "(0, inf) Pa", unit="Pa",
                              hint="both bodies are rigid (modulus2 = inf as well); "
                                   "at least one must be elastic")
    return E1, nu1, E2, nu2


def _inputs(radius, length, estar):
    return (check_positive("radius", radius, "m"), check_positive("length", length, "m"),
            check_positive("estar", estar, "Pa"))


# --------------------------------------------------------------------------------------
# Eq. 1
# --------------------------------------------------------------------------------------
def hertz_half_width(force, radius, length, estar):
    r"""Half-width b of the Hertzian contact strip of a cylinder (Li & Popov 2017, Eq. 1).

    .. math:: b = \sqrt{\frac{4 R F}{\pi E^* L}}

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < inf [N].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* (Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    float or ndarray
        b [m] (across the cylinder axis; the strip is 2b wide).

    Notes
    -----
    Plane-strain Hertz theory: uniform line load F/L, b << R, b << L.

    Examples
    --------
    >>> f"{hertz_half_width(1e3, 5e-3, 10e-3, 115.38e9) * 1e6:.2f} um"
    '74.28 um'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 1.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985),
       chapter 4.
    """
    F = check_positive("force", force, "N")
    R, L, E = _inputs(radius, length, estar)
    return out(np.sqrt(4 * R * F / (math.pi * E * L)))


def hertz_peak_pressure(force, radius, length, estar):
    r"""Hertz peak pressure p0 of a line contact (plane strain) [Pa].

    .. math:: p_0 = \frac{2F}{\pi b L} = \sqrt{\frac{F E^*}{\pi R L}}

    with b the half-width of Li & Popov (2017), Eq. 1.

    Parameters
    ----------
    force : array_like
        Normal force F > 0 [N].
    radius : array_like
        (Effective) radius R > 0 [m].
    length : array_like
        Roller length L > 0 [m].
    estar : array_like
        Effective modulus E* > 0 of Li & Popov (2017), Eq. 3 [Pa].

    Returns
    -------
    ndarray or float
        p0 [Pa].

    Notes
    -----
    The pressure at mid-length of a long roller (b << L). At the ends of a straight
    roller on an elastic half-space the pressure is singular; a finite end pressure
    needs a profile. Valid for 0 < F, R, L, E* < inf.

    Examples
    --------
    >>> f"{hertz_peak_pressure(1000.0, 5e-3, 10e-3, 115.38e9) / 1e6:.0f} MPa"
    '857 MPa'

    References
    ----------
    .. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985),
       Eq. 4.45.
    .. [2] Li & Popov (2017) [li-popov-2017], Eq. 1.
    """
    F = check_positive("force", force, "N")
    R, L, E = _inputs(radius, length, estar)
    return out(np.sqrt(F * E / (math.pi * R * L)))


# --------------------------------------------------------------------------------------
# Eq. 2 and the corrected Eq. 13
# --------------------------------------------------------------------------------------
_PT = dict(alpha=math.pi / 2, beta=1.0)
_PT_HINT = ("Eq. 2 reaches its largest depth L^2/R at F = pi E* L^3/R; beyond that it "
            "has no physical meaning")


def _pt_hint(R, L):
    """_PT_HINT, naming the geometry when it is the cause: a roller so short against its
    radius that L^2/R lies below the models' parabolic-gap range d <= 0.15 R."""
    lr = L / R
    if lr * lr >= 0.15:
        return _PT_HINT
    return (f"{_PT_HINT}; the cause is the geometry: L/R = {lr:.4g} puts that depth at "
            f"d/R = (L/R)^2 = {lr * lr:.3g} (L/R >= {math.sqrt(0.15):.3g} reaches "
            "d/R = 0.15)")


def puttock_thwaite_depth(force, radius, length, estar):
    r"""Depth of a cylinder on a flat, Puttock & Thwaite (Li & Popov 2017, Eq. 2).

    .. math::
        d = \frac{F}{\pi L E^*}\left(1 + \ln\frac{\pi E^* L^3}{R F}\right)
          = \frac{F}{\pi L E^*}\left(1 + \ln\frac{4L^2}{b^2}\right)

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < pi E* L^3/R [N].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* (Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    float or ndarray
        Depth d [m] (rigid-body approach from first contact).

    Notes
    -----
    Identical to Lundberg (1939). It is the Li-Popov form (Eq. 7) with alpha = pi/2,
    beta = 1. d(F) increases only up to F = pi E* L^3/R (d = L^2/R); larger forces are
    refused.

    Examples
    --------
    Steel on steel (E* = 115.38 GPa), R = 5 mm, L = 10 mm, 1 kN (about 3.36 um):

    >>> f"{puttock_thwaite_depth(1e3, 5e-3, 10e-3, 115.38e9) * 1e6:.3f} um"
    '3.363 um'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 2.
    .. [2] M. J. Puttock, E. G. Thwaite, Elastic compression of spheres and cylinders at
       point and line contact, National Standards Laboratory Technical Paper 25, CSIRO,
       Melbourne (1969).
    .. [3] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem
       Gebiete des Ingenieurwesens 10 (1939) 201-211.
    """
    R, L, E = _inputs(radius, length, estar)
    check_interval("force", force, 0.0, math.pi * E * L**3 / R, low_open=True,
                   high_open=True, unit="N", hint=_pt_hint(R, L))
    return lipopov_depth(force, R, L, E, **_PT)


def puttock_thwaite_force(depth, radius, length, estar):
    r"""Force on a cylinder at a given depth: the inverse of Eq. 2 (Li & Popov 2017).

    .. math::
        F = \frac{\pi E^* L^3}{R}\, e^{-u}, \qquad
        u = -1 - W_{-1}\left(-\frac{d R}{e L^2}\right)

    (W_-1: lower branch of the Lambert W function.)

    Parameters
    ----------
    depth : float or array_like
        Depth d, 0 < d < L^2/R [m].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* (Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    float or ndarray
        F [N].

    Notes
    -----
    Valid for 0 < d < L^2/R, the supremum of the MDR profile of Eq. 2 (Eq. 7 with
    alpha = pi/2, beta = 1); a larger depth is refused. F tends to pi E* L^3/R as d
    tends to L^2/R.

    Examples
    --------
    >>> round(puttock_thwaite_force(3.3634e-6, 5e-3, 10e-3, 115.38e9))
    1000

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 2 (inverted
       in closed form by the MDR, docs/theory.md, section 'MDR').
    .. [2] M. J. Puttock, E. G. Thwaite, Elastic compression of spheres and cylinders at
       point and line contact, National Standards Laboratory Technical Paper 25, CSIRO,
       Melbourne (1969).
    .. [3] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem
       Gebiete des Ingenieurwesens 10 (1939) 201-211.
    """
    R, L, E = _inputs(radius, length, estar)
    check_interval("depth", depth, 0.0, L**2 / R, low_open=True, high_open=True,
                   unit="m", hint=_pt_hint(R, L))
    return lipopov_force(depth, R, L, E, **_PT)


def puttock_thwaite_stiffness(force, radius, length, estar):
    r"""Contact stiffness k = dF/dd of Eq. 2 at a given force (corrected Eq. 13).

    .. math:: k = \frac{\pi L E^*}{\ln\left(\pi E^* L^3 / (R F)\right)}

    Li & Popov print this as Eq. 13, :math:`k = \pi L E^* \ln(R F/(\pi E^* L^3))`,
    which is inverted (and negative for every physical load). The expression here is the
    true derivative of Eq. 2, tested against a numerical derivative.

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < pi E* L^3/R [N].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* (Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    float or ndarray
        k [N/m].

    Notes
    -----
    Valid for 0 < F < pi E* L^3/R, where d(F) of Eq. 2 increases; k grows without
    bound as F approaches that limit (the logarithm vanishes).

    Examples
    --------
    >>> f"{puttock_thwaite_stiffness(1e3, 5e-3, 10e-3, 115.38e9):.4e} N/m"
    '3.2389e+08 N/m'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 2 and Eq. 13
       (corrected).
    .. [2] M. J. Puttock, E. G. Thwaite, Elastic compression of spheres and cylinders at
       point and line contact, National Standards Laboratory Technical Paper 25, CSIRO,
       Melbourne (1969).
    .. [3] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem
       Gebiete des Ingenieurwesens 10 (1939) 201-211.
    """
    R, L, E = _inputs(radius, length, estar)
    check_interval("force", force, 0.0, math.pi * E * L**3 / R, low_open=True,
                   high_open=True, unit="N", hint=_pt_hint(R, L))
    return lipopov_stiffness_at_force(force, R, L, E, **_PT)


def puttock_thwaite_stiffness_at_depth(depth, radius, length, estar):
    r"""Contact stiffness k = dF/dd of Eq. 2 at a given depth.

    .. math:: k = 2E^* a = \frac{\pi E^* L}{u}, \qquad
              u = -1 - W_{-1}\left(-\frac{d R}{e L^2}\right)

    Parameters
    ----------
    depth : float or array_like
        Depth d, 0 < d < L^2/R [m].
    radius, length : float or array_like
        R, L [m].
    estar : float or array_like
        E* [Pa].

    Returns
    -------
    float or ndarray
        k [N/m].

    Notes
    -----
    Eq. 2 is Eq. 7 with alpha = pi/2, beta = 1, so k = 2 E* a with the MDR contact
    half-length a = alpha L/u. Valid for 0 < d < L^2/R, the supremum of that profile.

    Examples
    --------
    >>> f"{puttock_thwaite_stiffness_at_depth(3.3634e-6, 5e-3, 10e-3, 115.38e9):.4e} N/m"
    '3.2389e+08 N/m'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 2 (k = 2 E*
       a by the MDR, docs/theory.md, section 'MDR').
    .. [2] M. J. Puttock, E. G. Thwaite, Elastic compression of spheres and cylinders at
       point and line contact, National Standards Laboratory Technical Paper 25, CSIRO,
       Melbourne (1969).
    .. [3] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem
       Gebiete des Ingenieurwesens 10 (1939) 201-211.
    """
    R, L, E = _inputs(radius, length, estar)
    check_interval("depth", depth, 0.0, L**2 / R, low_open=True, high_open=True,
                   unit="m", hint=_pt_hint(R, L))
    return lipopov_stiffness(depth, R, L, E, **_PT)


def puttock_thwaite_profile(x, radius, length):
    r"""MDR profile equivalent to Eq. 2: Eq. 7 with alpha = pi/2, beta = 1 [m].

    .. math:: g(x) = \frac{L^2}{R}\left(\frac{\pi L}{2x} + 1\right)e^{-\pi L/(2x)}

    Parameters
    ----------
    x : float or array_like
        MDR coordinate, 0 <= x < inf [m].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].

    Returns
    -------
    float or ndarray
        g(x) [m], below L^2/R.

    Notes
    -----
    Valid for 0 <= x < inf; see :func:`linecontact.lipopov.lipopov_profile`.

    Examples
    --------
    >>> f"{puttock_thwaite_profile(10e-3, 5e-3, 10e-3):.4e}"
    '1.0688e-02'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 7 with alpha
       = pi/2, beta = 1 (Eq. 2).
    """
    return lipopov_profile(x, radius, length, **_PT)


# --------------------------------------------------------------------------------------
# Eq. 4
# --------------------------------------------------------------------------------------
#: Constants c of the Johnson-type Eq. 4 by name. Li & Popov attribute c = 1 to Johnson
#: (1985) and 0.72, 0.572 to "other authors"; those two are named by their value only.
JOHNSON_CONSTANTS = {"johnson1985": 1.0, "1": 1.0, "0.72": 0.72, "0.572": 0.572}


def johnson_constant(c):
    """The constant c of Eq. 4: a number, or a name in :data:`JOHNSON_CONSTANTS`.

    Parameters
    ----------
    c : float or str
        The constant c of Eq. 4, any finite number [-], or one of the names
        ``"johnson1985"`` (1), ``"1"``, ``"0.72"``, ``"0.572"``.

    Returns
    -------
    float
        c [-].

    Notes
    -----
    Valid for -inf < c < inf (Li & Popov quote 1, 0.72 and 0.572).

    Examples
    --------
    >>> johnson_constant("johnson1985"), johnson_constant("0.72"), johnson_constant(0.6)
    (1.0, 0.72, 0.6)
    """
    if isinstance(c, str):
        if c not in JOHNSON_CONSTANTS:
            raise OutOfRangeError("c", c, "a finite number or one of "
                                  + ", ".join(repr(k) for k in JOHNSON_CONSTANTS))
        return JOHNSON_CONSTANTS[c]
    value = check_interval("c", c, -np.inf, np.inf, low_open=True, high_open=True)
    if value.ndim:
        raise OutOfRangeError("c", str(c), "a single number")
    return float(value)


def johnson_equivalent_beta(radius, length, c=1.0):
    r"""beta for which Eq. 7 with alpha = pi/2 reproduces Eq. 4 exactly.

    .. math:: \beta = 4 e^{-(1 + c)} (R/L)^2

    Substituting this into the Li-Popov d(F) (alpha = pi/2) gives Eq. 4 term by term,
    so the Johnson-type family is also an MDR model, with the profile of Eq. 7.

    Parameters
    ----------
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    c : float or str, optional
        Constant of Eq. 4 (see :func:`johnson_depth`) [-].

    Returns
    -------
    float or ndarray
        beta of Eq. 9 equivalent to Eq. 4 [-].

    Notes
    -----
    Valid for 0 < R, L < inf and any finite c.

    Examples
    --------
    >>> round(johnson_equivalent_beta(5e-3, 10e-3, 1.0), 6)
    0.135335

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 4 and Eq. 7
       (the identity is derived here).
    """
    R = check_positive("radius", radius, "m")
    L = check_positive("length", length, "m")
    return out(4 * math.exp(-(1 + johnson_constant(c))) * (R / L) ** 2)


def _johnson(radius, length, estar, c):
    R, L, E = _inputs(radius, length, estar)
    cc = johnson_constant(c)
    coeffs = dict(alpha=math.pi / 2, beta=4 * math.exp(-(1 + cc)) * (R / L) ** 2)
    hint = (f"Eq. 4 with c = {cc:g} has its largest depth 4 R exp(-(1 + c)) at "
            "F = 4 pi E* L R exp(-(1 + c)); beyond that d(F) decreases")
    return R, L, E, cc, coeffs, hint


def johnson_depth(force, radius, length, estar, c=1.0):
    r"""Depth of a cylinder on a flat, Johnson-type form (Li & Popov 2017, Eq. 4).

    .. math:: d = \frac{F}{\pi L E^*}\left(\ln\frac{4\pi E^* L R}{F} - c\right)

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < 4 pi E* L R exp(-(1 + c)) [N].
    radius : float or array_like
        Cylinder radius R, 0 < R < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* (Eq. 3), 0 < E* < inf [Pa].
    c : float or str, optional
        The constant: 1 (``"johnson1985"``, Johnson 1985; default), 0.72 or 0.572
        (other authors, per Li & Popov), or any number [-].

    Returns
    -------
    float or ndarray
        d [m].

    Notes
    -----
    This family measures the approach of the cylinder *axis*, a different reference
    point from Eq. 2, which is why the constants differ. Algebraically it equals Eq. 7
    with alpha = pi/2, beta = 4 exp(-(1 + c)) (R/L)^2 (:func:`johnson_equivalent_beta`);
    the inverse and the stiffness use that identity.

    Examples
    --------
    >>> f"{johnson_depth(1e3, 5e-3, 10e-3, 115.38e9, c=1) * 1e6:.3f} um"
    '2.812 um'
    >>> f"{johnson_depth(1e3, 5e-3, 10e-3, 115.38e9, c='0.572') * 1e6:.3f} um"
    '2.930 um'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 4.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985) (c = 1).
    """
    R, L, E, cc, coeffs, hint = _johnson(radius, length, estar, c)
    check_interval("force", force, 0.0, 4 * math.pi * E * L * R * math.exp(-(1 + cc)),
                   low_open=True, high_open=True, unit="N", hint=hint)
    return lipopov_depth(force, R, L, E, **coeffs)


def johnson_force(depth, radius, length, estar, c=1.0):
    r"""Force at a given depth: the inverse of Eq. 4 (Li & Popov 2017), via Lambert W.

    .. math::
        F = 4\pi E^* L R\, e^{z - c}, \qquad z = W_{-1}\left(-\frac{d}{4R} e^{c}\right)

    Parameters
    ----------
    depth : float or array_like
        Depth d, 0 < d < 4 R exp(-(1 + c)) [m].
    radius, length : float or array_like
        R, L [m].
    estar : float or array_like
        E* [Pa].
    c : float or str, optional
        Constant of Eq. 4 (see :func:`johnson_depth`) [-].

    Returns
    -------
    float or ndarray
        F [N].

    Notes
    -----
    Valid for 0 < d < 4 R exp(-(1 + c)), the largest depth of Eq. 4 (reached at
    F = 4 pi E* L R exp(-(1 + c))); a larger depth is refused.

    Examples
    --------
    >>> round(johnson_force(2.8116e-6, 5e-3, 10e-3, 115.38e9, c=1))
    1000

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 4.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985) (c = 1).
    """
    R, L, E, cc, coeffs, hint = _johnson(radius, length, estar, c)
    check_interval("depth", depth, 0.0, 4 * R * math.exp(-(1 + cc)), low_open=True,
                   high_open=True, unit="m", hint=hint)
    return lipopov_force(depth, R, L, E, **coeffs)


def johnson_stiffness(force, radius, length, estar, c=1.0):
    r"""Contact stiffness k = dF/dd of Eq. 4 at a given force.

    .. math:: k = \frac{\pi L E^*}{\ln\left(4\pi E^* L R / F\right) - c - 1}

    Parameters
    ----------
    force : float or array_like
        0 < F < 4 pi E* L R exp(-(1 + c)) [N].
    radius, length : float or array_like
        R, L [m].
    estar : float or array_like
        E* [Pa].
    c : float or str, optional
        Constant of Eq. 4 (see :func:`johnson_depth`) [-].

    Returns
    -------
    float or ndarray
        k [N/m].

    Notes
    -----
    The derivative of Eq. 4 at the given force, k = 1/(dd/dF). Valid for
    0 < F < 4 pi E* L R exp(-(1 + c)), where dd/dF > 0 (k grows without bound at the
    upper end).

    Examples
    --------
    >>> f"{johnson_stiffness(1e3, 5e-3, 10e-3, 115.38e9):.4e} N/m"
    '3.9437e+08 N/m'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 4.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985) (c = 1).
    """
    R, L, E, cc, coeffs, hint = _johnson(radius, length, estar, c)
    check_interval("force", force, 0.0, 4 * math.pi * E * L * R * math.exp(-(1 + cc)),
                   low_open=True, high_open=True, unit="N", hint=hint)
    return lipopov_stiffness_at_force(force, R, L, E, **coeffs)


# --------------------------------------------------------------------------------------
# Kunz & de Maria
# --------------------------------------------------------------------------------------
#: Coefficient of Kunz & de Maria's linear law F = c E* L d (experiment, 2002).
KUNZ_C = 0.175


def kunz_force(depth, length, estar, c=KUNZ_C):
    r"""Force of Kunz & de Maria's linear law for parallel cylinders (as cited by Li & Popov).

    .. math:: F = c\, E^* L\, d, \qquad c = 0.175

    Parameters
    ----------
    depth : float or array_like
        Depth d, 0 < d < inf [m].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        E* [Pa].
    c : float, optional
        Coefficient, 0 < c < inf; 0.175 from the experiment [-].

    Returns
    -------
    float or ndarray
        F [N].

    Notes
    -----
    An empirical fit to experiments on parallel cylinders; no radius dependence and a
    constant stiffness c E* L.

    Examples
    --------
    >>> round(kunz_force(5e-6, 10e-3, 115.38e9))
    1010

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], section 1.
    .. [2] Kunz & de Maria (2002), experiments on parallel cylinders, as cited by Li &
       Popov (2017) [1].
    """
    d = check_positive("depth", depth, "m")
    L = check_positive("length", length, "m")
    E = check_positive("estar", estar, "Pa")
    cc = check_positive("c", c)
    return out(cc * E * L * d)


def kunz_depth(force, length, estar, c=KUNZ_C):
    r"""Depth from Kunz & de Maria's linear law, d = F / (c E* L).

    .. math:: d = \frac{F}{c\, E^* L}

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < inf [N].
    length : float or array_like
        Cylinder length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E*, 0 < E* < inf [Pa].
    c : float, optional
        Coefficient, 0 < c < inf; 0.175 from the experiment [-].

    Returns
    -------
    float or ndarray
        d [m].

    Notes
    -----
    The inverse of :func:`kunz_force`, valid where it is: 0 < F, L, E*, c < inf.

    Examples
    --------
    >>> f"{kunz_depth(1e3, 10e-3, 115.38e9) * 1e6:.3f} um"
    '4.953 um'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], section 1.
    .. [2] Kunz & de Maria (2002), experiments on parallel cylinders, as cited by Li &
       Popov (2017) [1].
    """
    F = check_positive("force", force, "N")
    L = check_positive("length", length, "m")
    E = check_positive("estar", estar, "Pa")
    cc = check_positive("c", c)
    return out(F / (cc * E * L))


# --------------------------------------------------------------------------------------
# Palmgren, ISO 16281 (steel only)
# --------------------------------------------------------------------------------------
STEEL_MODULUS = 210e9
STEEL_POISSON = 0.3
#: E* of steel on steel, E = 210 GPa, nu = 0.3: 115.38 GPa.
STEEL_ESTAR = STEEL_MODULUS / (2 * (1 - STEEL_POISSON**2))
#: Relative tolerance on E* within which the steel formulas are accepted.
STEEL_ESTAR_TOLERANCE = 0.10
#: E* accepted by the steel-only formulas (Palmgren, ISO 16281).
STEEL_ESTAR_RANGE = Interval("estar", STEEL_ESTAR * (1 - STEEL_ESTAR_TOLERANCE),
                             STEEL_ESTAR * (1 + STEEL_ESTAR_TOLERANCE), unit="Pa")
STEEL_HINT = ("this is an empirical formula for steel on steel (E = 210 GPa, nu = 0.3, "
               f"E* = {STEEL_ESTAR / 1e9:.2f} GPa, accepted within "
               f"{STEEL_ESTAR_TOLERANCE:.0%}); it is not rescaled to other materials, "
               "use a physical model (li-popov, puttock-thwaite) instead")

#: Palmgren's coefficient, d [mm] = 3.84e-5 F[N]^0.9 / L[mm]^0.8 (one contact).
PALMGREN_C = 3.84e-5
#: ISO 16281 per-contact coefficient, d [mm] = 3.97e-5 F[N]^0.9 / L[mm]^0.8.
ISO16281_C = 3.97e-5


def _steel_depth(force, length, estar, coef):
    F = check_positive("force", force, "N")
    L = check_positive("length", length, "m")
    STEEL_ESTAR_RANGE.check(estar, hint=STEEL_HINT)
    # the source formula is in mm and N: d_mm = coef F^0.9 / L_mm^0.8
    return out(1e-3 * coef * F**0.9 / (1e3 * L) ** 0.8)


def _steel_force(depth, length, estar, coef):
    d = check_positive("depth", depth, "m")
    L = check_positive("length", length, "m")
    STEEL_ESTAR_RANGE.check(estar, hint=STEEL_HINT)
    return out((1e3 * d * (1e3 * L) ** 0.8 / coef) ** (1 / 0.9))


@document(STEEL=STEEL_ESTAR_RANGE)
def palmgren_depth(force, length, estar):
    r"""Depth of one roller-raceway contact, Palmgren's empirical formula (steel only).

    .. math:: d\,[\mathrm{mm}] = 3.84\times10^{-5}\,
              \frac{F\,[\mathrm{N}]^{0.9}}{L\,[\mathrm{mm}]^{0.8}}

    Parameters
    ----------
    force : float or array_like
        Normal force F on the roller, 0 < F < inf [N].
    length : float or array_like
        Roller (effective contact) length L, 0 < L < inf [m].
    estar : float or array_like
        Effective modulus E* [Pa]; only used to refuse non-steel pairs.

    Returns
    -------
    float or ndarray
        d [m] (converted from the source's mm; F in N, L converted to mm inside).

    Raises
    ------
    OutOfRangeError
        For E* outside the steel range below (no rescaling rule is applied).

    Notes
    -----
    Valid for steel on steel only: %(STEEL)s, i.e. E* within 10 % of the
    value for E = 210 GPa, nu = 0.3 (115.38 GPa). Bearing steels (E = 200 to 215 GPa,
    nu = 0.27 to 0.3) lie inside. The radius does not enter.

    Examples
    --------
    Steel, L = 10 mm, 1 kN (about 3.05 um):

    >>> f"{palmgren_depth(1e3, 10e-3, 115.38e9) * 1e6:.3f} um"
    '3.050 um'

    References
    ----------
    .. [1] A. Palmgren, Ball and Roller Bearing Engineering, SKF, Philadelphia (1959).
    """
    return _steel_depth(force, length, estar, PALMGREN_C)


@document(STEEL=STEEL_ESTAR_RANGE)
def palmgren_force(depth, length, estar):
    r"""Force at a given depth: the inverse of :func:`palmgren_depth` (steel only).

    .. math:: F\,[\mathrm{N}] = \left(\frac{d\,[\mathrm{mm}]\; L\,[\mathrm{mm}]^{0.8}}
              {3.84\times10^{-5}}\right)^{1/0.9}

    Parameters
    ----------
    depth : float or array_like
        Depth of one contact d, 0 < d < inf [m].
    length : float or array_like
        Roller (effective contact) length L, 0 < L < inf [m].
    estar : float or array_like
        E* [Pa]; only used to refuse non-steel pairs.

    Returns
    -------
    float or ndarray
        F [N].

    Notes
    -----
    Valid for %(STEEL)s only.

    Examples
    --------
    >>> round(palmgren_force(3.0502e-6, 10e-3, 115.38e9))
    1000

    References
    ----------
    .. [1] A. Palmgren, Ball and Roller Bearing Engineering, SKF, Philadelphia (1959).
    """
    return _steel_force(depth, length, estar, PALMGREN_C)


@document(STEEL=STEEL_ESTAR_RANGE)
def iso16281_depth(force, length, estar):
    r"""Depth of one roller-raceway contact per ISO 16281 (steel only).

    .. math:: d\,[\mathrm{mm}] = 3.97\times10^{-5}\,
              \frac{F\,[\mathrm{N}]^{0.9}}{L\,[\mathrm{mm}]^{0.8}}

    Parameters
    ----------
    force : float or array_like
        Normal force F, 0 < F < inf [N].
    length : float or array_like
        Roller (effective contact) length L, 0 < L < inf [m].
    estar : float or array_like
        E* [Pa]; only used to refuse non-steel pairs.

    Returns
    -------
    float or ndarray
        d [m] of one contact (mm in the source, converted).

    Notes
    -----
    The standard's whole-roller form :math:`Q = 35948\,L^{8/9}\delta^{10/9}` (N, mm)
    covers two contacts in series; solved for delta and halved it gives this
    per-contact coefficient (35948^-0.9 / 2 = 3.97e-5). Valid for steel only:
    %(STEEL)s (E* within 10 % of 115.38 GPa).

    Examples
    --------
    >>> f"{iso16281_depth(1e3, 10e-3, 115.38e9) * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    .. [1] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
       reference rating life for universally loaded rolling bearings.
    """
    return _steel_depth(force, length, estar, ISO16281_C)


@document(STEEL=STEEL_ESTAR_RANGE)
def iso16281_force(depth, length, estar):
    r"""Force at a given depth: the inverse of :func:`iso16281_depth` (steel only).

    .. math:: F\,[\mathrm{N}] = \left(\frac{d\,[\mathrm{mm}]\; L\,[\mathrm{mm}]^{0.8}}
              {3.97\times10^{-5}}\right)^{1/0.9}

    Parameters
    ----------
    depth : float or array_like
        Depth of one contact d, 0 < d < inf [m].
    length : float or array_like
        Roller (effective contact) length L, 0 < L < inf [m].
    estar : float or array_like
        E* [Pa]; only used to refuse non-steel pairs.

    Returns
    -------
    float or ndarray
        F [N].

    Notes
    -----
    Valid for %(STEEL)s only.

    Examples
    --------
    >>> round(iso16281_force(3.1535e-6, 10e-3, 115.38e9))
    1000

    References
    ----------
    .. [1] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
       reference rating life for universally loaded rolling bearings.
    """
    return _steel_force(depth, length, estar, ISO16281_C)
