"""Grid convergence of the paper's study: F(d), k(d) of two runs on different grids.

    python -m tools.studies.paper_compare COARSE_DIR FINE_DIR

Each folder holds a bem_paper_curves.csv written by ``python -m tools.build_tables paper
--out DIR``; the largest relative change of F and k over the depths both runs share is
printed per L/R (tables/README.md quotes it for 256^2 -> 512^2).
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from .paper_tables import CURVES


def compare_curves(coarse, fine):
    """{L/R: (largest |F_coarse/F_fine - 1|, largest |k_coarse/k_fine - 1|,
    |F_coarse/F_fine - 1| at the deepest common depth)} of two runs."""
    from linecontact.tables import read_table
    a = read_table(CURVES, directory=coarse).columns
    b = read_table(CURVES, directory=fine).columns
    out = {}
    for q in np.unique(a["L_over_R"]):
        ma, mb = a["L_over_R"] == q, b["L_over_R"] == q
        if not mb.any():
            continue
        da, db = a["d_over_R"][ma], b["d_over_R"][mb]
        common, ia, ib = np.intersect1d(np.round(da, 12), np.round(db, 12),
                                        return_indices=True)
        if common.size == 0:
            continue
        Fa, Fb = a["F_over_EstarR2"][ma][ia], b["F_over_EstarR2"][mb][ib]
        ka, kb = a["k_over_EstarR"][ma][ia], b["k_over_EstarR"][mb][ib]
        out[float(q)] = (float(np.max(np.abs(Fa / Fb - 1))), float(np.max(np.abs(ka / kb - 1))),
                         float(np.abs(Fa[-1] / Fb[-1] - 1)))
    return out


def main(argv=None):
    p = argparse.ArgumentParser(prog="python -m tools.studies.paper_compare",
                                description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("coarse", type=Path, help="folder of the coarser run")
    p.add_argument("fine", type=Path, help="folder of the finer run")
    args = p.parse_args(argv)
    res = compare_curves(args.coarse, args.fine)
    print("L/R      max|dF/F|   max|dk/k|   |dF/F| at d_max")
    for q, (eF, ek, eend) in res.items():
        print(f"{q:5g}   {eF:9.3%}   {ek:9.3%}   {eend:9.3%}")
    if res:
        print(f"all: max|dF/F| = {max(v[0] for v in res.values()):.3%}, "
              f"max|dk/k| = {max(v[1] for v in res.values()):.3%}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
