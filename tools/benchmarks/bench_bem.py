"""Which ideas pay in the BEM? Ratios measured in one run on this machine.

    python -m tools.benchmarks.bench_bem            # about a minute on 2 cores

1. operator: the mirror-symmetric DCT form against the plain zero-padded DC-FFT, same
   physical grid (the paper's 512 x 512), time per application (results agree to 1e-15);
2. backend: planned FFTW r2r transforms against scipy.fft, for the symmetric operator
   at the paper's grid and at a long-strip grid of the universal study, with 1 thread
   (how the studies run, one process per core) and 2;
3. warm start: a 20-step sweep (L/R = 5, 256 x 256) solved with each step started
   from the extrapolation of the previous two, against cold starts;
4. processes: the same four small sweeps in 1 process with 2 FFT threads against
   2 processes with 1 thread each (how tools/paper_study and tools/universal_study run).

Prints a table of times and ratios; the numbers recorded in tools/benchmarks/README.md
come from this script.
"""
from __future__ import annotations

import argparse
import multiprocessing as mp
import time

import numpy as np

from tools.bem.cylinder import Grid, sweep
from tools.bem.halfspace import DCFFTOperator, SymmetricOperator, unfold
from tools.bem.solver import solve_contact


def _time(fn, repeat):
    fn()
    t = time.perf_counter()
    for _ in range(repeat):
        fn()
    return (time.perf_counter() - t) / repeat


def bench_operators(repeat):
    rng = np.random.default_rng(0)
    rows = []
    q = rng.random((256, 256))
    sym = SymmetricOperator(256, 256, 1.0, 1.0, backend="scipy")
    dc = DCFFTOperator(512, 512, 1.0, 1.0, backend="scipy")
    full = unfold(q)
    assert np.allclose(sym(q), dc(full)[256:, 256:], rtol=1e-12)
    t_sym = _time(lambda: sym(q), repeat)
    t_dc = _time(lambda: dc(full), repeat)
    rows.append(("512x512: DC-FFT / symmetric DCT (scipy)", t_dc, t_sym))
    try:
        import pyfftw  # noqa: F401
    except ImportError:
        rows.append(("pyfftw not installed: backend comparison skipped", np.nan, np.nan))
        return rows
    for shape in [(256, 256), (1024, 40)]:
        q = rng.random(shape)
        for workers in (1, 2):
            a = SymmetricOperator(*shape, 1.0, 0.01, backend="scipy", workers=workers)
            b = SymmetricOperator(*shape, 1.0, 0.01, backend="pyfftw", workers=workers)
            rows.append((f"quarter {shape[0]}x{shape[1]}, {workers} thread(s): scipy / pyfftw",
                         _time(lambda: a(q), repeat), _time(lambda: b(q), repeat)))
    return rows


def bench_warm_start():
    R, L, d_max, steps, n = 1.0, 5.0, 0.15, 20, 256
    Y = np.sqrt(2 * R * d_max)
    g = Grid(n // 2, n // 2, L / n, 2 * Y / n)
    op = SymmetricOperator(g.mx, g.my, g.dx, g.dy, backend="scipy")
    h = np.broadcast_to(g.y ** 2 / (2 * R), (g.mx, g.my))
    depths = d_max * np.arange(1, steps + 1) / steps
    res = {}
    for mode in ("cold", "warm"):
        t = time.perf_counter()
        hist, its = [], 0
        for i, d in enumerate(depths):
            p0 = None
            if mode == "warm" and len(hist) == 2:
                p0 = 2 * hist[1] - hist[0]
            elif mode == "warm" and hist:
                p0 = hist[-1]
            s = solve_contact(op, h - d, d, tol=1e-6, p0=p0)
            its += s.iterations
            hist = (hist + [s.pressure])[-2:]
        res[mode] = (time.perf_counter() - t, its)
    return [("20-step sweep: cold / warm start (time)", res["cold"][0], res["warm"][0]),
            ("20-step sweep: cold / warm start (operator applications)",
             res["cold"][1], res["warm"][1])]


def _one(lr):
    return sweep(lr, n=128, steps=20, progress=False, backend="scipy", workers=1).wall_time


def bench_processes():
    lrs = [0.5, 1.0, 5.0, 10.0]
    t = time.perf_counter()
    for lr in lrs:
        sweep(lr, n=128, steps=20, progress=False, backend="scipy", workers=2)
    t1 = time.perf_counter() - t
    t = time.perf_counter()
    with mp.get_context("fork").Pool(2) as pool:
        pool.map(_one, lrs)
    t2 = time.perf_counter() - t
    return [("4 sweeps 128^2: 1 process x 2 threads / 2 processes x 1 thread", t1, t2)]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=30)
    args = parser.parse_args(argv)
    rows = bench_operators(args.repeat) + bench_warm_start() + bench_processes()
    print(f"{'comparison':66s} {'first':>10s} {'second':>10s} {'ratio':>7s}")
    for name, a, b in rows:
        print(f"{name:66s} {a:10.4g} {b:10.4g} {a / b:7.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
