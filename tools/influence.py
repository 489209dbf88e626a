"""Influence coefficients of the elastic half-space for uniform pressure on a rectangle.

Love (1929); Johnson, *Contact Mechanics* (1985), Eq. (3.25). The normal surface
displacement at (x, y) due to a unit pressure on the rectangle |x'| <= a, |y'| <= b is

.. math::

    u_z(x, y) = \\frac{1}{\\pi E^*} \\int_{-a}^{a}\\int_{-b}^{b}
        \\frac{d\\xi\\, d\\eta}{\\sqrt{(x-\\xi)^2 + (y-\\eta)^2}}
      = \\frac{1}{\\pi E^*} \\left[P(x+a, y+b) - P(x+a, y-b) - P(x-a, y+b) + P(x-a, y-b)\\right]

with the primitive :math:`P(X, Y) = X\\,\\mathrm{asinh}(Y/|X|) + Y\\,\\mathrm{asinh}(X/|Y|)`
(and P = 0 on the axes). Johnson prints the same result with logarithms,
X ln(Y + r) + Y ln(X + r); that form loses all digits where Y + r cancels
(Y < 0, |X| << |Y|). ln(Y + r) = asinh(Y/|X|) + ln|X|, and the ln|X| part depends
on X alone, so it drops out of the mixed difference: the asinh form is exact and
has no cancellation inside a term.

E* is the effective modulus, 1/E* = (1 - nu^2)/E for one elastic body (Li & Popov
2017, Eq. 3).
"""
from __future__ import annotations

import numpy as np


def _primitive(X, Y):
    """P(X, Y) with P = 0 where X = 0 or Y = 0 (its limit there)."""
    X = np.asarray(X, dtype=float)
    Y = np.asarray(Y, dtype=float)
    absX = np.abs(X)
    absY = np.abs(Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(absX > 0, X * np.arcsinh(Y / np.where(absX > 0, absX, 1.0)), 0.0)
        t2 = np.where(absY > 0, Y * np.arcsinh(X / np.where(absY > 0, absY, 1.0)), 0.0)
    return t1 + t2


def rectangle_displacement(x, y, dx, dy, estar=1.0):
    """Surface displacement under unit pressure on a dx-by-dy rectangle centred at 0.

    Parameters
    ----------
    x, y : array_like
        Field point relative to the centre of the cell [m].
    dx, dy : float
        Cell sides along x and y [m]; need not be equal.
    estar : float
        Effective modulus E* [Pa].

    Returns
    -------
    ndarray
        Displacement per unit pressure [m/Pa], positive into the body.

    Examples
    --------
    The centre of a square cell of side h: 4 ln(1 + sqrt 2)/pi * h/E*.

    >>> import numpy as np
    >>> float(rectangle_displacement(0.0, 0.0, 1.0, 1.0))  # doctest: +ELLIPSIS
    1.1222...
    >>> float(4 * np.log(1 + np.sqrt(2)) / np.pi)  # doctest: +ELLIPSIS
    1.1222...
    """
    a = 0.5 * dx
    b = 0.5 * dy
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    s = (_primitive(x + a, y + b) - _primitive(x + a, y - b)
         - _primitive(x - a, y + b) + _primitive(x - a, y - b))
    return s / (np.pi * estar)


def kernel_offsets(nx, ny, dx, dy, estar=1.0):
    """Influence coefficients K[i, j] for cell offsets i = 0..nx, j = 0..ny.

    K[i, j] is the displacement at the centre of a cell shifted by (i dx, j dy) from a
    loaded cell, per unit pressure [m/Pa]. The kernel is even in both offsets, so these
    values define it for negative offsets too.
    """
    i = np.arange(nx + 1) * dx
    j = np.arange(ny + 1) * dy
    return rectangle_displacement(i[:, None], j[None, :], dx, dy, estar)
