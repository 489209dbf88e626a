"""Tangential stiffness and partial slip of the finite cylinder: tables/tangential_cylinder.csv.

The MDR gives every contact the tangential stiffness k_t = (G*/E*) k_n with
G*/E* = 2(1-nu)/(2-nu) for a rigid indenter (Popov & Hess 2015, ch. 4), exact for
axisymmetric contacts. The finite cylinder's contact is elongated, so its true k_t
depends on the direction of the shift. This study measures it with the uncoupled
(Goodman 1962) tangential BEM of tools.bem.tangential.

Self-similarity: with the parabolic gap y^2/(2R), the normal problem depends on
d~ = d R/L^2 alone (docs/theory.md, section 'Self-similarity'), and so does its
contact set; the tangential problems on that set scale the same way (lengths with L,
displacements with L^2/R) and depend on nu in addition. So k_t/k_n = f(d~, nu) for
every L/R, one row per (nu, d~) in the table. tests/test_tangential_bem.py checks it in
physical units (L/R = 1 and 10, same d~); the run below repeats that check and records
it in the header.

Per depth d~ (one task of tools.studies.runner.run_study, L = R = E* = 1):

1. Normal contact on the adapted grid of tools.bem.cylinder.solve_depth, at two
   resolutions: N = (n_length, n_width) and 2N (twice the cells along the half-length
   and across the contact half-width). On each contact set the flat-punch problems with
   Love's kernel (k_n) and Cerruti's (k_t, across = shift along y, the rolling
   direction; along = shift along x, the axis) for every nu. The table's
   kt_kn_across/along are the 2N values; the N values and the change are kept.
2. Partial slip with Coulomb friction on a coarser grid (``--slip-n-length``,
   ``--slip-n-width``: BEM and laws are compared on the same grid), across and along, for
   every nu: the BEM curve F_t(u) (monotonic, from the virgin state, ``--slip-points``
   steps up to past gross slip) against two laws that need only F(d') (from normal
   solutions on the same grid, d' = d (j/J)):
     MDR:     F_t = mu [F(d) - F(d - G* u/(mu E*))]      (G*/E* = 2(1-nu)/(2-nu))
     scaled:  F_t = mu [F(d) - F(d - kappa u/mu)]         (kappa = k_t/k_n of the BEM)
   The largest difference over the whole curve (relative to mu F), the BEM's
   gross-slip shift relative to the scaled law's mu d/kappa, and the energy dissipated
   per fretting cycle (Masing rule, W = 8 int_0^u0 f - 4 u0 f(u0); the BEM obeys it
   exactly, tests/test_tangential_bem.py) at u0 = half the law's gross-slip shift. The
   curves scale exactly with mu (q(mu, u) = mu q(1, u/mu)), so mu = 1.

At nu = 0 the tangential problem is the normal one: the rows with nu = 0 have
k_t/k_n = 1 and partial-slip errors at the solver tolerance, a check built into the
table.

Budget: the default run (23 depths from 1e-10 to 15, 5 values of nu, 2 worker
processes) took 773 s (12.9 min) on the 2-core reference machine while other jobs ran
(load average 12-15), ``nice -n 10 python -m tools.build_tables tangential --workers 2``;
the table's ``wall_time`` line records each run's own figure.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from linecontact.tangential import mdr_stiffness_ratio

from ..bem.tangential import (cylinder_full_stick, load_path,
                             normal_force_on_grid, shear_modulus_for, tangential_operator)

REPO = Path(__file__).resolve().parents[2]
NUS = (0.0, 0.25, 0.3, 0.4, 0.5)


def add_arguments(parser):
    parser.add_argument("--d-min", type=float, default=1e-10,
                        help="smallest d~ = d R/L^2 (default 1e-10)")
    parser.add_argument("--d-max", type=float, default=15.0,
                        help="largest d~ (default 15 = 0.15 (R/L)^2 at L/R = 0.1)")
    parser.add_argument("--per-decade", type=float, default=2.0,
                        help="depths per decade of d~ (default 2)")
    parser.add_argument("--nu", type=float, nargs="+", default=list(NUS),
                        help=f"Poisson's ratios (default {' '.join(map(str, NUS))})")
    parser.add_argument("--n-length", type=int, default=256,
                        help="cells along the half-length on the coarser grid N "
                             "(default 256; 2N is also solved)")
    parser.add_argument("--n-width", type=int, default=32,
                        help="cells across the contact half-width on N (default 32)")
    parser.add_argument("--slip-n-length", type=int, default=128,
                        help="cells along the half-length for the partial-slip curves "
                             "(default 128; their errors are differences between BEM "
                             "and law on the same grid)")
    parser.add_argument("--slip-n-width", type=int, default=16,
                        help="cells across the contact half-width for partial slip "
                             "(default 16)")
    parser.add_argument("--slip-points", type=int, default=24,
                        help="shift steps of each partial-slip curve (default 24)")
    parser.add_argument("--slip-depths", type=int, default=32,
                        help="normal solutions d' = d j/J for the laws (default %(default)s)")
    parser.add_argument("--tol", type=float, default=1e-8,
                        help="solver tolerance (gap / displacement error relative to "
                             "d or the shift; default 1e-8)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for tangential_cylinder.csv (default tables/)")
    from .runner import add_runner_arguments
    add_runner_arguments(parser)


def _law(u, kappa, d, F, f_of):
    """mu = 1 law F_t/F = [F(d) - F(d - kappa u)]/F, F(d') = 0 for d' <= 0; kappa may
    be an array (one per u)."""
    dprime = d - kappa * np.asarray(u)
    return (F - np.where(dprime > 0, f_of(np.maximum(dprime, 0.0)), 0.0)) / F



def _masing_w(u, f, u0):
    """W(u0) = 8 int_0^u0 f - 4 u0 f(u0) for a curve given at points u (u[0] = 0),
    interpolated monotonically (PCHIP) and integrated on 4001 points."""
    from scipy.interpolate import PchipInterpolator
    fi = PchipInterpolator(u, f)
    s = np.linspace(0.0, u0, 4001)
    return 8 * np.trapezoid(fi(s), s) - 4 * u0 * float(fi(u0))


def partial_slip_measures(normal, nu, direction, kappa, points=24, depths=24, tol=1e-8,
                          f_of=None):
    """Partial-slip curve of the BEM against the MDR and the scaled law (mu = 1).

    Returns a dict: err_mdr, err_scaled (largest |F_t,BEM - F_t,law|/F over the curve),
    ugs (BEM gross-slip shift over the scaled law's d/kappa), w_mdr, w_scaled (W_BEM /
    W_law at u0 = half the law's gross-slip shift), the curve itself (u, f) and the
    operator applications used.
    """
    grid, p, d = normal.grid, normal.pressure, normal.d_tilde
    F = 4 * p.sum() * grid.cell_area
    gstar = mdr_stiffness_ratio(nu)
    op = tangential_operator(grid.mx, grid.my, grid.dx, grid.dy,
                             shear_modulus_for(1.0, nu), nu, direction, True, "scipy", 1)
    u_gs_bem = float(op(p)[p > 0].max())          # all cells slip: u = K (mu p), mu = 1
    U = 1.02 * max(u_gs_bem, d / kappa, d / gstar)
    shifts = U * np.arange(1, points + 1) / points
    states = load_path(op, p, 1.0, shifts, tol=tol, scale=U)
    f = np.array([4 * s.traction.sum() * grid.cell_area for s in states]) / F
    u = np.concatenate([[0.0], shifts])
    f = np.concatenate([[0.0], f])
    err_mdr = float(np.abs(f - _law(u, gstar, d, F, f_of)).max())
    err_scaled = float(np.abs(f - _law(u, kappa, d, F, f_of)).max())
    w = {}
    for name, k in (("mdr", gstar), ("scaled", kappa)):
        # both curves sampled at the same shifts and integrated the same way, so that
        # the quadrature error cancels in the ratio (at nu = 0 the ratio is 1)
        u0 = 0.5 * d / k
        w[name] = _masing_w(u, f, u0) / _masing_w(u, _law(u, k, d, F, f_of), u0)
    ratios, err_corr = shift_ratios(u, f, u_gs_bem, kappa, d, F, f_of)
    return dict(err_mdr=err_mdr, err_scaled=err_scaled,
                ugs=u_gs_bem * kappa / d, w_mdr=float(w["mdr"]),
                w_scaled=float(w["scaled"]), shift_ratio=ratios, err_corrected=err_corr,
                u=u, f=f, iterations=sum(s.iterations for s in states))


#: Load fractions F_t/(mu F) of the partial-slip correction columns.
Q_LEVELS = (0.1, 0.25, 0.5, 0.75, 0.9, 0.95, 0.99, 1.0)


def shift_ratios(u, f, u_gs_bem, kappa, d, F, f_of, levels=Q_LEVELS):
    """The BEM's shift over the scaled law's at equal load fraction Q = F_t/(mu F).

    u_BEM(Q) by inverting the monotone (PCHIP) interpolant of the sampled BEM curve,
    which ends at (u_gs,BEM, 1); u_law(Q) = [d - d'(Q)]/kappa with F(d') = (1 - Q) F.
    Also the largest force error of the corrected law (shift u_law(Q) r(Q), r linear
    in Q between the levels and 1 at Q = 0, as linecontact.tangential applies it)
    against the BEM curve, relative to mu F [-]. mu = 1.
    """
    from scipy.interpolate import PchipInterpolator
    from scipy.optimize import brentq
    below = u < u_gs_bem
    uu = np.concatenate([u[below], [u_gs_bem]])
    ff = np.concatenate([np.maximum.accumulate(f[below]), [1.0]])
    keep = np.concatenate([[True], np.diff(ff) > 0])
    fi = PchipInterpolator(uu[keep], ff[keep])

    def u_bem(q):
        return u_gs_bem if q >= 1 else brentq(lambda x: fi(x) - q, 0.0, u_gs_bem,
                                              xtol=1e-14 * u_gs_bem)

    def u_law(q):
        if q >= 1:
            return d / kappa
        dp = brentq(lambda x: f_of(x) - (1 - q) * F, 0.0, d, xtol=1e-14 * d)
        return (d - dp) / kappa

    ratios = np.array([u_bem(q) / u_law(q) for q in levels])
    qs = np.linspace(0.01, 1.0, 100)
    r = np.interp(qs, np.concatenate([[0.0], levels]), np.concatenate([[1.0], ratios]))
    u_corr = np.array([u_law(q) for q in qs]) * r
    err = float(np.abs(fi(np.minimum(u_corr, u_gs_bem)) - qs).max())
    return ratios, err


def solve_task(task):
    """One depth: full stick on N and 2N, partial slip on N, for every nu (module
    docstring). A module-level function of one picklable dict, for tools.studies.runner."""
    from scipy.interpolate import CubicSpline
    t0 = time.perf_counter()
    d, nus, nl, nw, tol = (task["d_tilde"], tuple(task["nus"]), task["n_length"],
                           task["n_width"], task["tol"])
    coarse = cylinder_full_stick(d, nus, nl, nw, tol=tol)
    fine = cylinder_full_stick(d, nus, 2 * nl, 2 * nw, tol=tol)
    kappa = cylinder_full_stick(d, nus, task["slip_n_length"], task["slip_n_width"],
                                tol=tol)
    normal = kappa.normal
    J = task["slip_depths"]
    dprime = d * np.arange(J, 0, -1) / J                      # deepest first: warm starts
    Fd = normal_force_on_grid(normal.grid, dprime, tol=tol, workers=1)
    f_of = CubicSpline(np.concatenate([[0.0], dprime[::-1]]),
                       np.concatenate([[0.0], Fd[::-1]]))
    out = dict(key=task["key"], d_tilde=d, nu=np.array(nus), kn_N=coarse.kn,
               kn_2N=fine.kn,
               across_N=coarse.ratio_across, along_N=coarse.ratio_along,
               across_2N=fine.ratio_across, along_2N=fine.ratio_along,
               grid_N=normal.grid.describe(), grid_2N=fine.normal.grid.describe(),
               force_check=float(abs(Fd[0] / (4 * normal.pressure.sum()
                                              * normal.grid.cell_area) - 1)))
    iters = coarse.iterations + fine.iterations + kappa.iterations
    slip = {}
    for direction, ratios in (("y", kappa.ratio_across), ("x", kappa.ratio_along)):
        for nu, kappa in zip(nus, ratios):
            m = partial_slip_measures(normal, nu, direction, float(kappa),
                                      task["slip_points"], J, tol, f_of)
            iters += m.pop("iterations")
            slip[(direction, nu)] = m
    for name in ("err_mdr", "err_scaled", "ugs", "w_mdr", "w_scaled", "err_corrected",
                 "shift_ratio"):
        out[f"{name}_across"] = np.array([slip[("y", nu)][name] for nu in nus])
        out[f"{name}_along"] = np.array([slip[("x", nu)][name] for nu in nus])
    out["curves"] = {f"{k[0]}_{k[1]}": (v["u"], v["f"]) for k, v in slip.items()}
    out["iterations"] = iters
    out["seconds"] = time.perf_counter() - t0
    return out


def self_similarity_check(d_tilde=1e-3, nu=0.3, tol=1e-11):
    """k_t/k_n at the same d~ for L/R = 1 and 10 in physical units (different R, E*),
    on grids that scale with L (tools.bem.cylinder.sweep): the largest relative difference
    [-]."""
    from ..bem.cylinder import sweep
    from ..bem.tangential import full_stick_stiffness
    out = []
    for l_over_r, radius, estar in [(1.0, 0.01, 2.3e11), (10.0, 0.002, 5e9)]:
        L = l_over_r * radius
        d = d_tilde * L ** 2 / radius
        s = sweep(l_over_r, n=(64, 32), steps=1, d_max_over_r=d / radius, radius=radius,
                  estar=estar, tol=tol, fields=True, progress=False, backend="scipy")
        quarter = s.pressure[0][32:, 16:]
        kn = s.stiffness[0]
        out.append([full_stick_stiffness(quarter, s.grid, estar, nu, dr, tol=tol)[0] / kn
                    for dr in ("y", "x")])
    return float(np.abs(np.array(out[0]) / np.array(out[1]) - 1).max())


def tasks_for(d_min=1e-10, d_max=15.0, per_decade=2.0, nus=NUS, n_length=256, n_width=32,
              slip_points=24, slip_depths=32, tol=1e-8, slip_n_length=128, slip_n_width=16):
    """The study's tasks, one per depth (log-spaced d~)."""
    n = int(round(np.log10(d_max / d_min) * per_decade)) + 1
    return [dict(key=f"d{d:.6e}", d_tilde=float(d), nus=[float(v) for v in nus],
                 n_length=n_length, n_width=n_width, slip_points=slip_points,
                 slip_n_length=slip_n_length, slip_n_width=slip_n_width,
                 slip_depths=slip_depths, tol=tol)
            for d in np.geomspace(d_min, d_max, n)]


def _shift_name(side, q):
    """Column name of the partial-slip correction read by linecontact.tangential."""
    return f"shift_ratio_{side}_q{q:g}"


def assemble(results):
    """Rows (nu, d~) of the table from the per-depth results, and a summary."""
    nus = results[0]["nu"]
    cols = {k: [] for k in (
        "nu", "d_tilde", "kt_kn_across", "kt_kn_along", "kt_kn_mdr", "mdr_err_across",
        "mdr_err_along", "kt_kn_across_N", "kt_kn_along_N", "grid_change_across",
        "grid_change_along", "ft_err_mdr_across", "ft_err_mdr_along",
        "ft_err_scaled_across", "ft_err_scaled_along", "ugs_across", "ugs_along",
        "w_ratio_mdr_across", "w_ratio_mdr_along", "w_ratio_scaled_across",
        "w_ratio_scaled_along", "ft_err_corrected_across", "ft_err_corrected_along")}
    for side in ("across", "along"):
        for q in Q_LEVELS:
            cols[_shift_name(side, q)] = []
    for i, nu in enumerate(nus):
        for r in results:
            mdr = mdr_stiffness_ratio(nu)
            cols["nu"].append(nu)
            cols["d_tilde"].append(r["d_tilde"])
            cols["kt_kn_across"].append(r["across_2N"][i])
            cols["kt_kn_along"].append(r["along_2N"][i])
            cols["kt_kn_mdr"].append(mdr)
            cols["mdr_err_across"].append(mdr / r["across_2N"][i] - 1)
            cols["mdr_err_along"].append(mdr / r["along_2N"][i] - 1)
            cols["kt_kn_across_N"].append(r["across_N"][i])
            cols["kt_kn_along_N"].append(r["along_N"][i])
            cols["grid_change_across"].append(r["across_2N"][i] / r["across_N"][i] - 1)
            cols["grid_change_along"].append(r["along_2N"][i] / r["along_N"][i] - 1)
            for name, key in (("ft_err_mdr", "err_mdr"), ("ft_err_scaled", "err_scaled"),
                              ("ugs", "ugs"), ("w_ratio_mdr", "w_mdr"),
                              ("w_ratio_scaled", "w_scaled"),
                              ("ft_err_corrected", "err_corrected")):
                cols[f"{name}_across"].append(r[f"{key}_across"][i])
                cols[f"{name}_along"].append(r[f"{key}_along"][i])
            for side in ("across", "along"):
                for j, q in enumerate(Q_LEVELS):
                    cols[_shift_name(side, q)].append(r[f"shift_ratio_{side}"][i][j])
    cols = {k: np.asarray(v, dtype=float) for k, v in cols.items()}
    elastic = cols["nu"] > 0
    summary = {}
    for side in ("across", "along"):
        e = cols[f"mdr_err_{side}"]
        summary[f"mdr_err_{side}"] = {float(nu): (float(e[cols["nu"] == nu].min()),
                                                  float(e[cols["nu"] == nu].max()))
                                      for nu in nus if nu > 0}
        summary[f"grid_change_{side}"] = float(np.abs(cols[f"grid_change_{side}"]).max())
        summary[f"ft_err_mdr_{side}"] = float(cols[f"ft_err_mdr_{side}"][elastic].max())
        summary[f"ft_err_scaled_{side}"] = float(cols[f"ft_err_scaled_{side}"][elastic].max())
        summary[f"ft_err_corrected_{side}"] = float(
            cols[f"ft_err_corrected_{side}"][elastic].max())
        summary[f"ugs_{side}"] = (float(cols[f"ugs_{side}"][elastic].min()),
                                  float(cols[f"ugs_{side}"][elastic].max()))
        for w in ("w_ratio_mdr", "w_ratio_scaled"):
            v = cols[f"{w}_{side}"][elastic]
            summary[f"{w}_{side}"] = (float(v.min()), float(v.max()))
    zero = ~elastic
    summary["nu0_oracle"] = float(max(
        np.abs(cols["kt_kn_across"][zero] - 1).max(initial=0),
        np.abs(cols["kt_kn_along"][zero] - 1).max(initial=0),
        cols["ft_err_mdr_across"][zero].max(initial=0),
        cols["ft_err_mdr_along"][zero].max(initial=0)))
    summary["interpolation"] = interpolation_error(cols)
    summary["force_check"] = float(max(r["force_check"] for r in results))
    return cols, summary


def interpolation_error(cols):
    """Largest error of a cubic spline in ln d~ through every other depth at the depths
    left out (per nu, both directions) [-]: how well the table's spacing resolves the
    curve (the error of interpolating the full table is smaller)."""
    from scipy.interpolate import CubicSpline
    worst = 0.0
    for nu in np.unique(cols["nu"]):
        sel = cols["nu"] == nu
        x = np.log(cols["d_tilde"][sel])
        for name in ("kt_kn_across", "kt_kn_along"):
            y = cols[name][sel]
            if x.size < 5:
                continue
            s = CubicSpline(x[::2], y[::2])
            mid = np.arange(1, x.size - 1, 2)
            worst = max(worst, float(np.abs(s(x[mid]) / y[mid] - 1).max()))
    return worst


def run(args):
    from linecontact.tables import write_table
    from .runner import run_study_from_args, table_meta, wall_time_line

    t0 = time.perf_counter()
    tasks = tasks_for(args.d_min, args.d_max, args.per_decade, args.nu, args.n_length,
                      args.n_width, args.slip_points, args.slip_depths, args.tol,
                      args.slip_n_length, args.slip_n_width)
    own_checkpoint = getattr(args, "checkpoint", None) is None
    if own_checkpoint:
        # out/ is git-ignored; removed once the table is written
        args.checkpoint = REPO / "out" / "partial_tangential"
    results = run_study_from_args(solve_task, tasks, args, desc="tangential study")
    cols, s = assemble(results)
    similar = self_similarity_check()
    wall = time.perf_counter() - t0
    nus = sorted(set(cols["nu"].tolist()))

    def rng(side, nu):
        lo, hi = s[f"mdr_err_{side}"][nu]
        return f"{100 * lo:+.1f} % .. {100 * hi:+.1f} %"

    mdr_errs = "; ".join(f"nu = {nu:g}: across {rng('across', nu)}, along {rng('along', nu)}"
                         for nu in nus if nu > 0)
    meta = table_meta(
        args.command_line,
        title="Full-stick tangential over normal stiffness k_t/k_n of a rigid parabolic "
              "cylinder of finite length on an elastic half-space, across and along its "
              "axis, against d~ = d R/L^2 and nu, with the MDR's error and the partial-slip "
              "law's",
        source="computed by the linecontact boundary-element solver (tools/bem/tangential.py, "
               "tools/studies/tangential_study.py): normal contact by Polonsky-Keer CG on Love's "
               "coefficients, tangential problems on its contact set with Cerruti's "
               "rectangle coefficients (Pohrt & Li 2014), uncoupled (Goodman 1962), one "
               "traction component parallel to the shift",
        units="nu [-], d_tilde = d R/L^2 [-], kt_kn_* = k_t/k_n [-] (across: shift along y, "
              "the rolling direction; along: shift along x, the axis; 2N grid), kt_kn_mdr = "
              "2(1-nu)/(2-nu) [-], mdr_err_* = kt_kn_mdr/kt_kn_* - 1 [-] (relative error of "
              "the MDR's k_t), kt_kn_*_N [-] (N grid), grid_change_* = kt_kn_*/kt_kn_*_N - 1 "
              "[-], ft_err_mdr_* = largest |F_t,BEM - F_t,MDR|/(mu F) over the monotonic "
              "partial-slip curve with F_t,MDR = mu [F(d) - F(d - G* u/(mu E*))] [-], "
              "ft_err_scaled_* = the same for the scaled law F_t = mu [F(d) - F(d - "
              "kappa u/mu)], kappa = k_t/k_n of the BEM on the partial-slip grid [-], ugs_* = BEM gross-slip "
              "shift / (mu d/kappa) [-], w_ratio_mdr_* = W_BEM/W_MDR and w_ratio_scaled_* = "
              "W_BEM/W_scaled, the energy dissipated per fretting cycle (Masing) at "
              "amplitude u0 = half the law's gross-slip shift [-], shift_ratio_*_qQ = the BEM's "
              "shift over the scaled law's at the load fraction F_t/(mu F) = Q (the "
              "partial-slip correction linecontact.tangential applies, linear in Q between "
              "the columns and 1 at Q = 0; q1 is the gross-slip shift) [-], "
              "ft_err_corrected_* = largest |F_t,BEM - F_t|/(mu F) of the scaled law so "
              "corrected [-]",
        accuracy=f"k_t/k_n: largest change from N to 2N {s['grid_change_across']:.1e} across, "
                 f"{s['grid_change_along']:.1e} along; spline in ln d_tilde through every "
                 f"other depth reproduces the rest within {s['interpolation']:.1e}; nu = 0 "
                 f"rows (exact oracle k_t = k_n and the MDR's partial slip): largest "
                 f"deviation {s['nu0_oracle']:.1e}; uncoupled (Goodman) approximation, exact "
                 "for nu = 0.5 or like materials; parabolic gap: d << R",
        mdr_error=f"MDR's k_t relative to the BEM (min .. max over d_tilde): {mdr_errs}",
        partial_slip=f"largest error over the whole curve, relative to mu F, nu > 0: MDR "
                     f"{s['ft_err_mdr_across']:.3f} across, {s['ft_err_mdr_along']:.3f} "
                     f"along; scaled law {s['ft_err_scaled_across']:.4f} across, "
                     f"{s['ft_err_scaled_along']:.4f} along; scaled law with the "
                     f"shift_ratio correction {s['ft_err_corrected_across']:.4f} across, "
                     f"{s['ft_err_corrected_along']:.4f} along; F(d') of the laws from a "
                     f"cubic spline through {args.slip_depths} normal solutions (its error "
                     f"shows in the nu = 0 rows); BEM gross slip / scaled law's: "
                     f"{s['ugs_across'][0]:.3f}-{s['ugs_across'][1]:.3f} across, "
                     f"{s['ugs_along'][0]:.3f}-{s['ugs_along'][1]:.3f} along",
        dissipation=f"W_BEM/W_MDR {s['w_ratio_mdr_across'][0]:.3f}-"
                    f"{s['w_ratio_mdr_across'][1]:.3f} across, "
                    f"{s['w_ratio_mdr_along'][0]:.3f}-{s['w_ratio_mdr_along'][1]:.3f} along; "
                    f"W_BEM/W_scaled {s['w_ratio_scaled_across'][0]:.3f}-"
                    f"{s['w_ratio_scaled_across'][1]:.3f} across, "
                    f"{s['w_ratio_scaled_along'][0]:.3f}-{s['w_ratio_scaled_along'][1]:.3f} "
                    "along (u0 = half the law's gross-slip shift)",
        self_similarity=f"L/R = 1 and 10 at d_tilde = 1e-3 in physical units (grids "
                        f"scaled with L): k_t/k_n differ by {similar:.1e}",
        grid=f"per depth: adapted grids of tools.bem.cylinder.solve_depth, N = {args.n_length} "
             f"cells along the half-length and {args.n_width} across the contact "
             f"half-width, 2N = {2 * args.n_length} and {2 * args.n_width}; quarter grids "
             f"by symmetry; partial slip on {args.slip_n_length} along the half-length and "
             f"{args.slip_n_width} across the half-width (kappa = k_t/k_n on that grid) with {args.slip_points} shift steps and "
             f"{args.slip_depths} normal depths for F(d')",
        tolerance=f"{args.tol:g} (gap error / d; punch displacement error / shift; partial "
                  "slip optimality / largest shift)",
        d_tilde_range=f"[{cols['d_tilde'].min():.6g}, {cols['d_tilde'].max():.6g}]",
        nu_values=" ".join(f"{v:g}" for v in nus),
        wall_time=wall_time_line(wall, results, "depths", args.scheduler, args.workers),
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "tangential_cylinder.csv"
    write_table(path, meta, cols)
    if own_checkpoint:
        import shutil
        shutil.rmtree(args.checkpoint, ignore_errors=True)
    print(f"wrote {path}: {len(cols['nu'])} rows in {wall:.0f} s")
    for k, v in s.items():
        print(f"  {k}: {v}")
    print(f"  self_similarity: {similar:.2e}")
    return 0
