"""Start-up cost of a one-case `linecontact calc`, as a ratio to `python -c "import numpy"`.

The command an engineer types for one case should cost about what any numpy script
costs, not what pandas or the whole of scipy cost (issue 11.6: within 2.5 times). This
script runs, interleaved, N times each:

    numpy      python -c "import numpy"                          (the yardstick)
    si         linecontact calc --radius 0.005 --length 0.01 --modulus 2.1e11
                 --poisson 0.3 --modulus2 2.1e11 --poisson2 0.3 --load 1000
    units      linecontact calc --radius 5mm --length 10mm --modulus 210GPa
                 --poisson 0.3 --modulus2 210GPa --poisson2 0.3 --load 1kN

and prints the median wall time of each and its ratio to the yardstick, and the median
of the per-round ratios (each round runs the three once, back to back, so a drift of the
machine's speed during the run cancels in them). By default linecontact runs as
``python -m linecontact`` from this checkout (the code under test, whatever is
installed; byte-compiled first, as an install is); ``--script`` times the console script installed next to this Python
instead. A ratio is portable where absolute times are not (disk cache, CPU); it is still
machine-dependent, so record the machine with it in tools/benchmarks/README.md.

Usage::

    python tools/benchmarks/bench_cli_startup.py [-n 20] [--importtime] [--script]

``--importtime`` also prints the ten slowest modules that linecontact imports
directly in the `units` command (``python -X importtime``), to see what a regression
pulled in. Runs in about N x 2 s.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
EXE = Path(sys.executable).parent / "linecontact"
MODULE = [sys.executable, "-m", "linecontact"]

ARGS = {
    "si": ["calc", "--radius", "0.005", "--length", "0.01", "--modulus", "2.1e11",
           "--poisson", "0.3", "--modulus2", "2.1e11", "--poisson2", "0.3",
           "--load", "1000"],
    "units": ["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
              "--poisson", "0.3", "--modulus2", "210GPa", "--poisson2", "0.3",
              "--load", "1kN"],
}


def commands(script=False):
    """The timed commands: the yardstick, then the two one-case calls."""
    launcher = [str(EXE)] if script else MODULE
    cmds = {"numpy": [sys.executable, "-c", "import numpy"]}
    cmds.update({name: launcher + args for name, args in ARGS.items()})
    return cmds


def _time(cmd):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                       cwd=REPO)
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{r.stderr}")
    return dt


def _slowest_imports(cmd, count=10):
    """What the command pulls in: modules that linecontact (or the script itself)
    imports directly, by cumulative import time, from ``python -X importtime``."""
    if cmd[0] == sys.executable:
        cmd = cmd[1:]
    r = subprocess.run(
        [sys.executable, "-X", "importtime", *cmd],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        cwd=REPO,
    )
    entries = []  # (nesting level, module, cumulative us), children before parents
    for line in r.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            _, cumulative, name = line.split("|")
            if cumulative.strip().isdigit():
                level = (len(name) - len(name.lstrip())) // 2
                entries.append((level, name.strip(), int(cumulative)))
    parent, pending = {}, []
    for i, (level, _, _) in enumerate(entries):
        while pending and entries[pending[-1]][0] > level:
            parent[pending.pop()] = i
        pending.append(i)
    rows = []
    for i, (_, name, cum) in enumerate(entries):
        by = entries[parent[i]][1] if i in parent else "(top level)"
        if not name.startswith("linecontact") and (
            by == "(top level)" or by.startswith("linecontact")
        ):
            rows.append((cum, name, by))
    return sorted(rows, reverse=True)[:count]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-n", type=int, default=20, help="runs per command (default 20)")
    parser.add_argument("--importtime", action="store_true", help="show the slowest imports")
    parser.add_argument("--script", action="store_true",
                        help="time the installed console script, not this checkout")
    args = parser.parse_args(argv)
    if args.script and not EXE.exists():
        sys.exit(f"{EXE} not found: install linecontact in this environment first")
    cmds = commands(args.script)
    if not args.script:
        # byte-compile the checkout, as pip does on install: under
        # PYTHONDONTWRITEBYTECODE=1 every run would otherwise recompile each module
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(REPO / "linecontact")],
                       check=True)

    for cmd in cmds.values():  # warm the disk cache (and pint's registry cache)
        _time(cmd)
    times = {name: [] for name in cmds}
    for _ in range(args.n):
        for name, cmd in cmds.items():
            times[name].append(_time(cmd))

    base = statistics.median(times["numpy"])
    print(f"python {sys.version.split()[0]}, {args.n} runs each, median wall time "
          f"({'console script' if args.script else 'python -m linecontact, this checkout'})")
    for name, ts in times.items():
        med = statistics.median(ts)
        paired = statistics.median(t / b for t, b in zip(ts, times["numpy"]))
        print(f"  {name:6s} {med * 1e3:7.1f} ms   ratio of medians: {med / base:5.2f}"
              f"   median of paired ratios: {paired:5.2f}")
    if args.importtime:
        print("what the 'units' command imports, slowest first (cumulative ms, importer):")
        for us, name, by in _slowest_imports(cmds["units"]):
            print(f"  {us / 1e3:7.1f}  {name:32s} {by}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
