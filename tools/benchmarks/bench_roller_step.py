"""Issue 20, item 2: what one Newton step of a profiled-roller solve costs, in place:
the linearisation (``SliceEquations.linearised``), the dense solve of the step's
system, and the rest of the step (scaling, sums, step, update, active set: the Python
and compiled glue of ``SliceEquations.bordered``).

    OPENBLAS_NUM_THREADS=1 python tools/benchmarks/bench_roller_step.py
        [--against DIR] [--repeat 200] [--engine c] [--tilt 2e-3]

The case of ``bench_roller_speed``: the ISO 16281 profile of tables/roller_accuracy.csv
(D = 10 mm, L = 14 mm, E* = 115.385 GPa), 4200 N, tilt 2 mrad (or ``--tilt free``), a
new roller per solve (its default slices). ``SliceEquations.bordered`` (the Newton
steps), ``SliceEquations.linearised`` and ``ProfiledRoller._grid`` are wrapped in
timers (``time.perf_counter``); per solve, a step's remainder is the time in
``bordered`` less its linearisations and its regrids (``_grid`` calls made while
``bordered`` runs), over its steps. The dense solve inside it is timed apart: each
solve's last Newton system (2 ns x 2 ns, three right-hand sides; the matrix
``linearised`` returned, scaled as the step scales it) is solved again ``--solves``
times after the run with the engine's solver (``np.linalg.solve``, under either
engine), the median taken. Printed: medians over the solves of
the per-call linearisation, the dense solve, the step's remainder less that solve
("glue"), the steps per solve and the solve itself. ``--against DIR`` times the
checkout DIR too, the two checkouts' solves alternating in one process (DIR's
``linecontact`` copied and imported as ``linecontact_b``, as ``bench_roller_speed
--interleave`` does). Wall time; the timers' own cost (about 0.1 us a call) included.
"""
from __future__ import annotations

import argparse
import importlib
import statistics
import sys
import time
from pathlib import Path

import numpy as np

D, L, ESTAR = 10e-3, 14e-3, 115.385e9
FORCE = 4200.0


def _instrument(slices, model, rec):
    """Wrap bordered, linearised and _grid of one checkout; rec collects per solve."""
    SE, PR = slices.SliceEquations, model.ProfiledRoller
    bordered, linearised, grid = SE.bordered, SE.linearised, PR._grid
    state = {"in_bordered": False}

    def w_bordered(self, *a, **k):
        state["in_bordered"] = True
        t0 = time.perf_counter()
        try:
            out = bordered(self, *a, **k)
        finally:
            state["in_bordered"] = False
        rec["bordered"] += time.perf_counter() - t0
        return out

    def w_linearised(self, S, q, c, theta, slope, targets):
        t0 = time.perf_counter()
        out = linearised(self, S, q, c, theta, slope, targets)
        dt = time.perf_counter() - t0
        rec["lin"].append(dt)
        if state["in_bordered"]:
            rec["lin_b"] += dt
            rec["steps"] += 1
            ns = len(S)
            J = out[1].copy(order="F")
            qsc = float(q[S].max())
            J[:ns, ns:] *= 1.0 / (qsc * self.R)
            J[ns:, :ns] *= qsc * self.R
            rec["system"] = (J, np.ones((2 * ns, 3)), self.engine)
        return out

    def w_grid(self, *a, **k):
        t0 = time.perf_counter()
        out = grid(self, *a, **k)
        if state["in_bordered"]:
            rec["grid_b"] += time.perf_counter() - t0
        return out

    SE.bordered, SE.linearised, PR._grid = w_bordered, w_linearised, w_grid


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", default=None, help="a second checkout to time")
    ap.add_argument("--repeat", type=int, default=200)
    ap.add_argument("--solves", type=int, default=200)
    ap.add_argument("--engine", default="c", choices=("numpy", "c"))
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
            slices = importlib.import_module(f"{pkg}.roller.slices")
            model = importlib.import_module(f"{pkg}.roller.model")
            prof = importlib.import_module(f"{pkg}.profiles").ISO16281Profile(L, D)
            rec = {}
            _instrument(slices, model, rec)
            where = here if pkg == "linecontact" else Path(args.against).resolve()
            runs.append(dict(name=where.name, roller=roller, slices=slices, prof=prof,
                             rec=rec, per=[]))

        def solve(run):
            rec = run["rec"]
            rec.update(bordered=0.0, lin_b=0.0, grid_b=0.0, steps=0, lin=[])
            t0 = time.perf_counter()
            run["roller"].ProfiledRoller(D / 2, L, ESTAR, run["prof"], engine=args.engine
                                         ).at_force(FORCE, tilt=tilt)
            total = time.perf_counter() - t0
            steps = rec["steps"]
            rest = (rec["bordered"] - rec["lin_b"] - rec["grid_b"]) / steps
            return dict(total=total, steps=steps, lin=statistics.median(rec["lin"]),
                        rest=rest)

        for _ in range(10):
            for run in runs:
                solve(run)
        for i in range(args.repeat):
            for run in (runs if i % 2 == 0 else runs[::-1]):
                run["per"].append(solve(run))
        # the dense solve of the last step's system, again, with the engine's solver
        # (the checkouts alternating)
        for run in runs:
            J, B, engine = run["rec"]["system"]
            run["solver"] = np.linalg.solve
            run["solver"](J.copy(order="F"), B)
            run["ts"] = []
            run["n2"] = J.shape[0]
        for i in range(args.solves):
            for run in (runs if i % 2 == 0 else runs[::-1]):
                J, B, _ = run["rec"]["system"]
                Jc = J.copy(order="F")
                t0 = time.perf_counter()
                run["solver"](Jc, B)
                run["ts"].append(time.perf_counter() - t0)
        for run in runs:
            run["solve"] = statistics.median(run["ts"])
        print(f"engine {args.engine}, tilt {args.tilt}, {args.repeat} solves each"
              f"{', alternating in one process' if len(names) > 1 else ''} (wall, medians, us)")
        print("checkout: linearised a call | dense solve (2ns) | glue a step "
              "(step less linearised and solve) | steps | one solve")
        for run in runs:
            med = {k: statistics.median(p[k] for p in run["per"])
                   for k in ("total", "steps", "lin", "rest")}
            print(f"{run['name']}: {med['lin'] * 1e6:6.1f} | {run['solve'] * 1e6:6.1f} "
                  f"({run['n2']}) | {(med['rest'] - run['solve']) * 1e6:6.1f} "
                  f"| {med['steps']:.0f} | {med['total'] * 1e3:.3f} ms")


if __name__ == "__main__":
    main()
