r"""The finite cylinder's BEM table of the full-stick k_t/k_n: its reader and ratios.

``tables/tangential_cylinder.csv`` (written by ``python -m tools.build_tables
tangential`` from the tangential BEM study) gives the full-stick stiffness ratio of a
rigid straight cylinder across and along its axis against nu and d~ = d R/L^2, and
optionally the partial-slip correction of the shift;
:class:`CylinderTangentialTable` reads and interpolates it,
:func:`cylinder_stiffness_ratios` gives the ratios of a model's cylinder.

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapter 4.
"""
from __future__ import annotations

import functools
import re

import numpy as np

from .._numerics import out
from ..checks import Interval, check_positive
from ..errors import OutOfRangeError, UnknownNameError
from ..tables import TableError, read_table
from .moduli import equivalent_poisson, mdr_stiffness_ratio

__all__ = [
    "CylinderTangentialTable",
    "cylinder_tangential_table",
    "cylinder_stiffness_ratios",
    "STRAIGHT_CYLINDER_MODELS",
    "TANGENTIAL_TABLE",
]

#: Name of the BEM table of the finite cylinder's tangential stiffness (tables/).
TANGENTIAL_TABLE = "tangential_cylinder"

#: Models of a straight (unprofiled, aligned) cylinder, to which the BEM table applies.
STRAIGHT_CYLINDER_MODELS = frozenset({"universal", "li-popov", "puttock-thwaite",
                                      "johnson", "kunz", "palmgren", "iso16281"})
_DIRECTIONS = ("across", "along")


_SHIFT_COLUMN = re.compile(r"^shift_ratio_(across|along)_q([0-9.]+)$")


class CylinderTangentialTable:
    r"""The BEM table of the finite cylinder's full-stick k_t/k_n, interpolated.

    The table (``tables/tangential_cylinder.csv``, written by
    ``python -m tools.build_tables`` from the tangential BEM study) has one row per
    (nu, d~ = d R/L^2) on a regular grid, with columns ``nu``, ``d_tilde``,
    ``kt_kn_across`` (shift across the axis, the rolling direction) and
    ``kt_kn_along`` (along the axis) [-]. The self-similarity of the parabolic-gap
    cylinder (docs/theory.md, section 'Self-similarity') makes the ratios functions of
    (nu, d~) alone, for any L/R.

    Interpolated is the correction factor of the MDR, :math:`c = (k_t/k_n) /
    [2(1-\nu)/(2-\nu)]` (exactly 1 at nu = 0, smooth in nu), by the interpolating
    tensor-product spline in (nu, ln d~) (bicubic with 4 or more values per axis; of
    degree n - 1 with n = 2 or 3 values). It passes through every node. Points outside
    the grid are refused.

    Optional partial-slip correction: columns ``shift_ratio_{across|along}_q{Q}``
    (e.g. ``shift_ratio_across_q0.5``) give the BEM's tangential shift over the
    stiffness-corrected law's (:class:`TangentialContact` with this ratio) at the load
    fraction F_t/(mu F) = Q in (0, 1]; between Q values the factor is interpolated
    linearly, from 1 at Q = 0 (equal full-stick stiffness). Without such columns the
    runtime uses the stiffness-corrected law.

    Parameters
    ----------
    table : linecontact.tables.Table
        The table as read by :func:`linecontact.tables.read_table`.

    Notes
    -----
    Valid inside the table's grid: its nu and d~ ranges (the header states grid,
    tolerance and L/R used).

    Examples
    --------
    >>> import os, tempfile
    >>> from linecontact.tables import read_table, write_table
    >>> meta = dict(title="demo", source="doctest", units="[-]", generated_by="doctest",
    ...             date="2026-01-01", version="0", accuracy="none")
    >>> cols = dict(nu=[0, 0, 0.5, 0.5], d_tilde=[1e-4, 1e-2, 1e-4, 1e-2],
    ...             kt_kn_across=[1, 1, 0.8, 0.9], kt_kn_along=[1, 1, 0.6, 0.6])
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_table(os.path.join(d, "t.csv"), meta, cols)
    ...     t = CylinderTangentialTable(read_table("t", directory=d))
    >>> f"{t.ratio('along', 0.25, 1e-3):.4f}"
    '0.8143'

    References
    ----------
    Popov & Hess (2015), chapter 4 (the MDR value the factor refers to).
    """

    def __init__(self, table):
        cols = table.columns
        where = str(table.path) if table.path is not None else "table"
        for name in ("nu", "d_tilde", "kt_kn_across", "kt_kn_along"):
            if name not in cols:
                raise TableError(f"{where}: no column {name!r}")
        self.table = table
        nu, dt = cols["nu"], cols["d_tilde"]
        self.nus = np.unique(nu)
        self.d_tildes = np.unique(dt)
        n1, n2 = self.nus.size, self.d_tildes.size
        if n1 * n2 != nu.size or n1 < 2 or n2 < 2:
            raise TableError(f"{where}: (nu, d_tilde) must form a full regular grid of at "
                             f"least 2 x 2 points; got {nu.size} rows for {n1} nu and "
                             f"{n2} d_tilde values")
        if np.any(self.d_tildes <= 0) or np.any(self.nus < 0) or np.any(self.nus > 0.5):
            raise TableError(f"{where}: nu must lie in [0, 0.5] and d_tilde be > 0")
        order = np.lexsort((dt, nu))
        self._grid = {}
        mdr = 2 * (1 - nu[order]) / (2 - nu[order])
        for name in cols:
            if name in ("nu", "d_tilde"):
                continue
            vals = cols[name][order].reshape(n1, n2)
            if name.startswith("kt_kn_"):
                vals = vals / mdr.reshape(n1, n2)
            self._grid[name] = vals
        self.nu_range = Interval("nu", float(self.nus[0]), float(self.nus[-1]))
        self.d_tilde_range = Interval("d_tilde", float(self.d_tildes[0]),
                                      float(self.d_tildes[-1]), rtol=1e-12)
        from scipy.interpolate import RectBivariateSpline

        z = np.log(self.d_tildes)
        kx, ky = min(3, n1 - 1), min(3, n2 - 1)
        self._splines = {name: RectBivariateSpline(self.nus, z, vals, kx=kx, ky=ky, s=0)
                         for name, vals in self._grid.items()}
        self._shift_q = {}
        for name in cols:
            m = _SHIFT_COLUMN.match(name)
            if m:
                self._shift_q.setdefault(m.group(1), []).append((float(m.group(2)), name))
        for direction, items in self._shift_q.items():
            items.sort()
            if not all(0 < q <= 1 for q, _ in items):
                raise TableError(f"{where}: shift_ratio columns need 0 < Q <= 1")

    @property
    def provenance(self):
        """The table's metadata (title, source, generated_by, grid, accuracy, ...)."""
        return dict(self.table.meta)

    def _interp(self, name, nu, d_tilde):
        nu = self.nu_range.check(nu, hint="outside the BEM table of the cylinder")
        dt = self.d_tilde_range.check(d_tilde, name="d_tilde",
                                      hint="d R/L^2 outside the BEM table of the cylinder")
        nu, dt = np.broadcast_arrays(nu, dt)
        res = self._splines[name].ev(nu.ravel(), np.log(dt.ravel()))
        return res.reshape(nu.shape)

    def ratio(self, direction, nu, d_tilde):
        """Full-stick k_t/k_n [-] in `direction` ("across"/"along") at (nu, d~)."""
        if direction not in _DIRECTIONS:
            raise UnknownNameError("direction", direction, _DIRECTIONS)
        c = self._interp(f"kt_kn_{direction}", nu, d_tilde)
        nu = np.asarray(nu, dtype=float)
        return out(c * 2 * (1 - nu) / (2 - nu))

    def value(self, column, nu, d_tilde):
        """Any column of the table [its unit] interpolated at (nu, d~) (e.g. the study's
        measured partial-slip error ``ft_err_scaled_across``)."""
        if column not in self._grid:
            raise UnknownNameError("column", column, list(self._grid))
        v = self._interp(column, nu, d_tilde)
        if column.startswith("kt_kn_"):
            nu = np.asarray(nu, dtype=float)
            v = v * 2 * (1 - nu) / (2 - nu)
        return out(v)

    @property
    def has_slip_correction(self):
        """True if the table carries a partial-slip correction (both directions)."""
        return all(d in self._shift_q for d in _DIRECTIONS)

    def _interp_many(self, names, nu, d_tilde):
        """Several columns at the same points (one range check): shape (len(names), ...)."""
        nu = self.nu_range.check(nu, hint="outside the BEM table of the cylinder")
        dt = self.d_tilde_range.check(d_tilde, name="d_tilde",
                                      hint="d R/L^2 outside the BEM table of the cylinder")
        nu, dt = np.broadcast_arrays(nu, dt)
        x, z = nu.ravel(), np.log(dt.ravel())
        return np.array([self._splines[n].ev(x, z).reshape(nu.shape) for n in names])

    def shift_correction(self, direction, nu, d_tilde):
        """(Q nodes, shift factors) at (nu, d~) including (0, 1), or None if absent."""
        items = self._shift_q.get(direction)
        if not items:
            return None
        qs = [0.0] + [q for q, _ in items]
        cs = [1.0] + list(self._interp_many([name for _, name in items], nu, d_tilde))
        return np.array(qs), np.array(cs, dtype=float)

    def shift_factor(self, direction, nu, d_tilde, q):
        """The partial-slip shift factor c(q) [-] at load fractions q in [0, 1] (1 where
        the table has no correction), vectorised over (nu, d~, q)."""
        items = self._shift_q.get(direction)
        nu, dt, q = np.broadcast_arrays(np.asarray(nu, float), np.asarray(d_tilde, float),
                                        np.asarray(q, float))
        if not items:
            return out(np.ones(q.shape))
        qs = np.array([0.0] + [qq for qq, _ in items])
        cs = self._interp_many([name for _, name in items], nu, dt)     # (nQ, ...)
        cs = np.concatenate([np.ones((1,) + nu.shape), cs]).reshape(qs.size, -1)
        qf = np.clip(q.ravel(), 0.0, 1.0)
        j = np.clip(np.searchsorted(qs, qf, side="right") - 1, 0, qs.size - 2)
        cols = np.arange(qf.size)
        w = (qf - qs[j]) / (qs[j + 1] - qs[j])
        res = cs[j, cols] * (1 - w) + cs[j + 1, cols] * w
        return out(res.reshape(q.shape))


@functools.lru_cache(maxsize=None)
def _cached_table(name):
    return CylinderTangentialTable(read_table(name))


def cylinder_tangential_table(name=TANGENTIAL_TABLE, directory=None):
    r"""The :class:`CylinderTangentialTable` of ``tables/<name>.csv`` (cached).

    .. math:: \frac{k_t}{k_n} = c(\nu, \ln\tilde d)\,\frac{2(1-\nu)}{2-\nu}

    with c the table's correction factor of the MDR, interpolated.

    Parameters
    ----------
    name : str, optional
        Table stem (default ``"tangential_cylinder"``).
    directory : path-like, optional
        Read from this folder instead of ``tables/`` (not cached).

    Returns
    -------
    CylinderTangentialTable

    Raises
    ------
    FileNotFoundError
        The table is not there (the BEM study has not been run).

    Notes
    -----
    Valid for tables with the columns nu, d_tilde, kt_kn_across, kt_kn_along on a
    regular (nu, d~) grid.

    Examples
    --------
    >>> cylinder_tangential_table("no_such_table")
    Traceback (most recent call last):
    ...
    FileNotFoundError: table 'no_such_table' not found in ...

    References
    ----------
    Popov & Hess (2015), chapter 4.
    """
    if directory is not None:
        return CylinderTangentialTable(read_table(name, directory=directory))
    return _cached_table(name)


def cylinder_stiffness_ratios(model, depth, gstar, *, table=None):
    r"""The finite cylinder's full-stick k_t/k_n across and along the axis, and the MDR's.

    .. math::

        \frac{k_t}{k_n}\Big|_{dir} = T_{dir}\!\left(\nu_{eq}, \frac{dR}{L^2}\right),
        \qquad \frac{k_t}{k_n}\Big|_{MDR} = \frac{G^*}{E^*}
        = \frac{2(1-\nu_{eq})}{2-\nu_{eq}}

    with T the BEM table and :math:`\nu_{eq}` = :func:`equivalent_poisson` (G*, E*).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        A straight-cylinder model (:data:`STRAIGHT_CYLINDER_MODELS`); its R, L and E*
        are used.
    depth : float or array_like
        Normal depth d [m].
    gstar : float
        Effective shear modulus G* [Pa].
    table : CylinderTangentialTable, optional
        Default :func:`cylinder_tangential_table`.

    Returns
    -------
    dict
        ``across``, ``along``, ``mdr`` (k_t/k_n [-]), ``mdr_error_across``,
        ``mdr_error_along`` (MDR/BEM - 1 [-]), ``nu`` and ``d_tilde`` [-]; if the table
        has the study's columns ``ft_err_scaled_{across,along}``, also
        ``slip_error_across``, ``slip_error_along``: the largest difference between
        the BEM's partial-slip curve and the law with this ratio, over mu F [-].

    Notes
    -----
    Valid inside the table's (nu, d R/L^2) grid; refused outside. The ratios belong
    to the BEM's normal contact of a rigid straight cylinder with the parabolic gap
    (d/R <= 0.15 in the study), any L/R.

    Examples
    --------
    With a made-up 2 x 2 table (the shipped one comes from the BEM study):

    >>> import os, tempfile
    >>> from linecontact.classical import effective_modulus
    >>> from linecontact.tangential import effective_shear_modulus
    >>> from linecontact.models import get_model
    >>> from linecontact.tables import read_table, write_table
    >>> meta = dict(title="demo", source="doctest", units="[-]", generated_by="doctest",
    ...             date="2026-01-01", version="0", accuracy="none")
    >>> cols = dict(nu=[0, 0, 0.5, 0.5], d_tilde=[1e-4, 1e-2, 1e-4, 1e-2],
    ...             kt_kn_across=[1, 1, 0.8, 0.9], kt_kn_along=[1, 1, 0.6, 0.6])
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_table(os.path.join(d, "t.csv"), meta, cols)
    ...     t = CylinderTangentialTable(read_table("t", directory=d))
    >>> m = get_model("kunz", 5e-3, 10e-3, effective_modulus(210e9, 0.3))
    >>> r = cylinder_stiffness_ratios(m, 1e-5, effective_shear_modulus(210e9, 0.3), table=t)
    >>> f"{r['across']:.4f} {r['along']:.4f} {r['mdr']:.4f} d~ = {r['d_tilde']:.0e}"
    '0.9483 0.7741 0.8235 d~ = 5e-04'

    References
    ----------
    Popov & Hess (2015), chapter 4 (MDR value); the BEM table's header (its source).
    """
    key = getattr(model, "key", "")
    if key not in STRAIGHT_CYLINDER_MODELS:
        raise OutOfRangeError("model", key or type(model).__name__,
                              "one of " + ", ".join(sorted(STRAIGHT_CYLINDER_MODELS)),
                              hint="the BEM table is for a straight, aligned cylinder; "
                                   "use method='mdr' for other shapes")
    table = table if table is not None else cylinder_tangential_table()
    d = check_positive("depth", depth, "m")
    nu = equivalent_poisson(gstar, model.estar)
    d_tilde = d * model.radius / model.length ** 2
    across = table.ratio("across", nu, d_tilde)
    along = table.ratio("along", nu, d_tilde)
    mdr = mdr_stiffness_ratio(nu)
    res = {"across": across, "along": along, "mdr": out(np.broadcast_to(mdr, np.shape(d))),
           "mdr_error_across": out(mdr / np.asarray(across) - 1),
           "mdr_error_along": out(mdr / np.asarray(along) - 1),
           "nu": nu, "d_tilde": out(d_tilde)}
    for side in _DIRECTIONS:   # the study's measured error of the partial-slip law
        column = f"ft_err_scaled_{side}"
        if column in table._grid:
            res[f"slip_error_{side}"] = table.value(column, nu, d_tilde)
    return res
