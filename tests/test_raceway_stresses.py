"""The stresses of a roller between raceways have one home (linecontact.stresses.raceways).

Facts checked:
- each contact's maxima are those of a contact of its own: the plane-strain strip of
  its effective radius at the roller load under a law, the slices' roller_stresses
  where solved by slices (the same call, so equal to the last bit);
- the roller's maximum of each measure is the larger contact's, that contact named;
- the case check is each contact's case_check, the worse the larger ratio, and the
  case depth that carries the roller the larger of the two minima;
- linecontact.bearing's most loaded roller's stresses are this rule's on its own
  solve of that roller (equal to the last bit: the same call).
"""
from __future__ import annotations

from linecontact.bearing import RadialRollerBearing
from linecontact.raceway import Raceways, roller_between_raceways
from linecontact.stresses import (HardnessProfile, MEASURES, case_check,
                                  line_contact_stresses, raceway_stresses,
                                  roller_stresses)

R1, L, E = 5.5e-3, 11e-3, 115.38e9
RACES = Raceways(29.5e-3, 40.5e-3)
HARD = HardnessProfile(700.0, 0.5e-3, 350.0)


def test_a_laws_contacts_are_strips_of_their_effective_radii_and_the_worse_is_named():
    sol = roller_between_raceways(R1, L, E, RACES, force=3e3)
    both = raceway_stresses(sol, L, E)
    for side in ("inner", "outer"):
        strip = line_contact_stresses(3e3, getattr(sol, f"radius_{side}"), L, E)
        for m in MEASURES:
            assert both[side].worst[m]["value"] == strip.worst[m]["value"]
    for m in MEASURES:
        side = max(("inner", "outer"), key=lambda k: both[k].worst[m]["value"])
        assert both.worst[m]["contact"] == side
        assert both.worst[m]["value"] == both[side].worst[m]["value"]
        assert both.worst[m]["depth"] == both[side].worst[m]["z"]
    # the inner contact has the smaller effective radius: the higher stresses
    assert all(both.worst[m]["contact"] == "inner" for m in MEASURES)


def test_the_case_check_is_each_contacts_and_the_depth_carries_both():
    sol = roller_between_raceways(R1, L, E, RACES, force=3e3, profile="iso16281")
    both = raceway_stresses(sol, L, E, friction=0.1)
    assert both["inner"].worst == roller_stresses(sol.inner, 0.1, 0.3).worst
    case = both.case_check(HARD)
    ratios = {k: case_check(both[k], HARD).max_ratio for k in ("inner", "outer")}
    assert case.worse == max(ratios, key=ratios.get)
    assert {k: c.max_ratio for k, c in case.checks.items()} == ratios
    need = [case_check(both[k], HARD).min_case_depth for k in ("inner", "outer")]
    assert case.min_case_depth == max(need)


def test_the_bearings_most_loaded_roller_takes_the_same_rule():
    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="iso16281")
    s = b.solve(10e3)
    again = raceway_stresses(s.roller, b.length, b.estar, b.profile)
    for m in MEASURES:
        assert s.stress[m] == again.worst[m]
    assert s.roller_stresses.case_check(HARD).checks["inner"].max_ratio == \
        again.case_check(HARD).checks["inner"].max_ratio
