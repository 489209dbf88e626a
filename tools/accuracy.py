"""How accurate is each model? Relative errors of F(d) and k(d) against the BEM.

Writes tables/model_accuracy.csv and docs/figures/model_accuracy.png, and prints the
summary table of tables/README.md. Run from the repository root::

    python -m tools.accuracy            # about a minute

Reference: the BEM. The universal curve *is* the BEM (exact scaling, docs/theory.md, section
'Self-similarity';
table accuracy in its header), so the other models are compared with it on a dense
grid of L/R (0.1 ... 20) and d/R (1e-6 ... 0.15). The universal model itself is compared
with independent BEM solutions (tools.cylinder.solve_depth, the table's own grids and
Richardson step) at depths that are *not* table nodes, which measures its
interpolation error plus the BEM's scatter.

Models: the Li-Popov form with the paper's Table 1 spline (0.1 <= L/R <= 6), with the
Eq. 11 constants (given for L/R >= 5; shown extrapolated below, the figure marks
where), with the regenerated coefficients (if tables/lipopov_regenerated.csv exists),
and Eq. 2 (Puttock-Thwaite). Where a Li-Popov form has no solution (d at or beyond
beta L^2/R) the error is recorded as NaN and drawn as "no answer".
"""
from __future__ import annotations

import argparse
import datetime as _dt
import math
import sys
from pathlib import Path

import numpy as np

from linecontact.models import get_model
from tools.build_tables import code_version
from linecontact.tables import available_tables, write_table
from linecontact.models import UniversalModel
from linecontact.validity import OutOfRangeError

REPO = Path(__file__).resolve().parent.parent
L_OVER_R = np.concatenate([np.round(np.arange(0.1, 1.0, 0.1), 1),
                           np.arange(1.0, 21.0, 1.0)])
D_OVER_R = np.geomspace(1e-6, 0.15, 31)


def comparison_models():
    """(column tag, label, key, options) of the models compared with the BEM."""
    models = [("lp_published", "Li-Popov, Table 1 spline", "li-popov",
               dict(coefficients="published")),
              ("lp_eq11", "Li-Popov, Eq. 11 constants", "li-popov",
               dict(coefficients="eq11", extrapolate=True))]
    if "lipopov_regenerated" in available_tables("lipopov_"):
        models.append(("lp_regenerated", "Li-Popov, regenerated coefficients",
                       "li-popov", dict(coefficients="regenerated")))
    models.append(("eq2", "Eq. 2 (Puttock-Thwaite)", "puttock-thwaite", {}))
    return models


def model_errors(models, l_over_r=L_OVER_R, d_over_r=D_OVER_R):
    """Signed relative errors (model/BEM - 1) of F and k on the (L/R, d/R) grid, and
    per model the L/R rows where it applies (NaN inside those: no answer)."""
    R, E = 1.0, 1.0
    out = {}
    for tag, _, key, opts in models:
        eF = np.full((len(l_over_r), len(d_over_r)), np.nan)
        ek = np.full_like(eF, np.nan)
        applies = np.zeros(len(l_over_r), dtype=bool)
        for i, lr in enumerate(l_over_r):
            ref = UniversalModel(R, lr * R, E)
            d = d_over_r * R
            F0, k0 = ref.force(d), ref.stiffness(d)
            try:
                m = get_model(key, R, lr * R, E, **opts)
                m.check_applicable()
            except OutOfRangeError:
                continue
            applies[i] = True
            for j, dj in enumerate(d):
                try:
                    eF[i, j] = m.force(dj) / F0[j] - 1
                    ek[i, j] = m.stiffness(dj) / k0[j] - 1
                except OutOfRangeError:
                    pass
        out[tag] = (eF, ek, applies)
    return out


def universal_errors(n_l=6, n_d=5, seed=0):
    """Universal model against independent BEM solutions off the table's nodes."""
    from tools.cylinder import solve_depth
    from linecontact.universal import universal_curve
    curve = universal_curve()
    rng = np.random.default_rng(seed)
    lrs = np.geomspace(0.1, 20, n_l)
    rows = []
    for lr in lrs:
        for ldr in np.linspace(-6, math.log10(0.15), n_d) + rng.uniform(-0.1, 0.1, n_d):
            dt = min(10 ** ldr / lr ** 2, curve.d_max)
            r1 = solve_depth(dt, 256, 32, tol=1e-7)
            r2 = solve_depth(dt, 512, 32, tol=1e-7)
            psi = 2 * r2.force - r1.force
            rows.append((lr, 10 ** ldr, float(curve.psi(dt)) / psi - 1,
                         float(curve.dpsi(dt)) / r2.stiffness - 1))
    return np.array(rows)


def summary(errs, models):
    """Markdown table: largest |error| per model and region (where the model applies)."""
    regions = [("0.1 <= L/R < 1", L_OVER_R < 1),
               ("1 <= L/R < 5", (L_OVER_R >= 1) & (L_OVER_R < 5)),
               ("5 <= L/R <= 20", L_OVER_R >= 5)]
    depths = [("d/R <= 1e-3", D_OVER_R <= 1e-3), ("d/R > 1e-3", D_OVER_R > 1e-3)]
    lines = ["| model | L/R | d/R | max abs. error F | max abs. error k |",
             "|---|---|---|---|---|"]
    for tag, label, _, _ in models:
        eF, ek, applies = errs[tag]
        for rname, region in regions:
            rows = region & applies
            if rows.any() and rows.sum() < region.sum():
                rname += f" (applies to L/R <= {L_OVER_R[rows].max():g})"
            for dname, dsel in depths:
                f = np.abs(eF[np.ix_(rows, dsel)])
                k = np.abs(ek[np.ix_(rows, dsel)])
                if not rows.any():
                    fs = ks = "not applicable"
                elif np.all(np.isnan(f)):
                    fs = ks = "no answer"
                else:
                    note = " (no answer at some d)" if np.isnan(f).any() else ""
                    fs = f"{np.nanmax(f) * 100:.2g} %{note}"
                    ks = f"{np.nanmax(k) * 100:.2g} %"
                lines.append(f"| {label} | {rname} | {dname} | {fs} | {ks} |")
    return "\n".join(lines)


def figure(errs, models, uni, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm

    levels = [0, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1, 3e-1, 1e9]
    labels = ["<0.1%", "0.1-0.3%", "0.3-1%", "1-3%", "3-10%", "10-30%", ">30%"]
    cmap = plt.get_cmap("RdYlGn_r", len(levels) - 1)
    norm = BoundaryNorm(levels, cmap.N)
    n = len(models)
    fig, axes = plt.subplots(2, n + 1, figsize=(4.0 * (n + 1), 7.2), sharey="row",
                             constrained_layout=True)
    X, Y = np.meshgrid(L_OVER_R, D_OVER_R, indexing="ij")
    for c, (tag, label, _, _) in enumerate(models):
        for r, name in enumerate(("F", "k")):
            ax = axes[r, c]
            e = np.abs(errs[tag][r])
            e[~errs[tag][2]] = np.nan
            ax.set_facecolor("0.85")
            pc = ax.pcolormesh(X, Y, np.ma.masked_invalid(e), cmap=cmap, norm=norm,
                               shading="nearest")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title(f"{label}\nerror of {name}(d)", fontsize=9)
            if tag == "lp_eq11":
                ax.axvline(5, color="k", ls="--", lw=1)
                ax.text(5.3, 2e-6, "Eq. 11 given\nfor L/R >= 5", fontsize=7)
            if r == 1:
                ax.set_xlabel("L/R")
            if c == 0:
                ax.set_ylabel("d/R")
    for r, name in enumerate(("F", "k")):
        ax = axes[r, n]
        ax.scatter(uni[:, 0], uni[:, 1], c=np.abs(uni[:, 2 + r]), cmap=cmap, norm=norm,
                        s=60, edgecolors="k")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"Universal curve vs independent BEM\nerror of {name}(d)", fontsize=9)
        if r == 1:
            ax.set_xlabel("L/R")
    cb = fig.colorbar(pc, ax=axes, ticks=[(a + b) / 2 for a, b in
                                          zip(levels[:-2], levels[1:-1])] + [0.5],
                      shrink=0.8)
    cb.ax.set_yticklabels(labels)
    cb.set_label("relative error against the BEM (grey: no answer / not applicable)")
    fig.suptitle("Accuracy of each model against the boundary-element solution "
                 "(python -m tools.accuracy)")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=REPO / "tables")
    parser.add_argument("--figure", type=Path,
                        default=REPO / "docs" / "figures" / "model_accuracy.png")
    parser.add_argument("--bem-points", type=int, nargs=2, default=(6, 5),
                        metavar=("N_L", "N_D"),
                        help="independent BEM checks of the universal model: L/R values, "
                             "d/R values (default 6 5)")
    args = parser.parse_args(argv)
    models = comparison_models()
    errs = model_errors(models)
    uni = universal_errors(*args.bem_points)
    cols = {"L_over_R": np.repeat(L_OVER_R, len(D_OVER_R)),
            "d_over_R": np.tile(D_OVER_R, len(L_OVER_R))}
    for tag, _, _, _ in models:
        applies = np.repeat(errs[tag][2], len(D_OVER_R))
        cols[f"F_err_{tag}"] = np.where(applies, errs[tag][0].ravel(), 98.0)
        cols[f"k_err_{tag}"] = np.where(applies, errs[tag][1].ravel(), 98.0)
    # the loader refuses non-finite numbers: flags 98 (not applicable) and 99 (no answer)
    for k, v in cols.items():
        cols[k] = np.where(np.isnan(v), 99.0, v)
    meta = {
        "title": "Relative error of each model's F(d) and k(d) against the BEM "
                 "(universal curve), model/BEM - 1",
        "source": "python -m tools.accuracy (this repository)",
        "units": "L_over_R [-], d_over_R [-], F_err_<model>, k_err_<model> [-] signed "
                 "relative errors; 98 = the model does not apply at this L/R (outside its "
                 "coefficient table), 99 = it gives no answer at this depth (beyond its "
                 "bound beta L^2/R)",
        "models": "; ".join(f"{t} = {l}" for t, l, _, _ in models),
        "generated_by": "python -m tools.accuracy " + " ".join(argv or sys.argv[1:]),
        "date": _dt.date.today().isoformat(),
        "version": code_version(),
        "accuracy": "reference = tables/universal_curve.csv; universal model vs "
                    f"independent BEM at {len(uni)} off-node points: largest |error| "
                    f"F {np.abs(uni[:, 2]).max():.1e}, k {np.abs(uni[:, 3]).max():.1e} "
                    "(k of the BEM: flat-punch value, scatters by ~0.5 %)",
    }
    args.out.mkdir(parents=True, exist_ok=True)
    write_table(args.out / "model_accuracy.csv", meta, cols)
    figure(errs, models, uni, args.figure)
    print(summary(errs, models))
    print()
    print("| Universal curve vs independent BEM (off-node) | all | all | "
          f"{np.abs(uni[:, 2]).max() * 100:.2g} % | {np.abs(uni[:, 3]).max() * 100:.2g} % |")
    print(f"\nwrote {args.out / 'model_accuracy.csv'} and {args.figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
