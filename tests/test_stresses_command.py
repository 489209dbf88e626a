"""`linecontact calc --stresses`: the calculator shows the library's stresses (no
physics of its own) and refuses bad input in one line."""
from __future__ import annotations

import json

import pytest

from linecontact.stresses import HardnessProfile, case_check, line_contact_stresses

BASE = ["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
        "--poisson", "0.3", "--load", "4kN"]


def _main(capsys, *argv):
    from linecontact.calc.cli import main
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_model_rows_carry_the_library_maxima(capsys):
    """Each model row's stress columns are line_contact_stresses at its force, and the
    check is case_check with the given hardness (same numbers, SI in JSON)."""
    status, out, err = _main(capsys, *BASE, "--stresses", "yes", "--surface-hardness",
                             "700", "--case-depth", "0.3mm", "--core-hardness", "350",
                             "--json")
    assert status == 0, err
    doc = json.loads(out)
    row = doc["models"][0]["rows"][0]
    estar = doc["inputs"]["estar"]
    s = line_contact_stresses(row["force"], 5e-3, 10e-3, estar)
    assert row["tresca_max"] == pytest.approx(s.worst["tresca"]["value"], rel=1e-12)
    assert row["von_mises_depth"] == pytest.approx(s.worst["von_mises"]["z"], rel=1e-12)
    c = case_check(s, HardnessProfile(700.0, 0.3e-3, 350.0))
    assert row["case_ratio"] == pytest.approx(c.max_ratio, rel=1e-12)
    assert "stresses" not in doc   # a plain line contact: uniform along the axis


def test_profiled_roller_section_field(capsys):
    """With a profile and --stress-field the JSON holds the worst along the roller and
    the section field at that x (a symmetric crown: the worst at a slice next to the
    centre, within half the widest slice's pitch of x = 0; an even slice count puts
    no slice at x = 0 itself)."""
    status, out, err = _main(capsys, *BASE, "--crown-radius", "500mm", "--stresses",
                             "yes", "--stress-field", "0mm", "--json")
    assert status == 0, err
    doc = json.loads(out)
    row = doc["stresses"][0]["rows"][0]
    from linecontact.roller.slices import DEFAULT_N_SLICES
    pitch = max(b - a for a, b in zip(row["x"], row["x"][1:]))
    assert len(row["x"]) == DEFAULT_N_SLICES
    assert abs(row["worst"]["tresca"]["x"]) <= 0.51 * pitch, (row["worst"], pitch)
    model_row = doc["models"][0]["rows"][0]
    assert model_row["tresca_max"] == pytest.approx(row["worst"]["tresca"]["value"],
                                                    rel=1e-12)
    sec = row["section"]
    assert len(sec["tresca"]) == len(sec["y"]) and len(sec["tresca"][0]) == len(sec["z"])
    assert max(max(r) for r in sec["tresca"]) <= row["worst"]["tresca"]["value"] * (1 + 1e-9)


def test_stress_note_checks_the_measured_range(capsys):
    """A profiled roller of L/(2R) = 15, beyond the stress table's measured 0.5-12: the
    row's note says its stresses lie outside the measured range, in the user's terms
    (the length and the contact's effective radius), not the measured errors as if
    inside (the calc passes the row's roller to the range check)."""
    base = [a if a != "10mm" else "150mm" for a in BASE]
    status, out, err = _main(capsys, *base, "--crown-radius", "500mm", "--stresses",
                             "yes", "--json")
    assert status == 0, err
    note = json.loads(out)["models"][0]["rows"][0]["flags"]
    assert "L/(2R) = 15 (roller length L = 150 mm, the contact's effective radius R = " \
           "5 mm: the roller's L/D on a flat) (measured 0.5-12): outside the range where " \
           "the 3D-corrected stresses were measured" in note, note


@pytest.mark.parametrize("extra,word", [
    (["--stresses", "yes", "--sliding-friction", "-0.1"], "sliding-friction"),
    (["--stresses", "yes", "--surface-hardness", "500", "--case-depth", "0.3mm",
      "--core-hardness", "600"], "hardness"),
    (["--stresses", "maybe"], "stresses"),
    (["--case-depth", "1mm"], "case-depth"),
])
def test_bad_input_one_line(capsys, extra, word):
    """Negative friction, a core harder than the surface, a bad flag, a hardness
    option without --stresses: status 2 and one line naming the option."""
    status, out, err = _main(capsys, *BASE, *extra)
    assert status == 2
    lines = [ln for ln in err.strip().splitlines() if ln]
    assert len(lines) == 1 and word in lines[0], err


def test_stresses_no_prints_no_stress_note(capsys):
    """`--stresses no` turns the feature off on every row, so the table carries neither
    its columns nor its note (a note under a table describes what the table shows);
    `--stresses yes` prints the note once."""
    status, out, _ = _main(capsys, *BASE, "--stresses", "no")
    assert status == 0 and "Note: stresses" not in out
    status, out, _ = _main(capsys, *BASE, "--stresses", "yes")
    assert status == 0 and out.count("Note: stresses") == 1


def test_stress_field_is_never_dropped_without_a_word(capsys, tmp_path):
    """--stress-field is the section field of a contact solved by slices, in the JSON
    of one case or a sweep. Asked of a straight roller under a law, the JSON says in
    the row's place that it has none (it was left out without a word); with a CSV
    batch, which has no place for it, and --linear, which a batch has no sweep for,
    the command is refused before anything is written."""
    from linecontact.calc.cli import main

    case = ["calc", "--radius", "5mm", "--length", "10mm", "--estar", "115GPa"]
    assert main(case + ["--load", "1kN", "--stresses", "yes", "--stress-field", "0mm",
                        "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert "no section field" in doc["stresses"][0]["rows"][0]["section"]["note"]
    src = tmp_path / "c.csv"
    src.write_text("load\n1kN\n", encoding="utf-8")
    for extra in (["--stresses", "yes", "--stress-field", "0mm"], ["--linear"]):
        assert main(case + [str(src), "-o", str(tmp_path / "o.csv")] + extra) == 2
        assert extra[-1 if extra == ["--linear"] else -2] in capsys.readouterr().err
        assert not (tmp_path / "o.csv").exists()
