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
from ._numerics import NotAKnotSpline
from .lipopov import _u_from_depth_ratio
from .models import ContactModel, register
from .tables import read_table, table_path
from .validity import Interval, OutOfRangeError, check_interval, document, out

__all__ = ["UniversalCurve", "UniversalModel", "universal_curve"]

TABLE = "universal_curve"

#: Depths beyond this fraction of R are refused unless asked for (extrapolate=True): the
#: range of the accuracy study, where y^2/(2R) stands in for the circle.
DEPTH_OVER_RADIUS = Interval("d/R", 0.0, 0.15, low_open=True)


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
        spline = NotAKnotSpline(self._z, self._lnpsi)
        self._spline = spline
        self._slope = lambda z: spline(z, 1)
        self._curv = lambda z: spline(z, 2)
        self.d_min = float(cols["d_tilde"][0])
        self.d_max = float(cols["d_tilde"][-1])
        # the spline's own end values (equal to the table's to rounding), so that the
        # forward and inverse functions share their range exactly
        self.psi_min = float(np.exp(self._spline(self._z[0])))
        self.psi_max = float(np.exp(self._spline(self._z[-1])))
        self.beta_small = float(table.meta["beta_small"])
        self.x_min = float(self.dpsi(self.d_min)) / 2
        self.x_max = float(self.dpsi(self.d_max)) / 2

    # -- forward -----------------------------------------------------------------
    def _check_depth(self, d_tilde):
        return check_interval("d_tilde", d_tilde, 0.0, self.d_max, low_open=True,
                              hint="the universal table ends there")

    def _small(self, d):
        """Eq. 7 with alpha = pi/2, beta = beta_small: u from d~ = beta (u+1) e^-u."""
        return _u_from_depth_ratio(d / self.beta_small)

    def _evaluate(self, d_tilde, on_table, below_table):
        """on_table(d) where d~ >= d_min, below_table(d) under it; any input shape."""
        d = self._check_depth(d_tilde)
        flat = np.atleast_1d(d).ravel()
        res = np.empty_like(flat)
        small = flat < self.d_min
        res[~small] = on_table(flat[~small])
        res[small] = below_table(flat[small])
        return res.reshape(d.shape)

    def psi(self, d_tilde):
        r""":math:`\Psi = F R/(E^* L^3)` at :math:`\tilde d = d R/L^2` [-]."""
        return self._evaluate(
            d_tilde, lambda d: np.exp(self._spline(np.log(d))),
            lambda d: 2 * self.alpha_small * self.beta_small * np.exp(-self._small(d)))

    def dpsi(self, d_tilde):
        r""":math:`\Psi' = k/(E^* L)` at :math:`\tilde d` [-]."""
        def on_table(d):
            z = np.log(d)
            return np.exp(self._spline(z) - z) * self._slope(z)

        return self._evaluate(d_tilde, on_table,
                              lambda d: 2 * self.alpha_small / self._small(d))

    # -- inverses ------------------------------------------------------------------
    def _newton(self, target, fun, dfun, z0, lo, hi):
        z = np.clip(z0, lo, hi)
        floor = 1e-14 * np.maximum(1.0, np.abs(z))   # rounding floor of a step in ln d~
        for _ in range(50):
            step = (fun(z) - target) / dfun(z)
            z = np.clip(z - step, lo, hi)
            if np.all(np.abs(step) <= floor):
                return z
        if np.max(np.abs(step)) < 1e-10:   # stalled at rounding: d~ good to 1e-10
            return z
        raise RuntimeError("Newton inversion of the universal curve did not converge "
                           f"(last step {np.max(np.abs(step)):.3g} in ln d~)")

    def depth_of_psi(self, psi):
        r""":math:`\tilde d` at which :math:`\Psi` takes the given value [-]."""
        p = check_interval("Psi", psi, 0.0, self.psi_max, low_open=True,
                           hint="the universal table ends there")
        small = p < self.psi_min
        lp = np.log(np.where(small, self.psi_min, p))
        z0 = np.interp(lp, self._lnpsi, self._z)
        z = self._newton(lp, self._spline, self._slope, z0, self._z[0], self._z[-1])
        d = np.minimum(np.exp(z), self.d_max)   # exp(ln d_max) may round above d_max
        if np.any(small):
            ps = np.where(small, p, self.psi_min)
            d_small = ps / (2 * self.alpha_small) * (
                1 + np.log(2 * self.alpha_small * self.beta_small / ps))
            d = np.where(small, d_small, d)
        return d

    def depth_of_x(self, x_tilde):
        r"""MDR profile :math:`\Phi(\tilde x) = \tilde d` with :math:`\Psi'(\tilde d)/2 = \tilde x` [-]."""
        # 1e-12 rounding allowance at the closed end (x~ computed as k/(2 E* L) from
        # physical values), as validity.Interval's rtol
        x = check_interval("x_tilde", x_tilde, 0.0, self.x_max * (1 + 1e-12),
                           hint="beyond the MDR contact radius at the largest depth of "
                                "the universal table")
        x = np.minimum(x, self.x_max)
        small = x < self.x_min
        lx = np.log(2 * np.where(small, self.x_min, x))

        def ln_dpsi(z):
            return self._spline(z) - z + np.log(self._slope(z))

        def d_ln_dpsi(z):
            return self._slope(z) - 1 + self._curv(z) / self._slope(z)

        zs = self._z
        z0 = np.interp(lx, ln_dpsi(zs), zs)
        z = self._newton(lx, ln_dpsi, d_ln_dpsi, z0, zs[0], zs[-1])
        d = np.minimum(np.exp(z), self.d_max)
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
@document(DR=DEPTH_OVER_RADIUS)
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
    extrapolate : bool, optional
        Accept depths beyond %(DR)s, up to the table's end (default False).

    Notes
    -----
    Valid for any L/R and for 0 < d <= min(d~_max L^2/R, 0.15 R): d~_max is the
    table's largest dimensionless depth (30 for the shipped table), and %(DR)s is the
    range over which the accuracy study compared the models, within which the parabolic
    gap y^2/(2R) stands in for the circle (it needs d << R). Beyond it a depth is
    refused unless ``extrapolate=True``. Below the table's smallest depth the
    small-depth asymptote continues the curve (see the module docstring). Accuracy: the
    table header's ``accuracy`` line (BEM discretisation) plus the parabolic
    approximation.

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

    def __init__(self, radius, length, estar, table=TABLE, extrapolate=False):
        super().__init__(radius, length, estar)
        self.table_name = table
        self.extrapolate = bool(extrapolate)
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
    def _radius_limited(self):
        """True when d <= 0.15 R, not the table's end, bounds the depth."""
        return (not self.extrapolate
                and DEPTH_OVER_RADIUS.high * self.radius < self.curve.d_max * self._dscale)

    @property
    def depth_limit(self):
        """Largest accepted depth [m]: the table's end d~_max L^2/R, and (unless
        ``extrapolate``) 0.15 R."""
        if self._radius_limited:
            return DEPTH_OVER_RADIUS.high * self.radius
        return self.curve.d_max * self._dscale

    @property
    def force_limit(self):
        """Force at :attr:`depth_limit` [N]."""
        return float(self.curve.psi(self.depth_limit / self._dscale)) * self._fscale

    def _limit_hint(self):
        if self._radius_limited:
            return (f"d/R <= {DEPTH_OVER_RADIUS.high:g}: the parabolic gap y^2/(2R) stands "
                    "in for the circle only for d << R (extrapolate=True accepts depths up "
                    f"to the table's end, d R/L^2 = {self.curve.d_max:g})")
        return f"the universal table ends at d R/L^2 = {self.curve.d_max:g}"

    def _dt(self, depth):
        d = check_interval("depth", depth, 0.0, self.depth_limit, low_open=True, unit="m",
                           hint=self._limit_hint())
        return d / self._dscale

    def _psi_of_force(self, force):
        F = check_interval("force", force, 0.0, self.force_limit, low_open=True, unit="N",
                           hint=self._limit_hint())
        # F <= force_limit was checked; F/scale may still round above psi_max at the end
        return np.minimum(F / self._fscale, self.curve.psi(self.depth_limit / self._dscale))

    def force(self, depth):
        """F(d) [N]; depth [m]."""
        return out(self.curve.psi(self._dt(depth)) * self._fscale)

    def depth(self, force):
        """d(F) [m]; force [N]."""
        d = self.curve.depth_of_psi(self._psi_of_force(force)) * self._dscale
        return out(np.minimum(d, self.depth_limit))   # rounding at the closed end only

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
