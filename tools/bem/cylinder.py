"""Drivers for the finite cylinder: the paper's sweep and depths on adapted grids.

The problem (Li & Popov 2017, section 2; docs/theory.md, section 'BEM'): a rigid cylinder of radius R
and length L, axis along x, pressed by a depth d into an elastic half-space of
effective modulus E*. The gap before loading is h(y) = y^2/(2R) for |x| <= L/2 and
there is no indenter beyond the flat ends, so the grid covers the cylinder's
footprint only; the zero padding of the operator makes the surface around it free.
Both mirror planes (x = 0, y = 0) are used: the solvers work on one quarter
(tools.bem.halfspace.SymmetricOperator) and forces are four times the quarter's.

Two drivers:

``sweep``
    The paper's study: one fixed grid of nx x ny cells over |x| <= L/2,
    |y| <= sqrt(2 R d_max) (no contact can reach beyond, since the displacement is
    positive), depths d_max/steps, ..., d_max, each step warm-started from the
    extrapolation of the previous two.
``solve_depth``
    One dimensionless depth d~ = d R/L^2 (docs/theory.md, section 'Self-similarity') on a grid adapted to its
    own contact: n_length cells along the half-length and n_width across the
    contact half-width b, with the strip |y| <= margin * b. b comes from a coarse
    first pass; the fine pass is repeated on a wider strip if its contact reaches
    the strip's edge. Depths over many decades are thus resolved alike, and a strip
    thousands of times longer than wide gets cells that are long in x and narrow
    in y.

The stiffness k = dF/dd is the force of a rigid flat punch whose footprint is the
converged contact set, at unit depth (tools.bem.solver.solve_punch): the exact derivative
of the discrete F(d) while the contact set does not change. ``stiffness='difference'``
uses ``numpy.gradient`` of F(d) instead (second-order inside, first-order at the first
and last step; sweep only).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
from scipy.fft import next_fast_len

from .halfspace import SymmetricOperator, best_backend
from .influence import kernel_offsets
from .solver import ConvergenceError, solve_contact, solve_punch


def _progress(iterable, total, desc, enabled):
    if not enabled:
        return iterable
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is in the test and tools extras
        return iterable
    return tqdm(iterable, total=total, desc=desc, leave=False)


@dataclass
class Grid:
    """A quarter grid (x > 0, y > 0) of the cylinder's footprint."""

    mx: int            #: cells along x in the quarter (full grid: 2 mx)
    my: int            #: cells along y in the quarter (full grid: 2 my)
    dx: float          #: cell side along the axis [m]
    dy: float          #: cell side across the axis [m]

    @property
    def x(self):
        """Cell-centre x of the quarter [m]."""
        return (np.arange(self.mx) + 0.5) * self.dx

    @property
    def y(self):
        """Cell-centre y of the quarter [m]."""
        return (np.arange(self.my) + 0.5) * self.dy

    @property
    def cell_area(self):
        return self.dx * self.dy

    def describe(self):
        return (f"{2 * self.mx} x {2 * self.my} cells (full), "
                f"dx = {self.dx:.6g}, dy = {self.dy:.6g}, aspect dx/dy = {self.dx / self.dy:.4g}")


@dataclass
class SweepResult:
    """F(d) of one cylinder on one grid (SI units of the inputs)."""

    l_over_r: float
    radius: float
    estar: float
    grid: Grid
    depth: np.ndarray        #: d [m]
    force: np.ndarray        #: F [N]
    stiffness: np.ndarray    #: k = dF/dd [N/m]
    area: np.ndarray         #: contact area [m^2]
    iterations: np.ndarray   #: operator applications per step (contact + punch)
    converged: np.ndarray    #: bool per step
    error: np.ndarray        #: achieved gap error / d per step
    tol: float
    wall_time: float
    pressure: list | None = None   #: full pressure fields per step, on request
    settings: dict = field(default_factory=dict)
    contact_iterations: np.ndarray | None = None  #: operator applications of the contact solve


def _widen(a, my):
    """A quarter field of a strip of rows, padded with zeros to `my` rows."""
    if a.shape[1] == my:
        return a
    out = np.zeros((a.shape[0], my), dtype=a.dtype)
    out[:, :a.shape[1]] = a
    return out


def _check_even(name, n):
    if n < 2 or n % 2:
        raise ValueError(f"{name} = {n} must be an even number of cells >= 2 "
                         "(the solver uses the two mirror planes)")


def sweep(l_over_r, n=512, steps=100, d_max_over_r=0.15, radius=1.0, estar=1.0,
          tol=1e-6, stiffness="punch", backend=None, workers=None, fields=False,
          progress=True, raise_on_failure=True, precondition=True, windows=8):
    """The paper's sweep: F(d), k(d), area for d = d_max/steps ... d_max.

    Parameters
    ----------
    l_over_r : float
        Length over radius L/R [-].
    n : int or (int, int)
        Full grid, cells along x (the length) and y (the width); even.
        The paper: 512 x 512.
    steps : int
        Equal depth steps from d_max/steps to d_max (the paper: 100).
    d_max_over_r : float
        Largest depth over radius (the paper: 0.15).
    radius, estar : float
        R [m] and E* [Pa]; results scale as F ~ E* R^2 at fixed L/R, d/R.
    tol : float
        Contact-solver tolerance: largest gap error / d (tools.bem.solver).
    stiffness : {'punch', 'difference', None}
    backend : {'scipy', 'pyfftw'}, optional
        FFT backend; default pyfftw when installed.
    fields : bool
        Keep the full pressure field of every step.
    progress : bool
        Show a progress bar.
    raise_on_failure : bool
        Raise ConvergenceError if a step does not converge (default); otherwise its
        force is NaN and ``converged`` says so.
    precondition : bool
        Preconditioned conjugate gradients (default; tools.bem.solver.bounded_cg) or the
        plain Polonsky-Keer iteration.
    windows : int
        Strip widths for the steps (each step is solved on the rows the cylinder
        overlaps, rounded up to a multiple of 1/windows of the grid; same discrete
        problem); 0: every step on the whole grid.

    Returns
    -------
    SweepResult
    """
    nx, ny = (n, n) if np.isscalar(n) else n
    _check_even("nx", nx)
    _check_even("ny", ny)
    if stiffness not in ("punch", "difference", None):
        raise ValueError(f"stiffness = {stiffness!r} is not one of 'punch', "
                         "'difference', None")
    backend = backend or best_backend()
    t0 = time.perf_counter()
    R = float(radius)
    L = float(l_over_r) * R
    d_max = d_max_over_r * R
    Y = np.sqrt(2 * R * d_max)
    grid = Grid(nx // 2, ny // 2, L / nx, 2 * Y / ny)
    h = np.broadcast_to(grid.y ** 2 / (2 * R), (grid.mx, grid.my))
    # Each step is solved on the rows |y| < sqrt(2 R d) that the rigid cylinder
    # overlaps (rounded up to one of `windows` strip widths, each with its operator):
    # outside them h - d >= 0 and K p > 0, so no cell there can touch, and the
    # problem on the strip is the same discrete problem as on the whole grid (same
    # cells, same kernel, zero pressure outside), at a fraction of the transform cost.
    # The contact covers only 55-80 % of those rows, so the iterations run on a strip
    # of the rows the contact is predicted to reach (a first pass, its result then
    # verified, and if need be continued, on the overlap strip), and the punch on
    # the rows of its footprint (cells outside the footprint carry no pressure and
    # their displacement does not enter its problem). A strip of m rows computes
    # K p exactly on its rows for any p zero beyond them, so the displacements of
    # earlier solutions on wider strips serve narrower ones (their first m rows).
    kernel = kernel_offsets(2 * grid.mx, 2 * grid.my, grid.dx, grid.dy, estar)
    chunk = max(grid.my // windows, 1) if windows else grid.my
    ops = {}

    def strip(rows):
        m = min(grid.my, chunk * -(-int(rows) // chunk))
        if m not in ops:
            ops[m] = SymmetricOperator(grid.mx, m, grid.dx, grid.dy, estar, backend,
                                       workers, kernel=kernel[:, :2 * m + 1])
        return m, ops[m]

    def support(p):
        """Rows 0..r-1 hold every nonzero of the quarter field p: r."""
        nz = np.flatnonzero(p.any(axis=0))
        return int(nz[-1]) + 1 if nz.size else 0

    def combine(states, coefs, m):
        """sum c p and, when every state's displacement covers m rows and its pressure
        lies within them, sum c K p on m rows (else None)."""
        p0 = sum(c * st[0] for c, st in zip(coefs, states))[:, :m]
        if all(st[1].shape[1] >= m and st[2] <= m for st in states):
            return p0, sum(c * st[1][:, :m] for c, st in zip(coefs, states))
        return p0, None

    depths = d_max * np.arange(1, steps + 1) / steps
    F = np.full(steps, np.nan)
    K = np.full(steps, np.nan)
    A = np.full(steps, np.nan)
    its = np.zeros(steps, dtype=int)
    cits = np.zeros(steps, dtype=int)
    conv = np.zeros(steps, dtype=bool)
    errs = np.full(steps, np.nan)
    pressures = [] if fields else None
    # the last two converged steps and the last punch: (pressure on all rows,
    # K pressure on the rows of its strip, rows of the pressure's support)
    history = []
    p_punch = None
    for i in _progress(range(steps), steps, f"L/R = {l_over_r:g}", progress):
        d = depths[i]
        m, op = strip(int(np.count_nonzero(grid.y ** 2 / (2 * R) < d)) + 1)
        # the start: the previous two steps extrapolated linearly (K p0 by the same
        # combination of their displacements: no operator application)
        if len(history) >= 2:
            states, coefs = history[-2:], (-1.0, 2.0)   # 2 p_(i-1) - p_(i-2)
        elif history:
            states, coefs = history[-1:], (np.sqrt(d / depths[i - 1]),)
        else:
            states, coefs = [], ()
        napply = 0
        p0 = kp0 = None
        if states and precondition:
            # first pass on the rows the contact is predicted to reach: the last
            # contact's rows grown like sqrt(d), two more, and the start's support
            reach = max(int(np.ceil(history[-1][2] * np.sqrt(d / depths[i - 1]))) + 2,
                        max(st[2] for st in states))
            mc, opc = strip(reach)
            if mc < m:
                p0, kp0 = combine(states, coefs, mc)
                first = solve_contact(opc, h[:, :mc] - d, d, tol=tol, p0=p0, kp0=kp0,
                                      verify=False)
                napply = first.iterations
                p0, kp0 = _widen(first.pressure, m), None   # verified on the strip below
        if states and p0 is None:
            p0, kp0 = combine(states, coefs, m)
        sol = solve_contact(op, h[:, :m] - d, d, tol=tol, p0=p0, precondition=precondition,
                            kp0=kp0)
        sol.iterations += napply
        u_sol = sol.displacement
        sol.pressure = _widen(sol.pressure, grid.my)
        sol.contact = _widen(sol.contact, grid.my)
        its[i] = sol.iterations
        cits[i] = sol.iterations
        conv[i] = sol.converged
        errs[i] = sol.error
        if not sol.converged:
            if raise_on_failure:
                raise ConvergenceError(
                    f"L/R = {l_over_r:g}, d/R = {d / R:.6g}: contact solver stopped after "
                    f"{sol.iterations} operator applications with gap error "
                    f"{sol.error:.3g} d > tol = {tol:g} d")
            history = []
            continue
        rows = support(sol.pressure)
        history = (history + [(sol.pressure, u_sol, rows)])[-3:]
        F[i] = 4 * sol.pressure.sum() * grid.cell_area
        A[i] = 4 * sol.contact.sum() * grid.cell_area
        if stiffness == "punch":
            # on the rows of the footprint; from dp/dd by the second-order backward
            # difference of the last three steps (the punch's pressure is dp/dd on a
            # fixed contact set: 7 % fewer iterations than the previous punch), else
            # from the previous punch, else from this step's contact pressure / d
            mp, opp = strip(rows) if precondition else (m, op)
            dd = depths[1] - depths[0] if steps > 1 else d
            if len(history) == 3:
                p0, kp0 = combine(history, (0.5 / dd, -2.0 / dd, 1.5 / dd), mp)
            elif p_punch is not None:
                p0, kp0 = combine([p_punch], (1.0,), mp)
            else:
                p0, kp0 = sol.pressure[:, :mp] / d, u_sol[:, :mp] / d
            pun = solve_punch(opp, sol.contact[:, :mp], tol=tol, p0=p0, kp0=kp0,
                              precondition=precondition)
            u_pun = pun.displacement
            pun.pressure = _widen(pun.pressure, grid.my)
            its[i] += pun.iterations
            errs[i] = max(errs[i], pun.error)
            if not pun.converged:
                if raise_on_failure:
                    raise ConvergenceError(
                        f"L/R = {l_over_r:g}, d/R = {d / R:.6g}: punch solver stopped with "
                        f"displacement error {pun.error:.3g} > tol = {tol:g}")
                conv[i] = False     # k of this step stays NaN
            else:
                p_punch = (pun.pressure, u_pun, support(pun.pressure))
                K[i] = 4 * pun.pressure.sum() * grid.cell_area
        if fields:
            from .halfspace import unfold
            pressures.append(unfold(sol.pressure))
    if stiffness == "difference":
        K = np.gradient(F, depths)
    return SweepResult(float(l_over_r), R, float(estar), grid, depths, F, K, A, its, conv,
                       errs, tol, time.perf_counter() - t0, pressures,
                       dict(n=(nx, ny), steps=steps, d_max_over_r=d_max_over_r,
                            stiffness=stiffness, backend=backend,
                            precondition=precondition, windows=windows), cits)


@dataclass
class DepthResult:
    """The dimensionless solution at one depth: L = R = E* = 1, so d = d~ and
    F = Psi(d~) = F R/(E* L^3), k = Psi'(d~) = k/(E* L)."""

    d_tilde: float
    force: float             #: Psi = F R / (E* L^3)
    stiffness: float         #: Psi' = k / (E* L)
    area: float              #: contact area / L^2
    half_width_centre: float  #: contact half-width at x = 0, / L
    half_width_max: float    #: largest contact half-width (at the ends), / L
    grid: Grid
    iterations: int
    converged: bool
    error: float
    wall_time: float
    pressure: np.ndarray | None = None  #: quarter pressure field, on request


def _extent(contact, grid):
    """Contact half-widths of the quarter: (at x = 0, largest over x, index of the
    outermost contact row)."""
    rows = np.where(contact.any(axis=0))[0]
    if rows.size == 0:
        return 0.0, 0.0, 0
    last = rows[-1]
    centre_rows = np.where(contact[0])[0]
    b0 = (centre_rows[-1] + 1) * grid.dy if centre_rows.size else 0.0
    return b0, (last + 1) * grid.dy, last


def solve_depth(d_tilde, n_length=256, n_width=32, margin=1.2, tol=1e-6,
                backend=None, workers=None, fields=False, p0=None):
    """F, k and contact size at one dimensionless depth d~ = d R / L^2.

    Parameters
    ----------
    d_tilde : float
        Dimensionless depth [-].
    n_length : int
        Cells along the half-length L/2.
    n_width : int
        Cells across the largest contact half-width.
    margin : float
        The strip covers |y| <= margin * b (b: largest contact half-width), never
        more than sqrt(2 R d), where the gap before loading exceeds d.
    tol : float
        Solver tolerance (gap error / d; punch displacement error).
    backend : {'scipy', 'pyfftw'}, optional
        FFT backend; default scipy (every depth has its own grid, so plans are not
        reused).
    fields : bool
        Return the quarter pressure field.

    Returns
    -------
    DepthResult
    """
    t0 = time.perf_counter()
    # a new grid per depth: FFTW's measured plans would cost more than they save
    backend = backend or "scipy"
    d = float(d_tilde)
    y_max = np.sqrt(2 * d)
    total_its = 0

    def run(Y, mx, my, start=None):
        grid = Grid(mx, my, 0.5 / mx, Y / my)
        op = SymmetricOperator(mx, my, grid.dx, grid.dy, 1.0, backend, workers)
        h = np.broadcast_to(grid.y ** 2 / 2, (mx, my))
        sol = solve_contact(op, h - d, d, tol=tol, p0=start)
        return grid, op, sol

    # pass 1: coarse, on the widest possible strip, to find the contact width
    grid, op, sol = run(y_max, max(n_length // 4, 8), max(n_width, 8))
    total_its += sol.iterations
    _, b, _ = _extent(sol.contact, grid)
    Y = min(margin * b, y_max)
    while True:
        my = int(np.ceil(n_width * Y / b)) if b > 0 else n_width
        my = next_fast_len(my)  # 2*my is then 5-smooth too: fast DCTs
        grid, op, sol = run(Y, n_length, my)
        total_its += sol.iterations
        if not sol.converged:
            raise ConvergenceError(f"d~ = {d:.6g}: contact solver stopped with gap error "
                                   f"{sol.error:.3g} d > tol = {tol:g} d on {grid.describe()}")
        b0, b_new, last = _extent(sol.contact, grid)
        if last < grid.my - 1 or Y >= y_max:
            break
        # contact reached the edge of the strip: widen it and solve again
        b = b_new
        Y = min(Y * 1.3, y_max)
    pun = solve_punch(op, sol.contact, tol=tol, p0=sol.pressure / d,
                      kp0=sol.displacement / d)
    total_its += pun.iterations
    if not pun.converged:
        raise ConvergenceError(f"d~ = {d:.6g}: punch solver did not converge "
                               f"(error {pun.error:.3g}) on {grid.describe()}")
    return DepthResult(d, 4 * sol.pressure.sum() * grid.cell_area,
                       4 * pun.pressure.sum() * grid.cell_area,
                       4 * sol.contact.sum() * grid.cell_area, b0, b_new, grid, total_its,
                       True, max(sol.error, pun.error), time.perf_counter() - t0,
                       sol.pressure if fields else None)
