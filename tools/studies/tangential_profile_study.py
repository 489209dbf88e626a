"""Tangential stiffness by direction of profiled rollers: tables/tangential_profiles.csv.

The runtime method (linecontact.mindlin.equivalent_ellipse_ratio, Contact.tangential
``method="ellipse"``) gives any elongated footprint the k_t/k_n of its *equivalent
ellipse*: the ellipse with the footprint's half-length a along the axis whose
flat-punch stiffness pi a E*/K(e) equals the footprint's normal stiffness k_n, and
Mindlin's ratio of that ellipse across (y) and along (x) the roller. Both k_t and k_n
are flat-punch stiffnesses of the same footprint (full stick: a rigid shift of the
contact set), so the ratio depends on the footprint's shape and nu alone. For a Hertz
ellipse it is Mindlin's ratio exactly; this study measures it for the other footprints.

Per case (a roller of radius R, length L and profile on a flat half-space, aligned, at
a force F given as q/(E* D), D = 2R, q = F/L; one task of tools.studies.runner):

1. 3D normal contact (tools.bem.roller.solve_roller_force, tilt held at 0) on two
   grids, N = (n_x, n_y) and 2N, each adapted to the contact; on each contact set the
   flat-punch problems with Love's kernel (k_n, the solver's stiffness) and Cerruti's
   (tools.bem.tangential: K_yy across, K_xx along, full DC-FFT) for every nu. The
   reference ratio is the 2N value; its grid change N -> 2N is recorded.
2. The equivalent ellipse from the BEM's own footprint (a = half the contact's extent
   in x on the 2N grid, k_n of the 2N grid): the method's error with exact inputs.
3. The library chain: the coupled slices of Contact (model 'profiled-roller', the
   default slice count) at the same force give a = half their contact length and
   k_n = dF/dd at held tilt, and the ratio from them: the error a user gets.
4. Partial slip on the N grid, across and along, for every nu: the BEM's monotonic
   curve F_t(u) (Coulomb, mu = 1, from the virgin state up to gross slip) against the
   scaled law F_t = mu [F(d) - F(d - kappa u/mu)] with kappa the equivalent ellipse's
   ratio (as linecontact applies it) and F(d') from normal solutions on the same grid;
   the largest difference over the curve relative to mu F, and the energy dissipated
   per fretting cycle (Masing) at half the law's gross-slip shift, BEM over law.

The curves scale exactly with mu, so mu = 1. Budget: the default run (42 cases, 3
values of nu) took 401-474 s with one worker process on the 2-core reference machine under
load (load average 14); the table's wall_time line records each run's own figure.
"""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from linecontact.mindlin import equivalent_axes_ratio, equivalent_ellipse_ratio
from linecontact.tangential import mdr_stiffness_ratio

from ..bem.roller import solve_roller, solve_roller_force
from ..bem.solver import ConvergenceError, solve_punch
from ..bem.tangential import load_path, shear_modulus_for, tangential_operator
from .tangential_study import _law, _masing_w

REPO = Path(__file__).resolve().parents[2]
NUS = (0.0, 0.3, 0.5)
#: Profiles of the study (before a colon: the profile's key in linecontact.profiles).
PROFILES = ("circular", "iso16281", "lundberg", "johns-gohar", "end-relief:corner",
            "end-relief:linear", "straight")


def make_profile(name, radius, length, estar, design_force):
    """The linecontact profile object of a case (None: straight, sharp ends)."""
    from linecontact import profiles as pr
    if name == "circular":
        return pr.CircularCrownProfile(length, 50 * length)
    if name == "iso16281":
        return pr.ISO16281Profile(length, 2 * radius)
    if name == "lundberg":
        return pr.LundbergProfile(length, estar, design_force)
    if name == "johns-gohar":
        return pr.JohnsGoharProfile(length, radius, estar, design_force)
    if name == "end-relief:corner":
        return pr.EndReliefProfile(length, corner_radius=0.1 * 2 * radius)
    if name == "end-relief:linear":
        return pr.EndReliefProfile(length, relief_length=0.1 * length,
                                   relief_drop=2.5e-4 * 2 * radius)
    if name == "straight":
        return None
    raise ValueError(f"profile = {name!r} is not one of {PROFILES}")


def add_arguments(parser):
    parser.add_argument("--profiles", nargs="+", default=list(PROFILES),
                        help=f"profiles (default: {' '.join(PROFILES)})")
    parser.add_argument("--l-over-d", type=float, nargs="+", default=[1.0, 3.0],
                        help="roller L/D (default 1 3)")
    parser.add_argument("--loads", type=float, nargs="+", default=[1e-4, 5e-4, 2e-3],
                        help="line loads q/(E* D) (default 1e-4 5e-4 2e-3); the "
                             "logarithmic profiles are designed for the middle one")
    parser.add_argument("--nu", type=float, nargs="+", default=list(NUS),
                        help=f"Poisson's ratios (default {' '.join(map(str, NUS))})")
    parser.add_argument("--n-x", type=int, default=128,
                        help="cells along the contact on N (default 128; 2N is also "
                             "solved)")
    parser.add_argument("--n-y", type=int, default=32,
                        help="cells across the contact on N (default 32)")
    parser.add_argument("--slip-points", type=int, default=20,
                        help="shift steps of each partial-slip curve (default 20)")
    parser.add_argument("--slip-depths", type=int, default=16,
                        help="normal solutions d' = d j/J for the law's F(d') "
                             "(default 16)")
    parser.add_argument("--tol", type=float, default=1e-8,
                        help="solver tolerance (default 1e-8)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for tangential_profiles.csv (default tables/)")
    from .runner import add_runner_arguments
    add_runner_arguments(parser)


RADIUS, ESTAR = 5e-3, 115.385e9


def _ratios(res, nus, tol):
    """k_t/k_n across (y) and along (x) on the BEM contact set, per nu."""
    g, S = res.grid, res.pressure > 0
    out = {"y": [], "x": []}
    for nu in nus:
        for dr in ("y", "x"):
            op = tangential_operator(g.nx, g.ny, g.dx, g.dy, shear_modulus_for(ESTAR, nu),
                                     nu, dr, symmetric=False, workers=1)
            sol = solve_punch(op, S, tol=tol)
            if not sol.converged:
                raise ConvergenceError(f"tangential punch ({dr}, nu = {nu}): error "
                                       f"{sol.error:.3g} > {tol:g}")
            out[dr].append(sol.pressure.sum() * g.cell_area / res.stiffness)
    return np.array(out["y"]), np.array(out["x"])


def _ellipse(half_length, kn, nu, direction):
    """The equivalent ellipse's k_t/k_n of a rigid roller on a half-space of nu."""
    r = mdr_stiffness_ratio(nu)
    return equivalent_ellipse_ratio(half_length, kn, r * ESTAR, ESTAR, direction)


def _slices(profile, length, force, nu):
    """Half contact length [m] and held-tilt k_n [N/m] of the runtime coupled slices."""
    from linecontact.contact import Contact, Elastic, Roller
    body = Elastic(ESTAR * (1 - nu * nu), nu)
    c = Contact(Roller(RADIUS, length, profile=profile), None, body,
                Elastic(math.inf, 0.3), model="profiled-roller")
    s = c.normal(force=force).solutions[0]
    return 0.5 * s.contact_length, float(s.stiffness_matrix[0, 0])


def _slip(res, nus, kappas, points, depths, radius, length, profile, tol):
    """Partial slip of the BEM against the scaled law with kappa, per (direction, nu)."""
    from scipy.interpolate import CubicSpline
    g, p, d = res.grid, res.pressure, res.depth
    F = res.force
    dprime = d * np.arange(depths, 0, -1) / depths
    Fd = []
    for dp in dprime:
        r = solve_roller(radius, length, ESTAR, dp, profile=profile, n_x=g.nx, n_y=g.ny,
                         window=g, stiffness=False, tol=tol)
        Fd.append(r.force)
    f_of = CubicSpline(np.concatenate([[0.0], dprime[::-1]]),
                       np.concatenate([[0.0], Fd[::-1]]))
    out = {}
    for (dr, nu), kappa in zip([(dr, nu) for nu in nus for dr in ("y", "x")], kappas):
        op = tangential_operator(g.nx, g.ny, g.dx, g.dy, shear_modulus_for(ESTAR, nu), nu,
                                 dr, symmetric=False, workers=1)
        u_gs = float(op(p)[p > 0].max())
        U = 1.02 * max(u_gs, d / kappa)
        shifts = U * np.arange(1, points + 1) / points
        states = load_path(op, p, 1.0, shifts, tol=tol, scale=U)
        f = np.concatenate([[0.0], [s.traction.sum() * g.cell_area / F for s in states]])
        u = np.concatenate([[0.0], shifts])
        u0 = 0.5 * d / kappa
        out[(dr, nu)] = dict(
            err=float(np.abs(f - _law(u, kappa, d, F, f_of)).max()),
            w=float(_masing_w(u, f, u0) / _masing_w(u, _law(u, kappa, d, F, f_of), u0)),
            force_check=float(abs(Fd[0] / F - 1)))
    return out


def solve_task(task):
    """One case (module docstring); a module-level function of one picklable dict."""
    t0 = time.perf_counter()
    nus, tol = tuple(task["nus"]), task["tol"]
    L = task["l_over_d"] * 2 * RADIUS
    F = task["load"] * ESTAR * 2 * RADIUS * L
    design = task["design_load"] * ESTAR * 2 * RADIUS * L
    profile = make_profile(task["profile"], RADIUS, L, ESTAR, design)
    kw = dict(tilt=0.0, profile=profile, tol=tol, fields=True)
    coarse = solve_roller_force(RADIUS, L, ESTAR, F, n_x=task["n_x"], n_y=task["n_y"], **kw)
    fine = solve_roller_force(RADIUS, L, ESTAR, F, n_x=2 * task["n_x"],
                              n_y=2 * task["n_y"], start=(coarse.depth, 0.0), **kw)
    across_N, along_N = _ratios(coarse, nus, tol)
    across, along = _ratios(fine, nus, tol)
    a_bem = 0.5 * fine.contact_length
    ell = {dr: np.array([_ellipse(a_bem, fine.stiffness, nu, dr) for nu in nus])
           for dr in ("y", "x")}
    lib = {"y": [], "x": []}
    a_lib = kn_lib = None
    for nu in nus:
        a_lib, kn_lib = _slices(profile, L, F, nu)
        for dr in ("y", "x"):
            lib[dr].append(_ellipse(a_lib, kn_lib, nu, dr))
    kap_N = {dr: [_ellipse(0.5 * coarse.contact_length, coarse.stiffness, nu, dr)
                  for nu in nus] for dr in ("y", "x")}
    kappas = [kap_N[dr][i] for i in range(len(nus)) for dr in ("y", "x")]
    slip = _slip(coarse, nus, kappas, task["slip_points"], task["slip_depths"], RADIUS, L,
                 profile, tol)
    return dict(
        key=task["key"], profile=task["profile"], l_over_d=task["l_over_d"],
        load=task["load"], nu=np.array(nus), across=across, along=along,
        across_N=across_N, along_N=along_N,
        ell_across=ell["y"], ell_along=ell["x"],
        lib_across=np.array(lib["y"]), lib_along=np.array(lib["x"]),
        edge_loaded=fine.edge_loaded, a_bem=a_bem, a_lib=a_lib,
        kn_bem=fine.stiffness, kn_lib=kn_lib,
        kprime=float(equivalent_axes_ratio(a_bem, fine.stiffness, ESTAR)),
        slip_err_across=np.array([slip[("y", nu)]["err"] for nu in nus]),
        slip_err_along=np.array([slip[("x", nu)]["err"] for nu in nus]),
        w_across=np.array([slip[("y", nu)]["w"] for nu in nus]),
        w_along=np.array([slip[("x", nu)]["w"] for nu in nus]),
        force_check=max(s["force_check"] for s in slip.values()),
        grid_N=coarse.grid.describe(), grid_2N=fine.grid.describe(),
        seconds=time.perf_counter() - t0)


def tasks_for(profiles=PROFILES, l_over_d=(1.0, 3.0), loads=(1e-4, 5e-4, 2e-3), nus=NUS,
              n_x=128, n_y=32, slip_points=20, slip_depths=16, tol=1e-8):
    """One task per (profile, L/D, load); the logarithmic profiles are designed for the
    middle load."""
    design = sorted(loads)[len(loads) // 2]
    return [dict(key=f"{p}-LD{ld:g}-q{q:.3e}", profile=p, l_over_d=float(ld),
                 load=float(q), design_load=float(design), nus=[float(v) for v in nus],
                 n_x=n_x, n_y=n_y, slip_points=slip_points, slip_depths=slip_depths,
                 tol=tol)
            for p in profiles for ld in l_over_d for q in loads]


COLUMNS = ("profile", "l_over_d", "load", "nu", "edge_loaded", "kprime",
           "kt_kn_across", "kt_kn_along", "kt_kn_mdr", "grid_change_across",
           "grid_change_along", "ellipse_err_across", "ellipse_err_along",
           "method_err_across", "method_err_along", "mdr_err_across", "mdr_err_along",
           "kn_slices_err", "half_length_slices_err", "ft_err_across", "ft_err_along",
           "w_ratio_across", "w_ratio_along")


def assemble(results):
    """Rows (case, nu) and the summary of the errors."""
    cols = {k: [] for k in COLUMNS}
    for r in results:
        for i, nu in enumerate(r["nu"]):
            mdr = mdr_stiffness_ratio(nu)
            row = dict(
                profile=PROFILES.index(r["profile"]), l_over_d=r["l_over_d"],
                load=r["load"], nu=nu,
                edge_loaded=int(r["edge_loaded"]), kprime=r["kprime"],
                kt_kn_across=r["across"][i], kt_kn_along=r["along"][i], kt_kn_mdr=mdr,
                grid_change_across=r["across"][i] / r["across_N"][i] - 1,
                grid_change_along=r["along"][i] / r["along_N"][i] - 1,
                ellipse_err_across=r["ell_across"][i] / r["across"][i] - 1,
                ellipse_err_along=r["ell_along"][i] / r["along"][i] - 1,
                method_err_across=r["lib_across"][i] / r["across"][i] - 1,
                method_err_along=r["lib_along"][i] / r["along"][i] - 1,
                mdr_err_across=mdr / r["across"][i] - 1,
                mdr_err_along=mdr / r["along"][i] - 1,
                kn_slices_err=r["kn_lib"] / r["kn_bem"] - 1,
                half_length_slices_err=r["a_lib"] / r["a_bem"] - 1,
                ft_err_across=r["slip_err_across"][i], ft_err_along=r["slip_err_along"][i],
                w_ratio_across=r["w_across"][i], w_ratio_along=r["w_along"][i])
            for k in COLUMNS:
                cols[k].append(row[k])
    cols = {k: np.array(v, dtype=float) for k, v in cols.items()}

    def worst(name):
        return float(np.abs(np.asarray(cols[name], float)).max())

    s = {k: worst(k) for k in COLUMNS[9:] if not k.startswith("w_")}
    s["w_ratio"] = (float(min(cols["w_ratio_across"].min(), cols["w_ratio_along"].min())),
                    float(max(cols["w_ratio_across"].max(), cols["w_ratio_along"].max())))
    s["force_check"] = max(r["force_check"] for r in results)
    for side in ("across", "along"):
        # the method's largest error plus the largest grid change of the reference
        s[f"stated_{side}"] = s[f"method_err_{side}"] + s[f"grid_change_{side}"]
        s[f"w_err_{side}"] = float(np.abs(cols[f"w_ratio_{side}"] - 1).max())
    s["stated"] = max(s["stated_across"], s["stated_along"])
    return cols, s


def run(args):
    from linecontact.tables import write_table
    from .runner import run_study_from_args, table_meta, wall_time_line

    t0 = time.perf_counter()
    tasks = tasks_for(args.profiles, args.l_over_d, args.loads, args.nu, args.n_x, args.n_y,
                      args.slip_points, args.slip_depths, args.tol)
    results = run_study_from_args(solve_task, tasks, args, desc="tangential profiles")
    cols, s = assemble(results)
    wall = time.perf_counter() - t0
    meta = table_meta(
        args.command_line,
        title="Full-stick tangential over normal stiffness k_t/k_n of profiled rollers on "
              "an elastic half-space, across and along the axis, 3D boundary elements "
              "against the equivalent ellipse's Mindlin ratio (the runtime method) and "
              "the MDR; partial slip of the scaled law",
        source="computed by the linecontact boundary-element solver (tools/bem/roller.py "
               "for the normal contact, tools/bem/tangential.py: flat-punch problems on its "
               "contact set with Cerruti's rectangle coefficients, uncoupled (Goodman "
               "1962), "
               "one traction component parallel to the shift; "
               "tools/studies/tangential_profile_study.py)",
        profiles=" ".join(f"{i}={n}" for i, n in enumerate(PROFILES)),
        units="profile = index in the 'profiles' line (linecontact.profiles: circular "
              "crown Rc = 50 L, iso16281 (L, D), lundberg and johns-gohar designed for "
              "the middle load, end-relief:corner a corner radius 0.1 D, "
              "end-relief:linear 0.1 L long and 2.5e-4 D deep, straight with sharp ends), "
              "l_over_d = L/(2R) [-], load = q/(E* 2R), q = F/L [-], nu [-], edge_loaded "
              "(0/1: the contact reaches a roller end), kprime = b/a of the equivalent "
              "ellipse [-], kt_kn_* = k_t/k_n of the BEM (2N grid; across: shift along y, "
              "the rolling direction; along: along the axis) [-], kt_kn_mdr = "
              "2(1-nu)/(2-nu) [-], grid_change_* = 2N/N - 1 [-], ellipse_err_* = the "
              "equivalent ellipse's ratio from the BEM footprint (a, k_n) / BEM - 1 [-], "
              "method_err_* = the same from the runtime slices' a and k_n (the error a "
              "user gets) [-], mdr_err_* = kt_kn_mdr / BEM - 1 [-], kn_slices_err and "
              "half_length_slices_err = slices / BEM - 1 [-], ft_err_* = largest "
              "|F_t,BEM - F_t,law|/(mu F) over the monotonic partial-slip curve, law "
              "F_t = mu [F(d) - F(d - kappa u/mu)] with kappa the equivalent ellipse's "
              "ratio, N grid [-], w_ratio_* = W_BEM/W_law per fretting cycle (Masing) at "
              "half the law's gross-slip shift [-]",
        accuracy=f"k_t/k_n of the BEM: largest change N -> 2N "
                 f"{s['grid_change_across']:.1e} across, {s['grid_change_along']:.1e} "
                 f"along; equivalent ellipse from the BEM footprint: within "
                 f"{s['ellipse_err_across']:.1e} across, {s['ellipse_err_along']:.1e} "
                 f"along; from the runtime slices: within {s['method_err_across']:.1e} "
                 f"across, {s['method_err_along']:.1e} along; uncoupled (Goodman) "
                 "approximation, exact for nu = 0.5 or like materials",
        stated_error=f"{s['stated']:.2e} (largest method error plus the largest grid "
                     "change: the error linecontact states for method='ellipse' within "
                     "this table's range)",
        mdr_error=f"MDR's k_t relative to the BEM: up to {s['mdr_err_across']:.1%} across, "
                  f"{s['mdr_err_along']:.1%} along",
        partial_slip=f"largest error of the scaled law over the whole curve, relative to "
                     f"mu F: {s['ft_err_across']:.4f} across, {s['ft_err_along']:.4f} "
                     f"along; W_BEM/W_law {s['w_ratio'][0]:.3f}-{s['w_ratio'][1]:.3f}; "
                     f"F(d') from a cubic spline through {args.slip_depths} normal "
                     f"solutions (force check {s['force_check']:.1e})",
        grid=f"per case: grids of tools.bem.roller adapted to the contact, N = {args.n_x} x "
             f"{args.n_y} cells, 2N = {2 * args.n_x} x {2 * args.n_y} (full grid, DC-FFT); "
             f"partial slip on N with {args.slip_points} shift steps; runtime slices: "
             "Contact(model='profiled-roller') with its default slice count",
        range=f"l_over_d {min(args.l_over_d):g}-{max(args.l_over_d):g}, load "
              f"{min(args.loads):g}-{max(args.loads):g}, nu "
              f"{' '.join(f'{v:g}' for v in args.nu)}, kprime "
              f"{cols['kprime'].min():.4f}-{cols['kprime'].max():.4f}",
        covered_l_over_d=f"{min(args.l_over_d):g}, {max(args.l_over_d):g}",
        covered_line_load_over_estar_d=f"{min(args.loads):g}, {max(args.loads):g}",
        covered_nu=f"{min(args.nu):g}, {max(args.nu):g}",
        covered_profiles=", ".join(dict.fromkeys(p.split(":")[0] for p in args.profiles)),
        runtime_error_across=f"stiffness_ratio {s['stated_across']:.3g}, partial_slip "
                             f"{s['ft_err_across']:.3g}, dissipation "
                             f"{s['w_err_across']:.3g}",
        runtime_error_along=f"stiffness_ratio {s['stated_along']:.3g}, partial_slip "
                            f"{s['ft_err_along']:.3g}, dissipation {s['w_err_along']:.3g}",
        tolerance=f"{args.tol:g} (gap error; punch displacement error / shift; partial "
                  "slip optimality / largest shift)",
        wall_time=wall_time_line(wall, results, "cases", args.scheduler, args.workers),
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "tangential_profiles.csv"
    write_table(path, meta, cols)
    print(f"wrote {path}: {len(cols['nu'])} rows in {wall:.0f} s")
    for k, v in s.items():
        print(f"  {k}: {v}")
    return 0
