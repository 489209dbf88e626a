"""The plug-in shape of a calculator feature (``linecontact calc``).

A feature is one module of :mod:`linecontact.calc.features` that adds options (= CSV
columns), the rules between them, output columns and, optionally, extra tables to the
calculator. It holds no physics: it reads its inputs, asks the library, and names what
it shows. The core (:mod:`~linecontact.calc.cases`, :mod:`~linecontact.calc.compute`,
:mod:`~linecontact.calc.render`, :mod:`~linecontact.calc.batch`,
:mod:`~linecontact.calc.cli`) never names a feature: it loops over
:data:`linecontact.calc.features.FEATURES`.

How to add a feature (one module + one registration line)
    1. Write ``linecontact/calc/features/NAME.py`` with these module-level names (a
       module satisfies the :class:`Feature` protocol by having them):

       ``name``
           Short name, e.g. ``"stresses"`` (the key of its :class:`State`).
       ``group``
           Title of its ``--help`` section.
       ``parameters``
           A tuple of :class:`Parameter` (``group=group``): each is an option
           ``--NAME`` AND a CSV column ``NAME``, parsed to SI before ``resolve`` sees
           it; a sweep ``START:STOP:N`` and a batch column come for free.
       ``fields``
           Mapping output column name -> :class:`Field` (heading, SI and engineering
           unit): every name ``columns`` may return.
       ``notes``
           Mapping key -> one paragraph (the JSON header's ``notes``; the table prints
           them under the table when the feature is active).
       ``resolve(values, present, fail) -> State | None``
           The input rules. ``values[name]``: SI float array (NaN where not given), or
           for ``text``/``path``/``angle`` parameters the cells as typed (list of str);
           also the resolved core values ``radius`` (R1 [m]), ``given`` ('load' or
           'depth' per row) and ``value`` (F [N] or d [m]). ``present[name]``: bool
           array, given in that row. ``fail(mask, name, valid, reason)`` refuses the
           rows of ``mask`` with one line (the parameter as the user wrote it, its
           value as typed, the valid range, the reason); ``fail.label(name)`` is the
           parameter as written (``--tilt`` or the column ``tilt``), ``fail.cell(name,
           i)`` its text in row i, ``fail.batch`` True for a CSV batch,
           ``fail.message(mask, text)`` refuses with a library's own one-line message
           (a :class:`~linecontact.errors.CombinationError`). Return None
           when none of the feature's inputs is given (the feature is then inactive and
           costs nothing: import heavy modules inside ``columns``/``blocks``), else a
           :class:`State` whose ``rows`` marks where it is active.
       ``columns(model, rows, normal, state) -> dict``
           For the indices ``rows`` (int array of case rows, all of one contact and one
           model, each with a computed normal state): ``model`` is that contact's law, a
           :class:`linecontact.models.ContactModel` (``model.radius``,
           ``model.length``, ``model.estar``, every method; a profiled roller's law is
           its coupled-slice F(d)), and ``model.contact`` the library's
           :class:`linecontact.contact.Contact` where a feature composed the contact (a
           profile, a tilt, raceways; None for a plain straight contact; a whole
           roller between raceways has no single law: use ``model.contact``).
           ``normal``: the normal state over ``rows``, SI arrays ``force``, ``depth``,
           ``stiffness``, ``half_width``, ``peak_pressure``, ``contact_radius``,
           ``moment``, ``tilt``, ``tilt_stiffness`` (NaN where not defined), and
           ``solution`` (object array: the library's
           :class:`~linecontact.roller.RollerSolution` or
           :class:`~linecontact.raceway.RacewaySolution` of the row, else None).
           Return name -> array over ``rows`` for the names of ``fields`` it computes,
           plus optionally ``"flags"``: a sequence of str (one per row, ``""`` for
           none) added to the rows' note cell. Called once per contact group and model.
       ``blocks(state, results) -> list[Block]``
           Extra tables printed after the main one (``[]`` for none), e.g. the profiled
           roller's rows. ``results.errors`` is the list of row errors: a one-case
           failure is written there (it ends the command with that line).
       ``figure(state, results) -> list`` (optional)
           ``--plot FILE``: what the feature computed, drawn by :mod:`linecontact.plot`
           (no physics: the library's result objects, asked of the library as in
           ``columns``). A list of items, each either a callable ``draw(fig=None)`` (a
           figure function of :mod:`linecontact.plot` with its result bound, e.g.
           ``functools.partial(plot.creep, result)``: one band of panels) or a str
           (one line on stderr: a result that has no figure, or what was left out of
           it); ``[]`` when the feature adds nothing. ``columns`` may remember each
           row's contact law for it with :func:`keep` (``state.kept[i]``: the first
           model set's, as ``columns`` saw it). :mod:`linecontact.calc.figure` puts
           the core's F(d) and every feature's items into one figure
           (:func:`linecontact.plot.panels` when there are several). A feature
           without ``figure`` is said on stderr as having none.

    2. Add the module to the tuple :data:`linecontact.calc.features.FEATURES`.

    That is all: ``--help``, the option parser, CSV batches, sweeps, the table, CSV and
    JSON renderers pick it up. A test: ``tests/test_cli.py`` runs every option in a
    batch and on the command line.

Adding a subcommand is one module plus one line
    A subcommand (``linecontact bearing``) is a question of its own, with its own
    inputs and results, on the same machinery (:mod:`linecontact.calc.command`).
    1. Write ``linecontact/calc/subcommands/NAME.py`` with these module-level names
       (the :class:`Subcommand` protocol):

       ``name``, ``help``, ``description``, ``epilog``
           ``linecontact NAME``, its line in ``linecontact --help``, its ``--help``.
       ``parameters``
           A tuple of :class:`Parameter`, as a feature's: each is an option
           ``--NAME``, a CSV column ``NAME`` and a ``--help`` entry (under its
           ``group``), parsed to SI by the unit rules; sweeps come for free.
       ``fields``
           Mapping output name -> :class:`Field`: the batch's columns (``NAME_UNIT``),
           the JSON's units, the one-case list.
       ``notes``
           Mapping key -> one paragraph (the JSON header's notes, printed under the
           table).
       ``note_fields`` (optional)
           Mapping note key -> the field it explains: the text leaves out a note
           whose field no row computed (the JSON header keeps every note).
       ``resolve(values, present, fail) -> State``
           The input rules over all rows, as a feature's (``fail`` refuses rows with
           one line); the State is handed to ``solve``.
       ``solve(values, i, state) -> object``
           Row i: ask the library. A library refusal (a ``ValueError`` of
           :mod:`linecontact.errors` or :mod:`linecontact._units`) is the row's
           error; no physics here.
       ``row(obj, state, i) -> dict``
           Field name -> SI value (None: not defined), plus ``"model_used"`` (the method),
           ``"notes"`` (list of str) and ``"note"`` (them joined, the batch's cell).
       ``model_of(obj) -> (key, label, provenance)``
           The JSON header's entry of the row's model.
       ``describe(obj, si) -> str``, ``blocks(obj) -> list[Block]``
           One case's first line, and its extra tables (e.g. one row per roller).
       ``to_json(obj) -> dict``
           One case's full result for ``--json`` (SI).
       ``figure(objects) -> matplotlib Figure``
           ``--plot FILE``: the computed cases drawn by :mod:`linecontact.plot`.

    2. Add the module to the tuple :data:`linecontact.calc.subcommands.SUBCOMMANDS`.

    That is all: the parser (``--si``, ``--json``, ``-o``, ``--plot``, ``--linear``,
    each option once), the one-case text and JSON (the calculator's header), the CSV
    batch with every rule of ``calc`` (:func:`linecontact.calc.batch.run_batch`:
    docs/batch.md, docs/inputs.md) and the DataFrame
    (:func:`linecontact.calc.frame.command_frame`) pick it up; its batch is held to
    the calculator's input-rule tests (tests/test_command_input_contracts.py, parametrised over
    the commands).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping, Protocol, Sequence

import re

import numpy as np

__all__ = ["Parameter", "Field", "State", "Block", "Feature", "Subcommand", "Fail",
           "option_name", "keep",
           "bounds_of", "RAW_KINDS", "each", "short", "flag_text",
           "DEPTH_OVER_RADIUS_MAX", "HALF_WIDTH_OVER_LENGTH_MAX"]

#: Kinds of :class:`Parameter` kept as typed (list of str) for the feature to read
#: (a profile spec, a file path).
RAW_KINDS = ("path", "text")


#: Depth beyond which a row is flagged: the range of Li & Popov's BEM study (d <= 0.15 R,
#: docs/theory.md, section 'BEM'); beyond it the gap is no longer y^2/(2R) to within
#: 1 % (circle vs parabola at y = b) and the tables do not reach.
DEPTH_OVER_RADIUS_MAX = 0.15
#: Hertz half-width beyond which a row is flagged: for b > L/2 the end zones, each about
#: b wide, where the pressure departs from the plane-strain strip meet, so no part of
#: the roller is in line contact and Eq. 1, 2 and 4 lose their basis.
HALF_WIDTH_OVER_LENGTH_MAX = 0.5


@dataclass(frozen=True)
class Parameter:
    """One input of the calculator: an option ``--NAME`` and a CSV column ``NAME``.

    Attributes
    ----------
    name : str
        Column name (``_`` becomes ``-`` in the option).
    kind : str
        A kind of :data:`linecontact._units.DIMENSIONS` (``length``, ``force``,
        ``pressure``, ``dimensionless``, ``time``, ``angle``), parsed to SI floats; or one of
        :data:`RAW_KINDS` (``text``, ``path``, ``angle``), kept as typed.
    help : str
        One line for ``--help``.
    group : str
        Title of its ``--help`` section.
    positive : bool
        Values must be > 0 (otherwise any finite number, e.g. a concave radius < 0).
    bounds : str, optional
        Name of a :mod:`linecontact.checks` Interval the value must lie in.
    sweep : bool
        May be a sweep ``START:STOP:N`` on the command line (every numeric parameter
        may: two sweeps give the grid).
    plausible : tuple of float, optional
        ``(low, high)`` [SI]: the magnitudes this quantity has in practice (of
        |value|). A BARE number outside it (SI by the input rule: ``--modulus 210``
        is 210 Pa) is not refused, but named as the likely cause when its case then
        fails (:func:`linecontact.calc.cases.likely_cause`).
    words : tuple of str
        Words accepted besides a number (e.g. ``("free",)`` for the tilt): such a cell
        is given (``present``) with the value NaN; ``fail.cell(name, i)`` has the word.
    json_only : str
        Non-empty for an input whose result is written to the ``--json`` output only
        (a block with no table): what it writes. Given without ``--json`` (option or
        CSV column) it is refused up front (:func:`linecontact.calc.render.refuse_json_only`),
        not computed and dropped.
    """

    name: str
    kind: str
    help: str
    group: str
    positive: bool = True
    bounds: str | None = None
    sweep: bool = True
    plausible: tuple | None = None
    words: tuple = ()
    json_only: str = ""


@dataclass(frozen=True)
class Field:
    """An output quantity: table heading, SI unit, engineering unit, and the factor
    SI -> engineering (value_eng = factor * value_SI)."""

    heading: str
    si: str
    eng: str
    factor: float


class State:
    """What a feature's ``resolve`` keeps for its ``columns`` and ``blocks``.

    ``rows`` (bool array over the cases) marks where the feature is active; any other
    attribute is the feature's own (keyword arguments). These optional attributes are
    read by the core:

    ``radius_eff``
        Float array, NaN where the feature leaves it: the effective radius of the
        contact the core evaluates in that row (a raceway's inner contact).
    ``modulus``
        Float array, NaN elsewhere: Young's modulus E1 of the second body for E* (a
        viscoelastic body's instantaneous modulus), in place of ``--modulus``.
    ``whole``
        Bool array: rows where the feature describes the whole body (a roller between
        two raceways): the core's single-contact columns are not shown there, the
        feature's columns come first, and the models are compared (``deviation``) on
        the field named by ``compared``.
    ``compared``
        With ``whole``: the name of the feature's field compared between models.
    ``parts``
        Callable i -> dict: the feature's parts of the library contact of row i
        (:class:`linecontact.contact.Contact`): Roller keywords (``profile``,
        ``crown_radius``, ``tilt``) or ``counterbody`` (e.g. a
        :class:`~linecontact.raceway.Raceways`). Rows with parts are evaluated as that
        composed contact (hashable values: rows with equal parts share one).
    ``models``
        Tuple of model keys: the default model set of the feature's rows (instead of
        the standard set of a straight cylinder), e.g. the slice models.
    ``signed``
        Bool array: rows where the feature gives a load or depth <= 0 a meaning (an
        adhesive contact under a tensile load); the core refuses them elsewhere (its
        message names the parameters of the features' module attribute ``signed``,
        a tuple of parameter names). In such a row the core's models (no adhesion:
        no contact) are not evaluated; the core columns show the given value only,
        and the feature's ``columns`` is called with NaN for the rest of ``normal``.
    ``kept``
        Object array: each row's contact law as ``columns`` saw it (:func:`keep`),
        for the feature's ``figure``.
    """

    def __init__(self, rows, **attrs):
        self.rows = np.asarray(rows, dtype=bool)
        self.__dict__.update(attrs)

    def __repr__(self):
        return f"State({', '.join(sorted(self.__dict__))})"


@dataclass
class Block:
    """An extra table: one row per case row (None where not computed).

    Attributes
    ----------
    name : str
        Key of the block in the JSON document (e.g. ``profiled_roller``); blocks of one
        name are listed together.
    label : str
        Heading of the first column in the table.
    fields : Mapping[str, Field]
        The numeric columns, in order.
    rows : list of dict or None
        Per case row: field name -> SI value (None: '-'), plus ``"label"`` (the first
        cell: the method), ``"text"`` (dict of text columns, e.g. edge) and ``"note"``.
    text_columns : tuple of str
        Headings of the text columns after the numbers (before the note).
    json_rows : list of dict
        The rows for ``--json`` (SI), as the feature wants them (may be richer).
    note : str
        One paragraph printed after the table.
    key : str
        Prefix of the block's columns in a CSV batch (``KEY_FIELD_UNIT``).
    units : Mapping[str, str]
        SI unit of each JSON row entry.
    scales : Mapping[str, float]
        Field name -> the magnitude of its quantity [SI] where it may be round-off (a
        moment that symmetry makes zero): a value below
        :data:`linecontact._units.NOISE` of it is printed as 0 (the JSON keeps it).
        Default: the column's largest value.
    """

    name: str
    label: str
    fields: Mapping[str, Field]
    rows: list
    text_columns: tuple = ()
    json_rows: list = field(default_factory=list)
    note: str = ""
    key: str = ""
    units: Mapping[str, str] = field(default_factory=dict)
    scales: Mapping[str, float] = field(default_factory=dict)


class Fail:
    """The refusal callback handed to ``resolve``: ``fail(mask, name, valid, reason)``.

    Sets the first error of each row of ``mask`` (one line: the parameter as written,
    its value as typed, the valid range, the reason). ``value`` (callable row -> text)
    overrides the value shown (default: the cell of ``name``, or nothing if missing).
    """

    def __init__(self, errors, cells, label, batch):
        self.errors = errors
        self.cells = cells
        self.label = label
        self.batch = batch

    def message(self, mask, text):
        """Refuse the rows of `mask` with `text` as it is (a library's one-line
        refusal, e.g. a CombinationError naming its parameters and values)."""
        for i in np.flatnonzero(mask):
            if not self.errors[i]:
                self.errors[i] = str(text)

    def cell(self, name, i):
        """The text of parameter `name` in row i, as typed ("" if not given)."""
        col = self.cells.get(name)
        if col is None:
            return ""
        if isinstance(col, np.ndarray):
            v = col[i]
            return "" if v != v else repr(float(v))
        return col[i]

    def __call__(self, mask, name, valid, reason, value=None):
        from .._units import InputError

        for i in np.flatnonzero(mask):
            if not self.errors[i]:
                typed = value(i) if value is not None else self.cell(name, i)
                self.errors[i] = str(InputError(self.label(name), typed, valid, reason))


def keep(state, rows, model):
    """Remember the contact law `model` of `rows` (the first one given per row: the
    first model set's) in ``state.kept`` (object array over the cases) for the
    feature's ``figure``: a reference per row, no copy."""
    kept = state.__dict__.get("kept")
    if kept is None:
        kept = state.kept = np.full(len(state.rows), None, dtype=object)
    rows = np.asarray(rows, dtype=np.intp)
    free = rows[np.equal(kept[rows], None)]
    kept[free] = model


def option_name(name):
    """``inner_raceway`` -> ``--inner-raceway``."""
    return "--" + name.replace("_", "-")


def bounds_of(p):
    """(inside, description) of a Parameter's validity Interval, or None."""
    if p.bounds is None:
        return None
    from importlib import import_module

    # 'POISSON_RATIO' (linecontact.checks) or 'bearing.ROLLER_COUNT' (its module's)
    where, _, name = p.bounds.rpartition(".")
    iv = getattr(import_module(f"linecontact.{where or 'checks'}"), name)
    return (iv.contains, iv.describe())


class Feature(Protocol):
    """What a feature module provides (see the module docstring)."""

    name: str
    group: str
    parameters: Sequence[Parameter]
    fields: Mapping[str, Field]
    notes: Mapping[str, str]

    def resolve(self, values: Mapping[str, Any], present: Mapping[str, np.ndarray],
                fail: Fail) -> State | None: ...

    def columns(self, model: Any, rows: np.ndarray, normal: Mapping[str, np.ndarray],
                state: State) -> dict: ...

    def blocks(self, state: State, results: Any) -> list: ...

    # optional: def figure(self, state: State, results: Any) -> list: ...


class Subcommand(Protocol):
    """What a subcommand module provides (see the module docstring)."""

    name: str
    help: str
    description: str
    epilog: str
    parameters: Sequence[Parameter]
    fields: Mapping[str, Field]
    notes: Mapping[str, str]

    def resolve(self, values: Mapping[str, Any], present: Mapping[str, np.ndarray],
                fail: Fail) -> State: ...

    def solve(self, values: Mapping[str, Any], i: int, state: State) -> Any: ...

    def row(self, obj: Any, state: State, i: int) -> dict: ...

    def model_of(self, obj: Any) -> tuple: ...

    def describe(self, obj: Any, si: bool) -> str: ...

    def blocks(self, obj: Any) -> list: ...

    def to_json(self, obj: Any) -> dict: ...

    def figure(self, objects: Sequence[Any]) -> Any: ...


def each(func, idx, notes, width=1, missing=""):
    """func(sub-index array) -> values (`width` per element, flattened), element by
    element where a call is refused (its reason in ``notes[k]``); returns shape (n,) or
    (n, width), NaN where refused. A missing file (a table not installed) is said in
    every note: `missing`, or the file name."""
    from ..errors import OutOfRangeError

    shape = (idx.size,) if width == 1 else (idx.size, width)
    try:
        return np.asarray(func(idx), dtype=float).reshape(shape)
    except FileNotFoundError as exc:
        for k in range(idx.size):
            notes[k] = missing or f"not installed: {exc.filename or exc}"
        return np.full(shape, np.nan)
    except OutOfRangeError:
        pass
    res = np.full(shape, np.nan)
    for k in range(idx.size):
        try:
            v = np.asarray(func(idx[k:k + 1]), dtype=float).ravel()
            res[k] = v[0] if width == 1 else v[:width]
        except OutOfRangeError as exc:
            notes[k] = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    return res


def short(text):
    """First clause of a library message (the parameter, value and range), without
    the element index of the one-element array it was evaluated on."""
    return re.sub(r" \(element \[\d+\] of shape \(\d+,\)\)", "", text.split("; ")[0])


def flag_text(depth, half_width, radius, length, where=""):
    """The geometry flags of one contact (``""`` for none): d > 0.15 R (beyond the
    parabolic-gap range of the models), b > L/2 (not a line contact); `where` names the
    contact (" (inner)")."""
    parts = []
    with np.errstate(invalid="ignore"):
        if depth / radius > DEPTH_OVER_RADIUS_MAX:
            parts.append(f"d > {DEPTH_OVER_RADIUS_MAX:g} R{where}: beyond the "
                         "parabolic-gap range of the models")
        if half_width / length > HALF_WIDTH_OVER_LENGTH_MAX:
            parts.append(f"b > {HALF_WIDTH_OVER_LENGTH_MAX:g} L{where}: not a line contact")
    return "; ".join(parts)
