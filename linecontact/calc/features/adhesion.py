"""Feature: adhesive contact (``--work-of-adhesion``).

``--work-of-adhesion W`` (J/m^2, mJ/m^2, N/m; a sweep too)
    JKR-type adhesion (linecontact.adhesion): the pull-off force under force and under
    depth control, for a straight cylinder from the adhesive BEM table (method 'bem',
    :class:`linecontact.adhesion.CylinderAdhesion`, tables/adhesion_cylinder.csv) and
    below it, down to s = b_c/L = 1e-3, the long roller's end model
    (tables/adhesion_long_roller.csv) with its stated error, beside the 2D JKR value
    times L; and by the MDR's rule of Hess on the row's model (method 'mdr': its plain
    value, with the error measured against those; not printed where neither gives a
    value); the state at zero load (the 2D JKR half-width and the MDR's depth);
    the depth at the given load, or the force at the given depth, with adhesion (rule
    of Hess, stable branch); and the Tabor parameter (z0 = 0.3 nm), flagged where JKR
    does not apply. One contact only (not with the raceways); not with a viscoelastic
    body (between the relaxed and the instantaneous limit the pull-off depends on the
    speed of the receding edge, which the correspondence principle does not give).

Zero and tensile loads, zero and negative depths (only with ``--work-of-adhesion``)
    The adhesive contact holds them (the State's ``signed`` rows; without adhesion the
    core refuses a load or depth <= 0). Under force control (``--load F``) the state
    is on the stable branch down to the force-controlled pull-off Fc
    (:meth:`linecontact.adhesion.AdhesiveContact.depth_at_force`); a tensile load
    below Fc has no equilibrium: one case is refused naming Fc, a sweep's row says so.
    Under depth control (``--depth d``, a sweep from deep to negative is a retraction)
    the cycle of :meth:`~linecontact.adhesion.AdhesiveContact.hysteresis`: the
    approach has no contact (F = 0) until d = 0, where it jumps onto the stable
    branch; the retraction stays on it down to the depth-controlled pull-off d_c,
    where it jumps off (F = 0). Each row's branch is in its flags; ``F adh`` is the
    retraction's (the stable branch) and ``F approach`` the approach's force.
    The non-adhesive columns of such a row show the given value only (no contact
    without adhesion).
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, each, keep, short

__all__: list = []

name = "adhesion"
#: With this parameter a load or depth <= 0 is accepted (the State's ``signed`` rows).
signed = ("work_of_adhesion",)
group = "adhesion (one contact)"

parameters = (
    Parameter("work_of_adhesion", "surface_energy", "work of adhesion w (J/m^2, mJ/m^2): "
              "adds the pull-off force (force and depth control), the contact at zero "
              "load and the force or depth with adhesion (JKR)", group),
)

fields = {
    "pull_off_force": Field("Fc BEM F-ctrl", "N", "mN", 1e3),
    "pull_off_depth_ctrl": Field("Fc BEM d-ctrl", "N", "mN", 1e3),
    "pull_off_error": Field("Fc err", "-", "%", 100.0),
    "pull_off_2d": Field("Fc 2D x L", "N", "mN", 1e3),
    "pull_off_mdr": Field("Fc MDR", "N", "mN", 1e3),
    "pull_off_mdr_error": Field("MDR err", "-", "%", 100.0),
    "zero_load_half_width": Field("b0 (2D JKR)", "m", "um", 1e6),
    "zero_load_depth": Field("d0 MDR", "m", "um", 1e6),
    "force_adhesive": Field("F adh", "N", "N", 1.0),
    "force_approach": Field("F approach", "N", "N", 1.0),
    "depth_adhesive": Field("d adh", "m", "um", 1e6),
    "radius_adhesive": Field("a adh (MDR)", "m", "um", 1e6),
    "tabor": Field("mu_T", "-", "-", 1.0),
}

notes = {
    "adhesion": "JKR adhesion with work of adhesion w. Fc BEM: pull-off force (negative: "
                "tensile) under force and depth control of the finite cylinder, method "
                "'bem': the adhesive BEM's table (tables/adhesion_cylinder.csv; detachment "
                "where the energy release rate at the contact edge exceeds w) relative to "
                "the 2D JKR value -3 (pi E* R w^2/16)^(1/3) L (Barquins 1988; printed as "
                "Fc 2D x L) for 0.025 <= s = b_c/L <= 0.5, and for 1e-3 <= s < 0.025 the "
                "long roller's end model (tables/adhesion_long_roller.csv: the ends peel "
                "first, the energy release rate of the line-loaded strip's end growing "
                "as ln(L/b); calibrated on the BEM and checked by BEM runs below its "
                "table), Fc err: its stated error (0: the BEM's own, in its table's "
                "header); Fc MDR: method 'mdr', the rule of Hess on the model's MDR "
                "profile (Popov & Hess 2015), force control, MDR err: its error measured "
                "against Fc BEM (not printed where Fc BEM is not given); b0: 2D JKR contact "
                "half-width at zero load (32 R^2 w/(pi E*))^(1/3); d0 MDR: depth at zero "
                "load by the rule of Hess; F adh / d adh: force at the given depth / depth "
                "at the given load with adhesion (rule of Hess, stable branch: the "
                "retraction's), F approach: the approach's force at the given depth (0 "
                "before first contact at d = 0), a adh: the MDR half-length there; "
                "loads and depths <= 0 are on the adhesive curve only (each row's branch "
                "in its flags; beyond the pull-off no contact); mu_T: Tabor "
                "parameter (R w^2/(E*^2 z0^3))^(1/3), z0 = 0.3 nm, JKR needs mu_T > 5.",
}

_MISSING = ("the BEM table adhesion_cylinder is not installed (python -m "
            "tools.build_tables adhesion)")


def resolve(values, present, fail):
    """One contact, elastic body."""
    P, label = present, fail.label
    rows = P["work_of_adhesion"]
    if not rows.any():
        return None
    raceways = np.zeros_like(rows)
    for nm in ("inner_raceway", "outer_raceway", "inner_raceway_diameter",
               "outer_raceway_diameter"):
        if nm in P:
            raceways |= P[nm]
    fail(rows & raceways, "work_of_adhesion",
         "one contact (without the raceways)", "not available for a whole roller")
    visco = np.zeros_like(rows)
    for nm in ("instantaneous_modulus", "long_term_modulus", "relaxation_time", "prony"):
        if nm in P:
            visco |= P[nm]
    fail(rows & visco, "work_of_adhesion", "an elastic body (without "
         f"{label('instantaneous_modulus')}, {label('prony')}, ...)",
         "a viscoelastic pull-off depends on the speed of the receding contact edge, "
         "which the correspondence principle does not give")
    # friction and the stresses are computed without adhesion (their laws are the
    # non-adhesive Hertz/Cattaneo ones): each such row says so
    names = [nm for nm in ("friction", "tangential_load", "stresses", "sliding_friction")
             if nm in P]
    without = ["" if not rows[i] or not any(P[nm][i] for nm in names) else
               ", ".join(label(nm) for nm in names if P[nm][i]) + ": computed without "
               "adhesion (the non-adhesive contact at this load)" for i in range(len(rows))]
    return State(rows, work=values["work_of_adhesion"], given=values["given"],
                 value=values["value"], without=without, signed=rows.copy(),
                 beyond=np.full(len(rows), "", dtype=object))


def columns(model, rows, normal, state):
    """Pull-off (BEM-corrected and MDR), zero load, the force or depth with adhesion and
    the Tabor parameter, for the rows of one contact and one model."""
    from ... import adhesion as ad
    from ...errors import OutOfRangeError

    keep(state, rows, model)
    n = len(rows)
    out = {c: np.full(n, np.nan) for c in fields}
    flags = [""] * n
    out["flags"] = flags

    def note(j, text):
        if text and text not in flags[j]:
            flags[j] = "; ".join(t for t in (flags[j], text) if t)

    sel = np.flatnonzero(state.rows[rows])
    for j in sel:
        r = rows[j]
        note(j, state.without[r])
        w = float(state.work[r])
        mu = float(ad.tabor_parameter(model.radius, w, model.estar))
        out["tabor"][j] = mu
        if mu < ad.TABOR_JKR:
            note(j, short(ad.tabor_note(mu)))
        sub = [""]

        def mdr(_, w=w):
            try:
                c = ad.AdhesiveContact.from_model(model, w)
            except NotImplementedError:
                raise OutOfRangeError("model", model.label, "a model with an MDR "
                                      "profile") from None
            st = _on_curve(c, state.given[r], float(state.value[r]))
            return [c.pull_off("force")["force"], c.zero_load()["depth"],
                    st["force"], st["depth"], st["radius"], st["approach"]], st

        kept = {}

        def values(ii):
            v, st = mdr(ii)
            kept.update(st)
            return v

        v = each(values, np.arange(1), sub, width=6)[0]
        note(j, "MDR: " + short(sub[0]) if sub[0] else "")
        out["pull_off_mdr"][j], out["zero_load_depth"][j] = v[0], v[1]
        out["force_adhesive"][j], out["depth_adhesive"][j] = v[2], v[3]
        out["radius_adhesive"][j], out["force_approach"][j] = v[4], v[5]
        if kept:
            note(j, kept["branch"])
            if kept.get("beyond") and not state.beyond[r]:
                state.beyond[r] = kept["beyond"]
        out["zero_load_half_width"][j] = ad.jkr_cylinder_zero_load_half_width(
            model.radius, model.estar, w)
        if getattr(model, "key", "") not in ad.CYLINDER_MODELS:
            if np.isfinite(out["pull_off_mdr"][j]):
                out["pull_off_mdr"][j] = np.nan
                note(j, "Fc MDR not printed: the rule of Hess's error is measured for a "
                        "straight cylinder only (adhesive BEM), not for this model")
            continue
        sub = [""]

        def bem(_, w=w):
            c = ad.CylinderAdhesion(model, w)
            out2d = [c.s, c.s_range[0], c.pull_off_2d]
            if not c.in_table and c.s < c.long_range[0]:
                return [np.nan, np.nan, np.nan, np.nan] + out2d
            f, d = c.pull_off("force"), c.pull_off("depth")
            return [f["force"], d["force"], f["mdr_error"], max(f["error"], d["error"])
                    ] + out2d

        v = each(bem, np.arange(1), sub, width=7, missing=_MISSING)[0]
        note(j, "Fc (BEM): " + short(sub[0]) if sub[0] else "")
        out["pull_off_force"][j], out["pull_off_depth_ctrl"][j] = v[0], v[1]
        out["pull_off_mdr_error"][j], out["pull_off_error"][j] = v[2], v[3]
        out["pull_off_2d"][j] = v[6]
        if state.given[r] == "load" and state.value[r] < v[0] and np.isfinite(
                out["depth_adhesive"][j]):
            note(j, f"the finite roller's pull-off (BEM) Fc = {_eng(v[0], 'N')} is above "
                    "this load: the MDR's state here is beyond the roller's pull-off")
        if v[4] < v[5] and np.isfinite(v[0]):
            note(j, f"Fc BEM: s = b_c/L = {v[4]:.3g} below the BEM table (s >= {v[5]:g}): "
                    "the long roller's end model, its ends peeling first, with its stated "
                    "error (Fc err)")
        elif v[4] < v[5]:
            note(j, f"Fc BEM: s = b_c/L = {v[4]:.3g} below the long roller's table, not "
                    "given (the ratio to the 2D JKR value keeps falling there); Fc MDR not "
                    "printed: its error is not measured there")
            out["pull_off_mdr"][j] = np.nan
    return out


def _eng(value, unit):
    """A value with the SI prefix that fits it (-2.052 mN, not -0.00205 N)."""
    from ...plot import engineering_unit

    factor, text = engineering_unit([value], unit)
    return f"{value * factor:.4g} {text}"


def _on_curve(c, given, value):
    """The state of the adhesive contact `c` (an AdhesiveContact) at the given load or
    depth, and its branch: dict of ``force`` (the stable branch's: the retraction's),
    ``approach`` (the approach's force under depth control), ``depth``, ``radius``
    (MDR half-length), ``branch`` (the flag) and ``beyond`` (the refusal of a load
    beyond the pull-off, '' otherwise). The values are the library's."""
    nan = np.nan
    if given == "load":
        off = c.pull_off("force")
        if value < off["force"]:
            text = (f"F = {_eng(value, 'N')} is beyond the pull-off Fc = "
                    f"{_eng(off['force'], 'N')} (force control, rule of Hess): no "
                    "equilibrium, the roller detaches")
            return {"force": nan, "approach": nan, "depth": nan, "radius": nan,
                    "branch": "adhesive: " + text, "beyond": text}
        d = float(c.depth_at_force(value))
        branch = ("adhesive: stable branch (force control)" if value >= 0 else
                  "adhesive: stable branch, reached on retraction only (tensile load "
                  "above the pull-off, force control)")
        return {"force": nan, "approach": nan, "depth": d,
                "radius": float(c.radius_at_depth(d)), "branch": branch, "beyond": ""}
    off = c.pull_off("depth")
    if value < off["depth"]:
        return {"force": 0.0, "approach": 0.0, "depth": nan, "radius": nan, "beyond": "",
                "branch": f"adhesive: below the pull-off depth dc = {_eng(off['depth'], 'm')} "
                          "(depth control): no contact on approach or retraction, F = 0"}
    a = float(c.radius_at_depth(value))
    F = float(c.force(a))
    if value < 0:
        return {"force": F, "approach": 0.0, "depth": nan, "radius": a, "beyond": "",
                "branch": "adhesive: retraction branch (in contact down to the pull-off "
                          f"depth dc = {_eng(off['depth'], 'm')}); approach: no contact yet, "
                          "F = 0"}
    return {"force": F, "approach": F, "depth": nan, "radius": a, "beyond": "",
            "branch": "adhesive: stable branch, approach and retraction (depth "
                      "control)"}


#: Adhesive figures drawn at most (a sweep of w: the first values, the rest said).
MAX_FIGURES = 3


def figure(state, results):
    """``--plot``: F(d) of the adhesive contact on approach and retraction with the
    pull-offs (:func:`linecontact.plot.adhesion`: a straight cylinder's with the 2D JKR
    and the finite roller's BEM pull-off beside it), the rows' states marked; one
    panel per work of adhesion of the first contact (at most :data:`MAX_FIGURES`)."""
    from functools import partial

    from ... import adhesion as ad
    from ... import plot
    from ...errors import OutOfRangeError

    kept = getattr(state, "kept", None)
    if kept is None:
        return []
    f = results.sets[0]["fields"]
    rows = [i for i in np.flatnonzero(state.rows) if kept[i] is not None]
    if not rows:
        return []
    m0 = kept[rows[0]]
    groups = {}
    for i in rows:
        if kept[i] is m0:
            groups.setdefault(float(state.work[i]), []).append(i)
    out, said = [], []
    for w, idx in list(groups.items())[:MAX_FIGURES]:
        pts = []
        for i in idx:
            if state.given[i] == "load":
                pts.append((f["depth_adhesive"][i], state.value[i]))
            elif np.isfinite(f["force_adhesive"][i]):
                pts.append((state.value[i], f["force_adhesive"][i]))
        d = np.array([p[0] for p in pts] + list(f["zero_load_depth"][idx] * 2.0))
        d = d[np.isfinite(d) & (d > 0)]
        if not d.size:
            said.append(f"--plot: adhesion (w = {w:g} J/m^2): no depth > 0 to draw "
                        "the cycle to")
            continue
        try:
            c = (ad.CylinderAdhesion(m0, w) if getattr(m0, "key", "") in ad.CYLINDER_MODELS
                 else ad.AdhesiveContact.from_model(m0, w))
        except (OutOfRangeError, NotImplementedError) as exc:
            said.append(f"--plot: adhesion (w = {w:g} J/m^2): no figure: "
                        f"{short(str(exc)) or type(exc).__name__}")
            continue
        out.append(partial(plot.adhesion, c, float(d.max()), points=pts))
        beyond = sum(1 for i in idx if state.beyond[i])
        if beyond:
            said.append(f"--plot: adhesion (w = {w:g} J/m^2): {beyond} row(s) beyond the "
                        "pull-off (no equilibrium) are not drawn")
    if len(groups) > MAX_FIGURES:
        said.append(f"--plot: adhesion drawn for the first {MAX_FIGURES} of "
                    f"{len(groups)} values of w (every row is in the table)")
    others = len(rows) - sum(len(v) for v in groups.values())
    if others:
        said.append(f"--plot: adhesion drawn for the first contact; {others} row(s) of "
                    "other contacts are in the table only")
    return out + said


def blocks(state, results):
    """No extra table. A load beyond the pull-off (no equilibrium) is the row's error
    in one case and in a batch (its row); a sweep's row keeps it in its flags (the
    sweep shows where the retraction ends)."""
    label = results.label
    if len(results.errors) > 1 and label("load").startswith("--"):
        return []

    def cell(nm, i):
        col = results.cases.cells.get(nm)
        return (f"{float(col[i]):g}" if isinstance(col, np.ndarray)
                else str(col[i]).strip())

    for i in np.flatnonzero(state.beyond != ""):
        if not results.errors[i]:
            results.errors[i] = (f"{label('load')} = {cell('load', i)!r}: {state.beyond[i]}"
                                 f"; valid: a load >= the pull-off with "
                                 f"{label('work_of_adhesion')} = "
                                 f"{cell('work_of_adhesion', i)!r}")
    return []
