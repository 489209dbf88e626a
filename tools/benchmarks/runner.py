"""The benchmark runner: ``python -m tools.benchmarks [NAME ...] [--repeat N]
[--against REF] [--record]`` (tools/benchmarks/README.md).

Every benchmark (a function of tools/benchmarks/suite.py) runs in a child process
whose working directory and first path entry are the checkout under test, with one
BLAS/OpenMP thread; it prints its figures as one JSON line, which this process
collects and prints as a table.

``--against REF`` times two commits in one run: REF is checked out with ``git worktree
add --detach`` in a temporary folder (its C extensions built in place, where it has a
setup.py), and the benchmark runs ``--repeat`` rounds, each a child on this checkout
and a child on REF, in alternating order (A B, B A, ...), one sample each; the ratio
this/REF of every figure is the median of the rounds' ratios, so that a drift of a
shared machine's speed cancels in it. The functions are this checkout's, the code they
time each checkout's own.

``--record`` writes each benchmark's figures to tools/benchmarks/results/NAME.txt (one
current record per benchmark, the command, commit, machine and date in its header;
git keeps the earlier ones).
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HOME = Path(__file__).resolve().parent            # tools/benchmarks
REPO = HOME.parents[1]
RESULTS = HOME / "results"
CHILD = HOME / "_child.py"


def _suite():
    import importlib.util

    spec = importlib.util.spec_from_file_location("lc_bench_suite", HOME / "suite.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _run_child(root, name, repeat):
    """The figures of benchmark `name` on the checkout `root` ({label: [value, unit]},
    or None where it was skipped)."""
    env = dict(os.environ, PYTHONPATH=str(root), LC_BENCH_HOME=str(HOME),
               PYTHONDONTWRITEBYTECODE="1")
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env[var] = "1"
    r = subprocess.run([sys.executable, str(CHILD), name, str(repeat)], cwd=root, env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in r.stderr.splitlines():
        if line.strip():
            print(f"  [{name}] {line}", file=sys.stderr)
    if r.returncode != 0:
        raise SystemExit(f"benchmark {name} failed on {root} (status {r.returncode})")
    return json.loads(r.stdout.strip().splitlines()[-1])


def _fmt(v):
    if v is None:
        return "-"
    a = abs(v)
    if a >= 100:
        return f"{v:.0f}"
    if a != 0 and a < 1e-3:
        return f"{v:.2g}"
    return f"{v:.3g}"


def _git(*args, cwd=REPO):
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True,
                          check=True).stdout.strip()


def _machine():
    load = " ".join(f"{x:.1f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") \
        else "?"
    import numpy
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            cpu = next(ln.split(":", 1)[1].strip() for ln in fh if ln.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return (f"{cpu}, {os.cpu_count()} cores, {platform.system()} "
            f"{platform.release()}; Python {platform.python_version()}, numpy "
            f"{numpy.__version__}; load average at the end {load}")


def _commit():
    head = _git("rev-parse", "--short", "HEAD")
    dirty = _git("status", "--porcelain", "--untracked-files=no")
    return head + (" with uncommitted changes" if dirty else "")


def _table(figures):
    lines = ["| figure | value | unit |", "|---|---|---|"]
    for label, (value, unit) in figures.items():
        lines.append(f"| {label} | {_fmt(value)} | {unit} |")
    return lines


def _checkout(ref, folder):
    """A detached worktree of `ref` in `folder`, its C extensions built in place."""
    _git("worktree", "add", "--detach", str(folder), ref)
    if (folder / "setup.py").exists():
        r = subprocess.run([sys.executable, "setup.py", "-q", "build_ext", "--inplace"],
                           cwd=folder, capture_output=True, text=True)
        if r.returncode != 0:
            print(f"{ref}: C extensions not built (status {r.returncode}); it runs "
                  "without them", file=sys.stderr)


def _paired_rounds(name, folder, repeat):
    """`repeat` rounds of one child on this checkout and one on `folder`, in
    alternating order; None where the benchmark is skipped."""
    rounds = []
    order = (("this", REPO), ("ref", folder))
    for i in range(repeat):
        pair = {}
        for side, root in (order if i % 2 == 0 else order[::-1]):
            pair[side] = _run_child(root, name, 1)
            if pair[side] is None:
                return None
        rounds.append(pair)
    return rounds


def _against(names, ref, repeat):
    """Each benchmark of `names` on this checkout and on the commit `ref`, paired."""
    sha = _git("rev-parse", "--short", ref)
    with tempfile.TemporaryDirectory(prefix="lc_bench_ref_") as tmp:
        folder = Path(tmp) / "ref"
        _checkout(ref, folder)
        try:
            for name in names:
                rounds = _paired_rounds(name, folder, repeat)
                if rounds is None:
                    print(f"## {name}: skipped\n")
                    continue
                print(f"## {name}: this checkout ({_commit()}) against {ref} ({sha}), "
                      f"{repeat} rounds, alternating\n")
                print(f"| figure | this | {ref} | this / {ref} (median of rounds) |")
                print("|---|---|---|---|")
                for label, (_, unit) in rounds[0]["this"].items():
                    a = [p["this"][label][0] for p in rounds]
                    b = [p["ref"][label][0] for p in rounds if label in p["ref"]]
                    ratio = [x / p["ref"][label][0] for x, p in zip(a, rounds)
                             if label in p["ref"] and p["ref"][label][0]]
                    row = f"{label} [{unit}]" if unit else label
                    print(f"| {row} | {_fmt(statistics.median(a))} | "
                          f"{_fmt(statistics.median(b)) if b else '-'} | "
                          f"{_fmt(statistics.median(ratio)) if ratio else '-'} |")
                print()
        finally:
            _git("worktree", "remove", "--force", str(folder))


def _summary(func, width=60):
    words = " ".join(func.__doc__.split())
    return words if len(words) <= width else words[:width].rsplit(" ", 1)[0] + " ..."


def main(argv=None):
    suite = _suite()
    names = list(suite.BENCHMARKS)
    listing = "\n".join(
        f"  {n:17s} {_summary(f)} (default --repeat {r})"
        for n, (f, r) in suite.BENCHMARKS.items())
    ap = argparse.ArgumentParser(
        prog="python -m tools.benchmarks",
        description="Run linecontact's benchmarks (tools/benchmarks/README.md).",
        epilog="benchmarks:\n" + listing,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("names", nargs="*", metavar="NAME",
                    help="benchmarks to run (default: all)")
    ap.add_argument("--repeat", type=int, default=None,
                    help="samples per benchmark (default: each benchmark's own); with "
                         "--against, rounds of paired children")
    ap.add_argument("--against", metavar="REF",
                    help="also time the commit REF (a git ref) and print the ratios")
    ap.add_argument("--record", action="store_true",
                    help="write each benchmark's figures to tools/benchmarks/results/"
                         "NAME.txt")
    a = ap.parse_args(argv)
    for n in a.names:
        if n not in names:
            ap.error(f"benchmark {n!r} is not one of: {', '.join(names)}")
    if a.repeat is not None and a.repeat < 1:
        ap.error(f"--repeat {a.repeat}: must be 1 or more")
    if a.record and a.against:
        ap.error("--record writes this checkout's figures; run it without --against")
    chosen = a.names or names
    if a.against:
        _against(chosen, a.against, a.repeat or 3)
        return 0
    for name in chosen:
        func, default = suite.BENCHMARKS[name]
        repeat = a.repeat or default
        figures = _run_child(REPO, name, repeat)
        if figures is None:
            print(f"## {name}: skipped\n")
            continue
        figures = {k: tuple(v) for k, v in figures.items()}
        command = f"python -m tools.benchmarks {name} --repeat {repeat}"
        head = [f"# {name}: {' '.join(func.__doc__.split())}",
                f"# command: {command} --record",
                f"# commit {_commit()}; "
                f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC",
                f"# machine: {_machine()}"]
        body = _table(figures)
        print(f"## {name} ({command})\n")
        print("\n".join(body) + "\n")
        if a.record:
            RESULTS.mkdir(exist_ok=True)
            (RESULTS / f"{name}.txt").write_text("\n".join(head + [""] + body) + "\n",
                                                 encoding="utf-8")
            print(f"(recorded in {(RESULTS / f'{name}.txt').relative_to(REPO)})\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
