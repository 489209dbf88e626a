"""How accurate is each model? Relative errors of F(d) and k(d) against the BEM.

Writes tables/model_accuracy.csv and docs/figures/model_accuracy.png, and prints the
summary tables (one per region and depth band, and the rows of the README's "Which model
to trust where"). Run from the repository root::

    python -m tools.build_tables accuracy          # about 2 minutes on 2 cores
    python -m tools.build_tables accuracy --bem-points 0 0   # skip the BEM check (5 s)

The 30 independent BEM solutions of the check run on the study runner (tools/studies/runner.py:
a local Dask cluster by default, ``--scheduler ADDRESS`` for an existing one,
``--checkpoint DIR --resume`` to continue an interrupted run).

Reference: the BEM. The universal curve *is* the BEM (exact scaling, docs/theory.md,
section 'Self-similarity'; table accuracy in its header), so the other models are
compared with it on a grid of L/R (0.1 ... 20) and d/R (1e-6 ... 0.15). The universal
model itself is compared with independent BEM solutions (tools.bem.cylinder.solve_depth, the
table's own grids and Richardson step) at depths that are *not* table nodes, which
measures its interpolation error plus the BEM's scatter.

Models: every row the command line prints (linecontact.models.standard_models): the
Li-Popov form with the paper's Table 1 spline (0.1 <= L/R <= 6), with the Eq. 11
constants (given for L/R >= 5; evaluated below that too, the figure marks where), with
the regenerated coefficients (if tables/lipopov_regenerated.csv exists), Eq. 2
(Puttock-Thwaite), the Johnson-type Eq. 4 with c = 1, 0.72, 0.572, Kunz's linear law and
the steel-only Palmgren and ISO 16281 formulas. All are compared at the E* of steel
on steel: every model's F is proportional to E* except the two steel formulas, which
apply to steel only; and each obeys F(lambda R, lambda L, lambda d) = lambda^2 F at fixed
E* (tests/test_models.py), so the errors depend on L/R and d/R alone. Where a model has
no answer (a Li-Popov form at d >= beta L^2/R) the error is recorded as "no answer".
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from linecontact.classical import STEEL_ESTAR
from linecontact.errors import OutOfRangeError
from linecontact.models import UniversalModel, get_model
from linecontact.tables import available_tables, write_table
from tools.studies.runner import add_runner_arguments, run_study_from_args, table_meta

REPO = Path(__file__).resolve().parents[2]
L_OVER_R = np.concatenate([np.round(np.arange(0.1, 1.0, 0.1), 1),
                           np.arange(1.0, 21.0, 1.0)])
D_OVER_R = np.geomspace(1e-6, 0.15, 31)
#: Radius of the compared cylinders [m] and E* [Pa] (the errors do not depend on R).
R_REF, E_REF = 5e-3, STEEL_ESTAR
#: Flags in the CSV (its loader refuses non-finite numbers).
NOT_APPLICABLE, NO_ANSWER = 98.0, 99.0
REGIONS = [("0.1 <= L/R < 1", L_OVER_R < 1),
           ("1 <= L/R < 5", (L_OVER_R >= 1) & (L_OVER_R < 5)),
           ("5 <= L/R <= 20", L_OVER_R >= 5)]
DEPTHS = [("d/R <= 1e-3", D_OVER_R <= 1e-3), ("d/R > 1e-3", D_OVER_R > 1e-3)]


def comparison_models():
    """(column tag, label, key, options) of the models compared with the BEM: the rows
    of linecontact.models.standard_models (the universal one excepted: it is the
    reference), each tagged with its ``accuracy_tag``."""
    models = [("lp_published", "Li-Popov, Table 1 spline", "li-popov",
               dict(coefficients="published")),
              ("lp_eq11", "Li-Popov, Eq. 11 constants", "li-popov",
               dict(coefficients="eq11", extrapolate=True))]
    if "lipopov_regenerated" in available_tables("lipopov_"):
        models.append(("lp_regenerated", "Li-Popov, regenerated coefficients",
                       "li-popov", dict(coefficients="regenerated")))
    models.append(("eq2", "Eq. 2 (Puttock-Thwaite)", "puttock-thwaite", {}))
    for c in (1.0, 0.72, 0.572):
        m = get_model("johnson", R_REF, R_REF, E_REF, c=c)
        models.append((m.accuracy_tag, f"Eq. 4, Johnson c = {c:g}", "johnson", dict(c=c)))
    models += [("kunz", "Kunz (F = 0.175 E* L d)", "kunz", {}),
               ("palmgren", "Palmgren (steel)", "palmgren", {}),
               ("iso16281", "ISO 16281 (steel)", "iso16281", {})]
    return models


def model_errors(models, l_over_r=L_OVER_R, d_over_r=D_OVER_R):
    """Signed relative errors (model/BEM - 1) of F and k on the (L/R, d/R) grid, and
    per model the L/R rows where it applies (NaN inside those: no answer)."""
    R, E = R_REF, E_REF
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


def bem_check_tasks(n_l=6, n_d=5, seed=0):
    """Tasks of the universal model's check: n_l L/R values (0.1 ... 20, log-spaced) x
    n_d depths d/R (1e-6 ... 0.15, jittered by up to 0.1 decade so that they miss the
    table's nodes), each clipped to the table's end d~_max."""
    from linecontact.universal import universal_curve
    d_max = universal_curve().d_max
    rng = np.random.default_rng(seed)
    tasks = []
    for lr in np.geomspace(0.1, 20, n_l) if n_l else []:
        for ldr in np.linspace(-6, math.log10(0.15), n_d) + rng.uniform(-0.1, 0.1, n_d):
            dt = min(10 ** ldr / lr ** 2, d_max)
            tasks.append({"key": f"lr={lr:.6g}_dr={10 ** ldr:.6g}", "l_over_r": float(lr),
                          "d_over_r": float(10 ** ldr), "d_tilde": float(dt)})
    return tasks


def bem_check(task):
    """One independent BEM solution at d~ (grids 256 and 512 cells along L/2, the
    table's Richardson step for F) against the universal model: (L/R, d/R, error of F,
    error of k)."""
    from linecontact.universal import universal_curve
    from tools.bem.cylinder import solve_depth
    curve = universal_curve()
    dt = task["d_tilde"]
    r1 = solve_depth(dt, 256, 32, tol=1e-7)
    r2 = solve_depth(dt, 512, 32, tol=1e-7)
    psi = 2 * r2.force - r1.force
    return (task["l_over_r"], task["d_over_r"], float(curve.psi(dt)) / psi - 1,
            float(curve.dpsi(dt)) / r2.stiffness - 1)


def _pct(x):
    """A relative error as a percentage with two significant digits ("190 %")."""
    return f"{float(f'{x * 100:.2g}'):g} %"


def _cell(errs, tag, rows, dsel):
    """(F text, k text) of the largest |error| over `rows` x `dsel` where it applies."""
    eF, ek, applies = errs[tag]
    rows = rows & applies
    if not rows.any():
        return "not applicable", "not applicable"
    f = np.abs(eF[np.ix_(rows, dsel)])
    k = np.abs(ek[np.ix_(rows, dsel)])
    if np.all(np.isnan(f)):
        return "no answer", "no answer"
    note = " (no answer at some d)" if np.isnan(f).any() else ""
    return _pct(np.nanmax(f)) + note, _pct(np.nanmax(k))


def _readme_cell(errs, tag, region, dsel):
    """F's largest |error|, k's added where larger by a half, then the notes."""
    eF, ek, applies = errs[tag]
    rows = region & applies
    if not rows.any():
        return "not applicable"
    f = np.abs(eF[np.ix_(rows, dsel)])
    k = np.abs(ek[np.ix_(rows, dsel)])
    if np.all(np.isnan(f)):
        return "no answer"
    text = _pct(np.nanmax(f))
    if np.nanmax(k) > 1.5 * np.nanmax(f) and _pct(np.nanmax(k)) != text:
        text += f" (k: {_pct(np.nanmax(k))})"
    if np.isnan(f).any():
        text += " (no answer at some d)"
    if rows.sum() < region.sum():
        text += f" (L/R <= {L_OVER_R[rows].max():g} only)"
    return text


def summary(errs, models):
    """Markdown table: largest |error| per model, L/R region and depth band (where the
    model applies)."""
    lines = ["| model | L/R | d/R | max abs. error F | max abs. error k |",
             "|---|---|---|---|---|"]
    for tag, label, _, _ in models:
        applies = errs[tag][2]
        for rname, region in REGIONS:
            rows = region & applies
            if rows.any() and rows.sum() < region.sum():
                rname += f" (applies to L/R <= {L_OVER_R[rows].max():g})"
            for dname, dsel in DEPTHS:
                fs, ks = _cell(errs, tag, region, dsel)
                lines.append(f"| {label} | {rname} | {dname} | {fs} | {ks} |")
    return "\n".join(lines)


def readme_rows(errs, models):
    """The rows of the README's table "Which model to trust where": one per model and
    depth band, one column per L/R region, F's error with k's added where it is larger
    by a half or more."""
    lines = ["| model | " + " | ".join(r for r, _ in REGIONS) + " |",
             "|---|" + "---|" * len(REGIONS)]
    for tag, label, _, _ in models:
        for dname, dsel in DEPTHS:
            cells = [_readme_cell(errs, tag, region, dsel) for _, region in REGIONS]
            lines.append(f"| {label}, {dname} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def figure(errs, models, uni, path):
    """Error maps: per model |error| of F(d) and of k(d) over (L/R, d/R), two models to a
    row; the universal model's check against independent BEM solutions last."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import BoundaryNorm

    levels = [0, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1, 3e-1, 1e9]
    labels = ["<0.1%", "0.1-0.3%", "0.3-1%", "1-3%", "3-10%", "10-30%", ">30%"]
    cmap = plt.get_cmap("RdYlGn_r", len(levels) - 1)
    norm = BoundaryNorm(levels, cmap.N)
    panels = [(tag, label) for tag, label, _, _ in models] + [("universal", None)]
    nrow = (len(panels) + 1) // 2
    fig, axes = plt.subplots(nrow, 4, figsize=(15, 3.1 * nrow), sharex=True, sharey=True,
                             constrained_layout=True, squeeze=False)
    X, Y = np.meshgrid(L_OVER_R, D_OVER_R, indexing="ij")
    pc = None
    for p, (tag, label) in enumerate(panels):
        for r, name in enumerate(("F", "k")):
            ax = axes[p // 2, 2 * (p % 2) + r]
            ax.set_xscale("log")
            ax.set_yscale("log")
            if tag == "universal":
                if len(uni):
                    ax.scatter(uni[:, 0], uni[:, 1], c=np.abs(uni[:, 2 + r]), cmap=cmap,
                               norm=norm, s=50, edgecolors="k")
                ax.set_title(f"Universal curve vs independent BEM\nerror of {name}(d)",
                             fontsize=9)
                continue
            e = np.abs(errs[tag][r])
            e[~errs[tag][2]] = np.nan
            ax.set_facecolor("0.85")
            pc = ax.pcolormesh(X, Y, np.ma.masked_invalid(e), cmap=cmap, norm=norm,
                               shading="nearest")
            ax.set_title(f"{label}\nerror of {name}(d)", fontsize=9)
            if tag == "lp_eq11":
                ax.axvline(5, color="k", ls="--", lw=1)
                ax.text(5.3, 2e-6, "Eq. 11 given\nfor L/R >= 5", fontsize=7)
    # the grid's cell edges (geometric midpoints), the same on every panel
    half = np.sqrt(D_OVER_R[1] / D_OVER_R[0])
    axes[0, 0].set_ylim(D_OVER_R[0] / half, D_OVER_R[-1] * half)
    axes[0, 0].set_xlim(L_OVER_R[0] / np.sqrt(2), L_OVER_R[-1] * np.sqrt(21 / 20))
    for ax in axes[-1]:
        ax.set_xlabel("L/R")
    for ax in axes[:, 0]:
        ax.set_ylabel("d/R")
    for ax in axes.flat[2 * len(panels):]:
        ax.set_visible(False)
    cb = fig.colorbar(pc, ax=axes, ticks=[(a + b) / 2 for a, b in
                                          zip(levels[:-2], levels[1:-1])] + [0.5],
                      shrink=0.5)
    cb.ax.set_yticklabels(labels)
    cb.set_label("relative error against the BEM (grey: no answer / not applicable)")
    fig.suptitle("Accuracy of each model against the boundary-element solution "
                 "(python -m tools.build_tables accuracy)")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=80)
    plt.close(fig)


def add_arguments(parser):
    """Options of ``python -m tools.build_tables accuracy``."""
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder of model_accuracy.csv (default tables/)")
    parser.add_argument("--figure", type=Path,
                        default=REPO / "docs" / "figures" / "model_accuracy.png")
    parser.add_argument("--bem-points", type=int, nargs=2, default=(6, 5),
                        metavar=("N_L", "N_D"),
                        help="independent BEM checks of the universal model: L/R values, "
                             "d/R values (default 6 5; 0 0 skips them)")
    add_runner_arguments(parser)


def run(args):
    """Compute the error grid, write the table and the figure, print the summaries."""
    models = comparison_models()
    errs = model_errors(models)
    tasks = bem_check_tasks(*args.bem_points)
    uni = np.array(run_study_from_args(bem_check, tasks, args,
                                       desc="universal model vs BEM") if tasks else [],
                   dtype=float).reshape(-1, 4)
    cols = {"L_over_R": np.repeat(L_OVER_R, len(D_OVER_R)),
            "d_over_R": np.tile(D_OVER_R, len(L_OVER_R))}
    for tag, _, _, _ in models:
        applies = np.repeat(errs[tag][2], len(D_OVER_R))
        for i, q in enumerate("Fk"):
            v = np.where(applies, errs[tag][i].ravel(), NOT_APPLICABLE)
            cols[f"{q}_err_{tag}"] = np.where(np.isnan(v), NO_ANSWER, v)
    if len(uni):
        check = (f"universal model vs independent BEM at {len(uni)} off-node points: "
                 f"largest |error| F {np.abs(uni[:, 2]).max():.1e}, k "
                 f"{np.abs(uni[:, 3]).max():.1e} (k of the BEM: flat-punch value, "
                 "scatters by ~0.5 %)")
    else:
        check = "universal model not re-checked against the BEM in this run"
    meta = table_meta(
        getattr(args, "command_line", "python -m tools.build_tables accuracy"),
        title="Relative error of each model's F(d) and k(d) against the BEM (universal "
              "curve), model/BEM - 1",
        source="python -m tools.build_tables accuracy (tools/studies/accuracy.py, this "
               "repository)",
        units="L_over_R [-], d_over_R [-], F_err_<model>, k_err_<model> [-] signed "
              f"relative errors; {NOT_APPLICABLE:g} = the model does not apply at this "
              f"L/R (outside its coefficient table), {NO_ANSWER:g} = it gives no answer "
              "at this depth (beyond its bound beta L^2/R)",
        models="; ".join(f"{t} = {lab}" for t, lab, _, _ in models),
        conditions=f"R = {R_REF:g} m, E* = {E_REF:.6g} Pa (steel on steel); the errors "
                   "depend on L/R and d/R only",
        accuracy="reference = tables/universal_curve.csv; " + check)
    args.out.mkdir(parents=True, exist_ok=True)
    write_table(args.out / "model_accuracy.csv", meta, cols)
    figure(errs, models, uni, args.figure)
    print(summary(errs, models))
    if len(uni):
        print("| Universal curve vs independent BEM (off-node) | all | all | "
              f"{_pct(np.abs(uni[:, 2]).max())} | {_pct(np.abs(uni[:, 3]).max())} |")
    print("\nREADME rows:\n")
    print(readme_rows(errs, models))
    print(f"\nwrote {args.out / 'model_accuracy.csv'} and {args.figure}")
    return 0


if __name__ == "__main__":
    from tools.build_tables import main
    sys.exit(main(["accuracy", *sys.argv[1:]]))
