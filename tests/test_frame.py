"""Cases as a DataFrame (linecontact/calc/frame.py): the CSV batch's rules, for pandas.

Facts checked:
- the results are the library's numbers at full precision (the universal curve's d(F)
  to 1e-12) and the same as `linecontact calc FILE.csv --si` for the same cells (to the
  CSV's 6 printed digits);
- every user column is kept with its values, dtype and the frame's index; a result
  column named like a user column gets the batch's result_ prefix;
- a bad row keeps its place and says why in `error` while the others are computed; an
  option fills empty cells only; bare numbers are SI;
- a frame the batch refuses as a whole raises ValueError naming the problem.
"""
from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest

pd = pytest.importorskip("pandas")

from linecontact.calc.cli import main
from linecontact.calc.frame import calc_frame
from linecontact.models import get_model

from doors import DOORS, IDS


def _cases():
    return pd.DataFrame({"tag": ["a", "b", "c", "d"],
                         "radius": ["5mm", 6e-3, "-1mm", "5 mm"],
                         "length": ["10mm", "12mm", "10mm", "10mm"],
                         "load": [1000.0, "2kN", 500.0, None],
                         "weight": [1, 2, 3, 4]},
                        index=[10, 11, 12, 13])


def test_results_are_the_librarys_and_the_batchs(tmp_path, capsys):
    cases = _cases()
    out = calc_frame(cases, estar="115.38GPa", load="700N")
    # user columns untouched, same index and dtypes
    assert list(out.index) == [10, 11, 12, 13]
    for c in cases.columns:
        assert out[c].tolist() == cases[c].tolist(), c
        assert out[c].dtype == cases[c].dtype, c
    # the library at full precision: row d is R 5 mm, L 10 mm, and its load is the
    # option's (its cell was empty; an option fills empty cells only)
    uni = get_model("universal", 5e-3, 10e-3, 115.38e9)
    assert out.loc[13, "force_N"] == 700.0
    assert out.loc[13, "depth_m"] == pytest.approx(float(uni.depth(700.0)), rel=1e-12)
    # a filled cell that differs from the option is an error in its row, as in a CSV
    # batch (docs/inputs.md), never silently overridden either way
    for i in (10, 11):
        assert "conflicts with the keyword load='700N'" in out.loc[i, "error"], \
            out.loc[i, "error"]
        assert math.isnan(out.loc[i, "depth_m"])
    # the bad row says why and the others are computed
    assert "radius" in out.loc[12, "error"] and math.isnan(out.loc[12, "depth_m"])
    assert out.loc[13, "error"] == ""
    # the same cells through the CSV batch give the same numbers (6 printed digits)
    path = tmp_path / "cases.csv"
    cases.to_csv(path, index=False)
    assert main(["calc", str(path), "--si", "--estar", "115.38GPa", "--load", "700N",
                 "-o", str(tmp_path / "out.csv")]) == 2      # rows a-c fail
    capsys.readouterr()
    rows = list(csv.DictReader(io.StringIO((tmp_path / "out.csv").read_text())))
    for r, (_, f) in zip(rows, out.iterrows()):
        for col in ("force_N", "depth_m", "stiffness_N_per_m", "peak_pressure_Pa"):
            if r[col]:
                assert float(r[col]) == pytest.approx(f[col], rel=5e-6), col
            else:
                assert math.isnan(f[col])
        # the same error, each in its door's words (an option there, a keyword here)
        assert r["error"] == f["error"] or (
            "--load 700N on the command line" in r["error"]
            and "the keyword load='700N'" in f["error"]), (r["error"], f["error"])
    assert out.attrs["linecontact"]["units"]["depth"] == "m"


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_user_column_named_like_a_result_is_kept(door):
    """A user column named like a result column (the model's, error) is kept as it was;
    the results get the batch's result_ prefix (one error column of each)."""
    cols = door.header.split(",")
    cells = door.row.format(load="1kN").split(",")
    model = "model" if door.name == "calc" else "model_used"
    cases = pd.DataFrame({**{c: [v] for c, v in zip(cols, cells)},
                          model: ["my roller"], "error": ["mine"]})
    options = {"model": "johnson:c=0.72"} if door.name == "calc" else {}
    out = door.frame(cases, **options)
    assert out[model].tolist() == ["my roller"] and out["error"].tolist() == ["mine"]
    assert out["result_error"].tolist() == [""]
    if door.name == "calc":
        assert out["result_model"].tolist() == ["Johnson (c = 0.72)"]
    else:
        assert out["result_model_used"].tolist()[0].startswith("Universal")


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_frames_refused_as_a_whole(door):
    first = door.header.split(",")[0]
    with pytest.raises(ValueError, match="no case columns"):
        door.frame(pd.DataFrame({"x": [1.0]}))
    with pytest.raises(ValueError, match=r"cases: columns of 2 levels.*flatten"):
        door.frame(pd.DataFrame([["5mm"]], columns=pd.MultiIndex.from_tuples(
            [("a", first)])))  # every row failed as "missing" (the names were tuples)
    with pytest.raises(ValueError, match=r"^cases \(DataFrame\): column .* twice"):
        door.frame(pd.DataFrame({first: ["5mm"], first.upper(): ["5mm"]}))  # no temp path
    typo = first[:-2] + first[-1] + first[-2]
    with pytest.raises(ValueError, match=f"'{typo}'.*did you mean '{first}'"):
        door.frame(pd.DataFrame({first: ["5mm"]}), **{typo: "5mm"})  # unknown keyword
    with pytest.raises(TypeError, match="DataFrame"):
        door.frame([{first: "5mm"}])
    with pytest.raises(ValueError, match="length"):             # a bad option value
        door.frame(pd.DataFrame({first: ["5mm"]}), length="-5mm")


def test_sweeps_of_numbers_are_si():
    """Bare numbers are SI: 0.005 m and 5 mm are the same case."""
    cases = pd.DataFrame({"radius": [0.005, "5mm"], "length": [0.01, "10mm"],
                          "load": [1e3, "1kN"], "estar": [115.38e9, "115.38GPa"]})
    out = calc_frame(cases)
    assert np.asarray(out["depth_m"])[0] == np.asarray(out["depth_m"])[1]


@pytest.mark.parametrize("door", DOORS, ids=IDS)
def test_a_frame_without_rows_gives_an_empty_frame_with_the_result_columns(door):
    """0 rows: no error, the user's columns and the result columns (those of a row of
    the same columns), no row (a notebook's filter that leaves nothing must not raise)."""
    first = door.header.split(",")[0]
    empty = door.frame(pd.DataFrame({first: pd.Series([], dtype=object)}))
    one = door.frame(pd.DataFrame({first: [None]}))
    assert len(empty) == 0 and list(empty.columns) == list(one.columns)
    assert "error" in empty.columns and empty.attrs["linecontact"]


def test_result_columns_do_not_depend_on_which_rows_fail():
    """The result columns are those of the computed contacts: a row refused for its
    radius (NaN there) adds no `radius_eff` column (NaN != NaN made it look like a
    counter-body), and an empty frame has the columns of a one-row frame."""
    good = pd.DataFrame({"radius": ["5mm"], "length": ["10mm"], "estar": ["115GPa"],
                         "load": ["1kN"]})
    bad = pd.concat([good, good.assign(radius=["-5mm"])], ignore_index=True)
    cols = list(calc_frame(good).columns)
    assert list(calc_frame(bad).columns) == cols
    assert list(calc_frame(good.iloc[:0]).columns) == cols
    assert "radius_eff_m" in calc_frame(good.assign(radius2=["20mm"])).columns


def test_a_conflict_with_a_keyword_is_said_as_a_keyword():
    """calc_frame(cases, load=...) against a filled, different cell: the row's error
    names the keyword the caller gave (load='...'), not a command-line option
    '--load ... on the command line' the caller never typed."""
    cases = pd.DataFrame({"radius": ["5mm"], "length": ["10mm"], "estar": ["115GPa"],
                          "load": ["2kN"]})
    err = calc_frame(cases, load="1kN")["error"][0]
    assert "the keyword load='1kN'" in err and "command line" not in err, err
    assert "--load" not in err, err
