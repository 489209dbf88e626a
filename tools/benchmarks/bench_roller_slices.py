"""Slice convergence of the coupled-slice roller model: peak pressure, deflection and
moment against the slice count, for the default graded slices and for uniform ones.

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_slices [--n 50,100,200,400]

Cases (D = 10 mm, E* = 115.385 GPa, ISO 16281 and Lundberg profiles as in
tables/roller_accuracy.csv, tools/studies/roller_study.py ``make_profile``):

- ``iso-14``: ISO 16281 profile, L = 14 mm, 4200 N, tilt 2 mrad given (the table's
  case whose peak sits near the contact's end; 3D BEM reference: the table's row);
- ``iso-20``: ISO 16281 profile, L = 20 mm, 40 kN, aligned (issue 20's example: with
  100 uniform slices the peak was reported 3.8 % high at the contact's end);
- ``lundberg-14``: Lundberg profile (F0/L = 800 N/mm), L = 14 mm, 28 kN, tilt 1 mrad
  (an end zone narrower than the slices: the BEM loads its end cell; the table's worst
  moment case).

For each: p_max [MPa], depth [um], moment [N m] and whether p_max is flagged
unresolved, per (n, spacing); the BEM values where the table has the case.

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_slices --ends \
        [--n 50,100,200]

The end zones of logarithmic profiles instead: every ISO 16281 and Lundberg case of
tables/roller_accuracy.csv whose peak 100 graded slices leave unresolved without the
end refinement (``refine_ends=False``; the contact ends microns before the roller
end; 19 cases, chosen at 100 slices whatever the default). Per case: the unrefined
100-slice peak, then at each n the default solve (the
end slices refined until the peak settles: the slices used, p_max, depth, moment,
resolved), and a reference of 400 slices graded 0.99 (end slices 0.35-0.75 um),
refined likewise; last, the largest differences from the reference over the cases:
p_max relative, depth over the largest overlap, moment relative (tilted) or over
F L/2 (aligned), and the median CPU seconds of a solve.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

D, ESTAR = 10e-3, 115.385e9


def _bem_row(length, profile_code, force, tilt):
    from linecontact.tables import read_table
    c = read_table("roller_accuracy").columns
    m = ((np.abs(c["roller_length"] - length) < 1e-9) & (c["profile"] == profile_code)
         & (np.abs(c["force"] - force) < 1e-6) & (np.abs(c["tilt"] - tilt) < 1e-12)
         & (c["free_tilt"] == 0))
    i = np.flatnonzero(m)
    return None if i.size == 0 else int(i[0]), c


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", default=None, help="slice counts (default 50,100,200,400; "
                    "with --ends 50,100,200)")
    ap.add_argument("--ends", action="store_true",
                    help="the end zones of the table's logarithmic-profile cases")
    a = ap.parse_args(argv)
    if a.ends:
        return ends([int(v) for v in (a.n or "50,100,200").split(",")])
    a.n = a.n or "50,100,200,400"
    from linecontact.roller import ProfiledRoller
    from linecontact.roller.model import DEFAULT_GRADING
    from tools.studies import roller_study as rs

    ns = [int(v) for v in a.n.split(",")]
    cases = [("iso-14", "iso16281", 2, 14e-3, 4200.0, 2e-3),
             ("iso-20", "iso16281", 2, 20e-3, 40e3, 0.0),
             ("lundberg-14", "lundberg", 3, 14e-3, 28e3, 1e-3)]
    for name, prof_name, code, L, F, tilt in cases:
        prof = rs.make_profile(prof_name, L, D / 2, ESTAR)
        i, c = _bem_row(L, code, F, tilt)
        print(f"{name}: {prof_name}, L {L * 1e3:g} mm, F {F:g} N, tilt {tilt * 1e3:g} mrad")
        if i is not None:
            print(f"  3D BEM (tables/roller_accuracy.csv row {i}): p_max "
                  f"{c['bem_p_max'][i] / 1e6:.1f} MPa, depth {c['bem_depth'][i] * 1e6:.5f}"
                  f" um, moment {c['bem_moment'][i]:.5f} N m, edge cell loaded "
                  f"{bool(c['bem_edge'][i])}")
        print("  n     spacing        p_max MPa   depth um    moment N m  resolved")
        for g, label in ((DEFAULT_GRADING, f"graded {DEFAULT_GRADING:g}"),
                         (0.0, "uniform")):
            for n in ns:
                s = ProfiledRoller(D / 2, L, ESTAR, prof, n_slices=n,
                                   grading=g).at_force(F, tilt=tilt)
                pm = "-" if s.p_max is None else f"{s.p_max / 1e6:9.1f}"
                print(f"  {n:<5d} {label:<12s} {pm:>10s}  {s.depth * 1e6:9.5f}  "
                      f"{s.moment:11.5f}  {s.p_max_resolved}", flush=True)
    return 0


def ends(ns):
    """The --ends report (module docstring)."""
    import time

    from linecontact.roller import ProfiledRoller
    from linecontact.tables import read_table
    from tools.studies import roller_study as rs

    c = read_table("roller_accuracy").columns
    worst = {n: [0.0, 0.0, 0.0] for n in ns}
    cpu = {n: [] for n in ns}
    count = 0
    for i in range(len(c["force"])):
        code = int(c["profile"][i])
        if rs.PROFILES[code] not in ("iso16281", "lundberg") or c["free_tilt"][i]:
            continue
        L, F, th = float(c["roller_length"][i]), float(c["force"][i]), float(c["tilt"][i])
        prof = rs.make_profile(rs.PROFILES[code], L)

        def solve(**kw):
            t0 = time.process_time()
            s = ProfiledRoller(D / 2, L, ESTAR, prof, **kw).at_force(F, tilt=th)
            return s, time.process_time() - t0

        u, _ = solve(n_slices=100, refine_ends=False)     # the cases chosen at 100
        if u.p_max_resolved or u.edge_loaded:
            continue
        count += 1
        ref, _ = solve(n_slices=400, grading=0.99)
        delta = ref.depth + abs(th) * L / 2          # the largest overlap (log profile)
        print(f"row {i}: {rs.PROFILES[code]}, L {L * 1e3:g} mm, F {F:g} N, tilt "
              f"{th * 1e3:g} mrad; unrefined 100 slices: p_max {u.p_max / 1e6:.1f} MPa "
              f"(not resolved); reference 400 graded 0.99 ({ref.n_slices} slices): p_max "
              f"{ref.p_max / 1e6:.1f} MPa, depth {ref.depth * 1e6:.5f} um, moment "
              f"{ref.moment:.5f} N m, resolved {ref.p_max_resolved}", flush=True)
        for n in ns:
            s, dt = solve(n_slices=n)
            cpu[n].append(dt)
            ep = s.p_max / ref.p_max - 1
            ed = (s.depth - ref.depth) / delta
            em = s.moment / ref.moment - 1 if th else (s.moment - ref.moment) / (F * L / 2)
            for k, v in enumerate((ep, ed, em)):
                worst[n][k] = max(worst[n][k], abs(v))
            print(f"  n {n:<4d} ({s.n_slices} slices): p_max {s.p_max / 1e6:9.1f} MPa "
                  f"({ep:+.3%}), depth {s.depth * 1e6:.5f} um ({ed:+.1e}), moment "
                  f"{s.moment:.5f} N m ({em:+.1e}), resolved {s.p_max_resolved}, CPU "
                  f"{dt:.3f} s", flush=True)
    print(f"{count} cases; largest |difference| from the reference:")
    for n in ns:
        p, d, m = worst[n]
        print(f"  n {n}: p_max {p:.3%}, depth {d:.1e} of the overlap, moment {m:.1e}; "
              f"median CPU {np.median(cpu[n]):.3f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
