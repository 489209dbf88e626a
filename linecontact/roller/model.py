"""The coupled-slice model of a profiled, tilted roller on a flat (or a raceway through
its effective radius): :class:`ProfiledRoller` and :func:`roller_contact` (the method is
described in :mod:`linecontact.roller`).
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from .._engine import check_engine, resolve_engine
from .._numerics import CACHE_BYTES, cache_nbytes, serial_blas
from ..checks import check_flag, check_interval, check_positive
from ..errors import OutOfRangeError
from ..profiles import (as_profile, drop_inside, drop_slope_inside, is_free_tilt,
                        profile_identity, roller_drop)
from .coverage import coverage_note, geometry_cause
from .slices import (DEFAULT_N_SLICES, N_SLICES, SLICE_GRADING, TILT_RANGE,
                     ConvergenceError, SliceEquations, coarse_slices)
from .solution import RollerSolution, contact_extent, peak_pressure

__all__ = ["ProfiledRoller", "roller_contact"]

#: Default grading of the slice widths towards the ends of the overlap interval
#: (slices.slice_positions; docs/profiled_rollers.md, "Slice convergence").
DEFAULT_GRADING = 0.8
#: refinements of the end slices where the peak is not resolved, and the change in
#: p_max between the last two below which it counts as converged
#: (ProfiledRoller._end_refined; docs/profiled_rollers.md, "Slice convergence")
REFINE_LEVELS = 5
REFINE_TOL = 2e-3
#: the relative distances from an infinite-drop end at which _end_root looks first
_END_STEPS = np.geomspace(1.0, 1e-6, 40)


class ProfiledRoller:
    """A profiled roller on a flat (or a raceway via R), solved by coupled slices.

    .. math:: h(x, y) = y^2/(2R) + P(x) - \\theta x

    The n slices span the interval where the rigid bodies overlap,
    {x : d + theta x - P(x) > 0} (clipped to the roller): on a half-space the surface
    displacement is positive wherever there is pressure, so the contact lies inside
    that interval, and the slices resolve the contact, not the whole roller.

    Parameters
    ----------
    radius : float
        Radius R across the axis, or the effective radius against a raceway,
        0 < R < inf [m].
    length : float
        Roller length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].
    profile : Profile or str or None, optional
        Profile drop (:mod:`linecontact.profiles`), a spec such as
        ``"circular:Rc=500mm"`` (see :func:`~linecontact.profiles.parse_profile`), or
        None for a straight roller. A spec is read with this R: ``"iso16281"`` without
        ``D=`` takes D = 2R, the roller's diameter only on a flat; against a raceway
        write ``"iso16281:D=..."``.
    n_slices : int, optional
        Number of slices n, 10 <= n <= 4000 [-] (default 50).
    grading : float, optional
        Grading of the slice widths towards both ends of the overlap interval,
        0 <= grading < 1 [-]: the end slices are (1 - grading) times the uniform width
        and the middle ones (1 + grading) times (default 0.8; 0: uniform slices). The
        pressure varies fastest near the contact's ends (a crown's edge, a profile's
        end zone, an end relief); graded slices resolve its peak there: with the
        defaults the peak pressure is within 0.9 % of the converged 3D BEM over
        tables/roller_accuracy.csv, where 100 uniform slices were 3 % off
        (docs/profiled_rollers.md, "Slice convergence").
    refine_ends : bool, optional
        Where the peak is not resolved (it sits within two slices of the contact's
        end, or in the end zone of an end where the profile's drop is infinite, e.g.
        a logarithmic profile at a high load, whose contact ends microns before the
        roller end), solve again with the three end slices at each end split into
        slices growing geometrically from 1/32, 1/64, ... 1/512 of their width (up to
        five levels), until two successive refinements agree within 0.2 % in p_max
        (default True; False:
        report the unrefined solution, flagged). Solutions whose peak is resolved
        are not affected.
    engine : {"auto", "numpy", "c"}, optional
        Who evaluates the slice equations' kernels, linearisation and Newton-step
        arithmetic: "numpy" (the reference), "c" (the C extension built at install
        where a C compiler exists: the same arithmetic, results equal to numpy's
        within 1e-10; refused where it does not run) or "auto" (default): "c" where
        the extension is built and current, else "numpy" (docs/profiled_rollers.md,
        "Engines").

    Notes
    -----
    Valid for small contacts (b << R, depth << R) and tilts |theta| < 0.1 rad. The
    profile must cover -L/2 <= x <= L/2. The overlap interval is found on a grid of
    16 n + 1 points along the roller. Accuracy: see the module docstring.

    A roller keeps its last solution to start the next (sweeps and end refinements
    are warm-started), so its solves change its state: use one roller per thread
    (a copy each; solving one roller from several threads at once is not safe).

    Examples
    --------
    Crowned roller, R = 10 mm, Rc = 500 mm, L = 20 mm, steel, 1 kN (exact Hertz: approach
    7.024 um, p0 1102 MPa):

    >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
    >>> s = r.at_force(1000.0)
    >>> f"{s.depth * 1e6:.3f} um, {s.p_max / 1e6:.0f} MPa, edge loaded: {s.edge_loaded}"
    '7.024 um, 1102 MPa, edge loaded: False'

    References
    ----------
    See the module docstring.
    """

    def __init__(self, radius, length, estar, profile=None, n_slices=DEFAULT_N_SLICES,
                 grading=DEFAULT_GRADING, refine_ends=True, engine="auto"):
        R = float(check_positive("radius", radius, "m"))
        L = float(check_positive("length", length, "m"))
        E = float(check_positive("estar", estar, "Pa"))
        n = N_SLICES.check(n_slices).item()
        if n != int(n):
            raise OutOfRangeError("n_slices", n_slices, "an integer in [10, 4000]")
        n = int(n)
        grading = float(SLICE_GRADING.check(grading).item())
        prof = as_profile(profile, R, L, E)
        fx, fP, end_cache, d0_cache, ident = _fine_grid(prof, L, n)
        # set at once, past __setattr__ (whose rebuild starts once _warm is set)
        self.__dict__.update(
            radius=R, length=L, estar=E, n_slices=n, grading=grading,
            _profile_spec=profile,             # read again with a new R (__setattr__)
            profile=prof,
            _fx=fx, _fP=fP, _end_cache=end_cache, _d0_shared=d0_cache, _ident=ident,
            _drop_at=drop_inside(prof, L), _drop_slope_at=drop_slope_inside(prof),
            # _drop_slope's step 1e-7 L and its bounds, inside the roller by 1e-9 L/2
            # (a logarithmic profile's drop is infinite at the ends): per roller
            _slope_consts=(1e-7 * L, -L / 2 * (1 - 1e-9), L / 2 * (1 - 1e-9)),
            refine_ends=check_flag("refine_ends", refine_ends),
            engine=check_engine(engine), _refine=0, _memo=None, _free_memo=0.0,
            _d0_memo=None, iterations=0)
        self._warm = None                        # last: marks the roller constructed

    #: The settings a solve depends on: one set after construction builds the roller
    #: anew, checked as at construction (the grid of the profile drop, the caches and
    #: the warm starts follow it): a length or grading set later was used by some
    #: steps and not by others, and a bad one was not refused.
    _SETTINGS = ("radius", "length", "estar", "profile", "n_slices", "grading",
                 "refine_ends", "engine")

    def __setattr__(self, name, value):
        if name in self._SETTINGS and "_warm" in self.__dict__:     # constructed
            args = {k: self.__dict__[k] for k in self._SETTINGS}
            args["profile"] = self._profile_spec
            args[name] = value
            self.__dict__.update(ProfiledRoller(**args).__dict__)
            return
        object.__setattr__(self, name, value)

    def first_contact_depth(self, tilt=0.0):
        """Depth of first contact, min over x of P(x) - theta x [m] (on the 16 n + 1 grid).

        .. math:: d_0 = \\min_x \\left[P(x) - \\theta x\\right]

        Parameters
        ----------
        tilt : float, optional
            Tilt theta [rad].

        Returns
        -------
        float
            d0 [m]; no contact for d <= d0.

        Notes
        -----
        The minimum over a grid of 16 n + 1 points, refined by the parabola through the
        three smallest values (exact for a circular crown).

        Examples
        --------
        >>> r = ProfiledRoller(5e-3, 10e-3, 1e11, "circular:Rc=0.1", n_slices=10)
        >>> r.first_contact_depth(), f"{r.first_contact_depth(1e-3) * 1e6:.3f} um"
        (0.0, '-0.050 um')
        """
        return self._contact_depth(TILT_RANGE.check(tilt).item())

    def _contact_depth(self, th):
        """first_contact_depth at a checked tilt th (a float), the last one kept: a
        solve at a given tilt asks twice (its start and its memo). The memo is read once
        (a pair replaced whole): another thread may replace it between two reads. Past
        the memo, the depths of the tilts met so far by the rollers that share this
        one's grid (_fine_grid: equal profiles, L and n), up to 64: a new roller per
        solve meets the same tilt each time."""
        memo = self._d0_memo
        if memo is not None and memo[0] == th:
            return memo[1]
        shared = self._d0_shared
        hmin = shared.get(th)
        if hmin is None:
            hmin = self._first_contact(th)
            if len(shared) >= 64:
                shared.clear()
            shared[th] = hmin
        self._d0_memo = (th, hmin)
        return hmin

    def _first_contact(self, th):
        """min over the 16 n + 1 points of P(x) - theta x, refined by a parabola."""
        h = self._fP - th * self._fx
        k = int(h.argmin())
        hmin = float(h[k])
        if 0 < k < len(h) - 1 and np.isfinite(h[k - 1:k + 2]).all():
            den = h[k - 1] - 2 * h[k] + h[k + 1]
            corr = (h[k + 1] - h[k - 1]) ** 2 / (8 * den) if den > 0 else 0.0
            if corr > 1e-12 * max(abs(h[k - 1]), abs(h[k + 1])):
                # vertex of the parabola through the three smallest values
                hmin = float(h[k] - corr)
        return hmin

    def _grid(self, d, th, n=None):
        """Slices over the overlap interval, its ends interpolated between grid points.

        The ends move continuously (piecewise linearly) with d and theta, so that F(d)
        is continuous; their derivatives enter the stiffness matrix. `n`: the number of
        base slices (default n_slices; the cold start's first sweeps take fewer).
        """
        fx = self._fx
        over = th * fx          # d + theta x - P in place (the sum commutes: the same
        over += d               # floats as the expression, without its temporaries)
        over -= self._fP
        # the first and last grid points inside (argmax of the mask: a tenth of
        # flatnonzero's time on the 16 n + 1 points, the same indices)
        mask = over > 0
        i = int(mask.argmax())
        dlo = dhi = (0.0, 0.0)
        last = len(fx) - 1
        # (the scalars below as Python floats: the same IEEE arithmetic as numpy's
        # scalars, at a fraction of the cost per operation)
        if not mask[i]:
            k = int(over.argmax())
            lo, hi = float(fx[max(k - 1, 0)]), float(fx[min(k + 1, last)])
        else:
            j = last - int(mask[::-1].argmax())
            lo, hi = float(fx[0]), float(fx[-1])
            h = float(fx[1] - fx[0])
            if i > 0:
                o0, o1 = over[i - 1:i + 1].tolist()
                if math.isfinite(o0):
                    x0, x1 = fx[i - 1:i + 1].tolist()
                    delta = o1 - o0
                    lo = x0 + h * (-o0 / delta)
                    dlo = (-h / delta, h * (-x0 * delta + o0 * (x1 - x0)) / delta**2)
                else:
                    # the drop is infinite at the end x = -L/2 (a logarithmic profile)
                    lo, dlo = self._end_root(d, th, float(fx[i]), -1)
            if j < last:
                o0, o1 = over[j:j + 2].tolist()
                if math.isfinite(o1):
                    x0, x1 = fx[j:j + 2].tolist()
                    delta = o0 - o1
                    hi = x0 + h * (o0 / delta)
                    dhi = (h / delta, h * (x0 * delta - o0 * (x0 - x1)) / delta**2)
                else:
                    hi, dhi = self._end_root(d, th, float(fx[j]), 1)
        # the drop and its slope at the slice centres in one evaluation of the profile
        # (the slope serves every Newton step on this grid, _drop_slope)
        got = []

        def drop(x):
            P, slope = self._drop_slope(x)
            got.append(slope)
            return P
        s = SliceEquations(self.radius, self.estar, lo, hi,
                           n or self.n_slices, drop, self.grading, self._refine,
                           resolve_engine(self.engine))
        s.dlo, s.dhi = dlo, dhi
        s.slope_values = got[0]
        return s

    def _end_root(self, d, th, x_in, side):
        """The end of the overlap interval between the last grid point x_in inside it
        and the roller end side L/2 (side = -1, +1), where the drop is infinite (a
        logarithmic profile): the rigid overlap d + theta x - P(x) falls to zero there
        within the last grid interval, L/(16 n) wide, which is as wide as several end
        slices. Located on 40 points graded geometrically towards the end (from the
        interval's width down to 1e-6 of it), then on 33 even points in the bracket,
        and interpolated linearly there, as on the grid (continuous in d and theta).
        Returns the end and its derivatives with respect to (d, theta)."""
        end = side * self.length / 2
        key = (side, x_in)
        # a scan in Python floats (the same arithmetic as numpy's, elementwise): the
        # first point outside comes after a few (the 4th-6th of 40 in the benchmark's
        # solves), where the array operations cost more than the scan
        d, th = float(d), float(th)
        for level in range(2):
            xs, Ps = self._end_points(key, end, side, x_in)[3:]
            for k, (xk, Pk) in enumerate(zip(xs, Ps)):
                if d + th * xk - Pk <= 0:     # (the first point, x_in, is inside)
                    break
            else:                           # overlapping to within 1e-6 of the interval
                return xs[-1], (0.0, 0.0)
            key += (k,)
        x0, x1 = xs[k - 1], xs[k]
        o0, o1 = d + th * x0 - Ps[k - 1], d + th * x1 - Ps[k]
        delta = o0 - o1
        h = x1 - x0
        root = x0 + h * (o0 / delta)
        return root, (h / delta, h * (x0 * delta - o0 * (x0 - x1)) / delta**2)

    def _end_points(self, key, end, side, x_in):
        """The distances u from the end, the points x and the drop there of one level
        of _end_root's search (and x and the drop as lists of floats): key (side, x_in)
        the 40 graded points, key (side, x_in, k) the 33 even points between the first
        level's points k - 1 and k. They depend only on the key: cached, as the Newton
        steps of a solve, and the solves of a sweep, meet the same few (the cache is
        shared by the rollers of equal profiles, _fine_grid)."""
        hit = self._end_cache.get(key)
        if hit is None:
            if len(key) == 2:
                u = abs(end - x_in) * _END_STEPS
            else:
                u0 = self._end_points(key[:2], end, side, x_in)[0]
                u = np.linspace(u0[key[2] - 1], u0[key[2]], 33)
            x = end - side * u
            P = roller_drop(self.profile, self.length, x)
            hit = (u, x, P, x.tolist(), P.tolist())
            if self._ident is not None and profile_identity(self.profile) != self._ident:
                # the profile was changed in place since construction: its drop is not
                # that of the rollers this cache is shared with (_fine_grid), kept out
                return hit
            if len(self._end_cache) >= 64:
                self._end_cache.clear()
            self._end_cache[key] = hit
        return hit

    def _drop_slope(self, x):
        """The drop P(x) and dP/dx at points x strictly inside the roller: the slope
        in closed form where the profile has one (profiles.drop_slope_inside: the
        smooth profiles of linecontact.profiles), else by central differences (step
        1e-7 L, inside the roller) from one evaluation of the profile at x, x + h and
        x - h (profiles.drop_inside: without roller_drop's clamp and checks for the
        profiles of linecontact.profiles). Central differences carry a relative error
        of ~1e-9 (rounding of P over h); the slope enters the Newton step's grid columns
        and the stiffness matrix, so the closed form moved the converged results of the
        104 cases of tables/roller_accuracy.csv within the Newton tolerance: the
        stiffness matrix by up to 8e-11 (of sqrt(K_ii K_jj)), q 1.4e-12, p_max 5e-13,
        the depth 1e-14; up to 4.8e-9 in the stiffness of a Lundberg roller with L =
        3 D (docs/profiled_rollers.md, "Time per solve")."""
        exact = self._drop_slope_at
        if exact is not None:
            return exact(x)
        h, lo_in, hi_in = self._slope_consts
        n = len(x)
        X = np.empty(3 * n)
        X[:n] = x
        xp, xm = X[n:2 * n], X[2 * n:]
        np.minimum(np.add(x, h, out=xp), hi_in, out=xp)
        np.maximum(np.subtract(x, h, out=xm), lo_in, out=xm)
        P = self._drop_at(X)
        dP = np.subtract(P[n:2 * n], P[2 * n:])
        return P[:n], np.divide(dP, np.subtract(xp, xm, out=xp), out=dP)

    # -- depth control ---------------------------------------------------------------
    @serial_blas
    def at_depth(self, depth, tilt=0.0):
        """Solve at depth d and tilt theta.

        .. math:: u(x_k, 0) = d + \\theta x_k - P(x_k) \\text{ on loaded slices}

        Parameters
        ----------
        depth : float or array_like
            Depth d of the roller point x = 0 [m]; must exceed
            :meth:`first_contact_depth` (else there is no contact). An array of
            several depths gives an array of solutions, one per depth (one value,
            also in a one-element array, gives one solution).
        tilt : float or str, optional
            Tilt theta, |theta| < 0.1 [rad] (default 0: aligned); ``"free"``: the tilt
            at which the moment about x = 0 vanishes at this depth.

        Returns
        -------
        RollerSolution, or an object ndarray of them (shape of `depth`)

        Raises
        ------
        OutOfRangeError
            A depth at or below first contact (no contact at all), or a bad tilt.

        Examples
        --------
        >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
        >>> f"{r.at_depth(7.0244e-6).force:.0f} N"
        '1000 N'
        """
        if np.size(depth) != 1:
            return _each(lambda d: self.at_depth(d, tilt), depth, "depth", "m")
        try:
            return self._end_refined(lambda: self._at_depth(depth, tilt))
        except ConvergenceError as exc:
            raise ConvergenceError(f"{exc}; the geometry may be the cause: "
                                   + geometry_cause(self.radius, self.length,
                                                    self.estar)) from exc

    def _at_depth(self, depth, tilt):
        if is_free_tilt(tilt):
            return self._free_tilt_at_depth(depth)
        th = TILT_RANGE.check(tilt).item()
        d0 = self.first_contact_depth(th)
        d = check_interval("depth", depth, d0, np.inf, low_open=True, high_open=True,
                           unit="m", hint=f"at tilt {th:.6g} rad the roller first touches "
                                          f"at depth {d0:.6g} m; at or below it there is "
                                          "no contact").item()
        return self._solution(*self._forces(d, th))

    def _end_refined(self, solve):
        """`solve()`, and where its peak is not resolved (at the contact's end, or in
        the end zone of an infinite-drop end) solved again with the end slices split
        (slices.end_refined, levels 1 to REFINE_LEVELS: end slices 1/32, 1/64, ...
        of the three base slices they replace, growing by at most 10 % a slice), each from
        the last solution, until two successive levels resolve the peak and agree
        within REFINE_TOL. Otherwise the finest level solved is returned, flagged
        unresolved, with the change it measured."""
        sol = solve()
        if sol.edge_loaded or sol.p_max_resolved or not self.refine_ends:
            return sol
        prev, change, done = sol, math.inf, 0
        try:
            for level in range(1, REFINE_LEVELS + 1):
                self._refine = level
                try:
                    sol = solve()
                except ConvergenceError as exc:
                    sol = dataclasses.replace(prev, message=(
                        f"{prev.message}; refining the end slices further failed "
                        f"({exc})"))
                    change = math.inf
                    break
                done = level
                if sol.edge_loaded:
                    return sol
                change = abs(sol.p_max / prev.p_max - 1)
                if level > 1 and sol.p_max_resolved and prev.p_max_resolved and (
                        change <= REFINE_TOL):
                    return dataclasses.replace(sol, message=(
                        f"{sol.message}; the end slices refined {level} times "
                        f"({sol.n_slices} slices, the finest "
                        f"{min(sol.width[0], sol.width[-1]):.3g} m wide): p_max changed by "
                        f"{100 * change:.2g} % at the last refinement"))
                prev = sol
        finally:
            self._refine = 0
        msg = sol.message
        if sol.p_max_resolved:
            msg += "; not converged, refine n_slices"
        return dataclasses.replace(sol, p_max_resolved=False, message=(
            f"{msg} (the end slices refined {done} times, {sol.n_slices} "
            f"slices, the finest {min(sol.width[0], sol.width[-1]):.3g} m wide: p_max "
            f"changed by {100 * change:.2g} % at the last refinement, more than "
            f"{100 * REFINE_TOL:g} %)"))

    def _warm_start(self, s, d, th):
        """The last solution, mapped onto the grid s by the relative position in the
        overlap interval and scaled with the largest overlap (q ~ overlap); None if
        there is none or the overlap changed by more than a factor 10."""
        if self._warm is None:
            return None
        e = float((d + th * s.x - s.P).max())          # largest overlap on the slices
        xi_o, qo, co, eo = self._warm
        ratio = e / eo if eo > 0 else 0.0
        if not 0.1 < ratio < 10.0:
            return None
        xi = (s.x - s.lo) / (s.hi - s.lo)
        return (np.interp(xi, xi_o, qo, left=0.0, right=0.0) * ratio,
                np.interp(xi, xi_o, co))

    def _controlled(self, d, th, force=None, zero_moment=False, tol=1e-11):
        """Solve with the force and/or zero moment imposed, Newton on the slice loads
        together with d and/or theta (SliceEquations.bordered) from depth d, tilt th."""
        # a cold start at a force begins on the coarser grid of its first sweeps
        # (SliceEquations.start_at_force)
        n0 = coarse_slices(self.n_slices) if (
            force is not None and self._warm is None) else self.n_slices
        s = self._grid(d, th, n0)
        warm = self._warm_start(s, d, th)
        first = None
        if force is not None:
            # the bordered linear start, with the last solution's strip widths where
            # there is one (a sweep, an end refinement). Starting from its loads as they
            # are, mapped onto this grid, took more Newton steps where the force was
            # within 10 % of it: the refined end slices' loads are poor there (over the
            # 104 cases of tables/roller_accuracy.csv the refinements' re-solves took
            # 396 steps that way, 184 this way; a 20-force sweep 427 and 252 at 2 mrad)
            width = None
            if warm is not None:
                # the last solution's strip widths, scaled as b ~ overlap^(1/2)
                xi_o, qo, co, eo = self._warm
                on = qo > 0
                ratio = float((d + th * s.x - s.P).max()) / eo
                width = (xi_o[on], np.sqrt(qo[on] / co[on] * ratio))
            try:
                first = s.start_at_force(self._grid, d, th, force, zero_moment, width,
                                         last_n=self.n_slices)
            except np.linalg.LinAlgError as err:
                # as a singular Newton system below: the nested iteration answers
                raise ConvergenceError(
                    f"the cold start's linear system became singular ({err})") from err
        if first is None:
            if n0 != self.n_slices:
                s = self._grid(d, th)
            S, q, c = s.start(d, th, warm)
        else:
            s, S, q, c, d, th = first
        try:
            s, S, q, c, d, th, F, M, K = s.bordered(self._grid, S, q, c, d, th, force,
                                                    zero_moment, tol)
        except np.linalg.LinAlgError as err:
            # a Newton system gone singular (a free tilt started far off: the loaded
            # set down to two slices, whose force and moment rows are then dependent)
            # is a failure to converge, which the caller answers with the nested
            # iteration (never a bare LinAlgError to the user)
            raise ConvergenceError(f"the Newton system became singular ({err})") from err
        self._warm = ((s.x - s.lo) / (s.hi - s.lo), q.copy(), c.copy(),
                      float((d + th * s.x - s.P).max()))
        self.iterations += s.iterations
        return d, th, F, M, K, (s, S, q, c)

    def _start_depth(self, F0, th):
        """A first depth for force F0 at tilt th: from the last solution of this roller
        (F ~ (d - d0)^slope), else the straight roller's 2D estimate."""
        d0 = self._contact_depth(th)
        L, R, E = self.length, self.radius, self.estar
        memo = self._memo           # read once: another thread may replace it (whole)
        if memo is not None and memo[0] == th:
            _, e_last, F_last, slope = memo
            return d0 + e_last * (F0 / F_last) ** (1.0 / slope)
        return d0 + F0 / (math.pi * E * L) * max(
            1.0 + math.log(max(math.pi * E * L**3 / (R * F0), math.e)), 2.0)

    def _forces(self, d, th, tol=1e-11):
        s = self._grid(d, th)
        warm = self._warm_start(s, d, th)
        S, q, c = s.solve(d, th, warm=warm, tol=tol)
        self._warm = ((s.x - s.lo) / (s.hi - s.lo), q.copy(), c.copy(),
                      float((d + th * s.x - s.P).max()))
        self.iterations += s.iterations
        scale = math.pi * self.estar
        F = scale * (s.w @ q)
        M = scale * ((s.w * s.x) @ q)
        K = s.sensitivities(S, q, c, th, s.slope_at_slices())
        return d, th, F, M, K, (s, S, q, c)

    def _solution(self, d, th, F, M, K, state, free_tilt=False):
        s, S, q, c = state
        qN = math.pi * self.estar * q
        qS, cS = q[S], c[S]
        b = np.zeros(q.shape)
        b[S] = np.sqrt(qS / cS)
        p = np.zeros(q.shape)
        p[S] = 2.0 * self.estar * np.sqrt(qS * cS)       # 2 q/(pi b)
        # the first and last loaded slice (argmax of the mask: the indices of
        # flatnonzero's first and last, without its index array)
        on = q > 0
        on0, on1 = int(on.argmax()), len(q) - 1 - int(on[::-1].argmax())
        if not on[on0]:          # (the solver keeps at least one: never met)
            raise ConvergenceError("no slice is loaded in the solution")
        start, stop, lo_edge, hi_edge = contact_extent(s.x, q, s.w, self.length,
                                                        s.lo, s.hi, (on0, on1))
        # within the end slice's width (or L/1000) of an end counts as reaching it: a
        # log profile's contact approaches the end without touching it exactly, and
        # the contact's end is located to within the slice width there
        near_lo = max(float(s.w[0]), 1e-3 * self.length)
        near_hi = max(float(s.w[-1]), 1e-3 * self.length)
        lo_edge = lo_edge or start <= -self.length / 2 + near_lo
        hi_edge = hi_edge or stop >= self.length / 2 - near_hi
        # an end where the drop is infinite (Lundberg, ISO 16281: ln 1/(1 - (2x/L)^2))
        # is never reached: the rigid overlap ends before it, the contact with it, and the
        # pressure stays finite (3D BEM, Lundberg at its design load, R 5 mm, L 10 mm,
        # 1 kN: contact ends 9.8 um before each end, peak 972 MPa 28 um from it, converged
        # from 1024 to 4096 cells; docs/profiled_rollers.md). A contact reaching the last
        # slice there is an end zone narrower than the slices: p_max unresolved, below.
        inf_lo, inf_hi = (not math.isfinite(self._fP[0]),
                          not math.isfinite(self._fP[-1]))
        end_zone = ((inf_lo and lo_edge and on0 == 0)
                    or (inf_hi and hi_edge and on1 == len(q) - 1))
        lo_edge = lo_edge and not inf_lo
        hi_edge = hi_edge and not inf_hi
        edge = {(True, True): "both", (True, False): "-x", (False, True): "+x"}.get(
            (lo_edge, hi_edge))
        notes = []
        resolved = False
        if edge is None:
            pm, xm = peak_pressure(s.x, p)
            k = int(p.argmax())
            resolved = on0 + 2 <= k <= on1 - 2 and not end_zone
            msg = ("peak of the Hertz strips (coupled slices, interpolated); the contact "
                   "stays inside the roller")
            if end_zone:
                # the largest slice pressure, not the parabola through p^2 (exact for a
                # Hertz peak, it overshoots a peak narrower than the slices: ISO/TS
                # 16281 profile, L 14 mm, D 10 mm, 300 N/mm, 2 mrad, 100 slices: 2545
                # MPa against the slice's 2434 and the converged BEM's 2363 (tables/
                # roller_accuracy.csv; 200 slices 2362)
                pm, xm = float(p[k]), float(s.x[k])
                msg += ("; it ends within the last slice before a roller end where the "
                        "profile's drop is infinite (never reached, the pressure stays "
                        "finite): that end zone and any peak in it are narrower than the "
                        "slices, not converged, refine n_slices")
            elif not resolved:
                msg += ("; the peak sits at the end of the contact, a concentration "
                        "narrower than a few slices: not converged, refine n_slices")
        else:
            pm = None
            xm = {"-x": -self.length / 2, "+x": self.length / 2}.get(edge, self.length / 2)
            msg = ("edge loaded: the contact reaches the roller end ({}), where the "
                   "pressure on a half-space is singular; a peak pressure there depends "
                   "on the slice width and is not reported").format(edge)
        bmax = b.max()
        if bmax > 0.1 * self.radius:
            notes.append(f"contact half-width b = {bmax:.3g} m exceeds 0.1 R: the "
                         "parabolic gap y^2/(2R) is inaccurate")
        # the largest rigid overlap on the 16 n + 1 points (where the drop is infinite
        # at an end the overlap there is -inf, never NaN: no floating-point warning to
        # silence, as _grid's overlap)
        over = th * self._fx
        over += d
        over -= self._fP
        approach = float(over.max())
        gaps = ([(start + self.length / 2) / self.length] if inf_lo else []) + (
            [(self.length / 2 - stop) / self.length] if inf_hi else [])
        notes.append(coverage_note(self.radius, self.length, self.estar,
                                    self.profile.key, F, th, approach, free_tilt,
                                    edge is not None, self.n_slices,
                                    min(gaps) if gaps else None))
        its, self.iterations = self.iterations, 0
        return RollerSolution._built(
            depth=float(d), tilt=float(th), force=float(F), moment=float(M),
            stiffness=float(K[0, 0]), tilt_stiffness=float(K[1, 1]), stiffness_matrix=K,
            x=s.x.copy(), width=s.w.copy(), q=qN, half_width=b, pressure=p, p_max=pm, x_at_p_max=xm,
            contact_start=start, contact_end=stop, contact_length=stop - start,
            edge_loaded=edge is not None, edge=edge, message=msg, method="coupled slices",
            n_slices=len(s.x), iterations=its, notes=tuple(notes),
            p_max_resolved=resolved)

    # -- force control -----------------------------------------------------------------
    def _depth_at_force(self, F0, th, tol):
        """Newton on ln(d - d0) for F(d) = F0 at fixed tilt (F increases with d)."""
        d0 = self.first_contact_depth(th)
        L, R, E = self.length, self.radius, self.estar
        memo = self._memo           # read once: another thread may replace it (whole)
        if memo is not None and memo[0] == th:
            # from the last solution of this roller: F ~ e^slope
            _, e_last, F_last, slope = memo
            e = e_last * (F0 / F_last) ** (1.0 / slope)
        else:
            # the straight roller's 2D estimate (a lower bound for a profiled roller)
            e = F0 / (math.pi * E * L) * max(
                1.0 + math.log(max(math.pi * E * L**3 / (R * F0), math.e)), 2.0)
        lo, hi = 0.0, math.inf
        err = 0.0 if memo is not None else math.inf   # a memo start is close
        for _ in range(100):
            # solve loosely while far from the force (inexact Newton), tightly near it
            inner = 1e-11 if err < 1e-3 else 1e-7
            st = self._forces(d0 + e, th, tol=inner)
            F, K = st[2], st[4]
            slope = min(max(K[0, 0] * e / F, 0.5), 3.0)  # d ln F/d ln e, 1 to about 1.5
            err = abs(F / F0 - 1)
            if err <= tol:
                if inner == 1e-11:
                    self._memo = (th, e, F, slope)
                    return st
                continue                      # the same depth once more, solved tightly
            if F < F0:
                lo = max(lo, e)
            else:
                hi = min(hi, e)
            en = e * (F0 / F) ** (1.0 / slope)
            if not lo < en < hi:
                en = math.sqrt(lo * hi) if (lo > 0 and math.isfinite(hi)) else (
                    e * 4 if F < F0 else e / 4)
            e = en
        raise ConvergenceError(f"no depth found for force {F0:g} N")

    @serial_blas
    def at_force(self, force, tilt=0.0, tol=1e-10):
        """Solve at force F, with a given tilt (default 0, aligned) or (tilt="free") at
        zero moment.

        .. math:: \\sum_k q_k w = F, \\qquad \\sum_k q_k x_k w = 0 \\text{ (tilt free)}

        Parameters
        ----------
        force : float or array_like
            Normal force F, 0 < F < inf [N]. An array of several forces gives an
            array of solutions, one per force (one value, also in a one-element array,
            gives one solution).
        tilt : float or str, optional
            Tilt theta [rad], |theta| < 0.1 (default 0: aligned); ``"free"`` solves
            for the tilt at which the moment about x = 0 vanishes (a roller free to
            tilt).
        tol : float, optional
            Relative tolerance on F (and on M/(F L)) [-].

        Returns
        -------
        RollerSolution, or an object ndarray of them (shape of `force`)

        Examples
        --------
        >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
        >>> s = r.at_force(1000.0, tilt=2e-3)      # contact moves to x* = Rc theta = 1 mm
        >>> f"M/F = {s.moment / s.force * 1e3:.3f} mm"
        'M/F = 1.000 mm'
        """
        if np.size(force) != 1:
            return _each(lambda f: self.at_force(f, tilt, tol), force, "force", "N")
        F0 = float(check_positive("force", force, "N"))
        try:
            return self._end_refined(lambda: self._at_force(F0, tilt, tol))
        except ConvergenceError as exc:
            raise ConvergenceError(f"{exc}; the geometry may be the cause: "
                                   + geometry_cause(self.radius, self.length,
                                                    self.estar, F0)) from exc

    def _at_force(self, F0, tilt, tol):
        free = is_free_tilt(tilt)
        th = self._free_memo if free else TILT_RANGE.check(tilt).item()
        try:
            # Newton on the slice loads together with d (and theta): one dense solve
            # per step
            st = self._controlled(self._start_depth(F0, th), th, force=F0,
                                  zero_moment=free)
        except ConvergenceError:
            st = None
        if st is not None and abs(st[2] / F0 - 1) <= tol and (
                not free or abs(st[3]) <= tol * F0 * self.length):
            d, th, F, K = st[0], st[1], st[2], st[4]
            e = d - self._contact_depth(th)
            if e > 0:
                self._memo = (th, e, F, min(max(K[0, 0] * e / F, 0.5), 3.0))
            if free:
                self._free_memo = th
            return self._solution(*st, free_tilt=free)
        # the nested iteration: slower, safeguarded
        if not free:
            return self._solution(*self._depth_at_force(F0, th, tol))
        L = self.length
        st = self._depth_at_force(F0, 0.0, tol)
        free = self._free_tilt(F0, st, tol)
        if free is not None:
            return self._solution(*free, free_tilt=True)
        th = 0.0
        for _ in range(60):
            st = self._depth_at_force(F0, th, tol)
            M, K = st[3], st[4]
            if abs(M) <= tol * F0 * L:
                return self._solution(*st, free_tilt=True)
            kmt = K[1, 1] - K[1, 0] * K[0, 1] / K[0, 0]     # dM/dtheta at constant F
            step = -M / kmt
            while abs(th + step) >= TILT_RANGE.high:
                step /= 2
            th = th + step
        raise ConvergenceError(f"no zero-moment tilt found for force {F0:g} N")

    def _free_tilt(self, F0, st, tol, steps=12):
        """Newton on (d, theta) together for F = F0 and M = 0 from the aligned solution
        `st` (its step from the exact 2x2 stiffness matrix), one slice solve per step;
        None if it leaves the admissible region or does not converge (the caller then
        iterates on theta with F solved at each tilt, slower but safe)."""
        L = self.length
        d, th = st[0], st[1]
        for _ in range(steps):
            F, M, K = st[2], st[3], st[4]
            if abs(F / F0 - 1) <= tol and abs(M) <= tol * F0 * L:
                return st
            try:
                dd, dth = np.linalg.solve(K, [F0 - F, -M])
            except np.linalg.LinAlgError:
                return None
            th_new = th + dth
            if not abs(th_new) < TILT_RANGE.high:
                return None
            d0 = self.first_contact_depth(th_new)
            d_new = d + dd
            if d_new <= d0:
                # keep the overlap positive: halve the distance to first contact
                d_new = d0 + 0.5 * (d - self.first_contact_depth(th))
            d, th = d_new, th_new
            st = self._forces(d, th)
        return None

    def _free_tilt_at_depth(self, depth):
        """Zero moment at a given centre depth: Newton on theta with dM/dtheta = K[1, 1]
        at fixed depth, safeguarded by bisection on the bracket it builds."""
        L = self.length
        th, lo, hi = 0.0, -TILT_RANGE.high, TILT_RANGE.high
        for _ in range(60):
            s = self._at_depth(depth, th)
            if abs(s.moment) <= 1e-10 * s.force * L:
                return s
            if s.moment > 0:
                hi = th
            else:
                lo = th
            new = th - s.moment / s.stiffness_matrix[1, 1]
            th = new if lo < new < hi else 0.5 * (lo + hi)
        raise ConvergenceError(f"no zero-moment tilt at depth {depth:g} m")


_FINE = {}


def _fine_grid(profile, length, n):
    """The 16 n + 1 points along the roller on which the overlap interval is found,
    the profile's drop there (checked: finite and >= 0, infinite only at an end), the
    cache of _end_root's points and that of the first-contact depth per tilt
    (_contact_depth), which depend on the profile, L and n alone:
    shared by the rollers of equal profiles (profiles.profile_identity; built anew for
    a profile without one), up to 16 of them (the arrays read-only); and that identity
    (None: not shared), against which a roller checks its profile before it adds
    _end_root's points, read off its live profile, to the shared cache (a profile
    changed in place after construction; the first-contact depths come from the
    grid itself)."""
    ident = profile_identity(profile)
    key = None if ident is None else (ident, length, n)
    hit = _FINE.get(key) if key is not None else None
    if hit is None:
        fx = np.linspace(-length / 2, length / 2, 16 * n + 1)
        fP = roller_drop(profile, length, fx, ends_may_be_inf=True)
        fx.flags.writeable = fP.flags.writeable = False
        hit = (fx, fP, {}, {})
        if key is not None:
            if len(_FINE) >= 16 or cache_nbytes(_FINE) > CACHE_BYTES:
                _FINE.clear()
            _FINE[key] = hit
    return hit + (ident,)


def roller_contact(radius, length, estar, profile=None, *, depth=None, force=None,
                   tilt=0.0, n_slices=DEFAULT_N_SLICES):
    """Solve a profiled, tilted roller on a flat at a depth or a force (coupled slices).

    .. math:: h(x, y) = y^2/(2R) + P(x) - \\theta x

    Give exactly one of `depth` or `force`, and the tilt (default 0: aligned; ``"free"``
    for zero moment).

    Parameters
    ----------
    radius : float
        Radius across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    profile : Profile or str or None
        Profile drop or spec (None: straight) [-].
    depth : float, optional
        Depth d [m].
    force : float, optional
        Force F [N].
    tilt : float or str, optional
        Tilt theta [rad] (default 0), or ``"free"``.
    n_slices : int, optional
        Number of slices [-] (default 50).

    Returns
    -------
    RollerSolution

    Raises
    ------
    OutOfRangeError
        Bad input (see :class:`ProfiledRoller`), neither or both of depth and force.

    Notes
    -----
    Valid for |theta| < 0.1 rad, b << R, 10 <= n_slices <= 4000; accuracy in the module
    docstring.

    Examples
    --------
    >>> s = roller_contact(10e-3, 20e-3, 115.385e9, "circular:Rc=0.2", force=2000.0)
    >>> f"{s.depth * 1e6:.2f} um, b {s.half_width.max() * 1e3:.4f} mm"
    '13.92 um, b 0.2859 mm'

    References
    ----------
    See the module docstring.
    """
    if (depth is None) == (force is None):
        raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                              "exactly one of depth, force")
    r = ProfiledRoller(radius, length, estar, profile, n_slices=n_slices)
    if depth is not None:
        return r.at_depth(depth, tilt)
    return r.at_force(force, tilt)


def _each(solve, values, name, unit):
    """An object array of `solve(v)` over the array `values` (same shape), each value
    checked first (finite numbers), so that an array of forces or depths is accepted
    wherever one is."""
    v = np.asarray(values, dtype=float)
    if not np.all(np.isfinite(v)):
        i = int(np.argmax(~np.isfinite(v.ravel())))
        raise OutOfRangeError(name, float(v.ravel()[i]), f"finite values [{unit}]",
                              unit=unit, where=f"element {i}")
    out = np.empty(v.shape, dtype=object)
    flat = v.ravel()
    # in increasing order: each solve starts from its neighbour's solution (the same
    # roller keeps the last solution and depth, ProfiledRoller._warm_start and
    # _start_depth), so a sweep costs a fraction of as many cold solves
    res = out.reshape(-1)
    for k in np.argsort(flat, kind="stable"):
        res[k] = solve(float(flat[k]))
    return out
