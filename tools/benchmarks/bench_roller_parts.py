"""Issue 20, item 2: what the parts of a profiled-roller solve outside the Newton steps
cost inside a solve: the regrid (``ProfiledRoller._grid``), the construction
(``ProfiledRoller.__init__``) and the post-processing (``ProfiledRoller._solution``).

    OPENBLAS_NUM_THREADS=1 python tools/benchmarks/bench_roller_parts.py
        [--against DIR] [--repeat 200] [--engine c] [--tilt 2e-3]

The case of ``bench_roller_speed``: the ISO 16281 profile of tables/roller_accuracy.csv
(D = 10 mm, L = 14 mm, E* = 115.385 GPa), 4200 N, tilt 2 mrad (or ``--tilt free``), a
new roller per solve (its default 50 slices). Each of the three methods is wrapped in a
timer (``time.perf_counter``) and the medians of their calls over ``--repeat`` solves
(after 10 to warm up) are printed, with the calls per solve and the median solve.
Inside a solve each part runs once between the compiled kernels and dense solves, so
it runs with cold caches: about twice its time in a loop of its own, which is why it
is timed here in place. ``--against DIR`` times the checkout DIR too, in the same
process, the two checkouts' solves alternating (DIR's ``linecontact`` copied to a
temporary directory and imported as ``linecontact_b``, as ``bench_roller_speed
--interleave`` does): the machine's drift between processes then moves both alike.
Wall time of the wrapped calls (the timer's own cost, about 0.1 us a call, included).
"""
from __future__ import annotations

import argparse
import importlib
import statistics
import sys
import time
from pathlib import Path

D, L, ESTAR = 10e-3, 14e-3, 115.385e9
FORCE = 4200.0
PARTS = ("_grid", "__init__", "_solution")


def _timed(model, times):
    """Wrap the PARTS methods of model.ProfiledRoller in timers appending to times."""
    for name in PARTS:
        inner = getattr(model.ProfiledRoller, name)

        def wrapper(*a, _inner=inner, _name=name, **k):
            t0 = time.perf_counter()
            out = _inner(*a, **k)
            times[_name].append(time.perf_counter() - t0)
            return out
        setattr(model.ProfiledRoller, name, wrapper)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", default=None, help="a second checkout to time")
    ap.add_argument("--repeat", type=int, default=200)
    ap.add_argument("--engine", default="c", choices=("numpy", "c", "auto"))
    ap.add_argument("--tilt", default="2e-3", help="tilt [rad] or 'free'")
    args = ap.parse_args(argv)
    here = Path(__file__).resolve().parents[2]
    sys.path.insert(0, str(here))
    tilt = "free" if args.tilt == "free" else float(args.tilt)
    from tools.benchmarks.bench_roller_speed import checkout_packages
    with checkout_packages(args.against) as names:
        runs = []
        for pkg in names:
            roller = importlib.import_module(f"{pkg}.roller")
            model = importlib.import_module(f"{pkg}.roller.model")
            prof = importlib.import_module(f"{pkg}.profiles").ISO16281Profile(L, D)
            times = {k: [] for k in PARTS}
            _timed(model, times)
            where = here if pkg == "linecontact" else Path(args.against).resolve()
            runs.append((where.name, roller, prof, times, []))

        def solve(roller, prof):
            return roller.ProfiledRoller(D / 2, L, ESTAR, prof, engine=args.engine
                                         ).at_force(FORCE, tilt=tilt)

        for _ in range(10):
            for _, roller, prof, times, _ in runs:
                solve(roller, prof)
        for _, _, _, times, _ in runs:
            for v in times.values():
                v.clear()
        for i in range(args.repeat):
            for name, roller, prof, times, total in (runs if i % 2 == 0 else runs[::-1]):
                t0 = time.perf_counter()
                solve(roller, prof)
                total.append(time.perf_counter() - t0)
        print(f"engine {args.engine}, tilt {args.tilt}, {args.repeat} solves each"
              f"{', alternating in one process' if len(names) > 1 else ''} (wall, medians)")
        for name, _, _, times, total in runs:
            print(f"{name}:")
            for part, v in times.items():
                print(f"  {part:10s} {len(v) / args.repeat:4.1f} calls a solve, "
                      f"{statistics.median(v) * 1e6:7.1f} us a call")
            print(f"  one solve  {statistics.median(total) * 1e3:.3f} ms")


if __name__ == "__main__":
    main()
