"""One question, the same answer from every door (issue 30, item 3).

Facts checked:
- the same case through ``linecontact calc`` (one case, ``--json``), its CSV batch
  (``--json``), its DataFrame (linecontact.calc.frame) and the library gives the same
  numbers: the three calculator doors are one code path, so equal to the last bit;
  the library's own calls (the same solve) equal them to 1e-12 relative (the JSON
  carries full precision);
- a slice row's stresses are the library's ``roller_stresses`` of that row's solve
  (the worst along the roller, not the mean-line-load strip); a roller between
  raceways gets each contact's ``roller_stresses`` and the case check of the worse;
- ``linecontact bearing`` through the same four doors equals
  ``RadialRollerBearing.solve``, and its case check is that of its most loaded roller
  between the same raceways (``roller_between_raceways`` + ``case_check``);
- for an ISO-profiled roller the bearing's most loaded roller and ``linecontact calc``
  of that roller between the same raceways at its load agree in approach, tilt and
  peak pressure to 1e-6 relative, aligned and misaligned: the bearing solves each
  loaded roller exactly (aligned: its tabulated equilibrium polished with exact
  solves of the rollers), the same solve as calc's.
"""
from __future__ import annotations

import contextlib
import csv
import io
import json

import numpy as np
import pytest

from linecontact.calc.cli import main

pd = pytest.importorskip("pandas")

STEEL = {"radius": "10mm", "length": "20mm", "modulus": "210GPa", "poisson": "0.3",
         "modulus2": "210GPa", "poisson2": "0.3", "load": "1kN", "stresses": "yes"}
RACEWAY = {"radius": "5.5mm", "length": "11mm", "estar": "115.38GPa",
           "inner_raceway": "29.5mm", "outer_raceway": "40.5mm", "profile": "iso16281",
           "load": "3kN", "stresses": "yes", "surface_hardness": "700",
           "case_depth": "0.5mm", "core_hardness": "350"}
BEARING = {"rollers": "14", "pitch_diameter": "70mm", "roller_diameter": "11mm",
           "length": "11mm", "radial_load": "10kN", "profile": "iso16281",
           "surface_hardness": "700", "case_depth": "0.5mm", "core_hardness": "350"}

#: the calc rows' numbers compared between the doors (None where not computed)
CALC_NUMBERS = ("force", "depth", "stiffness", "roller_deflection", "roller_stiffness",
                "depth_inner", "depth_outer", "peak_pressure_inner",
                "peak_pressure_outer", "tresca_max", "tresca_depth", "von_mises_max",
                "von_mises_depth", "orthogonal_shear_max", "orthogonal_shear_depth",
                "case_ratio", "case_ratio_depth", "min_case_depth")


def _run(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    assert status == 0, err.getvalue()
    return json.loads(out.getvalue())


def _options(case):
    return [x for k, v in case.items() for x in ("--" + k.replace("_", "-"), v)]


def _doors(tmp_path, command, case, extra=()):
    """The case's row through the one-case command, the CSV batch and the DataFrame,
    as dicts of SI numbers (the batch's and the frame's columns renamed to the
    one-case names by their unit suffix)."""
    one = _run(command, *_options(case), *extra, "--json")
    path = tmp_path / f"{command}.csv"
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(list(case))
        w.writerow(list(case.values()))
    batch = _run(command, str(path), *extra, "--json")["rows"][0]
    if command == "calc":
        from linecontact.calc.frame import calc_frame
        model = dict(zip(extra[::2], extra[1::2])).get("--model")
        frame = calc_frame(pd.DataFrame({k: [v] for k, v in case.items()}), model=model)
    else:
        from linecontact.calc.frame import command_frame
        frame = command_frame(command, pd.DataFrame({k: [v] for k, v in case.items()}))
    return one, batch, frame.iloc[0].to_dict()


def _si(row, name, units):
    """A batch/frame row's value of field `name` (its column NAME_SIUNIT)."""
    from linecontact.calc.batch import _col_name_of
    from linecontact.calc.feature import Field

    u = units[name]
    col = _col_name_of(name, Field("", u, u, 1.0), True)
    v = row.get(col)
    return None if v is None or v != v else float(v)


def _same(a, b):
    assert (a is None) == (b is None), (a, b)
    if a is not None:
        assert a == b, (a, b)


@pytest.mark.parametrize("profile", ["iso16281", None], ids=["iso16281", "straight"])
def test_a_slice_row_is_the_librarys_solve_from_every_door(tmp_path, profile):
    """A roller under the coupled-slice law of a plain contact (--model
    profiled-roller[:profile=...]): depth, stiffness and the stresses are the
    library's at_force solve and roller_stresses of it, from the command, the batch
    and the DataFrame alike. ISO-profiled: the worst along the roller (above the
    mean-line-load strip, 129 MPa Tresca, that the calculator printed for such a row
    before); straight: edge loaded, where the library withholds the maxima (a
    slice-width number), the row shows none and says why."""
    from linecontact.models import get_model
    from linecontact.stresses import line_contact_stresses, roller_stresses

    model = "profiled-roller" + (f":profile={profile}" if profile else "")
    one, batch, frame = _doors(tmp_path, "calc", STEEL, ("--model", model))
    row = one["models"][0]["rows"][0]
    units = one["units"]
    for name in CALC_NUMBERS:
        if name in row:
            _same(row[name], _si(batch, name, units))
            _same(row[name], _si(frame, name, units))
    E = 1 / (2 * (1 - 0.3 ** 2) / 210e9)
    law = get_model("profiled-roller", 10e-3, 20e-3, E, profile=profile)
    sol = law.at_force(1e3)
    st = roller_stresses(sol, 0.0, 0.3)
    assert row["depth"] == pytest.approx(sol.depth, rel=1e-12)
    assert row["stiffness"] == pytest.approx(sol.stiffness, rel=1e-12)
    if st.withheld:
        assert profile is None and "not reported" in row["flags"]
        assert all(row[f"{m}_max"] is None for m in st.withheld)
        return
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        assert row[f"{m}_max"] == pytest.approx(st.worst[m]["value"], rel=1e-12)
        assert row[f"{m}_depth"] == pytest.approx(st.worst[m]["z"], rel=1e-12)
    strip = line_contact_stresses(1e3, 10e-3, 20e-3, E, 0.0, 0.3)
    assert row["tresca_max"] > 1.5 * strip.worst["tresca"]["value"]


def test_a_roller_between_raceways_is_the_librarys_from_every_door(tmp_path):
    """An ISO-profiled roller between raceways with --stresses and the case check: the
    roller's deflection and contacts are roller_between_raceways', each measure's
    stresses the worse contact's roller_stresses and the case ratio the worse
    contact's case_check, from every door."""
    from linecontact.stresses import raceway_stresses
    from linecontact.profiles import as_profile
    from linecontact.raceway import Raceways, roller_between_raceways
    from linecontact.stresses import HardnessProfile, case_check

    one, batch, frame = _doors(tmp_path, "calc", RACEWAY)
    row = one["models"][0]["rows"][0]
    units = one["units"]
    for name in CALC_NUMBERS:
        if name in row:
            _same(row[name], _si(batch, name, units))
            _same(row[name], _si(frame, name, units))
    R1, L, E = 5.5e-3, 11e-3, 115.38e9
    sol = roller_between_raceways(R1, L, E, Raceways(29.5e-3, 40.5e-3), force=3e3,
                                  profile="iso16281")
    assert row["roller_deflection"] == pytest.approx(sol.deflection, rel=1e-12)
    assert row["peak_pressure_inner"] == pytest.approx(sol.peak_pressure_inner, rel=1e-12)
    both = raceway_stresses(sol, L, E, as_profile("iso16281", R1, L, E), 0.0, 0.3)
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        worst = max(s.worst[m]["value"] for s in both.values())
        assert row[f"{m}_max"] == pytest.approx(worst, rel=1e-12)
    hard = HardnessProfile(700, 0.5e-3, 350)
    ratio = max(case_check(s, hard).max_ratio for s in both.values())
    assert row["case_ratio"] == pytest.approx(ratio, rel=1e-12)
    assert "worse contact" in row["flags"]


def test_a_bearing_is_the_librarys_from_every_door(tmp_path):
    """linecontact bearing (one case, batch, DataFrame) equals RadialRollerBearing's
    solve field by field, and its case check is its most loaded roller's between the
    same raceways (roller_between_raceways + roller_stresses + case_check)."""
    from linecontact.bearing import RadialRollerBearing
    from linecontact.stresses import raceway_stresses
    from linecontact.calc.subcommands import bearing as door
    from linecontact.raceway import roller_between_raceways
    from linecontact.stresses import HardnessProfile, case_check

    one, batch, frame = _doors(tmp_path, "bearing", BEARING)
    row = one["rows"][0]
    units = one["units"]
    for name in door.fields:
        _same(row[name], _si(batch, name, units))
        _same(row[name], _si(frame, name, units))
    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="iso16281")
    s = b.solve(10e3)
    assert row["displacement"] == pytest.approx(s.displacement, rel=1e-12)
    assert row["max_roller_load"] == pytest.approx(s.max_roller_load, rel=1e-12)
    assert row["radial_stiffness"] == pytest.approx(s.stiffness[0, 0], rel=1e-12)
    assert row["life_iso16281"] == pytest.approx(s.life_iso16281, rel=1e-12)
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        assert row[m] == pytest.approx(s.stress[m]["value"], rel=1e-12)
    np.testing.assert_allclose(row["solution"]["roller_loads"], s.roller_loads,
                               rtol=1e-12)
    roller = roller_between_raceways(b.roller_diameter / 2, b.length, b.estar,
                                     b.raceways, force=s.max_roller_load,
                                     profile=b.profile, n_slices=b.n_slices)
    both = raceway_stresses(roller, b.length, b.estar, b.profile, 0.0, 0.3)
    hard = HardnessProfile(700, 0.5e-3, 350)
    ratio = max(case_check(st, hard).max_ratio for st in both.values())
    assert row["case_ratio"] == pytest.approx(ratio, rel=1e-12)


@pytest.mark.parametrize("extra", [[], ["--misalignment", "0.5mrad"]],
                         ids=["aligned", "misaligned"])
def test_the_bearings_most_loaded_roller_is_calcs_roller_between_raceways(extra):
    """ISO-profiled rollers: the bearing's most loaded roller (approach, tilt against
    the inner ring, peak pressure) and `linecontact calc` of that roller between the
    same raceways at its load (free to tilt, under the rings' misalignment at its
    azimuth) agree to 1e-6 relative; both at the same slice count."""
    dm, D, L = 70e-3, 11e-3, 11e-3
    b = _run("bearing", *_options({k: v for k, v in BEARING.items()
                                   if k in ("rollers", "pitch_diameter",
                                            "roller_diameter", "length", "radial_load",
                                            "profile")}),
             "--n-slices", "50", *extra, "--json")["rows"][0]
    s = b["solution"]
    j = int(np.argmax(s["roller_loads"]))
    Q = s["roller_loads"][j]
    mis = ["--misalignment", repr(s["roller_misalignment"][j])] if extra else []
    c = _run("calc", "--radius", repr(D / 2), "--length", repr(L), "--estar",
             repr(b["bearing"]["estar"]), "--inner-raceway", repr((dm - D) / 2),
             "--outer-raceway", repr((dm + D) / 2), "--profile", "iso16281", "--load",
             repr(Q), "--tilt", "free", "--model", "profiled-roller:n_slices=50",
             *mis, "--json")["models"][0]["rows"][0]
    # the same solve: the approach meets the roller's deflection to the bearing's
    # Newton tolerances (1e-9 aligned, 1e-10 tilted), 1e-6 asked
    assert c["roller_deflection"] == pytest.approx(s["approach"][j], rel=1e-6)
    # the tilt: 0 by symmetry when aligned (both exactly), else to 1e-6
    assert c["tilt"] == pytest.approx(s["roller_tilts"][j], rel=1e-6, abs=1e-15)
    peak = max(p for p in (c["peak_pressure_inner"], c["peak_pressure_outer"]) if p)
    assert peak == pytest.approx(s["peak_pressure"], rel=1e-6)
