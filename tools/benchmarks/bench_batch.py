"""Batch and sweep speed of ``linecontact calc``, as ratios to a one-case call (issue 11,
item 5: a 100 000-row batch within 5 times a one-case call).

It writes a benchmark CSV and runs, interleaved, N times each (whole processes, from
this repository's root, ``python -m linecontact``):

    one      calc --radius 5mm --length 10mm --modulus 210GPa --poisson 0.3 --load 1kN
    batch    calc BENCH.csv -o OUT.csv                      (--rows rows, default model)
    distinct calc DISTINCT.csv -o OUT.csv                   (--rows rows, every row its
                                                             own roller: random R, L/R,
                                                             load; issue 20, item 1)
    si       calc DISTINCT_SI.csv -o OUT.csv                (the same rollers and loads,
                                                             cells bare SI numbers)
    sweep    calc ... --load 100N:10kN:10000 -o OUT.txt     (all standard models)
    all      calc BENCH.csv --model all -o OUT.csv          (only with --all-models)

and prints the median wall time and the median CPU time (user + system of the child,
from ``resource.getrusage``) of each, and the ratio of each to ``one``, taken pair by
pair (interleaving keeps a ratio meaningful when the machine's speed drifts). Record
the results with the machine in tools/benchmarks/README.md.

The batch file (``--rows``, default 100 000) is what a spreadsheet of roller checks
looks like: ``--cylinders`` (default 100) distinct rollers (R from 1 to 20 mm, L/R from
0.5 to 5, steel on steel), each row a load between 100 N and 10 kN written with a unit
(``"123.4N"`` or ``"1.234kN"``), a name column and a free-text column kept as is.
The ``distinct`` file (always timed) makes every row its own cylinder, a parameter
study (random R, L/R and load, unit cells); the ``si`` file holds the same rollers
and loads as bare SI numbers (``0.010725``, ``2.1e+11``, ``1281``: 9 significant digits at most); ``--distinct``
makes the ``batch`` file distinct too (with ``--write-only``: write that file, with
``--si`` in SI numbers).

``--reference DIR`` also runs each file through the code of another checkout (for
example an export of the main branch: ``git archive main | tar -x -C DIR``) and
compares the output files byte for byte (the speed work must not change them).

Usage::

    python tools/benchmarks/bench_batch.py [-n 5] [--rows 100000] [--all-models]
    python tools/benchmarks/bench_batch.py --write-only --out /tmp/bench.csv

Runs in about N x (0.5 + 1.5 + 1) s on a quiet 2-core machine (about 5 s more per run
with ``--all-models``).
"""

from __future__ import annotations

import argparse
import csv
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
CASE = ["--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson", "0.3"]


def write_batch(path, rows=100_000, cylinders=100, distinct=False, seed=1, si=False):
    """Write the benchmark CSV to `path` (deterministic for a given seed); `si`: bare SI
    numbers in every cell instead of numbers with units."""
    rng = np.random.default_rng(seed)
    n_cyl = rows if distinct else cylinders
    radius_mm = np.round(rng.uniform(1.0, 20.0, n_cyl), 3)
    l_over_r = rng.uniform(0.5, 5.0, n_cyl)
    length_mm = np.round(radius_mm * l_over_r, 3)
    which = np.arange(rows) % n_cyl
    load = np.exp(rng.uniform(np.log(100.0), np.log(1e4), rows))
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "radius", "length", "modulus", "poisson", "modulus2",
                    "poisson2", "load", "comment"])
        for i in range(rows):
            c = which[i]
            F = load[i]
            if si:
                w.writerow([f"row {i}", f"{radius_mm[c] / 1e3:.9g}", f"{length_mm[c] / 1e3:.9g}",
                            "2.1e+11", "0.3", "2.1e+11", "0.3", f"{F:.4g}", "kept as is"])
                continue
            cell = f"{F / 1e3:.4g}kN" if F >= 1e3 else f"{F:.4g}N"
            w.writerow([f"row {i}", f"{radius_mm[c]:g}mm", f"{length_mm[c]:g}mm", "210GPa",
                        "0.3", "210GPa", "0.3", cell, "kept as is"])


def _run(cmd):
    """(wall s, cpu s) of one whole process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed (status {r.returncode}):\n{r.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def _compare(commands, reference):
    """Run every command that writes a file through the code in `reference` too and
    compare the two outputs byte for byte; exit with the first difference."""
    env = dict(os.environ, PYTHONPATH=str(reference))
    for name, cmd in commands.items():
        if "-o" not in cmd:
            continue
        out = Path(cmd[cmd.index("-o") + 1])
        ref = out.with_name("reference_" + out.name)
        ref_cmd = cmd[:cmd.index("-o") + 1] + [str(ref)] + cmd[cmd.index("-o") + 2:]
        subprocess.run(ref_cmd, cwd=reference, env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        if out.read_bytes() != ref.read_bytes():
            sys.exit(f"{name}: the output differs from the reference's ({out}, {ref})")
        print(f"{name}: output identical to the reference's ({out.stat().st_size} bytes)")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-n", type=int, default=5, help="runs of each command (default 5)")
    p.add_argument("--rows", type=int, default=100_000)
    p.add_argument("--cylinders", type=int, default=100)
    p.add_argument("--distinct", action="store_true", help="every row its own cylinder")
    p.add_argument("--all-models", action="store_true", help="also time --model all")
    p.add_argument("--out", help="where to write the CSV (default: a temporary folder)")
    p.add_argument("--write-only", action="store_true", help="write the CSV and stop")
    p.add_argument("--si", action="store_true", help="with --write-only: bare SI cells")
    p.add_argument("--reference", metavar="DIR",
                   help="also run the files through the checkout in DIR and compare the "
                        "outputs byte for byte")
    args = p.parse_args(argv)

    tmp = Path(tempfile.mkdtemp(prefix="lc_bench_"))
    bench = Path(args.out) if args.out else tmp / "bench.csv"
    write_batch(bench, args.rows, args.cylinders, args.distinct,
                si=args.si and args.write_only)
    print(f"wrote {args.rows} rows ({'distinct' if args.distinct else args.cylinders} "
          f"cylinders) to {bench}")
    if args.write_only:
        return
    distinct = tmp / "distinct.csv"
    write_batch(distinct, args.rows, distinct=True, seed=2)
    distinct_si = tmp / "distinct_si.csv"
    write_batch(distinct_si, args.rows, distinct=True, seed=2, si=True)
    py = [sys.executable, "-m", "linecontact", "calc"]
    commands = {
        "one": py + CASE + ["--load", "1kN"],
        "batch": py + [str(bench), "-o", str(tmp / "batch_out.csv")],
        "distinct": py + [str(distinct), "-o", str(tmp / "distinct_out.csv")],
        "si": py + [str(distinct_si), "-o", str(tmp / "si_out.csv")],
        "sweep": py + CASE + ["--load", "100N:10kN:10000", "-o", str(tmp / "sweep.txt")],
    }
    if args.all_models:
        commands["all"] = py + [str(bench), "--model", "all", "-o", str(tmp / "all.csv")]
    for cmd in commands.values():  # warm-up: disk cache, pint's cache, bytecode
        _run(cmd)
    if args.reference:
        _compare(commands, Path(args.reference).resolve())
    times = {name: [] for name in commands}
    for _ in range(args.n):
        for name, cmd in commands.items():
            times[name].append(_run(cmd))
    print(f"{'command':8} {'wall s':>8} {'cpu s':>8} {'wall/one':>9} {'cpu/one':>8}"
          f"   (medians of {args.n} interleaved runs)")
    for name in commands:
        wall = statistics.median(t[0] for t in times[name])
        cpu = statistics.median(t[1] for t in times[name])
        rw = statistics.median(a[0] / b[0] for a, b in zip(times[name], times["one"]))
        rc = statistics.median(a[1] / b[1] for a, b in zip(times[name], times["one"]))
        print(f"{name:8} {wall:8.3f} {cpu:8.3f} {rw:9.2f} {rc:8.2f}")
    print("commands (from the repository root):")
    for name, cmd in commands.items():
        print(f"  {name}: python {' '.join(cmd[1:])}")
    for f in tmp.iterdir():
        os.unlink(f)
    tmp.rmdir()


if __name__ == "__main__":
    main()
