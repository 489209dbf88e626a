"""The paper's cylinder sweep with the plain and the preconditioned BEM solver, paired.

For each grid, the same sweep (tools.bem.cylinder.sweep: L/R, 100 depth steps to
d = 0.15 R, tol 1e-6, flat-punch stiffness, pyFFTW with one thread when installed) runs
with the plain Polonsky-Keer iteration on the whole grid (``precondition=False,
windows=0``, the solver before) and with the preconditioned core on the overlapped strip
(the defaults), in pairs A B A B ...; prints per grid the operator applications per
depth step (contact solve and punch solve, median and largest; the preconditioned
solver also applies its preconditioner, at the cost of one operator application, once
per conjugate-gradient step), the CPU time of each sweep (``time.process_time``: the machine's load
does not enter; medians over the pairs) and their ratio, and the largest relative
change of F and k between the two (both meet the same tolerance).

Usage::

    python -m tools.benchmarks.bench_bem_precondition --n 128,256 --repeat 3
    python -m tools.benchmarks.bench_bem_precondition --n 512 --repeat 1 --out results/x.txt
"""
from __future__ import annotations

import argparse
import platform
import time

import numpy as np

from tools.bem.cylinder import sweep
from tools.bem.halfspace import best_backend

VARIANTS = {"plain": dict(precondition=False, windows=0),
            "preconditioned": dict(precondition=True, windows=8)}


def run(l_over_r, n, steps, tol, variant):
    t0 = time.process_time()
    res = sweep(l_over_r, n=n, steps=steps, tol=tol, backend=best_backend(), workers=1,
                progress=False, **VARIANTS[variant])
    cpu = time.process_time() - t0
    c = res.contact_iterations
    return res, cpu, c, res.iterations - c


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", default="128,256", help="full grids, comma separated")
    ap.add_argument("--l-over-r", type=float, default=5.0)
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--repeat", type=int, default=1, help="pairs per grid")
    ap.add_argument("--out", help="also write the report to this file")
    args = ap.parse_args(argv)
    lines = [f"# bench_bem_precondition: L/R = {args.l_over_r:g}, {args.steps} steps, "
             f"tol {args.tol:g}, backend {best_backend()} (1 thread); "
             f"{platform.machine()}, Python {platform.python_version()}, "
             f"numpy {np.__version__}; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}",
             "| grid | solver | contact op/step median (max) | punch op/step median (max) "
             "| CPU s (median) |",
             "|---|---|---|---|---|"]
    summary = []
    for n in (int(v) for v in args.n.split(",")):
        cpus = {v: [] for v in VARIANTS}
        last = {}
        for _ in range(args.repeat):
            for v in VARIANTS:
                res, cpu, c, p = run(args.l_over_r, n, args.steps, args.tol, v)
                cpus[v].append(cpu)
                last[v] = (res, c, p)
        for v in VARIANTS:
            res, c, p = last[v]
            lines.append(f"| {n}^2 | {v} | {np.median(c):g} ({c.max()}) | "
                         f"{np.median(p):g} ({p.max()}) | {np.median(cpus[v]):.2f} |")
        a, b = last["plain"][0], last["preconditioned"][0]
        ratio = np.median(cpus["plain"]) / np.median(cpus["preconditioned"])
        dF = np.max(np.abs(b.force / a.force - 1))
        dk = np.max(np.abs(b.stiffness / a.stiffness - 1))
        summary.append(f"{n}^2: CPU plain / preconditioned = {ratio:.2f}; largest relative "
                       f"change F {dF:.2g}, k {dk:.2g}")
    text = "\n".join(lines + [""] + summary)
    print(text)
    if args.out:
        with open(args.out, "w") as fh:
            fh.write(text + "\n")


if __name__ == "__main__":
    main()
