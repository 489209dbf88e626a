"""Batches on a dask cluster (issue 35, item 1): a calc batch and a bearing's tolerance
Monte Carlo, serial and through a ``dask scheduler`` with 1 and 2 ``dask worker``
processes started separately on 127.0.0.1; wall times, and whether each cluster run's
output equals the serial one byte for byte.

    python -m tools.benchmarks.bench_cluster_batch [--calc-rows 10000]
        [--bearing-rows 1000] [--workers 1,2] [--no-serial]
        [--out tools/benchmarks/results/cluster_batch.txt]

Wall time is what a batch costs its user; on a shared machine it moves with the load
(printed: the load average before and after, from /proc/loadavg), so the CPU time of
all the processes (the command, the scheduler, the workers: their start-up included)
is printed beside it: CPU / wall is how many cores the run got. The workers import
this checkout's linecontact (PYTHONPATH), the client checks that they do.
"""
from __future__ import annotations

import argparse
import contextlib
import datetime
import os
import random
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

#: The bearing of the Monte Carlo (docs/cluster.md): 14 rollers of 11 mm x 11 mm on a
#: 70 mm pitch circle, ISO 16281 profile, steel.
BEARING = ["--rollers", "14", "--pitch-diameter", "70mm", "--length", "11mm",
           "--modulus", "210GPa", "--poisson", "0.3", "--profile", "iso16281"]


def calc_cases(path, n, seed=1):
    """n calc rows: distinct rollers, a third crowned, every 17th refused (a negative
    load), row 5 a sweep in a cell (refused); every 7th from row 2 one crowned roller
    at its own load (one contact all through the file: solved as one sweep) and every
    7th from row 4 one plain roller."""
    rnd = random.Random(seed)
    lines = ["name,radius,length,estar,load,crown_radius"]
    for i in range(n):
        crown = "" if i % 3 else f"{rnd.uniform(200, 800):.1f}mm"
        load = "-1kN" if i % 17 == 0 else (
            "1kN:2kN:3" if i == 5 else f"{rnd.uniform(0.1, 20):.3f}kN")
        roller = (f"{rnd.uniform(3, 8):.4f}mm,{rnd.uniform(5, 20):.3f}mm,"
                  f"{rnd.uniform(100, 230):.1f}GPa")
        if i % 7 in (2, 4):
            roller, crown = "5mm,10mm,200GPa", "500mm" if i % 7 == 2 else ""
        lines.append(f"r{i},{roller},{load},{crown}")
    Path(path).write_text("\n".join(lines) + "\n")
    return Path(path)


def bearing_cases(path, n, seed=35, refused=(3,)):
    """The tolerance Monte Carlo of docs/cluster.md: per row a clearance (20 +- 5 um),
    a roller diameter (11 mm +- 1 um), a misalignment (0.5 +- 0.2 mrad) and a radial
    load (8 to 12 kN); rows in `refused` get a roller diameter of 0 (refused)."""
    rnd = random.Random(seed)
    lines = ["case,clearance,roller_diameter,misalignment,radial_load"]
    for i in range(n):
        d = "0mm" if i in refused else f"{rnd.gauss(11, 0.001):.5f}mm"
        lines.append(f"{i},{rnd.gauss(20, 5):.2f}um,{d},{rnd.gauss(0.5, 0.2):.3f}mrad,"
                     f"{rnd.uniform(8, 12):.3f}kN")
    Path(path).write_text("\n".join(lines) + "\n")
    return Path(path)


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextlib.contextmanager
def local_processes(workers, folder, procs=None):
    """`dask scheduler` and `workers` single-thread `dask worker` processes on
    127.0.0.1, started separately (appended to the list `procs` if given, the
    scheduler first); yields the address; all stopped at the end."""
    from dask.distributed import Client

    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, PYTHONPATH=str(REPO))
    procs = [] if procs is None else procs

    def start(*argv):
        procs.append(subprocess.Popen([sys.executable, "-m", "dask", *argv], cwd=REPO,
                                      env=env, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL))
    try:
        start("scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard")
        for k in range(workers):
            start("worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                  "--host", "127.0.0.1", "--local-directory", str(Path(folder, f"w{k}")))
        with Client(address, timeout="60s") as client:
            client.wait_for_workers(workers, timeout=120)
        yield address
    finally:
        for p in reversed(procs):
            p.terminate()
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


def _run(argv, out):
    """Wall time [s], exit status and output bytes of ``python -m linecontact ARGV``."""
    t0 = time.perf_counter()
    code = subprocess.run([sys.executable, "-m", "linecontact", *argv, "-o", str(out),
                           "--no-progress"], cwd=REPO, stderr=subprocess.DEVNULL).returncode
    wall = time.perf_counter() - t0
    data = Path(out).read_bytes()
    Path(out).unlink()
    return wall, code, data


def _compared(data, code, serial, serial_code):
    """'same' or 'DIFFERENT' against the serial output, or (no serial run) the number of
    lines the output has."""
    if serial is None:
        lines = data.count(b"\n")
        return f"not compared (no serial run), {lines} output lines"
    return "same" if data == serial and code == serial_code else "DIFFERENT"


def _cpu():
    """CPU seconds (user + system) of this process's finished children."""
    import resource

    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _load():
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calc-rows", type=int, default=10000)
    ap.add_argument("--bearing-rows", type=int, default=1000)
    ap.add_argument("--workers", default="1,2", help="worker counts, comma-separated")
    ap.add_argument("--out", type=Path, default=None, help="also write the record here")
    ap.add_argument("--no-serial", dest="serial", action="store_false",
                    help="run only on the cluster (for sizes whose serial run would take "
                         "hours): no byte-for-byte comparison, the output's rows counted")
    a = ap.parse_args(argv)
    counts = [int(k) for k in a.workers.split(",")]
    lines = [f"# cluster_batch: wall time of a batch {'serial and ' if a.serial else ''}"
             f"on a dask scheduler with k worker processes (1 thread each), all on this "
             f"machine, 127.0.0.1; "
             + ("'same' = the output equals the serial one byte for byte" if a.serial else
                "no serial run (--no-serial): the output's lines counted"),
             "# command: python -m tools.benchmarks.bench_cluster_batch "
             + " ".join(argv if argv is not None else sys.argv[1:]),
             f"# {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC; "
             f"{os.cpu_count()} cores; load average before: {_load()}", ""]
    print("\n".join(lines), flush=True)
    with tempfile.TemporaryDirectory(prefix="cluster-batch-") as folder:
        jobs = []
        if a.calc_rows:
            jobs.append((f"calc, {a.calc_rows} rows",
                         ["calc", str(calc_cases(Path(folder, "c.csv"), a.calc_rows))]))
        if a.bearing_rows:
            jobs.append((f"bearing Monte Carlo, {a.bearing_rows} rows",
                         ["bearing", str(bearing_cases(Path(folder, "b.csv"),
                                                       a.bearing_rows)), *BEARING]))
        for name, job in jobs:
            serial = code = None
            if a.serial:
                cpu0 = _cpu()
                wall, code, serial = _run(job, Path(folder, "out"))
                row = f"{name}: serial {wall:.1f} s (exit {code}), CPU {_cpu() - cpu0:.1f} s"
                print(row, flush=True)
                lines.append(row)
            for k in counts:
                cpu0 = _cpu()
                with local_processes(k, folder) as address:
                    wall_k, code_k, data = _run([*job, "--scheduler", address],
                                                Path(folder, "out"))
                cpu = _cpu() - cpu0     # the command, the scheduler, the workers
                row = (f"{name}: scheduler + {k} worker{'s' if k > 1 else ''} "
                       f"{wall_k:.1f} s (exit {code_k}), CPU {cpu:.1f} s (all "
                       f"processes, start-up included), "
                       f"{_compared(data, code_k, serial, code)}"
                       f"; load average now {_load()}")
                print(row, flush=True)
                lines.append(row)
    lines.append(f"# load average after: {_load()}")
    if a.out is not None:
        a.out.write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
