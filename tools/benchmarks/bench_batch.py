"""Batch speed of ``linecontact calc`` (issue 11, item 5): write the benchmark inputs.

The measurement itself is whole-process wall time, taken from outside (for instance
``/usr/bin/time -v``, or any tool that runs two commands in turn and reports the ratio
of their medians): a 100 000-row batch against a one-case call, and a 10 000-point
sweep against the same one-case call. This script writes the batch file and prints the
three commands; the results are recorded in tools/benchmarks/README.md.

The batch (``--rows``, default 100 000) is what a spreadsheet of roller checks looks
like: ``--cylinders`` (default 100) distinct rollers (R from 1 to 20 mm, L/R from 0.5
to 5, steel on steel), each row a load between 100 N and 10 kN written with a unit
(``"123.4N"`` or ``"1.234kN"``), a name column and a free-text column kept as is.
``--distinct`` makes every row its own cylinder: the worst case, one model object
per row.

Usage::

    python tools/benchmarks/bench_batch.py --out /tmp/bench.csv   # writes the file
    python -m linecontact calc /tmp/bench.csv -o /tmp/bench_out.csv
    python -m linecontact calc --radius 5mm --length 10mm --modulus 210GPa \
        --poisson 0.3 --load 1kN
    python -m linecontact calc --radius 5mm --length 10mm --modulus 210GPa \
        --poisson 0.3 --load 100N:10kN:10000 -o /tmp/sweep.txt
"""

from __future__ import annotations

import argparse
import csv

import numpy as np


def write_batch(path, rows=100_000, cylinders=100, distinct=False, seed=1):
    """Write the benchmark CSV to `path` (deterministic for a given seed)."""
    rng = np.random.default_rng(seed)
    n_cyl = rows if distinct else cylinders
    radius_mm = np.round(rng.uniform(1.0, 20.0, n_cyl), 3)
    l_over_r = rng.uniform(0.5, 5.0, n_cyl)
    length_mm = np.round(radius_mm * l_over_r, 3)
    which = np.arange(rows) % n_cyl
    load = rng.uniform(np.log(100.0), np.log(1e4), rows)
    load = np.exp(load)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "radius", "length", "modulus", "poisson", "modulus2",
                    "poisson2", "load", "comment"])
        for i in range(rows):
            c = which[i]
            F = load[i]
            cell = f"{F / 1e3:.4g}kN" if F >= 1e3 else f"{F:.4g}N"
            w.writerow([f"row {i}", f"{radius_mm[c]:g}mm", f"{length_mm[c]:g}mm", "210GPa",
                        "0.3", "210GPa", "0.3", cell, "kept as is"])


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default="/tmp/linecontact_bench.csv", help="CSV to write")
    p.add_argument("--rows", type=int, default=100_000)
    p.add_argument("--cylinders", type=int, default=100)
    p.add_argument("--distinct", action="store_true", help="every row its own cylinder")
    args = p.parse_args(argv)
    write_batch(args.out, args.rows, args.cylinders, args.distinct)
    print(f"wrote {args.rows} rows to {args.out}")


if __name__ == "__main__":
    main()
