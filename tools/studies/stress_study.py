"""Accuracy of the runtime slice stresses (linecontact.stresses) against a 3D field.

Writes tables/stress_accuracy.csv (``python -m tools.build_tables stress``).

Per case (a roller, a profile, a force F, a tilt theta; nu = 0.3; friction 0 and, on
the fine grid, the traction mu p in +y with mu = 0.1 and 0.2):

1. The reference: the 3D boundary-element pressure of tools.bem.roller at F and theta
   (``solve_roller_force``) on an adapted window with ``n_x`` x ``n_y`` cells and on
   twice as many in each direction on the same window (tools.bem.roller
   .grid_convergence); below each pressure the 3D stress field of tools.bem.stress
   (Love's rectangle, one DC-FFT per component and depth plane) on depth planes
   z/b = 0.1, 0.2, ..., 1.2 (b the BEM's largest contact half-width); the maximum
   of each measure (Tresca, von Mises, orthogonal shear |tau_yz|) over the cells of
   each plane, refined in depth by a parabola through the best plane and its two
   neighbours. The fine grid is the reference; the change from the coarse one is its
   stated resolution (``bem_change_*``).
2. The runtime: linecontact.roller.ProfiledRoller (default settings: 50 slices since
   issue 20's fourth round, 100 before) at the same F and
   theta, then linecontact.stresses.roller_stresses: the worst of each measure over the
   roller, and the wall/CPU time of the stresses against that of the contact solve.
3. Errors: value/value_3D - 1 per measure (``err_*``) and the depth difference over b
   (``dz_*``). Edge-loaded cases (the contact reaches a roller end cell on either BEM
   grid) carry a singular end pressure: the 3D maxima there sit at the end and depend
   on the grid (their change is printed), so their error is stated apart.

4. The stated errors are bounds: |rt/bem - 1| + |bem_change| (the finer grid's own
   error bounded by its change from the coarser one), the traction cases' change
   from their own fields on both grids.

Cases: the roller study's rollers and profiles (tools/studies/roller_study.py; D =
10 mm, E* = 115.385 GPa): the dense set, L = 14 mm with the circular crown, ISO/TS
16281, Lundberg's, Johns-Gohar's and straight-with-end-relief profiles, L = 30 mm with
the ISO profile; line loads 100, 800 and 2000 N/mm; tilts 0 and 2 mrad: 36 cases; and
every WIDE_EVERY-th case of the roller study's wide set (issue 32: L/D 0.5-12,
q/(E* D) 3e-6-3e-3, tilts 0-3 mrad; each L/D, load, profile and tilt at least once):
34 cases; and the relief set (issue 32: straight rollers with a corner-radius end
relief, drawn as tools/studies/population_study.py draws the rollers of cylindrical
and needle roller bearings and cam followers at 2-50 % of their ratings, seed 7,
RELIEF_SET): 36 cases. The end relief's stated errors are apart (``error_*.end-relief``:
the pressure's local peak at the junction of the straight part and the corner
radius is narrow: on cam-follower rings whose corner radius is about their own radius
the reference changes by up to 2.8 % between its grids and the orthogonal shear with
friction is up to 6 % high, where the other profiles' bounds are within 1.2 %). ``--quick``: 6 dense, 4 wide
and 3 relief. Friction to 0.4 (FRICTIONS): from mu = 0.25 the largest shear may sit at
the surface, where the reference is the exact surface field of its cells
(tools.bem.stress.StressField.surface, SURFACE_FRICTION); the stated errors above
mu = 0.2 are a class of their own (HIGH_FRICTION_ABOVE).

Budget: see the table's ``wall_time`` header (1 worker process).
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from linecontact.roller.slices import DEFAULT_N_SLICES

from ..bem.roller import grid_convergence, solve_roller_force
from ..bem.stress import MEASURES, StressField
from .roller_study import (DIAMETER, ESTAR, RELIEF, ROLLERS, add_grid_arguments,
                           task_profile, wide_tasks)
from .runner import add_runner_arguments, run_study_from_args, table_meta, wall_time_line

REPO = Path(__file__).resolve().parents[2]

POISSON = 0.3
LINE_LOADS = (1e5, 8e5, 2e6)          #: [N/m]
TILTS = (0.0, 2e-3)                   #: [rad]
PROFILES = {1: "circular crown", 2: "iso16281", 3: "lundberg", 4: "johns-gohar",
            5: "straight with end relief"}
#: the runtime profile keys (linecontact.profiles) of the study's profiles
PROFILE_KEYS = ("circular", "iso16281", "lundberg", "johns-gohar", "end-relief")
CODES = {v: k for k, v in PROFILES.items()}
DEPTHS_OVER_B = np.round(np.arange(0.10, 1.2001, 0.10), 4)
#: sliding friction of the traction cases (both grids; the traction mu p in +y)
FRICTIONS = (0.1, 0.2, 0.3, 0.4)
#: the stated errors with friction come in two classes: up to this friction
#: (error_3d_friction_*, over mu = 0.1, 0.2) and above it, to the largest of FRICTIONS
#: (error_3d_high_friction_*, over mu = 0.2, 0.3, 0.4), where the largest shear
#: reaches the surface and the runtime keeps the strip's plane-strain value there
HIGH_FRICTION_ABOVE = 0.2
#: friction from which the traction cases' maxima include the surface z = 0
#: (tools.bem.stress.StressField.surface: closed forms, exact for the cells, local
#: terms included). McEwen's plane-strain Tresca maximum reaches the surface at
#: mu = 0.25 (nu = 0.3; linecontact.stresses.strip_maxima), von Mises and |tau_yz| at
#: 0.3-0.4; at 0.2 the surface Tresca is 0.304 p0 against 0.319 p0 below it.
#: Checked (tests/test_stress_bem.py): on a long strip the surface Tresca and von
#: Mises maxima converge to McEwen's at first order in the cell size, -0.22 %,
#: -0.11 %, -0.053 % (mu = 0.4) and -0.12 %, -0.068 %, -0.031 % (mu = 0.3) with 32,
#: 64, 128 cells across the contact. It costs about one frictionless depth plane (a
#: quarter of a plane with the traction; D = 10, L = 14 mm, Rc 500 mm, 800 N/mm: 0.010
#: s against 0.041 s on 128 x 32 cells, 0.051 s against 0.151 s on 256 x 64), some 2 %
#: of a case's field time. From 0.1 it would leave the mu = 0.1, 0.2 maxima of 4 of 5
#: dense cases tried as they are, and move those of the edge-loaded circular crown at
#: 2000 N/mm, 2 mrad by +1 to +2 % (a maximum on the first plane, then bracketed by
#: the surface).
#: It replaces two planes at z/b = 0.01, 0.02 extrapolated to z = 0, each costing 4-12
#: times a deeper plane (the traction's cells cut into sub-cells of z/2), whose surface
#: Tresca at mu = 0.4 was off by +1.3 % (coarse) and +3.5 % (fine) on that roller.
#: Measured on that roller at mu = 0.4: the surface maxima change coarse to fine by
#: +0.36 % (Tresca), +0.12 % (von Mises), +0.08 % (|tau_yz|); they lie 2.7 % below
#: the runtime's (plane strain at the surface), a 3D effect of the finite contact (on
#: a uniform strip 36 b long the surface maxima are 2.3 % (Tresca) and 1.5 % (von
#: Mises) below McEwen's, falling as b/L)
SURFACE_FRICTION = 0.25
#: the stated errors (error_* and slice_error_* fields, read by linecontact.accuracy)
#: are the largest bound over the cases times this margin (the roller study's MARGIN:
#: the cases sample the range; the population check tests them off the grid)
MARGIN = 1.5
#: the last full run's time (1 worker, the shared 2-core VM), quoted in the header
#: of a table rebuilt from its checkpoints
STUDY_WALL = ("209 s for 106 cases with 1 worker (local dask cluster; the population "
              "check ran beside it on the 2-core VM), 2026-11-29")
#: every k-th case of the roller study's wide set (tools.studies.roller_study.wide_tasks)
WIDE_EVERY = 6
#: the relief set: end-relief rollers drawn as the population check draws them
#: (tools.studies.population_study.population_tasks with the profile fixed): per
#: family (cylindrical, needle, cam follower) and the draw's seed, other than the
#: population check's (32), which then tests the stated errors off these cases
RELIEF_SET = dict(per_family=12, seed=7)
#: the relief set's coarser BEM grid (the finer: twice each): the population check's.
#: On the study's 64 x 32 / 128 x 64 the reference's own change between the grids
#: reached 3-7 % below the narrow pressure peak at the relief's junction, and that
#: change enters each stated error
RELIEF_GRID = (128, 32)
#: the profile whose stress errors are stated apart (error_*.end-relief fields): at the
#: junction of the straight part and its corner radius the pressure has a narrow local
#: peak: on the relief set's cam-follower rings the reference changes by up to 2.8 %
#: between its grids and the orthogonal shear with friction is up to 6 % high (the
#: other profiles' bounds: within 1.2 %)
APART = "end-relief"


def relief_tasks(n_x=RELIEF_GRID[0], n_y=RELIEF_GRID[1], tol=1e-7,
                 per_family=RELIEF_SET["per_family"], seed=RELIEF_SET["seed"]):
    """The relief set (case_set 2): straight rollers with a corner-radius end relief of
    cylindrical and needle roller bearings and cam followers, drawn as the population
    check draws its rollers (relief 0.1-0.2 L, corner radius 20-100 mm, 2-50 % of the
    rating, tilts to 3 mrad; tools.studies.population_study), on the contact's
    effective radius; on RELIEF_GRID."""
    from .population_study import population_tasks

    out = []
    for t in population_tasks(per_family, seed, profile="end-relief"):
        kw = t["profile_kw"]
        out.append(dict(key=f"R{seed}-{t['key']}", roller=t["family"],
                        profile=PROFILES[5], radius=t["radius"], length=t["length"],
                        estar=t["estar"], force=t["force"], tilt=t["tilt"],
                        relief=dict(relief_fraction=kw["relief_length"] / t["length"],
                                    corner_radius=kw["corner_radius"]),
                        n_x=n_x, n_y=n_y, tol=tol, case_set=2))
    return out


def study_tasks(n_x=128, n_y=32, tol=1e-7, quick=False, wide=True, relief=True):
    """The cases (picklable dicts with a unique 'key'): the dense set and, with `wide`,
    every WIDE_EVERY-th case of the roller study's wide set (L/D 0.5-12, q/(E* D)
    1e-5-3e-3, tilts 0-3 mrad; each L/D and load at least once), and with `relief`
    the relief set (:func:`relief_tasks`; ``quick``: 1 per family)."""
    combos = [("A", PROFILES[k]) for k in range(1, 6)] + [("B", "iso16281")]
    loads = LINE_LOADS[::2] if quick else LINE_LOADS
    tilts = TILTS[::2] if quick else TILTS
    if quick:
        combos = combos[:3]
    tasks = []
    for roller, prof in combos:
        L = ROLLERS[roller]
        for q in loads:
            for th in tilts:
                tasks.append(dict(key=f"{roller}-{prof.replace(' ', '_')}-q{q / 1e3:g}"
                                      f"-t{th * 1e3:g}",
                                  roller=roller, profile=prof, radius=DIAMETER / 2,
                                  length=L, estar=ESTAR, force=q * L, tilt=th, n_x=n_x,
                                  n_y=n_y, tol=tol, case_set=0))
    if wide:
        tasks += wide_tasks(n_x, n_y, tol, quick)[::WIDE_EVERY]
    if relief:
        tasks += relief_tasks(tol=tol, **(dict(per_family=1) if quick else {}))
    return tasks


def field_maxima(res, depths_over_b=DEPTHS_OVER_B, poisson=POISSON, frictions=(0.0,)):
    """Maxima of the three measures of the 3D field below a BEM result's pressure and,
    for mu > 0, the traction mu p in +y: friction -> measure -> dict(value [Pa],
    x [m], y [m], z [m]); planes z = depths_over_b * b."""
    from ..bem.stress import measures
    g = res.grid
    b = res.half_width
    f = StressField(g.nx, g.ny, g.dx, g.dy, poisson, workers=1)
    zs = depths_over_b * b
    trac = any(mu > 0 for mu in frictions)
    per = {mu: {m: [] for m in MEASURES} for mu in frictions}
    surf = {}
    if any(mu >= SURFACE_FRICTION for mu in frictions):
        # the traction cases' surface z = 0, exact for the cells (tools.bem.stress
        # .StressField.surface: closed forms, local terms included)
        N, T = f.surface(res.pressure, traction=res.pressure)
        for mu in frictions:
            if mu < SURFACE_FRICTION:
                continue
            ms = measures({c: N[c] + mu * T[c] for c in N})
            surf[mu] = {}
            for m in MEASURES:
                k = int(np.argmax(ms[m]))
                i, j = np.unravel_index(k, ms[m].shape)
                surf[mu][m] = dict(value=float(ms[m].flat[k]), i=int(i), j=int(j))
    for z in zs:
        out = f.plane(res.pressure, z, traction=res.pressure if trac else None)
        N, T = out if trac else (out, None)
        for mu in frictions:
            fld = N if mu == 0 else {c: N[c] + mu * T[c] for c in N}
            ms = measures(fld)
            for m in MEASURES:
                k = int(np.argmax(ms[m]))
                i, j = np.unravel_index(k, ms[m].shape)
                per[mu][m].append(dict(value=float(ms[m].flat[k]), i=int(i), j=int(j)))
    res_out = {}
    x, y = g.x, g.y
    for mu in frictions:
        out = {}
        for m in MEASURES:
            v = np.array([p["value"] for p in per[mu][m]])
            k = int(np.argmax(v))
            zk, vk = zs[k], v[k]
            sm = surf.get(mu, {}).get(m)
            # with the surface computed one spacing above the first plane, a maximum
            # on the first plane is bracketed by the surface and the second plane
            above = (sm["value"] if sm is not None and len(zs) > 1
                     and np.isclose(zs[0], zs[1] - zs[0]) else None)
            # (bracketed only where the surface is no higher than the first plane: a
            # parabola through a higher surface would put its vertex above it)
            if 0 < k < len(zs) - 1 or (k == 0 and above is not None and above <= vk):
                # parabola through planes k-1 (or the surface), k, k+1 (spacing h)
                h = zs[1] - zs[0]
                a, c = (v[k - 1] if k > 0 else above), v[k + 1]
                den = a - 2 * vk + c
                if den < 0:
                    s = 0.5 * (a - c) / den
                    zk = zs[k] + s * h
                    vk = vk - 0.25 * (a - c) * s
            out[m] = dict(value=float(vk), z=float(zk), x=float(x[per[mu][m][k]["i"]]),
                          y=float(y[per[mu][m][k]["j"]]), plane=k, n_planes=len(zs))
            if sm is not None and sm["value"] > vk:
                # at the surface (plane -1: the surface z = 0, no bracket needed)
                out[m] = dict(value=sm["value"], z=0.0, x=float(x[sm["i"]]),
                              y=float(y[sm["j"]]), plane=-1, n_planes=len(zs))
        res_out[mu] = out
    return res_out


def bem_case(task):
    """The 3D references of one case on the two nested grids."""
    t0 = time.perf_counter()
    prof = task_profile(task)
    g = grid_convergence(solve_roller_force, task["radius"], task["length"],
                         task["estar"], task["force"], tilt=task["tilt"], profile=prof,
                         n_x=task["n_x"], n_y=task["n_y"], tol=task["tol"], workers=1,
                         fields=True)
    c, f = g["coarse"], g["fine"]
    t1 = time.perf_counter()
    mc = field_maxima(c, frictions=(0.0,) + FRICTIONS)
    mf = field_maxima(f, frictions=(0.0,) + FRICTIONS)
    return dict(fine=mf[0.0], coarse=mc[0.0], fine_friction=mf, coarse_friction=mc, edge=bool(c.edge_loaded or f.edge_loaded),
                half_width=f.half_width, p_max=f.p_max, nx=f.grid.nx, ny=f.grid.ny,
                contact_seconds=t1 - t0, field_seconds=time.perf_counter() - t1)


def runtime_case(task, n_slices=None):
    """The runtime model and its stresses (strips alone and 3D-corrected, without and
    with friction), with the wall and CPU times of the solve and the 3D-corrected
    frictionless stresses."""
    from linecontact.roller import ProfiledRoller
    from linecontact.stresses import reaches_end, roller_stresses
    prof = task_profile(task)
    model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof,
                           **({} if n_slices is None else {"n_slices": n_slices}))
    t0, c0 = time.perf_counter(), time.process_time()
    sol = model.at_force(task["force"], tilt=task["tilt"])
    t1, c1 = time.perf_counter(), time.process_time()
    s = roller_stresses(sol, 0.0, POISSON)
    t2, c2 = time.perf_counter(), time.process_time()
    fr = {mu: roller_stresses(sol, mu, POISSON).worst for mu in FRICTIONS}
    return dict(worst=s.worst, strip=s.strip_worst, friction=fr, edge=reaches_end(sol),
                solve_seconds=t1 - t0, solve_cpu=c1 - c0, stress_seconds=t2 - t1,
                stress_cpu=c2 - c1)


def run_case(task):
    """One case: the 3D references, the runtime and the errors (module docstring)."""
    ref = bem_case(task)
    rt = runtime_case(task)
    b = ref["half_width"]
    out = dict(bem_edge=ref["edge"], rt_edge=rt["edge"], bem_half_width=b,
               bem_p_max=ref["p_max"], bem_nx=ref["nx"], bem_ny=ref["ny"],
               bem_contact_seconds=ref["contact_seconds"],
               bem_field_seconds=ref["field_seconds"],
               rt_solve_seconds=rt["solve_seconds"], rt_solve_cpu=rt["solve_cpu"],
               rt_stress_seconds=rt["stress_seconds"], rt_stress_cpu=rt["stress_cpu"])
    for m in MEASURES:
        f, c, r, st = ref["fine"][m], ref["coarse"][m], rt["worst"][m], rt["strip"][m]
        out.update({f"bem_{m}": f["value"], f"bem_z_{m}": f["z"], f"bem_x_{m}": f["x"],
                    f"bem_change_{m}": f["value"] / c["value"] - 1,
                    f"bem_at_plane_edge_{m}": float(f["plane"] in (0, f["n_planes"] - 1)),
                    f"rt_{m}": r["value"], f"rt_z_{m}": r["z"], f"rt_x_{m}": r["x"],
                    f"err_{m}": r["value"] / f["value"] - 1,
                    f"dz_{m}": (r["z"] - f["z"]) / b,
                    f"strip_{m}": st["value"], f"err_strip_{m}": st["value"] / f["value"] - 1})
        for mu in FRICTIONS:
            fm, rm = ref["fine_friction"][mu][m], rt["friction"][mu][m]
            tag = f"mu{int(round(mu * 10))}"
            cm = ref["coarse_friction"][mu][m]
            out.update({f"bem_{tag}_{m}": fm["value"], f"rt_{tag}_{m}": rm["value"],
                        f"err_{tag}_{m}": rm["value"] / fm["value"] - 1,
                        f"bem_change_{tag}_{m}": fm["value"] / cm["value"] - 1})
    return out


def add_arguments(parser):
    add_grid_arguments(parser)
    parser.add_argument("--quick", action="store_true", help="a smoke run: 6 dense "
                        "cases, 4 of the wide set and 3 of the relief set")
    parser.add_argument("--no-wide", action="store_true",
                        help="the dense set only (L = 14, 30 mm)")
    parser.add_argument("--no-relief", action="store_true",
                        help="without the relief set (drawn end-relief rollers)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for stress_accuracy.csv (default tables/)")
    add_runner_arguments(parser)


def _units():
    u = {"roller_length": "m", "radius": "m", "relief_fraction": "-",
         "corner_radius": "m", "profile": "-", "force": "N", "line_load": "N/m",
         "tilt": "rad", "bem_edge": "-", "rt_edge": "-", "bem_half_width": "m",
         "bem_p_max": "Pa", "bem_nx": "-", "bem_ny": "-"}
    for m in MEASURES:
        u.update({f"bem_{m}": "Pa", f"bem_z_{m}": "m", f"bem_x_{m}": "m",
                  f"bem_change_{m}": "-", f"bem_at_plane_edge_{m}": "-", f"rt_{m}": "Pa",
                  f"rt_z_{m}": "m", f"rt_x_{m}": "m", f"err_{m}": "-", f"dz_{m}": "-",
                  f"strip_{m}": "Pa", f"err_strip_{m}": "-"})
        for mu in FRICTIONS:
            tag = f"mu{int(round(mu * 10))}"
            u.update({f"bem_{tag}_{m}": "Pa", f"rt_{tag}_{m}": "Pa", f"err_{tag}_{m}": "-",
                      f"bem_change_{tag}_{m}": "-"})
    u.update({"case_set": "-", "crown_radius": "m", "bem_contact_seconds": "s",
              "bem_field_seconds": "s",
              "rt_solve_seconds": "s", "rt_solve_cpu": "s", "rt_stress_seconds": "s",
              "rt_stress_cpu": "s"})
    return u


def tabulate(tasks, results):
    units = _units()
    col = {k: [] for k in units}
    for t, r in zip(tasks, results):
        rel = t.get("relief", RELIEF) if t["profile"] == PROFILES[5] else None
        row = dict(roller_length=t["length"], radius=t["radius"],
                   relief_fraction=rel["relief_fraction"] if rel else 0.0,
                   corner_radius=rel["corner_radius"] if rel else 0.0,
                   profile=CODES[t["profile"]],
                   force=t["force"], line_load=t["force"] / t["length"], tilt=t["tilt"],
                   case_set=t.get("case_set", 0),
                   crown_radius=t.get("crown_radius", 0.5))
        row.update(r)
        for k in units:
            col[k].append(float(row[k]))
    return {k: np.array(v) for k, v in col.items()}


def summarise(col, rows=None):
    """The largest bounds (off the ends, edge loaded; frictionless, with friction, the
    strips alone) over the cases where `rows` (a mask; default every case)."""
    if rows is not None:
        col = {k: v[rows] for k, v in col.items()}
    # edge loaded: on either BEM grid, or by the runtime's own flag (its contact within
    # half a slice of an end: what the runtime can know and states per result)
    edge = (col["bem_edge"] > 0) | (col["rt_edge"] > 0)
    s = {"n_off": int((~edge).sum()), "n_edge": int(edge.sum())}
    for m in MEASURES:
        e = np.abs(col[f"err_{m}"])
        ch = np.abs(col[f"bem_change_{m}"])
        dz = np.abs(col[f"dz_{m}"])
        # the stated errors are bounds: |rt/bem - 1| + |BEM grid change| (the finer
        # grid's own error at most its change from the coarser one, order >= 1)
        e = e + ch
        s[f"off_{m}"] = float(e[~edge].max()) if (~edge).any() else float("nan")
        s[f"edge_{m}"] = float(e[edge].max()) if edge.any() else float("nan")
        s[f"ch_off_{m}"] = float(ch[~edge].max()) if (~edge).any() else float("nan")
        s[f"ch_edge_{m}"] = float(ch[edge].max()) if edge.any() else float("nan")
        s[f"dz_off_{m}"] = float(dz[~edge].max()) if (~edge).any() else float("nan")
        es = np.abs(col[f"err_strip_{m}"]) + ch
        s[f"strip_off_{m}"] = float(es[~edge].max()) if (~edge).any() else float("nan")
        s[f"strip_edge_{m}"] = float(es[edge].max()) if edge.any() else float("nan")
        for tag, mus in (("fr", [mu for mu in FRICTIONS if mu <= HIGH_FRICTION_ABOVE]),
                         ("hf", [mu for mu in FRICTIONS if mu >= HIGH_FRICTION_ABOVE])):
            ef = np.max([np.abs(col[f"err_mu{int(round(mu * 10))}_{m}"])
                         + np.abs(col[f"bem_change_mu{int(round(mu * 10))}_{m}"])
                         for mu in mus], axis=0)
            s[f"{tag}_off_{m}"] = float(ef[~edge].max()) if (~edge).any() else float("nan")
            s[f"{tag}_edge_{m}"] = float(ef[edge].max()) if edge.any() else float("nan")
    ratio = col["rt_stress_cpu"] / col["rt_solve_cpu"]
    s["time_ratio_median"] = float(np.median(ratio)) if ratio.size else float("nan")
    s["time_ratio_max"] = float(ratio.max()) if ratio.size else float("nan")
    return s


def run(args):
    from linecontact.tables import write_table

    tasks = study_tasks(args.n_x, args.n_y, args.tol, args.quick, wide=not args.no_wide,
                        relief=not args.no_relief)
    t0 = time.perf_counter()
    results = run_study_from_args(run_case, tasks, args, desc="stress study")
    wall = time.perf_counter() - t0
    wall_line = wall_time_line(wall, results, "cases", args.scheduler, args.workers,
                               measured=STUDY_WALL)
    results = [{k: v for k, v in r.items() if k != "resumed"} for r in results]
    col = tabulate(tasks, results)
    # the error_* fields: over the dense and wide sets (every profile, as before the
    # relief set); the error_*.end-relief fields: over every end-relief case, the
    # relief set's included, and never below the former
    s = summarise(col, rows=col["case_set"] != 2)
    relief = col["profile"] == CODES[PROFILES[5]]
    sa = summarise(col, rows=relief)
    units = ", ".join(f"{k} [{u}]" for k, u in _units().items())
    # the covered ranges: those of the dense and wide sets, over which the all-profile
    # errors are stated (the relief set, inside them, adds the end relief's own)
    D = 2 * col["radius"]          # the contact's effective radius, doubled
    qn = col["line_load"] / (ESTAR * D)
    ldn = col["roller_length"] / D
    base = col["case_set"] != 2
    lo, hi = float(qn[base].min()), float(qn[base].max())
    ld = [float(ldn[base].min()), float(ldn[base].max())]
    tmax = float(np.max(np.abs(col["tilt"][base])))
    outside = ((qn < lo) | (qn > hi) | (ldn < ld[0]) | (ldn > ld[1])
               | (np.abs(col["tilt"]) > tmax)) & ~base
    if outside.any():
        raise ValueError(f"{int(outside.sum())} relief-set cases lie outside the dense and "
                         "wide sets' range (L/D, q/(E* D), tilt): their errors would "
                         "cover a range the other profiles were not measured in")
    rc = col["corner_radius"][relief] / col["radius"][relief]
    rf = col["relief_fraction"][relief]

    def errs(prefix, s=s):
        return ", ".join(f"{m} {s[f'{prefix}_{m}']:.3g}" for m in MEASURES)

    def stated(prefix):
        """(the all-profile field, the end-relief field) of one class, MARGIN times
        the largest bound"""
        whole = {m: MARGIN * s[f"{prefix}_{m}"] for m in MEASURES}
        apart = {m: max(whole[m], MARGIN * sa[f"{prefix}_{m}"]) for m in MEASURES}
        return tuple(", ".join(f"{m} {v[m]:.3g}" for m in MEASURES)
                     for v in (whole, apart))

    fields = {}
    for key, prefix in (("error_3d_off_ends", "off"), ("error_3d_edge_loaded", "edge"),
                        ("error_3d_friction_off_ends", "fr_off"),
                        ("error_3d_friction_edge_loaded", "fr_edge"),
                        ("error_3d_high_friction_off_ends", "hf_off"),
                        ("error_3d_high_friction_edge_loaded", "hf_edge"),
                        ("slice_error_off_ends", "strip_off"),
                        ("slice_error_edge_loaded", "strip_edge")):
        fields[key], fields[f"{key}.{APART}"] = stated(prefix)

    meta = table_meta(
        args.command_line,
        title="Accuracy of the runtime roller stresses (linecontact.stresses.roller_stresses: "
              "slice strips with the 3D correction of the worst, and the strips alone) "
              "against the 3D stress field below a 3D boundary-element pressure and "
              "traction",
        source="computed: tools/bem/roller.py (3D BEM pressure at the given force and "
               "tilt) and tools/bem/stress.py (Love's rectangle for the pressure, "
               "Cerruti's point force integrated over each cell for the traction mu p, "
               "one DC-FFT per component and depth plane) against "
               "linecontact.roller.ProfiledRoller + linecontact.stresses.roller_stresses",
        units=units,
        columns="profile codes: " + ", ".join(f"{k} = {v}" for k, v in PROFILES.items())
                + "; measures: tresca = (sigma_1 - sigma_3)/2, von_mises, orthogonal_shear "
                  "= |tau_yz| (y across the roller); bem_* = the maximum over the 3D "
                  "field on the finer grid, bem_z_* its depth (parabola through the depth "
                  "planes), bem_x_* its position along the roller; bem_change_* = fine/"
                  "coarse - 1; bem_at_plane_edge_* = 1 where the maximum sits on the first "
                  "or last depth plane (not bracketed); rt_* = the runtime's worst along "
                  "the roller (3D-corrected); strip_* the strips' worst alone; err_* = rt/bem - 1; bem/rt/err/bem_change_muK_*: with the traction mu p, mu = K/10 (both grids; from mu = 0.25 the surface included); dz_* = (z_rt - z_bem)/b; case_set: 0 dense, 1 wide (the roller study's), 2 relief (drawn end reliefs); radius: the contact's effective radius R; relief_fraction, corner_radius: the end relief's l/L and r; crown_radius: the circular crown's Rc; bem_edge = 1 "
                  "where the BEM contact reaches a roller end on either grid, rt_edge = 1 where "
                  "the runtime's comes within half a slice of one (linecontact.stresses."
                  "reaches_end); either counts as edge loaded in the header's errors; rt_*_cpu, rt_*_seconds: CPU and "
                  "wall time of the runtime contact solve and of its stresses",
        cases=f"D = {DIAMETER * 1e3:g} mm, E* = {ESTAR / 1e9:g} GPa, nu = {POISSON:g}, "
              f"friction 0, {', '.join(f'{mu:g}' for mu in FRICTIONS)}; dense set: L = 14 mm: circular crown (Rc 500 mm), iso16281, lundberg and "
              "johns-gohar (design 800 N/mm), straight with end relief (0.15 L, corner "
              "radius 50 mm); L = 30 mm: iso16281; line loads "
              f"{', '.join(f'{q / 1e3:g}' for q in LINE_LOADS)} N/mm; tilts "
              f"{', '.join(f'{t * 1e3:g}' for t in TILTS)} mrad"
              + (f"; wide set: every {WIDE_EVERY}th case of the roller study's wide "
                 "set (tools/studies/roller_study.py, wide_tasks: L/D 0.5-12, q/(E* D) "
                 "1e-5-3e-3, profiles 1-5, tilts 0, 1, 3 mrad)" if not args.no_wide else "")
              + (f"; relief set: {int((col['case_set'] == 2).sum())} straight rollers "
                 "with a corner-radius end relief drawn as the population check draws "
                 f"them (seed {RELIEF_SET['seed']}; relief_tasks: cylindrical, needle "
                 "and cam-follower rollers at 2-50 % of their ratings, relief 0.1-0.2 L, "
                 "corner radius 20-100 mm, tilts 0-3 mrad; L/D and the load on the "
                 "contact's effective radius)" if not args.no_relief else "")
              + (" (quick subset)" if args.quick else ""),
        grid=f"BEM: adapted window (contact box x 1.25, |y| <= 1.25 b), {args.n_x} x "
             f"{args.n_y} and {2 * args.n_x} x {2 * args.n_y} cells (the finer the "
             f"reference; the relief set {RELIEF_GRID[0]} x {RELIEF_GRID[1]} and "
             f"{2 * RELIEF_GRID[0]} x {2 * RELIEF_GRID[1]}); stress planes z/b = {DEPTHS_OVER_B[0]:g}-{DEPTHS_OVER_B[-1]:g} "
             "step 0.1 at the cell centres; runtime: the default settings "
             f"({DEFAULT_N_SLICES} slices); grid convergence of the "
             "reference beyond these two grids: tools/benchmarks/bench_stresses.py "
             "--grid-case",
        tolerance=f"{args.tol:g} (BEM gap error / largest interference); force 1e-6 F",
        accuracy=f"3D field change coarse to fine (frictionless), off the ends: {errs('ch_off')}; edge "
                 f"loaded: {errs('ch_edge')} (a singular end pressure: not converged)",
        runtime_error=f"largest bound |rt/bem - 1| + |bem_change| (the error_* fields "
                      f"state {MARGIN:g} times these) of the 3D-corrected runtime off the ends "
                      f"({s['n_off']} cases): {errs('off')}; with friction "
                      f"{', '.join(f'{mu:g}' for mu in FRICTIONS if mu <= HIGH_FRICTION_ABOVE)}: "
                      f"{errs('fr_off')}; with friction "
                      f"{', '.join(f'{mu:g}' for mu in FRICTIONS if mu >= HIGH_FRICTION_ABOVE)}: "
                      f"{errs('hf_off')}, edge loaded {errs('hf_edge')}; "
                      f"largest depth difference over b off the ends: {errs('dz_off')}; "
                      f"edge loaded ({s['n_edge']} cases): {errs('edge')}; the strips "
                      f"alone: off the ends {errs('strip_off')}, edge loaded "
                      f"{errs('strip_edge')} (the dense and wide sets, every profile); "
                      f"the end-relief profile over its {int(relief.sum())} cases (the "
                      f"relief set's included; the error_*.{APART} fields, never below the "
                      f"all-profile ones): off the ends ({sa['n_off']} cases) "
                      f"{errs('off', sa)}, with friction {errs('fr_off', sa)}, edge loaded "
                      f"({sa['n_edge']} cases) {errs('edge', sa)}",
        timing=f"runtime stresses (3D-corrected) over the runtime contact solve, CPU: "
               f"median {s['time_ratio_median']:.3g}, largest {s['time_ratio_max']:.3g}",
        covered=f"L/D {ld[0]:g}-{ld[-1]:g}; mean line load q/(E* D) {lo:.2g}-{hi:.2g}; "
                f"tilts 0-{tmax * 1e3:g} mrad; profiles {', '.join(PROFILE_KEYS)}; "
                f"friction 0-{max(FRICTIONS):g}; end relief: corner radius over the "
                f"contact's effective radius {rc.min():.3g}-{rc.max():.3g}, relief length "
                f"{rf.min():.3g}-{rf.max():.3g} L",
        covered_l_over_d=f"{ld[0]:.6g}, {ld[-1]:.6g}",
        covered_line_load_over_estar_d=f"{lo:.6g}, {hi:.6g}",
        covered_tilt_rad=f"0, {tmax:.6g}",
        covered_friction=f"0, {max(FRICTIONS):g}",
        high_friction_above=f"{HIGH_FRICTION_ABOVE:g}",
        covered_profiles=", ".join(PROFILE_KEYS),
        covered_end_relief_corner_radius_over_radius=f"{rc.min():.6g}, {rc.max():.6g}",
        covered_end_relief_fraction=f"{rf.min():.6g}, {rf.max():.6g}",
        **fields,
        wall_time=wall_line,
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "stress_accuracy.csv"
    write_table(path, meta, col)
    print(f"wrote {path}: {len(tasks)} cases in {wall:.0f} s")
    for k in ("accuracy", "runtime_error", "timing", "wall_time"):
        print(f"  {k}: {meta[k]}")
    return 0
