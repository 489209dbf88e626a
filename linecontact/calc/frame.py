"""Cases in a pandas DataFrame, results as a DataFrame: the CSV batch for notebooks.

:func:`calc_frame` takes a DataFrame whose columns are named like the CSV batch's
(``radius``, ``length``, ``estar``, ``load``, ``crown_radius``, ``inner_raceway``, ...:
the options of ``linecontact calc`` without the dashes) and returns a DataFrame of the
same rows by exactly the batch's rules (:mod:`linecontact.calc.batch`), because it IS
the batch: the frame is written as a CSV, run through
:func:`linecontact.calc.batch.run_batch` with JSON output (SI units, full precision)
and read back.

- Cells are unit strings (``"5 mm"``, ``"1kN"``) or numbers, which are SI (m, N, Pa),
  as in a CSV file; an empty cell (None, NaN) is "not given" and is filled by a keyword
  option of the same name (``calc_frame(df, estar="115GPa")``).
- Every user column is kept, untouched (values and dtypes), in its place and the
  result columns follow in SI (``estar_Pa``, ``model``, ``force_N``, ``depth_m``, ...,
  ``flags``, ``note``, and one ``error`` column); a result column whose name the user
  already has gets the batch's ``result_`` prefix.
- A row that cannot be computed keeps its place and says why in ``error``; the
  others are computed. Nothing is raised for a bad row; a bad frame as a whole (no
  case column, a column twice, columns of several levels) raises ValueError naming
  the frame (``cases (DataFrame): ...``). A frame without rows gives an empty frame
  with the result columns.
- ``result.attrs["linecontact"]`` holds the batch's JSON header (version, units of
  every column, notes, the models' provenance).

:func:`command_frame` does the same for a subcommand's batch (``command_frame("bearing",
cases)``: ``linecontact bearing FILE.csv``).

On a dask cluster: ``calc_frame(cases, client=client)`` (or a dask DataFrame of cases,
evaluated on the current distributed client) splits the rows into ranges evaluated on
the workers (:mod:`linecontact.calc.spread`) and returns the same DataFrame.

pandas is optional (``pip install 'linecontact[pandas]'``) and imported only here,
never on the one-case path.

Example::

    import pandas as pd
    from linecontact.calc.frame import calc_frame
    cases = pd.DataFrame({"radius": ["5mm", "6mm"], "length": ["10mm", "12mm"],
                          "load": [1000.0, 2000.0]})
    out = calc_frame(cases, estar="115.38GPa")
    out[["radius", "load", "depth_m", "stiffness_N_per_m", "error"]]
"""
from __future__ import annotations

import argparse
import contextlib
import csv
import io
import json
import math
import numbers
import re
import tempfile
from pathlib import Path

from .cases import PARAMETERS

__all__ = ["calc_frame", "command_frame"]


def _cell(value):
    """A DataFrame cell as CSV text: numbers as repr (SI), nothing as empty."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, numbers.Real):
        v = float(value)
        return "" if math.isnan(v) else repr(v)
    try:
        import pandas as pd
        if pd.isna(value):
            return ""
    except (TypeError, ValueError):
        pass
    return str(value)


def _on_client(cases, client, func):
    """(pandas cases, client): a dask DataFrame's rows gathered here (the cases are
    text; the evaluation is what goes to the cluster), and the client to evaluate
    them on: `client`, else for a dask DataFrame the current distributed client."""
    if client is None and not hasattr(cases, "npartitions"):
        return cases, None
    from .cluster import ClusterError, require_distributed

    require_distributed("client" if client is not None else "a dask DataFrame")
    if client is None:
        from distributed import get_client
        try:
            client = get_client()
        except ValueError:
            raise ClusterError(f"{func}: a dask DataFrame is evaluated on a distributed "
                               "client: give client= (distributed.Client(ADDRESS)) or "
                               "create one first") from None
    if hasattr(cases, "npartitions"):
        cases = client.compute(cases).result()
        # dask keeps text as pyarrow strings with pd.NA (its "dataframe.convert-string"
        # setting): back to pandas' own text dtype, so that the result equals the one
        # of the same rows as a pandas DataFrame, dtypes included
        import pandas as pd
        text = {c: "str" for c, t in cases.dtypes.items() if isinstance(t, pd.StringDtype)}
        if text:
            cases = cases.astype(text)
    return cases, client


def calc_frame(cases, *, model=None, client=None, **options):
    """Evaluate every row of `cases` by the CSV batch's rules; the results as a DataFrame.

    Parameters
    ----------
    cases : pandas.DataFrame or dask.dataframe.DataFrame
        One case per row; columns named like the batch's (see the module docstring).
        A dask DataFrame's rows are evaluated on the cluster of `client` (default: the
        current distributed client).
    model : str, optional
        Models as ``--model`` takes them (``"johnson:c=0.72,universal"``, ``"all"``);
        default the batch's: the best estimate only.
    client : distributed.Client, optional
        Evaluate the rows on this client's dask cluster, split into ranges of rows
        (:mod:`linecontact.calc.spread`): the same DataFrame as without.
    **options
        Values for empty or missing cells, by parameter name (``estar="115GPa"``).

    Returns
    -------
    pandas.DataFrame
        The user's columns, then the result columns [SI], same index and row order.

    Raises
    ------
    ValueError
        A frame the batch refuses as a whole, or an option value it refuses (one line,
        naming it); an unknown option name; with a cluster, a
        :class:`~linecontact.calc.cluster.ClusterError` (no dask installed, no client,
        a worker with other linecontact code, a lost scheduler).
    """
    from .batch import CALC
    from .compute import parse_model_option

    cases, client = _on_client(cases, client, "calc_frame")
    _check_frame(cases, PARAMETERS, "calc_frame", ["cases", "model", "client"], options)
    specs = parse_model_option(model)
    return _run(CALC, cases, options, specs, model, client)


def command_frame(command, cases, *, client=None, **options):
    """A subcommand's batch (``linecontact bearing FILE.csv``) on a DataFrame, by
    exactly that batch's rules (see the module docstring).

    Parameters
    ----------
    command : str
        The subcommand's name (:data:`linecontact.calc.subcommands.SUBCOMMANDS`), e.g.
        ``"bearing"``.
    cases : pandas.DataFrame or dask.dataframe.DataFrame
        One case per row; columns named like the subcommand's options without the
        dashes (``pitch_diameter``); a dask DataFrame as for :func:`calc_frame`.
    client : distributed.Client, optional
        Evaluate the rows on this client's dask cluster (as :func:`calc_frame`).
    **options
        Values for empty or missing cells, by parameter name.

    Returns
    -------
    pandas.DataFrame
        The user's columns, then the result columns [SI], same index and row order.

    Raises
    ------
    ValueError
        An unknown command; a frame the batch refuses as a whole, or an option value
        it refuses (one line, naming it); an unknown option name.

    Examples
    --------
    >>> import pandas as pd
    >>> out = command_frame("bearing", pd.DataFrame({"radial_load": ["5kN", "10kN"]}),
    ...                     rollers=14, pitch_diameter="70mm", roller_diameter="11mm",
    ...                     length="11mm")
    >>> [f"{q:.0f} N" for q in out["max_roller_load_N"]]
    ['1455 N', '2914 N']
    """
    from .command import Command
    from .subcommands import SUBCOMMANDS

    by_name = {m.name: m for m in SUBCOMMANDS}
    if command not in by_name:
        from ..errors import UnknownNameError
        raise UnknownNameError("command", command, sorted(by_name))
    table = Command(by_name[command])
    cases, client = _on_client(cases, client, "command_frame")
    _check_frame(cases, table.parameters, "command_frame", ["command", "cases", "client"],
                 options)
    return _run(table, cases, options, None, None, client)


def _check_frame(cases, parameters, func, keywords, options):
    import pandas as pd

    if not isinstance(cases, pd.DataFrame):
        raise TypeError(f"cases must be a pandas DataFrame, not {type(cases).__name__}")
    known = {p.name for p in parameters}
    unknown = sorted(set(options) - known)
    if unknown:
        from ..errors import UnknownKeywordError
        raise UnknownKeywordError(func, unknown[0], [*keywords, *sorted(known)])
    if isinstance(cases.columns, pd.MultiIndex):
        # every row failed as "radius: missing": the names were tuples
        raise ValueError(
            f"cases: columns of {cases.columns.nlevels} levels (e.g. "
            f"{cases.columns[0]!r}); valid: one level of names like the batch's columns "
            "(radius, length, ...): flatten them first, e.g. "
            "cases.columns = cases.columns.get_level_values(-1)")


def _run(table, cases, options, specs, model, client=None):
    """The batch of `table` (the calculator's or a subcommand's) on the frame's cells,
    JSON output (SI, full precision) read back into the frame's columns."""
    import pandas as pd

    from .batch import BatchError, run_batch

    if len(cases) == 0:  # no rows: no results, but the result columns all the same
        probe = pd.DataFrame({c: [None] for c in cases.columns})
        out = cases.copy()
        done = _run(table, probe, options, specs, model)
        for name in done.columns[len(cases.columns):]:
            out[name] = pd.Series([], index=cases.index, dtype=done[name].dtype)
        out.attrs["linecontact"] = done.attrs["linecontact"]
        return out
    header = [str(c) for c in cases.columns]
    opts = {p.name: (None if options.get(p.name) is None else _cell(options[p.name]))
            for p in table.parameters}
    with tempfile.TemporaryDirectory(prefix="linecontact-frame-") as folder:
        src, dst = Path(folder, "cases.csv"), Path(folder, "results.json")
        with open(src, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(header)
            for row in cases.itertuples(index=False, name=None):
                w.writerow([_cell(v) for v in row])
        args = argparse.Namespace(csv=str(src), model=model, progress=False, si=True,
                                  json=True, output=str(dst), plot=None, linear=False,
                                  client=client)
        # the batch's "N of M rows failed" line: the error column says it, row by row
        with contextlib.redirect_stderr(io.StringIO()):
            try:
                run_batch(args, [table.name, "<DataFrame>"], specs, opts, table)
            except BatchError as exc:  # said of the frame, not of the internal file
                raise BatchError(str(exc).replace(repr(str(src)), "cases (DataFrame)")
                                 ) from None
        doc = json.loads(dst.read_text(encoding="utf-8"))
    rows = doc.pop("rows")
    for r in rows:  # a conflict with a keyword, said as the frame's caller wrote it
        if r.get("error"):
            r["error"] = _keyword_words(r["error"])
    names = [k for k in rows[0] if k not in set(header)] if rows else []
    out = cases.copy()
    for name in names:
        values = [r.get(name) for r in rows]
        if all(v is None or isinstance(v, (int, float)) for v in values):
            values = [math.nan if v is None else float(v) for v in values]
            out[name] = pd.Series(values, index=cases.index, dtype=float)
        else:
            out[name] = pd.Series(["" if v is None else v for v in values],
                                  index=cases.index, dtype=object)
    out.attrs["linecontact"] = doc
    return out


_CONFLICT = re.compile(r"conflicts with --([a-z0-9-]+) (.*?) on the command line \(the "
                       r"option fills empty cells only; clear the cell or drop the "
                       r"option\); valid: the cell or --\1, not both")


def _keyword_words(text):
    """The batch's conflict between a cell and an option, in the words of a call:
    the keyword ``radial_load='5kN'`` of calc_frame/command_frame, not a command-line
    option ``--radial-load`` the caller never typed."""
    def words(m):
        name = m[1].replace("-", "_")
        return (f"conflicts with the keyword {name}={m[2]!r} (a keyword fills empty "
                f"cells only; clear the cell or drop the keyword); valid: the cell or "
                f"the keyword {name}, not both")
    return _CONFLICT.sub(words, text)
