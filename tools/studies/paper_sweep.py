"""The BEM sweeps of the paper's study, one task per L/R, run by tools.studies.runner.

Each task presses a rigid cylinder of length L = L/R (R = E* = 1) into the half-space
in equal steps from first contact to d_max (tools.bem.cylinder.sweep with the flat-punch
stiffness) and returns the curves as plain arrays. The task key names L/R; the grid,
steps, d_max, tolerance and backend are part of the task, so a checkpoint saved with
other settings is not resumed (tools.studies.runner).
"""
from __future__ import annotations

import time

import numpy as np

from .runner import run_study


def sweep_task(task):
    """One L/R (in a worker process): the sweep as plain arrays, R = E* = 1."""
    from tools.bem.cylinder import sweep
    t0, c0 = time.perf_counter(), time.process_time()
    res = sweep(task["l_over_r"], n=task["n"], steps=task["steps"],
                d_max_over_r=task["d_max"], radius=1.0, estar=1.0, tol=task["tol"],
                stiffness="punch", backend=task["backend"], workers=1, progress=False,
                raise_on_failure=False)
    return dict(l_over_r=task["l_over_r"], depth=res.depth, force=res.force,
                stiffness=res.stiffness, area=res.area, iterations=res.iterations,
                error=res.error, converged=res.converged,
                wall_time=time.perf_counter() - t0, cpu_time=time.process_time() - c0,
                grid=res.grid.describe(), backend=res.settings["backend"])


def sweep_tasks(l_over_r, n, steps, d_max, tol, backend=None):
    """The task list of :func:`sweep_task`, one per L/R, sorted by L/R."""
    return [dict(key=f"L_over_R={float(q):g}", l_over_r=float(q), n=n, steps=int(steps),
                 d_max=float(d_max), tol=float(tol), backend=backend)
            for q in sorted(set(float(v) for v in l_over_r))]


def longest_first(tasks):
    """The tasks in the order to run them: the longest first, so that no long one is
    left for the end while the other workers idle (the longest-processing-time rule).
    A sweep's work grows away from L/R = 1 both ways (the contact's ends, or its
    length, take more cells and more iterations; recorded per L/R in the header of
    tables/bem_paper_curves.csv), so the order is by |ln(L/R)|, largest first."""
    return sorted(tasks, key=lambda t: -abs(np.log(t["l_over_r"])))


def run_sweeps(l_over_r, n, steps, d_max, tol, backend=None, **runner):
    """The BEM sweeps for every L/R through :func:`tools.studies.runner.run_study` (keyword
    options `runner`: scheduler, workers, checkpoint, resume, progress), submitted
    longest first (:func:`longest_first`); results sorted by L/R."""
    tasks = sweep_tasks(l_over_r, n, steps, d_max, tol, backend)
    results = run_study(sweep_task, longest_first(tasks), desc="paper study (L/R done)",
                        **runner)
    return sorted(results, key=lambda r: r["l_over_r"])
