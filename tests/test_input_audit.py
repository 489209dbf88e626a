"""Hypothesis audits over random options, CSV cells and DataFrame cells of every door
(issue 36): ``linecontact calc`` and ``linecontact bearing`` (tests/doors.py), and the
DataFrame API (linecontact.calc.frame). Whatever the input: no traceback, a status of 0
or 2 with only the command's one-line messages on stderr, no nan/inf printed, no row
computed without a value or a word saying why (no silent drop), and no file overwritten
that the command read (the CSV given as -o) or wrote twice (-o and --plot)."""

from __future__ import annotations

import contextlib
import csv
import io

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from doors import DOORS, IDS
from linecontact.calc.cli import main

#: Values per kind of input: valid ones, units of another quantity or case, signs,
#: zero, inf, NaN, overflow, subnormal, words, sweeps, typography.
FUZZ = {
    "length": ["5mm", "20mm", "0.2in", "1e-3", "-5mm", "0", "inf", "nan", "5MM", "5 kg",
               "abc", "", "1e400", "1e-320", "5mm:1mm:3", "5\u00a0mm", "\u22125mm"],
    "pressure": ["210GPa", "3GPa", "1e9", "-1GPa", "0", "inf", "nan", "210", "1kN"],
    "dimensionless": ["0.3", "0.5", "0.6", "-0.1", "0", "nan", "1", "0.2:0.4:3"],
    "count": ["14", "3", "0", "-2", "40.5", "1000", "2.0", "nan", "5mm", "1e9"],
    "force": ["1kN", "100N", "0", "-1kN", "nan", "inf", "1e9", "1mN", "5mm", "1kN:2kN:3"],
    "angle": ["0", "1mrad", "0.5", "free", "-1mrad", "nan", "5deg", "0.05°"],
    "moment": ["0", "20 N m", "20N·m", "-5Nm", "1e9", "nan", "5mm"],
    "text": ["circular:Rc=0.5", "iso16281", "cone", "circular", "circular:Rc=-1", "yes",
             "von_mises", "all", "", "profiled-roller", "universal"],
    "time": ["10s", "0", "-1s", "1h", "nan", "1:10:3"],
    "path": ["/nonexistent/x.csv", ""],
    "surface_energy": ["0.05", "-1", "0", "nan", "50mJ/m2"],
}


def _parameters(door):
    if door.name == "calc":
        from linecontact.calc.cases import PARAMETERS
        return list(PARAMETERS)
    from linecontact.calc.subcommands import SUBCOMMANDS
    return list(next(m for m in SUBCOMMANDS if m.name == door.name).parameters)


def _run(argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))  # an exception here fails the test with its traceback
    return status, out.getvalue(), err.getvalue()


def _check(door, status, out, err, csv_out, inputs=()):
    assert status in (0, 2), (status, err)
    for line in err.splitlines():
        assert line.startswith(f"linecontact {door.name}:"), err
    if not csv_out or not out:
        assert "nan" not in out.lower().split(), out
        return
    for row in csv.DictReader(io.StringIO(out)):
        assert None not in row and "" not in row, row  # no column without a name
        cells = {k: (v or "").strip() for k, v in row.items() if k not in inputs}
        assert not any(v.lower() in ("nan", "inf", "-inf") for v in cells.values()), row
        if cells.get("error"):
            continue
        said = any(v for k, v in cells.items() if k.startswith(("note", "flags")))
        assert said or any(_number(v) for k, v in cells.items()
                           if k not in ("model", "model_used", "error")), row


def _number(text):
    try:
        float(text)
    except ValueError:
        return False
    return True


def _fuzz(p):
    return FUZZ.get(p.kind, FUZZ["dimensionless"])


@pytest.mark.parametrize("door", DOORS, ids=IDS)
@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_audit_of_random_options(door, data):
    """1-3 random inputs of the command on its valid case, with --json, --si or
    nothing: never a traceback, a stray stderr line or a nan printed."""
    given_ = {door.load} | {o[2:].replace("-", "_") for o in door.options[::2]}
    argv = [door.name, *door.options, door.load_option,
            "1kN" if door.name == "calc" else "10kN"]
    extra = data.draw(st.lists(st.sampled_from([p for p in _parameters(door)
                                                if p.name not in given_]),
                               min_size=1, max_size=3, unique_by=lambda p: p.name))
    for p in extra:
        argv += ["--" + p.name.replace("_", "-"), data.draw(st.sampled_from(_fuzz(p)))]
    argv += data.draw(st.sampled_from([[], ["--si"], ["--json"]]))
    _check(door, *_run(argv), csv_out=False)


@pytest.mark.parametrize("door", DOORS, ids=IDS)
@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_audit_of_random_csv_columns(door, data, tmp_path_factory):
    """Random batches (the valid case's columns plus 1-3 other input columns, 1-4 rows,
    a row with an extra cell now and then), written to stdout or given the input file
    as -o: the same rules, every row computed, said or refused in its error cell, no
    column without a name, and the input file never overwritten."""
    header = door.header.split(",")
    base = dict(zip(header, door.row.format(load="1kN" if door.name == "calc"
                                             else "10kN").split(",")))
    byname = {p.name: p for p in _parameters(door)}
    cols = header + [p.name for p in data.draw(st.lists(
        st.sampled_from([p for p in byname.values() if p.name not in base]),
        min_size=1, max_size=3, unique_by=lambda p: p.name))]
    rows = [[data.draw(st.sampled_from([base[c]] * 3 + _fuzz(byname[c])[:4]))
             if c in base else data.draw(st.sampled_from(_fuzz(byname[c])))
             for c in cols] for _ in range(data.draw(st.integers(1, 4)))]
    if data.draw(st.booleans()):
        rows[0].append("7")  # a cell beyond the header
    path = tmp_path_factory.mktemp("audit") / "cases.csv"
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(cols)
        w.writerows(rows)
    before = path.read_bytes()
    as_output = data.draw(st.booleans())
    status, out, err = _run([door.name, str(path),
                             *(["-o", str(path)] if as_output else []),
                             *data.draw(st.sampled_from([[], ["--si"]]))])
    assert path.read_bytes() == before  # the input is never overwritten
    if as_output:
        assert status == 2 and "input file" in err, err
        return
    _check(door, status, out, err, csv_out=True, inputs=set(cols))


pd = pytest.importorskip("pandas")


@pytest.mark.parametrize("door", DOORS, ids=IDS)
@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_audit_of_random_frames(door, data):
    """Random DataFrames (cells as strings, numbers, None; 0-4 rows; a column named
    twice in another case): the result has the frame's index and untouched user
    columns, each row computed, said or refused in `error`; a frame refused as a whole
    raises ValueError in one line naming no internal file."""
    header = door.header.split(",")
    base = dict(zip(header, door.row.format(load="1kN" if door.name == "calc"
                                             else "10kN").split(",")))
    byname = {p.name: p for p in _parameters(door)}
    cols = header + [p.name for p in data.draw(st.lists(
        st.sampled_from([p for p in byname.values() if p.name not in base]),
        max_size=2, unique_by=lambda p: p.name))]
    n = data.draw(st.integers(0, 4))
    cells = {c: [data.draw(st.one_of(st.sampled_from([base.get(c, "")] * 2
                                                      + _fuzz(byname[c])[:5]),
                                     st.none(), st.floats(-1e3, 1e3)))
                 for _ in range(n)] for c in cols}
    frame = pd.DataFrame(cells, index=[10 * i for i in range(n)])
    try:
        out = door.frame(frame)
    except ValueError as exc:
        assert "\n" not in str(exc) and "linecontact-frame" not in str(exc), exc
        assert "no rows" not in str(exc)  # 0 rows: an empty frame, not an error
        return
    assert list(out.index) == list(frame.index)
    for c in frame.columns:
        assert out[c].tolist() == frame[c].tolist() or frame[c].isna().any(), c
    assert "error" in out.columns
    for _, row in out.iterrows():
        if row["error"]:
            assert "linecontact-frame" not in row["error"]
            continue
        notes = " ".join(str(row[k]) for k in ("note", "flags") if k in row)
        assert notes.strip() or any(
            isinstance(v, float) and v == v for k, v in row.items() if k not in cols)
