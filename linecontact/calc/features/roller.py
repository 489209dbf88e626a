"""Feature: a profiled and tilted roller (``--crown-radius``, ``--profile``, ``--tilt``).

``--crown-radius RC``
    A circular crown of radius Rc (drop x^2/(2 Rc)); the same as
    ``--profile circular:Rc=RC``.
``--profile NAME[:OPT=VAL,...]``
    A roller profile of :func:`linecontact.profiles.parse_profile`: ``iso16281``,
    ``lundberg``, ``johns-gohar``, ``circular``, ``end-relief``, ``straight`` or
    ``file:PATH.csv``. ``lundberg`` and ``johns-gohar`` take their design load F0 from
    ``F0=`` or, with ``--load``, from the load of the row.
``--tilt ANGLE`` or ``--tilt free``
    Tilt of the roller axis ("1mrad", "0.05deg", or radians): positive brings the +x
    end closer (:mod:`linecontact.roller`). Without it the roller is aligned
    (theta = 0), as in :class:`linecontact.contact.Roller`; ``free``: the tilt at which
    the moment about the roller's centre vanishes (between raceways: the moments of its
    two contacts balance).

With any of them the contact is the library's composed contact
(:class:`linecontact.contact.Contact` with a :class:`~linecontact.contact.Roller` of
that profile and tilt): its models are the coupled-slice model (``profiled-roller``,
50 slices) and, for steel, ISO 16281 slicing (``iso16281-slicing``, 30 slices), and
a straight-cylinder law named with ``--model`` is refused for it. Every other feature
composes with it: the tangential law is the profiled contact's own (from its F(d)), the
raceways carry the profiled roller on both contacts. Columns: moment, tilt, tilt
stiffness, peak pressure and where it sits, contact length, and edge loading in the
note; ``--json`` adds the line load q(x) of every row. The peak pressure of an
edge-loaded roller is not printed (singular on a half-space).
"""
from __future__ import annotations

import math

import numpy as np

from ..feature import Block, Field, Parameter, State, keep

__all__: list = []

name = "roller"
group = "profiled and tilted roller"

parameters = (
    Parameter("crown_radius", "length", "crown radius Rc of a circular crown, drop "
              "x^2/(2 Rc): the contact becomes the profiled roller's (coupled slices, "
              "ISO 16281 slicing)", group),
    Parameter("profile", "text", "roller profile NAME[:OPT=VAL,...]: iso16281[:D=..], "
              "lundberg[:F0=..], johns-gohar[:F0=..], circular:Rc=.., end-relief:r=.. or "
              "end-relief:l=..,angle=.. (or drop=..), file:PATH.csv (x, drop in m)",
              group),
    Parameter("tilt", "angle", "tilt of the roller axis, e.g. 1mrad, 0.05deg (bare: rad), "
              "positive loads the +x end; 'free': moment equilibrium; default 0 "
              "(aligned), free between raceways", group, positive=False, words=("free",)),
)

NOTE = ("profiled roller: coupled slices (Hertz strips across, exact half-space "
        "coupling along the axis; linecontact.roller), 50 slices graded towards the "
        "contact's ends; d: the depth at the roller's centre x = 0 (negative "
        "where a tilt lifts the centre off; the row's note then gives the approach "
        "from first contact); M: moment about the roller centre; p max: peak pressure "
        "(not printed where the contact reaches a roller end: singular there on a "
        "half-space; the row's note names the end); ISO 16281 slicing: uncoupled "
        "slices of the standard, steel only. Accuracy: docs/profiled_rollers.md.")

notes = {"profiled_roller": NOTE}

#: The columns of a profiled or tilted roller.
fields = {
    "tilt": Field("tilt", "rad", "mrad", 1e3),
    "moment": Field("M", "N m", "N m", 1.0),
    "tilt_stiffness": Field("k tilt", "N m/rad", "N m/mrad", 1e-3),
    "p_max": Field("p max", "Pa", "MPa", 1e-6),
    "x_at_p_max": Field("x(p max)", "m", "mm", 1e3),
    "contact_length": Field("contact", "m", "mm", 1e3),
}

#: The quantities of a profiled-roller row in ``--json`` (with q(x)).
ROW_FIELDS = {
    "force": Field("F", "N", "kN", 1e-3),
    "depth": Field("d", "m", "um", 1e6),
    "stiffness": Field("k", "N/m", "N/um", 1e-6),
    **{k: fields[k] for k in ("moment", "tilt_stiffness", "p_max", "x_at_p_max",
                              "contact_length")},
}

#: The default models of a profiled or tilted roller (linecontact.raceway.SLICE_MODELS).
MODELS = ("profiled-roller", "iso16281-slicing")


def resolve(values, present, fail):
    """Rules of the profiled-roller inputs; the State's ``parts(i)`` are the Roller
    keywords of row i (profile, crown radius, tilt) and ``models`` its default set."""
    v, P, label = values, present, fail.label
    rows = P["crown_radius"] | P["profile"] | P["tilt"]
    if not rows.any():
        return None
    fail(P["crown_radius"] & P["profile"], "crown_radius",
         f"either {label('crown_radius')} or {label('profile')}, not both",
         f"conflicts with {label('profile')}")
    free = np.array([bool(P["tilt"][i]) and fail.cell("tilt", i).strip().lower() == "free"
                     for i in range(len(rows))], dtype=bool)
    # between raceways the roller tilts freely unless --tilt is given, as in
    # linecontact bearing (the raceways feature's row note says so)
    free |= ~P["tilt"] & np.any([P[k] for k in ("inner_raceway", "outer_raceway",
                                                 "inner_raceway_diameter",
                                                 "outer_raceway_diameter")], axis=0)
    with np.errstate(invalid="ignore"):
        fail(P["tilt"] & ~free & ~(np.abs(v["tilt"]) < 0.1), "tilt", "(-0.1, 0.1) rad, "
             "or free", "the roller models linearise the tilt (small angles)")
    _check_profiles(v, P, fail)
    state = State(rows, tilt=np.where(P["tilt"] & ~free, v["tilt"], 0.0), free=free,
                  crown=np.where(P["crown_radius"], v["crown_radius"], np.nan),
                  profile=list(v["profile"]), load=np.where(P["load"], v["load"], np.nan),
                  models=MODELS)
    state.parts = lambda i: _parts(state, i)
    return state


def _check_profiles(v, P, fail):
    """Each distinct --profile read once (linecontact.profiles.parse_profile, with the
    row's roller and load): a spec or file the library refuses is one line naming the
    option and the spec as typed."""
    from ..._units import range_error_parts
    from ...errors import OutOfRangeError, UnknownNameError
    from ...profiles import parse_profile

    label = fail.label
    seen = {}
    n = len(P["profile"])
    for i in np.flatnonzero(P["profile"]):
        spec = v["profile"][i].strip()
        R, L = float(v["radius"][i]), float(v["length"][i])
        force = float(v["load"][i]) if P["load"][i] else None
        key = (spec, R, L, force)
        if key not in seen:
            seen[key] = None
            if np.isfinite(R) and np.isfinite(L) and R > 0 and L > 0:
                try:
                    parse_profile(spec, length=L, radius=R, estar=1e11, diameter=2 * R,
                                  design_force=force)
                except UnknownNameError as exc:  # an unknown profile or option name
                    seen[key] = ("one of " + ", ".join(exc.valid),
                                 "not a profile" if exc.parameter == "profile"
                                 else f"unknown {exc.parameter} {exc.value!r}")
                except OutOfRangeError as exc:
                    valid, reason = range_error_parts(exc)
                    if exc.parameter == "profile":  # the spec itself
                        reason = exc.hint or "not a profile"
                    elif exc.parameter == "design_force":  # lundberg under --depth
                        reason += f" (give F0=.. in the spec, or {label('load')})"
                    seen[key] = (valid, reason)
        if seen[key] is not None:
            fail(np.arange(n) == i, "profile", *seen[key])


def _parts(state, i):
    """The Roller keywords of row i: a design force F0 from the row's load for the
    profiles that need one (lundberg, johns-gohar) when the spec has none."""
    parts = {"tilt": "free" if state.free[i] else float(state.tilt[i])}
    if np.isfinite(state.crown[i]):
        parts["crown_radius"] = float(state.crown[i])
    spec = state.profile[i].strip()
    if spec:
        name = spec.split(":")[0].strip().lower()
        if (name in ("lundberg", "johns-gohar") and "f0=" not in spec.lower()
                and np.isfinite(state.load[i])):
            spec += ("," if ":" in spec else ":") + f"F0={float(state.load[i])!r}"
        parts["profile"] = spec
    return parts


def columns(model, rows, normal, state):
    """The roller's own quantities from its solution: moment, tilt, tilt stiffness (the
    library's), peak pressure, where it sits and the contact length (one contact; the
    larger of the two contacts' peaks between raceways), edge loading in the flags."""
    keep(state, rows, model)
    n = len(rows)
    out = {k: np.full(n, np.nan) for k in fields}
    for k in ("tilt", "moment", "tilt_stiffness"):
        out[k] = normal[k]
    flags = [""] * n
    for j, sol in enumerate(normal["solution"]):
        if sol is None:
            continue
        if hasattr(sol, "peak_pressure_inner"):   # between raceways
            peaks = [p for p in (sol.peak_pressure_inner, sol.peak_pressure_outer)
                     if p is not None]
            if len(peaks) == 2:
                out["p_max"][j] = max(peaks)
            continue
        if sol.p_max is not None and not sol.edge_loaded:
            out["p_max"][j] = sol.p_max
        out["x_at_p_max"][j] = _clean(sol.x_at_p_max, sol)
        out["contact_length"][j] = sol.contact_length
        text = _depth_text(model, sol)
        if sol.edge_loaded:
            text.append(f"edge loaded ({_edge_text(sol)}): p max singular there")
        elif not sol.p_max_resolved:
            text.append("p max: not converged (a peak narrower than the slices)")
        text += list(sol.notes)
        flags[j] = "; ".join(text)
    out["moment"] = np.array([_clean(m, s) if s is not None and not hasattr(
        s, "peak_pressure_inner") else m for m, s in zip(out["moment"], normal["solution"])])
    out["flags"] = flags
    return out


def _depth_text(model, sol):
    """[what d means] where the depth at the roller's centre is not the approach from
    first contact (a tilt brings an end closer: d0 = Contact.first_contact_depth < 0,
    and d < 0 when the contact lies at one end), with that approach d - d0."""
    contact = getattr(model, "contact", None)
    if contact is None or not callable(getattr(contact, "first_contact_depth", None)):
        return []
    d0 = contact.first_contact_depth(sol.tilt)
    if not d0 < -1e-9 * abs(sol.depth):   # first contact at the centre: d is the approach
        return []
    return [f"d: the depth at the roller's centre x = 0 (tilted: first contact nearer "
            f"an end, at d0 = {d0 * 1e6:.4g} um); the approach from first contact d - d0 "
            f"= {(sol.depth - d0) * 1e6:.4g} um"]


def _clean(value, sol):
    """Rounding noise of a symmetric case (a moment or an x of 1e-12 of the scale)
    printed as 0."""
    if value is None or not np.isfinite(value):
        return np.nan if value is None else value
    scale_ = max(abs(sol.force), 1.0) * (sol.x[-1] - sol.x[0])
    return 0.0 if abs(value) < 1e-9 * scale_ else value


def blocks(state, results):
    """``--json``: the line load q(x) of every profiled row of the first model set
    (one block; no table: the columns are in the main table)."""
    sols = results.sets[0]["solution"] if results.sets else []
    json_rows = []
    for i, sol in enumerate(sols):
        if not state.rows[i] or sol is None or hasattr(sol, "peak_pressure_inner"):
            json_rows.append(None)
            continue
        json_rows.append(_json_row(sol, ""))
    if not any(r is not None for r in json_rows):
        return []
    return [Block(name="profiled_roller", key="profiled", label=str(results.sets[0]["label"][
        int(np.flatnonzero(state.rows)[0])]), fields={}, rows=[None] * len(json_rows),
        json_rows=json_rows, note=NOTE,
        units={c: ROW_FIELDS[c].si for c in ROW_FIELDS} | {"x": "m", "q": "N/m",
                                                           "width": "m",
                                                           "tilt": "rad"})]


#: Loads drawn at most in one q(x) figure (a longer sweep: evenly chosen, said).
MAX_CURVES = 8


def figure(state, results):
    """``--plot``: q(x) of the first model set's profiled rows with the roller's ends,
    above its profile drop and each row's rigid approach
    (:func:`linecontact.plot.profiled_roller`); rows of another roller (length or
    profile) and a roller between raceways are said, not drawn."""
    from functools import partial

    from ... import plot

    sols = results.sets[0]["solution"] if results.sets else []
    kept = getattr(state, "kept", None)
    rows = [i for i in np.flatnonzero(state.rows)
            if i < len(sols) and sols[i] is not None and kept is not None
            and kept[i] is not None and getattr(kept[i], "contact", None) is not None
            and not hasattr(sols[i], "peak_pressure_inner")]
    if not rows:
        return []
    c0 = kept[rows[0]].contact

    def same(c):
        return c.roller.length == c0.roller.length and c.profile == c0.profile

    mine = [i for i in rows if same(kept[i].contact)]
    said = []
    if len(rows) > len(mine):
        said.append(f"--plot: q(x) drawn for the roller of the first row; "
                    f"{len(rows) - len(mine)} row(s) of other rollers are in --json")
    if len(mine) > MAX_CURVES:
        pick = np.unique(np.round(np.linspace(0, len(mine) - 1, MAX_CURVES)).astype(int))
        said.append(f"--plot: q(x) of {len(pick)} of the {len(mine)} profiled rows "
                    "(evenly chosen; every row is in --json)")
        mine = [mine[k] for k in pick]
    return [partial(plot.profiled_roller, [sols[i] for i in mine], c0)] + said


def _edge_text(sol):
    if sol is None:
        return "-"
    return {"both": "both ends", "-x": "-x end", "+x": "+x end"}.get(sol.edge, "no")


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
               width=(None if getattr(sol, "width", None) is None
                      else [float(w) for w in sol.width]),
               notes=list(sol.notes), note=note)
    return row
