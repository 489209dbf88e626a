"""`linecontact bearing` with the bearing-life inputs: the command's fields, JSON and
batch columns are the library's solution (RadialRollerBearing, solve_spectrum), the
units of the new kinds are read as documented, and a spectrum file gives the
Palmgren-Miner life of its cases."""
from __future__ import annotations

import csv
import json
import math

import pytest

from linecontact.bearing import LoadCase, RadialRollerBearing, solve_spectrum
from linecontact.calc.cli import main

BASE = ["bearing", "--rollers", "14", "--pitch-diameter", "70mm", "--roller-diameter",
        "11mm", "--length", "11mm", "--radial-load", "10kN", "--clearance", "40um"]
LIFE = ["--speed", "1500rpm", "--viscosity", "20.7cSt", "--density", "860kg/m^3",
        "--pressure-viscosity", "2e-8", "--roughness-roller", "0.1um",
        "--roughness-raceway", "0.15um", "--contamination", "0.5", "--reliability",
        "0.99"]
FLANGES = ["--end-radius", "60mm", "--flange-angle", "3deg", "--inner-flange-height",
           "3.2mm", "--outer-flange-height", "3.2mm", "--axial-load", "1kN"]
W = 1500 * math.pi / 30


def _library():
    return RadialRollerBearing(
        14, 70e-3, 11e-3, 11e-3, 40e-6, viscosity=20.7e-6, density=860.0,
        pressure_viscosity=2e-8, roughness_roller=0.1e-6, roughness_raceway=0.15e-6,
        contamination=0.5, reliability=0.99, end_radius=60e-3,
        flange_angle=math.radians(3), inner_flange_height=3.2e-3,
        outer_flange_height=3.2e-3)


def _spectrum(tmp_path):
    path = tmp_path / "cases.csv"
    path.write_text("time_share,radial_load,speed\n0.8,10kN,1500rpm\n0.2,20kN,750rpm\n",
                    encoding="utf-8")
    return path


def test_json_fields_are_the_library_solution(capsys, tmp_path):
    """Every new field of the JSON row is the library's value (SI), the unit names
    rpm, cSt, kg/m^3, deg read to SI; the spectrum's combined lives are solve_spectrum's."""
    path = _spectrum(tmp_path)
    assert main(BASE + LIFE + FLANGES + ["--spectrum", str(path), "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    b = _library()
    s = b.solve(10e3, speed=W, axial_load=1000.0)
    assert row["kappa"] == pytest.approx(s.kappa, rel=1e-12)
    assert row["film_ratio"] == pytest.approx(s.film_ratio, rel=1e-12)
    assert row["film_minimum_inner"] == pytest.approx(s.film_minimum_inner[0].min(),
                                                      rel=1e-12)
    assert row["life_modified"] == pytest.approx(s.life_modified, rel=1e-12)
    assert row["life_modified_reference"] == pytest.approx(s.life_modified_reference,
                                                           rel=1e-12)
    assert row["static_safety"] == pytest.approx(s.static_safety, rel=1e-12)
    assert row["max_flange_force"] == pytest.approx(s.flange_forces.max(), rel=1e-12)
    assert sum(row["solution"]["flange_forces"]) == pytest.approx(1000.0, rel=1e-12)
    r = solve_spectrum(b, [LoadCase(0.8, 10e3, speed=W), LoadCase(0.2, 20e3,
                                                                  speed=W / 2)])
    for kind in ("iso281", "iso16281", "modified", "modified_reference"):
        assert row[f"spectrum_life_{kind}"] == pytest.approx(r.life[kind], rel=1e-12)
        assert row["spectrum"]["life"][kind] == pytest.approx(r.life[kind], rel=1e-12)
    L1, L2 = r.lives["iso281"]
    u1 = 0.8 * 1500 / (0.8 * 1500 + 0.2 * 750)
    assert row["spectrum_life_iso281"] == pytest.approx(1 / (u1 / L1 + (1 - u1) / L2),
                                                        rel=1e-12)


def test_fits_in_a_batch_give_the_operating_clearance(capsys, tmp_path):
    """A CSV with a shaft fit per row: the operating clearance column is
    P_d - I d/d_r (solid steel shaft, one material) and the plain row has none."""
    src = tmp_path / "b.csv"
    src.write_text("name,rollers,pitch_diameter,roller_diameter,length,radial_load,"
                   "clearance,shaft_interference,bore\n"
                   "fit,14,70mm,11mm,11mm,10kN,40um,20um,50mm\n"
                   "plain,14,70mm,11mm,11mm,10kN,40um,,\n", encoding="utf-8")
    out = tmp_path / "out.csv"
    assert main(["bearing", str(src), "-o", str(out), "--si"]) == 0
    rows = list(csv.DictReader(out.open(encoding="utf-8")))
    col = next(c for c in rows[0] if c.startswith("operating_clearance"))
    # the CSV carries 6 significant digits
    assert float(rows[0][col]) == pytest.approx(40e-6 - 20e-6 * 50 / 59, rel=1e-5)
    assert rows[1][col] in ("", "nan") and rows[1]["error"] == ""


@pytest.mark.parametrize("argv,words", [
    (["--viscosity", "20cSt"], ["speed"]),
    (["--density", "860kg/m^3", "--pressure-viscosity", "2e-8"], ["viscosity"]),
    (["--axial-load", "1kN"], ["end_radius"]),
    (["--temperature-difference", "10degC"], ["degC", "K"]),
    (["--speed", "50Hz"], ["Hz", "rpm"]),
])
def test_incomplete_or_misread_inputs_are_refused_in_one_line(capsys, argv, words):
    assert main(BASE + argv) == 2
    cap = capsys.readouterr()
    text = cap.err + cap.out
    assert all(w in text for w in words), text
    assert "Traceback" not in text


def test_a_bad_spectrum_file_names_the_row_and_column(capsys, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("time_share,radial_load\n0.5,10kN\n0.5,ten\n", encoding="utf-8")
    assert main(BASE + ["--spectrum", str(path)]) == 2
    err = capsys.readouterr().err
    assert "row 2" in err and "radial_load" in err
    path.write_text("time_share,radial_load\n0.5,10kN\n0.5,20kN\n", encoding="utf-8")
    assert main(BASE + ["--spectrum", str(path)]) == 2       # shares of time, no speed
    assert "speed" in capsys.readouterr().err


def test_header_keeps_the_clearance_as_given_beside_the_operating_one(capsys):
    """P_d in the header line is the clearance the user gave (40 um); the operating
    clearance after a 20 um shaft fit and 10 K (40 - 16.949 - 8.4 = 14.651 um,
    docs/bearing_life.md) is named as such beside it, never in its place."""
    fits = ["--shaft-interference", "20um", "--bore", "50mm", "--temperature-difference",
            "10K"]
    assert main(BASE + fits) == 0
    head = capsys.readouterr().out.splitlines()[0]
    assert "P_d = 40 um (operating 14.65" in head, head
    assert main(BASE) == 0
    head = capsys.readouterr().out.splitlines()[0]
    assert "P_d = 40 um," in head and "operating" not in head, head


def test_text_notes_explain_only_what_was_computed(capsys, tmp_path):
    """A plain bearing's text says nothing of flanges, films, duty cycles or a case
    check it did not compute (each of those notes came with every bearing); with
    their inputs, each note is there; the JSON header keeps every note."""
    words = {"flanges": "Note: axial load:", "film": "Note: EHL film",
             "spectrum": "Note: duty cycle:", "modified": "Note: L_nm ="}
    assert main(BASE) == 0
    out = capsys.readouterr().out
    assert not [w for w in words.values() if w in out], out
    path = _spectrum(tmp_path)
    assert main(BASE + LIFE + FLANGES + ["--spectrum", str(path)]) == 0
    out = capsys.readouterr().out
    assert all(w in out for w in words.values()), out
    assert main(BASE + ["--json"]) == 0
    assert set(words) <= set(json.loads(capsys.readouterr().out)["notes"])


def test_help_names_the_default_slice_counts_and_the_life_outputs(capsys):
    """`linecontact bearing --help` gives the slice counts the factory uses when none
    is given (it sent the reader to RadialRollerBearing, whose default moved to the
    factory's), and its description names the life outputs the options add."""
    from linecontact.roller.solvers import DEFAULT_SLICES

    try:
        main(["bearing", "--help"])
    except SystemExit:
        pass
    text = " ".join(capsys.readouterr().out.split()).replace("- ", "-")  # argparse's wrap
    for model, n in DEFAULT_SLICES.items():
        assert f"{n} for {model}" in text, (model, n)
    for word in ("EHL film", "L_nm", "static safety", "operating clearance", "duty cycle"):
        assert word in text, word


def test_a_spectrum_file_is_refused_in_its_own_words(capsys, tmp_path):
    """A duty-cycle file whose time shares lack a speed, or do not sum to 1, is refused
    naming --spectrum, the file's column and the remedy (a speed column or --speed,
    fractions summing to 1), not the library's keyword shares='revolutions' or its
    argument time_shares; a --speed fills the cases without one."""
    path = tmp_path / "cases.csv"
    path.write_text("time_share,radial_load\n0.8,10kN\n0.2,20kN\n", encoding="utf-8")
    assert main(BASE + ["--spectrum", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--spectrum" in err and "--speed" in err, err
    assert "shares=" not in err and "rows [1, 2] have none" in err, err
    assert main(BASE + ["--spectrum", str(path), "--speed", "1500rpm"]) == 0
    capsys.readouterr()
    path.write_text("time_share,radial_load,speed\n80,10kN,1500rpm\n20,20kN,750rpm\n",
                    encoding="utf-8")
    assert main(BASE + ["--spectrum", str(path)]) == 2
    err = capsys.readouterr().err
    assert "time_share column sums to 100" in err and "time_shares" not in err, err
