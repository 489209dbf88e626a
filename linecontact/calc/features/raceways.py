"""Feature: a whole roller between two raceways (``--inner-raceway``,
``--outer-raceway``, or their diameters; ``--misalignment``).

The roller and its two contacts are :func:`linecontact.raceway.roller_between_raceways`
(through :class:`linecontact.contact.Contact` with :class:`~linecontact.raceway.Raceways`):
the force F [N] passes through the inner contact (1/R = 1/R1 + 1/Ri) and the outer one
(1/R = 1/R1 - 1/Ro) in series, the roller deflection (ring approach) is the sum of their
depths and its stiffness the series value, for any contact law; a profiled or tilted
roller (``--crown-radius``, ``--profile``, ``--tilt``, ``--tilt free`` for moment
equilibrium) is solved by coupled slices on both contacts. A pair of raceways that does
not fit the roller (Ro - Ri not the roller diameter within 1 %) is refused with the
numbers.
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, keep

__all__: list = []

name = "raceways"
group = "whole roller between two raceways (instead of --radius2)"

parameters = (
    Parameter("inner_raceway", "length", "radius Ri of the inner raceway (convex)", group),
    Parameter("outer_raceway", "length", "radius Ro of the outer raceway (concave; "
              "give it positive)", group),
    Parameter("inner_raceway_diameter", "length", "diameter 2 Ri of the inner raceway "
              "(as data sheets give it; instead of --inner-raceway)", group),
    Parameter("outer_raceway_diameter", "length", "diameter 2 Ro of the outer raceway "
              "(instead of --outer-raceway)", group),
    Parameter("misalignment", "angle", "tilt of the outer ring against the inner ring "
              "in the roller's plane, e.g. 0.5mrad (needs a profiled or tilted roller "
              "model: coupled slices)", group, positive=False),
)

fields = {
    "roller_deflection": Field("delta roller", "m", "um", 1e6),
    "roller_stiffness": Field("k roller", "N/m", "N/um", 1e-6),
    "depth_inner": Field("d inner", "m", "um", 1e6),
    "depth_outer": Field("d outer", "m", "um", 1e6),
    "peak_pressure_inner": Field("p inner", "Pa", "MPa", 1e-6),
    "peak_pressure_outer": Field("p outer", "Pa", "MPa", 1e-6),
    "clearance": Field("clearance", "m", "um", 1e6),
}

notes = {
    "roller": "whole roller (linecontact.raceway): roller_deflection = d(inner contact) + "
              "d(outer contact) at the same force (the ring approach at the roller's "
              "centre), roller_stiffness the two contacts in series; depth_inner and "
              "depth_outer are the two contacts' own depths; p inner/outer: Hertz p0 of "
              "each strip for a law, the slice model's peak for a profiled roller; "
              "clearance: Ro - Ri - 2 R1.",
}


#: The default models where the library solves the roller by slices (misaligned
#: rings): the roller feature's (linecontact.raceway.SLICE_MODELS).
SLICE_DEFAULTS = ("profiled-roller", "iso16281-slicing")
#: The row's note of a straight roller between misaligned rings.
SLICED_NOTE = ("straight roller between misaligned raceways: solved by coupled slices "
               "(a straight-cylinder law has no tilt), as linecontact bearing does")
#: The row's note of a profiled roller between raceways without a tilt given.
FREE_NOTE = ("roller between raceways: its tilt is free (moment equilibrium), as in "
             "linecontact bearing; give {tilt} to hold it")


def resolve(values, present, fail):
    """Each raceway as a radius or a diameter, both or neither; not with --radius2; the
    pair must fit the roller (linecontact.raceway.check_fit)."""
    from ...errors import CombinationError
    from ...raceway import check_fit

    P, v, label = present, values, fail.label
    given = {s: P[f"{s}_raceway"] | P[f"{s}_raceway_diameter"] for s in ("inner", "outer")}
    rows = given["inner"] | given["outer"] | P["misalignment"]
    if not rows.any():
        return None
    radii = {}
    for side in ("inner", "outer"):
        r, d = f"{side}_raceway", f"{side}_raceway_diameter"
        fail(P[r] & P[d], d, f"either {label(r)} or {label(d)}, not both",
             f"conflicts with {label(r)}")
        radii[side] = np.where(P[r], v[r], v[d] / 2)
    both = (f"{label('inner_raceway')} and {label('outer_raceway')} (or their diameters) "
            "together")
    fail(given["inner"] & ~given["outer"], "outer_raceway", both,
         f"missing (needed with {label('inner_raceway')})")
    fail(given["outer"] & ~given["inner"], "inner_raceway", both,
         f"missing (needed with {label('outer_raceway')})")
    fail(P["misalignment"] & ~(given["inner"] & given["outer"]), "misalignment", both,
         "no raceways given")
    fail(rows & P["radius2"], "radius2",
         f"either {label('radius2')} (one contact) or the raceways (a whole roller)",
         "conflicts with the raceways")
    with np.errstate(invalid="ignore"):
        fail(P["misalignment"] & ~(np.abs(v["misalignment"]) < 0.1), "misalignment",
             "(-0.1, 0.1) rad", "the roller models linearise the tilt (small angles)")
    from ...raceway import effective_radius

    R1 = v["radius"]
    for i in np.flatnonzero(given["inner"] & given["outer"]):
        try:
            check_fit(float(R1[i]), float(radii["inner"][i]), float(radii["outer"][i]))
        except CombinationError as exc:  # the library's reason, said for the options
            name = "outer_raceway" if P["outer_raceway"][i] else "outer_raceway_diameter"
            fail(np.arange(len(rows)) == i, name,
                 f"{label('outer_raceway')} - {label('inner_raceway')} = the roller "
                 "diameter 2 R1 (+ a radial clearance within 1 % of it)", exc.reason)
        except ValueError:
            pass  # a value out of range: its own message comes from the core
    with np.errstate(invalid="ignore", divide="ignore"):
        r_in = effective_radius(R1, radii["inner"])
    psi = np.where(P["misalignment"], v["misalignment"], 0.0)
    shaped = P["crown_radius"] | P["profile"]
    # as linecontact bearing: a straight roller between misaligned rings is solved by
    # coupled slices (the library's default there; a straight-cylinder law has no
    # tilt), and a profiled roller tilts freely unless --tilt is given (the roller
    # feature's default between raceways); each row says so in its note
    with np.errstate(invalid="ignore"):
        sliced = rows & (psi != 0) & ~shaped & ~P["tilt"]
    state = State(rows, radius_eff=np.where(rows, r_in, np.nan), whole=rows,
                  compared="roller_deflection", inner=radii["inner"], outer=radii["outer"],
                  # the slice models' columns only where a row needs them (the
                  # default set of every row otherwise: the standard laws)
                  psi=psi, models=SLICE_DEFAULTS if sliced.any() else None,
                  said=[SLICED_NOTE if sliced[i] else FREE_NOTE.format(tilt=label("tilt"))
                        if shaped[i] and not P["tilt"][i] else "" for i in range(len(rows))])
    state.parts = lambda i: _parts(state, i)
    return state


def _parts(state, i):
    from ...raceway import Raceways

    return {"counterbody": Raceways(float(state.inner[i]), float(state.outer[i]),
                                    misalignment=float(state.psi[i]))}


def columns(model, rows, normal, state):
    """The whole roller's columns from its solution (linecontact.raceway.RacewaySolution)."""
    keep(state, rows, model)
    n = len(rows)
    out = {k: np.full(n, np.nan) for k in fields}
    out["roller_deflection"] = normal["depth"]
    out["roller_stiffness"] = normal["stiffness"]
    flags = [""] * n
    for j, sol in enumerate(normal["solution"]):
        if sol is None:
            continue
        flags[j] = state.said[rows[j]]
        out["depth_inner"][j] = sol.depth_inner
        out["depth_outer"][j] = sol.depth_outer
        for side in ("inner", "outer"):
            p = getattr(sol, f"peak_pressure_{side}")
            if p is not None:
                out[f"peak_pressure_{side}"][j] = p
            else:
                flags[j] = "; ".join(t for t in (flags[j], f"p {side}: singular at the "
                                                 "loaded end (edge loading)") if t)
        # Ro - Ri - 2 R1 of a pair that fits exactly: rounding noise printed as 0
        out["clearance"][j] = 0.0 if abs(sol.clearance) < 1e-9 * sol.radius_outer \
            else sol.clearance
        if sol.notes:
            flags[j] = "; ".join([t for t in (flags[j],) if t] + list(sol.notes))
        geometry = _geometry_flags(model.contact, sol, float(normal["force"][j]))
        if geometry:
            flags[j] = "; ".join(t for t in (flags[j], geometry) if t)
    out["flags"] = flags
    return out


#: Loads drawn at most in one q(x) band (a longer sweep: evenly chosen, said).
MAX_CURVES = 8


def figure(state, results):
    """``--plot``: a roller between raceways solved by slices: q(x) of its inner and of
    its outer contact (:func:`linecontact.plot.line_load` of the solution's ``inner``
    and ``outer``, the roller's ends marked), the first roller's rows; under a law
    (no slices) there is no q(x): said."""
    from functools import partial

    from ... import plot

    sols = results.sets[0]["solution"] if results.sets else []
    kept = getattr(state, "kept", None)
    rows = [i for i in np.flatnonzero(state.rows) if i < len(sols) and sols[i] is not None
            and kept is not None and kept[i] is not None]
    if not rows:
        return []
    sliced = [i for i in rows if getattr(sols[i], "inner", None) is not None]
    if not sliced:
        return ["--plot: a roller between raceways under a law has no q(x) (no slices); "
                "its deflection and each contact's depth and pressure are in the table"]
    c0 = kept[sliced[0]].contact
    mine = [i for i in sliced if kept[i].contact is c0]
    said = ["--plot: a roller between raceways: q(x) of the inner contact, then of the "
            "outer"]
    if len(rows) > len(mine):
        said.append(f"--plot: q(x) drawn for the roller of the first row; "
                    f"{len(rows) - len(mine)} row(s) of other rollers are in the table")
    if len(mine) > MAX_CURVES:
        pick = np.unique(np.round(np.linspace(0, len(mine) - 1, MAX_CURVES)).astype(int))
        said.append(f"--plot: q(x) of {len(pick)} of the {len(mine)} rows (evenly chosen)")
        mine = [mine[k] for k in pick]
    def draw(side, fig=None):
        made = plot.line_load([getattr(sols[i], side) for i in mine], c0, fig=fig)
        ax = (fig if fig is not None else made).axes[0]
        ax.set_title(f"{side} contact: {ax.get_title()}", fontsize=9)
        return made

    return [partial(draw, side) for side in ("inner", "outer")] + said[1:]


def _geometry_flags(contact, sol, force):
    """The geometry flags of each of the two contacts, as a plain contact's row has
    them (:func:`linecontact.calc.feature.flag_text`): d > 0.15 R of the contact's
    effective radius, and b > L/2 with b the Hertz half-width of its strip (Li & Popov
    2017, Eq. 1) at the roller's load."""
    from ...classical import hertz_half_width
    from ..feature import flag_text

    L = contact.roller.length
    estar = getattr(contact, "estar", None)
    parts = []
    for side in ("inner", "outer"):
        R = float(getattr(sol, f"radius_{side}"))
        try:
            b = float(hertz_half_width(force, R, L, estar))
        except (TypeError, ValueError):  # no E* (a viscoelastic body) or no force
            b = np.nan
        parts.append(flag_text(float(getattr(sol, f"depth_{side}")), b, R, L,
                               where=f" ({side})"))
    return "; ".join(t for t in parts if t)


def blocks(state, results):
    """No extra table."""
    return []
