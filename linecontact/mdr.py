r"""Method of dimensionality reduction (MDR) for arbitrary one-dimensional profiles.

The MDR (Popov & Hess 2015) replaces a three-dimensional normal contact by a 1D profile
g(x), even in x, pressed into a row of independent springs of stiffness E* dx. With the
contact half-length a,

.. math::
    d = g(a), \qquad F(d) = 2E^*\int_0^a \bigl(d - g(x)\bigr)\,dx, \qquad
    k = \frac{dF}{dd} = 2E^* a .

Both directions are offered:

- profile -> response: :func:`mdr_contact_radius`, :func:`mdr_force`,
  :func:`mdr_stiffness` for any callable g (monotone increasing, g(0) = 0), by root
  finding and quadrature;
- response -> profile: :func:`mdr_profile_from_force` (sampled F(d); k by finite
  differences) and :func:`mdr_profile_from_stiffness` (sampled k(d), exact):
  x = k/(2E*), g(x) = d. This is how Li & Popov turn BEM results into Eq. 7.

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
   Friction, Springer (2015).
.. [2] Li & Popov (2017) [li-popov-2017], section 3.
.. [3] docs/theory.md, section 'MDR'.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from ._numerics import out
from .checks import Interval, document
from .errors import OutOfRangeError

__all__ = [
    "mdr_contact_radius",
    "mdr_force",
    "mdr_stiffness",
    "mdr_profile_from_force",
    "mdr_profile_from_stiffness",
]

_MAX_DOUBLINGS = 200

#: Validity ranges checked by the functions below and rendered into their Notes (one
#: object for both, so the documented range is the enforced one).
_DEPTH = Interval("depth", 0.0, np.inf, low_open=True, high_open=True, unit="m")
_ESTAR = Interval("estar", 0.0, np.inf, low_open=True, high_open=True, unit="Pa")
_X_SCALE = Interval("x_scale", 0.0, np.inf, low_open=True, high_open=True, unit="m")
#: Sampled curves (profile extraction): zero is a valid first sample (first contact).
_SAMPLED_DEPTH = Interval("depth", 0.0, np.inf, high_open=True, unit="m")
_SAMPLED_FORCE = Interval("force", 0.0, np.inf, high_open=True, unit="N")
_SAMPLED_STIFFNESS = Interval("stiffness", 0.0, np.inf, high_open=True, unit="N/m")


def _radius_one(d, profile, x_scale):
    """Root a of g(a) = d for one depth, by a geometric bracket then Brent's method."""
    hi = x_scale
    g_hi = float(profile(hi))
    n = 0
    while g_hi < d:
        hi *= 2.0
        n += 1
        g_new = float(profile(hi))
        if n > _MAX_DOUBLINGS or not np.isfinite(g_new):
            raise OutOfRangeError(
                "depth", d, f"(0, sup g) m, sup g ~ {g_hi:.6g} m", unit="m",
                hint="the profile never reaches this depth (bounded profile)")
        g_hi = g_new
    lo = hi / 2.0
    n = 0
    while float(profile(lo)) >= d:
        hi = lo
        lo /= 2.0
        n += 1
        if n > 4 * _MAX_DOUBLINGS:
            raise OutOfRangeError("depth", d, "(0, inf) m", unit="m",
                                  hint="g(x) >= depth down to x ~ 0: is g(0) = 0?")
    return brentq(lambda x: float(profile(x)) - d, lo, hi, xtol=lo * 1e-14,
                  rtol=4 * np.finfo(float).eps, maxiter=500)


@document(D=_DEPTH, X=_X_SCALE)
def mdr_contact_radius(depth, profile, *, x_scale=1.0):
    r"""MDR contact half-length a at depth d: the root of g(a) = d for any 1D profile.

    .. math:: g(a) = d

    Parameters
    ----------
    depth : float or array_like
        Depth d (rigid-body approach), 0 < d < sup g [m].
    profile : callable
        The MDR profile g(x), in m for a scalar x >= 0 in m; monotone increasing,
        g(0) = 0.
    x_scale : float, optional
        A typical contact half-length, where the bracket search for a starts (any
        positive value works; one near the answer saves evaluations) [m].

    Returns
    -------
    float or ndarray
        Contact half-length a in the MDR plane [m] (same shape as `depth`).

    Raises
    ------
    OutOfRangeError
        A depth or x_scale outside its range, or a depth the (bounded) profile never
        reaches.

    Notes
    -----
    Valid for %(D)s and %(X)s; a bounded profile also needs d < sup g: the search
    doubles x from `x_scale` up to 200 times, and a depth still not reached (or a
    non-finite g) raises :class:`~linecontact.errors.OutOfRangeError` instead of
    returning a clamped or NaN value. The root is found by Brent's method to a relative
    tolerance of about 1e-14 in a. For a non-monotone g the root is one of several and
    the MDR itself does not apply.

    Examples
    --------
    Parabola g = x^2/R (the MDR profile of a sphere), R = 10 mm, d = 1 um:
    a = sqrt(R d) = 100 um.

    >>> a = mdr_contact_radius(1e-6, lambda x: x**2 / 10e-3)
    >>> f"{a * 1e6:.6f} um"
    '100.000000 um'

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [2] docs/theory.md, section 'MDR'.
    """
    d = _DEPTH.check(depth)
    xs = float(_X_SCALE.check(x_scale))
    flat = np.array([_radius_one(float(v), profile, xs) for v in d.ravel()])
    return out(flat.reshape(d.shape))


@document(D=_DEPTH, E=_ESTAR, X=_X_SCALE)
def mdr_force(depth, profile, estar, *, x_scale=1.0):
    r"""Normal force of an MDR profile at depth d, by quadrature.

    .. math:: F(d) = 2E^*\int_0^a \bigl(d - g(x)\bigr)\,dx, \qquad g(a) = d

    Parameters
    ----------
    depth : float or array_like
        Depth d (rigid-body approach), 0 < d < sup g [m].
    profile : callable
        The MDR profile g(x), in m for a scalar x >= 0 in m; monotone increasing,
        g(0) = 0.
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    x_scale : float, optional
        Start of the bracket search for a (see :func:`mdr_contact_radius`) [m].

    Returns
    -------
    float or ndarray
        Normal force F [N] (same shape as `depth`).

    Raises
    ------
    OutOfRangeError
        An input outside its range, or a depth the (bounded) profile never reaches.

    Notes
    -----
    Valid for %(D)s, %(E)s and %(X)s, with d < sup g for a bounded profile (see
    :func:`mdr_contact_radius`). Adaptive quadrature (QUADPACK) to a relative tolerance
    of 1e-10. F is the total force of the 3D contact whose MDR profile is g: for a
    cylinder of length L the profile already carries L (Li & Popov 2017, Eq. 7).

    Examples
    --------
    Sphere (g = x^2/R) reproduces Hertz, F = 4/3 E* R^1/2 d^3/2 (Johnson 1985, ch. 4):

    >>> E, R, d = 100e9, 10e-3, 1e-6
    >>> F = mdr_force(d, lambda x: x**2 / R, E)
    >>> round(F / (4 / 3 * E * R**0.5 * d**1.5), 10)
    1.0

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985).
    .. [3] docs/theory.md, section 'MDR'.
    """
    d = _DEPTH.check(depth)
    E = _ESTAR.check(estar)
    a = np.atleast_1d(np.asarray(mdr_contact_radius(d, profile, x_scale=x_scale)))
    forces = []
    for dv, av in zip(d.ravel(), a.ravel()):
        val, _ = quad(lambda x: dv - float(profile(x)), 0.0, av, epsabs=0.0,
                      epsrel=1e-10, limit=200)
        forces.append(val)
    return out(2 * E * np.array(forces).reshape(d.shape))


@document(D=_DEPTH, E=_ESTAR, X=_X_SCALE)
def mdr_stiffness(depth, profile, estar, *, x_scale=1.0):
    r"""Normal contact stiffness k = dF/dd of an MDR profile at depth d.

    .. math:: k = \frac{dF}{dd} = 2E^* a, \qquad g(a) = d

    Parameters
    ----------
    depth : float or array_like
        Depth d (rigid-body approach), 0 < d < sup g [m].
    profile : callable
        The MDR profile g(x), in m for a scalar x >= 0 in m; monotone increasing,
        g(0) = 0.
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    x_scale : float, optional
        Start of the bracket search for a (see :func:`mdr_contact_radius`) [m].

    Returns
    -------
    float or ndarray
        Stiffness k [N/m] (same shape as `depth`).

    Raises
    ------
    OutOfRangeError
        An input outside its range, or a depth the (bounded) profile never reaches.

    Notes
    -----
    Valid for %(D)s, %(E)s and %(X)s, with d < sup g for a bounded profile (see
    :func:`mdr_contact_radius`). Exact given a: no differentiation and no quadrature.

    Examples
    --------
    Parabola g = x^2/R, R = 10 mm, d = 1 um, E* = 100 GPa: a = 100 um, so
    k = 2 E* a = 2e7 N/m.

    >>> f"{mdr_stiffness(1e-6, lambda x: x**2 / 10e-3, 100e9):.6e}"
    '2.000000e+07'

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [2] docs/theory.md, section 'MDR'.
    """
    E = _ESTAR.check(estar)
    return out(2 * E * np.asarray(mdr_contact_radius(depth, profile, x_scale=x_scale)))


def _samples(depth, values, valid):
    d = np.asarray(_SAMPLED_DEPTH.check(depth))
    v = np.asarray(valid.check(values))
    name = valid.name
    if d.ndim != 1 or v.shape != d.shape:
        raise OutOfRangeError(name, f"shape {v.shape}", f"1D, the shape of depth {d.shape}")
    if d.size < 3:
        raise OutOfRangeError("depth", f"{d.size} samples", "at least 3 samples")
    if np.any(np.diff(d) <= 0):
        i = int(np.argmax(np.diff(d) <= 0))
        raise OutOfRangeError("depth", float(d[i + 1]), f"> {d[i]:.6g} m (the previous "
                              "sample): depths must increase strictly", unit="m")
    return d, v


def _check_monotone_x(x, d, what):
    if np.any(np.diff(x) <= 0):
        i = int(np.argmax(np.diff(x) <= 0))
        raise OutOfRangeError(
            what, float(x[i + 1]), f"> {x[i]:.6g} (the value at the previous depth)",
            where=f"at depth {d[i + 1]:.6g} m",
            hint="the MDR needs a monotone profile, i.e. a stiffness that increases "
                 "with depth (F(d) convex)")


@document(SD=_SAMPLED_DEPTH, SK=_SAMPLED_STIFFNESS, E=_ESTAR)
def mdr_profile_from_stiffness(depth, stiffness, estar):
    r"""MDR profile from sampled stiffness k(d): x = k/(2E*), g(x) = d (exact).

    .. math:: x = \frac{k(d)}{2E^*}, \qquad g(x) = d

    Parameters
    ----------
    depth : array_like
        Strictly increasing depths d, 1D, at least 3 samples, 0 <= d < inf [m].
    stiffness : array_like
        Stiffness k = dF/dd at those depths, strictly increasing, 0 <= k < inf [N/m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    x : ndarray
        MDR coordinate, the contact half-length at each depth [m].
    g : ndarray
        Profile values g(x), a copy of `depth` [m].

    Raises
    ------
    OutOfRangeError
        Samples outside their range, of different shapes, fewer than 3, depths not
        strictly increasing, or a stiffness that does not increase with depth (no
        monotone profile exists).

    Notes
    -----
    Valid for %(SD)s, %(SK)s and %(E)s, with the sample conditions above. Exact at the
    samples: the inversion of k = 2 E* a needs no differentiation.

    Examples
    --------
    Samples of the parabola g = x^2/R with R = 10 mm (k = 2 E* sqrt(R d)):

    >>> x, g = mdr_profile_from_stiffness([1e-6, 4e-6, 9e-6], [2e7, 4e7, 6e7], 100e9)
    >>> x * 1e6, g * 1e6
    (array([100., 200., 300.]), array([1., 4., 9.]))

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [2] Li & Popov (2017) [li-popov-2017].
    .. [3] docs/theory.md, section 'MDR'.
    """
    d, k = _samples(depth, stiffness, _SAMPLED_STIFFNESS)
    E = _ESTAR.check(estar)
    x = k / (2 * E)
    _check_monotone_x(x, d, "stiffness")
    return x, d.copy()


@document(SD=_SAMPLED_DEPTH, SF=_SAMPLED_FORCE, E=_ESTAR)
def mdr_profile_from_force(depth, force, estar):
    r"""MDR profile from a sampled force-depth curve (the paper's extraction step).

    .. math:: k = \frac{dF}{dd}, \qquad x = \frac{k}{2E^*}, \qquad g(x) = d

    k is estimated by second-order finite differences (``numpy.gradient``, non-uniform
    spacing allowed), so the result is as accurate as the sampling is fine; prefer
    :func:`mdr_profile_from_stiffness` when k is known directly (e.g. from the BEM).

    Parameters
    ----------
    depth : array_like
        Strictly increasing depths d, 1D, at least 3 samples, 0 <= d < inf [m].
    force : array_like
        Force F at those depths, 0 <= F < inf [N]; F(d) must be convex (k increasing).
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].

    Returns
    -------
    x : ndarray
        MDR coordinate, the contact half-length at each depth [m].
    g : ndarray
        Profile values g(x), a copy of `depth` [m].

    Raises
    ------
    OutOfRangeError
        Bad samples, or a k that does not increase (no monotone profile exists).

    Notes
    -----
    Valid for %(SD)s, %(SF)s and %(E)s, with the sample conditions above. The error of
    k, hence of x, is second order in the depth step (``edge_order=2`` at both ends).

    Examples
    --------
    Hertz sphere F = 4/3 E* sqrt(R) d^1.5 gives back g = x^2/R:

    >>> import numpy as np
    >>> E, R = 100e9, 10e-3
    >>> d = np.linspace(1e-6, 2e-6, 201)
    >>> x, g = mdr_profile_from_force(d, 4 / 3 * E * R**0.5 * d**1.5, E)
    >>> bool(np.allclose(g, x**2 / R, rtol=1e-4))
    True

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [2] Li & Popov (2017) [li-popov-2017].
    .. [3] docs/theory.md, section 'MDR'.
    """
    d, F = _samples(depth, force, _SAMPLED_FORCE)
    E = _ESTAR.check(estar)
    k = np.gradient(F, d, edge_order=2)
    x = k / (2 * E)
    _check_monotone_x(x, d, "force")
    return x, d.copy()
