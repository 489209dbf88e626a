r"""One normal contact state under tangential load: stick, partial slip, fretting.

:class:`TangentialContact` holds the normal state (depth or force) of a model and
answers the tangential force or shift, the stick radius, the unloading and reloading
branches (Masing) and the energy dissipated per fretting cycle, with the laws of
:mod:`linecontact.tangential.laws` (the MDR ratio G*/E* or the finite cylinder's
BEM ratio and partial-slip correction). Arrays of many shifts or forces are
evaluated by tables of the law built once per contact (:class:`_EndTable`).

References
----------
.. [1] R. D. Mindlin, H. Deresiewicz, Elastic spheres in contact under varying oblique
   forces, J. Appl. Mech. 20 (1953) 327-344 (the Masing branches, the energy per cycle).
.. [2] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapter 4.
"""
from __future__ import annotations

import numpy as np

from .._numerics import BLOCK, UniformHermite, blockwise, out
from ..checks import check_interval, check_positive
from ..errors import OutOfRangeError, UnknownNameError
from .cylinder_table import (_DIRECTIONS, cylinder_stiffness_ratios,
                             cylinder_tangential_table)
from .laws import _METHODS, _amplitude, _check_beyond, _friction, _ft
from .moduli import _ratio

__all__ = ["TangentialContact"]

_GL_T, _GL_W = np.polynomial.legendre.leggauss(64)


#: Arrays from this many elements on use the tabulated laws of TangentialContact (built
#: once per contact, about as costly as the direct evaluation of this many elements).
_TABLE_MIN = 1 << 15
#: Nodes of those tables, and the largest difference from the direct evaluation at the
#: cells' midpoints (over mu F, or over u*) with which a table is used.
_TABLE_NODES = 4097
_TABLE_TOL = 1e-12


class _EndTable:
    r"""A function y(x) on [0, 1] as a cubic Hermite table in :math:`s = (1-x)^{1/4}`.

    The partial-slip laws are smooth in the load fraction except at x = 1 (gross slip),
    where the depth of the rest d(F (1 - q)) goes to zero and the normal stiffness with
    it (logarithmically for a line contact, as a power for a power law): in
    :math:`1 - x = s^4` that end becomes smooth to high order, and equal steps in s
    crowd the nodes towards it. Cells holding a kink of the slip correction (its
    linear interpolation in q) are marked and evaluated directly, as is every element
    if the table misses the direct values at the cells' midpoints by more than `tol`.
    """

    def __init__(self, nodes_fun, exact, kinks, nodes=_TABLE_NODES, tol=_TABLE_TOL):
        s = np.linspace(0.0, 1.0, nodes)
        x = 1.0 - s ** 4
        x[0], x[-1] = 1.0, 0.0
        y, dydx = nodes_fun(x[1:])                       # x < 1: finite slopes
        y = np.concatenate([[float(exact(np.ones(1))[0])], y])
        slopes = np.concatenate([[0.0], -4.0 * s[1:] ** 3 * dydx])   # dy/ds, 0 at s = 0
        self.poly = UniformHermite(y, slopes)
        self.exact = exact
        bad = np.zeros(nodes - 1, dtype=bool)
        for xk in kinks:
            if 0.0 < xk < 1.0:
                t = (1.0 - xk) ** 0.25 * (nodes - 1)
                bad[min(int(np.floor(t)), nodes - 2)] = True
                bad[min(max(int(np.ceil(t)) - 1, 0), nodes - 2)] = True
        self.bad = bad
        sm = (np.arange(nodes - 1) + 0.5) / (nodes - 1)
        good = ~bad
        ym = self.poly(sm[good])
        #: Largest difference from the direct evaluation at the cells' midpoints.
        self.error = float(np.max(np.abs(ym - exact(1.0 - sm[good] ** 4)))) if good.any() \
            else 0.0
        self.usable = bool(self.error <= tol)

    def __call__(self, v, v_end, y_end):
        """The odd law y_end y(min(|v|/v_end, 1)) sign(v) of an array v, in blocks of
        BLOCK elements (v_end: where the law ends, gross slip; y_end: its value there).
        The marked cells' elements are evaluated directly, all together after the
        blocks."""
        poly, bad = self.poly, self.bad
        v = np.asarray(v, dtype=float)

        def pre(vb):                  # x = |v|/v_end, 1 from gross slip on
            x = np.abs(vb)
            x /= v_end
            return np.minimum(x, 1.0, out=x)

        def post(y, vb):
            y *= y_end
            y *= np.sign(vb)
            return y

        flat = v.ravel()
        res = np.empty(flat.size)
        redo = []
        for k in range(0, flat.size, BLOCK):
            vb = flat[k:k + BLOCK]
            s = pre(vb)
            np.subtract(1.0, s, out=s)
            np.maximum(s, 0.0, out=s)
            np.sqrt(s, out=s)
            np.sqrt(s, out=s)
            y, i = poly.evaluate(s)
            res[k:k + BLOCK] = post(y, vb)
            marked = np.flatnonzero(bad.take(i))
            if marked.size:
                redo.append(marked + k)
        if redo:
            j = np.concatenate(redo)
            res[j] = post(self.exact(pre(flat[j])), flat[j])
        return res.reshape(v.shape)


class TangentialContact:
    r"""One normal contact state under tangential load: stick, partial slip, fretting.

    The normal depth d (or force F, converted with the model's d(F)) is held constant
    while the tangential shift u varies; the normal and tangential problems are
    uncoupled (Goodman). With the stiffness ratio r (= G*/E* for the MDR, or the BEM
    table's direction-dependent k_t/k_n of the cylinder):

    .. math::

        f(u) = \mu\,[F(d) - F(d - r u/\mu)],\quad k_t = r k_n(d),\quad
        u^* = \mu d/r,

        F_t^{\downarrow}(u) = F_0 - 2f\!\left(\tfrac{u_0-u}{2}\right),\quad
        F_t^{\uparrow}(u) = -F_0 + 2f\!\left(\tfrac{u_0+u}{2}\right),\quad
        W = 8\int_0^{u_0} f\,ds - 4u_0 f(u_0).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model.
    friction : float
        Coulomb friction coefficient mu [-].
    gstar : float
        Effective shear modulus G* (:func:`effective_shear_modulus`) [Pa].
    depth : float, optional
        Normal depth d (give depth or force) [m].
    force : float, optional
        Normal force F; the depth is the model's d(F) [N].
    method : {"mdr", "bem"}, optional
        ``"mdr"`` (default): r = G*/E*. ``"bem"``: r = the cylinder's k_t/k_n in
        `direction` from the BEM table (straight-cylinder models only), and the
        table's partial-slip correction if it carries one and `slip_correction`.
    direction : {"across", "along"}, optional
        With ``method="bem"``: across the axis (rolling direction, default) or along.
    slip_correction : bool, optional
        With ``method="bem"``: apply the table's partial-slip correction when the table
        has one (default True); without one the law is the stiffness-corrected MDR law.
    table : CylinderTangentialTable, optional
        The BEM table (default :func:`cylinder_tangential_table`).

    Notes
    -----
    Valid for 0 < |u| <= u* (beyond: ``beyond="saturate"`` on request), mu > 0,
    2/3 <= G*/E* <= 1 (Poisson ratios in [0, 0.5]), and in the model's depth range.
    Exact for axisymmetric shapes and for any shape at nu = 0; for the finite cylinder
    see docs/tangential.md for the MDR's measured error and ``method="bem"``.
    Energies are integrated, in the form :math:`W = 4r\int_0^{u_0} (u_0 - 2s)
    [k_n(d - rs/\mu) - k_n(d)]\,ds` (by parts; free of the cancellation of the
    :math:`O(u_0^2)` terms), by 64-point Gauss-Legendre quadrature in
    :math:`s = u_0(1 - t^2)`, smooth at gross slip where the normal stiffness starts
    from zero; they need the model's k_n to be the derivative of its F. Against
    Mindlin-Deresiewicz's closed form for the sphere the relative error is below 1e-11
    for Q*/(mu P) from 0.01 to 1 (tests/test_tangential.py).

    Examples
    --------
    Rigid roller (R = 5 mm, L = 10 mm) on steel, 1 kN normal load, mu = 0.1:

    >>> from linecontact.classical import effective_modulus
    >>> from linecontact.tangential import effective_shear_modulus
    >>> from linecontact.models import get_model
    >>> E = effective_modulus(210e9, 0.3); G = effective_shear_modulus(210e9, 0.3)
    >>> c = TangentialContact(get_model("universal", 5e-3, 10e-3, E), 0.1, G, force=1e3)
    >>> f"{c.stiffness / 1e6:.1f} N/um", f"{c.gross_slip_shift * 1e9:.1f} nm"
    ('536.7 N/um', '203.3 nm')
    >>> f"{c.force(0.5 * c.gross_slip_shift):.2f} N", str(c.slip_state(1e-7))
    ('52.96 N', 'partial slip')
    >>> f"{c.dissipated_energy(50e-9) * 1e9:.2f} nJ"
    '24.20 nJ'

    References
    ----------
    C. Cattaneo (1938); R. D. Mindlin (1949); R. D. Mindlin, H. Deresiewicz (1953);
    K. L. Johnson, Contact Mechanics (1985), section 7.2; Popov & Hess (2015), ch. 4.
    """

    def __init__(self, model, friction, gstar, *, depth=None, force=None, method="mdr",
                 direction="across", slip_correction=True, table=None):
        if (depth is None) == (force is None):
            raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                                  "exactly one of depth, force")
        self.model = model
        self.friction = float(_scalar_check(_friction(friction), "friction"))
        self.gstar = float(_scalar_check(check_positive("gstar", gstar, "Pa"), "gstar"))
        if depth is None:
            self.normal_force = float(_scalar_check(check_positive("force", force, "N"),
                                                    "force"))
            self.depth = float(model.depth(self.normal_force))
        else:
            self.depth = float(_scalar_check(check_positive("depth", depth, "m"), "depth"))
            self.normal_force = float(model.force(self.depth))
        if method not in _METHODS:
            raise UnknownNameError("method", method, _METHODS)
        self.method = method
        self.direction = direction
        self.mdr_ratio = float(_ratio(self.gstar, model.estar))
        self._correction = None
        if method == "mdr":
            self.ratio = self.mdr_ratio
        else:
            if direction not in _DIRECTIONS:
                raise UnknownNameError("direction", direction, _DIRECTIONS)
            table = table if table is not None else cylinder_tangential_table()
            ratios = cylinder_stiffness_ratios(model, self.depth, self.gstar, table=table)
            self.ratio = float(ratios[direction])
            if slip_correction:
                self._correction = table.shift_correction(
                    direction, float(ratios["nu"]), float(ratios["d_tilde"]))

    #: Attributes the cached laws (the tables of :meth:`_table`, the nodes of
    #: :meth:`_q_of_shift_reference`) are built from: assigning one drops the caches, so
    #: they are rebuilt from the new settings on next use (never evaluated stale).
    _CACHE_INPUTS = frozenset({"model", "friction", "gstar", "depth", "normal_force",
                               "ratio", "_correction"})

    def __setattr__(self, name, value):
        if name in self._CACHE_INPUTS:
            for cache in ("_tables", "_q_nodes", "_u_nodes"):
                self.__dict__.pop(cache, None)
        object.__setattr__(self, name, value)

    # -- single numbers ------------------------------------------------------------
    @property
    def normal_stiffness(self):
        """Normal stiffness k_n = dF/dd at the depth [N/m]."""
        return float(self.model.stiffness(self.depth))

    @property
    def stiffness(self):
        """Full-stick tangential stiffness k_t = r k_n [N/m]."""
        return self.ratio * self.normal_stiffness

    @property
    def gross_slip_shift(self):
        """Shift at gross slip u* = c(1) mu d / r [m] (c(1): the BEM table's slip
        correction at gross slip with ``method="bem"``, else 1)."""
        return self.friction * self.depth / self.ratio * self._q_factor(1.0)

    @property
    def gross_slip_force(self):
        """Sliding force mu F [N]."""
        return self.friction * self.normal_force

    # -- monotonic loading ---------------------------------------------------------
    def _q_factor(self, q):
        """Slip correction: BEM shift / law shift at load fraction q (1 without one)."""
        if self._correction is None:
            return np.ones_like(np.asarray(q, dtype=float)) if np.ndim(q) else 1.0
        qs, cs = self._correction
        return np.interp(q, qs, cs)

    def _law_force(self, shift, beyond):
        return _ft(self.model, self.depth, shift, self.friction, self.ratio, beyond)

    def _law_shift(self, q):
        """Law shift at load fraction q in [0, 1]: d - r u/mu = d(F(1 - q))."""
        q = np.asarray(q, dtype=float)
        rest = self.normal_force * (1.0 - q)
        pos = rest > 0
        if q.ndim == 0:
            z = self.model.depth(rest) if pos else 0.0
        elif pos.all():
            z = self.model.depth(rest)
        else:
            # one evaluation over the whole array (the full normal force stands in
            # where nothing is left, then zeroed): no gather and scatter
            z = np.asarray(self.model.depth(np.where(pos, rest, self.normal_force)),
                           dtype=float)
            z[~pos] = 0.0
        return self.friction * (self.depth - z) / self.ratio

    def force(self, shift, *, beyond="raise"):
        r"""Tangential force F_t(u) [N] under a monotonic shift u [m] from zero.

        ``beyond="saturate"`` returns mu F beyond gross slip (|u| > u*) instead of
        raising :class:`OutOfRangeError`. With a slip correction, arrays of 32768 values
        or more are evaluated by a table built once per contact, equal to the root to
        1e-12 mu F (docs/tangential.md).
        """
        if self._correction is None:
            return out(self._law_force(shift, beyond))
        _check_beyond(beyond)
        u = np.asarray(shift, dtype=float)
        ustar = self.gross_slip_shift
        if u.size >= _TABLE_MIN and np.isfinite(u.min()) and np.isfinite(u.max()):
            table = self._table("force")
            if table is not None:
                top = max(-float(u.min()), float(u.max()))
                if beyond == "raise" and top > ustar * (1 + 1e-12):
                    raise OutOfRangeError("shift", top, f"[-{ustar:.6g}, {ustar:.6g}] m",
                                          unit="m", hint="beyond gross slip; "
                                                         "beyond='saturate'")
                return out(table(u, ustar, self.gross_slip_force))
        a = np.abs(u)
        if beyond == "raise" and np.any(a > ustar * (1 + 1e-12)):
            raise OutOfRangeError("shift", float(a.max()), f"[-{ustar:.6g}, {ustar:.6g}] m",
                                  unit="m", hint="beyond gross slip; beyond='saturate'")
        q = np.where(a >= ustar, 1.0, self._q_of_shift_reference(np.minimum(a, ustar)))
        return out(np.sign(u) * q * self.gross_slip_force)

    def _corrected_shift(self, q):
        return self._law_shift(q) * self._q_factor(q)

    def _shift_slope(self, q):
        """da/dq of the shift a(q) = u_law(q) c(q) for q in [0, 1) (c' of the segment of
        the slip correction to the right of q): du_law/dq = (mu/r) F / k_n(d(F(1-q)))."""
        q = np.asarray(q, dtype=float)
        z = np.asarray(self.model.depth(self.normal_force * (1.0 - q)), dtype=float)
        k = np.asarray(self.model.stiffness(z), dtype=float)
        dlaw = self.friction * self.normal_force / (self.ratio * k)
        if self._correction is None:
            return dlaw
        qs, cs = self._correction
        j = np.clip(np.searchsorted(qs, q, side="right") - 1, 0, qs.size - 2)
        law = self.friction * (self.depth - z) / self.ratio
        return dlaw * self._q_factor(q) + law * (cs[j + 1] - cs[j]) / (qs[j + 1] - qs[j])

    def _kinks(self):
        """Load fractions of the slip correction's kinks (none without one)."""
        return () if self._correction is None else tuple(self._correction[0][1:-1])

    def _table(self, which):
        """The tabulated law ("shift": u(q)/u*, "force": q(u/u*)), built once, or None
        where it does not reproduce the direct evaluation to _TABLE_TOL."""
        tables = self.__dict__.setdefault("_tables", {})
        if which not in tables:
            try:
                tables[which] = self._build_table(which)
            except (ValueError, ArithmeticError):
                # a model that cannot be evaluated at the table's nodes (e.g. at the
                # tiny rests near gross slip): the direct evaluation stays
                tables[which] = None
        return tables[which]

    def _build_table(self, which):
        ustar = self.gross_slip_shift
        if which == "shift":
            def nodes_fun(q):
                return self._corrected_shift(q) / ustar, self._shift_slope(q) / ustar

            table = _EndTable(nodes_fun, lambda q: self._corrected_shift(q) / ustar,
                              self._kinks())
        else:
            def nodes_fun(x):
                q = self._q_of_shift_reference(x * ustar)
                return q, ustar / self._shift_slope(q)

            def exact(x):                     # q = 1 at gross slip, as force() has it
                return np.where(x >= 1.0, 1.0, self._q_of_shift_reference(x * ustar))

            kinks = [float(self._corrected_shift(qk)) / ustar for qk in self._kinks()]
            table = _EndTable(nodes_fun, exact, kinks)
        return table if table.usable else None

    def _q_of_shift_reference(self, a):
        """q with u_law(q) c(q) = a (an increasing function of q on [0, 1]).

        A tabulated inverse brackets each root between two of 1025 nodes (one sorted
        search); the Illinois variant of regula falsi then converges superlinearly
        inside the bracket (each step one evaluation of the law over the array), to
        |bracket| <= 1e-15 or |u(q) - a| <= 1e-15 u*, where a bisection took 60 steps.
        """
        if not hasattr(self, "_q_nodes"):
            # nodes dense near q = 1, where d(F(1 - q)) varies fastest
            s = np.linspace(0.0, 1.0, 1025)
            self._q_nodes = 1.0 - (1.0 - s) ** 2
            self._u_nodes = np.maximum.accumulate(self._corrected_shift(self._q_nodes))
        qn, un = self._q_nodes, self._u_nodes
        flat = np.asarray(a, dtype=float).ravel()
        j = np.clip(np.searchsorted(un, flat, side="right") - 1, 0, qn.size - 2)
        lo, hi = qn[j].copy(), qn[j + 1].copy()
        flo, fhi = un[j] - flat, un[j + 1] - flat
        side = np.zeros(flat.shape, dtype=np.int8)
        eps = 1e-15 * max(un[-1], np.finfo(float).tiny)
        # first estimate: the table's linear inverse
        du = un[j + 1] - un[j]
        q = np.clip(lo + (flat - un[j]) * (hi - lo) / np.where(du > 0, du, 1.0), lo, hi)
        act = np.arange(flat.size)          # cells not yet converged
        for _ in range(100):
            f = self._corrected_shift(q[act]) - flat[act]
            done = (np.abs(f) <= eps) | (hi[act] - lo[act] <= 1e-15)
            keep = ~done
            act, f = act[keep], f[keep]
            if act.size == 0:
                break
            left = f < 0                     # root in (q, hi]
            l_, h_, fl, fh, sd, qa = lo[act], hi[act], flo[act], fhi[act], side[act], q[act]
            # Illinois: halve the value kept at the end that stays twice in a row
            fh = np.where(left & (sd == 1), 0.5 * fh, fh)
            fl = np.where(~left & (sd == -1), 0.5 * fl, fl)
            l_ = np.where(left, qa, l_)
            fl = np.where(left, f, fl)
            h_ = np.where(left, h_, qa)
            fh = np.where(left, fh, f)
            lo[act], hi[act], flo[act], fhi[act] = l_, h_, fl, fh
            side[act] = np.where(left, 1, -1)
            denom = fh - fl
            qn = np.where(denom > 0, l_ - fl * (h_ - l_) / np.where(denom > 0, denom, 1.0),
                          0.5 * (l_ + h_))
            q[act] = np.clip(qn, l_, h_)
        return q.reshape(np.shape(a))

    def shift(self, tangential_force):
        r"""Inverse law u(F_t) [m] for |F_t| <= mu F [N] (u* at mu F; beyond: refused).

        .. math:: u = c(q)\,\frac{\mu}{r}\left[d - d\!\left(F - |F_t|/\mu\right)\right]
                  \operatorname{sign} F_t, \qquad q = \frac{|F_t|}{\mu F}

        with c the BEM table's slip correction (``method="bem"``), else c = 1.
        """
        Ft = np.asarray(tangential_force, dtype=float)
        fmax = self.gross_slip_force
        check_interval("tangential_force", Ft, -fmax * (1 + 1e-12), fmax * (1 + 1e-12),
                       unit="N", hint="more than mu F: the contact slides (no static "
                                      "equilibrium)")
        if Ft.size >= _TABLE_MIN:
            table = self._table("shift")
            if table is not None:
                return out(table(Ft, fmax, self.gross_slip_shift))

        def chain(fb):
            q = np.minimum(np.abs(fb) / fmax, 1.0)
            return np.sign(fb) * self._law_shift(q) * self._q_factor(q)

        return out(blockwise(chain, Ft))

    def stick_radius(self, shift):
        r"""MDR stick radius c = a(z) [m] with F(z) = F - |F_t(u)|/mu (0 at gross slip).

        The radius of the stick zone of the MDR profile, exact for axisymmetric
        contacts; `shift` u [m], beyond gross slip refused.
        """
        q = np.abs(np.asarray(self.force(shift), dtype=float)) / self.gross_slip_force
        rest = self.normal_force * (1.0 - q)
        res = np.zeros(q.shape)
        pos = rest > self.normal_force * 1e-14
        if np.any(pos):
            res[pos] = self.model.contact_radius(self.model.depth(rest[pos]))
        return out(res)

    def slip_state(self, shift):
        """``"stick"`` (u = 0), ``"partial slip"`` (0 < |u| < u*) or ``"gross slip"``."""
        a = np.abs(np.asarray(shift, dtype=float))
        state = np.where(a == 0, "stick",
                         np.where(a < self.gross_slip_shift, "partial slip", "gross slip"))
        return state[()] if state.ndim == 0 else state

    # -- cyclic loading (Masing) ----------------------------------------------------
    def _amplitude(self, amplitude, beyond):
        return _amplitude(amplitude, beyond, self.gross_slip_shift,
                          "beyond gross slip; beyond='saturate' adds the sliding "
                          "(Coulomb) part of the loop")

    def unloading(self, shift, amplitude, *, beyond="raise"):
        r"""Masing unloading branch from (u0, F0): F_t = F0 - 2 f((u0 - u)/2) [N].

        `shift` u in [-u0, u0] [m], `amplitude` u0 [m].
        """
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        F0 = self.force(u0, beyond=beyond)
        return out(F0 - 2 * np.asarray(self.force((u0 - u) / 2, beyond=beyond)))

    def reloading(self, shift, amplitude, *, beyond="raise"):
        r"""Masing reloading branch from (-u0, -F0): F_t = -F0 + 2 f((u0 + u)/2) [N]."""
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        F0 = self.force(u0, beyond=beyond)
        return out(-F0 + 2 * np.asarray(self.force((u0 + u) / 2, beyond=beyond)))

    def loop(self, amplitude, n=101, *, beyond="raise"):
        """Closed hysteresis loop of amplitude u0 [m]: (u [m], F_t [N]), 2n - 1 points.

        Unloading from (u0, F0) to (-u0, -F0), then reloading back to (u0, F0).
        """
        u0 = float(_scalar_check(self._amplitude(amplitude, beyond), "amplitude"))
        down = np.linspace(u0, -u0, int(n))
        up = down[::-1][1:]
        u = np.concatenate([down, up])
        ft = np.concatenate([self.unloading(down, u0, beyond=beyond),
                             self.reloading(up, u0, beyond=beyond)])
        return u, ft

    def _masing_energy(self, amplitude):
        """W [J] for amplitudes u0 <= u* [m], law without slip correction.

        Integrating by parts, W = 8 int_0^u0 f - 4 u0 f(u0) = 4 int_0^u0 (u0 - 2s) f'(s) ds
        with f'(s) = r k_n(d - r s/mu); as int_0^u0 (u0 - 2s) ds = 0, k_n(d) may be
        subtracted, which removes the cancellation of the O(u0^2) terms (W ~ u0^3 at
        small amplitude). 64-point Gauss-Legendre in s = u0 (1 - t^2), smooth at
        s = u* where k_n(z) ~ sqrt(z) (sphere) starts.
        """
        u0 = np.asarray(amplitude, dtype=float)
        mu, r, d = self.friction, self.ratio, self.depth
        t = 0.5 * (_GL_T + 1.0)
        w = 0.5 * _GL_W
        u = u0[..., None]
        s = u * (1.0 - t ** 2)
        z = np.maximum(d - r * s / mu, 0.0)
        kz = np.zeros(z.shape)
        pos = z > 0
        kz[pos] = self.model.stiffness(z[pos])
        kd = float(self.model.stiffness(d))
        integrand = (u - 2 * s) * (kz - kd) * 2 * u * t
        return 4 * r * np.sum(integrand * w, axis=-1)

    def _masing_energy_direct(self, amplitude):
        """W = 8 int_0^u0 f - 4 u0 f(u0) [J] by quadrature of f itself (any law, e.g. with
        the BEM slip correction; relative cancellation ~ u*/u0 at small amplitude)."""
        u0 = np.asarray(amplitude, dtype=float)
        t = 0.5 * (_GL_T + 1.0)
        w = 0.5 * _GL_W
        u = u0[..., None]
        s = u * (1.0 - t ** 2)
        f = np.asarray(self.force(s))
        integral = np.sum(f * 2 * u * t * w, axis=-1)
        return 8 * integral - 4 * u0 * np.asarray(self.force(u0))

    def dissipated_energy(self, amplitude, *, beyond="raise"):
        r"""Energy dissipated per full cycle of amplitude u0 [m]: W [J] (Masing).

        .. math:: W = 8\int_0^{u_0} f(s)\,ds - 4 u_0 f(u_0)

        Beyond gross slip (``beyond="saturate"``) the sliding part adds
        4 mu F (u0 - u*). With a BEM slip correction the formula is integrated with
        the corrected f directly.
        """
        u0 = self._amplitude(amplitude, beyond)
        ustar = self.gross_slip_shift
        if self._correction is None:
            W = self._masing_energy(np.minimum(u0, ustar))
        else:
            W = self._masing_energy_direct(np.minimum(u0, ustar))
        W = W + 4 * self.gross_slip_force * np.maximum(u0 - ustar, 0.0)
        return out(W)


def _scalar_check(value, name):
    v = np.asarray(value)
    if v.ndim:
        raise OutOfRangeError(name, f"an array of shape {v.shape}", "a single number",
                              hint="one TangentialContact per normal state; its methods "
                                   "are vectorised over the shift")
    return v
