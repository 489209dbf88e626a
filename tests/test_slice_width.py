"""No slice-width numbers (issue 32): where a stress maximum depends on the slice width
(an edge-loaded roller: its end pressure is singular on a half-space, and the maxima
below it grow without limit as the slices are refined) the library flags it
(SubsurfaceStresses.withheld; a bearing's stress entry "withheld") and the calculators
print "-" with the reason and what converges instead, as for the peak pressure."""
import json

import pytest

from linecontact.calc.cli import main
from linecontact.roller import ProfiledRoller
from linecontact.stresses import EDGE_LOADED_STRESS, MEASURES, roller_stresses

BEARING = ["bearing", "--rollers", "20", "--pitch-diameter", "100mm", "--roller-diameter",
           "10mm", "--length", "10mm", "--radial-load", "10kN", "--misalignment", "1mrad"]


def _stress_lines(text):
    """The stress lines, each as its words: the table's column width follows the widest
    value of the other lines, which may differ between slice counts."""
    return [ln.split() for ln in text.splitlines()
            if ln.strip().startswith(("max Tresca", "max von Mises", "max orthogonal",
                                      "at depth"))]


def test_misaligned_bearing_prints_the_same_at_20_40_80_slices(capsys):
    """The misaligned straight-roller bearing of issue 32 (Z = 20, d_m = 100 mm,
    D = L = 10 mm, 10 kN, 1 mrad): its most loaded roller is edge loaded, and the
    Tresca maximum of its slices was 955, 1283, 1705 MPa at 20, 40, 80 slices. Every
    stress line prints the same at the three slice counts: "-", with the note saying
    why and what converges instead."""
    printed = []
    for n in ("20", "40", "80"):
        assert main(BEARING + ["--n-slices", n]) == 0
        out = capsys.readouterr().out
        printed.append(_stress_lines(out))
        assert "stress maxima not reported" in out and "corner radius" in out
    assert len(printed[0]) == 6
    assert printed[0] == printed[1] == printed[2]
    assert all(words[-2] == "-" for words in printed[0])
    assert main(BEARING + ["--n-slices", "20", "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert all(row[m] is None for m in MEASURES)
    assert all(row["solution"]["stress"][m]["withheld"] for m in MEASURES)


def test_edge_loaded_roller_stresses_are_flagged_and_a_crowned_one_is_not():
    """roller_stresses flags every measure of an edge-loaded straight roller (the
    reason names what converges instead); a crowned roller off its ends has none."""
    straight = ProfiledRoller(5e-3, 14e-3, 115.385e9, "straight", n_slices=30).at_force(1.4e3)
    s = roller_stresses(straight)
    assert straight.edge_loaded
    assert s.withheld == {m: EDGE_LOADED_STRESS for m in MEASURES}
    assert "withheld" in s.to_dict(arrays=False)
    crowned = ProfiledRoller(5e-3, 14e-3, 115.385e9, "circular:Rc=0.5",
                             n_slices=30).at_force(1.4e3)
    c = roller_stresses(crowned)
    assert not crowned.edge_loaded and c.withheld == {}
    assert "withheld" not in c.to_dict(arrays=False)


def test_calc_prints_no_stress_of_an_edge_loaded_roller(capsys):
    """linecontact calc --stresses on an edge-loaded straight roller (slices): the stress
    columns are null/"-" and the row's note says why; on the crowned roller they are
    the library's numbers."""
    base = ["calc", "--radius", "5mm", "--length", "14mm", "--load", "1.4kN",
            "--model", "profiled-roller", "--modulus", "210GPa", "--poisson", "0.3",
            "--stresses", "yes", "--json"]
    assert main(base + ["--profile", "straight"]) == 0
    row = json.loads(capsys.readouterr().out)["models"][0]["rows"][0]
    assert all(row[f"{m}_max"] is None for m in MEASURES)
    assert "stress maxima and case check not reported" in row["flags"]
    assert main(base + ["--crown-radius", "500mm"]) == 0
    row = json.loads(capsys.readouterr().out)["models"][0]["rows"][0]
    assert all(row[f"{m}_max"] > 0 for m in MEASURES)


@pytest.mark.parametrize("line_load", [800e3, 2000e3])
def test_end_relief_with_a_corner_radius_converges(line_load):
    """With an end relief (corner radius 50 mm over the last 2.1 mm, the stress study's
    roller: D 10 mm, L 14 mm; 800 and 2000 N/mm) the contact stays off the ends, the pressure peak at the
    relief is finite, and the stress maxima converge: at 50, 100 and 200 slices within
    0.5 % of 400 slices (measured 0.4 % at 50, 0.05 % from 100 on), none withheld."""
    def maxima(n):
        sol = ProfiledRoller(5e-3, 14e-3, 115.385e9, "end-relief:r=50mm,l=2.1mm",
                             n_slices=n).at_force(line_load * 14e-3)
        s = roller_stresses(sol)
        assert not sol.edge_loaded and s.withheld == {}
        return [s.worst[m]["value"] for m in MEASURES]

    ref = maxima(400)
    for n in (50, 100, 200):
        assert maxima(n) == pytest.approx(ref, rel=5e-3), n


def test_bearing_case_check_of_an_edge_loaded_roller_is_said_once(capsys):
    """The case check asked of a bearing whose most loaded roller is edge loaded is
    not reported, and its note says so in plain words, once ('case check, case check
    not reported' came from prefixing the calculator's own 'case check' text)."""
    hard = ["--surface-hardness", "700", "--case-depth", "0.5mm", "--core-hardness", "350"]
    assert main(BEARING + ["--n-slices", "20"] + hard + ["--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    assert row["case_ratio"] is None
    assert "case check not reported: inner contact: edge loaded" in row["note"]
    assert "case check, case check" not in row["note"]
