"""Wall time of the whole paper study, and its results against the shipped tables
(issue 20, item 4: 29 L/R, 512 x 512 cells, tol 1e-6, within 5 minutes on 2 cores).

Runs the study as a user does, one process::

    python -m tools.build_tables paper --out TMP --workers W [--l-over-r LIST] [--n N]

and prints its wall time and CPU time (the study process and its worker processes,
``resource.getrusage``), the machine's load average before and after (a busy machine
inflates the wall time: run it on a quiet one), and, when the settings are the shipped
tables' (512 x 512, 100 steps, d_max 0.15 R, tol 1e-6), the largest relative change of
F and k over every step against ``tables/bem_paper_curves.csv`` and of alpha, beta
against ``tables/lipopov_regenerated.csv``. The study's own tables go to a temporary
folder; the repository's tables are never touched.

Usage (from the repository root)::

    python -m tools.benchmarks.bench_paper_study                  # the whole study
    python -m tools.benchmarks.bench_paper_study --l-over-r 5     # one L/R, 512^2
    python -m tools.benchmarks.bench_paper_study --n 128 --l-over-r 1,5   # a quick check

``--save FILE`` appends the printed lines to FILE (e.g. results/paper_study_wall.txt).
"""
from __future__ import annotations

import argparse
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from tools.benchmarks import report

ROOT = Path(__file__).resolve().parents[2]
TARGET_S = 300.0


def _load():
    try:
        return " ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        return "n/a"


def _per_task(out):
    """One line: the CPU seconds of each L/R's sweep, from the study table's header
    (what the longest-first order of tools.studies.paper_sweep relies on)."""
    import re
    path = out / "bem_paper_curves.csv"
    if not path.exists():
        return []
    with open(path, encoding="utf-8") as fh:
        head = "".join(ln for ln in fh if ln.startswith("#"))
    found = re.findall(r"L/R ([0-9.]+): [0-9.]+ s wall, ([0-9.]+) s CPU", head)
    if not found:
        return []
    return ["CPU per L/R [s]: " + ", ".join(f"{q} {c}" for q, c in found)]


def _compare(out, l_over_r):
    """Lines: largest relative change of F, k (per step) and alpha, beta against the
    shipped tables, on the L/R values run."""
    from linecontact.tables import read_table

    lines = []
    new = read_table("bem_paper_curves", directory=out).columns
    old = read_table("bem_paper_curves", directory=ROOT / "tables").columns
    key_old = {(round(float(q), 6), int(s)): i
               for i, (q, s) in enumerate(zip(old["L_over_R"], old["step"]))}
    dF, dk, matched = [], [], 0
    for i, (q, s) in enumerate(zip(new["L_over_R"], new["step"])):
        j = key_old.get((round(float(q), 6), int(s)))
        if j is None:
            continue
        matched += 1
        dF.append(abs(new["F_over_EstarR2"][i] / old["F_over_EstarR2"][j] - 1))
        dk.append(abs(new["k_over_EstarR"][i] / old["k_over_EstarR"][j] - 1))
    if matched:
        lines.append(f"against tables/bem_paper_curves.csv ({matched} steps): largest "
                     f"relative change F {max(dF):.2g}, k {max(dk):.2g}; median F "
                     f"{np.median(dF):.2g}, k {np.median(dk):.2g}")
    new_c = read_table("lipopov_regenerated", directory=out).columns
    old_c = read_table("lipopov_regenerated", directory=ROOT / "tables").columns
    da, db = [], []
    for i, q in enumerate(new_c["L_over_R"]):
        j = np.flatnonzero(np.isclose(old_c["L_over_R"], q))
        if j.size:
            da.append(abs(new_c["alpha"][i] / old_c["alpha"][j[0]] - 1))
            db.append(abs(new_c["beta"][i] / old_c["beta"][j[0]] - 1))
    if da and len(l_over_r) > 1:
        lines.append(f"against tables/lipopov_regenerated.csv ({len(da)} L/R): largest "
                     f"relative change alpha {max(da):.2g}, beta {max(db):.2g}")
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--l-over-r", default=None,
                    help="L/R values (default: the paper's 29)")
    ap.add_argument("--n", type=int, default=512, help="grid cells per side (512)")
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--save", type=Path, default=None, help="append the report here")
    args = ap.parse_args(argv)

    with tempfile.TemporaryDirectory(prefix="lc_paper_") as tmp:
        cmd = [sys.executable, "-m", "tools.build_tables", "paper", "--out", tmp,
               "--workers", str(args.workers), "--n", str(args.n),
               "--steps", str(args.steps), "--no-progress"]
        if args.l_over_r:
            cmd += ["--l-over-r", args.l_over_r]
        load0 = _load()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if r.returncode:
            sys.exit(f"{' '.join(cmd)} failed ({r.returncode}):\n{r.stderr[-3000:]}")
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        values = (args.l_over_r.replace(",", " ").split() if args.l_over_r
                  else ["all 29"])
        lines = [
            f"# bench_paper_study {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
            f"{platform.machine()}, {os.cpu_count()} CPUs, Python "
            f"{platform.python_version()}",
            "command: python " + " ".join(cmd[1:]).replace(tmp, "TMP"),
            f"L/R: {' '.join(values)}; grid {args.n}^2; {args.steps} steps; "
            f"{args.workers} workers",
            f"wall {wall:.1f} s ({wall / 60:.2f} min; target {TARGET_S / 60:.0f} min for "
            f"the whole study at 512^2), CPU {cpu:.1f} s; load average before {load0}, "
            f"after {_load()}",
        ]
        lines += [ln for ln in r.stdout.splitlines() if ln.startswith("BEM ")]
        lines += _per_task(Path(tmp))
        if args.n == 512 and args.steps == 100:
            lines += _compare(Path(tmp), values)
        else:
            lines.append("(not compared with the shipped tables: other grid or steps)")
    report("\n".join(lines), args.save)


if __name__ == "__main__":
    main()
