"""The bearing-life quantities through RadialRollerBearing: operating clearance from
fits and temperature, EHL film and Lambda per contact, kappa and the modified lives,
static safety, flange contacts, damage per roller and the duty cycle; each against a
hand computation of its formula (docs/bearing_life.md's worked example)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.bearing import (LoadCase, RadialRollerBearing, basic_rating_life,
                                 solve_spectrum)
from linecontact.errors import CombinationError, OutOfRangeError

Z, DM, D, L = 14, 70e-3, 11e-3, 11e-3
W = 1500 * math.pi / 30                      # 1500 r/min [rad/s]
OIL = dict(viscosity=20.7e-6, density=860.0, pressure_viscosity=2e-8)
SURF = dict(roughness_roller=0.1e-6, roughness_raceway=0.15e-6)
FLANGES = dict(end_radius=60e-3, flange_angle=math.radians(3),
               inner_flange_height=3.2e-3, outer_flange_height=3.2e-3)
E_STEEL = 2 * 115.38e9 * (1 - 0.3 ** 2)      # the rings' E from the default E*, nu


def _bearing(**kw):
    return RadialRollerBearing(Z, DM, D, L, kw.pop("clearance", 40e-6), **kw)


# -- operating clearance --------------------------------------------------------------
def test_press_fit_shrinks_the_clearance_by_the_hand_ring_expansion():
    """A solid steel shaft in a steel ring grows the raceway by I d/d_r (Lame, one
    material): 20 um * 50/59 = 16.949 um; a massive steel housing shrinks the outer
    raceway by I D_r/D_o; rollers at the rings' mean temperature: -alpha dT d_m."""
    b = _bearing(shaft_interference=20e-6, bore=50e-3)
    assert b.clearance == pytest.approx(40e-6 - 20e-6 * 50 / 59, rel=1e-12)
    assert b.internal_clearance == 40e-6
    Dr = DM + D + 40e-6
    h = _bearing(housing_interference=15e-6, outside_diameter=100e-3)
    assert h.clearance == pytest.approx(40e-6 - 15e-6 * Dr / 100e-3, rel=1e-12)
    t = _bearing(temperature_difference=10.0)
    assert t.clearance == pytest.approx(40e-6 - 12e-6 * 10 * DM, rel=1e-12)
    s = _bearing(shaft_interference=20e-6, bore=50e-3, temperature_difference=10.0)
    ch = s.solve(10e3).clearance_changes
    assert ch["inner_fit"] + ch["outer_fit"] + ch["thermal"] + 40e-6 == \
        pytest.approx(s.clearance, rel=1e-12)
    assert s.clearance == pytest.approx(14.651e-6, rel=1e-4)     # docs' hand value
    # ring and housing of one material: the massive housing's I D_r/D_o whatever E
    al = _bearing(housing_interference=15e-6, outside_diameter=100e-3, ring_modulus=70e9)
    assert al.clearance == pytest.approx(h.clearance, rel=1e-12)


def test_press_fit_widens_the_load_zone_and_lengthens_L10r_a_preload_shortens_it():
    """The load distribution uses the operating clearance: a fit from 40 um to 23 um
    widens the load zone (psi_l = arccos(P_d/(2 delta_r))), lowers Q_max and lengthens
    L10r; a fit that leaves a preload loads every roller and L10r falls below the
    zero-clearance bearing's. ISO 281's L10 does not see the clearance."""
    F = 10e3
    loose = _bearing().solve(F)
    fitted = _bearing(shaft_interference=20e-6, bore=50e-3).solve(F)
    hand = RadialRollerBearing(Z, DM, D, L, 40e-6 - 20e-6 * 50 / 59).solve(F)
    assert fitted.clearance == pytest.approx(hand.clearance, rel=1e-12)
    assert fitted.max_roller_load == pytest.approx(hand.max_roller_load, rel=1e-9)
    assert fitted.load_zone > loose.load_zone
    assert fitted.max_roller_load < loose.max_roller_load
    assert fitted.life_iso16281 > loose.life_iso16281
    pre = _bearing(shaft_interference=80e-6, bore=50e-3).solve(F)
    zero = RadialRollerBearing(Z, DM, D, L).solve(F)
    assert pre.clearance < 0 and np.all(pre.roller_loads > 0)
    assert pre.life_iso16281 < zero.life_iso16281
    assert fitted.life_iso281 == loose.life_iso281


# -- film, kappa, modified lives ------------------------------------------------------
def _pan_hamrock(u, R, w, estar, eta, alpha, c=1.714, ew=-0.128, eu=0.694, eg=0.568):
    E = 2 * estar
    return R * c * (w / (E * R)) ** ew * (eta * u / (E * R)) ** eu * (alpha * E) ** eg


def test_minimum_film_per_contact_is_pan_hamrock_by_hand():
    """h_min of the most loaded roller's inner and outer contact: Pan & Hamrock's
    h_min/R = 1.714 W'^-0.128 U^0.694 G^0.568 with u = (d_m/4)(1 - (D/d_m)^2) omega,
    R_in = (1/r + 1/r_i)^-1, R_out = (1/r - 1/r_o)^-1, w' = Q/L; within 1 % of the hand number
    (0.1760 um inner, docs/bearing_life.md) and to round-off of the formula; Dowson &
    Higginson's 2.65 U^0.70 G^0.54 W'^-0.13 likewise."""
    s = _bearing(**OIL, **SURF).solve(10e3, speed=W)
    u = DM / 4 * (1 - (D / DM) ** 2) * W
    r1, ri, ro = D / 2, (DM - D) / 2, (DM + D) / 2 + 40e-6 / 2
    Rin, Rout = 1 / (1 / r1 + 1 / ri), 1 / (1 / r1 - 1 / ro)
    j = int(np.argmax(s.roller_loads))
    w = s.roller_loads[j] / L
    eta = 860.0 * 20.7e-6
    assert s.entrainment_speed == pytest.approx(u, rel=1e-12)
    hin = _pan_hamrock(u, Rin, w, 115.38e9, eta, 2e-8)
    hout = _pan_hamrock(u, Rout, w, 115.38e9, eta, 2e-8)
    assert np.all(s.film_minimum_inner[j] == pytest.approx(hin, rel=1e-12))
    assert np.all(s.film_minimum_outer[j] == pytest.approx(hout, rel=1e-12))
    assert s.film_minimum_inner[j, 0] == pytest.approx(0.1760e-6, rel=1e-2)
    assert s.film_minimum_outer[j, 0] == pytest.approx(0.2020e-6, rel=1e-2)
    hc = _pan_hamrock(u, Rin, w, 115.38e9, eta, 2e-8, 2.922, -0.166, 0.692, 0.470)
    assert s.film_central_inner[j, 0] == pytest.approx(hc, rel=1e-12)
    assert s.film_ratio_inner[j] == pytest.approx(hin / math.hypot(0.1e-6, 0.15e-6),
                                                  rel=1e-12)
    assert s.film_ratio == pytest.approx(min(s.film_ratio_inner.min(),
                                             s.film_ratio_outer.min()), rel=0)
    unloaded = s.roller_loads == 0
    assert np.all(np.isinf(s.film_minimum_inner[unloaded]))
    dh = _bearing(**OIL, film_formula="dowson-higginson").solve(10e3, speed=W)
    assert dh.film_minimum_inner[j, 0] == pytest.approx(
        _pan_hamrock(u, Rin, w, 115.38e9, eta, 2e-8, 2.65, -0.13, 0.70, 0.54), rel=1e-12)


def test_film_per_slice_of_a_profiled_roller_follows_its_lamina_line_loads():
    """A profiled roller: each lamina's h_min is the formula at that lamina's line load
    q_k/(L/n_s); the crowned ends carry less and have the thicker film (W'^-0.128)."""
    b = RadialRollerBearing(12, 60e-3, 8e-3, 8e-3, profile="circular:Rc=0.5", **OIL)
    s = b.solve(8e3, speed=W)
    j = int(np.argmax(s.roller_loads))
    n = s.slice_loads_inner.shape[1]
    u = 60e-3 / 4 * (1 - (8e-3 / 60e-3) ** 2) * W
    Rin = 1 / (1 / 4e-3 + 1 / 26e-3)
    on = s.slice_loads_inner[j] > 0
    hand = _pan_hamrock(u, Rin, s.slice_loads_inner[j, on] / (8e-3 / n), 115.38e9,
                        860 * 20.7e-6, 2e-8)
    assert s.film_minimum_inner[j, on] == pytest.approx(hand, rel=1e-12)
    mid = s.film_minimum_inner[j, n // 2]
    assert np.all(s.film_minimum_inner[j, on] >= mid * (1 - 1e-12))


def test_kappa_and_modified_lives_by_hand():
    """kappa = nu/nu1, nu1 = 4500 n^-0.5 d_m^-0.5 (n >= 1000 r/min): 20.7/13.887 =
    1.4906; a_ISO = 0.1[1 - (1.5859 - 1.2348/kappa^0.071739)(e_C C_u/P)^0.4]^-9.185
    with C_u = C0/8.2; L_nm = a1 a_ISO L10 (158.3 by hand at 99 %)."""
    s = _bearing(**OIL, contamination=0.5, reliability=0.99).solve(10e3, speed=W)
    nu1 = 4500 / math.sqrt(1500 * 70) * 1e-6
    assert s.rated_viscosity == pytest.approx(nu1, rel=1e-12)
    assert s.kappa == pytest.approx(20.7e-6 / nu1, rel=1e-12)
    C0 = 44e6 * (1 - D / DM) * Z * L * D
    assert s.fatigue_load_limit == pytest.approx(C0 / 8.2, rel=1e-12)
    x = 0.5 * C0 / 8.2 / 10e3
    a = 0.1 * (1 - (1.5859 - 1.2348 / s.kappa ** 0.071739) * x ** 0.4) ** -9.185
    a1 = 0.95 * (math.log(1 / 0.99) / math.log(1 / 0.9)) ** (2 / 3) + 0.05
    assert s.life_modification == pytest.approx(a, rel=1e-12)
    assert s.reliability_factor == pytest.approx(a1, rel=1e-12)
    assert s.life_modified == pytest.approx(a1 * a * s.life_iso281, rel=1e-12)
    assert s.life_modified == pytest.approx(158.3, rel=1e-3)
    Pref = s.rating * s.life_iso16281 ** -0.3
    assert s.reference_load == pytest.approx(Pref, rel=1e-12)
    assert s.life_modified_reference == pytest.approx(
        a1 * s.life_modification_reference * s.life_iso16281, rel=1e-12)


# -- static safety ----------------------------------------------------------------------
def test_static_safety_is_C0_over_P0_and_pressure_safety_from_the_peak():
    """s0 = C0r/P0r with ISO 76's C0r = 44 (1 - D/d_m) Z L D [N, mm] and P0r = F_r;
    the stress-based safety (4000 MPa/p_max)^2 from the computed peak pressure."""
    s = _bearing().solve(10e3)
    C0 = 44 * (1 - 11 / 70) * 14 * 11 * 11
    assert s.static_rating == pytest.approx(C0, rel=1e-12)
    assert s.static_load == 10e3
    assert s.static_safety == s.static_rating / s.static_load
    assert s.pressure_safety == pytest.approx((4000e6 / s.peak_pressure) ** 2, rel=1e-12)
    given = _bearing(static_rating=50e3).solve(10e3)
    assert given.static_safety == 5.0


# -- flanges ----------------------------------------------------------------------------
@pytest.mark.parametrize("rule", ["proportional", "equal"])
def test_flange_forces_sum_to_the_axial_load(rule):
    """Each roller passes F_a,j from one flange to the other; sum_j F_a,j = F_a, only
    loaded rollers carry it; each contact's normal force is F_a,j/cos(theta) and the
    couple F_a,j tan(theta)(2 R_e - l)."""
    s = _bearing(**FLANGES, axial_share=rule).solve(10e3, axial_load=1000.0)
    assert s.flange_forces.sum() == pytest.approx(1000.0, rel=1e-12)
    assert np.all(s.flange_forces[s.roller_loads == 0] == 0)
    th = math.radians(3)
    assert s.flange_normal_forces == pytest.approx(s.flange_forces / math.cos(th),
                                                   rel=1e-12)
    assert s.flange_couple == pytest.approx(
        s.flange_forces * math.tan(th) * (2 * 60e-3 - L), rel=1e-12)
    on = s.roller_loads > 0
    assert s.flange_load_offset[on] == pytest.approx(
        s.flange_couple[on] / (2 * s.roller_loads[on]), rel=1e-12)
    assert np.all(s.flange_pressure_inner[on] > s.flange_pressure_outer[on])
    tilted = _bearing(**FLANGES).solve(10e3, misalignment=3e-4, axial_load=500.0)
    assert tilted.flange_forces.sum() == pytest.approx(500.0, rel=1e-12)


# -- damage and duty cycle --------------------------------------------------------------
def test_roller_damage_shares_sum_to_one_and_follow_the_load():
    s = _bearing().solve(10e3)
    assert s.roller_damage.sum() == pytest.approx(1.0, rel=1e-12)
    assert int(np.argmax(s.roller_damage)) == int(np.argmax(s.roller_loads))
    assert np.all(s.roller_damage[s.roller_loads == 0] == 0)


def test_two_case_spectrum_life_is_palmgren_miner_through_the_bearing():
    """Shares of revolutions t1, t2 at lives L1, L2 solved alone: L = 1/(t1/L1 + t2/L2)
    for every life kind; shares of time at speeds n_i become t_i n_i / sum t_j n_j."""
    b = _bearing(**OIL, contamination=0.5)
    c1 = LoadCase(0.3, 10e3, speed=W)
    c2 = LoadCase(0.7, 20e3, speed=W / 2, misalignment=2e-4)
    r = solve_spectrum(b, [c1, c2], shares="revolutions")
    s1 = b.solve(10e3, speed=W)
    s2 = b.solve(20e3, misalignment=2e-4, speed=W / 2)
    for kind, attr in (("iso281", "life_iso281"), ("iso16281", "life_iso16281"),
                       ("modified", "life_modified"),
                       ("modified_reference", "life_modified_reference")):
        L1, L2 = getattr(s1, attr), getattr(s2, attr)
        assert r.life[kind] == pytest.approx(1 / (0.3 / L1 + 0.7 / L2), rel=1e-12)
        assert r.damage[kind] == pytest.approx(
            [0.3 / L1 * r.life[kind], 0.7 / L2 * r.life[kind]], rel=1e-12)
    assert r.life["iso281"] == pytest.approx(
        1 / (0.3 / basic_rating_life(s1.rating, 10e3)
             + 0.7 / basic_rating_life(s1.rating, 20e3)), rel=1e-12)
    t = solve_spectrum(b, [c1, c2])                        # shares of time
    u1 = 0.3 * W / (0.3 * W + 0.7 * W / 2)
    assert t.revolution_shares[0] == pytest.approx(u1, rel=1e-12)
    L1, L2 = t.lives["iso281"]
    life = 1 / (u1 / L1 + (1 - u1) / L2)
    assert t.life["iso281"] == pytest.approx(life, rel=1e-12)
    assert t.hours["iso281"] == pytest.approx(
        life * 1e6 * 2 * math.pi / (0.3 * W + 0.7 * W / 2) / 3600, rel=1e-12)


def test_a_standstill_case_of_a_lubricated_bearing_takes_no_damage():
    """A duty cycle with a case at standstill (shares of time, speed 0): it takes no
    revolutions, so the combined lives are the turning case's alone (every kind,
    the modified ones too), and its hours count the standstill time; the case is
    solved for its static safety, without the film and kappa that need rotation
    (a lubricated bearing's solve() refuses speed 0; the spectrum must not)."""
    b = _bearing(**OIL, contamination=0.5)
    r = solve_spectrum(b, [LoadCase(0.7, 10e3, speed=W), LoadCase(0.3, 30e3, speed=0.0)])
    s1 = b.solve(10e3, speed=W)
    assert r.revolution_shares.tolist() == [1.0, 0.0]
    for kind, attr in (("iso281", "life_iso281"), ("modified", "life_modified"),
                       ("modified_reference", "life_modified_reference")):
        assert r.life[kind] == pytest.approx(getattr(s1, attr), rel=1e-12)
        assert r.damage[kind].tolist() == [1.0, 0.0]
        # 1e6 revolutions at 1500 r/min for 70 % of the time
        assert r.hours[kind] == pytest.approx(
            getattr(s1, attr) * 1e6 / (0.7 * 1500 * 60), rel=1e-12)
    assert math.isnan(r.lives["modified"][1]) and r.solutions[1].kappa is None
    assert r.solutions[1].static_safety == pytest.approx(
        r.solutions[1].static_rating / 30e3, rel=1e-15)


# -- the new inputs change nothing they do not concern ----------------------------------
def test_lubricant_flanges_and_speed_leave_the_load_distribution_unchanged():
    """Film, life and flange inputs are read off the load distribution: every field of
    the plain solution is the same, bit for bit, with them."""
    plain = _bearing().solve(10e3)
    full = _bearing(**OIL, **SURF, contamination=0.5, reliability=0.99,
                    **FLANGES).solve(10e3, speed=W, axial_load=1000.0)
    keep = [k for k, v in plain.to_dict().items()
            if v is not None and k not in ("notes",)]
    a, b = plain.to_dict(), full.to_dict()
    assert all(repr(a[k]) == repr(b[k]) for k in keep)
    assert plain.speed is None and plain.film_ratio is None and plain.axial_load is None


# -- refusals ---------------------------------------------------------------------------
@pytest.mark.parametrize("kw,missing", [
    (dict(density=860.0, pressure_viscosity=2e-8), "viscosity"),
    (dict(viscosity=20e-6, pressure_viscosity=2e-8), "density"),
    (dict(viscosity=20e-6, **SURF), "pressure_viscosity"),
    (dict(contamination=0.5), "viscosity"),
    (dict(viscosity=20e-6, reliability=0.99), "contamination"),
    (dict(shaft_interference=20e-6), "bore"),
    (dict(bore=50e-3), "shaft_interference"),
    (dict(housing_interference=20e-6), "outside_diameter"),
    (dict(end_radius=60e-3, flange_angle=0.05), "inner_flange_height"),
])
def test_an_input_group_given_in_part_is_refused_naming_the_missing(kw, missing):
    with pytest.raises(CombinationError, match=f"{missing} = None"):
        _bearing(**kw)


def test_refusals_at_solve():
    with pytest.raises(CombinationError, match="speed"):
        _bearing(**OIL).solve(10e3)
    with pytest.raises(OutOfRangeError, match="speed"):
        _bearing(**OIL).solve(10e3, speed=0.0)
    with pytest.raises(CombinationError, match="axial_load"):
        _bearing().solve(10e3, axial_load=100.0)
    with pytest.raises(OutOfRangeError, match="bore"):
        _bearing(shaft_interference=20e-6, bore=60e-3)
