"""Benchmark (not a test): the paper's finite-cylinder sweep, ContactMechanics vs ours.

Solves the same displacement-controlled sweep twice in one run -- with
ContactMechanics (FreeFFTElasticHalfSpace + constrained_conjugate_gradients, its
free, non-periodic half-space) and with :func:`tools.bem.cylinder.sweep` -- on the same
grid, the same depths and the same physical tolerance, and prints wall time and CPU
time of each, their ratio, the largest relative force difference over the steps and
the iteration counts. Issue 3, item 6; target: ours >= 3x faster per sweep, forces
within 0.1 %.

The problem: rigid cylinder, radius R, length L (axis along x), pressed by depth d
into a half-space of effective modulus E*. nx x ny cells cover |x| <= L/2 and
|y| <= Y = sqrt(2 R d_max); cell centres x_i = -L/2 + (i + 1/2) dx,
y_j = -Y + (j + 1/2) dy; initial gap h(y) = y^2 / (2R); d = d_max k / steps,
k = 1..steps.

How ContactMechanics (1.8.x) is called, and why (read from its source):

* ``FreeFFTElasticHalfSpace((nx, ny), young=E*, physical_sizes=(L, 2Y))``. ``young``
  is the contact modulus E* (its docstring: "Equiv. Young's modulus E'"; the kernel
  is multiplied by 1/(pi young), no (1 - nu^2)). Internally 2nx x 2ny (zero padding).
  Its kernel is Love's / Johnson Eq. 3.25 for uniform pressure on a dx x dy
  rectangle, in the log form, evaluated at cell-centre offsets in wrap-around order:
  the same influence coefficients as ours; this script measures the difference.
* Heights are those of the rigid indenter, positive up: h = -y^2/(2R) (apex at 0);
  ``offset = d`` pushes it into the substrate. The constraint is u >= h + offset,
  u = surface displacement positive into the body; gap = u - h - offset.
* Solver: ``constrained_conjugate_gradients`` (Polonsky & Keer 1999) at fixed
  ``offset`` (displacement control). Its forces are pixel forces, negative =
  compressive internally; ``result.jac`` is the (positive) force per cell, so
  F = sum(result.jac).
* Convergence, all of which must hold (their meaning -> our setting):
    - ``pentol`` [length]: rms gap on the contact set, largest penetration on the
      contact set, and the largest change of displacement in the last iteration,
      each < pentol.  -> pentol = tol * d, our criterion (largest |gap| on the
      contact set and largest penetration outside it <= tol * d).
    - ``forcetol`` [force per cell]: largest tensile cell force produced by the CG
      step before it is clipped, and largest force in the padding. Default 1e-5,
      an absolute force as large as a whole cell's force here (1e-6 to 1e-4 E* R^2).
      -> forcetol = tol * d * dx dy / K00, K00 = self-influence coefficient: a
      leftover tensile force moves its own cell by less than the gap tolerance.
    - ``thermotol`` [relative]: change of the total force between iterations.
      -> thermotol = tol (1e-6 = their default).
  CM does not bound the largest separation on its contact set (only the rms), so
  the script evaluates our criterion on ContactMechanics' answer and prints it
  (``gap err``): typically 1-3 x tol, i.e. the mapping is generous to CM.
* Warm start (``--cm-warm forces``, default): ``initial_forces`` = the previous
  step's (padded) force field; ``none`` starts every step from zero.

Threads: ContactMechanics' muGrid FFT runs on one thread, so ours also runs on one
(``--ours-workers 1``, default; ``0`` = its own default, all cores). Ours runs twice:
F only (``stiffness="difference"``: no extra solve, like for like) and as the study
runs it (plus the flat-punch stiffness solve at every step).

Run from the repository root, in an environment that has contactmechanics
(``pip install contactmechanics`` -- only for this benchmark)::

    python -m tools.benchmarks contactmechanics     # 128 x 128, the runner
    python tools/benchmarks/contactmechanics.py             # 512 x 512, L/R = 5

The report goes to tools/benchmarks/results/contactmechanics.txt (the current record,
whichever grid; ``--no-save`` to keep it).
"""
from __future__ import annotations

import argparse
import inspect
import io
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

RESULTS = Path(__file__).resolve().parent / "results"


# --------------------------------------------------------------------------- problem
def grid(l_over_r, nx, ny, radius, d_max_over_r):
    length = l_over_r * radius
    d_max = d_max_over_r * radius
    half_width = np.sqrt(2.0 * radius * d_max)
    dx, dy = length / nx, 2.0 * half_width / ny
    x = -0.5 * length + (np.arange(nx) + 0.5) * dx
    y = -half_width + (np.arange(ny) + 0.5) * dy
    return length, half_width, dx, dy, x, y


def depths(steps, d_max_over_r, radius):
    return d_max_over_r * radius * np.arange(1, steps + 1) / steps


# ----------------------------------------------------------------- ContactMechanics
def run_contactmechanics(args, nx, ny):
    from ContactMechanics import FreeFFTElasticHalfSpace
    from ContactMechanics.Optimization.ConstrainedConjugateGradients import (
        constrained_conjugate_gradients)
    from SurfaceTopography import Topography

    R, E = args.radius, args.estar
    length, half_width, dx, dy, x, y = grid(args.l_over_r, nx, ny, R, args.d_max_over_r)
    ds = depths(args.steps, args.d_max_over_r, R)

    t_wall, t_cpu = time.perf_counter(), time.process_time()
    substrate = FreeFFTElasticHalfSpace((nx, ny), E, (length, 2.0 * half_width))
    heights = np.broadcast_to(-y ** 2 / (2.0 * R), (nx, ny)).copy()   # indenter, up
    topography = Topography(heights, physical_sizes=(length, 2.0 * half_width))
    area = dx * dy
    # self-influence coefficient K00 [m/Pa] from the substrate itself
    unit = np.zeros(substrate.nb_domain_grid_pts)
    unit[0, 0] = -area                                  # unit compressive pressure
    k00 = substrate.evaluate_disp(unit)[0, 0]

    force = np.empty(args.steps)
    cells = np.empty(args.steps, dtype=int)
    iters = np.empty(args.steps, dtype=int)
    nfev = np.empty(args.steps, dtype=int)
    gap_err = np.empty(args.steps)
    f_init = None
    for k, d in enumerate(ds):
        res = constrained_conjugate_gradients(
            substrate, topography, offset=d,
            pentol=args.tol * d,
            forcetol=args.tol * d * area / k00,
            thermotol=args.tol,
            initial_forces=f_init, maxiter=args.maxiter)
        if not res.success:
            raise RuntimeError(f"ContactMechanics did not converge at step {k + 1} "
                               f"(d = {d:g}): {res.message}")
        p = res.jac                                     # force per cell, >= 0
        force[k] = p.sum()
        contact = p > 0
        cells[k] = contact.sum()
        iters[k] = res.nit
        nfev[k] = res.nfev
        # our criterion (tools.bem.solver.solve_contact) evaluated on their answer:
        # largest |gap| on the contact set and largest penetration outside it, / d
        gap = res.x[:nx, :ny] - heights - d        # res.x = K * res.jac, same iterate
        gap_err[k] = max(np.abs(gap[contact]).max(initial=0.0),
                         -gap[~contact].min(initial=0.0)) / d
        if args.cm_warm == "forces":
            f_init = np.zeros(substrate.nb_domain_grid_pts)
            f_init[:nx, :ny] = -p
        if args.progress:
            print(f"\r  ContactMechanics step {k + 1}/{args.steps}  it {res.nit}",
                  end="", file=sys.stderr, flush=True)
    if args.progress:
        print(file=sys.stderr)
    wall = time.perf_counter() - t_wall
    cpu = time.process_time() - t_cpu
    return dict(depth=ds, force=force, cells=cells, iterations=iters, nfev=nfev,
                wall=wall, cpu=cpu, gap_err=gap_err, substrate=substrate)


# ---------------------------------------------------------------------------- ours
def run_ours(args, nx, ny, stiffness):
    from tools.bem.cylinder import sweep

    params = inspect.signature(sweep).parameters
    kwargs = dict(n=(nx, ny), steps=args.steps, d_max_over_r=args.d_max_over_r,
                  radius=args.radius, estar=args.estar, tol=args.tol,
                  progress=args.progress, stiffness=stiffness,
                  workers=args.ours_workers or None, backend=args.ours_backend)
    kwargs = {k: v for k, v in kwargs.items() if k in params}
    t_wall, t_cpu = time.perf_counter(), time.process_time()
    res = sweep(args.l_over_r, **kwargs)
    wall = time.perf_counter() - t_wall
    cpu = time.process_time() - t_cpu
    area = np.asarray(res.area, dtype=float)
    _, _, dx, dy, _, _ = grid(args.l_over_r, nx, ny, args.radius, args.d_max_over_r)
    conv = np.asarray(getattr(res, "converged", np.ones(args.steps, bool)))
    return dict(depth=np.asarray(res.depth, float), force=np.asarray(res.force, float),
                cells=np.rint(area / (dx * dy)).astype(int),
                iterations=np.asarray(res.iterations), nfev=np.asarray(res.iterations),
                wall=wall, cpu=cpu, converged=conv,
                gap_err=np.asarray(getattr(res, "error", np.full(args.steps, np.nan))),
                reported_wall=getattr(res, "wall_time", np.nan),
                backend=getattr(res, "settings", {}).get("backend", "?"),
                res=res)


def kernel_difference(substrate, nx, ny, dx, dy, estar):
    """Largest relative difference between ContactMechanics' kernel and ours."""
    from tools.bem.influence import kernel_offsets

    unit = np.zeros(substrate.nb_domain_grid_pts)
    unit[0, 0] = -dx * dy
    theirs = substrate.evaluate_disp(unit)[:nx, :ny]   # offsets 0..n-1 >= 0
    ours = kernel_offsets(nx, ny, dx, dy, estar)[:nx, :ny]
    rel = np.abs(theirs / ours - 1.0)
    i, j = np.unravel_index(np.argmax(rel), rel.shape)
    return rel.max(), (int(i), int(j)), np.abs(theirs - ours).max() / ours[0, 0]


# ---------------------------------------------------------------------------- main
def versions():
    out = {"python": platform.python_version()}
    for mod in ("numpy", "scipy", "ContactMechanics", "SurfaceTopography", "muGrid",
                "NuMPI", "pyfftw"):
        try:
            m = __import__(mod)
            out[mod] = getattr(m, "__version__", "?")
        except ImportError:
            out[mod] = "not installed"
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--l-over-r", type=float, default=5.0)
    ap.add_argument("--n", type=str, default="512",
                    help="cells per side, or NX,NY (default 512)")
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--tol", type=float, default=1e-6,
                    help="largest |gap| on the contact set / d (default 1e-6)")
    ap.add_argument("--d-max-over-r", type=float, default=0.15)
    ap.add_argument("--radius", type=float, default=1.0)
    ap.add_argument("--estar", type=float, default=1.0)
    ap.add_argument("--cm-warm", choices=("forces", "none"), default="forces",
                    help="ContactMechanics warm start between steps (default forces)")
    ap.add_argument("--maxiter", type=int, default=100000)
    ap.add_argument("--skip-ours", action="store_true",
                    help="run ContactMechanics only (no comparison)")
    ap.add_argument("--skip-punch", action="store_true",
                    help="skip the second run of ours that adds the punch stiffness")
    ap.add_argument("--ours-workers", type=int, default=1,
                    help="FFT threads for ours (default 1, like ContactMechanics; "
                         "0 = its own default, all cores)")
    ap.add_argument("--ours-backend", choices=("scipy", "pyfftw"), default=None,
                    help="FFT backend for ours (default: its own, pyfftw when installed)")
    ap.add_argument("--no-save", action="store_true")
    ap.add_argument("--progress", action="store_true")
    args = ap.parse_args(argv)
    nx, ny = (int(v) for v in args.n.split(",")) if "," in args.n else (int(args.n),) * 2

    out = io.StringIO()

    def say(*a):
        print(*a)
        print(*a, file=out)

    length, half_width, dx, dy, _, _ = grid(args.l_over_r, nx, ny, args.radius,
                                            args.d_max_over_r)
    say("# finite-cylinder sweep: ContactMechanics vs tools.bem.cylinder.sweep")
    say(f"# {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; command: "
        f"python tools/benchmarks/contactmechanics.py "
        + " ".join(argv if argv is not None else sys.argv[1:]))
    say(f"# L/R = {args.l_over_r:g}, grid {nx} x {ny} (dx = {dx:.4g} R, dy = {dy:.4g} R),"
        f" {args.steps} steps to d = {args.d_max_over_r:g} R, tol = {args.tol:g},"
        f" CM warm start: {args.cm_warm}")
    say(f"# machine: {platform.machine()}, {os.cpu_count()} cores, "
        f"{platform.platform()}; load average at start "
        + " ".join(f"{v:.2f}" for v in os.getloadavg()))
    say("# versions: " + ", ".join(f"{k} {v}" for k, v in versions().items()))

    cm = run_contactmechanics(args, nx, ny)
    runs = [("ContactMechanics", cm)]
    if not args.skip_ours:
        # like for like: F(d) only (k by differences of F, no extra solve) ...
        ours = run_ours(args, nx, ny, "difference")
        runs.append(("ours (F only)", ours))
        # ... and as the study runs it: plus the flat-punch stiffness at every step
        if not args.skip_punch:
            runs.append(("ours (F + punch k)", run_ours(args, nx, ny, "punch")))
        from tools.bem.halfspace import default_workers
        say(f"# ours: FFT backend {ours['backend']}, "
            f"{args.ours_workers or default_workers()} FFT threads; ContactMechanics: "
            f"muGrid FFTEngine, one thread")
        kmax, kat, kabs = kernel_difference(cm["substrate"], nx, ny, dx, dy, args.estar)
        say(f"# kernels: max |K_CM / K_ours - 1| = {kmax:.2e} at offset {kat};"
            f" max |K_CM - K_ours| / K_00 = {kabs:.2e}")
        for name, r in runs[1:]:
            if not np.allclose(r["depth"], cm["depth"], rtol=1e-12, atol=0):
                raise RuntimeError(f"{name}: the two sweeps used different depths")

    say("")
    say("# wall/cpu: whole sweep incl. set-up; 'applications' = half-space operator "
        "evaluations (CM: nfev, ours: iterations)")
    say("# gap err: our criterion max(|gap| on contact, penetration outside) / d, "
        "largest over steps")
    say(f"{'solver':20s} {'wall [s]':>9s} {'cpu [s]':>9s} {'CM/this':>7s} "
        f"{'iter tot':>8s} {'appl tot':>8s} {'appl/step':>9s} {'gap err':>8s}")
    for name, r in runs:
        it = r["iterations"]
        say(f"{name:20s} {r['wall']:9.2f} {r['cpu']:9.2f} {cm['wall'] / r['wall']:7.2f} "
            f"{it.sum():8d} {r['nfev'].sum():8d} {r['nfev'].mean():9.1f} "
            f"{np.nanmax(r['gap_err']):8.2e}")
    if len(runs) > 1:
        ours = runs[1][1]
        for name, r in runs[1:]:
            if not np.all(r["converged"]):
                say(f"# WARNING: {name} did not converge at steps "
                    f"{np.flatnonzero(~r['converged']) + 1}")
        rel = np.abs(cm["force"] / ours["force"] - 1.0)
        k = int(np.argmax(rel))
        k2 = int(np.argmax(rel[1:])) + 1 if args.steps > 1 else 0
        dcells = cm["cells"] - ours["cells"]
        say("")
        say(f"wall-time ratio CM / ours (F only)  : {cm['wall'] / ours['wall']:.2f}"
            f"   (cpu-time ratio {cm['cpu'] / ours['cpu']:.2f}; target >= 3)")
        if len(runs) > 2:
            r = runs[2][1]
            say(f"wall-time ratio CM / ours (F + k)   : {cm['wall'] / r['wall']:.2f}"
                f"   (cpu-time ratio {cm['cpu'] / r['cpu']:.2f})")
            say(f"forces of the two runs of ours agree to "
                f"{np.abs(r['force'] / ours['force'] - 1).max():.1e}")
        say(f"max |F_CM / F_ours - 1|, all steps   : {rel[k]:.2e} at step {k + 1}"
            f" (d = {cm['depth'][k] / args.radius:.4g} R)   (target <= 1e-3)")
        if args.steps > 1:
            say(f"max |F_CM / F_ours - 1|, steps 2..{args.steps:<4d}: {rel[k2]:.2e}"
                f" at step {k2 + 1}")
        say(f"contact cells at step 1: CM {cm['cells'][0]}, ours {ours['cells'][0]}"
            f" (of {nx * ny}; {cm['cells'][0] / nx:.1f} across the width);"
            f" steps whose contact sets differ in size: {np.count_nonzero(dcells)},"
            f" by at most {np.abs(dcells).max()} cells")

    say("")
    say("# per step (ours = F-only run)")
    head = f"{'step':>4s} {'d/R':>8s} {'F_CM/(E* R^2)':>14s} {'cells_CM':>8s} {'appl_CM':>7s}"
    if len(runs) > 1:
        head += (f" {'F_ours/(E* R^2)':>15s} {'cells_ours':>10s} {'appl_ours':>9s}"
                 f" {'rel diff':>9s}")
    say(head)
    scale = args.estar * args.radius ** 2
    for k in range(args.steps):
        line = (f"{k + 1:4d} {cm['depth'][k] / args.radius:8.5f} "
                f"{cm['force'][k] / scale:14.8e} {cm['cells'][k]:8d} {cm['nfev'][k]:7d}")
        if len(runs) > 1:
            line += (f" {ours['force'][k] / scale:15.8e} {ours['cells'][k]:10d}"
                     f" {ours['nfev'][k]:9d} {rel[k]:9.2e}")
        say(line)

    if not args.no_save:
        RESULTS.mkdir(exist_ok=True)
        name = "contactmechanics.txt"         # the one current record (grid in its header)
        (RESULTS / name).write_text(out.getvalue())
        print(f"# saved {RESULTS / name}")


if __name__ == "__main__":
    main()
