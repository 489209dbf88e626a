"""The roller law of a bearing as a table: delta(Q) of one roller on a grid of loads and
its monotone inverse Q(delta), cubic Hermite in (ln Q, ln delta) with the exact slopes
(the package docstring, :mod:`linecontact.bearing`, "How it is solved").
"""
from __future__ import annotations

import numpy as np

from ..errors import OutOfRangeError

__all__ = []


class _Law:
    """delta(Q) of one roller on a grid and its monotone inverse Q(delta)."""

    def __init__(self, Q, delta, k):
        self.lnQ = np.log(Q)
        self.lnd = np.log(delta)
        self.s = k * delta / Q  # d ln Q / d ln delta
        self.Qtop = float(Q[-1])
        self.dtop = float(delta[-1])
        if not np.all(np.diff(self.lnd) > 0):
            raise OutOfRangeError("roller law", "not increasing", "a deflection that "
                                  "grows with the load")

    def delta_of(self, Q):
        """delta(Q) by the Hermite interpolant of ln delta against ln Q."""
        lnQ = np.log(np.asarray(Q, dtype=float))
        return np.exp(self._hermite(lnQ, self.lnQ, self.lnd, 1.0 / self.s)[0])

    def force(self, delta):
        """(Q, dQ/d delta) at ring approaches delta (0 where delta <= 0)."""
        d = np.asarray(delta, dtype=float)
        Q = np.zeros_like(d)
        k = np.zeros_like(d)
        on = d > 0
        if np.any(d[on] > self.dtop * (1 + 1e-12)):
            exc = OutOfRangeError("roller approach", float(d.max()),
                                  f"(0, {self.dtop:.6g}] m (the tabulated roller law)",
                                  unit="m", hint="a roller load beyond the law's range")
            exc.top = self.dtop  # for the bearing's message in its user's words
            raise exc
        if np.any(on):
            v, dv = self._hermite(np.log(d[on]), self.lnd, self.lnQ, self.s)
            Q[on] = np.exp(v)
            k[on] = Q[on] * dv / d[on]
        return Q, k

    @staticmethod
    def _hermite(x, xs, ys, ss):
        """Cubic Hermite interpolation (value, slope); linear extension below xs[0]."""
        i = np.clip(np.searchsorted(xs, x) - 1, 0, len(xs) - 2)
        h = xs[i + 1] - xs[i]
        t = (x - xs[i]) / h
        below = x < xs[0]
        t = np.where(below, 0.0, t)
        h00 = 2 * t**3 - 3 * t**2 + 1
        h10 = t**3 - 2 * t**2 + t
        h01 = -2 * t**3 + 3 * t**2
        h11 = t**3 - t**2
        y = h00 * ys[i] + h10 * h * ss[i] + h01 * ys[i + 1] + h11 * h * ss[i + 1]
        dy = ((6 * t**2 - 6 * t) * ys[i] + (3 * t**2 - 4 * t + 1) * h * ss[i]
              + (-6 * t**2 + 6 * t) * ys[i + 1] + (3 * t**2 - 2 * t) * h * ss[i + 1]) / h
        y = np.where(below, ys[0] + ss[0] * (x - xs[0]), y)
        dy = np.where(below, ss[0], dy)
        return y, dy
