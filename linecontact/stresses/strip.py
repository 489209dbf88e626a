r"""Plane-strain stresses below a Hertz strip with a sliding traction (McEwen 1949).

A Hertz strip |y| <= b carries the pressure :math:`p(y) = p_0\sqrt{1 - y^2/b^2}` and a
sliding traction :math:`q(y) = \mu\, p(y)` in +y (the rolling direction, acting on the
body below). With depth z >= 0 into the body (McEwen 1949; Johnson 1985, section 4.2
for the pressure, section 7.2 for the traction)

.. math::

    m^2 = \tfrac12\left[\sqrt{(b^2 - y^2 + z^2)^2 + 4y^2z^2} + (b^2 - y^2 + z^2)\right],
    \quad
    n^2 = \tfrac12\left[\sqrt{(b^2 - y^2 + z^2)^2 + 4y^2z^2} - (b^2 - y^2 + z^2)\right],

m, n >= 0 with sign(n) = sign(y), :math:`D = m^2 + n^2`, the pressure gives

.. math::

    \sigma_y = -\frac{p_0}{b}\left[m\left(1 + \frac{z^2 + n^2}{D}\right) - 2z\right],\quad
    \sigma_z = -\frac{p_0}{b}\, m\left(1 - \frac{z^2 + n^2}{D}\right),\quad
    \tau_{yz} = -\frac{p_0}{b}\, n\,\frac{m^2 - z^2}{D},

and the traction (:math:`q_0 = \mu p_0`)

.. math::

    \sigma_y = \frac{q_0}{b}\left[n\left(2 - \frac{z^2 - m^2}{D}\right) - 2y\right],\quad
    \sigma_z = \frac{q_0}{b}\, n\,\frac{z^2 - m^2}{D},\quad
    \tau_{yz} = -\frac{q_0}{b}\left[m\left(1 + \frac{z^2 + n^2}{D}\right) - 2z\right],

and in plane strain :math:`\sigma_x = \nu(\sigma_y + \sigma_z)` (x along the roller).
Compression is negative. Printings of these formulas differ in their signs; every
component and sign here was checked against a direct numerical integration of the
Flamant (normal) and 2D Cerruti (tangential) line-load solutions (Johnson 1985,
Eqs. 2.15 and 2.19) to 1e-13 (tests/test_stresses.py).

References
----------
.. [1] E. McEwen, "Stresses in elastic cylinders in contact along a generatrix",
   Phil. Mag. 40 (1949) 454-459.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..checks import check_interval, check_positive
from .measures import MEASURES

__all__ = ["StripStresses", "strip_stresses", "StripMaxima", "strip_maxima"]

#: friction coefficients covered (beyond 1 the strip is far from Hertz's assumptions)
_MU_MAX = 1.0


def _check_material(friction, poisson):
    mu = float(check_interval("friction", friction, 0.0, _MU_MAX, unit="",
                              hint="mu is the coefficient of the sliding traction mu p "
                                   "in +y; for traction in -y mirror y"))
    nu = float(check_interval("poisson", poisson, 0.0, 0.5))
    return mu, nu


@dataclass(frozen=True)
class StripStresses:
    """Plane-strain stresses at points below a line contact (compression negative).

    Returned by :func:`strip_stresses` and the ``section``/``along_axis`` methods of
    :class:`SubsurfaceStresses`; not built by hand.

    Parameters
    ----------
    sigma_x : ndarray
        Normal stress along the roller axis, nu (sigma_y + sigma_z) [Pa].
    sigma_y : ndarray
        Normal stress across the contact (rolling direction) [Pa].
    sigma_z : ndarray
        Normal stress in depth [Pa].
    tau_yz : ndarray
        Shear stress in the y-z plane [Pa].

    Notes
    -----
    Valid as the strip solution: plane strain, small strains, b << radius.

    Examples
    --------
    >>> s = strip_stresses(0.0, 0.786e-4, 1e-4, 1e9)
    >>> f"{float(s.tresca) / 1e9:.3f} p0"
    '0.300 p0'
    """

    sigma_x: np.ndarray
    sigma_y: np.ndarray
    sigma_z: np.ndarray
    tau_yz: np.ndarray

    def _principal(self):
        c = 0.5 * (self.sigma_y + self.sigma_z)
        r = np.hypot(0.5 * (self.sigma_y - self.sigma_z), self.tau_yz)
        return c + r, c - r, self.sigma_x

    @property
    def tresca(self):
        """Maximum shear stress (sigma_1 - sigma_3)/2 over the three principal ones [Pa]."""
        s1, s2, s3 = self._principal()
        hi = np.maximum(np.maximum(s1, s2), s3)
        lo = np.minimum(np.minimum(s1, s2), s3)
        return 0.5 * (hi - lo)

    @property
    def von_mises(self):
        """Von Mises equivalent stress [Pa]."""
        sx, sy, sz, t = self.sigma_x, self.sigma_y, self.sigma_z, self.tau_yz
        return np.sqrt(np.maximum(sx * sx + sy * sy + sz * sz - sx * sy - sy * sz
                                  - sz * sx + 3.0 * t * t, 0.0))

    @property
    def orthogonal_shear(self):
        """Orthogonal shear stress |tau_yz| [Pa]."""
        return np.abs(self.tau_yz)

    def measure(self, name):
        """One of :data:`MEASURES` by name [Pa]."""
        if name not in MEASURES:
            raise ValueError(f"measure = {name!r} is not one of {MEASURES}")
        return getattr(self, name)

    def to_dict(self):
        """Components and measures as nested lists (JSON) [Pa]."""
        d = {k: np.asarray(getattr(self, k)).tolist()
             for k in ("sigma_x", "sigma_y", "sigma_z", "tau_yz")}
        for k in MEASURES:
            d[k] = np.asarray(self.measure(k)).tolist()
        return d


def _unit_strip(y, z, mu, nu):
    """Components of the unit strip (b = 1, p0 = 1) at (y, z) (broadcast)."""
    y = np.asarray(y, dtype=float)
    z = np.asarray(z, dtype=float)
    A = 1.0 - y * y + z * z
    R = np.sqrt(A * A + 4.0 * y * y * z * z)
    m = np.sqrt(np.maximum(0.5 * (R + A), 0.0))
    n = np.sign(y) * np.sqrt(np.maximum(0.5 * (R - A), 0.0))
    D = m * m + n * n
    # at the contact edges on the surface (|y| = 1, z = 0) m = n = 0: every ratio
    # multiplies m or n there, so any finite value gives the limit 0
    Ds = np.where(D > 0, D, 1.0)
    zz = z * z
    a = (zz + n * n) / Ds
    b = (m * m - zz) / Ds
    sy = -(m * (1.0 + a) - 2.0 * z)
    sz = -m * (1.0 - a)
    t = -n * b
    if mu:
        sy = sy + mu * (n * (2.0 + b) - 2.0 * y)
        sz = sz - mu * n * b
        t = t - mu * (m * (1.0 + a) - 2.0 * z)
    return nu * (sy + sz), sy, sz, t


def strip_stresses(y, z, half_width, peak_pressure, friction=0.0, poisson=0.3):
    r"""Plane-strain stresses below a Hertz strip with a sliding traction (McEwen 1949).

    .. math::

        \sigma_z = -\frac{p_0}{b}\, m\left(1 - \frac{z^2 + n^2}{m^2 + n^2}\right)
        + \frac{\mu p_0}{b}\, n\,\frac{z^2 - m^2}{m^2 + n^2}

    and the other components as in the module docstring.

    Parameters
    ----------
    y : array_like
        Position across the contact, from its centre, in the traction's direction [m].
    z : array_like
        Depth below the surface, z >= 0 [m].
    half_width : array_like
        Contact half-width b [m].
    peak_pressure : array_like
        Peak pressure p0 [Pa].
    friction : float, optional
        Coefficient mu of the traction mu p in +y, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio of the body, 0 <= nu <= 0.5 [-] (only sigma_x depends on it).

    Returns
    -------
    StripStresses
        The four components, broadcast over the inputs [Pa].

    Notes
    -----
    Valid for 0 <= z < inf, 0 < b < inf, 0 <= p0 < inf, plane strain, b << R.

    Examples
    --------
    Centre line, z = 0.786 b: the maximum shear 0.300 p0 (Johnson 1985, Fig. 4.6):

    >>> s = strip_stresses(0.0, 0.786, 1.0, 1.0)
    >>> f"{float(s.sigma_z):.3f} {float(s.sigma_y):.3f} {float(s.tresca):.3f}"
    '-0.786 -0.186 0.300'

    References
    ----------
    E. McEwen, Phil. Mag. 40 (1949) 454-459; K. L. Johnson, Contact Mechanics (1985),
    sections 4.2 and 7.2.
    """
    mu, nu = _check_material(friction, poisson)
    z = check_interval("z", z, 0.0, np.inf, unit="m")
    b = check_positive("half_width", half_width, "m")
    p0 = check_interval("peak_pressure", peak_pressure, 0.0, np.inf, unit="Pa")
    y = np.asarray(y, dtype=float)
    sx, sy, sz, t = _unit_strip(y / b, z / b, mu, nu)
    return StripStresses(sx * p0, sy * p0, sz * p0, t * p0)


@dataclass(frozen=True)
class StripMaxima:
    """Maxima of the three measures below the unit Hertz strip (b = 1, p0 = 1).

    Returned by :func:`strip_maxima`; not built by hand.

    Parameters
    ----------
    friction : float
        Coefficient of the traction [-].
    poisson : float
        Poisson's ratio [-].
    value : dict
        Measure name -> maximum over p0 [-].
    y : dict
        Measure name -> its position across the contact over b [-].
    z : dict
        Measure name -> its depth over b [-].

    Notes
    -----
    Valid for 0 <= mu <= 1, 0 <= nu <= 0.5.

    Examples
    --------
    >>> m = strip_maxima()
    >>> f"{m.value['tresca']:.4f} p0 at z = {m.z['tresca']:.4f} b"
    '0.3003 p0 at z = 0.7862 b'
    """

    friction: float
    poisson: float
    value: dict
    y: dict
    z: dict


@functools.lru_cache(maxsize=64)
def _maxima(mu, nu):
    """Grid search (0.02 b) then a zoom: a 21 x 21 grid around the best point, the
    window shrunk 5 times per pass, 10 passes (position to 1e-7 b); numpy only."""
    ys = np.linspace(-1.6, 1.6, 161)
    zs = np.linspace(0.0, 2.0, 101)
    Y, Z = np.meshgrid(ys, zs, indexing="ij")
    val, yy, zz = {}, {}, {}
    u = np.linspace(-1.0, 1.0, 21)
    for name in MEASURES:
        field_ = StripStresses(*_unit_strip(Y, Z, mu, nu)).measure(name)
        # ties (mu = 0: mirror images at +-y) go to y >= 0: the last flat index
        flat = field_.ravel()
        top = flat.max()
        k = np.flatnonzero(flat >= top * (1 - 1e-12))[-1]
        i, j = np.unravel_index(k, field_.shape)
        by, bz, best = ys[i], zs[j], top
        h = 0.04
        for _ in range(10):
            gy = by + h * u
            gz = np.maximum(bz + h * u, 0.0)
            v = StripStresses(*_unit_strip(gy[:, None], gz[None, :], mu, nu)).measure(name)
            k = np.flatnonzero(v.ravel() >= v.max() * (1 - 1e-14))[-1]
            a, c = np.unravel_index(k, v.shape)
            if v[a, c] >= best:
                by, bz, best = gy[a], gz[c], float(v[a, c])
            h /= 5.0
        val[name] = best
        yy[name] = float(by) + 0.0
        zz[name] = float(bz)
    return StripMaxima(mu, nu, val, yy, zz)


def strip_maxima(friction=0.0, poisson=0.3):
    r"""Maxima of Tresca, von Mises and orthogonal shear below the unit Hertz strip.

    .. math:: \max_{y,\,z \ge 0} \tau(y, z)/p_0 \text{ at } (y/b, z/b)

    The field is self-similar in b and p0, so these dimensionless figures give the
    maxima of any strip: value p0 at depth z b and position y b. Found by a grid
    search (0.02 b) refined by ten zooms of a 21 x 21 grid (to 1e-7 b);
    cached per (mu, nu).

    Parameters
    ----------
    friction : float, optional
        Coefficient mu of the traction mu p in +y, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio, 0 <= nu <= 0.5 [-].

    Returns
    -------
    StripMaxima
        value (over p0), y and z (over b) per measure.

    Notes
    -----
    Valid for 0 <= mu <= 1, 0 <= nu <= 0.5. Without friction the orthogonal shear has
    two mirror maxima (+-y); the one at y > 0 is returned.

    Examples
    --------
    >>> m = strip_maxima(0.0, 0.3)
    >>> f"{m.value['orthogonal_shear']:.4f} at y = {m.y['orthogonal_shear']:.4f} b"
    '0.2500 at y = 0.8660 b'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), sections 4.2 (Fig. 4.6) and 7.2
    (Figs. 7.5-7.7).
    """
    mu, nu = _check_material(friction, poisson)
    return _maxima(mu, nu)
