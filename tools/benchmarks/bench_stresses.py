"""Issue 17 targets: the runtime slice stresses against the 3D field, and their cost.

    python -m tools.benchmarks.bench_stresses            # about a minute on 2 cores

What it measures:

1. accuracy, from tables/stress_accuracy.csv (tools/studies/stress_study.py: the 3D
   field of tools/bem/stress.py below the 3D BEM pressure, finer of two nested grids,
   against linecontact.stresses.roller_stresses): the largest |rt/3D - 1| of each
   measure where the contact stays off the roller ends (target 1 %) and where it is
   edge loaded (stated), with the 3D field's own grid change;
2. time: per study roller (each profile, three loads, two tilts), the CPU time
   (time.process_time) of the runtime contact solve (ProfiledRoller.at_force, 100
   slices, model built beforehand) and of its stresses (roller_stresses), median of
   ``--repeat``; the stresses' first call (the cached strip maxima for a new (mu, nu),
   a grid search and ten zooms) is timed apart. Target: the stresses within
   twice the contact solve's time.

Prints a report and writes it to tools/benchmarks/results/stresses.txt.
"""
from __future__ import annotations

import argparse
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
MEASURES = ("tresca", "von_mises", "orthogonal_shear")


def accuracy(lines):
    from linecontact.tables import read_table
    t = read_table("stress_accuracy")
    c = t.columns
    edge = np.asarray(c["bem_edge"]) > 0
    lines.append(f"accuracy (tables/stress_accuracy.csv, {len(edge)} cases, "
                 f"{int((~edge).sum())} off the ends, {int(edge.sum())} edge loaded; "
                 f"generated {t.meta['date']}, {t.meta['version']}):")
    lines.append(f"{'measure':18s} {'off ends max |err|':>19s} {'median':>8s} "
                 f"{'edge max |err|':>15s} {'3D grid change (off/edge)':>26s} target 1 %")
    profiles = np.asarray(c["profile"])
    for m in MEASURES:
        e = np.abs(np.asarray(c[f"err_{m}"]))
        ch = np.abs(np.asarray(c[f"bem_change_{m}"]))
        off = e[~edge].max() if (~edge).any() else np.nan
        lines.append(f"{m:18s} {off:19.2%} {np.median(e[~edge]):8.2%} "
                     f"{e[edge].max() if edge.any() else np.nan:15.2%} "
                     f"{ch[~edge].max():12.2%} / {ch[edge].max() if edge.any() else np.nan:.2%}"
                     f"   {'met' if off <= 0.01 else 'NOT met'}")
    tilt = np.asarray(c["tilt"])
    even = (~edge) & (tilt == 0) & (profiles != 1) & (profiles != 5)
    lines.append(f"even load along the roller (untilted log profiles, off the ends, "
                 f"{int(even.sum())} cases): " + ", ".join(
                     f"{m} {np.abs(np.asarray(c[f'err_{m}']))[even].max():.2%}"
                     for m in MEASURES) + " (target 1 %: " + (
                     "met" if all(np.abs(np.asarray(c[f'err_{m}']))[even].max() <= 0.01
                                  for m in MEASURES) else "NOT met") + ")")
    lines.append("largest |err| off the ends by profile (codes as the table header):")
    for code in sorted(set(profiles.tolist())):
        sel = (~edge) & (profiles == code) & (np.asarray(c["roller_length"]) < 0.02)
        if sel.any():
            lines.append(f"  profile {int(code)} (L = 14 mm): " + ", ".join(
                f"{m} {np.abs(np.asarray(c[f'err_{m}']))[sel].max():.2%}" for m in MEASURES))
    sel = (~edge) & (np.asarray(c["roller_length"]) > 0.02)
    if sel.any():
        lines.append("  iso16281 (L = 30 mm, flat middle): " + ", ".join(
            f"{m} {np.abs(np.asarray(c[f'err_{m}']))[sel].max():.2%}" for m in MEASURES))


def timing(lines, repeat):
    from linecontact.roller import ProfiledRoller
    from linecontact.stresses import roller_stresses, strip_maxima
    from tools.studies import stress_study as ss
    from tools.studies.roller_study import make_profile

    t0 = time.process_time()
    # the first call for a (mu, nu) not asked before: the strip maxima are computed
    c0 = time.process_time()
    strip_maxima(0.05, 0.31)
    first = time.process_time() - c0
    strip_maxima(0.0, 0.3)   # the study's (mu, nu), cached before the timed loop
    ratios, solves, stresses = [], [], []
    for task in ss.study_tasks():
        prof = make_profile(task["profile"], task["length"], task["radius"], task["estar"])
        model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof)
        ts, tt = [], []
        for _ in range(repeat):
            c0 = time.process_time()
            sol = model.at_force(task["force"], tilt=task["tilt"])
            c1 = time.process_time()
            roller_stresses(sol, 0.0, 0.3, roller=model)
            c2 = time.process_time()
            ts.append(c1 - c0)
            tt.append(c2 - c1)
        if ts:
            solves.append(statistics.median(ts))
            stresses.append(statistics.median(tt))
            ratios.append(stresses[-1] / solves[-1])
    lines.append(f"time (CPU, median of {repeat} per case, {len(ratios)} cases): contact "
                 f"solve median {statistics.median(solves) * 1e3:.1f} ms; stresses median "
                 f"{statistics.median(stresses) * 1e3:.3f} ms; ratio stresses/solve median "
                 f"{statistics.median(ratios):.4f}, largest {max(ratios):.4f} (target <= 2: "
                 f"{'met' if max(ratios) <= 2 else 'NOT met'})")
    lines.append(f"first call of a new (mu, nu) (strip maxima computed and cached): "
                 f"{first * 1e3:.0f} ms CPU, once per process")
    lines.append(f"(timing section: {time.process_time() - t0:.0f} s CPU)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", type=Path, default=REPO / "tools" / "benchmarks" / "results"
                    / "stresses.txt")
    args = ap.parse_args(argv)
    import linecontact
    lines = [f"bench_stresses: linecontact {linecontact.__version__}, Python "
             f"{platform.python_version()}, numpy {np.__version__}, "
             f"{time.strftime('%Y-%m-%d')}", ""]
    accuracy(lines)
    lines.append("")
    timing(lines, args.repeat)
    text = "\n".join(lines) + "\n"
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
