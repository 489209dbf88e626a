"""Adhesive pull-off of the finite cylinder: tables/adhesion_cylinder.csv.

The rule of Hess (Popov & Hess 2015, chapter 5; linecontact.adhesion) is exact for
axisymmetric bodies and an approximation for the elongated contact of a roller. This
study measures the finite cylinder's pull-off force with the adhesive BEM of
tools.bem.adhesion (detachment where the energy release rate G = K_I^2/(2 E*) read from
the edge cell's tension exceeds w, with the coefficient of the edge's discrete shape:
straight runs derived from the plane-strain collocation problem, other edge cells Pohrt
& Popov's 2015 constant) and the rule's error.

Self-similarity: with the parabolic gap y^2/(2R), lengths scale with L, displacements
with L^2/R, pressures with E* L/R (docs/theory.md, section 'Self-similarity'), so the
work of adhesion enters through one number, w~ = w R^2/(E* L^3), and every result
F R/(E* L^3) is a function of w~ (and d~ = d R/L^2) alone, for every L/R. The table
uses s = b_c/L = (2 w~/pi)^(1/3), the 2D JKR half-width at pull-off over the length
(Barquins 1988), and gives forces over the 2D JKR value of the whole length,
F_2D = -3 (pi E* R w^2/16)^(1/3) L, i.e. F~_2D = -3 (pi w~^2/16)^(1/3): the ratio tends
to 1 for a roller whose ends do not matter. They do for a long one: at mid-length the
section follows the 2D law (checked, the ``long_strip`` line), but below s of about
0.08 the contact unzips from its ends before its middle reaches b_c (the 3D compliance
of a long strip grows as ln(L/b), and with it the energy released by peeling an end),
so the ratio falls below 1 as s -> 0: no 2D limit is imposed on the table or the
runtime.

Per s (one task per grid, L = R = E* = 1, w = w~): the retraction under depth control
on square cells of side h = b_c/n (n = --n values, default 8, 16; and 32 at the larger,
cheaper s as a check of the extrapolation, --check-n, --check-s; the criterion's own
error falls as 1/n, measured on the long strip below), from a pinned
contact 1.6 b_c wide to the jump-off; the smallest force is the pull-off force under
force control, the force at the last depth with contact (bisected) the one under depth
control. Converged value: first-order Richardson extrapolation of the two finest grids,
2 F(2n) - F(n) (the sphere's sequence, in the header, supports first order); accuracy:
|F(2n) - F(n)|. Under depth control the force is read at the steep end of the curve,
where the staircase of the contact edge makes the grid sequence irregular: the finest
grid's value is used and the change between the grids is its accuracy. The MDR rule on the universal curve's profile
(linecontact.adhesion.AdhesiveContact.from_model with the universal model) gives the
plain MDR values.

Oracles recorded in the header: the JKR sphere (pull-off 1.5 pi w R and 5/6 pi w R) and
Kendall's punch (sqrt(8 pi a^3 E* w)) on the same BEM (circular edges: Pohrt & Popov's
constant governs); the straight edge: a long flat strip punch at mid-length against
the exact 2D pull-off sqrt(2 pi E* w b), and the 2D JKR cylinder (Barquins 1988) at the
middle of a long parabolic strip, its pull-off per unit length on n = 8 .. 64 cells
across b_c (tools.bem.adhesion.long_strip), with Pohrt & Popov's constant beside it.

Budget: ``nice -n 10 python -m tools.build_tables adhesion --workers 2``; the table's
``wall_time`` line records each run's own figure.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[2]
S_VALUES = (0.025, 0.035, 0.05, 0.07, 0.1, 0.14, 0.2, 0.3, 0.5)
GRIDS = (8, 16)
#: A finer grid run at the cheaper (larger) s only, to check the extrapolation.
CHECK_N, CHECK_S = 32, (0.2, 0.3, 0.5)


def add_arguments(parser):
    parser.add_argument("--s", type=float, nargs="+", default=list(S_VALUES),
                        help="values of s = b_c/L = (2 w~/pi)^(1/3) (default "
                             f"{' '.join(map(str, S_VALUES))})")
    parser.add_argument("--n", type=int, nargs="+", default=list(GRIDS),
                        help="cells across b_c, coarse to fine, each twice the last "
                             f"(default {' '.join(map(str, GRIDS))})")
    parser.add_argument("--check-n", type=int, default=CHECK_N,
                        help="a finer grid to check the extrapolation (default "
                             f"{CHECK_N}; 0: none)")
    parser.add_argument("--check-s", type=float, nargs="+", default=list(CHECK_S),
                        help="the s values of that check (default "
                             f"{' '.join(map(str, CHECK_S))})")
    parser.add_argument("--steps", type=int, default=40,
                        help="depth steps of each retraction (default 40)")
    parser.add_argument("--out", type=Path, default=REPO / "tables",
                        help="folder for adhesion_cylinder.csv (default tables/)")
    from .runner import add_runner_arguments
    add_runner_arguments(parser)


def solve_task(task):
    from ..bem.adhesion import cylinder_retraction

    t0, c0 = time.perf_counter(), time.process_time()
    w = np.pi / 2 * task["s"] ** 3
    r = cylinder_retraction(w, n_width=task["n"], steps=task["steps"])
    return {"s": task["s"], "n": task["n"], "force": r.pull_off_force,
            "force_depth": r.pull_off_force_depth, "depth_off": r.pull_off_depth,
            "depth_min": r.extra["depth_min"], "width_min": r.extra["width_min"],
            "shape": r.shape, "seconds": time.perf_counter() - t0,
            "cpu": time.process_time() - c0}


def oracle_task(task):
    from ..bem.adhesion import kendall_punch, long_strip, sphere_retraction, strip_punch

    t0, c0 = time.perf_counter(), time.process_time()
    if task["kind"] == "sphere":
        r = sphere_retraction(1.0, 1.0, 1e-3, n_radius=task["n"], steps=task["steps"])
        res = {"force": -r.pull_off_force / (1.5 * np.pi * 1e-3),
               "depth": -r.pull_off_force_depth / (5 / 6 * np.pi * 1e-3)}
    elif task["kind"] == "strip":
        res = {"force": strip_punch(n_width=task["n"])}
    elif task["kind"] in ("long_strip", "long_strip_pp"):
        crit = "edge" if task["kind"] == "long_strip" else "pohrt-popov"
        r = long_strip(n_width=task["n"], criterion=crit)
        res = {"force": r["pull_off"], "b": r["b_pull_off"],
               "law": float(np.abs(r["ratio"] - 1).max())}
    else:
        k = kendall_punch(1.0, 1.0, 1e-3, n_radius=task["n"])
        res = {"force": k["force"] / -np.sqrt(8 * np.pi * 1e-3)}
    res.update(kind=task["kind"], n=task["n"], seconds=time.perf_counter() - t0,
               cpu=time.process_time() - c0)
    return res


def mdr_values(s):
    """Pull-off by the rule of Hess on the universal curve's profile (L = R = E* = 1)."""
    from linecontact.adhesion import AdhesiveContact
    from linecontact.models import UniversalModel

    m = UniversalModel(1.0, 1.0, 1.0, extrapolate=True)
    c = AdhesiveContact.from_model(m, np.pi / 2 * s ** 3)
    return c.pull_off("force")["force"], c.pull_off("depth")["force"]


def f2d(s):
    """2D JKR pull-off of the whole length, F R/(E* L^3) = -3 (pi w~^2/16)^(1/3)."""
    w = np.pi / 2 * s ** 3
    return -3 * np.cbrt(np.pi * w ** 2 / 16)


def assemble(results, grids):
    by = {(r["s"], r["n"]): r for r in results}
    ss = sorted({r["s"] for r in results})
    n1, n2 = grids[-2], grids[-1]
    cols = {k: [] for k in (
        "s", "w_tilde", "F2d", "ratio_force", "ratio_depth", "d_tilde_off",
        "mdr_ratio_force", "mdr_ratio_depth", "mdr_err_force", "mdr_err_depth",
        "grid_change_force", "grid_change_depth", "b_min_over_bc")}
    for n in grids:
        cols[f"ratio_force_n{n}"] = []
        cols[f"ratio_depth_n{n}"] = []
    for s in ss:
        F2 = f2d(s)
        fine, coarse = by[(s, n2)], by[(s, n1)]
        rf = (2 * fine["force"] - coarse["force"]) / F2
        rd = fine["force_depth"] / F2       # not smooth in h: the finest grid's
        mf, md = mdr_values(s)
        cols["s"].append(s)
        cols["w_tilde"].append(np.pi / 2 * s ** 3)
        cols["F2d"].append(F2)
        cols["ratio_force"].append(rf)
        cols["ratio_depth"].append(rd)
        cols["d_tilde_off"].append(fine["depth_off"])
        cols["mdr_ratio_force"].append(mf / F2)
        cols["mdr_ratio_depth"].append(md / F2)
        cols["mdr_err_force"].append(mf / F2 / rf - 1)
        cols["mdr_err_depth"].append(md / F2 / rd - 1)
        cols["grid_change_force"].append(fine["force"] / coarse["force"] - 1)
        cols["grid_change_depth"].append(fine["force_depth"] / coarse["force_depth"] - 1)
        cols["b_min_over_bc"].append(fine["width_min"] / s)
        for n in grids:
            cols[f"ratio_force_n{n}"].append(by[(s, n)]["force"] / F2)
            cols[f"ratio_depth_n{n}"].append(by[(s, n)]["force_depth"] / F2)
    return {k: np.array(v, dtype=float) for k, v in cols.items()}


def run(args):
    from linecontact.tables import write_table
    from .runner import run_study, run_study_from_args, table_meta, wall_time_line

    t0 = time.perf_counter()
    grids = sorted(args.n)
    tasks = [{"key": f"s{s:g}_n{n}", "s": float(s), "n": int(n), "steps": args.steps}
             for n in grids[::-1] for s in sorted(args.s, reverse=False)]
    check = [s for s in args.check_s if s in args.s] if args.check_n else []
    tasks += [{"key": f"s{s:g}_n{args.check_n}", "s": float(s), "n": int(args.check_n),
               "steps": args.steps} for s in check]
    own_checkpoint = getattr(args, "checkpoint", None) is None
    if own_checkpoint:
        args.checkpoint = REPO / "out" / "partial_adhesion"
    results = run_study_from_args(solve_task, tasks, args, desc="adhesion study")
    oracles = run_study(oracle_task, [
        {"key": f"sphere_{n}", "kind": "sphere", "n": n, "steps": args.steps}
        for n in (16, 32)] + [{"key": f"punch_{n}", "kind": "punch", "n": n}
                              for n in (32, 64, 128)]
        + [{"key": f"strip_{n}", "kind": "strip", "n": n} for n in (8, 16, 32)]
        + [{"key": f"long_strip_{n}", "kind": "long_strip", "n": n}
           for n in (64, 32, 16, 8)]
        + [{"key": "long_strip_pp_16", "kind": "long_strip_pp", "n": 16}],
        scheduler=args.scheduler, workers=args.workers, progress=False,
        checkpoint=args.checkpoint, resume=getattr(args, "resume", False),
        connect_timeout=getattr(args, "connect_timeout", None))
    cols = assemble([r for r in results if r["n"] in grids], grids)
    by = {(r["s"], r["n"]): r for r in results}
    check_lines = []
    for s_ in check:
        fine = by[(s_, args.check_n)]["force"] / f2d(s_)
        mid = by[(s_, grids[-1])]["force"] / f2d(s_)
        i = int(np.flatnonzero(cols["s"] == s_)[0])
        check_lines.append(f"s = {s_:g}: n = {args.check_n} gives {fine:.4f}, the "
                           f"extrapolation from n = {grids[-2]}, {grids[-1]} "
                           f"{cols['ratio_force'][i]:.4f}, from n = {grids[-1]}, "
                           f"{args.check_n} {2 * fine - mid:.4f}")
    wall = time.perf_counter() - t0
    sph = {o["n"]: o for o in oracles if o["kind"] == "sphere"}
    pun = {o["n"]: o for o in oracles if o["kind"] == "punch"}
    sph_line = "; ".join(f"n = {n}: force control {o['force']:.4f}, depth control "
                         f"{o['depth']:.4f}" for n, o in sorted(sph.items()))
    n_s = sorted(sph)
    sph_rich = 2 * sph[n_s[-1]]["force"] - sph[n_s[-2]]["force"]
    pun_line = "; ".join(f"n = {n}: {o['force']:.4f}" for n, o in sorted(pun.items()))
    strip = {o["n"]: o for o in oracles if o["kind"] == "strip"}
    strip_line = ", ".join(f"{o['force']:.4f} (n = {n})" for n, o in sorted(strip.items()))
    ls = {o["n"]: o for o in oracles if o["kind"] == "long_strip"}
    n_l = sorted(ls)
    ls_line = ", ".join(f"{ls[n]['force']:.4f} (n = {n})" for n in n_l)
    ls_rich = 2 * ls[n_l[-1]]["force"] - ls[n_l[-2]]["force"]
    ls_law = max(ls[n]["law"] for n in n_l[-1:])
    pp = [o for o in oracles if o["kind"] == "long_strip_pp"][0]
    small = cols["s"][:3]

    def rng(name):
        v = cols[name]
        return f"{100 * v.min():+.1f} % .. {100 * v.max():+.1f} %"

    meta = table_meta(
        args.command_line,
        title="Pull-off force of a rigid parabolic cylinder of finite length on an elastic "
              "half-space with JKR adhesion, over the 2D JKR value, against s = b_c/L, "
              "with the MDR rule's error",
        source="computed by the linecontact adhesive boundary-element solver "
               "(tools/bem/adhesion.py, tools/studies/adhesion_study.py): Love's "
               "coefficients on square cells, mirror-symmetric DCT operator; detachment "
               "where G = K_I^2/(2 E*) > w, K_I = -p_e sqrt(h)/alpha from the edge "
               "cell's tension p_e: alpha = 0.761535 on straight runs aligned with the "
               "cells (the plane-strain collocation limit), Pohrt & Popov's (2015) "
               "1/sqrt(2 x 0.473201) on other edge cells; retraction under depth control",
        units="s = b_c/L = (2 w~/pi)^(1/3) [-], w_tilde = w R^2/(E* L^3) [-], F2d = 2D JKR "
              "pull-off of the whole length, F R/(E* L^3) = -3 (pi w~^2/16)^(1/3) [-], "
              "ratio_force = BEM pull-off under force control over F2d, Richardson-"
              "extrapolated from the two finest grids [-], ratio_depth = the same under "
              "depth control on the finest grid (its grid sequence is not smooth) [-], "
              "ratio_*_nN = the same on the grid with N cells across b_c [-], "
              "d_tilde_off = depth at the depth-controlled jump-off d R/L^2 (finest grid) "
              "[-], mdr_ratio_* = the rule of Hess on the universal curve's MDR profile "
              "over F2d [-], mdr_err_* = mdr_ratio/ratio - 1 [-], grid_change_* = "
              "finest/next grid - 1 [-], b_min_over_bc = contact half-width at x = 0 at "
              "the force-controlled pull-off / b_c (finest grid) [-]",
        accuracy=f"measured grid error: force control, change between the two finest "
                 f"grids at most {np.abs(cols['grid_change_force']).max():.1e} (the "
                 f"extrapolation's error is smaller: grid_check); depth control (the force "
                 f"at the steep end of the curve, staircase-sensitive): at most "
                 f"{np.abs(cols['grid_change_depth']).max():.1e}; JKR sphere on the same "
                 f"BEM (exact 1): {sph_line}, force control extrapolated {sph_rich:.4f}; "
                 f"Kendall's punch (exact 1): {pun_line}",
        grid_check="; ".join(check_lines) or "none",
        straight_edge=f"flat strip punch (L = 40 b) at mid-length, line force at "
                      f"detachment over the exact 2D sqrt(2 pi E* w b): {strip_line}; "
                      f"2D JKR cylinder at the middle of a long parabolic strip (L = 40 "
                      f"b_c), pull-off per unit length over -3 (pi E* R w^2/16)^(1/3): "
                      f"{ls_line}, extrapolated {ls_rich:.4f}; F(b) per unit length "
                      f"against Barquins' law within {ls_law:.1e} over 0.8 <= b/b_c <= "
                      f"1.25 (n = {n_l[-1]}); with Pohrt & Popov's constant on every cell "
                      f"the same strip pulls off at {pp['force']:.3f} (n = 16)",
        long_roller_limit=f"per unit length at mid-length the 2D JKR law holds (the "
                          f"straight_edge line); the whole roller's ratio does not tend "
                          f"to 1: {', '.join(f'{r:.4f}' for r in cols['ratio_force'][:3])} "
                          f"at s = {', '.join(f'{v:g}' for v in small)}, falling as s "
                          "decreases (the contact unzips from its ends with the middle "
                          f"still {cols['b_min_over_bc'][0]:.2f} b_c wide: the energy a "
                          "long strip stores grows as ln(L/b)); no value is given below "
                          "the table",
        mdr_error=f"rule of Hess against the BEM over the table: force control "
                  f"{rng('mdr_err_force')}, depth control {rng('mdr_err_depth')}",
        grid=f"square cells, n = {' '.join(map(str, grids))} across b_c; quarter "
             f"0 <= x <= L/2, 0 <= y <= 2 b_c; {args.steps} depth steps from a pinned "
             f"contact of half-width 1.6 b_c, last step bisected 8 times",
        tolerance="1e-9 (CG displacement error on the contact set relative to the "
                  "largest prescribed displacement; 1e-3 while the set moves)",
        s_range=f"[{cols['s'].min():g}, {cols['s'].max():g}]",
        wall_time=wall_time_line(wall, results + oracles, "retractions and oracle runs",
                                 args.scheduler, args.workers),
        cpu_time=f"{sum(r.get('cpu', 0.0) for r in results + oracles):.0f} s in the "
                 f"tasks (the largest {max(r.get('cpu', 0.0) for r in results):.0f} s)",
    )
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "adhesion_cylinder.csv"
    write_table(path, meta, cols)
    if own_checkpoint:
        import shutil
        shutil.rmtree(args.checkpoint, ignore_errors=True)
    print(f"wrote {path}: {cols['s'].size} rows in {wall:.0f} s")
    for key in ("accuracy", "grid_check", "straight_edge", "long_roller_limit",
                "mdr_error"):
        print(f"  {key}: {meta[key]}")
    return 0
