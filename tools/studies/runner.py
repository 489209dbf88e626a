"""The one study runner: every BEM study (universal curve, the paper's rerun, and those
to come) runs its tasks through :func:`run_study`, and every table it writes gets its
header from :func:`table_meta`.

Tasks go to a ``dask.distributed`` client:

- by default a ``LocalCluster`` on this machine, ``--workers`` worker processes (default
  2) with one thread each, so that one task = one core (the BEM tasks ask their FFT
  backend for one thread too);
- with ``--scheduler ADDRESS`` (e.g. ``tcp://host:8786``) an existing cluster started
  with ``dask scheduler`` and ``dask worker ADDRESS --nthreads 1`` on each machine
  (docs/cluster.md). The scheduler and the workers need linecontact installed (the
  same code as this checkout: checked before any task runs), not the repository: the
  study code travels with the tasks (:func:`ship_study_code`). The ``tools`` package
  is uploaded to the cluster as a zip (``Client.upload_file``, which also reaches
  workers that join later), and a task function defined elsewhere in the checkout
  (a test, a script) is pickled by value with cloudpickle.

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
import tempfile
import zipfile
from pathlib import Path

__all__ = ["add_runner_arguments", "run_study", "run_study_from_args", "table_meta",
           "wall_time_line", "code_version", "ship_study_code", "check_same_linecontact",
           "linecontact_fingerprint", "DEFAULT_WORKERS"]

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


#: The repository root: the parent of the ``tools`` package.
_TOOLS = Path(__file__).resolve().parents[1]
_REPO = _TOOLS.parent


def linecontact_fingerprint():
    """SHA-1 of the Python sources of the linecontact package that this interpreter
    imports (relative paths and bytes of every ``*.py``, the data tables excluded),
    with its version: two processes compute the same numbers only if these agree.

    >>> linecontact_fingerprint().startswith("linecontact ")
    True
    """
    import linecontact
    root = Path(linecontact.__file__).resolve().parent
    digest = hashlib.sha1()
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root)
        if rel.parts[0] == "tables" or "__pycache__" in rel.parts:
            continue
        digest.update(rel.as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return f"linecontact {linecontact.__version__} sha1 {digest.hexdigest()[:12]}"


def _zip_tools(folder):
    """The ``tools`` package (its ``*.py`` files) as a zip named by its content hash,
    in `folder`; the path of the zip."""
    files = sorted(p for p in _TOOLS.rglob("*.py") if "__pycache__" not in p.parts)
    digest = hashlib.sha1()
    for p in files:
        digest.update(p.relative_to(_REPO).as_posix().encode() + b"\0" + p.read_bytes())
    path = Path(folder) / f"linecontact_tools_{digest.hexdigest()[:12]}.zip"
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        for p in files:
            # a fixed date: the same sources give the same bytes
            info = zipfile.ZipInfo(p.relative_to(_REPO).as_posix(), (1980, 1, 1, 0, 0, 0))
            zf.writestr(info, p.read_bytes(), zipfile.ZIP_DEFLATED)
    return path


# Run on the scheduler and every worker before the upload, as source text through the
# builtin exec (so it needs nothing from this repository there): a long-lived process
# forgets the tools modules it imported from an older upload, which would otherwise
# shadow the new zip's (importing a package reloads only its __init__).
_FORGET_TOOLS = """import sys
for _name in [m for m in sys.modules if m == "tools" or m.startswith("tools.")]:
    del sys.modules[_name]
"""


def _by_value_modules(func):
    """Modules of this checkout outside ``tools`` (uploaded) and ``linecontact``
    (installed on the cluster) that `func` comes from: a test or a script, which the
    workers cannot import, so it is pickled by value."""
    module = sys.modules.get(getattr(func, "__module__", None) or "")
    top = (module.__name__.split(".")[0] if module else "")
    file = getattr(module, "__file__", None)
    if module is None or top in ("tools", "linecontact", "__main__") or not file:
        return []
    try:
        Path(file).resolve().relative_to(_REPO)
    except ValueError:
        return []            # an installed package: the cluster has its own
    return [module]


def _run_pickled(task, func_pickle):
    """The task as the cluster runs it: `func_pickle` (cloudpickle of the study
    function, by value where the cluster lacks its module) called on `task`."""
    import pickle as _pickle
    return _pickle.loads(func_pickle)(task)


def ship_study_code(client):
    """Make this checkout's study code importable on a Dask cluster whose scheduler and
    workers have linecontact installed but not the repository.

    The ``tools`` package is zipped and sent with ``Client.upload_file`` (the scheduler
    and every worker, present and future, put it first on ``sys.path``; modules of an
    older upload are forgotten first). Then the workers' linecontact must be this
    checkout's (:func:`linecontact_fingerprint`): a study computed by other code than
    the version its table names would be a lie.

    Raises
    ------
    RuntimeError
        A worker imports a linecontact with other sources than this process (it names
        the worker, both fingerprints and what to install).
    """
    client.run_on_scheduler(exec, _FORGET_TOOLS, {})
    client.run(exec, _FORGET_TOOLS, {})
    with tempfile.TemporaryDirectory(prefix="linecontact-ship-") as folder:
        client.upload_file(str(_zip_tools(folder)))
    check_same_linecontact(client)


def check_same_linecontact(client, expected=None):
    """RuntimeError unless every worker's :func:`linecontact_fingerprint` equals
    `expected` (default: this process's)."""
    expected = expected or linecontact_fingerprint()
    found = client.run(linecontact_fingerprint)
    other = {w: f for w, f in found.items() if f != expected}
    if other:
        worker, theirs = sorted(other.items())[0]
        raise RuntimeError(
            f"{len(other)} of {len(found)} dask workers run other linecontact code "
            f"than this checkout (worker {worker}: {theirs}; here: {expected}); "
            f"install this checkout on them (pip install {_REPO}) and restart them")


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
    import cloudpickle
    client, cluster = _client(scheduler, workers)
    try:
        # a local cluster's scheduler is this process and its workers start with this
        # sys.path: they import the code from the checkout like this process does
        if scheduler:
            ship_study_code(client)
        by_value = _by_value_modules(func) if scheduler else []
        for module in by_value:
            cloudpickle.register_pickle_by_value(module)
        try:
            func_pickle = cloudpickle.dumps(func)
        finally:
            for module in by_value:
                cloudpickle.unregister_pickle_by_value(module)
        futures = client.map(_run_pickled, todo, func_pickle=func_pickle, pure=False)
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
