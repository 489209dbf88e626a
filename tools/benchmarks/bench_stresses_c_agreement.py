"""The C corner sums against numpy's on random rollers: roller_stresses' worst values.

    OPENBLAS_NUM_THREADS=1 nice -n 10 python -m tools.benchmarks.bench_stresses_c_agreement \
        --seed 2 --n 300

Random rollers (the study profiles, L 8-30 mm, R 3-10 mm, forces from light to edge
loaded, tilt 0 or up to 4 mrad either way, friction 0 or 0-0.5, Poisson 0.2-0.45),
each solved once and its stresses computed with the C corner sums and with numpy's
(stresses.love._CORNERS); reports the largest relative difference of every measure's worst
value and how many worst points lie on another slice (untilted: the mirror slice, a
tie). Writes tools/benchmarks/results/stresses_c_agreement.txt.
"""
from __future__ import annotations

import argparse
import datetime
from pathlib import Path

import numpy as np

import linecontact
from linecontact import stresses
from linecontact.roller import ProfiledRoller
from linecontact.stresses import love as st
from tools.studies.roller_study import make_profile

REPO = Path(__file__).resolve().parents[2]
ESTAR = 115.385e9
NAMES = ["circular crown", "iso16281", "lundberg", "johns-gohar", "straight with end relief"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=2)
    ap.add_argument("--n", type=int, default=300)
    ap.add_argument("--out", type=Path, default=REPO / "tools" / "benchmarks" / "results"
                    / "stresses_c_agreement.txt")
    a = ap.parse_args(argv)
    if st._cstresses is None:
        raise SystemExit("the C extension linecontact._ckernels is not built or current here")
    rng = np.random.default_rng(a.seed)
    worst, where, other, mirror, checks = 0.0, "", 0, 0, 0
    saved = st._CORNERS[0]
    try:
        for it in range(a.n):
            L, R = rng.uniform(8e-3, 30e-3), rng.uniform(3e-3, 10e-3)
            name = NAMES[rng.integers(len(NAMES))]
            prof = (make_profile(name, L, radius=R) if name != "circular crown"
                    else f"circular:Rc={rng.uniform(0.1, 2):.3f}")
            model = ProfiledRoller(R, L, ESTAR, prof)
            F = 10 ** rng.uniform(2, 4.7) * L / 14e-3
            tilt = rng.choice([0.0, rng.uniform(-4e-3, 4e-3)])
            mu, nu = rng.choice([0.0, rng.uniform(0, 0.5)]), rng.uniform(0.2, 0.45)
            sol = model.at_force(F, tilt=tilt)
            res = {}
            for c in ("c", "numpy"):
                st._CORNERS[0] = c
                res[c] = stresses.roller_stresses(sol, mu, nu, roller=model).worst
            for m in stresses.MEASURES:
                u, v = res["c"][m], res["numpy"][m]
                checks += 1
                r = abs(u["value"] - v["value"]) / abs(v["value"])
                if r > worst:
                    worst, where = r, (f"{name}, L {L * 1e3:.1f} mm, F {F:.0f} N, tilt "
                                       f"{tilt:.2g}, mu {mu:.2f}, nu {nu:.2f}, {m}")
                if u["slice"] != v["slice"]:
                    other += 1
                    mirror += tilt == 0.0 and u["slice"] + v["slice"] == sol.x.size - 1
    finally:
        st._CORNERS[0] = saved
    text = (f"bench_stresses_c_agreement: linecontact {linecontact.__version__}, numpy "
            f"{np.__version__}, {datetime.date.today().isoformat()}, seed {a.seed}, "
            f"{a.n} rollers\n"
            f"worst values, C corner sums against numpy's ({checks} checks): largest "
            f"relative difference {worst:.2g} ({where}); {other} on another slice "
            f"({mirror} of them the mirror slice of an untilted roller)\n")
    print(text, end="")
    a.out.write_text(text)


if __name__ == "__main__":
    main()
