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
- table_meta gives every table the same generated_by/date/version lines;
- the default local cluster listens on loopback only and its workers lack dask's
  MALLOC_TRIM_THRESHOLD_.

Faults on a cluster of separate processes (issue 35), each through the command line of
a toy study (`python -m tools.build_tables squares`, this module's add_arguments/run)
with the scheduler and workers started by DaskProcesses; each checks the one error
line (no traceback), the exit status and the tables/checkpoints:
- the scheduler killed mid-study: the line names --resume and says to restart the
  scheduler and the workers; after the restart --resume completes the same table;
- a worker that joins later with other linecontact code or without pyFFTW: its first
  task refuses, the study stops; the same for such a worker present at the start;
- bad --scheduler values (empty, malformed, dead port, an HTTP server, a web address):
  exit 2 within the connect timeout.
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


def listening(task):
    """A study task: the environment variable MALLOC_TRIM_THRESHOLD_ of the worker and
    the addresses on which the worker and its parent (the study's process: scheduler,
    nannies) listen for TCP connections."""
    import psutil
    addresses = set()
    for proc in (psutil.Process(), psutil.Process().parent()):
        addresses |= {c.laddr.ip for c in proc.net_connections(kind="tcp")
                      if c.status == psutil.CONN_LISTEN}
    return {"malloc_trim": os.environ.get("MALLOC_TRIM_THRESHOLD_"),
            "listen": sorted(addresses)}


def test_local_cluster_on_loopback_without_malloc_trim(monkeypatch):
    """The default local cluster listens on 127.0.0.1 only (scheduler, workers and their
    HTTP servers: nothing reachable from another machine), and its workers do not get
    dask's MALLOC_TRIM_THRESHOLD_=65536 (which turns off glibc's dynamic mmap threshold:
    a page fault storm on every large array; tools/benchmarks/results/paper_study.txt)."""
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    out = run_study(listening, [dict(key="a")], workers=1, progress=False)[0]
    assert out["malloc_trim"] is None
    assert out["listen"] == ["127.0.0.1"], out["listen"]
    assert "MALLOC_TRIM_THRESHOLD_" not in os.environ      # not leaked to this process


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
                      "--no-progress", "--checkpoint", "/tmp/x", "--connect-timeout", "7"])
    assert (a.scheduler, a.workers, a.resume, a.no_progress, a.checkpoint,
            a.connect_timeout) == ("tcp://h:8786", 3, True, True, Path("/tmp/x"), 7.0)
    # a zero or negative connect timeout is refused, not replaced by the default
    from tools.studies.runner import StudyError
    for bad in (0, -1.0):
        with pytest.raises(StudyError, match="--connect-timeout .*> 0") as err:
            run_study(square, [dict(key="a", x=1)], scheduler="tcp://127.0.0.1:1",
                      connect_timeout=bad, progress=False)
        assert err.value.exit_code == 2
    m = table_meta("python -m tools.build_tables demo", title="T", version="1",
                   source="S")
    assert list(m) == ["title", "source", "generated_by", "date", "version"]
    assert m["version"] == code_version() and m["version"].startswith("linecontact ")
    assert m["date"] == datetime.date.today().isoformat()


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _site(folder, linecontact=None, without_pyfftw=False):
    """A stand-in for a machine's site-packages outside the checkout: `folder` holding
    linecontact (a link to this checkout's package, or the copy `linecontact`) and, with
    `without_pyfftw`, a pyfftw that fails to import (a machine without pyFFTW)."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "linecontact").symlink_to(linecontact or REPO / "linecontact")
    if without_pyfftw:
        (folder / "pyfftw").mkdir()
        (folder / "pyfftw" / "__init__.py").write_text(
            "raise ImportError('no pyfftw on this machine (a test stand-in)')\n")
    return folder


class DaskProcesses:
    """`dask scheduler` and `dask worker --nthreads 1` as separate processes on
    127.0.0.1, started OUTSIDE the repository (cwd a temporary folder, PYTHONPATH a
    site folder holding only this checkout's linecontact: what `pip install` gives a
    cluster machine), so they cannot import tools/ or this test module. Every start is
    bounded (60 s); :meth:`close` stops them all (killed after 5 s)."""

    def __init__(self, root):
        self.root = root
        self.cwd = root / "outside"
        self.cwd.mkdir(parents=True, exist_ok=True)
        self.site = _site(root / "site")
        self.procs = []
        self.n = 0

    def env(self, site=None):
        keep = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
                if p and not Path(p).resolve().is_relative_to(REPO)]
        return dict(os.environ, PYTHONPATH=os.pathsep.join([str(site or self.site)]
                                                           + keep))

    def _start(self, argv, site=None):
        self.n += 1
        log = self.root / f"{self.n}-{argv[0]}.log"
        with open(log, "w") as fh:
            proc = subprocess.Popen([sys.executable, "-m", "dask", *argv], cwd=self.cwd,
                                    env=self.env(site), stdout=fh,
                                    stderr=subprocess.STDOUT)
        proc.log = log
        self.procs.append(proc)
        return proc

    def scheduler(self, port=0):
        """A scheduler on 127.0.0.1:`port` (0: a free one), no dashboard; (process,
        address) once it listens."""
        file = self.root / f"scheduler-{self.n + 1}.json"
        proc = self._start(["scheduler", "--host", "127.0.0.1", "--port", str(port),
                            "--no-dashboard", "--dashboard-address", "127.0.0.1:0",
                            "--scheduler-file", str(file)])
        deadline = time.monotonic() + 60
        while not file.exists():
            assert proc.poll() is None and time.monotonic() < deadline, \
                f"scheduler did not start: {proc.log.read_text()[-2000:]}"
            time.sleep(0.05)
        import json
        for _ in range(100):                 # written, but maybe not flushed yet
            try:
                return proc, json.loads(file.read_text())["address"]
            except (ValueError, KeyError):
                time.sleep(0.05)
        raise AssertionError(f"unreadable scheduler file {file}")

    def worker(self, address, site=None, wait=True):
        """One worker process with one thread (no nanny, no dashboard); with `wait`,
        once the scheduler counts one more worker."""
        before = self.n_workers(address) if wait else 0
        proc = self._start(["worker", address, "--nthreads", "1", "--nworkers", "1",
                            "--no-dashboard", "--dashboard-address", "127.0.0.1:0",
                            "--no-nanny", "--host", "127.0.0.1",
                            "--local-directory", str(self.root / f"w{self.n + 1}")],
                           site)
        if wait:
            from dask.distributed import Client
            with Client(address, timeout="60s") as client:
                client.wait_for_workers(before + 1, timeout=60)
        return proc

    @staticmethod
    def n_workers(address):
        from dask.distributed import Client
        with Client(address, timeout="60s") as client:
            return len(client.scheduler_info(n_workers=-1)["workers"])

    @staticmethod
    def stop(proc, kill=False):
        if proc.poll() is None:
            (proc.kill if kill else proc.terminate)()
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(timeout=10)

    def close(self):
        for p in reversed(self.procs):       # the workers first: they say goodbye to
            self.stop(p)                     # the scheduler, which must still be there


@pytest.fixture(scope="module")
def scheduler_and_worker(tmp_path_factory):
    """A scheduler and one worker as separate processes outside the checkout
    (:class:`DaskProcesses`); yields the scheduler address."""
    dask = DaskProcesses(tmp_path_factory.mktemp("dask"))
    # the premise: from there, linecontact imports but tools/ does not
    probe = subprocess.run(
        [sys.executable, "-c", "import importlib.util as u, linecontact; print("
                               "u.find_spec('tools') is None, linecontact.__file__)"],
        cwd=dask.cwd, env=dask.env(), capture_output=True, text=True, timeout=60)
    assert probe.stdout.split()[0] == "True", \
        f"the dask processes would see the checkout: {probe.stdout} {probe.stderr}"
    assert Path(probe.stdout.split()[1]).resolve().is_relative_to(REPO / "linecontact")
    try:
        _, address = dask.scheduler()
        dask.worker(address)
        yield address
    finally:
        dask.close()


def test_study_through_separate_scheduler_and_worker(tmp_path, scheduler_and_worker):
    args = argparse.Namespace(scheduler=scheduler_and_worker, workers=None,
                              checkpoint=tmp_path / "ck", resume=False, no_progress=True)
    out = run_study_from_args(square, _tasks([2, 3]), args)
    assert [r["y"] for r in out] == [4, 9]
    assert all(r["pid"] != os.getpid() for r in out)
    assert len(list((tmp_path / "ck").glob("*.pkl"))) == 2


def test_universal_study_cli_through_the_scheduler(tmp_path, scheduler_and_worker):
    """`python -m tools.build_tables universal --scheduler ADDRESS` on a tiny grid: the
    BEM tasks run on the separate worker and the table records where they ran (its
    wall_time line; its generated_by is the command that regenerates it, anywhere:
    no address, no output folder); the result equals a LocalCluster run of the same
    study (same tasks, same solver)."""
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
    assert remote.meta["generated_by"] == ("python -m tools.build_tables universal "
                                           + " ".join(tiny[:-1]))
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


# --- faults on a cluster of separate processes (issue 35) ---------------------------
# A toy study, 'squares', run as a user runs a study: `python -m tools.build_tables
# squares ...` in a separate process (the subcommand added for the test), through
# the runner's options; it writes out/squares.csv (x, y = x^2) with the header's
# wall_time line, which says how many results were resumed.

def add_arguments(parser):
    """Options of the toy study: --xs, --sleep (seconds per task), --out."""
    parser.add_argument("--xs", type=lambda t: [float(v) for v in t.split(",")])
    parser.add_argument("--sleep", type=float, default=0.0)
    parser.add_argument("--out", type=Path)
    add_runner_arguments(parser)


def run(args):
    from tools.studies.runner import wall_time_line
    tasks = [dict(key=f"x{x:g}", x=x, sleep=args.sleep) for x in args.xs]
    t0 = time.perf_counter()
    results = run_study_from_args(square, tasks, args, desc="squares")
    args.out.mkdir(parents=True, exist_ok=True)
    line = wall_time_line(time.perf_counter() - t0, results, "squares", args.scheduler)
    rows = "".join(f"{r['x']!r},{r['y']!r}\n" for r in results)
    (args.out / "squares.csv").write_text(f"# wall_time: {line}\nx,y\n{rows}")
    return 0


def _squares(*argv):
    """The toy study's command line, started as a separate process in the checkout
    (the study's client: this is where a user types the command)."""
    code = ("import sys; from tools import build_tables as b; "
            "b.SUBCOMMANDS['squares'] = 'tests.test_runner'; "
            "sys.exit(b.main(sys.argv[1:]))")
    return subprocess.Popen([sys.executable, "-c", code, "squares", "--no-progress",
                             *map(str, argv)], cwd=REPO, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def _one_line_error(proc, timeout=90):
    """(exit status, the error line) of a study that must fail with one line on
    stderr and no traceback."""
    out, err = proc.communicate(timeout=timeout)
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert "Traceback" not in err, err
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return proc.returncode, lines[0]


def _table(out):
    """The toy study's table: (header line, {x: y})."""
    text = (out / "squares.csv").read_text().splitlines()
    return text[0], {float(r.split(",")[0]): float(r.split(",")[1]) for r in text[2:]}


def _wait_for(condition, what, timeout=60):
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.05)


def test_lost_scheduler_one_line_then_resume(tmp_path):
    """The scheduler killed in the middle of a study: the study ends with one line
    (no traceback, exit 1) that names --resume and says to restart the scheduler AND
    the workers; the finished tasks are in the checkpoint folder and no table is
    written. After a restart (same port) --resume runs only the other tasks and the
    table equals x^2 for every x, stating how many results were resumed."""
    dask = DaskProcesses(tmp_path / "dask")
    port = _free_port()
    ck, out = tmp_path / "ck", tmp_path / "out"
    xs = "1,2,3,4,5,6,7,8"
    try:
        scheduler, address = dask.scheduler(port)
        dask.worker(address)
        study = _squares("--xs", xs, "--sleep", "0.4", "--scheduler", address,
                         "--checkpoint", ck, "--out", out)
        _wait_for(lambda: any(ck.glob("*.pkl")), "the first result")
        dask.stop(scheduler, kill=True)
        t0 = time.monotonic()
        code, line = _one_line_error(study)
        assert code == 1
        assert time.monotonic() - t0 < 60              # not a hang
        assert f"lost the dask scheduler at {address}" in line
        assert "restart the scheduler and the workers" in line and "--resume" in line
        saved = len(list(ck.glob("*.pkl")))
        assert 1 <= saved < 8 and f"{saved} of 8 tasks finished" in line
        assert not (out / "squares.csv").exists()
        for p in dask.procs:
            dask.stop(p)
        _, address = dask.scheduler(port)
        dask.worker(address)
        study = _squares("--xs", xs, "--sleep", "0.4", "--scheduler", address,
                         "--checkpoint", ck, "--out", out, "--resume")
        _, err = study.communicate(timeout=90)
        assert study.returncode == 0, err
        head, table = _table(out)
        assert table == {x: x * x for x in range(1, 9)}
        assert f"{saved} of them resumed" in head
    finally:
        dask.close()


def _no_table(out, ck):
    assert not (out / "squares.csv").exists()
    assert not list(ck.glob("*.pkl"))


@pytest.mark.parametrize("fault", ["other linecontact", "no pyfftw"])
def test_worker_joining_later_with_other_environment_is_refused(tmp_path, fault):
    """A worker that joins after the study started (so after the start-up check),
    with other linecontact code (one source line changed) or without pyFFTW: its
    first task refuses to run and the study stops with one line naming the worker,
    both environments and what to install; nothing computed there is kept."""
    import shutil
    dask = DaskProcesses(tmp_path / "dask")
    if fault == "other linecontact":
        other = tmp_path / "other" / "linecontact"
        shutil.copytree(REPO / "linecontact", other,
                        ignore=shutil.ignore_patterns("__pycache__"))
        with open(other / "__init__.py", "a") as fh:
            fh.write("# another version\n")
        site = _site(tmp_path / "site_bad", linecontact=other)
    else:
        site = _site(tmp_path / "site_bad", without_pyfftw=True)
    ck, out = tmp_path / "ck", tmp_path / "out"
    try:
        _, address = dask.scheduler()
        study = _squares("--xs", "1,2,3", "--scheduler", address, "--checkpoint", ck,
                         "--out", out)
        from dask.distributed import Client
        with Client(address, timeout="60s") as client:      # the tasks are queued:
            _wait_for(lambda: client.run_on_scheduler(      # the start-up check is over
                lambda dask_scheduler: len(dask_scheduler.tasks)) >= 3, "the tasks")
        dask.worker(address, site=site, wait=False)
        code, line = _one_line_error(study)
        assert code == 1
        assert "study stopped, dask worker tcp://127.0.0.1:" in line
        if fault == "other linecontact":
            assert "runs other linecontact code" in line and "pip install" in line
        else:
            assert "has FFT backend scipy, this process pyfftw" in line
            assert "pip install pyfftw" in line
        _no_table(out, ck)
    finally:
        dask.close()


def test_worker_there_at_the_start_without_pyfftw_is_refused(tmp_path):
    """The same check before any task runs, for a worker connected at the start."""
    dask = DaskProcesses(tmp_path / "dask")
    ck, out = tmp_path / "ck", tmp_path / "out"
    try:
        _, address = dask.scheduler()
        dask.worker(address, site=_site(tmp_path / "site_bad", without_pyfftw=True))
        code, line = _one_line_error(_squares("--xs", "1,2", "--scheduler", address,
                                              "--checkpoint", ck, "--out", out))
        assert code == 1
        assert "1 of 1 dask workers refused" in line and "FFT backend scipy" in line
        _no_table(out, ck)
    finally:
        dask.close()


def test_bad_scheduler_values_one_line_exit_2(tmp_path, scheduler_and_worker):
    """Each bad --scheduler gets one line and exit status 2 within the connect timeout
    (5 s here): empty (no silent local cluster), malformed, a port where nothing
    listens, a port of a server that is not dask (an HTTP server, which once held the
    client for minutes), a web address, a dask worker's address. All run at once, each
    its own process."""
    import http.server
    import threading
    from dask.distributed import Client
    with Client(scheduler_and_worker, timeout="60s") as client:
        worker = sorted(client.scheduler_info(n_workers=-1)["workers"])[0]
    web = http.server.ThreadingHTTPServer(("127.0.0.1", 0),
                                          http.server.BaseHTTPRequestHandler)
    threading.Thread(target=web.serve_forever, daemon=True).start()
    http_port, dead = web.server_address[1], _free_port()
    cases = {
        "": "empty: give the address of a running dask scheduler",
        "tcp://127.0.0.1": "not HOST:PORT",
        "tcp://127.0.0.1:port": "not HOST:PORT",
        "http://127.0.0.1:8787": "the scheme 'http' is not one of dask's",
        f"tcp://127.0.0.1:{dead}": f"nothing listens on port {dead} of 127.0.0.1",
        f"tcp://127.0.0.1:{http_port}": "does not answer as a dask scheduler",
        worker: "is a dask Worker, not the scheduler",
    }
    try:
        t0 = time.monotonic()
        runs = {a: _squares("--xs", "1", "--scheduler", a, "--connect-timeout", 5,
                            "--out", tmp_path / f"out{i}")
                for i, a in enumerate(cases)}
        for address, expected in cases.items():
            code, line = _one_line_error(runs[address])
            assert code == 2, (address, line)
            assert line.startswith(f"error: --scheduler {address!r}: ") and \
                expected in line, (address, line)
        # the timeout counts once per process; start-up under load adds to it
        assert time.monotonic() - t0 < 5 + 40
        assert not any(tmp_path.glob("out*/squares.csv"))
    finally:
        web.shutdown()
