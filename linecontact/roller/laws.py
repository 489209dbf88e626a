"""The two roller models as contact laws (:class:`linecontact.models.ContactModel`):
force(depth), depth(force), stiffness(depth) at a fixed tilt, registered under the keys
``profiled-roller`` and ``iso16281-slicing``.
"""
from __future__ import annotations

import numpy as np

from .._numerics import BLOCK, UniformHermite, out
from ..models import ContactModel, register
from ..profiles import as_profile
from ..checks import check_positive
from .slices import TILT_RANGE
from .solvers import DEFAULT_SLICES, slice_solver

__all__ = ["ProfiledRollerModel", "ISOSlicingModel"]


def _each(values, fn):
    """fn(one value) over an array of values, same shape (one slice solve per value)."""
    v = np.asarray(values, dtype=float)
    res = np.array([fn(float(e)) for e in v.ravel()]).reshape(v.shape)
    return out(res)


#: Arrays from this many elements on evaluate force(depth) and depth(force) from a table
#: of the solved law, built once per model (as TangentialContact's tables).
_TABLE_MIN = 1 << 15
#: Cells per piece of those tables (doubled up to twice where the check fails), and the
#: largest difference from a direct solve at a cell's midpoint, relative to the value
#: above first contact (F, or d - d0), with which a cell is used; a cell that misses it
#: is solved directly. 1e-6 is a thousandth of the models' own error against the 3D
#: BEM (about 1e-3, docs/roller.md).
_TABLE_CELLS = 64
_TABLE_TOL = 1e-6
#: Bisection steps locating an edge-loading onset (to 2^-40 of the table's range).
_ONSET_STEPS = 40


class _LawTable:
    r"""y(x) of a solved roller law on [x_0, x_J] as cubic Hermite pieces.

    The law is smooth between its breaks x_j (first contact, where a slice or a roller
    end comes into contact) but not across them, and at each break the new contact
    grows as a power of x - x_j: on piece j the variable is s with
    :math:`x = x_j + (x_{j+1} - x_j) s^g`, the grade g chosen so that the new contact's
    power becomes s^3, which the cubic reproduces, and equal steps in s crowd the nodes
    towards the break. The pieces share one
    :class:`UniformHermite` in S = (j + s)/J (slope 0 at each piece's start, the
    exact dy/dx times dx/dS at its end). Each cell's midpoint is compared with a direct
    solve; cells that miss it by more than `tol` (relative to y - y_0) are marked and
    solved directly.
    """

    def __init__(self, breaks, y0, nodes_fun, exact, grade, cells=_TABLE_CELLS,
                 tol=_TABLE_TOL):
        b = np.asarray(breaks, dtype=float)
        self.grade = float(grade)
        for c in (cells, 2 * cells, 4 * cells):
            self._build(b, y0, nodes_fun, exact, c, tol)
            if self.bad.sum() <= b.size - 1:        # at most each piece's first cell
                break
        self.exact = exact
        self.top = float(b[-1])

    def _build(self, b, y0, nodes_fun, exact, cells, tol):
        J = b.size - 1
        w = np.diff(b)
        s = np.linspace(0.0, 1.0, cells + 1)[1:]
        g = self.grade
        x = np.concatenate([[b[0]], (b[:-1, None] + w[:, None] * s ** g).ravel()])
        x[cells::cells] = b[1:]
        y, dydx = nodes_fun(x[1:])
        dxds = (J * g * w[:, None] * s ** (g - 1)).ravel()
        end = np.concatenate([[0.0], dxds * dydx])
        if J > 1:
            # the slope arriving at an inner break, solved just below it: at the break
            # itself a contact starting there can already count (its stiffness rises as
            # (d - d_j)^(1/9) for an ISO slice, so rounding alone changes it by 1e-3)
            below = b[1:-1] - 1e-12 * (b[-1] - b[0])
            end[cells:-1:cells] = dxds[cells - 1:-1:cells] * nodes_fun(below)[1]
        start = end.copy()
        start[cells::cells] = 0.0                    # each piece starts flat in its s
        self.poly = UniformHermite(np.concatenate([[y0], y]), start, end)
        self.b, self.inv_w, self.J = b, 1.0 / w, J
        # piece lookup without a search: the piece at each of 4096 equal bins' left
        # edges, then moved up while x passes the next break (once, where a bin holds
        # one break)
        self._bins = 4096 / (b[-1] - b[0])
        edges = b[0] + np.arange(4097) / self._bins
        self._lut = np.searchsorted(b[1:-1], edges, side="right")
        self._next = np.concatenate([b[1:-1], [np.inf]])
        sm = (np.arange(cells) + 0.5) / cells
        xm = (b[:-1, None] + w[:, None] * sm ** g).ravel()
        Sm = ((np.arange(J)[:, None] + sm) / J).ravel()
        em = exact(xm)
        err = np.abs(self.poly(Sm) - em) / np.abs(em - y0)
        self.bad = ~(err <= tol)
        self.errors = err
        #: Largest relative difference at the midpoints of the cells in use.
        self.error = float(err[~self.bad].max()) if (~self.bad).any() else 0.0

    def __call__(self, v):
        """y(v) for an array v in [x_0, top], in blocks; marked cells solved directly."""
        flat = np.asarray(v, dtype=float).ravel()
        res = np.empty(flat.size)
        redo = []
        b, inv_w, J, inv_g = self.b, self.inv_w, self.J, 1.0 / self.grade
        for k in range(0, flat.size, BLOCK):
            xb = flat[k:k + BLOCK]
            if J == 1:
                t = xb - b[0]
                t *= inv_w[0]
            else:
                t = xb - b[0]
                t *= self._bins
                j = self._lut.take(np.minimum(t.astype(np.intp), 4096))
                while True:
                    up = xb >= self._next.take(j)
                    if not up.any():
                        break
                    j += up
                t = xb - b.take(j)
                t *= inv_w.take(j)
            np.minimum(t, 1.0, out=t)
            np.maximum(t, 0.0, out=t)
            np.power(t, inv_g, out=t)
            if J > 1:
                t += j
                t *= 1.0 / J
            y, i = self.poly.evaluate(t)
            res[k:k + BLOCK] = y
            marked = np.flatnonzero(self.bad.take(i))
            if marked.size:
                redo.append(marked + k)
        if redo:
            j = np.concatenate(redo)
            res[j] = self.exact(flat[j])
        return res.reshape(np.shape(v))


class _Identity:
    """An object compared by identity (in the settings tuple of a model's tables)."""

    __slots__ = ("obj",)

    def __init__(self, obj):
        self.obj = obj

    def __eq__(self, other):
        return isinstance(other, _Identity) and other.obj is self.obj

    __hash__ = None


class _SolvedRoller(ContactModel):
    """The contact law of a roller model from its solutions (``at_depth``,
    ``at_force`` returning :class:`RollerSolution`): one solve per value, each giving
    force, depth and stiffness together. Subclasses set :attr:`axial_profile` and
    :attr:`n_slices`, and name themselves with ``_name`` and ``_slices``."""

    _name = ""
    _slices = "slices"
    #: The power alpha with which the force grows at each break, F - F_j ~ (d - d_j)^alpha
    #: (the tables' grades make it s^3: 3/alpha in d, 3 alpha in F).
    _onset_power = 10.0 / 9.0

    def __init__(self, radius, length, estar, tilt=0.0):
        super().__init__(radius, length, estar)
        self.tilt = TILT_RANGE.check(tilt).item()

    def __setattr__(self, name, value):
        # the tables are built from the geometry and tilt: a change drops them
        if name in ("tilt", "radius", "length", "estar", "axial_profile", "n_slices",
                    "roller"):
            self.__dict__.pop("_tables", None)
        object.__setattr__(self, name, value)

    @property
    def first_contact_depth(self):
        """Depth of the roller's centre at first contact at this tilt [m]."""
        if isinstance(self, ProfiledRollerModel):
            return self.roller.first_contact_depth(self.tilt)
        return float(np.min(self._slice_onsets()))

    def _slice_onsets(self):
        """Depth at which each slice centre x_k touches: P(x_k) - x_k tan(theta) [m]."""
        from ..profiles import roller_drop

        L, n = self.length, self.n_slices
        x = -L / 2 + L / n * (np.arange(n) + 0.5)
        return roller_drop(self.axial_profile, L, x) - x * np.tan(self.tilt)

    @property
    def label(self):
        s = f"{self._name} ({self.axial_profile.label}"
        if self.tilt:
            s += f", tilt {self.tilt * 1e3:.4g} mrad"
        return s + f", {self.n_slices} {self._slices})"

    def force(self, depth):
        """F(d) [N]; arrays of 32768 values or more from a table of the solved law built
        once per model, equal to the solves to 1e-6 F (see :class:`_LawTable`)."""
        v = np.asarray(depth, dtype=float)
        if v.size >= _TABLE_MIN:
            res = self._tabulated(v, "force")
            if res is not None:
                return out(res)
        return _each(depth, lambda d: self.at_depth(d).force)

    def depth(self, force):
        """d(F) [m]; arrays of 32768 values or more from a table of the solved law,
        equal to the solves to 1e-6 of d - d0 (d0: first contact)."""
        F = check_positive("force", force, "N")
        v = np.asarray(F, dtype=float)
        if v.size >= _TABLE_MIN:
            res = self._tabulated(v, "depth")
            if res is not None:
                return out(res)
        return _each(F, lambda f: self.at_force(f).depth)

    # -- the tabulated law (large arrays) ----------------------------------------------
    def _solutions(self, values, by):
        """RollerSolutions at the depths (by="depth") or forces (by="force"), 1-D."""
        solve = self.at_depth if by == "depth" else self.at_force
        return [solve(float(v)) for v in np.asarray(values, dtype=float).ravel()]

    def _edge_onsets(self, top):
        """Depths in (d0, top) where a roller end comes into contact (none here: the
        uncoupled slices' onsets are the breaks)."""
        return []

    def _breaks(self, top):
        """First contact, the onsets in between, top: the depths where the law is not
        smooth [m]."""
        d0 = self.first_contact_depth
        inner = [*self._slice_onsets(), *self._edge_onsets(top)] if top > d0 else []
        b = np.unique([d0, *[d for d in inner if d0 < d < top], top])
        keep = np.concatenate([[True], np.diff(b) > 1e-9 * (top - d0)])
        keep[-1] = True
        b = b[keep]
        return b[np.concatenate([np.diff(b) > 0, [True]])]

    def _tabulated(self, v, which):
        """The law at the array v from the table (built or extended as needed), or None
        (the direct path then answers, with its errors: a value out of range raises
        here exactly as there)."""
        lo, hi = float(v.min()), float(v.max())
        if not (np.isfinite(lo) and np.isfinite(hi)):
            return None
        if which == "force":
            d0 = self.first_contact_depth
            if lo <= d0:
                flat = v.ravel()
                self.at_depth(float(flat[np.argmax(flat <= d0)]))   # raises
                return None
        tables = self.__dict__.setdefault("_tables", {})
        key = self._solver_settings()
        if tables.get("settings", key) != key:
            tables.clear()                   # the solver's own settings changed
        tables["settings"] = key
        table = tables.get(which, False)
        # a build that failed up to some value is tried again for a smaller range
        failed = tables.get(which + "_failed_above", np.inf)
        if (table is False or (table is not None and table.top < hi)
                or (table is None and hi < failed)):
            try:
                table = self._build_table(which, hi)
            except (ValueError, ArithmeticError, RuntimeError):
                table = None                 # a law the solver cannot sweep: direct
                tables[which + "_failed_above"] = hi
            tables[which] = table
        return None if table is None else table(v)

    def _solver_settings(self):
        """What the solved law depends on besides the attributes whose assignment
        drops the tables (__setattr__): the settings of a solver object the model
        holds, which a user may change on that object (none here)."""
        return ()

    def _build_table(self, which, hi):
        d0 = self.first_contact_depth
        if which == "force":
            top = d0 + 1.25 * (hi - d0)

            def nodes(d):
                sol = self._solutions(d, "depth")
                return (np.array([e.force for e in sol]),
                        np.array([e.stiffness for e in sol]))

            return _LawTable(self._breaks(top), 0.0, nodes, lambda d: nodes(d)[0],
                             3.0 / self._onset_power)
        top = 1.25 * hi
        b = self._breaks(self.at_force(top).depth)
        Fb = np.array([0.0, *(e.force for e in self._solutions(b[1:-1], "depth")), top])

        def nodes(F):
            sol = self._solutions(F, "force")
            return (np.array([e.depth for e in sol]),
                    1.0 / np.array([e.stiffness for e in sol]))

        return _LawTable(Fb, d0, nodes, lambda F: nodes(F)[0], 3.0 * self._onset_power)

    def stiffness(self, depth):
        return _each(depth, lambda d: self.at_depth(d).stiffness)

    def stiffness_at_force(self, force):
        F = check_positive("force", force, "N")
        return _each(F, lambda f: self.at_force(f).stiffness)


@register
class ProfiledRollerModel(_SolvedRoller):
    """A profiled, tilted roller as a contact law: coupled slices at a fixed tilt.

    .. math:: F(d) = \\sum_k q_k(d, \\theta)\\,w, \\qquad k(d) = \\partial F/\\partial d

    Parameters
    ----------
    radius : float
        Radius across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    profile : Profile or str or None, optional
        Profile drop or spec (None: straight) [-].
    tilt : float, optional
        Tilt theta [rad], held fixed (default 0).
    n_slices : int, optional
        Number of slices [-] (default 50, the coupled slices' default,
        :data:`~linecontact.roller.solvers.DEFAULT_SLICES`).

    Notes
    -----
    The roller's profile drop is :attr:`axial_profile` (``profile()`` is the
    ContactModel's MDR profile, which this model does not have).
    ``depth`` is the depth d of the roller point x = 0 (as in :class:`RollerSolution`);
    it must exceed the first-contact depth min_x(P - theta x), which is negative for a
    tilted roller. :meth:`at_depth` and :meth:`at_force` return the full
    :class:`RollerSolution` (moment, q(x), peak pressure, edge loading). Validity and
    accuracy as :class:`ProfiledRoller`.

    Examples
    --------
    >>> m = ProfiledRollerModel(10e-3, 20e-3, 115.385e9, profile="circular:Rc=0.5")
    >>> f"{m.depth(1000.0) * 1e6:.2f} um", m.key
    ('7.02 um', 'profiled-roller')

    References
    ----------
    See :mod:`linecontact.roller`.
    """

    key = "profiled-roller"
    no_profile_reason = ("a coupled-slice solution of a profiled roller, not a "
                         "plane MDR contact; its axial drop is axial_profile")

    _name = "Profiled roller"
    _slices = "coupled slices"
    _onset_power = 1.5          # a crowned roller starts as a point contact, F ~ d^(3/2)

    def __init__(self, radius, length, estar, profile=None, tilt=0.0,
                 n_slices=DEFAULT_SLICES["profiled-roller"]):
        super().__init__(radius, length, estar, tilt)
        self.roller = slice_solver(self.key, self.radius, self.length, self.estar,
                                   profile, n_slices=n_slices)
        self.axial_profile = self.roller.profile
        self.n_slices = self.roller.n_slices

    #: the model's attributes that are the roller's own (a change builds a new roller)
    _ROLLER_ATTRIBUTES = ("radius", "length", "estar", "n_slices")

    def __setattr__(self, name, value):
        r = self.__dict__.get("roller")
        if (r is not None and name in self._ROLLER_ATTRIBUTES
                and value != getattr(r, name)):
            # `model.radius = ...` must change the law, not only the label: set on the
            # roller, which builds itself anew (checked there, its profile spec read
            # with the new R, as at construction; ProfiledRoller.__setattr__)
            setattr(r, name, value)
            super().__setattr__("axial_profile", r.profile)
            value = getattr(r, name)
        super().__setattr__(name, value)

    @property
    def provenance(self):
        return {"model": self.label, "method": "coupled slices with Hertz strips "
                "(linecontact.roller)", "profile": self.axial_profile.provenance,
                "tilt_rad": self.tilt, "n_slices": self.n_slices}

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m] and this model's tilt."""
        return self.roller.at_depth(depth, self.tilt)

    def _solver_settings(self):
        # `model.roller.grading = 0.5` changes the law as much as a new roller does;
        # the profile by identity (a user table's arrays do not compare as one bool)
        r = self.roller
        return (r.radius, r.length, r.estar, r.n_slices, r.grading, r.refine_ends,
                _Identity(r.profile))

    def _slice_onsets(self):
        return []                        # coupled slices: the ends' onsets are the breaks

    def _solutions(self, values, by):
        # one sweep in increasing order, each solve warm-started from its neighbour
        v = np.asarray(values, dtype=float).ravel()
        if v.size == 0:
            return []
        sol = (self.roller.at_depth(v, self.tilt) if by == "depth"
               else self.roller.at_force(v, self.tilt))
        return list(np.asarray(sol, dtype=object).ravel())

    def _edge_onsets(self, top):
        """Depths in (d0, top) where the contact reaches a roller end (one end, then
        both for a tilted roller), by bisection on the number of loaded ends."""
        def ends(d):
            return {None: 0, "both": 2}.get(self.at_depth(d).edge, 1)

        d0 = self.first_contact_depth
        n_top = ends(top)
        onsets = []
        for level in range(1, n_top + 1):
            lo, hi = d0, top
            for _ in range(_ONSET_STEPS):
                mid = 0.5 * (lo + hi)
                if mid <= lo or mid >= hi:
                    break
                lo, hi = (mid, hi) if ends(mid) < level else (lo, mid)
            onsets.append(hi)
        return onsets

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N] and this model's tilt."""
        return self.roller.at_force(force, self.tilt)


@register
class ISOSlicingModel(_SolvedRoller):
    """ISO 16281 slicing of a profiled, tilted roller as a contact law (steel only).

    .. math:: F(d) = \\sum_k \\frac{c}{n}\\,(d + x_k\\tan\\theta - P(x_k))_+^{10/9}

    Parameters
    ----------
    radius, length : float
        R, L [m].
    estar : float
        E* [Pa] (steel only).
    profile : Profile or str or None, optional
        Profile drop or spec [-].
    tilt : float, optional
        Tilt theta [rad] (default 0).
    n_slices : int, optional
        n >= 30 [-] (default 30, ISO 16281's,
        :data:`~linecontact.roller.solvers.DEFAULT_SLICES`).

    Notes
    -----
    See :func:`~linecontact.roller.iso_slicing`. Valid for steel on steel only.

    Examples
    --------
    >>> m = ISOSlicingModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    ISO 16281:2025.
    """

    key = "iso16281-slicing"
    no_profile_reason = "uncoupled slices, each with the empirical ISO 16281 law"

    _name = "ISO 16281 slicing"

    def __init__(self, radius, length, estar, profile=None, tilt=0.0,
                 n_slices=DEFAULT_SLICES["iso16281-slicing"]):
        super().__init__(radius, length, estar, tilt)
        self.n_slices = n_slices
        self.axial_profile = as_profile(profile, self.radius, self.length, self.estar)

    @property
    def provenance(self):
        return {"model": self.label, "method": "ISO 16281:2025 slicing, uncoupled "
                "slices", "profile": self.axial_profile.provenance, "tilt_rad": self.tilt}

    def check_applicable(self):
        from ..classical import STEEL_ESTAR_RANGE, STEEL_HINT
        STEEL_ESTAR_RANGE.check(self.estar, hint=STEEL_HINT)

    def _solver(self):
        # the model's attributes as they are now (a change changes the law)
        return slice_solver(self.key, self.radius, self.length, self.estar,
                            self.axial_profile, n_slices=self.n_slices)

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m]."""
        return self._solver().at_depth(depth, self.tilt)

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N]."""
        return self._solver().at_force(force, self.tilt)
