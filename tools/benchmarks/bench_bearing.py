"""Time the radial roller bearing solve (linecontact.bearing) on one core.

Cases (issue targets: 20 straight rollers under 50 ms, 20 profiled under 1 s):
``straight``  Z = 20, d_m = 100 mm, D = L = 10 mm, zero clearance, F_r = 10 kN, the
              universal curve (the default law);
``iso``       the same with the ISO/TS 16281 spring law;
``profiled``  the same rollers crowned (circular:Rc=0.5, 50 slices, the coupled
              slices' default in every door), the coupled-slice model;
``profiled_tilt``    the crowned rollers at a misalignment of 1 mrad (1 DOF);
``profiled_moment``  the crowned rollers under a tilting moment of 10 N m (2 DOF);
``iso_profile_tilt`` rollers of the ISO 16281 logarithmic profile at 1 mrad;
``straight_tilt``    straight rollers at 0.5 mrad (coupled slices, edge loaded).
Each timing is a whole ``RadialRollerBearing(...).solve(F, ...)`` (construction included),
after one warm-up call (imports, table reads); the minimum and median of N runs are
printed, wall time and the process's CPU time (on a shared, loaded machine the CPU
time is the one-core runtime; the wall time includes waiting for the core). Threads of the BLAS libraries are limited to one before numpy is imported;
pin the process to one core with ``taskset -c 0``.

Command (repository root)::

    taskset -c 0 python tools/benchmarks/bench_bearing.py -n 7
"""
import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

CASES = {
    "straight": (dict(model=None, profile=None), {}),
    "iso": (dict(model="iso16281", profile=None), {}),
    "profiled": (dict(model=None, profile="circular:Rc=0.5"), {}),
    "profiled_tilt": (dict(profile="circular:Rc=0.5"), dict(misalignment=1e-3)),
    "profiled_moment": (dict(profile="circular:Rc=0.5"), dict(moment=10.0)),
    "iso_profile_tilt": (dict(profile="iso16281"), dict(misalignment=1e-3)),
    "straight_tilt": (dict(profile=None), dict(misalignment=5e-4)),
}


def one(case):
    from linecontact.bearing import RadialRollerBearing

    bearing, load = CASES[case]
    t, c = time.perf_counter(), time.process_time()
    RadialRollerBearing(20, 100e-3, 10e-3, 10e-3, **bearing).solve(10e3, **load)
    return time.perf_counter() - t, time.process_time() - c


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=7)
    ap.add_argument("cases", nargs="*", default=list(CASES))
    args = ap.parse_args()
    for case in args.cases:
        one(case)
        runs = [one(case) for _ in range(args.n)]
        wall, cpu = [r[0] for r in runs], [r[1] for r in runs]
        print(f"{case:>16}: wall min {min(wall) * 1e3:8.1f} ms, median "
              f"{statistics.median(wall) * 1e3:8.1f} ms; cpu min {min(cpu) * 1e3:8.1f} "
              f"ms, median {statistics.median(cpu) * 1e3:8.1f} ms ({args.n} runs)")


if __name__ == "__main__":
    main()
