"""The calculator's inputs: parameters (command-line options = CSV columns), and their
conversion into checked SI arrays, one element per case.

Every input of ``linecontact calc`` is a :class:`~linecontact.calc.feature.Parameter`:
the core ones in :data:`CORE` (roller, second body, materials, load), the others
declared by the features of :data:`linecontact.calc.features.FEATURES`; all of them in
:data:`PARAMETERS`, grouped as in ``--help``. One declaration gives the option
``--NAME`` (``_`` written ``-``), the CSV column ``NAME`` (case-insensitive) and the
parsing rule of its kind (:mod:`linecontact._units`: a number with one unit name).
:func:`parse_cases` converts a table of cells (one case per row; the one-case command
is a table of one row, a sweep a table of N rows) into SI arrays and one error message
per bad row, by column (the unit rules and the per-unit factors are applied once per
column), then runs the rules: the core's, each feature's ``resolve`` (one loop), and
the core's that depend on the features (E*, the effective radius).

Geometry
    ``--radius`` R1 or ``--diameter`` D = 2 R1 of the roller; ``--radius2`` R2 of the
    second body at the contact (negative for a concave one, e.g. an outer raceway),
    giving the effective radius 1/R = 1/R1 + 1/R2 of two parallel cylinders (Hertz;
    Johnson 1985, Sec. 4.2) that every model uses; without it the second body is flat.
    A feature may set the contact's effective radius itself (the raceways).
"""

from __future__ import annotations

import operator

import numpy as np

from .._units import parse_column
from .feature import RAW_KINDS, Fail, Parameter, bounds_of, option_name
from .features import FEATURES

__all__ = ["CORE", "PARAMETERS", "BY_NAME", "Cases", "parse_cases", "parse_columns",
           "likely_cause"]

_CYL = "cylinder (roller)"
_BODY = "second body and materials"
_LOAD = "load (exactly one)"

#: Magnitudes the core quantities have in practice [SI] (Parameter.plausible): roller
#: dimensions 0.1 mm to 2 m, depths 0.1 nm to 1 cm, moduli 1 kPa (gels) to 10 TPa
#: (above diamond), forces 1 mN to 100 MN.
_SIZE, _DEPTH, _MODULUS, _FORCE = (1e-4, 2.0), (1e-10, 1e-2), (1e3, 1e13), (1e-3, 1e8)

#: The core inputs (every case has a roller, a second body and a load).
CORE = (
    Parameter("radius", "length", "roller radius R1", _CYL, plausible=_SIZE),
    Parameter("diameter", "length", "roller diameter D = 2 R1 (instead of --radius)", _CYL,
              plausible=_SIZE),
    Parameter("length", "length", "roller length L", _CYL, plausible=_SIZE),
    Parameter("radius2", "length", "radius R2 of the second body at the contact, negative "
              "if concave (e.g. a raceway bore): 1/R = 1/R1 + 1/R2; default: flat", _BODY,
              positive=False, plausible=_SIZE),
    Parameter("modulus", "pressure", "Young's modulus E1 of the second body "
              "(the half-space)", _BODY, plausible=_MODULUS),
    Parameter("poisson", "dimensionless", "Poisson's ratio nu1 of the second body", _BODY,
              bounds="POISSON_RATIO"),
    Parameter("modulus2", "pressure", "Young's modulus E2 of the roller "
              "(default: rigid)", _BODY, plausible=_MODULUS),
    Parameter("poisson2", "dimensionless", "Poisson's ratio nu2 of the roller", _BODY,
              bounds="POISSON_RATIO"),
    Parameter("estar", "pressure", "effective modulus E* of Eq. 3 (instead of the moduli)",
              _BODY, plausible=_MODULUS),
    Parameter("load", "force", "normal force F per contact, or a sweep START:STOP:N "
              "(> 0; zero or tensile only where a feature gives it a meaning: adhesion)",
              _LOAD, positive=False, plausible=_FORCE),
    Parameter("depth", "length", "indentation depth d of one contact (rigid-body "
              "approach), or a sweep START:STOP:N (> 0; zero or negative only with "
              "adhesion)", _LOAD, positive=False, plausible=_DEPTH),
)

#: The load parameters: signed in the declaration above (a sweep through 0 is spaced
#: linearly), positive by the core's rule (:func:`_resolve`) except in the rows a
#: feature marks ``signed`` (:class:`~linecontact.calc.feature.State`).
_SIGNED_LOADS = ("load", "depth")

#: Every input, in ``--help`` order: the core, then each feature's.
PARAMETERS = CORE + tuple(p for f in FEATURES for p in f.parameters)

BY_NAME = {p.name: p for p in PARAMETERS}


class Cases:
    """The checked cases: SI arrays, one element per row.

    Attributes
    ----------
    n : int
        Number of rows.
    values : dict
        Parameter name -> SI float array (NaN where not given or refused), or the cells
        as typed (list of str) for text and path parameters (see
        :data:`~linecontact.calc.feature.RAW_KINDS`); angles are parsed to rad.
    present : dict
        Parameter name -> bool array: given in that row.
    radius, radius_eff, length, estar : ndarray
        Roller radius R1, effective radius R of the contact the models see, roller
        length L [m] and effective modulus E* [Pa].
    given : ndarray of str
        'load' or 'depth' per row; ``value`` the force [N] or depth [m].
    states : dict
        Feature name -> :class:`~linecontact.calc.feature.State` of the active features.
    cells : dict
        The cells as given (for messages).
    """

    def __init__(self, n, values, present, cells):
        self.n = n
        self.values = values
        self.present = present
        self.cells = cells
        self.states = {}

    def __getitem__(self, name):
        """A value column by parameter name (``cases["length"]``)."""
        return self.values[name]

    def active(self):
        """(feature, state) of the active features, in registration order."""
        return [(f, self.states[f.name]) for f in FEATURES if f.name in self.states]

    def whole(self):
        """Bool array: rows where a feature describes the whole body (see State)."""
        out = np.zeros(self.n, bool)
        for _, st in self.active():
            w = getattr(st, "whole", None)
            if w is not None:
                out |= w
        return out


#: Cells of a column looked at to decide whether it repeats its values (see parse_cases).
_SAMPLE = 256


def parse_cases(cells, n, label=option_name):
    """Convert a table of cells into checked SI arrays, one element per case.

    Parameters
    ----------
    cells : dict
        Parameter name -> list of n strings (``""`` = not given) or an ndarray of n SI
        floats (NaN = not given; a sweep already parsed). Absent names are not given.
    n : int
        Number of cases.
    label : callable
        Name of a parameter in messages (``--radius`` or the CSV column ``radius``).

    Returns
    -------
    cases : Cases
    present : dict
        Name -> bool array: the cell was given.
    errors : list of str
        ``""`` for a good row, else the first problem of that row (one line: the
        parameter, the value as typed, the valid range).
    """
    values, present, raw, errors = parse_columns(PARAMETERS, cells, n, label)
    cases = Cases(n, values, present, raw)
    cases.label = label
    _resolve(cases, errors, Fail(errors, raw, label, not label("load").startswith("--")))
    return cases, present, errors


def parse_columns(parameters, cells, n, label=option_name):
    """The cells of each of `parameters` as SI arrays (the unit rules of
    :mod:`linecontact._units` and the per-unit factors applied once per column).

    Returns (values, present, raw, errors): name -> SI float array (NaN where not
    given or refused) or the cells as typed (:data:`RAW_KINDS`); name -> bool array
    (given); name -> the cells as given; the first problem of each row (``""``: none).
    The rules between parameters are the caller's (:func:`parse_cases`, a
    subcommand's ``resolve``).
    """
    errors = [""] * n
    values, present, raw = {}, {}, {}
    for p in parameters:
        col = cells.get(p.name)
        if col is None:
            values[p.name] = [""] * n if p.kind in RAW_KINDS else np.full(n, np.nan)
            present[p.name] = np.zeros(n, bool)
            continue
        if isinstance(col, np.ndarray) and col.dtype.kind == "f":
            values[p.name] = col.astype(float)
            present[p.name] = ~np.isnan(col)
            raw[p.name] = col
            continue
        if n and type(col[0]) is not str:  # cells as read are str; others converted
            col = ["" if c is None else str(c) for c in col]
        raw[p.name] = col
        if p.kind in RAW_KINDS:  # read by the feature (raw cells)
            present[p.name] = np.array([c.strip() != "" for c in col], dtype=bool)
            values[p.name] = col
            continue
        # distinct cells only where a column repeats its values (a batch of a few
        # cylinders, empty cells); a column of mostly distinct cells (a parameter
        # study) is parsed as it is, which gives the same values without the lookups
        sample = len(set(col[:_SAMPLE]))
        if n and sample == 1 and col.count(col[0]) == n:  # one value for all rows
            uniq, inv = [col[0]], np.zeros(n, dtype=np.intp)  # (e.g. the modulus)
        elif n > _SAMPLE and sample > _SAMPLE // 2:
            uniq, inv = col, None
        else:
            uniq = list(dict.fromkeys(col))    # in order of first appearance
            where = {c: i for i, c in enumerate(uniq)}
            inv = np.fromiter(map(where.__getitem__, col), dtype=np.intp, count=n)
        m = len(uniq)
        stripped = list(map(str.strip, uniq))
        u_given = np.fromiter(map(bool, stripped), dtype=bool, count=m)
        u_values = np.full(m, np.nan)
        u_errors = [""] * m
        words = (np.fromiter(map(p.words.__contains__, map(str.lower, stripped)),
                             dtype=bool, count=m) if p.words else np.zeros(m, bool))
        use = u_given & ~words
        gi = np.flatnonzero(use)
        if gi.size:
            every = gi.size == m
            parsed, errs = parse_column(label(p.name), uniq if every else
                                        [uniq[i] for i in gi], p.kind,
                                        positive=p.positive, bounds=bounds_of(p))
            u_values[gi] = parsed
            if any(errs):
                if every:
                    u_errors = errs
                else:
                    for i, e in zip(gi, errs):
                        u_errors[i] = e
        present[p.name] = u_given if inv is None else u_given[inv]
        values[p.name] = u_values if inv is None else u_values[inv]
        if any(u_errors):
            bad = [i for i, e in enumerate(u_errors) if e]
            rows = bad if inv is None else np.flatnonzero(np.isin(inv, bad))
            for j in rows:
                if not errors[j]:
                    errors[j] = u_errors[j if inv is None else inv[j]]
    return values, present, raw, errors


def refuse_estar_with_moduli(present, fail):
    """Refuse the rows that give E* and any of the moduli or Poisson's ratios (E* is
    either given or computed by Eq. 3, never both): the rule of every command that
    takes materials (``calc``, ``bearing``)."""
    for name in ("modulus", "poisson", "modulus2", "poisson2"):
        fail(present["estar"] & present[name], name,
             f"either {fail.label('estar')} or the moduli and Poisson's ratios, not both",
             f"conflicts with {fail.label('estar')}")


def _resolve(cases, errors, fail):
    """The rules: the core's, each feature's resolve, then E* and the contact radius."""
    v, P, n = cases.values, cases.present, cases.n
    label = fail.label
    # roller radius: --radius or --diameter
    fail(P["radius"] & P["diameter"], "diameter",
         f"either {label('radius')} or {label('diameter')}, not both",
         f"conflicts with {label('radius')}")
    fail(~P["radius"] & ~P["diameter"], "radius",
         f"a length > 0 (e.g. 5mm), or {label('diameter')}", "missing")
    radius = np.where(P["radius"], v["radius"], v["diameter"] / 2)
    fail(~P["length"], "length", "a length > 0 (e.g. 10mm)", "missing")

    # materials: E* directly, or Eq. 3 from the moduli
    refuse_estar_with_moduli(P, fail)
    pair = f"{label('modulus2')} and {label('poisson2')} together, or neither (rigid roller)"
    fail(P["modulus2"] & ~P["poisson2"], "poisson2", pair,
         f"missing (needed with {label('modulus2')})")
    fail(P["poisson2"] & ~P["modulus2"], "modulus2", pair,
         f"missing (needed with {label('poisson2')})")

    # the load: exactly one of force and depth
    fail(P["load"] & P["depth"], "load",
         f"exactly one of {label('load')} (a force) or {label('depth')} (a length)",
         "given together with a depth",
         lambda i: f"{fail.cell('load', i)}/{fail.cell('depth', i)}")
    fail(~P["load"] & ~P["depth"], "load",
         f"exactly one of {label('load')} (a force) or {label('depth')} (a length)",
         "missing")
    given = np.where(P["load"], "load", "depth")
    value = np.where(P["load"], v["load"], v["depth"])
    v.update(radius=radius, given=given, value=value)

    # the features, in registration order
    for f in FEATURES:
        state = f.resolve(v, P, fail)
        if state is not None:
            cases.states[f.name] = state
    _positive_loads(cases, fail)
    radius_eff_f = np.full(n, np.nan)
    modulus_f = np.full(n, np.nan)
    for _, st in cases.active():
        r = getattr(st, "radius_eff", None)
        if r is not None:
            radius_eff_f = np.where(np.isnan(radius_eff_f), r, radius_eff_f)
        m = getattr(st, "modulus", None)
        if m is not None:
            modulus_f = np.where(np.isnan(modulus_f), m, modulus_f)
    by_feature = ~np.isnan(modulus_f)

    fail(~P["estar"] & ~P["modulus"] & ~by_feature, "modulus",
         f"a modulus > 0 (e.g. 210GPa), or {label('estar')}", "missing")
    fail(~P["estar"] & P["modulus"] & ~P["poisson"], "poisson",
         bounds_of(BY_NAME["poisson"])[1], f"missing (needed with {label('modulus')})")

    # the second body
    with np.errstate(divide="ignore", invalid="ignore"):
        r2 = np.where(P["radius2"], v["radius2"], np.inf)
        inv = 1 / radius + 1 / r2
        radius_eff = np.where(P["radius2"], 1 / inv, radius)
        # a concave second body must be larger than the roller (else they conform)
        bad_r2 = P["radius2"] & ~(inv > 0)
    fail(bad_r2 & (v["radius2"] == 0), "radius2",
         f"a length != 0; negative (concave) only with |{label('radius2')}| > roller radius",
         "zero")
    fail(bad_r2 & (v["radius2"] != 0), "radius2",
         f"|{label('radius2')}| > roller radius for a concave second body",
         "the roller does not fit inside the concave body")
    radius_eff = np.where(np.isnan(radius_eff_f), radius_eff, radius_eff_f)

    ok = np.fromiter(map(operator.not_, errors), dtype=bool, count=n)
    estar = np.full(n, np.nan)
    direct = ok & P["estar"]
    estar[direct] = v["estar"][direct]
    eq3 = ok & ~P["estar"]
    if eq3.any():
        from ..classical import effective_modulus

        e2 = np.where(P["modulus2"], v["modulus2"], np.inf)[eq3]
        nu2 = np.where(P["poisson2"], v["poisson2"], 0.0)[eq3]
        e1 = np.where(by_feature, modulus_f, v["modulus"])[eq3]
        estar[eq3] = effective_modulus(e1, v["poisson"][eq3], e2, nu2)
    # the self-similar scales every model works in must be normal doubles (the one
    # rule of linecontact.models, checked here per row before any model is built)
    from ..models import SCALES_HINT, SCALES_VALID, scales_are_normal

    fail(ok & ~scales_are_normal(radius_eff, v["length"], estar), "length",
         SCALES_VALID + "; R the effective radius", SCALES_HINT)
    cases.radius, cases.radius_eff, cases.estar = radius, radius_eff, estar
    cases.length = v["length"]
    cases.given, cases.value = given, value
    v.update(radius_eff=radius_eff, estar=estar)


def _positive_loads(cases, fail):
    """The core's rule: a load or depth > 0, except in the rows a feature's State marks
    ``signed`` (it gives F <= 0 or d <= 0 a meaning: an adhesive contact under a tensile
    load); the refusal names the options that would allow it (the features' ``signed``
    module attribute)."""
    from .._units import _range_reason, _valid_text

    v, P, label = cases.values, cases.present, fail.label
    signed = np.zeros(cases.n, bool)
    for _, st in cases.active():
        s = getattr(st, "signed", None)
        if s is not None:
            signed |= np.asarray(s, dtype=bool)
    allow = [label(nm) for f in FEATURES for nm in getattr(f, "signed", ())]
    for name in _SIGNED_LOADS:
        kind = BY_NAME[name].kind
        with np.errstate(invalid="ignore"):
            bad = np.flatnonzero(P[name] & ~(v[name] > 0) & ~np.isnan(v[name]) & ~signed)
        valid = _valid_text(kind, True, None) + (
            f"; zero or negative only with {' or '.join(allow)}" if allow else "")
        for i in bad:
            mask = np.zeros(cases.n, bool)
            mask[i] = True
            fail(mask, name, valid, _range_reason(float(v[name][i]), kind, True, None))


#: Units tried, in order, to bring an implausible bare number into its range.
_SUGGEST = {"length": ("mm", "um", "cm"), "pressure": ("GPa", "MPa", "kPa"),
            "force": ("kN", "N", "MN")}


def likely_cause(cases, i, kinds=None):
    """'' or '; likely cause: ...' naming the inputs of row i typed as a BARE number
    whose SI value is implausible for its quantity (Parameter.plausible), with the
    unit that would make it plausible: a case that fails with ``--modulus 210`` (210
    Pa) is blamed on the modulus, not on the force the model then cannot carry.
    `kinds`: only inputs of these kinds (``{"length"}`` for a refused L/R), else all.

    Examples
    --------
    >>> cases, _, errors = parse_cases({"radius": ["5mm"], "length": ["10mm"],
    ...     "modulus": ["210"], "poisson": ["0.3"], "load": ["1kN"]}, 1)
    >>> likely_cause(cases, 0)
    "; likely cause: --modulus = '210' is 210 Pa (a bare number is SI), implausible for this quantity (1000 to 1e+13 Pa): 210GPa?"
    """
    import re

    from .._units import BUILTIN_UNITS, DIMENSIONS

    label = getattr(cases, "label", option_name)
    causes = []
    for p in PARAMETERS:
        if p.plausible is None or not cases.present[p.name][i]:
            continue
        if kinds is not None and p.kind not in kinds:
            continue
        col = cases.cells.get(p.name)
        if col is None or isinstance(col, np.ndarray):
            continue  # a sweep: typed with its own START/STOP
        text = str(col[i]).strip()
        if not re.fullmatch(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?", text):
            continue  # a unit was given: the user chose the magnitude
        v = abs(float(cases.values[p.name][i]))
        lo, hi = p.plausible
        if not v or lo <= v <= hi:
            continue
        si = DIMENSIONS[p.kind][1]
        hint = next((f"{text}{u}" for u in _SUGGEST.get(p.kind, ())
                     if lo <= v * BUILTIN_UNITS[p.kind][u] <= hi), "")
        causes.append(f"{label(p.name)} = {text!r} is {v:g} {si} (a bare number is SI), "
                      f"implausible for this quantity ({lo:g} to {hi:g} {si})"
                      + (f": {hint}?" if hint else ""))
    return "; likely cause: " + "; ".join(causes) if causes else ""
