"""1e6 evaluations of every closed-form model's F(d) and d(F), and of the partial-slip
force and shift, with paired before/after ratios where the old algorithm is kept.

CPU time (``time.process_time``, median of ``--repeat`` runs) for N values spread over
0.2-2 times the depth and force of a 5 mm x 10 mm steel roller at 1 kN. Two pairs run
the algorithm before and after in the same process, interleaved:

- universal d(F): the tabulated inverse spline polished by one Newton step
  (``NotAKnotSpline.solve_fast``) against the whole-spline Newton iteration (``UniversalCurve._newton``, still used for the MDR
  profile);
- partial-slip force with the BEM slip correction (``TangentialContact.force``,
  method "bem"; for arrays this large the cubic Hermite table built once per contact)
  against the 60-step bisection of two rounds ago (re-implemented here, the same
  lines), with the largest difference between the two.

With ``--vs-path DIR`` the table's entries are also measured with the ``linecontact``
package of another checkout DIR (e.g. the main branch before a change), this script
run as a child process alternately with DIR and with this checkout on its path
(``--rounds`` times, A B A B ...), and each entry's ratio old/new is the median of the
rounds' ratios: a paired comparison that holds while the machine's load drifts.

Usage::

    python -m tools.benchmarks.bench_models [-n 1000000] [--repeat 5]
    python -m tools.benchmarks.bench_models --vs-path ../main --rounds 5 --repeat 5
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

import linecontact.models as models
from linecontact.tangential import TangentialContact

CLOSED_FORM = ("johnson", "kunz", "li-popov", "palmgren", "iso16281", "puttock-thwaite",
               "universal")
R, L, ESTAR, F0 = 5e-3, 10e-3, 115.38e9, 1e3


def cpu(fun, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.process_time()
        fun()
        times.append(time.process_time() - t0)
    return float(np.median(times))


def paired(a, b, repeat):
    ta, tb = [], []
    for _ in range(repeat):
        for f, acc in ((a, ta), (b, tb)):
            t0 = time.process_time()
            f()
            acc.append(time.process_time() - t0)
    return float(np.median(ta)), float(np.median(tb)), float(np.median(np.array(ta) / np.array(tb)))


def bisection_force(tc, a):
    """The partial-slip force as computed before (60 bisection steps over the array)."""
    lo, hi = np.zeros(a.shape), np.ones(a.shape)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        below = tc._law_shift(mid) * tc._q_factor(mid) < a
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return np.where(a >= tc.gross_slip_shift, 1.0, 0.5 * (lo + hi)) * tc.gross_slip_force


def entries(n, rep):
    """CPU time of each table entry: {name: seconds} (public API only, so that it runs
    against another checkout's package too)."""
    s = np.linspace(0.2, 2.0, n)
    res = {}
    for key in CLOSED_FORM:
        m = models.get_model(key, R, L, ESTAR)
        d = s * float(m.depth(F0))
        F = s * F0
        res[f"{key} F(d)"] = cpu(lambda: m.force(d), rep)
        res[f"{key} d(F)"] = cpu(lambda: m.depth(F), rep)
    u = models.get_model("universal", R, L, ESTAR)
    for method in ("mdr", "bem"):
        tc = TangentialContact(u, 0.3, 0.8 * ESTAR, force=F0, method=method)
        a = np.linspace(0.0, 1.0, n) * tc.gross_slip_shift
        ft = np.linspace(-1.0, 1.0, n) * tc.gross_slip_force
        tc.force(a[:2]), tc.shift(ft[:2])      # contact built, tables not yet
        res[f"partial slip ({method}) force"] = cpu(lambda: tc.force(a), rep)
        res[f"partial slip ({method}) shift"] = cpu(lambda: tc.shift(ft), rep)
    return res


def paired_with(path, n, rep, rounds):
    """{name: (new median, old median, median of the rounds' old/new ratios)}: this
    script as a child process with the package of `path` (old) and of this checkout
    (new) first on its path, alternately."""
    here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    runs = {"old": [], "new": []}
    for _ in range(rounds):
        for which, root in (("old", os.path.abspath(path)), ("new", here)):
            env = dict(os.environ, PYTHONPATH=root)
            with tempfile.TemporaryDirectory() as cwd:    # no checkout in the cwd
                text = subprocess.run(
                    [sys.executable, os.path.abspath(__file__), "--json", "-n", str(n),
                     "--repeat", str(rep)], env=env, cwd=cwd, check=True,
                    capture_output=True, text=True).stdout
            runs[which].append(json.loads(text.splitlines()[-1]))
    out = {}
    for name in runs["new"][0]:
        new = np.array([r[name] for r in runs["new"]])
        old = np.array([r[name] for r in runs["old"]])
        out[name] = (float(np.median(new)), float(np.median(old)),
                     float(np.median(old / new)))
    return out


def slicing(n, rep, coupled=False):
    """The ISO 16281 slicing law of a crowned (Rc = 0.5 m), tilted (0.5 mrad) roller,
    30 slices touching at 30 depths: F(d) and d(F) of n values from the tables, the
    first call on a new model (it builds the table) apart, and the direct solves of
    2000 values scaled to n; the table against the solves at 500 of the points.
    ``coupled``: the same for the coupled-slice law (``profiled-roller``, default
    slices: 50 since issue 20's fourth round, 100 in the earlier records,
    1 mrad; 200 direct solves scaled, 100 check points: each is a coupled solve)."""
    from linecontact.roller.laws import ISOSlicingModel, ProfiledRollerModel

    if coupled:
        m = ProfiledRollerModel(R, L, ESTAR, profile="circular:Rc=0.5", tilt=1e-3)
        key, n_few, n_check = "profiled-roller (crowned, 1 mrad)", 200, 100
    else:
        m = ISOSlicingModel(R, L, ESTAR, profile="circular:Rc=0.5", tilt=5e-4)
        key, n_few, n_check = "iso16281-slicing (crowned, tilted)", 2000, 500
    s = np.linspace(0.2, 2.0, n)
    d = m.first_contact_depth + s * (float(m.depth(F0)) - m.first_contact_depth)
    F = s * F0
    for name, fun, x, ref in (("F(d)", m.force, d, lambda v: m.at_depth(v).force),
                              ("d(F)", m.depth, F, lambda v: m.at_force(v).depth)):
        t0 = time.process_time()
        y = fun(x)
        first = time.process_time() - t0
        again = cpu(lambda: fun(x), rep)
        few = x[:: max(1, n // n_few)][:n_few]
        direct = cpu(lambda: fun(few), 1) * n / few.size
        k = np.linspace(0, n - 1, n_check).astype(int)
        exact = np.array([ref(float(v)) for v in x[k]])
        base = exact if name == "F(d)" else exact - m.first_contact_depth
        err = float(np.max(np.abs(y[k] - exact) / base))
        print(f"{key} {name}: {again:.3f} s from the table, "
              f"first call {first:.2f} s (builds it), direct solves {direct:.0f} s "
              f"({n_few} scaled); largest difference {err:.1e} (of F, of d - d0) "
              f"at {n_check} points")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=10 ** 6)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", action="store_true",
                    help="print the table's entries as one JSON line, nothing else")
    ap.add_argument("--vs-path", metavar="DIR",
                    help="also time the entries with the linecontact package of DIR "
                         "(another checkout), paired, and print the ratios old/new")
    ap.add_argument("--rounds", type=int, default=5,
                    help="rounds of the paired comparison (child processes A B A B)")
    ap.add_argument("--profiled-roller", action="store_true",
                    help="time only the coupled-slice law's table (profiled-roller; its "
                         "build is a few hundred coupled solves: minutes)")
    args = ap.parse_args(argv)
    n, rep = args.n, args.repeat
    if args.profiled_roller:
        print(f"# bench_models --profiled-roller: N = {n}, CPU s, median of {rep}; "
              f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}"
              + (f"; load average {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg")
                 else ""))
        slicing(n, rep, coupled=True)
        return
    if args.json:
        print(json.dumps(entries(n, rep)))
        return
    s = np.linspace(0.2, 2.0, n)
    print(f"# bench_models: N = {n}, CPU s, median of {rep}; {platform.machine()}, "
          f"Python {platform.python_version()}, numpy {np.__version__}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}"
          + (f"; load average {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg")
             else ""))
    res = entries(n, rep)
    print("| model | F(d) | d(F) |")
    print("|---|---|---|")
    for key in CLOSED_FORM:
        print(f"| {key} | {res[key + ' F(d)']:.3f} | {res[key + ' d(F)']:.3f} |")
    for method in ("mdr", "bem"):
        print(f"partial slip ({method}): force {res[f'partial slip ({method}) force']:.3f} s, "
              f"shift {res[f'partial slip ({method}) shift']:.3f} s")
    u = models.get_model("universal", R, L, ESTAR)
    c = u.curve
    lp = np.log(np.clip(u._psi_of_force(s * F0), c.psi_min, c.psi_max))
    c.depth_of_psi(np.exp(lp[:2]))      # builds the inverse table
    old, new, ratio = paired(
        lambda: c._newton(lp, c._spline, c._slope, np.interp(lp, c._lnpsi, c._z),
                          c._z[0], c._z[-1]),
        lambda: c._spline.solve_fast(lp, c._inverse), rep)
    print(f"\nuniversal d(F) core, whole-spline Newton / tabulated inverse: {old:.3f} / "
          f"{new:.3f} s, ratio {ratio:.1f}")
    tc = TangentialContact(u, 0.3, 0.8 * ESTAR, force=F0, method="bem")
    a = np.linspace(0.0, 1.0, n) * tc.gross_slip_shift
    t0 = time.process_time()
    tc.force(a)
    first = time.process_time() - t0
    print(f"partial-slip force (bem), the first call on a new contact (it builds the "
          f"table): {first:.3f} s")
    dq = np.max(np.abs(tc.force(a) - bisection_force(tc, a))) / tc.gross_slip_force
    old, new, ratio = paired(lambda: bisection_force(tc, a), lambda: tc.force(a), rep)
    print(f"partial-slip force (bem), bisection / tabulated inverse: {old:.3f} / {new:.3f} s,"
          f" ratio {ratio:.1f}; largest difference {dq:.2g} mu F")
    slicing(n, rep)
    if args.vs_path:
        name = os.path.basename(os.path.normpath(args.vs_path))
        print(f"\npaired with the package of the checkout {name!r} (old), {args.rounds} rounds of "
              "child processes A B A B, each entry the median of its repeats:")
        print("| entry | new [s] | old [s] | old/new (median of rounds) |")
        print("|---|---|---|---|")
        for name, (tn, to, r) in paired_with(args.vs_path, n, rep, args.rounds).items():
            print(f"| {name} | {tn:.3f} | {to:.3f} | {r:.2f} |")


if __name__ == "__main__":
    main()
