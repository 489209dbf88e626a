"""Issue 17's accuracy target: the runtime slice stresses against the 3D field.

    python -m tools.benchmarks.bench_stresses            # seconds: it reads the table
    python -m tools.benchmarks.bench_stresses --grid-case A-circular_crown-q800-t2 \
        --grid-case A-lundberg-q100-t2                   # adds the 3D grid check (minutes)

What it measures, from tables/stress_accuracy.csv (tools/studies/stress_study.py: the
3D field of tools/bem/stress.py below the 3D BEM pressure and traction, finer of two
nested grids, against linecontact.stresses.roller_stresses): the largest |rt/3D - 1|
of each measure where the contact stays off the roller ends (target 1 %), without
and with friction, and where it is edge loaded (stated), for the 3D-corrected runtime
(the default) and the strips alone, with the 3D field's own grid change;
``--grid-case``: the 3D reference of a study case on three nested grids.

The stresses' cost against the contact solve is the ``stresses`` benchmark of the
runner (``python -m tools.benchmarks stresses``, tools/benchmarks/results/stresses.txt).

Prints a report and writes it to tools/benchmarks/results/stresses_accuracy.txt.
"""
from __future__ import annotations

import argparse
import platform
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
    ap.add_argument("--out", type=Path, default=REPO / "tools" / "benchmarks" / "results"
                    / "stresses_accuracy.txt")
    ap.add_argument("--grid-case", action="append", default=[],
                    help="a study case key (e.g. A-circular_crown-q800-t2) whose 3D "
                         "reference is solved on nested grids (--grid-n-x); repeatable")
    ap.add_argument("--grid-n-x", default="64,128",
                    help="coarse cells along x of each nested pair (default 64,128: "
                         "64 x 32, 128 x 64 and 256 x 128 cells)")
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
    text = "\n".join(lines) + "\n"
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
