"""The composed contact (linecontact.contact): every composition against an oracle or an
identity, named in each test's docstring.

Crowned rollers use 40 coupled slices: the identities hold at any slice count and the
Hertz oracles are met to 1e-4 there (k d/F = 1.50012 at 50 N, 1.50002 at 200 N for the
5 mm x 10 mm roller with a 50 mm crown; 1.500002 at 100 slices).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.contact import (Concave, Contact, Convex, Elastic, Flat, Raceways,
                                 Roller, Viscoelastic)
from linecontact.errors import CombinationError, UnknownNameError
from linecontact.profiles import CircularCrownProfile
from linecontact.raceway import roller_between_raceways
from linecontact.roller import ProfiledRoller
from linecontact.viscoelastic import PronySeries, StandardLinearSolid, effective_relaxation

N = 40
STEEL = Elastic(210e9, 0.3)
RIGID = Elastic(math.inf)


def crowned(**kw):
    return Contact(Roller(5e-3, 10e-3, crown_radius=0.05), None, STEEL, STEEL,
                   n_slices=N, **kw)


def test_at_nu_zero_a_crowned_contacts_tangential_law_is_its_normal_law():
    """At nu = 0 (G* = E*) the MDR is exact for any shape: k_t = k_n of the crowned
    contact itself, and the tangential force at a shift u is mu [F(e) - F(e - u/mu)]
    from the crowned roller's own F(e), evaluated here directly with ProfiledRoller
    (agreement 1e-9)."""
    zero = Elastic(210e9, 0.0)
    c = Contact(Roller(5e-3, 10e-3, crown_radius=0.05), None, zero, zero, n_slices=N)
    n = c.normal(force=200.0)
    t = c.tangential(0.2, force=200.0, shift=0.3 * 0.2 * n.approach)
    assert t.shear_ratio == 1.0
    assert t.stiffness == pytest.approx(t.normal.stiffness, rel=1e-15)
    assert t.stiffness == pytest.approx(n.stiffness, rel=1e-9)
    roller = ProfiledRoller(5e-3, 10e-3, c.estar, CircularCrownProfile(10e-3, 0.05),
                            n_slices=N)
    e = n.approach
    direct = 0.2 * (roller.at_depth(e, 0.0).force - roller.at_depth(0.7 * e, 0.0).force)
    assert t.tangential_force == pytest.approx(direct, rel=1e-9)


def test_crowned_mdr_tangential_stiffness_is_gstar_over_estar_times_its_own_hertz_kn():
    """A crowned contact's MDR k_t (method="mdr"; the default is Mindlin's by direction,
    tests/test_contact_mindlin.py) is G*/E* = 2(1 - nu)/(2 - nu) times its own k_n, and
    in the Hertz range (contact inside the roller) k_n = 3/2 F/delta (F ~ delta^3/2;
    to 2e-4 at 40 slices): the crowned value, not the straight cylinder's."""
    c = crowned()
    t = c.tangential(0.15, force=200.0, method="mdr")
    n = t.normal
    assert not n.solutions[0].edge_loaded
    assert t.shear_ratio == pytest.approx(2 * 0.7 / 1.7, rel=1e-14)
    assert t.stiffness == pytest.approx(t.shear_ratio * n.stiffness, rel=1e-15)
    assert n.stiffness == pytest.approx(1.5 * n.force / n.approach, rel=2e-4)
    straight = Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL).tangential(0.15,
                                                                         force=200.0)
    assert straight.stiffness > 1.2 * t.stiffness, "a crown is softer than a straight line"


def test_cam_follower_of_the_issue_gets_its_crowned_tangential_stiffness():
    """The crowned cam follower (R 8 mm, L 12 mm, Rc 300 mm, on a 25 mm cam, steel,
    2 kN): k_t with method="mdr" is its own MDR value, G*/E* k_n of the crowned contact
    (about 187 N/um), not the straight roller's (about 355 N/um)."""
    c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), STEEL, STEEL,
                n_slices=N)
    t = c.tangential(0.15, force=2e3, tangential_force=100.0, method="mdr")
    assert t.stiffness == pytest.approx(t.shear_ratio * t.normal.stiffness, rel=1e-15)
    assert 180e6 < t.stiffness < 195e6
    s = Contact(Roller(8e-3, 12e-3), Convex(25e-3), STEEL, STEEL).tangential(
        0.15, force=2e3, tangential_force=100.0)
    assert 340e6 < s.stiffness < 370e6


def test_crowned_partial_slip_follows_mindlin():
    """In the Hertz range the shift under Q has Mindlin's (1949) form,
    u = u* [1 - (1 - Q/(mu F))^(2/3)], u* = mu e/r (exact for F ~ e^3/2 whatever the
    ratio r: Mindlin's ellipse's by default; 1e-3 at 40 slices); a negative Q gives the
    same shift negated (the sign is the direction)."""
    c = crowned()
    mu, F = 0.15, 200.0
    for frac in (0.2, 0.7):
        t = c.tangential(mu, force=F, tangential_force=frac * mu * F)
        expect = t.gross_slip_shift * (1 - (1 - frac) ** (2 / 3))
        assert t.shift == pytest.approx(expect, rel=1e-3)
        assert t.state == "partial slip" and t.slip_fraction == pytest.approx(frac)
        neg = c.tangential(mu, force=F, tangential_force=-frac * mu * F)
        assert neg.shift == pytest.approx(-t.shift, rel=1e-12)


def test_gross_slip_gives_no_shift_and_says_why():
    """|Q| > mu F: the contact slides; the shift is None and get('shift') raises the
    reason with the numbers."""
    t = Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL).tangential(
        0.1, force=1e3, tangential_force=150.0)
    assert t.state == "gross slip" and t.shift is None
    with pytest.raises(CombinationError, match="tangential_force = 150.*slides"):
        t.get("shift")


def test_a_crown_radius_is_a_profile_and_selects_the_slice_model():
    """Roller(crown_radius=Rc) is the circular crown: the contact uses coupled slices
    and equals ProfiledRoller with CircularCrownProfile(L, Rc) (to rounding); the
    convex counter-body's effective radius 1/(1/R1 + 1/R2) is the roller's radius
    there."""
    c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), STEEL, STEEL,
                n_slices=N)
    assert c.model == "profiled-roller"
    r = c.normal(force=2e3)
    R = 1 / (1 / 8e-3 + 1 / 25e-3)
    direct = ProfiledRoller(R, 12e-3, c.estar, CircularCrownProfile(12e-3, 0.3),
                            n_slices=N).at_force(2e3, tilt=0.0)
    assert r.depth == pytest.approx(direct.depth, rel=1e-12)
    assert r.peak_pressure == pytest.approx(direct.p_max, rel=1e-12)
    np.testing.assert_allclose(r.q, direct.q, rtol=1e-12)


def test_no_tilt_given_is_aligned_and_free_tilt_is_asked_for():
    """Decided behaviour: no tilt given is an aligned roller (tilt 0, a moment for an
    asymmetric crown); tilt='free' solves the moment to zero (1e-9 F L)."""
    prof = CircularCrownProfile(10e-3, 0.05, offset=1e-3)
    held = Contact(Roller(5e-3, 10e-3, profile=prof), estar=115e9,
                   n_slices=N).normal(force=500.0)
    assert held.tilt == 0.0 and abs(held.moment) > 1e-3
    free = Contact(Roller(5e-3, 10e-3, profile=prof, tilt="free"), estar=115e9,
                   n_slices=N).normal(force=500.0)
    assert abs(free.moment) <= 1e-9 * 500.0 * 10e-3 and free.tilt != 0.0


def test_free_tilt_at_a_depth_balances_the_moment():
    """tilt='free' with a depth: the tilt at which the moment about the centre vanishes
    at that centre depth (the force-controlled free tilt, fed back as a depth, returns
    the same tilt and force to 1e-6)."""
    prof = CircularCrownProfile(10e-3, 0.05, offset=1e-3)
    c = Contact(Roller(5e-3, 10e-3, profile=prof, tilt="free"), estar=115e9, n_slices=N)
    a = c.normal(force=500.0)
    b = c.normal(depth=a.depth)
    assert b.tilt == pytest.approx(a.tilt, rel=1e-6)
    assert b.force == pytest.approx(500.0, rel=1e-6)


def test_viscoelastic_crowned_roller_creeps_from_e0_to_einf():
    """Lee & Radok with a crowned roller (coupled slices, the contact grows under a held
    force): at t = 0 the depth is the elastic one at E*(0), at t >> tau the elastic one
    at E*(inf) (independent Contact objects with those moduli; 1e-9)."""
    sls = StandardLinearSolid(3e9, 1e9, 10.0)
    c = Contact(Roller(5e-3, 10e-3, crown_radius=0.2), None, RIGID,
                Viscoelastic(sls, 0.0), n_slices=N)
    r = c.creep([0.0, 1e6], force=50.0)
    e0 = Contact(Roller(5e-3, 10e-3, crown_radius=0.2), estar=3e9,
                 n_slices=N).normal(force=50.0)
    einf = Contact(Roller(5e-3, 10e-3, crown_radius=0.2), estar=1e9,
                   n_slices=N).normal(force=50.0)
    assert r.depth[0] == pytest.approx(e0.depth, rel=1e-9)
    assert r.depth[1] == pytest.approx(einf.depth, rel=1e-9)
    assert r.long_term_depth == pytest.approx(einf.depth, rel=1e-9)


def test_viscoelastic_body_against_an_elastic_one_adds_compliances():
    """A viscoelastic body on an elastic one: J*(t) = (1 - nu1^2) J1(t) + (1 - nu2^2)/E2
    (the compliances add), for a three-term Prony series (inverted numerically) and a
    standard linear solid (closed form), at five times (1e-10)."""
    t = np.array([0.0, 0.05, 3.0, 200.0, 1e5])
    for body in (PronySeries(1e9, moduli=[2e9, 1e9, 0.5e9], times=[0.1, 10.0, 300.0]),
                 StandardLinearSolid(3e9, 1e9, 10.0)):
        m = effective_relaxation(body, 0.4, 210e9, 0.3)
        expect = (1 - 0.4 ** 2) * body.creep(t) + (1 - 0.3 ** 2) / 210e9
        np.testing.assert_allclose(m.creep(t), expect, rtol=1e-10)


def test_a_viscoelastic_roller_between_raceways_creeps_as_its_two_contacts():
    """A polymer roller between steel rings under a held force: the ring approach at
    each time is the sum of the two contacts' creep depths computed one by one (Contact
    with Convex(Ri) and Concave(Ro), same materials; 1e-12), for a law and for a
    crowned roller (coupled slices)."""
    sls = Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.4)
    t = [0.0, 10.0, 1e4]
    for roller in (Roller(5e-3, 10e-3), Roller(5e-3, 10e-3, crown_radius=0.2)):
        whole = Contact(roller, Raceways(20e-3, 30e-3), sls, STEEL, n_slices=N)
        r = whole.creep(t, force=200.0)
        parts = [Contact(roller, body, sls, STEEL, n_slices=N).creep(t, force=200.0)
                 for body in (Convex(20e-3), Concave(30e-3))]
        np.testing.assert_allclose(r.depth, parts[0].depth + parts[1].depth, rtol=1e-12)
        assert r.long_term_depth == pytest.approx(
            parts[0].long_term_depth + parts[1].long_term_depth, rel=1e-12)


def test_relaxation_under_a_held_depth_follows_the_relaxation_function():
    """A held depth relaxes the force with E*(t)/E*(0) (Lee & Radok, step and hold:
    exact), for a straight roller on a rigid-backed SLS: 1/3 at t >> tau."""
    c = Contact(Roller(5e-3, 10e-3), None, RIGID,
                Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    r = c.relaxation_history([0.0, 10.0, 1e5], depth=2e-6)
    assert r.force[1] / r.force[0] == pytest.approx((1 + 2 * math.exp(-1)) / 3,
                                                    rel=1e-12)
    assert r.force[2] / r.force[0] == pytest.approx(1 / 3, rel=1e-12)


def test_raceways_in_a_contact_are_the_whole_roller():
    """Contact(..., Raceways) is roller_between_raceways of the same parts (identical),
    and its depth is the ring approach d_in + d_out."""
    race = Raceways(inner_diameter=40e-3, outer_diameter=60e-3)
    c = Contact(Roller(diameter=10e-3, length=10e-3, crown_radius=0.2), race, STEEL,
                STEEL, n_slices=N)
    r = c.normal(force=1e3)
    s = roller_between_raceways(5e-3, 10e-3, c.estar, race, force=1e3,
                                profile=CircularCrownProfile(10e-3, 0.2), n_slices=N)
    assert r.depth == s.deflection == s.depth_inner + s.depth_outer
    assert r.stiffness == s.stiffness


def test_a_law_between_raceways_gives_one_solution_per_load():
    """Over an array of loads a law between raceways returns the arrays and one
    RacewaySolution per load, each equal to that load solved alone (to rounding)."""
    c = Contact(Roller(5e-3, 10e-3), Raceways(20e-3, 30e-3), STEEL, STEEL)
    r = c.normal(force=[1e3, 2e3, 3e3])
    assert len(r.solutions) == 3
    for k, F in enumerate((1e3, 2e3, 3e3)):
        one = c.normal(force=F)
        assert r.depth[k] == pytest.approx(one.depth, rel=1e-14)
        assert r.solutions[k].deflection == pytest.approx(one.depth, rel=1e-14)
        assert r.solutions[k].peak_pressure_outer == pytest.approx(
            one.solutions[0].peak_pressure_outer, rel=1e-14)


def test_effective_radius_of_each_counterbody():
    """Flat: R1; convex: 1/(1/R1 + 1/R2); concave: 1/(1/R1 - 1/R2) (Johnson 1985,
    section 4.2), radii or diameters alike."""
    assert Flat().effective_radius(8e-3) == 8e-3
    assert Convex(diameter=50e-3).effective_radius(8e-3) == pytest.approx(
        1 / (1 / 8e-3 + 1 / 25e-3), rel=1e-15)
    assert Concave(25e-3).effective_radius(8e-3) == pytest.approx(
        1 / (1 / 8e-3 - 1 / 25e-3), rel=1e-15)
    with pytest.raises(CombinationError, match="does not fit inside"):
        Concave(5e-3).effective_radius(8e-3)


@pytest.mark.parametrize("build, match", [
    (lambda: Contact(Roller(5e-3, 10e-3), None, Viscoelastic(StandardLinearSolid(
        3e9, 1e9, 10.0), 0.4), Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.4)),
     "one viscoelastic body against an elastic one"),
    (lambda: Contact(Roller(5e-3, 10e-3, crown_radius=0.3), estar=1e11,
                     model="universal"), "straight-cylinder law has no profile"),
    (lambda: Contact(Roller(5e-3, 10e-3), estar=1e11).tangential(0.1, force=1e3),
     "G\\* needs the bodies' Poisson ratios"),
    (lambda: Contact(Roller(5e-3, 10e-3), None, RIGID, Viscoelastic(
        StandardLinearSolid(3e9, 1e9, 10.0), 0.4)).tangential(0.1, force=1e3),
     "viscoelastic contact"),
    (lambda: Contact(Roller(5e-3, 10e-3, tilt="free", profile=CircularCrownProfile(
        10e-3, 0.05, offset=1e-3)), None, STEEL, STEEL, n_slices=N).tangential(
        0.1, force=1e3), "asymmetric profile"),
    (lambda: Contact(Roller(5e-3, 10e-3), Raceways(20e-3, 30e-3), STEEL,
                     STEEL).tangential(0.1, force=1e3), "between raceways"),
    (lambda: Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL).creep([0.0], force=1.0),
     "needs a viscoelastic body"),
    (lambda: Contact(Roller(5e-3, 10e-3), Raceways(20e-3, 30e-3), RIGID, Viscoelastic(
        StandardLinearSolid(3e9, 1e9, 10.0), 0.4)).relaxation_history([0.0], depth=1e-6),
     "held ring approach"),
    (lambda: Roller(5e-3, 10e-3, crown_radius=0.3, profile="straight"),
     "a crown radius is a profile"),
])
def test_undefined_combinations_are_refused_with_one_line(build, match):
    """Each combination that is not defined (physically, or by the methods here) is
    refused by a CombinationError (a ValueError) whose one line names the parameters,
    their values and why."""
    with pytest.raises(CombinationError, match=match) as err:
        build()
    assert isinstance(err.value, ValueError) and "\n" not in str(err.value)
    assert " = " in str(err.value)


def test_unknown_names_are_unknown_name_errors_listing_the_valid_ones():
    """An unknown model key or tilt word raises UnknownNameError (a ValueError, not an
    OutOfRangeError) listing what is accepted."""
    from linecontact.errors import OutOfRangeError

    with pytest.raises(UnknownNameError, match="'universal'") as err:
        Contact(Roller(5e-3, 10e-3), estar=1e11, model="hertz")
    assert not isinstance(err.value, OutOfRangeError)
    with pytest.raises(UnknownNameError, match="'free'"):
        Roller(5e-3, 10e-3, tilt="loose")


def test_a_law_states_why_it_has_no_load_distribution():
    """A straight-cylinder law has no q(x) and no tilt stiffness: None, and get()
    raises the reason naming the model."""
    r = Contact(Roller(5e-3, 10e-3), estar=115e9).normal(force=1e3)
    assert r.q is None and r.tilt_stiffness is None and r.moment == 0.0
    with pytest.raises(CombinationError, match="model = 'universal'"):
        r.get("q")
    assert r.get("force") == 1e3


def test_a_tilted_rollers_law_is_refused_by_the_laws_that_need_f0_zero():
    """A tilted roller's registered law gives F at the centre depth, which starts below
    0 (-theta^2 Rc/2 for a circular crown): the tangential and Lee-Radok laws built on
    F(d) with F(0) = 0 refuse it and name Contact, which takes the law in the
    approach (there the MDR shift is found)."""
    from linecontact.roller import ProfiledRollerModel
    from linecontact.tangential import tangential_force
    from linecontact.viscoelastic import force_history

    m = ProfiledRollerModel(5e-3, 10e-3, 115e9, "circular:Rc=0.2", tilt=1e-3,
                            n_slices=N)
    assert m.first_contact_depth == pytest.approx(-(1e-3) ** 2 * 0.2 / 2, rel=1e-9)
    with pytest.raises(CombinationError, match="Contact"):
        tangential_force(m, 1e-6, 1e-8, 0.2, 100e9)
    with pytest.raises(CombinationError, match="nonzero depth"):
        force_history(m, StandardLinearSolid(3e9, 1e9, 10.0), [0.0, 1.0], 1e-6)
    c = Contact(Roller(5e-3, 10e-3, crown_radius=0.2, tilt=1e-3), None, STEEL, STEEL,
                n_slices=N)
    t = c.tangential(0.2, force=300.0, tangential_force=30.0)
    assert t.state == "partial slip" and t.shift > 0
    assert t.normal.approach == pytest.approx(t.normal.depth + (1e-3) ** 2 * 0.2 / 2,
                                              rel=1e-9)


def test_bem_tangential_of_a_straight_cylinder_is_the_tables_and_refused_for_a_crown():
    """method='bem' gives a straight cylinder's direction-dependent k_t and shift, the
    same as linecontact.tangential.TangentialContact on the same law (1e-12); a crowned
    roller is refused (the table is for a straight, aligned cylinder)."""
    from linecontact.models import get_model
    from linecontact.tangential import TangentialContact

    c = Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL)
    m = get_model("universal", 5e-3, 10e-3, c.estar)
    for direction in ("across", "along"):
        t = c.tangential(0.1, force=1e3, tangential_force=-50.0, method="bem",
                         direction=direction)
        tc = TangentialContact(m, 0.1, c.gstar, force=1e3, method="bem",
                               direction=direction)
        assert t.stiffness == pytest.approx(tc.stiffness, rel=1e-12)
        assert t.shift == pytest.approx(tc.shift(-50.0), rel=1e-12) and t.shift < 0
    with pytest.raises(CombinationError, match="straight, aligned cylinder"):
        crowned().tangential(0.1, force=100.0, method="bem")


def test_no_tilt_is_aligned_in_every_roller_entry_point():
    """Decided behaviour, the same in every entry point: no tilt given is an aligned
    roller (ProfiledRoller.at_force, roller_contact, iso_slicing: tilt 0 and a moment for
    an offset crown); 'free' asks for zero moment; None is refused as ambiguous
    (UnknownNameError)."""
    from linecontact.roller import iso_slicing, roller_contact

    prof = "circular:Rc=0.1,x0=1mm"
    r = ProfiledRoller(5e-3, 10e-3, 115e9, prof, n_slices=N)
    for s in (r.at_force(800.0), roller_contact(5e-3, 10e-3, 115e9, prof, force=800.0,
                                                n_slices=N),
              iso_slicing(5e-3, 10e-3, 115.38e9, prof, force=800.0)):
        assert s.tilt == 0.0 and s.moment > 0
    for s in (r.at_force(800.0, "free"), r.at_depth(r.at_force(800.0, "free").depth,
                                                    "free"),
              iso_slicing(5e-3, 10e-3, 115.38e9, prof, force=800.0, tilt="free"),
              iso_slicing(5e-3, 10e-3, 115.38e9, prof, depth=2e-5, tilt="free")):
        assert abs(s.moment) <= 1e-9 * s.force * 10e-3 and s.tilt < 0
    with pytest.raises(UnknownNameError, match="aligned"):
        r.at_force(800.0, None)


def test_creep_returns_the_history_where_only_the_long_term_depth_is_out_of_range():
    """A soft long-term modulus (E_inf = 1e-3 E_0): d(t) over 100 s stays within the
    universal curve's range while d(inf) does not. The history is returned (equal to
    viscoelastic.creep_depth, the same integral), long_term_depth is None and its
    reason names the force and the range; a later time whose d(t) leaves the range is
    refused naming that time."""
    from linecontact.errors import OutOfRangeError
    from linecontact.viscoelastic import StandardLinearSolid, creep_depth

    c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                material2=Viscoelastic(StandardLinearSolid(3e9, 3e6, 10.0), 0.0))
    t = np.array([0.0, 1.0, 10.0, 30.0])
    r = c.creep(t, force=1e3)
    want = creep_depth(c.law(), c.relaxation, t, np.full(t.shape, 1e3))
    assert np.allclose(r.depth, want, rtol=1e-12, atol=0)
    assert r.long_term_depth is None
    params, reason = r.reasons["long_term_depth"]
    assert params == {"force": 1e3} and "outside" in reason and "\n" not in reason
    with pytest.raises(OutOfRangeError, match=r"at t = \d"):
        c.creep(np.array([0.0, 30.0, 1e3, 1e4]), force=1e3)
