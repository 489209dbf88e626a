"""A batch on a Dask cluster: ``linecontact calc FILE.csv --scheduler ADDRESS`` (or
``--workers N`` for a local cluster), the same for a subcommand (``linecontact bearing
FILE.csv --scheduler ...``), and :func:`linecontact.calc.frame.calc_frame` with a
client.

The batch reads the file and makes every whole-file check and every row's input
check in this process, exactly as without a cluster (:func:`~linecontact.calc.batch.
run_batch`); only the evaluation goes to the workers. The rows are split into parts of
about equal size (about :data:`RANGES_PER_WORKER` per worker, so that a slow part does
not hold the others up and the progress bar moves; :func:`split_rows`): a
subcommand's in consecutive ranges, calc's so that the rows of one contact stay
together (they are solved as one sweep, each load warm-started from its neighbour's).
Each part's cells, as the batch filled them from the options, and its rows' errors
travel to a worker, which reads them by the same rules, skips the rows already refused
and evaluates the others (:func:`_evaluate_rows`). What a row gets depends on its part
alone, so the parts' results put back in place (:func:`linecontact.calc.compute.
merge_results`, :meth:`linecontact.calc.command.CommandResults.merged`) are the serial
batch's, and the output is written by the same code: the same bytes.

Each task first checks that its worker runs the same linecontact code as this process
(:func:`linecontact.calc.cluster.linecontact_fingerprint`; a worker that joins later is
checked too): a worker with other code stops the batch in one line, since its rows
would differ. A lost scheduler stops it in one line too; nothing is written.
"""
from __future__ import annotations

import sys

from .cluster import ClusterError, connect, linecontact_fingerprint, quiet_client_logs

__all__ = ["evaluate_on_cluster", "split_rows", "RANGES_PER_WORKER", "WorkerMismatch"]

#: Parts of the rows per worker of the cluster (at least one row per part).
RANGES_PER_WORKER = 8


class WorkerMismatch(RuntimeError):
    """Raised by a task on a worker whose linecontact code differs from the client's."""


def _same(name):
    """A parameter's name in messages: the CSV column's (the batch's label)."""
    return name


def _evaluate_rows(table, cells, errors, model, specs, expected):
    """On a worker: the results of one part of the rows of `table`'s batch, from their
    cells (name -> list of str) and the client's errors of these rows (a row with one
    is not evaluated); what the batch's output does not need (the cases, the solution
    objects) stays here."""
    import argparse

    import numpy as np

    found = linecontact_fingerprint()
    if found != expected:
        try:
            from distributed import get_worker
            where = f"dask worker {get_worker().address}"
        except (ImportError, ValueError):
            where = "a dask worker"
        raise WorkerMismatch(f"{where} runs other linecontact code than this process "
                             f"(there: {found}; here: {expected}), so its rows would "
                             f"differ: install the same linecontact there and restart it")
    m = len(errors)
    cases, _, errs = table.parse(cells, m, _same)
    errs[:] = errors
    results = table.evaluate(cases, errs, argparse.Namespace(model=model), specs, None)
    results.cases = None
    if hasattr(results, "objects"):          # a subcommand's solution objects
        results.objects = [None] * m
    if hasattr(results, "sets"):             # calc: blocks are made; drop the rest
        results.label, results.features = None, []
        for s in results.sets:
            s["solution"] = np.full(m, None, dtype=object)
    return results


def evaluate_on_cluster(table, cells, errors, cases, *, model=None, specs=None,
                        scheduler=None, workers=None, connect_timeout=None,
                        client=None, progress=None, label=None):
    """The results of `table`'s batch, evaluated on a Dask cluster, equal to
    ``table.evaluate`` in this process (see the module docstring).

    Parameters
    ----------
    table : the batch's table (:data:`linecontact.calc.batch.CALC` or a Command)
    cells : dict
        Parameter name -> list of the n rows' cells (as the batch filled them).
    errors : list of str
        The rows' errors so far (updated in place, as by ``table.evaluate``).
    cases : Cases
        The whole batch's, as parsed here.
    model, specs
        ``--model`` as given and parsed (calc).
    scheduler : str, optional
        Address of a running dask scheduler; else a local cluster of `workers`.
    workers : int, optional
        Worker processes of the local cluster (default 2).
    connect_timeout : float, optional
        Seconds for `scheduler` to answer [s].
    client : distributed.Client, optional
        A client to use instead (a notebook's): neither opened nor closed here.
    progress : callable, optional
        Called with the number of rows done as ranges finish.
    label : callable, optional
        A parameter's name in messages (as for ``table.evaluate``).

    Raises
    ------
    ClusterError
        A bad address or no scheduler there (exit 2); a worker with other linecontact
        code, the scheduler lost, or a task failed for another reason (exit 1).
    """
    import contextlib

    saved = list(errors)
    opened = (contextlib.nullcontext(client) if client is not None else
              connect(scheduler, workers, connect_timeout))
    # with a remote scheduler every connection fault reaches the user as one line
    # (ClusterError): distributed's own logged tracebacks would bury it
    with quiet_client_logs(active=client is None and scheduler is not None), \
            opened as cl:
        try:
            nworkers = len(cl.scheduler_info().get("workers", {}))
        except Exception:  # noqa: BLE001 - the count only sizes the parts
            nworkers = 1
        rows = split_rows(table, cases, errors, max(1, nworkers) * RANGES_PER_WORKER)
        parts = _run_parts(cl, table, cells, errors, rows, model, specs, progress,
                           scheduler or "the client's scheduler")
    from .compute import Unmergeable

    try:
        return table.merge(parts, rows, errors, cases, label)
    except Unmergeable as exc:
        from . import render
        print(f"{render.PROG} {table.name}: note: the row ranges computed on the cluster "
              f"differ in what the whole batch decides ({exc}); the batch is computed "
              f"again in this process, so that the output is the serial one",
              file=sys.stderr)
        import argparse
        errors[:] = saved
        return table.evaluate(cases, errors, argparse.Namespace(model=model), specs,
                              progress)


def split_rows(table, cases, errors, k):
    """The rows of the batch in at most `k` parts of about equal size (arrays of row
    numbers, each ascending), for the workers: a subcommand's in consecutive ranges
    (each row is solved alone); calc's so that the rows of one contact stay in one
    part (:func:`linecontact.calc.compute.group_rows`: they are solved as one sweep),
    the contacts taken in the order of their first row."""
    import numpy as np

    n = len(errors)
    k = max(1, min(n, k))
    unit = table.groups(cases, errors)
    if unit is None:
        bounds = [n * j // k for j in range(k + 1)]
        return [np.arange(a, b) for a, b in zip(bounds[:-1], bounds[1:])]
    bad = unit < 0                          # a refused row: a unit of its own
    unit[bad] = unit.max(initial=-1) + 1 + np.arange(int(bad.sum()))
    _, first, inverse = np.unique(unit, return_index=True, return_inverse=True)
    inverse = np.ravel(inverse)
    sizes = np.bincount(inverse)
    order = np.argsort(first, kind="stable")
    start = np.empty_like(sizes)
    start[order] = np.cumsum(sizes[order]) - sizes[order]
    part = np.minimum(k - 1, start * k // n)[inverse]
    return [r for r in (np.flatnonzero(part == j) for j in range(k)) if r.size]


def _take(col, r):
    """The cells of rows `r` (ascending) of a column."""
    if r[-1] - r[0] + 1 == r.size:
        return col[int(r[0]):int(r[-1]) + 1]
    return [col[i] for i in r.tolist()]


def _run_parts(client, table, cells, errors, rows, model, specs, progress, where):
    """Submit the parts (row numbers `rows`), collect their results in order
    (progress as they finish); one-line ClusterErrors for the faults the user
    fixes."""
    from dask.distributed import as_completed

    n = len(errors)
    expected = linecontact_fingerprint()
    futures, done = [], 0
    try:
        for r in rows:
            futures.append(client.submit(
                _evaluate_rows, table, {name: _take(col, r) for name, col in
                                             cells.items()},
                [errors[i] for i in r.tolist()], model, specs, expected, pure=False))
        index = {f.key: j for j, f in enumerate(futures)}
        parts = [None] * len(futures)
        for fut in as_completed(futures):
            j = index[fut.key]
            try:
                parts[j] = fut.result()
            except WorkerMismatch as exc:
                client.cancel(futures)
                raise ClusterError(f"batch stopped, nothing written: {exc}",
                                   exit_code=1) from None
            done += rows[j].size
            if progress is not None:
                progress(done)
            fut.release()
        return parts
    except ClusterError:
        raise
    except Exception as exc:
        if getattr(client, "status", "running") != "running":
            raise ClusterError(f"lost the dask scheduler at {where} after {done} of {n} "
                               f"rows; nothing written: restart the scheduler and its "
                               f"workers and run the batch again", exit_code=1) from None
        client.cancel(futures)
        detail = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
        raise ClusterError(f"a task of the batch failed on the cluster after {done} of "
                           f"{n} rows, nothing written: {type(exc).__name__}"
                           + (f": {detail}" if detail else ""), exit_code=1) from None
