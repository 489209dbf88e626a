"""The adhesive BEM (tools/bem/adhesion.py) against exact oracles, and the shipped table.

The local detachment criterion of Pohrt & Popov (2015) reproduces the JKR theory as the
cells shrink; its error on the coarse grids run here is a few per cent (the grid
sequences are in tables/adhesion_cylinder.csv's header), which sizes the tolerances.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from tools.bem.adhesion import (cylinder_retraction, equilibrate, kendall_punch,
                                sphere_retraction)
from tools.bem.halfspace import SymmetricOperator


def test_kendall_punch_pull_off():
    """Kendall (1971): a flat punch of radius a pulls off at F = -sqrt(8 pi a^3 E* w);
    with 64 cells across a the local criterion gives it within 1.5 % (measured 0.7 %;
    32 cells: 1.7 %)."""
    r = kendall_punch(1.0, 1.0, 1e-3, n_radius=64)
    exact = -math.sqrt(8 * math.pi * r["area_radius"] ** 3 * 1e-3)
    assert r["force"] == pytest.approx(exact, rel=0.015)


def test_jkr_sphere_pull_off_converges():
    """JKR sphere: force-controlled pull-off -1.5 pi w R. The BEM's error shrinks with the
    cells (measured: +10.7 % with 8 cells across a_c, +5.1 % with 24) and is below 6 %
    with 24."""
    ref = -1.5 * math.pi * 1e-3
    coarse = sphere_retraction(1.0, 1.0, 1e-3, n_radius=8, steps=30).pull_off_force / ref
    fine = sphere_retraction(1.0, 1.0, 1e-3, n_radius=24, steps=30).pull_off_force / ref
    assert abs(fine - 1) < 0.06
    assert abs(fine - 1) < abs(coarse - 1)


def test_zero_work_keeps_the_non_adhesive_contact():
    """w -> 0 (sigma_c -> 0): no tension survives, and the equilibrium from the overlap
    set is the non-adhesive one: pressures >= 0 up to the solver's tolerance and the Hertz
    force of the sphere within the grid's error (3 %)."""
    m, h, R = 48, 1.0 / 24, 1.0
    op = SymmetricOperator(m, m, h, h, 1.0, workers=1)
    x = (np.arange(m) + 0.5) * h
    X, Y = np.meshgrid(x, x, indexing="ij")
    gap = (X ** 2 + Y ** 2) / (2 * R)
    d = 1.0
    S, p, _ = equilibrate(op, gap - d, 1e-12, gap - d < 0)
    assert p.min() > -1e-9 * p.max()
    F = 4 * p.sum() * h * h
    assert F == pytest.approx(4 / 3 * math.sqrt(R) * d ** 1.5, rel=0.03)


def test_cylinder_retraction_near_2d_jkr():
    """A roller with s = b_c/L = 0.2 pulls off within 15 % of the 2D JKR value of its
    length on a coarse grid (the study's converged ratio at s = 0.2 is 1.05: the end
    effects of a short roller)."""
    s = 0.2
    w = math.pi / 2 * s ** 3
    r = cylinder_retraction(w, n_width=8, steps=30)
    F2d = -3 * (math.pi * w ** 2 / 16) ** (1 / 3)
    assert 0.9 < r.pull_off_force / F2d < 1.15


def test_runtime_table_interpolation_within_two_percent():
    """The runtime's corrected pull-off (PCHIP through the table's rows and the 2D limit
    1 at s = 0) reproduces every row of the BEM table exactly, and each interior row
    within 2.5 % when that row is left out of the interpolation (measured: at most
    2.0 %, s = 0.3; the rows scatter by their own grid uncertainty, about 2 %)."""
    from scipy.interpolate import PchipInterpolator

    from linecontact.adhesion import CylinderAdhesion
    from linecontact.models import get_model
    from linecontact.tables import read_table

    cols = read_table("adhesion_cylinder").columns
    s, r = cols["s"], cols["ratio_force"]
    for i in range(1, s.size - 1):
        keep = np.arange(s.size) != i
        f = PchipInterpolator(np.r_[0.0, s[keep]], np.r_[1.0, r[keep]])
        assert abs(f(s[i]) / r[i] - 1) < 0.025, (s[i], f(s[i]), r[i])
    m = get_model("universal", 1.0, 1.0, 1.0, extrapolate=True)
    for si, ri in zip(s, r):
        c = CylinderAdhesion(m, math.pi / 2 * si ** 3)
        assert c.pull_off("force")["ratio"] == pytest.approx(ri, rel=1e-12)


def test_criterion_on_a_straight_edge_overestimates_by_a_third():
    """A limitation, kept visible: on a straight edge aligned with the cells (long flat
    strip punch) Pohrt & Popov's constant, calibrated on circular edges, gives a pull-off
    about 1.3 times the exact 2D value sqrt(2 pi E* w b). The continuum average of the
    square-root field over an edge cell of width h predicts the factor
    sqrt((4/pi)/0.473201) = 1.29 (pinned: measured 1.324 with 8 cells across b, 1.337
    with 16, 1.344 with 32)."""
    from tools.bem.adhesion import strip_punch

    assert 1.25 < strip_punch(n_width=16) < 1.40
