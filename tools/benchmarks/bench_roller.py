"""Issue 9 targets: the runtime roller model against the converged 3D BEM, and its speed.

    python -m tools.benchmarks.bench_roller            # about a minute on 2 cores

What it measures:

1. accuracy, on every case of tables/roller_accuracy.csv (the BEM reference of
   tools/studies/roller_study.py, finer of two nested grids): the runtime coupled-slice model
   (linecontact.roller) and ISO 16281 slicing are re-run now, at the case's force and
   tilt, and compared with the stored BEM deflection, moment and peak pressure (error
   definitions: tools/studies/roller_study.py). Targets (issue 9, item 8): runtime within 1 % in
   deflection and moment and within 5 % in peak pressure wherever the contact stays off
   the roller ends; elsewhere (edge loaded) and for ISO slicing the errors are stated.
2. time per solve, CPU (time.process_time: what other jobs on a shared machine do not
   inflate) and wall: the runtime model (median of ``--repeat`` solves of each case,
   model construction excluded and, for the wall time, also included) and the BEM at the
   study's two grids (``--bem-cases`` cases, one FFT thread, force control with Newton on
   the approach).

Prints a report and writes it to tools/benchmarks/results/roller_accuracy.txt.
"""
from __future__ import annotations

import argparse
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from tools.studies import roller_study as rs
from tools.bem.roller import solve_roller_force

REPO = Path(__file__).resolve().parents[2]
TARGETS = dict(depth=0.01, moment=0.01, p_max=0.05)


def _tasks_from_table(table):
    c = table.columns
    tasks = []
    for i in range(len(table)):
        prof = rs.PROFILES[int(c["profile"][i])]
        L = float(c["roller_length"][i])
        free = bool(c["free_tilt"][i])
        tasks.append(dict(key=f"row{i}", profile=prof, radius=rs.DIAMETER / 2, length=L,
                          estar=rs.ESTAR, force=float(c["force"][i]),
                          tilt=None if free else float(c["tilt"][i])))
    return tasks


def accuracy(table, repeat):
    """Errors of the runtime and of ISO slicing against the stored BEM, and runtime
    solve times (s), per case."""
    c = table.columns
    rows = []
    for i, task in enumerate(_tasks_from_table(table)):
        ref = dict(depth=c["bem_depth"][i], delta=c["bem_delta"][i],
                   moment=c["bem_moment"][i], p_max=c["bem_p_max"][i], tilt=c["tilt"][i])
        times, cpu = [], []
        for _ in range(repeat):
            rt = rs.runtime_case(task)
            times.append(rt["seconds"])
            cpu.append(rt["cpu_seconds"])
        t_total = time.perf_counter()
        rs.runtime_case(task)
        t_total = time.perf_counter() - t_total
        iso = rs.iso_case(task)
        kref = (c["bem_stiffness"][i], c["bem_tilt_stiffness"][i])
        rows.append(dict(task=task, edge=bool(c["bem_edge"][i]),
                         rt=rs.errors(ref, rt, task), iso=rs.errors(ref, iso, task),
                         rt_k=(rt["stiffness"] / kref[0] - 1, rt["tilt_stiffness"] / kref[1] - 1),
                         iso_k=(iso["stiffness"] / kref[0] - 1,
                                iso["tilt_stiffness"] / kref[1] - 1),
                         seconds=statistics.median(times), cpu=statistics.median(cpu),
                         seconds_total=t_total))
    return rows


def bem_times(table, n_cases):
    """Seconds per BEM force-controlled solve at the study's two grids."""
    tasks = _tasks_from_table(table)
    pick = np.linspace(0, len(tasks) - 1, n_cases).round().astype(int)
    # the study's standard pair (the row with the fewest cells along x: the end-zone
    # rows of logarithmic profiles have 8192 x 32, the others 256 x 64)
    i = int(np.argmin(table.columns["bem_nx"]))
    n_x, n_y = int(table.columns["bem_nx"][i]) // 2, int(table.columns["bem_ny"][i]) // 2
    out = []
    for i in pick:
        t = tasks[i]
        prof = rs.make_profile(t["profile"], t["length"], t["radius"], t["estar"])
        for scale in (1, 2):
            t0, c0 = time.perf_counter(), time.process_time()
            r = solve_roller_force(t["radius"], t["length"], t["estar"], t["force"],
                                   tilt=t["tilt"], profile=prof, n_x=scale * n_x,
                                   n_y=scale * n_y, workers=1)
            out.append((t, scale, r.grid.nx, r.grid.ny, time.perf_counter() - t0,
                        time.process_time() - c0, r.newton_steps))
    return out


def report(rows, bem, table_path):
    lines = []
    say = lines.append
    off = [r for r in rows if not r["edge"]]
    edge = [r for r in rows if r["edge"]]
    names = ("depth", "moment", "p_max", "tilt")

    def worst(subset, model, k):
        # moment: cases at a given tilt != 0; tilt: the free-tilt (zero moment) cases
        if k == 1:
            sel = [r for r in subset if r["task"]["tilt"]]
        elif k == 3:
            sel = [r for r in subset if r["task"]["tilt"] is None]
        else:
            sel = subset
        if not sel:
            return 0.0, "-"
        r = max(sel, key=lambda r: abs(r[model][k]))
        t = r["task"]
        tilt = "free" if t["tilt"] is None else f"{t['tilt'] * 1e3:g} mrad"
        return abs(r[model][k]), (f"{t['profile']}, L = {t['length'] * 1e3:g} mm, "
                                  f"F = {t['force']:g} N, tilt = {tilt}")

    try:                    # the repository's table by its relative path
        table_path = Path(table_path).resolve().relative_to(REPO)
    except ValueError:
        pass
    say(f"reference: {table_path} ({len(rows)} cases: {len(off)} off the ends, "
        f"{len(edge)} edge loaded)")
    say("")
    say("runtime model (linecontact.roller) against the converged BEM")
    for subset, label in ((off, "off the ends"), (edge, "edge loaded")):
        for k, name in enumerate(names):
            if label == "edge loaded" and name == "p_max":
                continue
            e, where = worst(subset, "rt", k)
            verdict = ""
            if label == "off the ends" and name in TARGETS:
                verdict = "PASS" if e <= TARGETS[name] else "FAIL"
                verdict = f"  target {TARGETS[name]:.0%}: {verdict}"
            say(f"  {label:13s} {name:7s} largest |error| {e:7.2%}{verdict}   ({where})")
    say("  (moment: cases at a given tilt != 0, relative to M; tilt: zero-moment cases, "
        "relative; edge-loaded peak pressure is a singular end peak: no target)")
    say("  all cases: dF/dd largest |error| "
        f"{max(abs(r['rt_k'][0]) for r in rows):.2%}, dM/dtheta "
        f"{max(abs(r['rt_k'][1]) for r in rows):.2%} (BEM: rigid punch on its staircase "
        "contact set)")
    say("")
    say("ISO 16281 slicing against the converged BEM (same cases)")
    for subset, label in ((off, "off the ends"), (edge, "edge loaded")):
        for k, name in enumerate(names):
            if label == "edge loaded" and name == "p_max":
                continue
            e, where = worst(subset, "iso", k)
            say(f"  {label:13s} {name:7s} largest |error| {e:7.2%}   ({where})")
    say("  all cases: dF/dd largest |error| "
        f"{max(abs(r['iso_k'][0]) for r in rows):.2%}, dM/dtheta "
        f"{max(abs(r['iso_k'][1]) for r in rows):.2%}")
    say("")
    t_rt = [r["seconds"] for r in rows]
    c_rt = [r["cpu"] for r in rows]
    t_tot = [r["seconds_total"] for r in rows]
    say(f"runtime solve (default slices): CPU median {statistics.median(c_rt) * 1e3:.1f} ms, "
        f"largest {max(c_rt) * 1e3:.0f} ms; wall median {statistics.median(t_rt) * 1e3:.1f}"
        f" ms, largest {max(t_rt) * 1e3:.0f} ms (model construction included: wall median "
        f"{statistics.median(t_tot) * 1e3:.1f} ms)")
    for t, scale, nx, ny, sec, cpu, steps in bem:
        tilt = "free" if t["tilt"] is None else f"{t['tilt'] * 1e3:g} mrad"
        say(f"BEM solve {nx:4d} x {ny:3d} cells: CPU {cpu:6.2f} s, wall {sec:6.2f} s "
            f"({steps} Newton steps; {t['profile']}, F = {t['force']:g} N, tilt = {tilt})")
    if bem:
        for scale in (1, 2):
            med = statistics.median(b[5] for b in bem if b[1] == scale)
            say(f"ratio of CPU medians, BEM ({'coarse' if scale == 1 else 'fine'} grid) / "
                f"runtime solve: {med / statistics.median(c_rt):.0f}")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--table", type=Path, default=REPO / "tables" / "roller_accuracy.csv")
    parser.add_argument("--repeat", type=int, default=5, help="runtime solves per case")
    parser.add_argument("--bem-cases", type=int, default=4,
                        help="cases whose BEM solve is timed (default 4)")
    parser.add_argument("--out", type=Path,
                        default=REPO / "tools" / "benchmarks" / "results" / "roller_accuracy.txt")
    args = parser.parse_args(argv)
    from linecontact.tables import read_table
    table = read_table(args.table.stem, directory=args.table.parent)
    t0 = time.perf_counter()
    rows = accuracy(table, args.repeat)
    bem = bem_times(table, args.bem_cases) if args.bem_cases else []
    head = (f"python -m tools.benchmarks.bench_roller {' '.join(argv or sys.argv[1:])}\n"
            f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {platform.node()}, "
            f"Python {platform.python_version()}, numpy {np.__version__}; "
            f"table version: {table.meta.get('version', '?')}\n")
    text = head + "\n" + report(rows, bem, args.table) + \
        f"\n\nbenchmark wall time {time.perf_counter() - t0:.0f} s\n"
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
