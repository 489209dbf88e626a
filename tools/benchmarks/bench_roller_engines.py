"""Issue 20, round 7: every engine of the profiled-roller solver against the numpy
reference over the cases of tables/roller_accuracy.csv (how close their results are).

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_engines
        [--engines c] [--sample N --seed S]

Cases: the ISO 16281 roller of tools/benchmarks/bench_roller_speed.py (4200 N) at 2
mrad and at a free tilt, and the 104 cases of tables/roller_accuracy.csv as the
accuracy study solves them (tools/benchmarks/bench_roller_newton.py ``_cases``: a new
``ProfiledRoller`` per case, ``at_force(F, tilt)``); ``--sample N`` adds N random cases
of the covered range. Each case is solved with engine="numpy" and with each engine
asked for (those that run here: the C extension built). Printed per
engine: the largest differences from numpy over every case (slice loads over the
largest, depth over the largest overlap, tilt times L over the largest overlap, force
over F, moment over F L/2, p_max relative, the stiffness matrix over its diagonal
scale; bench_roller_newton ``_differences``), the cases whose flags or slice counts
differ, the cases whose Newton step counts differ, and where two compiled engines ran,
how many cases they solve to the same bits.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np


def _available(engine):
    from linecontact.roller import slices
    if engine == "c":
        return slices.c_engine() is not None
    return True


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--engines", nargs="+", default=["c"], choices=("c",))
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args(argv)
    from tools.benchmarks.bench_roller_newton import _cases, _differences, _solve_all

    cases = _cases(a.sample, a.seed)
    ref, steps_ref, _ = _solve_all(cases, "numpy", True)
    got = {}
    for engine in a.engines:
        if not _available(engine):
            print(f"engine {engine}: not available here (skipped)")
            continue
        sols, steps, _ = _solve_all(cases, engine, True)
        got[engine] = sols
        w = _differences(cases, sols, ref)
        moved = sum(x != y for x, y in zip(steps, steps_ref))
        print(f"engine {engine} against numpy over {len(cases)} cases: largest difference "
              + ", ".join(f"{k} {v:.1e}" if isinstance(v, float) else f"{k} {v}"
                          for k, v in w.items())
              + f"; Newton step counts differ in {moved} cases "
              f"({sum(steps)} steps, numpy {sum(steps_ref)})")
    if len(got) == 2:
        (e1, s1), (e2, s2) = got.items()
        same = sum(x.depth == y.depth and np.array_equal(x.q, y.q)
                   and np.array_equal(x.stiffness_matrix, y.stiffness_matrix)
                   for (x, _), (y, _) in zip(s1, s2))
        print(f"{e1} and {e2}: the same depth, slice loads and stiffness matrix to the "
              f"last bit in {same} of {len(cases)} cases")
    return 0


if __name__ == "__main__":
    sys.exit(main())
