"""CPU time of one runtime roller solve on every case of tables/roller_accuracy.csv.

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_cpu [--repeat 3]
        [--save FILE.json] [--against FILE.json]

Each case as the study runs it (tools/studies/roller_study.py, ``runtime_case``): a new
``linecontact.roller.ProfiledRoller`` (default settings: 50 slices since issue 20's
fourth round, 100 in the records before) per case, then one
``at_force(F, tilt)`` (a task's tilt None: ``tilt="free"``, zero moment), timed with
``time.process_time`` (CPU time, not wall: the shared machine's load does not enter);
the cases run in table order in one process, so the first includes the one-time build of the strip-function table.
``--engine`` picks ``ProfiledRoller(engine=...)`` (default ``"auto"``).
``--repeat`` runs the whole list again and keeps each case's median. ``--save`` writes
the results (depth, moment, tilt, p_max, edge, CPU time, the Newton steps the solution
reports, the slice loads); ``--against`` compares with a saved run: the largest change
in depth (over the case's largest approach), moment (over F L/2), tilt, peak pressure
(relative), stiffness matrix and slice loads (over their largest), to show that a
speed-up leaves the results alone. ``--count`` also counts the Newton steps of every
solve a case makes (the linearisations, ``SliceEquations.linearised`` calls: the end
refinement's re-solves included, which a solution's ``iterations`` leaves out) and the
dense solves (``numpy.linalg.solve`` calls, any size); it wraps those functions, so
run it apart from the timing.

Complements tools/benchmarks/bench_roller.py (accuracy against the BEM, wall times).
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time

import numpy as np


def _counting():
    """Wrap SliceEquations.linearised and numpy.linalg.solve to count their calls."""
    from linecontact.roller import slices

    counts = {"linearised": 0, "solve": 0}

    def wrap(owner, name, key):
        fn = getattr(owner, name)

        def counted(*args, **kwargs):
            counts[key] += 1
            return fn(*args, **kwargs)
        setattr(owner, name, counted)
    wrap(slices.SliceEquations, "linearised", "linearised")
    wrap(np.linalg, "solve", "solve")
    return counts


def run(repeat=1, engine="auto"):
    from linecontact.roller import ProfiledRoller
    from linecontact.tables import read_table
    from tools.studies import roller_study as rs
    from tools.benchmarks.bench_roller import _tasks_from_table

    table = read_table("roller_accuracy")
    tasks = _tasks_from_table(table)
    out = [None] * len(tasks)
    times = [[] for _ in tasks]
    for _ in range(repeat):
        for i, t in enumerate(tasks):
            prof = rs.make_profile(t["profile"], t["length"], t["radius"], t["estar"])
            model = ProfiledRoller(t["radius"], t["length"], t["estar"], prof,
                                   engine=engine)
            c0 = time.process_time()
            r = model.at_force(t["force"], tilt="free" if t["tilt"] is None else t["tilt"])
            times[i].append(time.process_time() - c0)
            out[i] = dict(case=i, profile=t["profile"], force=t["force"], tilt=r.tilt,
                          given_tilt=t["tilt"], depth=r.depth, moment=r.moment,
                          p_max=r.p_max, edge=r.edge, iterations=r.iterations,
                          stiffness=np.asarray(r.stiffness_matrix).tolist(),
                          q=np.asarray(r.q).tolist(),
                          flags=[r.edge_loaded, r.p_max_resolved, r.message,
                                 list(r.notes), r.n_slices])
    for o, ts in zip(out, times):
        o["cpu_seconds"] = statistics.median(ts)
    return table, out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--save", default=None)
    ap.add_argument("--against", default=None)
    ap.add_argument("--count", action="store_true")
    ap.add_argument("--engine", default="auto", choices=("auto", "numpy", "c"),
                    help="ProfiledRoller(engine=...) of every case (default auto)")
    a = ap.parse_args(argv)
    counts = _counting() if a.count else None
    table, out = run(a.repeat, a.engine)
    t = np.array([o["cpu_seconds"] for o in out])
    order = np.argsort(-t)
    print(f"{len(t)} cases, default slices, CPU time per solve: median {np.median(t) * 1e3:.1f}"
          f" ms, largest {t.max() * 1e3:.1f} ms, over 100 ms: {(t > 0.1).sum()}")
    print(f"Newton steps the solutions report (the last end-refinement level's): "
          f"{sum(o['iterations'] for o in out)} over {len(out)} cases")
    if counts is not None:
        print(f"every solve of every case, {a.repeat} pass(es): {counts['linearised']} "
              f"Newton steps (linearisations), {counts['solve']} dense solves")
    for i in order[:5]:
        o = out[i]
        tilt = "free" if o["given_tilt"] is None else f"{o['given_tilt'] * 1e3:g} mrad"
        print(f"  case {i}: {o['profile']}, {o['force']:g} N, tilt {tilt}: "
              f"{t[i] * 1e3:.1f} ms")
    if a.save:
        with open(a.save, "w") as f:
            json.dump(out, f)
    if a.against:
        with open(a.against) as f:
            ref = json.load(f)
        c = table.columns
        ch = dict(depth=0.0, moment=0.0, tilt=0.0)
        for i, (x, y) in enumerate(zip(ref, out)):
            FL2 = c["force"][i] * c["roller_length"][i] / 2
            ch["depth"] = max(ch["depth"], abs(x["depth"] - y["depth"]) / c["bem_delta"][i])
            ch["moment"] = max(ch["moment"], abs(x["moment"] - y["moment"]) / FL2)
            if x["tilt"]:
                ch["tilt"] = max(ch["tilt"], abs(x["tilt"] / y["tilt"] - 1))
            if x.get("p_max") is not None and y["p_max"] is not None:
                ch["p_max"] = max(ch.get("p_max", 0.0), abs(x["p_max"] / y["p_max"] - 1))
            if "stiffness" in x:
                K0, K1 = np.array(x["stiffness"]), np.array(y["stiffness"])
                ch["stiffness"] = max(ch.get("stiffness", 0.0),
                                      np.abs(K0 - K1).max() / np.abs(K0).max())
            if "q" in x and len(x["q"]) == len(y["q"]):
                q0, q1 = np.array(x["q"]), np.array(y["q"])
                ch["q"] = max(ch.get("q", 0.0), np.abs(q0 - q1).max() / np.abs(q0).max())
            if "flags" in x:
                ch["cases with other flags"] = ch.get("cases with other flags", 0) + (
                    x["flags"] != y["flags"] or x["edge"] != y["edge"]
                    or (x["p_max"] is None) != (y["p_max"] is None))
        print("largest change against " + a.against + ": " + ", ".join(
            f"{k} {v:.1e}" if isinstance(v, float) else f"{k} {v}" for k, v in ch.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
