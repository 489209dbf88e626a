"""Does every stated error hold over the rollers users bring? A population check.

Writes tables/population_check.csv (``python -m tools.build_tables population``).

The accuracy tables (tables/roller_accuracy.csv, tables/stress_accuracy.csv) state the
runtime's largest error over a grid of cases; this study draws cases that are *not* on
that grid -- the rollers of real bearings at the loads of their ratings -- and checks,
per output, that the runtime states an error and that the stated error bounds the
output's difference to a converged 3D reference.

The population (seeded, ``--seeds``, one draw per seed; ``--per-family`` cases per
family and seed):

- cylindrical roller bearings: roller diameter D_we 5-30 mm, L_we/D_we 0.8-1.5,
  D_we/D_pw 0.12-0.25, Z rollers at a pitch of 1.25 D_we;
- needle roller bearings: D_we 2-6 mm, L_we/D_we 3-10, D_we/D_pw 0.06-0.15, a pitch of
  1.1 D_we;
- cam-follower and support-roller rings on a flat track: outer diameter 16-90 mm,
  width 0.5-0.8 of it, their inner needle complement (needles of 0.08 D, length 0.8 of
  the width, pitch diameter 0.55 D) setting the rating.

Each bearing's basic dynamic radial load rating C_r is ISO 281's
(linecontact.bearing.dynamic_load_rating); the radial load F_r is log-uniform between
2 % and 50 % of C_r and the most loaded roller carries Q = F_r/(Z J_r) with J_r the
load-zone integral at epsilon = 0.5 (Stribeck's zero clearance,
linecontact.bearing.load_zone_integral); the cam follower's ring carries F_r itself.
The contact is the roller on its inner raceway (the larger curvature: effective radius
R = D_we (1 - gamma)/2, gamma = D_we/D_pw) or the ring on its flat track (R = D/2),
steel on steel. The profile is drawn among a circular crown (the crown's end drop
5-40 um), ISO/TS 16281's logarithmic profile (of the roller's diameter), Lundberg's and
Johns-Gohar's (designed for the roller load at F_r = 0.3 C_r) and a straight roller with
end relief (0.1-0.2 L at each end, tangent corner radius 20-100 mm); the tilt is 0 for
one case in three, else uniform up to 3 mrad; the friction of the stresses uniform
0-0.4 (the stress table's range; MAX_FRICTION).

Per case, the outputs and their references:

- deflection, moment (tilted) and peak pressure: the runtime coupled-slice model
  (linecontact.roller.ProfiledRoller, its defaults) against the 3D BEM on two grids
  (tools.bem.roller.grid_convergence); where the profile's drop is infinite at the
  roller ends (ISO 16281, Lundberg) and the finer grid's contact comes within two
  cells of an end, the contact ends inside those cells, so the depth, moment, peak
  and edge flag come from the roller study's end grids instead (4096 x 16 and 8192 x
  32 cells of the same window, tools.studies.roller_study._end_zone, as in the roller
  table's own reference); the stated error is the roller table's
  ``runtime_error_*`` (off the ends or edge loaded, by the runtime's flag) where the
  runtime's coverage note says the case is inside the measured range;
- Tresca, von Mises and orthogonal shear maxima with the case's friction: the runtime
  stresses (linecontact.stresses.roller_stresses) against the 3D field below the BEM
  pressure and traction (tools.studies.stress_study.field_maxima); the stated error is
  linecontact.stresses.stress_accuracy's.

An output *holds* where |runtime - BEM_fine| + |BEM_fine - BEM_coarse| <= stated (the
finer grid's own error bounded by its change from the coarser one); what the runtime
withholds -- the peak pressure and the stress maxima of an edge-loaded contact, the
singular end peak's slice-width numbers -- is not an output. The header states the share of outputs with a stated error and the share of
those that hold.
"""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from .runner import add_runner_arguments, run_study_from_args, table_meta, wall_time_line

REPO = Path(__file__).resolve().parents[2]

ESTAR = 115.385e9            #: steel on steel, E = 210 GPa, nu = 0.3 [Pa]
POISSON = 0.3
FAMILIES = ("cylindrical", "needle", "cam-follower")
FAMILY_CODES = {k: i + 1 for i, k in enumerate(FAMILIES)}
PROFILE_KINDS = ("circular", "iso16281", "lundberg", "johns-gohar", "end-relief")
PROFILE_CODES = {k: i + 1 for i, k in enumerate(PROFILE_KINDS)}
LOAD_FRACTIONS = (0.02, 0.5)          #: F_r / C_r, log-uniform
MAX_TILT = 3e-3                       #: [rad]
#: the friction of the stresses: to 0.4, the range the stress table measures (from
#: 0.25 the largest shear may reach the surface, where the 3D reference is the exact
#: surface field of its cells: tools/studies/stress_study.py, SURFACE_FRICTION)
MAX_FRICTION = 0.4
DESIGN_FRACTION = 0.3                 #: F_r / C_r of the Lundberg, Johns-Gohar design
#: the outputs checked per case (roller outputs, then stress maxima)
ROLLER_OUTPUTS = ("depth", "moment", "p_max")
STRESS_OUTPUTS = ("tresca", "von_mises", "orthogonal_shear")
#: the last full run's time, quoted in the header of a table rebuilt from its
#: checkpoints (a rebuild after the accuracy tables changed re-reads the stated errors
#: only)
STUDY_WALL = ("339 s for 120 cases with 1 worker (local dask cluster; the stress study "
              "ran beside it on the 2-core VM), 2026-11-29")


def _draw_bearing(rng, family):
    """(roller diameter, length, pitch diameter, Z, b_m, contact radius, ring) of one
    drawn bearing [m]."""
    from linecontact.bearing import dynamic_load_rating
    if family == "cylindrical":
        Dw = rng.uniform(5e-3, 30e-3)
        L = Dw * rng.uniform(0.8, 1.5)
        g = rng.uniform(0.12, 0.25)
        pitch = 1.25
    elif family == "needle":
        Dw = rng.uniform(2e-3, 6e-3)
        L = Dw * rng.uniform(3.0, 10.0)
        g = rng.uniform(0.06, 0.15)
        pitch = 1.1
    else:
        D = rng.uniform(16e-3, 90e-3)
        B = D * rng.uniform(0.5, 0.8)
        dw, lw, dpw = 0.08 * D, 0.8 * B, 0.55 * D
        z = int(math.pi * dpw / (1.1 * dw))
        cr = dynamic_load_rating(z, dpw, dw, lw)
        return dict(roller_diameter=D, length=B, rating=cr, rollers=1, radius=D / 2,
                    needle=(z, dpw, dw, lw))
    Dpw = Dw / g
    z = int(math.pi * Dpw / (pitch * Dw))
    cr = dynamic_load_rating(z, Dpw, Dw, L)
    return dict(roller_diameter=Dw, length=L, rating=cr, rollers=z,
                radius=Dw * (1 - g) / 2, pitch_diameter=Dpw)


def roller_load(bearing, fraction):
    """The most loaded roller's load [N] at F_r = fraction C_r: F_r/(Z J_r(0.5)) for a
    bearing, F_r for a cam follower's ring (one contact)."""
    from linecontact.bearing import load_zone_integral
    fr = fraction * bearing["rating"]
    if bearing["rollers"] == 1:
        return fr
    return fr / (bearing["rollers"] * load_zone_integral(0.5))


def population_tasks(per_family=20, seed=32, profile=None):
    """The drawn cases (picklable dicts with a unique 'key'): module docstring. With
    `profile` (one of PROFILE_KINDS) every case gets that profile, drawn from the
    population's distributions (another sequence than the unforced draw of the same
    seed: each profile consumes its own number of draws; the stress study's relief
    set)."""
    rng = np.random.default_rng(seed)
    tasks = []
    for family in FAMILIES:
        for i in range(per_family):
            b = _draw_bearing(rng, family)
            frac = math.exp(rng.uniform(*np.log(LOAD_FRACTIONS)))
            kinds = PROFILE_KINDS if family != "cam-follower" else (
                "circular", "end-relief")
            kind = kinds[int(rng.integers(len(kinds)))]
            kind = kind if profile is None else profile
            L = b["length"]
            kw = {}
            if kind == "circular":
                drop = rng.uniform(5e-6, 40e-6)
                kw = dict(crown_radius=(L / 2) ** 2 / (2 * drop))
            elif kind == "iso16281":
                kw = dict(diameter=b["roller_diameter"])
            elif kind in ("lundberg", "johns-gohar"):
                kw = dict(design_force=roller_load(b, DESIGN_FRACTION))
            else:
                kw = dict(relief_length=rng.uniform(0.1, 0.2) * L,
                          corner_radius=rng.uniform(0.02, 0.1))
            tilt = 0.0 if rng.uniform() < 1 / 3 else float(rng.uniform(0, MAX_TILT))
            mu = float(rng.uniform(0, MAX_FRICTION))
            tasks.append(dict(
                key=f"P{seed}-{family}-{i}", seed=seed, family=family, profile=kind, profile_kw=kw,
                radius=b["radius"], length=L, roller_diameter=b["roller_diameter"],
                estar=ESTAR, force=roller_load(b, frac), load_fraction=frac,
                rating=b["rating"], tilt=tilt, friction=mu, n_x=128, n_y=32,
                tol=1e-7, check=False))
    return tasks


def population(per_family=20, seeds=(32, 33)):
    """The cases of every seed's draw, seed by seed (the table's row order)."""
    return [t for seed in seeds for t in population_tasks(per_family, seed)]


def table_population(columns):
    """The cases of a population_check table's rows, from its ``seed`` and ``family``
    columns."""
    seeds = list(dict.fromkeys(int(v) for v in columns["seed"]))
    return population(int(columns["family"].size // (len(FAMILIES) * len(seeds))), seeds)


def build_profile(task):
    """The linecontact.profiles object of a population case."""
    from linecontact import profiles as lp
    kind, kw, L = task["profile"], task["profile_kw"], task["length"]
    if kind == "circular":
        return lp.CircularCrownProfile(L, crown_radius=kw["crown_radius"])
    if kind == "iso16281":
        return lp.ISO16281Profile(L, diameter=kw["diameter"])
    if kind == "lundberg":
        return lp.LundbergProfile(L, task["estar"], design_force=kw["design_force"])
    if kind == "johns-gohar":
        return lp.JohnsGoharProfile(L, task["radius"], task["estar"],
                                    design_force=kw["design_force"])
    return lp.EndReliefProfile(L, corner_radius=kw["corner_radius"],
                               relief_length=kw["relief_length"])


def stated_roller_errors(note, edge):
    """The roller table's stated errors for a runtime result: None where its coverage
    `note` says the case lies outside the measured range, else the header's
    runtime_error_off_ends or _edge_loaded fields (by the runtime's `edge` flag)."""
    from linecontact.tables import read_table
    if "outside the range" in note or "not known" in note:
        return None
    meta = read_table("roller_accuracy").meta
    # the class the note states (linecontact.roller.coverage): edge loaded, the end
    # zone of an infinite-drop end, or off the ends
    key = ("runtime_error_edge_loaded" if edge else
           "runtime_error_end_zone" if "contact in the end zone" in note else
           "runtime_error_off_ends")
    return {k: float(v) for k, v in (item.split() for item in meta[key].split(","))}


def runtime_outputs(task):
    """The runtime's outputs of a population case and their stated errors (by the
    accuracy tables in tables/ as they are now): dict with the runtime solution's
    depth, moment, p_max (None: withheld), tilt, edge flag, the stress maxima with
    the case's friction, and ``stated_*`` per output (NaN where none is stated)."""
    from linecontact.roller import ProfiledRoller
    from linecontact.stresses import roller_stresses, stress_accuracy

    prof = build_profile(task)
    mu = task["friction"]
    model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof)
    sol = model.at_force(task["force"], tilt=task["tilt"])
    edge = bool(sol.edge_loaded)
    note = next((n for n in sol.notes if "measured against the 3D BEM" in n
                 or "error against the 3D BEM" in n), "")
    stated = stated_roller_errors(note, edge)
    st = roller_stresses(sol, mu, POISSON)
    s_note, s_stated = stress_accuracy(sol, mu, model)
    # a maximum the runtime withholds (an edge-loaded roller: the slice width's
    # number) is not an output: NaN
    out = dict(depth=sol.depth, moment=sol.moment, p_max=sol.p_max, edge=edge,
               note=note, stress_note=s_note,
               **{m: np.nan if m in st.withheld else st.worst[m]["value"]
                  for m in STRESS_OUTPUTS})
    key_of = dict(depth="depth", moment="moment" if task["tilt"] else "moment_untilted",
                  p_max="p_max")
    for k in ROLLER_OUTPUTS:
        # (the untilted moment's stated error is over F L/2, as its difference's)
        v = None if stated is None else stated.get(key_of[k])
        out[f"stated_{k}"] = np.nan if v is None or (k == "p_max" and sol.p_max is None) \
            else v
    for m in STRESS_OUTPUTS:
        out[f"stated_{m}"] = np.nan if s_stated is None else s_stated[m]
    return out


def run_case(task):
    """One population case: the BEM references on two grids (the stress fields with
    the case's friction) and the runtime's differences to them (module docstring); the
    stated errors are looked up afterwards (runtime_outputs, with the tables then
    shipped)."""
    from ..bem.roller import grid_convergence, solve_roller_force
    from .roller_study import _end_gap, _end_zone, _infinite_end
    from .stress_study import field_maxima

    t0 = time.perf_counter()
    prof = build_profile(task)
    mu = task["friction"]
    g = grid_convergence(solve_roller_force, task["radius"], task["length"], task["estar"],
                         task["force"], tilt=task["tilt"], profile=prof,
                         n_x=task["n_x"], n_y=task["n_y"], tol=task["tol"], workers=1,
                         fields=True)
    c, f = g["coarse"], g["fine"]
    fr = (0.0, mu) if mu > 0 else (0.0,)
    sf, sc = field_maxima(f, frictions=fr)[mu], field_maxima(c, frictions=fr)[mu]
    L, F = task["length"], task["force"]
    ref = dict(depth=f.depth, moment=f.moment, p_max=f.p_max,
               change_depth=f.depth - c.depth, change_moment=f.moment - c.moment,
               change_p_max=f.p_max / c.p_max - 1,
               edge=bool(c.edge_loaded or f.edge_loaded), end_grids=False)
    if _infinite_end(prof, L) and (f.edge_loaded or _end_gap(f, L) < 2 * f.grid.dx):
        # a logarithmic profile's contact within two cells of a roller end: it ends
        # microns before the end, inside those cells; the roller study's end grids
        # resolve it (its depth, moment, peak and edge flag, with their own change
        # between the two end grids: tools.studies.roller_study._end_zone)
        ref.update({k: v for k, v in _end_zone(task, prof, f).items() if k in ref},
                   end_grids=True)
    t1 = time.perf_counter()
    rt = runtime_outputs(task)
    # deflection over the largest approach, moment relative (tilted) or over F L/2
    xs = np.linspace(-L / 2, L / 2, 4097)
    with np.errstate(divide="ignore", invalid="ignore"):
        delta = float(np.max(ref["depth"] + f.tilt * xs - prof.drop(xs)))
    sm = abs(ref["moment"]) if task["tilt"] else F * L / 2
    bem_edge = ref["edge"]
    out = dict(bem_edge=bem_edge, bem_seconds=t1 - t0, end_grids=ref["end_grids"],
               diff_depth=(abs(rt["depth"] - ref["depth"]) + abs(ref["change_depth"]))
               / delta,
               diff_moment=(abs(rt["moment"] - ref["moment"]) + abs(ref["change_moment"]))
               / sm,
               # the peak: an output where the runtime states one (off its ends); where
               # the BEM's contact reaches an end its peak is singular: no reference,
               # the runtime's value differs from it without bound (inf: fails)
               diff_p_max=(np.nan if rt["p_max"] is None else np.inf if bem_edge else
                           abs(rt["p_max"] / ref["p_max"] - 1) + abs(ref["change_p_max"])))
    for m in STRESS_OUTPUTS:
        rv, fv, cv = rt[m], sf[m]["value"], sc[m]["value"]
        out[f"diff_{m}"] = abs(rv / fv - 1) + abs(fv / cv - 1)
    out["seconds"] = time.perf_counter() - t0
    return out


COLUMNS_UNITS = {
    "seed": "-", "family": "-", "profile": "-", "radius": "m", "roller_diameter": "m", "length": "m",
    "l_over_d": "-", "force": "N", "load_fraction": "-", "rating": "N", "tilt": "rad",
    "friction": "-", "line_load_over_estar_d": "-", "edge": "-", "bem_edge": "-",
    "end_grids": "-",
    **{f"{p}_{k}": "-" for k in ROLLER_OUTPUTS + STRESS_OUTPUTS
       for p in ("diff", "stated", "holds")},
    "bem_seconds": "s", "seconds": "s",
}


def tabulate(tasks, results, runtime):
    """Columns from the tasks, their BEM results (run_case) and their runtime outputs
    with stated errors (runtime_outputs)."""
    rows = []
    for t, r0, rt in zip(tasks, results, runtime):
        r = dict(r0, edge=rt["edge"], **{k: v for k, v in rt.items()
                                          if k.startswith("stated_")})
        for k in ROLLER_OUTPUTS + STRESS_OUTPUTS:
            # what the runtime withholds now (no number printed) is not an output
            if rt[k] is None or (isinstance(rt[k], float) and np.isnan(rt[k])):
                r[f"diff_{k}"] = np.nan
        row = dict(seed=t["seed"], family=FAMILY_CODES[t["family"]],
                   profile=PROFILE_CODES[t["profile"]],
                   radius=t["radius"], roller_diameter=t["roller_diameter"],
                   length=t["length"], l_over_d=t["length"] / t["roller_diameter"],
                   force=t["force"], load_fraction=t["load_fraction"],
                   rating=t["rating"], tilt=t["tilt"], friction=t["friction"],
                   line_load_over_estar_d=t["force"] / (t["length"] * t["estar"]
                                                        * 2 * t["radius"]),
                   edge=float(r["edge"]), bem_edge=float(r["bem_edge"]),
                   end_grids=float(r.get("end_grids", False)),
                   bem_seconds=r["bem_seconds"], seconds=r["seconds"])
        for k in ROLLER_OUTPUTS + STRESS_OUTPUTS:
            d, s = r[f"diff_{k}"], r[f"stated_{k}"]
            # flags: 1 holds, 0 fails, -1 no stated error, -2 not an output (the
            # withheld peak of an edge-loaded contact); NaN is not a CSV number
            row[f"diff_{k}"] = d if np.isfinite(d) else -1.0 if np.isnan(d) else 1e300
            row[f"stated_{k}"] = s if np.isfinite(s) else -1.0
            row[f"holds_{k}"] = (-2.0 if np.isnan(d) else -1.0 if not np.isfinite(s)
                                 else float(d <= s))
        rows.append(row)
    return {k: np.array([row[k] for row in rows], dtype=float) for k in COLUMNS_UNITS}


def summarise(col):
    """(share with a stated error, share of those that hold, counts, the failures)."""
    h = np.concatenate([col[f"holds_{k}"] for k in ROLLER_OUTPUTS + STRESS_OUTPUTS])
    outputs = h[h > -2]
    n = outputs.size
    stated = outputs[outputs >= 0]
    return dict(n=int(n), n_stated=int(stated.size), n_hold=int((stated == 1).sum()),
                share_stated=float(stated.size / n) if n else float("nan"),
                share_hold=float((stated == 1).mean()) if stated.size else float("nan"),
                by_output={k: (int((col[f"holds_{k}"] >= 0).sum()),
                               int((col[f"holds_{k}"] == 1).sum()),
                               int((col[f"holds_{k}"] > -2).sum()))
                           for k in ROLLER_OUTPUTS + STRESS_OUTPUTS})


def add_arguments(parser):
    parser.add_argument("--per-family", type=int, default=20,
                        help="cases per family (default 20: 60 cases)")
    parser.add_argument("--seeds", default="32,33",
                        help="the draws' seeds, comma-separated (default 32,33: two "
                             "independent populations; the stress study's relief set "
                             "is drawn with seed 7)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for population_check.csv (default tables/)")
    add_runner_arguments(parser)


def run(args):
    from linecontact.tables import read_table, write_table

    seeds = [int(v) for v in args.seeds.split(",")]
    tasks = population(args.per_family, seeds)
    t0 = time.perf_counter()
    results = run_study_from_args(run_case, tasks, args, desc="population check")
    wall = time.perf_counter() - t0
    runtime = [runtime_outputs(t) for t in tasks]
    col = tabulate(tasks, results, runtime)
    s = summarise(col)
    notes_out = sorted({r["note"].split(":")[0] for r in runtime
                        if "outside the range" in r["note"]}
                       | {r["stress_note"].split(":")[0] for r in runtime
                          if "outside the range" in r["stress_note"]})
    by = "; ".join(f"{k}: {st} of {n} stated, {ok} hold" for k, (st, ok, n)
                   in s["by_output"].items())
    versions = "; ".join(f"{stem}: {read_table(stem).meta.get('version')}, "
                         f"{read_table(stem).meta.get('date')}"
                         for stem in ("roller_accuracy", "stress_accuracy"))
    meta = table_meta(
        args.command_line,
        title="Population check: the runtime's stated errors against the 3D BEM over "
              "drawn rollers of cylindrical, needle and cam-follower bearings at 2-50 % "
              "of their ISO 281 ratings",
        source="computed: tools/studies/population_study.py (tools/bem/roller.py, "
               "tools/bem/stress.py) against linecontact.roller.ProfiledRoller and "
               "linecontact.stresses, stated errors from the accuracy tables "
               f"({versions})",
        units=", ".join(f"{k} [{u}]" for k, u in COLUMNS_UNITS.items()),
        columns="family: " + ", ".join(f"{v} = {k}" for k, v in FAMILY_CODES.items())
                + "; profile: " + ", ".join(f"{v} = {k}" for k, v in PROFILE_CODES.items())
                + "; radius: the contact's effective radius (roller on its inner "
                  "raceway, ring on a flat track); diff_* = |rt - bem_fine| + |bem_fine - "
                  "bem_coarse| (deflection over the largest approach, moment relative "
                  "where tilted, else over F L/2, the rest relative; 1e300: the runtime "
                  "states a peak pressure where the BEM's contact reaches an end, a "
                  "singular peak: no finite reference); stated_*: the "
                  "runtime's stated error (-1: none stated); holds_*: 1 diff <= stated, 0 "
                  "not, -1 no stated error, -2 not an output (what the runtime "
                  "withholds: the peak pressure and the stress maxima of an edge-loaded "
                  "contact); edge: the runtime's flag, "
                  "bem_edge: the BEM's (either grid); end_grids: 1 where the depth, "
                  "moment, peak and edge flag come from the roller study's end grids "
                  "(a logarithmic profile's contact within two cells of a roller end)",
        cases=f"{args.per_family} per family and seed, seeds "
              f"{', '.join(str(v) for v in seeds)}: module docstring of "
              "tools/studies/population_study.py",
        grid="BEM: the roller study's adapted window, 128 x 32 and 256 x 64 cells (a "
             "logarithmic profile's contact within two cells of an end: 4096 x 16 and "
             "8192 x 32 of the same window for the depth, moment and peak); "
             "stress planes z/b = 0.1-1.2 and the surface (tools/studies/stress_study.py)",
        accuracy="each difference includes the BEM reference's own grid change (coarse "
                 "to fine: diff_* = |rt - fine| + |fine - coarse|); the runtime solves to "
                 "its Newton tolerance (1e-11)",
        result=f"{s['n_stated']} of {s['n']} outputs ({s['share_stated']:.1%}) get a "
               f"stated error; {s['n_hold']} of those ({s['share_hold']:.1%}) hold "
               f"(diff <= stated); by output: {by}",
        outside=("; ".join(notes_out) if notes_out else "none"),
        wall_time=wall_time_line(wall, results, "cases", args.scheduler, args.workers,
                                 measured=STUDY_WALL),
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "population_check.csv"
    write_table(path, meta, col)
    print(f"wrote {path}: {len(tasks)} cases in {wall:.0f} s")
    for k in ("result", "outside", "wall_time"):
        print(f"  {k}: {meta[k]}")
    return 0
