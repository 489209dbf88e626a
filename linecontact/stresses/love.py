r"""Love's uniformly loaded rectangle: its stresses as sums over its four corners.

Below a uniform pressure on a rectangle every derivative of Boussinesq's potentials
is a signed sum over the rectangle's corners of an elementary function of the
offsets from the corner (Love 1929; :func:`rectangle_stresses`). The 3D correction of
the roller stresses (:mod:`linecontact.stresses.search`) sums these corner functions
over many rectangles at once: in numpy (:func:`_love_batches`, the reference) or in
the optional C extension (``linecontact._cstresses.c`` in ``linecontact._ckernels``:
the same arithmetic, loaded here; numpy where it is not built or stale).

References
----------
.. [1] A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on
   part of the boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
"""
from __future__ import annotations

import numpy as np

from .._engine import ckernels, resolve_engine
from ..checks import check_interval, check_positive
from ..errors import OutOfRangeError

__all__ = ["rectangle_stresses"]

#: the corner function of d2 psi1/dydz, the only one the orthogonal shear needs
_PYZ = 6


def _pyz_factor(X, Y, z):
    """1/(rho (Y^2 + z^2)) at every point and corner, rho = sqrt(X^2 + Y^2 + z^2): the
    factor of d2 psi1/dydz's corner sum alone (`only` = _PYZ in :func:`_love_corner`
    and :func:`_love_batches`; X, Y, z broadcast as there)."""
    z2 = z * z
    Y2 = Y * Y
    t = Y2 + z2
    rho = X * X + Y2
    rho += z2
    np.sqrt(rho, out=rho)
    t *= rho
    np.divide(1.0, t, out=t)
    return t


def _love_corner(X, Y, z, w=None, only=None):
    """The corner functions of Love's uniformly loaded rectangle at offsets (X, Y) from
    one corner, depth z > 0 (see :func:`rectangle_stresses`), stacked (10, ...).

    With corner weights `w` (n_corners,): their weighted sums over the
    corners instead, (10, ...); with `only` (an index) just that function's sum, the
    others left 0. The sums take the shortcuts of :func:`_love_weighted` where X is
    one row (1, n_corners) and z one column (n_points, 1), as the 3D correction's."""
    if (w is not None and np.ndim(X) == 2 and np.shape(X)[0] == 1
            and np.ndim(z) == 2 and np.shape(z)[1] == 1 and only in (None, _PYZ)):
        if only is None:
            return _love_weighted(X, Y, z, w)
        # d2 psi1/dydz alone: -z sum_c (X_c w_c)/(rho (Y^2 + z^2))
        out = np.zeros((10, Y.shape[0]))
        out[_PYZ] = -z[:, 0] * (_pyz_factor(X, Y, z) @ (X[0] * w))
        return out
    X2, Y2, z2 = X * X, Y * Y, z * z
    rho = np.sqrt(X2 + Y2 + z2)

    def h(den):
        # arctan(XY (rho - z)/den); den = 0 only where X = Y = 0, where XY = 0: the
        # limit 0 (the same as masking it)
        XY = X * Y
        return np.arctan(XY * (rho - z) / (den + (den == 0)))

    funcs = (lambda: -np.arctan(X * Y / (z * rho)),                           # d psi1/dz
             lambda: X * Y * (rho * rho + z2) / (rho * (X2 + z2) * (Y2 + z2)),  # d2 psi1/dz2
             lambda: -X * Y / (rho * (X2 + z2)),                               # d2 psi1/dx2
             lambda: -X * Y / (rho * (Y2 + z2)),                               # d2 psi1/dy2
             lambda: 1.0 / rho,                                                # d2 psi1/dxdy
             lambda: -Y * z / (rho * (X2 + z2)),                               # d2 psi1/dxdz
             lambda: -X * z / (rho * (Y2 + z2)),                               # d2 psi1/dydz
             lambda: h(X2 * rho + Y2 * z),                                     # d2 H1/dx2
             lambda: h(Y2 * rho + X2 * z),                                     # d2 H1/dy2
             lambda: np.log(rho + z))                                          # d2 H1/dxdy
    if w is None:
        return np.stack([np.broadcast_to(f(), rho.shape) for f in funcs])
    out = np.zeros((len(funcs),) + rho.shape[:-1])
    if only is not None:
        g = funcs[only]()
        out[only] = (g if g.shape == rho.shape else np.broadcast_to(g, rho.shape)) @ w
        return out
    return np.stack([np.broadcast_to(f(), rho.shape) for f in funcs]) @ w


def _love_weighted(X, Y, z, w):
    """The weighted corner sums sum_c w_c g(X_c, Y_pc, z_p) of all ten corner
    functions (:func:`_love_corner`) at the points p: X (1, n_corners), Y (n_points,
    n_corners), z (n_points, 1), w (n_corners,) -> (10, n_points); or with a leading
    axis of batches on each (X (n, 1, c), Y (n, p, c), z (n, p, 1), w (n, c)), each
    batch its own corners and weights -> (10, n, p).

    The functions with the reciprocals shared; two of them are not evaluated: as
    psi1 and H1 are harmonic (z > 0) and so is each corner function's potential,
    d2 psi1/dz2 = -(d2 psi1/dx2 + d2 psi1/dy2) and, as dH1/dz = psi1,
    d2 H1/dy2 = -(d psi1/dz + d2 H1/dx2) (both hold per corner to rounding). d2H1/dx2
    = arctan(XY (rho - z)/(X^2 rho + Y^2 z)) is taken as arctan(XY/(X^2 + z^2 +
    z rho)), its numerator and denominator times (rho + z) over X^2 + Y^2 (the same
    where X^2 + Y^2 > 0, and 0 where X = Y = 0, as the masked form), one division
    and arctan in place of arctan2. X is one row (the points share it): a factor X
    of a function goes into the weights (X w), a factor z (one per point) out of the
    sum, so that Y/(rho (X^2 + z^2)) serves d2 psi1/dx2 and d2 psi1/dxdz, and
    1/(rho (Y^2 + z^2)) d2 psi1/dydz and, times Y, d2 psi1/dy2; the work arrays are
    reused in place."""
    out = np.empty((10,) + Y.shape[:-1])
    X2, z2 = X * X, z * z
    zc = z[..., 0]
    Xw = X[..., 0, :] * w
    if Y.ndim == 2:
        def dot(A, v):
            return A @ v
    else:
        def dot(A, v):
            return np.matmul(A, v[..., None])[..., 0]
    Y2 = Y * Y
    a = X2 + z2                             # X^2 + z^2
    rho = Y2 + a
    np.sqrt(rho, out=rho)
    zr = z * rho                            # z rho
    XY = X * Y
    h = a + zr                              # X^2 + z^2 + z rho
    np.divide(XY, h, out=h)
    out[7] = dot(np.arctan(h, out=h), w)
    np.divide(XY, zr, out=zr)               # XY/(z rho)
    out[0] = -(dot(np.arctan(zr, out=zr), w))
    ir = np.divide(1.0, rho, out=XY)
    np.divide(ir, a, out=a)                 # 1/(rho (X^2 + z^2))
    Y2 += z2
    np.divide(ir, Y2, out=Y2)               # 1/(rho (Y^2 + z^2))
    out[4] = dot(ir, w)
    out[6] = -zc * (dot(Y2, Xw))
    Y2 *= Y
    out[3] = -(dot(Y2, Xw))
    a *= Y                                  # Y/(rho (X^2 + z^2))
    out[2] = -(dot(a, Xw))
    out[5] = -zc * (dot(a, w))
    rho += z
    out[9] = dot(np.log(rho, out=rho), w)
    out[1] = -(out[2] + out[3])
    out[8] = -(out[0] + out[7])
    return out


def _love_sums(X, Y, z, w, only=None):
    """The corner sums sum_c w_c g(X_c, Y_pc, z_p) of the corner functions
    (:func:`_love_corner`) at the points p of Y (n_points, n_corners), X (1,
    n_corners), z (n_points, 1): (10, n_points); `only` as there. Evaluated in blocks
    of points of a few thousand elements, which stay in the processor's cache."""
    n, c = Y.shape
    blocks = -(-n * c // _BLOCK)            # blocks of about equal size
    if blocks <= 1:
        return _love_corner(X, Y, z, w, only)
    step = -(-n // blocks)
    return np.concatenate([_love_corner(X, Y[i:i + step], z[i:i + step], w, only)
                           for i in range(0, n, step)], axis=1)


def _love_batches(items, only=None):
    """:func:`_love_sums` of several (X, Y, z, w) at once: their corners and points
    padded to the largest (offsets 0, weight 0; depth 1), one evaluation with a
    leading batch axis (in groups of about _BLOCK elements) in place of one per
    item; a list of (10, n_points) per item."""
    if len(items) == 1:
        return [_love_sums(*items[0], only)]
    ps = [it[1].shape[0] for it in items]
    if len(set(ps)) > 1:
        # one padded evaluation per number of points
        out = [None] * len(items)
        for p in sorted(set(ps)):
            at = [i for i in range(len(items)) if ps[i] == p]
            for i, t in zip(at, _love_batches([items[i] for i in at], only)):
                out[i] = t
        return out
    cs = [it[3].size for it in items]
    C, P = max(cs), max(ps)
    per = max(_BLOCK // (P * C), 1)
    out = []
    for g0 in range(0, len(items), per):
        grp = items[g0:g0 + per]
        n = len(grp)
        X = np.zeros((n, 1, C))
        Y = np.zeros((n, P, C))
        z = np.ones((n, P, 1))
        w = np.zeros((n, C))
        for i, (Xi, Yi, zi, wi) in enumerate(grp):
            c, p = wi.size, Yi.shape[0]
            X[i, 0, :c] = Xi[0]
            Y[i, :p, :c] = Yi
            z[i, :p] = zi
            w[i, :c] = wi
        if only is None:
            t = _love_weighted(X, Y, z, w)
        else:
            # d2 psi1/dydz alone (as _love_corner's)
            t = np.zeros((10, n, P))
            t[_PYZ] = -z[..., 0] * np.matmul(_pyz_factor(X, Y, z),
                                             (X[:, 0, :] * w)[..., None])[..., 0]
        out += [t[:, i, :Yi.shape[0]] for i, (_, Yi, _, _) in enumerate(grp)]
    return out


#: elements (points x corners) per block of :func:`_love_sums`
_BLOCK = 16384


# the corner sums in C (linecontact/_cstresses.c, in the extension linecontact._ckernels),
# built at install where a C compiler exists; numpy where it is not (or is stale)
_cstresses = ckernels()
#: which evaluates the 3D correction's corner sums: "c" (the extension, where it runs)
#: or "numpy" (the reference, :func:`_love_batches`), as engine "auto" chooses; a list,
#: so that a test can switch it
_CORNERS = [resolve_engine("auto")]


def _corners_c(xe, L, b, p0, q, k0, i0, i1, ye, means):
    """:func:`_corners_assemble` by the C extension (the same arithmetic, the corners
    in the same order), or None where it returns -1 (an input not finite, the grid
    not increasing) and numpy is to build them."""
    f = np.ascontiguousarray
    room = (b.size + 3) * ye.size + 4 * (b.size + 2)
    cx, cy, w = np.empty(room), np.empty(room), np.empty(room)
    k = _cstresses.corners(f(xe, dtype=float), float(L), f(b, dtype=float),
                           f(p0, dtype=float), f(q, dtype=float), int(k0), int(i0),
                           int(i1), f(ye, dtype=float), f(means, dtype=float), cx, cy, w)
    if k < 0:
        return None
    return cx[:k], cy[:k], w[:k]


def _love_c(X, cy, w, py, pz, only=None):
    """The corner sums of :func:`_love_weighted` (`only`: d2 psi1/dydz's alone, as
    :func:`_love_corner`'s) by the C extension, at the points (py, pz) for the corners
    at X (1, n) along the roller and cy (n,) across with weights w (n,): (10, len(py)),
    or None where the extension returns False (an input not finite, a depth outside
    (1e-60, 1e60) m or an offset not below 1e60 m) and numpy is to take them."""
    if only not in (None, _PYZ):
        return None
    f = np.ascontiguousarray
    py, pz = f(py, dtype=float), f(pz, dtype=float)
    out = np.empty((10, py.size))
    if _cstresses.love_sums(f(X[0], dtype=float), f(cy, dtype=float),
                            f(w, dtype=float), py, pz, only is not None, out):
        return out
    return None


def _love_components(t, z, nu):
    """The six stress components from the corner sums t (9, ...) at depth z."""
    k = 1.0 / (2.0 * np.pi)
    pz, pzz, pxx, pyy, pxy, pxz, pyz, hxx, hyy, hxy = t
    return (k * (2 * nu * pz - z * pxx - (1 - 2 * nu) * hxx),
            k * (2 * nu * pz - z * pyy - (1 - 2 * nu) * hyy),
            k * (pz - z * pzz),
            -k * ((1 - 2 * nu) * hxy + z * pxy),
            -k * z * pxz,
            -k * z * pyz)


def rectangle_stresses(x, y, z, dx, dy, poisson=0.3):
    r"""Stresses below a uniform unit pressure on a dx-by-dy rectangle (Love 1929).

    With Boussinesq's potentials :math:`H_1 = \int p\ln(\rho + z)\,dA` and
    :math:`\psi_1 = \int p/\rho\,dA` (Johnson 1985, Eqs. 3.18-3.19)

    .. math::

        \sigma_x = \frac{1}{2\pi}\left[2\nu\frac{\partial\psi_1}{\partial z}
        - z\frac{\partial^2\psi_1}{\partial x^2}
        - (1 - 2\nu)\frac{\partial^2 H_1}{\partial x^2}\right],\quad
        \sigma_z = \frac{1}{2\pi}\left[\frac{\partial\psi_1}{\partial z}
        - z\frac{\partial^2\psi_1}{\partial z^2}\right], \dots

    and for the rectangle every derivative is a signed sum over its four corners of an
    elementary function of the offsets X, Y from the corner and
    :math:`\rho = \sqrt{X^2 + Y^2 + z^2}` (docs/stresses.md lists the nine).

    Parameters
    ----------
    x, y : array_like
        Field point relative to the rectangle's centre [m].
    z : float or array_like
        Depth, z > 0 [m].
    dx, dy : float
        Rectangle sides [m].
    poisson : float, optional
        Poisson's ratio, 0 <= nu <= 0.5 [-].

    Returns
    -------
    dict
        sigma_x, sigma_y, sigma_z, tau_xy, tau_xz, tau_yz per unit pressure [-]
        (compression negative).

    Notes
    -----
    Valid for z > 0 (on the surface the field is singular at the rectangle's edges),
    any dx, dy > 0; linear elasticity of a homogeneous half-space.

    Examples
    --------
    Just below a loaded rectangle sigma_z = -p:

    >>> s = rectangle_stresses(0.0, 0.0, 1e-9, 1.0, 1.0)
    >>> f"{float(s['sigma_z']):.6f}"
    '-1.000000'

    References
    ----------
    A. E. H. Love, Phil. Trans. R. Soc. A 228 (1929) 377-420; K. L. Johnson, Contact
    Mechanics (1985), section 3.2.
    """
    nu = float(check_interval("poisson", poisson, 0.0, 0.5))
    check_positive("dx", dx, "m")
    check_positive("dy", dy, "m")
    x, y, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (x, y, z)))
    if np.any(z <= 0):
        raise OutOfRangeError("z", float(np.min(z)), "(0, inf) m", unit="m",
                              hint="the field is singular on the surface")
    a, b = 0.5 * float(dx), 0.5 * float(dy)
    t = 0.0
    for sx, X in ((1.0, x + a), (-1.0, x - a)):
        for sy, Y in ((1.0, y + b), (-1.0, y - b)):
            t = t + sx * sy * _love_corner(X, Y, z)
    return dict(zip(("sigma_x", "sigma_y", "sigma_z", "tau_xy", "tau_xz", "tau_yz"),
                    _love_components(t, z, nu)))
