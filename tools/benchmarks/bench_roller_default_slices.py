"""Could the profiled-roller model's default slice count come down? The runtime at
smaller slice counts (and other slice settings) against the 3D BEM of the accuracy
table, with its "not converged" count and its CPU time.

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_default_slices \
        [--variants 100,80,70,60,50,40,50/0.9,50/0.8/5] [--repeat 1] [--rows 0-103]

A variant is ``n[/grading[/levels[/tol]]]``: ``ProfiledRoller(..., n_slices=n,
grading=grading)`` (default: linecontact.roller.model.DEFAULT_GRADING) with the end
refinement (``refine_ends=True``) allowed up to ``levels`` levels (default
REFINE_LEVELS) and its agreement tolerance ``tol`` (default REFINE_TOL); levels and
tol are module constants of linecontact.roller.model, which this study sets for the
variant and restores. Each of the 104 cases of tables/roller_accuracy.csv is solved as
the accuracy study solves it (tools/studies/roller_study.py ``runtime_case``: a new
model per case, ``at_force(F, tilt)``, ``tilt="free"`` where the table's tilt is free;
CPU time of ``at_force`` alone, ``time.process_time``, the median of ``--repeat``), and
compared with the table's BEM columns with the study's error definitions
(``roller_study.errors``; the classes of its header: off the ends where the BEM's
contact stays off the roller end cells, edge loaded otherwise).

Per variant: the largest |error| off the ends (peak pressure, deflection, moment at a
given tilt != 0, moment at tilt 0 or free over F L/2, zero-moment tilt) and edge loaded
(deflection, moment); the number of cases left ``p_max_resolved=False`` that are not
edge loaded (the runtime's "not converged"); the median and total CPU of a solve, the
median Newton steps of the last solve (``iterations``) and the median and largest
slice count used (refined solves use more); and, on the table's speed case (ISO 16281,
L 14 mm, 4200 N, 2 mrad: the `roller` benchmark of tools/benchmarks/suite.py), its CPU.

``--exact`` adds, per variant (n and grading), a circular crown against exact Hertz
and a straight roller against the universal curve (``exact_checks``).

``--sample N`` adds N random cases inside the range the table covers (its header's
``covered_*`` fields: L/D 1.4-3 uniform, mean line load 100-2000 N/mm log-uniform at
D = 10 mm, the table's five profiles with a given tilt uniform in 0-2 mrad, and the
offset crown at a free tilt; ``--seed``), drawn once; a case whose reference note says
it is outside the covered range (the tilt drop over the approach) is drawn again. No
BEM there: the reference is 400 slices graded 0.99 with up to 5 end refinements (as
tools/benchmarks/bench_roller_slices.py ``--ends``). Per variant: the cases left "not
converged", and the largest differences from the reference (p_max relative where both
resolve it and the contact stays off the ends; depth over the largest overlap; moment
relative at a given tilt != 0, over F L/2 otherwise).
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time

import numpy as np


def parse_variant(text):
    from linecontact.roller import model
    parts = text.split("/")
    n = int(parts[0])
    g = float(parts[1]) if len(parts) > 1 and parts[1] else model.DEFAULT_GRADING
    lv = int(parts[2]) if len(parts) > 2 and parts[2] else model.REFINE_LEVELS
    tol = float(parts[3]) if len(parts) > 3 and parts[3] else model.REFINE_TOL
    return dict(n=n, grading=g, levels=lv, tol=tol)


def run_variant(v, table, tasks, rows, repeat):
    from linecontact.roller import ProfiledRoller, model
    from tools.studies import roller_study as rs

    c = table.columns
    saved = model.REFINE_LEVELS, model.REFINE_TOL
    model.REFINE_LEVELS, model.REFINE_TOL = v["levels"], v["tol"]
    try:
        out = []
        for i in rows:
            t = tasks[i]
            prof = rs.make_profile(t["profile"], t["length"], t["radius"], t["estar"])
            cpu = []
            for _ in range(repeat):
                m = ProfiledRoller(t["radius"], t["length"], t["estar"], prof,
                                   n_slices=v["n"], grading=v["grading"])
                c0 = time.process_time()
                r = m.at_force(t["force"], tilt="free" if t["tilt"] is None else t["tilt"])
                cpu.append(time.process_time() - c0)
            ref = dict(depth=c["bem_depth"][i], delta=c["bem_delta"][i],
                       moment=c["bem_moment"][i], p_max=c["bem_p_max"][i],
                       tilt=c["tilt"][i])
            got = dict(depth=r.depth, moment=r.moment, p_max=rs._peak(r), tilt=r.tilt)
            e_d, e_m, e_p, e_t = rs.errors(ref, got, t)
            out.append(dict(row=i, e_d=e_d, e_m=e_m, e_p=e_p, e_t=e_t,
                            edge=bool(c["bem_edge"][i]), rt_edge=bool(r.edge_loaded),
                            free=t["tilt"] is None, tilted=bool(t["tilt"]),
                            unresolved=not r.edge_loaded and not r.p_max_resolved,
                            cpu=statistics.median(cpu), its=r.iterations,
                            slices=r.n_slices, p_max=got["p_max"], depth=r.depth,
                            moment=r.moment))
        return out
    finally:
        model.REFINE_LEVELS, model.REFINE_TOL = saved


def sample_tasks(n, seed):
    """n random cases inside the covered range (module docstring, ``--sample``)."""
    from tools.studies import roller_study as rs
    rng = np.random.default_rng(seed)
    names = ("circular crown", "iso16281", "lundberg", "johns-gohar",
             "straight with end relief", "offset circular crown")
    out = []
    for _ in range(n):
        name = names[rng.integers(len(names))]
        L = rs.DIAMETER * rng.uniform(1.4, 3.0)
        q = float(np.exp(rng.uniform(np.log(1e5), np.log(2e6))))
        tilt = None if name == "offset circular crown" else float(rng.uniform(0, 2e-3))
        out.append(dict(profile=name, radius=rs.DIAMETER / 2, length=L, estar=rs.ESTAR,
                        force=q * L, tilt=tilt))
    return out


def _solve(t, n, grading, levels, tol=None):
    from linecontact.roller import ProfiledRoller, model
    from tools.studies import roller_study as rs
    saved = model.REFINE_LEVELS, model.REFINE_TOL
    model.REFINE_LEVELS = levels
    model.REFINE_TOL = saved[1] if tol is None else tol
    try:
        prof = rs.make_profile(t["profile"], t["length"], t["radius"], t["estar"])
        m = ProfiledRoller(t["radius"], t["length"], t["estar"], prof, n_slices=n,
                           grading=grading)
        c0 = time.process_time()
        r = m.at_force(t["force"], tilt="free" if t["tilt"] is None else t["tilt"])
        return r, time.process_time() - c0
    finally:
        model.REFINE_LEVELS, model.REFINE_TOL = saved


def sample_references(n, seed):
    """The sample's cases and their 400-slice references, redrawing a case outside the
    covered range."""
    tasks, refs, failed = [], [], []
    k = 0
    while len(tasks) < n:
        t = sample_tasks(1, seed * 100003 + k)[0]
        k += 1
        try:
            ref, _ = _solve(t, 400, 0.99, 5)
        except (ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            failed.append((t, f"{type(exc).__name__}: {exc}"))
            continue
        if any("outside the range" in note for note in ref.notes):
            continue
        tasks.append(t)
        refs.append(ref)
    return tasks, refs, failed


def sample_variant(v, tasks, refs):
    worst = [0.0, 0.0, 0.0]
    where = [None, None, None]
    unresolved, cpu, failed = [], [], []
    for i, (t, ref) in enumerate(zip(tasks, refs)):
        try:
            r, dt = _solve(t, v["n"], v["grading"], v["levels"], v["tol"])
        except (ArithmeticError, ValueError, np.linalg.LinAlgError):
            failed.append(i)
            continue
        cpu.append(dt)
        if not r.edge_loaded and not r.p_max_resolved:
            unresolved.append(i)
        L, F = t["length"], t["force"]
        with np.errstate(invalid="ignore"):
            delta = ref.depth + abs(ref.tilt) * L / 2
        e = [abs(r.p_max / ref.p_max - 1) if (r.p_max and ref.p_max and
                                             ref.p_max_resolved) else 0.0,
             abs(r.depth - ref.depth) / delta,
             abs(r.moment / ref.moment - 1) if t["tilt"] else
             abs(r.moment - ref.moment) / (F * L / 2)]
        for k in range(3):
            if e[k] > worst[k]:
                worst[k], where[k] = e[k], i
    return worst, where, unresolved, failed, statistics.median(cpu)


def exact_checks(v):
    """The variant's slices against exact solutions: a circular crown against exact
    Hertz (Johnson 1985 section 4.2; R 10 mm, L 20 mm, E* 115.385 GPa, Rc 500 mm at
    1 kN and 200 mm at 2 kN: the largest relative error in approach, p0, b, the
    contact half-length a and the stiffness), and a straight roller against the
    universal curve (force at a given depth, the cases of docs/profiled_rollers.md's
    table: relative error per case, in %)."""
    from linecontact.hertz import hertz_contact
    from linecontact.models import UniversalModel
    from linecontact.roller import ProfiledRoller
    E = 115.385e9
    crown = []
    for rc, F in ((0.5, 1000.0), (0.2, 2000.0)):
        h = hertz_contact(F, rc, 10e-3, E)
        s = ProfiledRoller(10e-3, 20e-3, E, f"circular:Rc={rc}", n_slices=v["n"],
                           grading=v["grading"]).at_force(F, tilt=0.0)
        crown.append([abs(s.depth / h.approach - 1), abs(s.p_max / h.p0 - 1),
                      abs(s.half_width.max() / h.b - 1),
                      abs(s.contact_length / 2 / h.a - 1),
                      abs(s.stiffness / h.stiffness - 1)])
    crown = np.max(crown, axis=0)
    straight = []
    for R, L, r in ((5e-3, 10e-3, 5e-6), (5e-3, 10e-3, 5e-5), (5e-3, 10e-3, 5e-4),
                    (5e-3, 25e-3, 8e-7), (5e-3, 25e-3, 8e-5), (10e-3, 5e-3, 4e-5),
                    (10e-3, 5e-3, 4e-3), (2e-3, 50e-3, 8e-7), (2e-3, 50e-3, 8e-6),
                    (20e-3, 4e-3, 1.3e-3), (20e-3, 4e-3, 3.8e-2)):
        d = r * L**2 / R
        s = ProfiledRoller(R, L, E, None, n_slices=v["n"], grading=v["grading"])
        straight.append(s.at_depth(d).force / UniversalModel(R, L, E).force(d) - 1)
    return crown, straight


def summary(out):
    def mx(key, pred):
        v = [abs(o[key]) for o in out if pred(o)]
        return max(v, default=0.0)

    def arg(key, pred):
        v = [(abs(o[key]), o["row"]) for o in out if pred(o)]
        return max(v, default=(0.0, -1))[1]

    return dict(
        off_p=mx("e_p", lambda o: not o["edge"]), off_p_row=arg("e_p", lambda o: not o["edge"]),
        off_d=mx("e_d", lambda o: not o["edge"]),
        off_m=mx("e_m", lambda o: not o["edge"] and o["tilted"]),
        off_m_row=arg("e_m", lambda o: not o["edge"] and o["tilted"]),
        off_m0=mx("e_m", lambda o: not o["edge"] and not o["tilted"]),
        off_t=mx("e_t", lambda o: not o["edge"] and o["free"]),
        edge_d=mx("e_d", lambda o: o["edge"]),
        edge_m=mx("e_m", lambda o: o["edge"] and o["tilted"]),
        unresolved=[o["row"] for o in out if o["unresolved"]],
        cpu_med=statistics.median(o["cpu"] for o in out),
        cpu_sum=sum(o["cpu"] for o in out),
        its_med=statistics.median(o["its"] for o in out),
        slices_med=statistics.median(o["slices"] for o in out),
        slices_max=max(o["slices"] for o in out))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--variants", default="100,80,70,60,50,40")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--rows", default=None, help="a range a-b of table rows (default all)")
    ap.add_argument("--per-case", action="store_true",
                    help="also print every case's errors")
    ap.add_argument("--sample", type=int, default=0,
                    help="random cases inside the covered range against 400 slices")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--exact", action="store_true",
                    help="also the crown against exact Hertz and the straight roller "
                         "against the universal curve")
    ap.add_argument("--no-table", action="store_true",
                    help="skip the table's cases (with --sample)")
    a = ap.parse_args(argv)

    from linecontact.tables import read_table
    from tools.benchmarks.bench_roller import _tasks_from_table
    from tools.benchmarks.suite import FORCE, L, TILT

    table = read_table("roller_accuracy")
    tasks = _tasks_from_table(table)
    c = table.columns
    if a.rows:
        lo, hi = (int(x) for x in a.rows.split("-"))
        rows = list(range(lo, hi + 1))
    else:
        rows = list(range(len(tasks)))
    speed = [i for i in rows if tasks[i]["profile"] == "iso16281"
             and abs(tasks[i]["length"] - L) < 1e-9 and tasks[i]["force"] == FORCE
             and tasks[i]["tilt"] == TILT]
    # the strip-function table, built once
    run_variant(parse_variant("100"), table, tasks, rows[:1], 1)
    n_off = sum(1 for i in rows if not c["bem_edge"][i])
    print(f"{len(rows)} cases of tables/roller_accuracy.csv ({n_off} off the ends, "
          f"{len(rows) - n_off} edge loaded); CPU medians of {a.repeat}")
    print("variant n/grading/levels/tol | off the ends: p_max  depth  moment(tilted) "
          "M0/(FL/2)  tilt | edge: depth moment | unresolved | CPU median, total | "
          "Newton steps median | slices median, max | speed case CPU")
    for text in a.variants.split(",") if not a.no_table else []:
        v = parse_variant(text)
        out = run_variant(v, table, tasks, rows, a.repeat)
        s = summary(out)
        sp = [o["cpu"] for o in out if o["row"] in speed]
        label = f"{v['n']}/{v['grading']:g}/{v['levels']}/{v['tol']:g}"
        print(f"{label:<20s} | {s['off_p']:.2%} (row {s['off_p_row']})  {s['off_d']:.3%}  "
              f"{s['off_m']:.3%} (row {s['off_m_row']})  {s['off_m0']:.1e}  "
              f"{s['off_t']:.3%} | {s['edge_d']:.3%} {s['edge_m']:.3%} | "
              f"{len(s['unresolved'])} {s['unresolved']} | {s['cpu_med'] * 1e3:.1f} ms, "
              f"{s['cpu_sum']:.2f} s | {s['its_med']:g} | {s['slices_med']:g}, "
              f"{s['slices_max']} | "
              + (f"{sp[0] * 1e3:.1f} ms" if sp else "-"), flush=True)
        if a.per_case:
            for o in out:
                print(f"    row {o['row']:3d} {tasks[o['row']]['profile']:<24s} "
                      f"p {o['e_p']:+.3%} d {o['e_d']:+.3%} m {o['e_m']:+.3%} "
                      f"edge {o['edge']:d}/{o['rt_edge']:d} unresolved {o['unresolved']:d} "
                      f"slices {o['slices']} cpu {o['cpu'] * 1e3:.1f} ms")
    if a.exact:
        print("against exact solutions: crown vs exact Hertz, largest |error| of two "
              "cases in approach, p0, b, a, stiffness; straight roller vs the universal "
              "curve, force error per case of docs/profiled_rollers.md's table [%]")
        for text in a.variants.split(","):
            v = parse_variant(text)
            crown, straight = exact_checks(v)
            print(f"{v['n']}/{v['grading']:g} | crown " + " ".join(f"{e:.2%}" for e in crown)
                  + " | straight " + " ".join(f"{100 * e:+.2f}" for e in straight),
                  flush=True)
    if a.sample:
        tasks, refs, ref_failed = sample_references(a.sample, a.seed)
        counts = {}
        for t in tasks:
            counts[t["profile"]] = counts.get(t["profile"], 0) + 1
        print(f"{a.sample} random cases inside the covered range (seed {a.seed}; "
              + ", ".join(f"{k} {v}" for k, v in counts.items()) + "), against 400 "
              "slices graded 0.99, up to 5 end refinements; the reference leaves "
              f"{sum(1 for r in refs if not r.edge_loaded and not r.p_max_resolved)} "
              f"unresolved, {sum(1 for r in refs if r.edge_loaded)} edge loaded")
        for t, why in ref_failed:
            print(f"  redrawn, the reference failed: {t['profile']}, L "
                  f"{t['length'] * 1e3:.4f} mm, F {t['force']:.2f} N, tilt "
                  f"{t['tilt'] if t['tilt'] is not None else 'free'}: {why}")
        print("variant n/grading/levels/tol | largest difference: p_max, depth/overlap, "
              "moment | unresolved | failed | CPU median")
        for text in a.variants.split(","):
            v = parse_variant(text)
            worst, where, unres, fails, cpu = sample_variant(v, tasks, refs)
            label = f"{v['n']}/{v['grading']:g}/{v['levels']}/{v['tol']:g}"
            print(f"{label:<20s} | {worst[0]:.3%} (case {where[0]}), {worst[1]:.1e}, "
                  f"{worst[2]:.1e} (case {where[2]}) | {len(unres)} {unres} | {fails} | "
                  f"{cpu * 1e3:.1f} ms", flush=True)
            if a.per_case:
                for i in unres + fails + [w for w in where if w is not None]:
                    t = tasks[i]
                    print(f"    case {i}: {t['profile']}, L {t['length'] * 1e3:.3f} mm, "
                          f"F {t['force']:.1f} N, tilt {t['tilt']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
