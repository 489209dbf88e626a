"""Feature: a whole roller between two raceways (``--inner-raceway``, ``--outer-raceway``).

The force F [N] passes through two contacts in series: roller on the inner raceway
(1/R = 1/R1 + 1/Ri) and roller in the outer raceway (1/R = 1/R1 - 1/Ro), both of the
roller's length L and the same E*. The roller's deflection is the sum of the two contact
depths, delta = d_i(F) + d_o(F), and its stiffness the series value
k = 1 / (1/k_i + 1/k_o) [N/m], printed in their own columns (``roller_deflection``,
``roller_stiffness``) apart from the per-contact depth of a single contact. Each contact
is a cylinder of the effective radius on a half-space, Hertz's reduction for two
parallel cylinders (Johnson 1985, Sec. 4.2) applied to the finite-length models.
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, flag_text

__all__: list = []

name = "raceways"
group = "whole roller between two raceways (instead of --radius2)"

parameters = (
    Parameter("inner_raceway", "length", "radius Ri of the inner raceway (convex)", group),
    Parameter("outer_raceway", "length", "radius Ro of the outer raceway (concave; "
              "give it positive)", group),
)

fields = {
    "roller_deflection": Field("delta roller", "m", "um", 1e6),
    "roller_stiffness": Field("k roller", "N/m", "N/um", 1e-6),
    "depth_inner": Field("d inner", "m", "um", 1e6),
    "depth_outer": Field("d outer", "m", "um", 1e6),
    "peak_pressure_inner": Field("p0 inner", "Pa", "MPa", 1e-6),
    "peak_pressure_outer": Field("p0 outer", "Pa", "MPa", 1e-6),
}

notes = {
    "roller": "whole roller: roller_deflection = d(inner contact) + d(outer contact) at "
              "the same force, roller_stiffness the two contacts in series; depth_inner "
              "and depth_outer are the two contacts' own depths (what a single-contact "
              "row reports as its depth).",
}


def resolve(values, present, fail):
    """Both raceways or neither; not with --radius2 or --depth; the roller fits."""
    P, v, label = present, values, fail.label
    rows = P["inner_raceway"] | P["outer_raceway"]
    if not rows.any():
        return None
    both = f"{label('inner_raceway')} and {label('outer_raceway')} together"
    fail(P["inner_raceway"] & ~P["outer_raceway"], "outer_raceway", both,
         f"missing (needed with {label('inner_raceway')})")
    fail(P["outer_raceway"] & ~P["inner_raceway"], "inner_raceway", both,
         f"missing (needed with {label('outer_raceway')})")
    fail(rows & P["radius2"], "radius2",
         f"either {label('radius2')} (one contact) or the raceways (a whole roller)",
         "conflicts with the raceways")
    fail(rows & P["depth"], "depth",
         f"{label('load')} with the raceways (the two contacts share the force)",
         "a depth cannot be split between two contacts")
    R1 = v["radius"]
    with np.errstate(invalid="ignore", divide="ignore"):
        outer_ok = v["outer_raceway"] > R1
        fail(rows & P["outer_raceway"] & ~outer_ok, "outer_raceway",
             f"{label('outer_raceway')} > roller radius",
             "the roller does not fit inside the outer raceway")
        r_in = 1 / (1 / R1 + 1 / v["inner_raceway"])
        r_out = 1 / (1 / R1 - 1 / v["outer_raceway"])
    return State(rows, radius_eff=np.where(rows, r_in, np.nan), radius_outer=r_out,
                 whole=rows, compared="roller_deflection")


def columns(model, rows, normal, state):
    """The whole roller: the core evaluated the inner contact; the outer one here."""
    from ...classical import hertz_half_width, hertz_peak_pressure

    R_out = float(state.radius_outer[rows[0]])
    outer = model.at(R_out)
    F = normal["force"]
    ok = np.isfinite(F) & (F > 0)
    d_out = np.full(F.shape, np.nan)
    k_out = np.full(F.shape, np.nan)
    flags = [""] * len(rows)
    from ...validity import OutOfRangeError

    if ok.any():
        try:
            r = outer.evaluate(force=F[ok])
            d_out[ok], k_out[ok] = r["depth"], r["stiffness"]
        except OutOfRangeError as exc:
            for j in np.flatnonzero(ok):
                flags[j] = f"outer contact: {str(exc).split('; ')[0]}"
    L, E = model.length, model.estar
    with np.errstate(divide="ignore", invalid="ignore"):
        F1 = np.where(ok, F, 1.0)
        p_in = np.where(ok, hertz_peak_pressure(F1, model.radius, L, E), np.nan)
        p_out = np.where(ok, hertz_peak_pressure(F1, R_out, L, E), np.nan)
        b_in = np.where(ok, hertz_half_width(F1, model.radius, L, E), np.nan)
        b_out = np.where(ok, hertz_half_width(F1, R_out, L, E), np.nan)
        for j in range(len(rows)):
            text = "; ".join(t for t in (
                flag_text(normal["depth"][j], b_in[j], model.radius, L, " (inner)"),
                flag_text(d_out[j], b_out[j], R_out, L, " (outer)"), flags[j]) if t)
            flags[j] = text
        return {
            "roller_deflection": normal["depth"] + d_out,
            "roller_stiffness": 1 / (1 / normal["stiffness"] + 1 / k_out),
            "depth_inner": normal["depth"],
            "depth_outer": d_out,
            "peak_pressure_inner": p_in,
            "peak_pressure_outer": p_out,
            "flags": flags,
        }


def blocks(state, results):
    """No extra table."""
    return []
