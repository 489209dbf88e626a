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
bearing, and for the case check the solution's own most loaded roller
(:attr:`~linecontact.bearing.BearingSolution.roller`, the same solve as
:func:`linecontact.raceway.roller_between_raceways` at its load with the bearing's
model, profile and slices, free to tilt under the rings' misalignment at its azimuth)
and its contacts' stresses (:attr:`~linecontact.bearing.BearingSolution.roller_stresses`:
:func:`linecontact.stresses.roller_stresses`, or the strip under a law) through
:func:`linecontact.stresses.case_check`: the same solve ``linecontact calc
--inner-raceway ... --outer-raceway ... --load Q_max --tilt free --stresses yes``
makes. This module reads, asks and names.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..cases import BY_NAME as _CALC
from ..cases import refuse_estar_with_moduli
from ..feature import Block, Field, Parameter, State
from ..features.stresses import HARDNESS, hardness_of

__all__: list = []

name = "bearing"
help = "load distribution, stiffness and rating life of a radial roller bearing"
description = ("Load distribution over the rollers, ring displacement, radial stiffness, "
               "load zone, peak pressure, subsurface stresses and rating lives (ISO 281, "
               "ISO 16281) of a radial cylindrical or needle roller bearing under a "
               "radial load (and a tilting moment or a misalignment); given their "
               "inputs, the EHL film, modified lives L_nm and L_nmr, static safety, "
               "operating clearance after fits and warming, flange contacts under an "
               "axial load, a duty cycle's life and the case-hardening check of the "
               "most loaded roller. A value is a number "
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
_LUB = "lubrication and modified life (docs/bearing_life.md)"
_MOUNT = "operating clearance: fits and ring temperatures"
_FLANGE = "flanges of NJ / NUP bearings: axial load"
_SPECTRUM = "duty cycle"

#: The bearing's inputs: option ``--NAME`` = CSV column ``NAME``.
parameters = (
    Parameter("rollers", "count", "number of rollers Z (>= 3, as many as fit on the "
              "pitch circle)", _GEOM, bounds="bearing.ROLLER_COUNT"),
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
    Parameter("n_slices", "count", "slices of a slice model (default: "
              "50 for profiled-roller, 30 for iso16281-slicing; "
              "linecontact.roller.solvers.DEFAULT_SLICES)", _MODEL,
              bounds="bearing.SLICE_COUNT"),
    Parameter("rating", "force", "basic dynamic load rating C_r (default: ISO 281 "
              "from the geometry)", _MODEL),
    Parameter("static_rating", "force", "basic static load rating C0r (default: ISO 76 "
              "from the geometry)", _MODEL),
    Parameter("speed", "angular_speed", "speed of the inner ring against the outer ring "
              "(e.g. 1500rpm): entrainment speed; with --viscosity kappa, film and "
              "modified lives", _LUB, positive=False),
    Parameter("viscosity", "kinematic_viscosity", "kinematic viscosity of the lubricant "
              "at the operating temperature (e.g. 20.7cSt)", _LUB),
    Parameter("density", "density", "density of the lubricant (e.g. 860kg/m^3): "
              "eta0 = rho nu for the film", _LUB),
    Parameter("pressure_viscosity", "inverse_pressure", "pressure-viscosity "
              "coefficient alpha in 1/Pa (e.g. 2e-8): with --viscosity and --density, "
              "the EHL film", _LUB),
    Parameter("roughness_roller", "length", "RMS roughness Rq of the rollers (e.g. "
              "0.1um): the film ratio Lambda", _LUB, positive=False),
    Parameter("roughness_raceway", "length", "RMS roughness Rq of the raceways", _LUB,
              positive=False),
    Parameter("film_formula", "text", "minimum-film formula: pan-hamrock (default) or "
              "dowson-higginson", _LUB),
    Parameter("contamination", "dimensionless", "contamination factor e_C, 0 to 1 (with "
              "--viscosity): the modified lives L_nm, L_nmr", _LUB, positive=False),
    Parameter("reliability", "dimensionless", "reliability of the modified lives, "
              "0.9 to 0.9995 (default 0.9)", _LUB),
    Parameter("fatigue_load_limit", "force", "fatigue load limit C_u (default: C0r/8.2, "
              "ISO 281's estimate)", _LUB),
    Parameter("shaft_interference", "length", "effective diametral interference of the "
              "inner ring on the shaft (with --bore)", _MOUNT, positive=False),
    Parameter("bore", "length", "bore of the inner ring", _MOUNT),
    Parameter("shaft_bore", "length", "bore of a hollow shaft (default solid)", _MOUNT,
              positive=False),
    Parameter("housing_interference", "length", "effective diametral interference of "
              "the outer ring in the housing (with --outside-diameter)", _MOUNT,
              positive=False),
    Parameter("outside_diameter", "length", "outside diameter of the outer ring", _MOUNT),
    Parameter("housing_diameter", "length", "outside diameter of the housing (default "
              "massive)", _MOUNT),
    Parameter("ring_modulus", "pressure", "Young's modulus of rings, shaft and housing "
              "for the fits (default: the rings' --modulus, or 2 E* (1 - nu^2))",
              _MOUNT),
    Parameter("temperature_difference", "temperature_difference", "inner ring warmer "
              "than the outer ring by (e.g. 10K; rollers at the mean)", _MOUNT,
              positive=False),
    Parameter("axial_load", "force", "axial load carried by the flanges (NJ, NUP; with "
              "the flange geometry)", _FLANGE, positive=False),
    Parameter("end_radius", "length", "radius R_e of the rollers' spherical ends", _FLANGE),
    Parameter("flange_angle", "angle", "inclination of the flange faces to the radial "
              "plane (e.g. 3deg)", _FLANGE),
    Parameter("inner_flange_height", "length", "height of the inner ring's flange above "
              "its raceway", _FLANGE),
    Parameter("outer_flange_height", "length", "height of the outer ring's flange above "
              "its raceway", _FLANGE),
    Parameter("overall_length", "length", "overall roller length between its end "
              "vertices (default --length)", _FLANGE),
    Parameter("end_chamfer", "length", "radial extent of the roller's corner (default 0)",
              _FLANGE, positive=False),
    Parameter("axial_share", "text", "how the rollers share the axial load: "
              "proportional (to their radial loads, default) or equal", _FLANGE),
    Parameter("spectrum", "path", "duty cycle: a CSV of load cases, columns time_share "
              "(or revolution_share), radial_load, and optionally speed, "
              "tilting_moment, misalignment, axial_load (values with units as in the "
              "options); the combined lives by Palmgren-Miner", _SPECTRUM),
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
    "static_rating": Field("C0r ISO 76", "N", "kN", 1e-3),
    "static_safety": Field("s0 = C0r/P0r", "-", "-", 1.0),
    "pressure_safety": Field("s0 (4000 MPa/p_max)^2", "-", "-", 1.0),
    "operating_clearance": Field("operating clearance", "m", "um", 1e6),
    "entrainment_speed": Field("entrainment speed u", "m/s", "m/s", 1.0),
    "kappa": Field("kappa = nu/nu1", "-", "-", 1.0),
    "film_minimum_inner": Field("h_min inner (Q_max roller)", "m", "um", 1e6),
    "film_minimum_outer": Field("h_min outer (Q_max roller)", "m", "um", 1e6),
    "film_central_inner": Field("h_c inner (Q_max roller)", "m", "um", 1e6),
    "film_central_outer": Field("h_c outer (Q_max roller)", "m", "um", 1e6),
    "film_ratio": Field("Lambda min", "-", "-", 1.0),
    "life_modification": Field("a_ISO", "-", "-", 1.0),
    "life_modified": Field("L_nm ISO 281", "1e6 rev", "1e6 rev", 1.0),
    "life_modified_reference": Field("L_nmr ISO 16281", "1e6 rev", "1e6 rev", 1.0),
    "max_flange_force": Field("F_a,j max (flanges)", "N", "N", 1.0),
    "flange_pressure_inner": Field("p0 inner flange max", "Pa", "MPa", 1e-6),
    "flange_pressure_outer": Field("p0 outer flange max", "Pa", "MPa", 1e-6),
    "flange_couple": Field("flange couple max", "N m", "N m", 1.0),
    "spectrum_life_iso281": Field("duty cycle L10", "1e6 rev", "1e6 rev", 1.0),
    "spectrum_life_iso16281": Field("duty cycle L10r", "1e6 rev", "1e6 rev", 1.0),
    "spectrum_life_modified": Field("duty cycle L_nm", "1e6 rev", "1e6 rev", 1.0),
    "spectrum_life_modified_reference": Field("duty cycle L_nmr", "1e6 rev", "1e6 rev",
                                              1.0),
    "spectrum_hours_iso281": Field("duty cycle L10h", "h", "h", 1.0),
    "case_ratio": Field("vM/allow (case check)", "-", "-", 1.0),
    "case_ratio_depth": Field("  at depth", "m", "um", 1e6),
    "min_case_depth": Field("CHD min", "m", "mm", 1e3),
}

#: Fields shown in one case's list only where computed (asked for by their options).
optional = ("case_ratio", "case_ratio_depth", "min_case_depth", "operating_clearance",
            "entrainment_speed", "kappa", "film_minimum_inner", "film_minimum_outer",
            "film_central_inner", "film_central_outer", "film_ratio",
            "life_modification", "life_modified", "life_modified_reference",
            "max_flange_force", "flange_pressure_inner", "flange_pressure_outer",
            "flange_couple", "spectrum_life_iso281", "spectrum_life_iso16281",
            "spectrum_life_modified", "spectrum_life_modified_reference",
            "spectrum_hours_iso281")

#: The output each optional note explains: left out of the text when no row has it.
note_fields = {"film": "film_minimum_inner", "modified": "life_modified",
               "flanges": "max_flange_force", "spectrum": "spectrum_life_iso281",
               "case": "case_ratio"}

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
    "static": "C0r = 44 (1 - D/d_m) Z L D [N, mm] (ISO 76), P0r = F_r; s0 = C0r/P0r, "
              "and from the computed peak pressure (4000 MPa/p_max)^2 (edge stresses "
              "included; docs/bearing_life.md).",
    "film": "EHL film of each roller's contacts per lamina (Pan & Hamrock 1989 by "
            "default, Dowson & Higginson 1977 by --film-formula; the central film Pan & "
            "Hamrock's) from the entrainment speed of pure rolling; shown: the most "
            "loaded roller's smallest over its laminae; Lambda = h_min/sqrt(Rq1^2 + "
            "Rq2^2); kappa = nu/nu1 (ISO 281's nu1, catalogue form).",
    "modified": "L_nm = a1 a_ISO L10 (ISO 281:2007, catalogue form; a_ISO at P = F_r, "
                "capped at 50); L_nmr = a1 a_ISO(P_ref) L10r with P_ref = C_r "
                "L10r^(-3/10).",
    "flanges": "axial load: each roller's flange force (shared in proportion to the "
               "radial loads, or equally), the Hertz pressure of its two flange "
               "contacts and their couple; the couple is not fed back into the rollers' "
               "tilt (docs/bearing_life.md).",
    "spectrum": "duty cycle: each case solved alone, combined by Palmgren-Miner, "
                "1/L = sum u_i/L_i with u_i the shares of revolutions (from shares of "
                "time: t_i n_i / sum t_j n_j).",
    "case": "case check (--surface-hardness, --case-depth, --core-hardness or "
            "--hardness-profile): the bearing's most loaded roller, solved exactly "
            "between the same raceways at Q_max (as linecontact.raceway."
            "roller_between_raceways, free to tilt under the rings' misalignment at its "
            "azimuth), each contact's von Mises over the "
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
    refuse_estar_with_moduli(P, fail)
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
    hardness = hardness_of(v, P, fail, np.ones(n, bool), v["roller_diameter"] / 2)
    spectra = [None] * n
    read = {}
    for i in np.flatnonzero(P["spectrum"]):
        path = v["spectrum"][i].strip()
        if path not in read:
            try:
                read[path] = read_spectrum(path)
            except Exception as exc:  # noqa: BLE001 - the row's error, one line
                read[path] = str(exc).splitlines()[0] if str(exc) else repr(exc)
        if isinstance(read[path], str):
            fail(np.arange(n) == i, "spectrum", "a CSV of load cases (time_share or "
                 "revolution_share, radial_load, ...)", read[path])
            continue
        cases, shares = read[path]
        from ...bearing.spectrum import SHARE_TOLERANCE

        column = "time_share" if shares == "time" else "revolution_share"
        total = sum(c["share"] for c in cases)
        if abs(total - 1.0) > SHARE_TOLERANCE:   # the library's rule, in file terms
            fail(np.arange(n) == i, "spectrum", f"a {column} column summing to 1 "
                 "(fractions, not percent)", f"its {column} column sums to {total:.6g}")
            continue
        # shares of time count revolutions at each case's speed: the file's speed
        # column or the bearing's speed; said here in the user's words (the library
        # would name its keyword shares='revolutions')
        slow = [k + 1 for k, c in enumerate(cases) if c["speed"] is None]
        if shares == "time" and slow and not P["speed"][i]:
            fail(np.arange(n) == i, "spectrum", f"a speed for every case: a speed "
                 f"column in the file, or {fail.label('speed')} for the bearing; or "
                 "revolution_share instead of time_share",
                 f"time_share needs each case's speed to count its revolutions; rows "
                 f"{slow} have none")
            continue
        spectra[i] = read[path]
    return State(np.ones(n, bool), estar=estar, hardness=hardness, spectra=spectra)


#: The columns of a duty-cycle CSV (``--spectrum``): each a Parameter, read with the
#: calculator's unit rules.
SPECTRUM_COLUMNS = (
    Parameter("time_share", "dimensionless", "share of time of the case (fractions "
              "summing to 1)", _SPECTRUM, positive=False),
    Parameter("revolution_share", "dimensionless", "share of revolutions of the case",
              _SPECTRUM, positive=False),
    Parameter("radial_load", "force", "radial load F_r", _SPECTRUM),
    Parameter("speed", "angular_speed", "speed of the inner ring (default --speed)",
              _SPECTRUM, positive=False),
    Parameter("tilting_moment", "moment", "tilting moment", _SPECTRUM, positive=False),
    Parameter("misalignment", "angle", "misalignment", _SPECTRUM, positive=False),
    Parameter("axial_load", "force", "axial load on the flanges", _SPECTRUM,
              positive=False),
)


def read_spectrum(path):
    """The load cases of a duty-cycle CSV: (cases as dicts of LoadCase's fields with
    None where not given, 'time' or 'revolutions'); ValueError naming the row and
    column of a bad cell."""
    from ..batch import read_table
    from ..cases import parse_columns

    header, body, _ = read_table(path)
    names = [h.strip().lower() for h in header]
    known = {p.name for p in SPECTRUM_COLUMNS}
    unknown = [h for h in names if h and h not in known]
    if unknown:
        raise ValueError(f"{path}: unknown columns {unknown} (known: {sorted(known)})")
    rows = [list(r) for r in body]
    n = len(rows)
    cells = {nm: [r[j].strip() if j < len(r) else "" for r in rows]
             for j, nm in enumerate(names) if nm}
    values, present, _, errors = parse_columns(SPECTRUM_COLUMNS, cells, n,
                                               lambda nm: nm)
    bad = [(i, e) for i, e in enumerate(errors) if e]
    if bad:
        raise ValueError(f"{path}: row {bad[0][0] + 1}: {bad[0][1]}")
    t, r = present["time_share"], present["revolution_share"]
    if not ((t.all() and not r.any()) or (r.all() and not t.any())):
        raise ValueError(f"{path}: give time_share or revolution_share in every row "
                         "(one of the two)")
    if not present["radial_load"].all():
        raise ValueError(f"{path}: radial_load missing in rows "
                         f"{(np.flatnonzero(~present['radial_load']) + 1).tolist()}")
    share = "time_share" if t.all() else "revolution_share"

    def cell(nm, i):
        return float(values[nm][i]) if present[nm][i] else None

    cases = [dict(share=float(values[share][i]), radial_load=cell("radial_load", i),
                  speed=cell("speed", i), moment=cell("tilting_moment", i),
                  misalignment=cell("misalignment", i), axial_load=cell("axial_load", i))
             for i in range(n)]
    return cases, ("time" if share == "time_share" else "revolutions")


_EXAMPLES = {"rollers": "14", "pitch_diameter": "70mm", "roller_diameter": "11mm",
             "length": "11mm", "radial_load": "10kN"}


class Solved:
    """One bearing: the library's bearing, its solution and the case check (or None)."""

    def __init__(self, bearing, solution, case=None, spectrum=None):
        self.bearing, self.solution, self.case = bearing, solution, case
        self.spectrum = spectrum


def _given(v, name, i):
    x = v[name][i]
    if isinstance(x, str):
        return x.strip() or None
    return None if x != x else float(x)


def solve(values, i, state):
    """Row i: :class:`linecontact.bearing.RadialRollerBearing` and its solve, and the
    case check of its most loaded roller (library refusals propagate: the row's
    error): a :class:`linecontact.stresses.RacewayCaseCheck` (the solution's
    ``roller_stresses.case_check``)."""
    from ...bearing import RadialRollerBearing

    g = {p.name: _given(values, p.name, i) for p in parameters}
    kw = {}
    if g["n_slices"] is not None:
        kw["n_slices"] = int(g["n_slices"])
    if g["poisson"] is not None:
        kw["poisson"] = g["poisson"]
    for nm in _LIBRARY:
        if g[nm] is not None:
            kw[nm] = g[nm]
    if (g["ring_modulus"] is None and g["modulus"] is not None
            and (g["shaft_interference"] is not None
                 or g["housing_interference"] is not None)):
        kw["ring_modulus"] = g["modulus"]        # the rings' own modulus for the fits
    b = RadialRollerBearing(int(g["rollers"]), g["pitch_diameter"], g["roller_diameter"],
                            g["length"], g["clearance"] or 0.0,
                            estar=float(state.estar[i]), model=g["model"],
                            profile=g["profile"], rating=g["rating"], **kw)
    s = b.solve(g["radial_load"], moment=g["tilting_moment"],
                misalignment=g["misalignment"], speed=g["speed"],
                axial_load=g["axial_load"])
    # the case check of the most loaded roller's two contacts: the solution's own
    # stresses of its own solve of that roller (BearingSolution.roller_stresses)
    case = None
    if state.hardness[i] is not None:
        case = s.roller_stresses.case_check(state.hardness[i])
    spectrum = None
    if state.spectra[i] is not None:
        from ...bearing import solve_spectrum

        cases, shares = state.spectra[i]
        cases = [dict(c, speed=g["speed"]) if c["speed"] is None else c for c in cases]
        spectrum = solve_spectrum(b, cases, shares=shares)
    return Solved(b, s, case, spectrum)


#: The parameters passed to :class:`linecontact.bearing.RadialRollerBearing` by name
#: where given (the lubricant, life factors, fits, temperatures and flanges).
_LIBRARY = ("static_rating", "viscosity", "density", "pressure_viscosity",
            "roughness_roller", "roughness_raceway", "film_formula", "contamination",
            "reliability", "fatigue_load_limit", "shaft_interference", "bore",
            "shaft_bore", "housing_interference", "outside_diameter",
            "housing_diameter", "ring_modulus", "temperature_difference", "end_radius",
            "flange_angle", "inner_flange_height", "outer_flange_height",
            "overall_length", "end_chamfer", "axial_share")


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
    j = int(np.argmax(s.roller_loads))
    out.update(static_rating=s.static_rating, static_safety=s.static_safety,
               pressure_safety=s.pressure_safety,
               operating_clearance=(s.clearance if s.clearance_changes is not None
                                    else None),
               entrainment_speed=s.entrainment_speed, kappa=s.kappa,
               film_ratio=s.film_ratio, life_modification=s.life_modification,
               life_modified=s.life_modified,
               life_modified_reference=s.life_modified_reference)
    for nm in ("film_minimum_inner", "film_minimum_outer", "film_central_inner",
               "film_central_outer"):
        a = getattr(s, nm)
        out[nm] = None if a is None else float(np.min(a[j]))
    if s.flange_forces is not None:
        out.update(max_flange_force=float(s.flange_forces.max()),
                   flange_pressure_inner=float(s.flange_pressure_inner.max()),
                   flange_pressure_outer=float(s.flange_pressure_outer.max()),
                   flange_couple=float(s.flange_couple.max()))
    sp = obj.spectrum
    if sp is not None:
        for kind in ("iso281", "iso16281", "modified", "modified_reference"):
            out[f"spectrum_life_{kind}"] = sp.life.get(kind)
        out["spectrum_hours_iso281"] = (sp.hours or {}).get("iso281")
    for m in ("tresca", "von_mises", "orthogonal_shear"):
        w = st.get(m)
        shown = w and "withheld" not in w     # an edge-loaded roller's: "-", see notes
        out[m] = w["value"] if shown else None
        out[f"{m}_depth"] = w["depth"] if shown else None
    notes = list(s.notes)
    if obj.case is not None:
        checks, texts, worse = obj.case.checks, obj.case.notes, obj.case.worse
        if worse is not None:
            c = checks[worse]
            out["case_ratio"] = c.max_ratio
            out["case_ratio_depth"] = c.depth_at_max
            out["min_case_depth"] = obj.case.min_case_depth
            notes.append(f"case check: worse contact {worse} (vM/allow inner "
                         + ", outer ".join(f"{checks[k].max_ratio:.4g}"
                                           if checks[k] is not None else "-"
                                           for k in ("inner", "outer")) + ")")
        notes += [t if t.startswith("case check") else f"case check, {t}"
                  for t in texts]
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


def scales(obj):
    """The size of the quantities that may be round-off in an aligned bearing [SI]:
    the ring tilt against delta_r/L, the moment against F_r L, the stiffness matrix's
    coupling terms against sqrt(K_rr K_tt) (the matrix's own scale); a value below
    :data:`linecontact._units.NOISE` of its scale is shown as 0."""
    b, s = obj.bearing, obj.solution
    K = s.stiffness
    out = {"tilt": (abs(s.displacement) + abs(b.clearance)) / b.length,
           "moment": s.radial_load * b.length}
    if K.shape == (2, 2):
        out["stiffness_rt"] = out["stiffness_tr"] = math.sqrt(abs(K[0, 0] * K[1, 1]))
    return out


def describe(obj, si):
    """The bearing in one line (SI with `si`), round-off shown as 0."""
    from ..._units import format_numbers

    b, s = obj.bearing, obj.solution
    sc = scales(obj)
    M = format_numbers([s.moment], 6, sc["moment"])[0]
    # P_d as given; the operating clearance after fits and warming beside it (the load
    # distribution's), never in its place
    given = getattr(b, "internal_clearance", b.clearance)
    factor, unit = (1.0, "m") if si else (1e6, "um")
    pd = f"{given * factor:.6g} {unit}"
    if given != b.clearance:
        pd += f" (operating {b.clearance * factor:.6g} {unit})"
    if si:
        th = format_numbers([s.tilt], 6, sc["tilt"])[0]
        return (f"radial roller bearing: Z = {b.rollers}, d_m = {b.pitch_diameter:.6g} m, "
                f"D = {b.roller_diameter:.6g} m, L = {b.length:.6g} m, P_d = "
                f"{pd}, E* = {b.estar:.6g} Pa, profile {b.profile.label}, "
                f"F_r = {s.radial_load:.6g} N, M = {M} N m, theta = {th} rad")
    th = format_numbers([s.tilt * 1e3], 6, sc["tilt"] * 1e3)[0]
    return (f"radial roller bearing: Z = {b.rollers}, d_m = {b.pitch_diameter * 1e3:.6g} "
            f"mm, D = {b.roller_diameter * 1e3:.6g} mm, L = {b.length * 1e3:.6g} mm, "
            f"P_d = {pd}, E* = {b.estar / 1e9:.5g} GPa, profile "
            f"{b.profile.label}, F_r = {s.radial_load:.6g} N, M = {M} N m, "
            f"theta = {th} mrad")


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
    film = s.film_ratio_inner is not None
    flange = s.flange_forces is not None
    life = s.speed is not None
    flds = dict(_ROLLER_FIELDS, **(_TILT_FIELDS if tilted else {}),
                **({"film_ratio": _LIFE_FIELDS["film_ratio"]} if film else {}),
                **({"damage": _LIFE_FIELDS["damage"]} if life else {}),
                **({"flange_force": _LIFE_FIELDS["flange_force"]} if flange else {}))
    rows = []
    for j in range(len(s.azimuth)):
        r = {"label": str(j), "azimuth": float(s.azimuth[j]),
             "approach": float(s.approach[j]), "load": float(s.roller_loads[j])}
        if tilted:
            r.update(moment=float(s.roller_moments[j]), tilt=float(s.roller_tilts[j]))
        if film:
            lam = min(float(s.film_ratio_inner[j]), float(s.film_ratio_outer[j]))
            r["film_ratio"] = lam if math.isfinite(lam) else None
        if life:
            r["damage"] = float(s.roller_damage[j])
        if flange:
            r["flange_force"] = float(s.flange_forces[j])
        rows.append(r)
    # round-off (an aligned profiled bearing's moments, 1e-16 N m) printed as 0 against
    # the quantity's scale: a roller's moment against Q_max L, its tilt against the
    # bearing's (scales)
    sizes = {"moment": s.max_roller_load * obj.bearing.length,
             "tilt": scales(obj)["tilt"]} if tilted else {}
    out = [Block(name="rollers", label="roller", fields=flds, rows=rows, scales=sizes,
                 note="roller j at azimuth psi_j from the load line; approach: "
                      "delta_r cos psi_j - P_d/2 (negative: a gap); Q: its load"
                      + ("; M_j: its inner contact's moment, tilt: its own against "
                         "the inner ring" if tilted else "")
                      + ("; Lambda: the smaller of its two contacts' film ratios"
                         if film else "")
                      + ("; damage: its share of the L10r damage" if life else "")
                      + ("; F_a,j: the axial force through its flanges" if flange
                         else "") + ".")]
    sp = obj.spectrum
    if sp is not None:
        cflds = dict(_CASE_FIELDS)
        crows = []
        for i, (c, sol) in enumerate(zip(sp.cases, sp.solutions)):
            r = {"label": str(i), "share": c.share, "u": float(sp.revolution_shares[i]),
                 "radial_load": c.radial_load, "speed": c.speed}
            for kind in sp.lives:
                r[f"life_{kind}"] = float(sp.lives[kind][i])
                r[f"damage_{kind}"] = float(sp.damage[kind][i])
            crows.append(r)
        cflds = {k: f for k, f in cflds.items()
                 if not (k.startswith(("life_", "damage_"))
                         and k.split("_", 1)[1] not in sp.lives)}
        out.append(Block(name="spectrum", label="case", fields=cflds, rows=crows,
                         note="load case i: its share as given, u_i its share of "
                              "revolutions, each life as if it acted alone and its "
                              "share of the damage (Palmgren-Miner)."))
    return out


_LIFE_FIELDS = {
    "film_ratio": Field("Lambda", "-", "-", 1.0),
    "damage": Field("damage", "-", "-", 1.0),
    "flange_force": Field("F_a,j", "N", "N", 1.0),
}
_CASE_FIELDS = {
    "share": Field("share", "-", "-", 1.0),
    "u": Field("u_i", "-", "-", 1.0),
    "radial_load": Field("F_r", "N", "kN", 1e-3),
    "speed": Field("speed", "rad/s", "rpm", 30 / math.pi),
    "life_iso281": Field("L10", "1e6 rev", "1e6 rev", 1.0),
    "damage_iso281": Field("damage L10", "-", "-", 1.0),
    "life_iso16281": Field("L10r", "1e6 rev", "1e6 rev", 1.0),
    "damage_iso16281": Field("damage L10r", "-", "-", 1.0),
    "life_modified": Field("L_nm", "1e6 rev", "1e6 rev", 1.0),
    "damage_modified": Field("damage L_nm", "-", "-", 1.0),
    "life_modified_reference": Field("L_nmr", "1e6 rev", "1e6 rev", 1.0),
    "damage_modified_reference": Field("damage L_nmr", "-", "-", 1.0),
}


def to_json(obj):
    """The row's full solution for ``--json`` [SI]: the bearing and
    :meth:`linecontact.bearing.BearingSolution.to_dict`."""
    b = obj.bearing
    return {"bearing": {"rollers": b.rollers, "pitch_diameter": b.pitch_diameter,
                        "roller_diameter": b.roller_diameter, "length": b.length,
                        "clearance": b.clearance, "estar": b.estar,
                        "profile": b.profile.label, "n_slices": b.n_slices},
            "solution": obj.solution.to_dict(),
            **({"spectrum": _spectrum_json(obj.spectrum)} if obj.spectrum is not None
               else {})}


def _spectrum_json(sp):
    """The duty cycle for ``--json`` [SI]: the cases, their shares of revolutions,
    lives and damage, and the combined lives."""
    return {"cases": [{k: getattr(c, k) for k in ("share", "radial_load", "speed",
                                                  "moment", "misalignment",
                                                  "axial_load")} for c in sp.cases],
            "revolution_shares": sp.revolution_shares.tolist(),
            "lives": {k: v.tolist() for k, v in sp.lives.items()},
            "damage": {k: v.tolist() for k, v in sp.damage.items()},
            "life": dict(sp.life), "hours": sp.hours}


def figure(objects):
    """``--plot``: :func:`linecontact.plot.bearing` of each bearing (one below the
    other for a sweep, :func:`linecontact.plot.panels`)."""
    from functools import partial

    from ... import plot

    if len(objects) == 1:
        return plot.bearing(objects[0].solution)
    return plot.panels(*(partial(plot.bearing, o.solution) for o in objects))
