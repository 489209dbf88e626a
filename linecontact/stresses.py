r"""Subsurface stresses below a line contact and along a profiled roller (plane strain).

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

Measures: the maximum shear (Tresca) :math:`(\sigma_1 - \sigma_3)/2` over the three
principal stresses, the von Mises stress
:math:`\sqrt{\tfrac12[(\sigma_1-\sigma_2)^2 + (\sigma_2-\sigma_3)^2 +
(\sigma_3-\sigma_1)^2]}`, and the orthogonal shear :math:`|\tau_{yz}|` (its amplitude
under rolling; Lundberg & Palmgren 1947).

Along a roller: a straight or profiled roller solved by coupled slices
(:mod:`linecontact.roller`) is a row of strips; slice k carries the line load q_k over
the half-width b_k, so :math:`p_{0,k} = 2q_k/(\pi b_k)` and its field is the strip
field scaled by p_{0,k} and b_k. The field is self-similar: the maxima are computed once
per (mu, nu) on the unit strip (a grid search refined by a bounded optimiser) and
scaled per slice, so the stresses of a whole roller cost microseconds. Where the load
varies along the roller (a crown, a relief, a tilt) the field is three-dimensional and
the strips are up to 5 % low; the worst of each measure therefore gets a 3D
correction: below the worst slices, McEwen's strip of the slice plus the 3D field of
the difference between the slices' Hertz pressures and that strip extended to
infinity, from Love's uniformly loaded rectangles (:func:`rectangle_stresses`;
Love 1929) on a grid of 24 cells across and one cell per slice along (one per slice
and across beyond 8 b). Its error against a 3D field (Love's and Cerruti's rectangles
below a 3D boundary-element pressure, tools/bem/stress.py) is measured in
tables/stress_accuracy.csv (tools/studies/stress_study.py) and stated in each
result's ``error`` and notes.

Case-hardening check: the stress envelope against depth (the largest over y at each
depth, since rolling sweeps every y past a material point) over the local allowable of
a hardness profile (:class:`HardnessProfile`), with the yield strength of steel from
its Vickers hardness by the correlation of Pavlina & Van Tyne (2008),
:math:`\sigma_{Y} = 2.876\,HV - 90.7` MPa; the allowable is sigma_Y for von Mises and
sigma_Y/2 for Tresca (the yield criteria themselves). See docs/stresses.md.

References
----------
.. [1] E. McEwen, "Stresses in elastic cylinders in contact along a generatrix",
   Phil. Mag. 40 (1949) 454-459.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
.. [3] G. Lundberg, A. Palmgren, "Dynamic capacity of rolling bearings", Acta
   Polytechnica, Mech. Eng. Ser. 1 (1947) no. 3.
.. [4] E. J. Pavlina, C. J. Van Tyne, "Correlation of yield strength and tensile
   strength with hardness for steels", J. Materials Engineering and Performance 17
   (2008) 888-893.
.. [5] ISO 2639:2002, Steels - Determination and verification of the depth of
   carburized and hardened cases (effective case depth at 550 HV).
.. [6] A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on
   part of the boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
"""
from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ._engine import ckernels, resolve_engine
from .validity import OutOfRangeError, check_interval, check_positive

__all__ = [
    "MEASURES",
    "StripStresses",
    "strip_stresses",
    "StripMaxima",
    "strip_maxima",
    "rectangle_stresses",
    "stress_measures",
    "reaches_end",
    "SubsurfaceStresses",
    "line_contact_stresses",
    "roller_stresses",
    "HardnessProfile",
    "yield_strength_from_hardness",
    "CaseCheck",
    "case_check",
]

#: where roller_stresses' 3D search looks (its ``search``)
_SEARCHES = ("candidates", "every slice")
#: the three stress measures, in the order they are reported
MEASURES = ("tresca", "von_mises", "orthogonal_shear")
#: allowable stress over the yield strength, per measure (the yield criteria)
_ALLOWABLE_FACTOR = {"tresca": 0.5, "von_mises": 1.0}
#: friction coefficients covered (beyond 1 the strip is far from Hertz's assumptions)
_MU_MAX = 1.0


def _check_material(friction, poisson):
    mu = float(check_interval("friction", friction, 0.0, _MU_MAX, unit="",
                              hint="mu is the coefficient of the sliding traction mu p "
                                   "in +y; for traction in -y mirror y"))
    nu = float(check_interval("poisson", poisson, 0.0, 0.5, high_open=True))
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
        Poisson's ratio of the body, 0 <= nu < 0.5 [-] (only sigma_x depends on it).

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
    Valid for 0 <= mu <= 1, 0 <= nu < 0.5.

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
        Poisson's ratio, 0 <= nu < 0.5 [-].

    Returns
    -------
    StripMaxima
        value (over p0), y and z (over b) per measure.

    Notes
    -----
    Valid for 0 <= mu <= 1, 0 <= nu < 0.5. Without friction the orthogonal shear has
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


@dataclass(frozen=True)
class SubsurfaceStresses:
    """Stress maxima along a roller (one strip per slice) and the worst of all.

    Returned by :func:`line_contact_stresses` and :func:`roller_stresses`; not built by
    hand. Per-measure dicts are keyed by :data:`MEASURES`.

    Parameters
    ----------
    x : ndarray
        Slice centres along the roller [m].
    half_width : ndarray
        Contact half-width b(x), 0 where unloaded [m].
    peak_pressure : ndarray
        Peak pressure p0(x) = 2 q(x)/(pi b(x)), 0 where unloaded [Pa].
    friction : float
        Coefficient of the sliding traction [-].
    poisson : float
        Poisson's ratio [-].
    value : dict
        Measure -> its maximum below each slice [Pa].
    depth : dict
        Measure -> its depth below each slice [m].
    y : dict
        Measure -> its position across the contact below each slice [m].
    worst : dict
        Measure -> dict(value [Pa], x [m], y [m], z [m], slice index).
    notes : tuple of str
        The measured accuracy of the slice method (or why it is not known here).
    edge_loaded : bool
        The contact reaches a roller end (the end slice's stresses are those of a
        singular pressure peak, resolved only to the slice width).
    strip_worst : dict or None
        With the 3D correction: the plane-strain strips' worst (as `worst`), for
        comparison; None without it.
    error : dict or None
        Measure -> the largest |value/value_3D - 1| measured for this kind of case in
        tables/stress_accuracy.csv [-]; None where the case lies outside the measured
        range (the notes say why).
    method : str
        "plane-strain strip" or "strip + 3D correction".

    Notes
    -----
    Valid as the plane-strain strip per slice: b << R, b(x) slowly varying along x
    (see the notes for the measured error where it is not).

    Examples
    --------
    >>> s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9)
    >>> f"{s.worst['tresca']['value'] / 1e6:.0f} MPa at {s.worst['tresca']['z'] * 1e6:.1f} um"
    '257 MPa at 58.4 um'
    """

    x: np.ndarray
    half_width: np.ndarray
    peak_pressure: np.ndarray
    friction: float
    poisson: float
    value: dict
    depth: dict
    y: dict
    worst: dict
    notes: tuple = field(default_factory=tuple)
    edge_loaded: bool = False
    strip_worst: dict = None
    error: dict = None
    method: str = "plane-strain strip"

    def _slice(self, x):
        x = float(x)
        lo, hi = self.x[0], self.x[-1]
        if self.x.size == 1:
            return float(self.half_width[0]), float(self.peak_pressure[0])
        if not lo <= x <= hi:
            raise OutOfRangeError("x", x, f"[{lo:.6g}, {hi:.6g}] m", unit="m",
                                  hint="the slices span the contact's overlap interval")
        # interpolate the line load and b; p0 from them
        q = 0.5 * np.pi * self.peak_pressure * self.half_width
        qx = float(np.interp(x, self.x, q))
        bx = float(np.interp(x, self.x, self.half_width))
        return bx, (2 * qx / (np.pi * bx) if bx > 0 else 0.0)

    def section(self, x, y, z):
        """The field on a section across the roller at x, on the grid y x z.

        Parameters
        ----------
        x : float
            Position along the roller, within the slices' span [m].
        y : array_like
            Positions across the contact [m].
        z : array_like
            Depths, z >= 0 [m].

        Returns
        -------
        StripStresses
            Components on the (len(y), len(z)) grid [Pa].
        """
        b, p0 = self._slice(x)
        Y, Z = np.meshgrid(np.asarray(y, float), np.asarray(z, float), indexing="ij")
        if b <= 0:
            zero = np.zeros_like(Y)
            return StripStresses(zero, zero, zero, zero)
        return strip_stresses(Y, Z, b, p0, self.friction, self.poisson)

    def along_axis(self, z, y=0.0):
        """The field along the roller (every slice) at depths z and position y.

        Parameters
        ----------
        z : array_like
            Depths, z >= 0 [m].
        y : float, optional
            Position across the contact [m].

        Returns
        -------
        StripStresses
            Components on the (n_slices, len(z)) grid, 0 below unloaded slices [Pa].
        """
        z = np.atleast_1d(check_interval("z", z, 0.0, np.inf, unit="m"))
        loaded = self.half_width > 0
        b = np.where(loaded, self.half_width, 1.0)[:, None]
        p0 = np.where(loaded, self.peak_pressure, 0.0)[:, None]
        mu, nu = self.friction, self.poisson
        comps = _unit_strip(float(y) / b, z[None, :] / b, mu, nu)
        return StripStresses(*(c * p0 for c in comps))

    def depth_envelope(self, measure, depths, x=None, n_y=241):
        """The largest stress over y at each depth, below the worst slice (or at x).

        Parameters
        ----------
        measure : str
            One of :data:`MEASURES`.
        depths : array_like
            Depths, z >= 0 [m].
        x : float, optional
            Position along the roller [m] (default: the slice of the measure's worst).
        n_y : int, optional
            Points over |y| <= 2 b [-].

        Returns
        -------
        ndarray
            The envelope at each depth [Pa].
        """
        if measure not in MEASURES:
            raise ValueError(f"measure = {measure!r} is not one of {MEASURES}")
        if x is None:
            k = self.worst[measure]["slice"]
            b, p0 = float(self.half_width[k]), float(self.peak_pressure[k])
        else:
            b, p0 = self._slice(x)
        z = np.atleast_1d(check_interval("depths", depths, 0.0, np.inf, unit="m"))
        ys = np.linspace(-2.0, 2.0, n_y)[:, None]
        s = StripStresses(*_unit_strip(ys, z[None, :] / b, self.friction, self.poisson))
        return s.measure(measure).max(axis=0) * p0

    def to_dict(self, arrays=True):
        """Plain-Python dict for JSON: the worst per measure, the along-axis profile if
        `arrays` (SI units; see ``units``).

        Parameters
        ----------
        arrays : bool, optional
            Include the per-slice arrays.

        Returns
        -------
        dict
            Keys worst, notes, edge_loaded, friction, poisson, method, error
            (strip_worst with the 3D correction; and x, half_width,
            peak_pressure, value, depth, y), units.
        """
        d = {"worst": {k: dict(v) for k, v in self.worst.items()},
             "friction": self.friction, "poisson": self.poisson,
             "edge_loaded": self.edge_loaded, "notes": list(self.notes),
             "method": self.method, "error": self.error}
        if self.strip_worst is not None:
            d["strip_worst"] = {k: dict(v) for k, v in self.strip_worst.items()}
        if arrays:
            d.update(x=self.x.tolist(), half_width=self.half_width.tolist(),
                     peak_pressure=self.peak_pressure.tolist(),
                     value={k: v.tolist() for k, v in self.value.items()},
                     depth={k: v.tolist() for k, v in self.depth.items()},
                     y={k: v.tolist() for k, v in self.y.items()})
        d["units"] = {"x": "m", "half_width": "m", "peak_pressure": "Pa", "value": "Pa",
                      "depth": "m", "y": "m", "z": "m"}
        return d


def _assemble(x, b, p0, mu, nu, notes=(), edge_loaded=False):
    m = _maxima(mu, nu)
    loaded = b > 0
    value, depth, yy, worst = {}, {}, {}, {}
    for name in MEASURES:
        value[name] = np.where(loaded, m.value[name] * p0, 0.0)
        depth[name] = np.where(loaded, m.z[name] * b, 0.0)
        yy[name] = np.where(loaded, m.y[name] * b, 0.0)
        k = int(np.argmax(value[name]))
        worst[name] = dict(value=float(value[name][k]), x=float(x[k]),
                           y=float(yy[name][k]), z=float(depth[name][k]), slice=k)
    return SubsurfaceStresses(x, b, p0, mu, nu, value, depth, yy, worst, tuple(notes),
                              bool(edge_loaded))


def line_contact_stresses(force, radius, length, estar, friction=0.0, poisson=0.3):
    r"""Stress maxima below an infinitely long (plane-strain) Hertz line contact.

    .. math:: b = \sqrt{\frac{4 F R}{\pi L E^*}}, \qquad
              p_0 = \sqrt{\frac{F E^*}{\pi L R}}

    with the maxima of :func:`strip_maxima` scaled by b and p0 (one slice at x = 0).

    Parameters
    ----------
    force : float
        Normal force F [N].
    radius : float
        Radius R across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    friction : float, optional
        Coefficient mu of the sliding traction, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio, 0 <= nu < 0.5 [-].

    Returns
    -------
    SubsurfaceStresses
        One slice.

    Notes
    -----
    Valid for 0 < F, R, L, E* < inf and b << R; the uniform line load F/L ignores the
    roller ends (for those use :func:`roller_stresses`).

    Examples
    --------
    >>> s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9, friction=0.1)
    >>> f"{s.worst['von_mises']['value'] / 1e6:.0f} MPa"
    '485 MPa'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), Eq. 4.45 and section 7.2.
    """
    from .classical import hertz_half_width, hertz_peak_pressure
    mu, nu = _check_material(friction, poisson)
    b = float(hertz_half_width(force, radius, length, estar))
    p0 = float(hertz_peak_pressure(force, radius, length, estar))
    return _assemble(np.zeros(1), np.array([b]), np.array([p0]), mu, nu,
                     notes=("plane-strain Hertz strip with the mean line load F/L: exact "
                            "for an infinitely long contact; the roller ends are not "
                            "modelled",))


def roller_stresses(solution, friction=0.0, poisson=0.3, roller=None, three_d=True,
                    search="candidates"):
    r"""Stress maxima along a roller solved by slices, per slice and the worst of all.

    .. math:: p_{0,k} = \frac{2 q_k}{\pi b_k},\qquad
              \tau_{\max,k} = \hat\tau(\mu, \nu)\, p_{0,k}
              \text{ at } z_k = \hat z(\mu, \nu)\, b_k

    per slice (plane strain); the worst of each measure then gets a 3D correction:
    below candidate slices (the strips' worst and two either side, p0's other peaks;
    where the contact reaches an end, slices spread over the whole roller, refined
    along it), the field is McEwen's strip of that slice plus the 3D field (Love's rectangles, :func:`rectangle_stresses`)
    of the difference between the slices' Hertz pressures and that strip extended
    to infinity, maximised over (y, z) by a zoomed grid search (docs/stresses.md).

    Parameters
    ----------
    solution : RollerSolution
        From :class:`linecontact.roller.ProfiledRoller`, :func:`~linecontact.roller.roller_contact`
        or :func:`~linecontact.roller.iso_slicing` (its ``x``, ``q``, ``half_width``).
    friction : float, optional
        Coefficient mu of the sliding traction, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio, 0 <= nu < 0.5 [-].
    roller : ProfiledRoller, optional
        The model that produced `solution`: with it the note also checks L/D, the
        mean line load and the profile against the measured range.
    three_d : bool, optional
        Apply the 3D correction to the worst (default; without it the worst is the
        plane-strain strips', up to 5 % low under a crown, a relief or a tilt).
    search : {"candidates", "every slice"}, optional
        Where the 3D correction's grid search looks: below the candidate slices
        (default), or below every loaded slice (a check of the candidates' choice:
        never lower, some 20-25 times the cost).

    Returns
    -------
    SubsurfaceStresses
        Per slice (plane strain) and worst (3D-corrected); ``error`` and the notes
        give the measured error against a 3D field.

    Notes
    -----
    Valid as the roller model (b << R, |theta| < 0.1 rad); the 3D correction covers the
    normal pressure (the traction's field stays the strip's); measured against a 3D
    field in tables/stress_accuracy.csv (``error``, notes). A measure whose strip
    maximum lies at the surface (mu >= 0.3) keeps the strip's value.

    Examples
    --------
    >>> from linecontact.roller import roller_contact
    >>> sol = roller_contact(5e-3, 14e-3, 115.385e9, "circular:Rc=0.5", force=4200.0)
    >>> s = roller_stresses(sol)
    >>> f"{s.worst['tresca']['value'] / 1e6:.0f} MPa (strips: {s.strip_worst['tresca']['value'] / 1e6:.0f} MPa)"
    '759 MPa (strips: 737 MPa)'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), sections 3.2, 4.2 and 7.2; E. McEwen
    (1949); A. E. H. Love (1929).
    """
    mu, nu = _check_material(friction, poisson)
    if search not in _SEARCHES:
        raise ValueError(f"search = {search!r} is not one of {_SEARCHES}")
    x = np.asarray(solution.x, dtype=float)
    b = np.asarray(solution.half_width, dtype=float)
    q = np.asarray(solution.q, dtype=float)
    loaded = (b > 0) & (q > 0)
    p0 = np.where(loaded, 2 * q / (np.pi * np.where(loaded, b, 1.0)), 0.0)
    b = np.where(loaded, b, 0.0)
    edge = bool(getattr(solution, "edge_loaded", False))
    note, error = stress_accuracy(solution, mu, roller, three_d and x.size > 1)
    notes = [note]
    if edge:
        notes.insert(0, "edge loaded: the end slice's pressure is a singular peak on a "
                        "half-space, so the stresses below it are resolved only to the "
                        "slice width (a grid-dependent number, like the peak pressure)")
    s = _assemble(x, b, p0, mu, nu, notes, edge)
    if not three_d or x.size < 2 or not loaded.any():
        return dataclasses.replace(s, error=error)
    # the contact at or near an end: the worst may lie anywhere along the roller, and
    # the search scans every part of it
    wide = edge or reaches_end(solution)
    w3 = _worst_3d(x, b, p0, mu, nu, _maxima(mu, nu), wide,
                   every=search == "every slice")
    if all(v is None for v in w3.values()):
        # every measure's worst at the surface (friction >= ~0.4): nothing corrected,
        # the strips' worst as it is, and the method says so
        return dataclasses.replace(s, error=error)
    worst = {k: (s.worst[k] if w3[k] is None else w3[k]) for k in MEASURES}
    return dataclasses.replace(s, worst=worst, strip_worst=s.worst, error=error,
                               method="strip + 3D correction")



# ---------------------------------------------------------------- 3D correction
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
        Poisson's ratio, 0 <= nu < 0.5 [-].

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
    nu = float(check_interval("poisson", poisson, 0.0, 0.5, high_open=True))
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


def _hertz_cell_means(edges, b):
    """Mean of sqrt(1 - y^2/b^2) over each cell [edges[i], edges[i+1]] (0 beyond b);
    b a scalar, or an array of half-widths (one row of cells each; 0 for none); edges
    one row for all, or one row per half-width."""
    b = np.asarray(b, dtype=float)[..., None]
    pos = b > 0
    bs = np.where(pos, b, 1.0)
    u = np.minimum(np.maximum(edges / bs, -1.0), 1.0)
    prim = 0.5 * (u * np.sqrt(1.0 - u * u) + np.arcsin(u))     # int sqrt(1-u^2) du
    out = (prim[..., 1:] - prim[..., :-1]) * bs / (edges[..., 1:] - edges[..., :-1])
    return np.where(pos, out, 0.0)


#: 3D correction: cells across the contact, near-field half-window over b
_N_Y = 24
_NEAR = 8.0
#: 3D search: zooms after the first 5 x 5 grid (3 x 3 each), window shrink per zoom
_ZOOMS = 3
_SHRINK = 2.5
#: the 3D search: every loaded slice's parts scanned first (a stride of n/this), and
#: how many best slices of each measure get the first (coarse) window (and the end
#: slices where p0 rises towards the end)
_STRIDE_PARTS = 4
_COARSE_SLICES = 1
#: p0's local maxima within this factor of the largest are candidates too
_PEAK_MARGIN = 1.1
#: where the contact reaches an end, each measure is also scored at these depths
#: over b (towards an end the 3D worst rises from the strip's 0.5-0.79 b to 0.35-0.4 b
#: below an end slice, and to ~0.15-0.2 b on the thin slices next to an end peak)
_SHALLOW_Z = (0.4, 0.2)
_SHALLOW_NEAR = 1.5


def _slice_edges(xc):
    """The slices' edges along the roller (midpoints; the end slices mirrored)."""
    n = xc.size
    xe = np.empty(n + 1)
    xe[1:-1] = 0.5 * (xc[1:] + xc[:-1])
    xe[0] = xc[0] - 0.5 * (xc[1] - xc[0])
    xe[-1] = xc[-1] + 0.5 * (xc[-1] - xc[-2])
    return xe


#: 0, 1, ..., _N_Y: the near grid's edges are -B + (2B/_N_Y) i (np.linspace's)
_STEPS_Y = np.arange(_N_Y + 1, dtype=float)


def _corners_3d(xc, b, p0, k0, xe=None):
    """Corner positions and weights of the pressure difference p - p_k0 (a row of
    Hertz strips, one per slice, minus the strip of slice k0 extended to infinity);
    `xe` the slices' edges (:func:`_slice_edges`, computed if not given)."""
    return _corners_many(xc, b, p0, [k0], xe)[0]


def _corners_many(xc, b, p0, ks, xe=None):
    """:func:`_corners_3d` of each slice k0 of `ks`: a list of (cx, cy, w); the
    slices' Hertz cell means on every k0's grid in one evaluation."""
    n = xc.size
    if xe is None:
        xe = _slice_edges(xc)
    L = xe[-1] - xe[0]
    q = 0.5 * np.pi * p0 * b                        # the line loads
    # near field: a common grid across |y| <= B, each slice's Hertz profile averaged
    # onto its cells; minus slice k0's profile; the extension of k0's strip beyond the
    # roller's ends (to +-1e6 L) closes the infinite strip whose field is McEwen's
    heads, rows_b = [], []
    for k0 in ks:
        b0, x0 = b[k0], xc[k0]
        near = np.abs(xc - x0) <= _NEAR * b0
        near[max(k0 - 2, 0):k0 + 3] = True
        at = np.flatnonzero(near)
        i0, i1 = int(at[0]), int(at[-1])
        bn = b[i0:i1 + 1]
        heads.append((k0, i0, i1, max(float(bn.max()), b0)))
        rows_b += [b[k0:k0 + 1], bn]
    B = np.array([h[3] for h in heads])
    ye = _STEPS_Y * ((B + B) / _N_Y)[:, None] - B[:, None]   # np.linspace(-B, B, _N_Y + 1)
    ye[:, -1] = B
    sizes = [h[2] - h[1] + 2 for h in heads]
    means_all = _hertz_cell_means(np.repeat(ye, sizes, axis=0), np.concatenate(rows_b))
    out, off = [], 0
    for (k0, i0, i1, _), ye, size in zip(heads, ye, sizes):
        means = means_all[off:off + size]
        off += size
        out.append(_corners_assemble(xe, L, b, p0, q, k0, i0, i1, ye, means))
    return out


def _corners_assemble(xe, L, b, p0, q, k0, i0, i1, ye, means):
    """The corners of :func:`_corners_3d` from k0's near window [i0, i1], its grid
    across ye and the cell means (k0's row, then the window's slices')."""
    if _CORNERS[0] == "c":
        got = _corners_c(xe, L, b, p0, q, k0, i0, i1, ye, means)
        if got is not None:
            return got
    n = b.size
    b0 = b[k0]
    ref = p0[k0] * means[0]
    lo_ext, hi_ext = int(i0 == 0), int(i1 == n - 1)
    rows = i1 - i0 + 1 + lo_ext + hi_ext
    # the cells' pressures with a frame of zeros: their corners' weights are the
    # mixed differences
    Pp = np.zeros((rows + 2, _N_Y + 2))
    Pp[1 + lo_ext:rows + 1 - hi_ext, 1:-1] = p0[i0:i1 + 1, None] * means[1:] - ref
    if lo_ext:
        Pp[1, 1:-1] = -ref
    if hi_ext:
        Pp[rows, 1:-1] = -ref
    xs = np.empty(rows + 1)
    xs[lo_ext:rows + 1 - hi_ext] = xe[i0:i1 + 2]
    if lo_ext:
        xs[0] = xe[0] - 1e6 * L
    if hi_ext:
        xs[-1] = xe[-1] + 1e6 * L
    W = Pp[1:, 1:] - Pp[1:, :-1] - Pp[:-1, 1:] + Pp[:-1, :-1]
    nn = W.size
    # far field (beyond _NEAR b0, where the distribution across matters to (b/r)^2
    # of a small difference): one cell per slice across |y| <= max(b, b0) with the
    # difference of the mean pressures (q - q_k0)/(2 max(b, b0)); beyond the roller's
    # ends (if the near grid does not reach them) k0's strip, one cell
    nl, nr = i0, n - 1 - i1                         # far slices left and right
    m = nl + nr + (1 - lo_ext) + (1 - hi_ext)       # far cells, the ends' included
    cx, cy, w = np.empty(nn + 4 * m), np.empty(nn + 4 * m), np.empty(nn + 4 * m)
    cx[:nn].reshape(rows + 1, _N_Y + 1)[:] = xs[:, None]
    cy[:nn].reshape(rows + 1, _N_Y + 1)[:] = ye
    w[:nn] = W.ravel()
    if m == 0:
        keep = w != 0
        return cx[keep], cy[keep], w[keep]
    q0 = q[k0]
    lo_x, hi_x, bf, dq = np.empty(m), np.empty(m), np.empty(m), np.empty(m)
    lo_x[:nl], hi_x[:nl] = xe[:nl], xe[1:nl + 1]
    lo_x[nl:nl + nr], hi_x[nl:nl + nr] = xe[i1 + 1:n], xe[i1 + 2:]
    bf[:nl], bf[nl:nl + nr] = b[:nl], b[i1 + 1:]
    np.maximum(bf[:nl + nr], b0, out=bf[:nl + nr])
    dq[:nl], dq[nl:nl + nr] = q[:nl], q[i1 + 1:]
    dq[:nl + nr] -= q0
    j = nl + nr
    if not lo_ext:
        lo_x[j], hi_x[j], bf[j], dq[j] = xe[0] - 1e6 * L, xe[0], b0, -q0
        j += 1
    if not hi_ext:
        lo_x[j], hi_x[j], bf[j], dq[j] = xe[-1], xe[-1] + 1e6 * L, b0, -q0
    pm = dq / (2 * bf)
    fx, fy, fw = cx[nn:].reshape(4, m), cy[nn:].reshape(4, m), w[nn:].reshape(4, m)
    fx[0], fx[1], fx[2], fx[3] = lo_x, lo_x, hi_x, hi_x
    fy[0], fy[2] = -bf, -bf
    fy[1], fy[3] = bf, bf
    fw[0], fw[3] = pm, pm
    fw[1], fw[2] = -pm, -pm
    # adjacent far cells of the same half-width share the corners on their common
    # edge (every cell below a slice narrower than b0, and the ends' extensions, has
    # half-width b0), and the near grid's end corners at +-B those of a far cell as
    # wide: one corner each, with the sum of the weights (exactly 0 between two
    # unloaded slices)
    order = np.lexsort((cy, cx))
    cx, cy, w = cx[order], cy[order], w[order]
    first = np.empty(cx.size, dtype=bool)
    first[0] = True
    np.not_equal(cx[1:], cx[:-1], out=first[1:])
    first[1:] |= cy[1:] != cy[:-1]
    at = np.flatnonzero(first)
    cx, cy, w = cx[at], cy[at], np.add.reduceat(w, at)
    keep = w != 0
    return cx[keep], cy[keep], w[keep]


def _field_3d(x, b, p0, mu, nu, batches, corners):
    """Stresses at points below slices: McEwen's strip of the slice (pressure and
    traction) plus the 3D field of the pressure's difference from it (Love's
    rectangles; `corners(k)` gives slice k's offsets along the roller (1, n), its
    corners across (n,) and weights (n,), from :func:`_corners_3d`). `batches`: a list
    of (k, py, pz, shear_only), the points (py, pz) below slice k; returns per batch
    the six components (sigma_x, sigma_y, sigma_z, tau_xy, tau_xz, tau_yz), or with
    `shear_only` tau_yz alone (the orthogonal shear's one component, one corner
    function). The corner sums are per slice; the strips' fields and the components
    of all batches are evaluated at once."""
    sums = [None] * len(batches)
    full = [i for i, bt in enumerate(batches) if not bt[3]]
    for group, only in ((full, None), ([i for i in range(len(batches)) if batches[i][3]],
                                       _PYZ)):
        items = []
        for i in group:
            k, py, pz, _ = batches[i]
            X, cy, w = corners(k)
            t = _love_c(X, cy, w, py, pz, only) if _CORNERS[0] == "c" else None
            if t is not None:
                sums[i] = t
            else:
                items.append((i, (X, py[:, None] - cy[None, :], pz[:, None], w)))
        for (i, _), t in zip(items, _love_batches([it for _, it in items], only)
                             if items else ()):
            sums[i] = t
    sizes = [bt[1].size for bt in batches]
    ends = [0]
    for size in sizes:
        ends.append(ends[-1] + size)
    if len(batches) == 1:
        k, py, pz = batches[0][:3]
        bk, s0 = b[k], p0[k]
    else:
        py = np.concatenate([bt[1] for bt in batches])
        pz = np.concatenate([bt[2] for bt in batches])
        ks = [bt[0] for bt in batches]
        bk, s0 = np.repeat(b[ks], sizes), np.repeat(p0[ks], sizes)
    sx, sy, sz, tyz = _unit_strip(py / bk, pz / bk, mu, nu)
    sx, sy, sz, tyz = s0 * sx, s0 * sy, s0 * sz, s0 * tyz
    if full:
        if len(full) == 1:
            T, rows = sums[full[0]], slice(ends[full[0]], ends[full[0] + 1])
        else:
            T = np.concatenate([sums[i] for i in full], axis=1)
            rows = np.concatenate([np.arange(ends[i], ends[i + 1]) for i in full])
        d = _love_components(T, pz[rows], nu)
        comps = (sx[rows] + d[0], sy[rows] + d[1], sz[rows] + d[2], d[3], d[4],
                 tyz[rows] + d[5])
    out, j = [], 0
    for i, (k, py_, pz_, shear) in enumerate(batches):
        r = slice(ends[i], ends[i + 1])
        if shear:
            out.append(tyz[r] - (1.0 / (2.0 * np.pi)) * pz[r] * sums[i][_PYZ])
        else:
            out.append(tuple(c[j:j + sizes[i]] for c in comps))
            j += sizes[i]
    return out


def stress_measures(sigma_x, sigma_y, sigma_z, tau_xy, tau_xz, tau_yz):
    r"""Tresca (maximum) shear, von Mises stress and orthogonal shear of 3D stress states.

    .. math::

        \tau_{\max} = \frac{\sigma_1 - \sigma_3}{2},\qquad
        \sigma_{vM} = \sqrt{\tfrac12[(\sigma_x - \sigma_y)^2 + (\sigma_y - \sigma_z)^2
        + (\sigma_z - \sigma_x)^2] + 3(\tau_{xy}^2 + \tau_{xz}^2 + \tau_{yz}^2)},
        \qquad \tau_{orth} = |\tau_{yz}|

    with :math:`\sigma_1 \ge \sigma_2 \ge \sigma_3` the principal stresses (x along
    the roller axis, y across the contact, z into the body); the one home of these
    measures for the runtime's 3D correction and the 3D reference field (tools/bem).

    Parameters
    ----------
    sigma_x, sigma_y, sigma_z : array_like
        Normal stresses [Pa].
    tau_xy, tau_xz, tau_yz : array_like
        Shear stresses [Pa].

    Returns
    -------
    dict
        ``tresca``, ``von_mises``, ``orthogonal_shear`` arrays of the broadcast
        shape [Pa].

    Notes
    -----
    Valid for any finite stresses, -inf < sigma, tau < inf.

    Examples
    --------
    Uniaxial tension of 100 MPa: maximum shear 50 MPa, von Mises 100 MPa.

    >>> m = stress_measures(100e6, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> f"{float(m['tresca']) / 1e6:.1f} {float(m['von_mises']) / 1e6:.1f}"
    '50.0 100.0'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), sections 4.2 and 7.2.
    """
    sx, sy, sz, txy, txz, tyz = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (sigma_x, sigma_y, sigma_z, tau_xy,
                                                tau_xz, tau_yz)))
    return {name: _measure_3d(name, sx, sy, sz, txy, txz, tyz) for name in MEASURES}


def _measure_3d(name, sx, sy, sz, txy, txz, tyz):
    """One of :data:`MEASURES` of broadcast 3D stress components (stress_measures)."""
    if name == "tresca":
        T = np.empty(np.shape(sx) + (3, 3))
        T[..., 0, 0], T[..., 1, 1], T[..., 2, 2] = sx, sy, sz
        T[..., 0, 1] = T[..., 1, 0] = txy
        T[..., 0, 2] = T[..., 2, 0] = txz
        T[..., 1, 2] = T[..., 2, 1] = tyz
        ev = np.linalg.eigvalsh(T)
        return 0.5 * (ev[..., -1] - ev[..., 0])
    if name == "von_mises":
        return np.sqrt(np.maximum(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2)
                                  + 3 * (txy ** 2 + txz ** 2 + tyz ** 2), 0.0))
    return np.abs(tyz)


def _search_grids():
    grids = []
    for n in (5, 3):
        u = np.linspace(-1.0, 1.0, n)
        U, V = (a.ravel() for a in np.meshgrid(u, u, indexing="ij"))
        keep = np.arange(U.size) != U.size // 2          # the centre: the best so far
        grids.append((U[keep], V[keep]))
    return grids


#: the 3D search's grids in (y, z) over the window's half-sides: 5 x 5 then 3 x 3,
#: each without its centre (the best point so far, whose value is known)
_SEARCH_GRIDS = _search_grids()


def _worst_3d(x, b, p0, mu, nu, m, wide=False, every=False):
    """The worst of each measure with the 3D correction (:func:`_field_3d`): the
    strip's optimum point below candidate slices scores them (p0's largest and two
    either side, p0's other local maxima within _PEAK_MARGIN; with `wide`, the
    contact at an end, also _STRIDE_PARTS + 1 slices spread over the loaded ones and
    every local maximum of p0 with its neighbours, each measure's best then climbing
    along the roller to a local maximum of the scanned slices, and every measure
    scored at shallower points too, z = _SHALLOW_Z b, where the worst lies near an
    end); the best slice of each measure and the best of p0's largest +-2 (the
    former search's choice) each get a 5 x 5 grid in (y, z) around its better point
    (+-0.4 b, +-0.3 b), then three zooms of a 3 x 3 grid (window / 2.5 each); the
    best is the worst.
    Measures whose strip optimum lies within 0.1 b of the surface keep the strip's
    value (None here).

    Each grid's centre is the best point so far, whose value is known, so it is not
    evaluated again; the points below the same slice are summed in one batch per
    pass (the orthogonal shear's apart, with tau_yz alone), each slice's corners
    built once (:func:`_corners_3d`) with their offsets along the roller. With
    `every`, every loaded slice is scanned and searched (a check of the choice)."""
    cache = {}
    xe = _slice_edges(x)

    def corners(k):
        if k not in cache:
            add([k])
        return cache[k]

    def add(ks):
        for k, (cx, cy, w) in zip(ks, _corners_many(x, b, p0, ks, xe)):
            cache[k] = ((x[k] - cx)[None, :], cy, w)

    def evaluate(pts):
        """pts: (name, ...) -> (k, py, pz); the measure `name` at those points below
        slice k, the points below one slice in one batch (the orthogonal shear's
        apart)."""
        batches, groups = [], []
        for shear in (False, True):
            rest = [n for n in pts if (n[0] == "orthogonal_shear") == shear]
            while rest:
                k = pts[rest[0]][0]
                group = [n for n in rest if pts[n][0] == k]
                rest = [n for n in rest if pts[n][0] != k]
                if len(group) == 1:
                    py, pz = pts[group[0]][1:]
                else:
                    py = np.concatenate([pts[n][1] for n in group])
                    pz = np.concatenate([pts[n][2] for n in group])
                batches.append((k, py, pz, shear))
                groups.append(group)
        out = {}
        for group, res in zip(groups, _field_3d(x, b, p0, mu, nu, batches, corners)):
            i0 = 0
            for n in group:
                i1 = i0 + pts[n][1].size
                out[n] = (np.abs(res[i0:i1]) if n[0] == "orthogonal_shear"
                          else _measure_3d(n[0], *(c[i0:i1] for c in res)))
                i0 = i1
        return out

    names = [n for n in MEASURES if m.z[n] >= 0.1]
    if not names:                       # every maximum at the surface (mu >= ~0.4)
        return {name: None for name in MEASURES}
    # the candidate slices, each scored by the 3D field at every measure's strip
    # optimum: p0's largest and two either side (every measure's strip maximum is a
    # constant times p0, so this is each measure's strip worst; taken from p0 itself,
    # so that rounding cannot split two mirror slices), p0's other local maxima along
    # the roller and their neighbours (a two-peaked pressure); where the contact
    # reaches an end (the 3D field departs from the strip's there: the worst can sit
    # on an end slice or well inside it) also every s-th loaded slice, the ends
    # included, and every local maximum of p0, each measure's best then climbing
    # along the roller (every measure scored at shallower points too)
    loaded = np.flatnonzero(b > 0)
    k = int(np.argmax(p0))
    seen = set()

    def scan(ks):
        ks = sorted({int(kk) for kk in ks if 0 <= kk < x.size and b[kk] > 0
                     and (in_half is None or not wide or in_half(kk))} - seen)
        if not ks:
            return 0
        seen.update(ks)
        add([kk for kk in ks if kk not in cache])
        # each measure's strip optimum and, where the contact reaches an end, on
        # the slices within _SHALLOW_NEAR b of a loaded end, its shallower points
        # (there the 3D worst rises far above the strip's depth); a slice's score is
        # the best of them, which the zooms start from
        base = [(m.y[n], m.z[n]) for n in names]
        more = base + [(m.y[n], zz) for n in shallow for zz in _SHALLOW_Z]
        near = [kk for kk in ks if shallow and min(x[kk] - xe[loaded[0]],
                                                   xe[loaded[-1] + 1] - x[kk])
                < _SHALLOW_NEAR * b[kk]]
        groups = [(g, p) for g, p in (([kk for kk in ks if kk not in near], base),
                                      (near, more)) if g]
        batches = [(kk, np.array([u for u, _ in p]) * b[kk],
                    np.array([v for _, v in p]) * b[kk], False)
                   for g, p in groups for kk in g]
        res = iter(_field_3d(x, b, p0, mu, nu, batches, corners))
        for g, p in groups:
            cols = [np.array(c) for c in zip(*(next(res) for _ in g))]
            for i, name in enumerate(names):
                js = [i] + ([len(names) + shallow.index(name) * len(_SHALLOW_Z) + d
                             for d in range(len(_SHALLOW_Z))]
                            if p is more and name in shallow else [])
                v = _measure_3d(name, *(c[:, js] for c in cols))
                best = np.argmax(v, axis=1)
                for s_, kk in enumerate(g):
                    j = js[best[s_]]
                    score[name][kk] = float(v[s_, best[s_]])
                    start[name][kk] = (p[j][0] * b[kk], p[j][1] * b[kk])
        return len(ks)

    score = {name: {} for name in names}
    start = {name: {} for name in names}
    shallow = ([n for n in names if m.z[n] > max(_SHALLOW_Z)]
               if wide or every else [])
    # p0's other local maxima whose strip worst is within the 3D correction's reach
    # off the ends (the strips up to 5 % low: a margin of 10 %) of the largest
    inner = ((p0[1:-1] > p0[:-2]) & (p0[1:-1] >= p0[2:])
             & (_PEAK_MARGIN * p0[1:-1] >= p0[k]))
    peaks = np.flatnonzero(inner) + 1
    if x.size > 2 and np.allclose(x, -x[::-1], rtol=0, atol=1e-12 * np.ptp(x)) \
            and np.allclose(p0, p0[::-1], rtol=1e-12, atol=0):
        # a mirror-symmetric load: its mirror slices tie, so one half is scanned
        mid = (x.size - 1) / 2
        in_half = (lambda kk: kk <= mid + 1) if k <= mid else (lambda kk: kk >= mid - 1)
        peaks = peaks[[in_half(pk) for pk in peaks]] if peaks.size else peaks
    else:
        in_half = None
    if every:
        in_half = None
        scan(loaded)
    elif not wide:
        scan(list(range(k - 2, k + 3)) + [pk + d for pk in peaks for d in (-1, 0, 1)])
    else:
        # every s-th loaded slice, counted from either end (a mirror-symmetric set),
        # and every local maximum of p0 with its neighbours (where the orthogonal
        # shear, whose 3D correction is small, has its worst off the ends)
        j = np.arange(_STRIDE_PARTS + 1)
        half = np.floor(np.minimum(j, _STRIDE_PARTS - j) * (loaded.size - 1)
                        / _STRIDE_PARTS + 0.5).astype(int)
        even = loaded[np.where(2 * j <= _STRIDE_PARTS, half, loaded.size - 1 - half)]
        tops = np.flatnonzero((p0[1:-1] > p0[:-2]) & (p0[1:-1] >= p0[2:])) + 1
        scan(list(range(k - 2, k + 3)) + list(even)
             + [pk + d for pk in tops for d in (-1, 0, 1)])
        # then each measure's best climbs along the roller until both its neighbours
        # are scanned and lower (a local maximum of the scanned slices)
        while scan([kb + d for name in names
                    for kb in (max(score[name], key=score[name].get),)
                    for d in (-1, 1)]):
            pass
    st = {}
    near_k = [kk for kk in range(k - 2, k + 3) if kk in score[names[0]]]
    for name in names:
        # the best two slices by their one point, each given the first (coarse)
        # window below; the better goes on to the zooms
        top = sorted(score[name], key=score[name].get,
                     reverse=True)[:_COARSE_SLICES if wide else 1]
        if every:
            top = sorted(score[name])
        # and the best of p0's largest +-2 (the former search's choice: off the ends
        # the result is never below it; at an end its zooms may start from a
        # shallower point and end up to ~0.7 % below the former search's)
        kk = max(near_k, key=score[name].get)
        top += [kk] if kk not in top else []
        st[name] = [dict(k=kk, val=score[name][kk], by=start[name][kk][0],
                         bz=start[name][kk][1], hy=0.4 * b[kk], hz=0.3 * b[kk])
                    for kk in top]
    # every candidate: a 5 x 5 grid, then three zooms of a 3 x 3 grid, all candidates'
    # points below one slice in one batch per pass
    for it in range(_ZOOMS + 1):
        U, V = _SEARCH_GRIDS[min(it, 1)]
        pts = {(name, j): (c["k"], c["by"] + c["hy"] * U,
                           np.maximum(c["bz"] + c["hz"] * V, 0.05 * b[c["k"]]))
               for name in names for j, c in enumerate(st[name])}
        for key, v in evaluate(pts).items():
            c = st[key[0]][key[1]]
            i = int(np.argmax(v))
            if v[i] > c["val"]:
                c["val"], c["by"], c["bz"] = float(v[i]), pts[key][1][i], pts[key][2][i]
            c["hy"] /= _SHRINK
            c["hz"] /= _SHRINK
    st = {name: max(c, key=lambda d: d["val"]) for name, c in st.items()}
    out = {name: None for name in MEASURES}
    for name in names:
        c = st[name]
        out[name] = dict(value=c["val"], x=float(x[c["k"]]), y=float(c["by"]),
                         z=float(c["bz"]), slice=c["k"])
    return out


# ---------------------------------------------------------------- accuracy note
_ACCURACY = []
#: the table's error fields: (3D-corrected?, friction?, edge loaded?) -> header key
_ERROR_KEYS = {(True, False, False): "error_3d_off_ends",
               (True, False, True): "error_3d_edge_loaded",
               (True, True, False): "error_3d_friction_off_ends",
               (True, True, True): "error_3d_friction_edge_loaded",
               (False, False, False): "slice_error_off_ends",
               (False, False, True): "slice_error_edge_loaded",
               (False, True, False): "slice_error_friction_off_ends",
               (False, True, True): "slice_error_friction_edge_loaded"}


def _accuracy():
    """The covered_* and error fields of tables/stress_accuracy.csv (or None)."""
    if not _ACCURACY:
        from .tables import read_table
        try:
            meta = read_table("stress_accuracy").meta
            errs = {}
            for key in _ERROR_KEYS.values():
                if key in meta:
                    errs[key] = {k: float(v) for k, v in
                                 (item.split() for item in meta[key].split(","))}
            cov = dict(l_over_d=tuple(float(v) for v in
                                      meta["covered_l_over_d"].split(",")),
                       line_load=tuple(float(v) for v in
                                       meta["covered_line_load_over_estar_d"].split(",")),
                       tilt=tuple(float(v) for v in meta["covered_tilt_rad"].split(",")),
                       friction=tuple(float(v) for v in
                                      meta.get("covered_friction", "0, 0").split(",")),
                       profiles=tuple(k.strip() for k in
                                      meta["covered_profiles"].split(",")),
                       errors=errs)
        except (FileNotFoundError, KeyError, ValueError):
            cov = None
        _ACCURACY.append(cov)
    return _ACCURACY[0]


def reaches_end(solution):
    r"""Whether a slice solution's contact reaches a roller end or comes within half a
    slice width h of it.

    .. math:: \min(x_\text{start} - x_\text{lo},\; x_\text{hi} - x_\text{end}) < h/2

    with h the mean slice width (the slices' span over their number, whatever their
    grading).

    There the 3D contact may be edge loaded where the slices are not (in the study of
    tables/stress_accuracy.csv every such case was), so the stresses' error is the
    edge-loaded one (the study's ``rt_edge``).

    Parameters
    ----------
    solution : RollerSolution
        A slice solution (its ``x`` [m], ``q`` [N/m], ``edge_loaded``, and
        ``contact_start``/``contact_end`` [m] where it has them).

    Returns
    -------
    bool
        True at or near an end.

    Notes
    -----
    Valid for slices spanning the contact, equal or graded (their ``width``;
    linecontact.roller).

    Examples
    --------
    >>> from linecontact.roller import roller_contact
    >>> reaches_end(roller_contact(5e-3, 14e-3, 115.385e9, "circular:Rc=0.5", force=4200.0))
    False

    References
    ----------
    docs/stresses.md (the accuracy section).
    """
    if bool(getattr(solution, "edge_loaded", False)):
        return True
    x = np.asarray(solution.x, dtype=float)
    if x.size < 2:
        return False
    width = getattr(solution, "width", None)
    w = (np.asarray(width, dtype=float) if width is not None
         else np.full(x.size, float(x[1] - x[0])))
    lo, hi = x[0] - 0.5 * w[0], x[-1] + 0.5 * w[-1]
    # the margin is half the MEAN slice width: graded slices (fine at the ends) would
    # otherwise shrink it several-fold below the uniform slices of the study that
    # measured the errors, and classify a contact ending 30 um from the end as off it
    h = (hi - lo) / x.size
    start = getattr(solution, "contact_start", None)
    end = getattr(solution, "contact_end", None)
    if start is None or end is None:
        loaded = np.flatnonzero(np.asarray(solution.q) > 0)
        if loaded.size == 0:
            return False
        start = x[loaded[0]] - 0.5 * w[loaded[0]]
        end = x[loaded[-1]] + 0.5 * w[loaded[-1]]
    return bool(min(start - lo, hi - end) < 0.5 * h)


def stress_accuracy(solution, friction=0.0, roller=None, three_d=True):
    """The measured error of the roller stresses for this solution and its note.

    Returns (note, error): error maps each measure to the largest |rt/3D - 1| of
    tables/stress_accuracy.csv for this kind of case (3D-corrected or strips, with or
    without friction, off the ends or edge loaded), None outside the measured range
    (L/D, q/(E* D), tilt, profile, friction), which the note names."""
    cov = _accuracy()
    where = "a 3D field below the 3D BEM pressure (tables/stress_accuracy.csv)"
    what = "3D-corrected stresses" if three_d else "slice (plane-strain) stresses"
    if cov is None:
        return f"the {what}' error against {where} is not known here", None
    outside = []
    if roller is not None:
        D = 2 * roller.radius
        # L/(2R) in the user's terms: R is the contact's effective radius (the
        # roller's on a flat; with a raceway's curvature added otherwise)
        ld = (f"L/(2R) = {roller.length / D:.2g} (roller length L = "
              f"{roller.length * 1e3:.4g} mm, the contact's effective radius R = "
              f"{roller.radius * 1e3:.4g} mm: the roller's L/D on a flat)")
        checks = [(ld, roller.length / D, cov["l_over_d"]),
                  ("mean line load q/(E* 2R) = "
                   f"{solution.force / (roller.length * roller.estar * D):.2g}",
                   solution.force / (roller.length * roller.estar * D), cov["line_load"])]
        outside += [f"{n} (measured {lo:.2g}-{hi:.2g})" for n, v, (lo, hi)
                    in checks if not lo * (1 - 1e-5) <= v <= hi * (1 + 1e-5)]
        key = getattr(roller.profile, "key", None)
        if key not in cov["profiles"]:
            outside.append(f"profile '{key}' (measured: {', '.join(cov['profiles'])})")
    method = getattr(solution, "method", "coupled slices")
    if method != "coupled slices":
        # the study solved every case by ProfiledRoller; another slice model's loads
        # (ISO 16281's uncoupled slices) were not measured against the 3D field
        outside.append(f"slice model '{method}' (measured: the coupled slices of "
                       "linecontact.roller.ProfiledRoller)")
    lo, hi = cov["friction"]
    if not lo <= friction <= hi * (1 + 1e-9):
        outside.append(f"friction = {friction:.3g} (measured {lo:.3g}-{hi:.3g})")
    th = abs(float(getattr(solution, "tilt", 0.0)))
    lo, hi = cov["tilt"]
    if not lo <= th <= hi * (1 + 1e-5):
        outside.append(f"|tilt| = {th:.3g} rad (measured {lo:.3g}-{hi:.3g} rad)")
    edge = reaches_end(solution)
    key = _ERROR_KEYS[(bool(three_d), friction > 0, edge)]
    e = cov["errors"].get(key)
    state = ("contact at (or within half a slice of) a roller end" if edge
             else "contact off the ends") + (", with traction" if friction > 0 else "")
    if e is None:
        outside.append(f"{state} (not measured for the {what})")
        return (f"{'; '.join(outside)}: the {what}' error against {where} is not "
                "known here"), None
    errs = ", ".join(f"{k.replace('_', ' ')} {100 * v:.2g} %" for k, v in e.items())
    if outside:
        return (f"{'; '.join(outside)}: outside the range where the {what} were "
                f"measured against {where}; inside it, {state}: largest errors "
                f"{errs}"), None
    return (f"{what} against {where}, {state}: largest errors {errs} (maximum of each "
            "measure over the roller)"), dict(e)


# ---------------------------------------------------------------- case hardening
def yield_strength_from_hardness(hardness):
    r"""Yield strength of steel from its Vickers hardness (Pavlina & Van Tyne 2008).

    .. math:: \sigma_Y = 2.876\, HV - 90.7 \quad [\mathrm{MPa}]

    Parameters
    ----------
    hardness : array_like
        Vickers hardness HV, 100 <= HV <= 1000 [-].

    Returns
    -------
    ndarray
        Yield strength [Pa].

    Notes
    -----
    A linear correlation fitted to steels (Pavlina & Van Tyne 2008); above about
    700 HV (60 HRC) it is used as an extrapolation of their data and should be
    replaced by the steel's measured strength where known. Valid input
    100 <= HV <= 1000.

    Examples
    --------
    >>> f"{float(yield_strength_from_hardness(700.0)) / 1e6:.0f} MPa"
    '1922 MPa'

    References
    ----------
    E. J. Pavlina, C. J. Van Tyne, J. Materials Engineering and Performance 17 (2008)
    888-893.
    """
    hv = check_interval("hardness", hardness, 100.0, 1000.0, unit="HV")
    return (2.876 * hv - 90.7) * 1e6


class HardnessProfile:
    r"""Hardness against depth of a case-hardened part: a case model or a measured table.

    The case model (ISO 2639 defines the effective case depth CHD as the depth where
    the hardness falls to 550 HV):

    .. math:: HV(z) = HV_c + (HV_s - HV_c)\, \exp\!\left[-\ln\frac{HV_s - HV_c}{550 - HV_c}
              \left(\frac{z}{\mathrm{CHD}}\right)^2\right]

    a smooth profile, flat at the surface, through 550 HV at z = CHD and towards the
    core hardness below; the shape is an assumption (measured profiles differ: give a
    table for a real part).

    Parameters
    ----------
    surface_hardness : float, optional
        HV_s, 550 < HV_s <= 1000 [-].
    case_depth : float, optional
        Effective case depth CHD, 0 < CHD < inf [m].
    core_hardness : float, optional
        HV_c, 100 <= HV_c < 550 and below HV_s [-].
    depths : array_like, optional
        Measured depths (instead of the model), increasing from 0 [m].
    hardness : array_like, optional
        Measured HV at `depths` [-].

    Notes
    -----
    Valid for 100 <= HV_c < 550 < HV_s <= 1000; a table is used only over its depth
    range (no extrapolation).

    Examples
    --------
    >>> h = HardnessProfile(700.0, 1e-3, 350.0)
    >>> f"{float(h(0.0)):.0f} {float(h(1e-3)):.0f} {float(h(3e-3)):.0f}"
    '700 550 352'

    References
    ----------
    ISO 2639:2002 (effective case depth at 550 HV).
    """

    LIMIT = 550.0  #: ISO 2639 limit hardness of the effective case depth [HV]

    def __init__(self, surface_hardness=None, case_depth=None, core_hardness=None, *,
                 depths=None, hardness=None):
        if depths is not None or hardness is not None:
            if depths is None or hardness is None:
                raise ValueError("depths and hardness: give both (a measured profile) "
                                 "or neither")
            z = np.asarray(depths, dtype=float)
            h = check_interval("hardness", hardness, 100.0, 1000.0, unit="HV")
            if z.ndim != 1 or z.size < 2 or z.shape != h.shape:
                raise ValueError(f"depths and hardness: two 1-D arrays of the same length "
                                 f">= 2, got shapes {z.shape} and {h.shape}")
            check_interval("depths", z, 0.0, np.inf, unit="m")
            if np.any(np.diff(z) <= 0):
                raise ValueError("depths must increase strictly")
            self.depths, self.hardness = z, h
            self.surface_hardness, self.core_hardness = float(h[0]), float(h[-1])
            self.case_depth = None
            return
        hs = float(check_interval("surface_hardness", surface_hardness, self.LIMIT,
                                  1000.0, low_open=True, unit="HV",
                                  hint="the effective case depth is where HV = 550"))
        hc = float(check_interval("core_hardness", core_hardness, 100.0, self.LIMIT,
                                  high_open=True, unit="HV",
                                  hint="the core must be softer than the 550 HV case limit"
                                       " and the surface"))
        self.case_depth = float(check_positive("case_depth", case_depth, "m"))
        self.surface_hardness, self.core_hardness = hs, hc
        self.depths = self.hardness = None

    def with_case_depth(self, case_depth):
        """The same model with another effective case depth [m]."""
        return HardnessProfile(self.surface_hardness, case_depth, self.core_hardness)

    def __call__(self, z):
        """HV at depths z [m]."""
        z = check_interval("z", z, 0.0, np.inf, unit="m")
        if self.depths is not None:
            check_interval("z", z, self.depths[0], self.depths[-1], unit="m",
                           hint="the measured hardness profile does not reach this depth")
            return np.interp(z, self.depths, self.hardness)
        hs, hc, c = self.surface_hardness, self.core_hardness, self.case_depth
        k = math.log((hs - hc) / (self.LIMIT - hc))
        return hc + (hs - hc) * np.exp(-k * (z / c) ** 2)


@dataclass(frozen=True)
class CaseCheck:
    """The case-hardening check: stress over allowable against depth.

    Returned by :func:`case_check`; not built by hand.

    Parameters
    ----------
    measure : str
        The stress measure compared (``tresca`` or ``von_mises``).
    depths : ndarray
        Depths [m].
    stress : ndarray
        Envelope of the measure over y at each depth, below the worst slice [Pa].
    allowable : ndarray
        Allowable stress at each depth [Pa].
    ratio : ndarray
        stress / allowable [-].
    max_ratio : float
        Largest ratio [-].
    depth_at_max : float
        Where it occurs [m].
    min_case_depth : float or None
        The smallest effective case depth with max_ratio <= 1 for this load (same
        surface and core hardness), None for a measured profile or when even the
        surface hardness throughout does not suffice [m].
    conversion : str
        The stated hardness-to-allowable conversion.

    Notes
    -----
    Valid as the stresses and the hardness profile it was made from.

    Examples
    --------
    >>> s = line_contact_stresses(4000.0, 5e-3, 10e-3, 115.385e9)
    >>> c = case_check(s, HardnessProfile(700.0, 0.3e-3, 350.0))
    >>> f"{c.max_ratio:.2f} at {c.depth_at_max * 1e6:.0f} um"
    '0.52 at 119 um'
    """

    measure: str
    depths: np.ndarray
    stress: np.ndarray
    allowable: np.ndarray
    ratio: np.ndarray
    max_ratio: float
    depth_at_max: float
    min_case_depth: object
    conversion: str


_CONVERSION = ("allowable = {f} x yield strength, yield strength = 2.876 HV - 90.7 MPa "
               "(Pavlina & Van Tyne 2008); {m} yield criterion")


def case_check(stresses, hardness, depths=None, measure="von_mises"):
    r"""Stress over allowable against depth for a case-hardened part, and the minimum
    effective case depth for the load.

    .. math:: r(z) = \frac{\max_y \sigma_{eq}(y, z)}{f\,\sigma_Y(HV(z))}, \qquad
              \sigma_Y = 2.876\,HV - 90.7\ \mathrm{MPa}

    with f = 1 for von Mises and f = 1/2 for Tresca (the yield criteria).

    Parameters
    ----------
    stresses : SubsurfaceStresses
        From :func:`line_contact_stresses` or :func:`roller_stresses` (the worst slice
        of the measure is checked).
    hardness : HardnessProfile
        The hardness against depth.
    depths : array_like, optional
        Depth grid, 0 <= z [m]; it must reach below the stress maximum (default: 400
        points to the deeper of 4 times the maximum's depth and 3 times the case depth).
    measure : str, optional
        ``"von_mises"`` (default) or ``"tresca"``.

    Returns
    -------
    CaseCheck

    Notes
    -----
    Valid as the stresses and the hardness profile (100 <= HV <= 1000). The minimum
    case depth is found by bisection on the case model's CHD (the ratio at every depth
    falls as CHD grows, the hardness model being increasing in CHD).

    Examples
    --------
    >>> s = line_contact_stresses(4000.0, 5e-3, 10e-3, 115.385e9)
    >>> c = case_check(s, HardnessProfile(700.0, 0.3e-3, 350.0), measure="tresca")
    >>> f"{c.max_ratio:.2f}, minimum CHD {c.min_case_depth * 1e6:.0f} um"
    '0.56, minimum CHD 74 um'

    References
    ----------
    E. J. Pavlina, C. J. Van Tyne (2008); ISO 2639:2002 (effective case depth).
    """
    if measure not in _ALLOWABLE_FACTOR:
        raise ValueError(f"measure = {measure!r} is not one of "
                         f"{tuple(_ALLOWABLE_FACTOR)} (the yield criteria)")
    w = stresses.worst[measure]
    z_max = w["z"]
    if depths is None:
        deep = 4 * z_max + (3 * hardness.case_depth if hardness.case_depth else 0.0)
        if hardness.depths is not None:
            deep = min(max(4 * z_max, 1e-9), hardness.depths[-1])
        depths = np.linspace(0.0, deep, 400)
    z = np.atleast_1d(check_interval("depths", depths, 0.0, np.inf, unit="m"))
    if z.max() < z_max * (1 + 1e-9) or (z_max > 0 and z.max() < 1.25 * z_max):
        raise OutOfRangeError("depths", float(z.max()), f"[{1.25 * z_max:.6g}, inf) m",
                              unit="m", where="the deepest point",
                              hint=f"the {measure} maximum lies at z = {z_max:.6g} m: "
                                   "the grid must reach below it")
    f = _ALLOWABLE_FACTOR[measure]
    sig = stresses.depth_envelope(measure, z)

    def ratio_for(h):
        allow = f * yield_strength_from_hardness(h(z))
        return sig / allow, allow

    ratio, allow = ratio_for(hardness)
    k = int(np.argmax(ratio))
    min_chd = None
    if hardness.case_depth is not None:
        hi = hardness.case_depth
        top = hardness.surface_hardness
        if float(np.max(sig / (f * yield_strength_from_hardness(top)))) <= 1.0:
            lo = 0.0
            while ratio_for(hardness.with_case_depth(hi))[0].max() > 1.0:
                lo, hi = hi, 2 * hi
            lo = lo if lo > 0 else hi * 1e-6
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if ratio_for(hardness.with_case_depth(mid))[0].max() > 1.0:
                    lo = mid
                else:
                    hi = mid
                if hi - lo < 1e-4 * hi:
                    break
            min_chd = hi
    name = "von Mises" if measure == "von_mises" else "Tresca"
    return CaseCheck(measure, z, sig, allow, ratio, float(ratio[k]), float(z[k]), min_chd,
                     _CONVERSION.format(f=f, m=name))


# An unknown keyword names the valid ones and the close match (docs/inputs.md).
from .validity import refuse_unknown_keywords  # noqa: E402
refuse_unknown_keywords(globals())
