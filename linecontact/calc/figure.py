"""``linecontact calc ... --plot FILE``: what the command computed, drawn with
:mod:`linecontact.plot` (no physics here: the curves are the library's, the points the
calculator's rows).

The figure has one band of panels per kind of result present, top to bottom
(:func:`linecontact.plot.panels` when there are several):

- F(d) of every model of the table for the case's contact, each drawn where it
  applies, with each model's computed rows (their depth and force) as points in that
  model's own style (:func:`linecontact.plot.force_depth` with ``points`` per model);
  rows of other contacts (a sweep over the geometry) are said on stderr, not drawn on
  curves they do not belong to; a whole roller between raceways shows its first
  contact's laws, without points (its rows are the roller's deflection, not one
  contact's depth);
- then each active feature's items, from its optional ``figure(state, results)``
  (:mod:`linecontact.calc.feature`): the profiled roller's q(x) with its ends and the
  profile, the adhesive F(d) with the pull-off, creep or relaxation against the load
  history, the tangential loop across and along, the stresses of the worst section.

A feature with no figure, and anything a feature leaves out, is said in one line on
stderr (``--plot: ...``), so that no computed result is dropped without a word.
"""
from __future__ import annotations

import sys
from functools import partial

import numpy as np

__all__ = ["draw_results", "draw_command", "items"]


def _law(s):
    """The F(d) law of a column set's first contact (None: a whole roller, a free
    tilt: no single law)."""
    return getattr(s["model"], "law", s["model"])


def _force_depth(results):
    """The core's F(d) item(s): [draw] and the lines said on stderr."""
    from .. import plot

    sets = [s for s in results.sets
            if s.get("model") is not None and _law(s) is not None]
    lawless = [s["model"].label for s in results.sets
               if s.get("model") is not None and _law(s) is None and not results.whole]
    said = [f"--plot: F(d): {label} has no single F(d) law to draw (its rows are in "
            "the table)" for label in lawless]
    if not sets:
        return said
    models, laws = [], []
    for s in sets:
        law = _law(s)
        if all(law is not m for m in models):
            models.append(law)
        laws.append(law)
    if results.whole:
        return [partial(plot.force_depth, models),
                "--plot: F(d) of the first contact's laws without points: the rows are "
                "the whole roller's deflection, not one contact's depth"]
    cases = results.cases
    ok = np.array([not e for e in results.errors], dtype=bool)
    m0 = models[0]
    with np.errstate(invalid="ignore"):
        same = ok & np.isclose(cases.radius_eff, m0.radius, rtol=1e-12, atol=0) \
            & np.isclose(cases.length, m0.length, rtol=1e-12, atol=0) \
            & np.isclose(cases.estar, m0.estar, rtol=1e-12, atol=0)
    points = {}
    for s, law in zip(sets, laws):
        d, F = s["fields"]["depth"][same], s["fields"]["force"][same]
        with np.errstate(invalid="ignore"):
            good = np.isfinite(d) & np.isfinite(F) & (d > 0) & (F > 0)
        if good.any():
            points.setdefault(law, []).extend(zip(d[good], F[good]))
    out = [partial(plot.force_depth, models, points=points or None)] + said
    others = int(np.sum(ok & ~same))
    if others:
        out.append(f"--plot: F(d) drawn for the contact R = {m0.radius:.6g} m, "
                   f"L = {m0.length:.6g} m, E* = {m0.estar:.6g} Pa; {others} row(s) of "
                   "other contacts are in the table only")
    return out


def items(results):
    """Everything the figure of `results` holds: callables ``draw(fig=None)`` (each a
    :mod:`linecontact.plot` figure with its result bound) and str (the lines said on
    stderr), in order: the core's F(d), then each active feature's."""
    out = _force_depth(results)
    states = results.cases.states
    for f in results.features:
        hook = getattr(f, "figure", None)
        if hook is None:
            out.append(f"--plot: the {f.name} results have no figure (they are in the "
                       "table)")
            continue
        out += hook(states[f.name], results)
    return out


def draw_results(results, path, stderr=None):
    """Draw the calculator's `results` and save them to `path` (png, svg or pdf): one
    figure, a band of panels per kind of result (:func:`items`); what has no figure is
    said in one line each on `stderr` (default ``sys.stderr``).

    Returns the path written."""
    from .. import plot

    parts = items(results)
    draws = [p for p in parts if callable(p)]
    stderr = sys.stderr if stderr is None else stderr
    for line in parts:
        if isinstance(line, str):
            print(line, file=stderr)
    if not draws:
        from .._units import InputError

        raise InputError("--plot", str(path), "a case with a result to draw",
                         "nothing to draw for this case (see the lines above)" if parts
                         else "nothing to draw for this case")
    fig = draws[0]() if len(draws) == 1 else plot.panels(*draws)
    return plot.save(fig, path)


def draw_command(command, results, path):
    """``linecontact SUBCOMMAND ... --plot FILE``: the subcommand's figure of the
    computed cases (its module's ``figure``, drawn by :mod:`linecontact.plot`), saved
    to `path` (png, svg or pdf). Returns the path written."""
    from .. import plot

    objects = [o for o in results.objects if o is not None]
    if not objects:
        raise ValueError("--plot: nothing to draw (no case computed)")
    return plot.save(command.module.figure(objects), path)
