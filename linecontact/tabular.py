"""Results as tables: a dict, a pandas DataFrame, or HTML for Jupyter.

The library's result objects (:class:`~linecontact.contact.ContactResult`,
:class:`~linecontact.contact.TangentialResult`,
:class:`~linecontact.contact.CreepResult`, :class:`~linecontact.roller.RollerSolution`,
:class:`~linecontact.raceway.RacewaySolution`, any dataclass documented the same way)
are read as a table: one row per load (or per time of a history), one column per output
that has one value per row, each column's unit taken from the result's own docstring
(the ``[N]`` of its Parameters entry), so that the unit shown is the one documented.
The result classes call these functions from ``to_dict``, ``to_frame`` and
``_repr_html_`` (a result displayed in Jupyter is this table, with pandas or
without).
"""
from __future__ import annotations

import dataclasses
import html
import inspect
import re

import numpy as np

__all__ = ["units_of", "table_columns", "to_dict", "to_frame", "html_table"]

_ENTRY = re.compile(r"^(\w+) : [^\n]*\n((?:[ \t]+[^\n]*\n?)+)", re.M)
_UNIT = re.compile(r"\[([^\[\]]+)\](?=[^\[\]]*$)")


def units_of(cls):
    """Field name -> unit, from the Parameters section of the class docstring.

    Parameters
    ----------
    cls : type
        A documented class (its docstring in numpydoc form).

    Returns
    -------
    dict
        Name -> the text between the brackets that ends its description (``"N"``,
        ``"m"``, ``"-"``); names without a unit are left out.

    Examples
    --------
    >>> from linecontact.contact import ContactResult
    >>> u = units_of(ContactResult)
    >>> u["force"], u["stiffness"], "model" in u
    ('N', 'N/m', False)
    """
    doc = inspect.getdoc(cls) or ""
    params = doc.split("Parameters\n----------\n", 1)
    if len(params) < 2:
        return {}
    section = re.split(r"\n\w[\w ]*\n-{3,}\n", params[1], maxsplit=1)[0] + "\n"
    units = {}
    for name, text in _ENTRY.findall(section):
        m = _UNIT.search(" ".join(text.split()))
        if m:
            units[name] = m.group(1)
    return units


def _fields(result):
    if dataclasses.is_dataclass(result):
        return [f.name for f in dataclasses.fields(result)]
    raise TypeError(f"not a result object: {type(result).__name__}")


def to_dict(result):
    """Every output of `result` by name (arrays as they are, nested results as dicts).

    Parameters
    ----------
    result : dataclass
        A result object of the library.

    Returns
    -------
    dict
        Field name -> value.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> d = to_dict(Contact(Roller(5e-3, 10e-3), estar=115.38e9).normal(force=1e3))
    >>> f"{d['depth'] * 1e6:.3f} um", d["model"]
    ('3.154 um', 'universal')
    """
    out = {}
    for name in _fields(result):
        v = getattr(result, name)
        out[name] = to_dict(v) if dataclasses.is_dataclass(v) else v
    return out


def table_columns(result):
    """The columns of `result` as a table: name -> 1-D array, all of one length.

    A field is a column when it is a number, a string or an array with one value per
    row (the length of the longest such field among force, depth, time and shift: the
    loads or the times); arrays of another length (q(x) along the roller) and nested
    results are not columns.

    Parameters
    ----------
    result : dataclass
        A result object of the library.

    Returns
    -------
    dict
        Column name -> ndarray (numbers float, text object), in field order.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9).normal(force=[1e3, 2e3])
    >>> cols = table_columns(c)
    >>> list(cols)[:3], len(cols["depth"])
    (['force', 'depth', 'approach'], 2)
    """
    values = {name: getattr(result, name) for name in _fields(result)}
    n = 1
    for key in ("force", "depth", "time", "shift", "tangential_force"):
        v = values.get(key)
        if v is not None and np.ndim(v) == 1:
            n = max(n, len(v))
    cols = {}
    for name, v in values.items():
        if v is None or dataclasses.is_dataclass(v) or isinstance(v, (dict, tuple)):
            continue
        if isinstance(v, str):
            cols[name] = np.full(n, v, dtype=object)
            continue
        a = np.asarray(v)
        if a.dtype.kind not in "biufUSO" or a.ndim > 1:
            continue
        if a.ndim == 0:
            a = np.full(n, a.item(), dtype=object if a.dtype.kind in "USO" else float)
        elif len(a) != n:
            continue
        cols[name] = a.astype(float) if a.dtype.kind in "biuf" else a.astype(object)
    return cols


def to_frame(result):
    """`result` as a pandas DataFrame (:func:`table_columns`), units in ``attrs``.

    Parameters
    ----------
    result : dataclass
        A result object of the library.

    Returns
    -------
    pandas.DataFrame
        One row per load or time; ``df.attrs["units"]``: column -> unit (SI).

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> df = to_frame(Contact(Roller(5e-3, 10e-3), estar=115.38e9).normal(force=[1e3, 2e3]))
    >>> df.shape[0], df.attrs["units"]["depth"]
    (2, 'm')
    """
    try:
        import pandas as pd
    except ImportError as exc:
        raise ImportError("to_frame needs pandas, which is not installed: pip install "
                          "'linecontact[pandas]' (or pip install pandas)") from exc
    cols = table_columns(result)
    df = pd.DataFrame(cols)
    units = units_of(type(result))
    df.attrs["units"] = {c: units[c] for c in cols if c in units}
    return df


def _fmt(v):
    if isinstance(v, float):
        return "-" if not np.isfinite(v) else f"{v:.6g}"
    return html.escape(str(v))


def html_table(result, max_rows=50):
    """`result` as an HTML table (``_repr_html_`` of the results): headings with units.

    Parameters
    ----------
    result : dataclass
        A result object of the library.
    max_rows : int
        Rows shown, 1 <= max_rows; the first and last halves of a longer table [-].

    Returns
    -------
    str
        An HTML ``<table>``, then the result's notes, if any.

    Notes
    -----
    Numbers are shown in SI with 6 significant digits; pandas is not needed.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> text = html_table(Contact(Roller(5e-3, 10e-3), estar=115.38e9).normal(force=1e3))
    >>> "<th>depth [m]</th>" in text, "<td>3.15448e-06</td>" in text
    (True, True)
    """
    cols = table_columns(result)
    units = units_of(type(result))
    names = list(cols)
    n = len(next(iter(cols.values()))) if cols else 0
    keep = list(range(n))
    if n > max_rows:
        h = max(1, max_rows // 2)
        keep = list(range(h)) + [None] + list(range(n - h, n))
    head = "".join(f"<th>{html.escape(c)}" + (f" [{html.escape(units[c])}]"
                                              if c in units else "") + "</th>"
                   for c in names)
    body = []
    for i in keep:
        if i is None:
            body.append("<tr>" + "<td>...</td>" * len(names) + "</tr>")
            continue
        body.append("<tr>" + "".join(f"<td>{_fmt(cols[c][i])}</td>" for c in names)
                    + "</tr>")
    text = (f"<table><caption>{html.escape(type(result).__name__)}</caption>"
            f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>")
    notes = getattr(result, "notes", ()) or ()
    reasons = getattr(result, "reasons", {}) or {}
    extra = [html.escape(str(t)) for t in notes]
    extra += [f"{html.escape(k)}: not defined ({html.escape(str(r[1]))})"
              for k, r in reasons.items()]
    if extra:
        text += "<ul>" + "".join(f"<li>{t}</li>" for t in extra) + "</ul>"
    return text
