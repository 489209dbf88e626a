"""The population check (tools/studies/population_study.py, tables/population_check.csv):
the rollers users bring -- cylindrical roller bearings, needles, cam-follower rings at
2-50 % of their ISO 281 ratings -- get a stated error on their outputs, and each stated
error bounds the output's difference to the 3D BEM (its own grid error included)."""
import math

import numpy as np
import pytest

import tools.studies.population_study as ps
from linecontact.bearing import dynamic_load_rating, load_zone_integral
from linecontact.tables import read_table

OUTPUTS = ps.ROLLER_OUTPUTS + ps.STRESS_OUTPUTS


def test_the_drawn_population_is_the_one_described():
    """The draw is what the module docstring says, family by family: the roller's own
    L/D (cylindrical 0.8-1.5, needles 3-10, cam-follower rings 0.5-0.8), loads 2-50 %
    of the ISO 281 rating, tilts 0-3 mrad, friction 0-0.2; the most loaded roller's
    load is F_r/(Z J_r(0.5)) (Stribeck, zero clearance) and a ring's the radial load;
    the same seed draws the same cases."""
    tasks = ps.population_tasks(20, 32)
    assert repr(tasks) == repr(ps.population_tasks(20, 32))
    span = {"cylindrical": (0.8, 1.5), "needle": (3.0, 10.0), "cam-follower": (0.5, 0.8)}
    for t in tasks:
        lo, hi = span[t["family"]]
        assert lo <= t["length"] / t["roller_diameter"] <= hi, t["key"]
        assert 0.02 <= t["load_fraction"] <= 0.5
        assert 0 <= t["tilt"] <= ps.MAX_TILT and 0 <= t["friction"] <= ps.MAX_FRICTION
        if t["family"] == "cam-follower":
            # a ring on a flat track: the contact's radius is the ring's
            assert t["radius"] == pytest.approx(t["roller_diameter"] / 2, rel=1e-15)
            assert t["force"] == pytest.approx(t["load_fraction"] * t["rating"],
                                               rel=1e-12)
        else:
            assert t["radius"] < t["roller_diameter"] / 2   # inner raceway: smaller
    # one cylindrical bearing by hand: ISO 281's C_r and Stribeck's roller load
    rng = np.random.default_rng(0)
    b = ps._draw_bearing(rng, "cylindrical")
    assert b["rating"] == dynamic_load_rating(b["rollers"], b["pitch_diameter"],
                                              b["roller_diameter"], b["length"])
    assert ps.roller_load(b, 0.1) == pytest.approx(
        0.1 * b["rating"] / (b["rollers"] * load_zone_integral(0.5)), rel=1e-15)
    assert b["rollers"] == int(math.pi * b["pitch_diameter"] / (1.25 * b["roller_diameter"]))


def test_the_shipped_population_check_meets_issue_32():
    """tables/population_check.csv (python -m tools.build_tables population): at least
    95 % of the outputs (deflection, moment, peak pressure where the runtime states
    one, Tresca, von Mises, orthogonal shear) get a stated error, and every stated error
    bounds |runtime - BEM| + |BEM grid change|; its flag columns are the stated
    functions of its value columns."""
    t = read_table("population_check")
    c = t.columns
    n = n_stated = 0
    for k in OUTPUTS:
        d, s, h = c[f"diff_{k}"], c[f"stated_{k}"], c[f"holds_{k}"]
        out, st = h > -2, h >= 0
        n += int(out.sum())
        n_stated += int(st.sum())
        np.testing.assert_array_equal(h[st], (d[st] <= s[st]).astype(float), err_msg=k)
        assert np.all(d[out] >= 0), k
        assert np.all(h[st] == 1), (k, np.flatnonzero(st & (h == 0)))
    assert n_stated >= 0.95 * n, (n_stated, n)
    assert f"{n_stated} of {n} outputs" in t.meta["result"]


@pytest.mark.parametrize("family", ps.FAMILIES)
def test_one_drawn_case_per_family_still_holds(family):
    """A small subset of the population rerun (the fastest shipped case of each family,
    BEM included): its outputs are stated and their differences to the BEM stay within
    the stated errors with today's code. The full population: pytest -m slow
    (test_the_population_check_holds_when_rerun)."""
    c = read_table("population_check").columns
    tasks = ps.population_tasks(_per_family(c), 32)
    rows = [i for i, t in enumerate(tasks) if t["family"] == family]
    i = min(rows, key=lambda j: c["seconds"][j])
    r, rt = ps.run_case(tasks[i]), ps.runtime_outputs(tasks[i])
    for k in OUTPUTS:
        d, s = r[f"diff_{k}"], rt[f"stated_{k}"]
        if np.isfinite(d) and c[f"holds_{k}"][i] >= 0:
            assert np.isfinite(s) and d <= s, (family, k, d, s)


def _per_family(c):
    return int(c["family"].size // len(ps.FAMILIES))


def test_the_stated_errors_of_today_still_bound_the_shipped_differences():
    """The stated errors re-read from the runtime and the shipped accuracy tables as
    they are now (runtime_outputs: no BEM; the differences are the shipped table's):
    a change of the tables or of the coverage notes that drops a stated error, or
    states one too small, shows here. At least 95 % stated, every one holds."""
    c = read_table("population_check").columns
    tasks = ps.population_tasks(_per_family(c), 32)
    n = n_stated = 0
    for i, t in enumerate(tasks):
        rt = ps.runtime_outputs(t)
        for k in OUTPUTS:
            if c[f"holds_{k}"][i] == -2:
                continue
            n += 1
            s = rt[f"stated_{k}"]
            if np.isfinite(s):
                n_stated += 1
                assert c[f"diff_{k}"][i] <= s, (t["key"], k, c[f"diff_{k}"][i], s)
    assert n_stated >= 0.95 * n, (n_stated, n)


@pytest.mark.slow
def test_the_population_check_holds_when_rerun(tmp_path):
    """The whole population rerun (about 10-20 min on the shared machine, one worker)
    reproduces the shipped table's verdicts."""
    from tools.build_tables import main as build_tables
    assert build_tables(["population", "--workers", "1", "--no-progress",
                         "--out", str(tmp_path)]) == 0
    new = read_table("population_check", directory=tmp_path).columns
    old = read_table("population_check").columns
    for k in OUTPUTS:
        np.testing.assert_array_equal(new[f"holds_{k}"], old[f"holds_{k}"], err_msg=k)
