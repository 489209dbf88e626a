"""One BLAS thread for the slice solver's small dense systems: a profiled-roller solve
with the library's limit (``linecontact._numerics.serial_blas``, the default) against
the same solve with BLAS left at its own thread count, alternated in one run (CPU
time, medians), and one 200 x 200 dense solve (a Newton step's at 100 slices) both ways,
with the load average of the machine printed beside them.

    python -m tools.benchmarks.bench_serial_blas [--repeat 15]

Run it WITHOUT ``OPENBLAS_NUM_THREADS=1`` (that would make both the same). The case is
the `roller` benchmark's (tools/benchmarks/suite.py): the ISO 16281 profile, D 10 mm, L 14 mm, 4200 N, tilt 2 mrad.
The gap is a matter of the machine's load: a multithreaded BLAS waits for its threads
to be scheduled, which on busy cores costs milliseconds per solve.
"""
from __future__ import annotations

import argparse
import os
import statistics
import time


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=15)
    a = ap.parse_args(argv)
    from threadpoolctl import threadpool_info

    from linecontact.roller import ProfiledRoller
    from tools.studies import roller_study as rs

    R, L, E = 5e-3, 14e-3, 115.385e9
    prof = rs.make_profile("iso16281", L, R, E)
    threads = [lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"]
    limited = ProfiledRoller.at_force
    free = ProfiledRoller.at_force.__wrapped__

    def one(fn):
        c0 = time.process_time()
        fn(ProfiledRoller(R, L, E, prof), 4200.0, tilt=2e-3)
        return time.process_time() - c0

    one(limited), one(free)          # first calls: tables, caches
    ts = {"one thread": [], "BLAS default": []}
    for _ in range(a.repeat):
        ts["one thread"].append(one(limited))
        ts["BLAS default"].append(one(free))
    med = {k: statistics.median(v) for k, v in ts.items()}
    # one 200 x 200 LU solve with three right-hand sides (a 100-slice Newton step)
    import numpy as np

    from linecontact._numerics import serial_blas
    rng = np.random.default_rng(0)
    A = rng.random((200, 200)) + 200 * np.eye(200)
    B = rng.random((200, 3))

    def solves(n=200):
        c0 = time.process_time()
        for _ in range(n):
            np.linalg.solve(A, B)
        return (time.process_time() - c0) / n

    small = {"one thread": serial_blas(solves)(), "BLAS default": solves()}
    print(f"BLAS threads by default: {threads}; load average {os.getloadavg()[0]:.1f}")
    for k, v in med.items():
        print(f"{k:>13}: median CPU {v * 1e3:.1f} ms ({a.repeat} solves)")
    print(f"ratio BLAS default / one thread: {med['BLAS default'] / med['one thread']:.2f}")
    for k, v in small.items():
        print(f"{k:>13}: one 200 x 200 solve (3 right-hand sides), CPU {v * 1e3:.3f} ms")
    print(f"ratio BLAS default / one thread: {small['BLAS default'] / small['one thread']:.0f}")


if __name__ == "__main__":
    main()
