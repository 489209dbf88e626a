"""Self-describing CSV tables shipped in ``tables/`` (read and written here).

File format (UTF-8 text)::

    # title: Li & Popov (2017) Table 1: coefficients of Eq. 9
    # source: ...
    # units: L_over_R [-], alpha [-], beta [-]
    # generated_by: transcribed by hand from ...
    # date: 2017-03-31
    # version: 1
    # accuracy: ...
    L_over_R,alpha,beta
    0.1,3.8695,17.1183
    ...

Leading lines ``# key: value`` are metadata (keys in :data:`REQUIRED_KEYS` are
mandatory, others such as ``grid`` or ``tolerance`` are allowed); then one header row of
comma-separated column names; then numeric rows, all finite. The loader refuses a file
that breaks any of this, so that no undescribed or damaged data reaches a formula.

Where tables are found: in an installed package they are package data next to this
module (``linecontact/tables/``); in a source checkout they are the top-level
``tables/`` folder. :func:`tables_dir` returns whichever exists.
"""
from __future__ import annotations

import io
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

__all__ = [
    "REQUIRED_KEYS",
    "Table",
    "TableError",
    "tables_dir",
    "table_path",
    "read_table",
    "write_table",
    "available_tables",
]

#: Metadata every table must carry.
REQUIRED_KEYS = ("title", "source", "units", "generated_by", "date", "version", "accuracy")


class TableError(ValueError):
    """A table file is malformed: missing metadata, ragged or non-finite data."""


@dataclass
class Table:
    """A self-describing table: its metadata, its columns and the file it came from.

    Made by :func:`read_table`, which checks the file; constructing one directly checks
    nothing (write it with :func:`write_table` to get the checks).

    Parameters
    ----------
    meta : dict[str, str]
        The ``# key: value`` metadata, in file order; the units of the columns are in
        ``meta["units"]``.
    columns : dict[str, ndarray]
        One float array per column, in file order, all of the same length.
    path : pathlib.Path, optional
        The file it was read from (None for a table built in memory).

    Examples
    --------
    >>> t = read_table("lipopov_published")
    >>> t.name, len(t), t.path.suffix
    ('lipopov_published', 15, '.csv')
    >>> t.meta["units"]
    'L_over_R [-], alpha [-], beta [-]'
    """

    meta: dict
    columns: dict
    path: Path = field(default=None)

    @property
    def name(self):
        """File stem, e.g. ``'lipopov_published'``."""
        return self.path.stem if self.path is not None else ""

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0


def tables_dir():
    """Directory holding the shipped tables.

    ``<package>/tables`` when installed (package data), else ``<checkout>/tables``.

    Examples
    --------
    >>> (tables_dir() / "lipopov_published.csv").is_file()
    True
    """
    here = Path(__file__).resolve().parent
    installed = here / "tables"
    if installed.is_dir() and any(installed.glob("*.csv")):
        return installed
    checkout = here.parent / "tables"
    if checkout.is_dir():
        return checkout
    raise FileNotFoundError(
        f"no tables directory: looked for {installed} (installed package) and "
        f"{checkout} (source checkout)")


def available_tables(prefix=""):
    """Stems of the tables in :func:`tables_dir` whose name starts with `prefix`.

    Parameters
    ----------
    prefix : str, optional
        Start of the file stem (default: every table).

    Returns
    -------
    list of str
        Sorted file stems (no ``.csv``).

    Examples
    --------
    >>> "lipopov_published" in available_tables("lipopov_")
    True
    """
    return sorted(p.stem for p in tables_dir().glob(f"{prefix}*.csv"))


def table_path(name):
    """Path of the shipped table `name` (a file stem) in :func:`tables_dir`.

    Parameters
    ----------
    name : str
        File stem, e.g. ``"lipopov_published"``.

    Returns
    -------
    pathlib.Path
        ``tables_dir() / (name + ".csv")``.

    Raises
    ------
    FileNotFoundError
        No such table; the message lists the available ones.

    Examples
    --------
    >>> table_path("lipopov_published").name
    'lipopov_published.csv'
    """
    path = tables_dir() / f"{name}.csv"
    if not path.is_file():
        raise FileNotFoundError(
            f"table {name!r} not found in {path.parent}; available: "
            f"{', '.join(available_tables()) or 'none'}")
    return path


def _parse(text, where):
    meta = {}
    lines = text.splitlines()
    i = 0
    while i < len(lines) and (lines[i].startswith("#") or not lines[i].strip()):
        line = lines[i]
        i += 1
        if not line.strip():
            continue
        body = line[1:].strip()
        if not body:
            continue
        key, sep, value = body.partition(":")
        if not sep:
            raise TableError(f"{where}: metadata line {i} is not '# key: value': {line!r}")
        meta[key.strip()] = value.strip()
    missing = [k for k in REQUIRED_KEYS if not meta.get(k)]
    if missing:
        raise TableError(f"{where}: missing required metadata {', '.join(missing)} "
                         f"(required: {', '.join(REQUIRED_KEYS)})")
    if i >= len(lines):
        raise TableError(f"{where}: no header row after the metadata")
    names = [c.strip() for c in lines[i].split(",")]
    if not all(names) or len(set(names)) != len(names):
        raise TableError(f"{where}: header row has empty or repeated names: {names}")
    rows = [ln for ln in lines[i + 1:] if ln.strip() and not ln.lstrip().startswith("#")]
    if not rows:
        raise TableError(f"{where}: no data rows")
    try:
        data = np.loadtxt(io.StringIO("\n".join(rows)), delimiter=",", dtype=float,
                          ndmin=2)
    except ValueError as exc:
        raise TableError(f"{where}: data rows are not {len(names)} numbers each: {exc}") \
            from exc
    if data.shape[1] != len(names):
        raise TableError(f"{where}: {data.shape[1]} data columns but {len(names)} names")
    if not np.all(np.isfinite(data)):
        r, c = np.argwhere(~np.isfinite(data))[0]
        raise TableError(f"{where}: non-finite value {data[r, c]} in column "
                         f"{names[c]!r}, data row {r + 1}")
    columns = {n: data[:, j].copy() for j, n in enumerate(names)}
    return meta, columns


def read_table(name, directory=None):
    """Read the self-describing CSV table `name` (a file stem) from ``tables/``.

    Parameters
    ----------
    name : str
        File stem, e.g. ``"lipopov_published"``.
    directory : path-like, optional
        Read from this folder instead of :func:`tables_dir`.

    Returns
    -------
    Table
        With ``.meta``, ``.columns`` and ``.path``.

    Raises
    ------
    FileNotFoundError
        No such table (the message lists the available ones).
    TableError
        Missing required metadata (:data:`REQUIRED_KEYS`), a bad header, ragged rows
        or non-finite numbers.

    Examples
    --------
    >>> t = read_table("lipopov_published")
    >>> t.meta["provenance"]
    'published, Li & Popov 2017, Table 1'
    >>> list(t.columns), len(t)
    (['L_over_R', 'alpha', 'beta'], 15)
    """
    if directory is None:
        path = table_path(name)
    else:
        path = Path(directory) / f"{name}.csv"
        if not path.is_file():
            raise FileNotFoundError(f"table {name!r} not found in {directory}")
    # utf-8-sig: a table re-saved by a spreadsheet may start with a byte-order mark
    meta, columns = _parse(path.read_text(encoding="utf-8-sig"), str(path))
    return Table(meta=meta, columns=columns, path=path)


def write_table(path, meta, columns):
    """Write a self-describing CSV table (the format :func:`read_table` reads).

    Parameters
    ----------
    path : path-like
        Output file (``.csv``).
    meta : dict[str, str]
        Metadata; must contain every key of :data:`REQUIRED_KEYS`; values single-line.
    columns : dict[str, array_like]
        Column name -> 1D values, all of the same length and finite. Written as the
        shortest decimal that reads back as the same float.

    Examples
    --------
    >>> import tempfile, os
    >>> meta = dict(title="t", source="s", units="x [m]", generated_by="doctest",
    ...             date="2026-01-01", version="0", accuracy="exact")
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_table(os.path.join(d, "demo.csv"), meta, {"x": [0.1, 0.2]})
    ...     read_table("demo", directory=d).columns["x"]
    array([0.1, 0.2])
    """
    missing = [k for k in REQUIRED_KEYS if not str(meta.get(k, "")).strip()]
    if missing:
        raise TableError(f"cannot write {path}: missing required metadata "
                         f"{', '.join(missing)}")
    for key, value in meta.items():
        if ":" in str(key) or "\n" in str(key) or "\n" in str(value):
            raise TableError(f"cannot write {path}: metadata {key!r} must be a single "
                             "line and its key may not contain ':'")
    names = list(columns)
    arrays = [np.asarray(columns[n], dtype=float).ravel() for n in names]
    if not names or len({a.size for a in arrays}) != 1:
        raise TableError(f"cannot write {path}: columns must be non-empty and equally long")
    if any("," in n or not n.strip() for n in names):
        raise TableError(f"cannot write {path}: empty column name or one with a comma")
    for n, a in zip(names, arrays):
        if not np.all(np.isfinite(a)):
            raise TableError(f"cannot write {path}: column {n!r} has non-finite values")
    out = io.StringIO()
    for key, value in meta.items():
        out.write(f"# {key}: {value}\n")
    out.write(",".join(names) + "\n")
    for row in zip(*arrays):
        out.write(",".join(repr(float(v)) for v in row) + "\n")
    Path(path).write_text(out.getvalue(), encoding="utf-8")
