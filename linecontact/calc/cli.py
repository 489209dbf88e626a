"""Command line: ``linecontact calc``, a spreadsheet-like calculator for one case, a
sweep, or a CSV file of cases. This module only parses arguments and dispatches.

Usage (``linecontact calc --help`` has the full list)::

    linecontact calc --radius 5mm --length 10mm --modulus 210GPa --poisson 0.3 --load 1kN
    linecontact calc --diameter 10mm --length 10mm --estar 115GPa --depth 2um
    linecontact calc ... --radius2 -40mm --load 1kN      # concave second body (raceway)
    linecontact calc ... --inner-raceway 20mm --outer-raceway 30mm --load 1kN  # whole roller
    linecontact calc ... --load 0.1kN:10kN:20          # sweep, geometric spacing
    linecontact calc ... --load 100N:1kN:10 --linear   # sweep, linear spacing
    linecontact calc cases.csv -o results.csv          # batch, one case per row
    linecontact calc ... --json                        # machine-readable, SI
    linecontact calc ... --model li-popov:coefficients=eq11,johnson:c=0.72
    linecontact calc ... --load 1kN --crown-radius 500mm --tilt 1mrad  # profiled roller
    linecontact calc ... --load 1kN --profile iso16281 --json          # ... with q(x)

Where things are
    :mod:`linecontact.calc.cases`    the core inputs (options = CSV columns), the rules;
    :mod:`linecontact.calc.feature`  the shape of a feature (and how to add one);
    :mod:`linecontact.calc.features` raceways, profiled roller, tangential, viscoelastic;
    :mod:`linecontact.calc.compute`  evaluation of the models on whole arrays;
    :mod:`linecontact.calc.render`   table, JSON (one header) and output files;
    :mod:`linecontact.calc.batch`    CSV in and out;
    :mod:`linecontact._units`        the rule for a value: a number with one unit name.

Adding options and output: a feature (see :mod:`linecontact.calc.feature`); its
parameters become ``--options``, CSV columns and ``--help`` sections here with no
change to this module. A subcommand (``linecontact bearing``) is one module of
:mod:`linecontact.calc.subcommands` plus its line in ``SUBCOMMANDS`` (the shape:
:class:`linecontact.calc.feature.Subcommand`): its parser, one case, sweeps, batch,
JSON and ``--plot`` are this module's and :mod:`linecontact.calc.command`'s. A flag
that is not a value (like ``--linear``) is added in :func:`build_parser` below.

Inputs
    Values may carry ONE unit name ("5mm", "0.2 in", "210 GPa", "1kN"); bare numbers are
    SI (m, N, Pa). No decimal comma, no expression, nothing non-finite (see
    :mod:`linecontact._units`). The second body is flat unless ``--radius2`` is given,
    and the roller rigid unless ``--modulus2``/``--poisson2`` are; ``--estar`` gives the
    effective modulus of Eq. 3 directly (E*, not E' = 2E*). Poisson's ratio may be 0.5.

Output
    One row per model of :func:`linecontact.models.standard_models` (in its order: the
    default best estimate first), or of ``--model``, and per value of a sweep. Columns:
    the given F or d, the other one, the stiffness k = dF/dd, the Hertz half-width b
    (Li & Popov (2017), Eq. 1) and peak pressure p0 of the strip (at mid-length; a
    straight roller's end pressure is higher, singular on a half-space), the MDR contact
    half-length a = k/(2E*), each model's deviation from the best estimate, and a note:
    flags for geometry no model covers (d > 0.15 R, b > L/2) and the model's own
    message when the case is outside its range (its values are then "-"). A whole
    roller between two raceways prints its deflection (sum of the two contacts) and
    series stiffness in their own columns. Engineering units, or SI with ``--si``.
    ``--json`` is always SI and carries one header: version, command, units, notes and
    each model's provenance.

Sweeps
    Any numeric option ``--NAME START:STOP:N``: N values from START to STOP, both
    included, spaced geometrically (equal ratios); ``--linear`` spaces them evenly, as
    does a sweep of a signed quantity through zero (``--tilt -1mrad:1mrad:5``). Two or
    more sweeps give the grid (every combination; the first option varies slowest).

Batch
    ``linecontact calc FILE.csv``: see :mod:`linecontact.batch` (user columns are never
    overwritten; a failing row says why in its ``error`` cell and the others are
    written).

Exit status: 0 on success, 2 on bad input (one line on stderr naming the parameter,
its value and the valid range; in a batch, when any row failed, after writing all
rows). A one-case call where no model covers the case prints the table and the first
model's note on stderr, status 2.

Nothing here runs at import; pandas is never imported, and pint only for a unit name
outside the built-in table of :mod:`linecontact._units` (mm, GPa, kN, in, lbf, psi, ...
need no pint), so a one-case call starts quickly.
"""

from __future__ import annotations

import argparse
import re
import sys

from .cases import PARAMETERS
from .feature import RAW_KINDS, option_name

__all__ = ["main"]

PROG = "linecontact"


class _Once(argparse.Action):
    """An option that takes a value, given once: a second occurrence is refused (argparse
    would silently keep the last one, so `--load 1kN ... --load 2kN` computed 2 kN)."""

    def __call__(self, parser, namespace, values, option_string=None):
        old = getattr(namespace, self.dest, None)
        if option_string is not None and old is not None and old is not self.default:
            parser.error(f"{option_string} is given twice ({old!r} and {values!r}); give "
                         "it once (several values: a sweep START:STOP:N or a CSV batch)")
        setattr(namespace, self.dest, values)


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose usage errors are one line on stderr and exit status 2, and
    whose options that take a value may be given once (:class:`_Once`)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.register("action", None, _Once)     # add_argument without an action
        self.register("action", "store", _Once)

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser():
    parser = _Parser(
        prog=PROG,
        description="Stiffness and deflection of a finite cylinder (roller) pressed on its "
        "side into an elastic half-space or a second cylinder.",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    calc = sub.add_parser(
        "calc",
        help="depth, stiffness and contact size for one case, a sweep or a CSV of cases",
        description="Depth (or force), stiffness, Hertz half-width and peak pressure, and "
        "MDR contact half-length of a roller of radius R and length L, one row per "
        "model. A value is a number with one unit name ('5mm', '0.2 in', '210 GPa', "
        "'1kN'); bare numbers are SI.",
        epilog="Sweeps: --NAME START:STOP:N (any numeric option) gives N values from START "
        "to STOP, both included, spaced geometrically; --linear spaces them evenly (a "
        "signed range through zero always is); two sweeps give the grid. Batch: "
        "FILE.csv holds one case per row with columns named like the options (inner_raceway "
        "for --inner-raceway); results are appended as columns, user columns are kept. "
        "Exit status 2 on bad input.",
    )
    calc.add_argument("csv", nargs="?", metavar="FILE.csv", help="batch: one case per row")
    groups = {}
    for p in PARAMETERS:
        if p.group not in groups:
            groups[p.group] = calc.add_argument_group(p.group)
        groups[p.group].add_argument(
            option_name(p.name), dest=p.name, metavar="VALUE", help=f"{p.help} [{p.kind}]"
        )
    out = calc.add_argument_group("models and output")
    out.add_argument(
        "--linear", action="store_true", help="linear instead of geometric sweep spacing"
    )
    out.add_argument(
        "--model",
        metavar="KEY[:OPT=VAL][,...]",
        help="only these models, e.g. 'li-popov:coefficients=eq11,johnson:c=0.72'; 'all' "
        "for the standard set. Yes/no options take true/false, yes/no or 1/0; a number "
        "takes the unit its model documents (profiled-roller:tilt=1mrad). Default: "
        "the standard set for one case, its first model (the best estimate) in a batch",
    )
    out.add_argument("--si", action="store_true", help="output in SI units (m, N, N/m, Pa)")
    out.add_argument("--json", action="store_true", help="machine-readable JSON (SI units)")
    out.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")
    out.add_argument("--plot", metavar="FILE", help="also draw the case (one case or a "
                     "sweep): F(d) of the models where each applies, with the computed "
                     "points, and a profiled roller's q(x); PNG, SVG or PDF by the "
                     "extension; needs matplotlib (pip install 'linecontact[plot]')")
    out.add_argument("--progress", dest="progress", action="store_true", default=None,
                     help="progress bar on stderr for a batch (default: batches of 10000 "
                     "rows or more, on a terminal)")
    out.add_argument("--no-progress", dest="progress", action="store_false",
                     help="no progress bar")
    _add_cluster_options(calc)
    for command in _commands().values():
        _add_cluster_options(_add_command(sub, command))
    return parser


def _add_cluster_options(parser):
    """A batch on a dask cluster (:mod:`linecontact.calc.spread`): the same output."""
    g = parser.add_argument_group(
        "batch on a dask cluster (pip install 'linecontact[cluster]'; docs/cluster.md)")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="evaluate the CSV batch's rows on the dask cluster of this "
                   "scheduler (tcp://HOST:PORT); the output is the same, byte for byte")
    g.add_argument("--workers", metavar="N",
                   help="evaluate the CSV batch's rows on a local dask cluster of N "
                   "worker processes (listening on 127.0.0.1 only)")
    g.add_argument("--connect-timeout", metavar="SECONDS",
                   help="with --scheduler: give up (exit 2) when the address does not "
                   "answer as a dask scheduler within this time (default 60)")


def _commands():
    """name -> :class:`~linecontact.calc.command.Command` of every registered
    subcommand (:data:`linecontact.calc.subcommands.SUBCOMMANDS`)."""
    from .command import Command
    from .subcommands import SUBCOMMANDS

    return {m.name: Command(m) for m in SUBCOMMANDS}


class _Renamed(argparse.Action):
    """An option renamed to the calculator's: refused with the new name."""

    def __init__(self, *args, now="", **kwargs):
        self.now = now
        super().__init__(*args, **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        parser.error(f"{option_string} is now {self.now}")


def _add_command(sub, command):
    """A subcommand's parser: its parameters (one option each, in their groups) and
    the calculator's output options."""
    m = command.module
    p = sub.add_parser(command.name, help=m.help, description=m.description,
                       epilog=m.epilog)
    p.add_argument("csv", nargs="?", metavar="FILE.csv", help="batch: one case per row")
    groups = {}
    for q in command.parameters:
        if q.group not in groups:
            groups[q.group] = p.add_argument_group(q.group)
        groups[q.group].add_argument(option_name(q.name), dest=q.name, metavar="VALUE",
                                     help=f"{q.help} [{q.kind}]")
    out = p.add_argument_group("output")
    out.add_argument("--linear", action="store_true",
                     help="linear instead of geometric sweep spacing")
    out.add_argument("--si", action="store_true", help="output in SI units")
    out.add_argument("--json", action="store_true", help="machine-readable JSON (SI units)")
    out.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")
    out.add_argument("--plot", metavar="FILE", help="also draw the case (one case or a "
                     "sweep); PNG, SVG or PDF by the extension; needs matplotlib (pip "
                     "install 'linecontact[plot]')")
    out.add_argument("--figure", action=_Renamed, now="--plot FILE (PNG, SVG or PDF by "
                     "the extension), as in linecontact calc", help=argparse.SUPPRESS)
    out.add_argument("--progress", dest="progress", action="store_true", default=None,
                     help="progress bar on stderr for a batch")
    out.add_argument("--no-progress", dest="progress", action="store_false",
                     help="no progress bar")
    return p


def _value_options():
    names = {p.name for p in PARAMETERS}
    for c in _commands().values():
        names |= {p.name for p in c.parameters}
    return {option_name(n) for n in names}


_VALUE_OPTIONS = _value_options()
_NEGATIVE = re.compile(r"^-(\d|\.\d)")


def _join_negative_values(argv):
    """Turn ``--radius2 -40mm`` into ``--radius2=-40mm`` so argparse does not take the
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


def sweep_cells(raw, linear=False, parameters=PARAMETERS):
    """Cells of a command line with sweeps: name -> ndarray of SI floats (a sweep, or
    the grid of several: every combination, the first varying slowest) or list of str.

    Returns (cells, n). A sweep of a signed quantity whose range includes zero or a
    negative end is spaced linearly (a geometric one has no such values).
    `parameters`: the command's (default: the calculator's).
    """
    import numpy as np

    from .._units import parse_quantity, parse_sweep

    sweeps = {}
    for p in parameters:
        text = raw.get(p.name)
        if not (p.sweep and p.kind not in RAW_KINDS and text is not None and ":" in text):
            continue
        lin = linear
        if not p.positive and not lin:
            ends = text.split(":")[:2]
            try:
                lin = any(parse_quantity(option_name(p.name), e, p.kind, positive=False) <= 0
                          for e in ends)
            except ValueError:
                pass  # parse_sweep says what is wrong
        sweeps[p.name] = np.array(parse_sweep(option_name(p.name), text, p.kind,
                                              linear=lin, positive=p.positive))
    n = 1
    for arr in sweeps.values():
        n *= len(arr)
    if n > 100000:
        raise _Failed(f"{' x '.join(option_name(k) for k in sweeps)}: a grid of {n} cases; "
                      "valid: at most 100000 (or a CSV batch)")
    grids = np.meshgrid(*sweeps.values(), indexing="ij") if sweeps else []
    cells = {k: g.ravel() for k, g in zip(sweeps, grids)}
    for k, v in raw.items():
        if v is not None and k not in cells:
            cells[k] = [v] * n
    return cells, n


def _calc_one(args, argv, specs):
    """One case or a sweep: a table (or JSON) with one row per model and value."""
    from . import render
    from .cases import parse_cases
    from .compute import compute

    raw = {p.name: getattr(args, p.name) for p in PARAMETERS}
    cells, n = sweep_cells(raw, args.linear)
    cases, present, errors = parse_cases(cells, n)
    if errors[0]:
        raise _Failed(errors[0])
    results = compute(cases, errors, specs)
    bad = next((e for e in errors if e), "")
    if bad:  # an unexpected failure of a model, or a feature's one-case refusal
        raise _Failed(bad)
    if args.plot is not None:  # refuse a bad file name before anything is written
        from ..errors import OutOfRangeError
        from ..plot import FORMATS
        if args.plot.rsplit(".", 1)[-1].lower() not in FORMATS:
            raise OutOfRangeError("--plot", args.plot, "a name ending in .png, .svg "
                                  "or .pdf")
    if args.json:
        render.write(render.one_json(argv, cases, present, results), args.output)
    else:
        render.write(render.table_text(cases, present, results, args.si), args.output)
    if args.plot is not None:
        from .figure import draw_results
        draw_results(results, args.plot)
    computed = any(not note for s in results.sets for note in s["note"])
    if not computed:
        notes = [s["note"][0] for s in results.sets]
        _error(notes[0] if notes else "no model selected")
        return 2
    return 0


def _command_one(command, args, argv):
    """A subcommand's one case or sweep: its text (or JSON), and the figure."""
    from . import render

    raw = {p.name: getattr(args, p.name) for p in command.parameters}
    cells, n = sweep_cells(raw, args.linear, command.parameters)
    cases, present, errors = command.parse(cells, n)
    if errors[0]:
        raise _Failed(errors[0])
    results = command.evaluate(cases, errors)
    bad = next((e for e in errors if e), "")
    if bad:
        raise _Failed(bad)
    _check_plot_name(args.plot)
    if args.json:
        render.write(command.json(argv, cases, present, results), args.output)
    else:
        render.write(command.text(cases, results, args.si), args.output)
    if args.plot is not None:
        command.draw(results, args.plot)
    return 0


def _check_plot_name(path):
    """Refuse a --plot file name of no known format before anything is written."""
    if path is None:
        return
    from ..plot import FORMATS
    from ..errors import OutOfRangeError
    if path.rsplit(".", 1)[-1].lower() not in FORMATS:
        raise OutOfRangeError("--plot", path, "a name ending in .png, .svg or .pdf")


#: The options that say where a batch runs, not what it computes.
_CLUSTER_OPTIONS = ("--scheduler", "--workers", "--connect-timeout")


def _without_cluster_options(argv):
    """The command line without the cluster's options (with their values): the JSON
    header's ``command`` says what was computed, the same wherever it ran, so that a
    batch on a cluster writes the serial batch's bytes."""
    out, skip = [], False
    for tok in argv:
        if skip:
            skip = False
            continue
        name = tok.split("=", 1)[0]
        if len(name) > 4 and sum(o.startswith(name) for o in _CLUSTER_OPTIONS) == 1:
            skip = "=" not in tok      # argparse's abbreviations too (--sched)
            continue
        out.append(tok)
    return out


def _check_cluster_options(args):
    """The cluster's options: with a CSV batch only, --scheduler or --workers (not
    both), their values read (a bad one: one line, exit 2, before the file is read)."""
    given = [o for o, v in (("--scheduler", args.scheduler), ("--workers", args.workers),
                            ("--connect-timeout", args.connect_timeout)) if v is not None]
    if not given:
        return
    if args.csv is None:
        raise _Failed(f"{given[0]} runs a CSV batch on a dask cluster; give the FILE.csv "
                      "(one case or a sweep is computed in this process)")
    if args.scheduler is not None and args.workers is not None:
        raise _Failed("--scheduler and --workers: give one (--workers N starts a local "
                      "cluster; the workers of --scheduler are the cluster's own)")
    if args.connect_timeout is not None and args.scheduler is None:
        raise _Failed("--connect-timeout is the time to reach --scheduler; give that "
                      "address too (or leave the option out)")
    from .cluster import (check_connect_timeout, check_scheduler_address,
                          check_workers_option, require_distributed)

    if args.scheduler is not None:
        check_scheduler_address(args.scheduler)
        args.connect_timeout = check_connect_timeout(args.connect_timeout)
    else:
        args.workers = check_workers_option(args.workers)
    require_distributed("--scheduler" if args.scheduler is not None else "--workers")


class _Failed(Exception):
    """A one-line error message already composed."""


def _error(message, command="calc"):
    print(f"{PROG} {command}: error: {message}", file=sys.stderr)


def main(argv=None):
    """Entry point of the ``linecontact`` console script; returns the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    try:
        args = parser.parse_args(_join_negative_values(argv))
    except SystemExit as exc:  # --help (0) or a usage error (2), already printed
        return exc.code if isinstance(exc.code, int) else 2
    if args.command is None:
        parser.print_help(sys.stderr)
        return 2
    name = args.command
    command = None if name == "calc" else _commands()[name]
    parameters = PARAMETERS if command is None else command.parameters
    try:
        from . import render

        if command is None:
            from .compute import parse_model_option

            specs = parse_model_option(args.model)
        else:
            specs = None
        render.refuse_input_as_output(args.output, [args.csv] + [
            getattr(args, p.name) for p in parameters if p.kind == "path"])
        render.refuse_same_output(args.output, getattr(args, "plot", None))
        if args.csv is None:  # a batch checks its columns too (batch.run_batch)
            render.refuse_json_only(parameters, {p.name: getattr(args, p.name)
                                                 for p in parameters}, args.json)
        _check_cluster_options(args)
        if args.csv is not None:
            from .batch import CALC, run_batch

            if getattr(args, "plot", None) is not None:
                raise _Failed("--plot draws one case or a sweep, not a CSV batch (read "
                              "the batch's output into linecontact.plot instead)")

            options = {p.name: getattr(args, p.name) for p in parameters}
            return run_batch(args, _without_cluster_options(argv), specs, options,
                             CALC if command is None else command)
        if command is not None:
            return _command_one(command, args, argv)
        return _calc_one(args, argv, specs)
    except _Failed as exc:
        _error(str(exc), name)
        return 2
    except ValueError as exc:
        from .cluster import ClusterError

        if isinstance(exc, ClusterError):
            _error(str(exc), name)
            return exc.exit_code
        # InputError, BatchError (ours) or the library's OutOfRangeError
        from .._units import InputError
        from ..errors import CombinationError, OutOfRangeError, UnknownNameError
        from .batch import BatchError

        if not isinstance(exc, (InputError, OutOfRangeError, BatchError, CombinationError,
                                UnknownNameError)):
            raise
        _error(str(exc), name)
        return 2
    except BrokenPipeError:  # the reader stopped early (`| head`): stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except KeyboardInterrupt:
        return 130
    except ImportError as exc:  # --plot without matplotlib: say how to install it
        from ..plot import MissingDependencyError

        if not isinstance(exc, MissingDependencyError):
            raise
        _error(str(exc), name)
        return 2
    except OSError as exc:  # the output file (render.OutputError names it) and others
        fname = getattr(exc, "filename", None)
        reason = exc.strerror or str(exc) or type(exc).__name__
        _error(f"{fname!r}: {reason}" if fname else reason, name)
        return 2
