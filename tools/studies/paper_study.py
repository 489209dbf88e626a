"""The paper's boundary-element study, rerun: alpha(L/R), beta(L/R) of Eq. 9 regenerated.

Li & Popov (2017), section 3 (docs/theory.md, section 'BEM'): for L/R = 0.1, 0.2, ...,
1.0 and 2, 3, ..., 20 (29 values) a rigid cylinder is pressed into the half-space in 100 equal
steps from first contact to d = 0.15 R on a 512 x 512 grid (tools.bem.cylinder.sweep, punch
stiffness). Each curve k(d) is turned into its MDR profile by extraction (docs/theory.md,
section 'MDR'; linecontact.mdr.mdr_profile_from_stiffness),

    x~ = k / (2 E* L),    g~ = d R / L^2                                      (Eq. 8)

and alpha, beta of Eq. 9, g~ = beta (alpha/x~ + 1) exp(-alpha/x~), are fitted to the
points by least squares. The paper does not say how it weighted the residuals, and
alpha and beta are strongly correlated, so several natural residuals are tried
(tools.studies.paper_fit.RESIDUALS), each fit is judged by what a user gets from it (the largest
relative error of F(d) and of k(d) of the fitted closed form, evaluated with the
runtime's linecontact.lipopov_force / lipopov_stiffness, against the BEM points), and
the residual with the smallest errors is shipped (``--residual``, default
tools.studies.paper_fit.SHIPPED_RESIDUAL).

The work is split by concern: this module is the command line; tools.studies.paper_sweep the
BEM tasks, run by tools.studies.runner (a Dask cluster: local by default, ``--scheduler
ADDRESS`` for an existing one); tools.studies.paper_fit the extraction and the fits (on the
runtime's closed forms, linecontact.lipopov); tools.studies.paper_tables the writers;
tools.studies.paper_compare the grid-convergence comparison of two runs.

Writes into ``--out`` (default ``tables/``):

``lipopov_regenerated.csv``
    L_over_R, alpha, beta, max_rel_err_F, max_rel_err_k, ... per L/R: a coefficient
    set that drops into the runtime as ``coefficients="regenerated"``.
``bem_paper_curves.csv``
    The raw BEM curves, dimensionless: d, F, k, contact area per L/R and step.
``paper_published_errors.csv``
    The F and k errors of the published Table 1 coefficients (and of Eq. 11's
    constants, L/R >= 5) against the same BEM points.
``paper_residual_comparison.csv``
    alpha, beta and F, k errors of every residual choice at every L/R.

Run time: the full 512 x 512 study is 29 sweeps of 100 contact + 100 punch solves,
14 000 - 23 000 operator applications per L/R: 222 s of CPU in all and 3.6 min wall
with 2 worker processes on the shared 2-core machine under a load of 2-5
(tools/benchmarks/results/paper_study.txt, ``python -m tools.build_tables paper
--out TMP``; the shipped tables' own run, with older code,
took 25.6 min: tables/README.md; each run's timings are in its table header). Each
finished L/R is saved in the checkpoint folder (default OUT/partial_paper/) until the
tables are written; ``--resume`` picks them up after an interruption. One L/R on a
coarse grid takes seconds::

    python -m tools.build_tables paper --l-over-r 5 --n 64 --steps 20 --out /tmp/check

``--from-curves FILE`` refits from a saved bem_paper_curves.csv without running the BEM.
Grid convergence (F(d) of two runs on different grids)::

    python -m tools.studies.paper_compare RUN_DIR_A RUN_DIR_B
"""
from __future__ import annotations

import argparse
import os
import platform
import shutil
import sys
import time
from pathlib import Path

import numpy as np

from .paper_fit import (RESIDUALS, SHIPPED_RESIDUAL, fit_all, points_from_curves,
                        residual_report)
from .paper_sweep import run_sweeps
from .paper_tables import CURVES, curves_from_results, write_curves, write_outputs
from .runner import DEFAULT_WORKERS, add_runner_arguments, wall_time_line

PAPER_L_OVER_R = tuple([round(0.1 * i, 1) for i in range(1, 11)] + list(range(2, 21)))


def _float_list(text):
    return [float(v) for v in text.replace(",", " ").split()]


def _grid(text):
    parts = [int(v) for v in text.lower().replace("x", ",").split(",") if v.strip()]
    if len(parts) not in (1, 2):
        raise argparse.ArgumentTypeError(f"--n {text!r}: give N or NX,NY")
    return parts[0] if len(parts) == 1 else tuple(parts)


def add_arguments(parser):
    """Options of ``python -m tools.build_tables paper``."""
    parser.add_argument("--l-over-r", type=_float_list, default=list(PAPER_L_OVER_R),
                        metavar="LIST",
                        help="L/R values, comma or space separated (default: the paper's "
                             "29, 0.1..1.0 step 0.1 and 2..20 step 1)")
    parser.add_argument("--n", type=_grid, default=512, metavar="N|NX,NY",
                        help="full grid, cells along the length and across (default 512)")
    parser.add_argument("--steps", type=int, default=100,
                        help="equal depth steps to --d-max (default 100)")
    parser.add_argument("--d-max", type=float, default=0.15, metavar="D_OVER_R",
                        help="largest depth over radius (default 0.15)")
    parser.add_argument("--tol", type=float, default=1e-6,
                        help="contact-solver tolerance, gap error / d (default 1e-6)")
    parser.add_argument("--residual", choices=list(RESIDUALS), default=SHIPPED_RESIDUAL,
                        help=f"fit residual shipped in the table (default "
                             f"{SHIPPED_RESIDUAL}); all are compared")
    parser.add_argument("--out", type=Path, default=None,
                        help="output folder (default: the repository's tables/)")
    parser.add_argument("--from-curves", type=Path, default=None, metavar="CSV",
                        help="refit from a saved bem_paper_curves.csv; no BEM run")
    parser.add_argument("--backend", choices=("scipy", "pyfftw"), default=None,
                        help="FFT backend (default pyfftw when installed)")
    add_runner_arguments(parser)


def _default_out():
    return Path(__file__).resolve().parents[2] / "tables"


def _refit_meta(args, table):
    """command line and run metadata of a refit from saved curves: the BEM run's
    settings, command and version are kept beside the refit's own."""
    keep = ("grid", "tolerance", "steps", "d_max_over_R", "wall_time", "machine")
    meta = {k: table.meta[k] for k in keep if k in table.meta}
    meta["bem_version"] = (table.meta.get("bem_version") or table.meta.get("code_version")
                           or table.meta.get("version", ""))
    command = f"{table.meta.get('generated_by', '')}; refitted by: {args.command_line}"
    return command, meta


def _run_meta(args, results, wall):
    nx, ny = (args.n, args.n) if np.isscalar(args.n) else args.n
    try:
        load = " ".join(f"{v:.2f}" for v in os.getloadavg())
    except OSError:
        load = "n/a"
    cpu = sum(r["cpu_time"] for r in results)
    per = "; ".join(f"L/R {r['l_over_r']:g}: {r['wall_time']:.1f} s wall, "
                    f"{r['cpu_time']:.1f} s CPU, {int(r['iterations'].sum())} op"
                    for r in results)
    n = None if args.scheduler is not None else (args.workers or DEFAULT_WORKERS)
    # one backend in every row (the runner refuses workers with another), but results
    # resumed from an earlier run may come from another: then each is named
    by_backend = {}
    for r in results:
        by_backend.setdefault(r["backend"], []).append(f"{r['l_over_r']:g}")
    backend = (next(iter(by_backend)) if len(by_backend) == 1 else
               "; ".join(f"{b} at L/R = {', '.join(q)}" for b, q in by_backend.items()))
    idle = (f" (on an idle machine about CPU / {n} = {cpu / n:.0f} s)" if n else "")
    return dict(
        grid=f"{nx} x {ny} cells over |x| <= L/2, |y| <= sqrt(2 R d_max) "
             f"({results[0]['grid']} at L/R = {results[0]['l_over_r']:g}); FFT "
             f"backend {backend}",
        steps=f"{args.steps} equal depth steps to d_max",
        d_max_over_R=f"{args.d_max:g}",
        tolerance=f"contact solver: largest gap error <= {args.tol:g} d; punch: "
                  f"displacement error <= {args.tol:g}",
        wall_time=wall_time_line(wall, results, "L/R", args.scheduler, args.workers)
                  + f"; 1 FFT thread per task; CPU time of the sweeps {cpu:.1f} s{idle}; "
                  f"load average after the run {load}; per L/R: {per}",
        machine=f"{platform.machine()}, {os.cpu_count()} CPUs, Python "
                f"{platform.python_version()}",
    )


def run(args):
    """``python -m tools.build_tables paper``: run (or reload), fit, write."""
    from linecontact.tables import read_table
    out = Path(args.out) if args.out is not None else _default_out()
    t0 = time.perf_counter()
    wall = None
    if args.from_curves is not None:
        src = Path(args.from_curves)
        table = read_table(src.stem, directory=src.parent)
        cols = table.columns
        command, meta_run = _refit_meta(args, table)
        curves = cols if src.resolve() != (out / f"{CURVES}.csv").resolve() else None
    else:
        checkpoint = args.checkpoint or out / "partial_paper"
        results = run_sweeps(args.l_over_r, args.n, args.steps, args.d_max, args.tol,
                             backend=args.backend, scheduler=args.scheduler,
                             workers=args.workers, checkpoint=checkpoint,
                             resume=args.resume, progress=not args.no_progress,
                             connect_timeout=args.connect_timeout)
        wall = time.perf_counter() - t0
        cols = curves = curves_from_results(results)
        command, meta_run = args.command_line, _run_meta(args, results, wall)
        if not all(np.all(r["converged"]) for r in results):
            bad = [r["l_over_r"] for r in results if not np.all(r["converged"])]
            print(f"warning: unconverged steps at L/R = {bad} (left out)", file=sys.stderr)
    out.mkdir(parents=True, exist_ok=True)
    if curves is not None:   # first, so that a failing fit cannot lose the BEM run
        write_curves(out, curves, command, meta_run)
        if args.from_curves is None and args.checkpoint is None:
            shutil.rmtree(checkpoint, ignore_errors=True)   # all kept in the curves
    points = points_from_curves(cols)
    fits = fit_all(points)
    closest, user = write_outputs(out, points, fits, args.residual, command, meta_run)
    for line in residual_report(fits):
        print(line)
    print(f"closest to Table 1: {closest}; shipped: {args.residual}")
    if wall is not None:
        print(f"BEM {meta_run['wall_time'].split(';')[0]}")
    print(f"wrote {out}")
    return 0
