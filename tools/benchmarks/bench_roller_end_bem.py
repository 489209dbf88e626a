"""A converged 3D BEM reference for the profiled-roller cases whose contact ends within
microns of a roller end (logarithmic profiles at high line loads), against the runtime
coupled-slice model at its default settings.

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_end_bem \\
        [--cases 44,31,47,27] [--n-x 1024,2048,4096] [--n-y 16]

The runtime (linecontact.roller.ProfiledRoller, defaults: 100 graded slices, the end
slices refined where the peak is not resolved) solves each case of
tables/roller_accuracy.csv at its force and tilt; the BEM (tools.bem.roller.solve_roller,
depth control) then solves at the runtime's depth and tilt on nested windows with
n_x cells along the axis (the window adapted on the first grid and kept) and n_y
across. The accuracy table's own BEM (128 and 256 cells along the axis, 55 um cells at
L = 14 mm) cannot resolve these end zones (its peak moves 2-21 % between its grids).
Printed per grid: the BEM force (the runtime's force is the case's), moment, p_max and
where, the contact's distance from the end and whether an end cell is loaded; then the
runtime's p_max and the differences F_bem/F - 1, M_bem/M - 1 and p/p_bem - 1 on the
finest grid.
"""
from __future__ import annotations

import argparse
import sys
import time

import numpy as np


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", default="44,31,47,27",
                    help="rows of tables/roller_accuracy.csv (0-based)")
    ap.add_argument("--n-x", default="1024,2048,4096")
    ap.add_argument("--n-y", type=int, default=16)
    ap.add_argument("--tol", type=float, default=1e-7)
    a = ap.parse_args(argv)
    from linecontact.roller import ProfiledRoller
    from linecontact.tables import read_table
    from tools.bem.roller import solve_roller
    from tools.studies import roller_study as rs

    c = read_table("roller_accuracy").columns
    nxs = [int(v) for v in a.n_x.split(",")]
    for i in (int(v) for v in a.cases.split(",")):
        L, code = float(c["roller_length"][i]), int(c["profile"][i])
        F, th = float(c["force"][i]), float(c["tilt"][i])
        prof = rs.make_profile(rs.PROFILES[code], L)
        s = ProfiledRoller(rs.DIAMETER / 2, L, rs.ESTAR, prof).at_force(F, tilt=th)
        print(f"case {i}: {rs.PROFILES[code]}, L {L * 1e3:g} mm, F {F:g} N, tilt "
              f"{th * 1e3:g} mrad; runtime (default, {s.n_slices} slices): depth "
              f"{s.depth * 1e6:.5f} um, M {s.moment:.5f} N m, p_max {s.p_max / 1e6:.1f} "
              f"MPa at {(L / 2 - abs(s.x_at_p_max)) * 1e6:.1f} um from the end, "
              f"resolved {s.p_max_resolved}; table BEM (256 cells) p_max "
              f"{c['bem_p_max'][i] / 1e6:.1f} MPa", flush=True)
        window, last = None, None
        for nx in nxs:
            t0 = time.perf_counter()
            r = solve_roller(rs.DIAMETER / 2, L, rs.ESTAR, s.depth, tilt=s.tilt,
                             profile=prof, n_x=nx, n_y=a.n_y, tol=a.tol, window=window,
                             stiffness=False, workers=1)
            window = r.grid if window is None else window
            gap = L / 2 - max(abs(r.contact_x[0]), abs(r.contact_x[1]))
            print(f"  BEM {r.grid.nx} x {r.grid.ny} (dx {r.grid.dx * 1e6:.2f} um): F "
                  f"{r.force:.2f} N, M {r.moment:.5f} N m, p_max {r.p_max / 1e6:.1f} MPa at "
                  f"{(L / 2 - abs(r.x_at_p_max)) * 1e6:.1f} um from the end, contact "
                  f"{gap * 1e6:.1f} um from the end, end cell loaded {r.edge_loaded} "
                  f"({time.perf_counter() - t0:.0f} s)", flush=True)
            last = r
        em = (last.moment / s.moment - 1) if th else (last.moment - s.moment) / (F * L / 2)
        print(f"  runtime vs finest BEM: F_bem/F - 1 = {last.force / F - 1:+.4%}, moment "
              f"{em:+.4%}, p_max {s.p_max / last.p_max - 1:+.3%}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
