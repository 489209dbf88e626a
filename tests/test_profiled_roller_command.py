"""The calculator's profiled-roller options (``linecontact calc --crown-radius``,
``--profile``, ``--tilt``; linecontact.calc.features.roller), called in process through
linecontact.calc.cli.main.

Each test states the fact it checks and why its tolerance.
"""
from __future__ import annotations

import json
import re

import pytest

from linecontact.hertz import hertz_contact

CROWN = ["calc", "--radius", "10mm", "--length", "20mm", "--estar", "115.385GPa"]
ROLLER = ["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
          "--poisson", "0.3"]


def _main(capsys, *argv):
    from linecontact.calc.cli import main

    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _json(capsys, *argv):
    status, out, err = _main(capsys, *argv, "--json", "--si")
    assert status == 0, err
    return json.loads(out)


def test_crown_radius_prints_the_hertz_contact(capsys):
    """--crown-radius makes the contact the crowned roller's: for a crown that stays
    inside the roller its coupled-slice row is the Hertz contact, approach 7.024 um
    and p0 1102 MPa (R 10 mm, Rc 500 mm, 1 kN, printed to 4 digits: 7.024 and 1102),
    not edge loaded; ISO 16281 slicing follows as its own row, and no
    straight-cylinder law is printed as if it were this roller's."""
    status, out, err = _main(capsys, *CROWN, "--load", "1kN", "--crown-radius", "500mm")
    assert status == 0, err
    lines = [ln for ln in out.splitlines() if ln.startswith("Profiled roller")]
    assert len(lines) == 1
    row = lines[0].split()
    h = hertz_contact(1000.0, 0.5, 0.01, 115.385e9)
    assert f"{h.approach * 1e6:.4g}" in row and f"{h.p0 / 1e6:.4g}" in row
    assert "ISO 16281 slicing (circular crown (Rc = 500 mm))" in out
    assert "Universal curve" not in out and "Li-Popov" not in out


def test_straight_law_with_a_profile_is_refused_as_the_api_refuses_it(capsys):
    """--model li-popov with --crown-radius: a straight-cylinder law has no profile;
    the row says so (the library's CombinationError) instead of printing the straight
    roller (status 2: nothing computed)."""
    status, out, err = _main(capsys, *CROWN, "--load", "1kN", "--crown-radius", "500mm",
                             "--model", "li-popov")
    assert status == 2 and "straight-cylinder law has no profile or tilt" in err, err


def test_json_carries_q_of_x(capsys):
    """--json gives each profiled-roller row its line load q(x) on the slices and the
    slice widths: it integrates to the force (sum q w = F, exact for the slice model up
    to the force tolerance 1e-10), with the tilt in radians and the stiffness matrix."""
    doc = _json(capsys, *ROLLER, "--load", "1kN", "--profile", "iso16281", "--tilt",
                "0.5mrad")
    blocks = doc["profiled_roller"]
    assert [b["label"].split(" (")[0] for b in blocks] == ["Profiled roller"]
    assert doc["models"][0]["rows"][0]["moment"] > 0
    row = blocks[0]["rows"][0]
    x, q = row["x"], row["q"]
    from linecontact.roller.slices import DEFAULT_N_SLICES
    assert len(x) == len(q) == DEFAULT_N_SLICES       # the default slices, unrefined here
    w = row["width"]
    assert sum(qk * wk for qk, wk in zip(q, w)) == pytest.approx(1000.0, rel=1e-9)
    assert row["tilt"] == pytest.approx(5e-4, rel=1e-12)
    assert row["force"] == pytest.approx(1000.0, rel=1e-9)
    assert len(row["stiffness_matrix"]) == 2 and row["moment"] > 0


def test_straight_roller_reports_edge_loading_not_a_number(capsys):
    """A straight roller solved by coupled slices (--model profiled-roller; without it
    a straight aligned roller is the universal law, as in Contact) is edge loaded: its
    peak pressure is singular on a half-space, so the row prints '-' for p max and says
    why (both ends); the JSON has p_max null and edge_loaded true."""
    argv = (*ROLLER, "--load", "1kN", "--tilt", "0", "--model", "profiled-roller")
    status, out, err = _main(capsys, *argv)
    assert status == 0, err
    row = next(ln for ln in out.splitlines() if ln.startswith("Profiled roller"))
    assert "both ends" in row and "singular" in row
    doc = _json(capsys, *argv)
    assert doc["models"][0]["rows"][0]["p_max"] is None
    r = doc["profiled_roller"][0]["rows"][0]
    assert r["p_max"] is None and r["edge_loaded"] is True


def test_sweep_gives_one_profiled_row_per_value(capsys):
    """A load sweep gives one profiled-roller row per load; the depth increases with
    the load (F(d) is increasing)."""
    doc = _json(capsys, *ROLLER, "--load", "0.5kN:2kN:3", "--crown-radius", "200mm")
    rows = doc["profiled_roller"][0]["rows"]
    assert len(rows) == 3
    depths = [r["depth"] for r in rows]
    assert depths == sorted(depths) and depths[0] > 0


@pytest.mark.parametrize("argv, name", [
    (["--profile", "cone"], "profile"),
    (["--crown-radius", "-5mm"], "--crown-radius"),
    (["--crown-radius", "0"], "--crown-radius"),
    (["--tilt", "5furlong"], "--tilt"),
    (["--tilt", "10deg"], "--tilt"),
    (["--crown-radius", "0.5", "--profile", "iso16281"], "--crown-radius"),
    (["--profile", "circular:Rc=-1"], "Rc"),
    (["--profile", "file:/nonexistent/p.csv"], "profile file"),
])
def test_bad_profile_input_is_one_line_exit_2(capsys, argv, name):
    """Bad profile input (unknown name, crown radius <= 0, an angle that is not one or
    beyond 0.1 rad, two profiles at once, a missing file) exits with status 2 and one
    line on stderr naming the parameter and the valid range; nothing on stdout."""
    status, out, err = _main(capsys, *ROLLER, "--load", "1kN", *argv)
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and name in err and "valid" in err


def test_profile_format_problems_name_the_option_not_a_range(capsys, tmp_path):
    """A problem in what --profile names (a NaN row of its file, lundberg without its
    design force under --depth, an unknown name) is one line naming --profile and the
    spec as typed, then what is wrong (for lundberg: where F0 comes from) and one
    'valid:'; it is not worded "is outside the valid range" (a missing value or a bad
    row is not a value out of a range)."""
    nan = tmp_path / "nan.csv"
    nan.write_text("x,drop\n-0.005,0\n0,nan\n0.005,0\n")
    for load, spec, what in ((["--load", "1kN"], f"file:{nan}", "'nan'"),
                             (["--depth", "1um"], "lundberg", "F0=.. in the spec, or --load"),
                             (["--load", "1kN"], "cone", "not a profile")):
        status, out, err = _main(capsys, *ROLLER, *load, "--profile", spec)
        assert status == 2 and out == "" and err.count("\n") == 1, err
        assert f"--profile = {spec!r}" in err and what in err, err
        assert err.count("valid") == 1 and "outside the valid range" not in err, err


def test_no_contact_is_refused(capsys, tmp_path):
    """A depth at which the roller does not touch at all (a measured profile whose
    smallest drop, 2 um, exceeds the depth, 1 um) exits 2 with one line naming the
    depth."""
    f = tmp_path / "p.csv"
    f.write_text("x,drop\n-0.005,3e-6\n0,2e-6\n0.005,3e-6\n")
    status, _, err = _main(capsys, *ROLLER, "--depth", "1um", "--profile", f"file:{f}")
    assert status == 2 and err.count("\n") == 1 and "depth" in err


def test_crowned_roller_between_raceways_is_the_library_composition(capsys):
    """A crowned roller between raceways, tilt free: the calculator's row is
    linecontact.raceway.roller_between_raceways of the same inputs (the same solver:
    equal to rtol 1e-9), its deflection the sum of the two contacts' depths (exact
    identity of the series contacts), and its free tilt 0 for a symmetric crown between
    aligned rings (|theta| < 1e-9 rad)."""
    from linecontact.raceway import Raceways, roller_between_raceways

    doc = _json(capsys, *ROLLER, "--load", "1kN", "--crown-radius", "0.1",
                "--inner-raceway", "20mm", "--outer-raceway", "30mm", "--tilt", "free")
    row = doc["models"][0]["rows"][0]
    from linecontact.classical import effective_modulus

    s = roller_between_raceways(5e-3, 10e-3, effective_modulus(210e9, 0.3),
                                Raceways(20e-3, 30e-3), force=1e3, profile="circular:Rc=0.1",
                                tilt="free")
    assert row["roller_deflection"] == pytest.approx(s.deflection, rel=1e-9)
    assert row["roller_stiffness"] == pytest.approx(s.stiffness, rel=1e-9)
    assert row["roller_deflection"] == pytest.approx(row["depth_inner"] + row["depth_outer"],
                                                     rel=1e-12)
    assert abs(row["tilt"]) < 1e-9


def test_batch_profile_rows_equal_the_one_case_call(capsys, tmp_path):
    """A CSV batch takes the profile and tilt columns: each profiled row's columns equal
    the one-case call's first (coupled-slice) row to the printed 6 digits (the same
    solver on the same inputs), and a row without a profile is the straight cylinder's
    (default model) with empty roller cells."""
    f = tmp_path / "cases.csv"
    f.write_text("radius,length,estar,load,crown_radius,tilt\n5mm,10mm,115GPa,1kN,0.1,\n"
                 "5mm,10mm,115GPa,2kN,0.2,0.5mrad\n5mm,10mm,115GPa,1kN,,\n")
    status, out, err = _main(capsys, "calc", str(f), "--si")
    assert status == 0, err
    import csv
    import io

    rows = list(csv.DictReader(io.StringIO(out)))
    for row, extra in zip(rows[:2], (["--load", "1kN", "--crown-radius", "0.1"],
                                     ["--load", "2kN", "--crown-radius", "0.2", "--tilt",
                                      "0.5mrad"])):
        one = _json(capsys, "calc", "--radius", "5mm", "--length", "10mm", "--estar", "115GPa",
                    *extra)["models"][0]["rows"][0]
        for name in ("force", "depth", "stiffness", "moment", "p_max"):
            col = next(c for c in row if c.startswith(f"{name}_"))
            assert float(row[col]) == pytest.approx(one[name], rel=1e-5, abs=1e-12), name
    assert rows[2]["moment_N_m"] == "" and rows[2]["error"] == ""
    assert rows[2]["model"].startswith("Universal") and rows[0]["model"].startswith(
        "Profiled roller")


def test_profile_file_cells_follow_the_one_input_rule(capsys, tmp_path):
    """The cells of a 'file:' profile are read like every other value (linecontact.
    _units: a number with at most one unit name, bare = m): '5mm, 1um' is the same
    profile as '0.005, 1e-6' (the same force to the last bit: rtol 0, the factors 1e-3
    and 1e-6 are the built-in ones), and a non-ASCII digit or '1_0' (both accepted by
    float() before) is one line, status 2."""
    bare, units = tmp_path / "bare.csv", tmp_path / "units.csv"
    bare.write_text("x,drop\n-0.005,1e-6\n0,0\n0.005,1e-6\n", encoding="utf-8")
    units.write_text("x,drop\n-5mm,1um\n0,0\n5mm,1um\n", encoding="utf-8")
    rows = [_json(capsys, *ROLLER, "--depth", "2um", "--profile", f"file:{p}")
            for p in (bare, units)]
    assert rows[0]["profiled_roller"][0]["rows"] == rows[1]["profiled_roller"][0]["rows"]
    for cell in ("\u0663", "1_0"):
        bad = tmp_path / "bad.csv"
        bad.write_text(f"x,drop\n-0.005,1e-6\n0,{cell}\n0.005,1e-6\n", encoding="utf-8")
        status, out, err = _main(capsys, *ROLLER, "--depth", "2um", "--profile",
                                 f"file:{bad}")
        assert status == 2 and len(err.strip().splitlines()) == 1 and cell in err, err


def test_profiled_row_prints_where_the_error_is_known(capsys):
    """The coupled-slice row carries the note of tables/roller_accuracy.csv's covered
    range: R 5 mm, L 14 mm (L/D 1.4), 4.2 kN (300 N/mm) is a case of that table, inside;
    L 150 mm (L/(2R) 15) is beyond its longest roller (L/D 12), outside, named in the
    row in the user's terms (the length and the contact's effective radius)."""
    base = ["calc", "--radius", "5mm", "--estar", "115.385GPa", "--load", "4.2kN",
            "--crown-radius", "500mm"]
    status, out, err = _main(capsys, *base, "--length", "14mm")
    assert status == 0, err
    row = next(r for r in out.splitlines() if r.startswith("Profiled roller"))
    assert "inside the range where this model's error was measured" in row
    status, out, err = _main(capsys, *base, "--length", "150mm")
    row = next(r for r in out.splitlines() if r.startswith("Profiled roller"))
    assert "L/(2R) = 15 (roller length L = 150 mm, the contact's effective radius R = " \
           "5 mm" in row and "(measured 0.5-12)" in row and "outside the range" in row


def test_plain_calc_does_not_import_the_roller_model():
    """Cold start: a one-case calc without profile flags never imports
    linecontact.roller (nor reads tables/roller_accuracy.csv, which only a roller solve
    does); checked in a fresh interpreter, since this one may have imported it."""
    import subprocess
    import sys
    from pathlib import Path

    code = ("import sys, io, contextlib\n"
            "from linecontact.calc.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    main(['calc', '--radius', '5mm', '--length', '10mm', '--estar',"
            " '115GPa', '--load', '1kN'])\n"
            "print('linecontact.roller' in sys.modules)\n")
    root = Path(__file__).resolve().parents[1]
    out = subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True,
                         text=True, check=True).stdout
    assert out.strip() == "False"


def test_iso_profile_on_a_raceway_scales_with_the_roller_diameter(capsys):
    """ISO 16281's reference profile is a drop of 0.00035 D ln(...) with D the
    roller's own diameter. Against a convex raceway (--radius2) the slices see the
    effective radius 1/R = 1/R1 + 1/R2, but the profile must still use D = 2 R1
    (10 mm here, not 2 R_eff = 8 mm, which made the drop 20 % too shallow)."""
    status, out, err = _main(capsys, "calc", "--radius", "5mm", "--radius2", "20mm", "--length",
                             "10mm", "--estar", "115GPa", "--load", "1kN",
                             "--profile", "iso16281")
    assert status == 0, err
    assert "ISO 16281 (D = 10 mm" in out and "D = 8 mm" not in out


def test_batch_rows_sharing_a_roller_are_one_sweep_equal_to_one_by_one(capsys, tmp_path,
                                                                       monkeypatch):
    """Rows of a batch that share a profiled roller (R, L, E*, profile, tilt) are solved
    together: one ProfiledRoller per distinct roller (2 here, for 8 rows in mixed order),
    its loads in increasing order as one sweep, each Newton solve starting from the
    previous load's solution (issue 20, item 2). The answers equal each row solved
    alone (a batch of one row: its own roller, a cold start) within the solver's
    tolerance: both converge the same equations to 1e-10 of F, so depth, moment, tilt,
    stiffness and peak pressure agree to 1e-8 (measured: 1e-14 to 4e-12)."""
    import csv as csv_module

    from linecontact.roller import ProfiledRoller

    rollers = [("6mm", "12mm", "iso16281", "0.3mrad"),
               ("8mm", "14mm", "circular:Rc=0.4", "free")]
    loads = ["9kN", "2kN", "15kN", "5kN"]
    rows = [[*rollers[i % 2], load] for load in loads for i in (0, 1)]
    head = ["radius", "length", "profile", "tilt", "load"]

    def write(path, body):
        with open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv_module.writer(fh)
            w.writerow(head)
            w.writerows(body)
        return str(path)

    built, solved = [], []
    init, at_force = ProfiledRoller.__init__, ProfiledRoller.at_force

    def counting_init(self, *a, **k):
        built.append(a[:2])
        init(self, *a, **k)

    def recording(self, force, *a, **k):
        solved.append((id(self), float(force)))
        return at_force(self, force, *a, **k)

    monkeypatch.setattr(ProfiledRoller, "__init__", counting_init)
    monkeypatch.setattr(ProfiledRoller, "at_force", recording)
    together = _json(capsys, "calc", write(tmp_path / "all.csv", rows), "--estar",
                     "115.385GPa")["rows"]
    assert len(built) == 2, built
    for roller in {r for r, _ in solved}:  # each roller's loads: one increasing sweep
        forces = [f for r, f in solved if r == roller]
        assert forces == sorted(forces) and len(forces) == 4, forces
    for k, row in enumerate(rows):
        alone = _json(capsys, "calc", write(tmp_path / f"row{k}.csv", [row]), "--estar",
                      "115.385GPa")["rows"][0]
        for name in ("depth_m", "moment_N_m", "tilt_rad", "stiffness_N_per_m",
                     "p_max_Pa", "contact_length_m"):
            a, b = together[k][name], alone[name]
            assert (a is None) == (b is None), (k, name)
            if a is not None:  # a moment to 1e-9 of F L, a tilt to 1e-12 rad (both
                # zero up to rounding at the free tilt of a symmetric profile)
                scale = {"moment_N_m": 1e-9 * together[k]["force_N"] * 0.014,
                         "tilt_rad": 1e-12}.get(name, 0.0)
                assert a == pytest.approx(b, rel=1e-8, abs=scale), (k, name)


def test_tilted_roller_table_says_what_its_negative_depth_is(capsys):
    """A roller tilted by 1 deg (L = 10 mm) is pressed in at its loaded end, with its
    centre lifted off: d < 0 at x = 0. The table's notes say that d is the centre's
    approach and how far the loaded end goes in (the profiled roller's note was held
    back for a --json-only block and never printed); the row gives the approach."""
    status, out, err = _main(capsys, "calc", "--radius", "5mm", "--length", "10mm",
                             "--estar", "115GPa", "--load", "1kN", "--tilt", "1deg")
    assert status == 0, err
    row = next(line for line in out.splitlines() if line.startswith("Profiled roller"))
    assert float(re.split(r"\s{2,}", row)[2]) < 0, row      # model, F [kN], d [um]
    note = next(line for line in out.splitlines() if line.startswith("Note: profiled"))
    assert "depth at the roller's centre" in note and "from first contact" in note


def test_a_tilted_rollers_depth_says_it_is_at_the_centre_and_gives_the_approach(capsys):
    """A straight roller tilted by 1 degree (17.45 mrad, inside the models' declared
    |theta| < 0.1 rad) touches first at its +x end: its depth at the centre x = 0 is
    negative, and the row says so with the approach from first contact, d - d0
    (Contact.first_contact_depth, about -theta L/2 for a straight roller): the
    library's ContactResult.approach of the same solve to the printed 4 digits. An
    aligned crowned roller (first contact at the centre, d0 = 0) has no such note:
    there d is the approach."""
    from linecontact.contact import Contact, Roller

    small = ["calc", "--radius", "5mm", "--length", "10mm", "--estar", "115.385GPa"]
    doc = _json(capsys, *small, "--load", "1kN", "--tilt", "1deg",
                "--model", "profiled-roller")
    row = doc["models"][0]["rows"][0]
    theta = doc["models"][0]["rows"][0]["tilt"]
    r = Contact(Roller(5e-3, 10e-3, profile="straight", tilt=theta),
                estar=115.385e9).normal(force=1e3)
    assert row["depth"] < 0 < r.approach
    assert row["depth"] == pytest.approx(r.depth, rel=1e-9)
    assert "depth at the roller's centre" in row["flags"]
    assert f"the approach from first contact d - d0 = {r.approach * 1e6:.4g} um" \
        in row["flags"]
    crowned = _json(capsys, *small, "--load", "1kN", "--crown-radius", "500mm",
                    "--model", "profiled-roller")["models"][0]["rows"][0]
    assert "first contact" not in crowned["flags"]


def test_a_tilt_past_the_declared_range_is_refused_with_the_range(capsys):
    """The roller models linearise the tilt: |theta| < 0.1 rad (5.7 degrees); 6 degrees
    is refused in one line naming --tilt, the value and the range (exit 2)."""
    status, out, err = _main(capsys, *ROLLER, "--load", "1kN", "--tilt", "6deg")
    assert status == 2 and "--tilt" in err and "(-0.1, 0.1) rad" in err
    assert len(err.strip().splitlines()) == 1
