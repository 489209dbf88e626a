"""Self-describing tables in tables/: format, loader refusals, shipped data documented.

Each test states the fact it checks in its docstring and assertion message.
"""
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from linecontact import tables as tb
from linecontact.tables import (REQUIRED_KEYS, TableError, available_tables, read_table,
                                tables_dir, write_table)

META = dict(title="demo", source="a test", units="x [m], y [N]", generated_by="pytest",
            date="2026-11-21", version="0", accuracy="exact by construction")


def test_published_table_is_self_describing():
    """lipopov_published.csv carries every required metadata key and its provenance."""
    t = read_table("lipopov_published")
    for key in REQUIRED_KEYS:
        assert t.meta.get(key), f"required metadata {key!r} missing"
    assert t.meta["provenance"] == "published, Li & Popov 2017, Table 1"
    assert t.meta["generated_by"].startswith("transcribed by hand from")
    assert list(t.columns) == ["L_over_R", "alpha", "beta"] and len(t) == 15
    assert t.path.name == "lipopov_published.csv" and t.name == "lipopov_published"


def test_every_shipped_table_loads_and_is_documented_in_the_readme():
    """Every CSV in tables/ passes the loader (required metadata, finite numbers) and has
    its own section in tables/README.md saying where it came from."""
    readme = (tables_dir() / "README.md").read_text(encoding="utf-8")
    names = available_tables()
    assert "lipopov_published" in names
    for name in names:
        read_table(name)
        assert f"## {name}.csv" in readme, f"tables/README.md has no section for {name}.csv"


@given(x=st.lists(st.floats(allow_nan=False, allow_infinity=False), min_size=1, max_size=20))
def test_write_then_read_gives_back_the_same_floats(tmp_path_factory, x):
    """write_table/read_table round trip is exact for any finite floats, metadata kept."""
    d = tmp_path_factory.mktemp("t")
    write_table(d / "demo.csv", {**META, "grid": "n/a"}, {"x": x, "y": x[::-1]})
    t = read_table("demo", directory=d)
    np.testing.assert_array_equal(t.columns["x"], np.array(x, dtype=float))
    np.testing.assert_array_equal(t.columns["y"], np.array(x[::-1], dtype=float))
    assert t.meta == {**META, "grid": "n/a"}


@pytest.mark.parametrize("key", REQUIRED_KEYS)
def test_loader_refuses_missing_metadata(tmp_path, key):
    """A table without one of the required metadata keys is refused, naming the key."""
    meta = {k: v for k, v in META.items() if k != key}
    text = "".join(f"# {k}: {v}\n" for k, v in meta.items()) + "x,y\n1,2\n"
    (tmp_path / "bad.csv").write_text(text)
    with pytest.raises(TableError, match=key):
        read_table("bad", directory=tmp_path)
    with pytest.raises(TableError, match=key):
        write_table(tmp_path / "bad2.csv", meta, {"x": [1.0]})


@pytest.mark.parametrize("rows, what", [("1,nan\n", "non-finite"), ("1,inf\n", "non-finite"),
                                        ("1,2\n3\n", "numbers"), ("1,abc\n", "numbers"),
                                        ("", "no data")])
def test_loader_refuses_bad_data(tmp_path, rows, what):
    """Non-finite numbers, ragged or non-numeric rows, and empty tables are refused."""
    text = "".join(f"# {k}: {v}\n" for k, v in META.items()) + "x,y\n" + rows
    (tmp_path / "bad.csv").write_text(text)
    with pytest.raises(TableError, match=what):
        read_table("bad", directory=tmp_path)


def test_writer_refuses_non_finite_and_ragged(tmp_path):
    """write_table refuses non-finite values, unequal columns and multi-line metadata."""
    with pytest.raises(TableError, match="non-finite"):
        write_table(tmp_path / "a.csv", META, {"x": [1.0, math.nan]})
    with pytest.raises(TableError, match="equally long"):
        write_table(tmp_path / "a.csv", META, {"x": [1.0], "y": [1.0, 2.0]})
    with pytest.raises(TableError, match="single"):
        write_table(tmp_path / "a.csv", {**META, "note": "two\nlines"}, {"x": [1.0]})


def test_missing_table_lists_the_available_ones():
    """Reading an absent table raises FileNotFoundError listing what exists."""
    with pytest.raises(FileNotFoundError, match="lipopov_published"):
        read_table("no_such_table")


def test_tables_dir_prefers_installed_package_data(tmp_path, monkeypatch):
    """The loader finds tables in an installed package (<pkg>/tables, package data) and
    falls back to the checkout's top-level tables/ (both layouts simulated here)."""
    pkg = tmp_path / "site" / "linecontact"
    (pkg / "tables").mkdir(parents=True)
    (pkg / "tables" / "x.csv").write_text("")
    monkeypatch.setattr(tb, "__file__", str(pkg / "tables.py"))
    assert tables_dir() == (pkg / "tables").resolve()
    checkout = tmp_path / "repo"
    (checkout / "linecontact").mkdir(parents=True)
    (checkout / "tables").mkdir()
    monkeypatch.setattr(tb, "__file__", str(checkout / "linecontact" / "tables.py"))
    assert tables_dir() == (checkout / "tables").resolve()


def test_shipped_tables_are_inside_the_package_data_mapping():
    """pyproject.toml installs the top-level tables/ as package data linecontact/tables."""
    root = Path(__file__).resolve().parent.parent
    text = (root / "pyproject.toml").read_text()
    assert '"linecontact.tables" = "tables"' in text and '"*.csv"' in text
