"""Feature: a viscoelastic second body (``--instantaneous-modulus``,
``--long-term-modulus``, ``--relaxation-time`` or ``--prony``; ``--time``).

``--instantaneous-modulus E0 --long-term-modulus EINF --relaxation-time TAU``, or
``--prony FILE.csv`` (columns tau_s, E_Pa and a ``# E_inf: VALUE`` line)
    A viscoelastic second body (instead of ``--modulus``; needs ``--poisson``) with the
    Young's moduli of a standard linear solid or a Prony series
    (:mod:`linecontact.viscoelastic`; every value in the file is a number with at most
    one unit name, bare = SI, by the rule of the command line). The elastic columns are
    then the instantaneous response (E* from E0); ``d(inf)`` is the long-term depth.
``--time T`` (a time or a sweep; with ``--load``)
    The depth after the load has been held for T (creep, Lee & Radok 1960):
    d(t) = F1^-1(F J*(t)), :func:`linecontact.viscoelastic.step_creep_depth`, with the
    creep function of the effective modulus J*(t) = (1 - nu1^2) J1(t) + (1 - nu2^2)/E2
    (the compliances of the two bodies add; a rigid roller has no second term).

Not combined: with the raceways (a whole roller), with friction.
"""
from __future__ import annotations

import numpy as np

from ..feature import Field, Parameter, State, keep, short

__all__: list = []

name = "viscoelastic"
group = "viscoelastic second body (instead of --modulus; creep)"

parameters = (
    Parameter("instantaneous_modulus", "pressure", "instantaneous Young's modulus E0 of a "
              "standard linear solid", group),
    Parameter("long_term_modulus", "pressure", "long-term Young's modulus E_inf < E0",
              group),
    Parameter("relaxation_time", "time", "relaxation time tau (at constant strain)", group),
    Parameter("prony", "path", "Prony series of the Young's modulus: a CSV file with "
              "columns tau_s, E_Pa and a line '# E_inf: VALUE' (instead of the three "
              "above)", group),
    Parameter("time", "time", "time t the load has been held, or a sweep START:STOP:N: "
              "the creep depth d(t) (with --load)", group, positive=False),
)

_SLS = ("instantaneous_modulus", "long_term_modulus", "relaxation_time")

fields = {
    "time": Field("t", "s", "s", 1.0),
    "creep_depth": Field("d(t)", "m", "um", 1e6),
    "depth_long_term": Field("d(inf)", "m", "um", 1e6),
}

notes = {
    "creep": "d(t): depth after the normal load has been held for t (Lee & Radok 1960, "
             "exact while the contact grows), d(t) = F1^-1(F J*(t)); d(inf): long-term "
             "depth; the other columns are the instantaneous response (E* from E0).",
}


def resolve(values, present, fail):
    """The body: all three SLS options or a Prony file; not with --modulus, --estar,
    friction or the raceways; --time needs the body and a load. The State's
    ``modulus`` (E0) gives E* its instantaneous value."""
    from ..._units import range_error_parts
    from ...errors import OutOfRangeError
    from ...viscoelastic import StandardLinearSolid, read_prony_series

    v, P, label = values, present, fail.label
    sls_any = P[_SLS[0]] | P[_SLS[1]] | P[_SLS[2]]
    sls_all = P[_SLS[0]] & P[_SLS[1]] & P[_SLS[2]]
    visco = sls_any | P["prony"]
    if not (visco | P["time"]).any():
        return None
    three = ", ".join(label(s) for s in _SLS)
    for nm in _SLS:
        fail(sls_any & ~P[nm], nm, f"{three} together (a standard linear solid)", "missing")
    fail(P["prony"] & sls_any, "prony", f"either {label('prony')} or {three}, not both",
         "conflicts with the standard linear solid options")
    fail(visco & P["modulus"], "modulus",
         f"either {label('modulus')} (elastic) or the viscoelastic options",
         "conflicts with the viscoelastic options")
    fail(visco & P["estar"], "estar",
         f"the viscoelastic options with {label('poisson')}, not {label('estar')}",
         "conflicts with the viscoelastic options")
    fail(visco & ~P["poisson"], "poisson", "a number in [0, 0.5]",
         "missing (needed with the viscoelastic options)")
    fail(P["time"] & ~visco, "time", f"with a viscoelastic body ({three}, or "
         f"{label('prony')})", "no viscoelastic material given")
    fail(P["time"] & ~P["load"], "time", f"with {label('load')} (creep under a held force)",
         "no force given")
    with np.errstate(invalid="ignore"):
        fail(P["time"] & ~(v["time"] >= 0), "time", "a time >= 0 (e.g. 10s, 5min, 0)",
             "negative")
        fail(sls_all & ~(v["long_term_modulus"] < v["instantaneous_modulus"]),
             "long_term_modulus", f"below {label('instantaneous_modulus')}",
             "not below the instantaneous modulus")
    raceways = P["inner_raceway"] | P["outer_raceway"]
    fail(P["time"] & raceways, "time", "one contact (without the raceways)",
         "not available for a whole roller")
    fail(visco & raceways, "inner_raceway", "one contact (without the raceways)",
         "a viscoelastic body is not available for a whole roller")
    fail(P["friction"] & visco, "friction", "an elastic second body",
         "not combined with a viscoelastic body")

    n = len(visco)
    E0 = np.full(n, np.nan)
    bodies = np.full(n, None, dtype=object)

    def store(material, i, nm):
        if isinstance(material, tuple):  # (valid, reason) of a refused material
            fail(np.arange(n) == i, nm, material[0], material[1])
            return
        E0[i] = material.instantaneous
        bodies[i] = material

    cache = {}
    for i in np.flatnonzero(sls_all & ~P["prony"]):
        key = (v[_SLS[0]][i], v[_SLS[1]][i], v[_SLS[2]][i])
        if key not in cache:
            try:
                cache[key] = StandardLinearSolid(*key)
            except OutOfRangeError as exc:
                cache[key] = (exc.valid, str(exc))
        store(cache[key], i, "relaxation_time")
    files = {}
    for i in np.flatnonzero(P["prony"] & ~sls_any):
        path = v["prony"][i].strip()
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
        store(files[path], i, "prony")
    state = State(visco, modulus=E0, bodies=bodies, time=v["time"], timed=P["time"],
                  loaded=P["load"], nu1=v["poisson"], any_time=bool(P["time"].any()))
    state.parts = lambda i: _parts(state, i)
    return state


def _parts(state, i):
    """The viscoelastic second body of row i (the counter-body's material)."""
    from ...contact import Viscoelastic

    if state.bodies[i] is None:
        return {}
    return {"material2": Viscoelastic(state.bodies[i], float(state.nu1[i]))}


def columns(model, rows, normal, state):
    """d(inf) and, with --time, d(t) under the held force, for the rows of one contact:
    :meth:`linecontact.contact.Contact.creep` (Lee & Radok) of the composed contact."""
    from ...errors import CombinationError, OutOfRangeError

    keep(state, rows, model)
    n = len(rows)
    out = {"depth_long_term": np.full(n, np.nan)}
    if state.any_time:
        out.update(time=np.full(n, np.nan), creep_depth=np.full(n, np.nan))
    flags = [""] * n
    out["flags"] = flags
    contact = model.contact
    if contact is None:
        return out
    F = normal["force"]
    for j, i in enumerate(rows):
        # creep under a held force (with a given depth the force would relax instead)
        if state.bodies[i] is None or not state.loaded[i]:
            continue
        notes = []
        if state.timed[i]:
            t = float(state.time[i])
            out["time"][j] = t
            try:
                out["creep_depth"][j] = _creep_only(contact, t, float(F[j]))
            except (CombinationError, OutOfRangeError) as exc:
                notes.append(_creep_note("d(t)", "E*_0 J*(t)", str(exc)))
        try:
            held = contact.creep([0.0], force=float(F[j]))
        except (CombinationError, OutOfRangeError) as exc:
            notes.append(_creep_note("d(inf)", "E*_0/E*_inf", str(exc)))
        else:
            if held.long_term_depth is None:  # the library says why
                notes.append(f"d(inf): {held.reasons['long_term_depth'][1]}")
            else:
                out["depth_long_term"][j] = held.long_term_depth
        flags[j] = "; ".join(notes)
    return out


def _creep_only(contact, t, force):
    """d(t) under a force held from 0 (Contact.creep, which returns the history even
    where only the long-term depth is beyond the model's range)."""
    return float(contact.creep([0.0, t], force=force).depth[-1])


def _creep_note(column, factor, text):
    """The model's refusal of a creep depth, said in terms of the creep."""
    if not text:
        return ""
    text = short(text)
    if text.startswith("force = "):
        text = (f"beyond the model's range: its elastic-equivalent force F {factor} = "
                + text[len("force = "):])
    return f"{column}: {text}"


#: Histories drawn at most (a load or depth sweep: the first values, the rest said).
MAX_FIGURES = 3
#: Samples of a drawn history [-].
SAMPLES = 121


def figure(state, results):
    """``--plot``: each row's load history and the response (:func:`linecontact.plot.creep`):
    under a held force the creep d(t) with the long-term depth, under a held depth the
    relaxation F(t) (:meth:`linecontact.contact.Contact.creep`,
    :meth:`~linecontact.contact.Contact.relaxation_history`), up to the latest
    ``--time`` of the rows (their times among the samples) or, without one, to five
    retardation times tau E0/E_inf of the slowest term (within e^-5 of the long-term
    state). One panel per held value of the first contact (at most
    :data:`MAX_FIGURES`)."""
    from functools import partial

    from ... import plot
    from ...errors import CombinationError, OutOfRangeError

    kept = getattr(state, "kept", None)
    if kept is None:
        return []
    rows = [i for i in np.flatnonzero(state.rows)
            if kept[i] is not None and kept[i].contact is not None
            and state.bodies[i] is not None]
    if not rows:
        return []
    m0 = kept[rows[0]]
    groups = {}
    cases = results.cases
    for i in rows:
        if kept[i] is m0:
            groups.setdefault((cases.given[i], float(cases.value[i])), []).append(i)
    out, said = [], []
    for (given, value), idx in list(groups.items())[:MAX_FIGURES]:
        body = state.bodies[idx[0]]
        times = [float(state.time[i]) for i in idx if state.timed[i]]
        end = max(times) if times and max(times) > 0 else \
            5.0 * float(np.max(body.times)) * body.instantaneous / body.long_term
        t = np.unique(np.concatenate([np.linspace(0.0, end, SAMPLES), times]))
        try:
            res = (m0.contact.creep(t, force=value) if given == "load"
                   else m0.contact.relaxation_history(t, depth=value))
        except (CombinationError, OutOfRangeError) as exc:
            said.append(f"--plot: {'creep' if given == 'load' else 'relaxation'} at "
                        f"{value:g} {'N' if given == 'load' else 'm'}: no figure: "
                        f"{short(str(exc))}")
            continue
        out.append(partial(plot.creep, res, given="force" if given == "load" else "depth"))
    if len(groups) > MAX_FIGURES:
        said.append(f"--plot: creep drawn for the first {MAX_FIGURES} of {len(groups)} "
                    "held values (every row is in the table)")
    others = len(rows) - sum(len(v) for v in groups.values())
    if others:
        said.append(f"--plot: creep drawn for the first contact; {others} row(s) of other "
                    "contacts are in the table only")
    return out + said


def blocks(state, results):
    """No extra table."""
    return []
