"""Issue 17 targets: the runtime slice stresses against the 3D field, and their cost.

    python -m tools.benchmarks.bench_stresses            # a few minutes on 2 cores
    python -m tools.benchmarks.bench_stresses --grid-case A-circular_crown-q800-t2 \
        --grid-case A-lundberg-q100-t2                   # adds the 3D grid check

What it measures:

1. accuracy, from tables/stress_accuracy.csv (tools/studies/stress_study.py: the 3D
   field of tools/bem/stress.py below the 3D BEM pressure and traction, finer of two
   nested grids, against linecontact.stresses.roller_stresses): the largest
   |rt/3D - 1| of each measure where the contact stays off the roller ends (target
   1 %), without and with friction, and where it is edge loaded (stated), for the
   3D-corrected runtime (the default) and the strips alone, with the 3D field's own
   grid change;
2. time: per study roller (each profile, three loads, two tilts), the CPU time
   (time.process_time) of the runtime contact solve (ProfiledRoller.at_force at its
   default slices, a fresh model built beforehand: no warm start from a previous solve) and
   of its stresses (roller_stresses with the 3D correction, the default), median of
   ``--repeat``; the stresses' first call (the cached strip maxima for a new (mu, nu),
   a grid search and ten zooms) is timed apart. Target: the stresses within
   twice the contact solve's time.

``--engine`` picks the contact solve's engine (``ProfiledRoller(engine=...)``, default
"auto": "c" where the C extension is built, else numpy); the stresses' corner sums are
C where the extension linecontact._cstresses is built, else numpy (the report says
which).

With ``--against DIR`` (another checkout) the timing also runs that checkout's
``linecontact/stresses.py`` on the same solutions, in turn with this one's (loaded as a
module of this checkout's package, so only the stresses module differs), and reports
the CPU ratio this/other per roller (median of ``--repeat`` each): a paired comparison
on a shared machine, where absolute times drift with the load; and the other module's
stresses/solve ratio on the same solves (its "before"); and whether the two modules give
the same worst values (largest relative difference, how many on another slice).

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


def _fmt(e, sel):
    return f"{np.abs(e)[sel].max():.2%}" if sel.any() else "-"


def accuracy(lines):
    from linecontact.tables import read_table
    t = read_table("stress_accuracy")
    c = {k: np.asarray(v) for k, v in t.columns.items()}
    edge = (c["bem_edge"] > 0) | (c["rt_edge"] > 0)     # as the study's header
    off = ~edge
    lines.append(f"accuracy (tables/stress_accuracy.csv, {len(edge)} cases, "
                 f"{int(off.sum())} off the ends, {int(edge.sum())} edge loaded; "
                 f"grid {t.meta['grid']}; generated {t.meta['date']}, {t.meta['version']}):")
    mu_tags = sorted({k.split("_")[1] for k in c if k.startswith("err_mu")})
    head = (f"{'measure':18s} {'3D-corr. off':>12s} {'median':>7s} "
            + "".join(f"{'mu 0.' + tg[2:] + ' off':>11s}" for tg in mu_tags)
            + f" {'strips off':>11s} {'3D-corr. edge':>14s} {'strips edge':>12s} "
              f"{'3D grid change off/edge':>24s}  target 1 % off the ends")
    lines.append(head)
    for m in MEASURES:
        e, es = c[f"err_{m}"], c[f"err_strip_{m}"]
        ch = np.abs(c[f"bem_change_{m}"])
        worst = max([np.abs(e)[off].max()] + [np.abs(c[f"err_{tg}_{m}"])[off].max()
                                              for tg in mu_tags])
        lines.append(f"{m:18s} {_fmt(e, off):>12s} {np.median(np.abs(e)[off]):7.2%} "
                     + "".join(f"{_fmt(c[f'err_{tg}_{m}'], off):>11s}" for tg in mu_tags)
                     + f" {_fmt(es, off):>11s} {_fmt(e, edge):>14s} {_fmt(es, edge):>12s} "
                       f"{ch[off].max():11.2%} / {ch[edge].max() if edge.any() else np.nan:.2%}"
                       f"  {'met' if worst <= 0.01 else 'NOT met'}")
    lines.append("largest |err| off the ends by profile, 3D-corrected (strips alone):")
    profiles = c["profile"]
    for code in sorted(set(profiles.tolist())):
        for L, name in ((0.014, "L = 14 mm"), (0.03, "L = 30 mm")):
            sel = off & (profiles == code) & np.isclose(c["roller_length"], L)
            if sel.any():
                lines.append(f"  profile {int(code)} ({name}, {int(sel.sum())} cases): " + ", ".join(
                    f"{m} {_fmt(c[f'err_{m}'], sel)} ({_fmt(c[f'err_strip_{m}'], sel)})"
                    for m in MEASURES))


def _other_stresses(directory):
    """DIR/linecontact/stresses.py as a module of this checkout's package."""
    import importlib.util
    path = Path(directory).resolve() / "linecontact" / "stresses.py"
    if not path.is_file():
        raise SystemExit(f"--against {directory}: no {path}")
    spec = importlib.util.spec_from_file_location("linecontact._against_stresses", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def timing(lines, repeat, against=None, engine="auto"):
    from linecontact.roller import ProfiledRoller
    from linecontact.stresses import roller_stresses, strip_maxima
    other = _other_stresses(against) if against else None
    if other is not None:
        other.strip_maxima(0.0, 0.3)
    paired = []
    # largest relative difference of a worst value, checks, on another slice, largest
    # shift of (y, z) on the same slice [m]
    agree = [0.0, 0, 0, 0.0, 0]     # and of those the mirror slice, untilted
    from tools.studies import stress_study as ss
    from tools.studies.roller_study import make_profile

    t0 = time.process_time()
    # the first call for a (mu, nu) not asked before: the strip maxima are computed
    c0 = time.process_time()
    strip_maxima(0.05, 0.31)
    first = time.process_time() - c0
    strip_maxima(0.0, 0.3)   # the study's (mu, nu), cached before the timed loop
    ratios, solves, stresses, keys, others = [], [], [], [], []
    tasks = ss.study_tasks()
    for task in tasks:
        prof = make_profile(task["profile"], task["length"], task["radius"], task["estar"])
        ts, tt, to = [], [], []
        for _ in range(repeat):
            # a fresh model each time: a model keeps its last solution as the next
            # solve's warm start, which makes a repeated solve of the same case a
            # fraction of a user's one solve
            model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof,
                                   engine=engine)
            c0 = time.process_time()
            sol = model.at_force(task["force"], tilt=task["tilt"])
            c1 = time.process_time()
            mine = roller_stresses(sol, 0.0, 0.3, roller=model)   # 3D-corrected (default)
            c2 = time.process_time()
            ts.append(c1 - c0)
            tt.append(c2 - c1)
            if other is not None:
                c3 = time.process_time()
                theirs = other.roller_stresses(sol, 0.0, 0.3, roller=model)
                to.append(time.process_time() - c3)
                for name in MEASURES:               # the same worst values, where
                    u, v = mine.worst[name], theirs.worst[name]
                    agree[0] = max(agree[0], abs(u["value"] - v["value"]) / abs(v["value"]))
                    agree[1] += 1
                    agree[2] += u["slice"] != v["slice"]
                    agree[4] += (u["slice"] != v["slice"] and not task["tilt"]
                                 and u["slice"] + v["slice"] == len(sol.x) - 1)
                    if u["slice"] == v["slice"]:
                        agree[3] = max(agree[3], abs(u["y"] - v["y"]), abs(u["z"] - v["z"]))
        if to:
            paired.append(statistics.median(tt) / statistics.median(to))
            others.append(statistics.median(to) / statistics.median(ts))
            to.clear()
        if ts:
            solves.append(statistics.median(ts))
            stresses.append(statistics.median(tt))
            ratios.append(stresses[-1] / solves[-1])
            keys.append(task["key"])
    k = int(np.argmax(ratios))
    lines.append(f"largest ratio: {keys[k]} (solve {solves[k] * 1e3:.1f} ms, stresses "
                 f"{stresses[k] * 1e3:.1f} ms)")
    from linecontact import stresses as _st
    lines.append(f"engine {engine!r}: the contact solve's, as ProfiledRoller(engine=...); the "
                 f"stresses' corner sums: {_st._CORNERS[0]} (C where the extension "
                 "linecontact._cstresses is built, else numpy)")
    lines.append(f"time (CPU, median of {repeat} per case, {len(ratios)} cases): contact "
                 f"solve median {statistics.median(solves) * 1e3:.1f} ms; stresses median "
                 f"{statistics.median(stresses) * 1e3:.3f} ms; ratio stresses/solve median "
                 f"{statistics.median(ratios):.4f}, largest {max(ratios):.4f} (target <= 2: "
                 f"{'met' if max(ratios) <= 2 else 'NOT met'})")
    if paired:
        lines.append(f"paired against the stresses module of {Path(against).resolve().name}/ "
                     f"(the same solutions, "
                     f"in turn): CPU of the stresses this/other, median {statistics.median(paired):.3f}, "
                     f"range {min(paired):.3f}-{max(paired):.3f} over {len(paired)} rollers; "
                     f"its stresses/solve ratio median {statistics.median(others):.4f}, largest "
                     f"{max(others):.4f} ({keys[int(np.argmax(others))]})")
        lines.append(f"worst values against {Path(against).resolve().name}/ (mu 0, nu 0.3, "
                     f"{agree[1]} checks: 3 measures x {repeat} solves x {len(paired)} "
                     f"rollers): largest relative difference {agree[0]:.2g}; "
                     f"{agree[2]} on another slice ({agree[4]} of them the mirror slice of "
                     f"an untilted roller: a tie decided by rounding), (y, z) on the same "
                     f"slice within "
                     f"{agree[3]:.2g} m")
    lines.append(f"first call of a new (mu, nu) (strip maxima computed and cached): "
                 f"{first * 1e3:.0f} ms CPU, once per process")
    lines.append(f"(timing section: {time.process_time() - t0:.0f} s CPU)")


def grid_convergence(lines, keys, n_xs):
    """The 3D reference of the study's cases `keys` on the nested grids n_x x n_x/2 and
    2 n_x x n_x (tools.studies.stress_study.bem_case) for each n_x: the maxima of the
    three measures [MPa] and their depths [um] on each grid."""
    from tools.studies import stress_study as ss
    lines.append("grid convergence of the 3D reference (cells along x x across; each "
                 "run solves a coarse and a fine grid on its own adapted window):")
    for key in keys:
        for n in n_xs:
            task = [t for t in ss.study_tasks(n_x=n, n_y=n // 2) if t["key"] == key]
            if not task:
                raise SystemExit(f"--grid-case {key!r} is not a study case")
            t0 = time.perf_counter()
            r = ss.bem_case(task[0])
            for g, m in (("coarse", 1), ("fine", 2)):
                lines.append(f"  {key} {m * n} x {m * n // 2}: " + ", ".join(
                    f"{k} {r[g][k]['value'] / 1e6:.3f} MPa at {r[g][k]['z'] * 1e6:.2f} um"
                    for k in MEASURES))
            lines.append(f"    ({time.perf_counter() - t0:.0f} s wall)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", type=Path, default=REPO / "tools" / "benchmarks" / "results"
                    / "stresses.txt")
    ap.add_argument("--grid-case", action="append", default=[],
                    help="a study case key (e.g. A-circular_crown-q800-t2) whose 3D "
                         "reference is solved on nested grids (--grid-n-x); repeatable")
    ap.add_argument("--grid-n-x", default="64,128",
                    help="coarse cells along x of each nested pair (default 64,128: "
                         "64 x 32, 128 x 64 and 256 x 128 cells)")
    ap.add_argument("--skip-timing", action="store_true")
    ap.add_argument("--engine", default="auto", choices=("auto", "numpy", "c"),
                    help="the contact solve's engine (ProfiledRoller(engine=...); default "
                         "auto, numpy for the few solves of this benchmark)")
    ap.add_argument("--against", default=None, metavar="DIR",
                    help="another checkout: time its linecontact/stresses.py in turn with "
                         "this one's on the same solutions")
    args = ap.parse_args(argv)
    import linecontact
    lines = [f"bench_stresses: linecontact {linecontact.__version__}, Python "
             f"{platform.python_version()}, numpy {np.__version__}, "
             f"{time.strftime('%Y-%m-%d')}", ""]
    accuracy(lines)
    if args.grid_case:
        lines.append("")
        grid_convergence(lines, args.grid_case,
                         [int(v) for v in args.grid_n_x.split(",")])
    if not args.skip_timing:
        lines.append("")
        timing(lines, args.repeat, args.against, args.engine)
    text = "\n".join(lines) + "\n"
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
