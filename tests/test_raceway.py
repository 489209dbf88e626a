"""The whole roller between two raceways (linecontact.raceway): each result against an
identity (contacts in series, moment balance, the derivative of the computed law), the
calculator's whole-roller columns, or a refusal message with its numbers.

The slice-model tests use 40 slices: the identities checked hold at any slice count,
and 40 keeps each solve to a fraction of a second.
"""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from linecontact.errors import CombinationError, UnknownNameError
from linecontact.raceway import (FIT_TOLERANCE, Raceways, check_fit, effective_radii,
                                 roller_between_raceways)
from linecontact.roller import ProfiledRoller

R1, L = 5e-3, 10e-3
E_STEEL = 210e9 / (2 * (1 - 0.3 ** 2))          # E* of steel on steel [Pa]
RACE = Raceways(20e-3, 30e-3)
N = 40


def test_effective_radii_are_hertz_sums_of_curvatures():
    """1/R_in = 1/R1 + 1/Ri (convex), 1/R_out = 1/R1 - 1/Ro (concave) (Johnson 1985,
    section 4.2): 5 mm roller on 20/30 mm raceways gives exactly 4 mm and 6 mm."""
    r_in, r_out = effective_radii(R1, 20e-3, 30e-3)
    assert r_in == pytest.approx(4e-3, rel=1e-15)
    assert r_out == pytest.approx(6e-3, rel=1e-15)


def test_diameters_are_radii_doubled():
    """A data sheet's raceway diameters give the same raceways as their radii."""
    a = Raceways(inner_diameter=40e-3, outer_diameter=60e-3)
    assert (a.inner, a.outer) == (RACE.inner, RACE.outer)


def test_straight_roller_equals_the_calculators_whole_roller_columns():
    """A straight roller between raceways equals the calculator's whole-roller output
    (linecontact calc --inner-raceway/--outer-raceway, columns roller_deflection and
    roller_stiffness) for every single-entry law it prints, to rounding (1e-12); the
    universal-curve values are also pinned as a regression (recorded 2026-11-24 from
    the calculator before this module existed)."""
    cmd = [sys.executable, "-m", "linecontact", "calc", "--radius", "5mm", "--length",
           "10mm", "--modulus", "210GPa", "--poisson", "0.3", "--modulus2", "210GPa",
           "--poisson2", "0.3", "--inner-raceway", "20mm", "--outer-raceway", "30mm",
           "--load", "1kN", "--json"]
    data = json.loads(subprocess.run(cmd, capture_output=True, text=True,
                                     check=True).stdout)
    from linecontact.models import available_models, get_model
    from linecontact.raceway import SLICE_MODELS

    # each law with its default options, found in the output by its label
    key_of = {get_model(k, R1, L, E_STEEL).label: k for k in available_models()
              if k not in SLICE_MODELS}
    checked = 0
    for m in data["models"]:
        key = key_of.get(m["label"])
        if key is None or m["rows"][0]["roller_deflection"] is None:
            continue
        s = roller_between_raceways(R1, L, E_STEEL, RACE, force=1e3, model=key)
        row = m["rows"][0]
        assert s.deflection == pytest.approx(row["roller_deflection"], rel=1e-12), key
        assert s.stiffness == pytest.approx(row["roller_stiffness"], rel=1e-12), key
        checked += 1
    assert checked >= 4, f"only {checked} laws compared"
    s = roller_between_raceways(R1, L, E_STEEL, RACE, force=1e3)
    assert s.deflection == pytest.approx(6.320152313407059e-06, rel=1e-9)
    assert s.stiffness == pytest.approx(173579457.96528864, rel=1e-9)


def test_law_solution_is_two_contacts_in_series_and_vectorised():
    """delta = d_in(F) + d_out(F) and 1/k = 1/k_in + 1/k_out, elementwise over an array
    of loads; a given deflection returns the force that produces it (to 1e-10)."""
    from linecontact.models import get_model

    F = np.array([200.0, 1e3, 5e3])
    s = roller_between_raceways(R1, L, E_STEEL, RACE, force=F)
    mi, mo = (get_model("universal", r, L, E_STEEL) for r in (4e-3, 6e-3))
    np.testing.assert_allclose(s.deflection, mi.depth(F) + mo.depth(F), rtol=1e-13)
    np.testing.assert_allclose(
        s.stiffness, 1 / (1 / mi.stiffness_at_force(F) + 1 / mo.stiffness_at_force(F)),
        rtol=1e-12)
    back = roller_between_raceways(R1, L, E_STEEL, RACE, deflection=s.deflection)
    np.testing.assert_allclose(back.force, F, rtol=1e-10)


def test_aligned_symmetric_profiled_roller_is_the_sum_of_its_two_contacts():
    """An aligned crowned roller between raceways (tilt held at 0, and free: aligned by
    symmetry) equals its two contacts computed one by one with ProfiledRoller at the
    same force: deflection the sum of the depths (1e-9), stiffness the series value,
    no tilt, no moment."""
    prof = "circular:Rc=0.2"
    single = [ProfiledRoller(r, L, E_STEEL, prof, n_slices=N).at_force(2e3, tilt=0.0)
              for r in (4e-3, 6e-3)]
    for tilt in (0.0, "free"):
        s = roller_between_raceways(R1, L, E_STEEL, RACE, force=2e3, profile=prof,
                                    tilt=tilt, n_slices=N)
        assert s.deflection == pytest.approx(single[0].depth + single[1].depth, rel=1e-9)
        assert s.stiffness == pytest.approx(
            1 / (1 / single[0].stiffness + 1 / single[1].stiffness), rel=1e-6)
        assert abs(s.tilt) < 1e-9 and abs(s.moment) < 1e-9 * 2e3 * L
        assert s.inner is not None and s.outer is not None


def test_free_tilt_balances_the_two_contacts_moments():
    """With misaligned rings (psi = 1 mrad) and the roller free to tilt, the moments of
    its two contacts about its centre balance (M_in = M_out to 1e-9 F L) and the two
    contact tilts add up to the misalignment (theta_in + theta_out = psi)."""
    race = Raceways(20e-3, 30e-3, misalignment=1e-3)
    s = roller_between_raceways(R1, L, E_STEEL, race, force=3e3,
                                profile="circular:Rc=0.5", tilt="free", n_slices=N)
    assert s.free_tilt and s.moment == 0.0
    assert abs(s.moment_inner - s.moment_outer) <= 1e-9 * 3e3 * L
    assert s.inner.tilt + s.outer.tilt == pytest.approx(1e-3, rel=1e-12)
    assert 0 < s.tilt < 1e-3, "the roller tilts part of the way, towards the stiffer side"


def test_held_tilt_reports_the_holding_moment_and_tilt_stiffness():
    """At a held tilt the roller needs the moment M_in - M_out; the reported tilt
    stiffness is d(M_in - M_out)/d theta at constant force, checked against a central
    difference of the computed moments (step 1e-5 rad, agreement 1e-3)."""
    kw = dict(force=2e3, profile="circular:Rc=0.5", n_slices=N)
    s = roller_between_raceways(R1, L, E_STEEL, RACE, tilt=5e-4, **kw)
    assert s.moment == pytest.approx(s.moment_inner - s.moment_outer, rel=1e-15)
    h = 1e-5
    mp = roller_between_raceways(R1, L, E_STEEL, RACE, tilt=5e-4 + h, **kw).moment
    mm = roller_between_raceways(R1, L, E_STEEL, RACE, tilt=5e-4 - h, **kw).moment
    assert s.tilt_stiffness == pytest.approx((mp - mm) / (2 * h), rel=1e-3)


def test_free_tilt_radial_stiffness_is_the_derivative_of_the_deflection():
    """With the tilt free the roller's stiffness (from the two stiffness matrices with
    the moment balance kept) is 1/(d delta/dF) of the computed free-tilt solutions
    (central difference, F +- 0.5 %, agreement 1e-3)."""
    race = Raceways(20e-3, 30e-3, misalignment=1e-3)
    kw = dict(profile="circular:Rc=0.5", tilt="free", n_slices=N)
    s = roller_between_raceways(R1, L, E_STEEL, race, force=3e3, **kw)
    dp = roller_between_raceways(R1, L, E_STEEL, race, force=3015.0, **kw).deflection
    dm = roller_between_raceways(R1, L, E_STEEL, race, force=2985.0, **kw).deflection
    assert s.stiffness == pytest.approx(30.0 / (dp - dm), rel=1e-3)


def test_deflection_control_inverts_force_control_for_a_profiled_roller():
    """A deflection given returns the force whose deflection it is (1e-8)."""
    kw = dict(profile="circular:Rc=0.2", n_slices=N)
    s = roller_between_raceways(R1, L, E_STEEL, RACE, force=1500.0, **kw)
    back = roller_between_raceways(R1, L, E_STEEL, RACE, deflection=s.deflection, **kw)
    assert back.force == pytest.approx(1500.0, rel=1e-8)


def test_raceways_that_do_not_fit_are_refused_with_the_numbers():
    """Ro - Ri must be the roller diameter within the fit tolerance (1 % of 2 R1 by
    default): diameters typed as radii, or the roller's diameter typed as its radius,
    are refused with the three radii, the difference and the likely cause."""
    with pytest.raises(CombinationError) as err:
        roller_between_raceways(R1, L, E_STEEL, Raceways(40e-3, 60e-3), force=1e3)
    msg = str(err.value)
    assert "\n" not in msg
    for text in ("roller_radius = 0.005 m", "inner_radius = 0.04 m",
                 "outer_radius = 0.06 m", "Ro - Ri = 0.02 m", "2 R1 = 0.01 m",
                 "diameters given as radii"):
        assert text in msg, (text, msg)
    with pytest.raises(CombinationError, match="roller's diameter given as its radius"):
        check_fit(10e-3, 20e-3, 30e-3)
    # inside the tolerance: a radial clearance of 50 um on a 10 mm roller (0.5 %)
    assert check_fit(R1, 20e-3, 30.05e-3) == pytest.approx(50e-6, rel=1e-9)
    assert FIT_TOLERANCE == 0.01
    with pytest.raises(CombinationError, match="exactly one"):
        Raceways(20e-3, 30e-3, inner_diameter=40e-3)


def test_combinations_without_a_definition_are_refused():
    """A straight-cylinder law has no profile or tilt; an unknown model is named with
    the valid ones (UnknownNameError, not OutOfRangeError); neither force nor
    deflection is refused."""
    with pytest.raises(CombinationError, match="straight-cylinder law"):
        roller_between_raceways(R1, L, E_STEEL, RACE, force=1e3, model="universal",
                                profile="circular:Rc=0.2")
    with pytest.raises(UnknownNameError, match="'universal'"):
        roller_between_raceways(R1, L, E_STEEL, RACE, force=1e3, model="hertz")
    with pytest.raises(CombinationError, match="exactly one of force and deflection"):
        roller_between_raceways(R1, L, E_STEEL, RACE)


def test_effective_radius_is_hertz_reduction():
    """1/R = 1/R1 + 1/R2 (Johnson 1985, section 4.2): two equal convex cylinders give
    R1/2, a flat (R2 = inf) R1, a concave body (R2 < 0) 1/(1/R1 - 1/|R2|); and it is
    the formula effective_radii checks and applies, bit for bit (one home)."""
    from linecontact.raceway import effective_radius

    assert effective_radius(5e-3, 5e-3) == 2.5e-3
    assert effective_radius(5e-3, np.inf) == 5e-3
    assert effective_radius(5e-3, -30e-3) == pytest.approx(6e-3, rel=1e-15)
    R1, Ri, Ro = np.array([5e-3, 4e-3]), np.array([20e-3, 16e-3]), np.array([30e-3, 24e-3])
    r_in, r_out = effective_radii(R1, Ri, Ro)
    assert np.array_equal(r_in, effective_radius(R1, Ri))
    assert np.array_equal(r_out, effective_radius(R1, -Ro))
    assert np.isnan(effective_radius(5e-3, np.nan))      # a row without raceways
