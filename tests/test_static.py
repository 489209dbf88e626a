"""Static load rating and safety (linecontact.bearing.ratings): ISO 76's C0r exactly, s0 = C0/P0,
and the 4000 MPa behind the factor 44."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.errors import OutOfRangeError
from linecontact.bearing.ratings import (
    PERMISSIBLE_PRESSURE, pressure_safety_factor, static_equivalent_load,
    static_load_rating, static_safety_factor)


def test_c0_is_iso_76_formula_exactly():
    """C0r = 44 (1 - D cos(a)/D_pw) i Z L_we D cos(a), N with lengths in mm:
    44 * (1 - 11/70) * 1 * 14 * 11 * 11 = 62823.2 N."""
    hand = 44 * (1 - 11 / 70) * 1 * 14 * 11 * 11
    assert hand == pytest.approx(62823.2, abs=0.05)
    assert static_load_rating(14, 70e-3, 11e-3, 11e-3) == pytest.approx(hand, rel=1e-14)
    # two rows at a 10 deg contact angle
    c = math.cos(math.radians(10))
    hand2 = 44 * (1 - 11 * c / 70) * 2 * 14 * 11 * 11 * c
    assert static_load_rating(14, 70e-3, 11e-3, 11e-3, rows=2,
                              contact_angle=math.radians(10)) == pytest.approx(hand2,
                                                                               rel=1e-14)


def test_c0_refuses_fractional_rollers_and_misfit():
    with pytest.raises(OutOfRangeError, match="rollers"):
        static_load_rating(13.5, 70e-3, 11e-3, 11e-3)
    with pytest.raises(OutOfRangeError, match="pitch_diameter"):
        static_load_rating(14, 10e-3, 11e-3, 11e-3)


def test_s0_is_c0_over_p0():
    C0 = static_load_rating(14, 70e-3, 11e-3, 11e-3)
    P0 = static_equivalent_load(20e3)
    assert P0 == 20e3
    assert static_safety_factor(C0, P0) == C0 / P0
    assert static_safety_factor(C0, 0.0) == math.inf


def test_factor_44_is_4000_mpa_at_the_inner_contact():
    """The meaning of C0: under F_r = C0, ISO 76's most loaded roller carries
    Q_max = 5 F_r / Z (i = 1, alpha = 0), and its inner line contact (radius
    R = D (1 - gamma)/2, steel E = 207 GPa, nu = 0.3) has the Hertz pressure
    p0 = sqrt(Q E* / (pi L R)) = 4000 MPa: 44 = pi 4000^2 / (2 * 5 E*) within the
    rounding of 44 (the exact factor is 44.2 for E = 207 GPa): within 0.5 %."""
    Z, dm, D, L = 14, 70e-3, 11e-3, 11e-3
    C0 = static_load_rating(Z, dm, D, L)
    Q = 5 * C0 / Z
    estar = 207e9 / (2 * (1 - 0.3 ** 2))
    R = D * (1 - D / dm) / 2
    p0 = math.sqrt(Q * estar / (math.pi * L * R))
    assert p0 == pytest.approx(PERMISSIBLE_PRESSURE, rel=5e-3)
    # and so the stress-based safety of that contact is 1 (to the same rounding)
    assert pressure_safety_factor(p0) == pytest.approx(1.0, rel=1e-2)


def test_pressure_safety_is_the_load_margin_of_a_line_contact():
    """p ~ sqrt(Q) in a line contact: scaling the load by s0 = (4000/p)^2 brings the
    peak pressure to exactly 4000 MPa."""
    estar, L, R = 115.4e9, 11e-3, 4.6e-3
    Q = 3000.0
    p = math.sqrt(Q * estar / (math.pi * L * R))
    s0 = pressure_safety_factor(p)
    assert math.sqrt(s0 * Q * estar / (math.pi * L * R)) == pytest.approx(
        PERMISSIBLE_PRESSURE, rel=1e-12)
    assert pressure_safety_factor(0.0) == math.inf
    assert np.allclose(pressure_safety_factor(np.array([1e9, 2e9])), [16.0, 4.0],
                       rtol=1e-14)
