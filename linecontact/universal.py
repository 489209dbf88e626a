r"""The universal curve: the default model of a straight finite cylinder.

With the parabolic gap :math:`h = y^2/(2R)` the contact problem of a rigid cylinder of
radius R and length L depends on the dimensionless depth :math:`\tilde d = d R/L^2`
alone (SPEC section 5), so that for every L/R

.. math::

    F = \frac{E^* L^3}{R}\,\Psi(\tilde d), \qquad
    k = \frac{dF}{dd} = E^* L\,\Psi'(\tilde d), \qquad
    a = \frac{k}{2E^*} = \frac{L}{2}\Psi'(\tilde d),

and the MDR profile (Popov & Hess 2015; Li & Popov 2017, Eq. 7 is a two-parameter
approximation of it) is :math:`g(x) = (L^2/R)\,\Phi(x/L)`, where
:math:`\Phi(\Psi'(\tilde d)/2) = \tilde d`.

:math:`\Psi` is tabulated once, by this package's boundary-element solver, in
``tables/universal_curve.csv`` (written by ``python -m tools.build_tables universal``;
its header states grid, tolerance, date, code version and accuracy). Here it is
evaluated through the cubic spline of :math:`\ln\Psi` against :math:`\ln\tilde d`
(smooth; :math:`\Psi` and :math:`\Psi'` increase along it, which a test checks), so
F, d(F), k and the profile are mutually consistent: k is the exact derivative of F.

Outside the table:

- below its smallest depth, the curve continues with Eq. 7 of Li & Popov (2017) with
  :math:`\alpha = \pi/2` (the 2D log law) and :math:`\beta` = the table's
  ``beta_small``, the effective beta at its smallest depth, which makes F continuous;
  the table header states the error this continuation makes per decade;
- beyond its largest depth, every function raises
  :class:`~linecontact.validity.OutOfRangeError`.

The parabolic gap is exact only for d << R (soft rollers pressed deep need the
circular profile); the accuracy study in tables/README.md covers d/R <= 0.15.
"""
from __future__ import annotations

import functools
import math

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.special import lambertw

from .models import ContactModel, register
from .tables import read_table, table_path
from .validity import OutOfRangeError, check_interval, out

__all__ = ["UniversalCurve", "UniversalModel", "universal_curve"]

TABLE = "universal_curve"


class UniversalCurve:
    r"""The dimensionless curve :math:`\Psi(\tilde d)` from a table, with its inverses.

    Parameters
    ----------
    table : linecontact.tables.Table
        A table with columns ``d_tilde``, ``Psi`` and metadata ``beta_small``.

    Examples
    --------
    >>> c = universal_curve()
    >>> bool(c.d_min < 1e-9 and c.d_max >= 20)
    True
    >>> float(c.depth_of_psi(c.psi(0.01)))  # doctest: +ELLIPSIS
    0.01...
    """

    alpha_small = math.pi / 2

    def __init__(self, table):
        cols = table.columns
        for name in ("d_tilde", "Psi"):
            if name not in cols:
                raise ValueError(f"table {table.path} has no column {name!r}")
        self.table = table
        self._z = np.log(cols["d_tilde"])
        self._lnpsi = np.log(cols["Psi"])
        self._spline = CubicSpline(self._z, self._lnpsi)
        self._slope = self._spline.derivative(1)
        self._curv = self._spline.derivative(2)
        self.d_min = float(cols["d_tilde"][0])
        self.d_max = float(cols["d_tilde"][-1])
        self.psi_min = float(cols["Psi"][0])
        self.psi_max = float(cols["Psi"][-1])
        self.beta_small = float(table.meta["beta_small"])
        self.x_min = float(self.dpsi(self.d_min)) / 2
        self.x_max = float(self.dpsi(self.d_max)) / 2

    # -- forward -----------------------------------------------------------------
    def _check_depth(self, d_tilde):
        d = np.asarray(d_tilde, dtype=float)
        if np.any(d > self.d_max):
            raise OutOfRangeError("d_tilde", float(d[d > self.d_max].flat[0]),
                                  f"(0, {self.d_max:g}]",
                                  hint="beyond the largest depth of the universal table")
        return d

    def _small(self, d):
        """Eq. 7 with alpha = pi/2, beta = beta_small: u from d~ = beta (u+1) e^-u."""
        w = lambertw(-d / (self.beta_small * math.e), k=-1)
        return -1.0 - np.real(w)

    def psi(self, d_tilde):
        r""":math:`\Psi = F R/(E^* L^3)` at :math:`\tilde d = d R/L^2` [-]."""
        d = self._check_depth(d_tilde)
        flat = np.atleast_1d(d).ravel()
        res = np.empty_like(flat)
        small = flat < self.d_min
        res[~small] = np.exp(self._spline(np.log(flat[~small])))
        u = self._small(flat[small])
        res[small] = 2 * self.alpha_small * self.beta_small * np.exp(-u)
        return res.reshape(d.shape)

    def dpsi(self, d_tilde):
        r""":math:`\Psi' = k/(E^* L)` at :math:`\tilde d` [-]."""
        d = self._check_depth(d_tilde)
        flat = np.atleast_1d(d).ravel()
        res = np.empty_like(flat)
        small = flat < self.d_min
        z = np.log(flat[~small])
        res[~small] = np.exp(self._spline(z) - z) * self._slope(z)
        res[small] = 2 * self.alpha_small / self._small(flat[small])
        return res.reshape(d.shape)

    # -- inverses ------------------------------------------------------------------
    def _newton(self, target, fun, dfun, z0, lo, hi):
        z = np.clip(z0, lo, hi)
        for _ in range(50):
            step = (fun(z) - target) / dfun(z)
            z = np.clip(z - step, lo, hi)
            if np.all(np.abs(step) < 1e-14):
                break
        return z

    def depth_of_psi(self, psi):
        r""":math:`\tilde d` at which :math:`\Psi` takes the given value [-]."""
        p = np.asarray(psi, dtype=float)
        if np.any(p > self.psi_max):
            raise OutOfRangeError("Psi", float(p[p > self.psi_max].flat[0]),
                                  f"(0, {self.psi_max:g}]",
                                  hint="beyond the largest depth of the universal table")
        small = p < self.psi_min
        lp = np.log(np.where(small, self.psi_min, p))
        z0 = np.interp(lp, self._lnpsi, self._z)
        z = self._newton(lp, self._spline, self._slope, z0, self._z[0], self._z[-1])
        d = np.exp(z)
        if np.any(small):
            ps = np.where(small, p, self.psi_min)
            d_small = ps / (2 * self.alpha_small) * (
                1 + np.log(2 * self.alpha_small * self.beta_small / ps))
            d = np.where(small, d_small, d)
        return d

    def depth_of_x(self, x_tilde):
        r"""MDR profile :math:`\Phi(\tilde x) = \tilde d` with :math:`\Psi'(\tilde d)/2 = \tilde x` [-]."""
        x = np.asarray(x_tilde, dtype=float)
        if np.any(x > self.x_max):
            raise OutOfRangeError("x_tilde", float(x[x > self.x_max].flat[0]),
                                  f"[0, {self.x_max:.6g}]",
                                  hint="beyond the MDR contact radius at the largest "
                                       "depth of the universal table")
        small = x < self.x_min
        lx = np.log(2 * np.where(small, self.x_min, x))

        def ln_dpsi(z):
            return self._spline(z) - z + np.log(self._slope(z))

        def d_ln_dpsi(z):
            return self._slope(z) - 1 + self._curv(z) / self._slope(z)

        zs = self._z
        z0 = np.interp(lx, ln_dpsi(zs), zs)
        z = self._newton(lx, ln_dpsi, d_ln_dpsi, z0, zs[0], zs[-1])
        d = np.exp(z)
        if np.any(small):
            xs = np.where(small & (x > 0), x, self.x_min)
            u = self.alpha_small / xs
            d_small = np.where(x > 0, self.beta_small * (u + 1) * np.exp(-u), 0.0)
            d = np.where(small, d_small, d)
        return d


@functools.lru_cache(maxsize=None)
def universal_curve(name=TABLE):
    """The :class:`UniversalCurve` of ``tables/<name>.csv``, read once and cached."""
    return UniversalCurve(read_table(name))


@register
class UniversalModel(ContactModel):
    r"""The BEM universal curve for one cylinder (the default model).

    .. math::

        F = \frac{E^* L^3}{R}\Psi\!\left(\frac{dR}{L^2}\right),\quad
        k = E^* L\,\Psi'\!\left(\frac{dR}{L^2}\right),\quad
        a = \frac{k}{2E^*},\quad g(x) = \frac{L^2}{R}\Phi\!\left(\frac{x}{L}\right)

    Parameters
    ----------
    radius : float
        Cylinder radius R [m].
    length : float
        Cylinder length L [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].
    table : str, optional
        Name of the table in tables/ (default ``"universal_curve"``).

    Notes
    -----
    Valid for any L/R and for 0 < d <= d~_max L^2/R, d~_max the table's largest
    dimensionless depth (30 for the shipped table); below the table's smallest depth
    the small-depth asymptote continues it (see the module docstring). Accuracy: the
    table header's ``accuracy`` line (BEM discretisation) plus the parabolic
    approximation of the circle, which needs d << R.

    Examples
    --------
    Steel on steel (E* = 115.4 GPa), R = 5 mm, L = 10 mm, F = 1 kN (a value of the
    shipped table; the Li-Popov form gives 3.055 um with Table 1, 3.147 um with Eq. 11,
    Eq. 2 gives 3.363 um):

    >>> m = UniversalModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.3f} um", f"{m.stiffness_at_force(1e3) / 1e6:.1f} N/um"
    ('3.154 um', '347.9 N/um')
    >>> bool(abs(m.force(m.depth(1e3)) / 1e3 - 1) < 1e-12)
    True

    References
    ----------
    Li, Q., Popov, V. L. (2017). Normal line contact of finite-length cylinders.
    Facta Universitatis, Series Mechanical Engineering 15(1), 63-71.
    """

    key = "universal"
    label = "Universal curve (BEM)"

    def __init__(self, radius, length, estar, table=TABLE):
        super().__init__(radius, length, estar)
        self.table_name = table
        self.curve = universal_curve(table)

    @classmethod
    def available(cls, table=TABLE):
        """True if the table exists in this installation."""
        try:
            return table_path(table).is_file()
        except (FileNotFoundError, OSError):
            return False

    @property
    def provenance(self):
        meta = dict(self.curve.table.meta)
        meta["model"] = self.label
        meta["table"] = str(self.curve.table.path.name)
        return meta

    # scales
    @property
    def _dscale(self):
        return self.length ** 2 / self.radius

    @property
    def _fscale(self):
        return self.estar * self.length ** 3 / self.radius

    @property
    def depth_limit(self):
        """Largest depth covered by the table, d~_max L^2/R [m]."""
        return self.curve.d_max * self._dscale

    @property
    def force_limit(self):
        """Force at :attr:`depth_limit` [N]."""
        return self.curve.psi_max * self._fscale

    def _scaled(self, name, value, unit, scale, table_end, symbol):
        """`value` / `scale` after checking 0 < value <= table_end * scale."""
        v = check_interval(name, value, 0.0, table_end * scale, low_open=True, unit=unit,
                           hint=f"the universal table ends at {symbol} = {table_end:.6g}")
        return v / scale

    def _dt(self, depth):
        return self._scaled("depth", depth, "m", self._dscale, self.curve.d_max, "d R/L^2")

    def _psi_of_force(self, force):
        return self._scaled("force", force, "N", self._fscale, self.curve.psi_max,
                            "F R/(E* L^3)")

    def force(self, depth):
        """F(d) [N]; depth [m]."""
        return out(self.curve.psi(self._dt(depth)) * self._fscale)

    def depth(self, force):
        """d(F) [m]; force [N]."""
        return out(self.curve.depth_of_psi(self._psi_of_force(force)) * self._dscale)

    def stiffness(self, depth):
        """k(d) = dF/dd [N/m]; depth [m]."""
        return out(self.curve.dpsi(self._dt(depth)) * self.estar * self.length)

    def profile(self, x):
        """MDR profile g(x) [m] for 0 <= x <= the MDR radius at the table's end [m]."""
        xv = np.asarray(x, dtype=float)
        if np.any(~np.isfinite(xv)) or np.any(xv < 0):
            bad = float(xv[~(np.isfinite(xv) & (xv >= 0))].flat[0]) if xv.ndim else float(xv)
            raise OutOfRangeError("x", bad, "[0, inf) m", unit="m")
        try:
            return out(self.curve.depth_of_x(xv / self.length) * self._dscale)
        except OutOfRangeError as exc:
            raise OutOfRangeError("x", float(exc.value) * self.length,
                                  f"[0, {self.curve.x_max * self.length:.6g}] m", unit="m",
                                  hint=exc.hint) from None
