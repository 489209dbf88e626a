"""Feature: a profiled and tilted roller (``--crown-radius``, ``--profile``, ``--tilt``).

``--crown-radius RC``
    A circular crown of radius Rc (drop x^2/(2 Rc)); the same as
    ``--profile circular:Rc=RC``.
``--profile NAME[:OPT=VAL,...]``
    A roller profile of :func:`linecontact.profiles.parse_profile`: ``iso16281``,
    ``lundberg``, ``johns-gohar``, ``circular``, ``end-relief``, ``straight`` or
    ``file:PATH.csv``. ``lundberg`` and ``johns-gohar`` take their design load F0 from
    ``F0=`` or, with ``--load``, from the load of the row.
``--tilt ANGLE``
    Tilt of the roller axis ("1mrad", "0.05deg", or radians): positive brings the +x
    end closer (:mod:`linecontact.roller`). Without it the roller is aligned
    (theta = 0).

With any of them the calculator prints, beside the straight-cylinder rows, the
profiled roller's rows: the coupled-slice model (:class:`linecontact.roller.ProfiledRoller`,
100 slices) and, for steel, ISO/TS 16281 slicing (:func:`linecontact.roller.iso_slicing`,
30 slices), each with force, depth, stiffness dF/dd, moment, tilt stiffness, peak
pressure and where it sits, contact length, and edge loading. The peak pressure of an
edge-loaded roller is not printed (singular on a half-space; a number would depend on
the slice width). ``--json`` adds the line load q(x) of every row.
"""
from __future__ import annotations

import math

import numpy as np

from ..feature import Block, Field, Parameter, State

__all__: list = []

name = "roller"
group = "profiled and tilted roller"

parameters = (
    Parameter("crown_radius", "length", "crown radius Rc of a circular crown, drop "
              "x^2/(2 Rc): adds the profiled-roller rows (coupled slices, ISO/TS 16281 "
              "slicing)", group),
    Parameter("profile", "text", "roller profile NAME[:OPT=VAL,...]: iso16281[:D=..], "
              "lundberg[:F0=..], johns-gohar[:F0=..], circular:Rc=.., end-relief:r=.. or "
              "end-relief:l=..,angle=.. (or drop=..), file:PATH.csv (x, drop in m)",
              group),
    Parameter("tilt", "angle", "tilt of the roller axis, e.g. 1mrad, 0.05deg (bare: rad); "
              "positive loads the +x end", group, positive=False),
)

NAMES = tuple(p.name for p in parameters)

NOTE = ("profiled roller: coupled slices (Hertz strips across, exact half-space "
        "coupling along the axis; linecontact.roller), 100 slices; M: moment about the "
        "roller centre; p max: peak pressure (not printed where the contact reaches a "
        "roller end: singular there on a half-space, 'edge'); ISO/TS 16281 slicing: "
        "uncoupled slices of the standard, steel only. Accuracy: docs/profiled_rollers.md.")

notes = {"profiled_roller": NOTE}

#: No columns in the main table: the profiled roller has its own rows (blocks).
fields: dict = {}

#: The quantities of a profiled-roller row (heading, SI unit, engineering unit).
ROW_FIELDS = {
    "force": Field("F", "N", "kN", 1e-3),
    "depth": Field("d", "m", "um", 1e6),
    "stiffness": Field("k", "N/m", "N/um", 1e-6),
    "moment": Field("M", "N m", "N m", 1.0),
    "tilt_stiffness": Field("k tilt", "N m/rad", "N m/mrad", 1e-3),
    "p_max": Field("p max", "Pa", "MPa", 1e-6),
    "x_at_p_max": Field("x(p max)", "m", "mm", 1e3),
    "contact_length": Field("contact", "m", "mm", 1e3),
}


def resolve(values, present, fail):
    """Rules of the profiled-roller inputs; the State holds per row the profile spec
    (``specs``: text, ("crown", Rc) or None) and the tilt [rad] (``tilts``, 0 where not
    given). The profile itself is built per row in :func:`blocks` (it may depend on the
    load)."""
    v, P, label = values, present, fail.label
    rows = P["crown_radius"] | P["profile"] | P["tilt"]
    if not rows.any():
        return None
    fail(P["crown_radius"] & P["profile"], "crown_radius",
         f"either {label('crown_radius')} or {label('profile')}, not both",
         f"conflicts with {label('profile')}")
    raceways = P["inner_raceway"] | P["outer_raceway"]
    for nm in NAMES:
        fail(P[nm] & raceways, nm, "one contact (without the raceways)",
             "not available for a whole roller")
    with np.errstate(invalid="ignore"):
        fail(P["tilt"] & ~(np.abs(v["tilt"]) < 0.1), "tilt", "(-0.1, 0.1) rad",
             "the roller models linearise the tilt (small angles)")
    tilts = np.where(P["tilt"], v["tilt"], 0.0)
    specs = [None] * len(rows)
    for i in np.flatnonzero(rows):
        if P["profile"][i]:
            specs[i] = v["profile"][i].strip()
        elif P["crown_radius"][i]:
            specs[i] = ("crown", float(v["crown_radius"][i]))
        else:
            specs[i] = "straight"
    return State(rows, specs=specs, tilts=tilts)


def columns(model, rows, normal, state):
    """No columns in the main table (the profiled roller has its own rows)."""
    return {}


def _profile(spec, R, L, E, force, diameter):
    from ...profiles import CircularCrownProfile, parse_profile

    if isinstance(spec, tuple):
        return CircularCrownProfile(L, spec[1])
    # R is the effective radius across the axis (against a raceway); the ISO/TS 16281
    # profile scales with the roller's own diameter D = 2 R1
    return parse_profile(spec, length=L, radius=R, estar=E, diameter=diameter,
                         design_force=force if np.isfinite(force) else None)


def blocks(state, results):
    """The profiled-roller rows (see :func:`_solve`), numpy's floating-point warnings
    off: an overflow or a strip of zero width on the way (a load or crown beyond the
    slicing's resolution) ends in the one-line message of that row (a ConvergenceError
    or a range error), and the warnings would only add lines to stderr."""
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        return _solve(state, results)


def _solve(state, results):
    """The profiled-roller rows of every good row with a profile input: two blocks
    ("coupled slices" and "ISO/TS 16281 slicing"), rows of
    :class:`linecontact.roller.RollerSolution` (None where not computed)."""
    from ..._units import InputError, range_error_parts
    from ...roller import ProfiledRoller, iso_slicing
    from ...validity import OutOfRangeError

    cases, errors = results.cases, results.errors
    label = results.label
    n = len(errors)
    coupled = {"label": [""] * n, "rows": [None] * n, "notes": [""] * n}
    iso = {"label": [""] * n, "rows": [None] * n, "notes": [""] * n}
    rollers = {}
    any_row = False
    for i in np.flatnonzero(state.rows):
        if errors[i]:
            continue
        R, L, E = (float(a[i]) for a in (cases.radius_eff, cases.length, cases.estar))
        given = str(cases.given[i])
        value = float(cases.value[i])
        force = value if given == "load" else math.nan
        tilt = float(state.tilts[i])
        spec = state.specs[i]
        try:
            prof = _profile(spec, R, L, E, force, 2 * float(cases.radius[i]))
        except OutOfRangeError as exc:  # the spec or its file: one line naming the option
            option, typed = ((label("crown_radius"), f"{spec[1]:.6g} m")
                             if isinstance(spec, tuple) else (label("profile"), spec))
            valid, reason = range_error_parts(exc)
            if exc.parameter == "profile":  # the spec itself: no 'profile = X' twice
                reason = exc.hint or "not a profile"
            elif exc.parameter == "design_force":  # lundberg/johns-gohar under --depth
                reason += f" (give F0=.. in the spec, or {label('load')})"
            errors[i] = str(InputError(option, typed, valid, reason))
            continue
        any_row = True
        key = (prof.label, R, L, E)
        if key not in rollers:
            rollers[key] = ProfiledRoller(R, L, E, prof, n_slices=100)
        roller = rollers[key]
        tilt_text = f", tilt {tilt * 1e3:.4g} mrad" if tilt else ""
        coupled["label"][i] = f"Profiled roller ({prof.label}{tilt_text})"
        iso["label"][i] = f"ISO/TS 16281 slicing ({prof.label}{tilt_text})"
        try:
            coupled["rows"][i] = (roller.at_force(value, tilt=tilt) if given == "load"
                                  else roller.at_depth(value, tilt))
        except Exception as exc:  # noqa: BLE001 - said in one line, never a traceback
            msg = _failure(exc, coupled["label"][i])
            if n == 1:          # one case: its one-line error (a sweep notes the row)
                errors[i] = msg
                continue
            coupled["notes"][i] = msg
        try:
            kw = {"force": value} if given == "load" else {"depth": value}
            iso["rows"][i] = iso_slicing(R, L, E, prof, tilt=tilt, **kw)
        except Exception as exc:  # noqa: BLE001 - said in the row's note
            iso["notes"][i] = _failure(exc, iso["label"][i])
    if not any_row:
        return []
    return [_block("profiled", coupled, True), _block("iso", iso, False)]


def _failure(exc, label):
    """One line for a row the roller solver refused (its range), could not solve (a
    ConvergenceError: said, never hidden, e.g. a crown so strong that the contact is
    narrower than the slices) or failed on unexpectedly (named, as a batch row's
    unexpected exception in linecontact.compute)."""
    from ...roller import ConvergenceError
    from ...validity import OutOfRangeError

    if isinstance(exc, OutOfRangeError):
        return str(exc)
    detail = (str(exc).strip().splitlines() or [""])[0]
    if isinstance(exc, ConvergenceError):
        return f"{label}: not computed: {detail}"
    return f"{label}: unexpected {type(exc).__name__}" + (f": {detail}" if detail else "")


def _edge_text(sol):
    if sol is None:
        return "-"
    return {"both": "both ends", "-x": "-x end", "+x": "+x end"}.get(sol.edge, "no")


def _block(key, b, coupled):
    """A :class:`~linecontact.calc.feature.Block` of solutions: the numbers (moment and
    x(p max) rounding noise of a symmetric case printed as 0), the edge, the note."""
    rows, json_rows = [], []
    for sol, note, lab in zip(b["rows"], b["notes"], b["label"]):
        if sol is None:
            rows.append(None if not note else {"label": lab, "note": note, "text": {}})
            json_rows.append({"note": note})
            continue
        row = {"label": lab}
        for c in ROW_FIELDS:
            val = getattr(sol, c)
            if val is not None and c in ("moment", "x_at_p_max"):
                scale_ = (abs(sol.force) if c == "moment" else 1.0) * (sol.x[-1] - sol.x[0])
                if abs(val) < 1e-9 * scale_:
                    val = 0.0
            row[c] = val
        text = note
        if sol.edge_loaded and coupled:
            text = "; ".join(t for t in ("p max: singular at the loaded end", note) if t)
        elif not sol.p_max_resolved:
            text = "; ".join(t for t in ("p max: not converged (a peak narrower than "
                                         "the slices)", note) if t)
        if sol.notes:
            text = "; ".join([text] + list(sol.notes)) if text else "; ".join(sol.notes)
        row["text"] = {"edge": _edge_text(sol)}
        row["note"] = text
        rows.append(row)
        json_rows.append(_json_row(sol, note))
    return Block(name="profiled_roller", key=key, label="profiled roller",
                 fields=ROW_FIELDS, rows=rows, text_columns=("edge",),
                 json_rows=json_rows, note=NOTE,
                 units={c: ROW_FIELDS[c].si for c in ROW_FIELDS} | {"x": "m", "q": "N/m",
                                                                    "tilt": "rad"})


def _json_row(sol, note):
    """A profiled-roller row for ``--json`` (SI), with q(x)."""
    def num(x):
        return None if x is None or not math.isfinite(float(x)) else float(x)

    row = {c: num(getattr(sol, c)) for c in ROW_FIELDS}
    row.update(tilt=sol.tilt, tilt_stiffness=num(sol.tilt_stiffness),
               stiffness_matrix=[[float(v) for v in r] for r in sol.stiffness_matrix],
               contact_start=sol.contact_start, contact_end=sol.contact_end,
               edge_loaded=bool(sol.edge_loaded), edge=sol.edge,
               p_max_resolved=bool(sol.p_max_resolved), message=sol.message,
               method=sol.method, n_slices=sol.n_slices,
               x=[float(x) for x in sol.x], q=[float(q) for q in sol.q],
               notes=list(sol.notes), note=note)
    return row
