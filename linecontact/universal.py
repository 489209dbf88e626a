r"""The universal curve: the default model of a straight finite cylinder.

With the parabolic gap :math:`h = y^2/(2R)` the contact problem of a rigid cylinder of
radius R and length L depends on the dimensionless depth :math:`\tilde d = d R/L^2`
alone (docs/theory.md, section 'Self-similarity'), so that for every L/R

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
  ``beta_small``, the effective beta at its smallest depth, which makes F continuous
  (evaluated by the closed forms of :mod:`linecontact.lipopov`,
  :func:`~linecontact.lipopov.dimensionless_force` and its kin); the table header
  states the error this continuation makes per decade;
- beyond its largest depth, every function raises
  :class:`~linecontact.errors.OutOfRangeError`.

The model built on the curve, registered under ``"universal"`` like every other model,
is :class:`linecontact.models.UniversalModel`.

The parabolic gap is exact only for d << R (soft rollers pressed deep need the
circular profile); the accuracy study in tables/README.md covers d/R <= 0.15.
"""
from __future__ import annotations

import math
import os

import numpy as np

from . import tables as _tables
from ._numerics import NotAKnotSpline, blockwise
from .checks import Interval, check_interval
from .lipopov import (dimensionless_depth, dimensionless_force, dimensionless_profile,
                      dimensionless_stiffness)
from .tables import read_table, table_path

__all__ = ["DEPTH_OVER_RADIUS", "TABLE", "UniversalCurve", "universal_curve"]

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

    Notes
    -----
    Valid for 0 < d~ <= d_max, the table's largest dimensionless depth (30 for the
    shipped table); a larger d~ raises :class:`~linecontact.errors.OutOfRangeError`.
    Between the table's smallest depth d_min and d_max, Psi is the cubic spline of
    ln Psi against ln d~; below d_min, Eq. 7 with alpha = pi/2 and beta = ``beta_small``
    continues it (see the module docstring).

    Examples
    --------
    >>> c = universal_curve()
    >>> bool(c.d_min < 1e-9 and c.d_max >= 20)
    True
    >>> float(c.depth_of_psi(c.psi(0.01)))  # doctest: +ELLIPSIS
    0.01...

    References
    ----------
    .. [1] docs/theory.md, sections 'Self-similarity' and 'BEM'.
    .. [2] Li & Popov (2017) [li-popov-2017], Eq. 7.
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
        self.d_min = float(cols["d_tilde"][0])
        self.d_max = float(cols["d_tilde"][-1])
        # the spline's own end values (equal to the table's to rounding), so that the
        # forward and inverse functions share their range exactly
        self.psi_min = float(np.exp(self._spline(self._z[0])))
        self.psi_max = float(np.exp(self._spline(self._z[-1])))
        self.beta_small = float(table.meta["beta_small"])
        self.x_min = float(self.dpsi(self.d_min)) / 2
        self.x_max = float(self.dpsi(self.d_max)) / 2

    # methods, not lambdas stored on the instance: a curve (and a model holding one)
    # pickles, e.g. to the workers of a process pool
    def _slope(self, z):
        return self._spline(z, 1)

    def _curv(self, z):
        return self._spline(z, 2)

    # -- forward -----------------------------------------------------------------
    def _check_depth(self, d_tilde):
        return check_interval("d_tilde", d_tilde, 0.0, self.d_max, low_open=True,
                              hint="the universal table ends there")

    def _evaluate(self, d_tilde, on_table, below_table):
        """on_table(d) where d~ >= d_min, below_table(d) under it; any input shape."""
        d = self._check_depth(d_tilde)
        if d.ndim and d.size and d.min() >= self.d_min:     # all on the table
            return blockwise(on_table, d)
        flat = np.atleast_1d(d).ravel()
        res = np.empty_like(flat)
        small = flat < self.d_min
        if not small.all():
            res[~small] = on_table(flat[~small])
        if small.any():
            res[small] = below_table(flat[small])
        return res.reshape(d.shape)

    def psi(self, d_tilde):
        r""":math:`\Psi = F R/(E^* L^3)` at :math:`\tilde d = d R/L^2` [-]."""
        return self._evaluate(
            d_tilde, self.on_table_psi,
            lambda d: dimensionless_force(d, self.alpha_small, self.beta_small))

    def on_table_psi(self, d_tilde):
        r""":math:`\Psi` at values of :math:`\tilde d` that lie in [d_min, d_max] (not
        checked: for callers that have checked them and fuse this elementwise function
        with their own scaling in blocks, as the universal model's F(d) does)."""
        x = self._spline(np.log(d_tilde))
        return np.exp(x, out=x)

    def dpsi(self, d_tilde):
        r""":math:`\Psi' = k/(E^* L)` at :math:`\tilde d` [-]."""
        def on_table(d):
            z = np.log(d)
            return np.exp(self._spline(z) - z) * self._slope(z)

        return self._evaluate(
            d_tilde, on_table,
            lambda d: dimensionless_stiffness(d, self.alpha_small, self.beta_small))

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
        on_table = self.on_table_depth

        if p.ndim and p.size and p.min() >= self.psi_min:     # all on the table
            return blockwise(on_table, p)
        small = p < self.psi_min
        d = on_table(np.where(small, self.psi_min, p))
        if np.any(small):
            ps = np.where(small, p, self.psi_min)
            d = np.where(small, dimensionless_depth(ps, self.alpha_small, self.beta_small),
                         d)
        return d

    def on_table_depth(self, psi):
        r""":math:`\tilde d` at values of :math:`\Psi` that lie in [psi_min, psi_max]
        (not checked: for callers that have checked them, and fuse this elementwise
        function with their own scaling in blocks, as the universal model's d(F) does).

        A tabulated inverse of the spline, polished by one Newton step on the spline
        (:meth:`linecontact._numerics.NotAKnotSpline.solve_fast`)."""
        if not hasattr(self, "_inverse"):
            self._inverse = self._spline.inverse_table()
        x = self._spline.solve_fast(np.log(psi), self._inverse)
        np.exp(x, out=x)
        return np.minimum(x, self.d_max, out=x)      # exp(ln d_max) may round above

    def depth_of_x(self, x_tilde):
        r"""MDR profile :math:`\Phi(\tilde x) = \tilde d` with :math:`\Psi'(\tilde d)/2 = \tilde x` [-]."""
        # 1e-12 rounding allowance at the closed end (x~ computed as k/(2 E* L) from
        # physical values), as checks.Interval's rtol
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
            xs = np.where(small, x, self.x_min)   # g~(0) = 0: the profile's own end
            d = np.where(small, dimensionless_profile(xs, self.alpha_small,
                                                      self.beta_small), d)
        return d


_CACHE: dict = {}


def universal_curve(name=TABLE):
    """The :class:`UniversalCurve` of ``tables/<name>.csv``, read once per file version.

    Parameters
    ----------
    name : str
        Table stem in tables/ (default ``"universal_curve"``) [-].

    Returns
    -------
    UniversalCurve

    Raises
    ------
    FileNotFoundError
        The table file is missing; the message names the file and how to regenerate it.

    Notes
    -----
    Cached per (path, modification time), so a table regenerated while a process runs
    is picked up, as for the Li-Popov coefficient tables.

    Examples
    --------
    >>> universal_curve().table.path.name
    'universal_curve.csv'
    """
    try:
        path = table_path(name)
    except FileNotFoundError:
        try:
            where = str(_tables.tables_dir() / f"{name}.csv")
        except FileNotFoundError as exc:   # no tables directory at all
            where = f"{name}.csv ({exc})"
        raise FileNotFoundError(
            f"table file {where} not found: the universal-curve model (the default) "
            "needs it; regenerate it with 'python -m tools.build_tables universal' "
            "or reinstall linecontact") from None
    key = (str(path), os.stat(path).st_mtime_ns)
    if key not in _CACHE:
        _CACHE[key] = UniversalCurve(read_table(name))
    return _CACHE[key]
