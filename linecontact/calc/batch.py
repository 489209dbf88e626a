"""Batch: ``linecontact calc FILE.csv``, one case per row, results appended as columns.

Reading
    The file is read with the csv module (UTF-8, a byte-order mark allowed), every cell
    as the text it is. Columns named like a parameter of :mod:`linecontact.calc.cases`
    (case-insensitive, surrounding spaces ignored) are inputs; options on the command
    line fill empty or missing cells, and a filled cell that differs from the option
    (by value) is an error in its row (never silently overridden either way). Cells
    follow the rules of :mod:`linecontact._units` (a number with one unit name), parsed
    once per column. A column that looks like an input but would not be read (a unit
    in the header, 'radius [mm]'; a close spelling, 'lode') refuses the file, naming
    its match; so does a semicolon-separated header.

Writing: no user data is ever lost
    Every input row is written, in its place, with all its cells exactly as read
    (a short row is padded with empty cells; cells beyond the header go under unnamed
    columns, and such a row is an error: its cells are shifted), followed by the result
    columns:
    ``estar_GPa``, then per model ``model``, ``force_kN``, ``depth_um``,
    ``stiffness_N_per_um``, ``half_width_um``, ``peak_pressure_MPa``,
    ``contact_radius_um`` (whole rollers: ``roller_deflection_um``,
    ``roller_stiffness_N_per_um``, ``depth_inner_um``, ...), ``deviation_pct`` (when
    several models are asked for), ``flags``, ``note``, and at the end ``error`` (SI
    names such as ``depth_m`` with ``--si`` or ``--json``). With several models (or
    ``--model all``) each result column gets the model's id as a suffix
    (``depth_um_johnson-c-0.72``).
    If a result column's name is already a column of the file (a rerun on its own
    output, or a user column called ``model`` or ``note``), the user's column is kept
    untouched and ALL result columns get the prefix ``result_`` (``result2_``, ... if
    that collides too), so the result columns stay one consistent set. A rerun on an
    output (a file with the ``error`` column) recognises its earlier result columns
    (named as the calculator names them, with or without a ``result_`` prefix): they
    are never read as inputs, are written back as they were, and one line on stderr
    says so and names the prefix of this run's results.
    A row that cannot be computed keeps its place and says why in ``error`` (its input
    problem in one line, or an unexpected exception of a model); a row outside a
    model's range says so in ``note``; all other rows are computed and written.

Speed
    With the default model alone (a default batch) and no feature, all rows are
    evaluated at once as arrays over their geometry
    (:meth:`linecontact.models.ContactModel.evaluate_many`), so 100 000 distinct
    rollers cost as much as 100 000 rows of one roller; otherwise rows are grouped by
    distinct cylinder and one model object per cylinder and model evaluates all its
    rows at once (:func:`linecontact.calc.compute.compute`). Rows outside the model's
    range always take the per-cylinder path, whose notes name the cylinder. A progress bar
    (tqdm when installed, else a plain line) is shown on stderr for batches of at
    least :data:`PROGRESS_ROWS` rows when stderr is a terminal, or always with
    ``--progress``; ``--no-progress`` hides it.

On a cluster
    ``--scheduler ADDRESS`` (a running dask cluster) or ``--workers N`` (a local one),
    or ``args.client`` (:func:`linecontact.calc.frame.calc_frame`'s ``client=``): the
    file is read and checked here as always, the rows are evaluated on the workers
    (:mod:`linecontact.calc.spread`), and the output is written here by the same code:
    the same bytes (docs/cluster.md). A cluster's bar is shown on a terminal whatever
    the batch's size.
"""

from __future__ import annotations

import csv
import io
import sys

import numpy as np

from .._units import InputError, parse_quantity
from . import render
from .cases import BY_NAME, PARAMETERS, parse_cases
from .compute import compute
from .feature import RAW_KINDS, bounds_of, option_name

__all__ = ["run_batch", "read_table", "result_columns", "PROGRESS_ROWS", "CALC"]

#: Batches of this many rows or more show a progress bar (on a terminal).
PROGRESS_ROWS = 10000


class BatchError(ValueError):
    """The file as a whole cannot be used (one line, naming the file)."""


def _unread_lookalikes(path, header, names, known, table=None):
    """Refuse a column that looks like an input but would not be read: a parameter's
    name with a unit in it ('radius [mm]', 'load_kN', 'E (GPa)') or a close spelling
    ('lode', 'raduis'), when that parameter is not itself a column. Units go in the
    cells (5mm), never in the header."""
    import difflib
    import re

    table = table or CALC
    BY_NAME = table.by_name
    # a file written by the calculator (it ends with the 'error' column) holds its
    # result columns, named like inputs with units (force_kN): those are not inputs
    rerun = any(re.sub(r"^result[0-9]*_", "", h) == "error" for h in names)
    results = table.result_names() if rerun else set()
    earlier = []
    for j, h in enumerate(names):
        if h in BY_NAME or not h:
            continue
        plain = re.sub(r"^result[0-9]*_", "", h)
        if any(plain == r or plain.startswith(r + "_") for r in results):
            earlier.append(header[j])
            continue  # a result column of an earlier run (a rerun on its own output)
        base = re.split(r"\s*[\[(]|_(?=[a-z]+$)|\s+in\s+|\s+", h.strip())[0]
        if base in BY_NAME and base not in known:
            match = base
        else:
            close = difflib.get_close_matches(h, list(BY_NAME), n=1, cutoff=0.75)
            match = close[0] if close and close[0] not in known else None
        if match is not None:
            from .._units import DIMENSIONS

            # the example in the matched input's own kind (10kN under radial_load)
            kind = BY_NAME[match].kind
            example = DIMENSIONS[kind][2].split(",")[0] if kind in DIMENSIONS else ""
            unit = (f"write the unit in each cell, e.g. {example} under {match!r}; "
                    if example and not example.replace(".", "").isdigit() else "")
            raise BatchError(
                f"{str(path)!r}: column {header[j]!r} is not an input and would not be "
                f"read; did you mean {match!r}? ({unit}rename the column if it is your "
                "own)")
    return earlier


#: The text columns of a result set (beside the fields' columns): a rerun's own.
_TEXT_RESULTS = ("model", "flags", "note", "error")


def _refuse_conflicts(cases, cells, conflicts, errors):
    """A command-line option fills the EMPTY cells of its column; a filled cell that
    differs from it (by value in SI, or as text for files and profiles) is an error in
    that row, naming both, never silently overridden one way or the other."""
    for name, (opt, si, filled) in conflicts.items():
        values = cases.values[name]
        for i in np.flatnonzero(filled):
            if errors[i]:
                continue
            if si is None:
                same = str(cells[name][i]).strip() == str(opt).strip()
            else:
                v = values[i]
                same = bool(np.isfinite(v)) and abs(v - si) <= 1e-12 * max(abs(si), abs(v))
            if not same:
                errors[i] = str(InputError(
                    name, cells[name][i], f"the cell or {option_name(name)}, not both",
                    f"conflicts with {option_name(name)} {opt} on the command line (the "
                    "option fills empty cells only; clear the cell or drop the option)"))


def read_table(path):
    """(header, rows, lines) of a CSV file, cells as text; BatchError with the reason.

    ``lines`` is the text of each row as in the file (line ends aside) when no cell is
    quoted, so that the output repeats the user's cells byte for byte; else None (the
    csv module then writes them back with minimal quoting).
    """
    try:
        with open(path, encoding="utf-8-sig", newline="") as fh:
            text = fh.read()
    except FileNotFoundError:
        hint = "" if str(path).lower().endswith(".csv") else (
            " (a value with a space must be quoted, e.g. --radius '5 mm')")
        raise BatchError(f"{str(path)!r}: no such file{hint}") from None
    except UnicodeDecodeError as exc:
        raise BatchError(f"{str(path)!r}: not UTF-8 text ({exc.reason} at byte "
                         f"{exc.start})") from None
    except OSError as exc:
        raise BatchError(f"{str(path)!r}: cannot read ({exc.strerror or exc})") from None
    except ValueError as exc:  # a path the OS cannot take (an embedded NUL)
        raise BatchError(f"{str(path)!r}: not a usable path ({exc})") from None
    lines = None
    if '"' not in text:  # no quoting: one line per row, cells split at commas
        if "\r" in text:
            text = text.replace("\r\n", "\n").replace("\r", "\n")
        lines = [ln for ln in text.split("\n") if ln]
        rows = _FlatRows.of(lines) or [ln.split(",") for ln in lines]
    else:
        try:
            rows = list(csv.reader(io.StringIO(text), skipinitialspace=True))
        except csv.Error as exc:
            raise BatchError(f"{str(path)!r}: cannot read as CSV ({exc})") from None
        rows = [r for r in rows if r]  # blank lines
    if not rows:
        raise BatchError(f"{str(path)!r}: the file is empty; expected a header row and "
                         "one case per row")
    if isinstance(rows, _FlatRows):
        header, body = rows.header(), rows.body()
    else:
        header, body = rows[0], rows[1:]
    if len(header) == 1 and header[0].count(";") >= 1:
        raise BatchError(f"{str(path)!r}: the header {header[0]!r} is separated by "
                         "semicolons; expected a comma-separated file (cells separated "
                         "by commas, numbers with a decimal point: 5.5mm), e.g. saved "
                         "as 'CSV UTF-8 (comma delimited)'")
    if not body:
        raise BatchError(f"{str(path)!r}: only a header row, no cases; expected one case "
                         "per row under the header")
    return header, body, (lines[1:] if lines is not None else None)


class _FlatRows:
    """The cells of a rectangular, unquoted CSV as one flat list (one split of the
    text instead of a list per row); rows and columns are slices of it."""

    def __init__(self, flat, width, start=0):
        self.flat, self.width, self.start = flat, width, start

    @classmethod
    def of(cls, lines):
        """A _FlatRows of these lines, or None if they do not all have as many cells
        as the first."""
        if not lines:
            return None
        commas = lines[0].count(",")
        counts = list(map(str.count, lines, [","] * len(lines)))   # C-level
        if counts.count(commas) != len(counts):
            return None
        return cls(",".join(lines).split(","), commas + 1)

    def header(self):
        return self.flat[: self.width]

    def body(self):
        return _FlatRows(self.flat, self.width, self.start + 1)

    def __len__(self):
        return len(self.flat) // self.width - self.start

    def __bool__(self):
        return len(self) > 0

    def __getitem__(self, i):
        a = (self.start + i) * self.width
        return self.flat[a: a + self.width]

    def __iter__(self):
        return (self[i] for i in range(len(self)))

    def column(self, j):
        """Cell j of every row (a C-level slice)."""
        return self.flat[self.start * self.width + j:: self.width]


def result_columns(names, taken):
    """Rename result columns that collide with the user's: prefix them all.

    >>> result_columns(["model", "error"], {"name", "model"})
    ['result_model', 'result_error']
    >>> result_columns(["model"], {"model", "result_model"})
    ['result2_model']
    """
    taken = {t.strip().lower() for t in taken}
    if not any(n.lower() in taken for n in names):
        return list(names)
    k = 1
    while True:
        prefix = "result_" if k == 1 else f"result{k}_"
        out = [prefix + n for n in names]
        if not any(n.lower() in taken for n in out):
            return out
        k += 1


class _Progress:
    def __init__(self, total, enabled):
        self.total = total
        self.bar = None
        self.enabled = enabled
        self.last = -1
        if not enabled:
            return
        try:
            from tqdm import tqdm
        except ImportError:
            return
        self.bar = tqdm(total=total, unit="row", file=sys.stderr, desc=render.PROG)

    def __call__(self, done):
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.update(done - self.bar.n)
            return
        pct = int(100 * done / self.total)
        if pct // 10 != self.last // 10:
            print(f"{render.PROG}: {done}/{self.total} rows ({pct} %)", file=sys.stderr)
            self.last = pct

    def close(self):
        if self.bar is not None:
            self.bar.close()


class _CalcTable:
    """What the batch loop asks of ``linecontact calc``: its parameters, the rules
    (:func:`~linecontact.calc.cases.parse_cases`), the evaluation
    (:func:`~linecontact.calc.compute.compute`), the result columns and the JSON
    header. A subcommand (:class:`linecontact.calc.command.Command`) answers the same
    questions, so that every batch follows the same rules."""

    name = "calc"
    parameters = PARAMETERS
    by_name = BY_NAME
    #: Columns whose cell may hold a sweep by mistake ('1kN:2kN:3'): said as such.
    sweep_columns = ("load", "depth")

    @staticmethod
    def parse(cells, n, label):
        return parse_cases(cells, n, label=label)

    @staticmethod
    def evaluate(cases, errors, args, specs, progress):
        return compute(cases, errors, specs, first_only=args.model is None,
                       progress=progress, label=lambda name: name)

    @staticmethod
    def layout(results, cases, si):
        return _result_layout(results, cases, si, len(results.sets) > 1)

    @staticmethod
    def header(argv, results):
        return render.json_header(argv, results)

    @staticmethod
    def groups(cases, errors):
        """Per row its contact's group (:func:`~linecontact.calc.compute.group_rows`):
        a batch on a cluster keeps each group in one part."""
        from .compute import group_rows

        return group_rows(cases, errors)[1]

    @staticmethod
    def merge(parts, rows, errors, cases, label=None):
        """The results of the whole batch from its parts'
        (:func:`~linecontact.calc.compute.merge_results`)."""
        from .compute import merge_results

        return merge_results(parts, rows, errors, cases, label)

    @staticmethod
    def result_names():
        """Every name a result column of this command may have (a rerun's own)."""
        from .compute import all_fields

        return {_col_name(f, si).lower() for f in all_fields()
                for si in (False, True)} | set(_TEXT_RESULTS)


#: The calculator's own table (the default of :func:`run_batch`).
CALC = _CalcTable()


def run_batch(args, argv, specs, options, table=CALC):
    """The batch command; returns the exit status (2 if any row failed).

    `table`: the command whose rows these are (:data:`CALC`, or a subcommand's
    :class:`~linecontact.calc.command.Command`): its parameters, rules, evaluation
    and result columns; the reading, the checks of the file and of the options
    against the cells, and the writing are the same for every command."""
    PARAMETERS, BY_NAME = table.parameters, table.by_name
    if getattr(args, "linear", False):
        # a batch has one value per cell, no sweep to space: --linear would do nothing
        raise BatchError("--linear spaces the values of a sweep, and a CSV batch has "
                         "none (one value per row): drop --linear, or give the sweep "
                         "without the CSV")
    header, body, lines = read_table(args.csv)
    n = len(body)
    names = [h.strip().lower() for h in header]
    known = {}
    for j, h in enumerate(names):
        if h in BY_NAME:
            if h in known:
                raise BatchError(f"{str(args.csv)!r}: column {header[j]!r} appears twice")
            known[h] = j
    earlier = _unread_lookalikes(args.csv, header, names, known, table)
    if not known and not any(v is not None for v in options.values()):
        raise BatchError(f"{str(args.csv)!r}: no case columns; expected some of: "
                         + ", ".join(p.name for p in PARAMETERS))
    # a row longer than the header keeps its extra cells under columns named by their
    # place (extra_5: the 5th cell; no column without a name), so the result columns
    # stay aligned; a shorter row is padded with empty cells
    flat = isinstance(body, _FlatRows)  # rectangular: every row as wide as the header
    width = len(header) if flat else max(len(header), max(map(len, body)))
    header = list(header) + _extra_names(header, width)
    full = flat or min(map(len, body)) >= width  # no short row (the usual case)
    transposed = None
    cells = {}
    conflicts = {}  # parameter -> (option text, option SI or None, filled cells)
    for p in PARAMETERS:
        j = known.get(p.name)
        opt = options.get(p.name)
        if j is None and opt is None:
            continue
        if j is None:
            col = [""] * n
        elif flat:
            col = body.column(j)
        elif full:
            if transposed is None:
                transposed = list(zip(*body))  # all columns at once (C loop)
            col = list(transposed[j])
        else:
            col = [r[j] if j < len(r) else "" for r in body]
        if opt is not None:
            if p.kind not in RAW_KINDS:
                if p.sweep and ":" in str(opt):
                    raise InputError(option_name(p.name), opt,
                                     "one value per row in a batch", "a sweep")
                # a bad value is the command line's error (exit 2), not every row's
                si = parse_quantity(option_name(p.name), opt, p.kind,
                                    positive=p.positive, bounds=bounds_of(p))
            else:
                si = None
            # text and path options are checked per row where they are read
            # (RAW_KINDS): e.g. a profile is refused in each row's 'error' cell, as a
            # profile column is. The option fills EMPTY cells only; a filled cell that
            # says something else is a conflict, refused in its row (below)
            if j is not None:
                conflicts[p.name] = (opt, si, [bool(c.strip()) for c in col])
            col = [c if c.strip() else opt for c in col]
        cells[p.name] = col
    # an input written to the JSON output only, given without --json (as an option or
    # in any cell of its column): refused once, before any row is computed
    json_only = {p.name: next((c for c in cells[p.name] if c.strip()), None)
                 for p in PARAMETERS if p.json_only and p.name in cells}
    named = (lambda name: option_name(name) if options.get(name) is not None
             else f"column {header[known[name]]!r}")
    render.refuse_json_only(PARAMETERS, json_only, args.json, named)
    # with --json too: a batch's JSON is one flat row per case, without the blocks of
    # one case's JSON where such an input's result goes (it ran and dropped the field)
    for p in PARAMETERS:
        if p.json_only and json_only.get(p.name) is not None:
            raise InputError(named(p.name), json_only[p.name],
                             f"one case or a sweep with --json ({p.json_only} is a block "
                             "of its JSON)", "a batch's JSON has one flat row per case "
                             "and no blocks: it would not be written anywhere")
    render.refuse_input_as_output(args.output, {c.strip() for p in PARAMETERS
                                                if p.kind == "path" and p.name in cells
                                                for c in cells[p.name]})
    cases, present, errors = table.parse(cells, n, lambda name: name)
    _refuse_conflicts(cases, cells, conflicts, errors)
    if not flat:  # a row with more cells than the header: its cells are shifted or
        # split (a decimal comma), so that error comes before any other of the row
        for i, r in enumerate(body):
            if len(r) > len(names):
                errors[i] = str(InputError(
                    f"row {i + 1}", ",".join(r[len(names):]),
                    f"at most {len(names)} cells, one per header column",
                    f"{len(r)} cells under a header of {len(names)} columns (a decimal "
                    "comma, or a missing header name?)"))
    for name in table.sweep_columns:  # a sweep in a cell: say so, not just "not a number"
        col = cells.get(name)
        if col is None or ":" not in "".join(col):
            continue
        for i, c in enumerate(col):
            if ":" in c and (not errors[i] or name in errors[i].split(" ")[0]):
                errors[i] = str(InputError(name, c, "one value per row in a batch",
                                           "a sweep"))
    spread = (getattr(args, "scheduler", None) is not None
              or getattr(args, "workers", None) is not None
              or getattr(args, "client", None) is not None)
    shown = getattr(args, "progress", None)
    progress = _Progress(n, shown if shown is not None else sys.stderr.isatty() and (
        spread or n >= PROGRESS_ROWS))
    try:
        if spread:  # the evaluation on a dask cluster: the same results
            from .spread import evaluate_on_cluster

            results = evaluate_on_cluster(
                table, cells, errors, cases, model=getattr(args, "model", None),
                specs=specs, scheduler=getattr(args, "scheduler", None),
                workers=getattr(args, "workers", None),
                connect_timeout=getattr(args, "connect_timeout", None),
                client=getattr(args, "client", None), progress=progress,
                label=lambda name: name)
        else:
            results = table.evaluate(cases, errors, args, specs, progress)
    finally:
        progress.close()
    si = args.si or args.json
    out_cols, getters = table.layout(results, cases, si)
    out_names = result_columns(out_cols, header)
    if earlier:  # a rerun on an output: say once what its result columns are
        prefix = out_names[-1][:-len(out_cols[-1])]
        shown = ", ".join(earlier[:3]) + (", ..." if len(earlier) > 3 else "")
        print(f"{render.PROG} {table.name}: note: {len(earlier)} columns of {str(args.csv)!r} "
              f"are results of an earlier run ({shown}): not read as inputs, written "
              f"back as they were; this run's results follow"
              + (f" as the {prefix}* columns" if prefix else ""), file=sys.stderr)
    if args.json:
        text = _json(table.header(argv, results), header, body, out_names, getters,
                     width)
    else:
        text = _csv(header, body, lines, out_names, getters, width)
    render.write(text, args.output)
    n_failed = len(errors) - errors.count("")
    if n_failed:
        print(f"{render.PROG} {table.name}: error: {n_failed} of {n} rows failed; see "
              "the 'error' column", file=sys.stderr)
        return 2
    return 0


def _col_name(field, si):
    u = render.unit(field, si)
    u = {"%": "pct", "-": "fraction"}.get(u, u).replace("/", "_per_").replace(" ", "_")
    return f"{field}_{u}"


def _result_layout(results, cases, si, multi):
    """Result column names and, for each, a function row index -> cell value."""
    cols, getters = [], []
    estar = render.scale("estar", cases.estar, si)
    cols.append(_col_name("estar", si))
    getters.append(("num", estar))
    # a column only where some row's contact radius differs from its roller's (a
    # counter-body or raceways); a row that failed (NaN radius) is not such a row
    reff_, r_ = np.asarray(cases.radius_eff, float), np.asarray(cases.radius, float)
    if np.any((reff_ != r_) & ~(np.isnan(reff_) & np.isnan(r_))):
        cols.append(_col_name("radius_eff", si))
        reff = np.where(cases.whole(), np.nan, cases.radius_eff)  # per contact there
        getters.append(("num", render.scale("radius_eff", reff, si)))
    fields = render.columns_of(results, "load")
    # in a batch the force comes first whatever is given
    for s in results.sets:
        sfx = f"_{s['id']}" if multi else ""
        if not multi:
            cols.append("model")
            getters.append(("text", s["label"]))
        for f in fields:
            cols.append(_col_name(f, si) + sfx)
            getters.append(("num", render.scale(f, s["fields"][f], si)))
        cols.append("flags" + sfx)
        getters.append(("text", s["flags"]))
        cols.append("note" + sfx)
        getters.append(("text", s["note"]))
    for b in results.blocks:  # a feature's extra rows: columns KEY_FIELD_UNIT
        if not b.fields and not b.text_columns:
            continue  # a block for --json only (e.g. q(x))
        n = len(results.errors)
        for f in b.fields:
            cols.append(f"{b.key}_{_col_name_of(f, b.fields[f], si)}")
            getters.append(_num_column(b.rows, f, b.fields[f], si))
        for t in b.text_columns:
            cols.append(f"{b.key}_{t}")
            getters.append(("text", ["" if r is None else r.get("text", {}).get(t, "")
                                     for r in b.rows]))
        cols.append(f"{b.key}_note")
        getters.append(("text", ["" if r is None else r.get("note", "") for r in b.rows]
                        if n else []))
    cols.append("error")
    getters.append(("text", results.errors))
    return cols, getters


def _num_column(rows, name, field, si):
    """('num', values over the rows): each row's `name` [SI], in the field's display
    unit unless `si`; NaN for a row without it (refused, or no such output)."""
    vals = np.array([np.nan if r is None or r.get(name) is None else float(r[name])
                     for r in rows])
    return "num", vals if si else vals * field.factor


def _col_name_of(name, field, si):
    u = field.si if si else field.eng
    u = {"%": "pct", "-": "fraction"}.get(u, u).replace("/", "_per_").replace(" ", "_")
    return f"{name}_{u}"


def _result_cells(getters):
    """The result part of every output line: numbers as '%.6g' ('' for none), text
    minimally quoted, each cell preceded by its comma.

    All rows at once as a byte matrix (:func:`_g6_bytes` for the numbers, a table
    lookup per distinct text, constant columns written once), its padding dropped and
    the whole split into lines; the same text as formatting each row in turn
    (:func:`_result_cells_by_row`, used when a text holds a NUL byte, the padding, or
    a line end, where the lines are split)."""
    n = len(getters[0][1]) if getters else 0
    if not n:
        return []
    pieces = []
    for kind, data in getters:
        if kind == "num":
            v = np.asarray(data, dtype=float)
            if _constant(v):
                pieces.append("," + format(float(v[0]), ".6g"))
            else:
                m = _g6_bytes(v)
                pieces.append(",")
                pieces.append(m[:, m.any(axis=0)])  # padding only: nothing to copy
            continue
        first = data[0]
        if list(data).count(first) == n:
            pieces.append("," + _quote(str(first)))
            continue
        distinct = list(dict.fromkeys(data))
        code = {t: k for k, t in enumerate(distinct)}
        texts = [_quote(str(t)).encode("utf-8") for t in distinct]
        if any(b"\0" in t or b"\n" in t for t in texts):
            return _result_cells_by_row(getters)
        table = np.zeros((len(texts), max(map(len, texts)) or 1), np.uint8)
        for k, t in enumerate(texts):
            table[k, :len(t)] = np.frombuffer(t, np.uint8)
        pieces.append(",")
        pieces.append(table[np.fromiter(map(code.__getitem__, data), np.intp, count=n)])
    if any("\0" in p or "\n" in p for p in pieces if isinstance(p, str)):
        return _result_cells_by_row(getters)
    pieces.append("\n")
    blocks, text = [], ""
    for p in pieces:  # neighbouring constant texts become one block
        if isinstance(p, str):
            text += p
            continue
        if text:
            blocks.append(np.broadcast_to(np.frombuffer(text.encode("utf-8"), np.uint8),
                                          (n, len(text.encode("utf-8")))))
            text = ""
        blocks.append(p)
    if text:
        blocks.append(np.broadcast_to(np.frombuffer(text.encode("utf-8"), np.uint8),
                                      (n, len(text.encode("utf-8")))))
    matrix = np.concatenate(blocks, axis=1)
    return matrix[matrix != 0].tobytes().decode("utf-8").split("\n")[:n]


def _constant(v):
    """Whether every value of v is the same finite number written the same way: equal
    (NaN != NaN) and of one sign bit ('%.6g' writes -0.0 as '-0', 0.0 as '0')."""
    # finite first: inf == inf, but a missing or infinite result is an empty cell,
    # which the row paths write cell by cell
    return bool(np.isfinite(v[0]) and np.all(v == v[0])
                and np.all(np.signbit(v) == np.signbit(v[0])))


#: 10**k for k = 0..22, each exact in double precision.
_POW10 = 10.0 ** np.arange(23)


def _g6_layouts():
    """Index table of :func:`_g6_bytes`: for each layout (fixed notation with decimal
    exponent -4..5, then the exponential one) and each position of the last nonzero
    digit (0..5), the source of each of the 11 characters of a number's text."""
    # source row: 0-5 the six digits, 6 '.', 7 '0', 8 'e', 9 the exponent's sign,
    # 10-11 its two digits, 12 padding
    table = np.full((11, 6, 11), 12, np.intp)
    for c in range(11):
        for last in range(6):
            if c < 10 and c >= 4:  # 1 <= |x| < 1e6: d.ddd, the point after e + 1 digits
                e = c - 4
                cols = list(range(e + 1))
                if last > e:
                    cols += [6] + list(range(e + 1, last + 1))
            elif c < 10:  # 1e-4 <= |x| < 1: 0.000ddd
                cols = [7, 6] + [7] * (3 - c) + list(range(last + 1))
            else:  # d.ddde+XX
                cols = [0] + ([6] + list(range(1, last + 1)) if last else []) + [8, 9, 10, 11]
            table[c, last, :len(cols)] = cols
    return table.reshape(66, 11)


_G6 = _g6_layouts()


def _g6_bytes(values):
    """(n, 13) uint8: ``'%.6g' % x`` of each value as ASCII, padded with zero bytes
    (all zero for NaN and infinities: an empty cell).

    Byte for byte ``format(x, '.6g')``: the six significant digits are the scaled value
    a 10^(5-e) rounded to an integer, where the scaling by an exact power of ten is
    one correctly rounded operation (relative error <= 2^-53, so <= 1.2e-10 on a value
    below 1e6); a value within 1e-8 of a rounding tie, or outside 1e-17 <= |x| < 1e28
    (beyond the exact powers), is formatted by Python itself; non-finite values are
    empty. Then the layout of '%g' (fixed notation for exponents
    -4 to 5, else exponential with two exponent digits; trailing zeros and a bare point
    dropped) is one lookup per value in :data:`_G6`.
    """
    x = np.asarray(values, dtype=float)
    n = x.size
    a = np.abs(x)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        e = np.floor(np.log10(a))
        fast = np.isfinite(e) & (e >= -17) & (e <= 27)
        e = np.where(fast, e, 0.0).astype(np.intp)
        for _ in range(2):  # log10 may be one off next to a power of ten: correct it
            k = 5 - e
            s = np.where(k >= 0, a * _POW10[np.abs(k)], a / _POW10[np.abs(k)])
            adjust = (s >= 1e6).astype(np.intp) - (s < 1e5)
            if not adjust.any():
                break
            e += adjust
            fast &= (e >= -17) & (e <= 27)
            e[~fast] = 0
        fast &= (s >= 1e5) & (s < 1e6) & (np.abs(s - np.floor(s) - 0.5) > 1e-8)
        m = np.where(fast, np.rint(s), 1e5)
    carry = m >= 1e6  # 999999.6 rounds to 1e6: one digit more, 1.00000e(e+1)
    m[carry] = 1e5
    e += carry
    m = m.astype(np.int32)
    source = np.empty((n, 13), np.uint8)
    for j in range(5, -1, -1):
        q = m // 10
        source[:, j] = m - 10 * q + 48
        m = q
    source[:, 6] = 46
    source[:, 7] = 48
    source[:, 8] = 101
    source[:, 9] = np.where(e < 0, 45, 43)
    ae = np.abs(e)
    source[:, 10] = ae // 10 + 48
    source[:, 11] = ae % 10 + 48
    source[:, 12] = 0
    last = 5 - np.argmax(source[:, 5::-1] != 48, axis=1)
    layout = np.where((e >= -4) & (e < 6), e + 4, 10) * 6 + last
    index = _G6[layout] + (np.arange(n) * 13)[:, None]
    out = np.zeros((n, 13), np.uint8)  # the 13th: '-1.23457e+100' (by Python, below)
    out[:, 0] = np.where(np.signbit(x), 45, 0)
    out[:, 1:12] = source.ravel().take(index)
    zero = a == 0
    if zero.any():  # '0', or '-0' for a negative zero
        out[zero, 1:] = 0
        out[zero, 1] = 48
        fast |= zero
    for i in np.flatnonzero(~fast).tolist():
        v = float(x[i])
        text = format(v, ".6g").encode("ascii") if v - v == 0 else b""
        out[i] = 0
        out[i, :len(text)] = np.frombuffer(text, np.uint8)
    return out


def _result_cells_by_row(getters):
    """:func:`_result_cells`, one row at a time (a C-level format per row where all
    numbers are finite, the constant columns written into the format once)."""
    n = len(getters[0][1]) if getters else 0
    parts, cols, kinds, finite = [], [], [], np.ones(n, bool)
    for kind, data in getters:
        if kind == "num":
            v = np.asarray(data, dtype=float)
            finite &= np.isfinite(v)
            if n and _constant(v):
                parts.append(format(float(v[0]), ".6g").replace("%", "%%"))
                continue
            parts.append("%.6g")
            cols.append(v.tolist())
            kinds.append(kind)
        else:
            first = data[0] if n else ""
            if n and list(data).count(first) == n:
                parts.append(_quote(str(first)).replace("%", "%%"))
                continue
            cache = {}
            parts.append("%s")
            cols.append([cache[t] if t in cache else cache.setdefault(t, _quote(str(t)))
                         for t in data])
            kinds.append(kind)
    template = "," + ",".join(parts)
    if not cols:
        return [template.replace("%%", "%")] * n
    slow_kinds = [kind for kind, _ in getters]
    slow_cols = None

    def slow(i):
        nonlocal slow_cols
        if slow_cols is None:  # every column, for the rows with a missing number
            slow_cols = [np.asarray(d, dtype=float).tolist() if k == "num" else d
                         for k, d in getters]
        return "," + ",".join(
            (format(c[i], ".6g") if c[i] - c[i] == 0 else "") if k == "num"
            else _quote(str(c[i])) for k, c in zip(slow_kinds, slow_cols))

    return [template % row if ok else slow(i)
            for i, (row, ok) in enumerate(zip(zip(*cols), finite.tolist()))]


def _extra_names(header, width):
    """Names of the columns of the cells beyond the header (a row longer than it):
    ``extra_K`` for the K-th cell of a row, ``_`` prepended while the name is taken."""
    taken = {h.strip().lower() for h in header}
    names = []
    for k in range(len(header) + 1, width + 1):
        name = f"extra_{k}"
        while name in taken:
            name = "_" + name
        names.append(name)
    return names


def _quote(text):
    """A CSV cell with minimal quoting (as the csv module writes it)."""
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def _csv(header, body, lines, out_names, getters, width):
    """The output CSV: the user's rows (their original text when unquoted) followed by
    the result cells. Built as one joined string (an io.StringIO holds 4 bytes per
    character: 120 MB for a 100 000-row output, and the time to fault that in)."""
    results = _result_cells(getters)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(list(header) + out_names)
    head = buf.getvalue()
    if lines is not None and isinstance(body, _FlatRows):  # no row to pad
        out = list(map(str.__add__, lines, results))
    elif lines is not None:
        out = [ln + "," * (width - len(r)) + res if len(r) < width
               else ln + res for ln, r, res in zip(lines, body, results)]
    else:
        pad = [""] * width
        out = [",".join(_quote(c) for c in (r + pad[len(r):] if len(r) < width else r))
               + res for r, res in zip(body, results)]
    del results
    out.append("")
    return head + "\n".join(out)


def _json(doc, header, body, out_names, getters, width):
    import json

    rows = []
    for i, r in enumerate(body):
        row = {}
        cells = r + [""] * (width - len(r)) if len(r) < width else r
        for h, c in zip(header, cells):
            row[h] = c
        for name, (kind, data) in zip(out_names, getters):
            row[name] = render.num(data[i]) if kind == "num" else data[i]
        rows.append(row)
    doc["rows"] = rows
    return json.dumps(doc, indent=2) + "\n"
