r"""The two pieces of numerical analysis the runtime needs, in numpy alone.

A cubic spline with not-a-knot ends (the interpolant of the shipped tables) and the
lower branch :math:`W_{-1}` of the Lambert W function (the closed forms of the Li-Popov
model). Both used to come from scipy (``scipy.interpolate.CubicSpline``,
``scipy.special.lambertw``), whose import alone costs several hundred milliseconds,
more than the whole one-case computation; tests/test_lipopov.py checks that both agree
with scipy to 1e-12. Besides them, :func:`out`: the shape every result is returned in
(a Python float for a scalar, the array otherwise).

References
----------
.. [1] C. de Boor, A Practical Guide to Splines, Springer (1978), ch. IV (cubic spline
   interpolation, the not-a-knot end condition).
.. [2] R. M. Corless, G. H. Gonnet, D. E. G. Hare, D. J. Jeffrey, D. E. Knuth, "On the
   Lambert W function", Adv. Comput. Math. 5 (1996) 329-359.
.. [3] N. M. Temme, Special Functions, Wiley (1996), section 11.2.3 (inversion of
   t = u - ln(1 + u) near u = 0).
"""
from __future__ import annotations

import functools
import math
import threading

import numpy as np

__all__ = ["NotAKnotSpline", "UniformHermite", "blockwise", "lambertw_m1",
           "log1p_excess_root", "out", "serial_blas"]


def out(x):
    """Return a Python float for a 0-d result, the array otherwise (internal helper)."""
    x = np.asarray(x)
    if x.ndim == 0:
        return float(x)
    return x


class NotAKnotSpline:
    r"""Cubic spline through (x_i, y_i) with not-a-knot end conditions.

    On the interval :math:`[x_i, x_{i+1}]`, with :math:`t = x - x_i`,

    .. math:: s(x) = c_{0,i} t^3 + c_{1,i} t^2 + c_{2,i} t + c_{3,i},

    twice continuously differentiable, and the third derivative continuous across
    :math:`x_1` and :math:`x_{n-2}` (not-a-knot). The coefficients are computed once,
    from the knot slopes solved by one tridiagonal system (de Boor 1978, ch. IV); they are the
    coefficients ``scipy.interpolate.CubicSpline(x, y).c`` holds (the same end rule,
    also for 2 points: a line, and 3 points: a parabola).

    Parameters
    ----------
    x : array_like
        Knots, strictly increasing, at least 2 [same unit as the argument].
    y : array_like
        Values at the knots [any unit].

    Notes
    -----
    Outside [x_0, x_{n-1}] the end polynomials are continued, as scipy does; callers
    check their own ranges first. Evaluation: searchsorted + Horner, O(log n) per point.

    Examples
    --------
    A cubic is reproduced exactly (not-a-knot has no end error for cubics):

    >>> s = NotAKnotSpline([0.0, 1.0, 2.0, 3.0, 5.0], [0.0, 1.0, 8.0, 27.0, 125.0])
    >>> float(s(4.0)), float(s(4.0, 1)), float(s(4.0, 2))
    (64.0, 48.0, 24.0)

    References
    ----------
    C. de Boor, A Practical Guide to Splines, Springer (1978), ch. IV.
    """

    def __init__(self, x, y):
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        if x.ndim != 1 or x.shape != y.shape or x.size < 2:
            raise ValueError("spline knots: x and y must be 1-D of the same length >= 2")
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
            raise ValueError("spline knots must be finite")
        h = np.diff(x)
        if np.any(h <= 0):
            raise ValueError("spline knots x must be strictly increasing")
        m = np.diff(y) / h
        n = x.size
        if n == 2:
            s = np.array([m[0], m[0]])
        elif n == 3:
            # not-a-knot at both ends of a single interior knot: the parabola through
            # the three points, p'(x) = m_0 + c (2 x - x_0 - x_1)
            c = (m[1] - m[0]) / (x[2] - x[0])
            s = m[0] + c * (2 * x - x[0] - x[1])
        else:
            s = _slopes_not_a_knot(x, h, m)
        t = (s[:-1] + s[1:] - 2 * m) / h
        self.x = x
        #: Coefficients, shape (4, n - 1), highest power first (scipy's PPoly layout).
        self.c = np.stack([t / h, (m - s[:-1]) / h - t, s[:-1], y[:-1]])
        # interval lookup: searchsorted over the interior knots gives the interval index
        # directly, the end intervals continued outside; one gather per evaluation
        self._inner = x[1:-1]
        self._rows = np.ascontiguousarray(self.c.T)
        # equally spaced knots (the tables in ln d~): the interval index by arithmetic
        # instead of a binary search (a knot itself may land in either neighbour, whose
        # polynomials agree there to rounding)
        self._uniform = bool(n > 2 and np.all(np.abs(h - h.mean()) <= 1e-12 * h.mean()))
        self._h = float(h.mean())

    def _interval(self, xq):
        if self._uniform:
            # truncation towards zero, then clamped at 0: the floor, clamped, for any
            # value (in place by minimum and maximum: np.clip's Python layers cost
            # more than the pass itself on a block)
            i = np.asarray((xq - self.x[0]) * (1.0 / self._h)).astype(np.intp)
            np.minimum(i, self.x.size - 2, out=i)
            return np.maximum(i, 0, out=i)
        return np.searchsorted(self._inner, xq, side="right")

    def _horner(self, i, t):
        """((c0 t + c1) t + c2) t + c3 on the intervals i, in place (the same
        operations in the same order as the plain expression)."""
        c = self.c
        r = np.asarray(c[0].take(i))
        r *= t
        r += c[1].take(i)
        r *= t
        r += c[2].take(i)
        r *= t
        r += c[3].take(i)
        return r

    def __call__(self, xq, nu=0):
        """Value (nu = 0) or derivative of order nu = 1, 2 of the spline at xq."""
        xq = np.asarray(xq, dtype=float)
        i = self._interval(xq)
        t = xq - self.x[i]
        if nu == 0:
            return self._horner(i, t)
        c0, c1, c2 = (self.c[k][i] for k in range(3))
        if nu == 1:
            return (3 * c0 * t + 2 * c1) * t + c2
        if nu == 2:
            return 6 * c0 * t + 2 * c1
        raise ValueError(f"derivative order nu = {nu!r}: 0, 1 or 2")

    def solve(self, yq, rtol=1e-13):
        """x with s(x) = yq on [x_0, x_{n-1}], for a spline increasing there.

        One interval lookup over the knot values, then Newton's method on that
        interval's cubic alone (its coefficients gathered once; a step is one Horner
        pass, no new lookup), started from the chord and kept inside the interval. The
        cubic is monotone on its interval, so the iteration converges in a few steps
        to rounding (steps <= rtol times the interval).

        Parameters
        ----------
        yq : array_like
            Values between s(x_0) and s(x_{n-1}) [unit of y]; outside, the end knot.

        Returns
        -------
        ndarray
            x [unit of x], same shape as yq.
        """
        yq = np.asarray(yq, dtype=float)
        if not hasattr(self, "_yk"):
            self._yk = np.append(self.c[3], self(self.x[-1]))
            if np.any(np.diff(self._yk) <= 0):
                raise ValueError("spline inverse: the knot values are not increasing")
        yk = self._yk
        i = np.clip(np.searchsorted(yk, yq, side="right") - 1, 0, yk.size - 2)
        c0, c1, c2, c3 = (self.c[k][i] for k in range(4))
        h = self.x[i + 1] - self.x[i]
        target = yq - c3
        t = np.clip(target / (yk[i + 1] - yk[i]), 0.0, 1.0) * h
        for _ in range(30):
            f = ((c0 * t + c1) * t + c2) * t - target
            df = (3 * c0 * t + 2 * c1) * t + c2
            step = f / df
            t = np.clip(t - step, 0.0, h)
            if np.all(np.abs(step) <= rtol * h):
                break
        return self.x[i] + t

    def inverse_table(self, nodes=4097):
        """A fast inverse of an increasing spline: the not-a-knot spline of x against
        y on `nodes` equally spaced values of y (each solved by :meth:`solve`), to be
        evaluated with :meth:`solve_fast`."""
        y = np.linspace(self._yk[0] if hasattr(self, "_yk") else float(self(self.x[0])),
                        float(self(self.x[-1])), nodes)
        self.solve(y[:1])          # builds the knot values
        y[0], y[-1] = self._yk[0], self._yk[-1]
        return NotAKnotSpline(y, self.solve(y))

    def solve_fast(self, yq, table):
        """x with s(x) = yq: the inverse table's cubic (an arithmetic lookup on its equal
        spacing), then one Newton step on this spline (also an arithmetic lookup when
        its knots are equally spaced). The table's own error (about 1e-10 in x for
        the universal curve's 4097 nodes) is squared by the Newton step, to rounding.

        The step's derivative dx/ds is the inverse table's own slope at yq (its
        coefficients are gathered for the value anyway): its relative error, about
        1e-7, multiplies the step of about 1e-10 (tests/test_universal.py holds the
        result to the whole-spline Newton iteration)."""
        shape = np.shape(yq)
        yq = np.asarray(yq, dtype=float).ravel()
        j = table._interval(yq)
        tc = table.c
        u = yq - table.x.take(j)
        c0, c1, c2 = tc[0].take(j), tc[1].take(j), tc[2].take(j)
        x = c0 * u
        x += c1
        c1 *= 2.0
        slope = c0
        slope *= 3.0
        slope *= u
        slope += c1                         # 3 c0 u + 2 c1
        x *= u
        x += c2
        x *= u
        x += tc[3].take(j)
        slope *= u
        slope += c2                         # dx/dy = (3 c0 u + 2 c1) u + c2
        # (an estimate a rounding outside [x_0, x_{n-1}] takes the end interval's cubic)
        i = self._interval(x)
        f = self._horner(i, x - self.x.take(i))
        f -= yq
        f *= slope
        np.subtract(x, f, out=x)
        np.maximum(x, self.x[0], out=x)
        return np.minimum(x, self.x[-1], out=x).reshape(shape)


class UniformHermite:
    r"""Piecewise cubic Hermite interpolant on n equally spaced nodes of [0, 1].

    On the cell :math:`[s_i, s_{i+1}]`, :math:`s_i = i h`, :math:`h = 1/(n-1)`, with
    :math:`t = s/h - i` in [0, 1], the cubic through the values :math:`y_i, y_{i+1}`
    with the slopes :math:`m_i, m_{i+1}` (dy/ds):

    .. math::

        p(t) = y_i + h m_i t + (3\Delta_i - 2 h m_i - h m_{i+1}) t^2
               + (h m_i + h m_{i+1} - 2\Delta_i) t^3, \qquad \Delta_i = y_{i+1} - y_i.

    Its error is :math:`h^4 \max|y^{(4)}|/384` for a smooth y with exact slopes (de Boor
    1978, ch. II); a cell over which y is not smooth (a kink) is not covered by that
    bound, and callers mark such cells (:meth:`cells`). The cell is found by arithmetic
    on the equal spacing (no search), the four coefficients by one gather of a row.

    Parameters
    ----------
    values : array_like
        y at the n >= 2 nodes [any unit].
    slopes : array_like
        dy/ds at the nodes [unit of y].
    end_slopes : array_like, optional
        dy/ds approaching each node from below, used at the upper end of each cell
        (default `slopes`): for a variable s with a corner at a node (a table joined
        from pieces, each graded towards its own start) [unit of y].

    Notes
    -----
    Valid for 0 <= s <= 1; outside, the end cells' cubics are continued (callers
    check their range first).

    Examples
    --------
    A cubic is reproduced exactly:

    >>> s = np.linspace(0.0, 1.0, 5)
    >>> p = UniformHermite(s ** 3, 3 * s ** 2)
    >>> round(float(p(np.array([0.3]))[0]), 15)
    0.027

    References
    ----------
    C. de Boor, A Practical Guide to Splines, Springer (1978), ch. II (cubic Hermite
    interpolation and its error).
    """

    def __init__(self, values, slopes, end_slopes=None):
        y = np.asarray(values, dtype=float)
        m = np.asarray(slopes, dtype=float)
        me = m if end_slopes is None else np.asarray(end_slopes, dtype=float)
        if y.ndim != 1 or y.shape != m.shape or y.shape != me.shape or y.size < 2:
            raise ValueError("UniformHermite: values and slopes 1-D, same length >= 2")
        self.n = y.size
        h = 1.0 / (self.n - 1)
        dy = np.diff(y)
        m0, m1 = h * m[:-1], h * me[1:]
        # the (t^3, t^2, t, 1) coefficients of each cell, one contiguous array each (four
        # gathers by np.take are faster than one gather of rows and strided columns)
        self._c = tuple(np.ascontiguousarray(c) for c in
                        (m0 + m1 - 2 * dy, 3 * dy - 2 * m0 - m1, m0, y[:-1]))

    def cells(self, s):
        """Cell index of each s in [0, 1] (the last node belongs to the last cell)."""
        x = np.asarray(s, dtype=float) * (self.n - 1)
        return np.minimum(x.astype(np.intp), self.n - 2)

    def __call__(self, s):
        """p(s) for s in [0, 1] (an array)."""
        return self.evaluate(s)[0]

    def evaluate(self, s):
        """(p(s), cell index of each s) for s in [0, 1] (an array), Horner in place."""
        x = np.asarray(s, dtype=float) * (self.n - 1)
        i = x.astype(np.intp)
        np.minimum(i, self.n - 2, out=i)
        x -= i                               # t in [0, 1]
        c3, c2, c1, c0 = self._c
        r = c3.take(i)
        r *= x
        r += c2.take(i)
        r *= x
        r += c1.take(i)
        r *= x
        r += c0.take(i)
        return r, i


def _slopes_not_a_knot(x, h, m):
    """Knot slopes of the not-a-knot spline (n >= 4): a tridiagonal system (the
    not-a-knot rows couple only s_0, s_1 and s_{n-2}, s_{n-1}, as scipy's banded
    system does), solved by Gaussian elimination without pivoting in O(n).

    Elimination runs in Python floats: for the tables' 15-130 knots it takes well under
    a millisecond, where a first LAPACK call (numpy.linalg) costs 40 ms of start-up.
    The interior rows are diagonally dominant; the first row is not (|h_1| < x_2 - x_0),
    but eliminating it against the dominant second row is stable (the multiplier
    h_1 / h_1 = 1 is bounded); tests/test_lipopov.py checks against scipy to 1e-12.
    """
    n = x.size
    h, m = h.tolist(), m.tolist()
    lower, diag, upper, rhs = [0.0] * n, [0.0] * n, [0.0] * n, [0.0] * n
    for i in range(1, n - 1):
        lower[i], diag[i], upper[i] = h[i], 2 * (h[i - 1] + h[i]), h[i - 1]
        rhs[i] = 3 * (h[i] * m[i - 1] + h[i - 1] * m[i])
    d = float(x[2] - x[0])
    diag[0], upper[0] = h[1], d
    rhs[0] = ((h[0] + 2 * d) * h[1] * m[0] + h[0] ** 2 * m[1]) / d
    d = float(x[-1] - x[-3])
    lower[-1], diag[-1] = d, h[-2]
    rhs[-1] = (h[-1] ** 2 * m[-2] + (2 * d + h[-1]) * h[-2] * m[-1]) / d
    for i in range(1, n):                      # forward elimination
        w = lower[i] / diag[i - 1]
        diag[i] -= w * upper[i - 1]
        rhs[i] -= w * rhs[i - 1]
    s = [0.0] * n
    s[-1] = rhs[-1] / diag[-1]
    for i in range(n - 2, -1, -1):             # back substitution
        s[i] = (rhs[i] - upper[i] * s[i + 1]) / diag[i]
    return np.array(s)


# coefficients of u - ln(1 + u) = sum_{k>=2} (-1)^k u^k / k, for |u| <= 0.3: terms up
# to k = 40 leave a relative remainder below 2 * 0.3^39 / 41 ~ 2e-22
_SERIES = np.array([(-1.0) ** k / k for k in range(40, 1, -1)])
_SERIES_LIST = _SERIES.tolist()


def _excess(u):
    """u - ln(1 + u) without cancellation for small u (series for |u| <= 0.3)."""
    small = np.abs(u) <= 0.3
    if not small.any():
        return u - np.log1p(u)
    us = np.where(small, u, 0.0)
    acc = np.zeros_like(us)
    for coef in _SERIES:
        acc = acc * us + coef
    series = acc * us * us
    with np.errstate(invalid="ignore", divide="ignore"):
        direct = u - np.log1p(u)
    return np.where(small, series, direct)


def log1p_excess_root(t, *, checked=True):
    r"""The root u >= 0 of :math:`u - \ln(1 + u) = t`, for t >= 0.

    .. math:: u = -1 - W_{-1}\left(-e^{-1-t}\right)

    the quantity the Li-Popov closed forms need with :math:`t = -\ln D` (Li & Popov
    2017, Eq. 7 at the contact radius: :math:`(u + 1)e^{-u} = D`). Solved by two
    Halley steps (an array, in blocks of :data:`BLOCK` elements) or Newton's method (one
    number) from the series :math:`u = s + s^2/3 + s^3/36 - s^4/270 + s^5/4320`,
    :math:`s = \sqrt{2t}` (small t; Temme 1996) or the fixed point
    :math:`u = t + \ln(1 + u)` (large t), to rounding (relative error about 1e-16).

    Parameters
    ----------
    t : float or array_like
        0 <= t < inf [-]; t = 0 gives u = 0.
    checked : bool, optional
        False skips the range check of t, for callers whose t lies in the range by
        construction (default True).

    Returns
    -------
    ndarray
        u >= 0 [-].

    Notes
    -----
    Valid for 0 <= t <= 1.7e308. Working in t keeps full relative accuracy in u near
    u = 0 (D -> 1), where :math:`W_{-1}` as a function of its argument is
    ill-conditioned.

    Examples
    --------
    >>> u = float(log1p_excess_root(1.0))
    >>> round(u, 12), abs(u - math.log1p(u) - 1.0) < 1e-15
    (2.146193220621, True)

    References
    ----------
    N. M. Temme, Special Functions, Wiley (1996), section 11.2.3.
    """
    t = np.asarray(t, dtype=float)
    if checked and (np.any(~(t >= 0)) or np.any(np.isinf(t))):
        raise ValueError("log1p_excess_root: t must be finite and >= 0")
    if t.size == 0:
        return t.copy()
    if t.ndim == 0:      # the same steps as an array element, so both agree exactly
        return np.asarray(_root_block(t.reshape(1))[0])
    return blockwise(_root_block, t)


#: Elements per block of :func:`blockwise`: 16384 float64 (128 kB) keep a dozen
#: temporaries of an elementwise chain in the CPU's L2 cache, where whole-array
#: temporaries of 1e6 elements each go through main memory (measured: the same
#: operations 2-3 times faster in blocks, docs/history.md, "Model evaluation").
BLOCK = 16384


def blockwise(fun, x, block=BLOCK):
    """fun(x) for an elementwise fun, applied to contiguous blocks of x.

    Parameters
    ----------
    fun : callable
        Elementwise function of one float array, returning a float array of the same
        shape [-].
    x : array_like
        Argument, any shape [any unit].
    block : int, optional
        Elements per block [-].

    Returns
    -------
    ndarray
        fun(x), same shape as x.

    Notes
    -----
    Valid for elementwise functions only: fun must not couple elements (each block is
    computed on its own). Small arrays are passed whole.

    Examples
    --------
    >>> float(blockwise(np.sqrt, np.full(40000, 4.0), block=1000).sum())
    80000.0

    References
    ----------
    NumPy User Guide, "Copies and views" (contiguous slices are views, no copy).
    """
    x = np.asarray(x, dtype=float)
    if x.size <= block:
        return fun(x)
    flat = x.ravel()
    res = np.empty(flat.size)
    for i in range(0, flat.size, block):
        res[i:i + block] = fun(flat[i:i + block])
    return res.reshape(x.shape)


def _excess_series(u):
    """u - ln(1 + u) by its series (|u| <= ~0.3), Horner in place."""
    acc = np.full(u.shape, _SERIES_LIST[0])
    for coef in _SERIES_LIST[1:]:
        acc *= u
        acc += coef
    acc *= u
    acc *= u
    return acc


def _halley(u, t, series):
    """Two Halley steps on h(u) = u - ln(1 + u) - t, in place on u.

    With h' = u/(1 + u) and h''/h'^2 = 1/u^2 the step is
    n / (1 - h/(2 u^2)), n = h (1 + u)/u the Newton step. The relative error obeys
    e' ~ e^3, so starts within 2.4e-2 (the starts of :func:`_root_block`) reach
    rounding in two steps.
    """
    h = np.empty_like(u)
    w = np.empty_like(u)
    for _ in range(2):
        if series:
            h[...] = _excess_series(u)
        else:
            np.log1p(u, out=h)
            np.subtract(u, h, out=h)
        h -= t
        np.divide(h, u, out=w)          # h/u
        np.add(u, 1.0, out=h)
        h *= w                          # Newton step h (1 + u)/u
        w *= -0.5
        w /= u
        w += 1.0                        # 1 - h/(2 u^2)
        h /= w
        u -= h
    return u


def _halley_large(u, t):
    """:func:`_halley` for t >= 2 (u >= 3), with fewer passes: ln(1 + u) by log of the
    rounded 1 + u (its relative rounding, <= 1.1e-16, moves h by as much absolutely,
    the root by 1.4e-16 absolutely, under u's own rounding of 4.4e-16), and one
    reciprocal 1/u in place of two divisions by u."""
    h = np.empty_like(u)
    w = np.empty_like(u)
    r = np.empty_like(u)
    for _ in range(2):
        np.add(u, 1.0, out=w)
        np.log(w, out=h)
        np.subtract(u, h, out=h)
        h -= t
        np.divide(1.0, u, out=r)
        h *= r                          # h/u
        w *= h                          # Newton step h (1 + u)/u
        h *= r
        h *= -0.5
        h += 1.0                        # 1 - h/(2 u^2)
        w /= h
        u -= w
    return u


def _root_block(t):
    """:func:`log1p_excess_root` of one block (t >= 0, finite), Halley from a start
    within 2.4e-2 relative: the series in s = sqrt(2t) (Temme 1996) for t < 2, the
    fixed point u = t + ln(1 + u) iterated three times from u = t above (by log of the
    rounded 1 + u, exact to 1.1e-16 absolutely there)."""
    lo = float(t.min()) if t.size else 0.0
    if lo >= 2.0:                                  # the common case: one branch
        u = np.empty_like(t)
        np.add(t, 1.0, out=u)
        for k in range(3):
            np.log(u, out=u)
            u += t
            if k < 2:
                u += 1.0
        return _halley_large(u, t)
    # NaN where no branch applies (t < 0 or NaN, reachable only unchecked): no root
    u = np.full_like(t, np.nan)
    for kind, sel in ((0, (t > 0) & (t < 0.04)), (1, (t >= 0.04) & (t < 2.0)),
                      (2, t >= 2.0)):
        if not sel.any():
            continue
        ts = t[sel]
        if kind < 2:
            s = np.sqrt(2 * ts)
            us = s * (1 + s * (1 / 3 + s * (1 / 36 + s * (-1 / 270 + s / 4320))))
            u[sel] = _halley(us, ts, kind == 0)
        else:
            us = ts + np.log(1.0 + ts + np.log(1.0 + ts + np.log(1.0 + ts)))
            u[sel] = _halley_large(us, ts)
    u[t == 0] = 0.0
    return u


def _series_start(t):
    """Starting guess of u from t: the inverse series (t < 1) or the fixed point."""
    if t < 1.0:
        s = math.sqrt(2 * t)
        return s * (1 + s * (1 / 3 + s * (1 / 36 + s * (-1 / 270 + s / 4320))))
    return t + math.log1p(t + math.log1p(t + math.log1p(t)))


def _excess_scalar(u):
    """:func:`_excess` for one Python float."""
    if abs(u) > 0.3:
        return u - math.log1p(u)
    acc = 0.0
    for coef in _SERIES_LIST:
        acc = acc * u + coef
    return acc * u * u


def _root_scalar(t):
    """The reference root for one number, in Python floats: Newton's method from the
    same starts, iterated until the step is below 1e-9 relative, plus one step (the
    algorithm :func:`log1p_excess_root` used before its blockwise Halley steps; the
    tests hold the two equal to rounding)."""
    if t == 0.0:
        return 0.0
    u = _series_start(t)
    for _ in range(40):
        step = (_excess_scalar(u) - t) * (1 + u) / u
        u -= step
        if abs(step) <= 1e-9 * u:
            return u - (_excess_scalar(u) - t) * (1 + u) / u
    raise RuntimeError("log1p_excess_root: Newton iteration did not converge")


def lambertw_m1(x):
    r"""Lower real branch :math:`W_{-1}(x)` of the Lambert W function, -1/e <= x < 0.

    .. math:: W e^{W} = x, \qquad W \le -1

    Computed as :math:`-1 - u` with u from :func:`log1p_excess_root` at
    :math:`t = -1 - \ln(-x)`.

    Parameters
    ----------
    x : float or array_like
        -1/e <= x < 0 [-] (values within rounding of -1/e count as -1/e).

    Returns
    -------
    ndarray
        :math:`W_{-1}(x) \le -1` [-].

    Notes
    -----
    Valid for -1/e <= x < 0; outside it raises ValueError. Agrees with
    ``scipy.special.lambertw(x, -1).real`` to 1e-12 relative for x <= -(1 - 1e-6)/e
    (tests/test_lipopov.py); closer to the branch point the rounding of x alone moves W
    by eps/|1 + W| relative, and below 1/e - x ~ 2e-9 scipy's residual
    :math:`W e^W - x` grows to 1e-9 while this one stays at rounding.

    Examples
    --------
    >>> w = float(lambertw_m1(-0.1))
    >>> round(w, 12), abs(w * math.exp(w) + 0.1) < 1e-16
    (-3.577152063957, True)

    References
    ----------
    R. M. Corless et al., "On the Lambert W function", Adv. Comput. Math. 5 (1996)
    329-359.
    """
    x = np.asarray(x, dtype=float)
    if np.any(~((x >= -1 / math.e * (1 + 1e-15)) & (x < 0))):
        raise ValueError("lambertw_m1: x must lie in [-1/e, 0)")
    t = np.maximum(-1.0 - np.log(-x), 0.0)
    return -1.0 - log1p_excess_root(t)


class _SerialBlas:
    """One BLAS thread while a solver of small dense systems runs (process-wide,
    re-entrant; restored when the outermost call returns).

    A multithreaded BLAS (OpenBLAS, MKL) splits even a 200 x 200 LU solve across its
    threads; on a machine whose cores are busy with other work each solve then waits for
    a thread to be scheduled, and a profiled-roller solve (tens of such solves) cost
    17 times the CPU time it takes with one thread on the 2-core development machine at
    a load of 6 (tools/benchmarks/results/serial_blas.txt). The limit comes from threadpoolctl (a dependency); where it is not
    installed this is a no-op. The controller is built on first use (about 20 ms, once
    per process); entering costs about 30 us, and about 1 us where BLAS runs one thread
    at the time (decided at each outermost entry).
    """

    def __init__(self):
        self._lock = threading.Lock()
        self._depth = 0
        self._limiter = None
        self._controller = None        # False: threadpoolctl missing

    def _blas(self):
        if self._controller is None:
            try:
                from threadpoolctl import ThreadpoolController
            except ImportError:
                self._controller = False
            else:
                self._controller = ThreadpoolController().select(user_api="blas")
        return self._controller

    def __enter__(self):
        with self._lock:
            if self._depth == 0:
                # whether BLAS runs several threads now (about 1 us a library): a
                # caller's limit in force at the first use must not decide for later
                ctl = self._blas()
                many = ctl and any(lib.num_threads > 1 for lib in ctl.lib_controllers)
                self._limiter = ctl.limit(limits=1) if many else None
            self._depth += 1
        return self

    def __exit__(self, *exc):
        with self._lock:
            self._depth -= 1
            if self._depth == 0 and self._limiter is not None:
                self._limiter.restore_original_limits()
                self._limiter = None
        return False


_SERIAL_BLAS = _SerialBlas()


def serial_blas(fn):
    """Decorator: run `fn` with one BLAS thread (:class:`_SerialBlas`), for the solvers
    whose work is many small dense solves (the coupled slices of a roller, a bearing's
    rollers)."""
    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with _SERIAL_BLAS:
            return fn(*args, **kwargs)
    return wrapper


#: The most a module-wide cache of n x n slice geometry holds before it is emptied
#: (linecontact.roller: one geometry is several n x n arrays; at the largest n = 4000
#: three of them take 384 MB, so only the newest is kept then).
CACHE_BYTES = 2**28


def cache_nbytes(cache):
    """Bytes of the arrays held in a dict cache's values (arrays or tuples of them)."""
    total = 0
    for v in list(cache.values()):
        for a in (v if isinstance(v, tuple) else (v,)):
            total += getattr(a, "nbytes", 0)
    return total
