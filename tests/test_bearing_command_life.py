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
