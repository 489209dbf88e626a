"""The calculator's inputs: parameters (command-line options = CSV columns), and their
conversion into checked SI arrays, one element per case.

Every input of ``linecontact calc`` is a :class:`Parameter` in :data:`PARAMETERS`,
grouped as in ``--help``. The same declaration gives the option ``--NAME`` (``_``
written ``-``), the CSV column ``NAME`` (case-insensitive) and the parsing rule of its
kind (:mod:`linecontact._units`: a number with one unit name). :func:`parse_cases`
converts a table of cells (one case per row; the one-case command is a table of one
row, a sweep a table of N rows) into SI arrays and one error message per bad row, by
column (the unit rules and the per-unit factors are applied once per column).

Adding a group of options (profiled rollers, tangential load, ...)
    1. Append :class:`Parameter` entries with a new ``group`` title to
       :data:`PARAMETERS`: they appear in ``--help``, are accepted as options and as
       CSV columns, and arrive parsed (SI float arrays, NaN where absent) in the
       ``cases`` dict of :func:`parse_cases`, with ``present[NAME]`` saying where given.
    2. If they constrain each other, add the rule to :func:`_resolve` (a mask of the
       offending rows and one message; the first error of a row wins).
    3. Read them in :mod:`linecontact.compute` (see its docstring for output columns).

Geometry
    ``--radius`` R1 or ``--diameter`` D = 2 R1 of the roller; ``--radius2`` R2 of the
    second body at the contact (negative for a concave one, e.g. an outer raceway),
    giving the effective radius 1/R = 1/R1 + 1/R2 of two parallel cylinders (Hertz;
    Johnson 1985, Sec. 4.2) that every model uses; without it the second body is flat.
    ``--inner-raceway`` Ri and ``--outer-raceway`` Ro (both > 0, the outer one
    concave) describe a whole roller between two raceways: two contacts in series,
    with 1/R = 1/R1 + 1/Ri and 1/R = 1/R1 - 1/Ro (see :mod:`linecontact.compute`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._units import InputError, parse_column


__all__ = ["Parameter", "PARAMETERS", "BY_NAME", "RAW_KINDS", "parse_cases", "option_name",
           "bounds_of"]

#: Kinds of :class:`Parameter` that :func:`parse_cases` does not parse: their cells are
#: kept as typed and checked where they are used (a profile spec, a file path, a tilt).
RAW_KINDS = ("path", "text", "angle")


@dataclass(frozen=True)
class Parameter:
    """One input of the calculator: an option ``--NAME`` and a CSV column ``NAME``.

    Parameters
    ----------
    name : str
        Column name (``_`` becomes ``-`` in the option).
    kind : str
        A kind of :data:`linecontact._units.DIMENSIONS` (``length``, ``force``,
        ``pressure``, ``dimensionless``, ``time``), parsed here to SI floats; or
        ``text``, ``path`` or ``angle``, not parsed here (``present`` marks where given;
        the code that uses them reads the raw cells and checks them, e.g. the tilt in
        :mod:`linecontact.calc_roller`).
    help : str
        One line for ``--help``.
    group : str
        Title of its ``--help`` section.
    positive : bool
        Values must be > 0 (otherwise any finite number, e.g. a concave radius < 0).
    bounds : str, optional
        Name of a :mod:`linecontact.validity` Interval that the value must lie in
        (its ``describe()`` is the valid range in messages).
    sweep : bool
        May be a sweep ``START:STOP:N`` on the command line (one case).
    """

    name: str
    kind: str
    help: str
    group: str
    positive: bool = True
    bounds: str | None = None
    sweep: bool = False


_CYL = "cylinder (roller)"
_BODY = "second body and materials"
_LOAD = "load (exactly one)"
_RACE = "whole roller between two raceways (instead of --radius2)"
_TAN = "tangential contact (one contact; see linecontact.calc_tangential)"
_VISCO = "viscoelastic second body (instead of --modulus; creep)"
_PROFILE = "profiled and tilted roller (one contact; see linecontact.calc_roller)"

#: Every input, in ``--help`` order.
PARAMETERS = (
    Parameter("radius", "length", "roller radius R1", _CYL),
    Parameter("diameter", "length", "roller diameter D = 2 R1 (instead of --radius)", _CYL),
    Parameter("length", "length", "roller length L", _CYL),
    Parameter("radius2", "length", "radius R2 of the second body at the contact, negative "
              "if concave (e.g. a raceway bore): 1/R = 1/R1 + 1/R2; default: flat", _BODY,
              positive=False),
    Parameter("modulus", "pressure", "Young's modulus E1 of the second body "
              "(the half-space)", _BODY),
    Parameter("poisson", "dimensionless", "Poisson's ratio nu1 of the second body", _BODY,
              bounds="POISSON_RATIO"),
    Parameter("modulus2", "pressure", "Young's modulus E2 of the roller "
              "(default: rigid)", _BODY),
    Parameter("poisson2", "dimensionless", "Poisson's ratio nu2 of the roller", _BODY,
              bounds="POISSON_RATIO"),
    Parameter("estar", "pressure", "effective modulus E* of Eq. 3 (instead of the moduli)",
              _BODY),
    Parameter("load", "force", "normal force F per contact, or a sweep START:STOP:N", _LOAD,
              sweep=True),
    Parameter("depth", "length", "indentation depth d of one contact (rigid-body "
              "approach), or a sweep START:STOP:N", _LOAD, sweep=True),
    Parameter("inner_raceway", "length", "radius Ri of the inner raceway (convex)", _RACE),
    Parameter("outer_raceway", "length", "radius Ro of the outer raceway (concave; "
              "give it positive)", _RACE),
    Parameter("friction", "dimensionless", "Coulomb friction coefficient mu: adds the "
              "full-stick tangential stiffness across and along the axis (BEM) and the "
              "MDR's", _TAN),
    Parameter("tangential_load", "force", "tangential force Q at constant normal load, or a "
              "sweep START:STOP:N: the shift and the slip state (needs --friction)", _TAN,
              sweep=True),
    Parameter("instantaneous_modulus", "pressure", "instantaneous Young's modulus E0 of a "
              "standard linear solid", _VISCO),
    Parameter("long_term_modulus", "pressure", "long-term Young's modulus E_inf < E0",
              _VISCO),
    Parameter("relaxation_time", "time", "relaxation time tau (at constant strain)",
              _VISCO),
    Parameter("prony", "path", "Prony series of the Young's modulus: a CSV file with "
              "columns tau_s, E_Pa and a line '# E_inf: VALUE' (instead of the three "
              "above)", _VISCO),
    Parameter("time", "time", "time t the load has been held, or a sweep START:STOP:N: "
              "the creep depth d(t) (with --load)", _VISCO, positive=False, sweep=True),
    Parameter("crown_radius", "length", "crown radius Rc of a circular crown, drop "
              "x^2/(2 Rc): adds the profiled-roller rows (coupled slices, ISO/TS 16281 "
              "slicing)", _PROFILE),
    Parameter("profile", "text", "roller profile NAME[:OPT=VAL,...]: iso16281[:D=..], "
              "lundberg[:F0=..], johns-gohar[:F0=..], circular:Rc=.., end-relief:r=.. or "
              "end-relief:l=..,angle=.. (or drop=..), file:PATH.csv (x, drop in m)",
              _PROFILE),
    Parameter("tilt", "angle", "tilt of the roller axis, e.g. 1mrad, 0.05deg (bare: rad); "
              "positive loads the +x end", _PROFILE, positive=False),
)

BY_NAME = {p.name: p for p in PARAMETERS}


def option_name(name):
    """``inner_raceway`` -> ``--inner-raceway``."""
    return "--" + name.replace("_", "-")


def bounds_of(p):
    """(inside, description) of a Parameter's validity Interval, or None."""
    if p.bounds is None:
        return None
    from . import validity

    iv = getattr(validity, p.bounds)
    return (iv.contains, iv.describe())


def parse_cases(cells, n, label=option_name):
    """Convert a table of cells into SI arrays, one element per case.

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
    cases : dict
        Name -> float array [SI] (NaN where not given or refused), plus ``radius``
        (R1, from the radius or the diameter), ``radius_eff`` (1/R = 1/R1 + 1/R2, or
        R1), ``estar`` [Pa], ``given`` (array of 'load'/'depth'), ``value`` (the load
        [N] or the depth [m]) and ``raceways`` (bool array).
    present : dict
        Name -> bool array: the cell was given.
    errors : list of str
        ``""`` for a good row, else the first problem of that row (one line: the
        parameter, the value as typed, the valid range).
    """
    errors = [""] * n
    values, present, raw = {}, {}, {}
    for p in PARAMETERS:
        col = cells.get(p.name)
        if col is None:
            values[p.name] = np.full(n, np.nan)
            present[p.name] = np.zeros(n, bool)
            raw[p.name] = [""] * n
            continue
        if isinstance(col, np.ndarray) and col.dtype.kind == "f":
            values[p.name] = col.astype(float)
            present[p.name] = ~np.isnan(col)
            raw[p.name] = [repr(float(v)) for v in col] if n <= 10 else None
            continue
        if n and type(col[0]) is not str:  # cells as read are str; others converted
            col = ["" if c is None else str(c) for c in col]
        raw[p.name] = col
        if p.kind in RAW_KINDS:  # read where it is used (raw cells)
            present[p.name] = np.array([c.strip() != "" for c in col], dtype=bool)
            values[p.name] = np.full(n, np.nan)
            continue
        # distinct cells only: a batch repeats its cylinders (and its empty cells)
        if n and col.count(col[0]) == n:  # one value for all rows (e.g. the modulus)
            uniq, inv = [col[0]], np.zeros(n, dtype=np.intp)
        else:
            where = {}
            inv = np.fromiter((where.setdefault(c, len(where)) for c in col),
                              dtype=np.intp, count=n)
            uniq = list(where)
        u_given = np.array([c.strip() != "" for c in uniq], dtype=bool)
        u_values = np.full(len(uniq), np.nan)
        u_errors = [""] * len(uniq)
        gi = np.flatnonzero(u_given)
        if gi.size:
            parsed, errs = parse_column(label(p.name), [uniq[i] for i in gi], p.kind,
                                        positive=p.positive, bounds=bounds_of(p))
            u_values[gi] = parsed
            for i, e in zip(gi, errs):
                u_errors[i] = e
        present[p.name] = u_given[inv]
        values[p.name] = u_values[inv]
        bad = [i for i, e in enumerate(u_errors) if e]
        if bad:
            for j in np.flatnonzero(np.isin(inv, bad)):
                if not errors[j]:
                    errors[j] = u_errors[inv[j]]
    cases = _resolve(values, present, raw, errors, n, label)
    return cases, present, errors


def _resolve(v, present, raw, errors, n, label):
    """Rules between parameters; each sets the first error of its offending rows."""

    def cell(name, i):
        col = raw.get(name)
        if col is None:
            return repr(float(v[name][i]))
        return col[i]

    def fail(mask, name, valid, reason, value=lambda i: ""):
        for i in np.flatnonzero(mask):
            if not errors[i]:
                errors[i] = str(InputError(label(name), value(i), valid, reason))

    P = present
    # roller radius: --radius or --diameter
    fail(P["radius"] & P["diameter"], "diameter",
         f"either {label('radius')} or {label('diameter')}, not both",
         f"conflicts with {label('radius')}", lambda i: cell("diameter", i))
    fail(~P["radius"] & ~P["diameter"], "radius",
         f"a length > 0 (e.g. 5mm), or {label('diameter')}", "missing")
    radius = np.where(P["radius"], v["radius"], v["diameter"] / 2)
    fail(~P["length"], "length", "a length > 0 (e.g. 10mm)", "missing")

    # materials: E* directly, or Eq. 3 from the moduli
    elastic = ("modulus", "poisson", "modulus2", "poisson2")
    for name in elastic:
        fail(P["estar"] & P[name], name,
             f"either {label('estar')} or the moduli and Poisson's ratios, not both",
             f"conflicts with {label('estar')}", lambda i, nm=name: cell(nm, i))
    nu_range = bounds_of(BY_NAME["poisson"])[1]
    from .calc_tangential import resolve as _resolve_tangential

    visco, E0, materials = _resolve_tangential(v, P, raw, fail, label, n)
    fail(~P["estar"] & ~P["modulus"] & ~visco, "modulus",
         f"a modulus > 0 (e.g. 210GPa), or {label('estar')}", "missing")
    fail(~P["estar"] & P["modulus"] & ~P["poisson"], "poisson", nu_range,
         f"missing (needed with {label('modulus')})")
    pair = f"{label('modulus2')} and {label('poisson2')} together, or neither (rigid roller)"
    fail(P["modulus2"] & ~P["poisson2"], "poisson2", pair,
         f"missing (needed with {label('modulus2')})")
    fail(P["poisson2"] & ~P["modulus2"], "modulus2", pair,
         f"missing (needed with {label('poisson2')})")

    # the load: exactly one of force and depth
    fail(P["load"] & P["depth"], "load",
         f"exactly one of {label('load')} (a force) or {label('depth')} (a length)",
         "given together with a depth", lambda i: f"{cell('load', i)}/{cell('depth', i)}")
    fail(~P["load"] & ~P["depth"], "load",
         f"exactly one of {label('load')} (a force) or {label('depth')} (a length)",
         "missing")

    # geometry of the second body(ies)
    raceways = P["inner_raceway"] | P["outer_raceway"]
    both = f"{label('inner_raceway')} and {label('outer_raceway')} together"
    fail(P["inner_raceway"] & ~P["outer_raceway"], "outer_raceway", both,
         f"missing (needed with {label('inner_raceway')})")
    fail(P["outer_raceway"] & ~P["inner_raceway"], "inner_raceway", both,
         f"missing (needed with {label('outer_raceway')})")
    fail(raceways & P["radius2"], "radius2",
         f"either {label('radius2')} (one contact) or the raceways (a whole roller)",
         "conflicts with the raceways", lambda i: cell("radius2", i))
    fail(raceways & P["depth"], "depth",
         f"{label('load')} with the raceways (the two contacts share the force)",
         "a depth cannot be split between two contacts", lambda i: cell("depth", i))
    with np.errstate(divide="ignore", invalid="ignore"):
        r2 = np.where(P["radius2"], v["radius2"], np.inf)
        inv = 1 / radius + 1 / r2
        radius_eff = np.where(P["radius2"], 1 / inv, radius)
        # a concave second body must be larger than the roller (else they conform)
        bad_r2 = P["radius2"] & ~(inv > 0)
    fail(bad_r2 & (v["radius2"] == 0), "radius2",
         f"a length != 0; negative (concave) only with |{label('radius2')}| > roller radius",
         "zero", lambda i: cell("radius2", i))
    fail(bad_r2 & (v["radius2"] != 0), "radius2",
         f"|{label('radius2')}| > roller radius for a concave second body",
         "the roller does not fit inside the concave body", lambda i: cell("radius2", i))
    with np.errstate(divide="ignore", invalid="ignore"):
        outer_ok = v["outer_raceway"] > radius
    fail(raceways & P["outer_raceway"] & ~outer_ok, "outer_raceway",
         f"{label('outer_raceway')} > roller radius",
         "the roller does not fit inside the outer raceway",
         lambda i: cell("outer_raceway", i))

    ok = np.array([not e for e in errors], dtype=bool)
    estar = np.full(n, np.nan)
    direct = ok & P["estar"]
    estar[direct] = v["estar"][direct]
    eq3 = ok & ~P["estar"]
    if eq3.any():
        from .classical import effective_modulus

        e2 = np.where(P["modulus2"], v["modulus2"], np.inf)[eq3]
        nu2 = np.where(P["poisson2"], v["poisson2"], 0.0)[eq3]
        e1 = np.where(visco, E0, v["modulus"])[eq3]   # viscoelastic: instantaneous E0
        estar[eq3] = effective_modulus(e1, v["poisson"][eq3], e2, nu2)
    # the self-similar scales every model works in must be normal doubles (the one
    # rule of linecontact.models, checked here per row before any model is built)
    from .models import SCALES_HINT, SCALES_VALID, scales_are_normal

    fail(ok & ~scales_are_normal(radius_eff, v["length"], estar), "length",
         SCALES_VALID + "; R the effective radius", SCALES_HINT,
         lambda i: cell("length", i))
    from .calc_roller import resolve as _resolve_roller

    roller_rows, roller_specs, roller_tilts = _resolve_roller(v, P, raw, fail, label, n)
    given = np.where(P["load"], "load", "depth")
    value = np.where(P["load"], v["load"], v["depth"])
    cases = dict(v)
    cases.update(_roller_rows=roller_rows, _roller_spec=roller_specs,
                 _roller_tilt=roller_tilts)
    cases.update(radius=radius, radius_eff=radius_eff, estar=estar, given=given,
                 value=value, raceways=raceways, material=materials, _present=present)
    return cases
