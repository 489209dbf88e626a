"""The time per corner and point of the stresses' corner sums: C against numpy.

    OPENBLAS_NUM_THREADS=1 nice -n 10 python -m tools.benchmarks.bench_corner_sums

The corners are those of real slices (linecontact.stresses.search._corners_many of
the ISO 16281 roller of the `roller` benchmark, tools/benchmarks/suite.py, at 4200 N
and 2 mrad tilt, its loaded slices); the points n = 3, 16, 32, 48 across each slice at depths 0.3-1.2 b (where the 3D
correction's search evaluates them). Each evaluation is timed (time.process_time, the
best of ``--repeat`` of a loop of calls, C and numpy in turn) for the C extension
(linecontact._ckernels.love_sums, through stresses.love._love_c) and numpy's
stresses.love._love_weighted on the same corners and points, and reported in ns per
corner and point (CPU / (corners x points)). Writes tools/benchmarks/results/corner_sums.txt.
"""
from __future__ import annotations

import argparse
import datetime
import platform
import time
from pathlib import Path

import numpy as np

import linecontact
from linecontact.roller import ProfiledRoller
from linecontact.stresses import love as st
from linecontact.stresses import search
from tools.benchmarks.suite import D, ESTAR, FORCE, L, TILT
from tools.studies.roller_study import make_profile

REPO = Path(__file__).resolve().parents[2]


def _per_pair(fn, n_pairs, repeat, loops):
    best = np.inf
    for _ in range(repeat):
        t0 = time.process_time()
        for _ in range(loops):
            fn()
        best = min(best, (time.process_time() - t0) / loops)
    return best / n_pairs * 1e9


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--out", type=Path,
                    default=REPO / "tools" / "benchmarks" / "results" / "corner_sums.txt")
    a = ap.parse_args(argv)
    if st._cstresses is None:
        raise SystemExit("the C extension linecontact._ckernels is not built or current here")
    model = ProfiledRoller(D / 2, L, ESTAR, make_profile("iso16281", L, D / 2, ESTAR))
    sol = model.at_force(FORCE, tilt=TILT)
    x, b, q = (np.asarray(v) for v in (sol.x, sol.half_width, sol.q))
    loaded = (b > 0) & (q > 0)
    p0 = np.where(loaded, 2 * q / (np.pi * np.where(loaded, b, 1.0)), 0.0)
    b = np.where(loaded, b, 0.0)
    ks = [int(k) for k in np.flatnonzero(loaded)][::4]
    corners = search._corners_many(x, b, p0, ks)
    lines = [f"bench_corner_sums: linecontact {linecontact.__version__}, Python "
             f"{platform.python_version()}, numpy {np.__version__}, "
             f"{datetime.date.today().isoformat()}",
             "corners of every 4th loaded slice of the ISO 16281 roller (4200 N, 2 mrad); "
             f"CPU per corner and point, best of {a.repeat}",
             f"{'points':>6} {'corners':>8} {'C ns':>7} {'numpy ns':>9} {'numpy/C':>8}"]
    rows = []
    for npt in (3, 16, 32, 48):
        for k, (cx, cy, w) in zip(ks, corners):
            py = np.linspace(-1.2, 1.2, npt) * b[k]
            pz = np.linspace(0.3, 1.2, npt) * b[k]
            X = cx[None, :] - x[k]
            Y, Z = py[:, None] - cy[None, :], pz[:, None]
            pairs = npt * cx.size
            loops = max(1, 200000 // pairs)
            tc = _per_pair(lambda: st._love_c(X, cy, w, py, pz), pairs, a.repeat, loops)
            tn = _per_pair(lambda: st._love_weighted(X, Y, Z, w), pairs, a.repeat, loops)
            rows.append((npt, cx.size, tc, tn))
        sel = [r for r in rows if r[0] == npt]
        tc, tn = np.median([r[2] for r in sel]), np.median([r[3] for r in sel])
        lines.append(f"{npt:>6} {int(np.median([r[1] for r in sel])):>8} {tc:7.1f} "
                     f"{tn:9.1f} {tn / tc:8.2f}")
    big = [r for r in rows if r[0] >= 16]
    lines.append("n = 16-48 points (median over slices and n): C "
                 f"{np.median([r[2] for r in big]):.1f} ns, numpy "
                 f"{np.median([r[3] for r in big]):.1f} ns per corner and point")
    text = "\n".join(lines) + "\n"
    print(text, end="")
    a.out.write_text(text)


if __name__ == "__main__":
    main()
