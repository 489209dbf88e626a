"""The study runner (tools/studies/runner.py) on Dask.

Facts checked:
- a tiny study through a LocalCluster returns func(task) for every task, in task order
  (not in completion order), and writes one checkpoint per task;
- resume skips the finished keys: func runs only for the tasks without a checkpoint
  (counted by a side effect, one file per call), and a task whose settings changed
  under the same key is run again;
- a task that raises makes the study raise, and the tasks finished before it keep
  their checkpoints;
- resume without a checkpoint folder is refused (it would run every task again);
- the same study runs through a `dask scheduler` and a `dask worker` started as separate
  processes on localhost (what `--scheduler ADDRESS` does on a cluster), both started
  OUTSIDE the repository (cwd a temporary folder, PYTHONPATH without the checkout), so
  they have the installed linecontact but cannot import tools/ or this test module: the
  runner ships the study code with the tasks;
- a worker whose linecontact differs from this checkout's is refused, naming both;
- table_meta gives every table the same generated_by/date/version lines.
"""
from __future__ import annotations

import argparse
import datetime
import os
import socket
import subprocess
import sys
import time
import uuid
from pathlib import Path

import pytest

from tools.studies.runner import (add_runner_arguments, code_version, run_study,
                          run_study_from_args, table_meta)

REPO = Path(__file__).resolve().parent.parent


def square(task):
    """A study task: x^2, and one file per call in task['calls'] (counts the calls)."""
    if task.get("calls"):
        Path(task["calls"], f"{task['key']}-{uuid.uuid4().hex}").touch()
    time.sleep(task.get("sleep", 0.0))
    if task["x"] < 0:
        raise ArithmeticError(f"negative x = {task['x']}")
    return {"x": task["x"], "y": task["x"] ** 2, "pid": os.getpid()}


def _tasks(xs, calls=None):
    # later tasks finish first (sleep shrinks), so order must come from the runner
    return [dict(key=f"x{x}", x=x, calls=str(calls) if calls else None,
                 sleep=0.05 * (len(xs) - i)) for i, x in enumerate(xs)]


def _calls(folder):
    return sorted(p.name.split("-")[0] for p in Path(folder).iterdir())


def test_local_cluster_results_in_task_order(tmp_path):
    calls = tmp_path / "calls"
    calls.mkdir()
    xs = [3, 1, 4, 1.5, 5]
    out = run_study(square, _tasks(xs, calls), workers=2, checkpoint=tmp_path / "ck",
                    progress=False)
    assert [r["y"] for r in out] == [x ** 2 for x in xs]
    assert len(list((tmp_path / "ck").glob("*.pkl"))) == len(xs)
    assert len(_calls(calls)) == len(xs)
    assert all(r["pid"] != os.getpid() for r in out)      # ran in worker processes


def test_resume_skips_finished_keys(tmp_path, scheduler_and_worker):
    calls = tmp_path / "calls"
    calls.mkdir()
    ck = tmp_path / "ck"
    first = _tasks([1, 2], calls)
    on = dict(scheduler=scheduler_and_worker, progress=False)   # one cluster for all runs
    run_study(square, first, checkpoint=ck, **on)
    assert _calls(calls) == ["x1", "x2"]
    # an interrupted study resumed with two more tasks: only those run
    more = _tasks([1, 2, 3, 4], calls)
    for t, f in zip(more, first):
        t["sleep"] = f["sleep"]                     # same settings as the first run
    out = run_study(square, more, checkpoint=ck, resume=True, **on)
    assert [r["y"] for r in out] == [1, 4, 9, 16]
    assert [r.get("resumed", False) for r in out] == [True, True, False, False]
    assert _calls(calls) == ["x1", "x2", "x3", "x4"]
    # the same key with other settings is not a finished task: it runs again
    changed = [dict(more[0], x=10)] + more[1:]
    out = run_study(square, changed, checkpoint=ck, resume=True, **on)
    assert out[0]["y"] == 100
    assert _calls(calls) == ["x1", "x1", "x2", "x3", "x4"]


def test_failing_task_raises_and_keeps_finished(tmp_path, scheduler_and_worker):
    ck = tmp_path / "ck"
    tasks = [dict(key="ok", x=2.0, sleep=0.0), dict(key="bad", x=-1.0, sleep=0.5)]
    with pytest.raises(ArithmeticError, match="negative x"):
        run_study(square, tasks, scheduler=scheduler_and_worker, checkpoint=ck,
                  progress=False)
    assert [p.name.split("-")[0] for p in ck.glob("*.pkl")] == ["ok"]
    with pytest.raises(ValueError, match="unique"):
        run_study(square, [dict(key="a", x=1), dict(key="a", x=2)], progress=False)
    with pytest.raises(ValueError, match="key"):
        run_study(square, [dict(x=1)], progress=False)
    # resuming with no checkpoint folder would silently run everything again
    with pytest.raises(ValueError, match="resume.*--checkpoint"):
        run_study(square, tasks, resume=True, progress=False)


def test_options_and_table_meta():
    p = add_runner_arguments(argparse.ArgumentParser())
    a = p.parse_args(["--scheduler", "tcp://h:8786", "--workers", "3", "--resume",
                      "--no-progress", "--checkpoint", "/tmp/x"])
    assert (a.scheduler, a.workers, a.resume, a.no_progress, a.checkpoint) == \
        ("tcp://h:8786", 3, True, True, Path("/tmp/x"))
    m = table_meta("python -m tools.build_tables demo", title="T", version="1",
                   source="S")
    assert list(m) == ["title", "source", "generated_by", "date", "version"]
    assert m["version"] == code_version() and m["version"].startswith("linecontact ")
    assert m["date"] == datetime.date.today().isoformat()


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _outside_env():
    """This environment with the checkout (and tests/) taken off PYTHONPATH."""
    keep = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
            if p and not Path(p).resolve().is_relative_to(REPO)]
    return dict(os.environ, PYTHONPATH=os.pathsep.join(keep))


@pytest.fixture(scope="module")
def scheduler_and_worker(tmp_path_factory):
    """`dask scheduler` and one `dask worker --nthreads 1` as separate processes on
    localhost (a free port, no dashboard); yields the scheduler address. Start-up is
    bounded (60 s for the worker to register); both processes are stopped at the end
    (the worker, then the scheduler; killed if one has not stopped within 5 s)."""
    from dask.distributed import Client
    logs_dir = tmp_path_factory.mktemp("dask")
    outside = tmp_path_factory.mktemp("outside")        # cwd of both: not the checkout
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = _outside_env()
    # the premise: from there, linecontact imports (installed) but tools/ does not
    probe = subprocess.run(
        [sys.executable, "-c", "import importlib.util as u, linecontact; "
                               "print(u.find_spec('tools') is None)"],
        cwd=outside, env=env, capture_output=True, text=True, timeout=60)
    assert probe.stdout.strip() == "True", \
        f"the dask processes would see the checkout: {probe.stdout} {probe.stderr}"
    procs, logs = [], []

    def start(*argv):
        log = open(logs_dir / f"{argv[0]}.log", "w")
        logs.append(log)
        procs.append(subprocess.Popen([sys.executable, "-m", "dask", *argv],
                                      cwd=outside, env=env, stdout=log,
                                      stderr=subprocess.STDOUT))

    try:
        start("scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard")
        start("worker", address, "--nthreads", "1", "--nworkers", "1", "--no-dashboard",
              "--no-nanny", "--local-directory", str(logs_dir / "worker"))
        with Client(address, timeout="60s") as client:     # bounded: fails, never hangs
            client.wait_for_workers(1, timeout=60)
        yield address
    finally:
        for p in reversed(procs):       # the worker first: it says goodbye to the
            p.terminate()               # scheduler, which must still be there
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=10)
        for log in logs:
            log.close()


def test_study_through_separate_scheduler_and_worker(tmp_path, scheduler_and_worker):
    args = argparse.Namespace(scheduler=scheduler_and_worker, workers=None,
                              checkpoint=tmp_path / "ck", resume=False, no_progress=True)
    out = run_study_from_args(square, _tasks([2, 3]), args)
    assert [r["y"] for r in out] == [4, 9]
    assert all(r["pid"] != os.getpid() for r in out)
    assert len(list((tmp_path / "ck").glob("*.pkl"))) == 2


def test_universal_study_cli_through_the_scheduler(tmp_path, scheduler_and_worker):
    """`python -m tools.build_tables universal --scheduler ADDRESS` on a tiny grid: the
    BEM tasks run on the separate worker and the table records where they ran; the
    result equals a LocalCluster run of the same study (same tasks, same solver)."""
    from linecontact.tables import read_table
    from tools.build_tables import main as build_tables
    tiny = ["--d-min", "1e-3", "--d-max", "1e-1", "--per-decade", "1", "--n-length", "8",
            "--n-width", "4", "--check-every", "0", "--no-progress"]
    assert build_tables(["universal", *tiny, "--out", str(tmp_path / "remote"),
                         "--scheduler", scheduler_and_worker]) == 0
    assert build_tables(["universal", *tiny, "--out", str(tmp_path / "local"),
                         "--workers", "1"]) == 0
    remote = read_table("universal_curve", directory=tmp_path / "remote")
    local = read_table("universal_curve", directory=tmp_path / "local")
    assert scheduler_and_worker in remote.meta["wall_time"]
    assert remote.meta["generated_by"].endswith(scheduler_and_worker)
    assert len(remote) == 3
    for name in ("Psi", "dPsi", "beta_eff"):
        assert remote.columns[name].tolist() == local.columns[name].tolist(), name
    assert not (tmp_path / "remote" / "partial_universal").exists()


def test_worker_with_other_linecontact_is_refused(scheduler_and_worker):
    """The check that guards every study on a cluster: a fingerprint other than the
    workers' is refused with both named (here the expected one is made up)."""
    from dask.distributed import Client
    from tools.studies.runner import check_same_linecontact, ship_study_code
    with Client(scheduler_and_worker, timeout="60s") as client:
        ship_study_code(client)                  # the workers' own code agrees
        with pytest.raises(RuntimeError, match=r"1 of 1 dask workers .*here: linecontact "
                                               r"0\.0 sha1 000"):
            check_same_linecontact(client, expected="linecontact 0.0 sha1 000")
