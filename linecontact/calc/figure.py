"""``linecontact calc ... --plot FILE``: the calculator's case drawn with
:mod:`linecontact.plot` (no physics here: the curves are the library's, the points the
calculator's rows).

The figure has one panel per kind of result present:

- F(d) of every model of the table for the case's contact, each drawn where it
  applies, with the computed rows (their depth and force) as points; a whole roller
  between raceways shows its first contact's laws, without points (its rows are the
  roller's deflection, not one contact's depth);
- the line load q(x) of each profiled-roller row (the coupled-slice model, one line
  per sweep value).
"""
from __future__ import annotations

import numpy as np

__all__ = ["draw_results"]


def draw_results(results, path):
    """Draw the calculator's `results` and save them to `path` (png, svg or pdf).

    Returns the path written."""
    from matplotlib.figure import Figure

    from .. import plot

    sets = [s for s in results.sets if s.get("model") is not None]
    rollers = [b for b in results.blocks
               if b.name == "profiled_roller" and any("q" in r for r in b.json_rows)]
    sets = [s for s in sets if getattr(s["model"], "law", s["model"]) is not None]
    n = (1 if sets else 0) + len(rollers[:1])
    if n == 0:
        raise ValueError("--plot: nothing to draw for this case")
    fig = Figure(figsize=(6.4, 4.4 * n), layout="constrained")
    axes = np.atleast_1d(fig.subplots(n, 1))
    k = 0
    if sets:
        models, seen = [], set()
        for s in sets:
            # a composed contact's entry carries its law (None: no single F(d) to draw)
            law = getattr(s["model"], "law", s["model"])
            if s["id"] not in seen and law is not None:
                seen.add(s["id"])
                models.append(law)
        points = []
        if not results.whole:
            for s in sets:
                points += list(zip(s["fields"]["depth"], s["fields"]["force"]))
        plot.force_depth(models, points=points, ax=axes[k])
        k += 1
    if rollers:
        ax = axes[k]
        for row in rollers[0].json_rows:
            if "q" not in row:
                continue
            x, q = np.asarray(row["x"]), np.asarray(row["q"])
            ax.plot(x * 1e3, q * 1e-3,
                    label=f"F = {row['force']:.4g} N, tilt {row['tilt'] * 1e3:.3g} mrad")
        ax.set_xlabel("x along the roller [mm]")
        ax.set_ylabel("line load q [N/mm]")
        ax.set_title(f"profiled roller: {rollers[0].json_rows[0].get('method', '')}",
                     fontsize=9)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
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
