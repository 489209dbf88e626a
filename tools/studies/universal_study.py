"""The universal curve of the finite cylinder: tables/universal_curve.csv.

docs/theory.md, section 'Self-similarity': with the parabolic gap h = y^2/(2R) the contact problem depends on the
dimensionless depth d~ = d R / L^2 alone, so for every L/R

    F = E* L^3/R * Psi(d~),     k = dF/dd = E* L * Psi'(d~),

and the MDR profile (docs/theory.md, section 'MDR': x = k/(2E*), g = d) is g = (L^2/R) Phi(x/L) with
x~ = Psi'(d~)/2 and g~ = d~ (one Phi for all L/R).

What this computes, per depth (log-spaced in d~, each on its own adapted grid,
tools.bem.cylinder.solve_depth with L = R = E* = 1):

1. Psi on two grids, n_length and 2 n_length cells along the half-length (n_width
   across the contact half-width on both). The force converges at first order in the
   cell length along the axis (the pressure of a flat-ended cylinder is singular at its
   ends; measured order 1.0 for d~ >= 1e-2, 0.7-0.9 below), and fast across it, so the
   shipped Psi is the Richardson extrapolation 2 Psi_2N - Psi_N. Every ``check_every``-th
   depth is also solved with 4 n_length (and 2 n_width) to measure how good that
   extrapolation is; the table's accuracy line is the largest such difference.
2. Psi' = dPsi/dd~ as the derivative of the cubic spline of ln Psi against ln d~,
   evaluated by the runtime itself (linecontact.universal.UniversalCurve), because the flat-punch stiffness of a staircase
   contact set scatters by up to 0.5 %; the punch value on the finer grid is kept as
   an independent check (column k_punch) and its largest deviation is reported.
3. The effective beta of the Li-Popov form with alpha = pi/2 (Eq. 7 with the 2D log
   law's alpha), beta_eff = Psi/pi * exp(pi d~/Psi - 1)
   (linecontact.lipopov.effective_beta), to show how the small-depth asymptote is
   approached (docs/theory.md, section 'Self-similarity'). The runtime continues the curve below the
   table with alpha = pi/2 and beta = beta_eff at the smallest tabulated depth; the
   error of that continuation in F is |delta beta/beta| / (pi d~/Psi - 1), recorded.

Budget: the default run (about 110 depths, 2 workers) is meant to finish within
10 minutes on a 2-core machine; ``--workers`` (or ``--scheduler`` for a cluster) and the
grid options trade time for accuracy. The depths are tasks of tools.studies.runner: each
finished depth is checkpointed (default OUT/partial_universal/) and ``--resume`` picks
them up after an interruption.
"""
from __future__ import annotations

import shutil
import time
from pathlib import Path

import numpy as np

from linecontact.lipopov import effective_beta, fit_dimensionless_profile
from linecontact.tables import Table
from linecontact.universal import UniversalCurve

from ..bem.cylinder import solve_depth
from .runner import add_runner_arguments, run_study, table_meta, wall_time_line

REPO = Path(__file__).resolve().parents[2]


def add_arguments(parser):
    parser.add_argument("--d-min", type=float, default=1e-16,
                        help="smallest d~ = d R/L^2 (default 1e-16)")
    parser.add_argument("--d-max", type=float, default=30.0,
                        help="largest d~ (default 30)")
    parser.add_argument("--per-decade", type=int, default=6,
                        help="depths per decade of d~ (default 6)")
    parser.add_argument("--n-length", type=int, default=256,
                        help="cells along the half-length on the coarser of the two "
                             "grids (default 256)")
    parser.add_argument("--n-width", type=int, default=32,
                        help="cells across the contact half-width (default 32)")
    parser.add_argument("--tol", type=float, default=1e-7,
                        help="solver tolerance: gap error / d (default 1e-7)")
    parser.add_argument("--check-every", type=int, default=6,
                        help="every k-th depth is also solved on finer grids to "
                             "measure the error (default 6; 0: never)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for universal_curve.csv (default tables/)")
    add_runner_arguments(parser)


def _solve_one(task):
    """One depth (a task of tools.studies.runner): Psi on the grids N and 2N, and on the check
    grids where asked."""
    d, nl, nw, tol, check = (task[k] for k in ("d_tilde", "n_length", "n_width", "tol",
                                                 "check"))
    t0 = time.perf_counter()
    r1 = solve_depth(d, nl, nw, tol=tol, workers=1)
    r2 = solve_depth(d, 2 * nl, nw, tol=tol, workers=1)
    out = dict(d_tilde=d, psi_n=r1.force, psi_2n=r2.force, k_punch=r2.stiffness,
               b_centre=r2.half_width_centre, b_max=r2.half_width_max,
               area=r2.area, iterations=r1.iterations + r2.iterations,
               aspect=r2.grid.dx / r2.grid.dy)
    if check:
        r4 = solve_depth(d, 4 * nl, nw, tol=tol, workers=1)
        r2w = solve_depth(d, 2 * nl, 2 * nw, tol=tol, workers=1)
        out.update(psi_4n=r4.force, psi_2n_2w=r2w.force)
    else:
        out.update(psi_4n=np.nan, psi_2n_2w=np.nan)
    out["seconds"] = time.perf_counter() - t0
    return out


def depth_tasks(d_min=1e-16, d_max=30.0, per_decade=6, n_length=256, n_width=32,
                tol=1e-7, check_every=6):
    """The tasks of the study: one per depth, log-spaced, every `check_every`-th (and
    the last) also solved on the check grids."""
    n = int(round(np.log10(d_max / d_min) * per_decade)) + 1
    depths = np.geomspace(d_min, d_max, n)
    return [dict(key=f"{i:04d}_d_tilde={d:.6e}", d_tilde=float(d), n_length=int(n_length),
                 n_width=int(n_width), tol=float(tol),
                 check=bool(check_every) and (i % check_every == 0 or i == n - 1))
            for i, d in enumerate(depths)]


def compute(d_min=1e-16, d_max=30.0, per_decade=6, n_length=256, n_width=32, tol=1e-7,
            check_every=6, **runner):
    """Run the study through tools.studies.runner.run_study (keyword options `runner`:
    scheduler, workers, checkpoint, resume, progress); returns (columns, summary)."""
    tasks = depth_tasks(d_min, d_max, per_decade, n_length, n_width, tol, check_every)
    depths = np.array([t["d_tilde"] for t in tasks])
    n = len(tasks)
    t0 = time.perf_counter()
    rows = run_study(_solve_one, tasks, desc="universal curve (depths)", **runner)
    wall = time.perf_counter() - t0
    col = {k: np.array([r[k] for r in rows]) for k in rows[0] if k != "resumed"}
    psi = 2 * col["psi_2n"] - col["psi_n"]          # Richardson, order 1
    beta = effective_beta(depths, psi)               # alpha = pi/2
    # Psi' from the runtime's own spline of ln Psi against ln d~ (on the table's knots)
    curve = UniversalCurve(Table(meta={"beta_small": repr(float(beta[0]))},
                                 columns={"d_tilde": depths, "Psi": psi}))
    dpsi = np.asarray(curve.dpsi(depths))
    checked = np.isfinite(col["psi_4n"])
    psi_fine = 2 * col["psi_4n"] - col["psi_2n"]
    richardson_err = np.abs(psi[checked] / psi_fine[checked] - 1)
    width_err = np.abs(col["psi_2n_2w"][checked] / col["psi_2n"][checked] - 1)
    punch_dev = np.abs(col["k_punch"] / dpsi - 1)
    columns = {
        "d_tilde": depths,
        "Psi": psi,
        "dPsi": dpsi,
        "x_tilde": dpsi / 2,
        "beta_eff": beta,
        "b_centre": col["b_centre"],
        "b_max": col["b_max"],
        "area": col["area"],
        "Psi_N": col["psi_n"],
        "Psi_2N": col["psi_2n"],
        "k_punch": col["k_punch"],
        "seconds": col["seconds"],
    }
    # the small-depth limit: a free fit of Eq. 9 over the lowest three decades (alpha
    # should be pi/2), and beta_eff extrapolated in 1/x, x = pi d~/Psi ~ ln(1/d~)
    low = depths <= depths[0] * 1e3
    alpha_fit, beta_fit = fit_dimensionless_profile(dpsi[low] / 2, depths[low])
    x = np.pi * depths / psi
    tail = depths <= 1e-8
    beta_limit = [float(np.linalg.lstsq(
        np.vstack([x[tail] ** -k for k in range(order + 1)]).T, beta[tail],
        rcond=None)[0][0]) for order in (1, 2)] if tail.sum() > 3 else [np.nan, np.nan]
    # continuation below the table: error of using beta_eff(d_min) where the true
    # beta_eff keeps drifting; the drift over the last decade bounds it per decade
    last = depths <= depths[0] * 10 ** 1.0001
    drift_per_decade = abs(beta[last][-1] / beta[0] - 1)
    # at fixed d~: d~ = Psi/pi (1 + ln(pi beta/Psi))  =>  dPsi/Psi = -(dbeta/beta)/(x - 1)
    sens = 1.0 / (np.pi * depths[0] / psi[0] - 1.0)
    summary = dict(
        wall_time=wall, n=n, richardson_err=float(richardson_err.max(initial=0)),
        width_err=float(width_err.max(initial=0)),
        punch_dev=float(np.max(punch_dev)), punch_dev_median=float(np.median(punch_dev)),
        beta_small=float(beta[0]), drift_per_decade=float(drift_per_decade),
        continuation_err_per_decade=float(drift_per_decade * sens),
        alpha_fit=float(alpha_fit), beta_fit=float(beta_fit), beta_limit=beta_limit,
        checked=int(checked.sum()),
        wall_time_line=wall_time_line(wall, rows, "depths", runner.get("scheduler"),
                                      runner.get("workers")),
        monotone=bool(np.all(np.diff(psi) > 0)
                                                   and np.all(np.diff(dpsi) > 0)),
    )
    return columns, summary


def run(args):
    from linecontact.tables import write_table

    checkpoint = args.checkpoint or args.out / "partial_universal"
    columns, s = compute(args.d_min, args.d_max, args.per_decade, args.n_length,
                         args.n_width, args.tol, args.check_every,
                         scheduler=args.scheduler, workers=args.workers,
                         checkpoint=checkpoint, resume=args.resume,
                         progress=not args.no_progress,
                         connect_timeout=args.connect_timeout)
    meta = table_meta(args.command_line, **{
        "title": "Universal force-depth curve of a rigid parabolic cylinder of finite "
                 "length on an elastic half-space: F R/(E* L^3) = Psi(d R/L^2)",
        "source": "computed by the linecontact boundary-element solver (tools/), "
                  "Polonsky-Keer CG on Love's rectangle coefficients, free-space "
                  "DC-FFT in its mirror-symmetric DCT form",
        "units": "d_tilde = d R/L^2 [-], Psi = F R/(E* L^3) [-], dPsi = k/(E* L) [-], "
                 "x_tilde = a/L = k/(2 E* L) [-] (MDR contact radius; the MDR profile is "
                 "g~ = d_tilde at x~ = x_tilde), beta_eff [-] (Eq. 7 with alpha = pi/2), "
                 "b_centre, b_max = contact half-width at x = 0 and largest, / L [-], "
                 "area = contact area / L^2 [-], Psi_N, Psi_2N = raw BEM forces on the two "
                 "grids [-], k_punch = flat-punch stiffness on the finer grid / (E* L) [-], "
                 "seconds = wall time of that depth [s]",
        "grid": f"per depth: {args.n_length} and {2 * args.n_length} cells along the "
                f"half-length L/2, {args.n_width} across the largest contact half-width "
                f"(strip |y| <= 1.2 b), quarter grids by symmetry; checks every "
                f"{args.check_every}th depth with {4 * args.n_length} along and "
                f"{2 * args.n_width} across",
        "tolerance": f"{args.tol:g} (largest gap error in contact and penetration "
                     "outside it, relative to d)",
        "method": "Psi = 2 Psi_2N - Psi_N (Richardson, first order in the axial cell "
                  "length, measured); dPsi from the cubic spline of ln Psi against "
                  "ln d_tilde (not-a-knot), evaluated by the runtime "
                  "(linecontact.universal.UniversalCurve)",
        "accuracy": f"Psi: largest difference from the extrapolation one grid finer "
                    f"{s['richardson_err']:.1e}, largest effect of doubling the cells "
                    f"across the width {s['width_err']:.1e} ({s['checked']} depths "
                    f"checked); dPsi: flat-punch stiffness deviates by "
                    f"{s['punch_dev_median']:.1e} (median), {s['punch_dev']:.1e} (largest; "
                    "staircase contact sets); parabolic gap y^2/(2R): exact only for d << R",
        "small_depth_asymptote": f"below d_tilde = {args.d_min:g}: Eq. 7 with alpha = "
                                 f"pi/2, beta = {s['beta_small']:.6f} (beta_eff at the "
                                 f"smallest depth); beta_eff drifted by "
                                 f"{s['drift_per_decade']:.2e} over the last decade, i.e. "
                                 f"{s['continuation_err_per_decade']:.1e} in F per decade "
                                 "of continuation",
        "alpha_small": "pi/2",
        "small_depth_fit": f"Eq. 9 fitted freely to the lowest three decades: alpha = "
                           f"{s['alpha_fit']:.5f} (pi/2 = {np.pi / 2:.5f}), beta = "
                           f"{s['beta_fit']:.4f}",
        "beta_limit_estimate": f"beta_eff extrapolated to d_tilde -> 0 in powers of "
                               f"1/x, x = pi d_tilde/Psi, over d_tilde <= 1e-8: "
                               f"{s['beta_limit'][0]:.4f} (order 1), "
                               f"{s['beta_limit'][1]:.4f} (order 2); an estimate, not "
                               "used by the runtime",
        "beta_small": f"{s['beta_small']:.8f}",
        "d_tilde_range": f"[{columns['d_tilde'][0]:.6g}, {columns['d_tilde'][-1]:.6g}]",
        "wall_time": s["wall_time_line"],
    })
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "universal_curve.csv"
    write_table(path, meta, columns)
    if args.checkpoint is None:
        shutil.rmtree(checkpoint, ignore_errors=True)   # all kept in the table
    print(f"wrote {path}: {s['n']} depths in {s['wall_time']:.0f} s")
    for k, v in s.items():
        print(f"  {k}: {v}")
    return 0
