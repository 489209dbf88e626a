"""Pull-off of long rollers, s = b_c/L below the BEM table: tables/adhesion_long_roller.csv.

The adhesive BEM table (tables/adhesion_cylinder.csv, tools.studies.adhesion_study)
stops at s = b_c/L = 0.025; most rollers lie below (a PDMS roller R 5 mm, L 20 mm:
s = 0.003). There the roller pulls off below the 2D JKR value times L because its ends
peel first. This study gives the pull-off down to s = 1e-3 by an end model whose two
constants are fitted on the BEM at s = 0.025 .. 0.05 and on BEM runs below the table.

The end model (a slender-body energy balance). Far from its ends the contact of a long
roller is a 2D JKR section of half-width b with line force (Barquins 1988)

    f(b) = pi E* b^2/(4R) - sqrt(2 pi E* w b),    b = beta b_c,
    rho_2D(beta) = f/f_c = (4/3) (sqrt(beta) - beta^2/4),

rho_2D the section's tension over the 2D pull-off tension f_c = (3 pi/4) E* b_c^2/R
(rho_2D = 1 at beta = 1, 0 at the zero-load width beta = 16^(1/3)). The 3D surface displacement of a long strip loaded by a line force f is
logarithmic in its length, u = f (2 ln(L/b) + O(1))/(pi E*) (Boussinesq's 1/r kernel,
Johnson 1985, chapter 3, integrated along a slender strip), so the elastic energy it stores per unit length is
f^2 (ln(L/b) + O(1))/(pi E*). When an end of the contact peels back by da at fixed
depth this energy is released over the contact area 2 b da: the end's energy release
rate G_e = f^2 (k ln(L/b) + c)/(2 pi E* b), k = 1 and c the O(1) terms (the Hertz
part of the section, the end's shape) in this simplest form (both fitted below). With
the section law this reads

    G_e / w = (beta^2/4 - sqrt(beta))^2 / beta * (k ln(1/(s beta)) + c),

and an end that starts to peel under force control does not stop (the shorter contact
carries the same force: its line force, and G_e, grow), so the pull-off is the first
state of the stable branch (beta falling from 16^(1/3) at zero load) with G_e = w, or
the 2D pull-off (beta = 1) where G_e < w there. At the end-peeling pull-off

    rho(s) = (4/3) sqrt(beta / (k ln(1/(s beta)) + c)),

so rho -> 0 as s -> 0, like (4/3) 16^(1/6) / sqrt(k ln(1/s)): slowly (1/rho grows with
the square root of ln(L/b_c)), and it never tends to the 2D value: the 2D law holds
per unit length in the middle, but a longer roller stores more energy per unit length
(ln(L/b)) to drive its ends.

Fit and checks. A log coefficient of exactly 1 with one constant c met the BEM below
the table at s = 0.0125, 0.00625 (-0.3 %, +0.75 %) but not at s = 0.003125 (+2.2 %):
the end zone's tension exceeds the middle's by a factor that itself depends on
ln(L/b). So G_e = f^2 (k ln(L/b) + c)/(2 pi E* b) with two constants: k (the far
field's log coefficient, not the criterion's) fitted, in the relative residual, on the
longest BEM series, the coarse grid's (n = 8 cells across b_c: the BEM table's columns
ratio_force_n8 at s = 0.025, 0.035, 0.05, and the --check runs on that grid), c per
grid with that k (n = 16 likewise). The grid converges at first order (the
criterion's error falls as 1/n, tools.bem.adhesion): c = 2 c_16 - c_8, its error
|c_16 - c_8|. Prediction test: the model refitted without the smallest s of the n = 8
series, against that value.

Error of the table's ratio: |rho(s; c +- dc) - rho(s; c)| (the larger) plus the model
error times rho (the largest of the fit residuals and the prediction test, plus the
prediction test's error per halving of s below the smallest fitted s: there the model
is a prediction), plus the BEM table's error at its smallest rows (its extrapolated
values against the finest grid's) times rho. Depth control: at these s the end-
peeling instability ends the retraction under depth control too (the BEM's force at
the jump-off equals the force minimum within the difference recorded per check run);
the depth-controlled ratio is the force-controlled one with that largest measured
difference added to its error.

Budget: ``nice -n 10 python -m tools.build_tables adhesion-long --workers 1``; the
table's ``wall_time`` and ``cpu_time`` record the run's own figures (the check
retractions on one core at load 8-17: n = 8, s = 0.0125 about 1 min, s = 0.00625 4 min,
s = 0.003125 about 35 min; n = 16, s = 0.0125 15 min).
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]

#: Calibration rows of tables/adhesion_cylinder.csv (its smallest s).
CALIBRATION_S = (0.025, 0.035, 0.05)
#: Grids of the calibration (the table's columns ratio_force_nN).
GRIDS = (8, 16)
#: BEM runs below the table, fitted and checked: (s, n).
CHECK_RUNS = ((0.0125, 8), (0.00625, 8), (0.0125, 16), (0.003125, 8))
#: Rows of the written table: s from S_MIN to the BEM table's start, log-spaced.
S_MIN, S_ROWS = 1e-3, 25
#: Zero-load width of the 2D JKR section over b_c: 16^(1/3).
BETA_ZERO = 16 ** (1 / 3)


def rho_2d(beta):
    """The 2D JKR section's tension over its pull-off value at half-width beta b_c."""
    beta = np.asarray(beta, dtype=float)
    return 4 / 3 * (np.sqrt(beta) - beta ** 2 / 4)


def end_release(beta, s, c, k=1.0):
    """G_e/w, the end's energy release rate over w (module doc): (beta^2/4 -
    sqrt(beta))^2/beta (k ln(1/(s beta)) + c)."""
    return (beta ** 2 / 4 - np.sqrt(beta)) ** 2 / beta * (k * np.log(1 / (s * beta)) + c)


def pull_off_beta(s, c, k=1.0):
    """The middle section's half-width over b_c at pull-off: the largest beta in
    [1, 16^(1/3)] with G_e = w, or 1 (the 2D pull-off) where G_e < w at beta = 1."""
    from scipy.optimize import brentq

    if end_release(1.0, s, c, k) <= 1.0:
        return 1.0
    return float(brentq(lambda b: end_release(b, s, c, k) - 1.0, 1.0,
                        BETA_ZERO * (1 - 1e-12), xtol=1e-14, rtol=1e-14))


def ratio(s, c, k=1.0):
    """The end model's pull-off over the 2D JKR value times L (force control)."""
    return float(rho_2d(pull_off_beta(s, c, k)))


def fit(data, k=None):
    """Least squares in the relative residual: (k, c) for data {s: rho}, or c alone with
    k given. Returns (k, c, residuals model/BEM - 1 in the order of data)."""
    from scipy.optimize import least_squares

    ss = list(data)
    if k is None:
        res = least_squares(lambda p: [ratio(s, p[1], p[0]) / data[s] - 1 for s in ss],
                            [1.0, -0.4], xtol=1e-14, ftol=1e-14, gtol=1e-14)
        k_, c_ = map(float, res.x)
    else:
        res = least_squares(lambda p: [ratio(s, p[0], k) / data[s] - 1 for s in ss],
                            [-0.4], xtol=1e-14, ftol=1e-14, gtol=1e-14)
        k_, c_ = float(k), float(res.x[0])
    return k_, c_, [ratio(s, c_, k_) / data[s] - 1 for s in ss]


def add_arguments(parser):
    parser.add_argument("--check", type=str, nargs="+",
                        default=[f"{s:g}:{n}" for s, n in CHECK_RUNS],
                        help="BEM check runs below the table, S:N (default "
                             f"{' '.join(f'{s:g}:{n}' for s, n in CHECK_RUNS)})")
    parser.add_argument("--steps", type=int, default=40,
                        help="depth steps of each retraction (default 40, the BEM "
                             "table's)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for adhesion_long_roller.csv (default tables/)")
    parser.add_argument("--bem-table", type=Path, default=REPO / "tables",
                        help="folder of adhesion_cylinder.csv, the calibration's data "
                             "(default tables/)")
    from .runner import add_runner_arguments
    add_runner_arguments(parser)


def run(args):
    from linecontact.tables import read_table, write_table
    from .adhesion_study import solve_task
    from .runner import run_study_from_args, table_meta, wall_time_line

    t0 = time.perf_counter()
    bem = read_table("adhesion_cylinder", directory=args.bem_table)
    cols = bem.columns
    # the BEM table's own error at its calibration rows (extrapolated vs finest grid)
    tab_err = max(abs(float(cols["ratio_force"][i]) / float(cols[f"ratio_force_n{GRIDS[1]}"][i])
                      - 1) for i in range(len(cols["s"])) if cols["s"][i] <= max(CALIBRATION_S))

    runs = [tuple(float(v) if k == 0 else int(v) for k, v in enumerate(x.split(":")))
            for x in args.check]
    for s, n in runs:
        if n not in GRIDS or not 0 < s < float(cols["s"][0]):
            raise SystemExit(f"--check {s:g}:{n}: N must be one of the BEM table's grids "
                             f"{', '.join(map(str, GRIDS))} and 0 < S < {cols['s'][0]:g}")
    tasks = [{"key": f"s{s:g}_n{n}", "s": s, "n": n, "steps": args.steps}
             for s, n in sorted(runs, key=lambda r: r[1] * r[1] / r[0])]
    own_checkpoint = getattr(args, "checkpoint", None) is None
    if own_checkpoint:
        args.checkpoint = REPO / "out" / "partial_adhesion_long"
    results = run_study_from_args(solve_task, tasks, args, desc="adhesion-long study")

    from .adhesion_study import f2d

    # per grid: the BEM table's rows s <= 0.05 and the runs below it
    data = {n: {} for n in GRIDS}
    for n in GRIDS:
        for s in CALIBRATION_S:
            i = int(np.flatnonzero(np.isclose(cols["s"], s))[0])
            data[n][float(s)] = float(cols[f"ratio_force_n{n}"][i])
    depth_err = 0.0
    for r in results:
        rf, rd = r["force"] / f2d(r["s"]), r["force_depth"] / f2d(r["s"])
        data[r["n"]][r["s"]] = rf
        depth_err = max(depth_err, abs(rd / rf - 1))
    # k from the longest series (the coarse grid's: the far field's log coefficient, not
    # the criterion's), c per grid with that k, then c extrapolated in the grid
    n1, n2 = GRIDS
    k, c1, res1 = fit(data[n1])
    _, c2, res2 = fit(data[n2], k)
    c_inf, dc = 2 * c2 - c1, abs(c2 - c1)
    # the prediction test: refit without the smallest s of the long series, predict it
    s_last = min(data[n1])
    k_l, c_l, _ = fit({s: v for s, v in data[n1].items() if s != s_last})
    loo = ratio(s_last, c_l, k_l) / data[n1][s_last] - 1
    fit_err = max(abs(v) for v in res1 + res2)
    # below the data the model is a prediction: its error grows by |loo| per halving
    # of s below the smallest fitted s (the prediction test's distance: one halving)
    s_data = min(min(d) for d in data.values())

    def model_err(s):
        return max(fit_err, abs(loo)) + abs(loo) * max(0.0, np.log2(s_data / s))
    c_grid = {n1: c1, n2: c2}
    check_lines = []
    for r in sorted(results, key=lambda r: (r["n"], -r["s"])):
        rf, rd = r["force"] / f2d(r["s"]), r["force_depth"] / f2d(r["s"])
        m = ratio(r["s"], c_grid[r["n"]], k)
        check_lines.append(f"s = {r['s']:g}, n = {r['n']}: BEM {rf:.4f} (depth control "
                           f"{rd:.4f}), model with c_{r['n']} {m:.4f} ({100 * (m / rf - 1):+.2f} "
                           f"%); the middle's half-width at pull-off BEM "
                           f"{r['width_min'] / r['s']:.2f} b_c, model "
                           f"{pull_off_beta(r['s'], c_grid[r['n']], k):.2f} b_c")
    cal_lines = [f"n = {n}: {len(data[n])} BEM values at s = "
                 f"{', '.join(f'{s:g}' for s in sorted(data[n]))}, residuals "
                 f"{', '.join(f'{100 * v:+.2f} %' for _, v in sorted(zip(data[n], res)))}"
                 for n, res in ((n1, res1), (n2, res2))]

    s_rows = np.geomspace(S_MIN, float(cols["s"][0]), S_ROWS)
    out = {k: [] for k in ("s", "ratio_force", "error_force", "ratio_depth", "error_depth",
                           "beta", "ratio_force_n8", "ratio_force_n16")}
    for s in s_rows:
        r0 = ratio(s, c_inf, k)
        e_c = max(abs(ratio(s, c_inf + dc, k) - r0), abs(ratio(s, c_inf - dc, k) - r0))
        err = e_c + (model_err(s) + tab_err) * r0
        out["s"].append(s)
        out["ratio_force"].append(r0)
        out["error_force"].append(err)
        out["ratio_depth"].append(r0)
        out["error_depth"].append(err + depth_err * r0)
        out["beta"].append(pull_off_beta(s, c_inf, k))
        out["ratio_force_n8"].append(ratio(s, c1, k))
        out["ratio_force_n16"].append(ratio(s, c2, k))
    out = {k: np.array(v, dtype=float) for k, v in out.items()}
    wall = time.perf_counter() - t0
    meta = table_meta(
        args.command_line,
        title="Pull-off force of a long rigid parabolic cylinder on an elastic half-space "
              "with JKR adhesion, over the 2D JKR value times L, against s = b_c/L below "
              "the adhesive BEM table: end model calibrated on the BEM",
        source="end model (tools/studies/adhesion_long_study.py): the middle a 2D JKR "
               "section (Barquins 1988), the ends peel when G_e = f^2 (k ln(L/b) + c)/(2 "
               "pi E* b) reaches w (the energy a long line-loaded strip stores per unit "
               "length); k and c fitted to the adhesive BEM (tools/bem/adhesion.py; "
               "tables/adhesion_cylinder.csv at s = "
               f"{', '.join(f'{v:g}' for v in CALIBRATION_S)} and BEM retractions below "
               "that table)",
        units="s = b_c/L = (2 w R^2/(pi E* L^3))^(1/3) [-], ratio_force = pull-off under "
              "force control over the 2D JKR value -3 (pi E* R w^2/16)^(1/3) L [-], "
              "error_force = its stated error (absolute, in the ratio) [-], ratio_depth, "
              "error_depth = the same under depth control [-], beta = the middle's "
              "half-width at pull-off over b_c [-], ratio_force_nN = the model with the "
              "constant of BEM grid n = N (the grid convergence) [-]",
        model="pull-off at the first state of the stable branch with G_e/w = (beta^2/4 - "
              "sqrt(beta))^2/beta (k ln(1/(s beta)) + c) = 1; ratio = (4/3)(sqrt(beta) - "
              f"beta^2/4); k = {k!r}, c = {c_inf!r} +- {dc!r}",
        calibration=f"k = {k!r} and c_{n1} = {c1!r} fitted on grid n = {n1}, c_{n2} = "
                    f"{c2!r} on n = {n2} with that k; " + "; ".join(cal_lines)
                    + f"; first-order extrapolation c = 2 c_{n2} - c_{n1}, error "
                      f"|c_{n2} - c_{n1}|; prediction test: fitted without s = "
                      f"{s_last:g} (n = {n1}) the model gives it within {100 * loo:+.2f} %",
        check="; ".join(check_lines),
        accuracy=f"error = |ratio(c +- dc) - ratio(c)| + (model error + BEM table error "
                 f"{tab_err:.2e}) x ratio; model error = {max(fit_err, abs(loo)):.2e} (the "
                 "largest |model/BEM - 1| of the fits on either grid and of the prediction "
                 f"test) + {abs(loo):.2e} per halving of s below s = {s_data:g} (the "
                 "prediction test's error per halving); depth control adds "
                 f"{depth_err:.2e} x ratio (the largest measured |depth/force control - 1| "
                 "of the check runs)",
        asymptote="ratio -> (4/3) 16^(1/6)/sqrt(k ln(1/s)) -> 0 as s -> 0 (the end's "
                  "energy release grows as ln(L/b_c)); never the 2D value",
        s_range=f"[{s_rows[0]:g}, {s_rows[-1]:g}]",
        wall_time=wall_time_line(wall, results, "BEM check retractions", args.scheduler,
                                 args.workers),
        cpu_time=f"{sum(r.get('cpu', 0.0) for r in results):.0f} s in the check "
                 "retractions (" + ", ".join(f"s = {r['s']:g}, n = {r['n']}: "
                                             f"{r.get('cpu', 0.0):.0f} s"
                                             for r in results) + ")",
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "adhesion_long_roller.csv"
    write_table(path, meta, out)
    if own_checkpoint:
        import shutil
        shutil.rmtree(args.checkpoint, ignore_errors=True)
    print(f"wrote {path}: {out['s'].size} rows in {wall:.0f} s")
    for key in ("model", "calibration", "check", "accuracy"):
        print(f"  {key}: {meta[key]}")
    return 0
