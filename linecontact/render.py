"""Renderers of the calculator's results: the plain-text table, JSON, CSV cells.

The columns come from :mod:`linecontact.compute` (:data:`~linecontact.compute.FIELDS`,
:data:`~linecontact.compute.CONTACT_COLUMNS`, :data:`~linecontact.compute.ROLLER_COLUMNS`):
a new output quantity listed there shows up here without a change. Engineering units by
default (F in kN, lengths in um, k in N/um, p0 in MPa, moduli in GPa, R and L in mm),
SI with ``--si``; JSON is always SI.

The JSON document has one header, written by :func:`json_header` for every command:
``linecontact_version``, ``command`` (argv as typed), ``units`` (SI unit of every
field), ``notes`` (what p0, the flags and the deviation mean), and ``models`` (key,
label, column id and provenance of every model that produced a value).
"""

from __future__ import annotations

import math

import numpy as np

from .calc_tangential import NOTES as _TANGENTIAL_NOTES
from .compute import CONTACT_COLUMNS, FIELDS, P0_NOTE, ROLLER_COLUMNS, _model_id

__all__ = ["PROG", "fmt", "unit", "scale", "columns_of", "json_header", "table_text",
           "one_json", "write"]

PROG = "linecontact"

NOTES = {
    "peak_pressure": P0_NOTE,
    "deviation": "deviation: this model's depth (its force when the depth is given; the "
                 "roller deflection for a whole roller) over that of the default best "
                 "estimate (the first model of the standard set), minus 1.",
    "flags": "flags: the row's geometry is outside what the models cover: d > 0.15 R "
             "(beyond the range of the BEM study behind the tables and the parabolic "
             "gap) or Hertz half-width b > L/2 (not a line contact).",
    "tangential": _TANGENTIAL_NOTES["tangential"],
    "creep": _TANGENTIAL_NOTES["creep"],
    "roller": "whole roller: roller_deflection = d(inner contact) + d(outer contact) at "
              "the same force, roller_stiffness the two contacts in series; depth_inner "
              "and depth_outer are the two contacts' own depths (what a single-contact "
              "row reports as its depth).",
}


def fmt(value, digits=4):
    """A number for the table: 4 significant digits, '-' for none."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}g}"


def _fmt_column(values):
    """:func:`fmt` of every element of a float array (a list of str)."""
    return [format(v, ".4g") if v == v else "-" for v in np.asarray(values, float).tolist()]


def unit(field, si):
    """Unit of a field's column: SI or engineering."""
    f = FIELDS[field]
    return f.si if si else f.eng


def scale(field, value, si):
    """A field's value(s) in the column's unit."""
    return value if si else value * FIELDS[field].factor


def columns_of(results, given):
    """The numeric columns, in order: the given quantity first; roller columns when
    any row is a whole roller; the deviation only when it compares two models."""
    cols = []
    if results.roller:
        cols += [c for c in ROLLER_COLUMNS if c != "deviation"]
    if not results.roller or _any_contact(results):
        first = "force" if given == "load" else "depth"
        second = "depth" if first == "force" else "force"
        cols += [first, second] + [c for c in CONTACT_COLUMNS
                                   if c not in ("force", "depth", "deviation")]
    seen = []
    for c in cols:
        if c not in seen:
            seen.append(c)
    seen += [c for c in getattr(results, "extra", []) if c not in seen]
    if results.deviation:
        seen.append("deviation")
    return seen


def _any_contact(results):
    f = results.sets[0]["fields"] if results.sets else None
    return f is not None and bool(np.any(np.isfinite(f["depth"])))


def _version():
    try:
        from . import __version__
    except ImportError:
        from importlib.metadata import version

        return version("linecontact")
    return __version__


def _jsonable(obj):
    """Provenance dicts may hold numpy scalars or paths: make them JSON-safe."""
    if obj is None or isinstance(obj, (bool, int, str)):
        return obj
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    try:
        return _jsonable(obj.item())  # numpy scalar
    except AttributeError:
        return str(obj)


def json_header(argv, results):
    """The one JSON header of every command (see the module docstring)."""
    return {
        "linecontact_version": _version(),
        "command": [PROG] + list(argv),
        "units": {name: f.si for name, f in FIELDS.items()},
        "notes": dict(NOTES),
        "models": [
            {
                "key": m.key,
                "label": m.label,
                "id": mid,
                "provenance": _jsonable(getattr(m, "provenance", None)),
            }
            for mid, m in results.models.items()
        ],
    }


def _case_line(cases, present, si):
    """The case in one line: R (and R2, R eff, raceways), L, L/R, E* (and moduli)."""

    def q(field, key):
        return f"{fmt(scale(field, float(cases[key][0]), si))} {unit(field, si)}"

    line = f"R = {q('radius', 'radius')}"
    if present["radius2"][0]:
        line += f", R2 = {q('radius', 'radius2')} (R eff = {q('radius_eff', 'radius_eff')})"
    if cases["raceways"][0]:
        line += (f", inner raceway {q('radius', 'inner_raceway')}, outer raceway "
                 f"{q('radius', 'outer_raceway')}")
    L_over_R = float(cases["length"][0] / cases["radius_eff"][0])
    line += f", L = {q('length', 'length')}, L/R = {fmt(L_over_R)}, E* = {q('estar', 'estar')}"
    material = cases.get("material")
    body = material[0] if material is not None else None
    if present["modulus"][0] or body is not None:
        if body is None:
            line += f" (E1 = {q('estar', 'modulus')}, "
        elif present["prony"][0]:
            line += (f" at t = 0 (viscoelastic body: Prony series of {body.moduli.size} "
                     f"terms, E0 = {fmt(body.instantaneous * (1 if si else 1e-9))} "
                     f"{unit('estar', si)}, E_inf = "
                     f"{fmt(body.long_term * (1 if si else 1e-9))} {unit('estar', si)}, ")
        else:
            line += (f" at t = 0 (viscoelastic body: E0 = {q('estar', 'instantaneous_modulus')}"
                     f", E_inf = {q('estar', 'long_term_modulus')}, tau = "
                     f"{fmt(float(cases['relaxation_time'][0]))} s, ")
        line += f"nu1 = {fmt(float(cases['poisson'][0]))}; "
        if present["modulus2"][0]:
            line += f"E2 = {q('estar', 'modulus2')}, nu2 = {fmt(float(cases['poisson2'][0]))})"
        else:
            line += "rigid roller)"
    if present["friction"][0]:
        line += f", mu = {fmt(float(cases['friction'][0]))}"
    return line


def table_text(cases, present, results, si):
    """Plain-text table of one case or a sweep: one row per model and value."""
    given = str(cases["given"][0])
    cols = columns_of(results, given)
    header = ["model"] + [f"{FIELDS[c].heading} [{unit(c, si)}]" for c in cols] + ["note"]
    n = len(cases["value"])
    columns = [[] for _ in range(len(header))]  # column-wise: fast for a long sweep
    for s in results.sets:
        f = s["fields"]
        columns[0].extend(s["label"][:n].tolist())
        for k, c in enumerate(cols, start=1):
            columns[k] += _fmt_column(scale(c, f[c], si))
        columns[-1] += ["; ".join(t for t in (a, b) if t) for a, b in zip(s["flags"], s["note"])]
    lines = [_case_line(cases, present, si), ""]
    lines += aligned([header] + [list(r) for r in zip(*columns)])
    lines += ["", "Note: " + P0_NOTE]
    if results.roller:
        lines.append("Note: " + NOTES["roller"])
    extra = getattr(results, "extra", [])
    if any(c.startswith(("kt_", "shift_")) for c in extra):
        lines.append("Note: " + NOTES["tangential"])
    if "depth_long_term" in extra:
        lines.append("Note: " + NOTES["creep"])
    return "\n".join(lines) + "\n"


def aligned(rows):
    """Lines of a plain-text table: the first column left-aligned, the numeric ones
    right-aligned to their widest cell, the last (a note) left as it is."""
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]) - 1)]
    lines = []
    for r in rows:
        cells = [r[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(r[1:-1], widths[1:])]
        lines.append("  ".join(cells + [r[-1]]).rstrip())
    return lines


def _num(v):
    """A JSON number: the float, or None (null) for none, NaN or inf."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def one_json(argv, cases, present, results, extra=None):
    """JSON of one case or a sweep: the header, the inputs [SI], rows per model.

    `extra`: further top-level entries (e.g. ``profiled_roller`` of
    :mod:`linecontact.calc_roller`)."""
    import json

    given = str(cases["given"][0])
    cols = columns_of(results, given)
    inputs = {
        k: float(cases[k][0])
        for k in ("radius", "radius2", "radius_eff", "length", "estar", "modulus", "poisson",
                  "modulus2", "poisson2", "inner_raceway", "outer_raceway", "friction",
                  "instantaneous_modulus", "long_term_modulus", "relaxation_time")
        if k in ("radius", "radius_eff", "length", "estar") or present[k][0]
    }
    if present["prony"][0]:
        m = cases["material"][0]
        inputs["prony"] = None if m is None else {
            "long_term_modulus": m.long_term, "moduli": m.moduli.tolist(),
            "times": m.times.tolist()}
    for k in ("tangential_load", "time"):
        if present[k][0]:
            vals = [float(x) for x in cases[k]]
            inputs[k] = vals if len(set(vals)) > 1 else vals[0]
    values = [float(v) for v in cases["value"]]
    inputs[given] = values if len(values) > 1 else values[0]
    doc = json_header(argv, results)
    doc["inputs"] = inputs
    entries = []
    for entry, s in zip(_entries(doc["models"], results), results.sets):
        rows = []
        for i in range(len(values)):
            row = {c: _num(s["fields"][c][i]) for c in cols}
            row["flags"] = s["flags"][i]
            row["note"] = s["note"][i]
            rows.append(row)
        entries.append(dict(entry, rows=rows))
    doc["models"] = entries
    if extra:
        doc.update(extra)
    return json.dumps(doc, indent=2) + "\n"


def _entries(model_docs, results):
    """The header entry of each column set (a refused model: its text, no provenance)."""
    by_id = {m["id"]: m for m in model_docs}
    out = []
    for s in results.sets:
        model = s.get("model")
        m = by_id.get(_model_id(model) if model is not None else s["id"])
        if m is None:
            label = s["label"][0] or s["id"]
            m = {"key": label, "label": label, "id": s["id"], "provenance": None}
        out.append(m)
    return out


def write(text, path):
    """Write `text` to stdout or to the file `path` (errors name the file)."""
    import sys

    if path is None:
        sys.stdout.write(text)
        sys.stdout.flush()  # a closed pipe shows here, inside main's error handling
        return
    try:
        with open(path, "w", encoding="utf-8", newline="") as fh:
            fh.write(text)
    except (OSError, ValueError) as exc:  # ValueError: an embedded NUL in the path
        raise OutputError(path, exc) from None


class OutputError(OSError):
    """The output file cannot be written: names the file and the reason."""

    def __init__(self, path, exc):
        reason = getattr(exc, "strerror", None) or str(exc) or type(exc).__name__
        super().__init__(f"cannot write the output file {str(path)!r}: {reason}")
