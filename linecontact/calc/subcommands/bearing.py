"""Subcommand ``linecontact bearing``: a radial cylindrical or needle roller bearing, one
bearing, a sweep or a CSV of bearings (a :class:`~linecontact.calc.feature.Subcommand`).

Its inputs are :data:`parameters` (each an option ``--NAME`` and a CSV column ``NAME``);
the roller length and the materials are the very parameters of ``linecontact calc``
(:data:`linecontact.calc.cases.CORE`): here ``--modulus``/``--poisson`` are the rings and
``--modulus2``/``--poisson2`` the rollers (default: the rings' material), or
``--estar``; none of them: steel on steel. The case-hardening check of the most loaded
roller takes the options of ``calc --stresses`` (``--surface-hardness``,
``--case-depth``, ``--core-hardness`` or ``--hardness-profile``).

All physics is the library's: :class:`linecontact.bearing.RadialRollerBearing` for the
bearing, and for the case check its most loaded roller between the same raceways at
its load (:func:`linecontact.raceway.roller_between_raceways`, the per-roller
reference, with the bearing's model, profile and slices; the roller free to tilt
under the rings' misalignment at its azimuth), each contact's stresses
(:func:`linecontact.stresses.roller_stresses`, or the strip under a law) and
:func:`linecontact.stresses.case_check`: the same solve ``linecontact calc
--inner-raceway ... --outer-raceway ... --load Q_max --stresses yes`` makes. This module
reads, asks and names.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..cases import BY_NAME as _CALC
from ..feature import Block, Field, Parameter, State
from ..features.stresses import HARDNESS, case_of_contacts, contact_stresses, hardness_of
from ..features.stresses import min_case_depth as _min_case_depth

__all__: list = []

name = "bearing"
help = "load distribution, stiffness and rating life of a radial roller bearing"
description = ("Load distribution over the rollers, ring displacement, radial stiffness, "
               "load zone, peak pressure, subsurface stresses and rating lives (ISO 281, "
               "ISO 16281) of a radial cylindrical or needle roller bearing under a "
               "radial load (and a tilting moment or a misalignment), with the "
               "case-hardening check of the most loaded roller. A value is a number "
               "with one unit name ('70mm', '10kN'); bare numbers are SI.")
epilog = ("Sweeps: --NAME START:STOP:N (any numeric option) gives N bearings, spaced "
          "geometrically (--linear: evenly); two sweeps give the grid. Batch: FILE.csv "
          "with one bearing per row, columns named like the options (pitch_diameter "
          "for --pitch-diameter); results are appended as columns, user columns are "
          "kept. Exit status 2 on bad input or when any row failed.")

_GEOM = "bearing geometry"
_LOAD = "load"
_MAT = "materials (rings: --modulus/--poisson; rollers: --modulus2/--poisson2)"
_MODEL = "contact model"
_CASE = "case-hardening check of the most loaded roller"

#: The bearing's inputs: option ``--NAME`` = CSV column ``NAME``.
parameters = (
    Parameter("rollers", "dimensionless", "number of rollers Z (>= 3)", _GEOM),
    Parameter("pitch_diameter", "length", "pitch diameter d_m", _GEOM),
    Parameter("roller_diameter", "length", "roller diameter D", _GEOM),
    _CALC["length"],
    Parameter("clearance", "length", "radial internal clearance P_d = d_o - d_i - 2D "
              "(negative: preload; default 0)", _GEOM, positive=False),
    Parameter("radial_load", "force", "radial load F_r", _LOAD),
    Parameter("tilting_moment", "moment", "tilting moment M on the inner ring about the "
              "axis normal to the load plane (e.g. 20Nm): the ring tilt is solved; the "
              "rollers by slices, free to tilt", _LOAD, positive=False),
    Parameter("misalignment", "angle", "given tilt of the inner ring against the outer "
              "ring in the load plane (e.g. 1mrad, 0.05deg; positive: the rings close at "
              "+x on the loaded side), instead of --tilting-moment", _LOAD,
              positive=False),
    replace(_CALC["modulus"], help="Young's modulus of the rings (with --poisson; "
            "default: steel, E* = 115.38 GPa)", group=_MAT),
    replace(_CALC["poisson"], help="Poisson's ratio of the rings (also of the von Mises "
            "stress; default 0.3)", group=_MAT),
    replace(_CALC["modulus2"], help="Young's modulus of the rollers (default: the "
            "rings')", group=_MAT),
    replace(_CALC["poisson2"], help="Poisson's ratio of the rollers (default: the "
            "rings')", group=_MAT),
    replace(_CALC["estar"], group=_MAT),
    Parameter("profile", "text", "roller profile spec (e.g. circular:Rc=500mm, "
              "iso16281, lundberg); default straight", _MODEL),
    Parameter("model", "text", "contact law of each contact: universal (default for a "
              "straight roller), iso16281 (the ISO spring), profiled-roller (default "
              "for a profile), iso16281-slicing, any key of linecontact calc", _MODEL),
    Parameter("n_slices", "dimensionless", "slices of a slice model (default: the "
              "bearing's, linecontact.bearing.RadialRollerBearing)", _MODEL),
    Parameter("rating", "force", "basic dynamic load rating C_r (default: ISO 281 "
              "from the geometry)", _MODEL),
) + tuple(Parameter(p.name, p.kind, p.help, _CASE, p.positive, p.bounds, p.sweep,
                    p.plausible, p.words) for p in HARDNESS)

#: Output quantities of one bearing: heading, SI unit, engineering unit, factor.
fields = {
    "displacement": Field("delta_r", "m", "um", 1e6),
    "radial_stiffness": Field("K_rr", "N/m", "N/um", 1e-6),
    "tilt": Field("ring tilt theta", "rad", "mrad", 1e3),
    "moment": Field("moment M", "N m", "N m", 1.0),
    "stiffness_rt": Field("K_rt = dF_r/dtheta", "N/rad", "N/mrad", 1e-3),
    "stiffness_tr": Field("K_tr = dM/d delta_r", "N", "N m/um", 1e-6),
    "stiffness_tt": Field("K_tt = dM/dtheta", "N m/rad", "N m/mrad", 1e-3),
    "max_roller_load": Field("Q_max", "N", "N", 1.0),
    "load_zone": Field("load zone psi_l", "rad", "deg", 180 / math.pi),
    "loaded_rollers": Field("loaded", "count", "count", 1.0),
    "peak_pressure": Field("p_max", "Pa", "MPa", 1e-6),
    "rating": Field("C_r", "N", "kN", 1e-3),
    "life_iso281": Field("L10 ISO 281", "1e6 rev", "1e6 rev", 1.0),
    "life_iso16281": Field("L10r ISO 16281", "1e6 rev", "1e6 rev", 1.0),
    "tresca": Field("max Tresca shear", "Pa", "MPa", 1e-6),
    "tresca_depth": Field("  at depth", "m", "um", 1e6),
    "von_mises": Field("max von Mises", "Pa", "MPa", 1e-6),
    "von_mises_depth": Field("  at depth", "m", "um", 1e6),
    "orthogonal_shear": Field("max orthogonal shear", "Pa", "MPa", 1e-6),
    "orthogonal_shear_depth": Field("  at depth", "m", "um", 1e6),
    "case_ratio": Field("vM/allow (case check)", "-", "-", 1.0),
    "case_ratio_depth": Field("  at depth", "m", "um", 1e6),
    "min_case_depth": Field("CHD min", "m", "mm", 1e3),
}

#: Fields shown in one case's list only where computed (asked for by their options).
optional = ("case_ratio", "case_ratio_depth", "min_case_depth")

notes = {
    "clearance": "P_d is the radial internal clearance (ISO 5753-1), Harris' diametral "
                 "clearance d_o - d_i - 2D; roller j's approach is delta_r cos psi_j - "
                 "P_d/2.",
    "life": "L10 = (C_r/F_r)^(10/3) (ISO 281:2007); L10r: ISO 16281:2025 (ISO/TS "
            "16281:2008) lamina method on the lamina loads, exponent 4 of line contact "
            "(docs/iso16281.md).",
    "tilt": "with --tilting-moment or --misalignment each roller is solved by slices "
            "(profiled-roller for a straight roller with no --model), free to tilt "
            "between its rings; the ring sees theta cos psi_j at roller j. K_rt, K_tr, "
            "K_tt: the 2x2 stiffness d(F_r, M)/d(delta_r, theta), slice models only.",
    "stress": "subsurface stress: the most loaded roller, the worst of its two contacts "
              "(linecontact.stresses), no traction: under a slice model one Hertz strip "
              "per slice, the worst 3D-corrected (measured error in the notes below); "
              "under a law the plane-strain Hertz strip at the mean line load Q/L; von "
              "Mises with the rings' Poisson's ratio (0.3 if not given).",
    "case": "case check (--surface-hardness, --case-depth, --core-hardness or "
            "--hardness-profile): the most loaded roller between the same raceways at "
            "Q_max (linecontact.raceway.roller_between_raceways, free to tilt under the "
            "rings' misalignment at its azimuth), each contact's von Mises over the "
            "yield strength 2.876 HV - 90.7 MPa (Pavlina & Van Tyne 2008, "
            "linecontact.stresses.case_check), the worse contact named; CHD min: the "
            "smallest effective case depth that carries both contacts.",
}

_REQUIRED = ("rollers", "pitch_diameter", "roller_diameter", "length", "radial_load")
_STEEL_ESTAR = 115.38e9  # steel on steel, 210 GPa and 0.3 each (the library's default)


def resolve(values, present, fail):
    """The rules: the geometry and load given; E* or the moduli, not both (the rollers
    default to the rings' material); a moment or a misalignment, not both; the
    case-check inputs complete."""
    from ...classical import effective_modulus

    v, P, label = values, present, fail.label
    n = len(P["rollers"])
    for nm in _REQUIRED:
        fail(~P[nm], nm, f"a value (e.g. {_EXAMPLES[nm]})", "missing")
    for nm in ("modulus", "poisson", "modulus2", "poisson2"):
        fail(P["estar"] & P[nm], nm,
             f"either {label('estar')} or the moduli and Poisson's ratios, not both",
             f"conflicts with {label('estar')}")
    fail(~P["modulus"] & (P["modulus2"] | P["poisson2"]), "modulus",
         f"the rings' {label('modulus')} and {label('poisson')} with the rollers'",
         f"missing (needed with {label('modulus2')})")
    fail(P["modulus"] & ~P["poisson"], "poisson", "0 <= nu <= 0.5",
         f"missing (needed with {label('modulus')})")
    fail(P["tilting_moment"] & P["misalignment"], "misalignment",
         f"either {label('tilting_moment')} or {label('misalignment')} (the moment a "
         "misalignment needs is an output)", f"conflicts with {label('tilting_moment')}")
    estar = np.full(n, _STEEL_ESTAR)
    estar = np.where(P["estar"], v["estar"], estar)
    moduli = P["modulus"] & P["poisson"] & ~P["estar"]
    if moduli.any():
        e2 = np.where(P["modulus2"], v["modulus2"], v["modulus"])
        nu2 = np.where(P["poisson2"], v["poisson2"], v["poisson"])
        with np.errstate(invalid="ignore", divide="ignore"):
            estar = np.where(moduli, effective_modulus(
                np.where(moduli, v["modulus"], 1.0), np.where(moduli, v["poisson"], 0.3),
                np.where(moduli, e2, 1.0), np.where(moduli, nu2, 0.3)), estar)
    for nm in ("rollers", "n_slices"):  # counts: a whole number, never rounded
        with np.errstate(invalid="ignore"):
            fail(P[nm] & (v[nm] != np.round(v[nm])), nm, "a whole number",
                 "not a whole number")
    hardness = hardness_of(v, P, fail, np.ones(n, bool))
    return State(np.ones(n, bool), estar=estar, hardness=hardness)


_EXAMPLES = {"rollers": "14", "pitch_diameter": "70mm", "roller_diameter": "11mm",
             "length": "11mm", "radial_load": "10kN"}


class Solved:
    """One bearing: the library's bearing, its solution and the case check (or None)."""

    def __init__(self, bearing, solution, case=None):
        self.bearing, self.solution, self.case = bearing, solution, case


def _given(v, name, i):
    x = v[name][i]
    if isinstance(x, str):
        return x.strip() or None
    return None if x != x else float(x)


def solve(values, i, state):
    """Row i: :class:`linecontact.bearing.RadialRollerBearing` and its solve, and the
    case check of its most loaded roller (library refusals propagate: the row's
    error)."""
    from ...bearing import RadialRollerBearing

    g = {p.name: _given(values, p.name, i) for p in parameters}
    kw = {}
    if g["n_slices"] is not None:
        kw["n_slices"] = int(g["n_slices"])
    if g["poisson"] is not None:
        kw["poisson"] = g["poisson"]
    b = RadialRollerBearing(int(g["rollers"]), g["pitch_diameter"], g["roller_diameter"],
                            g["length"], g["clearance"] or 0.0,
                            estar=float(state.estar[i]), model=g["model"],
                            profile=g["profile"], rating=g["rating"], **kw)
    s = b.solve(g["radial_load"], moment=g["tilting_moment"],
                misalignment=g["misalignment"])
    case = None
    if state.hardness[i] is not None:
        case = case_check(b, s, state.hardness[i])
    return Solved(b, s, case)


def most_loaded_roller(bearing, solution):
    """The bearing's most loaded roller between its raceways at its load Q_max, as
    :func:`linecontact.raceway.roller_between_raceways` solves it (the bearing's model,
    profile and slices; under a tilt, free to tilt with the rings' misalignment
    theta cos psi_j at its azimuth): a :class:`~linecontact.raceway.RacewaySolution`."""
    from ...raceway import Raceways, roller_between_raceways

    s = solution
    j = int(np.argmax(s.roller_loads))
    race = bearing.raceways
    psi = float(s.roller_misalignment[j]) if s.roller_misalignment is not None else 0.0
    tilted = psi != 0.0 or s.tilt != 0.0 or s.moment != 0.0
    model = bearing.model
    if tilted and not bearing.sliced:
        model = "profiled-roller"  # as the bearing solves a tilt with no model named
    if psi:
        race = Raceways(race.inner, race.outer, misalignment=psi,
                        fit_tolerance=race.fit_tolerance)
    sliced = tilted or bearing.sliced
    return roller_between_raceways(
        bearing.roller_diameter / 2, bearing.length, bearing.estar, race,
        force=float(s.roller_loads[j]), model=model, profile=bearing.profile,
        tilt="free" if tilted else 0.0, n_slices=bearing.n_slices if sliced else None)


def case_check(bearing, solution, hardness):
    """The case check of the most loaded roller's two contacts: (checks, texts, worse)
    of :func:`linecontact.calc.features.stresses.case_of_contacts`."""
    roller = most_loaded_roller(bearing, solution)
    both = contact_stresses(roller, bearing.length, bearing.estar, bearing.profile, 0.0,
                            bearing.poisson)
    return case_of_contacts(both, hardness)


def row(obj, state, i):
    """The fields of one bearing [SI] (None where not defined), its model and notes."""
    s = obj.solution
    K = s.stiffness
    two = K.shape == (2, 2)
    st = s.stress or {}
    out = {
        "displacement": s.displacement,
        "radial_stiffness": float(K[0, 0]),
        "tilt": s.tilt,
        "moment": s.moment,
        "stiffness_rt": float(K[0, 1]) if two else None,
        "stiffness_tr": float(K[1, 0]) if two else None,
        "stiffness_tt": float(K[1, 1]) if two else None,
        "max_roller_load": s.max_roller_load,
        "load_zone": s.load_zone,
        "loaded_rollers": int((s.roller_loads > 0).sum()),
        "peak_pressure": s.peak_pressure,
        "rating": s.rating,
        "life_iso281": s.life_iso281,
        "life_iso16281": s.life_iso16281,
    }
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        w = st.get(m)
        shown = w and "withheld" not in w     # an edge-loaded roller's: "-", see notes
        out[m] = w["value"] if shown else None
        out[f"{m}_depth"] = w["depth"] if shown else None
    notes = list(s.notes)
    if obj.case is not None:
        checks, texts, worse = obj.case
        if worse is not None:
            c = checks[worse]
            out["case_ratio"] = c.max_ratio
            out["case_ratio_depth"] = c.depth_at_max
            out["min_case_depth"] = _min_case_depth(checks)
            notes.append(f"case check: worse contact {worse} (vM/allow inner "
                         + ", outer ".join(f"{checks[k].max_ratio:.4g}"
                                           if checks[k] is not None else "-"
                                           for k in ("inner", "outer")) + ")")
        notes += [f"case check, {t}" for t in texts]
    out["model_used"] = s.model
    out["notes"] = notes
    out["note"] = "; ".join(notes)
    return out


def model_of(obj):
    """(key, label, provenance) of the row's contact model, for the JSON header."""
    b = obj.bearing
    return b.model, obj.solution.model, {"model": obj.solution.model,
                                         "composed": "linecontact.bearing."
                                                     "RadialRollerBearing"}


def describe(obj, si):
    """The bearing in one line."""
    b, s = obj.bearing, obj.solution
    return (f"radial roller bearing: Z = {b.rollers}, d_m = {b.pitch_diameter * 1e3:.6g} "
            f"mm, D = {b.roller_diameter * 1e3:.6g} mm, L = {b.length * 1e3:.6g} mm, "
            f"P_d = {b.clearance * 1e6:.6g} um, E* = {b.estar / 1e9:.5g} GPa, profile "
            f"{b.profile.label}, F_r = {s.radial_load:.6g} N, M = {s.moment:.6g} N m, "
            f"theta = {s.tilt * (1 if si else 1e3):.6g} " + ("rad" if si else "mrad"))


_ROLLER_FIELDS = {
    "azimuth": Field("psi", "rad", "deg", 180 / math.pi),
    "approach": Field("approach", "m", "um", 1e6),
    "load": Field("Q", "N", "N", 1.0),
}
_TILT_FIELDS = {
    "moment": Field("M_j", "N m", "N m", 1.0),
    "tilt": Field("tilt", "rad", "mrad", 1e3),
}


def blocks(obj):
    """The table of one bearing's rollers (azimuth, approach, load; moment and tilt
    under a tilt)."""
    s = obj.solution
    tilted = s.stiffness.shape == (2, 2)
    flds = dict(_ROLLER_FIELDS, **(_TILT_FIELDS if tilted else {}))
    rows = []
    for j in range(len(s.azimuth)):
        r = {"label": str(j), "azimuth": float(s.azimuth[j]),
             "approach": float(s.approach[j]), "load": float(s.roller_loads[j])}
        if tilted:
            r.update(moment=float(s.roller_moments[j]), tilt=float(s.roller_tilts[j]))
        rows.append(r)
    return [Block(name="rollers", label="roller", fields=flds, rows=rows,
                  note="roller j at azimuth psi_j from the load line; approach: "
                       "delta_r cos psi_j - P_d/2 (negative: a gap); Q: its load"
                       + ("; M_j: its inner contact's moment, tilt: its own against "
                          "the inner ring" if tilted else "") + ".")]


def to_json(obj):
    """The row's full solution for ``--json`` [SI]: the bearing and
    :meth:`linecontact.bearing.BearingSolution.to_dict`."""
    b = obj.bearing
    return {"bearing": {"rollers": b.rollers, "pitch_diameter": b.pitch_diameter,
                        "roller_diameter": b.roller_diameter, "length": b.length,
                        "clearance": b.clearance, "estar": b.estar,
                        "profile": b.profile.label, "n_slices": b.n_slices},
            "solution": obj.solution.to_dict()}


def figure(objects):
    """``--plot``: :func:`linecontact.plot.bearing` of each bearing (one below the
    other for a sweep, :func:`linecontact.plot.panels`)."""
    from functools import partial

    from ... import plot

    if len(objects) == 1:
        return plot.bearing(objects[0].solution)
    return plot.panels(*(partial(plot.bearing, o.solution) for o in objects))
