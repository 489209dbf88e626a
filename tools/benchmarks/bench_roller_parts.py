"""Issue 20, item 2: what the parts of a profiled-roller solve outside the Newton steps
cost inside a solve: the regrid (``ProfiledRoller._grid``), the construction
(``ProfiledRoller.__init__``) and the post-processing (``ProfiledRoller._solution``).

    OPENBLAS_NUM_THREADS=1 python tools/benchmarks/bench_roller_parts.py [--src DIR]
        [--repeat 200] [--engine numba] [--tilt 2e-3]

The case of ``bench_roller_speed``: the ISO 16281 profile of tables/roller_accuracy.csv
(D = 10 mm, L = 14 mm, E* = 115.385 GPa), 4200 N, tilt 2 mrad (or ``--tilt free``), a
new roller per solve (its default 50 slices). Each of the three methods is wrapped in a
timer (``time.perf_counter``) and the medians of their calls over ``--repeat`` solves
(after 20 to warm up) are printed, with the calls per solve and the median solve.
Inside a solve each part runs once between the compiled kernels and dense solves, so
it runs with cold caches: about twice its time in a loop of its own, which is why it
is timed here in place. ``--src DIR`` imports ``linecontact`` from the checkout DIR
instead (the same command times an older version; the methods it wraps exist since
issue 20's fourth round). Wall time of the wrapped calls (the timer's own cost, about
0.1 us a call, included); the figures move with the machine's load: compare runs
taken close together, alternating the checkouts.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

D, L, ESTAR = 10e-3, 14e-3, 115.385e9
FORCE = 4200.0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--src", default=None, help="checkout whose linecontact to time")
    ap.add_argument("--repeat", type=int, default=200)
    ap.add_argument("--engine", default="numba", choices=("numpy", "numba", "auto"))
    ap.add_argument("--tilt", default="2e-3", help="tilt [rad] or 'free'")
    args = ap.parse_args(argv)
    if args.src:
        sys.path.insert(0, str(Path(args.src).resolve()))
    import linecontact
    from linecontact.profiles import ISO16281Profile
    from linecontact.roller import ProfiledRoller
    from linecontact.roller import model

    tilt = "free" if args.tilt == "free" else float(args.tilt)
    prof = ISO16281Profile(L, D)
    times = {"_grid": [], "__init__": [], "_solution": []}

    def timed(name):
        inner = getattr(model.ProfiledRoller, name)

        def wrapper(*a, **k):
            t0 = time.perf_counter()
            out = inner(*a, **k)
            times[name].append(time.perf_counter() - t0)
            return out
        setattr(model.ProfiledRoller, name, wrapper)

    for name in times:
        timed(name)

    def solve():
        return ProfiledRoller(D / 2, L, ESTAR, prof, engine=args.engine).at_force(
            FORCE, tilt=tilt)

    for _ in range(20):
        solve()
    for v in times.values():
        v.clear()
    total = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        solve()
        total.append(time.perf_counter() - t0)
    print(f"linecontact from {Path(linecontact.__file__).parent.parent}, engine "
          f"{args.engine}, tilt {args.tilt}, {args.repeat} solves (wall, medians)")
    for name, v in times.items():
        print(f"  {name:10s} {len(v) / args.repeat:4.1f} calls a solve, "
              f"{statistics.median(v) * 1e6:7.1f} us a call")
    print(f"  one solve  {statistics.median(total) * 1e3:.3f} ms")


if __name__ == "__main__":
    main()
