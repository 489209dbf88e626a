"""The one study runner: every BEM study (universal curve, the paper's rerun, and those
to come) runs its tasks through :func:`run_study`, and every table it writes gets its
header from :func:`table_meta`.

Tasks go to a ``dask.distributed`` client:

- by default a ``LocalCluster`` on this machine, ``--workers`` worker processes (default
  2) with one thread each, so that one task = one core (the BEM tasks ask their FFT
  backend for one thread too);
- with ``--scheduler ADDRESS`` (e.g. ``tcp://host:8786``) an existing cluster started
  with ``dask scheduler`` and ``dask worker ADDRESS --nthreads 1`` on each machine
  (README.md, "Running a study on a cluster"). The workers must be able to import
  ``tools`` and ``linecontact``: start them from the repository root or put it on their
  ``PYTHONPATH``.

Each task is a picklable dict with a unique ``"key"`` (str). As results arrive, the
client (this process, never a worker) saves each one in the checkpoint folder as
``<key>.pkl`` together with the task that produced it; ``resume=True`` then returns the
saved result of every task whose key *and* settings match and runs only the rest, so an
interrupted long study loses at most the tasks that were running.

Example (a study is any module-level function of one task)::

    from tools.studies.runner import run_study
    results = run_study(solve, [{"key": "L5", "l_over_r": 5.0}, ...],
                        checkpoint="out/partial", resume=True, desc="paper study")
"""
from __future__ import annotations

import datetime
import hashlib
import os
import pickle
import re
import subprocess
import sys
from pathlib import Path

__all__ = ["add_runner_arguments", "run_study", "run_study_from_args", "table_meta",
           "wall_time_line", "code_version", "DEFAULT_WORKERS"]

#: Worker processes of the default LocalCluster (the 2 cores of the reference machine).
DEFAULT_WORKERS = 2


def code_version():
    """'linecontact X, git DESCRIBE' of the checkout that runs this: the ``version``
    line of every table the tools write (one meaning in every table)."""
    import linecontact
    try:
        described = subprocess.run(
            ["git", "describe", "--always", "--dirty", "--tags"],
            cwd=Path(__file__).resolve().parent, capture_output=True, text=True,
            timeout=10).stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        described = "unknown"
    return f"linecontact {linecontact.__version__}, git {described}"


def table_meta(command_line, **fields):
    """The metadata header of a table written by the tools.

    `fields` (title, source, units, accuracy, grid, ...) in the order given, then
    ``generated_by`` = `command_line` (the command that regenerates the table), ``date``
    (today, ISO) and ``version`` (:func:`code_version`). A field of the same name in
    `fields` is overridden, so no table can carry its own meaning of "version".
    """
    meta = {k: v for k, v in fields.items()
            if k not in ("generated_by", "date", "version")}
    meta["generated_by"] = command_line
    meta["date"] = datetime.date.today().isoformat()
    meta["version"] = code_version()
    return meta


def add_runner_arguments(parser):
    """Add ``--scheduler``, ``--workers``, ``--checkpoint``, ``--resume``,
    ``--no-progress`` to an argparse parser (read back by :func:`run_study_from_args`)."""
    g = parser.add_argument_group("study runner (dask.distributed)")
    g.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="address of a running dask scheduler, e.g. tcp://host:8786 "
                        "(default: a local cluster on this machine)")
    g.add_argument("--workers", type=int, default=None, metavar="N",
                   help=f"worker processes of the local cluster, one thread each "
                        f"(default {DEFAULT_WORKERS}; ignored with --scheduler)")
    g.add_argument("--checkpoint", type=Path, default=None, metavar="DIR",
                   help="folder for the per-task checkpoint files (default: the "
                        "study's own where it has one, see its help; else none)")
    g.add_argument("--resume", action="store_true",
                   help="reuse the results saved in the checkpoint folder by an "
                        "interrupted run with the same task settings (an error "
                        "without a checkpoint folder)")
    g.add_argument("--no-progress", action="store_true", help="no progress bar")
    return parser


def _file_of(folder, key):
    """Checkpoint file of `key`: a readable, filesystem-safe stem plus a short hash, so
    that distinct keys never share a file."""
    safe = re.sub(r"[^A-Za-z0-9._=+-]", "_", key)[:80]
    digest = hashlib.sha1(key.encode()).hexdigest()[:8]
    return Path(folder) / f"{safe}-{digest}.pkl"


def _load(folder, task):
    """The saved result of `task`, or None when absent, unreadable or from a task with
    other settings."""
    path = _file_of(folder, task["key"])
    try:
        with open(path, "rb") as fh:
            saved = pickle.load(fh)
    except (OSError, EOFError, pickle.UnpicklingError, AttributeError, ImportError):
        return None
    if not isinstance(saved, dict) or repr(saved.get("task")) != repr(task):
        return None
    return saved


def _save(folder, task, result):
    """Write the checkpoint of one task atomically (a crash never leaves half a file)."""
    path = _file_of(folder, task["key"])
    tmp = path.with_suffix(".tmp")
    with open(tmp, "wb") as fh:
        pickle.dump({"task": task, "result": result}, fh, protocol=pickle.HIGHEST_PROTOCOL)
    os.replace(tmp, path)


def _client(scheduler, workers):
    from dask.distributed import Client, LocalCluster
    if scheduler:
        return Client(scheduler, timeout="60s"), None
    cluster = LocalCluster(n_workers=int(workers or DEFAULT_WORKERS),
                           threads_per_worker=1, processes=True,
                           dashboard_address=":0")   # a free port: never clashes
    return Client(cluster), cluster


def run_study(func, tasks, *, scheduler=None, workers=None, checkpoint=None,
              resume=False, progress=True, desc=""):
    """Run ``func(task)`` for every task on a Dask cluster; the results in task order.

    Parameters
    ----------
    func : callable
        A picklable module-level function of one task.
    tasks : list of dict
        Picklable dicts, each with a unique ``"key"`` (str).
    scheduler : str, optional
        Address of a running dask scheduler; default a ``LocalCluster`` of `workers`
        processes with one thread each.
    workers : int, optional
        Worker processes of the local cluster (default :data:`DEFAULT_WORKERS`).
    checkpoint : path, optional
        Folder in which each result is saved as it arrives (``<key>-<hash>.pkl``).
    resume : bool
        Return the saved results of tasks found in `checkpoint` with the same key and
        settings instead of running them again.
    progress : bool
        A tqdm progress bar on stderr.
    desc : str
        Label of the progress bar.

    Returns
    -------
    list
        ``func(task)`` for every task, in the order of `tasks`. Results taken from the
        checkpoint are the saved objects (dicts get ``"resumed": True``).

    Raises
    ------
    ValueError
        Keys missing, not str, or repeated; `resume` without a `checkpoint` folder
        (there would be nothing to resume from, and every task would run again).
    Exception
        The first exception raised by a task; the results finished before it stay in
        the checkpoint folder.
    """
    tasks = list(tasks)
    keys = [t.get("key") if isinstance(t, dict) else None for t in tasks]
    if not all(isinstance(k, str) and k for k in keys):
        raise ValueError("every task must be a dict with a non-empty str 'key'")
    if len(set(keys)) != len(keys):
        dup = sorted({k for k in keys if keys.count(k) > 1})
        raise ValueError(f"task keys must be unique; repeated: {', '.join(dup)}")
    if resume and checkpoint is None:
        raise ValueError("resume = True needs the checkpoint folder of the earlier run "
                         "(--checkpoint DIR); none was given")
    done = {}
    if checkpoint is not None:
        Path(checkpoint).mkdir(parents=True, exist_ok=True)
        if resume:
            for t in tasks:
                saved = _load(checkpoint, t)
                if saved is not None:
                    result = saved["result"]
                    if isinstance(result, dict):
                        result["resumed"] = True
                    done[t["key"]] = result
    todo = [t for t in tasks if t["key"] not in done]
    bar = None
    if progress:
        from tqdm import tqdm
        bar = tqdm(total=len(tasks), initial=len(done), desc=desc or "study",
                   unit="task", file=sys.stderr)
    try:
        if todo:
            _run_on_dask(func, todo, scheduler, workers, checkpoint, done, bar)
    finally:
        if bar is not None:
            bar.close()
    return [done[k] for k in keys]


def _run_on_dask(func, todo, scheduler, workers, checkpoint, done, bar):
    from dask.distributed import as_completed
    client, cluster = _client(scheduler, workers)
    try:
        futures = client.map(func, todo, pure=False)
        task_of = {f.key: t for f, t in zip(futures, todo)}
        for fut in as_completed(futures):
            task = task_of[fut.key]
            try:
                result = fut.result()
            except BaseException:
                client.cancel(futures)
                raise
            done[task["key"]] = result
            if checkpoint is not None:
                _save(checkpoint, task, result)
            if bar is not None:
                bar.update(1)
                bar.set_postfix_str(f"last {task['key']}")
            fut.release()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def wall_time_line(wall, results, what, scheduler=None, workers=None):
    """The ``wall_time`` header line of a study's table, the same in every table:
    ``'W s for N WHAT with P processes (local dask cluster)'`` or ``'... on the dask
    cluster at ADDRESS'``, and how many results came from the checkpoints of an earlier
    run (their time is not in W).

    >>> wall_time_line(12.3, [{}, {}], "depths", workers=2)
    '12 s for 2 depths with 2 processes (local dask cluster)'
    >>> wall_time_line(12.3, [{"resumed": True}, {}], "depths").split("; ")[1]
    "1 of them resumed from an earlier run's checkpoints (not in this wall time)"
    """
    n = int(workers or DEFAULT_WORKERS)
    where = (f"on the dask cluster at {scheduler}" if scheduler else
             f"with {n} process{'es' if n != 1 else ''} (local dask cluster)")
    line = f"{wall:.0f} s for {len(results)} {what} {where}"
    resumed = sum(bool(isinstance(r, dict) and r.get("resumed")) for r in results)
    if resumed:
        line += (f"; {resumed} of them resumed from an earlier run's checkpoints "
                 "(not in this wall time)")
    return line


def run_study_from_args(func, tasks, args, desc=""):
    """:func:`run_study` with the options of :func:`add_runner_arguments` read from the
    parsed `args` (missing attributes take the defaults)."""
    return run_study(func, tasks,
                     scheduler=getattr(args, "scheduler", None),
                     workers=getattr(args, "workers", None),
                     checkpoint=getattr(args, "checkpoint", None),
                     resume=getattr(args, "resume", False),
                     progress=not getattr(args, "no_progress", False),
                     desc=desc)
