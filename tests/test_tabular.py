"""Results as tables (linecontact/tabular.py) and in Jupyter (_repr_html_).

Facts checked:
- units come from each result's docstring, so the heading's unit is the documented one
  (force [N], stiffness [N/m], time [s]);
- a result over several loads is one row per load with the same numbers as the result's
  arrays; q(x) along the roller (another length) is not a column;
- to_dict holds every output, nested results as dicts;
- the HTML table shows the units and the reasons of outputs not defined; a long
  history is cut to max_rows with a '...' row.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
from linecontact.tabular import html_table, table_columns, to_dict, units_of
from linecontact.viscoelastic import StandardLinearSolid

ESTAR = 115.38e9


def test_rows_are_the_results_arrays():
    r = Contact(Roller(5e-3, 10e-3), estar=ESTAR).normal(force=[1e3, 2e3, 3e3])
    cols = table_columns(r)
    np.testing.assert_array_equal(cols["depth"], r.depth)
    np.testing.assert_array_equal(cols["stiffness"], r.stiffness)
    assert cols["model"].tolist() == ["universal"] * 3
    assert "q" not in cols and "reasons" not in cols


def test_profiled_roller_q_is_not_a_column_but_in_the_dict():
    r = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=ESTAR).normal(force=1e3)
    assert "q" not in table_columns(r) and len(table_columns(r)["force"]) == 1
    d = r.to_dict()
    np.testing.assert_array_equal(d["q"], r.q)
    assert "<th>peak_pressure [Pa]</th>" in r._repr_html_()


def test_units_from_docstrings_and_nested_results():
    from linecontact.contact import CreepResult, TangentialResult
    assert units_of(CreepResult)["time"] == "s"
    assert units_of(TangentialResult)["stiffness"] == "N/m"
    c = Contact(Roller(5e-3, 10e-3), material1=Elastic(210e9, 0.3),
                material2=Elastic(210e9, 0.3))
    t = c.tangential(0.1, force=1e3, tangential_force=20.0)
    d = to_dict(t)
    assert isinstance(d["normal"], dict) and d["normal"]["force"] == 1e3
    assert "<th>tangential_force [N]</th>" in html_table(t)


def test_long_history_is_cut():
    c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    r = c.creep(np.linspace(0, 30, 7), force=1e3)
    text = html_table(r, max_rows=4)
    assert text.count("<tr>") == 1 + 2 + 1 + 2          # heading, 2 first, ..., 2 last
    assert "<td>...</td>" in text and "<th>time [s]</th>" in text


def test_to_frame():
    pd = pytest.importorskip("pandas")
    r = Contact(Roller(5e-3, 10e-3), estar=ESTAR).normal(force=[1e3, 2e3])
    df = r.to_frame()
    assert isinstance(df, pd.DataFrame) and df["force"].tolist() == [1e3, 2e3]
    assert df.attrs["units"]["peak_pressure"] == "Pa"
