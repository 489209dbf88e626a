"""Renderers of the calculator's results: the plain-text table, JSON, CSV cells.

The columns come from :mod:`linecontact.calc.compute` (the core's
:data:`~linecontact.calc.compute.FIELDS` and the features' ``fields``); the notes and
extra tables (blocks) from the active features: a new feature shows up here without a
change. Engineering units by
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

from .compute import CONTACT_COLUMNS, P0_NOTE, all_fields, model_id
from .features import FEATURES

__all__ = ["PROG", "FIELDS", "NOTES", "fmt", "unit", "scale", "columns_of", "json_header",
           "table_text", "blocks_text", "swept_inputs", "one_json", "num", "aligned", "write",
           "clean_json", "command_text", "refuse_same_output"]

#: Every output column (the core's and the features').
FIELDS = all_fields()

PROG = "linecontact"

NOTES = {
    "peak_pressure": P0_NOTE,
    "deviation": "deviation: this model's depth (its force when the depth is given; the "
                 "roller deflection for a whole roller) over that of the default best "
                 "estimate (the first model of the standard set), minus 1.",
    "flags": "flags: the row's geometry is outside what the models cover: d > 0.15 R "
             "(beyond the range of the BEM study behind the tables and the parabolic "
             "gap) or Hertz half-width b > L/2 (not a line contact).",
}
for _f in FEATURES:
    NOTES.update(_f.notes)


def fmt(value, digits=4):
    """A number for the table: 4 significant digits, '-' for none."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}g}"


def _fmt_column(values):
    """:func:`fmt` of every element of a float array (a list of str), round-off shown
    as 0 (:func:`linecontact._units.format_numbers`)."""
    from .._units import format_numbers

    return format_numbers(values)


def unit(field, si):
    """Unit of a field's column: SI or engineering."""
    f = FIELDS[field]
    return f.si if si else f.eng


def column_unit(field, values, si):
    """(factor from SI, unit) of a field's column holding the SI `values`: SI with
    `si`, else the field's engineering unit where the values read well in it, or the
    SI prefix that fits them (:func:`linecontact._units.display_unit`: a soft
    contact's force in mN, not 0.0001 kN)."""
    from .._units import display_unit

    f = FIELDS[field]
    if si:
        return 1.0, f.si
    return display_unit(values, f.si, f.eng, f.factor)


def scale(field, value, si):
    """A field's value(s) in the column's unit."""
    return value if si else value * FIELDS[field].factor


def columns_of(results, given):
    """The numeric columns, in order: the whole-body columns (with the force) when any
    row is one; the single-contact columns (the given quantity first) when any row is
    one; the features' columns; the deviation only when it compares two models."""
    cols = []
    if results.whole:
        cols += ["force"] + list(results.whole_columns)
    if results.contact or not results.whole:
        first = "force" if given == "load" else "depth"
        second = "depth" if first == "force" else "force"
        cols += [first, second] + [c for c in CONTACT_COLUMNS
                                   if c not in ("force", "depth", "deviation")]
    seen = []
    for c in cols + list(results.extra):
        if c not in seen:
            seen.append(c)
    if results.deviation:
        seen.append("deviation")
    return seen


def _version():
    try:
        from .. import __version__
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


def json_header(argv, results, fields=None, notes=None):
    """The one JSON header of every command (see the module docstring); `fields` and
    `notes`: a subcommand's own (default: the calculator's)."""
    return {
        "linecontact_version": _version(),
        "command": [PROG] + list(argv),
        "units": {name: f.si for name, f in (FIELDS if fields is None else fields).items()},
        "notes": dict(NOTES if notes is None else notes),
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
    """The case in one line: R (and R2, R eff), L, L/R, E* (and moduli), then the given
    inputs of the active features as typed."""

    def q(field, key):
        value = float(cases[key][0])
        factor, u = column_unit(field, value, si)
        return f"{fmt(value * factor)} {u}"

    line = f"R = {q('radius', 'radius')}"
    if present["radius2"][0]:
        line += f", R2 = {q('radius', 'radius2')}"
    if cases.radius_eff[0] != cases.radius[0]:
        line += f" (R eff = {q('radius_eff', 'radius_eff')})"
    L_over_R = float(cases.length[0] / cases.radius_eff[0])
    line += f", L = {q('length', 'length')}, L/R = {fmt(L_over_R)}, E* = {q('estar', 'estar')}"
    if present["modulus"][0] or present["poisson"][0]:
        line += " ("
        if present["modulus"][0]:
            line += f"E1 = {q('estar', 'modulus')}, "
        line += f"nu1 = {fmt(float(cases['poisson'][0]))}; "
        if present["modulus2"][0]:
            line += f"E2 = {q('estar', 'modulus2')}, nu2 = {fmt(float(cases['poisson2'][0]))})"
        else:
            line += "rigid roller)"
    given = []
    for f, _ in cases.active():
        for p in f.parameters:
            if present[p.name][0]:
                typed = _typed(cases, p.name)
                if typed is not None:
                    given.append(f"{p.name.replace('_', ' ')} {typed}")
    if given:
        line += "; " + ", ".join(given)
    return line


def _typed(cases, name):
    """A parameter's cell in the first row as typed, or None where it varies (a sweep:
    its values are in the table)."""
    col = cases.cells.get(name)
    if col is None:
        return None
    if isinstance(col, np.ndarray):
        return None if len(col) > 1 and np.any(col != col[0]) else fmt(float(col[0]))
    if len(set(col)) > 1:
        return None
    return col[0].strip()


#: Units of a swept input in the table: kind -> (engineering unit, factor from SI).
_INPUT_UNITS = {"length": ("mm", 1e3), "force": ("kN", 1e-3), "pressure": ("GPa", 1e-9),
                "moment": ("N m", 1.0),
                "angle": ("mrad", 1e3), "time": ("s", 1.0), "dimensionless": ("-", 1.0),
                "surface_energy": ("mJ/m^2", 1e3), "angular_speed": ("rpm", 30 / math.pi),
                "kinematic_viscosity": ("cSt", 1e6), "density": ("kg/m^3", 1.0),
                "inverse_pressure": ("1/Pa", 1.0), "temperature_difference": ("K", 1.0),
                "count": ("-", 1.0)}


def swept_inputs(cases, shown=None):
    """The inputs that vary between the rows of a sweep and are not an output column
    already (e.g. the tilt of a load x tilt grid): [(Parameter, SI array)]. `shown`:
    the output columns printed (default: every field; a swept radius or length, fields
    the table does not print, then gets no column and its rows could not be told
    apart)."""
    from .cases import PARAMETERS

    shown = FIELDS if shown is None else shown
    out = []
    for p in PARAMETERS:
        col = cases.cells.get(p.name)
        if (isinstance(col, np.ndarray) and p.name not in ("load", "depth")
                and p.name not in shown and len(col) > 1 and np.any(col != col[0])):
            out.append((p, col))
    return out


def table_text(cases, present, results, si):
    """Plain-text table of one case or a sweep: one row per model and value (a swept
    input that is not an output gets its own column), then the features' notes and
    extra tables."""
    from .._units import DIMENSIONS

    given = str(cases.given[0])
    cols = columns_of(results, given)
    swept = swept_inputs(cases, cols)
    heads = []
    for p, _ in swept:
        u = DIMENSIONS[p.kind][1] if si else _INPUT_UNITS[p.kind][0]
        heads.append(f"{p.name.replace('_', ' ')} [{u or '-'}]")
    # each column's unit fits its values (over every model's rows)
    shown = {c: column_unit(c, np.concatenate([np.ravel(s["fields"][c]).astype(float)
                                               for s in results.sets]), si)
             for c in cols} if results.sets else {c: (1.0, unit(c, si)) for c in cols}
    header = (["model"] + heads + [f"{FIELDS[c].heading} [{shown[c][1]}]" for c in cols]
              + ["note"])
    n = cases.n
    columns = [[] for _ in range(len(header))]  # column-wise: fast for a long sweep
    for s in results.sets:
        f = s["fields"]
        columns[0].extend(s["label"][:n].tolist())
        for k, (p, col) in enumerate(swept, start=1):
            columns[k] += _fmt_column(col if si else col * _INPUT_UNITS[p.kind][1])
        for k, c in enumerate(cols, start=1 + len(swept)):
            columns[k] += _fmt_column(np.asarray(f[c], float) * shown[c][0])
        columns[-1] += ["; ".join(t for t in (a, b) if t) for a, b in zip(s["flags"], s["note"])]
    lines = [_case_line(cases, present, si), ""]
    lines += aligned([header] + [list(r) for r in zip(*columns)])
    lines += ["", "Note: " + P0_NOTE]
    for f in results.features:
        lines += ["Note: " + t for t in f.notes.values() if not _block_note(results, t)]
    return "\n".join(lines) + "\n" + blocks_text(results.blocks, given, si)


def _block_note(results, text):
    """Whether a block prints `text` under its own table (a block without rows, e.g.
    the profiled roller's q(x) for --json only, prints no table and no note)."""
    return any(b.note == text and any(r is not None for r in b.rows)
               for b in results.blocks)


def blocks_text(blocks, given, si):
    """The features' extra tables (e.g. the profiled roller's rows), each after its
    rows' note; blocks of one name share one table."""
    from .._units import NOISE, display_unit, format_numbers

    out = ""
    names = []
    for b in blocks:
        if b.name not in names:
            names.append(b.name)
    for name in names:
        group = [b for b in blocks if b.name == name]
        fields = group[0].fields
        first = "force" if given == "load" else "depth"
        cols = ([first] if first in fields else []) + [c for c in fields if c != first]
        rows = [(b, row) for b in group for row in b.rows if row is not None]
        shown = {}  # each column's unit fits its values
        values = {}
        for c in cols:
            vals = [np.nan if row.get(c) is None else float(row[c]) for _, row in rows]
            size = group[0].scales.get(c)
            if size is not None:  # round-off of its quantity's scale: 0 (the unit too)
                vals = [0.0 if abs(v) <= NOISE * abs(size) else v for v in vals]
            values[c] = vals
            shown[c] = ((1.0, fields[c].si) if si else
                        display_unit(vals, fields[c].si, fields[c].eng, fields[c].factor))
        cells_of = {c: format_numbers([v * shown[c][0] for v in values[c]]) for c in cols}
        header = [group[0].label] + [
            f"{fields[c].heading} [{shown[c][1]}]" for c in cols
        ] + list(group[0].text_columns) + ["note"]
        table = []
        for i, (b, row) in enumerate(rows):
            cells = [row.get("label", "")] + [cells_of[c][i] for c in cols]
            cells += [row.get("text", {}).get(t, "-") for t in b.text_columns]
            table.append(cells + [row.get("note", "")])
        if not table:
            continue
        out += "\n".join([""] + aligned([header] + table) + ["", "Note: " + group[0].note])
        out += "\n"
    return out


def aligned(rows):
    """Lines of a plain-text table: the first column left-aligned, the numeric ones
    right-aligned to their widest cell, the last (a note) left as it is."""
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]) - 1)]
    lines = []
    for r in rows:
        cells = [r[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(r[1:-1], widths[1:])]
        lines.append("  ".join(cells + [r[-1]]).rstrip())
    return lines


def num(v):
    """A JSON number: the float, or None (null) for none, NaN or inf."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def one_json(argv, cases, present, results):
    """JSON of one case or a sweep: the header, the inputs [SI], rows per model, and
    the features' blocks (each under its name, e.g. ``profiled_roller``)."""
    import json

    given = str(cases.given[0])
    cols = columns_of(results, given)
    inputs = {k: float(cases[k][0]) for k in ("radius", "radius_eff", "length", "estar")}
    for name in present:
        if name in inputs or name in ("diameter", "load", "depth") or not present[name][0]:
            continue
        col = cases[name]
        if isinstance(col, np.ndarray):
            vals = [float(x) for x in col]
            inputs[name] = vals if len(set(vals)) > 1 else vals[0]
        else:
            inputs[name] = col[0].strip()
    values = [float(v) for v in cases.value]
    inputs[given] = values if len(values) > 1 else values[0]
    doc = json_header(argv, results)
    doc["inputs"] = inputs
    entries = []
    for entry, s in zip(_entries(doc["models"], results), results.sets):
        rows = []
        for i in range(len(values)):
            row = {c: num(s["fields"][c][i]) for c in cols}
            row["flags"] = s["flags"][i]
            row["note"] = s["note"][i]
            rows.append(row)
        entries.append(dict(entry, rows=rows))
    doc["models"] = entries
    for b in results.blocks:
        label = next((r["label"] for r in b.rows if r and r.get("label")), b.label)
        doc.setdefault(b.name, []).append({"label": label, "rows": b.json_rows,
                                           "units": dict(b.units)})
    return json.dumps(doc, indent=2) + "\n"


def clean_json(x):
    """JSON-safe: NaN and infinities (an edge-loaded roller's peak pressure, an
    infinite life) become null, numpy scalars and arrays plain numbers and lists."""
    if isinstance(x, dict):
        return {str(k): clean_json(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [clean_json(v) for v in x]
    if isinstance(x, np.ndarray):
        return clean_json(x.tolist())
    if hasattr(x, "item") and not isinstance(x, (str, bytes)):
        x = x.item()
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def command_text(command, cases, results, si):
    """Plain text of a subcommand (:class:`linecontact.calc.command.Command`): one
    case as its description, its fields one per line and the module's tables (its
    blocks); a sweep as one row per case (the swept inputs, then the fields); then the
    command's notes and each case's own."""
    from .._units import DIMENSIONS, format_numbers

    module, fields = command.module, command.fields
    n = cases.n
    lines = []
    if n == 1:
        obj, row = results.objects[0], results.rows[0]
        lines += [module.describe(obj, si), f"model: {row.get('model_used', '')}", ""]
        table = []
        optional = getattr(module, "optional", ())
        # round-off (an aligned bearing's K_rt) as 0 against its quantity's scale
        sizes = module.scales(obj) if hasattr(module, "scales") else {}
        for name, f in fields.items():
            v = row.get(name)
            if v is None and name in optional:
                continue  # an output asked for by its options only (the case check)
            k = 1.0 if si else f.factor
            size = sizes.get(name)
            table.append([f"  {f.heading}",
                          "-" if v is None else format_numbers(
                              [v * k], scale=None if size is None else size * k)[0],
                          f.si if si else f.eng])
        lines += aligned(table)
        text = blocks_text(module.blocks(obj), "load", si)
        lines += text.rstrip("\n").split("\n") if text else []
    else:
        swept = []
        for p in command.parameters:
            col = cases.cells.get(p.name)
            if isinstance(col, np.ndarray) and len(col) > 1 and np.any(col != col[0]):
                swept.append((p, col))
        shown = [k for k in fields if any(r is not None and r.get(k) is not None
                                          for r in results.rows)]
        header = (["case"] + [f"{p.name.replace('_', ' ')} ["
                              f"{(DIMENSIONS[p.kind][1] if si else _INPUT_UNITS[p.kind][0]) or '-'}]"
                              for p, _ in swept]
                  + [f"{fields[k].heading} [{fields[k].si if si else fields[k].eng}]"
                     for k in shown] + ["note"])
        table = [header]
        for i in range(n):
            row = results.rows[i] or {}
            cells = [str(i + 1)]
            cells += [fmt(float(col[i]) if si else float(col[i]) * _INPUT_UNITS[p.kind][1])
                      for p, col in swept]
            obj = results.objects[i]
            sizes = (module.scales(obj) if obj is not None and hasattr(module, "scales")
                     else {})
            for k in shown:
                v = row.get(k)
                f = 1.0 if si else fields[k].factor
                size = sizes.get(k)
                cells.append("-" if v is None else format_numbers(
                    [v * f], scale=None if size is None else size * f)[0])
            table.append(cells + [row.get("note", "")])
        lines += aligned(table)
    # a note on an output no row computed (the flanges' without an axial load) is
    # left out of the text; the JSON header keeps them all
    needs = getattr(module, "note_fields", {})
    lines += [""] + [f"Note: {t}" for k, t in command.notes.items()
                     if k not in needs or any(r and r.get(needs[k]) is not None
                                              for r in results.rows)]
    if n == 1:
        lines += [f"Note: {t}" for t in results.rows[0].get("notes", ())]
    return "\n".join(lines) + "\n"


def _entries(model_docs, results):
    """The header entry of each column set (a refused model: its text, no provenance)."""
    by_id = {m["id"]: m for m in model_docs}
    out = []
    for s in results.sets:
        model = s.get("model")
        m = by_id.get(model_id(model) if model is not None else s["id"])
        if m is None:
            label = s["label"][0] or s["id"]
            m = {"key": s.get("key") or label, "label": label, "id": s["id"],
                 "provenance": None}
        out.append(m)
    return out


def write(text, path):
    """Write `text` to stdout or to the file `path` (errors name the file).

    The file is written atomically: into a temporary file beside it, renamed onto
    `path` only once complete (``os.replace``), so an interrupted or failed run
    leaves the old file, or none, never a partial one.
    """
    import os
    import sys
    import tempfile

    if path is None:
        sys.stdout.write(text)
        sys.stdout.flush()  # a closed pipe shows here, inside main's error handling
        return
    tmp = None
    try:
        folder = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".",
                                   suffix=".part", dir=folder)
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # as open() would create it, not mkstemp's 0600
        os.replace(tmp, path)
        tmp = None
    except (OSError, ValueError) as exc:  # ValueError: an embedded NUL in the path
        raise OutputError(path, exc) from None
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


def refuse_input_as_output(output, inputs):
    """Raise :class:`OutputError` if the output file `output` is one of the `inputs`
    (the CSV batch, a Prony file, ...): writing it would destroy the input. Compared
    as files (same inode where both exist, else the same absolute path)."""
    import os

    if output is None:
        return
    for name in inputs:
        if not name:
            continue
        try:
            same = (os.path.samefile(output, name) if os.path.exists(output)
                    and os.path.exists(name)
                    else os.path.abspath(output) == os.path.abspath(name))
        except (OSError, ValueError):
            continue
        if same:
            raise OutputError(output, ValueError(
                f"-o names the input file {str(name)!r}, which would be overwritten; "
                "give another output file"))


def refuse_same_output(output, plot):
    """Raise :class:`OutputError` if ``-o`` and ``--plot`` name the same file (the
    figure would overwrite the table, or the table the figure): compared as files (same
    inode where it exists, else the same absolute path), before anything is written."""
    import os

    if output is None or plot is None:
        return
    try:
        same = (os.path.samefile(output, plot) if os.path.exists(output)
                and os.path.exists(plot) else
                os.path.abspath(output) == os.path.abspath(plot))
    except (OSError, ValueError):
        return
    if same:
        raise OutputError(plot, ValueError(
            f"--plot names the -o file {str(output)!r}; the figure would overwrite the "
            "table: give two different files"))


def refuse_json_only(parameters, given, json, label=None):
    """Raise :class:`~linecontact._units.InputError` if an input whose result goes to
    the ``--json`` output only (:attr:`Parameter.json_only`) is given without
    ``--json``: it would be computed and written nowhere. `given`: parameter name ->
    what was given (the option's text, or for a CSV batch its first filled cell), None
    where not given; `label`: name -> the input as the user named it (default: the
    option)."""
    if json:
        return
    from .._units import InputError
    from .feature import option_name

    for p in parameters:
        if p.json_only and given.get(p.name) is not None:
            raise InputError((label or option_name)(p.name), given[p.name],
                             f"with --json ({p.json_only} is written to the JSON "
                             "output only)",
                             "no --json: it would not be written anywhere")


class OutputError(OSError):
    """The output file cannot be written: names the file and the reason."""

    def __init__(self, path, exc):
        reason = getattr(exc, "strerror", None) or str(exc) or type(exc).__name__
        super().__init__(f"cannot write the output file {str(path)!r}: {reason}")
