"""The benchmarks: one function per hot path of linecontact (and of its 3D BEM).

Each function ``NAME(repeat)`` times its workload ``repeat`` times and returns its
figures, ``{label: (value, unit)}``: medians of the ``repeat`` samples, and ratios that
carry from one machine to another better than absolute times do (to ``import numpy``,
to a one-case call, to the numpy engine). CPU time (``time.process_time``, or the
child's user + system time for whole processes) where one core's work is meant: on a
shared machine other jobs inflate wall time, not CPU time.

This module imports only the standard library, numpy, ``linecontact`` and ``tools.bem``
/ ``tools.studies`` through their public names, and those inside the functions: the
runner (tools/benchmarks/runner.py) loads it by its file path in a child process whose
path starts at the checkout under test, so that the same functions time another
commit's code (``--against REF``). A function returns ``None`` (and prints why) when
what it measures is not there (an optional package missing).
"""
from __future__ import annotations

import contextlib
import csv
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

#: the checkout under test (the child's working directory, first on its path)
ROOT = Path.cwd()

#: the one-case command of the README's main job
ONE_CASE = ["--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson",
            "0.3", "--modulus2", "210GPa", "--poisson2", "0.3", "--load", "1kN"]
ONE_CASE_SI = ["--radius", "0.005", "--length", "0.01", "--modulus", "2.1e11",
               "--poisson", "0.3", "--modulus2", "2.1e11", "--poisson2", "0.3",
               "--load", "1000"]

#: the profiled roller of ISO 16281 (tables/roller_accuracy.csv): D 10 mm, L 14 mm,
#: E* 115.385 GPa, 4200 N (300 N/mm), tilt 2 mrad given or free
D, L, ESTAR, FORCE, TILT = 10e-3, 14e-3, 115.385e9, 4200.0, 2e-3

#: engine names tried on ProfiledRoller(engine=...); those the checkout refuses are
#: skipped with their reason
ENGINES = ("numpy", "c")


def _median(xs):
    return float(statistics.median(xs))


def _cpu(fn, repeat):
    """Median CPU time of `repeat` calls of fn() [s]."""
    ts = []
    for _ in range(repeat):
        c0 = time.process_time()
        fn()
        ts.append(time.process_time() - c0)
    return _median(ts)


def _process(cmd):
    """(wall s, CPU s) of one whole process run in the checkout; exits on failure."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed (status {r.returncode}):\n{r.stderr}")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


# ------------------------------------------------------------------ CLI start-up
def cli_startup(repeat):
    """Wall time of a one-case ``linecontact calc`` (``python -m linecontact``, the
    checkout byte-compiled first as an install is) against ``python -c "import
    numpy"``, interleaved; the ratio is the median of the rounds' ratios (target:
    within 2.5, issue 11)."""
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "linecontact")],
                   check=True)
    py = [sys.executable, "-m", "linecontact", "calc"]
    cmds = {"import numpy": [sys.executable, "-c", "import numpy"],
            "one case, SI numbers": py + ONE_CASE_SI, "one case, units": py + ONE_CASE}
    for cmd in cmds.values():
        _process(cmd)                       # warm the disk cache
    times = {k: [] for k in cmds}
    for _ in range(repeat):
        for k, cmd in cmds.items():
            times[k].append(_process(cmd)[0])
    out = {f"{k} (wall)": (_median(v) * 1e3, "ms") for k, v in times.items()}
    base = times["import numpy"]
    for k in list(cmds)[1:]:
        out[f"{k} / import numpy"] = (_median(a / b for a, b in zip(times[k], base)), "")
    return out


# -------------------------------------------------------------- model evaluation
def models(repeat, n=10 ** 6):
    """CPU time of `n` evaluations of each closed-form model's F(d) and d(F) (a 5 mm x
    10 mm steel roller, 0.2-2 times its depth and force at 1 kN) and of the
    partial-slip force and shift (the universal curve, mu 0.3, "mdr" and "bem")."""
    import linecontact.models as lm
    from linecontact.tangential import TangentialContact

    R, Lr, E, F0 = 5e-3, 10e-3, 115.38e9, 1e3
    s = np.linspace(0.2, 2.0, n)
    out = {}
    for key in ("universal", "li-popov", "johnson", "kunz", "palmgren", "iso16281",
                "puttock-thwaite"):
        m = lm.get_model(key, R, Lr, E)
        d, F = s * float(m.depth(F0)), s * F0
        out[f"{key} F(d)"] = (_cpu(lambda: m.force(d), repeat), "s")
        out[f"{key} d(F)"] = (_cpu(lambda: m.depth(F), repeat), "s")
    u = lm.get_model("universal", R, Lr, E)
    for method in ("mdr", "bem"):
        tc = TangentialContact(u, 0.3, 0.8 * E, force=F0, method=method)
        a = np.linspace(0.0, 1.0, n) * tc.gross_slip_shift
        ft = np.linspace(-1.0, 1.0, n) * tc.gross_slip_force
        tc.force(a[:2]), tc.shift(ft[:2])
        out[f"partial slip ({method}) force"] = (_cpu(lambda: tc.force(a), repeat), "s")
        out[f"partial slip ({method}) shift"] = (_cpu(lambda: tc.shift(ft), repeat), "s")
    return out


# --------------------------------------------------------------------- CSV batch
def write_batch(path, rows=100_000, cylinders=100, distinct=False, seed=1, si=False):
    """A batch CSV as a spreadsheet of roller checks: `cylinders` rollers (R 1-20 mm,
    L/R 0.5-5, steel on steel; every row its own with `distinct`), each row a load of
    100 N - 10 kN with a unit (bare SI numbers with `si`), a name and a free-text column
    kept as is. Deterministic for a seed."""
    rng = np.random.default_rng(seed)
    n_cyl = rows if distinct else cylinders
    radius_mm = np.round(rng.uniform(1.0, 20.0, n_cyl), 3)
    length_mm = np.round(radius_mm * rng.uniform(0.5, 5.0, n_cyl), 3)
    which = np.arange(rows) % n_cyl
    load = np.exp(rng.uniform(np.log(100.0), np.log(1e4), rows))
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["name", "radius", "length", "modulus", "poisson", "modulus2",
                    "poisson2", "load", "comment"])
        for i in range(rows):
            c, F = which[i], load[i]
            if si:
                w.writerow([f"row {i}", f"{radius_mm[c] / 1e3:.9g}",
                            f"{length_mm[c] / 1e3:.9g}", "2.1e+11", "0.3", "2.1e+11",
                            "0.3", f"{F:.4g}", "kept as is"])
            else:
                cell = f"{F / 1e3:.4g}kN" if F >= 1e3 else f"{F:.4g}N"
                w.writerow([f"row {i}", f"{radius_mm[c]:g}mm", f"{length_mm[c]:g}mm",
                            "210GPa", "0.3", "210GPa", "0.3", cell, "kept as is"])


def batch(repeat, rows=100_000):
    """CPU time of ``linecontact calc FILE -o OUT`` on a 100 000-row CSV (whole
    processes), as a ratio to the one-case call (median of interleaved pairs; target:
    within 5, issue 11): 100 rollers with unit cells, every row its own roller, the
    same in bare SI numbers."""
    py = [sys.executable, "-m", "linecontact", "calc"]
    with tempfile.TemporaryDirectory(prefix="lc_bench_") as tmp:
        tmp = Path(tmp)
        write_batch(tmp / "batch.csv", rows)
        write_batch(tmp / "distinct.csv", rows, distinct=True, seed=2)
        write_batch(tmp / "si.csv", rows, distinct=True, seed=2, si=True)
        cmds = {"one case": py + ONE_CASE}
        for k, f in (("100 rollers", "batch"), ("every row its roller", "distinct"),
                     ("every row its roller, SI cells", "si")):
            cmds[k] = py + [str(tmp / f"{f}.csv"), "-o", str(tmp / f"{f}_out.csv")]
        for cmd in cmds.values():
            _process(cmd)
        cpu = {k: [] for k in cmds}
        for _ in range(repeat):
            for k, cmd in cmds.items():
                cpu[k].append(_process(cmd)[1])
    out = {f"{k} (CPU)": (_median(v), "s") for k, v in cpu.items()}
    for k in list(cmds)[1:]:
        out[f"{rows} rows, {k} / one case"] = (
            _median(a / b for a, b in zip(cpu[k], cpu["one case"])), "")
    return out


def batch_profiled(repeat, rows=200, rollers=4):
    """CPU time of a CSV of profiled rollers (4 rollers: ISO 16281, crowned, Lundberg,
    end relief; tilts 0-0.5 mrad; loads 1-40 kN) when rows that share a roller are
    solved as one load sweep (``linecontact calc``, in this process), against each row
    in a file of its own; the ratio is the median of interleaved pairs."""
    from linecontact.calc.cli import main

    header = ["name", "radius", "length", "modulus", "poisson", "modulus2", "poisson2",
              "profile", "tilt", "load"]
    profiles = ["iso16281", "circular:Rc=0.5", "lundberg:F0=20000", "end-relief:r=0.002"]
    rng = np.random.default_rng(3)
    radius = np.round(rng.uniform(5.0, 12.0, rollers), 2)
    length = np.round(radius * rng.uniform(1.5, 2.5, rollers), 2)
    tilt = np.round(rng.uniform(0.0, 0.5, rollers), 2)
    which = rng.permutation(np.arange(rows) % rollers)
    load = np.round(np.exp(rng.uniform(np.log(1e3), np.log(4e4), rows)), -1)
    table = [[f"row {i}", f"{radius[k]:g}mm", f"{length[k]:g}mm", "210GPa", "0.3",
              "210GPa", "0.3", profiles[k % len(profiles)], f"{tilt[k]:g}mrad",
              f"{load[i]:g}N"] for i, k in enumerate(which)]

    def write(path, body):
        with open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(header)
            w.writerows(body)

    def calc(path, out):
        with contextlib.redirect_stderr(io.StringIO()):
            if main(["calc", str(path), "--json", "-o", str(out)]) != 0:
                raise RuntimeError(f"calc {path} failed")
        return json.loads(Path(out).read_text(encoding="utf-8"))["rows"]

    with tempfile.TemporaryDirectory(prefix="lc_bench_") as tmp:
        tmp = Path(tmp)
        write(tmp / "all.csv", table)
        for i, r in enumerate(table):
            write(tmp / f"row{i}.csv", [r])
        calc(tmp / "all.csv", tmp / "g.json")                  # imports, tables
        grouped, single = [], []
        for _ in range(repeat):
            c0 = time.process_time()
            g = calc(tmp / "all.csv", tmp / "g.json")
            grouped.append(time.process_time() - c0)
            c0 = time.process_time()
            o = [calc(tmp / f"row{i}.csv", tmp / "o.json")[0] for i in range(rows)]
            single.append(time.process_time() - c0)
    dq = max(abs(a["depth_m"] / b["depth_m"] - 1) for a, b in zip(g, o))
    return {f"{rows} rows grouped (CPU)": (_median(grouped) / rows * 1e3, "ms a row"),
            f"{rows} rows one by one (CPU)": (_median(single) / rows * 1e3, "ms a row"),
            "grouped / one by one": (_median(a / b for a, b in zip(grouped, single)), ""),
            "largest depth difference grouped / one by one": (dq, "")}


# -------------------------------------------------------- profiled-roller solve
def _iso_profile():
    from linecontact import profiles

    return profiles.ISO16281Profile(L, diameter=D)


def roller(repeat, inner=20):
    """CPU time of one cold profiled-roller solve (a new ``ProfiledRoller`` at its
    default slices, ``at_force``) of the ISO 16281 roller, tilt 2 mrad and free, with
    every engine the checkout runs (``engine=...``), the engines alternating in one
    process; each sample the median of `inner` solves; the ratio of each engine to
    numpy is the median of the pairs. And the coarse 3D BEM (128 x 32 cells, one FFT
    thread) of the same case, as a ratio to the default engine's solve."""
    from linecontact.roller import ProfiledRoller

    prof = _iso_profile()

    def solve(engine, tilt):
        kw = {} if engine == "default" else {"engine": engine}
        return ProfiledRoller(D / 2, L, ESTAR, prof, **kw).at_force(FORCE, tilt=tilt)

    engines = ["default"]
    for e in ENGINES:
        try:
            solve(e, TILT)                          # loads a compiled engine
        except Exception as exc:                    # refused here: say so, skip it
            print(f"roller: engine {e!r} skipped ({type(exc).__name__}: "
                  f"{str(exc).splitlines()[0]})", file=sys.stderr)
            continue
        engines.append(e)
    out = {}
    for label, tilt in (("tilt 2 mrad", TILT), ("tilt free", "free")):
        ts = {e: [] for e in engines}
        for i in range(repeat):
            for e in (engines if i % 2 == 0 else engines[::-1]):
                ts[e].append(_cpu(lambda: solve(e, tilt), inner))
        for e in engines:
            out[f"one solve, {label}, engine {e}"] = (_median(ts[e]) * 1e3, "ms")
        if "numpy" in engines:
            for e in engines:
                if e not in ("numpy", "default"):
                    out[f"{label}: {e} / numpy"] = (
                        _median(a / b for a, b in zip(ts[e], ts["numpy"])), "")
        if label == "tilt 2 mrad":
            try:
                from tools.bem.roller import solve_roller_force
            except ImportError:
                continue
            tb = _cpu(lambda: solve_roller_force(D / 2, L, ESTAR, FORCE, tilt=TILT,
                                                 profile=prof, n_x=128, n_y=32, workers=1),
                      max(1, min(repeat, 3)))
            out["coarse 3D BEM 128 x 32, tilt 2 mrad"] = (tb * 1e3, "ms")
            out["coarse 3D BEM / one solve (default engine)"] = (
                tb / _median(ts["default"]), "")
    return out


# ----------------------------------------------------------------------- stresses
def stresses(repeat):
    """CPU time of the subsurface stresses (``roller_stresses``, 3D-corrected, mu 0,
    nu 0.3) of the 36 rollers of tables/stress_accuracy.csv (6 profiles x 3 loads x 2
    tilts) against their contact solve (a fresh ``ProfiledRoller``, default engine);
    per roller the medians of `repeat`; target: the stresses within twice the solve
    (issue 17). The first call of a new (mu, nu) (the strip maxima, cached) apart."""
    from linecontact.roller import ProfiledRoller
    from linecontact.stresses import roller_stresses, strip_maxima
    from tools.studies import stress_study as ss
    from tools.studies.roller_study import make_profile

    c0 = time.process_time()
    strip_maxima(0.05, 0.31)
    first = time.process_time() - c0
    strip_maxima(0.0, 0.3)
    solves, stress, ratios = [], [], []
    for task in ss.study_tasks():
        prof = make_profile(task["profile"], task["length"], task["radius"], task["estar"])
        ts, tt = [], []
        for _ in range(repeat):
            model = ProfiledRoller(task["radius"], task["length"], task["estar"], prof)
            c0 = time.process_time()
            sol = model.at_force(task["force"], tilt=task["tilt"])
            c1 = time.process_time()
            roller_stresses(sol, 0.0, 0.3, roller=model)
            ts.append(c1 - c0)
            tt.append(time.process_time() - c1)
        solves.append(_median(ts))
        stress.append(_median(tt))
        ratios.append(stress[-1] / solves[-1])
    return {"contact solve, median over 36 rollers": (_median(solves) * 1e3, "ms"),
            "stresses, median over 36 rollers": (_median(stress) * 1e3, "ms"),
            "stresses / solve, median": (_median(ratios), ""),
            "stresses / solve, largest": (max(ratios), ""),
            "first call of a new (mu, nu)": (first * 1e3, "ms")}


# ------------------------------------------------------------------------ bearing
BEARING_CASES = {
    "straight": (dict(), {}),
    "iso16281 spring law": (dict(model="iso16281"), {}),
    "crowned": (dict(profile="circular:Rc=0.5"), {}),
    "crowned, misaligned 1 mrad": (dict(profile="circular:Rc=0.5"),
                                   dict(misalignment=1e-3)),
    "crowned, moment 10 N m": (dict(profile="circular:Rc=0.5"), dict(moment=10.0)),
    "iso16281 profile, misaligned 1 mrad": (dict(profile="iso16281"),
                                            dict(misalignment=1e-3)),
    "straight, misaligned 0.5 mrad": (dict(), dict(misalignment=5e-4)),
}


def bearing(repeat):
    """CPU time of a whole ``RadialRollerBearing(20, 100 mm, 10 mm, 10 mm,
    ...).solve(10 kN, ...)`` (construction included) per case (targets, issue 21: 20
    straight rollers under 50 ms, 20 profiled under 1 s)."""
    from linecontact.bearing import RadialRollerBearing

    out = {}
    for name, (kw, load) in BEARING_CASES.items():
        def one():
            RadialRollerBearing(20, 100e-3, 10e-3, 10e-3, **kw).solve(10e3, **load)
        one()
        out[name] = (_cpu(one, repeat) * 1e3, "ms")
    return out


# ---------------------------------------------------------------------------- BEM
def bem(repeat):
    """The 3D BEM of tools/bem: one application of the half-space operator on the
    paper's 512 x 512 grid (the mirror-symmetric DCT form on its 256 x 256 quarter,
    scipy, one thread) and the paper's sweep (L/R 5, 20 load steps) on a 128 x 128 grid,
    one FFT thread: CPU time."""
    from tools.bem.cylinder import sweep
    from tools.bem.halfspace import SymmetricOperator

    q = np.random.default_rng(0).random((256, 256))
    op = SymmetricOperator(256, 256, 1.0, 1.0, backend="scipy", workers=1)
    op(q)
    t_op = _cpu(lambda: [op(q) for _ in range(20)], repeat) / 20
    one = lambda: sweep(5.0, n=128, steps=20, progress=False, workers=1)  # noqa: E731
    one()
    return {"operator 512 x 512 (symmetric quarter)": (t_op * 1e3, "ms"),
            "sweep L/R 5, 128 x 128, 20 steps": (_cpu(one, repeat), "s")}


# --------------------------------------------------- ContactMechanics (optional)
def contactmechanics(repeat):
    """The paper's finite-cylinder sweep (L/R 5, 100 steps to d = 0.15 R, tol 1e-6,
    128 x 128) solved by ContactMechanics (FreeFFTElasticHalfSpace, constrained CG)
    and by tools.bem.cylinder.sweep, one thread each: their CPU ratio and the largest
    force difference. Only where ``contactmechanics`` is installed (not a dependency:
    ``pip install contactmechanics``); how it is called: tools/benchmarks/
    contactmechanics.py."""
    try:
        import ContactMechanics  # noqa: F401
    except ImportError:
        print("contactmechanics: skipped (the package ContactMechanics is not installed; "
              "pip install contactmechanics)", file=sys.stderr)
        return None
    import argparse
    import importlib.util

    here = Path(os.environ["LC_BENCH_HOME"]) / "contactmechanics.py"
    spec = importlib.util.spec_from_file_location("lc_bench_cm", here)
    cm_mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cm_mod)
    args = argparse.Namespace(l_over_r=5.0, steps=100, tol=1e-6, d_max_over_r=0.15,
                              radius=1.0, estar=1.0, cm_warm="forces", maxiter=100000,
                              ours_workers=1, ours_backend=None, progress=False)
    cpu_cm, cpu_ours, dq = [], [], 0.0
    for _ in range(repeat):
        cm = cm_mod.run_contactmechanics(args, 128, 128)
        ours = cm_mod.run_ours(args, 128, 128, "difference")
        cpu_cm.append(cm["cpu"])
        cpu_ours.append(ours["cpu"])
        dq = max(dq, float(np.max(np.abs(cm["force"] / ours["force"] - 1))))
    return {"ContactMechanics sweep (CPU)": (_median(cpu_cm), "s"),
            "ours sweep (CPU)": (_median(cpu_ours), "s"),
            "ContactMechanics / ours": (_median(a / b for a, b in zip(cpu_cm, cpu_ours)),
                                        ""),
            "largest |F_CM / F_ours - 1|": (dq, "")}


#: name -> (function, default repeat), in the order they run
BENCHMARKS = {
    "cli_startup": (cli_startup, 10),
    "models": (models, 5),
    "batch": (batch, 3),
    "batch_profiled": (batch_profiled, 2),
    "roller": (roller, 10),
    "stresses": (stresses, 3),
    "bearing": (bearing, 5),
    "bem": (bem, 3),
    "contactmechanics": (contactmechanics, 1),
}
