"""Cost of one direct kernel column (``SymmetricOperator.add_columns``, one cell with its
three mirror images) against one operator application (a cosine-transform pair), on the
quarter grids of the paper sweep's strips (tools.bem.cylinder.sweep at 512^2: 256 rows
along x, 64 to 256 along y), one FFT thread, the default backend (pyFFTW when installed).

It backs the figures in docs/theory.md ("Work per load step") and
``SymmetricOperator.sparse_limit``: how many single-cell corrections cost one transform
pair. Each figure is the median of ``--repeat`` timings of ``--loops`` calls
(``time.process_time``), so a loaded machine slows both sides alike.

Usage (from the repository root)::

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_add_columns [--save FILE]
"""
from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np

from tools.bem.halfspace import SymmetricOperator, best_backend
from tools.benchmarks import report


def _per_call(f, loops, repeat):
    times = []
    for _ in range(repeat):
        c0 = time.process_time()
        for _ in range(loops):
            f()
        times.append((time.process_time() - c0) / loops)
    return float(np.median(times))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mx", type=int, default=256)
    ap.add_argument("--my", default="64,128,256")
    ap.add_argument("--loops", type=int, default=40)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--save", default=None, help="append the report here")
    args = ap.parse_args(argv)
    backend = best_backend()
    lines = [f"# bench_add_columns {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
             f"{platform.machine()}, {os.cpu_count()} CPUs, Python "
             f"{platform.python_version()}; backend {backend}, 1 thread; "
             f"{args.repeat} x {args.loops} calls; load average "
             f"{' '.join(f'{v:.1f}' for v in os.getloadavg())}",
             "quarter | transform pair [ms] | one column [ms] | columns per pair | "
             "sparse_limit"]
    rng = np.random.default_rng(0)
    for my in (int(v) for v in args.my.split(",")):
        op = SymmetricOperator(args.mx, my, 1.0 / args.mx, 1.0 / my, 1.0, backend, 1)
        p = rng.random((args.mx, my))
        u = np.zeros((args.mx, my))
        cell = np.array([(args.mx // 3) * my + my // 3])
        value = np.array([1.0])
        t_pair = _per_call(lambda: op(p), args.loops, args.repeat)
        t_col = _per_call(lambda: op.add_columns(u, cell, value), args.loops, args.repeat)
        lines.append(f"{args.mx} x {my} | {1e3 * t_pair:.3f} | {1e3 * t_col:.3f} | "
                     f"{t_pair / t_col:.1f} | {op.sparse_limit}")
    report("\n".join(lines), args.save)


if __name__ == "__main__":
    main()
