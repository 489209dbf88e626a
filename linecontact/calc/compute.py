"""The calculator's results: every model evaluated on whole arrays of cases, the
per-row quantities derived from them (Hertz half-width and peak pressure, geometry
flags, deviation from the best estimate), and the columns of the active features.

A default batch (the default model alone, no feature, plain contacts) is evaluated
in one call over all rows, as arrays over their geometry
(:meth:`linecontact.models.ContactModel.evaluate_many`: the same values as one model
per contact); the rows it does not cover (outside the model's range) and every other
case follow the per-contact path below.

Cases (:func:`linecontact.calc.cases.parse_cases`) are grouped by distinct contact
(effective radius, length, E*): one model object per group and model, each evaluated
once per group on the array of its loads or depths with
:meth:`linecontact.models.ContactModel.evaluate`. A model that refuses some elements
(:class:`~linecontact.errors.OutOfRangeError`) is re-evaluated on halves of the
array until the refused elements are isolated: each of them gets the model's message as
its ``note``, the others their values. Any other exception is reported the same way,
in the row's ``error`` (never lost, never stopping the other rows). Then each active
feature (:mod:`linecontact.calc.feature`) is asked for its columns over the group's
rows, and for its extra tables (blocks) once at the end.

Output columns: the core's :data:`FIELDS` (name -> :class:`Field`: heading, SI and
engineering unit) and each feature's ``fields``; :func:`all_fields` has them all.
"""

from __future__ import annotations

import operator
import re

import numpy as np

from .feature import DEPTH_OVER_RADIUS_MAX, HALF_WIDTH_OVER_LENGTH_MAX, Field, flag_text
from .features import FEATURES

__all__ = ["FIELDS", "CONTACT_COLUMNS", "P0_NOTE", "all_fields", "parse_model_option",
           "model_id", "compute", "Results"]


#: Every numeric output quantity.
FIELDS = {
    "force": Field("F", "N", "kN", 1e-3),
    "depth": Field("d", "m", "um", 1e6),
    "stiffness": Field("k", "N/m", "N/um", 1e-6),
    "half_width": Field("b (Hertz)", "m", "um", 1e6),
    "peak_pressure": Field("p0 (Hertz)", "Pa", "MPa", 1e-6),
    "contact_radius": Field("a (MDR)", "m", "um", 1e6),
    "deviation": Field("vs best", "-", "%", 100.0),
    "estar": Field("E*", "Pa", "GPa", 1e-9),
    "radius": Field("R", "m", "mm", 1e3),
    "radius_eff": Field("R eff", "m", "mm", 1e3),
    "length": Field("L", "m", "mm", 1e3),
}

#: Columns of one contact, in order (the given quantity, F or d, comes first).
CONTACT_COLUMNS = ("force", "depth", "stiffness", "half_width", "peak_pressure",
                   "contact_radius", "deviation")


def all_fields():
    """Every output column: the core's and every feature's (name -> Field)."""
    out = dict(FIELDS)
    for f in FEATURES:
        out.update(f.fields)
    return out

P0_NOTE = ("p0: Hertz peak pressure of the plane-strain strip, p0 = sqrt(F E*/(pi R L)) "
           "(Johnson 1985, Eq. 4.45), i.e. at mid-length; at the ends of a straight roller "
           "the pressure is higher, singular on an elastic half-space (edge loading).")


# ---------------------------------------------------------------------------------------
# model selection


class Refused:
    """Stands in for a model that refused the cylinder when it was built."""

    def __init__(self, text, exc, key=None):
        self.key = key or text  # the registry key (the JSON entry's "key"); the text
        self.label = text       # as typed is its label
        self.provenance = None
        self.exc = exc


def parse_model_option(spec):
    """Parse ``--model``: None or 'all' (standard set) or ``KEY[:OPT=VALUE...]``, comma-separated.

    Returns None for the standard set, else a list of (text, key, options). An option
    whose default in the model's constructor is a bool takes only true/false, yes/no,
    1/0; one whose default is a number takes a number; other options take the text.

    Examples
    --------
    >>> parse_model_option("johnson:c=0.72")
    [('johnson:c=0.72', 'johnson', {'c': 0.72})]
    >>> parse_model_option("li-popov:extrapolate=no")[0][2]
    {'extrapolate': False}
    """
    if spec is None or spec.strip() == "all":
        return None
    from .. import models
    from .._units import InputError

    valid = "all, or comma-separated KEY[:OPTION=VALUE...] with KEY one of: " + ", ".join(
        models.available_models()
    )
    parsed = []
    for text in (t.strip() for t in spec.split(",")):
        if not text:
            raise InputError("--model", spec, valid, "empty model name")
        key, *opts = text.split(":")
        if key not in models.MODELS and key in models.DEFINED_IN:
            # registered on import of its module (kept off the one-case path until asked)
            from importlib import import_module

            import_module(models.DEFINED_IN[key])
        if key not in models.MODELS:
            from .._units import QUANTITY

            import difflib

            close = difflib.get_close_matches(key, models.available_models(), n=1)
            raise InputError("--model", spec if QUANTITY.match(text) else text, valid,
                             "a decimal comma in an option? (write c=1.5, not c=1,5)"
                             if QUANTITY.match(text) else "unknown model" + (
                                 f"; did you mean {close[0]!r}?" if close else ""))
        defaults = _option_defaults(models.MODELS[key])
        options = {}
        for opt in opts:
            name, eq, value = opt.partition("=")
            name = name.strip()
            if not eq or not name:
                raise InputError("--model", text, valid, f"option {opt!r} is not OPTION=VALUE")
            if name not in defaults:
                import difflib

                close = [n for n in defaults if n.lower() == name.lower()] or \
                    difflib.get_close_matches(name, list(defaults), n=1)
                raise InputError(
                    "--model", text,
                    f"options of {key}: {', '.join(defaults) or 'none'}",
                    f"unknown option {name!r}"
                    + (f"; did you mean {close[0]!r}?" if close else ""))
            if name in options:  # the last would silently win
                raise InputError("--model", text, f"each option of {key} once",
                                 f"option {name!r} is given twice")
            options[name] = _option_value(f"--model {key}:{name}", value.strip(),
                                          defaults[name],
                                          _option_kind(models.MODELS[key], name))
        # the same model twice ('johnson,johnson:c=1': c = 1 is the default) gives two
        # sets under one id: a batch's columns twice under one name, one lost on reading
        same = repr((key, sorted({**defaults, **options}.items())))
        earlier = next((t for t, k, o in parsed
                        if repr((k, sorted({**_option_defaults(models.MODELS[k]),
                                            **o}.items()))) == same), None)
        if earlier is not None:
            raise InputError("--model", spec, "each model once",
                             f"{text!r} is the same model as {earlier!r}")
        parsed.append((text, key, options))
    return parsed


def _option_defaults(cls):
    import inspect

    sig = inspect.signature(cls.__init__)
    return {
        n: p.default
        for n, p in list(sig.parameters.items())[4:]  # self, radius, length, estar
        if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
    }


def _option_kind(cls, option):
    """The quantity kind of a model option, from the unit its docstring gives it.

    The docstring contract (Parameters with the unit in brackets, e.g. ``tilt : float``
    ... ``[rad]``) is the one declaration of an option's unit: its SI unit selects the
    kind of :data:`linecontact._units.DIMENSIONS` (``[rad]`` -> angle, ``[m]`` ->
    length, ...), so that ``tilt=1mrad`` is read as 1e-3 rad. An option without a
    bracketed SI unit is a pure number.
    """
    import re

    from .._units import DIMENSIONS

    m = re.search(rf"^\s*{re.escape(option)} : [^\n]*\n((?:[ \t]+[^\n]*\n?)*?)"
                  r"(?=^\s*\w+ : |^\s*$|\Z)", cls.__doc__ or "", re.MULTILINE)
    units = re.findall(r"\[([^\]]+)\]", m.group(1)) if m else []
    for kind, (_, si, _) in DIMENSIONS.items():
        if si and si in units:
            return kind
    return "dimensionless"


def _option_value(name, text, default, kind="dimensionless"):
    """A model option's value, by the type of its default (bool, number, text); a
    number may carry a unit of its `kind` (see :func:`_option_kind`)."""
    from .._units import QUANTITY, InputError, parse_bool, parse_quantity

    if isinstance(default, bool):
        return parse_bool(name, text)
    if isinstance(default, (int, float)):
        if isinstance(default, int) and kind == "dimensionless":
            kind = "count"  # an integer option (n_slices): a fraction is refused here
        try:
            value = parse_quantity(name, text, kind, positive=False)
        except InputError:
            if QUANTITY.match(text) or text[:1] in "+-.0123456789":
                raise  # a number with a wrong unit (tilt=1mm), not a name
            return text  # a named constant (e.g. johnson c=johnson1985); the model checks
        # an integer option (n_slices=40) stays an int
        return int(value) if isinstance(default, int) and value.is_integer() else value
    return text


def model_id(model):
    """A short column-safe name: the label as a slug ('Johnson (c = 0.72)' ->
    'johnson-c-0.72')."""
    import re

    return re.sub(r"[^a-z0-9.]+", "-", model.label.lower()).strip("-")


def _build(specs, R, L, E, first_only, default_key=None):
    """The models for one cylinder (Refused stand-ins for those refused at build).

    `default_key`: the registry key of the standard set's first model when it is
    known (from a first call) to be the default model: with `first_only` only that
    model is built, not the whole standard set (a batch of distinct cylinders).
    """
    from .. import models
    from .._units import InputError
    from ..errors import OutOfRangeError, UnknownNameError

    if specs is None:
        if first_only and default_key is not None:
            return [models.get_model(default_key, R, L, E)]
        standard = list(models.standard_models(R, L, E))
        return standard[:1] if first_only else standard
    chosen = []
    for text, key, options in specs:
        try:
            chosen.append(models.get_model(key, R, L, E, **options))
        except OutOfRangeError as exc:  # refused for this cylinder: a row with a note
            chosen.append(Refused(text, exc, key))
        except (TypeError, UnknownNameError) as exc:  # an option the model does not take
            raise InputError(
                "--model", text, "options the model takes (see its docstring)", str(exc)
            ) from None
    return chosen


def _spec_of(model):
    """(text, key, options) of a built model (the standard set's: the options it was
    built with, read back from its attributes)."""
    options = {}
    for name in _option_defaults(type(model)):
        if hasattr(model, name):
            options[name] = getattr(model, name)
    return (model.label, model.key, options)


# ---------------------------------------------------------------------------------------
# evaluation


class _Model:
    """A model as the features see it: every attribute of the contact's law (a
    :class:`~linecontact.models.ContactModel`), plus ``contact``: the library's
    :class:`~linecontact.contact.Contact` when the row's contact is composed (a profile,
    a tilt, raceways; None for a plain straight contact)."""

    def __init__(self, law, contact=None):
        self._law = law
        self.contact = contact

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        law = self._law
        if law is None:
            law = self.contact.law()  # raises CombinationError for a whole roller
            self._law = law
        return getattr(law, name)


def _user_note(exc, given, cases, i):
    """The note of a row a model refuses, in the user's words: the option or column
    they wrote (``--load = '1kN'``, not "force = 1000 N (element [0] of shape (1,))"),
    the cylinder it was refused for (the geometry and E* decide a model's range),
    the model's own reason, and the likely cause among the inputs
    (:func:`linecontact.calc.cases.likely_cause`)."""
    from .cases import likely_cause
    from .feature import option_name

    label = getattr(cases, "label", option_name)
    parameter = getattr(exc, "parameter", None)
    if parameter in ("force", "depth") and getattr(exc, "valid", None):
        name = "load" if given == "load" else "depth"
        col = cases.cells.get(name)
        typed = (str(col[i]).strip() if col is not None and not isinstance(col, np.ndarray)
                 else f"{cases.value[i]:.6g} {'N' if name == 'load' else 'm'}")
        text = (f"{label(name)} = {typed!r} is outside this model's range {exc.valid} "
                f"for R = {cases.radius_eff[i]:.6g} m, L = {cases.length[i]:.6g} m, "
                f"E* = {cases.estar[i]:.6g} Pa")
        if getattr(exc, "hint", ""):
            text += f"; {exc.hint}"
    elif parameter == "estar" and not cases.present["estar"][i]:
        text = str(exc).replace(
            "estar = ", f"E* = (from {label('modulus')} and {label('poisson')}) ", 1)
    else:
        text = str(exc)
    # the inputs a refusal can come from: a ratio of lengths, a modulus, or (a force or
    # depth range) all of them
    kinds = {"L/R": {"length"}, "length_over_radius": {"length"},
             "estar": {"pressure"}}.get(parameter)
    return text + likely_cause(cases, i, kinds)


def _safe_evaluate(evaluate, label, given, values, notes, errors, idx, describe=None):
    """evaluate(given, values) -> dict of arrays; refused elements isolated by halving.

    Returns a dict of arrays (NaN where refused; ``solution`` an object array); writes
    ``notes[idx[i]]`` (out of the model's range, a combination the library refuses, a
    solver that did not converge) or ``errors[idx[i]]`` (any other exception);
    ``describe(exc, row)`` words a refusal for the user (default ``str(exc)``).
    """
    describe = describe or (lambda exc, row: str(exc))
    import sys

    from ..errors import CombinationError, OutOfRangeError

    def converged(exc):
        roller = sys.modules.get("linecontact.roller")  # imported only by a slice model
        return roller is None or not isinstance(exc, roller.ConvergenceError)

    n = len(values)
    out = {k: np.full(n, np.nan) for k in _NORMAL}
    out["solution"] = np.full(n, None, dtype=object)
    out["force" if given == "load" else "depth"][:] = values  # given, even where refused
    stack = [(0, n)]
    while stack:
        lo, hi = stack.pop()
        try:
            r = evaluate(given, values[lo:hi])
        except Exception as exc:  # noqa: BLE001 - reported in the row, never lost
            said = isinstance(exc, (OutOfRangeError, CombinationError)) or not converged(exc)
            if not said:
                if hi - lo == 1:
                    detail = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                    errors[idx[lo]] = (f"{label}: unexpected {type(exc).__name__}"
                                       + (f": {detail}" if detail else ""))
                else:
                    mid = (lo + hi) // 2
                    stack += [(mid, hi), (lo, mid)]
                continue
            if hi - lo == 1:
                text = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                notes[idx[lo]] = (describe(exc, idx[lo]) if converged(exc)
                                  else f"{label}: not computed: {text}")
            else:
                mid = (lo + hi) // 2
                stack += [(mid, hi), (lo, mid)]
            continue
        for k in out:
            v = r.get(k)
            if v is not None:
                out[k][lo:hi] = v
    return out


#: The normal-contact quantities the core keeps per row (NaN where not defined).
_NORMAL = ("force", "depth", "stiffness", "contact_radius", "half_width", "peak_pressure",
           "moment", "tilt", "tilt_stiffness")


def _law_evaluator(model):
    """evaluate(given, values) of a plain straight contact: the law on the whole array
    (Hertz's half-width and p0 of the strip follow in _hertz, as in
    linecontact.contact.Contact.normal)."""

    def evaluate(given, values):
        return model.evaluate(**{("force" if given == "load" else "depth"): values})

    return evaluate


def _hertz(r, R, L, E):
    """Hertz's half-width b and strip peak pressure p0 of a plain contact from its force,
    only in the rows the model computed (a finite depth): a row no model covers shows
    no number at all (issue 22: a radius of 1e30 m printed b = 1e18 um and p0 =
    6e-14 MPa beside a refused depth)."""
    from ..classical import hertz_half_width, hertz_peak_pressure

    F = r["force"]
    ok = np.isfinite(F) & (F > 0) & np.isfinite(r["depth"])
    if ok.any():
        r["half_width"][ok] = hertz_half_width(F[ok], R, L, E)
        r["peak_pressure"][ok] = hertz_peak_pressure(F[ok], R, L, E)


def _contact_evaluator(contact):
    """evaluate(given, values) of a composed contact: Contact.normal (one solve per
    value for a slice model; the two contacts in series between raceways)."""

    def evaluate(given, values):
        if contact.raceways and not contact.sliced and np.ndim(values) > 0:
            # one solution per value (a law between raceways solves arrays at once, but
            # the features read each row's two contacts from its own solution)
            parts = [evaluate(given, float(x)) for x in values]
            return {k: np.concatenate([np.atleast_1d(np.asarray(p[k], dtype=object
                                                                 if k == "solution"
                                                                 else float))
                                       for p in parts]) for k in parts[0]}
        res = contact.normal(**{("force" if given == "load" else "depth"): values})
        out = {k: getattr(res, k, None) for k in _NORMAL if k != "contact_radius"}
        if contact.sliced:  # no Hertz strip: the slice model's own peak (p_max) says it
            out["half_width"] = out["peak_pressure"] = None
        if not contact.sliced and not contact.raceways:
            law = contact.law()
            out["contact_radius"] = law.contact_radius(res.depth)
        sols = list(res.solutions)
        if np.ndim(values) == 0:
            out["solution"] = np.array(sols[:1] + [None], dtype=object)[:1]
        elif len(sols) == len(values):
            out["solution"] = np.array(sols + [None], dtype=object)[:-1]
        elif len(sols) == 1:  # a law between raceways: one solution over the array
            out["solution"] = np.array([sols[0]] * len(values) + [None], dtype=object)[:-1]
        return {k: v for k, v in out.items() if v is not None}

    return evaluate


def _contact_label(contact, spec_text):
    """A column-set label for a composed contact: the law's, or the slice method's with
    the profile and the tilt."""
    if contact.sliced:
        name = {"profiled-roller": "Profiled roller",
                "iso16281-slicing": "ISO 16281 slicing"}.get(contact.model, spec_text)
        tilt = contact.tilt
        text = (", free tilt" if tilt == "free" else
                f", tilt {tilt * 1e3:.4g} mrad" if tilt else "")
        return f"{name} ({contact.profile.label}{text})"
    if contact.raceways:
        from ..models import get_model

        return get_model(contact.model, 1.0, 1.0, 1.0, **contact.options).label
    return contact.law().label


class _Entry:
    """The JSON header entry of a composed contact's model: key, label, provenance."""

    def __init__(self, contact, label):
        self.key = contact.model
        self.label = label
        try:
            #: the contact's force-depth law (a ContactModel), None where it has none
            self.law = contact.law()
            prov = self.law.provenance
        except Exception:  # noqa: BLE001 - a whole roller or a free tilt: no single law
            self.law = None
            prov = {"model": contact.model, "composed": "linecontact.contact.Contact"}
        self.provenance = prov


class Results:
    """Per model set j: arrays over all rows of every field, plus notes and flags.

    Attributes
    ----------
    sets : list of dict
        One per model column set: ``fields`` (name -> float array [SI]), ``note`` and
        ``flags`` (object arrays of str), ``label`` (object array of str: the model per
        row), ``id`` (the column suffix) and ``model`` (the model built for the first
        contact, for the JSON header).
    models : dict
        Model id -> a model object (for provenance).
    errors : list of str
        The row errors (input errors and unexpected exceptions).
    cases : Cases
        The cases evaluated.
    label : callable
        Name of a parameter in messages (``--tilt`` or the column ``tilt``).
    whole : bool
        Some rows are a whole body described by a feature (a roller between raceways).
    contact : bool
        Some rows are single contacts.
    whole_columns : list of str
        The columns of the whole-body rows (shown first).
    extra : list of str
        The features' columns, in order.
    features : list
        The active features (their notes are printed).
    blocks : list of Block
        The features' extra tables.
    deviation : bool
        The deviation column is meaningful (a reference other than the model itself).
    """

    def __init__(self, n, n_sets, errors, cases, label):
        self.sets = [
            {"fields": {}, "note": np.full(n, "", dtype=object),
             "flags": np.full(n, "", dtype=object), "label": np.full(n, "", dtype=object),
             "id": "", "solution": np.full(n, None, dtype=object)}
            for _ in range(n_sets)
        ]
        for s in self.sets:
            for f in CONTACT_COLUMNS:
                s["fields"][f] = np.full(n, np.nan)
        self.models = {}
        self.origins = {}       # model id -> (first row of the group that
        self.errors = errors    # registered it, its set): merge_results
        self.cases = cases
        self.label = label
        self.whole = False
        self.contact = False
        self.whole_columns = []
        self.extra = []
        self.features = []
        self.blocks = []
        self.deviation = False


def _core_parts(cases, i):
    """The library parts of row i from the core inputs: Roller keywords, counter-body,
    materials (:mod:`linecontact.contact`)."""
    import math

    from ..contact import Concave, Convex, Elastic, Flat

    v, P = cases.values, cases.present
    parts = {"radius": float(cases.radius[i]), "length": float(cases.length[i])}
    if P["radius2"][i]:
        r2 = float(v["radius2"][i])
        parts["counterbody"] = Convex(r2) if r2 > 0 else Concave(-r2)
    else:
        parts["counterbody"] = Flat()
    if P["estar"][i]:
        parts["estar"] = float(v["estar"][i])
    else:
        parts["material1"] = (Elastic(float(v["modulus2"][i]), float(v["poisson2"][i]))
                              if P["modulus2"][i] else Elastic(math.inf))
        if P["modulus"][i]:
            parts["material2"] = Elastic(float(v["modulus"][i]), float(v["poisson"][i]))
    return parts


def _build_contact(parts, key, options):
    """A library Contact from the row's parts (core and features) and a model."""
    from ..contact import Contact, Roller

    p = dict(parts)
    roller = Roller(p.pop("radius"), p.pop("length"), profile=p.pop("profile", None),
                    crown_radius=p.pop("crown_radius", None), tilt=p.pop("tilt", 0.0))
    counterbody = p.pop("counterbody")
    if "estar" in p:
        return Contact(roller, counterbody, estar=p["estar"], model=key, **options)
    return Contact(roller, counterbody, p.get("material1"), p.get("material2"), model=key,
                   **options)


def _group_key(cases, errors, composed):
    """(key, parts_of, ok): per row the values that make one contact (rows of equal
    key are evaluated together, groups in the order of their keys), the parts a
    feature composes per row, and the rows without an error. `composed`: the active
    features that compose a contact (profile, tilt, raceways)."""
    n = len(errors)
    # rows whose contact a feature composes: one integer code per distinct set of
    # parts, in the order of their first row, so that they group with their own kind
    codes = np.zeros(n)
    parts_of = {}
    ok = np.fromiter(map(operator.not_, errors), dtype=bool, count=n)
    if composed:
        seen = {}
        for i in np.flatnonzero(ok):
            extra = {}
            for f, st in composed:
                if st.rows[i]:
                    extra.update(st.parts(i))
            if extra:
                key = tuple(sorted(extra.items()))
                codes[i] = seen.setdefault(key, len(seen) + 1)
                parts_of[i] = extra
    v, P = cases.values, cases.present

    def col(a):
        a = np.asarray(a, dtype=float)
        return np.where(np.isnan(a), -1.0, a)

    key = np.stack([col(cases.radius_eff), col(cases.length), col(cases.estar), codes,
                    col(cases.radius), col(np.where(P["radius2"], v["radius2"], np.nan)),
                    col(np.where(P["modulus"], v["modulus"], np.nan)),
                    col(np.where(P["poisson"], v["poisson"], np.nan)),
                    col(np.where(P["modulus2"], v["modulus2"], np.nan)),
                    col(np.where(P["poisson2"], v["poisson2"], np.nan))], axis=1)
    return key, parts_of, ok


def compute(cases, errors, specs, *, first_only=False, progress=None, label=None):
    """Evaluate the selected models and the active features for every good row.

    Parameters
    ----------
    cases : Cases
        From :func:`linecontact.calc.cases.parse_cases`.
    errors : list of str
        Row errors so far (rows with one are skipped); unexpected exceptions are added.
    specs : list or None
        From :func:`parse_model_option` (None: the standard set, or the default set of
        a feature that describes the contact, e.g. the profiled roller's).
    first_only : bool
        Only the first model of the set (the default best estimate).
    progress : callable, optional
        Called with the number of rows finished after each group.
    label : callable, optional
        Name of a parameter in messages (default: the option ``--name``).

    Returns
    -------
    Results
    """
    from .feature import option_name

    n = len(errors)
    active = cases.active()
    composed = [(f, st) for f, st in active if getattr(st, "parts", None) is not None]
    key, parts_of, ok = _group_key(cases, errors, composed)
    rows = np.flatnonzero(ok)
    from ..models import DEFAULT_MODEL

    probe = _build(specs, 1.0, 1.0, 1.0, first_only)  # the column sets, in order
    default_specs = None if specs is not None else [_spec_of(m) for m in probe]
    feature_sets = {}
    for f, st in composed:
        keys = getattr(st, "models", None)
        if keys:
            feature_sets[f.name] = [(k, k, {}) for k in (keys[:1] if first_only else keys)]
    n_sets = len(probe)
    if specs is None and feature_sets:
        # every good row composed by a feature with its own default set: that set
        covered = np.zeros(n, bool)
        for f, st in composed:
            if f.name in feature_sets:
                covered |= st.rows
        if np.all(covered[ok]):
            n_sets = max(len(s) for s in feature_sets.values())
    # the default model alone when it heads the standard set (it does when installed)
    default_key = (DEFAULT_MODEL if specs is None and first_only
                   and probe[0].key == DEFAULT_MODEL else None)
    results = Results(n, n_sets, errors, cases, label or option_name)
    for s, m in zip(results.sets, probe):
        s["id"] = model_id(m)
    reference = specs is not None and not first_only
    ref_key = None
    if reference:  # the best estimate alone per contact, as for a default batch
        from ..models import standard_models

        first = standard_models(1.0, 1.0, 1.0)[0]
        ref_key = DEFAULT_MODEL if first.key == DEFAULT_MODEL else None
    results.deviation = n_sets > 1 or reference
    whole = cases.whole()
    produced = {}
    # the default model alone on plain contacts (no feature): all rows as arrays over
    # their geometry at once (ContactModel.evaluate_many), the groups only registered
    fast = None
    if default_key is not None and not active and not parts_of and not reference:
        try:
            fast = _evaluate_many(results, cases, rows, default_key)
        except Exception:  # noqa: BLE001 - the per-contact path isolates it to its rows
            fast = None
    if fast is not None and fast.any():
        i0 = np.flatnonzero(fast)[0]
        covered = np.flatnonzero(fast)       # the first of them in the groups' order
        at = int(covered[np.lexsort(key[covered].T[::-1])[0]])
        _register(results, _build(specs, cases.radius_eff[i0], cases.length[i0],
                                  cases.estar[i0], first_only, default_key)[0], at)
        rows = rows[~fast[rows]]          # the rest: per contact, below
        if progress is not None:
            progress(int(fast.sum()))
    if rows.size:
        k = key[rows]
        order = np.lexsort(k.T[::-1])  # rows of one contact become neighbours
        ks = k[order]
        bounds = np.flatnonzero(np.any(ks[1:] != ks[:-1], axis=1)) + 1
        groups = np.split(rows[order], bounds)
    else:
        groups = []
    # an intermediate that overflows (a force of 1e300 N) is caught by _no_overflow
    # below, in the row's flags; numpy's warnings would only add lines to stderr
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        done = 0 if fast is None else int(fast.sum())
        for g in groups:
            i0 = g[0]
            try:
                if i0 in parts_of:
                    sets, refs = _composed_sets(cases, i0, parts_of[i0], specs,
                                                default_specs, feature_sets, composed,
                                                reference, errors, g)
                    if sets is None:
                        continue
                else:
                    R, L, E = cases.radius_eff[i0], cases.length[i0], cases.estar[i0]
                    sets = [(m, None) for m in _build(specs, R, L, E, first_only,
                                                      default_key)]
                    refs = ([(m, None) for m in _build(None, R, L, E, True, ref_key)]
                            if reference else None)
            except Exception as exc:  # noqa: BLE001 - reported in the rows, never lost
                for i in g:
                    errors[i] = f"unexpected {type(exc).__name__}: {exc}"
                continue
            _evaluate_group(results, g, cases, active, whole, sets, refs, produced)
            done += len(g)
            if progress is not None:
                progress(done)
    names = set().union(*(s["fields"] for s in results.sets))
    for s in results.sets:  # a set some groups do not have: its values are none there
        for name in names - set(s["fields"]):
            s["fields"][name] = np.full(n, np.nan)
    _no_overflow(results)
    ok = np.fromiter(map(operator.not_, errors), dtype=bool, count=n)
    results.whole = bool(np.any(whole & ok))
    results.contact = bool(np.any(~whole & ok))
    # a feature none of whose rows is on (`--stresses no`) prints no note
    results.features = [f for f, st in active if np.any(st.rows)]
    _sort_columns(results, active, produced)
    for f, st in active:
        results.blocks += f.blocks(st, results)
    return results


def _register(results, model, at):
    """Name the single column set after its first model (as _evaluate_group does);
    `at`: the row of the evaluated ones whose group would come first."""
    s = results.sets[0]
    s["id"] = model_id(model)
    s["named"] = True
    s["named_at"] = at
    results.models.setdefault(s["id"], model)
    results.origins.setdefault(s["id"], (at, 0))
    if s.get("model") is None:
        s["model"] = model


def _evaluate_many(results, cases, rows, key):
    """The single default model on the plain rows `rows`, as arrays over their geometry
    (one call, no model object per cylinder): writes the rows it covers into the
    first column set exactly as _evaluate_group would (the same values: the model's own
    operations element by element) and returns a bool array over all rows marking them,
    or None when the model has no such evaluation. Rows outside the model's range are
    left to the per-contact path (their notes name the contact)."""
    from ..models import MODELS

    label = getattr(MODELS[key], "label", None)
    if not isinstance(label, str):   # a label that depends on the options
        return None
    n = len(results.errors)
    done = np.zeros(n, bool)
    if not rows.size:
        return done
    R, L, E = cases.radius_eff[rows], cases.length[rows], cases.estar[rows]
    given, values = cases.given[rows], cases.value[rows]
    r = {k: np.full(rows.size, np.nan) for k in _NORMAL}
    covered = np.zeros(rows.size, bool)
    for which in ("load", "depth"):
        sel = np.flatnonzero(given == which)
        if not sel.size:
            continue
        got = MODELS[key].evaluate_many(R[sel], L[sel], E[sel],
                                        **{("force" if which == "load" else "depth"):
                                           values[sel]})
        if got is None:
            return None
        res, ok = got
        for k, v in res.items():
            r[k][sel] = v
        covered[sel] = ok
    if not covered.any():
        return done
    keep = np.flatnonzero(covered)
    rows = rows[keep]
    r = {k: v[keep] for k, v in r.items()}
    _hertz(r, R[keep], L[keep], E[keep])
    s = results.sets[0]
    s["label"][rows] = label
    f = s["fields"]
    for name, arr in r.items():
        if name not in f:
            f[name] = np.full(n, np.nan)
        f[name][rows] = arr
    Rk, Lk = R[keep], L[keep]
    with np.errstate(invalid="ignore"):
        odd = ((r["depth"] / Rk > DEPTH_OVER_RADIUS_MAX)
               | (r["half_width"] / Lk > HALF_WIDTH_OVER_LENGTH_MAX))
    for j in np.flatnonzero(odd):
        s["flags"][rows[j]] = flag_text(r["depth"][j], r["half_width"][j], Rk[j], Lk[j])
    done[rows] = True
    return done


def _composed_sets(cases, i0, extra, specs, default_specs, feature_sets, composed,
                   reference, errors, g):
    """(sets, refs) of a composed contact: one library Contact per model of the set
    (a Refused stand-in where the library refuses the model for this contact), or
    (None, None) with the rows' errors set when the library refuses the combination
    whatever the model (raceways that do not fit, ...)."""
    from ..errors import CombinationError, OutOfRangeError

    parts = dict(_core_parts(cases, i0), **extra)
    try:
        default = _build_contact(parts, None, {})  # the combination, its default model
    except (CombinationError, OutOfRangeError) as exc:
        for i in g:
            errors[i] = str(exc)
        return None, None
    chosen = specs
    if chosen is None:
        # the library's default decides: a slice model (profile, tilt) -> the feature's
        # set; a straight law (e.g. a straight roller whose free tilt is 0 by symmetry)
        # -> the standard set
        chosen = default_specs
        for f, st in composed:
            if f.name in feature_sets and st.rows[i0] and default.sliced:
                chosen = feature_sets[f.name]
    sets = []
    for text, key, options in chosen:
        try:
            c = _build_contact(parts, key, options)
        except (CombinationError, OutOfRangeError) as exc:
            sets.append((Refused(text, exc, key), None))
            continue
        sets.append((c, text))
    refs = None
    if reference:
        try:
            refs = [(_build_contact(parts, None, {}), "default")]
        except (CombinationError, OutOfRangeError) as exc:
            refs = [(Refused("default", exc), None)]
    return sets, refs


def _sort_columns(results, active, produced):
    """Append each active feature's produced columns, in its field order, to
    `results.whole_columns` (a whole-bearing state) or `results.extra` (per contact)."""
    for f, st in active:
        names = [c for c in f.fields if c in produced]
        if getattr(st, "whole", None) is not None:
            results.whole_columns += names
        else:
            results.extra += names


def _no_overflow(results):
    """No 'inf' in any output: a result beyond the double range, or one whose value in
    the engineering unit of the table is (e.g. 1e305 m in um), is not shown ('-') and
    its row's flags say so, for that model (a flag: the other values stand)."""
    fields = all_fields()
    for s in results.sets:
        for name, arr in s["fields"].items():
            if arr.dtype.kind != "f":
                continue
            factor = max(fields[name].factor, 1.0) if name in fields else 1.0
            with np.errstate(over="ignore", invalid="ignore"):
                bad = np.isinf(arr) | np.isinf(arr * factor)
            for i in np.flatnonzero(bad):
                arr[i] = np.nan
                msg = (f"{fields[name].heading if name in fields else name}: beyond the "
                       "double-precision range (overflow), not shown")
                s["flags"][i] = "; ".join(t for t in (s["flags"][i], msg) if t)


class _Sink:
    """Swallows per-row messages (item assignment) that nobody reads."""

    def __setitem__(self, key, value):
        pass


def _evaluate_set(item, g, cases, active, whole, notes, errors, produced=None):
    """One model (a law, or a composed Contact) on the rows g of one contact: the core
    fields, the features' columns (name -> array over g) and the flags (list over g)."""
    obj, text = item
    given = cases.given[g]
    values = cases.value[g]
    if text is None and not isinstance(obj, Refused):
        from ..errors import OutOfRangeError

        try:
            obj.check_applicable()  # refused for the whole cylinder: one message
        except OutOfRangeError as exc:
            obj = Refused(obj.label, exc, obj.key)
    refused = isinstance(obj, Refused)
    if refused:
        model, label = None, obj.label
    elif text is None:  # a plain law
        model, label = _Model(obj), obj.label
        evaluate = _law_evaluator(obj)
    else:
        model, label = _Model(None, obj), _contact_label(obj, text)
        evaluate = _contact_evaluator(obj)
    r = {k: np.full(len(g), np.nan) for k in _NORMAL}
    r["solution"] = np.full(len(g), None, dtype=object)
    if refused:
        for which, name in (("load", "force"), ("depth", "depth")):
            sel = given == which
            r[name][sel] = values[sel]  # the given quantity, even where refused
        for i in g:
            notes[i] = _user_note(obj.exc, given[0], cases, i)
    else:
        # a load or depth <= 0 (a feature's signed row: adhesion) has no contact without
        # the feature: the core's law is not asked, the given value stands
        with np.errstate(invalid="ignore"):
            unloaded = ~(values > 0)
        for which, name in (("load", "force"), ("depth", "depth")):
            sel = unloaded & (given == which)
            r[name][sel] = values[sel]
        for which in ("load", "depth"):
            sel = np.flatnonzero((given == which) & ~unloaded)
            if sel.size:
                rr = _safe_evaluate(evaluate, label, which, values[sel], notes, errors,
                                    g[sel], lambda exc, i, w=which: _user_note(
                                        exc, w, cases, i))
                for k in r:
                    r[k][sel] = rr[k]
    L = cases.length[g[0]]
    if text is None:  # a plain straight contact (or its refused stand-in)
        _hertz(r, cases.radius_eff[g[0]], L, cases.estar[g[0]])
    flags = [""] * len(g)
    w = whole[g]
    R = cases.radius_eff[g[0]]
    with np.errstate(invalid="ignore"):  # only the flagged rows are worded (a long sweep)
        odd = ~w & ((r["depth"] / R > DEPTH_OVER_RADIUS_MAX)
                    | (r["half_width"] / L > HALF_WIDTH_OVER_LENGTH_MAX))
    for j in np.flatnonzero(odd):
        flags[j] = flag_text(r["depth"][j], r["half_width"][j], R, L)
    if refused:
        return r, flags, label, obj
    with np.errstate(invalid="ignore"):
        unloaded = ~(values > 0)
    for f, st in active:
        signed = getattr(st, "signed", None)
        here = np.isfinite(r["force"]) & np.isfinite(r["depth"])
        if signed is not None:
            here = here | (signed[g] & unloaded)
        sel = np.flatnonzero(st.rows[g] & here)
        if not sel.size:
            continue
        normal = {k: r[k][sel] for k in r}
        cols = f.columns(model, g[sel], normal, st)
        for name, arr in cols.items():
            if name == "flags":
                for j, t in zip(sel, arr):
                    if t:
                        flags[j] = "; ".join(x for x in (flags[j], t) if x)
                continue
            if name not in r:
                r[name] = np.full(len(g), np.nan)
            r[name][sel] = arr
            if produced is not None:
                produced[name] = True
    return r, flags, label, obj


def _evaluate_group(results, g, cases, active, whole, sets, refs, produced):
    errors = results.errors
    given = cases.given[g]
    w = whole[g]
    compared = {}
    for _, st in active:
        if getattr(st, "whole", None) is not None:
            compared = {"name": st.compared, "rows": st.whole[g]}

    def quantity(r):
        q = np.where(given == "load", r["depth"], r["force"])
        if compared:
            q = np.where(compared["rows"], r.get(compared["name"], np.nan), q)
        return q

    per_set = []
    for j, item in enumerate(sets[:len(results.sets)]):
        s = results.sets[j]
        r, flags, label, obj = _evaluate_set(item, g, cases, active, whole, s["note"],
                                             errors, produced)
        per_set.append(r)
        if not s.get("named"):  # the column suffix of the set: its first model's
            s["id"] = (model_id(item[0]) if item[1] is None
                       and not isinstance(item[0], Refused)
                       else re.sub(r"[^a-z0-9.]+", "-", str(item[1] or obj.label).lower())
                       .strip("-"))
            s["named"] = True
            s["named_at"] = int(g[0])       # the group that named it (merge_results)
        first = item[0]  # the model as built (its provenance even where it refused)
        if not isinstance(first, Refused) and item[1] is not None:
            first = _Entry(first, label)  # a composed contact: its model's entry
        if isinstance(first, Refused):
            s.setdefault("key", first.key)  # a refused model: its registry key
        else:
            mid = model_id(first)
            if mid not in results.models:
                results.models[mid] = first
                results.origins[mid] = (int(g[0]), j)
            if s.get("model") is None:  # the first contact's model: its JSON entry
                s["model"] = first
        s["label"][g] = label
        f = s["fields"]
        for name, arr in r.items():
            if name == "solution":
                s["solution"][g] = arr
                continue
            if name not in f:
                f[name] = np.full(len(errors), np.nan)
            f[name][g] = arr
        for k in ("depth", "stiffness", "half_width", "peak_pressure", "contact_radius"):
            f[k][g[w]] = np.nan  # a whole body: the features' columns say it
        for k, t in enumerate(flags):
            if t:
                s["flags"][g[k]] = t
    ref_q = None
    if refs is not None:
        sink = _Sink()  # the reference model's own notes are not reported
        whole_features = [(f, st) for f, st in active if getattr(st, "whole", None) is not None]
        rr, _, _, _ = _evaluate_set(refs[0], g, cases, whole_features, whole, sink, sink)
        ref_q = quantity(rr)
    elif len(per_set) > 1:
        ref_q = quantity(per_set[0])
    if ref_q is not None:
        for j, r in enumerate(per_set):
            with np.errstate(divide="ignore", invalid="ignore"):
                results.sets[j]["fields"]["deviation"][g] = quantity(r) / ref_q - 1


class Unmergeable(ValueError):
    """Partial results (:func:`merge_results`) whose shape differs between the parts in
    a way whose whole-batch value cannot be told from the parts (a message says how)."""


def merge_results(parts, rows, errors, cases, label=None):
    """The :class:`Results` of a whole batch from those of parts of its rows, each
    computed by :func:`compute` on those rows alone (the batch on a cluster,
    :mod:`linecontact.calc.spread`); the same as :func:`compute` on all the rows when
    no part splits a group of :func:`group_rows` (a contact's rows are solved as one
    sweep, each load warm-started from its neighbour's: equal to a row alone within
    the solver's tolerance, not bit for bit).

    Every value of a group depends on that group alone; what the whole batch decides
    is taken from the parts: the fields of each set (a field some part lacks is none
    there, as :func:`compute` fills it), the set's id (from the part whose group comes
    first in the whole batch's order of the groups), the models (in that order: the
    JSON header's), whether any row is whole or a single contact, the features'
    columns (in the features' order, from `cases`, the whole batch's), the features'
    blocks (their rows put in place).

    Parameters
    ----------
    parts : list of Results
        ``errors`` of each its rows' errors, ``cases`` unused.
    rows : list of int arrays
        The rows of the batch that each part holds, in the part's order; together
        every row once.
    errors : list of str
        The whole batch's row errors: updated in place from the parts' (a model's
        unexpected exception), and the merged result's ``errors``.
    cases : Cases
        The whole batch's cases.
    label : callable, optional
        As for :func:`compute`.

    Returns
    -------
    Results

    Raises
    ------
    Unmergeable
        The parts chose different numbers of model sets, or comparisons.
    """
    import copy

    from .feature import option_name

    n = len(errors)
    rows = [np.asarray(r, dtype=np.intp) for r in rows]
    if sum(r.size for r in rows) != n or any(len(p.errors) != r.size
                                             for p, r in zip(parts, rows)):
        raise ValueError(f"merge_results: the parts hold {sum(r.size for r in rows)} "
                         f"rows, the batch {n}")
    # the whole batch's order of the groups (as compute evaluates them): a row's key
    key = group_rows(cases, errors)[0]

    def rank(row, part_rows):
        """Where the group of a part's row comes in the whole batch's order."""
        return tuple(key[part_rows[row]].tolist())

    for p, r in zip(parts, rows):
        for i, e in zip(r.tolist(), p.errors):
            errors[i] = e
    n_sets = {len(p.sets) for p in parts}
    if len(n_sets) != 1:
        raise Unmergeable(f"the parts chose {sorted(n_sets)} model sets")
    if len({p.deviation for p in parts}) != 1:
        raise Unmergeable("the parts differ on the deviation column")
    out = Results(n, n_sets.pop(), errors, cases, label or option_name)
    for j, s in enumerate(out.sets):
        ps = [p.sets[j] for p in parts]
        for q, r in zip(ps, rows):
            for k, arr in q["fields"].items():
                if k not in s["fields"]:
                    s["fields"][k] = np.full(n, np.nan)
                s["fields"][k][r] = arr
            for k in ("note", "flags", "label", "solution"):
                s[k][r] = q[k]
        # named by the first group of the whole batch that evaluated it
        named = sorted(((rank(q["named_at"], r), q["id"]) for q, r in zip(ps, rows)
                        if q.get("named")), key=lambda t: t[0])
        s["id"] = named[0][1] if named else ps[0]["id"]
        if named:
            s["named"] = True
        for k in ("model", "key"):
            found = next((q[k] for q in ps if q.get(k) is not None), None)
            if found is not None:
                s[k] = found
    # the models in the order the whole batch's groups registered them
    first = {}
    for p, r in zip(parts, rows):
        for mid, (row, j) in p.origins.items():
            at = (rank(row, r), j)
            if mid not in first or at < first[mid][0]:
                first[mid] = (at, p.models[mid])
    for mid in sorted(first, key=lambda m: first[m][0]):
        out.models[mid] = first[mid][1]
    out.whole = any(p.whole for p in parts)
    out.contact = any(p.contact for p in parts)
    out.deviation = parts[0].deviation
    produced = set()
    for p in parts:
        produced.update(p.whole_columns, p.extra)
    active = cases.active()
    _sort_columns(out, active, produced)   # as compute orders them
    out.features = [f for f, st in active if np.any(st.rows)]
    keys = list(dict.fromkeys(b.key for p in parts for b in p.blocks))
    for bkey in keys:
        blocks = [next((b for b in p.blocks if b.key == bkey), None) for p in parts]
        merged = copy.copy(next(b for b in blocks if b is not None))
        merged.rows, merged.json_rows = [None] * n, [None] * n
        for b, r in zip(blocks, rows):
            if b is None:
                continue
            for k, i in enumerate(r.tolist()):
                merged.rows[i] = b.rows[k]
                if b.json_rows is not None:
                    merged.json_rows[i] = b.json_rows[k]
        out.blocks.append(merged)
    return out


def group_rows(cases, errors):
    """(key, group): per row the values that make one contact (as :func:`compute`
    groups the rows: a group's loads are solved as one sweep) and the number of its
    group (groups numbered in the order of their first row; -1 for a row with an
    error). A batch split into parts that keep each group whole computes the same
    values as the whole (:func:`merge_results`)."""
    composed = [(f, st) for f, st in cases.active()
                if getattr(st, "parts", None) is not None]
    key, _, ok = _group_key(cases, errors, composed)
    group = np.full(len(errors), -1, dtype=np.intp)
    good = np.flatnonzero(ok)
    if good.size:
        _, first, inverse = np.unique(key[good], axis=0, return_index=True,
                                      return_inverse=True)
        order = np.argsort(np.argsort(first, kind="stable"), kind="stable")
        group[good] = order[np.ravel(inverse)]
    return key, group
