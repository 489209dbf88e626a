"""Issue 20, round 6: the Newton steps of the force-controlled profiled-roller solve
(linecontact.roller.slices.SliceEquations.bordered) and its error estimate
(slices.newton_error, NEWTON_C).

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_newton
        [--engine numpy|c] [--sample N --seed S]

Cases: the ISO 16281 roller of tools/benchmarks/bench_roller_speed.py (D 10 mm, L 14
mm, 4200 N) at 2 mrad and at a free tilt, then the 104 cases of
tables/roller_accuracy.csv as the accuracy study solves them (a new
``ProfiledRoller`` per case, ``at_force(F, tilt)``, ``tilt="free"`` where the table's
tilt is free); ``--sample N`` adds N random cases of the covered range
(tools/benchmarks/bench_roller_default_slices.py ``sample_tasks``).

Printed:

1. the Newton steps (``SliceEquations.linearised`` calls, every solve of a case, end
   refinements included) with the estimate (the default) and without it
   (``NEWTON_C = inf``: every solve ends only on a full step below the tolerance,
   converged to rounding), on the speed case per tilt and over the table;
2. the largest differences between the two over every case: slice loads (over the
   largest), depth (over the largest overlap), tilt (times L over the largest
   overlap), force and moment (over F and F L/2), p_max (relative), the stiffness
   matrix (over its diagonal scale), and the cases whose flags differ;
3. the calibration of NEWTON_C: over every solve without the estimate, the iterates
   (the states each linearisation starts from, and the state returned), and for each
   two successive iterates on the same loaded set, the estimate w = newton_error of the
   step between them and the error left after it (the distance of the later iterate
   from the returned state, in the step's norm: loads over the largest, c R, d and
   the tilt's travel over the largest overlap); the largest ratio error / w where the
   error is above the rounding floor (2e-12) and w below 1e-6.
"""
from __future__ import annotations

import argparse
import math
import sys

import numpy as np

D, L, ESTAR, FORCE = 10e-3, 14e-3, 115.385e9, 4200.0


def _cases(sample=0, seed=0):
    from linecontact.tables import read_table
    from tools.benchmarks.bench_roller import _tasks_from_table
    from tools.studies import roller_study as rs

    prof = rs.make_profile("iso16281", L, D / 2, ESTAR)
    out = [("speed case, 2 mrad", D / 2, L, ESTAR, prof, FORCE, 2e-3),
           ("speed case, free tilt", D / 2, L, ESTAR, prof, FORCE, "free")]
    tasks = _tasks_from_table(read_table("roller_accuracy"))
    if sample:
        from tools.benchmarks.bench_roller_default_slices import sample_tasks
        tasks = tasks + sample_tasks(sample, seed)
    for i, t in enumerate(tasks):
        out.append((f"case {i}", t["radius"], t["length"], t["estar"],
                    rs.make_profile(t["profile"], t["length"], t["radius"], t["estar"]),
                    t["force"], "free" if t["tilt"] is None else t["tilt"]))
    return out


class _Recorder:
    """Wraps SliceEquations.bordered and .linearised: per bordered call, the iterates
    (q, c, d, theta, the loaded set, the grid's span and largest overlap, R) each
    linearisation starts from, then the state returned."""

    def __init__(self):
        from linecontact.roller import slices
        self.calls, self.steps = [], 0
        lin, bord = slices.SliceEquations.linearised, slices.SliceEquations.bordered
        rec = self

        def linearised(self, S, q, c, theta, slope, targets):
            rec.steps += 1
            if rec.calls:
                i = int(S[0])
                d = float(self._over[i] - theta * self.x[i] + self.P[i])
                rec.calls[-1].append(dict(S=S.copy(), q=q.copy(), c=c.copy(), d=d,
                                          theta=float(theta), R=self.R,
                                          span=self.hi - self.lo,
                                          dmax=float(self._over.max())))
            return lin(self, S, q, c, theta, slope, targets)

        def bordered(self, *args, **kwargs):
            rec.calls.append([])
            out = bord(self, *args, **kwargs)
            s, S, q, c, d, theta = out[:6]
            rec.calls[-1].append(dict(S=S.copy(), q=q.copy(), c=c.copy(), d=float(d),
                                      theta=float(theta), R=s.R, span=s.hi - s.lo,
                                      dmax=float((d + theta * s.x - s.P).max()),
                                      final=True))
            return out
        self._saved = (lin, bord)
        slices.SliceEquations.linearised = linearised
        slices.SliceEquations.bordered = bordered

    def restore(self):
        from linecontact.roller import slices
        slices.SliceEquations.linearised, slices.SliceEquations.bordered = self._saved


def _solve_all(cases, engine, estimate):
    from linecontact.roller import ProfiledRoller
    from linecontact.roller import slices
    saved = slices.NEWTON_C
    if not estimate:
        slices.NEWTON_C = math.inf
    rec = _Recorder()
    sols, steps, calls = [], [], []
    try:
        for name, R, length, E, prof, F, tilt in cases:
            rec.steps, rec.calls = 0, []
            r = ProfiledRoller(R, length, E, prof, engine=engine)
            s = r.at_force(F, tilt=tilt)
            over = s.depth - r.first_contact_depth(s.tilt)
            sols.append((s, over))
            steps.append(rec.steps)
            calls.append([c for c in rec.calls if c and c[-1].get("final")])
    finally:
        rec.restore()
        slices.NEWTON_C = saved
    return sols, steps, calls


def _differences(cases, new, ref):
    worst = dict(q=0.0, depth=0.0, tilt=0.0, force=0.0, moment=0.0, p_max=0.0,
                 stiffness=0.0, flags=0)
    for (name, R, length, E, prof, F, tilt), (s, over), (t, _) in zip(cases, new, ref):
        if len(s.q) == len(t.q):
            worst["q"] = max(worst["q"], np.abs(s.q - t.q).max() / np.abs(t.q).max())
        worst["depth"] = max(worst["depth"], abs(s.depth - t.depth) / over)
        worst["tilt"] = max(worst["tilt"], abs(s.tilt - t.tilt) * length / over)
        worst["force"] = max(worst["force"], abs(s.force - t.force) / F)
        worst["moment"] = max(worst["moment"], abs(s.moment - t.moment) / (F * length / 2))
        if s.p_max is not None and t.p_max is not None:
            worst["p_max"] = max(worst["p_max"], abs(s.p_max / t.p_max - 1))
        K, Kr = s.stiffness_matrix, t.stiffness_matrix
        scale = np.sqrt(np.outer(np.diag(np.abs(Kr)), np.diag(np.abs(Kr))))
        worst["stiffness"] = max(worst["stiffness"], float(np.max(np.abs(K - Kr) / scale)))
        worst["flags"] += (s.edge_loaded, s.p_max_resolved, s.message, s.n_slices) != (
            t.edge_loaded, t.p_max_resolved, t.message, t.n_slices)
    return worst


def _distance(a, f):
    """a's distance from the returned state f in the step's norm."""
    S = f["S"]
    qsc = f["q"][S].max()
    return max(np.abs(a["q"] - f["q"]).max() / qsc,
               np.abs(a["c"][S] - f["c"][S]).max() * f["R"],
               abs(a["d"] - f["d"]) / f["dmax"],
               abs(a["theta"] - f["theta"]) * f["span"] / f["dmax"])


def calibration(calls, floor=5e-12, w_max=1e-6):
    """(the largest error / w, its w and error, the number of steps counted)."""
    from linecontact.roller.slices import newton_error
    worst, n = (0.0, 0.0, 0.0), 0
    for per_case in calls:
        for it in per_case:
            f = it[-1]
            for a, b in zip(it[:-2], it[1:-1]):
                if not np.array_equal(a["S"], b["S"]):
                    continue
                S = a["S"]
                qs, cs = a["q"][S], a["c"][S]
                w = newton_error(qs, cs, b["q"][S] - qs, b["c"][S] - cs, qs.max(), a["R"],
                                 (b["d"] - a["d"]) / a["dmax"],
                                 (b["theta"] - a["theta"]) * a["span"] / a["dmax"])
                err = _distance(b, f)
                if err > floor and w < w_max:
                    n += 1
                    if err / w > worst[0]:
                        worst = (err / w, w, err)
    return worst + (n,)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--engine", default="numpy", choices=("numpy", "c"))
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--seed", type=int, default=7)
    a = ap.parse_args(argv)
    cases = _cases(a.sample, a.seed)
    new, steps_new, _ = _solve_all(cases, a.engine, True)
    ref, steps_ref, calls_ref = _solve_all(cases, a.engine, False)
    print(f"engine {a.engine}; Newton steps (linearisations, every solve of a case), "
          "with the error estimate / without:")
    for k in range(2):
        print(f"  {cases[k][0]}: {steps_new[k]} / {steps_ref[k]}")
    m = len(cases) - 2
    print(f"  the other {m} cases: {sum(steps_new[2:])} / {sum(steps_ref[2:])}")
    w = _differences(cases, new, ref)
    print("largest difference with / without the estimate: " + ", ".join(
        f"{k} {v:.1e}" if isinstance(v, float) else f"{k} {v}" for k, v in w.items()))
    ratio, wq, err, n = calibration(calls_ref)
    print(f"calibration of NEWTON_C over {n} steps (error above 5e-12, w below 1e-6): "
          f"largest error / w = {ratio:.3g} (w {wq:.2e}, error {err:.2e})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
