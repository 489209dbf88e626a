"""The cheaper regrid, construction and post-processing of the coupled-slice roller
(linecontact.roller.model, linecontact.profiles.drop_inside / profile_identity) give
the floats of the code they replace: the drop at points inside the roller without
roller_drop's clamp and checks, the fine grid shared by rollers of equal profiles, the
central-difference slope from one evaluation, and the contact's ends and peak read off
the slices as Python floats. Comparisons are exact (==) where only overhead was removed.
"""
import math

import numpy as np
import pytest

from linecontact import profiles as lp
from linecontact.roller import ProfiledRoller
from linecontact.roller import model as rm
from linecontact.roller.solution import contact_extent, peak_pressure

E = 115.385e9
D, L = 10e-3, 14e-3

PROFILES = [
    lp.StraightProfile(L),
    lp.EndReliefProfile(L, corner_radius=1e-3),
    lp.EndReliefProfile(L, relief_length=1e-3, relief_drop=5e-6),
    lp.CircularCrownProfile(L, 0.5, offset=1e-3),
    lp.ISO16281Profile(L, D),
    lp.ISO16281Profile(40e-3, D),            # L > 2.5 D: flat middle
    lp.LundbergProfile(L, E, 4200.0),
    lp.JohnsGoharProfile(L, D / 2, E, 4200.0),
    lp.TabulatedProfile(np.linspace(-L / 2, L / 2, 11), np.linspace(0, 1e-5, 11) ** 2 / 1e-5),
]


def _inside(length):
    # slice centres and the central-difference points, down to 1e-9 L/2 from an end
    x = np.linspace(-length / 2, length / 2, 201)[1:-1]
    return np.concatenate([x, [-length / 2 * (1 - 1e-9), length / 2 * (1 - 1e-9)]])


@pytest.mark.parametrize("prof", PROFILES, ids=lambda p: p.label)
def test_drop_inside_equals_roller_drop(prof):
    """drop_inside (the formula without the clamp and the checks) returns exactly the
    floats of roller_drop at points strictly inside the roller."""
    length = prof.length or L            # a table covers the 14 mm roller
    x = _inside(length)
    got = lp.drop_inside(prof, length)(x)
    assert np.array_equal(got, lp.roller_drop(prof, length, x))


class _Negative(lp.CircularCrownProfile):
    def _drop(self, x):
        return -super()._drop(x)


def test_drop_inside_checks_a_user_profile():
    """A profile class that is not one of linecontact.profiles' own (here a subclass
    whose drop is negative) goes through roller_drop's checks: refused by name."""
    f = lp.drop_inside(_Negative(L, 0.5), L)
    with pytest.raises(lp.OutOfRangeError, match="profile drop"):
        f(np.array([-1e-3, 2e-3]))


def test_profile_identity():
    """Equal parameters give equal keys, a parameter changed in place a new key, a
    table or a user's class none (their drop is not named by hashable parameters)."""
    a, b = lp.ISO16281Profile(L, D), lp.ISO16281Profile(L, D)
    assert lp.profile_identity(a) == lp.profile_identity(b)
    assert lp.profile_identity(a) != lp.profile_identity(lp.LundbergProfile(L, E, 1e3))
    b.diameter = 2 * D
    assert lp.profile_identity(a) != lp.profile_identity(b)
    assert lp.profile_identity(PROFILES[-1]) is None
    assert lp.profile_identity(_Negative(L, 0.5)) is None


def test_fine_grid_is_shared_and_read_only():
    """Rollers of equal profiles share the 16 n + 1 point grid and its drop, equal to a
    fresh evaluation, read-only; a profile changed in place is evaluated anew."""
    p1, p2 = lp.ISO16281Profile(L, D), lp.ISO16281Profile(L, D)
    r1, r2 = ProfiledRoller(D / 2, L, E, p1), ProfiledRoller(D / 2, L, E, p2)
    assert r1._fP is r2._fP and r1._fx is r2._fx
    assert not r1._fP.flags.writeable and not r1._fx.flags.writeable
    fx = np.linspace(-L / 2, L / 2, 16 * r1.n_slices + 1)
    assert np.array_equal(r1._fx, fx)
    assert np.array_equal(r1._fP, lp.roller_drop(p1, L, fx, ends_may_be_inf=True))
    p2.diameter = 12e-3
    r3 = ProfiledRoller(D / 2, L, E, p2)
    assert r3._fP is not r1._fP
    assert np.array_equal(r3._fP, lp.roller_drop(p2, L, fx, ends_may_be_inf=True))
    # the first-contact depth per tilt is shared with the grid: equal to a fresh one's
    d0 = r1.first_contact_depth(1e-3)
    assert r2._d0_shared[1e-3] == d0 == r2._first_contact(1e-3)
    # a table has no identity: its own grid each time, the same floats
    t = PROFILES[-1]
    r4, r5 = ProfiledRoller(D / 2, L, E, t), ProfiledRoller(D / 2, L, E, t)
    assert r4._fP is not r5._fP and np.array_equal(r4._fP, r5._fP)


@pytest.mark.parametrize("prof", [PROFILES[1], PROFILES[2], PROFILES[-1]],
                         ids=lambda p: p.label)
def test_drop_slope_equals_the_reference(prof):
    """_drop_slope for a profile without a closed-form slope (an end relief, a table;
    one evaluation into one buffer) gives exactly the drop and the central difference
    (P(x + h) - P(x - h))/(x_+ - x_-), h = 1e-7 L, both points kept 1e-9 L/2 inside the
    roller, of the code it replaced."""
    r = ProfiledRoller(D / 2, L, E, prof)
    x = _inside(L)[::7]
    h, lo, hi = 1e-7 * L, -L / 2 * (1 - 1e-9), L / 2 * (1 - 1e-9)
    xp, xm = np.minimum(x + h, hi), np.maximum(x - h, lo)
    n = len(x)
    P = lp.roller_drop(prof, L, np.concatenate((x, xp, xm)))
    got_P, got_s = r._drop_slope(x)
    assert np.array_equal(got_P, P[:n])
    assert np.array_equal(got_s, (P[n:2 * n] - P[2 * n:]) / (xp - xm))


def test_contact_extent_exact_roots():
    """The contact's ends where q falls linearly (the line through the last two loaded
    slices) or as a parabola (through the last three) are its exact roots."""
    x = np.linspace(-1.0, 1.0, 11)
    w = np.full(11, 0.2)
    q = np.where(np.abs(x) < 0.65, 0.7 - np.abs(x), 0.0)     # roots at +-0.7
    start, stop, lo_edge, hi_edge = contact_extent(x, q, w, 2.4)
    assert (start, stop) == pytest.approx((-0.7, 0.7), rel=1e-14)
    assert not lo_edge and not hi_edge
    q = np.where(np.abs(x) < 0.65, 0.49 - x ** 2, 0.0)        # a parabola, same roots
    start, stop, _, _ = contact_extent(x, q, w, 2.4)
    assert (start, stop) == pytest.approx((-0.7, 0.7), rel=1e-14)
    assert isinstance(start, float) and isinstance(stop, float)


def test_peak_pressure_exact_for_hertz():
    """The parabola through p^2 at the three slices around the largest is exact for a
    Hertz (semi-elliptical) pressure on unevenly spaced slices."""
    x = np.array([-0.9, -0.5, -0.2, 0.15, 0.4, 0.8])
    p0, x0, a = 2.0, 0.05, 1.0
    p = p0 * np.sqrt(1 - ((x - x0) / a) ** 2)
    pm, xm = peak_pressure(x, p)
    assert pm == pytest.approx(p0, rel=1e-14) and xm == pytest.approx(x0, rel=1e-13)
    assert math.isfinite(pm)


SMOOTH = [p for p in PROFILES if type(p) in (lp.StraightProfile, lp.CircularCrownProfile,
                                              lp.ISO16281Profile, lp.LundbergProfile,
                                              lp.JohnsGoharProfile)]


@pytest.mark.parametrize("prof", SMOOTH, ids=lambda p: p.label)
def test_closed_form_slope(prof):
    """drop_slope_inside: the drop exactly drop_inside's floats, and dP/dx equal to a
    fourth-order central difference (step 1e-4 L: truncation ~1e-16 L^4 P^(5), rounding
    ~1e-12 P/h) to 1e-8 of the largest slope; the closed form is exact, the difference
    the check. The end relief and tables have none (their kinks and knots)."""
    length = prof.length
    x = _inside(length)[:-2]
    x = x[np.abs(x) < length / 2 * 0.98]
    P, S = lp.drop_slope_inside(prof)(x)
    assert np.array_equal(P, lp.drop_inside(prof, length)(x))
    h = 1e-4 * length
    f = lp.drop_inside(prof, length)
    ref = (8 * (f(x + h) - f(x - h)) - (f(x + 2 * h) - f(x - 2 * h))) / (12 * h)
    scale = max(np.max(np.abs(ref)), 1e-30)
    if type(prof) is lp.ISO16281Profile and prof.long:
        # the kink of the second derivative where the flat middle ends: away from it
        edge = (length - 2.5 * prof.diameter) / 2
        keep = np.abs(np.abs(x) - edge) > 3 * h
        S, ref = S[keep], ref[keep]
    assert np.max(np.abs(S - ref)) <= 1e-8 * scale
    assert lp.drop_slope_inside(PROFILES[1]) is None       # end relief: differences
    assert lp.drop_slope_inside(PROFILES[-1]) is None      # table: differences


@pytest.mark.parametrize("value", [0.005, 50, -0.0, 0.0, 1e308, 2.3e-308, -0.05, 0.1,
                                   float("nan"), float("inf"), 5e-320, -5e-320, 2 ** 60,
                                   2 ** 53])
@pytest.mark.parametrize("ends", [(0.0, np.inf, True, True), (-0.1, 0.1, True, True),
                                  (0.0, 0.5, False, False), (10, 4000, False, False),
                                  (0, 2 ** 53 + 1, False, True)])
def test_scalar_check_matches_the_array_path(value, ends):
    """check_interval's fast path for one Python number returns the 0-d float array of
    the general path (the value checked as a 1-element array, then reshaped), and
    refuses exactly what it refuses (NaN, out of range, subnormal; 2^60 below an open
    end of 2^53 + 1, which rounds to 2^53 as a float: refused there, as 2^53 is)."""
    from linecontact.checks import check_interval
    from linecontact.errors import OutOfRangeError
    lo, hi, lo_open, hi_open = ends
    kw = dict(low_open=lo_open, high_open=hi_open)
    try:
        ref = check_interval("v", np.array([float(value)]), lo, hi, **kw)[0]
    except OutOfRangeError:
        with pytest.raises(OutOfRangeError):
            check_interval("v", value, lo, hi, **kw)
        return
    got = check_interval("v", value, lo, hi, **kw)
    assert got.shape == () and got.dtype == np.float64
    assert got.item() == ref and math.copysign(1, got.item()) == math.copysign(1, ref)


def test_solution_built_as_the_constructor_builds_it():
    """RollerSolution._built (the solver's fast path) holds the same attributes, in the
    same order (to_dict and JSON follow it), as the dataclass constructor given the
    same fields; a missing or unknown field is refused."""
    from linecontact.roller.solution import RollerSolution
    s = ProfiledRoller(D / 2, L, E, lp.ISO16281Profile(L, D)).at_force(4200.0, tilt=2e-3)
    kw = dict(reversed(list(vars(s).items())))           # another order of the names
    ref = RollerSolution(**kw)
    got = RollerSolution._built(**kw)
    assert type(got) is RollerSolution
    assert list(vars(got)) == list(vars(ref)) == list(vars(s))
    assert all(vars(got)[k] is vars(ref)[k] for k in vars(ref))
    assert list(got.to_dict()) == list(ref.to_dict())
    kw.pop("notes")
    with pytest.raises(TypeError):
        RollerSolution._built(**kw)
    with pytest.raises(TypeError):
        RollerSolution._built(**kw, notes=(), extra=1)


def test_a_profile_changed_in_place_leaves_the_shared_caches_alone():
    """A roller's _end_root points are cached per grid shared by the rollers of equal
    profiles (_fine_grid). A roller whose profile object is changed in place after
    construction evaluates the changed drop there: that must not reach the cache of
    the profile's former parameters, so that a new roller of a profile equal to the
    original solves exactly as with caches of its own (here the drop the changed
    Lundberg profile, 20 kN design force instead of 4.2 kN, wrote there moved another
    roller's slice loads by 60 % of the largest)."""
    case = dict(force=9000.0, tilt=2e-3)          # the contact reaches the end zone
    rm._FINE.clear()
    ref = ProfiledRoller(D / 2, L, E, lp.LundbergProfile(L, E, 4200.0)).at_force(**case)
    rm._FINE.clear()
    p = lp.LundbergProfile(L, E, 4200.0)
    changed = ProfiledRoller(D / 2, L, E, p)
    p.design_force = 20000.0                      # changed in place after construction
    changed.at_force(**case)
    fresh = ProfiledRoller(D / 2, L, E, lp.LundbergProfile(L, E, 4200.0))
    assert fresh._end_cache is changed._end_cache     # the grid is shared
    got = fresh.at_force(**case)
    assert got.depth == ref.depth and np.array_equal(got.q, ref.q)


class _UserCrown(lp.CircularCrownProfile):
    """A user's profile class (not one of linecontact.profiles' own: checked drop)."""


@pytest.mark.parametrize("prof", [_UserCrown(L, 0.5), PROFILES[1], PROFILES[-1]],
                         ids=["user class", "end relief", "table"])
def test_roller_pickles_with_any_profile(prof):
    """A roller is pickled to the workers of a process pool or Dask: with a user's
    profile class too (the drop it evaluates inside the roller, drop_inside's checked
    roller_drop, must pickle), answering as the original."""
    import pickle
    r = ProfiledRoller(D / 2, L, E, prof)
    got = pickle.loads(pickle.dumps(r)).at_force(2000.0, tilt=1e-3)
    want = r.at_force(2000.0, tilt=1e-3)
    assert got.depth == want.depth and np.array_equal(got.q, want.q)
