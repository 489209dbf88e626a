"""A batch of profiled rollers: rows that share a roller solved together, against the
same rows solved one by one (issue 20, item 2).

The file (``--rows`` rows, default 200) holds ``--rollers`` distinct profiled rollers
(default 4: R, L, the profile and the tilt of each drawn once; steel on steel), each row
one of them at a load between 1 and 40 kN, rows in random order. ``linecontact calc``
groups the rows of one roller (:func:`linecontact.calc.compute.compute`: one Contact,
one :class:`linecontact.roller.ProfiledRoller`, its loads solved as one sweep in
increasing order, each from the previous solution). One by one, each row is a file of
its own (its own roller, a cold start).

Both run in this process (``linecontact.calc.cli.main`` with ``--json``, full
precision), interleaved ``--repeat`` times; printed: the CPU time of each (medians),
the ratio grouped / one by one (median of the pairs), and the largest relative
difference between the two answers, row by row, in depth, moment, tilt, stiffness,
peak pressure and contact length (the solver's tolerance is 1e-10 of F). Also timed:
the same one-row files without profile and tilt (a straight roller, the default law),
the calculator's own cost per call that one by one includes.

BLAS threads: one (``OPENBLAS_NUM_THREADS=1`` and its kin, unless set), as the other
roller benchmarks; on a shared machine, threads of a 100 x 100 dense solve wait for
each other (a profiled solve took 4 s instead of 30 ms under load).

Usage::

    python tools/benchmarks/bench_batch_profiled.py [--rows 200] [--rollers 4] [--repeat 3]
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # before numpy is imported

import argparse  # noqa: E402
import contextlib  # noqa: E402
import csv  # noqa: E402
import io  # noqa: E402
import json  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

HEADER = ["name", "radius", "length", "modulus", "poisson", "modulus2", "poisson2",
          "profile", "tilt", "load"]
PROFILES = ["iso16281", "circular:Rc=0.5", "lundberg:F0=20000", "end-relief:r=0.002"]
#: The quantities compared (JSON row keys, SI).
COMPARED = ("depth_m", "moment_N_m", "tilt_rad", "stiffness_N_per_m", "p_max_Pa",
            "contact_length_m")


def write_rows(path, rows=200, rollers=4, seed=3):
    """The benchmark CSV (deterministic for a seed); returns its rows (lists of cells)."""
    rng = np.random.default_rng(seed)
    radius = np.round(rng.uniform(5.0, 12.0, rollers), 2)
    length = np.round(radius * rng.uniform(1.5, 2.5, rollers), 2)
    tilt = np.round(rng.uniform(0.0, 0.5, rollers), 2)
    which = rng.permutation(np.arange(rows) % rollers)
    load = np.round(np.exp(rng.uniform(np.log(1e3), np.log(4e4), rows)), -1)
    out = []
    for i in range(rows):
        k = which[i]
        out.append([f"row {i}", f"{radius[k]:g}mm", f"{length[k]:g}mm", "210GPa", "0.3",
                    "210GPa", "0.3", PROFILES[k % len(PROFILES)], f"{tilt[k]:g}mrad",
                    f"{load[i]:g}N"])
    _write(path, out)
    return out


def _write(path, rows):
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(HEADER)
        w.writerows(rows)


def _calc(path, out):
    """Run ``linecontact calc PATH --json -o OUT`` in this process; its JSON rows."""
    from linecontact.calc.cli import main

    with contextlib.redirect_stderr(io.StringIO()):
        status = main(["calc", str(path), "--json", "-o", str(out)])
    if status != 0:
        sys.exit(f"calc {path} failed (status {status})")
    return json.loads(Path(out).read_text(encoding="utf-8"))["rows"]


def grouped(path, folder):
    t = time.process_time()
    rows = _calc(path, folder / "grouped.json")
    return time.process_time() - t, rows


def one_by_one(rows, folder, plain=False):
    """Each row a file of its own; `plain`: without its profile and tilt (a straight
    roller, the default law: the calculator's own cost per call, no slice solve)."""
    files = []
    for i, r in enumerate(rows):
        f = folder / f"{'plain' if plain else 'row'}{i}.csv"
        _write(f, [r[:7] + ["", ""] + r[9:]] if plain else [r])
        files.append(f)
    t = time.process_time()
    out = [_calc(f, folder / "one.json")[0] for f in files]
    return time.process_time() - t, out


def largest_difference(a_rows, b_rows):
    """Largest |a/b - 1| per compared quantity (|a - b| / scale where b is zero)."""
    worst = {}
    for a, b in zip(a_rows, b_rows):
        for k in COMPARED:
            x, y = a.get(k), b.get(k)
            if x is None or y is None:
                if (x is None) != (y is None):
                    worst[k] = float("inf")
                continue
            scale = abs(y) if y else 1.0
            worst[k] = max(worst.get(k, 0.0), abs(x - y) / scale)
    return worst


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rows", type=int, default=200)
    p.add_argument("--rollers", type=int, default=4)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args(argv)
    folder = Path(tempfile.mkdtemp(prefix="lc_bench_profiled_"))
    path = folder / "profiled.csv"
    rows = write_rows(path, args.rows, args.rollers)
    grouped(path, folder)  # warm-up: imports, tables
    times = []
    for _ in range(args.repeat):
        tg, g_rows = grouped(path, folder)
        to, o_rows = one_by_one(rows, folder)
        tp, _ = one_by_one(rows, folder, plain=True)
        times.append((tg, to, tp))
    tg = statistics.median(t[0] for t in times)
    to = statistics.median(t[1] for t in times)
    tp = statistics.median(t[2] for t in times)
    ratio = statistics.median(t[0] / t[1] for t in times)
    print(f"{args.rows} profiled rows, {args.rollers} rollers "
          f"({', '.join(PROFILES[k % len(PROFILES)] for k in range(args.rollers))}), "
          f"{args.repeat} interleaved pairs, CPU s (medians):")
    print(f"  grouped (one sweep per roller)  {tg:8.3f}  ({tg / args.rows * 1e3:.2f} ms a row)")
    print(f"  one by one (a file per row)     {to:8.3f}  ({to / args.rows * 1e3:.2f} ms a row)")
    print(f"  ratio grouped / one by one      {ratio:8.3f}")
    print(f"  (a file per row without the profile and tilt, the calculator's own cost: "
          f"{tp:.3f}, {tp / args.rows * 1e3:.2f} ms a row)")
    worst = largest_difference(g_rows, o_rows)
    print("largest relative difference grouped vs one by one: "
          + ", ".join(f"{k} {v:.1e}" for k, v in worst.items()))
    for f in folder.iterdir():
        f.unlink()
    folder.rmdir()


if __name__ == "__main__":
    main()
