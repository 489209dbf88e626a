"""1e6 evaluations of every closed-form model's F(d) and d(F), and of the partial-slip
force and shift, with paired before/after ratios where the old algorithm is kept.

CPU time (``time.process_time``, median of ``--repeat`` runs) for N values spread over
0.2-2 times the depth and force of a 5 mm x 10 mm steel roller at 1 kN. Two pairs run
the algorithm before and after in the same process, interleaved:

- universal d(F): the tabulated inverse spline polished by one Newton step
  (``NotAKnotSpline.solve_fast``) against the whole-spline Newton iteration (``UniversalCurve._newton``, still used for the MDR
  profile);
- partial-slip force with the BEM slip correction (``TangentialContact.force``,
  method "bem"): the bracketing table and Illinois steps against the 60-step
  bisection it replaced (re-implemented here, the same lines).

Usage::

    python -m tools.benchmarks.bench_models [-n 1000000] [--repeat 5]
"""
from __future__ import annotations

import argparse
import platform
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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=10 ** 6)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    n, rep = args.n, args.repeat
    s = np.linspace(0.2, 2.0, n)
    print(f"# bench_models: N = {n}, CPU s, median of {rep}; {platform.machine()}, "
          f"Python {platform.python_version()}, numpy {np.__version__}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print("| model | F(d) | d(F) |")
    print("|---|---|---|")
    for key in CLOSED_FORM:
        m = models.get_model(key, R, L, ESTAR)
        d = s * float(m.depth(F0))
        F = s * F0
        print(f"| {key} | {cpu(lambda: m.force(d), rep):.3f} | "
              f"{cpu(lambda: m.depth(F), rep):.3f} |")
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
    for method in ("mdr", "bem"):
        tc = TangentialContact(u, 0.3, 0.8 * ESTAR, force=F0, method=method)
        a = np.linspace(0.0, 1.0, n) * tc.gross_slip_shift
        ft = np.linspace(-1.0, 1.0, n) * tc.gross_slip_force
        print(f"partial slip ({method}): force {cpu(lambda: tc.force(a), rep):.3f} s, "
              f"shift {cpu(lambda: tc.shift(ft), rep):.3f} s")
    tc = TangentialContact(u, 0.3, 0.8 * ESTAR, force=F0, method="bem")
    a = np.linspace(0.0, 1.0, n) * tc.gross_slip_shift
    dq = np.max(np.abs(tc.force(a) - bisection_force(tc, a))) / tc.gross_slip_force
    old, new, ratio = paired(lambda: bisection_force(tc, a), lambda: tc.force(a), rep)
    print(f"partial-slip force (bem), bisection / tabulated inverse: {old:.3f} / {new:.3f} s,"
          f" ratio {ratio:.1f}; largest difference {dq:.2g} mu F")


if __name__ == "__main__":
    main()
