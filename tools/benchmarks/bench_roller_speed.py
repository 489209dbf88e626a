"""Issue 20, item 2: the time of one profiled-roller solve, of a load sweep on one roller,
and of the coarse 3D BEM on the same case (CPU time, medians).

    OPENBLAS_NUM_THREADS=1 python -m tools.benchmarks.bench_roller_speed [--repeat 30]
        [--sweep 20] [--bem-repeat 3] [--no-bem] [--n-slices N] [--engine E]
        [--against DIR [--rounds 2 | --interleave]] [--kernels]

The case: the ISO 16281 profile of tables/roller_accuracy.csv (D = 10 mm, L = 14 mm,
E* = 115.385 GPa), 4200 N (300 N/mm), tilt 2 mrad given (the table's case whose peak
pressure was 3 % off with 100 uniform slices), and the same at a free (zero-moment)
tilt. Measured:

1. one solve, cold: a new ``ProfiledRoller`` (the version's default slices, 50 since
   issue 20's fourth round and 100 before, or ``--n-slices``) and ``at_force``,
   ``--repeat`` times, median CPU time (``time.process_time``: on a shared, loaded
   machine what other jobs do not inflate; single-threaded BLAS);
2. a load sweep: ``at_force`` of ``--sweep`` forces from 100 to 2000 N/mm on one roller
   (the array call, solved in increasing order, each from its neighbour's solution),
   against as many cold solves of the same forces: the ratio of CPU times;
3. the coarse 3D BEM (tools/bem/roller.py ``solve_roller_force``, 128 x 32 cells, one
   FFT thread, the coarser grid of the accuracy study) on the same case: median CPU of
   ``--bem-repeat`` solves, and the ratio BEM / one solve.

Runs against any checkout whose ``linecontact`` is first on the path (it uses only
``ProfiledRoller(R, L, E*, profile, n_slices=...)`` and ``at_force``), so that the
same command times an older version for a paired comparison. ``--against DIR`` does
that pairing itself: it runs this command (without ``--against``) in turn on this
checkout and on the checkout DIR (each in a fresh process with its own directory first
on ``PYTHONPATH``), ``--rounds`` times each, A B A B, and prints the ratios of the
one-solve medians round by round and their median. ``--no-refine`` solves with
``refine_ends=False`` (the solver alone, without the end refinement's re-solves;
only for versions that have that option). ``--engine E`` passes ``engine=E`` to
``ProfiledRoller`` (only where given, so that the same command still times versions
without engines; with ``--against`` the other checkout gets it too where its own
script takes ``--engine``, else it runs its own default). ``--kernels`` instead
prints what the C engine costs to load (in a fresh process) and
the per-call time of ``SliceEquations.kernels`` and ``.linearised`` with each engine
(numpy, and c where its extension is built), and whole solves with the engines
alternating in one process.
``--against DIR --interleave`` instead alternates the two checkouts' solves within one
process (DIR's ``linecontact`` copied to a temporary directory and imported as
``linecontact_b``, which works as long as the package imports itself relatively):
the machine's drift between processes, which moves medians of separate runs by 1.5x
on a shared VM, then leaves the ratio alone. It prints, per tilt, both medians and the
median of the --repeat pair ratios (``--engine`` goes to both checkouts).
"""
from __future__ import annotations

import argparse
import contextlib
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

D, L, ESTAR = 10e-3, 14e-3, 115.385e9
FORCE, TILT = 4200.0, 2e-3


@contextlib.contextmanager
def other_checkout(path):
    """The package ``linecontact`` of the checkout `path` importable as
    ``linecontact_b`` for the duration (copied to a temporary directory put first on
    sys.path; which works as long as the package imports itself relatively): the
    ``--interleave`` pairing here and in bench_roller_parts.py and bench_roller_step.py.
    Yields the name."""
    import shutil
    import tempfile
    tmp = tempfile.mkdtemp()
    try:
        shutil.copytree(Path(path).resolve() / "linecontact", Path(tmp) / "linecontact_b",
                        ignore=shutil.ignore_patterns("__pycache__"))
        sys.path.insert(0, tmp)
        yield "linecontact_b"
    finally:
        if tmp in sys.path:
            sys.path.remove(tmp)
        shutil.rmtree(tmp, ignore_errors=True)


@contextlib.contextmanager
def checkout_packages(against=None):
    """The package names to time: ``["linecontact"]``, and with a second checkout
    `against` also ``"linecontact_b"`` (:func:`other_checkout`, for the duration)."""
    if against is None:
        yield ["linecontact"]
        return
    with other_checkout(against) as name:
        yield ["linecontact", name]


def _cpu(fn, repeat):
    ts = []
    out = None
    for _ in range(repeat):
        c0 = time.process_time()
        out = fn()
        ts.append(time.process_time() - c0)
    return statistics.median(ts), out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=30)
    ap.add_argument("--sweep", type=int, default=20)
    ap.add_argument("--bem-repeat", type=int, default=3)
    ap.add_argument("--no-bem", action="store_true")
    ap.add_argument("--n-slices", type=int, default=None,
                    help="slice count (default: the checkout's own default)")
    ap.add_argument("--no-refine", action="store_true")
    ap.add_argument("--against", default=None, metavar="DIR")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--engine", default=None, choices=("auto", "numpy", "c"))
    ap.add_argument("--kernels", action="store_true")
    ap.add_argument("--interleave", action="store_true")
    a = ap.parse_args(argv)
    if a.against and a.interleave:
        return _interleaved(a)
    if a.against:
        return _paired(a, argv if argv is not None else sys.argv[1:])
    if a.kernels:
        return _kernel_costs(a)
    extra = {"refine_ends": False} if a.no_refine else {}
    if a.engine is not None:                # only where given: older versions lack it
        extra["engine"] = a.engine
    if a.n_slices is not None:
        extra["n_slices"] = a.n_slices

    import linecontact
    from linecontact.roller import ProfiledRoller
    from tools.studies import roller_study as rs

    R = D / 2
    prof = rs.make_profile("iso16281", L, R, ESTAR)

    def cold(force, tilt):
        return ProfiledRoller(R, L, ESTAR, prof, **extra).at_force(force, tilt=tilt)

    cold(FORCE, TILT)                      # the strip-function table, built once
    print(f"linecontact from {os.path.relpath(linecontact.__file__)}")
    print(f"case: ISO 16281 profile, D {D * 1e3:g} mm, L {L * 1e3:g} mm, F {FORCE:g} N, "
          f"{a.n_slices or 'default'} slices (default spacing of this version)"
          + (", refine_ends=False" if a.no_refine else "")
          + (f", engine={a.engine}" if a.engine else ""))
    rows = {}
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        t, s = _cpu(lambda: cold(FORCE, tilt), a.repeat)
        rows[label] = t
        pm = "-" if s.p_max is None else f"{s.p_max / 1e6:.1f} MPa"
        print(f"one solve, cold, {label}: CPU median {t * 1e3:.2f} ms over {a.repeat} "
              f"(depth {s.depth * 1e6:.5f} um, M {s.moment:.5f} N m, tilt "
              f"{s.tilt * 1e3:.5f} mrad, p_max {pm}, slice solves {s.iterations})")

    forces = np.linspace(100e3, 2000e3, a.sweep) * L
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        def sweep():
            return ProfiledRoller(R, L, ESTAR, prof, **extra).at_force(forces, tilt=tilt)

        def singles():
            return [cold(f, tilt) for f in forces]

        ts, sw = _cpu(sweep, 3)
        tc, one = _cpu(singles, 3)
        dev = max(abs(x.depth / y.depth - 1) for x, y in zip(sw, one))
        print(f"sweep of {a.sweep} forces ({forces[0]:g}-{forces[-1]:g} N), {label}: "
              f"CPU {ts * 1e3:.1f} ms, {a.sweep} cold solves {tc * 1e3:.1f} ms, ratio "
              f"{ts / tc:.2f} (largest depth difference {dev:.1e})")

    if not a.no_bem:
        from tools.bem.roller import solve_roller_force

        for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", None)):
            tb, r = _cpu(lambda: solve_roller_force(R, L, ESTAR, FORCE, tilt=tilt,
                                                    profile=prof, n_x=128, n_y=32,
                                                    workers=1), a.bem_repeat)
            print(f"coarse 3D BEM 128 x 32, {label}: CPU median {tb * 1e3:.0f} ms over "
                  f"{a.bem_repeat}; ratio BEM / one solve {tb / rows[label]:.0f}")
    return 0


def _kernel_costs(a):
    """--kernels: what the C engine costs and saves: loading it in a fresh process,
    per call (SliceEquations.kernels and .linearised, numpy against c, on the slice
    grid of the converged 2 mrad solve: CPU medians of --repeat x 20 calls) and per
    solve (--repeat rounds, the engines alternating)."""
    import json

    slices = {} if a.n_slices is None else {"n_slices": a.n_slices}

    probe = (
        "import json, os, time\n"
        "c = time.process_time()\n"
        "from linecontact.roller import ProfiledRoller\n"
        "from tools.studies import roller_study as rs\n"
        "prof = rs.make_profile('iso16281', %r, %r, %r)\n"
        "t = {}\n"
        "c0 = time.process_time()\n"
        "ProfiledRoller(%r, %r, %r, prof, engine='numpy').at_force(%r, tilt=%r)\n"
        "t['first numpy solve'] = time.process_time() - c0\n"
        "c0 = time.process_time()\n"
        "from linecontact.roller import slices\n"
        "if slices.c_engine() is not None:\n"
        "    t['import the C engine'] = time.process_time() - c0\n"
        "    c0 = time.process_time()\n"
        "    ProfiledRoller(%r, %r, %r, prof, engine='c').at_force(%r, tilt=%r)\n"
        "    t['first c solve'] = time.process_time() - c0\n"
        "print(json.dumps(t))\n"
    ) % ((L, D / 2, ESTAR) + (D / 2, L, ESTAR, FORCE, TILT) * 2)
    rows = [json.loads(subprocess.run([sys.executable, "-c", probe], capture_output=True,
                                      text=True, check=True).stdout) for _ in range(3)]
    med = {k: statistics.median(r[k] for r in rows) for k in rows[0]}
    print("fresh process: " + ", ".join(f"{k} {v * 1e3:.0f} ms" for k, v in med.items())
          + f" (median of {len(rows)})")

    from linecontact.roller import ProfiledRoller
    from linecontact.roller import slices as sl
    from tools.studies import roller_study as rs

    engines = ["numpy"]
    if getattr(sl, "c_engine", lambda: None)() is not None:
        engines.append("c")
    prof = rs.make_profile("iso16281", L, D / 2, ESTAR)
    roller = ProfiledRoller(D / 2, L, ESTAR, prof, engine="numpy", **slices)
    sol = roller.at_force(FORCE, tilt=TILT)
    times = {}
    for engine in engines:
        s = roller._grid(sol.depth, sol.tilt)
        s.engine = engine
        q = np.interp(s.x, sol.x, sol.q) / (np.pi * ESTAR)
        S = np.flatnonzero(q > 0)
        c = np.full(s.n, 1.0 / (4 * s.R))
        b = np.sqrt(4 * s.R * q[S])
        c[S] = q[S] / b ** 2
        s._over = sol.depth + sol.tilt * s.x - s.P
        slope = s.slope_at_slices()
        every = np.arange(s.n)
        s.linearised(S, q, c, sol.tilt, slope, every)     # compiled: loaded once
        for name, fn in (("kernels", lambda: s.kernels(S, b)),
                         ("linearised", lambda: s.linearised(S, q, c, sol.tilt, slope,
                                                             every))):
            t, _ = _cpu(lambda: [fn() for _ in range(20)], a.repeat)
            times[(name, engine)] = t / 20
    print(f"per call, {s.n} slices, {len(S)} loaded (CPU median over {a.repeat} x 20):")
    for name in ("kernels", "linearised"):
        tn = times[(name, "numpy")]
        print(f"  {name}: numpy {tn * 1e6:.0f} us, "
              + ", ".join(f"{e} {times[(name, e)] * 1e6:.0f} us" for e in engines[1:])
              + "; ratio to numpy "
              + ", ".join(f"{e} {times[(name, e)] / tn:.3f}" for e in engines[1:]))
    # whole solves, the engines alternating in this one process (their order reversed
    # every other round), so that the machine's drift between processes does not
    # enter the ratios
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        ts = {e: [] for e in engines}
        for i in range(a.repeat):
            for engine in (engines if i % 2 == 0 else engines[::-1]):
                c0 = time.process_time()
                ProfiledRoller(D / 2, L, ESTAR, prof, **slices,
                               engine=engine).at_force(FORCE, tilt=tilt)
                ts[engine].append(time.process_time() - c0)
        med = {e: statistics.median(ts[e]) * 1e3 for e in engines}
        print(f"one solve, {label}, engines alternating in one process ({a.repeat} "
              f"rounds): CPU median " + ", ".join(f"{e} {med[e]:.2f} ms" for e in engines))
        for e in engines[1:]:
            ratios = [b / n for b, n in zip(ts[e], ts["numpy"])]
            print(f"  ratio {e}/numpy median of pairs {statistics.median(ratios):.3f} "
                  f"(quartiles {np.percentile(ratios, 25):.3f}-"
                  f"{np.percentile(ratios, 75):.3f})")
    return 0


def _interleaved(a):
    """--against DIR --interleave: this checkout (A) and DIR (B) in one process, their
    cold solves alternating (A B, then B A), --repeat pairs per tilt."""
    import importlib
    import inspect

    import linecontact
    from tools.studies import roller_study as rs

    other = Path(a.against).resolve()
    with other_checkout(other):
        roller_b = importlib.import_module("linecontact_b.roller")
        profiles_b = importlib.import_module("linecontact_b.profiles")
        from linecontact import profiles as profiles_a
        from linecontact import roller as roller_a
        extra = {} if a.engine is None else {"engine": a.engine}
        if a.n_slices is not None:
            extra["n_slices"] = a.n_slices
        # an older checkout without engines solves with its only (numpy) code
        takes = inspect.signature(roller_b.ProfiledRoller).parameters
        extra_b = {k: v for k, v in extra.items() if k in takes}
        prof_a = rs.make_profile("iso16281", L, D / 2, ESTAR)
        # the same profile built by the other checkout (its own classes)
        prof_b = getattr(profiles_b, type(prof_a).__name__)(L, D)
        print(f"A = {Path(linecontact.__file__).parents[1].name}, B = {other.name} "
              f"(imported as linecontact_b), engine={a.engine or 'default'}"
              f"{'' if 'engine' in extra_b or a.engine is None else ' (B: none, its numpy code)'}, "
              f"{a.repeat} pairs per tilt, alternating in one process")
        for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
            def one(mod, prof, kw):
                return mod.ProfiledRoller(D / 2, L, ESTAR, prof, **kw).at_force(
                    FORCE, tilt=tilt)
            runs = {"A": (roller_a, prof_a, extra), "B": (roller_b, prof_b, extra_b)}
            for k in "AB":                      # tables, caches, compiled code loaded
                one(*runs[k])
            ts = {"A": [], "B": []}
            sol = {}
            for i in range(a.repeat):
                for k in ("AB" if i % 2 == 0 else "BA"):
                    c0 = time.process_time()
                    sol[k] = one(*runs[k])
                    ts[k].append(time.process_time() - c0)
            ratios = [x / y for x, y in zip(ts["A"], ts["B"])]
            dev = abs(sol["A"].depth / sol["B"].depth - 1)
            ta, tb = (statistics.median(ts[k]) * 1e3 for k in "AB")
            print(f"interleaved, one solve, {label}: CPU median A {ta:.2f} ms "
                  f"({sol['A'].iterations} steps), B {tb:.2f} ms "
                  f"({sol['B'].iterations} steps); ratio A/B median of pairs "
                  f"{statistics.median(ratios):.3f} (quartiles "
                  f"{np.percentile(ratios, 25):.3f}-{np.percentile(ratios, 75):.3f}); "
                  f"depth A/B - 1 = {dev:.1e}")
    return 0


def _paired(a, argv):
    """This command on this checkout (A) and on the checkout a.against (B), in turn,
    a.rounds times each; the ratios A/B of the one-solve medians."""
    here = Path(__file__).resolve().parents[2]
    other = Path(a.against).resolve()
    args, skip = [], False
    for v in argv:                             # the same options, less --against/--rounds
        if skip:
            skip = False
            continue
        if v in ("--against", "--rounds", "--engine"):
            skip = True
            continue
        if v.startswith(("--against=", "--rounds=", "--engine=")):
            continue
        args.append(v)
    mine = args + (["--engine", a.engine] if a.engine else [])
    # the other checkout gets the engine too where its script knows the option
    theirs = mine if "--engine" in (
        other / "tools" / "benchmarks" / "bench_roller_speed.py").read_text() else args
    pat = re.compile(r"one solve, cold, (.+?): CPU median ([\d.]+) ms")
    ratios = {}
    for r in range(a.rounds):
        got = {}
        for name, root in (("A", here), ("B", other)):
            env = dict(os.environ, PYTHONPATH=str(root))
            out = subprocess.run([sys.executable, "-m", "tools.benchmarks.bench_roller_speed",
                                  *(mine if name == "A" else theirs)], cwd=root, env=env,
                                 capture_output=True, text=True, check=True).stdout
            print(f"--- round {r + 1}, {name} = {root.name}:")
            print(out.rstrip())
            got[name] = {k: float(v) for k, v in pat.findall(out)}
        for k in got["A"]:
            ratios.setdefault(k, []).append(got["A"][k] / got["B"][k])
    for k, v in ratios.items():
        print(f"paired ratio A/B, one solve, {k}: rounds "
              + ", ".join(f"{x:.3f}" for x in v) + f"; median {statistics.median(v):.3f}"
              f" (B/A {1 / statistics.median(v):.1f} x)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
