"""The BEM sweep's preconditioner on the quarter against the padded one, paired.

The preconditioned conjugate gradient of tools.bem.solver applies M ~ K^-1 once per
step. Before: M was the inverse of the kernel's symmetric-periodic embedding on the
zero-padded grid (2 mx x 2 my, the operator's own transforms with the spectrum
inverted: as costly as an operator application). Now
(tools.bem.halfspace.SymmetricOperator.precondition): the same embedding on the
quarter itself (mx x my, no padding: a quarter of the transform size). This script runs
the paper's sweep (tools.bem.cylinder.sweep, punch stiffness, 100 steps to 0.15 R,
tol 1e-6, one FFT thread) with each, alternating in one process, and prints the CPU
time (``time.process_time``, median of ``--repeat``), operator applications, and the
largest relative change of F and k between the two.

Usage::

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_bem_quarter_preconditioner \\
        --n 256 --l-over-r 5 --repeat 3
"""
from __future__ import annotations

import argparse
import platform
import time

import numpy as np

from tools.bem import halfspace
from tools.bem.cylinder import sweep


def padded_precondition(self, g):
    """The preconditioner before: the operator's transforms (zero-padded 2mx x 2my)
    with the kernel's spectrum inverted (divisors at least 1e-3 of the largest)."""
    if not hasattr(self, "_kinv_padded"):
        kh = self._khat
        scale = 1.0 if self.backend != "pyfftw" else (4.0 * kh.size) ** 2
        self._kinv_padded = np.ascontiguousarray(
            1.0 / np.maximum(kh, 1e-3 * np.abs(kh).max()) / scale)
    saved = self._khat
    self._khat = self._kinv_padded
    try:
        return self(g)
    finally:
        self._khat = saved


def run(which, n, q):
    quarter = halfspace.SymmetricOperator.precondition
    if which == "padded":
        halfspace.SymmetricOperator.precondition = padded_precondition
    try:
        t0 = time.process_time()
        r = sweep(q, n=n, steps=100, d_max_over_r=0.15, radius=1.0, estar=1.0, tol=1e-6,
                  stiffness="punch", workers=1, progress=False, raise_on_failure=False)
        return time.process_time() - t0, r
    finally:
        halfspace.SymmetricOperator.precondition = quarter


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--l-over-r", type=float, default=5.0)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    cpu = {"padded": [], "quarter": []}
    res = {}
    for _ in range(args.repeat):
        for which in ("padded", "quarter"):
            t, r = run(which, args.n, args.l_over_r)
            cpu[which].append(t)
            res[which] = r
    a, b = res["padded"], res["quarter"]
    ratios = np.array(cpu["padded"]) / np.array(cpu["quarter"])
    print(f"# bench_bem_quarter_preconditioner: L/R = {args.l_over_r:g}, {args.n}^2, 100 "
          f"steps, tol 1e-6, {a.settings['backend']} (1 thread); {platform.machine()}, "
          f"Python {platform.python_version()}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    for name, r in res.items():
        print(f"{name:8}: CPU median {np.median(cpu[name]):.2f} s (runs "
              f"{', '.join(f'{t:.2f}' for t in cpu[name])}); operator applications "
              f"{int(r.iterations.sum())} (contact {int(r.contact_iterations.sum())}); "
              f"all converged {bool(r.converged.all())}")
    print(f"CPU padded / quarter: median of pairs {np.median(ratios):.2f} "
          f"({', '.join(f'{x:.2f}' for x in ratios)})")
    print(f"largest relative change F {np.nanmax(abs(b.force / a.force - 1)):.2g}, "
          f"k {np.nanmax(abs(b.stiffness / a.stiffness - 1)):.2g}")


if __name__ == "__main__":
    main()
