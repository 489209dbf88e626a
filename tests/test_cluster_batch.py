"""Batches on a dask cluster (linecontact.calc.spread): ``linecontact calc FILE.csv
--scheduler ADDRESS``, ``linecontact bearing FILE.csv --scheduler ADDRESS`` and
``calc_frame(..., client=)`` write the serial batch's output byte for byte, and every
bad ``--scheduler`` is one line with exit status 2 within the connect timeout.

The cluster is a ``dask scheduler`` and two ``dask worker`` processes started
separately on 127.0.0.1 (the issue's setting), importing this checkout's linecontact
(PYTHONPATH), as a user's workers import the same installed code.
"""
import os
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("distributed")

from linecontact.calc.cli import main  # noqa: E402
# the cases: a calc batch with plain, crowned and refused rows; the bearing's
# tolerance Monte Carlo of docs/cluster.md (one of the benchmark's, the same rows)
from tools.benchmarks.bench_cluster_batch import (BEARING, bearing_cases,  # noqa: E402
                                                  calc_cases, local_processes)

REPO = Path(__file__).resolve().parents[1]


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def scheduler(tmp_path_factory):
    """A scheduler and two single-thread workers, each its own process, on 127.0.0.1;
    yields the address; all stopped at the end (killed after 5 s)."""
    from dask.distributed import Client

    logs_dir = tmp_path_factory.mktemp("dask")
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, PYTHONPATH=str(REPO))
    procs, logs = [], []

    def start(name, *argv):
        log = open(logs_dir / f"{name}.log", "w")
        logs.append(log)
        procs.append(subprocess.Popen([sys.executable, "-m", "dask", *argv], cwd=REPO,
                                      env=env, stdout=log, stderr=subprocess.STDOUT))

    try:
        start("scheduler", "scheduler", "--host", "127.0.0.1", "--port", str(port),
              "--no-dashboard")
        for k in range(2):
            start(f"worker{k}", "worker", address, "--nthreads", "1", "--no-nanny",
                  "--no-dashboard", "--host", "127.0.0.1",
                  "--local-directory", str(logs_dir / f"w{k}"))
        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=120)
        yield address
    finally:
        for p in reversed(procs):
            p.terminate()
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=10)
        for log in logs:
            log.close()


def _both(tmp_path, argv, scheduler, name="out"):
    """(serial bytes, status), (cluster bytes, status) of one command line, each
    written to the same output name (the JSON header records it)."""
    out = tmp_path / name
    runs = []
    for extra in ([], ["--scheduler", scheduler]):
        if out.exists():
            out.unlink()
        code = main([*argv, "-o", str(out), *extra])
        runs.append((out.read_bytes(), code))
    return runs


@pytest.mark.parametrize("flags, rows", [([], 300), (["--json"], 300),
                                         (["--model", "all", "--si"], 100)])
def test_calc_batch_on_cluster_is_the_serial_batch(tmp_path, scheduler, flags, rows):
    """Hundreds of rows, mixed plain and crowned, some refused: the same bytes (CSV,
    JSON with its header's model list, every model's columns), the same status."""
    src = calc_cases(tmp_path / "cases.csv", rows)
    (serial, s_code), (spread, c_code) = _both(tmp_path, ["calc", str(src), *flags],
                                               scheduler)
    assert s_code == c_code == 2          # the refused rows
    assert serial == spread


def test_bearing_batch_on_cluster_is_the_serial_batch(tmp_path, scheduler):
    """Tens of rows of a bearing's tolerance Monte Carlo (ISO 16281 profile, a slice
    model per row; one refused): the same bytes and status, CSV and JSON."""
    for rows, flags in ((16, []), (6, ["--json"])):
        src = bearing_cases(tmp_path / "mc.csv", rows)
        (serial, s_code), (spread, c_code) = _both(
            tmp_path, ["bearing", str(src), *BEARING, *flags], scheduler)
        assert s_code == c_code == 2      # the row with a roller diameter of 0
        assert serial == spread


def _frame_cases(tmp_path, n=120):
    import pandas as pd

    cases = pd.read_csv(calc_cases(tmp_path / "c.csv", n), dtype=str,
                        keep_default_na=False)
    cases.index = cases.index * 10 + 3       # kept, not renumbered
    return cases


def _same_frame(one, other):
    import pandas as pd

    pd.testing.assert_frame_equal(one, other, check_exact=True)
    assert one.attrs == other.attrs


def test_frames_with_a_client(tmp_path, scheduler):
    """calc_frame and command_frame with client=: the serial frames (values, dtypes,
    index, header) exactly."""
    import pandas as pd
    from dask.distributed import Client

    from linecontact.calc.frame import calc_frame, command_frame

    cases = _frame_cases(tmp_path)
    b = pd.read_csv(bearing_cases(tmp_path / "b.csv", 6), dtype=str)
    bearing = dict(rollers=14, pitch_diameter="70mm", length="11mm")
    with Client(scheduler, timeout="60s") as client:
        spread = calc_frame(cases, client=client)
        b_spread = command_frame("bearing", b, client=client, **bearing)
    _same_frame(calc_frame(cases), spread)
    _same_frame(command_frame("bearing", b, **bearing), b_spread)


def test_dask_dataframe_of_cases(tmp_path, scheduler):
    """A dask DataFrame of cases is evaluated on the current client: the serial frame
    of its rows, dtypes included (dask's pyarrow strings back to pandas' own)."""
    pytest.importorskip("dask.dataframe")    # needs pyarrow
    import dask.dataframe as dd
    from dask.distributed import Client

    from linecontact.calc.frame import calc_frame

    cases = _frame_cases(tmp_path, 40)
    with Client(scheduler, timeout="60s"):
        lazy = calc_frame(dd.from_pandas(cases, npartitions=3))
    _same_frame(calc_frame(cases), lazy)


def test_a_worker_with_other_code_stops_the_batch(tmp_path, scheduler, monkeypatch,
                                                  capsys):
    """Each task compares its worker's linecontact code with the client's: another
    fingerprint (here the client's, changed) stops the batch in one line, exit 1,
    and writes nothing."""
    from linecontact.calc import spread

    monkeypatch.setattr(spread, "linecontact_fingerprint", lambda: "linecontact other")
    out = tmp_path / "o.csv"
    code = main(["calc", str(calc_cases(tmp_path / "c.csv", 20)), "-o", str(out),
                 "--scheduler", scheduler])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 1 and not out.exists()
    assert len(err) == 1 and "other linecontact code" in err[0] \
        and "nothing written" in err[0], err


class _NotDask:
    """A TCP server that accepts, answers like a web server (or says nothing, `reply`
    None) and holds the connection (the issue's HTTP port that held a client for
    330 s)."""

    def __init__(self, reply=b"HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nhello"):
        self.reply = reply
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.port = self.sock.getsockname()[1]
        self.conns = []
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self):
        while True:
            try:
                c, _ = self.sock.accept()
            except OSError:
                return
            self.conns.append(c)
            try:
                if self.reply:
                    c.sendall(self.reply)
            except OSError:
                pass

    def close(self):
        for c in self.conns:
            c.close()
        self.sock.close()


def test_bad_scheduler_is_one_line_and_exit_2(tmp_path, capsys):
    """Malformed, empty, a web address, a dead port, a server that is not dask: one
    line naming --scheduler, exit 2, nothing written, within the connect timeout
    (3 s here; a dead port at once; a silent server after the 3 s)."""
    src = calc_cases(tmp_path / "c.csv", 5)
    out = tmp_path / "o.csv"
    server, silent = _NotDask(), _NotDask(reply=None)
    dead = _free_port()
    try:
        for value, says in (("tcp://127.0.0.1", "HOST:PORT"), ("", "empty"),
                            ("http://127.0.0.1:8787", "web address"),
                            (f"127.0.0.1:{dead}", "nothing listens"),
                            (f"tcp://127.0.0.1:{server.port}",
                             "does not answer as a dask scheduler"),
                            (f"127.0.0.1:{silent.port}", "within 3 s")):
            t0 = time.monotonic()
            code = main(["calc", str(src), "-o", str(out), "--scheduler", value,
                         "--connect-timeout", "3"])
            took = time.monotonic() - t0
            err = capsys.readouterr().err.strip().splitlines()
            assert code == 2 and not out.exists(), (value, err)
            assert len(err) == 1 and "--scheduler" in err[0] and says in err[0], err
            assert took < 3 + 5, (value, took)      # the timeout and start-up
    finally:
        server.close()
        silent.close()


def test_cluster_options_need_a_batch_and_dask(tmp_path, capsys, monkeypatch):
    """--scheduler without a CSV, with --workers, a bad --workers or --connect-timeout:
    one line, exit 2; without dask installed the line names the extra."""
    src = calc_cases(tmp_path / "c.csv", 3)
    one = ["calc", "--radius", "5mm", "--length", "10mm", "--estar", "115GPa",
           "--load", "1kN"]
    for argv, says in (([*one, "--scheduler", "tcp://127.0.0.1:1"], "FILE.csv"),
                       (["calc", str(src), "--scheduler", "tcp://127.0.0.1:1",
                         "--workers", "2"], "give one"),
                       (["calc", str(src), "--workers", "0"], ">= 1"),
                       (["calc", str(src), "--scheduler", "tcp://127.0.0.1:1",
                         "--connect-timeout", "-1"], "> 0")):
        assert main(argv) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and says in err[0], err
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    assert main(["calc", str(src), "--scheduler", "tcp://127.0.0.1:1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "linecontact[cluster]" in err[0], err


def test_json_header_does_not_name_the_cluster(tmp_path):
    """The header's command is what was computed: the cluster's options (any spelling
    argparse takes) are left out, so the bytes are the serial batch's."""
    from linecontact.calc.cli import _without_cluster_options

    argv = ["calc", "f.csv", "--scheduler", "tcp://h:1", "--json", "--sched=tcp://h:1",
            "--workers", "2", "--connect-timeout", "5", "--si"]
    assert _without_cluster_options(argv) == ["calc", "f.csv", "--json", "--si"]


@pytest.mark.slow
def test_issue_sizes_on_cluster(tmp_path, scheduler):
    """The issue's sizes: a 10 000-row calc batch and a 1 000-row bearing batch through
    the scheduler and two workers equal the serial outputs byte for byte (minutes on
    two cores; tools/benchmarks/results/cluster_batch.txt has a recorded run)."""
    (serial, s_code), (spread, c_code) = _both(
        tmp_path, ["calc", str(calc_cases(tmp_path / "c.csv", 10000))], scheduler)
    assert serial == spread and s_code == c_code
    (serial, s_code), (spread, c_code) = _both(
        tmp_path, ["bearing", str(bearing_cases(tmp_path / "b.csv", 1000)), *BEARING],
        scheduler)
    assert serial == spread and s_code == c_code


def test_parts_keep_each_contact_whole(tmp_path):
    """calc's rows of one contact are solved as one warm-started sweep (equal to a row
    alone within the solver's tolerance, not bit for bit: split into consecutive
    ranges, this file's JSON differs in 1e-15 digits), so split_rows keeps each
    contact's rows in one part; every row is in exactly one part; a subcommand's
    parts are consecutive ranges."""
    import numpy as np

    from linecontact.calc.batch import CALC
    from linecontact.calc.cases import parse_cases
    from linecontact.calc.batch import read_table
    from linecontact.calc.compute import group_rows
    from linecontact.calc.spread import split_rows

    header, body, _ = read_table(calc_cases(tmp_path / "c.csv", 300))
    names = [h.strip().lower() for h in header]
    cells = {h: [r[j] for r in body] for j, h in enumerate(names) if h != "name"}
    cases, _, errors = parse_cases(cells, len(body), lambda n: n)
    parts = split_rows(CALC, cases, errors, 16)
    assert np.array_equal(np.sort(np.concatenate(parts)), np.arange(300))
    group = group_rows(cases, errors)[1]
    shared = np.bincount(group[group >= 0]).argmax()
    assert (group == shared).sum() > 40          # the roller that runs through the file
    for g in np.unique(group[group >= 0]):
        assert sum(np.isin(np.flatnonzero(group == g), p).any() for p in parts) == 1
    assert len(parts) > 8                        # the rest is still spread

    class Sub:  # a subcommand's table: every row solved alone
        groups = staticmethod(lambda cases, errors: None)
    ranges = split_rows(Sub, cases, errors, 4)
    assert [(r[0], r[-1]) for r in ranges] == [(0, 74), (75, 149), (150, 224), (225, 299)]


def test_lost_scheduler_is_one_line(tmp_path):
    """The scheduler killed while a bearing batch runs on it: one line naming it and
    what to restart, exit 1, no traceback, nothing written (its own scheduler and
    worker: the module's stay up)."""
    from dask.distributed import Client

    src = bearing_cases(tmp_path / "b.csv", 300)
    out = tmp_path / "o.csv"
    procs = []
    with local_processes(1, tmp_path, procs) as address:
        cmd = subprocess.Popen([sys.executable, "-m", "linecontact", "bearing", str(src),
                                *BEARING, "--scheduler", address, "-o", str(out)],
                               cwd=REPO, stderr=subprocess.PIPE, text=True,
                               env=dict(os.environ, PYTHONPATH=str(REPO)))
        try:
            with Client(address, timeout="60s") as client:   # wait for the parts
                t0 = time.monotonic()
                while not client.run_on_scheduler(
                        lambda dask_scheduler: len(dask_scheduler.tasks)):
                    assert time.monotonic() - t0 < 120 and cmd.poll() is None
                    time.sleep(0.2)
            time.sleep(1)
            procs[0].kill()                                  # the scheduler
            err = cmd.communicate(timeout=120)[1].strip().splitlines()
        finally:
            if cmd.poll() is None:
                cmd.kill()
    assert cmd.returncode == 1 and not out.exists(), err
    assert len(err) == 1 and "lost the dask scheduler at " + address in err[0] \
        and "restart the scheduler and its workers" in err[0], err
