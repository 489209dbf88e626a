"""Modified rating life (linecontact.bearing.ratings): ISO 281:2007's a_ISO for roller bearings, the
reliability factor a1, L_nm = a1 a_ISO L10 and ISO 16281's L_nmr, each against its
published form evaluated by hand."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.bearing import RadialRollerBearing, basic_rating_life
from linecontact.errors import OutOfRangeError
from linecontact.bearing.ratings import (
    A_ISO_CAP, RELIABILITY_FACTORS, fatigue_load_limit, life_modification_factor,
    modified_rating_life, modified_reference_rating_life, reference_equivalent_load,
    reliability_factor)


def test_a_iso_by_hand():
    """kappa = 1.5 (branch 1 <= kappa <= 4), e_C C_u / P = 0.5 * 8/10 = 0.4:
    1.2348 / 1.5^0.071739 = 1.2348 / 1.029514 = 1.199401; 1.5859 - 1.199401 = 0.386499;
    0.4^0.4 = 0.693145; bracket = 1 - 0.386499 * 0.693145 = 0.732099;
    a_ISO = 0.1 * 0.732099^-9.185 = 1.7535."""
    hand = 0.1 * (1 - (1.5859 - 1.2348 / 1.5 ** 0.071739) * 0.4 ** 0.4) ** -9.185
    assert hand == pytest.approx(1.7535, rel=1e-4)
    assert life_modification_factor(1.5, 0.5, 8e3, 10e3) == pytest.approx(hand, rel=1e-12)


@pytest.mark.parametrize("kappa, c2, c3", [(0.2, 1.3993, 0.054381),
                                           (0.7, 1.2348, 0.19087),
                                           (3.0, 1.2348, 0.071739)])
def test_a_iso_each_branch_is_the_published_one(kappa, c2, c3):
    x = 0.3
    hand = 0.1 * (1 - (1.5859 - c2 / kappa ** c3) * x ** 0.4) ** -9.185
    assert life_modification_factor(kappa, 1.0, 3e3, 10e3) == pytest.approx(hand,
                                                                             rel=1e-12)


def test_a_iso_branches_meet():
    """The published constants make a_ISO continuous in kappa: at kappa = 1 exactly (the
    same c2), at kappa = 0.4 to the constants' five digits (1.3993/0.4^0.054381 =
    1.470749 vs 1.2348/0.4^0.19087 = 1.470700)."""
    for k, rel in ((1.0, 1e-12), (0.4, 2e-4)):
        below = life_modification_factor(k * (1 - 1e-13), 0.5, 8e3, 10e3)
        at = life_modification_factor(k, 0.5, 8e3, 10e3)
        assert at == pytest.approx(below, rel=rel)


def test_a_iso_is_capped_at_50():
    """Published cap: where the bracket reaches zero (clean, lightly loaded) and above."""
    # bracket = 1 - (1.5859 - 1.2348/2^0.071739) x^0.4 <= 0 for x >= about 25
    assert life_modification_factor(2.0, 1.0, 30e3, 1e3) == A_ISO_CAP
    a = life_modification_factor(2.0, 1.0, np.array([1e3, 5e3, 1e4, 3e4]), 10e3)
    assert np.all(a <= A_ISO_CAP) and a[-1] == A_ISO_CAP
    assert np.all(np.diff(a) >= 0)           # a lower load ratio never raises life


def test_a_iso_kappa_range_as_published():
    """Below 0.1 refused (not defined); above 4 the value at 4 (documented)."""
    with pytest.raises(OutOfRangeError, match="kappa"):
        life_modification_factor(0.09, 0.5, 8e3, 10e3)
    assert life_modification_factor(9.0, 0.5, 8e3, 10e3) == \
        life_modification_factor(4.0, 0.5, 8e3, 10e3)
    with pytest.raises(OutOfRangeError, match="contamination"):
        life_modification_factor(1.0, 1.5, 8e3, 10e3)


def test_a_iso_at_kappa_0_1_is_about_0_1():
    """At kappa = 0.1, 1.5859 - 1.3993/0.1^0.054381 = -0.0001: a_ISO = 0.1 whatever the
    cleanliness (the published curves' common origin), to 1e-3."""
    for x in (0.01, 0.5, 2.0):
        assert life_modification_factor(0.1, 1.0, x * 1e4, 1e4) == pytest.approx(
            0.1, rel=1e-3)


def test_reliability_factor_reproduces_the_iso_table():
    """a1 = 0.95 (ln(1/R)/ln(1/0.9))^(2/3) + 0.05 rounds to every entry of ISO 281's
    table at the entry's printed digits."""
    for percent, a1 in RELIABILITY_FACTORS.items():
        digits = len(repr(a1).split(".")[1])
        assert round(float(reliability_factor(percent / 100)), digits) == a1, percent
    with pytest.raises(OutOfRangeError):
        reliability_factor(0.85)
    with pytest.raises(OutOfRangeError):
        reliability_factor(0.9999)


def test_modified_life_is_a1_a_iso_l10_with_a_iso_capped():
    """L_nm = a1 a_ISO L10 with the cap: a clean, light case gives 50, not more."""
    L10 = basic_rating_life(65e3, 10e3)                  # (6.5)^(10/3) = 512.5
    a = life_modification_factor(2.0, 1.0, 30e3, 1e3)    # capped: 50
    a1 = reliability_factor(0.99)
    assert a == 50.0
    assert modified_rating_life(L10, a, a1) == pytest.approx(a1 * 50.0 * L10, rel=1e-15)
    assert modified_rating_life(L10, 1.7535, 1.0) == pytest.approx(898.7, rel=1e-3)
    with pytest.raises(OutOfRangeError, match="life_modification"):
        modified_rating_life(L10, 51.0)


def test_fatigue_load_limit_simplified_by_hand():
    """C_u = C0/8.2 up to d_m = 100 mm, times (100/d_m)^0.3 above."""
    assert fatigue_load_limit(82e3, 70e-3) == pytest.approx(10e3, rel=1e-12)
    assert fatigue_load_limit(82e3, 0.1) == pytest.approx(10e3, rel=1e-12)
    assert fatigue_load_limit(820e3, 0.4) == pytest.approx(100e3 * 0.25 ** 0.3,
                                                            rel=1e-12)


def test_reference_load_inverts_the_life_law():
    """(C_r / P_ref)^(10/3) = L10r."""
    P = reference_equivalent_load(65e3, 777.0)
    assert (65e3 / P) ** (10 / 3) == pytest.approx(777.0, rel=1e-12)


def test_modified_reference_life_of_a_computed_load_distribution():
    """L_nmr = a1 a_ISO(kappa, e_C C_u / P_ref) L10r on the lamina loads of a solved
    bearing; P_ref gives L10r back through ISO 281's law."""
    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, clearance=10e-6)
    s = b.solve(10e3)
    r = modified_reference_rating_life(b.rating, 70e-3, 11e-3, s.slice_loads_inner,
                                       s.slice_loads_outer, 1.5, 0.5, 8e3,
                                       reliability=0.95)
    assert r.basic == pytest.approx(s.life_iso16281, rel=1e-12)
    assert (b.rating / r.reference_load) ** (10 / 3) == pytest.approx(r.basic, rel=1e-12)
    assert r.life_modification == life_modification_factor(1.5, 0.5, 8e3,
                                                            r.reference_load)
    assert r.reliability_factor == reliability_factor(0.95)
    assert r.life == pytest.approx(r.reliability_factor * r.life_modification * r.basic,
                                   rel=1e-15)


def test_unloaded_bearing_has_infinite_reference_life():
    q = np.zeros((14, 5))
    r = modified_reference_rating_life(65e3, 70e-3, 11e-3, q, q, 1.0, 0.5, 8e3)
    assert math.isinf(r.basic) and math.isinf(r.life) and r.life_modification == 50.0


def test_worked_example_of_the_docs_is_what_the_library_gives():
    """docs/bearing_life.md's worked example: its code blocks run, and the numbers its
    comments and hand checks quote are the library's (to their printed digits)."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parents[1] / "docs" / "bearing_life.md").read_text()
    ns = {}
    exec("\n".join(re.findall(r"```python\n(.*?)```", text, re.S)), ns)
    s, s2, r = ns["s"], ns["s2"], ns["r"]
    quoted = {"L10": (s.life_iso281, 386.71), "C0": (s.static_rating, 62823.2),
              "s0": (s.static_safety, 6.282), "Cu": (s.fatigue_load_limit, 7661.4),
              "kappa": (s.kappa, 1.4906), "a_iso": (s.life_modification, 1.6480),
              "a1": (s.reliability_factor, 0.2483), "Lnm": (s.life_modified, 158.3),
              "s0p": (s.pressure_safety, 5.909), "L10r": (s.life_iso16281, 648.9),
              "Pref": (s.reference_load, 8561.7),
              "a_ref": (s.life_modification_reference, 2.0380),
              "Lnmr": (s.life_modified_reference, 328.4),
              "u": (s.entrainment_speed, 2.6810),
              "h": (s.film_minimum_inner[0, 0] * 1e6, 0.1760),
              "h_out": (s.film_minimum_outer[0, 0] * 1e6, 0.2020),
              "hc": (s.film_central_inner[0, 0] * 1e6, 0.1869),
              "lambda": (s.film_ratio_inner[0], 0.976),
              "lambda_out": (s.film_ratio_outer[0], 1.120),
              "Fa": (s.flange_forces[0], 336.93),
              "couple": (s.flange_couple[0], 1.9247),
              "p_flange": (s.flange_pressure_inner[0] / 1e6, 642.7),
              "op": (s2.clearance * 1e6, 14.651),
              "Q fitted": (s2.max_roller_load, 3272.9),
              "L10r fitted": (s2.life_iso16281, 947.4),
              "spectrum": (r.life["iso281"], 192.50),
              "spectrum modified": (r.life["modified"], 38.57),
              "hours": (r.hours["iso281"], 2376.6)}
    for name, (value, doc) in quoted.items():
        digits = len(repr(doc).split(".")[1])
        assert round(float(value), digits) == doc, (name, value, doc)
