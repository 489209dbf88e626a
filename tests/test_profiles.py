"""Roller profiles (linecontact.profiles): the formulas' defining properties, the user
table and the command-line parser, and the refusal of bad input.

Each test states the fact it checks and why its tolerance.
"""
import math

import numpy as np
import pytest

from linecontact.errors import OutOfRangeError
from linecontact.profiles import (JOHNS_GOHAR_C, CircularCrownProfile, EndReliefProfile,
                                  ISO16281Profile, JohnsGoharProfile, LundbergProfile,
                                  StraightProfile, TabulatedProfile, parse_angle,
                                  parse_profile)

L, R, E = 10e-3, 5e-3, 115.385e9
X = np.linspace(-L / 2 * 0.999, L / 2 * 0.999, 401)


def _builtins():
    return [StraightProfile(L), EndReliefProfile(L, corner_radius=2e-3),
            EndReliefProfile(L, relief_length=1e-3, relief_angle=1e-3),
            CircularCrownProfile(L, 0.2), ISO16281Profile(L, 2 * R),
            ISO16281Profile(40e-3, 2 * R), LundbergProfile(L, E, 2e3),
            JohnsGoharProfile(L, R, E, 2e3)]


@pytest.mark.parametrize("prof", _builtins(), ids=lambda p: p.label)
def test_builtin_profiles_are_symmetric_nonnegative_and_zero_at_the_centre(prof):
    """Every built-in profile is a drop: P >= 0, P(0) = 0, P(-x) = P(x) (to rounding:
    the formulas are even in x), and it does not decrease from the centre outwards."""
    x = np.linspace(-prof.length / 2 * 0.999, prof.length / 2 * 0.999, 401)
    P = prof.drop(x)
    assert np.all(P >= 0) and prof.drop(0.0) == 0.0
    np.testing.assert_allclose(P, P[::-1], rtol=1e-12, atol=0)
    half = P[200:]
    assert np.all(np.diff(half) >= 0)


def test_iso16281_branches():
    """ISO 16281: for L <= 2.5 D, P = 0.00035 D ln[1/(1 - (2x/L)^2)]; for L > 2.5 D
    the middle (|x| <= (L - 2.5 D)/2) is flat and the ends carry 0.0005 D ln[1/(1 - t^2)]
    over 1.25 D each; the drop is continuous at the flat's end and infinite at x = L/2.
    Exact formulas: 1e-14."""
    D = 10e-3
    short = ISO16281Profile(20e-3, D)
    x = 7e-3
    assert short.drop(x) == pytest.approx(0.00035 * D * math.log(1 / (1 - (2 * x / 20e-3) ** 2)),
                                          rel=1e-14)
    long = ISO16281Profile(40e-3, D)
    flat = (40e-3 - 2.5 * D) / 2
    assert long.drop(flat) == 0.0 and long.drop(-flat * 0.5) == 0.0
    assert long.drop(flat + 1e-9) < 1e-15        # continuous: ~ 0.0005 D t^2
    t = (2 * 18e-3 - 40e-3 + 2.5 * D) / (2.5 * D)
    assert long.drop(18e-3) == pytest.approx(0.0005 * D * math.log(1 / (1 - t * t)), rel=1e-14)
    assert math.isinf(long.drop(20e-3))


def test_lundberg_and_johns_gohar():
    """Lundberg: P = F0/(pi L E*) ln[1/(1-(2x/L)^2)], infinite at the ends. Johns-Gohar:
    the same factor with (1 - 0.3033 b/a)(x/a)^2, finite at the ends, where it equals
    F0/(pi L E*) ln(a/(0.3033 b)) with b = sqrt(4 R F0/(pi E* L)) (Li & Popov 2017
    Eq. 1); inside, the two differ by less than the Johns-Gohar end correction.
    Exact formulas: 1e-12."""
    F0 = 2e3
    lund = LundbergProfile(L, E, F0)
    jg = JohnsGoharProfile(L, R, E, F0)
    A = F0 / (math.pi * L * E)
    b = math.sqrt(4 * R * F0 / (math.pi * E * L))
    assert lund.drop(3e-3) == pytest.approx(A * math.log(1 / (1 - 0.36)), rel=1e-12)
    assert math.isinf(lund.drop(L / 2))
    assert jg.drop(L / 2) == pytest.approx(A * math.log((L / 2) / (JOHNS_GOHAR_C * b)),
                                           rel=1e-12)
    assert 0 < lund.drop(3e-3) - jg.drop(3e-3) < A * 0.01


def test_end_relief_is_tangent_and_reaches_its_drop():
    """A corner radius r over l starts tangent to the straight part (drop and slope 0
    there, finite-difference slope below 1e-6) and drops r - sqrt(r^2 - l^2) at the end;
    a dub-off given by its end drop reaches exactly that drop, and by its angle the
    slope tan(alpha). Exact formulas: 1e-12."""
    r, lr = 2e-3, 1e-3
    arc = EndReliefProfile(L, corner_radius=r, relief_length=lr)
    x0 = L / 2 - lr
    assert arc.drop(x0) == 0.0
    assert (arc.drop(x0 + 1e-9) - arc.drop(x0)) / 1e-9 < 1e-6
    assert arc.drop(L / 2) == pytest.approx(r - math.sqrt(r * r - lr * lr), rel=1e-12)
    dub = EndReliefProfile(L, relief_length=lr, relief_drop=4e-6)
    assert dub.drop(-L / 2) == pytest.approx(4e-6, rel=1e-12)
    ang = EndReliefProfile(L, relief_length=lr, relief_angle=2e-3)
    assert ang.drop(L / 2) == pytest.approx(lr * math.tan(2e-3), rel=1e-12)


def test_offset_crown_is_asymmetric():
    """An offset crown has its apex (P = 0, the minimum) at x0 and is symmetric about
    x0, not about 0: asymmetric profiles are allowed."""
    p = CircularCrownProfile(L, 0.1, offset=1e-3)
    assert p.drop(1e-3) == 0.0
    assert p.drop(3e-3) == pytest.approx(p.drop(-1e-3), rel=1e-12)
    assert p.drop(3e-3) != pytest.approx(p.drop(-3e-3))


def test_table_profile_reads_csv_and_interpolates(tmp_path):
    """A CSV of (x, drop) with a header and a comment is read; the drop is the linear
    interpolation (exact at the nodes and midway), and x outside the table is refused,
    naming x and the table's range."""
    f = tmp_path / "prof.csv"
    f.write_text("# measured profile\nx,drop\n-0.005,2e-6\n0,0\n0.005,1e-6\n")
    p = TabulatedProfile.from_csv(f)
    assert p.drop(0.0) == 0.0 and p.drop(-0.005) == 2e-6
    assert p.drop(0.0025) == pytest.approx(0.5e-6, rel=1e-12)
    with pytest.raises(OutOfRangeError) as err:
        p.drop(0.006)
    assert err.value.parameter == "x" and "[-0.005, 0.005]" in str(err.value)
    assert parse_profile(f"file:{f}", length=L).label.startswith("table prof.csv")


@pytest.mark.parametrize("text, param, fragment", [
    ("x,drop\n0,0\n0.002,1e-6\n0.001,2e-6\n", "x", "increase strictly"),
    ("x,drop\n0,0\n0.002,1e-6\n0.002,2e-6\n", "x", "increase strictly"),
    ("x,drop\n0,0\n0.001,nan\n0.002,2e-6\n", "profile file", "not a finite number"),
    ("x,drop\n0,0\n0.001,-1e-6\n0.002,2e-6\n", "drop", "[0, inf) m"),
    ("x,drop\n0,0\n", "x", "at least 2"),
    ("x,drop\n0,0\n0.001\n", "profile file", "two numbers"),
])
def test_bad_profile_tables_are_refused(tmp_path, text, param, fragment):
    """A table that is not monotone in x, has NaN, a negative drop, too few rows or a
    malformed row raises OutOfRangeError naming the parameter, the value and the valid
    range (one line), never a silently repaired profile."""
    f = tmp_path / "bad.csv"
    f.write_text(text)
    with pytest.raises(OutOfRangeError) as err:
        TabulatedProfile.from_csv(f)
    assert err.value.parameter == param and fragment in str(err.value)
    assert "\n" not in str(err.value)


def test_parse_profile_names_options_and_units():
    """Every name of the command-line form builds its profile; values take units
    ("500mm", "2kN", "0.1deg") or bare SI numbers; defaults come from the case
    (iso16281's D = 2R, lundberg's F0 = the design force)."""
    assert parse_profile("straight", length=L).drop(1e-3) == 0.0
    c = parse_profile("circular:Rc=500mm", length=L)
    assert c.crown_radius == pytest.approx(0.5)
    assert parse_profile("circular:Rc=0.5,x0=1mm", length=L).offset == pytest.approx(1e-3)
    assert parse_profile("iso16281", length=L, radius=R).diameter == 2 * R
    assert parse_profile("iso16281:D=8mm", length=L).diameter == pytest.approx(8e-3)
    assert parse_profile("lundberg:F0=2kN", length=L, estar=E).design_force == pytest.approx(2e3)
    assert parse_profile("lundberg", length=L, estar=E, design_force=500.0).design_force == 500.0
    jg = parse_profile("johns-gohar:F0=1000", length=L, radius=R, estar=E)
    assert isinstance(jg, JohnsGoharProfile)
    er = parse_profile("end-relief:l=1mm,angle=0.1deg", length=L)
    assert er.slope == pytest.approx(math.tan(math.radians(0.1)))
    assert parse_profile("end-relief:r=2mm", length=L).corner_radius == pytest.approx(2e-3)


def test_parse_profile_refuses_unknown_names_listing_the_valid_ones():
    """An unknown profile or option name is an UnknownNameError (not an
    OutOfRangeError: a name has no range) naming it and listing the valid ones, in one
    line."""
    from linecontact.errors import UnknownNameError

    for spec, param, fragment in (("cone", "profile",
                                   "'straight', 'end-relief', 'circular'"),
                                  ("circular:radius=1", "circular option", "'Rc'")):
        with pytest.raises(UnknownNameError) as err:
            parse_profile(spec, length=L)
        assert err.value.parameter == param and fragment in str(err.value)
        assert "\n" not in str(err.value)


@pytest.mark.parametrize("spec, kw, param, fragment", [
    ("circular:Rc=-0.2", {}, "Rc", "a length > 0"),
    ("circular:Rc=0", {}, "Rc", "a length > 0"),
    ("circular", {}, "crown_radius", "(0, inf) m"),
    ("circular:Rc=5kN", {}, "Rc", "length"),
    ("lundberg", {"estar": E}, "design_force", "(0, inf) N"),
    ("end-relief:l=1mm,drop=-2um", {}, "drop", "a length > 0"),
    ("end-relief:l=1mm,drop=-2e-6", {}, "drop", "a length > 0"),
    ("circular:Rc=1_0", {}, "Rc", "a length > 0"),
    ("circular:Rc=nan", {}, "Rc", "a length > 0"),
    ("end-relief:l=1mm", {}, "relief_angle", "exactly one of"),
    ("file:", {}, "profile", "file:PATH.csv"),
])
def test_parse_profile_refuses_bad_input(spec, kw, param, fragment):
    """Missing or non-positive values (crown radius <= 0,
    negative relief drop), a force where a length belongs: OutOfRangeError naming the
    parameter, the value and the valid range, in one line."""
    with pytest.raises(OutOfRangeError) as err:
        parse_profile(spec, length=L, **kw)
    assert err.value.parameter == param and fragment in str(err.value)
    assert "\n" not in str(err.value)


def test_parse_angle():
    """Angles with units: 1 mrad = 1e-3 rad, 0.05 deg = 0.05 pi/180 rad, a bare number
    is radians (exact conversions); unknown units and |angle| >= 0.1 rad (beyond the
    linearised tilt) are refused, naming the parameter."""
    assert parse_angle("1mrad") == pytest.approx(1e-3, rel=1e-15)
    assert parse_angle("0.05deg") == pytest.approx(0.05 * math.pi / 180, rel=1e-15)
    assert parse_angle("-2e-4") == -2e-4
    for bad in ("1 furlong", "abc", "0.2", "10deg"):
        with pytest.raises(OutOfRangeError) as err:
            parse_angle(bad, parameter="--tilt")
        assert err.value.parameter == "--tilt"


def test_iso16281_default_diameter_is_the_rollers_not_twice_an_effective_radius():
    """ISO 16281's reference profile scales with the roller diameter D. Against a
    raceway the contact's radius is the effective one (R 5 mm on an inner ring of
    20 mm: R_eff = 4 mm), so `diameter` gives D; without it D = 2 radius (a flat)."""
    L = 10e-3
    on_flat = parse_profile("iso16281", length=L, radius=5e-3)
    on_race = parse_profile("iso16281", length=L, radius=4e-3, diameter=10e-3)
    assert on_flat.diameter == on_race.diameter == 10e-3
    assert on_race.drop(4e-3) == ISO16281Profile(L, 10e-3).drop(4e-3)
    assert parse_profile("iso16281:D=8mm", length=L, diameter=10e-3).diameter == 8e-3
