"""No input silently ignored (issue 22): the calculator's rules for command-line options
against CSV cells, CSV headers and rows, output files, messages and uncovered output.

Each test holds one rule over a class of inputs (generated where the class is large):
- a command-line option fills the EMPTY cells of its column; a filled cell that says
  something else is an error in that row (the cell and the option named);
- a column that looks like an input but would not be read (a unit in the header, a
  close spelling) refuses the file naming its match; a row with more cells than the
  header is an error in that row; a semicolon-separated file is refused with that hint;
- ``-o`` naming an input file is refused and the input left intact; every output file
  is written whole or not at all (a temporary file renamed at the end).
"""
from __future__ import annotations

import contextlib
import csv
import io
import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from linecontact.calc import render
from linecontact.calc.cli import main

from doors import DOORS, IDS

HEADER = "radius,length,modulus,poisson,load"
ROW = "5mm,10mm,210GPa,0.3,{load}"


def _calc(argv, command="calc"):
    """(status, stdout, stderr) of ``linecontact COMMAND ARGV`` run in this process."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main([command, *argv])
    return status, out.getvalue(), err.getvalue()


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@settings(max_examples=25, deadline=None)
@given(cell=st.sampled_from(["1kN", "1000", "1000 N", "2kN", "2000", "0.5kN", "", "3kN"]),
       option=st.sampled_from(["1kN", "1000", "2kN", "2000N"]))
@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_an_option_and_a_filled_cell_that_differ_are_refused_in_that_row(
        tmp_path_factory, door, cell, option):
    """--load (a bearing's --radial-load) fills an empty cell; a filled cell equal to
    it in SI (1kN = 1000) is computed at that load; one that differs is an error in
    its row naming the cell and the option, never silently computed with one of the
    two."""
    path = tmp_path_factory.mktemp("conflict") / "bom.csv"
    path.write_text(door.header + "\n" + door.row.format(load=cell) + "\n")
    status, out, err = _calc([str(path), door.load_option, option], door.name)
    row = _rows(out)[0]
    si = {"1kN": 1e3, "1000": 1e3, "1000 N": 1e3, "2kN": 2e3, "2000": 2e3, "2000N": 2e3,
          "0.5kN": 500.0, "3kN": 3e3}
    if cell == "" or si[cell] == si[option]:
        assert status == 0 and row["error"] == ""
        # calc prints the force; a bearing's through its 6-digit C_r and L10
        assert door.load_of(row) == pytest.approx(si[option], rel=1e-12 if
                                                  door.name == "calc" else 2e-5)
    else:
        assert status == 2 and row[door.result] == ""
        assert f"conflicts with {door.load_option}" in row["error"]
        assert repr(cell) in row["error"]


#: Header forms that say a parameter with a unit: each is not read as the parameter.
_UNIT_FORMS = ("{} [mm]", "{} (GPa)", "{}_kN", "{} in mm")


def _header_table():
    """The CSV-header boundary as a table, one row per (door, refused column): every
    parameter of every door in every unit form, and each door's close spellings. Each
    row: (door, parameter, refused header, the file's text, the words the message
    must hold)."""
    rows = []
    for door in DOORS:
        for name in door.parameters:
            for form in _UNIT_FORMS:
                header = form.format(name)
                rows.append((door, name, header, f"{header},other\n5,x\n",
                             f"did you mean {name!r}"))
        cols = door.header.split(",")
        for typo, name in door.typos:
            if name in cols:
                header = ",".join(typo if c == name else c for c in cols)
                text = header + "\n" + door.row.format(load="1kN") + "\n"
            else:
                text = (door.header + f",{typo}\n" + door.row.format(load="1kN")
                        + ",1\n")
            rows.append((door, name, typo, text, f"did you mean {name!r}"))
    return rows


HEADER_TABLE = _header_table()


def test_every_column_that_looks_like_an_input_but_is_not_read_is_refused(tmp_path):
    """The CSV-header boundary, one table: every parameter's name written with a unit
    ('radius [mm]', 'modulus (GPa)', 'load_kN', 'length in mm') and every close
    spelling of a parameter (difflib ratio >= 0.75: 'raduis', 'radial_lode') is not
    silently a user column: the file is refused (status 2) and the message names the
    parameter it matches. Every door's every parameter is a row."""
    path = tmp_path / "header.csv"
    failed = []
    for door, _, header, text, words in HEADER_TABLE:
        path.write_text(text)
        status, out, err = _calc([str(path)], door.name)
        if not (status == 2 and words in err):
            failed.append((door.name, header, status, err))
    assert not failed, failed


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_a_rerun_on_its_own_output_is_not_refused(tmp_path, door):
    """The result columns of an earlier run (force_kN, depth_um, ...) look like inputs
    with units but are the calculator's own: a rerun on its output is accepted."""
    first = tmp_path / "first.csv"
    src = tmp_path / "in.csv"
    src.write_text(door.header + "\n" + door.row.format(load="1kN") + "\n")
    assert _calc([str(src), "-o", str(first)], door.name)[0] == 0
    status, out, err = _calc([str(first)], door.name)
    assert status == 0, err


@settings(max_examples=10, deadline=None)
@given(st.integers(1, 4))
@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_a_row_with_more_cells_than_the_header_is_an_error_in_that_row(
        tmp_path_factory, door, extra):
    """A row with more cells than the header (a decimal comma, a missing header name)
    is an error in that row, whatever else it holds (never shifted under the wrong
    headers); the other rows are computed."""
    path = tmp_path_factory.mktemp("wide") / "wide.csv"
    wide = door.row.format(load="1kN") + ",1" * extra
    path.write_text(door.header + "\n" + door.row.format(load="1kN") + "\n" + wide
                    + "\n")
    status, out, err = _calc([str(path)], door.name)
    rows = _rows(out)
    assert status == 2 and rows[0]["error"] == "" and float(rows[0][door.result]) > 0
    assert f"{5 + extra} cells under a header of 5 columns" in rows[1]["error"]
    assert rows[1][door.result] == ""


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_a_semicolon_separated_file_is_refused_with_that_hint(tmp_path, door):
    """A file separated by semicolons (a European spreadsheet export) is one column
    to a CSV reader: refused, saying semicolons, not 'no case columns'."""
    path = tmp_path / "semi.csv"
    path.write_text(door.header.replace(",", ";") + "\n" + door.row.format(
        load="1kN").replace(",", ";") + "\n")
    status, out, err = _calc([str(path)], door.name)
    assert status == 2 and "semicolons" in err and "comma-separated" in err


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_a_column_given_twice_is_refused(tmp_path, door):
    """A column given twice would leave one of them silently unread: the file is
    refused naming it."""
    path = tmp_path / "twice.csv"
    first = door.header.split(",")[0]
    path.write_text(door.header + f",{first}\n" + door.row.format(load="1kN")
                    + ",7\n")
    status, out, err = _calc([str(path)], door.name)
    assert status == 2 and out == "" and f"column {first!r} appears twice" in err


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_linear_with_a_batch_is_refused_as_a_conflict(tmp_path, door):
    """--linear spaces a sweep's values; a CSV batch has one value per row, so with a
    CSV it would do nothing: refused up front by the shared batch loop, for every
    command, one line naming the conflict, status 2, nothing written."""
    path = tmp_path / "in.csv"
    path.write_text(door.header + "\n" + door.row.format(load="1kN") + "\n")
    status, out, err = _calc([str(path), "--linear"], door.name)
    assert status == 2 and out == "" and len(err.splitlines()) == 1, err
    assert "--linear" in err and "CSV batch" in err


@pytest.mark.parametrize("how", ["option", "column"])
def test_a_json_only_input_in_a_batch_without_json_is_refused_once(tmp_path, how):
    """--stress-field writes a block of the --json output only: a CSV batch without
    --json (the option, or a filled cell of its column) is refused once up front, as
    the one case is (one line naming the input and 'with --json', status 2, nothing
    written); with --json too, as the batch's JSON has no place for it. The rule is the parameter's declaration
    (Parameter.json_only), the same for every door."""
    case = "radius,length,estar,load,profile,stresses"
    cells = "5mm,10mm,115GPa,1kN,iso16281,yes"
    path = tmp_path / "in.csv"
    if how == "column":
        path.write_text(case + ",stress_field\n" + cells + ",\n" + cells + ",0mm\n")
        extra = []
    else:
        path.write_text(case + "\n" + cells + "\n")
        extra = ["--stress-field", "0mm"]
    status, out, err = _calc([str(path), *extra])
    assert status == 2 and out == "" and len(err.splitlines()) == 1, err
    named = "--stress-field" if how == "option" else "column 'stress_field'"
    assert err.split(": error: ")[1].startswith(named) and "with --json" in err
    # with --json too: the batch's JSON has one flat row per case and no blocks, so
    # the field would be computed and written nowhere (it ran with status 0)
    status, out, err = _calc([str(path), *extra, "--json"])
    assert status == 2 and out == "" and len(err.splitlines()) == 1, err
    assert err.split(": error: ")[1].startswith(named) and "no blocks" in err


@pytest.mark.parametrize("spelled", ["same", "dot", "absolute"])
@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_output_naming_the_input_file_is_refused_and_the_input_kept(
        tmp_path, monkeypatch, door, spelled):
    """-o naming the input CSV, however spelled (the same path, ./x/../FILE, absolute),
    is refused before anything is written: the input is byte for byte unchanged."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "x").mkdir()
    path = tmp_path / "bom.csv"
    text = door.header + "\n" + door.row.format(load="1kN") + "\n"
    path.write_text(text)
    out = {"same": "bom.csv", "dot": "./x/../bom.csv", "absolute": str(path)}[spelled]
    status, _, err = _calc(["bom.csv", "-o", out], door.name)
    assert status == 2 and "input file" in err
    assert path.read_text() == text


def test_output_naming_the_prony_file_is_refused(tmp_path):
    """Any input file counts, not only the batch: -o naming the --prony file."""
    prony = tmp_path / "p.csv"
    prony.write_text("# E_inf: 1e9\ntau_s,E_Pa\n0.1,2e9\n")
    before = prony.read_text()
    status, _, err = _calc(["--radius", "5mm", "--length", "10mm", "--poisson", "0.3",
                            "--prony", str(prony), "--load", "1kN", "--time", "1s",
                            "-o", str(prony)])
    assert status == 2 and "input file" in err and prony.read_text() == before


def test_an_output_file_is_written_whole_or_not_at_all(tmp_path, monkeypatch):
    """The output is written to a temporary file renamed at the end: when the write
    fails midway, the previous file is intact and no partial or temporary file is
    left in the folder."""
    target = tmp_path / "out.csv"
    target.write_text("previous\n")

    class Boom(OSError):
        pass

    real_fdopen = os.fdopen

    def failing_fdopen(fd, *a, **k):
        fh = real_fdopen(fd, *a, **k)

        class Half:
            def __enter__(self):
                return self

            def __exit__(self, *exc):
                fh.close()

            def write(self, text):
                fh.write(text[: len(text) // 2])
                raise Boom("disk full")

        return Half()

    monkeypatch.setattr(os, "fdopen", failing_fdopen)
    with pytest.raises(render.OutputError, match="disk full"):
        render.write("a,b\n1,2\n" * 100, str(target))
    monkeypatch.undo()
    assert target.read_text() == "previous\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
    render.write("new\n", str(target))
    assert target.read_text() == "new\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]


@settings(max_examples=8, deadline=None)
@given(st.lists(st.tuples(st.integers(-5, 30), st.integers(-3, 9)), min_size=1,
                max_size=12))
def test_no_derived_value_is_printed_where_no_model_covers_the_row(tmp_path_factory,
                                                                   cases):
    """Output no model covers is not a number: in every model's columns the Hertz
    half-width and peak pressure (and the MDR contact radius) are shown exactly where
    the model computed the depth, for radii 1e-5..1e30 m and loads 1e-3..1e9 N (a
    radius of 1e30 m printed b = 1e18 um, p0 = 6e-14 MPa beside a refused depth)."""
    path = tmp_path_factory.mktemp("uncovered") / "c.csv"
    path.write_text("radius,load\n" + "".join(f"1e{r},1e{f}\n" for r, f in cases))
    status, out, err = _calc([str(path), "--length", "10mm", "--modulus", "210GPa",
                              "--poisson", "0.3", "--model", "all", "--si"])
    rows = _rows(out)
    depth_cols = [c for c in rows[0] if c.startswith("depth_m")]
    assert depth_cols
    for row in rows:
        for col in depth_cols:
            suffix = col[len("depth_m"):]
            for derived in ("half_width_m", "peak_pressure_Pa", "contact_radius_m"):
                if derived + suffix in row:
                    assert (row[derived + suffix] == "") == (row[col] == ""), (
                        derived + suffix, row)


@settings(max_examples=15, deadline=None)
@given(st.sampled_from(["load", "depth"]), st.integers(9, 12),
       st.sampled_from(["", " N", "kN"]))
def test_a_refused_row_names_the_option_as_typed_never_internal_wording(which, e, unit):
    """A load or depth outside a model's range is reported with the option the user
    wrote and the value as typed (--load = '1e9kN'), the cylinder it was refused for
    (R, L, E*: the geometry decides the range), and never the library's internal
    wording ('force = ... (element [0] of shape (1,))')."""
    unit = {"load": unit, "depth": {"": "", " N": " m", "kN": "mm"}[unit]}[which]
    typed = f"1e{e}{unit}"
    status, out, err = _calc(["--radius", "5mm", "--length", "10mm", "--modulus",
                              "210GPa", "--poisson", "0.3", f"--{which}", typed,
                              "--model", "li-popov"])
    text = out + err
    assert f"--{which} = {typed!r}" in text and "for R = 0.005 m" in text, text
    assert "element [" not in text and "of shape" not in text


PLAUSIBLE = [("radius", "5"), ("length", "10"), ("modulus", "210"), ("modulus", "70"),
             ("load", "1e9")]


@pytest.mark.parametrize("name,bare", PLAUSIBLE)
def test_an_implausible_bare_number_is_named_as_the_likely_cause(name, bare):
    """A bare number is SI (--modulus 210 is 210 Pa, --radius 5 is 5 m): not refused,
    but when the case then fails the message names it as the likely cause with the
    unit that makes it plausible; the same value typed with a unit is the user's
    choice and is not blamed."""
    base = {"radius": "5mm", "length": "10mm", "modulus": "210GPa", "poisson": "0.3",
            "load": "1kN"}
    argv = [a for k, v in {**base, name: bare}.items() for a in (f"--{k}", v)]
    status, out, err = _calc(argv + ["--model", "li-popov"])
    text = out + err
    assert status == 2 and f"likely cause: --{name} = {bare!r}" in text, text
    # the suggested unit, when there is one, makes the value plausible
    from linecontact._units import parse_quantity
    from linecontact.calc.cases import BY_NAME

    p = BY_NAME[name]
    tail = text.split(f"likely cause: --{name} = {bare!r}")[1].split("\n")[0]
    if tail.endswith("?"):
        suggested = tail.rsplit(": ", 1)[1][:-1]
        lo, hi = p.plausible
        assert lo <= parse_quantity("x", suggested, p.kind) <= hi, suggested
    # with the unit spelled out (the same SI value) the user chose it: no blame
    si = {"radius": "m", "length": "m", "modulus": "Pa", "load": "N"}[name]
    argv = [a for k, v in {**base, name: bare + si}.items() for a in (f"--{k}", v)]
    status, out, err = _calc(argv + ["--model", "li-popov"])
    assert "likely cause" not in out + err


# ---- the JSON header's model keys; the raceway contacts' geometry flags --------------

@pytest.mark.parametrize("extra", [
    [],                                              # plain contacts, L/R out of range
    ["--profile", "circular:Rc=0.5"],                # composed contacts, refused laws
    ["--inner-raceway", "20mm", "--outer-raceway", "30mm"],
])
def test_every_json_model_key_is_a_registry_key(extra):
    """models[].key of the JSON header is the model's registry key (what get_model
    takes), also for a model refused for the whole contact; the text as typed or the
    label is in models[].label."""
    import json

    from linecontact.models import available_models

    status, out, err = _calc(["--radius", "5mm", "--length", "200mm", "--estar", "115GPa",
                              "--load", "1kN", "--model", "johnson:c=0.7,li-popov",
                              "--json", *extra])
    if not out:
        pytest.skip(f"the combination is refused as a whole: {err}")
    doc = json.loads(out)
    keys = [m["key"] for m in doc["models"]]
    assert keys and all(k in available_models() for k in keys), keys
    assert all(m["label"] for m in doc["models"])


@settings(max_examples=10, deadline=None)
@given(load=st.floats(1e2, 1e6), length_mm=st.sampled_from([1.0, 3.0, 10.0]))
def test_raceway_contacts_carry_the_geometry_flags(tmp_path_factory, load, length_mm):
    """Each contact of a roller between raceways is flagged as a plain contact's row is:
    d > 0.15 R (R its effective radius) and b > L/2 (b the Hertz half-width of its strip,
    Li & Popov 2017 Eq. 1), named inner or outer; and only then."""
    import json
    import math

    from linecontact.classical import hertz_half_width
    from linecontact.raceway import Raceways

    estar = 1e9
    status, out, err = _calc(["--radius", "5mm", "--length", f"{length_mm}mm",
                              "--estar", "1GPa", "--load", f"{load!r}",
                              "--inner-raceway", "20mm", "--outer-raceway", "30mm",
                              "--model", "johnson", "--json", "--si"])
    doc = json.loads(out)
    row = doc["models"][0]["rows"][0]
    if row.get("depth_inner") is None:
        return  # refused by the law: nothing to flag
    L = length_mm * 1e-3
    radii = dict(zip(("inner", "outer"), Raceways(20e-3, 30e-3).effective_radii(5e-3)))
    for side, R in radii.items():
        d = row[f"depth_{side}"]
        b = float(hertz_half_width(load, R, L, estar))
        assert (f"d > 0.15 R ({side})" in row["flags"]) == (d / R > 0.15), row["flags"]
        assert (f"b > 0.5 L ({side})" in row["flags"]) == (b / L > 0.5), row["flags"]
    assert math.isfinite(row["roller_deflection"])


_ROUND_TRIPS = [("calc", "radius,length,modulus,poisson,load,profile,part\n"
                "5mm,10mm,210GPa,0.3,1kN,,a\n"
                "5mm,10mm,210GPa,0.3,2kN,circular:Rc=0.5,b\n"
                "5mm,10mm,210GPa,0.3,-1kN,,c\n", flags)
               for flags in ([], ["--si"], ["--model", "johnson:c=0.72,universal"])]
_ROUND_TRIPS += [("bearing", "rollers,pitch_diameter,roller_diameter,length,radial_load,"
                  "profile,part\n"
                  "14,70mm,11mm,11mm,10kN,,a\n"
                  "14,70mm,11mm,11mm,5kN,circular:Rc=500mm,b\n"
                  "14,70mm,11mm,11mm,-1kN,,c\n", flags) for flags in ([], ["--si"])]


@pytest.mark.parametrize("command,text,flags", _ROUND_TRIPS,
                         ids=[f"{c}{''.join(f)}" for c, _, f in _ROUND_TRIPS])
def test_a_rerun_round_trip_gives_the_same_results_and_says_so(tmp_path, command, text,
                                                               flags):
    """calc in.csv -o out.csv; calc out.csv -o out2.csv (and the same with bearing):
    out2 holds out's columns exactly as they were, then this run's results under the
    prefix result_, cell for cell equal to out's results (the earlier results are not
    read as inputs: nothing changes), and stderr says in one line which columns are
    results of the earlier run."""
    src, out1, out2 = tmp_path / "in.csv", tmp_path / "out.csv", tmp_path / "out2.csv"
    src.write_text(text)
    s1, _, err1 = _calc([str(src), "-o", str(out1), *flags], command)
    s2, _, err2 = _calc([str(out1), "-o", str(out2), *flags], command)
    assert s1 == s2 and "note" not in err1
    notes = [ln for ln in err2.splitlines() if "results of an earlier run" in ln]
    assert len(notes) == 1 and "result_" in notes[0], err2
    first = list(csv.reader(io.StringIO(out1.read_text())))
    second = list(csv.reader(io.StringIO(out2.read_text())))
    n_in = 7
    width = len(first[0])
    assert [r[:width] for r in second] == first, "out.csv's columns written back as read"
    assert second[0][width:] == ["result_" + h for h in first[0][n_in:]]
    assert [r[width:] for r in second[1:]] == [r[n_in:] for r in first[1:]], \
        "the same results a second time"


def test_a_geometry_outside_the_table_is_named_in_the_row():
    """The command line's note for a roller too short for the universal table (L/R =
    0.002: the table ends at d/R = 30 (L/R)^2) names L/R and the covered range, beside
    the option as typed."""
    status, out, err = _calc(["--radius", "5mm", "--length", "0.01mm", "--estar", "115GPa",
                              "--load", "1kN", "--model", "universal"])
    assert "--load = '1kN'" in out and "L/R = 0.002" in out and "L/R >= 0.0707" in out, out


def _value_options():
    """(subcommand, option string) of every option that takes a value."""
    import argparse

    from linecontact.calc.cli import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    out = []
    for name, p in sub.choices.items():
        for a in p._actions:
            # (an option renamed, hidden from --help, is refused at once with its new
            # name: not an option that takes a value)
            if a.option_strings and a.nargs is None and a.help != argparse.SUPPRESS \
                    and not isinstance(a, (argparse._StoreTrueAction,
                                           argparse._StoreFalseAction,
                                           argparse._HelpAction)):
                out.append((name, a.option_strings[-1]))
    return out


VALUE_OPTIONS = _value_options()


def test_an_option_given_twice_is_refused_naming_both_values(capsys):
    """The command-line boundary for repeats, one table (every option that takes a
    value, of every subcommand): argparse keeps the last of two occurrences silently
    (`--load 1kN ... --load 2kN` computed 2 kN); each refuses a second occurrence on
    one line naming the option and both values (status 2)."""
    assert {c for c, _ in VALUE_OPTIONS} >= {d.name for d in DOORS}
    failed = []
    for command, option in VALUE_OPTIONS:
        try:
            status = main([command, option, "aa1", option, "bb2"])
        except SystemExit as exc:
            status = exc.code
        err = capsys.readouterr().err
        if not (status == 2 and f"{option} is given twice ('aa1' and 'bb2')" in err
                and err.count("\n") == 1):
            failed.append((command, option, status, err))
    assert not failed, failed


# ---- an audit over the options and CSV columns (the 138 inputs, as a class) ----

#: Values per kind of input: valid ones, units of another quantity or case, signs,
#: zero, inf, NaN, overflow, subnormal, words, sweeps.
_FUZZ_VALUES = {
    "length": ["5mm", "20mm", "0.2in", "1e-3", "-5mm", "0", "inf", "nan", "5MM", "5 kg",
               "abc", "", "1e400", "1e-320", "5mm:1mm:3"],
    "pressure": ["210GPa", "3GPa", "1e9", "-1GPa", "0", "inf", "nan", "210", "1kN"],
    "dimensionless": ["0.3", "0.5", "0.6", "-0.1", "0", "nan", "1", "0.2:0.4:3"],
    "force": ["1kN", "100N", "0", "-1kN", "nan", "inf", "1e9", "1mN", "5mm", "1kN:2kN:3"],
    "angle": ["0", "1mrad", "0.5", "free", "-1mrad", "nan", "5deg"],
    "text": ["circular:Rc=0.5", "iso16281", "cone", "circular", "circular:Rc=-1", "yes",
             "von_mises", "all", ""],
    "time": ["10s", "0", "-1s", "1h", "nan", "1:10:3"],
    "path": ["/nonexistent/x.csv", ""],
    "surface_energy": ["0.05", "-1", "0", "nan"],
}


def _audit(status, out, err, csv_out, inputs=()):
    """The audit's rules: a status of 0 or 2; stderr holds only the calculator's own
    one-line messages; no result cell says nan or inf (the input cells are written back
    as they were); a computed row without a force or depth has a note, a flag or an
    error saying why."""
    assert status in (0, 2), (status, err)
    for line in err.splitlines():
        assert line.startswith("linecontact calc:"), err
    if not csv_out or not out:
        assert "nan" not in out.lower().split(), out
        return
    for row in _rows(out):
        cells = {k: (v or "").strip() for k, v in row.items() if k and k not in inputs}
        assert not any(v.lower() in ("nan", "inf", "-inf") for v in cells.values()), row
        if cells.get("error"):
            continue
        has_value = any(v for k, v in cells.items()
                        if k.startswith(("depth_", "force_")) and not k.startswith(
                            ("depth_inner", "depth_outer", "depth_long")))
        said = any(v for k, v in cells.items() if k.startswith(("note", "flags")))
        assert has_value or said, row


@settings(max_examples=30, deadline=None)
@given(st.data())
def test_audit_of_random_options(data):
    """Random options (1-3 of every calculator input, with the values above) on a valid
    steel case, with --json, --si, --model: never a traceback, a status other than 0 or
    2, a stray stderr line or a nan printed."""
    from linecontact.calc.cases import PARAMETERS

    argv = ["--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson",
            "0.3"]
    argv += data.draw(st.sampled_from([["--load", "1kN"], ["--depth", "2um"]]))
    given_ = {"radius", "length", "modulus", "poisson", "load", "depth"}
    extra = data.draw(st.lists(st.sampled_from([p for p in PARAMETERS
                                                if p.name not in given_]),
                               min_size=1, max_size=3, unique_by=lambda p: p.name))
    for p in extra:
        argv += [option_name_of(p.name), data.draw(st.sampled_from(_FUZZ_VALUES[p.kind]))]
    argv += data.draw(st.sampled_from([[], ["--si"], ["--model", "all"],
                                       ["--model", "johnson,universal"]]))
    status, out, err = _calc(argv)
    _audit(status, out, err, csv_out=False)


def option_name_of(name):
    return "--" + name.replace("_", "-")


@settings(max_examples=20, deadline=None)
@given(st.data())
def test_audit_of_random_csv_columns(tmp_path_factory, data):
    """Random CSV batches (a steel case's columns plus 1-3 other input columns, 1-4 rows
    of random values): the same rules, and every row of the output either computed,
    said (note, flags) or refused in its error cell."""
    from linecontact.calc.cases import PARAMETERS

    byname = {p.name: p for p in PARAMETERS}
    base = {"radius": "5mm", "length": "10mm", "modulus": "210GPa", "poisson": "0.3",
            "load": "1kN", "depth": "2um"}
    cols = ["radius", "length", "modulus", "poisson",
            data.draw(st.sampled_from(["load", "depth"]))]
    cols += [p.name for p in data.draw(st.lists(
        st.sampled_from([p for p in PARAMETERS if p.name not in base]),
        min_size=1, max_size=3, unique_by=lambda p: p.name))]
    rows = [[data.draw(st.sampled_from([base[c]] * 3 + _FUZZ_VALUES[byname[c].kind][:4]))
             if c in base else data.draw(st.sampled_from(_FUZZ_VALUES[byname[c].kind]))
             for c in cols] for _ in range(data.draw(st.integers(1, 4)))]
    path = tmp_path_factory.mktemp("audit") / "cases.csv"
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(cols)
        w.writerows(rows)
    status, out, err = _calc([str(path), *data.draw(st.sampled_from(
        [[], ["--si"], ["--model", "johnson,universal"]]))])
    _audit(status, out, err, csv_out=True, inputs=set(cols))


@pytest.mark.parametrize("spec,says", [
    ("johnson:c=0.7:c=0.8", "option 'c' is given twice"),
    ("li-popov:extrapolate=yes:extrapolate=no", "option 'extrapolate' is given twice"),
    ("johnsen", "did you mean 'johnson'?"),
    ("johnson:cc=0.7", "did you mean 'c'?"),
    ("johnson:C=0.7", "did you mean 'c'?"),
])
def test_a_model_option_twice_or_misspelt_is_refused(spec, says):
    """--model KEY:OPT=V:OPT=W kept the last value silently (as argparse does for an
    option given twice): refused; a misspelt model or option names the close match."""
    status, out, err = _calc(["--radius", "5mm", "--length", "10mm", "--estar", "115GPa",
                              "--load", "1kN", "--model", spec])
    assert status == 2 and says in err and err.count("\n") == 1, err


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_plot_follows_one_rule_for_every_command(tmp_path, door):
    """--plot FILE: the format by the extension (PNG, SVG or PDF), another one refused
    before anything is written (the output file is not created), and not with a CSV
    batch; a bearing's former --figure is refused naming --plot."""
    pytest.importorskip("matplotlib")
    case = [x for c, v in zip(door.header.split(","), door.row.format(
        load="1kN").split(",")) for x in ("--" + c.replace("_", "-"), v)]
    out = tmp_path / "out.txt"
    status, _, err = _calc([*case, "--plot", str(tmp_path / "f.jpg"), "-o", str(out)],
                           door.name)
    assert status == 2 and ".png, .svg or .pdf" in err and not out.exists()
    status, _, err = _calc([*case, "--plot", str(tmp_path / "f.svg")], door.name)
    assert status == 0 and (tmp_path / "f.svg").read_text().lstrip().startswith("<")
    path = tmp_path / "in.csv"
    path.write_text(door.header + "\n" + door.row.format(load="1kN") + "\n")
    status, _, err = _calc([str(path), "--plot", str(tmp_path / "g.png")], door.name)
    assert status == 2 and "not a CSV batch" in err
    if door.name == "bearing":
        status, _, err = _calc([*case, "--figure", "x.png"], door.name)
        assert status == 2 and "--figure is now --plot" in err


def test_a_unit_header_is_answered_with_a_cell_of_that_parameters_kind(tmp_path):
    """The advice for 'NAME [mm]' shows a cell of NAME's own kind (1kN under
    'radial_load'), never '5mm under radius' whatever the column (a length for a force),
    and none for a pure number or a word, which have no unit to move. One table: every
    parameter of every door."""
    from linecontact._units import DIMENSIONS

    path = tmp_path / "units.csv"
    failed = []
    for door in DOORS:
        for name in door.parameters:
            path.write_text(f"{name} [mm],other\n5,x\n")
            status, out, err = _calc([str(path)], door.name)
            kind = next(p.kind for p in _parameters(door) if p.name == name)
            example = DIMENSIONS.get(kind, ("", "", ""))[2].split(",")[0]
            if example and not example.replace(".", "").isdigit():
                if f"e.g. {example} under {name!r}" not in err:
                    failed.append((door.name, name, err))
            elif "write the unit" in err:
                failed.append((door.name, name, err))
    assert not failed, failed


def _parameters(door):
    if door.name == "calc":
        from linecontact.calc.cases import PARAMETERS
        return PARAMETERS
    from linecontact.calc.subcommands import SUBCOMMANDS
    return next(m for m in SUBCOMMANDS if m.name == door.name).parameters
