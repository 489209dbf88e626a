"""Adhesive normal contact by the boundary-element method (JKR-type, short-range adhesion).

The detachment criterion is the local, mesh-dependent one of Pohrt & Popov (2015): on a
grid of square cells of side h, a cell in contact detaches when its tensile stress
exceeds

    sigma_c = sqrt(E* w / (0.473201 h)),

w the work of adhesion; a cell out of contact attaches when the surfaces touch (its gap
reaches zero). As h -> 0 this reproduces Griffith's energy balance at the contact edge,
the JKR theory (Johnson, Kendall & Roberts 1971): the criterion is calibrated so that
the stress of the edge cell under the square-root singularity of the JKR field equals
sigma_c exactly when the energy release rate equals w.

The driver works under depth control, the only control that follows every stable
state: from a compressed start the depth is lowered step by step, and at each depth
the contact set is brought to equilibrium by

    repeat: solve K_SS p = d - h on the contact set S (pressures of either sign),
            remove the cells of S whose tension exceeds sigma_c,
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
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .halfspace import SymmetricOperator
from .solver import ConvergenceError, solve_punch

#: The constant of Pohrt & Popov's criterion for square cells.
POHRT_POPOV_CONSTANT = 0.473201


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
    sigma_c : float
        Detachment stress [Pa].
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
        remove = S & (p < -sigma_c)
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


def retract(op, gap_fn, h, estar, work, d_start, d_end, steps=60, bisections=8,
            tol=1e-9, width_axis_row=0):
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
    """
    sigma_c = critical_stress(estar, work, h)
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
def sphere_retraction(radius, estar, work, n_radius=32, steps=60, backend="scipy"):
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
    return retract(op, gap, h, estar, work, d_start, -1.0 * d_c, steps=steps)


def kendall_punch(radius, estar, work, n_radius=32, backend="scipy", tol=1e-10):
    """Pull-off force of a rigid flat circular punch of radius a by the local criterion:
    the unit-depth punch solution scaled until its most-stressed cell reaches sigma_c
    (linear, so one solve); Kendall (1971): F = -sqrt(8 pi a^3 E* w)."""
    h = radius / n_radius
    m = n_radius + 2
    op = SymmetricOperator(m, m, h, h, estar, backend=backend, workers=1)
    x = (np.arange(m) + 0.5) * h
    X, Y = np.meshgrid(x, x, indexing="ij")
    S = X ** 2 + Y ** 2 <= radius ** 2
    sol = solve_punch(op, S, tol=tol)
    sigma_c = critical_stress(estar, work, h)
    depth = -sigma_c / float(sol.pressure[S].max())
    area = 4 * float(S.sum()) * h * h
    return {"force": 4 * float(sol.pressure.sum()) * h * h * depth, "depth": depth,
            "area_radius": float(np.sqrt(area / np.pi)), "h": h}


def strip_punch(length_over_width=40.0, n_width=16, estar=1.0, work=1e-3, tol=1e-10):
    """The criterion on a straight edge aligned with the cells: a long rigid flat strip
    punch (|x| <= L/2, |y| <= b, L = length_over_width * b), unit-depth solution scaled
    until the edge cell at mid-length reaches sigma_c. Returns the line force there over
    the exact 2D pull-off sqrt(2 pi E* w b) of a flat strip of half-width b (Griffith:
    K = P'/sqrt(pi b), G = K^2/(2 E*)). 1 would mean the criterion holds on straight
    edges; Pohrt & Popov's constant was calibrated for another edge (the staircase of a
    circle), and this ratio measures how far it is from a straight one."""
    b = 1.0
    h = b / n_width
    mx, my = int(round(0.5 * length_over_width * n_width)), n_width
    op = SymmetricOperator(mx, my, h, h, estar, workers=1)
    sol = solve_punch(op, np.ones((mx, my), bool), tol=tol)
    p = sol.pressure
    line = 2 * h * float(p[0].sum()) * critical_stress(estar, work, h) / float(p[0, -1])
    return line / np.sqrt(2 * np.pi * estar * work * b)


# --------------------------------------------------------------------------------------
# the finite cylinder
# --------------------------------------------------------------------------------------
def cylinder_retraction(w_tilde, n_width=16, steps=50, margin=2.0, d_start=None,
                        d_end=None, backend="scipy"):
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
    res = retract(op, gap, h, 1.0, w_tilde, d_start, d_end, steps=steps)
    res.extra.update(b_c=b_c, my=my, mx=mx, w_tilde=w_tilde)
    return res
