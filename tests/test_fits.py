"""Operating clearance (linecontact.bearing.fits): Lame interference fits against hand-computed ring
expansion, thermal change, and the operating clearance's effect on the load zone."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.bearing import RadialRollerBearing
from linecontact.errors import OutOfRangeError
from linecontact.bearing.fits import (
    fit_pressure, inner_raceway_expansion, operating_clearance, outer_raceway_contraction,
    thermal_clearance_change)

E, NU = 210e9, 0.3


def test_fit_pressure_by_hand():
    """Solid steel shaft in a steel ring, d = 50 mm, raceway d_r = 59 mm, I = 20 um:
    same material, so p = I E (d_r^2 - d^2) / (2 d d_r^2)
    = 20e-6 * 210e9 * (3481 - 2500) / (2 * 50 * 3481) * 1e3 = 11.836 MPa."""
    hand = 20e-6 * 210e9 * (59 ** 2 - 50 ** 2) / (2 * 50 * 59 ** 2) * 1e3
    assert hand == pytest.approx(11.836e6, rel=1e-4)
    assert fit_pressure(20e-6, 50e-3, 0.0, 59e-3, E, NU, E, NU) == pytest.approx(
        hand, rel=1e-12)


def test_inner_ring_expansion_by_hand():
    """Solid shaft of the ring's material: the raceway grows by I d/d_r
    (20 um * 50/59 = 16.949 um), whatever E and nu."""
    for E_, nu in ((210e9, 0.3), (70e9, 0.33)):
        dd = inner_raceway_expansion(20e-6, 50e-3, 59e-3, E_, nu)
        assert dd == pytest.approx(20e-6 * 50 / 59, rel=1e-12)


def test_outer_ring_contraction_by_hand():
    """Massive housing of the ring's material: the raceway shrinks by I D_r/D
    (20 um * 81/110 = 14.727 um)."""
    dD = outer_raceway_contraction(20e-6, 110e-3, 81e-3, E, NU)
    assert dD == pytest.approx(20e-6 * 81 / 110, rel=1e-12)


def test_hollow_shaft_and_light_housing_expand_less():
    """A hollow shaft or an aluminium housing is more compliant: less of the
    interference reaches the raceway; a thin-walled hollow shaft tends to none."""
    solid = inner_raceway_expansion(20e-6, 50e-3, 59e-3, E, NU)
    hollow = inner_raceway_expansion(20e-6, 50e-3, 59e-3, E, NU, shaft_bore=40e-3)
    thin = inner_raceway_expansion(20e-6, 50e-3, 59e-3, E, NU, shaft_bore=49.99e-3)
    assert thin < hollow < solid and thin < 0.01 * solid
    steel = outer_raceway_contraction(20e-6, 110e-3, 81e-3, E, NU)
    alu = outer_raceway_contraction(20e-6, 110e-3, 81e-3, E, NU, housing_modulus=70e9,
                                    housing_poisson=0.33)
    finite = outer_raceway_contraction(20e-6, 110e-3, 81e-3, E, NU,
                                       housing_diameter=130e-3)
    assert alu < steel and finite < steel


def test_lame_displacement_by_independent_stress_function():
    """The ring's raceway growth equals the Lame displacement u(b) of a thick cylinder
    under internal pressure p, u(r) = p a^2/(E (b^2 - a^2)) ((1 - nu) r + (1 + nu) b^2/r),
    at r = b, doubled (a hollow shaft and a different shaft material)."""
    I, d, dr, ds, Es, nus = 30e-6, 50e-3, 60e-3, 20e-3, 200e9, 0.28
    p = fit_pressure(I, d, ds, dr, Es, nus, E, NU)
    a, b = d / 2, dr / 2
    u_b = p * a ** 2 / (E * (b ** 2 - a ** 2)) * ((1 - NU) * b + (1 + NU) * b ** 2 / b)
    dd = inner_raceway_expansion(I, d, dr, E, NU, shaft_bore=ds, shaft_modulus=Es,
                                 shaft_poisson=nus)
    assert dd == pytest.approx(2 * u_b, rel=1e-12)
    # and the joint closes the interference: ring bore growth + shaft shrinkage = I
    ring_bore = p * a / E * ((b ** 2 + a ** 2) / (b ** 2 - a ** 2) + NU)
    c = ds / 2
    shaft = p * a / Es * ((a ** 2 + c ** 2) / (a ** 2 - c ** 2) - nus)
    assert 2 * (ring_bore + shaft) == pytest.approx(I, rel=1e-12)


def test_thermal_change_by_hand():
    """Rollers at the rings' mean temperature: -alpha dT d_m = -12e-6 * 10 * 70 mm
    = -8.4 um; everything 10 K warmer: alpha dT P_d (the clearance grows with the parts)."""
    assert thermal_clearance_change(59e-3, 81e-3, 11e-3, 10.0, 0.0) == pytest.approx(
        -8.4e-6, rel=1e-12)
    Pd = 81e-3 - 59e-3 - 2 * 11e-3 + 40e-6          # raceways leaving 40 um
    assert thermal_clearance_change(59e-3, 81.04e-3, 11e-3, 10.0, 10.0) == \
        pytest.approx(12e-6 * 10 * Pd, rel=1e-9)


def test_operating_clearance_sums_the_changes():
    assert operating_clearance(40e-6, 16.949e-6, 14.727e-6, -8.4e-6) == pytest.approx(
        40e-6 - 16.949e-6 - 14.727e-6 - 8.4e-6, rel=1e-12)
    with pytest.raises(OutOfRangeError, match="inner_expansion"):
        operating_clearance(40e-6, -1e-6)


def test_press_fit_changes_the_load_zone_and_the_reference_life():
    """A press fit reduces the clearance: from 40 um to the operating clearance the load
    zone widens, the most loaded roller carries less and L10r grows; a fit that leaves a
    preload (negative operating clearance) loads every roller and L10r falls below the
    zero-clearance value. (ISO 281's L10 ignores the clearance.)"""
    dd = inner_raceway_expansion(20e-6, 50e-3, 59e-3, E, NU)            # 16.95 um
    op = operating_clearance(40e-6, dd)                                  # 23.05 um
    tight = operating_clearance(40e-6, inner_raceway_expansion(80e-6, 50e-3, 59e-3, E,
                                                               NU))     # -27.8 um
    assert op == pytest.approx(40e-6 - 20e-6 * 50 / 59, rel=1e-12) and tight < 0
    F = 10e3
    loose = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, clearance=40e-6).solve(F)
    fitted = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, clearance=op).solve(F)
    zero = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, clearance=0.0).solve(F)
    pre = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, clearance=tight).solve(F)
    assert fitted.max_roller_load < loose.max_roller_load
    assert fitted.life_iso16281 > loose.life_iso16281
    assert pre.life_iso16281 < zero.life_iso16281
    assert np.count_nonzero(fitted.roller_loads) >= np.count_nonzero(loose.roller_loads)
    assert np.count_nonzero(pre.roller_loads) == 14
    assert fitted.life_iso281 == loose.life_iso281
