"""The 3D stress search's choice of slices against a search below every loaded slice.

    python -m tools.benchmarks.bench_stress_search            # about a minute on 2 cores
    python -m tools.benchmarks.bench_stress_search --random 60 --seed 20

``roller_stresses`` (linecontact.stresses) looks for each measure's 3D-corrected worst
below candidate slices (p0's largest and its neighbours, p0's other peaks; where the
contact reaches a roller end also spread slices, p0's local maxima and a climb along
the roller). ``search="every slice"`` runs the same zoomed grid search below every
loaded slice, so the difference is what the choice of slices misses. The rollers:
the stress study's 106 (tools/studies/stress_study.py: the dense set, five profiles at
L = 14 mm and ISO 16281 at 30 mm, 100/800/2000 N/mm, tilt 0 and 2 mrad; the wide set's
34, L/D 0.5-12; the relief set's 36 drawn end reliefs), three named edge-loaded
rollers (a circular crown at 35.8 kN and 1.86 mrad; Lundberg 25.4 kN, 1.2 mrad, 162
slices; ISO 16281 60.5 kN, 1.76 mrad) and ``--random`` rollers whose contact reaches an
end (the five profiles in turn, L 14 or 30 mm, 300-2500 N/mm log-uniform, tilt
0-2.5 mrad; seeded). Prints the largest shortfall |every/candidates - 1| per measure,
apart for the contact off the ends and at an end, and the CPU time of both searches;
writes tools/benchmarks/results/stress_search.txt.
"""
from __future__ import annotations

import argparse
import platform
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
ESTAR = 115.385e9


def rollers(n_random, seed):
    """(label, solution, model or None) of the study's, the named and random rollers."""
    from linecontact.roller import ProfiledRoller, roller_contact
    from linecontact.stresses import reaches_end
    from tools.studies import stress_study as ss
    from tools.studies.roller_study import make_profile, task_profile
    out = []
    for t in ss.study_tasks():
        prof = task_profile(t)      # the task's own crown radius and end relief
        model = ProfiledRoller(t["radius"], t["length"], t["estar"], prof)
        out.append((t["key"], model.at_force(t["force"], tilt=t["tilt"]), model))
    out.append(("circular crown 35.8 kN 1.86 mrad",
                roller_contact(5e-3, 14e-3, ESTAR, "circular:Rc=0.5", force=35.8e3,
                               tilt=1.86e-3), None))
    for prof, f, th, n in (("lundberg", 25.4e3, 1.2e-3, 162),
                           ("iso16281", 60.5e3, 1.76e-3, 50)):
        out.append((f"{prof} {f / 1e3:g} kN {th * 1e3:g} mrad",
                    roller_contact(5e-3, 14e-3, ESTAR, make_profile(prof, 14e-3), force=f,
                                   tilt=th, n_slices=n), None))
    rng = np.random.default_rng(seed)
    names = ("circular crown", "iso16281", "lundberg", "johns-gohar",
             "straight with end relief")
    i = found = 0
    while found < n_random:
        prof = names[i % len(names)]
        i += 1
        L = (14e-3, 30e-3)[int(rng.integers(2))]
        f = float(np.exp(rng.uniform(np.log(3e5), np.log(2.5e6)))) * L
        th = float(rng.uniform(0.0, 2.5e-3))
        sol = roller_contact(5e-3, L, ESTAR, make_profile(prof, L), force=f, tilt=th)
        if sol.edge_loaded or reaches_end(sol):
            out.append((f"{prof} L {L * 1e3:g} mm {f:.0f} N {th * 1e3:.2f} mrad", sol, None))
            found += 1
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--random", type=int, default=60,
                    help="random rollers whose contact reaches an end (default 60)")
    ap.add_argument("--seed", type=int, default=20)
    ap.add_argument("--out", type=Path, default=REPO / "tools" / "benchmarks" / "results"
                    / "stress_search.txt")
    args = ap.parse_args(argv)
    import linecontact
    from linecontact.stresses import MEASURES, reaches_end, roller_stresses
    cases = rollers(args.random, args.seed)
    short = {True: {m: (0.0, "") for m in MEASURES}, False: {m: (0.0, "") for m in MEASURES}}
    count = {True: 0, False: 0}
    t_cand = t_every = 0.0
    below = 0
    import linecontact.stresses.search as search
    former = {m: (0.0, "") for m in MEASURES}
    above = 0.0
    for label, sol, model in cases:
        end = bool(sol.edge_loaded or reaches_end(sol))
        count[end] += 1
        c0 = time.process_time()
        a = roller_stresses(sol, roller=model).worst
        c1 = time.process_time()
        e = roller_stresses(sol, roller=model, search="every slice").worst
        c2 = time.process_time()
        t_cand += c1 - c0
        t_every += c2 - c1
        for m in MEASURES:
            r = e[m]["value"] / a[m]["value"] - 1
            below += r < -1e-12
            above = max(above, -r)
            if r > short[end][m][0]:
                short[end][m] = (r, f"{label}: slice {a[m]['slice']} against "
                                    f"{e[m]['slice']}")
        if not end:
            # the former choice off the ends: one best-scored slice zoomed, not every
            # candidate
            saved = search._TOP, search._ZOOMED
            search._TOP, search._ZOOMED = 1, None
            try:
                f = roller_stresses(sol, roller=model).worst
            finally:
                search._TOP, search._ZOOMED = saved
            for m in MEASURES:
                r = e[m]["value"] / f[m]["value"] - 1
                if r > former[m][0]:
                    former[m] = (r, f"{label}: {f[m]['value'] / 1e6:.1f} MPa with one "
                                    f"slice, {a[m]['value'] / 1e6:.1f} MPa with "
                                    f"every candidate's first grid, {e[m]['value'] / 1e6:.1f} MPa below "
                                    "every slice")
    lines = [f"bench_stress_search: linecontact {linecontact.__version__}, Python "
             f"{platform.python_version()}, numpy {np.__version__}, "
             f"{time.strftime('%Y-%m-%d')}",
             f"rollers: {len(cases) - 3 - args.random} study, 3 named, {args.random} random reaching an end (seed "
             f"{args.seed}); {count[False]} with the contact off the ends, {count[True]} "
             f"at an end; mu 0, nu 0.3",
             "largest shortfall of the candidates' worst below the worst of a search "
             "below every loaded slice (every/candidates - 1):"]
    for end in (False, True):
        lines.append(f"  contact {'at an end' if end else 'off the ends'}:")
        for m in MEASURES:
            r, where = short[end][m]
            lines.append(f"    {m:18s} {r:8.3%}  {where}")
    lines.append("the former choice off the ends (one best-scored slice zoomed, not "
                 "every candidate's first grid, the best zoomed), largest shortfall below every "
                 "slice:")
    for m in MEASURES:
        r, where = former[m]
        lines.append(f"    {m:18s} {r:8.3%}  {where}")
    lines.append(f"every-slice results below the candidates' (the every-slice search "
                 f"starts each slice's zooms from its own best point, so it is no strict "
                 f"upper bound): {below}, by at most {above:.3%}")
    lines.append(f"CPU: candidates {t_cand:.2f} s, every slice {t_every:.1f} s "
                 f"({t_every / t_cand:.0f} times) over {len(cases)} rollers")
    text = "\n".join(lines) + "\n"
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
