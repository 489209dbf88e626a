"""Issue 20, item 2: the time of one profiled-roller solve, of a load sweep on one roller,
and of the coarse 3D BEM on the same case (CPU time, medians).

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_speed [--repeat 30]
        [--sweep 20] [--bem-repeat 3] [--no-bem] [--n-slices N]

The case: the ISO 16281 profile of tables/roller_accuracy.csv (D = 10 mm, L = 14 mm,
E* = 115.385 GPa), 4200 N (300 N/mm), tilt 2 mrad given (the table's case whose peak
pressure was 3 % off with 100 uniform slices), and the same at a free (zero-moment)
tilt. Measured:

1. one solve, cold: a new ``ProfiledRoller`` (the version's default slices, 50 since
   issue 20's fourth round and 100 before, or ``--n-slices``) and ``at_force``,
   ``--repeat`` times, median CPU time (``time.process_time``: on a shared, loaded
   machine what other jobs do not inflate; single-threaded BLAS);
2. a load sweep: ``at_force`` of ``--sweep`` forces from 100 to 2000 N/mm on one roller
   (the array call, solved in increasing order, each from its neighbour's solution),
   against as many cold solves of the same forces: the ratio of CPU times;
3. the coarse 3D BEM (tools/bem/roller.py ``solve_roller_force``, 128 x 32 cells, one
   FFT thread, the coarser grid of the accuracy study) on the same case: median CPU of
   ``--bem-repeat`` solves, and the ratio BEM / one solve.

Runs against any checkout whose ``linecontact`` is first on the path (it uses only
``ProfiledRoller(R, L, E*, profile, n_slices=...)`` and ``at_force``), so that the
same command times an older version for a paired comparison. ``--against DIR`` does
that pairing itself: it runs this command (without ``--against``) in turn on this
checkout and on the checkout DIR (each in a fresh process with its own directory first
on ``PYTHONPATH``), ``--rounds`` times each, A B A B, and prints the ratios of the
one-solve medians round by round and their median. ``--no-refine`` solves with
``refine_ends=False`` (the solver alone, without the end refinement's re-solves;
only for versions that have that option).
"""
from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

D, L, ESTAR = 10e-3, 14e-3, 115.385e9
FORCE, TILT = 4200.0, 2e-3


def _cpu(fn, repeat):
    ts = []
    out = None
    for _ in range(repeat):
        c0 = time.process_time()
        out = fn()
        ts.append(time.process_time() - c0)
    return statistics.median(ts), out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=30)
    ap.add_argument("--sweep", type=int, default=20)
    ap.add_argument("--bem-repeat", type=int, default=3)
    ap.add_argument("--no-bem", action="store_true")
    ap.add_argument("--n-slices", type=int, default=None,
                    help="slice count (default: the checkout's own default)")
    ap.add_argument("--no-refine", action="store_true")
    ap.add_argument("--against", default=None, metavar="DIR")
    ap.add_argument("--rounds", type=int, default=2)
    a = ap.parse_args(argv)
    if a.against:
        return _paired(a, argv if argv is not None else sys.argv[1:])
    extra = {"refine_ends": False} if a.no_refine else {}
    if a.n_slices is not None:
        extra["n_slices"] = a.n_slices

    import linecontact
    from linecontact.roller import ProfiledRoller
    from tools.studies import roller_study as rs

    R = D / 2
    prof = rs.make_profile("iso16281", L, R, ESTAR)

    def cold(force, tilt):
        return ProfiledRoller(R, L, ESTAR, prof, **extra).at_force(force, tilt=tilt)

    cold(FORCE, TILT)                      # the strip-function table, built once
    print(f"linecontact from {os.path.relpath(linecontact.__file__)}")
    print(f"case: ISO 16281 profile, D {D * 1e3:g} mm, L {L * 1e3:g} mm, F {FORCE:g} N, "
          f"{a.n_slices or 'default'} slices (default spacing of this version)"
          + (", refine_ends=False" if a.no_refine else ""))
    rows = {}
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        t, s = _cpu(lambda: cold(FORCE, tilt), a.repeat)
        rows[label] = t
        pm = "-" if s.p_max is None else f"{s.p_max / 1e6:.1f} MPa"
        print(f"one solve, cold, {label}: CPU median {t * 1e3:.2f} ms over {a.repeat} "
              f"(depth {s.depth * 1e6:.5f} um, M {s.moment:.5f} N m, tilt "
              f"{s.tilt * 1e3:.5f} mrad, p_max {pm}, slice solves {s.iterations})")

    forces = np.linspace(100e3, 2000e3, a.sweep) * L
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        def sweep():
            return ProfiledRoller(R, L, ESTAR, prof, **extra).at_force(forces, tilt=tilt)

        def singles():
            return [cold(f, tilt) for f in forces]

        ts, sw = _cpu(sweep, 3)
        tc, one = _cpu(singles, 3)
        dev = max(abs(x.depth / y.depth - 1) for x, y in zip(sw, one))
        print(f"sweep of {a.sweep} forces ({forces[0]:g}-{forces[-1]:g} N), {label}: "
              f"CPU {ts * 1e3:.1f} ms, {a.sweep} cold solves {tc * 1e3:.1f} ms, ratio "
              f"{ts / tc:.2f} (largest depth difference {dev:.1e})")

    if not a.no_bem:
        from tools.bem.roller import solve_roller_force

        for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", None)):
            tb, r = _cpu(lambda: solve_roller_force(R, L, ESTAR, FORCE, tilt=tilt,
                                                    profile=prof, n_x=128, n_y=32,
                                                    workers=1), a.bem_repeat)
            print(f"coarse 3D BEM 128 x 32, {label}: CPU median {tb * 1e3:.0f} ms over "
                  f"{a.bem_repeat}; ratio BEM / one solve {tb / rows[label]:.0f}")
    return 0


def _paired(a, argv):
    """This command on this checkout (A) and on the checkout a.against (B), in turn,
    a.rounds times each; the ratios A/B of the one-solve medians."""
    here = Path(__file__).resolve().parents[2]
    other = Path(a.against).resolve()
    args, skip = [], False
    for v in argv:                             # the same options, less --against/--rounds
        if skip:
            skip = False
            continue
        if v in ("--against", "--rounds"):
            skip = True
            continue
        if v.startswith(("--against=", "--rounds=")):
            continue
        args.append(v)
    pat = re.compile(r"one solve, cold, (.+?): CPU median ([\d.]+) ms")
    ratios = {}
    for r in range(a.rounds):
        got = {}
        for name, root in (("A", here), ("B", other)):
            env = dict(os.environ, PYTHONPATH=str(root))
            out = subprocess.run([sys.executable, "-m", "tools.benchmarks.bench_roller_speed",
                                  *args], cwd=root, env=env, capture_output=True, text=True,
                                 check=True).stdout
            print(f"--- round {r + 1}, {name} = {root.name}:")
            print(out.rstrip())
            got[name] = {k: float(v) for k, v in pat.findall(out)}
        for k in got["A"]:
            ratios.setdefault(k, []).append(got["A"][k] / got["B"][k])
    for k, v in ratios.items():
        print(f"paired ratio A/B, one solve, {k}: rounds "
              + ", ".join(f"{x:.3f}" for x in v) + f"; median {statistics.median(v):.3f}"
              f" (B/A {1 / statistics.median(v):.1f} x)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
