"""The figures of docs/plots.md: one representative case per figure of linecontact.plot.

    python -m tools.figures_plots [--out docs/figures] [--svg] [--only NAME ...]

Writes ``docs/figures/plot_<name>.png`` (and ``.svg`` with ``--svg``) at 100 dpi, each
drawn by a function of :mod:`linecontact.plot` from the library's own result of the
case below; nothing here is computed that the library does not return. Runs in about
half a minute on one core (the stress field's 3D correction and the BEM tables'
look-ups dominate). matplotlib is an optional dependency (the ``plot`` extra).

The cases (SI; steel E* = 115.38 GPa is E = 210 GPa, nu = 0.3 on both bodies):

``force_depth``
    The eleven laws of ``standard_models`` for R = 5 mm, L = 10 mm, steel, with the
    universal curve's states at 0.1, 1 and 10 kN marked (each curve where it applies).
``profiled_roller``
    A crowned roller (R = 5 mm, L = 14 mm, Rc = 0.5 m) tilted by 1 mrad at 0.5, 2 and
    5 kN: q(x) with the contact's and the roller's ends, the profile and the approach.
``pressure_map``
    The same roller at 2 kN: p(x, y).
``adhesion``
    A hydrogel roller (R = 1 mm, L = 2 mm, E* = 67 kPa), w = 50 mJ/m^2, cycled to
    30 um: approach and retraction, the pull-offs, the 2D JKR and the BEM table's.
``creep``
    A rigid roller (R = 5 mm, L = 10 mm) on a standard linear solid (E*: 3 GPa
    instantaneous, 1 GPa relaxed, tau = 10 s): creep under a force ramped to 1 kN in
    5 s and held, and relaxation under a depth of 50 um held (two results, panels).
``tangential``
    Steel roller R = 5 mm, L = 10 mm at 1 kN, mu = 0.1: the BEM-corrected laws across
    and along the axis, loop amplitude 0.6 u* (across).
``stresses``
    The tilted crowned roller at 5 kN (roller_stresses, mu = 0): von Mises field at
    the worst section, maxima along the roller, the case check of a 700/350 HV case,
    CHD 0.3 mm.
``bearing``
    14 crowned rollers (D = 11 mm, L = 11 mm, Rc = 0.3 m) on d_m = 70 mm at 10 kN with
    1 mrad misalignment: roller loads, moments and tilts.
``panels``
    Several results at once: the profiled roller's q(x) and its stresses (plot.panels).
"""
from __future__ import annotations

import argparse
import math
import sys
from functools import partial
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
STEEL = 115.38e9


def _crowned(tilt=1e-3):
    from linecontact.contact import Contact, Roller

    return Contact(Roller(5e-3, 14e-3, crown_radius=0.5, tilt=tilt), estar=STEEL)


def force_depth():
    from linecontact import plot
    from linecontact.models import standard_models

    models = standard_models(5e-3, 10e-3, STEEL)
    F = np.array([1e2, 1e3, 1e4])
    return plot.force_depth(models, points={models[0]: zip(models[0].depth(F), F)})


def profiled_roller():
    from linecontact import plot

    c = _crowned()
    return plot.profiled_roller([c.normal(force=f) for f in (500.0, 2e3, 5e3)], c)


def pressure_map():
    from linecontact import plot

    return plot.pressure_map(_crowned().normal(force=2e3))


def adhesion():
    from linecontact import plot
    from linecontact.adhesion import CylinderAdhesion
    from linecontact.models import get_model

    return plot.adhesion(CylinderAdhesion(get_model("universal", 1e-3, 2e-3, 6.7e4), 0.05),
                         30e-6, n=121)


def _visco():
    from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
    from linecontact.viscoelastic import StandardLinearSolid

    return Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                   material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))


def creep():
    from linecontact import plot

    c = _visco()
    t = np.linspace(0.0, 60.0, 121)
    ramp = 1e3 * np.minimum(t / 5.0, 1.0)
    return plot.panels(partial(plot.creep, c.creep(t, force=ramp)),
                       partial(plot.creep, c.relaxation_history(t, depth=50e-6)))


def tangential():
    from linecontact import plot
    from linecontact.models import get_model
    from linecontact.classical import effective_modulus
    from linecontact.tangential import TangentialContact, effective_shear_modulus

    m = get_model("universal", 5e-3, 10e-3, effective_modulus(210e9, 0.3))
    G = effective_shear_modulus(210e9, 0.3)
    cs = [TangentialContact(m, 0.1, G, force=1e3, method="bem", direction=d)
          for d in ("across", "along")]
    u0 = 0.6 * min(c.gross_slip_shift for c in cs)
    return plot.hysteresis(cs, u0)


def _stresses():
    from linecontact.stresses import HardnessProfile, case_check, roller_stresses

    s = roller_stresses(_crowned().normal(force=5e3).solutions[0])
    return s, case_check(s, HardnessProfile(700.0, 0.3e-3, 350.0))


def stresses():
    from linecontact import plot

    s, check = _stresses()
    return plot.stresses(s, case=check)


def bearing():
    from linecontact import plot
    from linecontact.bearing import RadialRollerBearing

    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="circular:Rc=0.3")
    return plot.bearing(b.solve(10e3, misalignment=1e-3))


def panels():
    from linecontact import plot

    c = _crowned()
    s, _ = _stresses()
    return plot.panels(partial(plot.line_load, c.normal(force=5e3), c),
                       partial(plot.stresses, s, measure="tresca"),
                       title="crowned roller, 5 kN, tilt 1 mrad")


#: name -> function returning the figure (the module docstring describes each case)
FIGURES = {f.__name__: f for f in (force_depth, profiled_roller, pressure_map, adhesion,
                                   creep, tangential, stresses, bearing, panels)}


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default=str(ROOT / "docs" / "figures"),
                   help="folder for plot_<name>.png (default docs/figures)")
    p.add_argument("--svg", action="store_true", help="also write plot_<name>.svg")
    p.add_argument("--only", nargs="+", choices=sorted(FIGURES), metavar="NAME",
                   help="draw only these (" + ", ".join(FIGURES) + ")")
    args = p.parse_args(argv)
    from linecontact import plot

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name in args.only or FIGURES:
        fig = FIGURES[name]()
        paths = plot.save_all(fig, out / f"plot_{name}",
                              ("png", "svg") if args.svg else ("png",))
        print(*(str(x) for x in paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())
