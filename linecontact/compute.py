"""The calculator's results: every model evaluated on whole arrays of cases, plus the
per-row quantities derived from them (Hertz half-width and peak pressure, geometry
flags, deviation from the best estimate, whole-roller deflection).

Cases (:func:`linecontact.cases.parse_cases`) are grouped by distinct cylinder
(effective radius, length, E*, raceways): one model object per group and model, each
evaluated once per group on the array of its loads or depths with
:meth:`linecontact.models.ContactModel.evaluate`. A model that refuses some elements
(:class:`~linecontact.validity.OutOfRangeError`) is re-evaluated on halves of the
array until the refused elements are isolated: each of them gets the model's message as
its ``note``, the others their values. Any other exception is reported the same way,
in the row's ``error`` (never lost, never stopping the other rows).

Output columns are :data:`FIELDS` (name -> :class:`Field`: heading, SI and engineering
unit). To add one: add a :class:`Field`, compute its array in :func:`_contact_fields`
(per contact) or :func:`compute` (per row), and list it in :data:`CONTACT_COLUMNS` or
:data:`ROLLER_COLUMNS`; the table, CSV and JSON renderers (:mod:`linecontact.render`)
pick it up from there.

Whole roller between two raceways (``--inner-raceway``, ``--outer-raceway``)
    The force F [N] passes through two contacts in series: roller on inner raceway
    (1/R = 1/R1 + 1/Ri) and roller in outer raceway (1/R = 1/R1 - 1/Ro), both of the
    roller's length L and the same E*. The roller's deflection is the sum of the two
    contact depths, delta = d_i(F) + d_o(F), and its stiffness the series value
    k = 1 / (1/k_i + 1/k_o) [N/m]. This is the quantity ISO/TS 16281's whole-roller
    law describes; it is printed in its own columns (``roller_deflection``,
    ``roller_stiffness``), apart from the per-contact depth of a single contact.
    Each contact is modelled as a cylinder of the effective radius on a half-space,
    which is Hertz's reduction for two parallel cylinders (Johnson 1985, Sec. 4.2)
    applied to the finite-length models.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Field", "FIELDS", "CONTACT_COLUMNS", "ROLLER_COLUMNS", "DEPTH_OVER_RADIUS_MAX",
           "HALF_WIDTH_OVER_LENGTH_MAX", "parse_model_option",
           "compute", "Results"]


@dataclass(frozen=True)
class Field:
    """An output quantity: its table heading, SI unit and engineering unit.

    ``factor`` converts SI to the engineering unit (value_eng = factor * value_SI).
    """

    heading: str
    si: str
    eng: str
    factor: float


#: Every numeric output quantity.
FIELDS = {
    "force": Field("F", "N", "kN", 1e-3),
    "depth": Field("d", "m", "um", 1e6),
    "stiffness": Field("k", "N/m", "N/um", 1e-6),
    "half_width": Field("b (Hertz)", "m", "um", 1e6),
    "peak_pressure": Field("p0 (Hertz)", "Pa", "MPa", 1e-6),
    "contact_radius": Field("a (MDR)", "m", "um", 1e6),
    "deviation": Field("vs best", "-", "%", 100.0),
    "roller_deflection": Field("delta roller", "m", "um", 1e6),
    "roller_stiffness": Field("k roller", "N/m", "N/um", 1e-6),
    "depth_inner": Field("d inner", "m", "um", 1e6),
    "depth_outer": Field("d outer", "m", "um", 1e6),
    "peak_pressure_inner": Field("p0 inner", "Pa", "MPa", 1e-6),
    "peak_pressure_outer": Field("p0 outer", "Pa", "MPa", 1e-6),
    "estar": Field("E*", "Pa", "GPa", 1e-9),
    "radius": Field("R", "m", "mm", 1e3),
    "radius_eff": Field("R eff", "m", "mm", 1e3),
    "length": Field("L", "m", "mm", 1e3),
    # tangential and viscoelastic (linecontact.calc_tangential)
    "kt_mdr": Field("kt MDR", "N/m", "N/um", 1e-6),
    "kt_across": Field("kt across", "N/m", "N/um", 1e-6),
    "kt_along": Field("kt along", "N/m", "N/um", 1e-6),
    "tangential_load": Field("Q", "N", "kN", 1e-3),
    "slip_fraction": Field("Q/(mu F)", "-", "%", 100.0),
    "shift_mdr": Field("u MDR", "m", "um", 1e6),
    "shift_across": Field("u across", "m", "um", 1e6),
    "shift_along": Field("u along", "m", "um", 1e6),
    "time": Field("t", "s", "s", 1.0),
    "creep_depth": Field("d(t)", "m", "um", 1e6),
    "depth_long_term": Field("d(inf)", "m", "um", 1e6),
}

#: Columns of one contact, in order (the given quantity, F or d, comes first).
CONTACT_COLUMNS = ("force", "depth", "stiffness", "half_width", "peak_pressure",
                   "contact_radius", "deviation")
#: Columns of a whole roller between two raceways.
ROLLER_COLUMNS = ("force", "roller_deflection", "roller_stiffness", "depth_inner",
                  "depth_outer", "peak_pressure_inner", "peak_pressure_outer", "deviation")

#: Depth beyond which a row is flagged: the range of Li & Popov's BEM study (d <= 0.15 R,
#: docs/theory.md, section 'BEM'); beyond it the gap is no longer y^2/(2R) to within
#: 1 % (circle vs parabola at y = b) and the tables do not reach.
DEPTH_OVER_RADIUS_MAX = 0.15
#: Hertz half-width beyond which a row is flagged: for b > L/2 the end zones, each about
#: b wide, where the pressure departs from the plane-strain strip meet, so no part of
#: the roller is in line contact and Eq. 1, 2 and 4 lose their basis.
HALF_WIDTH_OVER_LENGTH_MAX = 0.5

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
        if key not in models.MODELS and key in models.DEFINED_IN:
            # registered on import of its module (kept off the one-case path until asked)
            from importlib import import_module

            import_module(models.DEFINED_IN[key])
        if key not in models.MODELS:
            from ._units import _QUANTITY

            raise InputError("--model", spec if _QUANTITY.match(text) else text, valid,
                             "a decimal comma in an option? (write c=1.5, not c=1,5)"
                             if _QUANTITY.match(text) else "unknown model")
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

    from ._units import DIMENSIONS

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
    from ._units import _QUANTITY, InputError, parse_bool, parse_quantity

    if isinstance(default, bool):
        return parse_bool(name, text)
    if isinstance(default, (int, float)):
        try:
            value = parse_quantity(name, text, kind, positive=False)
        except InputError:
            if _QUANTITY.match(text) or text[:1] in "+-.0123456789":
                raise  # a number with a wrong unit (tilt=1mm), not a name
            return text  # a named constant (e.g. johnson c=johnson1985); the model checks
        # an integer option (n_slices=40) stays an int; 40.5 goes to the model to refuse
        return int(value) if isinstance(default, int) and value.is_integer() else value
    return text


def _model_id(model):
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
    from . import models
    from ._units import InputError
    from .validity import OutOfRangeError

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


def _safe_evaluate(model, given, values, notes, errors, idx):
    """evaluate() on `values`; refused elements isolated by halving.

    Returns a dict of arrays (NaN where refused); writes ``notes[idx[i]]`` (out of the
    model's range) or ``errors[idx[i]]`` (any other exception) for refused elements.
    """
    from .validity import OutOfRangeError

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
    from .classical import hertz_half_width, hertz_peak_pressure

    F = r["force"]
    ok = np.isfinite(F) & (F > 0)
    b = np.full(F.shape, np.nan)
    p0 = np.full(F.shape, np.nan)
    if ok.any():
        b[ok] = hertz_half_width(F[ok], R, L, E)
        p0[ok] = hertz_peak_pressure(F[ok], R, L, E)
    r["half_width"] = b
    r["peak_pressure"] = p0
    with np.errstate(invalid="ignore"):
        r["_deep"] = r["depth"] / R > DEPTH_OVER_RADIUS_MAX
        r["_wide"] = b / L > HALF_WIDTH_OVER_LENGTH_MAX
    return r


def _flag_text(deep, wide, where=""):
    parts = []
    if deep:
        parts.append(f"d > {DEPTH_OVER_RADIUS_MAX:g} R{where}: beyond the parabolic-gap "
                     "range of the models")
    if wide:
        parts.append(f"b > {HALF_WIDTH_OVER_LENGTH_MAX:g} L{where}: not a line contact")
    return "; ".join(parts)


class Results:
    """Per model set j: arrays over all rows of every field, plus notes and flags.

    Attributes
    ----------
    sets : list of dict
        One per model column set: ``fields`` (name -> float array [SI]), ``note`` and
        ``flags`` (object arrays of str), ``label`` (object array of str: the model per
        row), ``id`` (the column suffix) and ``model`` (the model built for the first
        cylinder, for the JSON header).
    models : dict
        Model id -> a model object (for provenance).
    errors : list of str
        The row errors (input errors and unexpected exceptions).
    roller : bool
        Some rows are whole rollers between raceways.
    deviation : bool
        The deviation column is meaningful (a reference other than the model itself).
    """

    def __init__(self, n, n_sets, errors):
        self.sets = [
            {"fields": {}, "note": np.full(n, "", dtype=object),
             "flags": np.full(n, "", dtype=object), "label": np.full(n, "", dtype=object),
             "id": ""}
            for _ in range(n_sets)
        ]
        from .calc_tangential import ALL_COLUMNS

        for s in self.sets:
            for f in set(CONTACT_COLUMNS) | set(ROLLER_COLUMNS) | set(ALL_COLUMNS):
                s["fields"][f] = np.full(n, np.nan)
        self.models = {}
        self.errors = errors
        self.roller = False
        self.deviation = False
        self.extra = []  # tangential/viscoelastic columns (linecontact.calc_tangential)


def compute(cases, errors, specs, *, first_only=False, progress=None):
    """Evaluate the selected models for every good row.

    Parameters
    ----------
    cases : dict
        From :func:`linecontact.cases.parse_cases`.
    errors : list of str
        Row errors so far (rows with one are skipped); unexpected exceptions are added.
    specs : list or None
        From :func:`parse_model_option` (None: the standard set).
    first_only : bool
        Only the first model of the standard set (the default best estimate).
    progress : callable, optional
        Called with the number of rows finished after each group.

    Returns
    -------
    Results
    """
    n = len(errors)
    ok = np.array([not e for e in errors], dtype=bool)
    R1, Reff, L, E = cases["radius"], cases["radius_eff"], cases["length"], cases["estar"]
    Ri, Ro = cases["inner_raceway"], cases["outer_raceway"]
    race = cases["raceways"]
    key = np.stack([Reff, L, E, np.where(race, Ri, -1.0), np.where(race, Ro, -1.0),
                    np.where(race, R1, -1.0)], axis=1)
    rows = np.flatnonzero(ok)
    if rows.size:
        k = key[rows]
        order = np.lexsort(k.T[::-1])  # rows of one cylinder become neighbours
        ks = k[order]
        bounds = np.flatnonzero(np.any(ks[1:] != ks[:-1], axis=1)) + 1
        groups = np.split(rows[order], bounds)
    else:
        groups = []
    from .models import DEFAULT_MODEL

    probe = _build(specs, 1.0, 1.0, 1.0, first_only)  # the column sets, in order
    # the default model alone when it heads the standard set (it does when installed)
    default_key = (DEFAULT_MODEL if specs is None and first_only
                   and probe[0].key == DEFAULT_MODEL else None)
    results = Results(n, len(probe), errors)
    for s, m in zip(results.sets, probe):
        s["id"] = _model_id(m)
    reference = specs is not None and not first_only
    ref_key = None
    if reference:  # the best estimate alone per cylinder, as for a default batch
        from .models import standard_models

        first = standard_models(1.0, 1.0, 1.0)[0]
        ref_key = DEFAULT_MODEL if first.key == DEFAULT_MODEL else None
    results.deviation = len(probe) > 1 or reference
    # an intermediate that overflows (a force of 1e300 N) is caught by _no_overflow
    # below, in the row's flags; numpy's warnings would only add lines to stderr
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        _compute_groups(results, groups, cases, specs, first_only, default_key,
                        reference, ref_key, progress)
    _no_overflow(results)
    ok = np.array([not e for e in errors], dtype=bool)
    results.roller = bool(np.any(race & ok))
    from .calc_tangential import columns as _extra_columns

    results.extra = list(_extra_columns(cases, cases["_present"])) if "_present" in cases \
        else []
    return results


def _no_overflow(results):
    """No 'inf' in any output: a result beyond the double range, or one whose value in
    the engineering unit of the table is (e.g. 1e305 m in um), is not shown ('-') and
    its row's flags say so, for that model (a flag: the other values stand)."""
    for s in results.sets:
        for name, arr in s["fields"].items():
            factor = max(FIELDS[name].factor, 1.0) if name in FIELDS else 1.0
            with np.errstate(over="ignore", invalid="ignore"):
                bad = np.isinf(arr) | np.isinf(arr * factor)
            for i in np.flatnonzero(bad):
                arr[i] = np.nan
                msg = (f"{FIELDS[name].heading if name in FIELDS else name}: beyond the "
                       "double-precision range (overflow), not shown")
                s["flags"][i] = "; ".join(t for t in (s["flags"][i], msg) if t)


def _compute_groups(results, groups, cases, specs, first_only, default_key, reference,
                    ref_key, progress):
    """Every group of rows of one cylinder (the loop of :func:`compute`)."""
    errors = results.errors
    R1, Reff, L, E = cases["radius"], cases["radius_eff"], cases["length"], cases["estar"]
    Ri, Ro = cases["inner_raceway"], cases["outer_raceway"]
    race = cases["raceways"]
    done = 0
    for g in groups:
        i0 = g[0]
        try:
            if race[i0]:
                R_in = 1 / (1 / R1[i0] + 1 / Ri[i0])
                R_out = 1 / (1 / R1[i0] - 1 / Ro[i0])
                contacts = [R_in, R_out]
            else:
                contacts = [Reff[i0]]
            sets = [_build(specs, R, L[i0], E[i0], first_only, default_key)
                    for R in contacts]
            refs = ([_build(None, R, L[i0], E[i0], True, ref_key) for R in contacts]
                    if reference else None)
        except Exception as exc:  # noqa: BLE001 - reported in the rows, never lost
            for i in g:
                errors[i] = f"unexpected {type(exc).__name__}: {exc}"
            continue
        _evaluate_group(results, g, cases, contacts, sets, refs, L[i0], E[i0])
        done += len(g)
        if progress is not None:
            progress(done)


class _Sink:
    """Swallows per-row messages (item assignment) that nobody reads."""

    def __setitem__(self, key, value):
        pass


def _evaluate_group(results, g, cases, contacts, sets, refs, L, E):
    given = cases["given"][g]
    values = cases["value"][g]
    errors = results.errors
    sink = _Sink()  # the reference model's own notes are not reported
    per_set = []  # j -> list over contacts of field dicts (arrays over g)
    for j in range(len(sets[0])):
        per_contact = []
        for c, R in enumerate(contacts):
            model = sets[c][j]
            r = {k: np.full(len(g), np.nan) for k in ("force", "depth", "stiffness",
                                                      "contact_radius")}
            notes = results.sets[j]["note"]
            for which in ("load", "depth"):
                sel = np.flatnonzero(given == which)
                if not sel.size:
                    continue
                idx = g[sel]
                rr = _safe_evaluate(model, which, values[sel], notes, errors, idx)
                for k in r:
                    r[k][sel] = rr[k]
            per_contact.append(_contact_fields(r, R, L, E))
            mid = _model_id(model)
            if mid not in results.models:
                results.models[mid] = model
        per_set.append(per_contact)
        s = results.sets[j]
        label = sets[0][j].label
        if s.get("model") is None:  # the first cylinder's model: the JSON entry of a set
            s["model"] = sets[0][j]
        s["label"][g] = label
    ref_q = None
    if refs is not None:
        ref_contacts = []
        for c, R in enumerate(contacts):
            r = {k: np.full(len(g), np.nan) for k in ("force", "depth")}
            for which in ("load", "depth"):
                sel = np.flatnonzero(given == which)
                if sel.size:
                    rr = _safe_evaluate(refs[c][0], which, values[sel], sink, sink,
                                        g[sel])
                    r["force"][sel], r["depth"][sel] = rr["force"], rr["depth"]
            ref_contacts.append(r)
        ref_q = _quantity(ref_contacts, given)
    elif len(per_set) > 1:
        ref_q = _quantity(per_set[0], given)
    for j, per_contact in enumerate(per_set):
        s = results.sets[j]
        f = s["fields"]
        if len(contacts) == 1:
            r = per_contact[0]
            for k in ("force", "depth", "stiffness", "half_width", "peak_pressure",
                      "contact_radius"):
                f[k][g] = r[k]
            for k in np.flatnonzero(r["_deep"] | r["_wide"]):
                s["flags"][g[k]] = _flag_text(r["_deep"][k], r["_wide"][k])
            if "_present" in cases:  # tangential / viscoelastic columns and flags
                from .calc_tangential import add_fields

                add_fields(f, s["flags"], g, sets[0][j], r, cases, cases["_present"])
        else:
            ri, ro = per_contact
            f["force"][g] = ri["force"]
            f["depth_inner"][g] = ri["depth"]
            f["depth_outer"][g] = ro["depth"]
            f["roller_deflection"][g] = ri["depth"] + ro["depth"]
            with np.errstate(divide="ignore", invalid="ignore"):
                f["roller_stiffness"][g] = 1 / (1 / ri["stiffness"] + 1 / ro["stiffness"])
            f["peak_pressure_inner"][g] = ri["peak_pressure"]
            f["peak_pressure_outer"][g] = ro["peak_pressure"]
            for k in np.flatnonzero(ri["_deep"] | ri["_wide"] | ro["_deep"] | ro["_wide"]):
                s["flags"][g[k]] = "; ".join(
                    t for t in (_flag_text(ri["_deep"][k], ri["_wide"][k], " (inner)"),
                                _flag_text(ro["_deep"][k], ro["_wide"][k], " (outer)")) if t)
        if ref_q is not None:
            with np.errstate(divide="ignore", invalid="ignore"):
                f["deviation"][g] = _quantity(per_contact, given) / ref_q - 1


def _quantity(per_contact, given):
    """The computed quantity compared between models: the depth (whole roller: the sum
    of the two contacts' depths) when the force is given, the force when the depth is."""
    if len(per_contact) == 2:
        return per_contact[0]["depth"] + per_contact[1]["depth"]
    r = per_contact[0]
    return np.where(given == "load", r["depth"], r["force"])
