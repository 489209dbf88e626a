"""Adhesive normal contact by the boundary-element method (JKR-type, short-range adhesion).

Detachment criterion: Griffith's energy balance at the contact edge, read from the
edge cell's tension through the stress-intensity factor of the square-root field. Near
a contact edge the JKR pressure is p = -K_I/sqrt(2 pi r) (r the distance from the edge)
and the energy release rate is G = K_I^2/(2 E*) (Johnson, Kendall & Roberts 1971;
Maugis 2000). On a grid of square cells of side h, the collocation BEM gives an edge
cell the tension alpha K_I/sqrt(h), alpha a number fixed by the discrete shape of the
edge there; so K_I = -p_e sqrt(h)/alpha and the cell detaches where G > w, i.e. where

    -p_e > sigma_c = alpha sqrt(2 E* w / h),

and a cell out of contact attaches where the surfaces touch (its gap reaches zero), the
state of the JKR's stable branch being the one with G = w on the edge. Two shapes of
edge, two alphas:

* a straight edge aligned with the cells (a run of cells with the same single free
  side, at least :data:`STRAIGHT_RUN` cells on either side along it): alpha_s =
  :data:`STRAIGHT_EDGE_ALPHA` = 0.761535, derived from the plane-strain collocation
  problem of a flat strip punch (:func:`straight_edge_alpha`, exact limit of n cells
  across the strip as n -> oo; Richardson from n = 1024, 2048);
* every other edge cell (the staircase of a curved edge, corners, run ends): Pohrt &
  Popov's (2015) constant, sigma_c = sqrt(E* w/(0.473201 h)), i.e. alpha_c =
  1/sqrt(2 x 0.473201) = 1.0279, calibrated on circular edges (JKR sphere, Kendall's
  punch).

With Pohrt & Popov's constant everywhere a straight edge held 1.34 times the exact 2D
pull-off (alpha_s/alpha_c = 0.741): the criterion's coefficient depends on the edge's
discrete shape, and a roller's long edges are straight. The run length 4 keeps the
circle's staircase on the calibrated constant: its near-axis runs, next to a step, carry
up to 4 % more tension than a straight edge; with 4 cells either side the largest
straight-run cell stays below the staircase's governing cell up to 256 cells across the
radius (measured; docs/adhesion.md).

The driver works under depth control, the only control that follows every stable
state: from a compressed start the depth is lowered step by step, and at each depth
the contact set is brought to equilibrium by

    repeat: solve K_SS p = d - h on the contact set S (pressures of either sign),
            remove the cells of S whose tension exceeds their sigma_c,
            add the cells outside S that penetrate (gap < 0),
    until S does not change.

Along this retraction curve F(d) the smallest force is the pull-off force under force
control (dF/dd = 0 there) and the force at the last depth with contact, found by
bisection of the last step, is the pull-off force under depth control (the contact
jumps off at the smallest depth it can hold).

The linear solve on a fixed set with a general right-hand side is plain conjugate
gradients (K_SS is symmetric positive definite); :func:`tools.bem.solver.solve_punch`
solves the unit right-hand side of the flat punch and is used for Kendall's punch.

References
----------
.. [1] R. Pohrt, V. L. Popov, Adhesive contact simulation of elastic solids using local
   mesh-dependent detachment criterion in boundary elements method, Facta Universitatis,
   Series Mechanical Engineering 13(1) (2015) 3-10.
.. [2] K. L. Johnson, K. Kendall, A. D. Roberts, Surface energy and the contact of
   elastic solids, Proc. R. Soc. Lond. A 324 (1971) 301-313.
.. [3] K. Kendall, The adhesion and surface energy of elastic solids, J. Phys. D 4
   (1971) 1186-1195.
.. [4] D. Maugis, Contact, Adhesion and Rupture of Elastic Solids, Springer (2000),
   chapter 3 (G = K_I^2/(2 E*) at a contact edge).
.. [5] M. Barquins, Adherence and rolling kinetics of a rigid cylinder in contact with
   a natural rubber surface, J. Adhesion 26 (1988) 1-12 (the 2D JKR cylinder).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .halfspace import SymmetricOperator
from .solver import ConvergenceError, solve_punch

#: The constant of Pohrt & Popov's criterion for square cells.
POHRT_POPOV_CONSTANT = 0.473201

#: Edge-cell tension over K_I/sqrt(h) on a straight edge aligned with the cells: the
#: n -> oo limit of the plane-strain collocation problem (:func:`straight_edge_alpha`;
#: n = 1024: 0.7616467, n = 2048: 0.7615910, Richardson 0.7615353).
STRAIGHT_EDGE_ALPHA = 0.7615353

#: Cells on either side along the edge that make a straight run (see module doc).
STRAIGHT_RUN = 4


#: The retraction starts from the contact set of the geometric overlap, pinned, of
#: this size relative to the (2D or sphere) JKR size at force-controlled pull-off: the
#: contact then holds until its edge tension reaches sigma_c and joins the JKR branch
#: before the pull-off (checked: the smallest force lies inside the curve).
START_FACTOR = 1.6

#: Tolerance of the inner solves while the contact set is still moving.
LOOSE_TOL = 1e-3


def critical_stress(estar, work, h):
    """Pohrt & Popov's detachment stress of a square cell of side h [Pa]:
    sqrt(E* w / (0.473201 h))."""
    return float(np.sqrt(estar * work / (POHRT_POPOV_CONSTANT * h)))


def straight_edge_alpha(n):
    """Edge-cell pressure of a flat strip punch in plane strain, collocation on n cells
    across the half-width b, over K_I/sqrt(h) (K_I = P'/sqrt(pi b), h = b/n).

    The 2D problem: uniform pressure p_j on cells of width h, the surface displacement
    of a strip load -(2/(pi E*)) int ln|y - t| p dt (Johnson 1985, Eq. 2.25), equal at
    every cell centre (rigid punch) and the line force P' = 1. Its limit as n -> oo is
    :data:`STRAIGHT_EDGE_ALPHA` (the error falls as 1/n).
    """
    def prim(z):                       # int ln|z| dz
        z = np.asarray(z, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(z == 0, 0.0, z * np.log(np.abs(z)) - z)

    h = 1.0 / n
    y = (np.arange(n) + 0.5) * h
    Y, T = y[:, None], y[None, :]
    G = -(prim(Y - T + h / 2) - prim(Y - T - h / 2)) - (prim(Y + T + h / 2)
                                                         - prim(Y + T - h / 2))
    A = np.zeros((n + 1, n + 1))
    A[:n, :n], A[:n, n], A[n, :n] = G, -1.0, 2 * h
    rhs = np.zeros(n + 1)
    rhs[n] = 1.0
    p = np.linalg.solve(A, rhs)[:n]
    return float(p[-1] * np.sqrt(h) * np.sqrt(np.pi))


def _neighbour(A, axis, step):
    """A at index + step along axis on the quarter grid: mirror planes at index 0 (index
    -1 is index 0), False beyond the far end."""
    n = A.shape[axis]
    idx = np.arange(n) + step
    idx = np.where(idx < 0, -idx - 1, idx)
    ok = idx < n
    B = np.take(A, np.clip(idx, 0, n - 1), axis=axis)
    shape = [1, 1]
    shape[axis] = n
    return B & ok.reshape(shape)


def straight_cells(S, run=STRAIGHT_RUN):
    """Cells of S on a straight edge aligned with the cells: one free side (a
    4-neighbour outside S), and the run cells on either side along the edge with the
    same single free side (quarter grid, mirror planes at index 0)."""
    S = np.asarray(S, dtype=bool)
    free = [S & ~_neighbour(S, ax, st) for ax, st in ((0, 1), (0, -1), (1, 1), (1, -1))]
    one = sum(f.astype(int) for f in free) == 1
    out = np.zeros_like(S)
    for f, (ax, _) in zip(free, ((0, 1), (0, -1), (1, 1), (1, -1))):
        g = f & one
        along = 1 - ax
        r = g.copy()
        for k in range(1, run + 1):
            r &= _neighbour(g, along, k) & _neighbour(g, along, -k)
        out |= r
    return out


def critical_stress_field(S, estar, work, h, run=STRAIGHT_RUN):
    """Detachment stress of each cell of S [Pa]: alpha sqrt(2 E* w/h), alpha the straight
    edge's on straight runs and Pohrt & Popov's elsewhere (module doc)."""
    sc = critical_stress(estar, work, h)
    field = np.full(np.shape(S), sc)
    field[straight_cells(S, run)] = STRAIGHT_EDGE_ALPHA * np.sqrt(2 * estar * work / h)
    return field


def _dot(a, b):
    return float(np.einsum("i,i->", a, b))


def solve_on_set(op, S, rhs, p0=None, tol=1e-9, maxiter=None):
    """Pressures p on S (zero elsewhere) with (K p)_S = rhs_S, by conjugate gradients.

    Parameters
    ----------
    op : callable
        Half-space operator p -> K p.
    S : ndarray of bool
        The contact set.
    rhs : ndarray
        Prescribed displacement on S [m] (values outside S are ignored).
    p0 : ndarray, optional
        Start (e.g. the previous step's pressures).
    tol : float
        Largest displacement error on S, relative to max |rhs_S|.

    Returns
    -------
    p, u : ndarray
        Pressures and the displacement K p (recomputed at the end).
    """
    p = np.zeros(S.shape) if p0 is None else np.where(S, p0, 0.0)
    if not S.any():
        return p, np.zeros_like(p)
    scale = max(float(np.abs(rhs[S]).max()), 1e-300)
    if maxiter is None:
        maxiter = 100 + int(20 * np.sqrt(S.sum()))
    u = op(p)
    r = np.where(S, rhs - u, 0.0)
    z = r.copy()
    rr = _dot(r[S], r[S])
    n = 0
    while np.abs(r[S]).max() > tol * scale and n < maxiter:
        q = np.where(S, op(z), 0.0)
        alpha = rr / _dot(z[S], q[S])
        p += alpha * z
        r -= alpha * q
        rr_new = _dot(r[S], r[S])
        z = np.where(S, r + (rr_new / rr) * z, 0.0)
        rr = rr_new
        n += 1
    u = op(p)
    err = float(np.abs(u[S] - rhs[S]).max()) / scale
    if err > 10 * tol:
        raise ConvergenceError(f"CG on the contact set: error {err:.3g} > {tol:g} after "
                               f"{n} iterations")
    return p, u


def equilibrate(op, separation, sigma_c, S, p=None, tol=1e-9, max_rounds=5000):
    """The adhesive equilibrium at one depth, from the contact set S (see module doc).

    Parameters
    ----------
    op : callable
        Half-space operator.
    separation : ndarray
        Gap before deformation h - d at the cell centres [m] (inf where no indenter).
    sigma_c : float or callable
        Detachment stress [Pa], or a function S -> per-cell detachment stress (the
        edge-shape criterion, :func:`critical_stress_field`).
    S : ndarray of bool
        Start contact set (e.g. the previous depth's).
    p : ndarray, optional
        Start pressures.

    Returns
    -------
    S, p, u : the converged contact set, pressures and displacements.
    """
    S = S.copy()
    rhs = -np.where(np.isfinite(separation), separation, 0.0)
    # rounds at a loose tolerance while the set moves (the edge often "unzips" one
    # cell per round), then the tight one; the set is final only if it survives the
    # tight solve unchanged
    loose = max(tol, LOOSE_TOL)
    tight = False
    for _ in range(max_rounds):
        if not S.any():
            z = np.zeros(S.shape)
            return S, z, z.copy()
        p, u = solve_on_set(op, S, rhs, p0=p, tol=tol if tight else loose)
        gap = u + separation
        sc = sigma_c(S) if callable(sigma_c) else sigma_c
        remove = S & (p < -sc)
        add = (~S) & (gap < 0)
        if not remove.any() and not add.any():
            if tight or loose == tol:
                return S, p, u
            tight = True
            continue
        tight = False
        S = (S & ~remove) | add
    raise ConvergenceError(f"contact set did not settle in {max_rounds} rounds")


@dataclass
class Retraction:
    """A retraction curve under depth control and its pull-off forces."""

    depth: np.ndarray            #: depths [m], decreasing
    force: np.ndarray            #: total force [N] (negative = tensile)
    area: np.ndarray             #: contact area [m^2]
    width: np.ndarray            #: contact half-width at x = 0 along y [m]
    pull_off_force: float        #: smallest force along the curve (force control) [N]
    pull_off_force_depth: float  #: force at the last depth with contact (depth control) [N]
    pull_off_depth: float        #: that last depth [m]
    h: float                     #: cell side [m]
    shape: tuple                 #: quarter grid (mx, my)
    rounds: int = 0              #: equilibrium rounds used
    extra: dict = field(default_factory=dict)


CRITERIA = ("edge", "pohrt-popov")


def detachment(estar, work, h, criterion="edge"):
    """The detachment stress for :func:`equilibrate`: 'edge' (default) the edge-shape
    criterion (:func:`critical_stress_field`, a function of the contact set),
    'pohrt-popov' the published constant on every cell (a number)."""
    if criterion == "edge":
        return lambda S: critical_stress_field(S, estar, work, h)
    if criterion == "pohrt-popov":
        return critical_stress(estar, work, h)
    raise ValueError(f"criterion = {criterion!r}: one of {', '.join(CRITERIA)}")


def retract(op, gap_fn, h, estar, work, d_start, d_end, steps=60, bisections=8,
            tol=1e-9, width_axis_row=0, criterion="edge"):
    """Retraction from depth d_start down to the jump-off, on a quarter grid.

    Parameters
    ----------
    op : SymmetricOperator
        Quarter operator (forces are 4x the quarter's).
    gap_fn : ndarray
        The indenter's gap before loading h(x, y) at the quarter's cell centres [m]
        (inf where there is no indenter).
    h : float
        Cell side (square cells) [m].
    estar, work : float
        E* [Pa] and w [J/m^2].
    d_start, d_end : float
        First depth (in compression) and the lowest depth tried [m]; the curve stops
        earlier when the contact jumps off. d_end must lie below the jump-off.
    steps : int
        Equal depth steps from d_start to d_end.
    bisections : int
        Halvings of the last step before the jump-off (depth-control pull-off).
    criterion : {'edge', 'pohrt-popov'}
        Detachment criterion (:func:`detachment`).
    """
    sigma_c = detachment(estar, work, h, criterion)
    cell = h * h
    S = np.isfinite(gap_fn) & (gap_fn - d_start < 0)
    p = None
    rows = []
    depths = np.linspace(d_start, d_end, steps + 1)

    def record(d, S, p):
        width = float(S[width_axis_row].sum()) * h
        rows.append((d, 4 * float(p.sum()) * cell, 4 * float(S.sum()) * cell, width))

    last = None
    step = depths[1] - depths[0]          # negative
    d, n_extra = depths[0], 0
    while True:
        S_new, p_new, _ = equilibrate(op, gap_fn - d, sigma_c, S, p, tol=tol)
        if not S_new.any():
            break
        S, p = S_new, p_new
        record(d, S, p)
        last = d
        d += step
        if d < d_end + 0.5 * step:        # past d_end: extend at the same step
            n_extra += 1
            if n_extra > 3 * steps:
                raise ValueError(f"d_end = {d_end:g} m: the contact still holds at "
                                 f"{d:g} m; lower it")
    if last is None:
        raise ValueError(f"d_start = {d_start:g} m: no adhesive contact at the start")
    # bisection of the last step: the lowest depth that still holds contact
    lo_state = (last, S, p)
    hi = last + step                      # jumps off here
    for _ in range(bisections):
        mid = 0.5 * (lo_state[0] + hi)
        S_new, p_new, _ = equilibrate(op, gap_fn - mid, sigma_c, lo_state[1], lo_state[2],
                                      tol=tol)
        if S_new.any():
            lo_state = (mid, S_new, p_new)
            record(mid, S_new, p_new)
        else:
            hi = mid
    arr = np.array(rows)
    order = np.argsort(-arr[:, 0])
    arr = arr[order]
    d_last, S_last, p_last = lo_state
    F_last = 4 * float(p_last.sum()) * cell
    i_min = int(np.argmin(arr[:, 1]))
    if i_min == 0:
        raise ValueError("the smallest force is at the start: start deeper (d_start)")
    return Retraction(depth=arr[:, 0], force=arr[:, 1], area=arr[:, 2], width=arr[:, 3],
                      pull_off_force=float(arr[i_min, 1]),
                      pull_off_force_depth=F_last, pull_off_depth=float(d_last),
                      h=h, shape=op.shape, extra={"index_min": i_min,
                                                  "depth_min": float(arr[i_min, 0]),
                                                  "width_min": float(arr[i_min, 3]),
                                                  "area_min": float(arr[i_min, 2])})


# --------------------------------------------------------------------------------------
# oracles' drivers: the JKR sphere and Kendall's punch
# --------------------------------------------------------------------------------------
def sphere_retraction(radius, estar, work, n_radius=32, steps=60, backend="scipy",
                      criterion="edge"):
    """JKR sphere (gap r^2/(2R)) on a quarter grid with n_radius cells across the
    contact radius at force-controlled pull-off, a_c = (9 pi w R^2/(8 E*))^(1/3)."""
    a_c = (9 * np.pi * work * radius ** 2 / (8 * estar)) ** (1 / 3)
    h = a_c / n_radius
    a_start = START_FACTOR * a_c            # pinned start, past the pull-off radius
    m = int(np.ceil(1.3 * a_start / h))
    op = SymmetricOperator(m, m, h, h, estar, backend=backend, workers=1)
    x = (np.arange(m) + 0.5) * h
    X, Y = np.meshgrid(x, x, indexing="ij")
    gap = (X ** 2 + Y ** 2) / (2 * radius)
    d_start = a_start ** 2 / (2 * radius)      # geometric overlap radius = a_start
    d_c = a_c ** 2 / radius                    # JKR scale of depth
    return retract(op, gap, h, estar, work, d_start, -1.0 * d_c, steps=steps,
                   criterion=criterion)


def kendall_punch(radius, estar, work, n_radius=32, backend="scipy", tol=1e-10,
                  criterion="edge"):
    """Pull-off force of a rigid flat circular punch of radius a by the local criterion:
    the unit-depth punch solution scaled until its first cell reaches its sigma_c
    (linear, so one solve); Kendall (1971): F = -sqrt(8 pi a^3 E* w)."""
    h = radius / n_radius
    m = n_radius + 2
    op = SymmetricOperator(m, m, h, h, estar, backend=backend, workers=1)
    x = (np.arange(m) + 0.5) * h
    X, Y = np.meshgrid(x, x, indexing="ij")
    S = X ** 2 + Y ** 2 <= radius ** 2
    sol = solve_punch(op, S, tol=tol)
    sc = detachment(estar, work, h, criterion)
    sc = sc(S) if callable(sc) else np.full(S.shape, sc)
    depth = -1.0 / float((sol.pressure[S] / sc[S]).max())
    area = 4 * float(S.sum()) * h * h
    return {"force": 4 * float(sol.pressure.sum()) * h * h * depth, "depth": depth,
            "area_radius": float(np.sqrt(area / np.pi)), "h": h}


def strip_punch(length_over_width=40.0, n_width=16, estar=1.0, work=1e-3, tol=1e-10,
                criterion="edge"):
    """The criterion on a straight edge aligned with the cells: a long rigid flat strip
    punch (|x| <= L/2, |y| <= b, L = length_over_width * b), unit-depth solution scaled
    until the edge cell at mid-length reaches its sigma_c. Returns the line force there
    over the exact 2D pull-off sqrt(2 pi E* w b) of a flat strip of half-width b
    (Griffith: K = P'/sqrt(pi b), G = K^2/(2 E*)): 1 when the criterion holds on a
    straight edge (the 3D BEM at mid-length against the 2D derivation of
    STRAIGHT_EDGE_ALPHA); Pohrt & Popov's constant gives 1.34."""
    b = 1.0
    h = b / n_width
    mx, my = int(round(0.5 * length_over_width * n_width)), n_width
    op = SymmetricOperator(mx, my, h, h, estar, workers=1)
    sol = solve_punch(op, np.ones((mx, my), bool), tol=tol)
    p = sol.pressure
    sc = detachment(estar, work, h, criterion)
    sc = sc(np.ones((mx, my), bool))[0, -1] if callable(sc) else sc
    line = 2 * h * float(p[0].sum()) * sc / float(p[0, -1])
    return line / np.sqrt(2 * np.pi * estar * work * b)


def long_strip(n_width=16, length_over_bc=40.0, widths=(0.8, 1.25), criterion="edge",
               tol=1e-10):
    """The 2D JKR cylinder at the middle of a long contact strip: the criterion against
    Barquins' law on a parabolic cylinder (R = E* = 1, w = pi/2 b_c^3 with b_c = 1/40 of
    the strip's length, i.e. s = 1/length_over_bc).

    For each half-width b = m h (m cells, h = b_c/n_width) the contact set is the
    rectangle |x| <= L/2, |y| <= b; its pressures are p0 + d p1 (p0: the parabolic gap at
    d = 0, p1: the flat punch at unit depth), and d is set so that the mid-length edge
    cell's tension equals its sigma_c (G = w there). The line force f = 2 h sum_j p[0, j]
    at mid-length is then compared with f_2D(b) = pi b^2/4 - sqrt(2 pi w b) (Barquins
    1988) and its smallest value over m with the 2D pull-off -3 (pi w^2/16)^(1/3). 3D end
    effects at mid-length: below 5e-4 at L = 40 b (the flat strip punch,
    :func:`strip_punch`, against the 2D collocation).

    Returns
    -------
    dict
        ``b`` (half-widths over b_c), ``ratio`` (f/f_2D at each b), ``pull_off`` (the
        smallest f over the 2D pull-off), ``b_pull_off`` (its b over b_c).
    """
    from .solver import bounded_cg

    b_c = 1.0 / length_over_bc
    w = np.pi / 2 * b_c ** 3
    h = b_c / n_width
    mx = int(round(0.5 / h))
    my = int(np.ceil(1.1 * widths[1] * n_width)) + 1
    op = SymmetricOperator(mx, my, h, h, 1.0, workers=1)
    y = (np.arange(my) + 0.5) * h
    gap = np.broadcast_to(y ** 2 / 2, (mx, my))
    sc_fn = detachment(1.0, w, h, criterion)
    ms = np.arange(int(round(widths[0] * n_width)), int(round(widths[1] * n_width)) + 1)
    bs, ratios, forces = [], [], []
    p0 = p1 = None
    for m in ms:
        S = np.zeros((mx, my), bool)
        S[:, :m] = True
        big = np.where(S, np.inf, 0.0)
        r1 = bounded_cg(op, S.astype(float), -big, big, p1, tol=tol)
        r0 = bounded_cg(op, np.where(S, -gap, 0.0), -big, big, p0, tol=tol * b_c ** 2)
        p1, p0 = r1.x, r0.x
        sc = sc_fn(S)[0, m - 1] if callable(sc_fn) else sc_fn
        d = (-sc - p0[0, m - 1]) / p1[0, m - 1]
        f = 2 * h * float((p0[0] + d * p1[0]).sum())
        b = m * h
        f2 = np.pi * b ** 2 / 4 - np.sqrt(2 * np.pi * w * b)
        bs.append(b / b_c)
        ratios.append(f / f2)
        forces.append(f)
    fc = -3 * np.cbrt(np.pi * w ** 2 / 16)
    i = int(np.argmin(forces))
    return {"b": np.array(bs), "ratio": np.array(ratios), "pull_off": forces[i] / fc,
            "b_pull_off": bs[i], "h": h}


# --------------------------------------------------------------------------------------
# the finite cylinder
# --------------------------------------------------------------------------------------
def cylinder_retraction(w_tilde, n_width=16, steps=50, margin=2.0, d_start=None,
                        d_end=None, backend="scipy", criterion="edge"):
    """Finite cylinder in self-similar units (L = R = E* = 1, w = w~ = w R^2/(E* L^3)).

    Square cells of side h = b_c/n_width, b_c = (2 w~/pi)^(1/3) the 2D JKR half-width
    at force-controlled pull-off; the quarter covers 0 <= x <= 1/2 (the cylinder's
    half-length; no indenter beyond) and 0 <= y <= margin b_c (the 2D zero-load
    half-width is 16^(1/3) b_c = 2.52 b_c). The start depth puts the contact past its
    zero-load size. Returns a :class:`Retraction` in these units.
    """
    b_c = (2 * w_tilde / np.pi) ** (1 / 3)
    h = b_c / n_width
    mx = int(round(0.5 / h))
    h = 0.5 / mx
    my = int(np.ceil(margin * b_c / h))
    op = SymmetricOperator(mx, my, h, h, 1.0, backend=backend, workers=1)
    y = (np.arange(my) + 0.5) * h
    gap = np.broadcast_to(y ** 2 / 2, (mx, my)).copy()
    if d_start is None:
        d_start = (START_FACTOR * b_c) ** 2 / 2   # geometric overlap half-width

    if d_end is None:
        d_end = -2.0 * b_c ** 2 * max(1.0, np.log(1.0 / b_c))
    res = retract(op, gap, h, 1.0, w_tilde, d_start, d_end, steps=steps,
                  criterion=criterion)
    res.extra.update(b_c=b_c, my=my, mx=mx, w_tilde=w_tilde)
    return res
