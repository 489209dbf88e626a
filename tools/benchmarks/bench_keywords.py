"""Cost of the unknown-keyword guard (linecontact.validity.refuse_unknown_keywords).

Every public callable of the library is wrapped so that an unknown keyword names the
valid ones; the wrapper forwards the call inside a ``try``. This script times the same
calls with the guards in place and with every guard removed (each wrapper replaced by
the function it wraps, in every loaded linecontact module and class), interleaved in
one process, and prints the paired ratios of CPU time (``time.process_time``, so that a
shared machine's load does not count; median of ``--repeat`` pairs):

- one scalar call of ``classical.johnson_depth`` (one guard);
- one scalar ``force`` and ``depth`` of the default (universal) model (the method's
  guard and the guarded helpers it calls);
- the same with 1e6-element arrays (``-n``);

and, first, the wrapper alone: a no-op function called plain and guarded.

Usage::

    python -m tools.benchmarks.bench_keywords [-n 1000000] [--repeat 7]
"""
from __future__ import annotations

import argparse
import platform
import statistics
import sys
import time
import timeit

import numpy as np

import linecontact
from linecontact import classical
from linecontact.models import get_model

R, L, ESTAR = 5e-3, 10e-3, 115.38e9


def _swaps():
    """(owner, name, guarded, original) of every guard in the loaded modules."""
    out = []
    for modname, module in list(sys.modules.items()):
        if not modname.startswith("linecontact") or module is None:
            continue
        for name, obj in list(vars(module).items()):
            if getattr(obj, "_keywords_checked", False) and hasattr(obj, "__wrapped__"):
                out.append((module, name, obj, obj.__wrapped__))
            if isinstance(obj, type) and obj.__module__.startswith("linecontact"):
                for attr, member in list(vars(obj).items()):
                    inner = getattr(member, "__func__", member)
                    if getattr(inner, "_keywords_checked", False) and \
                            hasattr(inner, "__wrapped__"):
                        if inner is member:
                            plain = inner.__wrapped__
                        else:
                            plain = type(member)(inner.__wrapped__)
                        if attr == "__init__" and getattr(inner.__wrapped__,
                                                          "_keywords_checked", False):
                            continue
                        out.append((obj, attr, member, plain))
    return out


def _set(swaps, guarded):
    for owner, name, g, plain in swaps:
        setattr(owner, name, g if guarded else plain)


def per_call(stmt, number):
    return timeit.timeit(stmt, number=number, timer=time.process_time) / number


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args(argv)

    model = get_model("universal", R, L, ESTAR)
    d0 = float(model.depth(1e3))
    forces = np.linspace(200.0, 2000.0, args.n)
    depths = np.linspace(0.2 * d0, 2 * d0, args.n)
    model.force(depths[:10])  # load tables and lazy modules before the swap
    from linecontact.validity import refuse_unknown_keywords

    def noop(x, c=1.0):
        return x

    ns = {"__all__": ["noop"], "noop": noop}
    refuse_unknown_keywords(ns)
    guarded_noop = ns["noop"]
    t_plain = statistics.median(per_call(lambda: noop(1.0), 200000) for _ in range(7))
    t_guard = statistics.median(per_call(lambda: guarded_noop(1.0), 200000)
                                for _ in range(7))
    print(f"# the wrapper alone (a no-op function): {t_plain * 1e9:.0f} ns plain, "
          f"{t_guard * 1e9:.0f} ns guarded: {(t_guard - t_plain) * 1e9:+.0f} ns a call")
    swaps = _swaps()
    cases = {
        "johnson_depth scalar": (lambda: classical.johnson_depth(1e3, R, L, ESTAR), 300),
        "universal force scalar": (lambda: model.force(d0), 300),
        "universal depth scalar": (lambda: model.depth(1e3), 100),
        f"johnson_depth n={args.n:g}": (lambda: classical.johnson_depth(forces, R, L,
                                                                        ESTAR), 1),
        f"universal force n={args.n:g}": (lambda: model.force(depths), 1),
        f"universal depth n={args.n:g}": (lambda: model.depth(forces), 1),
    }
    print(f"# bench_keywords: {len(swaps)} guards; python {platform.python_version()}, "
          f"numpy {np.__version__}, linecontact {linecontact.__version__}, "
          f"{platform.machine()}; median of {args.repeat} interleaved pairs")
    print("| call | guarded | unguarded | ratio guarded/unguarded | overhead |")
    print("|---|---|---|---|---|")
    for label, (fun, number) in cases.items():
        g, u = [], []
        for _ in range(args.repeat):
            _set(swaps, True)
            g.append(per_call(fun, number))
            _set(swaps, False)
            u.append(per_call(fun, number))
        _set(swaps, True)
        ratios = [a / b for a, b in zip(g, u)]
        mg, mu = statistics.median(g), statistics.median(u)
        print(f"| {label} | {mg * 1e6:.3g} us | {mu * 1e6:.3g} us | "
              f"{statistics.median(ratios):.3f} | {(mg - mu) * 1e9:+.0f} ns |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
