"""Accuracy of the runtime roller model and of ISO 16281 slicing against the 3D BEM.

Writes tables/roller_accuracy.csv and docs/figures/roller_accuracy.png
(``python -m tools.build_tables roller``).

What it computes, per case (a roller, a profile, a force F and a tilt theta, or no
tilt: the roller free to tilt, zero moment):

1. The reference: the 3D boundary-element solution of tools.bem.roller at the force F
   and the given tilt (Newton on the approach d; on (d, theta) where the tilt is free),
   on an adapted window with ``n_x`` x ``n_y`` cells and again with twice as many in
   each direction on the same window (tools.bem.roller.grid_convergence). The
   reference is the finer grid; the change between the two grids is its stated
   resolution (columns ``bem_change_*``); every ``check_every``-th case is also solved
   on a third grid (4x) and the observed orders go to the header. Where the profile's
   drop is infinite at the roller ends (ISO 16281, Lundberg) and the finer grid's
   contact comes within two cells of an end, the contact ends microns before the end,
   inside those cells (55 um at L = 14 mm on 256 cells): the peak pressure, where it
   sits, the contact's extent and edge loading come instead from ``END_GRIDS`` =
   4096 x 16 and 8192 x 32 cells of the same window (1.7 um along the axis at L = 14
   mm), each one depth-controlled solve at the finer grid's depth and tilt; the depth
   and moment too, corrected to the force F to first order with the finer grid's
   stiffnesses (the force there differs from F by under 0.2 %); the change between
   those two grids is then the stated resolution, and there is no third grid (the
   convergence of that end zone on 2048-16384 cells:
   tools/benchmarks/bench_roller_end_bem.py). A case is *edge
   loaded* when the contact reaches a roller end cell on either grid: its peak
   pressure is then a singular end peak that depends on the grid (reported, never
   used as a target).
2. The runtime coupled-slice model of linecontact.roller (``ProfiledRoller.at_force``,
   default settings: 50 slices since issue 20's fourth round, 100 before) at the same
   F and theta, and the ISO 16281 slicing method
   (``iso_slicing``, 30 slices) with its misalignment term; each gives an approach d,
   a moment M, a peak pressure, the stiffnesses dF/dd and dM/dtheta and, where free,
   the tilt.
3. Errors against the reference: deflection (d - d_ref)/delta_ref with delta_ref the
   largest approach along the roller, max_x (d + theta x - P(x)) (= d for an untilted
   symmetric profile; the approach at the roller centre alone can be near zero for a
   tilted crowned roller); moment M/M_ref - 1 at a given tilt theta != 0 and
   (M - M_ref)/(F L/2) otherwise; tilt theta/theta_ref - 1 where it is free; peak
   pressure p/p_ref - 1 (a target only off the ends).

The cases: steel rollers of diameter D = 10 mm (E* = 115.385 GPa, steel on steel).
L = 14 mm (ISO's L <= 2.5 D branch) with five profiles -- circular crown (Rc = 500 mm),
ISO 16281 logarithmic, Lundberg's and Johns-Gohar's for a design load of 800 N/mm,
straight with tangent circular end relief (0.15 L at each end, arc radius 50 mm) -- at
tilts 0, 0.5, 1, 2 mrad; L = 30 mm with the ISO profile (its L > 2.5 D branch, flat
middle) at the same tilts; and two free-tilt cases on L = 14 mm: a crown offset by
x0 = 2 mm (exact zero-moment tilt -x0/Rc) and an asymmetric crown (Rc = 500 mm for
x < 0, 250 mm for x > 0, given as a 2001-point user table). Mean line loads
F/L = 100, 300, 800, 2000 N/mm (Hertz line-contact pressure sqrt(q E*/(pi R)) =
0.86-3.8 GPa). 104 cases.

The wide set (issue 32, ``wide_tasks``): the rollers users bring -- L/D 0.5, 0.8, 1,
1.5, 3, 6, 10 and 12 (cam-follower rings, cylindrical roller bearings, needles, a
needle's contact on an inner raceway reaching L/(2R) = 12) at mean line
loads q/(E* D) = 1e-5, 1e-4, 1e-3, 3e-3 (and 3e-6), each with the five profiles (the crown radius
scaled with L^2, WIDE_CROWN_RADII), the tilt cycling through 0, 1, 3 mrad: 200 cases,
ordered so that any first N (``--wide-limit``) spread over the grid. A wide-set case
whose BEM changes by more than REFINE between the two grids takes a third (4x) grid as
its reference. ``--bem-from`` reuses the BEM of the cases an earlier table has and
computes the others.

4. The runtime's stated errors (header ``runtime_error_*``, read by
   linecontact.accuracy) are bounds: per row |error| + |BEM grid change| (the finer
   grid's own error is at most its change from the coarser one at an observed order
   >= 1), their largest by the class the runtime states: its own edge flag, and the
   end zone (within END_ZONE L of an end where the drop is infinite) apart.

Budget: the wide set's first 140 cases took 576 s wall (138 cases) + 87 s (2 refined on
512 x 128) with 1 worker, niced, on the shared 2-core VM at load average 7-10 (median
8.3 s per case); the 20 of L/D 12 about 240 s, the 40 of q/(E* D) = 3e-6 288 s. Measured 150 s, 198 s, 461 s and 598 s for the 104 cases with the default grids on the
shared 2-core VM (2 Dask workers; the longer two at load average 8-16; the table's
header line ``wall_time``); the cases are independent, so the study runs through
tools.studies.runner.run_study (checkpoints, ``--resume``, a Dask cluster). ``--quick`` runs 28
cases (about 2 min).
"""
from __future__ import annotations

import math
import re
import time
from pathlib import Path

import numpy as np

from ..bem.roller import grid_convergence, solve_roller, solve_roller_force
from .runner import add_runner_arguments, run_study_from_args, table_meta, wall_time_line

REPO = Path(__file__).resolve().parents[2]

ESTAR = 115.385e9            #: steel on steel, E = 210 GPa, nu = 0.3 [Pa]
DIAMETER = 0.010             #: roller diameter D [m]
ROLLERS = {"A": 0.014, "B": 0.030}   #: roller lengths [m]
LINE_LOADS = (1e5, 3e5, 8e5, 2e6)     #: mean line loads F/L [N/m]
TILTS = (0.0, 5e-4, 1e-3, 2e-3)       #: [rad]
CROWN_RADIUS = 0.5                    #: circular crown [m]
CROWN_OFFSET = 0.002                  #: offset crown (free tilt: theta = -x0/Rc) [m]
CROWN_RADII_ASYM = (0.5, 0.25)        #: asymmetric crown: Rc for x < 0 and x > 0 [m]
DESIGN_LINE_LOAD = 8e5                #: Lundberg / Johns-Gohar design load F0/L [N/m]
RELIEF = dict(relief_fraction=0.15, corner_radius=0.05)  #: relief length / L, arc [m]
#: a wide-set case whose BEM changes more than this from the coarser to the finer grid
#: (peak pressure relative, off the ends; depth over the largest approach; moment over
#: |M| or F L/2) takes the third grid (4x) as its reference and the finer as its
#: coarse one: the stated bound |error| + |change| then rests on a resolved change
REFINE = dict(p_max=1e-2, depth=1e-3, moment=5e-3)
#: the end zone [L]: a contact ending within this of a roller end where the profile's
#: drop is infinite has its own stated errors (runtime_error_end_zone)
END_ZONE = 0.01
#: the stated errors (header runtime_error_* fields, read by linecontact.accuracy) are
#: the largest bound over the table's cases times this margin: the cases sample the
#: range, and a case between them may exceed their largest (the population check,
#: tools/studies/population_study.py, tests the stated errors on cases off the grid)
MARGIN = 1.5
#: the two grids (n_x, n_y) on the finer grid's window where a logarithmic profile's
#: contact comes within two cells of a roller end (module docstring, item 1)
END_GRIDS = ((4096, 16), (8192, 32))

#: the wide set (issue 32: the rollers users bring): L/D of cylindrical roller bearings
#: (0.8-1.5), needles (3-10) and cam-follower rings (0.5-0.8), mean line loads
#: q/(E* D) from light to heavy, tilts to 3 mrad; D = DIAMETER throughout
WIDE_L_OVER_D = (0.5, 0.8, 1.0, 1.5, 3.0, 6.0, 10.0)
#: appended after the first block (its order and cases unchanged): a needle of L/D 10
#: on an inner raceway has L/(2R) = 10/(1 - D/d_m), up to 12 at D/d_m = 0.15, with R
#: the contact's effective radius (the population check found them outside L/D 10)
WIDE_EXTRA_L_OVER_D = (12.0,)
#: and a lighter load for every L/D (appended last): a large cam-follower ring or a
#: long needle at 2 % of its rating carries q/(E* 2R) down to 5e-6 (the population
#: check found four such contacts below 1e-5)
WIDE_EXTRA_LINE_LOADS_OVER_ESTAR_D = (3e-6,)
WIDE_LINE_LOADS_OVER_ESTAR_D = (1e-5, 1e-4, 1e-3, 3e-3)
WIDE_TILTS = (0.0, 1e-3, 3e-3)        #: [rad]
#: the wide set's crown radius: CROWN_RADIUS (L / 14 mm)^2 within these bounds [m]
#: (the 14 mm roller's end drop of 49 um at 8-37 mm; a shallower crown on the short
#: rollers, a deeper drop on the needles)
WIDE_CROWN_RADII = (0.1, 5.0)
#: the profiles of the wide set (codes 1-5) and the set's code in the case_set column
WIDE_PROFILES = (1, 2, 3, 4, 5)
CASE_SETS = {0: "dense (L = 14, 30 mm)", 1: "wide (issue 32)"}
#: the wide set's order (wide_tasks) and its third-grid cases ((i + 2j + 3k) mod this
#: = 0 over the L/D, load and profile indices: one in seven)
WIDE_STRIDE = 37
WIDE_CHECK_EVERY = 7

#: profile codes of the table (numeric columns only)
PROFILES = {1: "circular crown", 2: "iso16281", 3: "lundberg", 4: "johns-gohar",
            5: "straight with end relief", 6: "offset circular crown",
            7: "asymmetric crown"}
#: profiles of the zero-moment (free tilt) cases
FREE_TILT = ("offset circular crown", "asymmetric crown")
CODES = {v: k for k, v in PROFILES.items()}


def make_profile(name, length, radius=DIAMETER / 2, estar=ESTAR, crown_radius=CROWN_RADIUS,
                 relief=None):
    """The profile object (linecontact.profiles) of a study case, by name
    (`crown_radius` [m]: the circular crown's; `relief`: the end relief's
    ``relief_fraction`` (of L) and ``corner_radius`` [m], default RELIEF)."""
    from linecontact import profiles as lp
    if name == "circular crown":
        return lp.CircularCrownProfile(length, crown_radius=crown_radius)
    if name == "iso16281":
        return lp.ISO16281Profile(length, diameter=2 * radius)
    if name == "lundberg":
        return lp.LundbergProfile(length, estar, design_force=DESIGN_LINE_LOAD * length)
    if name == "johns-gohar":
        return lp.JohnsGoharProfile(length, radius, estar,
                                    design_force=DESIGN_LINE_LOAD * length)
    if name == "straight with end relief":
        rel = RELIEF if relief is None else relief
        return lp.EndReliefProfile(length, corner_radius=rel["corner_radius"],
                                   relief_length=rel["relief_fraction"] * length)
    if name == "offset circular crown":
        return lp.CircularCrownProfile(length, crown_radius=CROWN_RADIUS,
                                       offset=CROWN_OFFSET)
    if name == "asymmetric crown":
        # a user table (the CSV route): two crown radii meeting at x = 0, 2001 points
        # (linear interpolation changes the drop by < 1e-4 of its end value)
        x = np.linspace(-length / 2, length / 2, 2001)
        rc = np.where(x < 0, CROWN_RADII_ASYM[0], CROWN_RADII_ASYM[1])
        return lp.TabulatedProfile(x, x ** 2 / (2 * rc), source="asymmetric crown")
    raise ValueError(f"profile {name!r} is not one of {sorted(CODES)}")


def wide_crown_radius(length):
    """The wide set's crown radius for a roller of length `length` [m]
    (WIDE_CROWN_RADII)."""
    lo, hi = WIDE_CROWN_RADII
    return float(min(max(CROWN_RADIUS * (length / ROLLERS["A"]) ** 2, lo), hi))


def task_profile(task):
    """The profile object of a task dict (its crown radius and end relief where it
    carries them)."""
    return make_profile(task["profile"], task["length"], task["radius"], task["estar"],
                        task.get("crown_radius", CROWN_RADIUS), task.get("relief"))


def wide_tasks(n_x=128, n_y=32, tol=1e-7, quick=False):
    """The wide set (WIDE_*): every L/D and line load with each of the five profiles,
    the tilt cycling through WIDE_TILTS with the L/D, load and profile indices (so
    each L/D and each profile meets every tilt): 140 cases, then the 20 of
    WIDE_EXTRA_L_OVER_D and the 40 of WIDE_EXTRA_LINE_LOADS_OVER_ESTAR_D, each block
    in its own order (``quick``: the first and last L/D and load of the first block,
    20)."""
    lds = WIDE_L_OVER_D[::len(WIDE_L_OVER_D) - 1] if quick else WIDE_L_OVER_D
    out = _wide_block(lds, 0, n_x, n_y, tol, quick)
    if not quick:
        out += _wide_block(WIDE_EXTRA_L_OVER_D, len(WIDE_L_OVER_D), n_x, n_y, tol, quick)
        out += _wide_block(WIDE_L_OVER_D + WIDE_EXTRA_L_OVER_D, 0, n_x, n_y, tol, quick,
                           qs=WIDE_EXTRA_LINE_LOADS_OVER_ESTAR_D,
                           j0=len(WIDE_LINE_LOADS_OVER_ESTAR_D))
    return out


def _wide_block(lds, i0, n_x, n_y, tol, quick, qs=None, j0=0):
    """The wide set's cases of the L/D values `lds` (indices from `i0`, for the tilt
    cycle and the third-grid rule), in their stride order."""
    # the order: a stride permutation (WIDE_STRIDE, prime to the count), so that any
    # first n cases spread over L/D, load and profile (``--wide-limit``); the third-grid
    # check by the case itself, not its place
    if qs is None:
        qs = (WIDE_LINE_LOADS_OVER_ESTAR_D[::len(WIDE_LINE_LOADS_OVER_ESTAR_D) - 1]
              if quick else WIDE_LINE_LOADS_OVER_ESTAR_D)
    tasks = []
    for i, ld in enumerate(lds, start=i0):
        L = ld * DIAMETER
        for j, qn in enumerate(qs, start=j0):
            q = qn * ESTAR * DIAMETER
            for k, code in enumerate(WIDE_PROFILES):
                prof = PROFILES[code]
                th = WIDE_TILTS[(i + j + k) % len(WIDE_TILTS)]
                tasks.append(dict(
                    key=f"W-ld{ld:g}-{prof.replace(' ', '_')}-qn{qn:g}-t{th * 1e3:g}",
                    roller="W", profile=prof, radius=DIAMETER / 2, length=L,
                    estar=ESTAR, force=q * L, tilt=th, n_x=n_x, n_y=n_y, tol=tol,
                    crown_radius=wide_crown_radius(L), case_set=1,
                    check=(i + 2 * j + 3 * k) % WIDE_CHECK_EVERY == 0))
    n = len(tasks)
    stride = next(s for s in range(WIDE_STRIDE, n + WIDE_STRIDE) if math.gcd(s, n) == 1)
    return [tasks[(m * stride) % n] for m in range(n)]


def study_tasks(n_x=128, n_y=32, tol=1e-7, check_every=7, quick=False, wide=True,
                wide_limit=None):
    """The list of cases (picklable dicts with a unique 'key'): the dense set and, with
    `wide`, the wide set (wide_tasks); every `check_every`-th case is also solved on a
    third grid (4 n_x x 4 n_y) to measure the order."""
    tasks = []
    combos = ([("A", PROFILES[k]) for k in range(1, 6)] + [("B", "iso16281")]
              + [("A", p) for p in FREE_TILT])
    loads = LINE_LOADS[1::2] if quick else LINE_LOADS
    for roller, prof in combos:
        L = ROLLERS[roller]
        # the FREE_TILT profiles are free to tilt (tilt None: zero moment)
        tilts = (None,) if prof in FREE_TILT else (
            TILTS[::2] if quick else TILTS)
        for q in loads:
            for th in tilts:
                tag = "free" if th is None else f"{th * 1e3:g}"
                tasks.append(dict(
                    key=f"{roller}-{prof.replace(' ', '_')}-q{q / 1e3:g}-t{tag}",
                    roller=roller, profile=prof, radius=DIAMETER / 2, length=L,
                    estar=ESTAR, force=q * L, tilt=th, n_x=n_x, n_y=n_y, tol=tol,
                    crown_radius=CROWN_RADIUS, case_set=0))
    for i, t in enumerate(tasks):
        t["check"] = bool(check_every) and i % check_every == 0
    if wide:
        w = wide_tasks(n_x, n_y, tol, quick)
        tasks += w[:wide_limit] if wide_limit is not None else w
    return tasks


def _largest_approach(depth, tilt, profile, length):
    xs = np.linspace(-length / 2, length / 2, 4097)
    with np.errstate(divide="ignore", invalid="ignore"):
        return float(np.max(depth + tilt * xs - profile.drop(xs)))


def bem_case(task):
    """The BEM reference of one case on two nested grids (module docstring, item 1)."""
    t0 = time.perf_counter()
    prof = task_profile(task)
    g = grid_convergence(solve_roller_force, task["radius"], task["length"], task["estar"],
                         task["force"], tilt=task["tilt"], profile=prof,
                         n_x=task["n_x"], n_y=task["n_y"], tol=task["tol"], workers=1)
    c, f = g["coarse"], g["fine"]
    edge = bool(c.edge_loaded or f.edge_loaded)
    order_d = order_m = np.nan
    refined = _infinite_end(prof, task["length"]) and (
        f.edge_loaded or _end_gap(f, task["length"]) < 2 * f.grid.dx)
    delta0 = _largest_approach(f.depth, f.tilt, prof, task["length"])
    scale_m0 = abs(f.moment) if task["tilt"] else task["force"] * task["length"] / 2
    unresolved = task.get("case_set", 0) == 1 and (
        (not edge and abs(f.p_max / c.p_max - 1) > REFINE["p_max"])
        or abs(f.depth - c.depth) > REFINE["depth"] * delta0
        or abs(f.moment - c.moment) > REFINE["moment"] * scale_m0)
    if (task.get("check") or unresolved) and not refined:
        # a third grid on the same window: the observed order of d and M
        h = solve_roller_force(task["radius"], task["length"], task["estar"], task["force"],
                               tilt=task["tilt"], profile=prof, n_x=2 * f.grid.nx,
                               n_y=2 * f.grid.ny, tol=task["tol"], window=f.grid,
                               start=(f.depth, f.tilt), workers=1)
        order_d = _order(c.depth, f.depth, h.depth)
        order_m = _order(c.moment, f.moment, h.moment)
        if unresolved:
            # the reference moves one grid up: (fine, third) as (coarse, fine)
            c, f = f, h
            edge = bool(c.edge_loaded or f.edge_loaded)
    out = dict(order_depth=order_d, order_moment=order_m,
        depth=f.depth, moment=f.moment, p_max=f.p_max, x_at_p_max=f.x_at_p_max,
        contact_length=f.contact_length, stiffness=f.stiffness,
        tilt_stiffness=f.tilt_stiffness, edge=edge,
        end_gap=_end_gap(f, task["length"]),
        delta=_largest_approach(f.depth, f.tilt, prof, task["length"]), tilt=f.tilt,
        change_depth=f.depth - c.depth, change_moment=f.moment - c.moment,
        change_tilt=f.tilt - c.tilt, change_stiffness=f.stiffness / c.stiffness - 1,
        change_tilt_stiffness=f.tilt_stiffness / c.tilt_stiffness - 1,
        change_p_max=f.p_max / c.p_max - 1,
        richardson_depth=g["richardson_depth"], richardson_moment=g["richardson_moment"],
        nx=f.grid.nx, ny=f.grid.ny, dx=f.grid.dx, dy=f.grid.dy,
        iterations=c.iterations + f.iterations)
    if refined:
        out.update(_end_zone(task, prof, f))
    out["seconds"] = time.perf_counter() - t0
    return out


def _end_zone(task, prof, f):
    """A logarithmic profile's contact that ends within two cells of a roller end, on
    the END_GRIDS of the finer grid's window (module docstring, item 1): one
    depth-controlled solve per grid at that grid's depth and tilt, the depth then
    corrected to the force F to first order with its stiffness dF/dd (and the moment
    with dM/dd = dF/dtheta); p_max, where it sits, the contact's extent and edge loading
    from the solve itself (at a force within 0.2 % of F). The stiffnesses stay the
    finer standard grid's. Returns the fields of bem_case that it replaces."""
    L, F = task["length"], task["force"]
    res = []
    for nx, ny in END_GRIDS:
        r = solve_roller(task["radius"], L, task["estar"], f.depth, tilt=f.tilt,
                         profile=prof, n_x=nx, n_y=ny, tol=task["tol"], window=f.grid,
                         stiffness=False, workers=1)
        dd = (F - r.force) / f.stiffness
        res.append((r, f.depth + dd, r.moment + f.coupling * dd))
    (rc, dc, mc), (rf, df, mf) = res
    return dict(depth=df, moment=mf, p_max=rf.p_max, x_at_p_max=rf.x_at_p_max,
                contact_length=rf.contact_length, edge=bool(rc.edge_loaded or rf.edge_loaded),
                end_gap=_end_gap(rf, L), delta=_largest_approach(df, f.tilt, prof, L),
                change_depth=df - dc, change_moment=mf - mc,
                change_p_max=rf.p_max / rc.p_max - 1, end_force_change=rf.force / F - 1,
                nx=rf.grid.nx, ny=rf.grid.ny, dx=rf.grid.dx, dy=rf.grid.dy,
                iterations=f.iterations + rc.iterations + rf.iterations)


def _infinite_end(profile, length):
    """Whether the profile's drop is infinite at a roller end (ISO 16281, Lundberg)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return bool(np.any(np.isinf(profile.drop(np.array([-length / 2, length / 2])))))


def _end_gap(sol, length):
    """The contact's distance from the nearer roller end on a BEM grid [m]."""
    return length / 2 - max(abs(sol.contact_x[0]), abs(sol.contact_x[1]))


def _order(a, b, c):
    """Observed convergence order from three grids refined by 2; NaN where the changes
    are not monotone or the last one is below 1e-6 of the value (the force-control
    tolerance: noise, not discretisation)."""
    if (b - a) * (c - b) <= 0 or abs(c - b) < 1e-6 * abs(c):
        return np.nan
    return float(np.log2(abs(b - a) / abs(c - b)))


# --- runtime and ISO slicing ---------------------------------------------------------

def _peak(sol):
    """p_max of a runtime solution; where it is edge loaded the runtime reports None
    (a singular end peak) and the largest slice pressure stands in (flagged *_edge)."""
    return float(sol.p_max) if sol.p_max is not None else float(np.max(sol.pressure))


def runtime_case(task, n_slices=None):
    """The runtime coupled-slice model (linecontact.roller.ProfiledRoller) at the case's
    F and theta: d, M, p_max, stiffnesses, edge loading and the wall and CPU seconds of
    the solve (the model built once beforehand; CPU time is what a shared machine's
    load does not inflate); `n_slices` None: the model's default."""
    from linecontact.roller import ProfiledRoller
    prof = task_profile(task)
    model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof,
                           **({} if n_slices is None else {"n_slices": n_slices}))
    t0, c0 = time.perf_counter(), time.process_time()
    r = model.at_force(task["force"], tilt="free" if task["tilt"] is None else task["tilt"])
    dt, dc = time.perf_counter() - t0, time.process_time() - c0
    L = task["length"]
    # the runtime contact's distance from the nearer roller end, over L
    gap = (L / 2 - max(abs(r.contact_start), abs(r.contact_end))) / L
    return dict(depth=r.depth, moment=r.moment, p_max=_peak(r), edge=bool(r.edge_loaded),
                tilt=r.tilt, stiffness=r.stiffness, tilt_stiffness=r.tilt_stiffness,
                seconds=dt, cpu_seconds=dc, end_gap=gap)


def iso_case(task, n_slices=30):
    """ISO 16281 slicing (linecontact.roller.iso_slicing, with its misalignment
    term) at the case's F and theta."""
    from linecontact.roller import iso_slicing
    prof = task_profile(task)
    r = iso_slicing(task["radius"], task["length"], task["estar"], prof,
                    force=task["force"],
                    tilt="free" if task["tilt"] is None else task["tilt"], n_slices=n_slices)
    return dict(depth=r.depth, moment=r.moment, p_max=_peak(r), edge=bool(r.edge_loaded),
                tilt=r.tilt, stiffness=r.stiffness, tilt_stiffness=r.tilt_stiffness)


def errors(ref, got, task):
    """Deflection, moment, peak-pressure and tilt errors of `got` against the BEM `ref`
    [-] (definitions: module docstring, item 3); the tilt error is 0 where the tilt is
    given."""
    e_d = (got["depth"] - ref["depth"]) / ref["delta"]
    if task["tilt"]:
        e_m = got["moment"] / ref["moment"] - 1
    else:
        e_m = (got["moment"] - ref["moment"]) / (task["force"] * task["length"] / 2)
    e_p = got["p_max"] / ref["p_max"] - 1
    e_t = got["tilt"] / ref["tilt"] - 1 if task["tilt"] is None else 0.0
    return e_d, e_m, e_p, e_t


def run_case(task):
    """One study case: the BEM reference, the runtime and ISO slicing, and their errors
    (a module-level function of one task, for tools.studies.runner.run_study)."""
    return compare_case(task, bem_case(task))


def compare_case(task, ref):
    """The runtime and ISO slicing of one case against its BEM reference `ref` (the
    dict of bem_case), and their errors: the result of run_case."""
    out = {f"bem_{k}": v for k, v in ref.items()}
    for name, fn in (("rt", runtime_case), ("iso", iso_case)):
        got = fn(task)
        e_d, e_m, e_p, e_t = errors(ref, got, task)
        out.update({f"{name}_depth": got["depth"], f"{name}_moment": got["moment"],
                    f"{name}_p_max": got["p_max"], f"{name}_edge": got["edge"],
                    f"{name}_tilt": got["tilt"], f"{name}_err_depth": e_d,
                    f"{name}_err_moment": e_m, f"{name}_err_p_max": e_p,
                    f"{name}_err_tilt": e_t,
                    f"{name}_err_stiffness": got["stiffness"] / ref["stiffness"] - 1,
                    f"{name}_err_tilt_stiffness":
                        got["tilt_stiffness"] / ref["tilt_stiffness"] - 1})
        if "seconds" in got:
            out[f"{name}_seconds"] = got["seconds"]
            out[f"{name}_cpu_seconds"] = got["cpu_seconds"]
            out[f"{name}_end_gap"] = got["end_gap"]
    return out


def bem_from_table(tasks, table, n_x, n_y, tol, check_every=7, missing_ok=False):
    """The BEM references of `tasks` (dicts as bem_case returns them) read back from
    an earlier roller_accuracy table (``--bem-from``), whose cases, grids, tolerance
    and third-grid cases (``--check-every``: its accuracy line, reused, holds their
    observed orders, and the header's grid line names them) must be this run's: the
    inverse of tabulate's bem_* columns (the observed orders are not columns: NaN, the
    table's ``accuracy`` line keeps them). With `missing_ok`, a case the table lacks
    gives None in its place (the caller computes it) instead of an error."""
    c = table.columns
    tol_field = str(table.meta.get("tolerance", "")).split(" ")[0]
    if tol_field != f"{tol:g}":
        raise ValueError(f"--bem-from: the table's tolerance is {tol_field}, this run's "
                         f"{tol:g}")
    every = re.search(r"every (\d+)th case also on", str(table.meta.get("grid", "")))
    if every is None or int(every.group(1)) != check_every:
        raise ValueError("--bem-from: the table solved every "
                         f"{every.group(1) if every else '(unstated)'}th case on a third "
                         f"grid, this run's --check-every is {check_every}")
    refs = []
    for t in tasks:
        free = t["tilt"] is None
        m = ((np.abs(c["roller_length"] - t["length"]) < 1e-12)
             & (c["profile"] == CODES[t["profile"]])
             & (np.abs(c["force"] - t["force"]) <= 1e-9 * t["force"])
             & (c["free_tilt"] == float(free))
             & (free | (np.abs(c["tilt"] - (t["tilt"] or 0.0)) < 1e-12)))
        if "case_set" in c:
            m &= c["case_set"] == t.get("case_set", 0)
            m &= np.abs(c["crown_radius"] - t.get("crown_radius", CROWN_RADIUS)) < 1e-12
        elif t.get("case_set", 0) != 0:
            m &= False          # a table before the wide set: its cases are all dense
        i = np.flatnonzero(m)
        if i.size == 0 and missing_ok:
            refs.append(None)   # not in the table: computed by the caller
            continue
        if i.size != 1:
            raise ValueError(f"--bem-from: case {t['key']} is {i.size} times in the table "
                             "(1 expected: the same cases)")
        i = int(i[0])
        if c["bem_nx"][i] != END_GRIDS[1][0] and (c["bem_nx"][i], c["bem_ny"][i]) not in (
                (2 * n_x, 2 * n_y), (4 * n_x, 4 * n_y)):
            raise ValueError(f"--bem-from: case {t['key']} has a finer grid of "
                             f"{c['bem_nx'][i]:g} x {c['bem_ny'][i]:g} cells, this run "
                             f"{2 * n_x} x {2 * n_y}")
        r = {k: float(c[f"bem_{k}"][i]) for k in (
            "depth", "delta", "moment", "p_max", "x_at_p_max", "contact_length",
            "end_gap", "stiffness", "tilt_stiffness", "nx", "ny", "change_p_max",
            "change_stiffness", "change_tilt_stiffness", "seconds")}
        scale_m = abs(r["moment"]) if t["tilt"] else t["force"] * t["length"] / 2
        r.update(tilt=float(c["tilt"][i]), edge=bool(c["bem_edge"][i]),
                 change_depth=c["bem_change_depth"][i] * r["delta"],
                 change_moment=c["bem_change_moment"][i] * scale_m,
                 change_tilt=c["bem_change_tilt"][i] * c["tilt"][i] if free else 0.0,
                 order_depth=np.nan, order_moment=np.nan)
        refs.append(r)
    return refs


def runtime_settings():
    """What the rt_* and iso_* columns ran: the runtime model's settings (its defaults,
    runtime_case) and ISO slicing's slice count, for the header (``runtime_settings``):
    the table describes the model at those settings, which a later default may not
    be."""
    import inspect

    from linecontact.roller import model
    from linecontact.roller.slices import DEFAULT_N_SLICES
    return (f"linecontact.roller.ProfiledRoller at its defaults: {DEFAULT_N_SLICES} "
            f"slices graded {model.DEFAULT_GRADING:g} towards the overlap interval's "
            f"ends, the end slices refined up to {model.REFINE_LEVELS} levels where the "
            f"peak is unresolved (until p_max settles within {model.REFINE_TOL:g}); "
            "ISO 16281 slicing (iso_slicing): "
            f"{inspect.signature(iso_case).parameters['n_slices'].default} slices")


def bem_from_line(meta, name):
    """The ``bem_from`` header line of a table whose BEM columns are reused from an
    earlier table (file `name`, header `meta`): the run that computed them, its
    version, date and wall time. Where that table had itself reused them (its own
    ``bem_from``), its line is carried over unchanged: the BEM columns are still those
    of the run it names, not of the reusing run (whose command, version and time say
    nothing about them)."""
    if meta.get("bem_from"):
        return meta["bem_from"]
    # the earlier command, its checkpoint folder (a local path) named generically
    cmd = re.sub(r"--checkpoint[ =]\S+", "--checkpoint DIR",
                 str(meta.get("generated_by")))
    return (f"the bem_* columns (and the accuracy line) are those of the earlier "
            f"{name}, reused unchanged (the 3D BEM does not use linecontact.roller): "
            f"written by '{cmd}', {meta.get('version')}, {meta.get('date')}; its "
            f"wall_time: {meta.get('wall_time')}")


# --- the study ---------------------------------------------------------------------

def add_grid_arguments(parser):
    """--n-x, --n-y, --tol: the 3D BEM grid of a roller case (this study's and the
    stress study's, which solves the same contact)."""
    parser.add_argument("--n-x", type=int, default=128,
                        help="cells along the axis over the contact window, coarser of "
                             "the two grids (default 128)")
    parser.add_argument("--n-y", type=int, default=32,
                        help="cells across the strip |y| <= 1.25 b (default 32)")
    parser.add_argument("--tol", type=float, default=1e-7,
                        help="contact-solver tolerance: gap error / largest "
                             "interference (default 1e-7)")


def add_arguments(parser):
    add_grid_arguments(parser)
    parser.add_argument("--check-every", type=int, default=7,
                        help="every k-th case also on a third grid (4x) to measure the "
                             "convergence order (default 7, so that all tilts are sampled; 0: never)")
    parser.add_argument("--no-wide", action="store_true",
                        help="the dense set only (L = 14, 30 mm), without the wide set "
                             "(WIDE_*: L/D 0.5-12, q/(E* D) 3e-6-3e-3, tilts to 3 mrad)")
    parser.add_argument("--wide-limit", type=int, default=None, metavar="N",
                        help="only the first N cases of the wide set (its order spreads "
                             "any first N over L/D, load and profile; default: all)")
    parser.add_argument("--quick", action="store_true",
                        help="a quarter of the cases (two loads, two tilts): a smoke run")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for roller_accuracy.csv (default tables/)")
    # a str, not a Path: Path('') is '.', so '' could not mean "no figure"
    parser.add_argument("--figure",
                        default=str(REPO / "docs" / "figures" / "roller_accuracy.png"),
                        help="where to write the figure ('' for none)")
    parser.add_argument("--bem-from", type=Path, default=None, metavar="CSV",
                        help="take the BEM columns of an earlier roller_accuracy.csv "
                             "(the same cases, grids and tolerance; its accuracy line, "
                             "provenance and time are carried into the header) and "
                             "recompute only the runtime and ISO slicing columns: for a "
                             "change of linecontact.roller, which the 3D BEM does not use")
    add_runner_arguments(parser)


COLUMNS_UNITS = {
    "roller_length": "m", "profile": "-", "force": "N", "line_load": "N/m", "tilt": "rad",
    "free_tilt": "-",
    "bem_depth": "m", "bem_delta": "m", "bem_moment": "N m", "bem_p_max": "Pa",
    "bem_x_at_p_max": "m", "bem_contact_length": "m", "bem_end_gap": "m", "bem_edge": "-",
    "bem_stiffness": "N/m", "bem_tilt_stiffness": "N m/rad", "bem_change_depth": "-",
    "bem_change_moment": "-", "bem_change_p_max": "-", "bem_change_tilt": "-",
    "bem_change_stiffness": "-", "bem_change_tilt_stiffness": "-", "bem_nx": "-", "bem_ny": "-",
    "rt_depth": "m", "rt_moment": "N m", "rt_p_max": "Pa", "rt_edge": "-",
    "rt_err_depth": "-", "rt_err_moment": "-", "rt_err_p_max": "-", "rt_tilt": "rad",
    "rt_err_tilt": "-", "rt_err_stiffness": "-", "rt_err_tilt_stiffness": "-",
    "rt_seconds": "s", "rt_cpu_seconds": "s", "rt_end_gap": "-",
    "iso_depth": "m", "iso_moment": "N m", "iso_p_max": "Pa", "iso_edge": "-",
    "iso_err_depth": "-", "iso_err_moment": "-", "iso_err_p_max": "-", "iso_tilt": "rad",
    "iso_err_tilt": "-", "iso_err_stiffness": "-", "iso_err_tilt_stiffness": "-",
    "bem_seconds": "s",
    "crown_radius": "m", "case_set": "-",
    "rt_bound_depth": "-", "rt_bound_moment": "-", "rt_bound_p_max": "-",
    "rt_bound_tilt": "-", "rt_bound_stiffness": "-", "rt_bound_tilt_stiffness": "-",
}
#: the runtime's error bound per quantity: |rt_err_*| + |bem_change_*| (the finer BEM
#: grid's own error is at most its change from the coarser one where the observed order
#: is at least 1: a Richardson estimate E_fine = change/(2^p - 1) <= |change|)
BOUNDS = ("depth", "moment", "p_max", "tilt", "stiffness", "tilt_stiffness")


def tabulate(tasks, results):
    """Table columns (dict of arrays) from the tasks and their results."""
    rows = []
    for t, r in zip(tasks, results):
        scale_m = abs(r["bem_moment"]) if t["tilt"] else t["force"] * t["length"] / 2
        rows.append({
            "roller_length": t["length"], "profile": CODES[t["profile"]],
            "force": t["force"], "line_load": t["force"] / t["length"],
            "tilt": r["bem_tilt"], "free_tilt": float(t["tilt"] is None),
            **{k: float(r[k]) for k in ("bem_depth", "bem_delta", "bem_moment", "bem_p_max",
                                        "bem_x_at_p_max", "bem_contact_length",
                                        "bem_end_gap", "bem_stiffness",
                                        "bem_tilt_stiffness", "bem_nx", "bem_ny")},
            "bem_edge": float(r["bem_edge"]),
            "bem_change_depth": r["bem_change_depth"] / r["bem_delta"],
            "bem_change_moment": r["bem_change_moment"] / scale_m,
            "bem_change_p_max": r["bem_change_p_max"],
            "bem_change_tilt": r["bem_change_tilt"] / r["bem_tilt"] if t["tilt"] is None
            else 0.0,
            "bem_change_stiffness": r["bem_change_stiffness"],
            "bem_change_tilt_stiffness": r["bem_change_tilt_stiffness"],
            **{f"{m}_{k}": float(r[f"{m}_{k}"]) for m in ("rt", "iso")
               for k in ("depth", "moment", "p_max", "edge", "err_depth", "err_moment",
                         "err_p_max", "tilt", "err_tilt", "err_stiffness",
                         "err_tilt_stiffness")},
            "rt_seconds": r["rt_seconds"], "rt_cpu_seconds": r["rt_cpu_seconds"],
            "rt_end_gap": r["rt_end_gap"],
            "bem_seconds": r["bem_seconds"],
            "crown_radius": t.get("crown_radius", CROWN_RADIUS),
            "case_set": t.get("case_set", 0),
        })
        row = rows[-1]
        for k in BOUNDS:
            row[f"rt_bound_{k}"] = abs(row[f"rt_err_{k}"]) + abs(row[f"bem_change_{k}"])
    return {k: np.array([row[k] for row in rows], dtype=float) for k in COLUMNS_UNITS}


def summarise(col, tasks, results):
    """The accuracy statements of the header (largest errors by class)."""
    edge = col["bem_edge"] > 0
    free = col["free_tilt"] > 0
    tilted = (col["tilt"] != 0) & ~free
    s = {}

    def mx(a, mask):
        return float(np.max(np.abs(a[mask]), initial=0.0))

    # the runtime's stated errors: its bounds (|error| + the BEM's grid change), by
    # the runtime's own edge flag (the class whose error a user is shown); its peak
    # pressure only where the BEM's is off the ends too (a finite peak), the rows where
    # the two flags differ counted apart
    rte = col["rt_edge"] > 0
    # the end zone: a contact within END_ZONE L of a roller end where the drop is
    # infinite (ISO 16281, Lundberg), where the BEM reference is least resolved; its
    # rows (by the BEM's gap, with a factor 2 of overlap each way, so a runtime whose
    # own gap falls on the other side of the line is still bounded) have their errors
    gap = col["bem_end_gap"] / col["roller_length"]
    inf_end = np.isin(col["profile"], [CODES["iso16281"], CODES["lundberg"]])
    zone = inf_end & (gap < 2 * END_ZONE)
    clear = ~(inf_end & (gap < END_ZONE / 2))
    s["rt_zone_d"] = mx(col["rt_bound_depth"], ~rte & zone)
    s["rt_zone_m"] = mx(col["rt_bound_moment"], ~rte & zone & tilted)
    s["rt_zone_m0"] = mx(col["rt_bound_moment"], ~rte & zone & ~tilted)
    s["rt_zone_p"] = mx(col["rt_bound_p_max"], ~rte & zone & ~edge)
    s["rt_zone_t"] = mx(col["rt_bound_tilt"], ~rte & zone & free)
    s["n_zone"] = int((~rte & zone).sum())
    rte = rte | ~clear      # below: off the ends and clear of the end zone
    s["rt_off_d"] = mx(col["rt_bound_depth"], ~rte)
    s["rt_off_m"] = mx(col["rt_bound_moment"], ~rte & tilted)
    s["rt_off_m0"] = mx(col["rt_bound_moment"], ~rte & ~tilted)
    s["rt_off_p"] = mx(col["rt_bound_p_max"], ~rte & ~edge)
    s["rt_off_t"] = mx(col["rt_bound_tilt"], ~rte & free)
    rte = col["rt_edge"] > 0
    s["rt_edge_d"] = mx(col["rt_bound_depth"], rte)
    s["rt_edge_m"] = mx(col["rt_bound_moment"], rte & tilted)
    s["rt_edge_m0"] = mx(col["rt_bound_moment"], rte & ~tilted)
    s["rt_edge_t"] = mx(col["rt_bound_tilt"], rte & free)
    s["rt_k"] = mx(col["rt_bound_stiffness"], np.ones_like(edge))
    s["rt_kt"] = mx(col["rt_bound_tilt_stiffness"], np.ones_like(edge))
    s["n_rt_off"], s["n_rt_edge"] = int((~rte & clear).sum()), int(rte.sum())
    s["n_flag_differ"] = int((~rte & edge).sum())
    # the same by case set and L/D band (documentation: the runtime reads the above)
    bands = []
    for lo, hi in ((0, 1.0), (1.0, 2.0), (2.0, 5.0), (5.0, np.inf)):
        ld = col["roller_length"] / DIAMETER
        sel = ~rte & (ld >= lo) & (ld < hi) if np.isfinite(hi) else ~rte & (ld >= lo)
        if sel.any():
            bands.append(f"L/D {lo:g}-{hi:g} ({int(sel.sum())} cases): deflection "
                         f"{mx(col['rt_bound_depth'], sel):.2%}, moment "
                         f"{mx(col['rt_bound_moment'], sel & tilted):.2%}, peak pressure "
                         f"{mx(col['rt_bound_p_max'], sel & ~edge):.2%}")
    s["bands"] = "; ".join(bands)
    for m in ("iso",):
        s[f"{m}_off_d"] = mx(col[f"{m}_err_depth"], ~edge)
        s[f"{m}_off_m"] = mx(col[f"{m}_err_moment"], ~edge & tilted)
        s[f"{m}_off_m0"] = mx(col[f"{m}_err_moment"], ~edge & ~tilted)
        s[f"{m}_off_p"] = mx(col[f"{m}_err_p_max"], ~edge)
        s[f"{m}_edge_d"] = mx(col[f"{m}_err_depth"], edge)
        s[f"{m}_edge_m"] = mx(col[f"{m}_err_moment"], edge & tilted)
        s[f"{m}_off_t"] = mx(col[f"{m}_err_tilt"], ~edge & free)
        s[f"{m}_edge_t"] = mx(col[f"{m}_err_tilt"], edge & free)
        s[f"{m}_k"] = mx(col[f"{m}_err_stiffness"], np.ones_like(edge))
        s[f"{m}_kt"] = mx(col[f"{m}_err_tilt_stiffness"], np.ones_like(edge))
    s["bem_off_d"] = mx(col["bem_change_depth"], ~edge)
    s["bem_off_m"] = mx(col["bem_change_moment"], ~edge)
    s["bem_off_p"] = mx(col["bem_change_p_max"], ~edge)
    s["bem_edge_d"] = mx(col["bem_change_depth"], edge)
    s["bem_edge_m"] = mx(col["bem_change_moment"], edge)
    s["bem_k"] = mx(col["bem_change_stiffness"], np.ones_like(edge))
    s["bem_kt"] = mx(col["bem_change_tilt_stiffness"], np.ones_like(edge))
    od = np.array([r["bem_order_depth"] for r in results], dtype=float)
    om = np.array([r["bem_order_moment"] for r in results], dtype=float)
    edge_t = np.array([bool(r["bem_edge"]) for r in results])
    s["orders"] = "; ".join(
        f"{label}: d {_span(od[mask])}, M {_span(om[mask & tilted])}"
        for label, mask in (("off the ends", ~edge_t), ("edge loaded", edge_t)))
    s["n_off"], s["n_edge"] = int((~edge).sum()), int(edge.sum())
    end = col["bem_nx"] == END_GRIDS[1][0]
    s["n_end"] = int(end.sum())
    q = col["line_load"][~edge]
    s["range_q"] = (float(q.min(initial=np.inf)), float(q.max(initial=-np.inf)))
    s["rt_seconds"] = float(np.median(col["rt_seconds"]))
    s["rt_cpu_seconds"] = float(np.median(col["rt_cpu_seconds"]))
    s["case_seconds"] = float(np.sum(col["bem_seconds"]) + np.sum(col["rt_seconds"]))
    # the range the study covers (where the runtime's error is known)
    L = col["roller_length"]
    s["range"] = (
        f"L/D {np.min(L) / DIAMETER:g}-{np.max(L) / DIAMETER:g}; mean line load "
        f"q/(E* D) {np.min(col['line_load']) / (ESTAR * DIAMETER):.2g}-"
        f"{np.max(col['line_load']) / (ESTAR * DIAMETER):.2g} (q = "
        f"{np.min(col['line_load']) / 1e3:g}-{np.max(col['line_load']) / 1e3:g} N/mm at "
        f"D = {DIAMETER * 1e3:g} mm); given tilts |theta| <= "
        f"{np.max(np.abs(col['tilt'][col['free_tilt'] == 0])) * 1e3:.3g} mrad, free "
        f"(zero-moment) tilts up to {np.max(np.abs(col['tilt'][col['free_tilt'] > 0])) * 1e3:.3g}"
        " mrad, "
        f"tilt drop over the half-length up to "
        f"{np.max(np.abs(col['tilt']) * L / 2 / col['bem_delta']):.2g} times the largest "
        f"approach; profiles {', '.join(PROFILES.values())}")
    s["bem_seconds"] = float(np.median(col["bem_seconds"]))
    # the same range as data (read by linecontact.roller to note cases outside it):
    # "low, high" pairs; |theta| for tilts; profile keys of linecontact.profiles
    given, freet = col["free_tilt"] == 0, col["free_tilt"] > 0
    inf_rows = np.isin(col["profile"], [CODES["iso16281"], CODES["lundberg"]])
    drop = np.abs(col["tilt"]) * L / 2 / col["bem_delta"]
    qn = col["line_load"] / (ESTAR * DIAMETER)
    s["covered_fields"] = {
        "covered_l_over_d": f"{np.min(L) / DIAMETER:.6g}, {np.max(L) / DIAMETER:.6g}",
        "covered_line_load_over_estar_d": f"{np.min(qn):.6g}, {np.max(qn):.6g}",
        "covered_given_tilt_rad": f"0, {np.max(np.abs(col['tilt'][given])):.6g}",
        "covered_free_tilt_rad": f"0, {np.max(np.abs(col['tilt'][freet]), initial=0):.6g}",
        "covered_tilt_drop_over_approach": f"0, {np.max(drop):.6g}",
        # the study's profiles by runtime key (its user-table case is a smooth
        # asymmetric crown, not any table: "file" is not listed)
        "covered_profiles": "circular, iso16281, lundberg, johns-gohar, end-relief",
        # the closest a contact came to an end where the drop is infinite (the BEM's
        # contact on its finer grid, over L): closer, the end zone was not measured
        # the closest a contact came to an end where the drop is infinite with the BEM
        # off that end (its finer grid's contact, over L), raised to the farthest the
        # runtime's contact stayed from the end where the BEM's reached it (there the
        # runtime, off the end, states a peak pressure the BEM finds singular)
        "covered_infinite_end_gap_over_length": (
            f"{max(np.min(col['bem_end_gap'][end & ~edge] / L[end & ~edge], initial=np.inf), 1.0001 * np.max(col['rt_end_gap'][inf_rows & (col['rt_edge'] == 0) & edge], initial=0.0)):.6g}"
            ", 0.5"),
        "runtime_error_off_ends": (
            f"depth {MARGIN * s['rt_off_d']:.3g}, moment {MARGIN * s['rt_off_m']:.3g}, moment_untilted "
            f"{MARGIN * s['rt_off_m0']:.3g}, p_max {MARGIN * s['rt_off_p']:.3g}, tilt {MARGIN * s['rt_off_t']:.3g}"),
        "runtime_error_end_zone": (
            f"depth {MARGIN * s['rt_zone_d']:.3g}, moment {MARGIN * s['rt_zone_m']:.3g}, moment_untilted "
            f"{MARGIN * s['rt_zone_m0']:.3g}, p_max {MARGIN * s['rt_zone_p']:.3g}, tilt {MARGIN * s['rt_zone_t']:.3g}"),
        "end_zone_gap_over_length": f"{END_ZONE:g}",
        "runtime_error_edge_loaded": (
            f"depth {MARGIN * s['rt_edge_d']:.3g}, moment {MARGIN * s['rt_edge_m']:.3g}, moment_untilted "
            f"{MARGIN * s['rt_edge_m0']:.3g}, tilt {MARGIN * s['rt_edge_t']:.3g}"),
    }
    return s


def _span(a):
    a = a[np.isfinite(a)]
    if a.size == 0:
        return "not measured"
    return f"{a.min():.2f}-{a.max():.2f} ({a.size} cases)"


def figure(col, path):
    """docs/figures/roller_accuracy.png: |error| of the runtime and of ISO slicing
    against the BEM, per quantity, over the line load; hollow markers: edge loaded;
    grey crosses: the BEM's own grid change (its resolution)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    edge = col["bem_edge"] > 0
    free = col["free_tilt"] > 0
    tilted = (col["tilt"] != 0) & ~free
    # the middle panel: the moment at a given tilt, the tilt itself where it is free
    col = dict(col)
    for m in ("rt", "iso"):
        col[f"{m}_err_mt"] = np.where(free, col[f"{m}_err_tilt"], col[f"{m}_err_moment"])
    col["bem_change_mt"] = np.where(free, col["bem_change_tilt"], col["bem_change_moment"])
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.8), sharex=True)
    panels = [("err_depth", "change_depth", np.ones_like(edge), "deflection", 1.0),
              ("err_mt", "change_mt", tilted | free,
               "moment (given tilt) or tilt (zero moment)", 1.0),
              ("err_p_max", "change_p_max", ~edge, "peak pressure (off the ends)", 5.0)]
    markers = {1: "o", 2: "s", 3: "^", 4: "D", 5: "v", 6: "P", 7: "*"}
    models = (("iso", "C1", "ISO 16281 slicing"),       # drawn first: runtime on top
              ("rt", "C0", "runtime (coupled slices, 100)"))
    # spread the cases of one load sideways: profile and tilt
    shift = np.exp(0.04 * (col["profile"] - 3.5) + 20 * np.abs(col["tilt"]) * ~free)
    x = col["line_load"] / (ESTAR * DIAMETER) * shift
    floor = 1e-4
    for ax, (key, chg, mask, title, target) in zip(axes, panels):
        for m, colour, _ in models:
            err = np.maximum(100 * np.abs(col[f"{m}_{key}"]), floor)
            for code, mk in markers.items():
                for hollow in (False, True):
                    sel = mask & (col["profile"] == code) & (edge == hollow)
                    if sel.any():
                        ax.scatter(x[sel], err[sel], marker=mk, s=26, edgecolors=colour,
                                   facecolors="none" if hollow else colour,
                                   linewidths=0.9, zorder=3 if m == "rt" else 2)
        ax.scatter(x[mask], np.maximum(100 * np.abs(col[f"bem_{chg}"][mask]), floor),
                   marker="x", s=12, color="0.55", linewidths=0.7)
        ax.axhline(target, color="k", lw=0.8, ls="--")
        ax.set_xscale("log")
        ax.set_yscale("log")

        ax.set_title(title, fontsize=10)
        ax.set_xlabel("mean line load q/(E* D) [-]")
        ax.grid(True, which="major", lw=0.3, alpha=0.6)
    axes[0].set_ylabel(f"|error| against the 3D BEM [%] (floor {floor:g} %)")
    handles = [Line2D([], [], ls="", marker="o", color=c, label=lab) for _, c, lab in models]
    handles.append(Line2D([], [], ls="", marker="x", color="0.55",
                          label="BEM grid change (N to 2N)"))
    handles += [Line2D([], [], ls="", marker=mk, color="0.3", label=PROFILES[code])
                for code, mk in markers.items()]
    handles.append(Line2D([], [], ls="", marker="o", markerfacecolor="none",
                          markeredgecolor="0.3", label="edge loaded (hollow)"))
    fig.legend(handles=handles, loc="lower center", ncol=6, fontsize=8, frameon=False)
    fig.suptitle("Profiled and tilted rollers (D = 10 mm, L = 5-100 mm, tilt 0-3 mrad): "
                 "runtime model and ISO slicing against the 3D BEM; dashed: targets "
                 "1 %, 1 %, 5 %", fontsize=10)
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def run(args):
    from linecontact.tables import write_table

    tasks = study_tasks(args.n_x, args.n_y, args.tol, args.check_every, args.quick,
                        wide=not args.no_wide, wide_limit=args.wide_limit)
    t0 = time.perf_counter()
    old = None
    n_computed = len(tasks)
    if args.bem_from is not None:
        from linecontact.tables import read_table
        old = read_table(args.bem_from.stem, directory=args.bem_from.parent)
        refs = bem_from_table(tasks, old, args.n_x, args.n_y, args.tol,
                              args.check_every, missing_ok=True)
        todo = [t for t, r in zip(tasks, refs) if r is None]
        n_computed = len(todo)
        new = iter(run_study_from_args(run_case, todo, args, desc="roller study")
                   if todo else [])
        results = [dict(next(new), new=True) if r is None else compare_case(t, r)
                   for t, r in zip(tasks, refs)]
    else:
        results = run_study_from_args(run_case, tasks, args, desc="roller study")
    wall = time.perf_counter() - t0
    col = tabulate(tasks, results)
    s = summarise(col, tasks, results)
    accuracy = (
        f"BEM grid change (coarse to fine) off the ends: d {s['bem_off_d']:.1e}, "
        f"M {s['bem_off_m']:.1e}, p_max {s['bem_off_p']:.1e}; edge loaded: d "
        f"{s['bem_edge_d']:.1e}, M {s['bem_edge_m']:.1e}; all cases: dF/dd "
        f"{s['bem_k']:.1e}, dM/dtheta {s['bem_kt']:.1e} (flat and tilted punch on "
        "the staircase contact set); observed orders "
        f"{s['orders']} (from three grids; they scatter where the changes are "
        "1e-5-1e-4, at the staircase contact boundary's level)")
    wall_line = (wall_time_line(wall, results, "cases", args.scheduler, args.workers)
                 + f"; the per-case times sum to {s['case_seconds']:.0f} s")
    reuse = {}
    if old is not None:
        # the BEM columns are the earlier table's where it had the case: its accuracy
        # line (the observed orders are not columns) and its provenance and time
        reuse["bem_from"] = bem_from_line(old.meta, args.bem_from.name)
        if n_computed:
            from .runner import code_version
            import datetime
            sets = sorted({t.get("case_set", 0) for t, r in zip(tasks, refs) if r is None})
            reuse["bem_from"] = (
                f"rows of case_set {', '.join(str(k) for k in sets)}: the bem_* columns "
                "computed by '"
                + re.sub(r"--(checkpoint|out|figure)[ =]\S+", r"--\1 DIR", args.command_line)
                + f"', {code_version()}, "
                f"{datetime.date.today().isoformat()} ({n_computed} cases; {wall:.0f} s "
                "in this run, the checkpoints of earlier runs not counted); the other "
                f"rows: {reuse['bem_from']}")
        if n_computed == 0:
            accuracy = old.meta["accuracy"]
            wall_line = (f"{wall:.1f} s for the runtime and ISO slicing columns of "
                         f"{len(tasks)} cases in one process (the BEM columns reused: "
                         "bem_from)")
        else:
            accuracy = (accuracy + f" (all {len(tasks)} cases; the observed orders of "
                        f"the {n_computed} computed in this run); the reused cases' "
                        f"own line: {old.meta['accuracy']}")
            wall_line = (wall_time_line(wall, [r for r in results if r.get("new")],
                                        "cases' BEM", args.scheduler, args.workers)
                         + f" and the runtime and ISO slicing of all {len(tasks)} cases "
                         f"({len(tasks) - n_computed} BEM references reused: bem_from)")
    units = ", ".join(f"{k} [{u}]" for k, u in COLUMNS_UNITS.items())
    meta = table_meta(
        args.command_line,
        title="Accuracy of the runtime profiled-roller model (linecontact.roller) and of "
              "ISO 16281 slicing against a 3D boundary-element solution",
        source="computed: tools/bem/roller.py (Love's rectangle coefficients, free-space "
               "DC-FFT, Polonsky-Keer CG, Newton on the approach at the given force and "
               "tilt) against linecontact.roller",
        units=units,
        columns="profile codes: " + ", ".join(f"{k} = {v}" for k, v in PROFILES.items())
                + "; *_edge = 1 where the contact reaches a roller end (BEM: an end cell "
                  "on either grid); rt_end_gap: the runtime contact's distance from the "
                  "nearer roller end over L; err_depth = (d - d_bem)/delta_bem with delta_bem = "
                  "max_x (d + theta x - P(x)); err_moment = M/M_bem - 1 (given tilt "
                  "!= 0), (M - M_bem)/(F L/2) (tilt 0 or free); free_tilt = 1: the tilt is "
                  "solved for zero moment (tilt column: the BEM's), err_tilt = "
                  "theta/theta_bem - 1 there (0 elsewhere); err_p_max = p/p_bem - 1 (a grid-"
                  "dependent singular end peak on edge-loaded rows: not a physical "
                  "number); bem_change_* = BEM change from the coarser to the finer grid "
                  "(depth over delta, moment over |M| or F L/2, tilt over the tilt, "
                  "stiffnesses relative); err_stiffness, err_tilt_stiffness = k/k_bem - 1 "
                  "for dF/dd at fixed tilt and dM/dtheta at fixed d, the BEM's from the "
                  "flat and tilted rigid punch on its contact set; crown_radius: the "
                  "circular crown's Rc (unused by the other profiles); case_set: "
                  + ", ".join(f"{k} = {v}" for k, v in CASE_SETS.items())
                  + "; rt_bound_* = |rt_err_*| + |bem_change_*|: the runtime's error "
                  "bound against a converged 3D solution (the finer grid's own error "
                  "taken as at most its change from the coarser one, the Richardson "
                  "estimate change/(2^p - 1) at an observed order p >= 1)",
        cases=f"D = {DIAMETER * 1e3:g} mm, E* = {ESTAR / 1e9:g} GPa; dense set: L = 14 mm: profiles "
              f"1-5 at the tilts below and the offset crown (x0 = {CROWN_OFFSET * 1e3:g} "
              f"mm, zero moment: theta = -x0/Rc) and an asymmetric crown (Rc = "
              f"{CROWN_RADII_ASYM[0] * 1e3:g} mm for x < 0, {CROWN_RADII_ASYM[1] * 1e3:g} mm "
              f"for x > 0, a 2001-point user table; zero moment), L = 30 mm: iso16281; crown radius {CROWN_RADIUS * 1e3:g} mm; "
              f"Lundberg and Johns-Gohar designed for F0/L = {DESIGN_LINE_LOAD / 1e3:g} "
              f"N/mm; end relief: {RELIEF['relief_fraction']:g} L at each end, tangent "
              f"corner radius {RELIEF['corner_radius'] * 1e3:g} mm; line loads "
              f"{', '.join(f'{q / 1e3:g}' for q in LINE_LOADS)} N/mm; tilts "
              f"{', '.join(f'{t * 1e3:g}' for t in TILTS)} mrad"
              + ("" if args.no_wide else
                 f"; wide set (case_set 1): L/D "
                 f"{', '.join(f'{v:g}' for v in WIDE_L_OVER_D)} x mean line load q/(E* D) "
                 f"{', '.join(f'{v:g}' for v in WIDE_LINE_LOADS_OVER_ESTAR_D)} x profiles "
                 "1-5 (the same designs; the crown radius CROWN_RADIUS (L/14 mm)^2 within "
                 f"{WIDE_CROWN_RADII[0] * 1e3:g}-{WIDE_CROWN_RADII[1] * 1e3:g} mm), the tilt "
                 f"cycling through {', '.join(f'{t * 1e3:g}' for t in WIDE_TILTS)} mrad with "
                 "the L/D, load and profile indices"),
        grid=f"per case an adapted window (contact box x 1.25, |y| <= 1.25 b) with "
             f"{args.n_x} x {args.n_y} and {2 * args.n_x} x {2 * args.n_y} cells; the "
             f"finer grid is the reference; every {args.check_every}th case also on "
             f"{4 * args.n_x} x {4 * args.n_y}; where a logarithmic profile's contact "
             f"comes within two cells of a roller end ({s['n_end']} cases) the same "
             f"window: p_max, its place, the contact's extent and depth and moment "
             f"(depth control at the finer grid's depth and tilt, corrected to the force "
             f"to first order) from {END_GRIDS[0][0]} x {END_GRIDS[0][1]} and "
             f"{END_GRIDS[1][0]} x {END_GRIDS[1][1]} cells instead (bem_nx, bem_ny), no "
             "third grid; a wide-set case whose change from the coarser to the finer grid "
             f"exceeds {REFINE['p_max']:g} in peak pressure (off the ends), "
             f"{REFINE['depth']:g} delta in depth or {REFINE['moment']:g} in moment "
             f"({int(np.sum(col['bem_nx'] == 4 * args.n_x))} cases) takes "
             f"{4 * args.n_x} x {4 * args.n_y} as its reference and "
             f"{2 * args.n_x} x {2 * args.n_y} as its coarser grid",
        tolerance=f"{args.tol:g} (gap error / largest interference); force 1e-6 F; "
                  "moment 1e-6 F L/2",
        accuracy=accuracy,
        runtime_settings=runtime_settings(),
        runtime_error=f"largest bound |error| + |BEM grid change| (rt_bound_*; the "
                      f"runtime_error_* fields state {MARGIN:g} times these), by the "
                      f"runtime's own edge flag: off the ends ({s['n_rt_off']} cases): deflection "
                      f"{s['rt_off_d']:.2%}, moment {s['rt_off_m']:.2%} (tilted), "
                      f"{s['rt_off_m0']:.1e} F L/2 (untilted), peak pressure "
                      f"{s['rt_off_p']:.2%} (where the BEM's contact is off the ends too; "
                      f"{s['n_flag_differ']} cases off the ends for the runtime reach an "
                      f"end cell of the BEM), zero-moment tilt {s['rt_off_t']:.2%} (the "
                      f"contact clear of the end zone: {END_ZONE / 2:g} L or more from a "
                      "roller end where the drop is infinite); in the end zone (within "
                      f"{2 * END_ZONE:g} L of such an end, {s['n_zone']} cases): deflection "
                      f"{s['rt_zone_d']:.2%}, moment {s['rt_zone_m']:.2%} (tilted), peak "
                      f"pressure {s['rt_zone_p']:.2%}; edge "
                      f"loaded ({s['n_rt_edge']} cases): deflection {s['rt_edge_d']:.2%}, "
                      f"moment {s['rt_edge_m']:.2%}, tilt {s['rt_edge_t']:.2%}; all cases: "
                      f"dF/dd {s['rt_k']:.2%}, dM/dtheta {s['rt_kt']:.2%}; off the ends "
                      f"by L/D: {s['bands']}",
        iso_error=f"largest |error| off the ends: deflection {s['iso_off_d']:.2%}, moment "
                  f"{s['iso_off_m']:.2%}, peak pressure {s['iso_off_p']:.2%}, zero-moment "
                  f"tilt {s['iso_off_t']:.2%}; edge loaded: deflection "
                  f"{s['iso_edge_d']:.2%}, moment {s['iso_edge_m']:.2%}, tilt "
                  f"{s['iso_edge_t']:.2%}; all cases: dF/dd {s['iso_k']:.2%}, dM/dtheta "
                  f"{s['iso_kt']:.2%}",
        covered=s["range"],
        **s["covered_fields"],
        **reuse,
        wall_time=wall_line + "; median per case: BEM "
                  f"{s['bem_seconds']:.2f} s (both grids, wall), runtime solve "
                  f"{s['rt_seconds'] * 1e3:.1f} ms wall, {s['rt_cpu_seconds'] * 1e3:.1f} ms "
                  "CPU",
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "roller_accuracy.csv"
    write_table(path, meta, col)
    print(f"wrote {path}: {len(tasks)} cases in {wall:.0f} s")
    for k in ("accuracy", "runtime_error", "iso_error", "wall_time"):
        print(f"  {k}: {meta[k]}")
    if args.figure:
        print(f"wrote {figure(col, Path(args.figure))}")
    return 0
