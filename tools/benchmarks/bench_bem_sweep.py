"""The paper's BEM sweep of this checkout against an earlier one, paired: CPU time,
operator applications per load step, and the results' change.

Each run is a child process (``python -c``, ``PYTHONPATH`` set to one checkout) that
runs tools.bem.cylinder.sweep (punch stiffness, 100 steps to d = 0.15 R, tol 1e-6, one
FFT thread, the default FFT backend) for every L/R given, after a short warm-up sweep
(20 steps) that makes FFTW's plans for the grid's strips: the study's worker processes
make them once for all their L/R. It reports the CPU time of each sweep
(``time.process_time`` in the child), its operator applications per step (contact
solves, the first pass on the contact's rows included, and punch solves; an application
on a narrower strip costs less, in proportion to its rows), and the largest relative
change of F and k between the two checkouts. The runs alternate (before, after, before,
after, ...) so that a change of the machine's load hits both alike; the ratio is the
median over the pairs.

Usage (from the repository root; BEFORE is a checkout of the earlier commit, e.g.
``git worktree add ../before COMMIT``)::

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_bem_sweep --before ../before \\
        --n 512 --l-over-r 0.1,5,20 --repeat 2 [--save FILE]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from tools.benchmarks import report

ROOT = Path(__file__).resolve().parents[2]

CHILD = r"""
import json, sys, time
import numpy as np
from tools.bem.cylinder import sweep
n, values = int(sys.argv[1]), [float(v) for v in sys.argv[2].split(",")]
sweep(values[0], n=n, steps=20, tol=1e-6, workers=1, progress=False)   # plans
for q in values:
    c0 = time.process_time()
    r = sweep(q, n=n, steps=100, d_max_over_r=0.15, tol=1e-6, stiffness="punch",
              workers=1, progress=False, raise_on_failure=False)
    cpu = time.process_time() - c0
    cits = r.contact_iterations if r.contact_iterations is not None else r.iterations
    print(json.dumps(dict(l_over_r=q, cpu=cpu, force=r.force.tolist(),
                          stiffness=r.stiffness.tolist(), ops=r.iterations.tolist(),
                          contact_ops=np.asarray(cits).tolist(),
                          converged=bool(np.all(r.converged)))), flush=True)
"""


def run(checkout, n, values):
    env = dict(os.environ, PYTHONPATH=str(checkout), OPENBLAS_NUM_THREADS="1")
    r = subprocess.run([sys.executable, "-c", CHILD, str(n), ",".join(map(str, values))],
                       cwd=checkout, env=env, capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"the sweep in {checkout} failed:\n{r.stderr[-3000:]}")
    return {d["l_over_r"]: d for d in map(json.loads, r.stdout.splitlines())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", type=Path, required=True,
                    help="a checkout of the earlier commit")
    ap.add_argument("--n", type=int, default=512)
    ap.add_argument("--l-over-r", default="0.1,5,20")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--save", type=Path, default=None, help="append the report here")
    args = ap.parse_args(argv)
    values = [float(v) for v in args.l_over_r.split(",")]
    runs = {"before": [], "after": []}
    for _ in range(args.repeat):
        runs["before"].append(run(args.before.resolve(), args.n, values))
        runs["after"].append(run(ROOT, args.n, values))
    lines = [f"# bench_bem_sweep {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
             f"{platform.machine()}, {os.cpu_count()} CPUs, Python "
             f"{platform.python_version()}; grid {args.n}^2, 100 steps, tol 1e-6; "
             f"{args.repeat} pair(s); load average {' '.join(f'{v:.1f}' for v in os.getloadavg())}",
             "L/R | CPU before / after (median of pairs) | ops/step before (contact + punch) "
             "| ops/step after | largest change F, k | converged"]
    tot_b = tot_a = 0.0
    for q in values:
        cb = [r[q]["cpu"] for r in runs["before"]]
        ca = [r[q]["cpu"] for r in runs["after"]]
        ratio = float(np.median([b / a for b, a in zip(cb, ca)]))
        tot_b += float(np.median(cb))
        tot_a += float(np.median(ca))
        b0, a0 = runs["before"][0][q], runs["after"][0][q]

        def per_step(d):
            ops = np.asarray(d["ops"])
            c = np.asarray(d["contact_ops"])
            return f"{np.median(ops):.0f} ({np.median(c):.0f} + {np.median(ops - c):.0f})"

        dF = np.max(np.abs(np.asarray(a0["force"]) / np.asarray(b0["force"]) - 1))
        dk = np.max(np.abs(np.asarray(a0["stiffness"]) / np.asarray(b0["stiffness"]) - 1))
        lines.append(f"{q:g} | {np.median(cb):.2f} / {np.median(ca):.2f} s = {ratio:.2f} "
                     f"(pairs {', '.join(f'{b / a:.2f}' for b, a in zip(cb, ca))}) | "
                     f"{per_step(b0)} | {per_step(a0)} | {dF:.2g}, {dk:.2g} | "
                     f"{b0['converged']} / {a0['converged']}")
    lines.append(f"sum of medians: {tot_b:.2f} / {tot_a:.2f} s = {tot_b / tot_a:.2f}")
    report("\n".join(lines), args.save)


if __name__ == "__main__":
    main()
