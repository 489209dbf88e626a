"""The calculator's results: every model evaluated on whole arrays of cases, the
per-row quantities derived from them (Hertz half-width and peak pressure, geometry
flags, deviation from the best estimate), and the columns of the active features.

Cases (:func:`linecontact.calc.cases.parse_cases`) are grouped by distinct contact
(effective radius, length, E*): one model object per group and model, each evaluated
once per group on the array of its loads or depths with
:meth:`linecontact.models.ContactModel.evaluate`. A model that refuses some elements
(:class:`~linecontact.validity.OutOfRangeError`) is re-evaluated on halves of the
array until the refused elements are isolated: each of them gets the model's message as
its ``note``, the others their values. Any other exception is reported the same way,
in the row's ``error`` (never lost, never stopping the other rows). Then each active
feature (:mod:`linecontact.calc.feature`) is asked for its columns over the group's
rows, and for its extra tables (blocks) once at the end.

Output columns: the core's :data:`FIELDS` (name -> :class:`Field`: heading, SI and
engineering unit) and each feature's ``fields``; :func:`all_fields` has them all.
"""

from __future__ import annotations

import numpy as np

from .feature import Field, flag_text
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

    def __init__(self, text, exc):
        self.key = text
        self.label = text
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

            raise InputError("--model", spec if QUANTITY.match(text) else text, valid,
                             "a decimal comma in an option? (write c=1.5, not c=1,5)"
                             if QUANTITY.match(text) else "unknown model")
        defaults = _option_defaults(models.MODELS[key])
        options = {}
        for opt in opts:
            name, eq, value = opt.partition("=")
            name = name.strip()
            if not eq or not name:
                raise InputError("--model", text, valid, f"option {opt!r} is not OPTION=VALUE")
            if name not in defaults:
                raise InputError(
                    "--model", text,
                    f"options of {key}: {', '.join(defaults) or 'none'}",
                    f"unknown option {name!r}")
            options[name] = _option_value(f"--model {key}:{name}", value.strip(),
                                          defaults[name],
                                          _option_kind(models.MODELS[key], name))
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
        try:
            value = parse_quantity(name, text, kind, positive=False)
        except InputError:
            if QUANTITY.match(text) or text[:1] in "+-.0123456789":
                raise  # a number with a wrong unit (tilt=1mm), not a name
            return text  # a named constant (e.g. johnson c=johnson1985); the model checks
        # an integer option (n_slices=40) stays an int; 40.5 goes to the model to refuse
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
    from ..validity import OutOfRangeError

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
            chosen.append(Refused(text, exc))
        except TypeError as exc:  # an option the model does not take
            raise InputError(
                "--model", text, "options the model takes (see its docstring)", str(exc)
            ) from None
    return chosen


# ---------------------------------------------------------------------------------------
# evaluation


class _Model:
    """A model as the features see it: every attribute of the ContactModel, plus
    :meth:`at`: the same law (key and options) at another effective radius (built once
    per radius)."""

    def __init__(self, model, build):
        self._model = model
        self._build = build
        self._at = {}

    def __getattr__(self, name):
        return getattr(self._model, name)

    def at(self, radius):
        """The same model at effective radius `radius` [m]."""
        radius = float(radius)
        if radius not in self._at:
            self._at[radius] = self._build(radius)
        return self._at[radius]


def _safe_evaluate(model, given, values, notes, errors, idx):
    """evaluate() on `values`; refused elements isolated by halving.

    Returns a dict of arrays (NaN where refused); writes ``notes[idx[i]]`` (out of the
    model's range) or ``errors[idx[i]]`` (any other exception) for refused elements.
    """
    from ..validity import OutOfRangeError

    n = len(values)
    out = {k: np.full(n, np.nan) for k in ("force", "depth", "stiffness", "contact_radius")}
    out["force" if given == "load" else "depth"][:] = values  # given, even where refused
    if not isinstance(model, Refused):
        try:
            model.check_applicable()  # refused for the whole cylinder: one message
        except OutOfRangeError as exc:
            model = Refused(model.label, exc)
    if isinstance(model, Refused):
        for i in idx:
            notes[i] = str(model.exc)
        return out
    stack = [(0, n)]
    while stack:
        lo, hi = stack.pop()
        try:
            r = model.evaluate(**{("force" if given == "load" else "depth"): values[lo:hi]})
        except OutOfRangeError as exc:
            if hi - lo == 1:
                notes[idx[lo]] = str(exc)
            else:
                mid = (lo + hi) // 2
                stack += [(mid, hi), (lo, mid)]
            continue
        except Exception as exc:  # noqa: BLE001 - reported in the row, never lost
            if hi - lo == 1:
                detail = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                errors[idx[lo]] = (f"{model.label}: unexpected {type(exc).__name__}"
                                   + (f": {detail}" if detail else ""))
            else:
                mid = (lo + hi) // 2
                stack += [(mid, hi), (lo, mid)]
            continue
        for k in out:
            out[k][lo:hi] = r[k]
    return out


def _contact_fields(r, R, L, E):
    """Per-contact derived fields from an evaluate() result (arrays): b, p0, flags."""
    from ..classical import hertz_half_width, hertz_peak_pressure

    F = r["force"]
    ok = np.isfinite(F) & (F > 0)
    b = np.full(F.shape, np.nan)
    p0 = np.full(F.shape, np.nan)
    if ok.any():
        b[ok] = hertz_half_width(F[ok], R, L, E)
        p0[ok] = hertz_peak_pressure(F[ok], R, L, E)
    r["half_width"] = b
    r["peak_pressure"] = p0
    return r


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
             "id": ""}
            for _ in range(n_sets)
        ]
        for s in self.sets:
            for f in CONTACT_COLUMNS:
                s["fields"][f] = np.full(n, np.nan)
        self.models = {}
        self.errors = errors
        self.cases = cases
        self.label = label
        self.whole = False
        self.contact = False
        self.whole_columns = []
        self.extra = []
        self.features = []
        self.blocks = []
        self.deviation = False


def compute(cases, errors, specs, *, first_only=False, progress=None, label=None):
    """Evaluate the selected models and the active features for every good row.

    Parameters
    ----------
    cases : Cases
        From :func:`linecontact.calc.cases.parse_cases`.
    errors : list of str
        Row errors so far (rows with one are skipped); unexpected exceptions are added.
    specs : list or None
        From :func:`parse_model_option` (None: the standard set).
    first_only : bool
        Only the first model of the standard set (the default best estimate).
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
    ok = np.array([not e for e in errors], dtype=bool)
    key = np.stack([cases.radius_eff, cases.length, cases.estar], axis=1)
    rows = np.flatnonzero(ok)
    if rows.size:
        k = key[rows]
        order = np.lexsort(k.T[::-1])  # rows of one contact become neighbours
        ks = k[order]
        bounds = np.flatnonzero(np.any(ks[1:] != ks[:-1], axis=1)) + 1
        groups = np.split(rows[order], bounds)
    else:
        groups = []
    from ..models import DEFAULT_MODEL

    probe = _build(specs, 1.0, 1.0, 1.0, first_only)  # the column sets, in order
    # the default model alone when it heads the standard set (it does when installed)
    default_key = (DEFAULT_MODEL if specs is None and first_only
                   and probe[0].key == DEFAULT_MODEL else None)
    results = Results(n, len(probe), errors, cases, label or option_name)
    for s, m in zip(results.sets, probe):
        s["id"] = model_id(m)
    reference = specs is not None and not first_only
    ref_key = None
    if reference:  # the best estimate alone per contact, as for a default batch
        from ..models import standard_models

        first = standard_models(1.0, 1.0, 1.0)[0]
        ref_key = DEFAULT_MODEL if first.key == DEFAULT_MODEL else None
    results.deviation = len(probe) > 1 or reference
    active = cases.active()
    whole = cases.whole()
    produced = {}
    # an intermediate that overflows (a force of 1e300 N) is caught by _no_overflow
    # below, in the row's flags; numpy's warnings would only add lines to stderr
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        done = 0
        for g in groups:
            i0 = g[0]
            R, L, E = cases.radius_eff[i0], cases.length[i0], cases.estar[i0]
            try:
                sets = _build(specs, R, L, E, first_only, default_key)
                refs = _build(None, R, L, E, True, ref_key) if reference else None
            except Exception as exc:  # noqa: BLE001 - reported in the rows, never lost
                for i in g:
                    errors[i] = f"unexpected {type(exc).__name__}: {exc}"
                continue
            _evaluate_group(results, g, cases, active, whole, sets, refs,
                            (specs, L, E, first_only, default_key), produced)
            done += len(g)
            if progress is not None:
                progress(done)
    _no_overflow(results)
    ok = np.array([not e for e in errors], dtype=bool)
    results.whole = bool(np.any(whole & ok))
    results.contact = bool(np.any(~whole & ok))
    results.features = [f for f, _ in active]
    for f, st in active:
        names = [c for c in f.fields if c in produced]
        if getattr(st, "whole", None) is not None:
            results.whole_columns += names
        else:
            results.extra += names
    for f, st in active:
        results.blocks += f.blocks(st, results)
    return results


def _no_overflow(results):
    """No 'inf' in any output: a result beyond the double range, or one whose value in
    the engineering unit of the table is (e.g. 1e305 m in um), is not shown ('-') and
    its row's flags say so, for that model (a flag: the other values stand)."""
    fields = all_fields()
    for s in results.sets:
        for name, arr in s["fields"].items():
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


def _evaluate_set(model, g, cases, active, whole, notes, errors, produced=None):
    """One model on the rows g of one contact: the core fields, the features' columns
    (name -> array over g) and the flags (list over g)."""
    given = cases.given[g]
    values = cases.value[g]
    r = {k: np.full(len(g), np.nan) for k in ("force", "depth", "stiffness",
                                              "contact_radius")}
    for which in ("load", "depth"):
        sel = np.flatnonzero(given == which)
        if sel.size:
            rr = _safe_evaluate(model._model if isinstance(model, _Model) else model,
                                which, values[sel], notes, errors, g[sel])
            for k in r:
                r[k][sel] = rr[k]
    R, L, E = cases.radius_eff[g[0]], cases.length[g[0]], cases.estar[g[0]]
    r = _contact_fields(r, R, L, E)
    flags = [""] * len(g)
    w = whole[g]
    for j in np.flatnonzero(~w):
        flags[j] = flag_text(r["depth"][j], r["half_width"][j], R, L)
    if isinstance(model, Refused):
        return r, flags
    for f, st in active:
        sel = np.flatnonzero(st.rows[g])
        if not sel.size:
            continue
        normal = {k: r[k][sel] for k in ("force", "depth", "stiffness")}
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
    return r, flags


def _evaluate_group(results, g, cases, active, whole, sets, refs, build, produced):
    specs, L, E, first_only, default_key = build
    errors = results.errors
    given = cases.given[g]
    w = whole[g]
    compared = {}
    for _, st in active:
        if getattr(st, "whole", None) is not None:
            compared = {"name": st.compared, "rows": st.whole[g]}

    def wrap(m, j):
        if isinstance(m, Refused):
            return m
        return _Model(m, lambda R: _build(specs, R, L, E, first_only, default_key)[j])

    def quantity(r):
        q = np.where(given == "load", r["depth"], r["force"])
        if compared:
            q = np.where(compared["rows"], r.get(compared["name"], np.nan), q)
        return q

    per_set = []
    for j, m in enumerate(sets):
        s = results.sets[j]
        model = wrap(m, j)
        r, flags = _evaluate_set(model, g, cases, active, whole, s["note"], errors, produced)
        per_set.append(r)
        mid = model_id(m)
        if mid not in results.models:
            results.models[mid] = m
        if s.get("model") is None:  # the first contact's model: the JSON entry of a set
            s["model"] = m
        s["label"][g] = m.label
        f = s["fields"]
        for name, arr in r.items():
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
        model = _Model(refs[0], lambda R: _build(None, R, L, E, True, None)[0]) \
            if not isinstance(refs[0], Refused) else refs[0]
        whole_features = [(f, st) for f, st in active if getattr(st, "whole", None) is not None]
        rr, _ = _evaluate_set(model, g, cases, whole_features, whole, sink, sink)
        ref_q = quantity(rr)
    elif len(per_set) > 1:
        ref_q = quantity(per_set[0])
    if ref_q is not None:
        for j, r in enumerate(per_set):
            with np.errstate(divide="ignore", invalid="ignore"):
                results.sets[j]["fields"]["deviation"][g] = quantity(r) / ref_q - 1
