"""The calculator's tangential and viscoelastic inputs and columns (``linecontact calc``).

Inputs (declared in :data:`linecontact.cases.PARAMETERS`, groups "tangential contact"
and "viscoelastic second body"):

``--friction MU``
    Coulomb friction coefficient: adds the full-stick tangential stiffness of the MDR,
    k_t = (G*/E*) k_n (:func:`linecontact.tangential.tangential_stiffness`), and the
    finite cylinder's own values across and along the axis from the BEM table
    (:func:`linecontact.tangential.cylinder_stiffness_ratios`; "-" with a note where
    the table is not installed or the case is outside it). G* needs the moduli and
    Poisson's ratios (not ``--estar``).
``--tangential-load Q`` (a force or a sweep; needs ``--friction``)
    The tangential shift u of the Cattaneo-Mindlin law at the given normal force or
    depth, held constant (:func:`linecontact.tangential.tangential_shift`) with the MDR's G*/E* and with the
    BEM's ratio in each direction (times the table's partial-slip correction of the
    shift, when it has one: as ``TangentialContact(..., method="bem")``), Q/(mu F),
    and the slip state in the flags: partial slip for Q < mu F, gross slip (no static
    solution: u is "-") for Q > mu F.
``--instantaneous-modulus E0 --long-term-modulus EINF --relaxation-time TAU``, or
``--prony FILE.csv`` (columns tau_s, E_Pa and a ``# E_inf: VALUE`` line)
    A viscoelastic second body (instead of ``--modulus``; needs ``--poisson``) with the
    Young's moduli of a standard linear solid or a Prony series
    (:mod:`linecontact.viscoelastic`; every value in the file is a number with at most
    one unit name, bare = SI, by the rule of the command line). The elastic columns are then the instantaneous
    response (E* from E0); ``d(inf)`` is the long-term depth.
``--time T`` (a time or a sweep; with ``--load``)
    The depth after the load has been held for T (creep, Lee & Radok 1960):
    d(t) = F1^-1(F J*(t)), :func:`linecontact.viscoelastic.step_creep_depth`, with the
    creep function of the effective modulus J*(t) = (1 - nu1^2) J1(t) + (1 - nu2^2)/E2
    (the compliances of the two bodies add; a rigid roller has no second term).

Not combined: the tangential and viscoelastic options with the raceways (a whole
roller), the friction options with a viscoelastic body.
"""
from __future__ import annotations

import re

import numpy as np

__all__: list = []

#: Output columns of this module, in display order (names of compute.FIELDS).
FRICTION_COLUMNS = ("kt_mdr", "kt_across", "kt_along")
LOAD_COLUMNS = ("tangential_load", "slip_fraction", "shift_mdr", "shift_across",
                "shift_along")
CREEP_COLUMNS = ("time", "creep_depth")
VISCO_COLUMNS = ("depth_long_term",)
ALL_COLUMNS = FRICTION_COLUMNS + LOAD_COLUMNS + CREEP_COLUMNS + VISCO_COLUMNS

NOTES = {
    "tangential": "kt: full-stick tangential stiffness; MDR: (G*/E*) k (Popov & Hess 2015, "
                  "exact for axisymmetric contacts); across (rolling direction) and along "
                  "the axis: the finite cylinder's BEM ratio k_t/k_n (tables/"
                  "tangential_cylinder.csv) times k; u: tangential shift under Q at "
                  "constant normal force or depth, u = (mu/r) [d - d(F - Q/mu)] with "
                  "r = G*/E* (MDR) or the BEM ratio, times the table's partial-slip "
                  "correction across/along (Cattaneo 1938, Mindlin 1949); gross slip at "
                  "Q = mu F. Uncoupled normal and tangential problems (Goodman).",
    "creep": "d(t): depth after the normal load has been held for t (Lee & Radok 1960, "
             "exact while the contact grows), d(t) = F1^-1(F J*(t)); d(inf): long-term "
             "depth; the other columns are the instantaneous response (E* from E0).",
}


class _Material:
    """Creep function of the effective modulus: (1 - nu1^2) J1(t) + (1 - nu2^2)/E2."""

    def __init__(self, body, poisson, modulus2, poisson2):
        self.body = body
        self.factor = 1.0 - poisson ** 2
        self.rigid = 0.0 if not np.isfinite(modulus2) else (1.0 - poisson2 ** 2) / modulus2

    def creep(self, t):
        return self.factor * np.asarray(self.body.creep(t)) + self.rigid

    @property
    def long_term_compliance(self):
        return self.factor / self.body.long_term + self.rigid


def resolve(v, P, raw, fail, label, n):
    """Rules between the issue-10 inputs (one message per offending row, through `fail`).

    Returns (visco, E0, materials): the rows with a viscoelastic second body, its
    instantaneous Young's modulus [Pa] (NaN elsewhere) and the body per row (a
    :class:`~linecontact.viscoelastic.PronySeries`, or None).
    """
    from ._units import range_error_parts
    from .validity import OutOfRangeError
    from .viscoelastic import StandardLinearSolid, read_prony_series

    sls_names = ("instantaneous_modulus", "long_term_modulus", "relaxation_time")
    sls_any = P[sls_names[0]] | P[sls_names[1]] | P[sls_names[2]]
    sls_all = P[sls_names[0]] & P[sls_names[1]] & P[sls_names[2]]
    visco = sls_any | P["prony"]
    three = ", ".join(label(s) for s in sls_names)
    for name in sls_names:
        fail(sls_any & ~P[name], name, f"{three} together (a standard linear solid)",
             "missing")
    fail(P["prony"] & sls_any, "prony",
         f"either {label('prony')} or {three}, not both", "conflicts with the standard "
         "linear solid options", lambda i: raw["prony"][i])
    fail(visco & P["modulus"], "modulus",
         f"either {label('modulus')} (elastic) or the viscoelastic options",
         "conflicts with the viscoelastic options", lambda i: raw["modulus"][i])
    fail(visco & P["estar"], "estar",
         f"the viscoelastic options with {label('poisson')}, not {label('estar')}",
         "conflicts with the viscoelastic options", lambda i: raw["estar"][i])
    fail(visco & ~P["poisson"], "poisson", "a number in [0, 0.5]",
         "missing (needed with the viscoelastic options)")
    fail(P["time"] & ~visco, "time",
         f"with a viscoelastic body ({three}, or {label('prony')})",
         "no viscoelastic material given", lambda i: raw["time"][i])
    fail(P["time"] & ~P["load"], "time", f"with {label('load')} (creep under a held force)",
         "no force given", lambda i: raw["time"][i])
    with np.errstate(invalid="ignore"):
        fail(P["time"] & ~(v["time"] >= 0), "time", "a time >= 0 (e.g. 10s, 5min, 0)",
             "negative", lambda i: raw["time"][i])
        fail(sls_all & ~(v["long_term_modulus"] < v["instantaneous_modulus"]),
             "long_term_modulus", f"below {label('instantaneous_modulus')}",
             "not below the instantaneous modulus", lambda i: raw["long_term_modulus"][i])
    raceways = P["inner_raceway"] | P["outer_raceway"]
    for name in ("friction", "tangential_load", "time"):
        fail(P[name] & raceways, name, "one contact (without the raceways)",
             "not available for a whole roller", lambda i, nm=name: raw[nm][i])
    fail(visco & raceways, "inner_raceway", "one contact (without the raceways)",
         "a viscoelastic body is not available for a whole roller",
         lambda i: raw["inner_raceway"][i])
    fail(P["friction"] & visco, "friction", "an elastic second body",
         "not combined with a viscoelastic body", lambda i: raw["friction"][i])
    fail(P["friction"] & P["estar"], "friction",
         f"with {label('modulus')} and {label('poisson')} (G* needs Poisson's ratio), not "
         f"{label('estar')}", "G* unknown", lambda i: raw["friction"][i])
    fail(P["tangential_load"] & ~P["friction"], "tangential_load",
         f"with {label('friction')}", "no friction coefficient given",
         lambda i: raw["tangential_load"][i])

    E0 = np.full(n, np.nan)
    materials = np.full(n, None, dtype=object)
    sls = sls_all & ~P["prony"]
    cache = {}
    for i in np.flatnonzero(sls):
        key = (v[sls_names[0]][i], v[sls_names[1]][i], v[sls_names[2]][i])
        if key not in cache:
            try:
                cache[key] = StandardLinearSolid(*key)
            except OutOfRangeError as exc:
                cache[key] = (exc.valid, str(exc))
        _store(cache[key], i, E0, materials, fail, "relaxation_time", raw)
    files = {}
    for i in np.flatnonzero(P["prony"] & ~sls_any):
        path = raw["prony"][i].strip()
        if path not in files:
            try:
                files[path] = read_prony_series(path)
            except OutOfRangeError as exc:
                files[path] = range_error_parts(exc)
            except OSError as exc:
                files[path] = ("a readable CSV file (tau_s, E_Pa, '# E_inf: VALUE')",
                               exc.strerror or type(exc).__name__)
            except UnicodeDecodeError as exc:
                files[path] = ("a UTF-8 text CSV file (tau_s, E_Pa, '# E_inf: VALUE')",
                               f"not UTF-8 text ({exc.reason} at byte {exc.start})")
            except ValueError as exc:  # a path the OS cannot take (an embedded NUL)
                files[path] = ("a readable CSV file (tau_s, E_Pa, '# E_inf: VALUE')",
                               f"not a usable path ({exc})")
        _store(files[path], i, E0, materials, fail, "prony", raw)
    return visco, E0, materials


def _store(material, i, E0, materials, fail, name, raw):
    mask = np.zeros(E0.shape, bool)
    mask[i] = True
    if isinstance(material, tuple):  # (valid, reason) of a refused material
        fail(mask, name, material[0], material[1], lambda j: raw[name][j])
        return
    E0[i] = material.instantaneous
    materials[i] = material


def columns(cases, present):
    """The issue-10 columns to show for these cases, in order."""
    cols = []
    if present["friction"].any():
        cols += FRICTION_COLUMNS
    if present["tangential_load"].any():
        cols += LOAD_COLUMNS
    visco = cases.get("material")
    if present["time"].any():
        cols += CREEP_COLUMNS
    if visco is not None and any(m is not None for m in visco):
        cols += VISCO_COLUMNS
    return cols


def _each(func, idx, notes, width=1):
    """func(sub-index array) -> values (`width` per element, flattened), element by
    element where a call is refused (its reason in ``notes[k]``); returns shape (n,) or
    (n, width), NaN where refused."""
    from .validity import OutOfRangeError

    shape = (idx.size,) if width == 1 else (idx.size, width)
    try:
        return np.asarray(func(idx), dtype=float).reshape(shape)
    except FileNotFoundError:
        for k in range(idx.size):
            notes[k] = ("the BEM table tangential_cylinder is not installed (python -m "
                        "tools.build_tables tangential)")
        return np.full(shape, np.nan)
    except OutOfRangeError:
        pass
    res = np.full(shape, np.nan)
    for k in range(idx.size):
        try:
            v = np.asarray(func(idx[k:k + 1]), dtype=float).ravel()
            res[k] = v[0] if width == 1 else v[:width]
        except OutOfRangeError as exc:
            notes[k] = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    return res


def add_fields(fields, flags, g, model, r, cases, present):
    """Fill this module's fields for the rows `g` of one cylinder and one model.

    `fields`: name -> full-length arrays (created here if absent); `flags`: the rows'
    flag texts (appended to); `r`: the model's force, depth, stiffness over `g`.
    """
    from . import tangential as tg
    from .viscoelastic import step_creep_depth

    n = len(flags)
    for name in ALL_COLUMNS:
        if name not in fields:
            fields[name] = np.full(n, np.nan)
    if not hasattr(model, "force"):   # a model refused at build (compute.Refused)
        return
    F, d, k = r["force"], r["depth"], r["stiffness"]
    ok = np.isfinite(d) & (d > 0) & np.isfinite(F)
    notes = [""] * len(g)

    def note(j, text):
        if text and text not in notes[j]:
            notes[j] = "; ".join(t for t in (notes[j], text) if t)

    fr = present["friction"][g] & ok
    if fr.any():
        sel = np.flatnonzero(fr)
        rows = g[sel]
        E2 = np.where(present["modulus2"][rows], cases["modulus2"][rows], np.inf)
        nu2 = np.where(present["poisson2"][rows], cases["poisson2"][rows], 0.0)
        gstar = tg.effective_shear_modulus(cases["modulus"][rows], cases["poisson"][rows],
                                           E2, nu2)
        gstar = np.atleast_1d(gstar)
        ratio_mdr = gstar / model.estar
        fields["kt_mdr"][rows] = ratio_mdr * k[sel]
        bem = {"across": np.full(sel.size, np.nan), "along": np.full(sel.size, np.nan)}
        sub_notes = [""] * sel.size
        def ratios(ii):
            r = tg.cylinder_stiffness_ratios(model, d[sel][ii], gstar[ii])
            return np.stack([np.atleast_1d(r["across"]), np.atleast_1d(r["along"])], axis=1)

        both = _each(ratios, np.arange(sel.size), sub_notes, width=2)
        bem["across"], bem["along"] = both[:, 0], both[:, 1]
        for j, t in zip(sel, sub_notes):
            note(j, "kt across/along: " + _short(t) if t else "")
        fields["kt_across"][rows] = bem["across"] * k[sel]
        fields["kt_along"][rows] = bem["along"] * k[sel]
        tl = present["tangential_load"][rows]
        if tl.any():
            s2 = sel[tl]
            rows2 = g[s2]
            Q = cases["tangential_load"][rows2]
            mu = cases["friction"][rows2]
            fields["tangential_load"][rows2] = Q
            frac = Q / (mu * F[s2])
            fields["slip_fraction"][rows2] = frac
            partial = frac <= 1.0 + 1e-12
            for j, fq in zip(s2, frac):
                note(j, "partial slip" if fq < 1.0 - 1e-12 else
                     "gross slip onset: Q = mu F" if fq <= 1.0 + 1e-12 else
                     "gross slip: Q > mu F, the contact slides (no static shift)")
            if partial.any():
                s3 = s2[partial]
                rows3 = g[s3]
                gs = gstar[tl][partial]
                fields["shift_mdr"][rows3] = tg.tangential_shift(
                    model, d[s3], cases["tangential_load"][rows3],
                    cases["friction"][rows3], gs)
                for direction in ("across", "along"):
                    ratio = bem[direction][tl][partial]
                    good = np.isfinite(ratio)
                    if good.any():
                        u = np.atleast_1d(tg.tangential_shift(
                            model, d[s3][good], cases["tangential_load"][rows3[good]],
                            cases["friction"][rows3[good]], gs[good], ratio=ratio[good]))
                        u = u * _slip_correction(model, direction, d[s3][good], gs[good],
                                                 frac[partial][good])
                        fields[f"shift_{direction}"][rows3[good]] = u
    materials = cases.get("material")
    if materials is not None:
        # creep under a held force (with a given depth the force would relax instead)
        vis = (np.array([materials[i] is not None for i in g], bool) & ok
               & (cases["given"][g] == "load"))
        # rows with the same body and second-body constants are evaluated together
        keys = {}
        for j in np.flatnonzero(vis):
            i = g[j]
            e2 = cases["modulus2"][i] if present["modulus2"][i] else np.inf
            n2 = cases["poisson2"][i] if present["poisson2"][i] else 0.0
            keys.setdefault((id(materials[i]), cases["poisson"][i], e2, n2), []).append(j)
        for (_, nu1, e2, n2), js in keys.items():
            js = np.array(js)
            rows = g[js]
            mat = _Material(materials[rows[0]], nu1, e2, n2)
            sub = [""] * js.size
            val = _each(lambda ii: model.depth(
                F[js][ii] * mat.long_term_compliance * model.estar), np.arange(js.size), sub)
            fields["depth_long_term"][rows] = val
            for j, t in zip(js, sub):
                note(j, _creep_note("d(inf)", "E*_0/E*_inf", t))
            timed = present["time"][rows]
            if timed.any():
                jt, rt = js[timed], rows[timed]
                fields["time"][rt] = cases["time"][rt]
                sub = [""] * jt.size
                val = _each(lambda ii: step_creep_depth(model, mat, F[jt][ii],
                                                           cases["time"][rt][ii]),
                               np.arange(jt.size), sub)
                fields["creep_depth"][rt] = val
                for j, t in zip(jt, sub):
                    note(j, _creep_note("d(t)", "E*_0 J*(t)", t))
    for j, i in enumerate(g):
        if notes[j]:
            flags[i] = "; ".join(t for t in (flags[i], notes[j]) if t)


def _slip_correction(model, direction, depth, gstar, q):
    """The BEM table's partial-slip shift factor at load fractions q (1 without one),
    as in :class:`linecontact.tangential.TangentialContact` with method="bem"."""
    from . import tangential as tg

    table = tg.cylinder_tangential_table()
    nu = tg.equivalent_poisson(gstar, model.estar)
    return np.atleast_1d(table.shift_factor(direction, nu,
                                            depth * model.radius / model.length ** 2, q))


def _creep_note(column, factor, text):
    """The model's refusal of a creep depth, said in terms of the creep."""
    if not text:
        return ""
    text = _short(text)
    if text.startswith("force = "):
        text = (f"beyond the model's range: its elastic-equivalent force F {factor} = "
                + text[len("force = "):])
    return f"{column}: {text}"


def _short(text):
    """First clause of a library message (the parameter, value and range), without
    the element index of the one-element array it was evaluated on."""
    return re.sub(r" \(element \[\d+\] of shape \(\d+,\)\)", "", text.split("; ")[0])
