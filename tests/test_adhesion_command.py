"""The calculator's adhesion option (linecontact.calc.features.adhesion).

Run in-process through linecontact.calc.cli.main. Facts checked: every printed number is
the library's (same functions: rtol 1e-12 on the JSON's floats); units J/m^2 and mJ/m^2
give the same case; every bad combination is one line on stderr naming the parameter,
exit status 2.
"""
import json

import numpy as np
import pytest

from linecontact.adhesion import AdhesiveContact, CylinderAdhesion, tabor_parameter
from linecontact.calc.cli import main
from linecontact.classical import effective_modulus
from linecontact.models import get_model

CASE = ["calc", "--radius", "0.5mm", "--length", "2mm", "--modulus", "2MPa",
        "--poisson", "0.5", "--model", "universal"]


def _row(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)["models"][0]["rows"][0]


#: A hydrogel roller inside the BEM table (s = b_c/L = 0.039).
GEL = ["calc", "--radius", "1mm", "--length", "2mm", "--modulus", "50kPa", "--poisson",
       "0.5", "--model", "universal"]


def test_bem_columns_are_the_library_values(capsys):
    """Inside the BEM table: the corrected pull-off under both controls and the MDR's
    measured error equal the library's (method 'bem')."""
    row = _row(capsys, GEL + ["--load", "0.1mN", "--work-of-adhesion", "50mJ/m^2"])
    m = get_model("universal", 1e-3, 2e-3, effective_modulus(5e4, 0.5))
    c = CylinderAdhesion(m, 0.05)
    assert c.in_table
    assert row["pull_off_force"] == pytest.approx(c.pull_off("force")["force"], rel=1e-12)
    assert row["pull_off_depth_ctrl"] == pytest.approx(c.pull_off("depth")["force"],
                                                       rel=1e-12)
    assert row["pull_off_mdr_error"] == pytest.approx(
        c.pull_off("force", method="mdr")["error"], rel=1e-12)


def test_columns_are_the_library_values(capsys):
    """Below the BEM table (s = 0.0067) the pull-off is the long roller's end model
    (the row's note says so) with its stated error, beside the 2D JKR value times L, and
    the MDR's error is measured against it; the MDR pull-off, zero load, the depth at
    the load with adhesion and the Tabor parameter equal the library's."""
    row = _row(capsys, CASE + ["--load", "10mN", "--work-of-adhesion", "40mJ/m^2"])
    E = effective_modulus(2e6, 0.5)
    m = get_model("universal", 0.5e-3, 2e-3, E)
    mdr = AdhesiveContact.from_model(m, 0.04)
    c = CylinderAdhesion(m, 0.04)
    f, d = c.pull_off("force"), c.pull_off("depth")
    assert f["method"] == "end-model"
    assert row["pull_off_force"] == pytest.approx(f["force"], rel=1e-12)
    assert row["pull_off_depth_ctrl"] == pytest.approx(d["force"], rel=1e-12)
    assert row["pull_off_error"] == pytest.approx(max(f["error"], d["error"]), rel=1e-12)
    assert row["pull_off_2d"] == pytest.approx(c.pull_off_2d, rel=1e-12)
    assert row["pull_off_mdr_error"] == pytest.approx(f["mdr_error"], rel=1e-12)
    assert "below the BEM table" in json.dumps(row)
    assert "end model" in json.dumps(row)
    assert row["pull_off_mdr"] == pytest.approx(mdr.pull_off("force")["force"], rel=1e-12)
    assert row["zero_load_depth"] == pytest.approx(mdr.zero_load()["depth"], rel=1e-12)
    assert row["depth_adhesive"] == pytest.approx(mdr.depth_at_force(0.01), rel=1e-12)
    assert row["tabor"] == pytest.approx(tabor_parameter(0.5e-3, 0.04, E), rel=1e-12)
    assert row["depth_adhesive"] > row["depth"], "adhesion pulls the roller in deeper"


def test_below_the_long_roller_table_no_pull_off_and_no_bare_mdr(capsys):
    """s = b_c/L below 1e-3 (R 5 mm, L 200 mm, w 1 mJ/m^2: s = 9e-5): neither the pull-off
    nor the rule of Hess is printed (its error is measured nowhere there: it is never
    the only pull-off shown without one); the 2D JKR value times L is, and the note
    says why."""
    argv = ["calc", "--radius", "5mm", "--length", "200mm", "--modulus", "2MPa",
            "--poisson", "0.5", "--model", "universal", "--load", "10mN",
            "--work-of-adhesion", "1mJ/m^2"]
    row = _row(capsys, argv)
    for key in ("pull_off_force", "pull_off_mdr", "pull_off_error"):
        assert row[key] is None or np.isnan(row[key])
    m = get_model("universal", 5e-3, 0.2, effective_modulus(2e6, 0.5))
    c = CylinderAdhesion(m, 1e-3)
    assert c.s < 1e-3
    assert row["pull_off_2d"] == pytest.approx(c.pull_off_2d, rel=1e-12)
    assert "below the long roller's table" in json.dumps(row)


def test_depth_given_gives_the_adhesive_force(capsys):
    """With --depth the row has the force at that depth with adhesion (rule of Hess),
    smaller than without: adhesion adds tension at the contact edge."""
    row = _row(capsys, CASE + ["--depth", "5um", "--work-of-adhesion", "0.04 J/m^2"])
    m = get_model("universal", 0.5e-3, 2e-3, effective_modulus(2e6, 0.5))
    F = AdhesiveContact.from_model(m, 0.04).force_at_depth(5e-6)
    assert row["force_adhesive"] == pytest.approx(F, rel=1e-12)
    assert row["force_adhesive"] < row["force"]


@pytest.mark.parametrize("extra, word", [
    (["--work-of-adhesion", "40mJ/m"], "unknown unit"),
    (["--work-of-adhesion", "5mm"], "surface energy"),
    (["--work-of-adhesion", "-1mJ/m^2"], "work-of-adhesion"),
    (["--work-of-adhesion", "40mJ/m^2", "--inner-raceway", "20mm", "--outer-raceway",
      "21mm"], "raceways"),
    (["--work-of-adhesion", "40mJ/m^2", "--instantaneous-modulus", "3MPa",
      "--long-term-modulus", "1MPa", "--relaxation-time", "1s"], "receding"),
])
def test_bad_combinations_are_one_line(capsys, extra, word):
    """A bad unit, a negative w, w with the raceways or with a viscoelastic body: one
    line on stderr naming the parameter, exit status 2."""
    argv = [a for a in CASE if a not in ("--modulus", "2MPa")] if "--instantaneous-modulus" \
        in extra else CASE
    assert main(argv + ["--load", "10mN"] + extra) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and word in err and "work" in err, err
