"""Feature: subsurface stresses and the case-hardening check (``--stresses``).

``--stresses yes``
    Adds to every model row the maxima of the Tresca (max shear), von Mises and
    orthogonal shear stresses below the contact and their depths: for a straight-roller
    law the plane-strain Hertz strip with the row's mean line load F/L
    (:func:`linecontact.stresses.line_contact_stresses`); for a profiled or tilted
    roller (``--profile``, ``--crown-radius``, ``--tilt``: the rows of the slice models)
    the worst along the roller, one strip per slice with the 3D correction of the
    worst (:func:`linecontact.stresses.roller_stresses`), with its measured error in
    the note. ``--json`` adds, for those rows, the along-axis profile (every
    slice's maxima).
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
notes). A whole roller between raceways (``--inner-raceway``, ``--outer-raceway``): the
stresses of each contact (:func:`linecontact.stresses.raceway_stresses`), each
measure's worse contact in the main columns and named in the note, both contacts'
maxima and case ratios in a table of their own; the case check takes the worse
contact (CHD min: the larger minimum).
"""
from __future__ import annotations

import math

import numpy as np

from ..feature import Block, Field, Parameter, State, keep

__all__ = ["hardness_of", "HARDNESS"]

name = "stresses"
group = "subsurface stresses and case-hardening check"

parameters = (
    Parameter("stresses", "text", "yes: the maxima of Tresca, von Mises and orthogonal "
              "shear below the contact and their depths, per model row and along the "
              "roller", group),
    Parameter("sliding_friction", "dimensionless", "coefficient mu of the sliding "
              "traction mu p for the stresses, 0 to 1", group, positive=False),
    Parameter("stress_field", "length", "with --json: the stress field on the section "
              "across the roller at this x", group, positive=False,
              json_only="the field on the section"),
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
        "slice of the coupled-slice model, the worst with a 3D correction (Love 1929; "
        "measured error in the row's note); tau max = (sigma1 - sigma3)/2, tau orth = "
        "|tau_yz|; case check: von Mises over the yield strength 2.876 HV - 90.7 MPa "
        "(Pavlina & Van Tyne 2008) on the worst slice's plane-strain envelope (low by "
        "the 3D correction where it raises the worst, up to 5.6 %), CHD min: the "
        "smallest effective case depth with a ratio <= 1. docs/stresses.md.")
notes = {"stresses": NOTE}

#: Each contact's maxima of a whole roller between raceways (its block).
_CONTACT_FIELDS = {}
for _m in _MEASURES:
    for _side in ("inner", "outer"):
        _CONTACT_FIELDS[f"{_m}_{_side}"] = Field(f"{_HEAD[_m]} {_side}", "Pa", "MPa", 1e-6)
for _side in ("inner", "outer"):
    _CONTACT_FIELDS[f"case_ratio_{_side}"] = Field(f"vM/allow {_side}", "-", "-", 1.0)

CONTACTS_NOTE = ("a whole roller between raceways: each contact's stress maxima (its "
                 "slices' worst where solved by slices, else the plane-strain strip of "
                 "its effective radius at the roller load) and case-check ratio; the "
                 "main columns show the worse contact of each measure, named in the "
                 "note ('worse'); CHD min: the larger of the two contacts' minima.")

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
    with np.errstate(invalid="ignore"):
        fail(P["sliding_friction"] & ~((v["sliding_friction"] >= 0)
                                        & (v["sliding_friction"] <= 1)),
             "sliding_friction", "[0, 1]", "outside the range of the strip solution")
    hardness = hardness_of(v, P, fail, on, v["radius"])
    nu = np.where(P["poisson"], v["poisson"], 0.3)
    return State(on, mu=np.where(P["sliding_friction"], v["sliding_friction"], 0.0),
                 nu=nu, nu_given=P["poisson"], hardness=hardness,
                 section=np.where(P["stress_field"], v["stress_field"], np.nan))


#: The case-check inputs (a subcommand declares them too: ``linecontact bearing``).
HARDNESS = tuple(p for p in parameters if p.name in _HARD + ("hardness_profile",))


def hardness_of(v, P, fail, on, radius):
    """The rows' hardness profiles (:class:`linecontact.stresses.HardnessProfile`, None
    where none is given) from the three values or the measured CSV: the three
    together, or the file, not both; only in the rows of `on`; a case depth within
    the roller's `radius` (array over the rows [m]: HardnessProfile.check_fits)."""
    label = fail.label
    n = len(on)
    three = ", ".join(label(s) for s in _HARD)
    some = P[_HARD[0]] | P[_HARD[1]] | P[_HARD[2]]
    for nm in _HARD:
        fail(some & ~P[nm], nm, f"{three} together", "missing")
    fail(some & P["hardness_profile"], "hardness_profile",
         f"either {label('hardness_profile')} or {three}", "conflicts")
    hardness = [None] * n
    from ...errors import OutOfRangeError
    from ...stresses import HardnessProfile
    for i in np.flatnonzero(on & (some | P["hardness_profile"])):
        try:
            if P["hardness_profile"][i]:
                hardness[i] = _read_profile(v["hardness_profile"][i].strip())
            else:
                hardness[i] = HardnessProfile(*(float(v[nm][i]) for nm in _HARD))
                if np.isfinite(radius[i]) and radius[i] > 0:
                    hardness[i].check_fits(float(radius[i]))
        except OutOfRangeError as exc:
            nm = exc.parameter if exc.parameter in _HARD else "hardness_profile"
            fail(np.arange(n) == i, nm, exc.valid,
                 exc.hint if nm == "case_depth" and exc.hint else str(exc))
        except (OSError, ValueError) as exc:
            fail(np.arange(n) == i, "hardness_profile", "a readable CSV (depth_m, HV)",
                 str(exc).splitlines()[0] if str(exc) else type(exc).__name__)
    return hardness


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
    from ...errors import OutOfRangeError

    n = len(rows)
    out = {k: np.full(n, np.nan) for k in fields}
    flags = [""] * n
    F = normal["force"]
    for j, i in enumerate(rows):
        if not state.rows[i] or not (np.isfinite(F[j]) and F[j] > 0):
            continue
        sol = normal["solution"][j] if "solution" in normal else None
        try:
            if _is_raceways(sol):  # a whole roller: each contact's, the worse flagged
                _between_raceways(out, flags, j, sol, model, state, i)
                continue
            keep(state, [i], model)
            s = _stresses_of(model, sol, float(F[j]), state, i)
            if _is_slices(sol) or (sol is None and _slice_law(model)):
                flags[j] = "; ".join(s.notes)
        except OutOfRangeError as exc:
            flags[j] = str(exc)
            continue
        if s.withheld:    # an edge-loaded roller: slice-width numbers, "-" and why
            flags[j] = "; ".join(t for t in (flags[j], "stress maxima and case check "
                                 "not reported: " + s.withheld[_MEASURES[0]]) if t)
            continue
        for m in _MEASURES:
            out[f"{m}_max"][j] = s.worst[m]["value"]
            out[f"{m}_depth"][j] = s.worst[m]["z"]
        if state.hardness[i] is not None:
            c, text = _case(s, state.hardness[i])
            _put_case(out, j, c)
            flags[j] = "; ".join(t for t in (flags[j], text) if t)
    out["flags"] = flags
    return out


def _stresses_of(model, sol, force, state, i):
    """The SubsurfaceStresses of one contact of row i: the worst along a profiled
    roller's slices (:func:`linecontact.stresses.roller_stresses`), else the
    plane-strain strip at F/L (:func:`~linecontact.stresses.line_contact_stresses`)."""
    from ...stresses import line_contact_stresses, roller_stresses

    if sol is None and _slice_law(model):
        # a slice model named as the law of a plain contact (--model profiled-roller):
        # the row's own solve, as the library's at this force
        sol = model.at_force(force)
    if _is_slices(sol):
        return roller_stresses(sol, state.mu[i], state.nu[i], roller=_measured_as(model))
    return line_contact_stresses(force, model.radius, model.length, model.estar,
                                 state.mu[i], state.nu[i])


def figure(state, results):
    """``--plot``: the stresses of the worst row (the largest von Mises maximum of the
    first model set): the field of its worst section with the maximum marked, the
    maxima along the roller and, with a hardness profile, the allowable at each depth
    of maximum and the case check (:func:`linecontact.plot.stresses`, von Mises, the
    measure of the check)."""
    from functools import partial

    from ... import plot
    from ...errors import OutOfRangeError

    kept = getattr(state, "kept", None)
    f = results.sets[0]["fields"]
    if kept is None or "von_mises_max" not in f:
        return (["--plot: stresses of a roller between raceways: no figure (each "
                 "contact's maxima are in the table)"]
                if getattr(state, "by_contact", None) else [])
    value = np.where(np.equal(kept, None), np.nan, f["von_mises_max"])
    if not np.isfinite(value).any():
        return ["--plot: stresses: no maximum computed (the rows' notes say why)"]
    i = int(np.nanargmax(value))
    model = kept[i]
    try:
        s = _stresses_of(model, results.sets[0]["solution"][i], float(f["force"][i]),
                         state, i)
    except OutOfRangeError as exc:
        return [f"--plot: stresses: no figure: {exc}"]
    case = _case(s, state.hardness[i])[0] if state.hardness[i] is not None else None
    out = [partial(plot.stresses, s, measure="von_mises", case=case)]
    if np.sum(np.isfinite(value)) > 1:
        out.append(f"--plot: stresses drawn for the worst row (row {i + 1}, von Mises "
                   f"{value[i] * 1e-6:.4g} MPa) of {int(np.sum(np.isfinite(value)))}")
    return out


def _case(s, hardness):
    """(CaseCheck or None, flag text) of one contact's stresses
    (:func:`linecontact.stresses.noted_case_check`)."""
    from ...stresses import noted_case_check

    return noted_case_check(s, hardness)


def _put_case(out, j, c):
    if c is None:
        return
    out["case_ratio"][j] = c.max_ratio
    out["case_ratio_depth"][j] = c.depth_at_max
    if c.min_case_depth is not None:
        out["min_case_depth"][j] = c.min_case_depth


def _is_raceways(sol):
    """A whole roller's solution (linecontact.raceway.RacewaySolution)."""
    return sol is not None and hasattr(sol, "depth_inner") and hasattr(sol, "radius_outer")


def _between_raceways(out, flags, j, sol, model, state, i):
    """A whole roller's row (:func:`linecontact.stresses.raceway_stresses`): each
    measure's worse contact in the main columns (its contact named in the flags),
    each contact's own maxima kept for the block, the case check over both."""
    from ...stresses import raceway_stresses

    c = model.contact
    both = raceway_stresses(sol, c.roller.length, c.estar, c.profile, float(state.mu[i]),
                            float(state.nu[i]))
    worst = both.worst
    worse = {m: worst[m]["contact"] for m in _MEASURES}
    # a maximum not converged in a contact (an edge-loaded one: the slice width's
    # number) is not reported: that measure's worse is unknown, and so is the case check
    held = both.withheld
    for m in _MEASURES:
        if "withheld" in worst[m]:
            continue
        out[f"{m}_max"][j] = worst[m]["value"]
        out[f"{m}_depth"][j] = worst[m]["depth"]
    texts = [f"stresses: worse contact {_said(worse)}"] if not held else [
        "stress maxima and case check not reported: " + "; ".join(
            f"{k} contact: {h[_MEASURES[0]]}" for k, h in held.items())]
    for side, st in both.items():
        texts += [f"{side}: {t}" for t in st.notes]
    row = {f"{m}_{side}": (None if m in both[side].withheld
                           else both[side].worst[m]["value"])
           for m in _MEASURES for side in both}
    if state.hardness[i] is not None and not held:
        case = both.case_check(state.hardness[i])
        for k, ck in case.checks.items():
            row[f"case_ratio_{k}"] = None if ck is None else ck.max_ratio
        texts += list(case.notes)
        if case.worse is not None:
            _put_case(out, j, case.checks[case.worse])
            need = case.min_case_depth
            out["min_case_depth"][j] = np.nan if need is None else need
            texts.insert(1, f"case check: worse contact {case.worse}")
    row["text"] = {"worse": "-" if held else _said(worse)}
    flags[j] = "; ".join(texts)
    state.__dict__.setdefault("by_contact", {}).setdefault(int(i), row)


def _said(worse):
    """'inner' when every measure's worse contact is the inner one, else per measure."""
    sides = set(worse.values())
    if len(sides) == 1:
        return sides.pop()
    return ", ".join(f"{_HEAD[m]} {side}" for m, side in worse.items())


def _slice_law(model):
    """The row's law is a slice model's (its solutions: ``at_force`` -> RollerSolution)."""
    return getattr(model, "contact", None) is None and callable(
        getattr(model, "at_force", None)) and hasattr(model, "axial_profile")


def _measured_as(model):
    """The row's roller as :func:`linecontact.stresses.stress_accuracy` checks it
    against the measured range (radius, length, estar, profile), or None where the
    contact has no single radius (raceways: the note then checks only tilt and
    friction)."""
    from types import SimpleNamespace

    c = getattr(model, "contact", None)
    if c is None and _slice_law(model):
        return SimpleNamespace(radius=model.radius, length=model.length,
                               estar=model.estar, profile=model.axial_profile)
    if c is None or getattr(c, "radius", None) is None:
        return None
    return SimpleNamespace(radius=c.radius, length=c.roller.length, estar=c.estar,
                           profile=c.profile)


#: Why a row has no section field: it is drawn from the slices of one contact.
SECTION_UNSOLVED = ("--stress-field: no section field for this row: the field is that "
                    "of one contact solved by slices (a profiled or tilted roller, or "
                    "--model profiled-roller on a flat or a second body)")


def _is_slices(sol):
    """A slice solution of one contact (linecontact.roller.RollerSolution)."""
    return sol is not None and hasattr(sol, "half_width") and hasattr(sol, "q") \
        and np.ndim(getattr(sol, "q")) == 1


def blocks(state, results):
    """``--json``: for the rows of the first model set solved by slices (a profiled
    roller), the along-axis profile of the maxima and, with --stress-field, the section
    field; no table (the maxima are in the main table)."""
    from ...stresses import roller_stresses

    sols = results.sets[0]["solution"] if results.sets else []
    json_rows = []
    for i, sol in enumerate(sols):
        if not state.rows[i] or not _is_slices(sol):
            # --stress-field asked of a row that has no slices (a law, or a roller
            # between raceways): say so rather than leave the field out without a word
            asked = state.rows[i] and np.isfinite(state.section[i])
            json_rows.append({"section": {"note": SECTION_UNSOLVED}} if asked else None)
            continue
        try:
            s = roller_stresses(sol, float(state.mu[i]), float(state.nu[i]))
        except ValueError as exc:
            json_rows.append({"note": str(exc)})
            continue
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
    out = []
    if any(r is not None for r in json_rows):
        out.append(Block(name="stresses", key="stresses", label="stresses along the roller",
                         fields={}, rows=[None] * len(json_rows), text_columns=(),
                         json_rows=json_rows, note="",
                         units={k: f.si for k, f in _ROW_FIELDS.items()}))
    by_contact = getattr(state, "by_contact", {})
    if by_contact:
        n = len(state.rows)
        rows = [None] * n
        for i, row in by_contact.items():
            rows[i] = dict(row, label="roller between raceways")
        out.append(Block(name="stresses_contacts", key="contacts",
                         label="each contact", fields=_CONTACT_FIELDS, rows=rows,
                         text_columns=("worse",),
                         json_rows=[None if r is None else
                                    {k: v for k, v in r.items() if k != "label"}
                                    for r in rows],
                         note=CONTACTS_NOTE,
                         units={k: f.si for k, f in _CONTACT_FIELDS.items()}))
    return out
