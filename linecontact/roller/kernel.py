r"""The strip kernel of the coupled-slice roller model: the displacement and curvature
influence of a semi-elliptical strip (:func:`strip_influence`), exact, from a series, a
graded quadrature and a cached spline table.

The model that uses them is described in :mod:`linecontact.roller`.

References
----------
K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), Eq. 3.19
(Boussinesq) and section 4.3 (line contact).
"""
from __future__ import annotations

import collections
import math

import numpy as np

from .._numerics import NotAKnotSpline
from ..checks import check_interval

__all__ = ["strip_influence"]


_C0 = 0.5 + math.log(2.0)       # a(tau) - ln(2 tau) -> C0 as tau -> inf
#: the limit of r = a(tau) - ln(2 tau) as tau -> inf, the constant term of its series in
#: tau^-2 (far_field_coefficients gives the others)
R_INF = _C0
_TAU_SERIES = 2.5               # series for tau >= this, quadrature below
_NTERMS = 28


def _series_coefficients():
    from math import lgamma
    k = np.arange(1, _NTERMS + 1)
    # M_k = (4/pi) int_0^1 s^2k sqrt(1 - s^2) ds = (2/pi) Gamma(k+1/2) Gamma(3/2)/Gamma(k+2)
    M = np.array([(2 / math.pi) * math.exp(lgamma(j + 0.5) + lgamma(1.5) - lgamma(j + 2))
                  for j in range(_NTERMS + 1)])
    # asinh z = ln 2z + sum_k (-1)^(k+1) C(2k, k) / (4^k 2k) z^(-2k)
    alpha = np.array([(-1.0) ** (j + 1) * math.exp(lgamma(2 * j + 1) - 2 * lgamma(j + 1)
                                                   - j * math.log(4)) / (2 * j) * M[j]
                      for j in k])

    def binom(a, j):
        v = 1.0
        for t in range(j):
            v *= (a - t) / (t + 1)
        return v

    # P(tau, s) - 1/s^2 = (1/s^2)[(1 + 2e)(1 + e)^(-3/2) - 1], e = s^2/tau^2
    gamma = np.array([(binom(-1.5, j) + 2 * binom(-1.5, j - 1)) * M[j - 1] for j in k])
    return alpha, gamma


_ALPHA, _GAMMA = _series_coefficients()


def far_field_coefficients(nterms):
    """The series of the four strip functions in u = tau^-2 (tau >= 2.5), as a
    (nterms, 4) array c: r - C0, tau a', p and tau p' equal sum_j c[j - 1] u^j
    (j = 1..nterms) less the constant 1 of tau a' (all four differences of two edges,
    as the kernel uses them, lose the constants)."""
    k = np.arange(1, nterms + 1)
    a, g = _ALPHA[:nterms], _GAMMA[:nterms]
    return np.column_stack([a, -2 * k * a, g, -2 * k * g])
_GL_X, _GL_W = np.polynomial.legendre.leggauss(40)


def _series(coef, u):
    s = np.zeros_like(u)
    d = np.zeros_like(u)
    for j in range(len(coef) - 1, -1, -1):
        s = s * u + coef[j]
        d = d * u + (j + 1) * coef[j]
    return s * u, d * u


def _near(tau):
    """Quadrature for 0 < tau < 2.5 in phi (s = sin phi), graded by phi = tau sinh(t)."""
    t = tau[:, None]
    T = np.arcsinh(np.pi / (2 * t))
    tt = 0.5 * T * (_GL_X + 1)
    phi = t * np.sinh(tt)
    w = (0.5 * T * _GL_W) * t * np.cosh(tt) * (4 / np.pi) * np.cos(phi) ** 2
    s2 = np.sin(phi) ** 2
    t2 = t * t
    rho2 = s2 + t2
    rho = np.sqrt(rho2)
    a = _C0 + np.sum(w * np.log(t + rho), -1)
    ta = tau * np.sum(w / rho, -1)
    f = (t2 * t2 + s2 * t2 - s2 * s2) / ((t * t2 + 2 * s2 * t + rho2 * rho) * rho2 * rho)
    p = np.sum(w * f, -1)
    tp = tau * np.sum(w * (2 * s2 - t2) / (rho2 * rho2 * rho), -1)
    return a - np.log(2 * tau), ta, p, tp


_TAB_MIN = 1e-4
_TAB_MAX = 1.0e4
_NEAR_TABLE = []


def _near_table():
    """Cubic spline in ln(tau) of the four functions over [1e-4, 1e4] (built once).

    3685 nodes, h = 0.005 in ln tau, values from the quadrature (tau < 2.5) and the
    series (tau >= 2.5): interpolation error below 1e-10 of the function's scale
    (checked against the direct evaluation in tests). Evaluating the spline is several
    times cheaper than the 28-term series or the quadrature. Returns a function of
    ln(tau) (1D array) giving an array of shape (len, 4).

    The spline is the not-a-knot cubic (de Boor, A Practical Guide to Splines, 1978,
    chapter IV; what scipy's CubicSpline builds by default) of
    :class:`linecontact._numerics.NotAKnotSpline`, whose coefficients are taken here and
    evaluated by indexing the uniform grid (no search, no scipy import: the first solve
    of a process stays fast).
    """
    if not _NEAR_TABLE:
        n = 3685
        z0, z1 = math.log(_TAB_MIN), math.log(_TAB_MAX)
        z = np.linspace(z0, z1, n)
        h = (z1 - z0) / (n - 1)
        y = np.column_stack(_direct(np.exp(z)))             # (n, 4)
        # (function, power, segment), lowest power first
        c = np.stack([NotAKnotSpline(z, y[:, j]).c[::-1] for j in range(4)])
        # one contiguous (function, segment) table per power: the gathers and the
        # Horner steps then run along the points (an inner loop over the four
        # functions is several times slower)
        coef = np.ascontiguousarray(c.transpose(1, 0, 2))   # (power, function, segment)
        c0, c1, c2, c3 = coef

        def spline(zq):
            u = (zq - z0) * (1.0 / h)
            i = np.minimum(u.astype(np.intp), n - 2)        # u >= 0: tau >= _TAB_MIN
            t = (u - i) * h
            # (the take method: np.take's Python wrapper costs more than a gather
            # of a few hundred points)
            return ((c3.take(i, 1) * t + c2.take(i, 1)) * t
                    + c1.take(i, 1)) * t + c0.take(i, 1)

        _NEAR_TABLE.append((spline, SplineTable(_TAB_MIN, _TAB_MAX, z0, h, coef)))
    return _NEAR_TABLE[0][0]


#: the spline table as data: tau_min <= tau < tau_max, nodes z0 + i h in z = ln tau,
#: coefficients coef[power, function, segment] (spline_table)
SplineTable = collections.namedtuple("SplineTable", "tau_min tau_max z0 h coef")


def spline_table():
    """The cubic spline of the four strip functions in z = ln(tau) that
    :func:`strip_values` evaluates, as data for other implementations of the same
    evaluation (the C engine, :mod:`linecontact.roller._cengine`): valid for
    tau_min <= tau < tau_max; with u = (z - z0)(1/h), segment i = min(floor(u),
    nseg - 1) and t = (u - i) h, function f (r, tau a', p, tau p') is
    ((c3 t + c2) t + c1) t + c0 with c_k = coef[k, f, i] (coef: (4, 4, nseg))."""
    _near_table()
    return _NEAR_TABLE[0][1]


def _direct(flat):
    """The four functions by series (tau >= 2.5) or quadrature (below), 1D input."""
    r = np.empty_like(flat)
    ta = np.empty_like(flat)
    p = np.empty_like(flat)
    tp = np.empty_like(flat)
    # fewer series terms where tau is large (1e-16 relative in each band)
    for lo, hi, nt in ((_TAU_SERIES, 6.0, _NTERMS), (6.0, 30.0, 12), (30.0, np.inf, 6)):
        band = (flat >= lo) & (flat < hi)
        if not np.any(band):
            continue
        u = 1.0 / flat[band] ** 2
        s, ds = _series(_ALPHA[:nt], u)
        r[band] = _C0 + s
        ta[band] = 1.0 - 2 * ds
        s, ds = _series(_GAMMA[:nt], u)
        p[band] = s
        tp[band] = -2 * ds
    near = flat < _TAU_SERIES
    if np.any(near):
        r[near], ta[near], p[near], tp[near] = _near(flat[near])
    return r, ta, p, tp


def strip_influence(tau, direct=False):
    r"""The four functions of a semi-elliptical strip used by the coupled-slice model.

    For a line load q on |x'| < X, spread over |y'| < b as :math:`(2q/\pi b)
    \sqrt{1 - y'^2/b^2}`, the displacement and its y-curvature on the strip's centre line
    at distance t from one end follow from (with :math:`\tau = t/b`, s = y'/b)

    .. math::

        a(\tau) = \frac{4}{\pi}\int_0^1\sqrt{1-s^2}\,\operatorname{asinh}(\tau/s)\,ds,
        \qquad
        \hat p(\tau) = \frac{4}{\pi}\int_0^1\sqrt{1-s^2}\left[
            \frac{\tau(\tau^2 + 2s^2)}{s^2(\tau^2+s^2)^{3/2}} - \frac{1}{s^2}\right]ds .

    Parameters
    ----------
    tau : float or array_like
        t/b > 0 [-].
    direct : bool, optional
        Evaluate by series/quadrature instead of the cached spline table [-].

    Returns
    -------
    tuple of ndarray
        :math:`a(\tau) - \ln 2\tau`, :math:`\tau a'(\tau)`, :math:`\hat p(\tau)`,
        :math:`\tau \hat p'(\tau)` [-].

    Notes
    -----
    For tau >= 2.5 from the convergent series in :math:`\tau^{-2}` (the asinh and
    binomial series integrated against the semi-ellipse's moments
    :math:`M_k = (2/\pi)\Gamma(k+1/2)\Gamma(3/2)/\Gamma(k+2)`, 28 terms); below by
    40-point Gauss-Legendre quadrature in :math:`\varphi` (s = sin phi) graded as
    :math:`\varphi = \tau\sinh t`: relative accuracy 1e-13 for tau >= 0.01 and 1e-8
    down to tau = 1e-4 (checked against adaptive quadrature in tests). For
    1e-4 <= tau < 1e4 the default reads a cubic spline in ln tau of those values (error
    below 1e-10 of each function's scale). Large tau:
    :math:`a - \ln 2\tau \to 1/2 + \ln 2`, :math:`\hat p \to 1/(2\tau^2)`.

    Examples
    --------
    >>> r, ta, p, tp = strip_influence([0.5, 10.0])
    >>> [round(float(v), 6) for v in r], [round(float(v), 6) for v in p]
    ([1.355305, 1.193771], [0.714725, 0.004972])

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), Eq. 3.19 (Boussinesq) and section 4.3.
    """
    tau = check_interval("tau", tau, 0.0, np.inf, low_open=True, high_open=True)
    flat = np.atleast_1d(tau).ravel()
    vals = _direct(flat) if direct else strip_values(flat)
    return tuple(v.reshape(np.shape(tau)) for v in vals)


def strip_values(flat):
    """strip_influence without input checks (1D array of tau > 0)."""
    if flat.min() >= _TAB_MIN and flat.max() < _TAB_MAX:     # (NaN: the mask below)
        return _near_table()(np.log(flat))
    tab = (flat >= _TAB_MIN) & (flat < _TAB_MAX)
    out = np.empty((4, flat.size))
    r, ta, p, tp = out
    if np.any(tab):
        r[tab], ta[tab], p[tab], tp[tab] = _near_table()(np.log(flat[tab]))
    rest = ~tab
    r[rest], ta[rest], p[rest], tp[rest] = _direct(flat[rest])
    return out
