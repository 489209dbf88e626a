"""Input rules at every door (issue 36): what the calculator does with inputs that a
bearing or the library treats otherwise is the same, or said in the row's note; never
a refusal in a Python keyword, never a silent default of its own."""

from __future__ import annotations

import contextlib
import io
import json
import math

import numpy as np

import pytest

from linecontact.calc.cli import main

RACEWAYS = ["--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson",
            "0.3", "--load", "1kN", "--inner-raceway-diameter", "40mm",
            "--outer-raceway-diameter", "60mm"]


def _json(argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["calc", *argv, "--json"]) in (0, None)
    return json.loads(out.getvalue())


@pytest.mark.parametrize("extra,tilt,note", [
    (["--misalignment", "1mrad"], 0.0, "coupled slices"),     # straight, misaligned
    (["--crown-radius", "1m"], "free", "tilt is free"),      # crowned, no --tilt
    (["--crown-radius", "1m", "--misalignment", "1mrad"], "free", "tilt is free"),
    (["--crown-radius", "1m", "--tilt", "0"], 0.0, None),    # held where asked
])
def test_a_roller_between_raceways_is_solved_as_the_bearing_and_the_library_solve_it(
        extra, tilt, note):
    """Between raceways the calculator takes the bearing's defaults: a straight roller
    between misaligned rings is solved by coupled slices (not refused with
    "use model='profiled-roller'"), a profiled roller tilts freely unless --tilt is
    given; each row's note says so. The roller deflection equals the library's
    Contact with the same parts (same solver: equal to 1e-12)."""
    from linecontact.contact import Contact, Roller
    from linecontact.raceway import Raceways

    doc = _json(RACEWAYS + extra)
    first = doc["models"][0]
    row = first["rows"][0]
    assert first["key"] == "profiled-roller" and row["roller_deflection"] is not None, row
    said = f"{row['flags']}; {row['note']}"  # the table's note column: both
    assert "model=" not in said
    if note is None:
        assert "free" not in said
    else:
        assert note in said, said
    psi = 1e-3 if "--misalignment" in extra else 0.0
    crown = {"crown_radius": 1.0} if "--crown-radius" in extra else {}
    c = Contact(Roller(5e-3, 10e-3, tilt=tilt, **crown),
                counterbody=Raceways(20e-3, 30e-3, misalignment=psi),
                estar=210e9 / (1 - 0.3**2), model="profiled-roller")
    expected = float(c.normal(force=1e3).get("depth"))
    assert row["roller_deflection"] == pytest.approx(expected, rel=1e-12)


SOFT = ["--radius", "5mm", "--length", "10mm", "--modulus", "3MPa", "--poisson", "0.45",
        "--load", "0.1N", "--model", "universal"]
STEEL = ["--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson", "0.3",
         "--load", "1kN", "--model", "universal"]

#: Inputs that a part of the result does not use: each row must say so (the option as
#: typed, and what was computed instead), never drop it silently.
UNUSED = [
    (STEEL + ["--friction", "0.3", "--stresses", "yes"], "the stresses are frictionless"),
    (SOFT + ["--work-of-adhesion", "50mJ/m2", "--friction", "0.3"],
     "--friction: computed without adhesion"),
    (SOFT + ["--work-of-adhesion", "50mJ/m2", "--stresses", "yes"],
     "--stresses: computed without adhesion"),
]


@pytest.mark.parametrize("argv,said", UNUSED)
def test_an_input_a_result_does_not_use_is_said_in_the_row(argv, said):
    """--friction is the partial-slip coefficient, not the stresses' sliding friction
    (which is --sliding-friction: not applied, as a stick zone is not full sliding);
    friction and stresses are computed without adhesion. The row's note names the option
    as typed."""
    row = _json(argv)["models"][0]["rows"][0]
    assert said in f"{row['flags']}; {row['note']}", row


def test_sliding_friction_given_needs_no_such_note():
    """With --sliding-friction the stresses use it: no note."""
    row = _json(STEEL + ["--friction", "0.3", "--stresses", "yes", "--sliding-friction",
                         "0.1"])["models"][0]["rows"][0]
    assert "frictionless" not in f"{row['flags']}; {row['note']}"


ONE_CASE = {"calc": ["calc", "--radius", "5mm", "--length", "10mm", "--estar", "115GPa",
                     "--load", "1kN"],
            "bearing": ["bearing", "--rollers", "14", "--pitch-diameter", "70mm",
                        "--roller-diameter", "11mm", "--length", "11mm", "--radial-load",
                        "10kN"]}


@pytest.mark.parametrize("command", sorted(ONE_CASE))
@pytest.mark.parametrize("plot,output", [("same.png", "same.png"),
                                         ("same.png", "./same.png")])
def test_plot_and_output_naming_one_file_is_refused_before_anything_is_written(
        command, plot, output, tmp_path, monkeypatch, capsys):
    """-o and --plot naming one file: status 2, one line naming both, no file written
    (the figure overwrote the table, exit 0)."""
    monkeypatch.chdir(tmp_path)
    status = main(ONE_CASE[command] + ["--plot", plot, "-o", output])
    err = capsys.readouterr().err
    assert status == 2 and "--plot" in err and "-o" in err and len(err.splitlines()) == 1
    assert not any(tmp_path.iterdir())


#: Impossible geometry at the calculator's door: (options, the option named, the
#: valid range's words). Each is refused in one line by the library's own check.
IMPOSSIBLE = [
    (STEEL[:-2] + ["--stresses", "yes", "--surface-hardness", "700", "--case-depth",
                   "6mm", "--core-hardness", "350"], "--case-depth", "roller's radius"),
    # not geometry, but an input that did nothing: the field is JSON output only
    (STEEL + ["--stresses", "yes", "--stress-field", "0mm"], "--stress-field",
     "with --json"),
]


@pytest.mark.parametrize("argv,option,valid", IMPOSSIBLE)
def test_impossible_geometry_is_refused_naming_the_option_and_the_range(argv, option,
                                                                        valid, capsys):
    """Status 2, one line: the option as typed, the reason and the valid range."""
    status = main(["calc", *argv])
    err = capsys.readouterr().err
    assert status == 2 and len(err.splitlines()) == 1, err
    assert err.split(": error: ")[1].startswith(option) and valid in err.split("valid:")[1]


def test_a_case_deeper_than_the_roller_radius_is_refused_by_the_library():
    """HardnessProfile.check_fits: CHD < R passes, CHD >= R is refused (a case past
    the axis leaves no core)."""
    from linecontact.errors import OutOfRangeError
    from linecontact.stresses import HardnessProfile

    HardnessProfile(700.0, 4.9e-3, 350.0).check_fits(5e-3)
    for chd in (5e-3, 6e-3):
        with pytest.raises(OutOfRangeError, match="case_depth"):
            HardnessProfile(700.0, chd, 350.0).check_fits(5e-3)


# ---- the library's geometry and counts (RadialRollerBearing, the ratings) ----

@pytest.mark.parametrize("dm,D", [(65e-3, 11e-3), (70e-3, 11e-3), (200e-3, 10e-3),
                                  (23e-3, 10e-3), (1.0, 1e-3)])
def test_max_rollers_is_the_last_count_whose_neighbours_do_not_overlap(dm, D):
    """Z rollers of diameter D fit on the pitch circle d_m iff neighbouring centres, a
    chord d_m sin(pi/Z) apart, are more than D apart: max_rollers is that Z exactly
    (checked against every Z from 3)."""
    from linecontact.bearing import max_rollers

    fits = [z for z in range(3, 5000) if dm * math.sin(math.pi / z) > D]
    assert max_rollers(dm, D) == max(fits)


#: Library calls that must be refused in one line naming the parameter and its range.
REFUSED = [
    (lambda B: B(40, 65e-3, 11e-3, 12e-3), "rollers", "[3, 18]"),
    (lambda B: B(19, 65e-3, 11e-3, 12e-3), "rollers", "[3, 18]"),
    (lambda B: B(14, 65e-3, 11e-3, 12e-3, profile="iso16281", n_slices=40.7),
     "n_slices", "an integer"),
    (lambda B: B(14, 65e-3, 11e-3, 12e-3, profile="iso16281", n_slices=1000),
     "n_slices", "[10, 200]"),
    (lambda B: B(14, 65e-3, 11e-3, 12e-3, clearance=-5e-3).solve(10e3), "clearance",
     "at F_r"),
    (lambda B: B(14, 65e-3, 11e-3, 12e-3, clearance=-5e-3, profile="iso16281")
     .solve(10e3), "clearance", "at F_r"),
]


@pytest.mark.parametrize("call,parameter,valid", REFUSED)
def test_the_bearing_refuses_impossible_geometry_and_counts(call, parameter, valid):
    """Overlapping rollers (40 of 11 mm on 65 mm computed a rating and a life), a
    fractional or a too large slice count (truncated; 1000 ran past 5 min), a preload
    pressing the rollers beyond the law's range (reported as an internal 'roller
    approach'): refused naming the parameter the user gave, its value and range."""
    from linecontact.bearing import RadialRollerBearing
    from linecontact.errors import OutOfRangeError

    with pytest.raises(OutOfRangeError) as info:
        call(RadialRollerBearing)
    assert info.value.parameter == parameter and valid in str(info.value), info.value
    assert "\n" not in str(info.value)


def test_the_ratings_refuse_overlapping_rollers():
    """ISO 281's rating of an impossible bearing is refused, not computed."""
    from linecontact.bearing import dynamic_load_rating
    from linecontact.errors import OutOfRangeError

    with pytest.raises(OutOfRangeError, match="overlap"):
        dynamic_load_rating(40, 65e-3, 11e-3, 12e-3)


def test_solve_takes_an_array_of_loads():
    """docs/inputs.md: functions of a force take arrays. solve(array) is an object
    array of solutions, each the scalar call's (identical numbers)."""
    from linecontact.bearing import RadialRollerBearing

    b = RadialRollerBearing(14, 65e-3, 11e-3, 12e-3)
    loads = np.array([[1e3, 2e3], [5e3, 1e4]])
    out = b.solve(loads)
    assert out.shape == loads.shape and out.dtype == object
    for idx, F in np.ndenumerate(loads):
        one = b.solve(float(F))
        assert out[idx].max_roller_load == one.max_roller_load
        assert out[idx].displacement == one.displacement


#: The bearing command's refusals in the user's words: (options, the option named
#: first, words of the reason, words of the valid range).
BEARING_WORDS = [
    (["--rollers", "0"], "--rollers = '0'", "out of range", "an integer, 3 <= rollers"),
    (["--rollers", "40.5"], "--rollers = '40.5'", "not an integer", "an integer"),
    (["--rollers", "40"], "--rollers = '40'", "40 rollers overlap", "[3, 18]"),
    (["--rollers", "14", "--clearance", "-5mm"], "--clearance = '-5mm'", "preload",
     "at F_r"),
    (["--rollers", "14", "--n-slices", "40.5", "--profile", "iso16281"],
     "--n-slices = '40.5'", "not an integer", "10 <= n_slices <= 200"),
    (["--rollers", "14", "--n-slices", "1000", "--profile", "iso16281"],
     "--n-slices = '1000'", "out of range", "10 <= n_slices <= 200"),
    (["--rollers", "14", "--surface-hardness", "700", "--case-depth", "6mm",
      "--core-hardness", "350"], "--case-depth = '6mm'", "no core", "roller's radius"),
]


@pytest.mark.parametrize("extra,head,reason,valid", BEARING_WORDS)
def test_the_bearing_command_refuses_in_the_users_words(extra, head, reason, valid, capsys):
    """One line: the option as typed (never the library's 'roller approach' or a
    message about 'a number > 0 (e.g. 0.3)' for a count), the reason, the range."""
    status = main(["bearing", "--pitch-diameter", "65mm", "--roller-diameter", "11mm",
                   "--length", "12mm", "--radial-load", "10kN", *extra])
    err = capsys.readouterr().err
    assert status == 2 and len(err.splitlines()) == 1, err
    message = err.split(": error: ")[1]
    assert message.startswith(head) and reason in message.split("; valid:")[0], err
    assert valid in message.split("; valid:")[1], err


@pytest.mark.parametrize("si", [False, True])
def test_an_aligned_bearing_prints_round_off_as_zero_and_si_headers(si, capsys):
    """K_rt, K_tr, M and theta of an aligned bearing are round-off (1e-14 N/mrad): shown
    as 0 against their scale (sqrt(K_rr K_tt), F_r L, delta_r/L); with --si the first
    line is in SI too (no mm)."""
    status = main(ONE_CASE["bearing"] + ["--tilting-moment", "0"] + (["--si"] if si else []))
    out = capsys.readouterr().out.splitlines()
    assert status == 0
    assert ("mm" not in out[0]) if si else ("mm" in out[0])
    for line in out:
        if line.strip().startswith(("K_rt", "K_tr", "moment M", "ring tilt")):
            assert " 0  " in line, line  # the value column, then the unit
