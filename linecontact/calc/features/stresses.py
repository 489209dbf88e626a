"""Feature: subsurface stresses and the case-hardening check (``--stresses``).

``--stresses yes``
    Adds to every model row the maxima of the Tresca (max shear), von Mises and
    orthogonal shear stresses below the contact and their depths: the plane-strain
    Hertz strip with the row's mean line load F/L (:func:`linecontact.stresses
    .line_contact_stresses`). It also adds the roller's rows: the coupled-slice model
    (:class:`linecontact.roller.ProfiledRoller`, with ``--profile``/``--crown-radius``/
    ``--tilt`` when given, else straight) and the worst of each measure along it
    (:func:`linecontact.stresses.roller_stresses`), with the slice method's measured
    error in the note. ``--json`` adds the along-axis profile (every slice's maxima).
``--sliding-friction MU``
    The sliding traction mu p across the contact (Johnson 1985, section 7.2), 0 <= mu
    <= 1 (default 0).
``--stress-field X``
    With ``--json``: the field on the section across the roller at x = X.
``--surface-hardness HV --case-depth CHD --core-hardness HV``, or ``--hardness-profile FILE.csv``
    The case-hardening check: the largest stress over the allowable against depth, its
    depth and the minimum effective case depth for the load
    (:func:`linecontact.stresses.case_check`; von Mises against the yield strength
    2.876 HV - 90.7 MPa, Pavlina & Van Tyne 2008). The CSV has columns depth_m, HV.

Poisson's ratio of the stressed body: ``--poisson`` where given, else 0.3 (said in the
notes). Not combined with the raceways (a whole roller).
"""
from __future__ import annotations

import math

import numpy as np

from ..feature import Block, Field, Parameter, State

__all__: list = []

name = "stresses"
group = "subsurface stresses and case-hardening check"

parameters = (
    Parameter("stresses", "text", "yes: the maxima of Tresca, von Mises and orthogonal "
              "shear below the contact and their depths, per model row and along the "
              "roller", group),
    Parameter("sliding_friction", "dimensionless", "coefficient mu of the sliding "
              "traction mu p for the stresses, 0 to 1", group, positive=False),
    Parameter("stress_field", "length", "with --json: the stress field on the section "
              "across the roller at this x", group, positive=False),
    Parameter("surface_hardness", "dimensionless", "surface hardness HV (> 550) for the "
              "case-hardening check", group),
    Parameter("case_depth", "length", "effective case depth CHD (to 550 HV, ISO 2639)",
              group),
    Parameter("core_hardness", "dimensionless", "core hardness HV (< 550)", group),
    Parameter("hardness_profile", "path", "measured hardness: a CSV with columns "
              "depth_m, HV (instead of the three above)", group),
)

_HARD = ("surface_hardness", "case_depth", "core_hardness")
_MEASURES = ("tresca", "von_mises", "orthogonal_shear")
_HEAD = {"tresca": "tau max", "von_mises": "von Mises", "orthogonal_shear": "tau orth"}

fields = {}
for _m in _MEASURES:
    fields[f"{_m}_max"] = Field(_HEAD[_m], "Pa", "MPa", 1e-6)
    fields[f"{_m}_depth"] = Field(f"z({_HEAD[_m]})", "m", "um", 1e6)
fields["case_ratio"] = Field("vM/allow", "-", "-", 1.0)
fields["case_ratio_depth"] = Field("z(vM/allow)", "m", "um", 1e6)
fields["min_case_depth"] = Field("CHD min", "m", "mm", 1e3)

NOTE = ("stresses: plane-strain Hertz strip (McEwen 1949; Johnson 1985, sections 4.2 and "
        "7.2) with the mean line load F/L per model row; along the roller one strip per "
        "slice of the coupled-slice model; tau max = (sigma1 - sigma3)/2, tau orth = "
        "|tau_yz|; case check: von Mises over the yield strength 2.876 HV - 90.7 MPa "
        "(Pavlina & Van Tyne 2008), CHD min: the smallest effective case depth with a "
        "ratio <= 1. docs/stresses.md.")
notes = {"stresses": NOTE}

_ROW_FIELDS = {}
for _m in _MEASURES:
    _ROW_FIELDS[f"{_m}_max"] = fields[f"{_m}_max"]
    _ROW_FIELDS[f"{_m}_depth"] = fields[f"{_m}_depth"]
    _ROW_FIELDS[f"{_m}_x"] = Field(f"x({_HEAD[_m]})", "m", "mm", 1e3)


def resolve(values, present, fail):
    """--stresses yes|no; hardness options complete and consistent; all need
    --stresses; not with the raceways."""
    v, P, label = values, present, fail.label
    mine = P["stresses"] | P["sliding_friction"] | P["stress_field"] | P["hardness_profile"]
    for nm in _HARD:
        mine = mine | P[nm]
    if not mine.any():
        return None
    n = len(mine)
    on = np.zeros(n, bool)
    for i in np.flatnonzero(P["stresses"]):
        text = v["stresses"][i].strip().lower()
        if text in ("yes", "true", "1"):
            on[i] = True
        elif text not in ("no", "false", "0"):
            fail(np.arange(n) == i, "stresses", "yes or no", "not yes or no")
    for nm in ("sliding_friction", "stress_field", "hardness_profile") + _HARD:
        fail(P[nm] & ~on, nm, f"with {label('stresses')} yes", "stresses not asked for")
    raceways = P["inner_raceway"] | P["outer_raceway"]
    fail(on & raceways, "stresses", "one contact (without the raceways)",
         "not available for a whole roller")
    with np.errstate(invalid="ignore"):
        fail(P["sliding_friction"] & ~((v["sliding_friction"] >= 0)
                                        & (v["sliding_friction"] <= 1)),
             "sliding_friction", "[0, 1]", "outside the range of the strip solution")
    three = ", ".join(label(s) for s in _HARD)
    some = P[_HARD[0]] | P[_HARD[1]] | P[_HARD[2]]
    for nm in _HARD:
        fail(some & ~P[nm], nm, f"{three} together", "missing")
    fail(some & P["hardness_profile"], "hardness_profile",
         f"either {label('hardness_profile')} or {three}", "conflicts")
    hardness = [None] * n
    from ...validity import OutOfRangeError
    from ...stresses import HardnessProfile
    for i in np.flatnonzero(on & (some | P["hardness_profile"])):
        try:
            if P["hardness_profile"][i]:
                hardness[i] = _read_profile(v["hardness_profile"][i].strip())
            else:
                hardness[i] = HardnessProfile(*(float(v[nm][i]) for nm in _HARD))
        except OutOfRangeError as exc:
            nm = exc.parameter if exc.parameter in _HARD else "hardness_profile"
            fail(np.arange(n) == i, nm, exc.valid, str(exc))
        except (OSError, ValueError) as exc:
            fail(np.arange(n) == i, "hardness_profile", "a readable CSV (depth_m, HV)",
                 str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
    specs = [None] * n
    for i in np.flatnonzero(on):
        if P["profile"][i]:
            specs[i] = v["profile"][i].strip()
        elif P["crown_radius"][i]:
            specs[i] = ("crown", float(v["crown_radius"][i]))
        else:
            specs[i] = "straight"
    nu = np.where(P["poisson"], v["poisson"], 0.3)
    return State(on, mu=np.where(P["sliding_friction"], v["sliding_friction"], 0.0),
                 nu=nu, nu_given=P["poisson"], hardness=hardness, specs=specs,
                 tilts=np.where(P["tilt"], v["tilt"], 0.0),
                 section=np.where(P["stress_field"], v["stress_field"], np.nan))


def _read_profile(path):
    from ...stresses import HardnessProfile
    data = np.genfromtxt(path, delimiter=",", names=True, comments="#")
    names = data.dtype.names or ()
    if "depth_m" not in names or "HV" not in names:
        raise ValueError(f"{path}: needs the columns depth_m and HV (has {names})")
    return HardnessProfile(depths=np.atleast_1d(data["depth_m"]),
                           hardness=np.atleast_1d(data["HV"]))


def columns(model, rows, normal, state):
    """The strip maxima for the mean line load F/L of each model row, and the check."""
    from ...stresses import case_check, line_contact_stresses
    from ...validity import OutOfRangeError

    n = len(rows)
    out = {k: np.full(n, np.nan) for k in fields}
    flags = [""] * n
    F = normal["force"]
    for j, i in enumerate(rows):
        if not state.rows[i] or not (np.isfinite(F[j]) and F[j] > 0):
            continue
        try:
            s = line_contact_stresses(F[j], model.radius, model.length, model.estar,
                                      state.mu[i], state.nu[i])
        except OutOfRangeError as exc:
            flags[j] = str(exc)
            continue
        for m in _MEASURES:
            out[f"{m}_max"][j] = s.worst[m]["value"]
            out[f"{m}_depth"][j] = s.worst[m]["z"]
        if state.hardness[i] is not None:
            try:
                c = case_check(s, state.hardness[i])
                out["case_ratio"][j] = c.max_ratio
                out["case_ratio_depth"][j] = c.depth_at_max
                if c.min_case_depth is not None:
                    out["min_case_depth"][j] = c.min_case_depth
            except OutOfRangeError as exc:
                flags[j] = str(exc)
    out["flags"] = flags
    return out


def blocks(state, results):
    """The roller's rows: coupled slices (profiled or straight) and the worst stresses
    along it; --json: the along-axis profile and the section field."""
    from ...roller import ProfiledRoller
    from ...stresses import roller_stresses
    from .roller import roller_profile

    cases, errors = results.cases, results.errors
    rows, json_rows = [], []
    any_row = False
    nu_note = ""
    for i in range(len(errors)):
        if not state.rows[i] or errors[i]:
            rows.append(None)
            json_rows.append({})
            continue
        R, L, E = (float(a[i]) for a in (cases.radius_eff, cases.length, cases.estar))
        given, value = str(cases.given[i]), float(cases.value[i])
        force = value if given == "load" else math.nan
        tilt = float(state.tilts[i])
        spec = state.specs[i]
        label = f"stresses along the roller ({spec if isinstance(spec, str) else 'crown'}"
        label += f", tilt {tilt * 1e3:.4g} mrad)" if tilt else ")"
        try:
            prof = roller_profile(spec, R, L, E, force, 2 * float(cases.radius[i]))
            r = ProfiledRoller(R, L, E, prof, n_slices=100)
            sol = r.at_force(value, tilt=tilt) if given == "load" else r.at_depth(value, tilt)
            s = roller_stresses(sol, float(state.mu[i]), float(state.nu[i]), roller=r)
        except Exception as exc:  # noqa: BLE001 - one line in the row's note
            text = (str(exc).strip().splitlines() or [type(exc).__name__])[0]
            rows.append({"label": label, "note": text, "text": {}})
            json_rows.append({"note": text})
            continue
        any_row = True
        row = {"label": label, "text": {}}
        for m in _MEASURES:
            w = s.worst[m]
            row[f"{m}_max"], row[f"{m}_depth"], row[f"{m}_x"] = w["value"], w["z"], w["x"]
        row["note"] = "; ".join(s.notes)
        rows.append(row)
        doc = s.to_dict(arrays=True)
        if np.isfinite(state.section[i]):
            x0 = float(state.section[i])
            b = float(np.max(s.half_width))
            ys = np.linspace(-2 * b, 2 * b, 41)
            zs = np.linspace(0.0, 2 * b, 41)
            try:
                sec = s.section(x0, ys, zs)
                doc["section"] = dict(x=x0, y=ys.tolist(), z=zs.tolist(), **sec.to_dict())
            except ValueError as exc:
                doc["section"] = {"note": str(exc)}
        json_rows.append(doc)
        if not state.nu_given[i]:
            nu_note = " Poisson's ratio 0.3 (no --poisson given)."
    if not any_row and not any(rows):
        return []
    return [Block(name="stresses", key="stresses", label="roller stresses",
                  fields=_ROW_FIELDS, rows=rows, text_columns=(), json_rows=json_rows,
                  note=NOTE + nu_note,
                  units={k: f.si for k, f in _ROW_FIELDS.items()})]
