"""Figures of the paper's study rerun (tools/studies/paper_study.py), as PNG in docs/figures/.

    python -m tools.studies.figures_paper [--tables tables] [--out docs/figures] [--n 512]

Reads tables/bem_paper_curves.csv, tables/lipopov_regenerated.csv,
tables/lipopov_published.csv and tables/paper_residual_comparison.csv; only the
pressure field (Fig. 2) runs the BEM (one sweep to d = 0.1 R, about half a minute on
512 x 512). matplotlib is an optional dependency (the ``tools`` extra).

``paper_fig3_collapse.png``
    All 29 L/R in dimensionless form (docs/theory.md, section 'Self-similarity'): F R/(E* L^3) against d R/L^2,
    and the extracted MDR profiles g~ against x~ (Eq. 8) with their fits of Eq. 9
    (the paper's Fig. 3b).
``paper_fig4_coefficients.png``
    alpha and beta against L/R: regenerated, published Table 1, Eq. 11 (Fig. 4).
``paper_fig7_profile.png``
    The BEM profile against the one implied by Puttock & Thwaite's Eq. 2
    (alpha = pi/2, beta = 1) and by Eq. 11 (alpha = pi/2, beta = 0.4573) (Fig. 7).
``paper_fig2_pressure.png``
    Pressure field at L/R = 5, d = 0.1 R, with its peaks at the cylinder ends (Fig. 2).
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def _plt():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:  # pragma: no cover
        sys.exit("tools/studies/figures_paper.py needs matplotlib: pip install 'linecontact[tools]'")
    plt.rcParams.update({"font.size": 10, "axes.grid": True, "grid.alpha": 0.3,
                         "figure.dpi": 110, "savefig.dpi": 130})
    return plt


def _load(tables):
    from linecontact.tables import read_table
    from tools.studies.paper_tables import CURVES, REGENERATED, RESIDUAL_COMPARISON
    cur = read_table(CURVES, directory=tables)
    reg = read_table(REGENERATED, directory=tables)
    pub = read_table("lipopov_published")
    try:
        comp = read_table(RESIDUAL_COMPARISON, directory=tables)
    except FileNotFoundError:
        comp = None
    return cur, reg, pub, comp


def _colors(plt, qs):
    cmap = plt.get_cmap("viridis")
    norm = plt.matplotlib.colors.LogNorm(vmin=min(qs), vmax=max(qs))
    return cmap, norm


def fig3(plt, cur, reg, out):
    from linecontact.lipopov import dimensionless_profile
    c = cur.columns
    qs = np.unique(c["L_over_R"])
    cmap, norm = _colors(plt, qs)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    for q in qs:
        m = c["L_over_R"] == q
        col = cmap(norm(q))
        ax1.loglog(c["d_tilde"][m], c["F_tilde"][m], ".", ms=2.5, color=col)
        ax2.loglog(c["x_tilde"][m], c["d_tilde"][m], ".", ms=2.5, color=col)
        i = np.flatnonzero(reg.columns["L_over_R"] == q)
        if i.size:
            a, b = reg.columns["alpha"][i[0]], reg.columns["beta"][i[0]]
            x = np.geomspace(c["x_tilde"][m].min(), c["x_tilde"][m].max(), 200)
            ax2.loglog(x, dimensionless_profile(x, a, b), "-", lw=0.9, color=col)
    # the universal curve (tables/universal_curve.csv: adapted grids, Richardson), drawn
    # over the same range: an independent BEM computation of the one curve
    from linecontact.tables import read_table
    u = read_table("universal_curve").columns
    span = (u["d_tilde"] >= c["d_tilde"].min() / 2) & (u["d_tilde"] <= c["d_tilde"].max() * 2)
    kw = dict(color="k", lw=1.0, ls="--", label="universal curve (tables/universal_curve.csv)")
    ax1.loglog(u["d_tilde"][span], u["Psi"][span], **kw)
    ax2.loglog(u["x_tilde"][span], u["d_tilde"][span], **kw)
    ax1.legend(fontsize=8, loc="upper left")
    ax2.legend(fontsize=8, loc="upper left")
    ax1.set_xlabel(r"$\tilde d = dR/L^2$")
    ax1.set_ylabel(r"$\tilde F = FR/(E^* L^3)$")
    ax1.set_title("(a) force: every L/R on one curve (self-similarity)")
    ax2.xaxis.set_minor_formatter(plt.matplotlib.ticker.NullFormatter())
    ax2.set_xlabel(r"$\tilde x = k/(2E^*L)$")
    ax2.set_ylabel(r"$\tilde g = dR/L^2$")
    ax2.set_title("(b) MDR profile, BEM points and fits of Eq. 9 (coloured lines)")
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=norm)
    cb = fig.colorbar(sm, ax=[ax1, ax2], shrink=0.9)
    cb.set_label("L/R")
    fig.suptitle(f"BEM rerun of Li & Popov's study: {len(qs)} L/R, "
                 f"d up to 0.15 R ({_grid_label(cur)})")
    path = out / "paper_fig3_collapse.png"
    fig.savefig(path)
    plt.close(fig)
    return path


def _grid_label(table):
    g = table.meta.get("grid", "")
    return g.split(" cells")[0] + " cells" if "cells" in g else "grid n/a"


def fig4(plt, reg, pub, comp, out):
    from scipy.interpolate import CubicSpline

    from linecontact.lipopov import ALPHA_EQ11, BETA_EQ11
    from tools.studies.paper_fit import RESIDUALS
    r, p = reg.columns, pub.columns
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
    q = np.geomspace(r["L_over_R"].min(), r["L_over_R"].max(), 300)
    # the runtime's interpolation of a table in any folder: the not-a-knot cubic spline in
    # log(L/R) (tests/test_paper_study.py asserts the runtime's equals it to 1e-13)
    lq = np.log(r["L_over_R"])
    spline = (CubicSpline(lq, r["alpha"])(np.log(q)), CubicSpline(lq, r["beta"])(np.log(q)))
    shipped = reg.meta.get("residual", "").split(":")[0]
    alt = "F_rel"
    for j, (ax, key, eq11) in enumerate(zip(axes, ("alpha", "beta"),
                                            (ALPHA_EQ11, BETA_EQ11))):
        ax.semilogx(r["L_over_R"], r[key], "o", ms=4, color="C0",
                    label=f"regenerated ({shipped} fit)")
        ax.semilogx(q, spline[j], "-", lw=0.8, color="C0")
        if comp is not None and alt != shipped:
            m = comp.columns["residual"] == RESIDUALS[alt][0]
            ax.semilogx(comp.columns["L_over_R"][m], comp.columns[key][m], "^", ms=4,
                        mfc="none", color="C2", label=f"regenerated ({alt} fit)")
        ax.semilogx(p["L_over_R"], p[key], "s", ms=5, mfc="none", color="C3",
                    label="published, Table 1")
        ax.semilogx([5, r["L_over_R"].max()], [eq11, eq11], "--", color="C1",
                    label=f"Eq. 11: {key} = {eq11:.4g}")
        ax.set_xlabel("L/R")
        ax.set_ylabel(rf"$\{key}$")
        if key == "beta":
            ax.set_yscale("log")
        ax.legend(fontsize=8)
    axes[0].set_title(r"$\alpha$ of Eq. 9")
    axes[1].set_title(r"$\beta$ of Eq. 9")
    path = out / "paper_fig4_coefficients.png"
    fig.savefig(path)
    plt.close(fig)
    return path


def fig7(plt, cur, reg, out):
    from linecontact.lipopov import ALPHA_EQ11, BETA_EQ11
    from linecontact.lipopov import dimensionless_profile
    c = cur.columns
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
    for ax, sel in ((ax1, (5.0, 10.0, 20.0)), (ax2, (0.5, 1.0, 2.0))):
        xs = []
        for k, q in enumerate(sel):
            m = c["L_over_R"] == q
            if not m.any():
                continue
            ax.plot(c["x_tilde"][m], c["d_tilde"][m], "o", ms=3, color=f"C{k}",
                    label=f"BEM, L/R = {q:g}")
            i = np.flatnonzero(reg.columns["L_over_R"] == q)
            x = np.linspace(1e-3, c["x_tilde"][m].max() * 1.05, 300)
            xs.append(x[-1])
            if i.size:
                ax.plot(x, dimensionless_profile(x, reg.columns["alpha"][i[0]], reg.columns["beta"][i[0]]),
                        "-", lw=1, color=f"C{k}")
        x = np.linspace(1e-3, max(xs), 400)
        ax.plot(x, dimensionless_profile(x, math.pi / 2, 1.0), "k--", lw=1.2,
                label=r"Eq. 2 (P&T): $\alpha=\pi/2$, $\beta=1$")
        ax.plot(x, dimensionless_profile(x, ALPHA_EQ11, BETA_EQ11), "k:", lw=1.2,
                label=r"Eq. 11: $\alpha=\pi/2$, $\beta=0.4573$")
        top = max(c["d_tilde"][np.isin(c["L_over_R"], sel)].max() * 1.15, 1e-3)
        ax.set_ylim(0, top)
        ax.set_xlim(0, max(xs))
        ax.set_xlabel(r"$\tilde x = x/L$")
        ax.set_ylabel(r"$\tilde g = gR/L^2$")
        ax.legend(fontsize=8)
    ax1.set_title("long cylinders: BEM profile (points), its fit (lines)")
    ax2.set_title("short cylinders")
    path = out / "paper_fig7_profile.png"
    fig.savefig(path)
    plt.close(fig)
    return path


def fig2(plt, out, n=512, l_over_r=5.0, d_over_r=0.1):
    from tools.bem.cylinder import sweep
    res = sweep(l_over_r, n=n, steps=20, d_max_over_r=d_over_r, fields=True,
                stiffness=None, progress=False)
    p = res.pressure[-1]                      # full field, rows along x (axis)
    g = res.grid
    x = (np.arange(-g.mx, g.mx) + 0.5) * g.dx / res.radius
    y = (np.arange(-g.my, g.my) + 0.5) * g.dy / res.radius
    contact = p > 0
    ymax = np.abs(y[contact.any(axis=0)]).max() * 1.3
    keep = np.abs(y) <= ymax
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 6.5), constrained_layout=True,
                                   gridspec_kw=dict(height_ratios=[1.2, 1]))
    # colour scale capped below the end singularity (the peak itself is in the line plot)
    vmax = 2.5 * p[g.mx, g.my] / res.estar
    pm = ax1.pcolormesh(x, y[keep], p[:, keep].T / res.estar, shading="auto",
                        cmap="magma", vmin=0, vmax=vmax)
    ax1.set_xlabel("x/R (along the axis)")
    ax1.set_ylabel("y/R")
    ax1.set_title(f"contact pressure p/E*, L/R = {l_over_r:g}, d = {d_over_r:g} R "
                  f"({2 * g.mx} x {2 * g.my} cells; F = "
                  f"{res.force[-1] / (res.estar * res.radius**2):.4g} E* R^2)")
    ax1.grid(False)
    fig.colorbar(pm, ax=ax1, label="p/E* (capped)", extend="max")
    j0 = g.my                                 # first row above y = 0
    ax2.plot(x, p[:, j0] / res.estar, "-", color="C3", label="p on the axis, y = 0")
    ax2.plot(x, p.sum(axis=1) * g.dy / (res.estar * res.radius), "-", color="C0",
             label=r"line load $\int p\,dy$ / (E* R)")
    ax2.set_xlabel("x/R")
    ax2.set_ylabel("p/E*,  line load/(E* R)")
    ax2.set_title("the pressure peaks at the cylinder ends (edge of the rigid flat ends)")
    ax2.legend(fontsize=8)
    path = out / "paper_fig2_pressure.png"
    fig.savefig(path)
    plt.close(fig)
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m tools.studies.figures_paper",
                                 description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tables", type=Path, default=ROOT / "tables",
                    help="folder with the paper study's tables (default tables/)")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "figures")
    ap.add_argument("--n", type=int, default=512, help="grid of the pressure field")
    ap.add_argument("--skip-pressure", action="store_true",
                    help="no BEM run: leave Fig. 2 out")
    args = ap.parse_args(argv)
    plt = _plt()
    args.out.mkdir(parents=True, exist_ok=True)
    cur, reg, pub, comp = _load(args.tables)
    paths = [fig3(plt, cur, reg, args.out), fig4(plt, reg, pub, comp, args.out),
             fig7(plt, cur, reg, args.out)]
    if not args.skip_pressure:
        paths.append(fig2(plt, args.out, n=args.n))
    for p in paths:
        print(f"wrote {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
