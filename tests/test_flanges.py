"""Roller end / flange contacts of NJ and NUP bearings (linecontact.bearing.flanges): equilibrium,
the tilting couple from the contact points, and the Hertz contact of the end sphere."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.errors import CombinationError, UnknownNameError
from linecontact.bearing.flanges import axial_load_shares, flange_contacts

GEOM = dict(roller_diameter=11e-3, roller_length=11e-3, pitch_diameter=70e-3,
            end_radius=60e-3, flange_angle=math.radians(3), estar=115.4e9,
            inner_flange_height=3.2e-3, outer_flange_height=3.2e-3)


@pytest.mark.parametrize("rule", ["proportional", "equal"])
def test_flange_forces_sum_to_the_axial_load(rule):
    """Equilibrium of the ring: the rollers' axial forces add up to F_a; the unloaded
    rollers carry none."""
    Q = np.array([3200.0, 2500.0, 900.0, 0.0, 0.0, 0.0, 900.0, 2500.0])
    Fa = axial_load_shares(2500.0, Q, rule=rule)
    assert Fa.sum() == pytest.approx(2500.0, rel=1e-15)
    assert np.all(Fa[Q == 0] == 0.0)
    c = flange_contacts(Fa, **GEOM)
    # each contact's axial component is the roller's share: the flange forces' axial
    # components sum to the bearing's axial load
    axial = c.normal_force * math.cos(GEOM["flange_angle"])
    assert axial.sum() == pytest.approx(2500.0, rel=1e-14)


def test_proportional_share_by_hand():
    Fa = axial_load_shares(3000.0, [4000.0, 2000.0, 0.0, 2000.0])
    assert Fa.tolist() == [1500.0, 750.0, 0.0, 750.0]
    with pytest.raises(CombinationError, match="no roller is loaded"):
        axial_load_shares(100.0, [0.0, 0.0])
    with pytest.raises(UnknownNameError):
        axial_load_shares(100.0, [1.0], rule="stiffness")


def test_tilting_couple_from_the_contact_points():
    """M = sum of r x F over the two contacts, written out from the geometry: end A
    (inner flange, x = -l/2) touched at (x_A - R_e cos t, -R_e sin t) by N(cos t, sin t),
    end B at (x_B + R_e cos t, R_e sin t) by -N(cos t, sin t), the sphere centres at
    x_A = -l/2 + R_e and x_B = l/2 - R_e; the forces cancel and the couple is
    F_a tan t (2 R_e - l)."""
    Fa, t, Re, l = 500.0, GEOM["flange_angle"], GEOM["end_radius"], GEOM["roller_length"]
    N = Fa / math.cos(t)
    xA, xB = -l / 2 + Re, l / 2 - Re
    pA = np.array([xA - Re * math.cos(t), -Re * math.sin(t)])
    pB = np.array([xB + Re * math.cos(t), Re * math.sin(t)])
    FA = N * np.array([math.cos(t), math.sin(t)])
    FB = -FA
    cross = lambda p, f: p[0] * f[1] - p[1] * f[0]     # noqa: E731
    M = cross(pA, FA) + cross(pB, FB)
    c = flange_contacts(Fa, **GEOM)
    assert c.tilting_moment == pytest.approx(M, rel=1e-12)
    assert M == pytest.approx(Fa * math.tan(t) * (2 * Re - l), rel=1e-12)
    # the contact points are where the end sphere's normal is the flange's
    assert c.offset == pytest.approx(-pA[1], rel=1e-15)
    assert c.height == pytest.approx(GEOM["roller_diameter"] / 2 - Re * math.sin(t),
                                     rel=1e-15)


def test_end_sphere_on_a_flat_flange_is_hertz_sphere_on_plane():
    """With the flange's circumferential curvature made negligible (a huge pitch
    diameter), each contact is a sphere R_e on a plane:
    a = (3 N R_e / (4 E*))^(1/3), p0 = 3 N / (2 pi a^2): within 1e-4."""
    g = dict(GEOM, pitch_diameter=1e3)
    c = flange_contacts(800.0, **g)
    N = 800.0 / math.cos(g["flange_angle"])
    a = (3 * N * g["end_radius"] / (4 * g["estar"])) ** (1 / 3)
    p0 = 3 * N / (2 * math.pi * a * a)
    assert c.inner_p0 == pytest.approx(p0, rel=1e-4)
    assert c.outer_p0 == pytest.approx(p0, rel=1e-4)
    assert c.inner_semi_axes[0] == pytest.approx(a, rel=1e-4)


def test_inner_flange_is_the_more_stressed_one():
    """The inner ring's flange is convex along the circumference, the outer's concave:
    at the same force the inner contact is smaller and its pressure higher."""
    c = flange_contacts(np.array([0.0, 300.0, 900.0]), **GEOM)
    assert c.inner_p0[0] == 0.0 and c.outer_p0[0] == 0.0
    assert np.all(c.inner_p0[1:] > c.outer_p0[1:])
    # Hertz: p0 ~ N^(1/3)
    assert c.inner_p0[2] / c.inner_p0[1] == pytest.approx(3 ** (1 / 3), rel=1e-12)
    assert np.all(c.inner_rim_margin[1:] > 0)


def test_contact_off_the_flange_is_refused():
    """R_e sin(theta) too small: the end would touch above the flange rim."""
    with pytest.raises(CombinationError, match="outside the flange face"):
        flange_contacts(500.0, **dict(GEOM, flange_angle=math.radians(1)))
