"""3D boundary-element driver for profiled and misaligned rollers on a half-space.

The problem (docs/profiled_rollers.md): a rigid roller of radius R and length L, axis
along x (|x| <= L/2), y across it, pressed into an elastic half-space of effective
modulus E* (1/E* = (1 - nu^2)/E summed over both bodies, Li & Popov 2017, Eq. 3). Its
profile drop P(x) >= 0 and tilt theta give the gap before loading

.. math::

    h(x, y) = \\frac{y^2}{2R} + P(x) - \\theta x ,

and at the rigid-body approach d (measured at the roller centre x = 0) the contact
problem is p >= 0, g = u_z[p] + h - d >= 0, p g = 0 on |x| <= L/2 (no indenter beyond
the ends). Force and moment about the roller centre:

.. math::

    F = \\int p \\, dA, \\qquad M = \\int p\\, x \\, dA, \\qquad
    q(x) = \\int p(x, y) \\, dy .

Numerics (roles as in tools/):

- Love's rectangle coefficients (tools.bem.influence, Johnson 1985 Eq. 3.25) on cells that
  may be thousands of times longer than wide;
- the free-space zero-padded DC-FFT of Liu, Wang & Liu (2000) (tools.bem.halfspace
  DCFFTOperator) on the full grid: a tilt or an asymmetric profile has no mirror plane
  across the axis. (The gap is even in y, so a mirror in y would be legitimate; there
  is no operator symmetric in y only, and the full DC-FFT is exact for any field.)
- the displacement-controlled constrained conjugate gradients of Polonsky & Keer
  (1999) (tools.bem.solver.solve_contact), with the tolerance on the gap relative to the
  largest rigid interference max_x (d + theta x - P(x));
- stiffnesses on the converged (fixed) contact set S: with the contact set held, the
  pressures are linear in (d, theta), p = K_SS^-1 (d + theta x - P - y^2/2R), so

  .. math::

      \\frac{\\partial F}{\\partial d} = \\int K_{SS}^{-1} 1, \\quad
      \\frac{\\partial M}{\\partial \\theta} = \\int x\\, K_{SS}^{-1} x, \\quad
      \\frac{\\partial F}{\\partial \\theta} = \\frac{\\partial M}{\\partial d}
          = \\int x\\, K_{SS}^{-1} 1 ,

  the first by tools.bem.solver.solve_punch (a rigid flat punch, as tools/bem/cylinder.py),
  the "tilt punch" K_SS p = x by the same solver on the symmetric scaled operator
  W^-1 K W^-1 with W = diag(x - c), c < min x (see :func:`tilt_punch`).

Grids, adapted to the load (as tools.bem.cylinder.solve_depth does across the axis):
the contact lies inside the rigid interference region {d + theta x - P(x) > y^2/2R}
(the displacement is positive), so a first pass on that region's bounding box finds
the contact; the second pass covers the contact's bounding box times ``margin`` in x
(clipped at the roller ends) and |y| <= margin * b (b: the largest contact half-width)
with ``n_x`` x ``n_y`` cells, and is widened and repeated if the contact touches a
window edge that is not a roller end. Force control (:func:`solve_roller_force`) runs
Newton's method on (d, theta) with the exact fixed-contact-set Jacobian above.

Verification: tests/test_roller_bem.py (exact Hertz for a circular crown, the tilted
crown's shift x* = Rc theta with M = F Rc theta, grid convergence).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
from scipy.fft import next_fast_len

from linecontact.checks import check_positive
from linecontact.errors import OutOfRangeError

from .halfspace import DCFFTOperator
from .solver import ConvergenceError, solve_contact, solve_punch

__all__ = ["RollerGrid", "RollerResult", "solve_roller", "solve_roller_force",
           "tilt_punch", "grid_convergence", "first_contact_depth"]

#: samples of P(x) along the roller used to find the interference region
_N_SAMPLES = 4097


def _drop_function(profile):
    """P(x) [m] from None (straight), an object with ``drop(x)`` or a callable.
    P may be +inf where the roller can never touch (a logarithmic profile's ends)."""
    if profile is None:
        return lambda x: np.zeros_like(np.asarray(x, dtype=float))
    fn = getattr(profile, "drop", profile)
    if not callable(fn):
        raise TypeError(f"profile = {profile!r} is neither a callable P(x) nor an object "
                        "with a drop(x) method")
    return fn


def _drop_values(drop, x):
    v = np.asarray(drop(np.asarray(x, dtype=float)), dtype=float)
    v = np.broadcast_to(v, np.shape(x)).astype(float)
    # +inf is a drop that never touches (a logarithmic profile at its ends)
    if np.any(np.isnan(v)):
        i = int(np.flatnonzero(np.isnan(v))[0])
        raise OutOfRangeError("profile drop", float(v.flat[i]), "[0, inf) m", unit="m",
                              where=f"at x = {float(np.ravel(x)[i]):.6g} m")
    if np.any(v < 0):
        i = int(np.flatnonzero(v < 0)[0])
        raise OutOfRangeError("profile drop", float(v.flat[i]), "[0, inf) m", unit="m",
                              where=f"at x = {float(np.ravel(x)[i]):.6g} m",
                              hint="a profile is a drop P(x) >= 0 from the roller's "
                                   "generatrix")
    return v


def first_contact_depth(length, tilt=0.0, profile=None):
    """The depth at which the roller first touches: d_c = min over |x| <= L/2 of P(x) - theta x.

    .. math::

        d_c(\\theta) = \\min_{|x| \\le L/2} \\left[P(x) - \\theta x\\right]

    Parameters
    ----------
    length : float
        Roller length L [m].
    tilt : float
        Tilt theta [rad] (positive: the end x = +L/2 dips in).
    profile : callable or object with drop(x), optional
        Profile drop P(x) [m]; None for a straight roller.

    Returns
    -------
    float
        d_c [m], sampled on 4097 points along the roller (exact at them).

    Notes
    -----
    Any depth d > d_c gives contact; valid for any profile that is finite on the
    roller (end values included).

    Examples
    --------
    >>> first_contact_depth(0.02, tilt=1e-3)     # straight roller: its end x = L/2
    -1e-05

    References
    ----------
    Johnson, K. L. (1985) Contact Mechanics, CUP, section 4.2 (the gap of two bodies).
    """
    L = float(check_positive("length", length, "m"))
    xs = np.linspace(-L / 2, L / 2, _N_SAMPLES)
    return float(np.min(_drop_values(_drop_function(profile), xs) - tilt * xs))


@dataclass
class RollerGrid:
    """A window x_lo <= x <= x_lo + nx dx, |y| <= ny dy/2 of the roller's footprint."""

    x_lo: float         #: left edge of the window [m]
    nx: int             #: cells along x
    dx: float           #: cell side along the axis [m]
    ny: int             #: cells along y (even; y = 0 is a cell edge)
    dy: float           #: cell side across the axis [m]
    left_end: bool      #: the window starts at the roller end x = -L/2
    right_end: bool     #: the window ends at the roller end x = +L/2

    @property
    def x(self):
        """Cell-centre x [m]."""
        return self.x_lo + (np.arange(self.nx) + 0.5) * self.dx

    @property
    def y(self):
        """Cell-centre y [m]."""
        return (np.arange(self.ny) - self.ny / 2 + 0.5) * self.dy

    @property
    def x_hi(self):
        return self.x_lo + self.nx * self.dx

    @property
    def half_width(self):
        return 0.5 * self.ny * self.dy

    @property
    def cell_area(self):
        return self.dx * self.dy

    def describe(self):
        return (f"{self.nx} x {self.ny} cells over x in [{self.x_lo:.6g}, {self.x_hi:.6g}] m, "
                f"|y| <= {self.half_width:.6g} m (dx = {self.dx:.4g} m, dy = {self.dy:.4g} m)")


@dataclass
class RollerResult:
    """One converged roller solution (SI units)."""

    depth: float              #: rigid-body approach d at x = 0 [m]
    tilt: float               #: theta [rad]
    force: float              #: F [N]
    moment: float             #: M = int p x dA about the roller centre [N m]
    stiffness: float          #: dF/dd at fixed theta and contact set [N/m]
    tilt_stiffness: float     #: dM/dtheta at fixed d and contact set [N m/rad]
    coupling: float           #: dF/dtheta = dM/dd [N/rad] = [N]
    x: np.ndarray             #: cell-centre x of the window [m]
    line_load: np.ndarray     #: q(x) = int p dy [N/m] at x
    p_max: float              #: peak pressure [Pa] (quadratic interpolation off the ends)
    x_at_p_max: float         #: where the peak sits along x [m]
    contact_length: float     #: extent in x of the contact set [m] (to one cell)
    contact_x: tuple          #: (x_min, x_max) of the contact set [m] (cell edges)
    half_width: float         #: largest contact half-width across the axis [m]
    area: float               #: contact area [m^2]
    edge_loaded: bool         #: the contact reaches a roller end x = -L/2 or +L/2
    ends: tuple               #: (touches x = -L/2, touches x = +L/2)
    grid: RollerGrid
    iterations: int           #: operator applications, all passes
    error: float              #: largest achieved relative error (gap / punch)
    tol: float
    wall_time: float          #: seconds
    newton_steps: int = 0     #: force control only
    pressure: np.ndarray | None = field(default=None, repr=False)  #: [Pa], nx x ny

    @property
    def mean_x(self):
        """Centre of pressure M/F [m]."""
        return self.moment / self.force


class _Roller:
    """The geometry and operator cache of one roller."""

    def __init__(self, radius, length, estar, profile, tol, backend, workers):
        self.R = float(check_positive("radius", radius, "m"))
        self.L = float(check_positive("length", length, "m"))
        self.estar = float(check_positive("estar", estar, "Pa"))
        self.drop = _drop_function(profile)
        self.tol = float(tol)
        self.backend = backend
        self.workers = workers
        self.xs = np.linspace(-self.L / 2, self.L / 2, _N_SAMPLES)
        self.ps = _drop_values(self.drop, self.xs)
        self.its = 0

    # --- geometry -------------------------------------------------------------------
    def interference_box(self, d, theta):
        """(x_lo, x_hi, y_max) bounding the rigid interference region; None if empty."""
        i = d + theta * self.xs - self.ps
        inside = np.flatnonzero(i > 0)
        if inside.size == 0:
            return None
        step = self.xs[1] - self.xs[0]
        x_lo = max(self.xs[inside[0]] - step, -self.L / 2)
        x_hi = min(self.xs[inside[-1]] + step, self.L / 2)
        return x_lo, x_hi, np.sqrt(2 * self.R * i.max()), float(i.max())

    def grid(self, x_lo, x_hi, Y, nx, ny):
        nx = int(next_fast_len(max(int(nx), 4)))
        ny = int(next_fast_len(max(int(ny), 4)))
        ny += ny % 2
        eps = 1e-12 * self.L
        g = RollerGrid(x_lo, nx, (x_hi - x_lo) / nx, ny, 2 * Y / ny,
                       x_lo <= -self.L / 2 + eps, x_hi >= self.L / 2 - eps)
        op = DCFFTOperator(nx, ny, g.dx, g.dy, self.estar, self.backend, self.workers)
        h0 = (g.y ** 2 / (2 * self.R))[None, :] + _drop_values(self.drop, g.x)[:, None]
        return g, op, h0

    def contact(self, bundle, d, theta, p0=None):
        g, op, h0 = bundle
        sep = h0 - theta * g.x[:, None] - d
        scale = max(-sep.min(), 1e-300)
        sol = solve_contact(op, sep, scale, tol=self.tol, p0=p0)
        self.its += sol.iterations
        if not sol.converged:
            raise ConvergenceError(
                f"d = {d:.6g} m, theta = {theta:.6g} rad: contact solver stopped after "
                f"{sol.iterations} operator applications with gap error {sol.error:.3g} "
                f"(relative to the largest interference) > tol = {self.tol:g} on "
                f"{g.describe()}")
        return sol

    # --- windows --------------------------------------------------------------------
    def adapt(self, d, theta, n_x, n_y, margin, p_hint=None):
        """Fine grid bundle and its solution at (d, theta)."""
        box = self.interference_box(d, theta)
        if box is None:
            dc = float(np.min(self.ps - theta * self.xs))
            raise OutOfRangeError("depth", d, f"({dc:.6g}, inf) m", unit="m",
                                  where=f"tilt {theta:.6g} rad",
                                  hint="the roller does not reach the half-space: "
                                       "no contact at all")
        X0, X1, Y0, _ = box
        coarse = self.grid(X0, X1, Y0, max(n_x // 2, 16), max(n_y, 16))
        sol = self.contact(coarse, d, theta)
        g = coarse[0]
        cols = np.flatnonzero(sol.contact.any(axis=1))
        rows = np.flatnonzero(sol.contact.any(axis=0))
        if cols.size == 0:
            # the interference is thinner than a coarse cell: the fine pass takes the
            # whole interference box
            lo, hi, Y = X0, X1, Y0
        else:
            c_lo = g.x_lo + cols[0] * g.dx - g.dx
            c_hi = g.x_lo + (cols[-1] + 1) * g.dx + g.dx
            b = np.abs(g.y[rows]).max() + 1.5 * g.dy
            xc, half = 0.5 * (c_lo + c_hi), 0.5 * (c_hi - c_lo)
            lo, hi = max(xc - margin * half, X0), min(xc + margin * half, X1)
            Y = min(margin * b, Y0)
        for _ in range(20):
            bundle = self.grid(lo, hi, Y, n_x, n_y)
            sol = self.contact(bundle, d, theta, p0=_resample(p_hint, bundle[0]))
            touch = _touching(sol.contact, bundle[0], X0, X1, Y0)
            if not any(touch):
                return bundle, sol
            grow = 0.3 * (hi - lo)
            lo = max(lo - grow, X0) if touch[0] else lo
            hi = min(hi + grow, X1) if touch[1] else hi
            Y = min(1.3 * Y, Y0) if touch[2] else Y
        raise ConvergenceError(f"d = {d:.6g} m, theta = {theta:.6g} rad: the contact "
                               "window did not settle in 20 widenings")

    # --- results ---------------------------------------------------------------------
    def result(self, bundle, sol, d, theta, t0, stiffness=True, fields=False):
        g, op, _ = bundle
        p = sol.pressure
        dA = g.cell_area
        x = g.x
        F = float(p.sum() * dA)
        q = p.sum(axis=1) * g.dy
        M = float(np.sum(q * x) * g.dx)
        err = sol.error
        kdd = kdt = ktt = np.nan
        p1 = px = None
        if stiffness:
            p1, px, e1 = _punches(op, sol.contact, x, self.tol, d, p)
            self.its += e1[1]
            err = max(err, e1[0])
            kdd = float(p1.sum() * dA)
            kdt = float(np.sum(p1.sum(axis=1) * x) * dA)
            ktt = float(np.sum(px.sum(axis=1) * x) * dA)
        S = sol.contact
        cols = np.flatnonzero(S.any(axis=1))
        rows = np.flatnonzero(S.any(axis=0))
        ends = (bool(g.left_end and S[0].any()), bool(g.right_end and S[-1].any()))
        pm, xm = _peak(p, g)
        return RollerResult(
            depth=float(d), tilt=float(theta), force=F, moment=M, stiffness=kdd,
            tilt_stiffness=ktt, coupling=kdt, x=x, line_load=q, p_max=pm, x_at_p_max=xm,
            contact_length=float((cols[-1] - cols[0] + 1) * g.dx),
            contact_x=(float(g.x_lo + cols[0] * g.dx), float(g.x_lo + (cols[-1] + 1) * g.dx)),
            half_width=float(np.abs(g.y[rows]).max() + 0.5 * g.dy),
            area=float(S.sum() * dA), edge_loaded=any(ends), ends=ends, grid=g,
            iterations=self.its, error=float(err), tol=self.tol,
            wall_time=time.perf_counter() - t0, pressure=p if fields else None), (p1, px)


def _touching(S, g, X0, X1, Y0):
    """Does the contact reach a window edge that is neither a roller end nor the edge of
    the interference region? (left, right, across)"""
    eps = 1e-9 * max(g.dx, g.dy)
    left = S[0].any() and g.x_lo > X0 + eps
    right = S[-1].any() and g.x_hi < X1 - eps
    across = (S[:, 0].any() or S[:, -1].any()) and g.half_width < Y0 - eps
    return bool(left), bool(right), bool(across)


def _resample(p, g):
    """A start for the solver on grid g from a pressure field on another grid (or None).

    ``p`` is (grid, field); nearest-cell sampling is enough for a warm start."""
    if p is None:
        return None
    g0, f0 = p
    i = np.floor((g.x - g0.x_lo) / g0.dx).astype(int)
    j = np.floor((g.y + g0.half_width) / g0.dy).astype(int)
    ok_i = (i >= 0) & (i < g0.nx)
    ok_j = (j >= 0) & (j < g0.ny)
    out = np.zeros((g.nx, g.ny))
    out[np.ix_(ok_i, ok_j)] = f0[np.ix_(i[ok_i], j[ok_j])]
    return out if out.any() else None


def tilt_punch(op, footprint, x, tol=1e-8, p0=None):
    """Pressures of a rigid flat punch tilted by unit angle: K_SS p = x on the footprint S.

    .. math::

        K_{SS}\\, p = x \\ \\text{on } S, \\quad p = 0 \\text{ off } S;
        \\qquad
        p = W^{-1} q, \\ \\ (W^{-1} K W^{-1})_{SS}\\, q = 1, \\ \\ W = \\mathrm{diag}(x - c)

    With c chosen so that w = x - c lies in [s/2, 3s/2] (s: the window's extent in x,
    centred on its middle x_m: c = x_m - s), W^-1 K W^-1 is symmetric positive definite
    like K, so the flat-punch conjugate gradients (tools.bem.solver.solve_punch) apply
    unchanged; then K p_w = x - c and p = p_w + c K_SS^-1 1.

    Parameters
    ----------
    op : callable
        Half-space operator p -> K p on an nx x ny grid [m/Pa].
    footprint : ndarray of bool
        Contact set S, nx x ny.
    x : ndarray
        Cell-centre x of the grid columns (length nx) [m].
    tol : float
        Solver tolerance, relative (see tools.bem.solver.solve_punch) [-].
    p0 : ndarray, optional
        Start for K_SS^-1 1 (e.g. contact pressure / depth) [Pa/m].

    Returns
    -------
    (p_unit, p_tilt, error, iterations)
        K_SS^-1 1 [Pa/m] and K_SS^-1 x [Pa/rad], the larger achieved relative error,
        and the operator applications used.

    Notes
    -----
    The scaling costs at most a factor 9 in the condition number (w spans a ratio of
    3). Valid for any footprint.

    Examples
    --------
    >>> import numpy as np
    >>> from tools.bem.halfspace import DCFFTOperator
    >>> op = DCFFTOperator(8, 4, 1.0, 1.0)
    >>> S = np.ones((8, 4), dtype=bool)
    >>> x = np.arange(8) + 0.5 - 4
    >>> p1, px, err, its = tilt_punch(op, S, x, tol=1e-10)
    >>> bool(np.allclose(op(px), np.broadcast_to(x[:, None], (8, 4)), atol=1e-8))
    True

    References
    ----------
    Polonsky, I. A. & Keer, L. M. (1999) Wear 231, 206-219 (the CG solver);
    Johnson, K. L. (1985) Contact Mechanics, section 5.2 (the tilted rigid punch).
    """
    S = np.asarray(footprint, dtype=bool)
    x = np.asarray(x, dtype=float)
    unit = solve_punch(op, S, tol=tol, p0=p0)
    s = max(x.max() - x.min(), 1e-300)
    c = 0.5 * (x.max() + x.min()) - s
    w = np.broadcast_to((x - c)[:, None], S.shape)
    scaled = solve_punch(lambda f: op(f / w) / w, S, tol=tol)
    p_tilt = scaled.pressure / w + c * unit.pressure
    err = max(unit.error, scaled.error)
    ok = unit.converged and scaled.converged
    if not ok:
        raise ConvergenceError(f"punch solver did not converge (error {err:.3g} > "
                               f"tol = {tol:g})")
    return unit.pressure, p_tilt, err, unit.iterations + scaled.iterations


def _punches(op, S, x, tol, d, p):
    scale = max(abs(d), 1e-300)
    p1, px, err, its = tilt_punch(op, S, x, tol=tol, p0=p / scale if d > 0 else None)
    return p1, px, (err, its)


def _peak(p, g):
    """Peak pressure and its x: the largest cell, refined by a parabola through it and
    its neighbours in x and in y where all three are loaded (not at a window edge)."""
    i, j = np.unravel_index(np.argmax(p), p.shape)
    pm, x = float(p[i, j]), float(g.x[i])
    corr = 0.0
    if 0 < i < g.nx - 1 and p[i - 1, j] > 0 and p[i + 1, j] > 0:
        a, b, c = p[i - 1, j], p[i, j], p[i + 1, j]
        curv = a - 2 * b + c
        if curv < 0:
            t = 0.5 * (a - c) / curv
            x += t * g.dx
            corr += -0.125 * (a - c) ** 2 / curv
    if 0 < j < g.ny - 1 and p[i, j - 1] > 0 and p[i, j + 1] > 0:
        a, b, c = p[i, j - 1], p[i, j], p[i, j + 1]
        curv = a - 2 * b + c
        if curv < 0:
            corr += -0.125 * (a - c) ** 2 / curv
    return pm + corr, x


def solve_roller(radius, length, estar, depth, tilt=0.0, profile=None, n_x=64, n_y=32,
                 margin=1.25, tol=1e-7, window=None, stiffness=True, fields=False,
                 backend="scipy", workers=None):
    """Roller at a given approach d and tilt theta: F, M, q(x), p_max, stiffnesses.

    .. math::

        p \\ge 0,\\quad u_z[p] + \\frac{y^2}{2R} + P(x) - \\theta x - d \\ge 0,
        \\quad p\\,g = 0;\\qquad F = \\int p\\,dA,\\ M = \\int p\\,x\\,dA

    Parameters
    ----------
    radius : float
        Roller radius R (effective radius across the axis for a raceway) [m].
    length : float
        Roller length L [m]; the roller occupies |x| <= L/2.
    estar : float
        Effective modulus E* [Pa].
    depth : float
        Rigid-body approach d at the roller centre x = 0 [m].
    tilt : float
        Tilt theta [rad]; positive loads the end x = +L/2.
    profile : callable or object with drop(x), optional
        Profile drop P(x) >= 0 [m] over |x| <= L/2 (linecontact.profiles objects or any
        callable); None: a straight roller with sharp ends.
    n_x, n_y : int
        Cells of the fine grid along x (over the window) and y (over |y| <= Y).
    margin : float
        The fine window covers the first pass's contact box times margin [-].
    tol : float
        Solver tolerance: gap error relative to the largest interference; punch
        displacement error relative to unit depth [-].
    window : RollerGrid, optional
        Reuse this window (x range and strip half-width; cell counts from n_x, n_y)
        instead of adapting one: for grid-convergence studies on nested windows.
    stiffness : bool
        Compute dF/dd, dM/dtheta, dF/dtheta (two more CG solves).
    fields : bool
        Keep the pressure field.
    backend : {'scipy', 'pyfftw'}
        FFT backend (tools.bem.halfspace).
    workers : int, optional
        FFT threads.

    Returns
    -------
    RollerResult

    Notes
    -----
    Valid for any profile P >= 0 on the roller (+inf where it can never touch) and any
    tilt, with small slopes (half-space theory: contact size << R, Rc and the body
    sizes). Accuracy (tests/test_roller_bem.py): exact Hertz to 2e-4 in approach,
    5e-4 in p0, 1.2e-3 in the semi-axes with 32 x 32 cells (second order); a straight
    roller's force converges at first order (end singularity), 1e-3 low with 256 cells
    along it. An edge-loaded solution (``edge_loaded``) has a singular end pressure:
    its ``p_max`` depends on the grid and is not a physical number.

    Examples
    --------
    >>> r = solve_roller(0.01, 0.02, 115.385e9, 5e-6, profile=lambda x: x**2 / 1.0,
    ...                  n_x=32, n_y=32)
    >>> r.edge_loaded, round(r.force)   # Hertz: 1000 N (5 um/7.0244 um)^1.5 = 600.5 N
    (False, 601)

    References
    ----------
    Johnson, K. L. (1985) Contact Mechanics, Eq. 3.25 and section 4.2;
    Polonsky, I. A. & Keer, L. M. (1999) Wear 231, 206-219;
    Liu, S., Wang, Q. & Liu, G. (2000) Wear 243, 101-111 (DC-FFT).
    """
    t0 = time.perf_counter()
    roller = _Roller(radius, length, estar, profile, tol, backend, workers)
    d, theta = float(depth), float(tilt)
    if window is None:
        bundle, sol = roller.adapt(d, theta, n_x, n_y, margin)
    else:
        bundle = roller.grid(window.x_lo, window.x_hi, window.half_width, n_x, n_y)
        sol = roller.contact(bundle, d, theta)
    return roller.result(bundle, sol, d, theta, t0, stiffness, fields)[0]


def solve_roller_force(radius, length, estar, force, tilt=None, profile=None, n_x=64,
                       n_y=32, margin=1.25, tol=1e-7, ftol=1e-6, window=None,
                       fields=False, maxiter=40, backend="scipy", workers=None,
                       start=None):
    """Roller at a given force: (d, theta) with zero moment, or d at a given theta.

    Newton's method on the equilibrium residuals with the exact Jacobian of the
    fixed-contact-set problem (module docstring):

    .. math::

        \\begin{pmatrix} \\partial_d F & \\partial_\\theta F \\\\
                         \\partial_d M & \\partial_\\theta M \\end{pmatrix}
        \\begin{pmatrix} \\Delta d \\\\ \\Delta\\theta \\end{pmatrix}
        = \\begin{pmatrix} F_0 - F \\\\ -M \\end{pmatrix}

    (tilt=None: zero moment, the roller free to tilt), or the first row alone with
    Delta theta = 0 (tilt given: F and M at that tilt).

    Parameters
    ----------
    radius, length, estar : float
        R [m], L [m], E* [Pa] as in :func:`solve_roller`.
    force : float
        Applied force F0 [N].
    tilt : float or None
        None: find the tilt of zero moment; a number: the given tilt [rad].
    profile : callable or object with drop(x), optional
        Profile drop P(x) [m].
    n_x, n_y, margin, tol, window, fields, backend, workers
        As in :func:`solve_roller`.
    ftol : float
        Equilibrium tolerance: |F/F0 - 1| <= ftol and |M| <= ftol F0 L/2 [-].
    maxiter : int
        Newton steps allowed.
    start : (float, float), optional
        Initial (d [m], theta [rad]), e.g. a coarser solution.

    Returns
    -------
    RollerResult
        With ``newton_steps`` set.

    Notes
    -----
    The window is re-adapted while |F/F0 - 1| > 5 % and kept fixed after, so the last
    steps see one discrete system (quadratic convergence). Valid as
    :func:`solve_roller`.

    Examples
    --------
    >>> r = solve_roller_force(0.01, 0.02, 115.385e9, 600.0, profile=lambda x: x**2,
    ...                        n_x=32, n_y=32)
    >>> round(r.depth * 1e6, 3), abs(r.moment) < 1e-6 * 600 * 0.01  # Hertz: 4.997 um
    (4.996, True)

    References
    ----------
    Polonsky, I. A. & Keer, L. M. (1999) Wear 231, 206-219;
    Johnson, K. L. (1985) Contact Mechanics, section 4.2.
    """
    t0 = time.perf_counter()
    roller = _Roller(radius, length, estar, profile, tol, backend, workers)
    F0 = float(check_positive("force", force, "N"))
    free = tilt is None
    theta = 0.0 if free else float(tilt)
    L, E = roller.L, roller.estar
    if start is not None:
        d, theta = float(start[0]), (float(start[1]) if free else theta)
    else:
        dc = float(np.min(roller.ps - theta * roller.xs))
        # first guess: the approach of a line contact is a few q/E* with q = F0/L
        # (an underestimate for a crowned roller); the Newton steps grow it 4x at most
        d = dc + 2.0 * F0 / (E * L)
    bundle = None if window is None else roller.grid(window.x_lo, window.x_hi,
                                                     window.half_width, n_x, n_y)
    fixed = window is not None
    guess = None          # warm start on the current bundle
    hint = None           # (grid, pressure) to seed a new window
    rF = rM = np.inf
    for steps in range(1, maxiter + 1):
        if bundle is None:
            bundle, sol = roller.adapt(d, theta, n_x, n_y, margin, p_hint=hint)
        else:
            sol = roller.contact(bundle, d, theta, p0=guess)
            if not fixed and any(_touching(sol.contact, bundle[0],
                                           *roller.interference_box(d, theta)[:3])):
                bundle, sol = roller.adapt(d, theta, n_x, n_y, margin,
                                           p_hint=(bundle[0], sol.pressure))
        res, (p1, px) = roller.result(bundle, sol, d, theta, t0, stiffness=True,
                                      fields=fields)
        rF = res.force / F0 - 1
        rM = res.moment / (F0 * L / 2) if free else 0.0
        if abs(rF) <= ftol and abs(rM) <= ftol:
            res.newton_steps = steps
            res.wall_time = time.perf_counter() - t0
            return res
        delta = d - float(np.min(roller.ps - theta * roller.xs))
        dd, dt = (F0 - res.force) / res.stiffness, 0.0
        if free and abs(rF) < 0.2:
            # the fixed-set Jacobian holds while the contact set changes little: only
            # near the force; and a tilt step may rock the contact's ends by no more
            # than twice the overlap (the contact moves, which the Jacobian ignores)
            J = np.array([[res.stiffness, res.coupling], [res.coupling, res.tilt_stiffness]])
            dd, dt = np.linalg.solve(J, [F0 - res.force, -res.moment])
            limit = 2 * delta / (0.5 * res.contact_length)
            if abs(dt) > limit:
                dt = np.copysign(limit, dt)
                dd = (F0 - res.force - res.coupling * dt) / res.stiffness
        d_new, t_new = d + dd, theta + dt
        delta_new = d_new - float(np.min(roller.ps - t_new * roller.xs))
        if delta_new < 0.3 * delta:     # keep contact: shrink the overlap 3x at most
            d_new += 0.3 * delta - delta_new
        elif delta_new > 4 * delta:     # nor grow it more than 4x in one step
            d_new += 4 * delta - delta_new
        if not fixed and abs(rF) > 0.05:
            hint, bundle, guess = (bundle[0], sol.pressure), None, None
        else:
            # the fixed-set linearisation predicts the next pressures
            guess = np.maximum(sol.pressure + (d_new - d) * p1 + (t_new - theta) * px, 0)
            guess = guess if guess.any() else None
        d, theta = d_new, t_new
    raise ConvergenceError(f"force control did not converge in {maxiter} Newton steps "
                           f"(F/F0 - 1 = {rF:.3g}, M/(F0 L/2) = {rM:.3g})")


def grid_convergence(solve, *args, refine=2, order=None, **kwargs):
    """The same roller on a grid and on one `refine` times finer on the same window.

    .. math::

        Q_\\infty \\approx Q_{2N} + \\frac{Q_{2N} - Q_N}{2^k - 1}

    (Richardson extrapolation, for a known order k).

    Parameters
    ----------
    solve : callable
        :func:`solve_roller` or :func:`solve_roller_force`.
    *args, **kwargs
        Its arguments (``n_x``, ``n_y`` are those of the coarser grid).
    refine : int
        Refinement factor in both directions [-].
    order : float, optional
        Convergence order k for the Richardson estimate [-]; default 2 when the contact
        stays off the roller ends (a Hertz-like field: measured ~2 in
        tests/test_roller_bem.py) and 1 when it is edge loaded (the end singularity:
        measured 0.8-1.0 for the flat-ended cylinder, tests/test_bem.py).

    Returns
    -------
    dict
        ``coarse``, ``fine`` (RollerResult), ``order``, and for each of depth, tilt,
        force, moment, p_max: ``change_<name>`` (fine/coarse - 1 [-]) and
        ``richardson_<name>`` (extrapolated value, SI).

    Notes
    -----
    The fine grid reuses the coarse solution's window, so the two are nested and the
    change measures the discretisation alone. Valid as ``solve``.

    Examples
    --------
    >>> g = grid_convergence(solve_roller, 0.01, 0.02, 115.385e9, 5e-6,
    ...                      profile=lambda x: x**2, n_x=16, n_y=16)
    >>> abs(g["change_force"]) < 0.02
    True

    References
    ----------
    Richardson, L. F. (1911) Phil. Trans. R. Soc. A 210, 307-357.
    """
    n_x = kwargs.pop("n_x", 64)
    n_y = kwargs.pop("n_y", 32)
    coarse = solve(*args, n_x=n_x, n_y=n_y, **kwargs)
    kwargs["window"] = coarse.grid
    if solve is solve_roller_force:
        kwargs["start"] = (coarse.depth, coarse.tilt)
    fine = solve(*args, n_x=refine * coarse.grid.nx, n_y=refine * coarse.grid.ny, **kwargs)
    k = order if order is not None else (1.0 if fine.edge_loaded else 2.0)
    out = dict(coarse=coarse, fine=fine, order=k)
    for name in ("depth", "tilt", "force", "moment", "p_max"):
        a, b = getattr(coarse, name), getattr(fine, name)
        out[f"change_{name}"] = (b / a - 1) if a != 0 else (b - a)
        out[f"richardson_{name}"] = b + (b - a) / (refine ** k - 1)
    return out
