"""Command line: ``linecontact calc``, a spreadsheet-like calculator for one case, a
sweep, or a CSV file of cases.

Usage (``linecontact calc --help`` has the full list)::

    linecontact calc --radius 5mm --length 10mm --modulus 210GPa --poisson 0.3 --load 1kN
    linecontact calc --radius 5mm --length 10mm --estar 115GPa --depth 2um
    linecontact calc ... --load 0.1kN:10kN:20          # sweep, geometric spacing
    linecontact calc ... --load 100N:1kN:10 --linear   # sweep, linear spacing
    linecontact calc cases.csv -o results.csv          # batch, one case per row
    linecontact calc ... --json                        # machine-readable, SI
    linecontact calc ... --model li-popov:coefficients=eq11,johnson:c=0.72

Inputs
    Values may carry a unit ("5mm", "0.2 in", "210 GPa", "1kN"), parsed by pint and
    checked for their dimension; bare numbers are SI (m, N, Pa). The second body
    (``--modulus2``, ``--poisson2``) is rigid when omitted; ``--estar`` gives the
    effective modulus of Eq. 3 directly (E*, not E' = 2E*).

Output
    A table with one row per model of :func:`linecontact.models.standard_models` (in its
    order: the default best estimate first), or of ``--model``, and per value of a
    sweep. Columns: the given F or d, the other one, the stiffness k = dF/dd, the Hertz
    half-width b of Eq. 1 (at that F), the MDR contact half-length a = k/(2E*), and a
    note with the model's own message when the case is outside its validity range (its
    values are then "-"; the other rows are unaffected). Engineering units (F in kN,
    lengths in um, k in N/um, moduli in GPa, R and L in mm), or SI with ``--si``.
    ``--json`` is always SI and carries the package version, the command, and each
    model's provenance (table metadata for the table-backed ones).

Sweeps
    ``--load START:STOP:N`` (or ``--depth``): N values from START to STOP, both
    included, spaced geometrically (equal ratios, right for loads over decades);
    ``--linear`` spaces them evenly.

Batch
    ``linecontact calc FILE.csv`` reads one case per row (columns radius, length,
    modulus, poisson, modulus2, poisson2, estar, load, depth; cells may carry units;
    other columns are passed through; options given on the command line fill empty or
    missing columns; header names are case-insensitive). It writes the same rows, cells
    unchanged, with result columns appended: ``estar_GPa``, ``model``, ``force_kN``,
    ``depth_um``, ``stiffness_N_per_um``, ``half_width_um``, ``contact_radius_um``,
    ``note``, ``error`` (SI names such as ``depth_m`` with ``--si`` or ``--json``).
    The model is the default best estimate, the first of the standard set (the
    universal curve when installed, else Li-Popov Table 1), unless ``--model`` names
    others; with several (or ``all``) each result column gets the model's id as a
    suffix (``depth_um_johnson-c-0.72``). Result columns already in the file (a rerun
    on its own output) are replaced. A row that cannot be computed keeps its place and
    says why in ``error``; a row outside the model's range says so in ``note``.

Exit status: 0 on success, 2 on bad input (one line on stderr naming the parameter,
its value and the valid range; in a batch, when any row failed, after writing all
rows). A one-case call where no model covers the case prints the table and the first
model's note on stderr, status 2.

Nothing here runs at import; heavy modules (numpy, scipy, pandas, pint) are imported
only by the code paths that need them, so a one-case call starts quickly.
"""

from __future__ import annotations

import argparse
import math
import re
import sys

__all__ = ["main"]

PROG = "linecontact"

#: Case parameters: option/column name -> (kind, help).
CASE_PARAMETERS = {
    "radius": ("length", "cylinder radius R"),
    "length": ("length", "cylinder length L"),
    "modulus": ("pressure", "Young's modulus E1 of the half-space"),
    "poisson": ("dimensionless", "Poisson's ratio nu1 of the half-space"),
    "modulus2": ("pressure", "Young's modulus E2 of the cylinder (default: rigid)"),
    "poisson2": ("dimensionless", "Poisson's ratio nu2 of the cylinder"),
    "estar": ("pressure", "effective modulus E* of Eq. 3 (instead of the moduli)"),
    "load": ("force", "normal force F, or a sweep START:STOP:N"),
    "depth": ("length", "indentation depth d (rigid-body approach), or a sweep START:STOP:N"),
}


def _poisson_bounds():
    """(inside, text) for Poisson's ratio, from the library's own range."""
    from .validity import POISSON_RATIO

    return (lambda v: bool(POISSON_RATIO.contains(v)), POISSON_RATIO.describe())


#: Output units: name -> (SI unit, engineering unit, factor SI -> engineering).
UNITS = {
    "force": ("N", "kN", 1e-3),
    "depth": ("m", "um", 1e6),
    "stiffness": ("N/m", "N/um", 1e-6),
    "half_width": ("m", "um", 1e6),
    "contact_radius": ("m", "um", 1e6),
    "estar": ("Pa", "GPa", 1e-9),
    "radius": ("m", "mm", 1e3),
    "length": ("m", "mm", 1e3),
}

RESULT_FIELDS = ("force", "depth", "stiffness", "half_width", "contact_radius")

_HEADINGS = {
    "force": "F",
    "depth": "d",
    "stiffness": "k",
    "half_width": "b (Hertz)",
    "contact_radius": "a (MDR)",
}


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose usage errors are one line on stderr and exit status 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


# ---------------------------------------------------------------------------------------
# argument parsing


def _build_parser():
    parser = _Parser(
        prog=PROG,
        description="Stiffness and deflection of a finite rigid cylinder pressed on its "
        "side into an elastic half-space.",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    calc = sub.add_parser(
        "calc",
        help="depth, stiffness and contact size for one case, a sweep or a CSV of cases",
        description="Depth (or force), stiffness, Hertz half-width (Eq. 1) and MDR contact "
        "radius of a cylinder of radius R and length L on an elastic half-space, one row "
        "per model. Values may carry units ('5mm', '0.2 in', '210 GPa', '1kN'); bare "
        "numbers are SI.",
        epilog="Sweeps: --load START:STOP:N (or --depth) gives N values from START to STOP, "
        "both included, spaced geometrically (equal ratios: right for loads over decades); "
        "--linear spaces them evenly. Batch: FILE.csv holds one case per row with columns "
        "named like the options; results are appended as columns for the default best "
        "estimate unless --model names others. Exit status 2 on bad input.",
    )
    calc.add_argument("csv", nargs="?", metavar="FILE.csv", help="batch: one case per row")
    for name, (kind, text) in CASE_PARAMETERS.items():
        calc.add_argument(f"--{name}", metavar="VALUE", help=f"{text} [{kind}]")
    calc.add_argument(
        "--linear", action="store_true", help="linear instead of geometric sweep spacing"
    )
    calc.add_argument(
        "--model",
        metavar="KEY[:OPT=VAL][,...]",
        help="only these models, e.g. 'li-popov:coefficients=eq11,johnson:c=0.72'; 'all' "
        "for the standard set. Default: the standard set for one case, its first model "
        "(the default best estimate) in a batch",
    )
    calc.add_argument("--si", action="store_true", help="output in SI units (m, N, N/m, Pa)")
    calc.add_argument("--json", action="store_true", help="machine-readable JSON (SI units)")
    calc.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")
    return parser


_VALUE_OPTIONS = {f"--{name}" for name in CASE_PARAMETERS}
_NEGATIVE = re.compile(r"^-(\d|\.\d)")


def _join_negative_values(argv):
    """Turn ``--radius -5mm`` into ``--radius=-5mm`` so argparse does not take the
    value for an option (and the range check can report it properly)."""
    out = []
    i = 0
    while i < len(argv):
        tok = argv[i]
        if tok in _VALUE_OPTIONS and i + 1 < len(argv) and _NEGATIVE.match(argv[i + 1]):
            out.append(f"{tok}={argv[i + 1]}")
            i += 2
        else:
            out.append(tok)
            i += 1
    return out


# ---------------------------------------------------------------------------------------
# cases


def _parse_case(raw, *, allow_sweep=True, linear=False, label=lambda name: f"--{name}"):
    """Check and convert one case given as {name: text or None}.

    Returns a dict of SI floats (radius, length, estar, and the moduli given) with
    ``given`` ('load' or 'depth') and ``values`` (one value, or a sweep). Raises
    InputError on the first problem; ``label`` names a parameter in messages
    (``--radius`` on the command line, ``radius`` for a CSV column).
    """
    from ._units import InputError, parse_quantity, parse_sweep

    def present(name):
        v = raw.get(name)
        return v is not None and str(v).strip() != ""

    def get(name, **kw):
        return parse_quantity(label(name), raw[name], CASE_PARAMETERS[name][0], **kw)

    case = {}
    for name in ("radius", "length"):
        if not present(name):
            raise InputError(label(name), "", "a length > 0 (e.g. 5mm)", "missing")
        case[name] = get(name)

    elastic = [n for n in ("modulus", "poisson", "modulus2", "poisson2") if present(n)]
    if present("estar"):
        if elastic:
            raise InputError(
                label(elastic[0]),
                raw[elastic[0]],
                f"either {label('estar')} or the moduli and Poisson's ratios, not both",
                f"conflicts with {label('estar')}",
            )
        case["estar"] = get("estar")
    else:
        if not present("modulus"):
            raise InputError(
                label("modulus"), "", f"a modulus > 0 (e.g. 210GPa), or {label('estar')}", "missing"
            )
        if not present("poisson"):
            raise InputError(
                label("poisson"),
                "",
                _poisson_bounds()[1],
                f"missing (needed with {label('modulus')})",
            )
        case["modulus"] = get("modulus")
        case["poisson"] = get("poisson", bounds=_poisson_bounds())
        if present("modulus2") != present("poisson2"):
            have, need = (
                ("modulus2", "poisson2") if present("modulus2") else ("poisson2", "modulus2")
            )
            raise InputError(
                label(need),
                "",
                f"{label('modulus2')} and {label('poisson2')} together, "
                "or neither (rigid cylinder)",
                f"missing (needed with {label(have)})",
            )
        if present("modulus2"):
            case["modulus2"] = get("modulus2")
            case["poisson2"] = get("poisson2", bounds=_poisson_bounds())
        case["estar"] = _effective_modulus(
            case["modulus"],
            case["poisson"],
            case.get("modulus2", math.inf),
            case.get("poisson2", 0.0),
        )

    has_load, has_depth = present("load"), present("depth")
    if has_load == has_depth:
        which = "both given" if has_load else "missing"
        raise InputError(
            f"{label('load')}/{label('depth')}",
            f"{raw.get('load')}/{raw.get('depth')}" if has_load else "",
            f"exactly one of {label('load')} (a force) or {label('depth')} (a length)",
            which,
        )
    given = "load" if has_load else "depth"
    kind = CASE_PARAMETERS[given][0]
    if allow_sweep:
        case["values"] = parse_sweep(label(given), raw[given], kind, linear=linear)
    else:
        if ":" in str(raw[given]):
            raise InputError(label(given), raw[given], "one value per row in a batch", "a sweep")
        case["values"] = [parse_quantity(label(given), raw[given], kind)]
    case["given"] = given
    return case


def _effective_modulus(e1, nu1, e2, nu2):
    """E* of Eq. 3 from linecontact.classical (E2 = inf: rigid cylinder)."""
    from . import classical

    return float(classical.effective_modulus(e1, nu1, e2, nu2))


# ---------------------------------------------------------------------------------------
# models and evaluation


def _select_models(specs, case, *, first_only=False):
    """The models for one case.

    ``specs`` is None (the standard set of :func:`linecontact.models.standard_models`,
    or only its first model, the default best estimate, when ``first_only``) or the
    list from :func:`_parse_model_option`. A model that refuses the case when it is
    built stands in as :class:`_Refused`, so that its row carries the reason.
    """
    from . import models
    from .validity import OutOfRangeError

    r, l, e = case["radius"], case["length"], case["estar"]
    if specs is None:
        standard = list(models.standard_models(r, l, e))
        return standard[:1] if first_only else standard
    chosen = []
    for text, key, options in specs:
        try:
            chosen.append(models.get_model(key, r, l, e, **options))
        except OutOfRangeError as exc:  # refused for this case: a row with a note
            chosen.append(_Refused(text, exc))
        except TypeError as exc:  # an option the model does not take
            from ._units import InputError

            raise InputError(
                "--model", text, "options the model takes (see its docstring)", str(exc)
            ) from None
    return chosen


class _Refused:
    """Stands in for a model that refused the case when it was built."""

    def __init__(self, text, exc):
        self.key = text
        self.label = text
        self.provenance = None
        self.exc = exc


def _parse_model_option(spec):
    """Parse ``--model``: None or 'all' (standard set) or ``KEY[:OPT=VALUE...]``, comma-separated.

    Returns None for the standard set, else a list of (text, key, options); raises
    InputError naming the valid keys for an unknown one.

    Examples
    --------
    >>> _parse_model_option("johnson:c=0.72")
    [('johnson:c=0.72', 'johnson', {'c': 0.72})]
    """
    if spec is None or spec.strip() == "all":
        return None
    from . import models
    from ._units import InputError

    valid = "all, or comma-separated KEY[:OPTION=VALUE...] with KEY one of: " + ", ".join(
        models.available_models()
    )
    parsed = []
    for text in (t.strip() for t in spec.split(",")):
        if not text:
            raise InputError("--model", spec, valid, "empty model name")
        key, *opts = text.split(":")
        if key not in models.MODELS:
            raise InputError("--model", text, valid, "unknown model")
        options = {}
        for opt in opts:
            name, eq, value = opt.partition("=")
            if not eq or not name.strip():
                raise InputError("--model", text, valid, f"option {opt!r} is not OPTION=VALUE")
            options[name.strip()] = _option_value(value.strip())
        parsed.append((text, key, options))
    return parsed


def _option_value(text):
    """A --model option value: true/false, a number, or the text itself.

    >>> _option_value("False"), _option_value("0.72"), _option_value("eq11")
    (False, 0.72, 'eq11')
    """
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return float(text)
    except ValueError:
        return text


def _model_id(model):
    """A short column-safe name for one row set: the label as a slug
    ('Johnson (c = 0.72)' -> 'johnson-c-0.72')."""
    return re.sub(r"[^a-z0-9.]+", "-", model.label.lower()).strip("-")


def _hertz_half_width(force, case):
    """Hertz half-width b of Eq. 1 (linecontact.classical)."""
    from . import classical

    return float(classical.hertz_half_width(force, case["radius"], case["length"], case["estar"]))


def _evaluate(model, case, value):
    """One row: {force, depth, stiffness, half_width, contact_radius, note} in SI.

    A model outside its validity range gives NaNs and its message as ``note``.
    """
    from .validity import OutOfRangeError

    row = dict.fromkeys(RESULT_FIELDS, math.nan)
    row["note"] = ""
    try:
        if isinstance(model, _Refused):
            raise model.exc
        if case["given"] == "load":
            row["force"] = value
            row["depth"] = float(model.depth(value))
            row["stiffness"] = float(model.stiffness_at_force(value))
        else:
            row["depth"] = value
            row["force"] = float(model.force(value))
            row["stiffness"] = float(model.stiffness(value))
        try:
            row["contact_radius"] = float(model.contact_radius(row["depth"]))
        except NotImplementedError:
            pass
    except OutOfRangeError as exc:
        row["note"] = str(exc)
    if row["force"] > 0:
        row["half_width"] = _hertz_half_width(row["force"], case)
    return row


def _compute(case, models_):
    """[(model, [row per value])] for one case."""
    return [(m, [_evaluate(m, case, v) for v in case["values"]]) for m in models_]


# ---------------------------------------------------------------------------------------
# output


def _fmt(value, digits=4):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}g}"


def _unit(field, si):
    s, eng, _ = UNITS[field]
    return s if si else eng


def _scale(field, value, si):
    return value if si else value * UNITS[field][2]


def _case_line(case, si):
    """The case in one line: R, L, L/R, E* (and the moduli it came from)."""

    def q(field, key):
        return f"{_fmt(_scale(field, case[key], si))} {_unit(field, si)}"

    line = (
        f"R = {q('radius', 'radius')}, L = {q('length', 'length')}, "
        f"L/R = {_fmt(case['length'] / case['radius'])}, E* = {q('estar', 'estar')}"
    )
    if "modulus" in case:
        line += f" (E1 = {q('estar', 'modulus')}, nu1 = {_fmt(case['poisson'])}; "
        if "modulus2" in case:
            line += f"E2 = {q('estar', 'modulus2')}, nu2 = {_fmt(case['poisson2'])})"
        else:
            line += "rigid cylinder)"
    return line


def _render_table(case, results, si):
    """Plain-text table: one row per model and value."""
    first = "force" if case["given"] == "load" else "depth"
    second = "depth" if first == "force" else "force"
    fields = [first, second, "stiffness", "half_width", "contact_radius"]
    header = ["model"] + [f"{_HEADINGS[f]} [{_unit(f, si)}]" for f in fields] + ["note"]
    body = []
    for model, rows in results:
        for row in rows:
            body.append(
                [model.label] + [_fmt(_scale(f, row[f], si)) for f in fields] + [row["note"]]
            )
    widths = [max(len(r[i]) for r in [header] + body) for i in range(len(header) - 1)]
    lines = [_case_line(case, si), ""]
    for r in [header] + body:
        cells = [r[0].ljust(widths[0])] + [c.rjust(w) for c, w in zip(r[1:-1], widths[1:])]
        lines.append("  ".join(cells + [r[-1]]).rstrip())
    return "\n".join(lines) + "\n"


def _nan_to_none(v):
    return None if isinstance(v, float) and not math.isfinite(v) else v


def _model_json(model):
    return {
        "key": model.key,
        "label": model.label,
        "id": _model_id(model),
        "provenance": _jsonable(getattr(model, "provenance", None)),
    }


def _jsonable(obj):
    """Provenance dicts may hold numpy scalars or paths: make them JSON-safe."""
    if obj is None or isinstance(obj, (bool, int, str)):
        return obj
    if isinstance(obj, float):
        return _nan_to_none(obj)
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    try:
        return _jsonable(obj.item())  # numpy scalar
    except AttributeError:
        return str(obj)


def _version():
    try:
        from . import __version__
    except ImportError:
        from importlib.metadata import version

        return version("linecontact")
    return __version__


def _units_json():
    return {f: UNITS[f][0] for f in RESULT_FIELDS + ("estar", "radius", "length")}


def _render_json(case, results, argv):
    import json

    inputs = {
        k: case[k]
        for k in ("radius", "length", "estar", "modulus", "poisson", "modulus2", "poisson2")
        if k in case
    }
    inputs[case["given"]] = case["values"] if len(case["values"]) > 1 else case["values"][0]
    doc = {
        "linecontact_version": _version(),
        "command": [PROG] + list(argv),
        "units": _units_json(),
        "inputs": inputs,
        "models": [
            dict(_model_json(m), rows=[{k: _nan_to_none(v) for k, v in r.items()} for r in rows])
            for m, rows in results
        ],
    }
    return json.dumps(doc, indent=2) + "\n"


def _write(text, path):
    if path is None:
        sys.stdout.write(text)
        sys.stdout.flush()  # a closed pipe shows here, inside main's error handling
    else:
        with open(path, "w", encoding="utf-8", newline="") as fh:
            fh.write(text)


# ---------------------------------------------------------------------------------------
# commands


def _calc_one(args, argv):
    raw = {name: getattr(args, name) for name in CASE_PARAMETERS}
    case = _parse_case(raw, linear=args.linear)
    results = _compute(case, _select_models(_parse_model_option(args.model), case))
    if args.json:
        _write(_render_json(case, results, argv), args.output)
    else:
        _write(_render_table(case, results, args.si), args.output)
    computed = [r for _, rows in results for r in rows if not r["note"]]
    if not computed:
        notes = [r["note"] for _, rows in results for r in rows]
        _error(notes[0] if notes else "no model selected")
        return 2
    return 0


def _batch_columns(si):
    """Result column names: e.g. depth_um, stiffness_N_per_um; suffixed _KEY when
    several models are reported."""
    names = {}
    for f in RESULT_FIELDS:
        unit = _unit(f, si).replace("/", "_per_")
        names[f] = f"{f}_{unit}"
    return names


def _calc_batch(args, argv):
    import pandas as pd

    from ._units import InputError

    try:
        table = pd.read_csv(
            args.csv,
            dtype=str,
            keep_default_na=False,
            skipinitialspace=True,
            encoding="utf-8-sig",  # spreadsheets often write a byte-order mark
        )
    except FileNotFoundError:
        hint = (
            ""
            if args.csv.lower().endswith(".csv")
            else (" (a value with a space must be quoted, e.g. --radius '5 mm')")
        )
        _error(f"{args.csv!r}: no such file{hint}")
        return 2
    except Exception as exc:  # pandas parser errors, empty file, encoding
        detail = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        _error(f"{args.csv!r}: cannot read as CSV ({detail})")
        return 2
    table.columns = [str(c).strip() for c in table.columns]
    lower = {c.lower(): c for c in table.columns}
    known = [name for name in CASE_PARAMETERS if name in lower]
    options = {name: getattr(args, name) for name in CASE_PARAMETERS}
    if not known and not any(v is not None for v in options.values()):
        _error(f"{args.csv!r}: no case columns; expected some of: " + ", ".join(CASE_PARAMETERS))
        return 2
    specs = _parse_model_option(args.model)
    # default: the first of the standard set (the universal curve when installed)
    first_only = args.model is None
    multi = not first_only and (specs is None or len(specs) > 1)

    si = args.si or args.json  # JSON is always SI
    names = _batch_columns(si)
    out_rows = []
    n_failed = 0
    models_seen = {}
    for i, cells in enumerate(table.to_dict("records")):
        raw = dict(options)
        for name in known:
            cell = cells[lower[name]]
            if str(cell).strip() != "":
                raw[name] = cell
        out = {}
        try:
            case = _parse_case(raw, allow_sweep=False, label=lambda n: n)
            results = _compute(case, _select_models(specs, case, first_only=first_only))
        except InputError as exc:
            n_failed += 1
            out["error"] = str(exc)
            out_rows.append(out)
            continue
        out["estar_" + _unit("estar", si)] = _scale("estar", case["estar"], si)
        for model, rows in results:
            models_seen[_model_id(model)] = model
            row = rows[0]
            sfx = f"_{_model_id(model)}" if multi else ""
            if not multi:
                out["model"] = model.label
            for f in RESULT_FIELDS:
                out[names[f] + sfx] = _scale(f, row[f], si)
            out["note" + sfx] = row["note"]
        out["error"] = ""
        out_rows.append(out)

    results_df = pd.DataFrame(out_rows, index=table.index)
    # results of an earlier run on the same file are replaced, not duplicated
    table = table.drop(columns=[c for c in results_df.columns if c in table.columns])
    # fixed column order: estar, then per model, then error
    order = [c for c in results_df.columns if c != "error"] + ["error"]
    merged = pd.concat([table, results_df[order]], axis=1)

    if args.json:
        import json

        doc = {
            "linecontact_version": _version(),
            "command": [PROG] + list(argv),
            "units": _units_json(),
            "models": [_model_json(m) for m in models_seen.values()],
            "rows": [
                {k: _nan_to_none(v) for k, v in r.items()}
                for r in merged.astype(object).where(merged.notna(), None).to_dict("records")
            ],
        }
        _write(json.dumps(doc, indent=2) + "\n", args.output)
    else:
        text = merged.to_csv(index=False, float_format="%.6g", lineterminator="\n")
        _write(text, args.output)
    if n_failed:
        _error(f"{n_failed} of {len(table)} rows failed; see the 'error' column")
        return 2
    return 0


def _error(message):
    print(f"{PROG} calc: error: {message}", file=sys.stderr)


def main(argv=None):
    """Entry point of the ``linecontact`` console script; returns the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = _build_parser()
    try:
        args = parser.parse_args(_join_negative_values(argv))
    except SystemExit as exc:  # --help (0) or a usage error (2), already printed
        return exc.code if isinstance(exc.code, int) else 2
    if args.command is None:
        parser.print_help(sys.stderr)
        return 2
    try:
        if args.csv is not None:
            return _calc_batch(args, argv)
        return _calc_one(args, argv)
    except ValueError as exc:
        # InputError (ours) or the library's OutOfRangeError; the check imports
        # linecontact.validity (numpy) only now, when it has already been loaded
        from ._units import InputError
        from .validity import OutOfRangeError

        if not isinstance(exc, (InputError, OutOfRangeError)):
            raise
        _error(str(exc))
        return 2
    except BrokenPipeError:  # the reader stopped early (`| head`): stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except KeyboardInterrupt:
        return 130
    except OSError as exc:  # e.g. -o into a missing directory
        _error(f"{exc.filename!r}: {exc.strerror}")
        return 2
