"""A subcommand of ``linecontact`` (e.g. ``linecontact bearing``) run by the calculator's
machinery: the shape of one is :class:`linecontact.calc.feature.Subcommand`, the
registration :data:`linecontact.calc.subcommands.SUBCOMMANDS`.

:class:`Command` wraps a subcommand module and answers what the calculator's core asks
of a command, so that a subcommand gets, with no code of its own:

- its options: one ``--NAME`` per :class:`~linecontact.calc.feature.Parameter`
  (the CSV column ``NAME``, the ``--help`` entry), read by the unit rules
  (:func:`linecontact.calc.cases.parse_columns`), each given once, sweeps
  ``START:STOP:N`` of any numeric one (:func:`linecontact.calc.cli.sweep_cells`);
- the output options of ``linecontact calc``: ``--si``, ``--json`` (the one header of
  :func:`linecontact.calc.render.json_header`), ``-o`` (never onto an input, written
  atomically), ``--plot FILE`` (PNG, SVG or PDF by the extension, refused before
  anything is written, not with a CSV batch);
- the CSV batch of :func:`linecontact.calc.batch.run_batch` with all its rules
  (docs/batch.md, docs/inputs.md): user columns kept and never overwritten, a column
  twice or misspelt or with a unit in its header refused, an option against a filled
  cell refused in that row, a ragged row an error in that row, exit status 2 when any
  row failed; and the DataFrame of :mod:`linecontact.calc.frame`.

A row the library refuses (a bearing that does not fit, a load beyond the law) keeps
its place and says why in ``error``.
"""
from __future__ import annotations

import numpy as np

from .feature import RAW_KINDS, Fail, option_name

__all__ = ["Command", "CommandResults", "command_named"]

#: The text columns of a subcommand's row, after its fields (then ``error``): the
#: model or method the row was solved with (not ``model``: a subcommand may take a
#: ``model`` input column, which a rerun on its output would read), and the note.
TEXT_COLUMNS = ("model_used", "note")


class CommandResults:
    """A subcommand's results: per row the module's ``solve`` result (``objects``, None
    where not computed), its fields [SI] (``rows``: name -> value or None), the
    model label and the note; ``errors`` the row errors; ``models`` the JSON header's
    entries (id -> object with key, label, provenance)."""

    def __init__(self, n, errors, cases):
        self.errors = errors
        self.cases = cases
        self.objects = [None] * n
        self.rows = [None] * n
        self.models = {}

    @classmethod
    def merged(cls, parts, rows, errors, cases):
        """The results of a whole batch from those of parts of its rows
        (:meth:`Command.evaluate` on each alone, the batch on a cluster; a row's
        solution depends on that row alone): `rows` the rows each part holds, in
        order, consecutive ranges in row order (so that the models come in the order
        of their first row, as a serial run registers them). `errors`, the whole
        batch's, is updated in place."""
        if sum(len(r) for r in rows) != len(errors):
            raise ValueError(f"CommandResults.merged: the parts hold "
                             f"{sum(len(r) for r in rows)} rows, the batch {len(errors)}")
        out = cls(len(errors), errors, cases)
        for p, r in zip(parts, rows):
            for k, i in enumerate(list(r)):
                errors[i] = p.errors[k]
                out.objects[i] = p.objects[k]
                out.rows[i] = p.rows[k]
            for mid, entry in p.models.items():
                out.models.setdefault(mid, entry)
        return out


class _Entry:
    def __init__(self, key, label, provenance):
        self.key, self.label, self.provenance = key, label, provenance


class Command:
    """A subcommand module (:class:`~linecontact.calc.feature.Subcommand`) as the
    calculator's core sees a command (see the module docstring)."""

    def __init__(self, module):
        self.module = module
        self.name = module.name
        self.parameters = tuple(module.parameters)
        self.by_name = {p.name: p for p in self.parameters}
        self.fields = dict(module.fields)
        self.notes = dict(module.notes)
        self.sweep_columns = tuple(p.name for p in self.parameters
                                   if p.sweep and p.kind not in RAW_KINDS)

    # -- the rules and the evaluation ---------------------------------------------
    def parse(self, cells, n, label=option_name):
        """(cases, present, errors) of a table of cells, as
        :func:`linecontact.calc.cases.parse_cases` for ``calc``: the unit rules per
        column, then the module's ``resolve``."""
        from .cases import Cases, parse_columns

        values, present, raw, errors = parse_columns(self.parameters, cells, n, label)
        cases = Cases(n, values, present, raw)
        cases.label = label
        fail = Fail(errors, raw, label, not label(self.parameters[0].name).startswith("--"))
        cases.state = self.module.resolve(values, present, fail)
        return cases, present, errors

    def evaluate(self, cases, errors, args=None, specs=None, progress=None):
        """Solve every good row (the module's ``solve``); a refusal of the library is
        the row's error (one line), any other exception too, never lost."""
        from .._units import InputError
        from ..errors import CombinationError, OutOfRangeError, UnknownNameError

        n = cases.n
        res = CommandResults(n, errors, cases)
        done = 0
        for i in range(n):
            if errors[i]:
                continue
            try:
                # an intermediate that overflows (a moment of 1e300 N m) ends in the
                # library's refusal or a NaN the row shows as none; numpy's warnings
                # would only add lines to stderr (as in calc's evaluation)
                with np.errstate(over="ignore", divide="ignore", invalid="ignore",
                                 under="ignore"):
                    obj = self.module.solve(cases.values, i, cases.state)
                    row = self.module.row(obj, cases.state, i)
            except OutOfRangeError as exc:
                errors[i] = self._in_user_words(exc, cases, i)
                continue
            except (InputError, CombinationError, UnknownNameError) as exc:
                errors[i] = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
                continue
            except Exception as exc:  # noqa: BLE001 - reported in the row, never lost
                detail = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                errors[i] = (f"unexpected {type(exc).__name__}"
                             + (f": {detail}" if detail else ""))
                continue
            res.objects[i], res.rows[i] = obj, row
            key, label, provenance = self.module.model_of(obj)
            mid = label
            res.models.setdefault(mid, _Entry(key, label, provenance))
            done += 1
            if progress is not None:
                progress(done)
        return res

    def _in_user_words(self, exc, cases, i):
        """The library's refusal of one of the command's own inputs (``rollers``,
        ``clearance``, ``n_slices``: the library names its parameters as the command
        does) said as the user gave it: the option or column and the value as typed
        (``--clearance = '-5mm': a preload presses ...; valid: ...``); any other
        refusal as the library words it."""
        text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        name = getattr(exc, "parameter", None)
        col = cases.cells.get(name) if name in self.by_name else None
        if col is None:
            return text
        label = getattr(cases, "label", option_name)
        typed = (f"{float(col[i]):.6g}" if isinstance(col, np.ndarray)
                 else str(col[i]).strip())
        reason = getattr(exc, "hint", "") or "out of range"
        return f"{label(name)} = {typed!r}: {reason}; valid: {exc.valid}"

    # -- the batch on a cluster (linecontact.calc.spread) ---------------------------
    def __reduce__(self):
        """Pickled by name (a task for a worker): the worker's own subcommand."""
        return command_named, (self.name,)

    @staticmethod
    def groups(cases, errors):
        """None: every row is solved alone (the parts may be any ranges)."""
        return None

    @staticmethod
    def merge(parts, rows, errors, cases, label=None):
        """The results of the whole batch from its parts' (:meth:`CommandResults.merged`)."""
        return CommandResults.merged(parts, rows, errors, cases)

    # -- the batch's columns and header --------------------------------------------
    def layout(self, results, cases, si):
        """Result column names and, for each, ('num' or 'text', values over the rows):
        every field (``NAME_UNIT``, as ``calc`` names them), the model used, the note,
        and ``error`` last."""
        from .batch import _col_name_of, _num_column

        cols, getters = [], []
        rows = results.rows
        for name, f in self.fields.items():
            cols.append(_col_name_of(name, f, si))
            getters.append(_num_column(rows, name, f, si))
        for t in TEXT_COLUMNS:
            cols.append(t)
            getters.append(("text", ["" if r is None else str(r.get(t, "")) for r in rows]))
        cols.append("error")
        getters.append(("text", results.errors))
        return cols, getters

    def header(self, argv, results):
        """The one JSON header (:func:`linecontact.calc.render.json_header`) with this
        command's units and notes."""
        from . import render

        return render.json_header(argv, results, fields=self.fields, notes=self.notes)

    def result_names(self):
        """Every name a result column of this command may have (a rerun's own)."""
        from .batch import _col_name_of

        return ({_col_name_of(n, f, si).lower() for n, f in self.fields.items()
                 for si in (False, True)} | set(TEXT_COLUMNS) | {"error"})

    # -- one case or a sweep ---------------------------------------------------------
    def text(self, cases, results, si):
        """The plain-text output of one case (its description, the fields as a list,
        the module's tables, the notes) or of a sweep (one row per case)."""
        from . import render

        return render.command_text(self, cases, results, si)

    def json(self, argv, cases, present, results):
        """JSON of one case or a sweep: the header, the inputs [SI], and one row per
        case (the fields [SI], the model, the notes, and the module's solution)."""
        import json

        from . import render

        doc = self.header(argv, results)
        inputs = {}
        for p in self.parameters:
            if not present[p.name].any():
                continue
            col = cases.values[p.name]
            if isinstance(col, np.ndarray):
                vals = [render.num(x) for x in col]
            else:
                vals = [c.strip() for c in col]
            inputs[p.name] = vals if len(set(map(str, vals))) > 1 else vals[0]
        doc["inputs"] = inputs
        rows = []
        for i, (obj, row) in enumerate(zip(results.objects, results.rows)):
            if row is None:
                rows.append({"error": results.errors[i]})
                continue
            out = {k: render.num(row.get(k)) for k in self.fields}
            out.update({t: row.get(t, "") for t in TEXT_COLUMNS})
            out.update(self.module.to_json(obj))
            rows.append(out)
        doc["rows"] = rows
        return json.dumps(render.clean_json(doc), indent=2, allow_nan=False) + "\n"

    def draw(self, results, path):
        """``--plot``: the module's figure of the computed rows, saved by
        :func:`linecontact.plot.save` (png, svg or pdf)."""
        from .figure import draw_command

        return draw_command(self, results, path)


def command_named(name):
    """The :class:`Command` of the registered subcommand `name`
    (:data:`linecontact.calc.subcommands.SUBCOMMANDS`)."""
    from .subcommands import SUBCOMMANDS

    return Command(next(m for m in SUBCOMMANDS if m.name == name))
