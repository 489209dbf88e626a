"""Feature: adhesive contact (``--work-of-adhesion``).

``--work-of-adhesion W`` (J/m^2, mJ/m^2, N/m; a sweep too)
    JKR-type adhesion (linecontact.adhesion): the pull-off force under force and under
    depth control, for a straight cylinder from the adhesive BEM table (method 'bem',
    :class:`linecontact.adhesion.CylinderAdhesion`, tables/adhesion_cylinder.csv; inside
    its range of s = b_c/L only) and by the MDR's rule of Hess on the row's model
    (method 'mdr': its plain value, with the error the BEM measured); the state at zero load (the 2D JKR half-width and the MDR's depth);
    the depth at the given load, or the force at the given depth, with adhesion (rule
    of Hess, stable branch); and the Tabor parameter (z0 = 0.3 nm), flagged where JKR
    does not apply. One contact only (not with the raceways); not with a viscoelastic
    body (between the relaxed and the instantaneous limit the pull-off depends on the
    speed of the receding edge, which the correspondence principle does not give).
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, each, short

__all__: list = []

name = "adhesion"
group = "adhesion (one contact)"

parameters = (
    Parameter("work_of_adhesion", "surface_energy", "work of adhesion w (J/m^2, mJ/m^2): "
              "adds the pull-off force (force and depth control), the contact at zero "
              "load and the force or depth with adhesion (JKR)", group),
)

fields = {
    "pull_off_force": Field("Fc BEM F-ctrl", "N", "mN", 1e3),
    "pull_off_depth_ctrl": Field("Fc BEM d-ctrl", "N", "mN", 1e3),
    "pull_off_mdr": Field("Fc MDR", "N", "mN", 1e3),
    "pull_off_mdr_error": Field("MDR err", "-", "%", 100.0),
    "zero_load_half_width": Field("b0 (2D JKR)", "m", "um", 1e6),
    "zero_load_depth": Field("d0 MDR", "m", "um", 1e6),
    "force_adhesive": Field("F adh", "N", "N", 1.0),
    "depth_adhesive": Field("d adh", "m", "um", 1e6),
    "tabor": Field("mu_T", "-", "-", 1.0),
}

notes = {
    "adhesion": "JKR adhesion with work of adhesion w. Fc BEM: pull-off force (negative: "
                "tensile) under force and depth control of the finite cylinder, method "
                "'bem': the adhesive BEM's table (tables/adhesion_cylinder.csv; detachment "
                "where the energy release rate at the contact edge exceeds w) relative to "
                "the 2D JKR value -3 (pi E* R w^2/16)^(1/3) L (Barquins 1988), given for "
                "0.025 <= s = b_c/L <= 0.5 only; "
                "Fc MDR: method 'mdr', the rule of Hess on the model's MDR profile (Popov & "
                "Hess 2015), force control, MDR err: its error measured against the BEM "
                "(inside the table only); b0: 2D JKR contact "
                "half-width at zero load (32 R^2 w/(pi E*))^(1/3); d0 MDR: depth at zero "
                "load by the rule of Hess; F adh / d adh: force at the given depth / depth "
                "at the given load with adhesion (rule of Hess, stable branch); mu_T: Tabor "
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
    return State(rows, work=values["work_of_adhesion"], given=values["given"],
                 value=values["value"])


def columns(model, rows, normal, state):
    """Pull-off (BEM-corrected and MDR), zero load, the force or depth with adhesion and
    the Tabor parameter, for the rows of one contact and one model."""
    from ... import adhesion as ad
    from ...errors import OutOfRangeError

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
            res = [c.pull_off("force")["force"], c.zero_load()["depth"]]
            if state.given[r] == "depth":
                res += [c.force_at_depth(float(state.value[r])), np.nan]
            else:
                res += [np.nan, c.depth_at_force(float(state.value[r]))]
            return res

        v = each(mdr, np.arange(1), sub, width=4)[0]
        note(j, "MDR: " + short(sub[0]) if sub[0] else "")
        out["pull_off_mdr"][j], out["zero_load_depth"][j] = v[0], v[1]
        out["force_adhesive"][j], out["depth_adhesive"][j] = v[2], v[3]
        out["zero_load_half_width"][j] = ad.jkr_cylinder_zero_load_half_width(
            model.radius, model.estar, w)
        if getattr(model, "key", "") not in ad.CYLINDER_MODELS:
            continue
        sub = [""]

        def bem(_, w=w):
            c = ad.CylinderAdhesion(model, w)
            if not c.in_table:
                return [np.nan, np.nan, np.nan, c.s, c.s_range[0]]
            f, d = c.pull_off("force"), c.pull_off("depth")
            return [f["force"], d["force"], f["mdr_error"], c.s, c.s_range[0]]

        v = each(bem, np.arange(1), sub, width=5, missing=_MISSING)[0]
        note(j, "Fc (BEM): " + short(sub[0]) if sub[0] else "")
        out["pull_off_force"][j], out["pull_off_depth_ctrl"][j] = v[0], v[1]
        out["pull_off_mdr_error"][j] = v[2]
        if v[3] < v[4]:
            note(j, f"Fc BEM: s = b_c/L = {v[3]:.3g} below the BEM table (s >= {v[4]:g}), "
                    "not given: the roller's ratio to the 2D JKR value falls there (its "
                    "ends peel first); Fc MDR's error not measured there")
    return out


def blocks(state, results):
    """No extra table."""
    return []
