"""The calculator's profiled-roller inputs and rows (``linecontact calc``, issue 9).

Inputs (declared in :data:`linecontact.cases.PARAMETERS`, group "profiled and tilted
roller"):

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

Not combined: the profile options with the raceways (a whole roller), in a batch (CSV
of cases: refused with a message, one case or a sweep only).
"""
from __future__ import annotations

import math

import numpy as np

from .compute import FIELDS as _FIELDS
from .compute import Field
from .render import _num, aligned

__all__: list = []

NAMES = ("crown_radius", "profile", "tilt")

NOTE = ("profiled roller: coupled slices (Hertz strips across, exact half-space "
        "coupling along the axis; linecontact.roller), 100 slices; M: moment about the "
        "roller centre; p max: peak pressure (not printed where the contact reaches a "
        "roller end: singular there on a half-space, 'edge'); ISO/TS 16281 slicing: "
        "uncoupled slices of the standard, steel only. Accuracy: docs/profiled_rollers.md.")

#: Row quantities: name -> :class:`linecontact.compute.Field` (heading, SI unit,
#: engineering unit, factor SI -> eng); F, d and k as in the straight rows.
FIELDS = {
    **{k: _FIELDS[k] for k in ("force", "depth", "stiffness")},
    "moment": Field("M", "N m", "N m", 1.0),
    "tilt_stiffness": Field("k tilt", "N m/rad", "N m/mrad", 1e-3),
    "p_max": Field("p max", "Pa", "MPa", 1e-6),
    "x_at_p_max": Field("x(p max)", "m", "mm", 1e3),
    "contact_length": Field("contact", "m", "mm", 1e3),
}


def resolve(v, P, raw, fail, label, n):
    """Rules of the profiled-roller inputs; returns (rows, profiles, tilts).

    `rows`: bool array of rows with a profiled roller; `profiles`: per row the profile
    spec text (or None); `tilts`: per row the tilt [rad] (0 where not given). The
    profile itself is built per row in :func:`solve` (it may depend on the load).
    """
    from .profiles import parse_angle
    from .validity import OutOfRangeError

    given = P["crown_radius"] | P["profile"] | P["tilt"]
    batch = not label("profile").startswith("--")
    for name in NAMES:
        fail(P[name] & batch, name, "one case or a sweep on the command line",
             "profiled rollers are not computed in a batch", lambda i, nm=name: raw[nm][i])
    fail(P["crown_radius"] & P["profile"], "crown_radius",
         f"either {label('crown_radius')} or {label('profile')}, not both",
         f"conflicts with {label('profile')}", lambda i: raw["crown_radius"][i])
    raceways = P["inner_raceway"] | P["outer_raceway"]
    for name in NAMES:
        fail(P[name] & raceways, name, "one contact (without the raceways)",
             "not available for a whole roller", lambda i, nm=name: raw[nm][i])
    tilts = np.zeros(n)
    for i in np.flatnonzero(P["tilt"]):
        try:
            tilts[i] = parse_angle(raw["tilt"][i], parameter=label("tilt"))
        except OutOfRangeError as exc:
            fail(np.arange(n) == i, "tilt", exc.valid, exc.hint or "not an angle",
                 lambda k: raw["tilt"][k])
    specs = [None] * n
    for i in np.flatnonzero(given):
        if P["profile"][i]:
            specs[i] = raw["profile"][i].strip()
        elif P["crown_radius"][i]:
            specs[i] = ("crown", float(v["crown_radius"][i]))
        else:
            specs[i] = "straight"
    return given, specs, tilts


def _profile(spec, R, L, E, force, diameter):
    from .profiles import CircularCrownProfile, parse_profile

    if isinstance(spec, tuple):
        return CircularCrownProfile(L, spec[1])
    # R is the effective radius across the axis (against a raceway); the ISO/TS 16281
    # profile scales with the roller's own diameter D = 2 R1
    return parse_profile(spec, length=L, radius=R, estar=E, diameter=diameter,
                         design_force=force if np.isfinite(force) else None)


def solve(cases, errors):
    """The profiled-roller rows (see :func:`_solve`), numpy's floating-point warnings
    off: an overflow or a strip of zero width on the way (a load or crown beyond the
    slicing's resolution) ends in the one-line message of that row (a ConvergenceError
    or a range error), and the warnings would only add lines to stderr."""
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        return _solve(cases, errors)


def _solve(cases, errors):
    """The profiled-roller rows of every good row with a profile input.

    Returns a list of blocks, one per model ("coupled slices", "ISO/TS 16281
    slicing"), each a dict with ``label`` and ``rows`` (one per case row: a
    :class:`linecontact.roller.RollerSolution` or None) and ``notes`` (per row).
    """
    rows = cases.get("_roller_rows")
    if rows is None or not np.any(rows):
        return []          # no profile flags: linecontact.roller is not imported
    from ._units import InputError, range_error_parts
    from .cases import option_name as label
    from .roller import ProfiledRoller, iso_slicing
    from .validity import OutOfRangeError, UnknownNameError

    n = len(errors)
    coupled = {"label": "", "rows": [None] * n, "notes": [""] * n}
    iso = {"label": "", "rows": [None] * n, "notes": [""] * n}
    rollers = {}
    for i in np.flatnonzero(rows):
        if errors[i]:
            continue
        R, L, E = (float(cases[k][i]) for k in ("radius_eff", "length", "estar"))
        given = str(cases["given"][i])
        value = float(cases["value"][i])
        force = value if given == "load" else math.nan
        tilt = float(cases["_roller_tilt"][i])
        spec = cases["_roller_spec"][i]
        try:
            prof = _profile(spec, R, L, E, force, 2 * float(cases["radius"][i]))
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
        except UnknownNameError as exc:  # an unknown profile or option name
            option, typed = label("profile"), spec
            reason = ("not a profile" if exc.parameter == "profile"
                      else f"unknown {exc.parameter} {exc.value!r}")
            errors[i] = str(InputError(option, typed, "one of " + ", ".join(exc.valid),
                                       reason))
            continue
        key = (prof.label, R, L, E)
        if key not in rollers:
            rollers[key] = ProfiledRoller(R, L, E, prof, n_slices=100)
        roller = rollers[key]
        tilt_text = f", tilt {tilt * 1e3:.4g} mrad" if tilt else ""
        coupled["label"] = f"Profiled roller ({prof.label}{tilt_text})"
        iso["label"] = f"ISO/TS 16281 slicing ({prof.label}{tilt_text})"
        try:
            coupled["rows"][i] = (roller.at_force(value, tilt=tilt) if given == "load"
                                  else roller.at_depth(value, tilt))
        except Exception as exc:  # noqa: BLE001 - said in one line, never a traceback
            msg = _failure(exc, coupled["label"])
            if n == 1:          # one case: its one-line error (a sweep notes the row)
                errors[i] = msg
                continue
            coupled["notes"][i] = msg
        try:
            kw = {"force": value} if given == "load" else {"depth": value}
            iso["rows"][i] = iso_slicing(R, L, E, prof, tilt=tilt, **kw)
        except Exception as exc:  # noqa: BLE001 - said in the row's note
            iso["notes"][i] = _failure(exc, iso["label"])
    return [b for b in (coupled, iso) if b["label"]]


def _failure(exc, label):
    """One line for a row the roller solver refused (its range), could not solve (a
    ConvergenceError: said, never hidden, e.g. a crown so strong that the contact is
    narrower than the slices) or failed on unexpectedly (named, as a batch row's
    unexpected exception in linecontact.compute)."""
    from .roller import ConvergenceError
    from .validity import OutOfRangeError

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


def table_text(blocks, given, si):
    """The profiled-roller rows as a plain-text table (after the straight rows)."""
    if not blocks:
        return ""
    first = "force" if given == "load" else "depth"
    cols = [first] + [c for c in FIELDS if c != first]
    header = ["profiled roller"] + [
        f"{FIELDS[c].heading} [{FIELDS[c].si if si else FIELDS[c].eng}]" for c in cols
    ] + ["edge", "note"]
    table = []
    for b in blocks:
        for sol, note in zip(b["rows"], b["notes"]):
            cells = [b["label"]]
            for c in cols:
                val = None if sol is None else getattr(sol, c)
                if val is not None and c in ("moment", "x_at_p_max"):
                    # rounding noise of a symmetric case prints as 0
                    scale_ = (abs(sol.force) if c == "moment" else 1.0) * (sol.x[-1] - sol.x[0])
                    if abs(val) < 1e-9 * scale_:
                        val = 0.0
                if val is None:
                    cells.append("-")
                else:
                    cells.append(f"{val if si else val * FIELDS[c].factor:.4g}")
            text = note
            if sol is not None and sol.edge_loaded and b["label"].startswith("Profiled"):
                text = "; ".join(t for t in ("p max: singular at the loaded end", note) if t)
            elif sol is not None and not sol.p_max_resolved:
                text = "; ".join(t for t in ("p max: not converged (a peak narrower than "
                                             "the slices)", note) if t)
            if sol is not None and sol.notes:
                text = "; ".join([text] + list(sol.notes)) if text else "; ".join(sol.notes)
            table.append(cells + [_edge_text(sol), text])
    lines = [""] + aligned([header] + table)
    lines += ["", "Note: " + NOTE]
    return "\n".join(lines) + "\n"


def json_blocks(blocks):
    """The profiled-roller rows for ``--json`` (SI), with q(x) of every row."""
    out = []
    for b in blocks:
        rows = []
        for sol, note in zip(b["rows"], b["notes"]):
            if sol is None:
                rows.append({"note": note})
                continue
            row = {c: _num(getattr(sol, c)) for c in FIELDS}
            row.update(tilt=sol.tilt, tilt_stiffness=_num(sol.tilt_stiffness),
                       stiffness_matrix=[[float(v) for v in r] for r in sol.stiffness_matrix],
                       contact_start=sol.contact_start, contact_end=sol.contact_end,
                       edge_loaded=bool(sol.edge_loaded), edge=sol.edge,
                       p_max_resolved=bool(sol.p_max_resolved), message=sol.message,
                       method=sol.method, n_slices=sol.n_slices,
                       x=[float(x) for x in sol.x], q=[float(q) for q in sol.q],
                       notes=list(sol.notes), note=note)
            rows.append(row)
        out.append({"label": b["label"], "rows": rows,
                    "units": {c: FIELDS[c].si for c in FIELDS} | {"x": "m", "q": "N/m",
                                                                  "tilt": "rad"}})
    return out
