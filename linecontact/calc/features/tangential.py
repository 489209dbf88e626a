"""Feature: tangential contact (``--friction``, ``--tangential-load``).

``--friction MU``
    Coulomb friction coefficient: adds the full-stick tangential stiffness of the MDR,
    k_t = (G*/E*) k_n (:func:`linecontact.tangential.tangential_stiffness`), and the
    finite cylinder's own values across and along the axis from the BEM table
    (:func:`linecontact.tangential.cylinder_stiffness_ratios`; "-" with a note where
    the table is not installed or the case is outside it). G* needs the moduli and
    Poisson's ratios (not ``--estar``).
    For a crowned roller (``--crown-radius``) whose Hertz ellipse lies inside it, the
    values across and along are Mindlin's for the ellipse, and for any other roller
    solved by slices those of the equivalent ellipse of its footprint
    (:meth:`linecontact.contact.Contact.tangential`, :mod:`linecontact.mindlin`), with
    the error measured in tables/tangential_profiles.csv in the notes: the calculator
    prints both directions, so it takes no direction option.
``--tangential-load Q`` (a force or a sweep; needs ``--friction``)
    The tangential shift u of the Cattaneo-Mindlin law at the given normal force or
    depth, held constant (:func:`linecontact.tangential.tangential_shift`) with the MDR's
    G*/E* and with the BEM's ratio in each direction (times the table's partial-slip
    correction of the shift, when it has one: as ``TangentialContact(...,
    method="bem")``), Q/(mu F), and the slip state in the flags: partial slip for
    |Q| < mu F, gross slip (no static solution: u is "-") for |Q| > mu F. The sign of Q
    is its direction: u has the sign of Q.
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, each, keep, short

__all__: list = []

name = "tangential"
group = "tangential contact (one contact)"

parameters = (
    Parameter("friction", "dimensionless", "Coulomb friction coefficient mu: adds the "
              "full-stick tangential stiffness across and along the axis (BEM) and the "
              "MDR's", group),
    Parameter("tangential_load", "force", "tangential force Q at constant normal load "
              "(its sign is its direction), or a sweep START:STOP:N: the shift and the "
              "slip state (needs --friction)", group, positive=False),
)

#: Output columns, in display order: with --friction, and with --tangential-load.
FRICTION_COLUMNS = ("kt_mdr", "kt_across", "kt_along")
LOAD_COLUMNS = ("tangential_load", "slip_fraction", "shift_mdr", "shift_across",
                "shift_along")

fields = {
    "kt_mdr": Field("kt MDR", "N/m", "N/um", 1e-6),
    "kt_across": Field("kt across", "N/m", "N/um", 1e-6),
    "kt_along": Field("kt along", "N/m", "N/um", 1e-6),
    "tangential_load": Field("Q", "N", "kN", 1e-3),
    "slip_fraction": Field("Q/(mu F)", "-", "%", 100.0),
    "shift_mdr": Field("u MDR", "m", "um", 1e6),
    "shift_across": Field("u across", "m", "um", 1e6),
    "shift_along": Field("u along", "m", "um", 1e6),
}

notes = {
    "tangential": "kt: full-stick tangential stiffness; MDR: (G*/E*) k (Popov & Hess 2015, "
                  "exact for axisymmetric contacts); across (rolling direction) and along "
                  "the axis: the finite cylinder's BEM ratio k_t/k_n (tables/"
                  "tangential_cylinder.csv) times k, or for a crowned roller whose Hertz "
                  "ellipse lies inside it Mindlin's ratio of the ellipse (Mindlin 1949) "
                  "times k, or for another roller solved by slices Mindlin's ratio of the "
                  "equivalent ellipse (the footprint's half-length and k) times k; u: "
                  "tangential shift under Q at "
                  "constant normal force or depth, u = (mu/r) [d - d(F - |Q|/mu)] sign(Q) "
                  "with r = G*/E* (MDR) or the BEM ratio, times the table's partial-slip "
                  "correction across/along (Cattaneo 1938, Mindlin 1949); gross slip at "
                  "|Q| = mu F. Uncoupled normal and tangential problems (Goodman).",
}

_MISSING = ("the BEM table tangential_cylinder is not installed (python -m "
            "tools.build_tables tangential)")


def resolve(values, present, fail):
    """Friction needs the moduli (G*), one contact; a tangential load needs friction."""
    P, label = present, fail.label
    rows = P["friction"] | P["tangential_load"]
    if not rows.any():
        return None
    raceways = P["inner_raceway"] | P["outer_raceway"]
    for nm in ("friction", "tangential_load"):
        fail(P[nm] & raceways, nm, "one contact (without the raceways)",
             "not available for a whole roller")
    fail(P["friction"] & P["estar"], "friction",
         f"with {label('modulus')} and {label('poisson')} (G* needs Poisson's ratio), not "
         f"{label('estar')}", "G* unknown")
    fail(P["tangential_load"] & ~P["friction"], "tangential_load",
         f"with {label('friction')}", "no friction coefficient given")
    v = values
    # --friction (Coulomb, for the partial slip above) is not the sliding friction of
    # the stresses (full sliding, q = mu p): a row with both --friction and the
    # stresses but no --sliding-friction says which coefficient its stresses used
    stresses = np.array([bool(P["stresses"][i]) and fail.cell("stresses", i).strip()
                         .lower() not in ("no", "false", "0") for i in range(len(rows))],
                        dtype=bool) if "stresses" in P else np.zeros_like(rows)
    unslid = P["friction"] & stresses & ~P.get("sliding_friction", np.zeros_like(rows))
    return State(rows, friction=v["friction"], tangential_load=v["tangential_load"],
                 unslid=unslid, unslid_note=(
                     f"the stresses are frictionless: {label('friction')} is the Coulomb "
                     "coefficient of the partial slip (stick zone, Cattaneo-Mindlin), not "
                     f"the full sliding of the stresses; give {label('sliding_friction')} "
                     "for them"),
                 loaded=P["tangential_load"], friction_given=P["friction"],
                 e1=v["modulus"], nu1=v["poisson"],
                 e2=np.where(P["modulus2"], v["modulus2"], np.inf),
                 nu2=np.where(P["poisson2"], v["poisson2"], 0.0),
                 any_load=bool(P["tangential_load"].any()))


def columns(model, rows, normal, state):
    """k_t (MDR, BEM across and along) and, under a tangential load, the shift and the
    slip state, for the rows of one contact and one model."""
    from ... import tangential as tg

    n = len(rows)
    out = {c: np.full(n, np.nan) for c in FRICTION_COLUMNS + (
        LOAD_COLUMNS if state.any_load else ())}
    flags = [""] * n
    out["flags"] = flags
    keep(state, rows, model)
    F, d, k = normal["force"], normal["depth"], normal["stiffness"]
    ok = np.isfinite(d) & (d > 0) & np.isfinite(F)

    def note(j, text):
        if text and text not in flags[j]:
            flags[j] = "; ".join(t for t in (flags[j], text) if t)

    for j in np.flatnonzero(state.unslid[rows]):
        note(j, state.unslid_note)
    sel = np.flatnonzero(state.friction_given[rows] & ok)
    if not sel.size:
        return out
    if model.contact is not None:  # a composed contact: the library's own tangential law
        _composed(model.contact, rows, sel, F, state, out, note)
        return out
    r = rows[sel]
    gstar = np.atleast_1d(tg.effective_shear_modulus(state.e1[r], state.nu1[r],
                                                     state.e2[r], state.nu2[r]))
    out["kt_mdr"][sel] = gstar / model.estar * k[sel]
    sub = [""] * sel.size

    def ratios(ii):
        rr = tg.cylinder_stiffness_ratios(model, d[sel][ii], gstar[ii])
        return np.stack([np.atleast_1d(rr["across"]), np.atleast_1d(rr["along"])], axis=1)

    both = each(ratios, np.arange(sel.size), sub, width=2, missing=_MISSING)
    bem = {"across": both[:, 0], "along": both[:, 1]}
    for j, t in zip(sel, sub):
        note(j, "kt across/along: " + short(t) if t else "")
    out["kt_across"][sel] = bem["across"] * k[sel]
    out["kt_along"][sel] = bem["along"] * k[sel]
    tl = state.loaded[r]
    if not tl.any():
        return out
    s2 = sel[tl]
    r2 = rows[s2]
    Q = state.tangential_load[r2]
    mu = state.friction[r2]
    out["tangential_load"][s2] = Q
    frac = Q / (mu * F[s2])
    out["slip_fraction"][s2] = frac
    partial = np.abs(frac) <= 1.0 + 1e-12
    for j, fq in zip(s2, np.abs(frac)):
        note(j, "partial slip" if fq < 1.0 - 1e-12 else
             "gross slip onset: |Q| = mu F" if fq <= 1.0 + 1e-12 else
             "gross slip: |Q| > mu F, the contact slides (no static shift)")
    if not partial.any():
        return out
    s3 = s2[partial]
    r3 = rows[s3]
    gs = gstar[tl][partial]
    Q3 = state.tangential_load[r3]
    out["shift_mdr"][s3] = tg.tangential_shift(model, d[s3], Q3, state.friction[r3], gs)
    for direction in ("across", "along"):
        ratio = bem[direction][tl][partial]
        good = np.isfinite(ratio)
        if good.any():
            u = np.atleast_1d(tg.tangential_shift(
                model, d[s3][good], Q3[good], state.friction[r3[good]], gs[good],
                ratio=ratio[good]))
            u = u * _slip_correction(model, direction, d[s3][good], gs[good],
                                     np.abs(frac[partial][good]))
            out[f"shift_{direction}"][s3[good]] = u
    return out


def _composed(contact, rows, sel, F, state, out, note):
    """k_t, Q/(mu F) and the shift of a composed contact (a profiled or tilted roller):
    :meth:`linecontact.contact.Contact.tangential`, the MDR on the contact's own F(d);
    the BEM table's across/along values are for a straight, aligned cylinder only."""
    from ...errors import CombinationError, OutOfRangeError

    for j in sel:
        i = rows[j]
        Q = float(state.tangential_load[i]) if state.loaded[i] else None
        try:
            t = contact.tangential(float(state.friction[i]), force=float(F[j]),
                                   tangential_force=Q, method="mdr")
        except (CombinationError, OutOfRangeError) as exc:
            note(j, f"kt: {short(str(exc))}")
            continue
        out["kt_mdr"][j] = t.stiffness
        _directions(contact, float(state.friction[i]), float(F[j]), Q, j, out, note)
        if Q is None:
            continue
        out["tangential_load"][j] = Q
        out["slip_fraction"][j] = np.sign(Q) * t.slip_fraction
        if t.shift is not None:
            out["shift_mdr"][j] = t.shift
        note(j, {"gross slip": "gross slip: |Q| >= mu F, the contact slides (no static "
                 "shift)" if t.shift is None else "gross slip onset: |Q| = mu F"}.get(
                     str(t.state), str(t.state)))


def _directions(contact, mu, F, Q, j, out, note):
    """k_t (and the shift under Q) across and along the axis of a composed contact where
    the library has a law by direction (the default of
    :meth:`linecontact.contact.Contact.tangential`: a crowned roller's Mindlin ellipse,
    any other sliced profile's equivalent ellipse), with the library's notes; "-" with
    the reason elsewhere."""
    methods = set()
    for direction in ("across", "along"):
        t = contact.tangential(mu, force=F, tangential_force=Q, direction=direction)
        if t.method not in ("mindlin", "ellipse"):
            note(j, "kt across/along: the law by direction is for a roller solved by "
                    "slices (a straight cylinder's law: method='bem')")
            return
        methods.add(t.method)
        if t.notes:
            note(j, f"kt {direction}: " + "; ".join(t.notes))
        out[f"kt_{direction}"][j] = t.stiffness
        if Q is not None and t.shift is not None:
            out[f"shift_{direction}"][j] = t.shift
    note(j, "kt/u across/along: " + ("Mindlin's Hertz ellipse (crowned roller)"
                                     if methods == {"mindlin"} else
                                     "the equivalent ellipse of the footprint"))


def _slip_correction(model, direction, depth, gstar, q):
    """The BEM table's partial-slip shift factor at load fractions q (1 without one),
    as in :class:`linecontact.tangential.TangentialContact` with method="bem"."""
    from ... import tangential as tg

    table = tg.cylinder_tangential_table()
    nu = tg.equivalent_poisson(gstar, model.estar)
    return np.atleast_1d(table.shift_factor(direction, nu,
                                            depth * model.radius / model.length ** 2, q))


#: Normal states drawn at most (a sweep of the normal load: the first, the rest said).
MAX_FIGURES = 3


def _laws(model, mu, gstar, force):
    """The tangential laws drawn for one normal state: the finite cylinder's BEM law
    across and along (:class:`linecontact.tangential.TangentialContact`,
    ``method="bem"``), or the MDR's where the table does not answer (its reason)."""
    from ... import tangential as tg
    from ...errors import OutOfRangeError

    try:
        return [tg.TangentialContact(model, mu, gstar, force=force, method="bem",
                                     direction=direction)
                for direction in ("across", "along")], ""
    except (OutOfRangeError, FileNotFoundError) as exc:
        why = short(str(exc)) if isinstance(exc, OutOfRangeError) else _MISSING
        return [tg.TangentialContact(model, mu, gstar, force=force)], why


def figure(state, results):
    """``--plot``: F_t(u) from stick to gross slip and the fretting loop
    (:func:`linecontact.plot.hysteresis`) across and along the axis (the BEM table's
    law; the MDR's where the table does not answer), the rows' (u, Q) marked, at the
    amplitude of the largest computed shift (else half the smallest gross-slip shift);
    one panel per normal state of the first contact (at most :data:`MAX_FIGURES`). A
    composed contact (a profiled roller) is said, not drawn."""
    from functools import partial

    from ... import plot
    from ... import tangential as tg

    kept = getattr(state, "kept", None)
    if kept is None:
        return []
    f = results.sets[0]["fields"]
    rows = [i for i in np.flatnonzero(state.friction_given) if kept[i] is not None
            and np.isfinite(f["force"][i]) and f["force"][i] > 0]
    if not rows:
        return []
    m0 = kept[rows[0]]
    if m0.contact is not None:
        return ["--plot: tangential: no figure for a composed contact's law (a profiled "
                "or tilted roller): its k_t and shifts are in the table"]
    groups = {}
    for i in rows:
        if kept[i] is m0:
            groups.setdefault((float(f["force"][i]), float(state.friction[i])),
                              []).append(i)
    out, said = [], []
    for (F, mu), idx in list(groups.items())[:MAX_FIGURES]:
        i0 = idx[0]
        gstar = float(tg.effective_shear_modulus(state.e1[i0], state.nu1[i0],
                                                 state.e2[i0], state.nu2[i0]))
        laws, why = _laws(m0, mu, gstar, F)
        if why:
            said.append(f"--plot: tangential: the MDR's law (G*/E*), the BEM's across "
                        f"and along not available: {why}")
        name = "across" if len(laws) == 2 else "mdr"
        u = np.array([f[f"shift_{name}"][i] if f"shift_{name}" in f else np.nan
                      for i in idx])
        Q = np.array([state.tangential_load[i] for i in idx])
        ustar = min(float(c.gross_slip_shift) for c in laws)
        good = np.isfinite(u)
        amp = min(float(np.max(np.abs(u[good]))), ustar) if good.any() else 0.5 * ustar
        if not amp > 0:
            amp = 0.5 * ustar
        pts = list(zip(u[good], Q[good])) or None
        out.append(partial(plot.hysteresis, laws, amp, points=pts))
    if len(groups) > MAX_FIGURES:
        said.append(f"--plot: tangential drawn for the first {MAX_FIGURES} of "
                    f"{len(groups)} normal states (every row is in the table)")
    others = len(rows) - sum(len(v) for v in groups.values())
    if others:
        said.append(f"--plot: tangential drawn for the first contact; {others} row(s) of "
                    "other contacts are in the table only")
    return out + said


def blocks(state, results):
    """No extra table."""
    return []
