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
    of the ISO 281 rating, tilts 0-3 mrad, friction 0-0.4; the most loaded roller's
    load is F_r/(Z J_r(0.5)) (Stribeck, zero clearance) and a ring's the radial load;
    the same seed draws the same cases."""
    tasks = ps.population_tasks(20, 32)
    assert repr(tasks) == repr(ps.population_tasks(20, 32))
    assert all(t["seed"] == 33 for t in ps.population_tasks(2, 33))
    # the friction reaches the high-friction class (above 0.2) of the stress table
    assert ps.MAX_FRICTION == 0.4 and max(t["friction"] for t in tasks) > 0.3
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


def test_the_shipped_population_check_is_consistent():
    """tables/population_check.csv (python -m tools.build_tables population): its flag
    columns are the stated functions of its value columns (holds = diff <= stated where
    an error is stated), and its header's result line counts them."""
    t = read_table("population_check")
    c = t.columns
    n = n_stated = n_hold = 0
    for k in OUTPUTS:
        d, s, h = c[f"diff_{k}"], c[f"stated_{k}"], c[f"holds_{k}"]
        out, st = h > -2, h >= 0
        n += int(out.sum())
        n_stated += int(st.sum())
        n_hold += int((h == 1).sum())
        np.testing.assert_array_equal(h[st], (d[st] <= s[st]).astype(float), err_msg=k)
        assert np.all(d[out] >= 0), k
    assert t.meta["result"].startswith(f"{n_stated} of {n} outputs"), t.meta["result"]
    assert f"{n_hold} of those" in t.meta["result"]


def test_the_shipped_population_check_meets_issue_32():
    """Issue 32's criterion: at least 95 % of the outputs get a stated error and every
    stated error bounds its difference to the 3D BEM (the table's two populations,
    seeds 32 and 33, each alone too: the second is no sample of the first)."""
    c = read_table("population_check").columns
    for seed in (32, 33):
        rows = c["seed"] == seed
        h = np.concatenate([c[f"holds_{k}"][rows] for k in OUTPUTS])
        h = h[h > -2]
        assert (h >= 0).mean() >= 0.95 and np.all(h[h >= 0] == 1), seed
    h = np.concatenate([c[f"holds_{k}"] for k in OUTPUTS])
    h = h[h > -2]
    assert (h >= 0).mean() >= 0.95 and np.all(h[h >= 0] == 1)


def test_the_population_shares_do_not_regress():
    """The shares measured when the table was built (header line ``result``: outputs
    with a stated error, and of those the share that holds) are the floor: a change of
    the runtime, its notes or the accuracy tables that loses stated errors or states
    smaller ones than the differences shows here (the stated errors re-read now, the
    differences the shipped table's)."""
    import re
    t = read_table("population_check")
    c = t.columns
    m = re.match(r"(\d+) of (\d+) outputs .*?; (\d+) of those", t.meta["result"])
    stated0, n0, hold0 = (int(v) for v in m.groups())
    tasks = ps.table_population(c)
    n = n_stated = n_hold = 0
    for i, task in enumerate(tasks):
        rt = ps.runtime_outputs(task)
        for k in OUTPUTS:
            if c[f"holds_{k}"][i] == -2:
                continue
            n += 1
            s = rt[f"stated_{k}"]
            if np.isfinite(s):
                n_stated += 1
                n_hold += bool(c[f"diff_{k}"][i] <= s)
    assert n == n0
    assert n_stated >= stated0 and n_hold >= hold0, (n_stated, n_hold, stated0, hold0)


@pytest.mark.parametrize("family", ps.FAMILIES)
def test_one_drawn_case_per_family_still_holds(family):
    """A small subset of the population rerun (the fastest shipped case of each family,
    BEM included): its outputs are stated and their differences to the BEM stay within
    the stated errors with today's code. The full population: pytest -m slow
    (test_the_population_check_holds_when_rerun)."""
    c = read_table("population_check").columns
    tasks = ps.table_population(c)
    # the fastest case of the family whose every stated output held when shipped
    rows = [i for i, t in enumerate(tasks) if t["family"] == family
            and all(c[f"holds_{k}"][i] != 0 for k in OUTPUTS)]
    i = min(rows, key=lambda j: c["seconds"][j])
    r, rt = ps.run_case(tasks[i]), ps.runtime_outputs(tasks[i])
    for k in OUTPUTS:
        d, s = r[f"diff_{k}"], rt[f"stated_{k}"]
        if np.isfinite(d) and c[f"holds_{k}"][i] >= 0:
            assert np.isfinite(s) and d <= s, (family, k, d, s)


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
