r"""Figures of the library's results: the pictures an engineer would rather look at.

Each function draws one kind of result of the library and returns the ``Figure``;
:func:`save` writes it as PNG, SVG or PDF (:func:`save_all`: PNG and SVG at once).
Nothing here computes physics of its own: the curves are the values the library
returns, taken from the result objects (or, for a law, asked of the object that the
result came from), so a figure shows exactly what the numbers are.

- :func:`force_depth`: F(d) of several contact laws for one cylinder, each drawn only
  where it answers (its validity range), its measured error against the 3D BEM in the
  legend (tables/model_accuracy.csv), and optionally computed points on top;
- :func:`line_load`: the line load q(x) along a profiled roller, its ends marked;
- :func:`profiled_roller`: q(x) above the roller's profile drop P(x) and the rigid
  approach d + theta x (the overlap that the slices resolve);
- :func:`pressure_map`: the contact pressure p(x, y) of a profiled roller, each slice
  the plane-strain Hertz ellipse of its own load (:func:`pressure_field`);
- :func:`adhesion`: F(d) of an adhesive contact on approach and retraction with the
  pull-off marked, the 2D JKR and the finite roller's BEM pull-off beside it;
- :func:`creep`: the load history and the response of a viscoelastic contact (creep
  d(t) under F(t), or relaxation F(t) under d(t));
- :func:`hysteresis`: the tangential force F_t(u) up to gross slip (partial slip) and
  the fretting loop (Masing), one curve per direction given;
- :func:`stresses`: the subsurface field of the worst section with its maximum
  marked, the maxima along the roller, and the case-hardening check;
- :func:`bearing`: roller loads, moments and tilts around the ring.

Several results in one figure: :func:`panels`. Every function takes ``fig=`` (a
``Figure`` or ``SubFigure`` to draw into; the single-panel ones also ``ax=``), so
:func:`panels` stacks any of them. Readable by default: each curve its own colour,
marker and dash, the legend outside the data (right of the axes), units on every axis
with the SI prefix that fits the data's magnitude
(:func:`linecontact._units.engineering_unit`: a soft
contact's force in mN, a steel roller's in kN). :data:`PLOTS` lists the figures by
name (:func:`register` adds one).

matplotlib is an optional dependency (``pip install 'linecontact[plot]'``); importing
this module does not import it, and a function that needs it raises
:class:`MissingDependencyError` saying how to install it. Figures are built with
``matplotlib.figure.Figure`` directly (no pyplot, no window, no global state).

References
----------
.. [1] J. D. Hunter, Matplotlib: a 2D graphics environment, Computing in Science &
   Engineering 9 (2007) 90-95.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 5.6
   (plane-strain Hertz pressure of a cylinder).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ._units import engineering_unit
from .errors import OutOfRangeError, UnknownNameError

__all__ = ["force_depth", "line_load", "profiled_roller", "pressure_field",
           "pressure_map", "adhesion", "creep", "hysteresis", "stresses", "bearing",
           "panels", "engineering_unit", "save", "save_all", "register", "PLOTS",
           "FORMATS", "MissingDependencyError"]

#: File formats :func:`save` writes (by the file's extension).
FORMATS = ("png", "svg", "pdf")

#: Every figure by name: name -> function (a later feature adds its own, see register).
PLOTS: dict = {}

#: Resolution of the raster (PNG) files [dots per inch]: 100 keeps a figure near 100 kB.
DPI = 100

#: Width of a figure: the axes and, right of them, the legend [inch].
_WIDTH = 8.0
#: Height of one panel [inch].
_PANEL = 3.1


class MissingDependencyError(ImportError):
    """matplotlib is not installed: the message says how to install it."""


def register(name):
    """Decorator adding a figure function to :data:`PLOTS` under `name`.

    Parameters
    ----------
    name : str
        The figure's name (e.g. ``"film"``); must be new.

    Returns
    -------
    callable
        The decorator (it returns the function unchanged).

    Examples
    --------
    >>> sorted(PLOTS)[:3]
    ['adhesion', 'bearing', 'creep']
    """
    def deco(func):
        if name in PLOTS:
            raise ValueError(f"plot {name!r} is already registered")
        PLOTS[name] = func
        return func
    return deco


# --------------------------------------------------------------------------------------
# units, styles, layout
# --------------------------------------------------------------------------------------
def _quantity(value, unit, digits=4):
    """'67 kPa': a value with the prefix that fits it."""
    f, u = engineering_unit(value, unit)
    return f"{value * f:.{digits}g} {u}"


_COLOURS = tuple(f"C{i}" for i in range(10))
_MARKERS = ("o", "s", "^", "v", "D", "<", ">", "p", "h", "*", "X")
_DASHES = ("-", "--", "-.", ":")


def _style(i):
    """Plot keywords of curve i: its own colour, marker and dash (eleven F(d) laws
    stay apart, also in grey print)."""
    return {"color": _COLOURS[i % 10], "marker": _MARKERS[i % len(_MARKERS)],
            "linestyle": _DASHES[(i // 10 + i) % len(_DASHES)], "ms": 4}


def _legend(ax, handles=None, labels=None, **kw):
    """The legend outside the data: right of the axes, top-aligned."""
    args = () if handles is None else (handles, labels)
    kw.setdefault("fontsize", 7)
    return ax.legend(*args, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                     borderaxespad=0.0, frameon=False, **kw)


def _matplotlib():
    try:
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - exercised with matplotlib hidden
        raise MissingDependencyError(
            "linecontact.plot needs matplotlib, which is not installed: "
            "pip install 'linecontact[plot]' (or pip install matplotlib)") from exc
    return Figure


def _root(fig):
    """The top-level Figure of a Figure or SubFigure."""
    return fig.get_figure(root=True) if hasattr(fig, "get_figure") else fig


def _new(fig, nrows, ax=None, sharex=False):
    """(figure to return, list of nrows axes): drawn on `ax` (one panel), inside `fig`
    (a Figure or SubFigure), or on a new figure."""
    Figure = _matplotlib()
    if ax is not None:
        if nrows != 1:
            raise OutOfRangeError("ax", "an Axes", f"fig= (a Figure or SubFigure): this "
                                  f"figure has {nrows} panels")
        return _root(ax.figure), [ax]
    if fig is None:
        fig = Figure(figsize=(_WIDTH, _PANEL * nrows + 0.3), layout="constrained")
    axes = list(fig.subplots(nrows, 1, sharex=sharex, squeeze=False)[:, 0])
    fig._linecontact_panels = nrows          # read by panels() to size the stack
    return _root(fig), axes


def panels(*draw, title=None):
    """One figure holding several results, each drawn by its figure function.

    Parameters
    ----------
    *draw : callable
        Each a figure function with its result bound, taking ``fig=``: e.g.
        ``functools.partial(plot.creep, result)``; drawn top to bottom, each in its
        own SubFigure (its panels, legends and colour bars kept together).
    title : str, optional
        The figure's title.

    Returns
    -------
    matplotlib.figure.Figure
        Its height the sum of the parts' panels.

    Examples
    --------
    >>> from functools import partial
    >>> from linecontact.models import get_model
    >>> ms = [get_model("universal", 5e-3, 10e-3, 115.38e9)]
    >>> fig = panels(partial(force_depth, ms), partial(force_depth, ms, depth=[1e-6, 2e-6]))
    >>> len(fig.axes)
    2
    """
    if not draw:
        raise OutOfRangeError("draw", "nothing", "at least one figure function")
    for d in draw:
        if not callable(d):
            raise OutOfRangeError("draw", repr(d), "callables taking fig= (e.g. "
                                  "functools.partial(plot.creep, result))")
    Figure = _matplotlib()
    fig = Figure(figsize=(_WIDTH, _PANEL * len(draw)), layout="constrained")
    grid = fig.add_gridspec(len(draw), 1)
    subs = [fig.add_subfigure(grid[i, 0]) for i in range(len(draw))]
    for d, sub in zip(draw, subs):
        d(fig=sub)
    rows = [getattr(sub, "_linecontact_panels", 1) for sub in subs]
    grid.set_height_ratios(rows)
    fig.set_size_inches(_WIDTH, _PANEL * sum(rows) + 0.3)
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def save(fig, path, *, dpi=DPI):
    """Write `fig` to `path`; the format is the extension (png, svg or pdf).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or path
        Output file, ending in .png, .svg or .pdf.
    dpi : float, optional
        Resolution of a PNG [dots per inch] (default :data:`DPI`).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    OutOfRangeError
        Another extension (naming it and the valid ones).

    Notes
    -----
    Valid for 0 < dpi (matplotlib's own check); the vector formats ignore it.

    Examples
    --------
    >>> save(None, "figure.jpg")
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: plot file = 'figure.jpg' is outside the valid range a name ending in .png, .svg or .pdf
    """
    path = Path(path)
    ext = path.suffix.lower().lstrip(".")
    if ext not in FORMATS:
        raise OutOfRangeError("plot file", str(path), "a name ending in "
                              + ", ".join("." + f for f in FORMATS[:-1])
                              + f" or .{FORMATS[-1]}")
    fig.savefig(path, format=ext, dpi=dpi)
    return path


def save_all(fig, stem, formats=("png", "svg"), *, dpi=DPI):
    """Write `fig` once per format: ``stem.png``, ``stem.svg`` (:func:`save`).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    stem : str or path
        The files' path without the extension.
    formats : sequence of str, optional
        Formats among :data:`FORMATS` (default PNG and SVG).
    dpi : float, optional
        Resolution of a PNG [dots per inch].

    Returns
    -------
    list of pathlib.Path
        The paths written.

    Notes
    -----
    Valid as :func:`save` (0 < dpi; the formats among :data:`FORMATS`).

    Examples
    --------
    >>> import os, tempfile
    >>> from linecontact.models import get_model
    >>> fig = force_depth([get_model("universal", 5e-3, 10e-3, 115.38e9)])
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     [p.name for p in save_all(fig, os.path.join(folder, "fd"))]
    ['fd.png', 'fd.svg']
    """
    stem = Path(stem)
    return [save(fig, stem.with_name(stem.name + "." + f), dpi=dpi) for f in formats]


def _answer(func, values):
    """func at each value, NaN where it refuses (outside its validity range)."""
    try:
        return np.asarray(func(values), dtype=float)
    except (OutOfRangeError, ValueError):
        out = np.full(np.shape(values), np.nan)
        for i, v in enumerate(values):
            try:
                out[i] = float(func(v))
            except (OutOfRangeError, ValueError):
                pass
        return out


def _points(points):
    """(n, 2) finite array of (x, y) pairs (NaN pairs dropped)."""
    pts = np.array([(float(a), float(b)) for a, b in points], dtype=float).reshape(-1, 2)
    return pts[np.all(np.isfinite(pts), axis=1)]


# --------------------------------------------------------------------------------------
# normal contact: F(d), q(x), the profile, the pressure
# --------------------------------------------------------------------------------------
@register("force-depth")
def force_depth(models, depth=None, *, points=None, fig=None, ax=None):
    r"""F(d) of contact laws for one cylinder, each where it answers, with its error.

    Each model is evaluated on the depth grid; where it refuses (outside its range of
    L/R, depth or material) nothing is drawn, so a curve's extent IS its validity range.
    Each model has its own colour, marker and dash; the legend, right of the axes,
    gives each model's measured error against the 3D boundary-element reference
    (:attr:`linecontact.models.ContactModel.measured_error`, from
    tables/model_accuracy.csv) where the accuracy study covers it.

    Parameters
    ----------
    models : sequence of linecontact.models.ContactModel
        The laws, e.g. :func:`linecontact.models.standard_models` (R, L, E*).
    depth : array_like, optional
        Depths d, 0 < d [m]; default 200 values spaced geometrically from 1e-6 R to
        0.15 R (the geometry every model shares) of the first model.
    points : sequence of (depth, force), or mapping, optional
        Computed states to mark, d [m] and F [N] (NaN pairs are skipped): pairs are
        drawn as black circles; a mapping model (or its label) -> pairs draws each
        model's states filled in that model's colour and marker.
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).
    ax : matplotlib.axes.Axes, optional
        The axes to draw on instead.

    Returns
    -------
    matplotlib.figure.Figure
        Log-log axes, d and F with the SI prefixes that fit (the axis labels say
        which; :func:`engineering_unit`); one line per model with the model's label,
        NaN where refused. ``line.scale`` holds the (depth, force) factors from SI.

    Notes
    -----
    Valid where each model is (its own checks decide); depths must be positive.

    Examples
    --------
    >>> from linecontact.models import standard_models
    >>> fig = force_depth(standard_models(5e-3, 10e-3, 115.38e9)[:2])
    >>> [line.get_label() for line in fig.axes[0].lines]
    ['Universal curve (BEM)', 'Li-Popov (Table 1 spline)']
    >>> fig.axes[0].get_xlabel(), fig.axes[0].get_ylabel()
    ('depth d [µm]', 'force F [kN]')
    """
    models = list(models)
    if not models:
        raise OutOfRangeError("models", "[]", "at least one contact model")
    R = models[0].radius
    d = (np.geomspace(1e-6 * R, 0.15 * R, 200) if depth is None
         else np.asarray(depth, dtype=float).ravel())
    if d.size == 0 or not np.all(d > 0):
        raise OutOfRangeError("depth", float(np.min(d)) if d.size else "[]",
                              "(0, inf) m, at least one value")
    Fs = [_answer(m.force, d) for m in models]
    groups = {}
    if points is not None and hasattr(points, "items"):
        labels = {m.label: m for m in models}
        for key, pairs in points.items():
            m = labels.get(key, key)
            if m not in models:
                raise OutOfRangeError("points", str(getattr(key, "label", key)),
                                      "a key among the models drawn (a model or its "
                                      "label)")
            groups[models.index(m)] = _points(pairs)
    elif points:
        groups[None] = _points(points)
    allF = np.concatenate(Fs + [g[:, 1] for g in groups.values()])
    sd, ud = engineering_unit(d, "m")
    sf, uf = engineering_unit(allF, "N")
    fig, (ax,) = _new(fig, 1, ax)
    handles, texts = [], []
    every = max(1, d.size // 12)
    for i, (m, F) in enumerate(zip(models, Fs)):
        err = m.measured_error
        line, = ax.plot(d * sd, F * sf, label=m.label, markevery=(i % every, every),
                        lw=1.1, **_style(i))
        line.measured_error = err           # kept with the line for readers and tests
        line.scale = (sd, sf)
        handles.append(line)
        texts.append(m.label + (f": {_short_error(err)}" if err else ""))
    for i, pts in groups.items():
        if not pts.size:
            continue
        kw = ({"marker": "o", "color": "k", "mfc": "none"} if i is None else
              {"marker": _style(i)["marker"], "color": _style(i)["color"], "mec": "k"})
        line, = ax.plot(pts[:, 0] * sd, pts[:, 1] * sf, ls="none", ms=6, zorder=5,
                        label="computed" if i is None else f"{models[i].label}: computed",
                        **kw)
        line.scale = (sd, sf)
        if i is None or "computed" not in texts:
            handles.append(line)
            texts.append("computed")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"depth d [{ud}]")
    ax.set_ylabel(f"force F [{uf}]")
    m0 = models[0]
    ax.set_title(f"R = {_quantity(m0.radius, 'm')}, L = {_quantity(m0.length, 'm')}, "
                 f"E* = {_quantity(m0.estar, 'Pa')}", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    _legend(ax, handles, texts, fontsize=6,
            title="measured error against the 3D BEM\n(tables/model_accuracy.csv)",
            title_fontsize=6)
    return fig


def _short_error(text):
    """'F a to b, k c to d' of a measured-error text, else its first clause."""
    import re
    m = re.search(r"(F [^,]+, k [^(;]+?)(\s*\(|;|$)", text)
    if m and "not " not in text.split(":")[0]:
        return m.group(1)
    return text.split(";")[0].split(" (")[0]


def _solution(result):
    """The roller solution of a ContactResult (one load) or a RollerSolution itself."""
    sols = getattr(result, "solutions", None)
    if sols is not None:           # a ContactResult
        if len(sols) != 1 or not hasattr(sols[0], "half_width"):
            raise OutOfRangeError("result", getattr(result, "model", "?"),
                                  "a profiled roller's result at one load "
                                  "(Contact.normal with one force or depth)")
        return sols[0]
    if not hasattr(result, "half_width"):
        raise OutOfRangeError("result", type(result).__name__,
                              "a RollerSolution or a ContactResult of a profiled roller")
    return result


def _solutions(result):
    """A list of roller solutions: one result or a sequence of them (a sweep)."""
    if isinstance(result, (list, tuple)):
        if not result:
            raise OutOfRangeError("result", "[]", "at least one roller solution")
        return [_solution(r) for r in result]
    return [_solution(result)]


def _roller_geometry(roller):
    """(length [m], Profile) of a ProfiledRoller or a Contact."""
    length = getattr(roller, "length", None)
    if length is None:                           # a Contact: its Roller has the length
        length = getattr(getattr(roller, "roller", None), "length", None)
    profile = getattr(roller, "profile", None)
    if length is None or not hasattr(profile, "drop"):
        raise OutOfRangeError("roller", type(roller).__name__,
                              "a linecontact.roller.ProfiledRoller or a "
                              "linecontact.contact.Contact (its length and profile)")
    return float(length), profile


def _draw_line_load(ax, sols, length=None):
    """q(x) of each solution on `ax`, the roller's ends marked when `length` is known."""
    sx = engineering_unit(np.concatenate([np.asarray(s.x) for s in sols]
                                         + [[length / 2] if length else []]), "m")
    sq = engineering_unit(np.concatenate([np.asarray(s.q) for s in sols]), "N/m")
    for i, s in enumerate(sols):
        label = (f"F = {_quantity(s.force, 'N')}, tilt {_quantity(s.tilt, 'rad', 3)}"
                 if len(sols) > 1 else f"q(x), {s.method}")
        line, = ax.plot(np.asarray(s.x) * sx[0], np.asarray(s.q) * sq[0], label=label,
                        markevery=max(1, len(s.x) // 15), **_style(i))
        line.scale = (sx[0], sq[0])
        ends = ax.plot([s.contact_start * sx[0], s.contact_end * sx[0]], [0.0, 0.0],
                       ls="none", marker="|", ms=12, mew=2, color=_style(i)["color"],
                       label="contact ends" if i == 0 else "_contact ends")
        ends[0].scale = line.scale
    if length:
        ax.axvline(-length / 2 * sx[0], color="k", lw=1.5, label="roller ends")
        ax.axvline(length / 2 * sx[0], color="k", lw=1.5, label="_roller ends")
    ax.set_xlabel(f"x along the roller [{sx[1]}]")
    ax.set_ylabel(f"line load q [{sq[1]}]")
    ax.grid(True, lw=0.3)
    _legend(ax)
    return sx, sq


@register("line-load")
def line_load(result, roller=None, *, fig=None, ax=None):
    """The line load q(x) along a profiled roller, the contact's and roller's ends marked.

    Parameters
    ----------
    result : RollerSolution or ContactResult, or a sequence of them
        A profiled roller at one load (a ContactResult of ``model="profiled-roller"``
        or ``"iso16281-slicing"``), or several (a sweep: one line each).
    roller : linecontact.roller.ProfiledRoller or linecontact.contact.Contact, optional
        The roller that was solved: with it the roller's ends x = -L/2 and L/2 are
        drawn (vertical lines ``"roller ends"``).
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).
    ax : matplotlib.axes.Axes, optional
        The axes to draw on instead.

    Returns
    -------
    matplotlib.figure.Figure
        One line per solution: x against q with the prefixes that fit (labels), and
        the contact's ends as markers on q = 0 (line ``"contact ends"``).

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9)
    >>> r = c.normal(force=1e3)
    >>> ax = line_load(r, c).axes[0]
    >>> line = ax.lines[0]
    >>> w = r.solutions[0].width * line.scale[0]          # slice widths, axis unit
    >>> ax.get_ylabel(), f"{np.sum(line.get_ydata() * w):.0f} N"
    ('line load q [kN/m]', '1000 N')
    """
    sols = _solutions(result)
    length = _roller_geometry(roller)[0] if roller is not None else None
    fig, (ax,) = _new(fig, 1, ax)
    _draw_line_load(ax, sols, length)
    s = sols[0]
    ax.set_title(f"{s.method}: F = {_quantity(s.force, 'N')}, d = "
                 f"{_quantity(s.depth, 'm')}, tilt {_quantity(s.tilt, 'rad', 3)}"
                 if len(sols) == 1 else f"{s.method}: {len(sols)} loads", fontsize=9)
    return fig


@register("profiled-roller")
def profiled_roller(result, roller, *, fig=None):
    r"""A profiled roller's line load q(x) above its profile, the ends marked.

    Top: q(x) (:func:`line_load`), the roller's ends and the contact's ends. Bottom:
    the profile drop P(x) over the roller's length and, for each solution, the rigid
    approach :math:`d + \theta x`: the bodies overlap (and the slices are laid) where
    it exceeds P(x).

    Parameters
    ----------
    result : RollerSolution or ContactResult, or a sequence of them
        A profiled roller at one load, or several.
    roller : linecontact.roller.ProfiledRoller or linecontact.contact.Contact
        The roller that was solved (its length and profile).
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels sharing x: q(x) and (line ``"profile drop P(x)"``, the profile's
        label in the legend) the drop with the approach lines ``"d + theta x"``.

    Notes
    -----
    The drop is drawn at 401 points inside the roller, 1e-9 L from its ends (where a
    logarithmic profile's drop is infinite; non-finite values are not drawn).

    Examples
    --------
    >>> from linecontact.roller import ProfiledRoller
    >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
    >>> fig = profiled_roller(r.at_force(1e3), r)
    >>> fig.axes[1].lines[0].get_label(), fig.axes[1].get_ylabel()
    ('profile drop P(x)', 'drop, approach [µm]')
    """
    sols = _solutions(result)
    length, profile = _roller_geometry(roller)
    fig, (ax, ax2) = _new(fig, 2, sharex=True)
    sx, _ = _draw_line_load(ax, sols, length)
    ax.set_xlabel("")
    ax.set_title(f"{sols[0].method}: {getattr(profile, 'label', type(profile).__name__)}",
                 fontsize=9)
    x = np.linspace(-0.5, 0.5, 401) * length * (1 - 1e-9)
    with np.errstate(divide="ignore", invalid="ignore"):
        P = np.asarray(profile.drop(x), dtype=float)
    P = np.where(np.isfinite(P), P, np.nan)
    approach = [s.depth + s.tilt * x for s in sols]
    sz, uz = engineering_unit(np.concatenate([P] + approach), "m")
    line, = ax2.plot(x * sx[0], P * sz, color="k", lw=1.5, label="profile drop P(x)")
    line.scale = (sx[0], sz)
    for i, (s, a) in enumerate(zip(sols, approach)):
        ln, = ax2.plot(x * sx[0], a * sz, ls="--", color=_style(i)["color"], lw=1,
                       label=r"d + $\theta$ x" + (f" (F = {_quantity(s.force, 'N')})"
                                                  if len(sols) > 1 else ""))
        ln.scale = (sx[0], sz)
    for e in (-length / 2, length / 2):
        ax2.axvline(e * sx[0], color="k", lw=1.5)
    top = np.nanmax(np.concatenate(approach)) * sz
    ax2.set_ylim(0.0, 2.5 * top if top > 0 else None)
    ax2.set_xlabel(f"x along the roller [{sx[1]}]")
    ax2.set_ylabel(f"drop, approach [{uz}]")
    ax2.grid(True, lw=0.3)
    _legend(ax2)
    return fig


def pressure_field(result, ny=81):
    r"""The contact pressure p(x, y) of a profiled roller's slices.

    Each slice k carries the plane-strain Hertz pressure of its own line load, an
    ellipse of half-width :math:`b_k` and peak :math:`p_k = 2 q_k/(\pi b_k)` (the
    solution's ``half_width`` and ``pressure``):

    .. math:: p(x_k, y) = p_k \sqrt{1 - (y/b_k)^2}, \quad |y| < b_k; \quad 0 \text{ else}

    Parameters
    ----------
    result : linecontact.roller.RollerSolution or linecontact.contact.ContactResult
        A profiled roller at one load.
    ny : int
        Points across the contact, 3 <= ny [-]; the y grid spans the largest b_k.

    Returns
    -------
    x, y, p : ndarray
        Slice centres x [m] (n), across-axis positions y [m] (ny) and the pressure
        p [Pa] (ny, n).

    Notes
    -----
    Valid as the slice model that produced the solution (slices much narrower than
    they are long; see docs/profiled_rollers.md). The integral of p over y is q_k in
    each slice (pi b_k p_k / 2).

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> r = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9).normal(force=1e3)
    >>> x, y, p = pressure_field(r)
    >>> f"{p.max() / 1e6:.0f} MPa"
    '1521 MPa'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 5.6.
    """
    sol = _solution(result)
    ny = int(ny)
    if ny < 3:
        raise OutOfRangeError("ny", ny, "[3, inf)")
    b = np.asarray(sol.half_width, dtype=float)
    pk = np.asarray(sol.pressure, dtype=float)
    bmax = float(b.max()) if b.size and b.max() > 0 else 1.0
    y = np.linspace(-bmax, bmax, ny)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = 1.0 - (y[:, None] / np.where(b > 0, b, np.inf)[None, :]) ** 2
    p = np.where((s > 0) & (b[None, :] > 0), np.nan_to_num(pk)[None, :]
                 * np.sqrt(np.clip(s, 0, None)), 0.0)
    return np.asarray(sol.x, dtype=float), y, p


@register("pressure-map")
def pressure_map(result, *, ny=81, fig=None, ax=None):
    """The pressure map p(x, y) of a profiled roller (:func:`pressure_field`).

    Parameters
    ----------
    result : linecontact.roller.RollerSolution or linecontact.contact.ContactResult
        A profiled roller at one load.
    ny : int
        Points across the contact, 3 <= ny [-].
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).
    ax : matplotlib.axes.Axes, optional
        The axes to draw on instead.

    Returns
    -------
    matplotlib.figure.Figure
        A colour map of p over x (along) and y (across), with a colour bar, in the
        prefixes that fit (labels); ``fig.axes[0].collections[0].get_array()`` holds
        p in the colour bar's unit.

    Notes
    -----
    Valid as :func:`pressure_field`.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> r = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9).normal(force=1e3)
    >>> fig = pressure_map(r)
    >>> f"{fig.axes[0].collections[0].get_array().max():.3g}", fig.axes[1].get_ylabel()
    ('1.52', 'pressure p [GPa]')
    """
    x, y, p = pressure_field(result, ny)
    fig, (ax,) = _new(fig, 1, ax)
    sx, ux = engineering_unit(x, "m")
    sy, uy = engineering_unit(y, "m")
    sp, up = engineering_unit(p, "Pa")
    mesh = ax.pcolormesh(x * sx, y * sy, p * sp, shading="nearest", cmap="viridis")
    ax.figure.colorbar(mesh, ax=ax, label=f"pressure p [{up}]")
    ax.set_xlabel(f"x along the roller [{ux}]")
    ax.set_ylabel(f"y across [{uy}]")
    sol = _solution(result)
    ax.set_title(f"{sol.method}: slice pressure, peak {_quantity(np.nanmax(p), 'Pa')}",
                 fontsize=9)
    return fig


# --------------------------------------------------------------------------------------
# adhesion
# --------------------------------------------------------------------------------------
@register("adhesion")
def adhesion(contact, depth_max=None, *, n=201, loop=None, points=None, fig=None,
             ax=None):
    r"""F(d) of an adhesive contact on approach and retraction, the pull-off marked.

    The curves are :meth:`linecontact.adhesion.AdhesiveContact.hysteresis` (the rule
    of Hess under depth control: the approach jumps into contact at d = 0, the
    retraction jumps off at the depth-controlled pull-off); the pull-off states under
    depth and force control (:meth:`~linecontact.adhesion.AdhesiveContact.pull_off`)
    are marked on them. For a finite cylinder (a
    :class:`~linecontact.adhesion.CylinderAdhesion`) the references beside it are
    the 2D JKR pull-off of the whole length, :math:`L\,F_{c,2D}/L`
    (:func:`~linecontact.adhesion.jkr_cylinder_pull_off`), and the finite roller's
    pull-off from the adhesive BEM table (force control as a line, depth control as a
    point; not drawn, and the title says so, where the case lies outside the table).

    Parameters
    ----------
    contact : linecontact.adhesion.CylinderAdhesion or AdhesiveContact
        The adhesive contact (a CylinderAdhesion: its MDR contact ``mdr`` gives the
        curves, its table the finite roller's pull-off).
    depth_max : float, optional
        Deepest point of the cycle, 0 < depth_max [m] (needed unless `loop` is given).
    n : int, optional
        Points per branch [-].
    loop : dict, optional
        The cycle already computed (what ``hysteresis`` returned): drawn as given.
    points : sequence of (depth, force), optional
        Computed states to mark, d [m] and F [N] (NaN pairs are skipped), e.g. the
        calculator's rows: black circles, line ``"computed"``.
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).
    ax : matplotlib.axes.Axes, optional
        The axes to draw on instead.

    Returns
    -------
    matplotlib.figure.Figure
        Lines ``"approach"`` and ``"retraction"`` (the loop's arrays, in the units of
        the axis labels; ``line.scale`` the factors from SI), the markers
        ``"pull-off, depth control"`` and ``"pull-off, force control"`` (for a
        cylinder with `` (MDR)`` appended: the rule of Hess's values), and for a
        cylinder ``"2D JKR pull-off"``, ``"finite roller (BEM), force control"`` and
        ``"finite roller (BEM), depth control"``.

    Notes
    -----
    Valid as the adhesive contact (JKR: a large Tabor parameter; the MDR's rule on an
    elongated contact is an approximation, its error against the BEM given in the
    pull-off's legend entry; docs/adhesion.md).

    Examples
    --------
    >>> from linecontact.models import get_model
    >>> from linecontact.adhesion import CylinderAdhesion
    >>> c = CylinderAdhesion(get_model("universal", 1e-3, 2e-3, 6.7e4), 0.05)
    >>> ax = adhesion(c, 30e-6, n=41).axes[0]
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('depth d [µm]', 'force F [mN]')
    """
    cyl = contact if hasattr(contact, "pull_off_2d") else None
    adh = cyl.mdr if cyl is not None else contact
    if not hasattr(adh, "hysteresis"):
        raise OutOfRangeError("contact", type(contact).__name__,
                              "an AdhesiveContact or a CylinderAdhesion")
    if loop is None:
        if depth_max is None:
            raise OutOfRangeError("depth_max", "None", "(0, inf) m",
                                  hint="the deepest point of the cycle (or loop=)")
        loop = adh.hysteresis(depth_max, n)
    da, Fa = np.asarray(loop["approach_depth"]), np.asarray(loop["approach_force"])
    dr, Fr = np.asarray(loop["retraction_depth"]), np.asarray(loop["retraction_force"])
    marks = []                       # (label, d or None, F, style)
    title = [f"w = {_quantity(adh.work, 'J/m^2')}, E* = {_quantity(adh.estar, 'Pa')}",
             f"lost per cycle {_quantity(float(loop.get('energy', np.nan)), 'J')}"]
    if adh.work > 0:
        off_d, off_f = adh.pull_off("depth"), adh.pull_off("force")
        by = " (MDR)" if cyl is not None else ""
        marks += [("pull-off, depth control" + by, off_d["depth"], off_d["force"],
                   {"marker": "o", "color": "C3", "ms": 8, "mfc": "none", "mew": 1.5}),
                  ("pull-off, force control" + by, off_f["depth"], off_f["force"],
                   {"marker": "v", "color": "C3", "ms": 8})]
    refs = []                        # (label, F, style)
    if cyl is not None:
        refs.append(("2D JKR pull-off", cyl.pull_off_2d,
                     {"color": "0.35", "ls": ":", "lw": 1.2}))
        try:
            bem_f, bem_d = cyl.pull_off("force"), cyl.pull_off("depth")
        except OutOfRangeError as exc:
            title.append("BEM table: " + str(exc).split(" is outside")[0]
                         + " outside it")
        else:
            refs.append(("finite roller (BEM), force control", bem_f["force"],
                         {"color": "C2", "ls": "--", "lw": 1.2}))
            marks.append(("finite roller (BEM), depth control", bem_d["depth"],
                          bem_d["force"], {"marker": "s", "color": "C2", "ms": 7,
                                           "mfc": "none", "mew": 1.5}))
            title.append(f"MDR pull-off (force control) {bem_f['mdr_error']:+.1%} "
                         "against the BEM")
    pts = _points(points) if points is not None else np.zeros((0, 2))
    sd, ud = engineering_unit(np.concatenate([da, dr, pts[:, 0]]), "m")
    sf, uf = engineering_unit(np.concatenate([Fa, Fr, [r[1] for r in refs], pts[:, 1]]),
                              "N")
    fig, (ax,) = _new(fig, 1, ax)
    for d, F, label, st in ((da, Fa, "approach", _style(0)), (dr, Fr, "retraction",
                                                              _style(1))):
        st = dict(st, linestyle="-" if label == "approach" else "--")
        line, = ax.plot(d * sd, F * sf, label=label, markevery=max(1, d.size // 12), **st)
        line.scale = (sd, sf)
    for label, F, st in refs:
        ax.axhline(F * sf, label=label, **st)
    for label, d, F, st in marks:
        line, = ax.plot([d * sd], [F * sf], ls="none", label=label, zorder=6, **st)
        line.scale = (sd, sf)
    if pts.size:
        line, = ax.plot(pts[:, 0] * sd, pts[:, 1] * sf, ls="none", marker="o", color="k",
                        mfc="none", ms=7, label="computed", zorder=7)
        line.scale = (sd, sf)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.axvline(0.0, color="k", lw=0.5)
    ax.set_xlabel(f"depth d [{ud}]")
    ax.set_ylabel(f"force F [{uf}]")
    ax.set_title("; ".join(title), fontsize=8)
    ax.grid(True, lw=0.3)
    _legend(ax)
    return fig


# --------------------------------------------------------------------------------------
# viscoelastic: creep and relaxation
# --------------------------------------------------------------------------------------
def _given(result, given):
    """'force' (creep: d(t) under F(t)) or 'depth' (relaxation: F(t) under d(t))."""
    if given is None:
        why = getattr(result, "reasons", {}).get("long_term_depth")
        prescribed = isinstance(why, tuple) and why and isinstance(why[0], dict) \
            and why[0].get("depth") == "given"
        return "depth" if prescribed else "force"
    if given not in ("force", "depth"):
        raise UnknownNameError("given", given, ["force", "depth"])
    return given


@register("creep")
def creep(result, *, given=None, fig=None):
    """A viscoelastic contact's response against its load history.

    Creep (:meth:`linecontact.contact.Contact.creep`): the force history F(t) on top,
    the depth d(t) below it with the long-term depth under the last force. Relaxation
    (:meth:`~linecontact.contact.Contact.relaxation_history`): the depth history d(t)
    on top, the force F(t) below.

    Parameters
    ----------
    result : linecontact.contact.CreepResult
        The history.
    given : {"force", "depth"}, optional
        Which history was prescribed (default: read from the result, whose
        ``reasons`` say that a relaxation's depth was given).
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        Two panels sharing t: the prescribed history (line ``"force history"`` or
        ``"depth history"``) and the response (line ``"depth"`` or ``"force"``), in
        the units of the axis labels (``line.scale``: the factors from SI).

    Examples
    --------
    >>> import math
    >>> from linecontact.contact import Contact, Roller, Elastic, Viscoelastic
    >>> from linecontact.viscoelastic import StandardLinearSolid
    >>> c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
    ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    >>> ax = creep(c.creep([0.0, 10.0, 30.0], force=1e3)).axes[1]
    >>> [f"{d:.2f}" for d in ax.lines[0].get_ydata()], ax.get_ylabel()
    (['82.58', '122.15', '168.03'], 'depth d [µm]')
    """
    t = np.asarray(getattr(result, "time", []), dtype=float)
    if t.size == 0 or not hasattr(result, "long_term_depth"):
        raise UnknownNameError("result", type(result).__name__, ["CreepResult"])
    given = _given(result, given)
    F, d = np.asarray(result.force, dtype=float), np.asarray(result.depth, dtype=float)
    st, ut = engineering_unit(t, "s")
    fig, (ax1, ax2) = _new(fig, 2, sharex=True)
    hist, resp = ((F, "N", "force", "F"), (d, "m", "depth", "d")) if given == "force" \
        else ((d, "m", "depth", "d"), (F, "N", "force", "F"))
    long_term = result.long_term_depth if given == "force" else None
    for ax, (v, unit, name, sym), label, i in ((ax1, hist, f"{hist[2]} history", 0),
                                               (ax2, resp, resp[2], 1)):
        extra = [long_term] if (ax is ax2 and long_term is not None) else []
        sv, uv = engineering_unit(np.concatenate([v, extra]), unit)
        line, = ax.plot(t * st, v * sv, label=label, markevery=max(1, t.size // 15),
                        drawstyle="default", **_style(i))
        line.scale = (st, sv)
        if extra:
            ax.axhline(long_term * sv, ls=":", color="0.4", label="long-term depth")
        ax.set_ylabel(f"{name} {sym} [{uv}]")
        ax.grid(True, lw=0.3)
        _legend(ax)
    ax2.set_xlabel(f"time t [{ut}]")
    kind = "creep under the force history" if given == "force" else \
        "relaxation under the depth history"
    ax1.set_title(f"{result.model}: {kind} (Lee & Radok)", fontsize=9)
    return fig


# --------------------------------------------------------------------------------------
# tangential: partial slip and the fretting loop
# --------------------------------------------------------------------------------------
def _tangential_name(c):
    """'across (BEM)', 'along (BEM)', 'x (Mindlin)', 'y (Mindlin)' or 'MDR (G*/E*)'."""
    method = getattr(c, "method", "mdr")
    if method == "bem":
        return f"{c.direction} (BEM)"
    if method == "mindlin":
        return f"{c.direction} (Mindlin)"
    if method == "ellipse":
        return f"{c.direction} (equivalent ellipse)"
    return "MDR (G*/E*)"


@register("hysteresis")
def hysteresis(contact, amplitude, *, n=101, beyond="raise", points=None, fig=None):
    """The tangential force F_t(u): partial slip to gross slip, and the fretting loop.

    Top: the monotonic loading F_t(u) from stick to gross slip
    (:meth:`linecontact.tangential.TangentialContact.force` up to the gross-slip shift
    u*, marked with mu F). Bottom: the closed Masing loop of amplitude u0
    (:meth:`~linecontact.tangential.TangentialContact.loop`) and the energy it
    dissipates per cycle. Several contacts (e.g. the BEM law ``direction="across"``
    and ``"along"``) are drawn side by side, each its own colour.

    Parameters
    ----------
    contact : TangentialContact or sequence of TangentialContact
        The contact(s) at their normal load, with the friction coefficient (also
        :class:`linecontact.mindlin.EllipticalTangentialContact`, a crowned roller's
        ellipse by direction).
    amplitude : float
        Shift amplitude u0, 0 < u0 <= u* of every contact unless ``beyond`` is
        ``"saturate"`` [m].
    n : int
        Points per branch, 2 <= n [-].
    beyond : {"raise", "saturate"}
        Beyond gross slip: refuse, or add the sliding (Coulomb) part.
    points : sequence of (shift, tangential force), optional
        Computed states to mark on the loading curve, u [m] and F_t [N] (e.g. a
        :class:`~linecontact.contact.TangentialResult`'s ``shift`` and
        ``tangential_force``).
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        Panel 1: lines ``"<name>: partial slip"`` (u, F_t) and markers
        ``"<name>: gross slip"`` at (u*, mu F); panel 2: lines ``"<name>: loop"``
        (2n - 1 points, closed) and ``"<name>: loading"``; ``line.scale`` the
        factors from SI to the axis units. <name> is ``"MDR (G*/E*)"``, or the
        direction for the BEM law (``"across (BEM)"``).

    Notes
    -----
    Valid as the contact's law: 0 < u0 <= u*, the normal state held constant.

    Examples
    --------
    >>> from linecontact.models import get_model
    >>> from linecontact.tangential import TangentialContact
    >>> c = TangentialContact(get_model("universal", 5e-3, 10e-3, 115.38e9), 0.1,
    ...                       0.8 * 115.38e9, force=1e3)
    >>> u0 = 0.5 * c.gross_slip_shift
    >>> loop = hysteresis(c, u0).axes[1].lines[0]            # closed, through (u0, F(u0))
    >>> f"{loop.get_ydata()[0]:.2f} N", f"{loop.get_ydata()[-1]:.2f} N", f"{c.force(u0):.2f} N"
    ('53.15 N', '53.15 N', '53.15 N')
    """
    contacts = list(contact) if isinstance(contact, (list, tuple)) else [contact]
    if not contacts:
        raise OutOfRangeError("contact", "[]", "at least one TangentialContact")
    u0 = float(amplitude)
    n = int(n)
    mono, loops = [], []
    for c in contacts:
        ustar = float(c.gross_slip_shift)
        top = max(ustar, u0) if beyond == "saturate" else ustar
        up = np.linspace(0.0, top, n)
        mono.append((up, np.asarray(c.force(up, beyond="saturate" if top > ustar
                                            else "raise"), dtype=float), ustar))
        u, ft = c.loop(u0, n, beyond=beyond)
        ul = np.linspace(0.0, u0, n)
        loops.append((u, ft, ul, np.asarray(c.force(ul, beyond=beyond), dtype=float),
                      float(c.dissipated_energy(u0, beyond=beyond))))
    pts = _points(points) if points is not None else np.zeros((0, 2))
    su, uu = engineering_unit(np.concatenate([m[0] for m in mono] + [pts[:, 0]]), "m")
    sf, uf = engineering_unit(np.concatenate([m[1] for m in mono]
                                             + [lp[1] for lp in loops]
                                             + [[c.gross_slip_force for c in contacts]]),
                              "N")
    fig, (ax1, ax2) = _new(fig, 2)
    for i, (c, (up, fu, ustar), (u, ft, ul, fl, W)) in enumerate(zip(contacts, mono,
                                                                     loops)):
        name, st = _tangential_name(c), _style(i)
        line, = ax1.plot(up * su, fu * sf, label=f"{name}: partial slip",
                         markevery=max(1, n // 10), **st)
        line.scale = (su, sf)
        g, = ax1.plot([ustar * su], [c.gross_slip_force * sf], ls="none", marker="*",
                      ms=11, color=st["color"], mec="k", label=f"{name}: gross slip",
                      zorder=6)
        g.scale = (su, sf)
        ax1.axhline(c.gross_slip_force * sf, color=st["color"], lw=0.6, ls=":")
        line, = ax2.plot(u * su, ft * sf, label=f"{name}: loop",
                         markevery=max(1, n // 8), **st)
        line.scale = (su, sf)
        line._legend_text = f"{name}: loop, W = {_quantity(W, 'J')} per cycle"
        ld, = ax2.plot(ul * su, fl * sf, ls=":", lw=0.9, color=st["color"],
                       label=f"{name}: loading")
        ld.scale = (su, sf)
    if pts.size:
        p, = ax1.plot(pts[:, 0] * su, pts[:, 1] * sf, ls="none", marker="o", color="k",
                      mfc="none", ms=7, label="computed", zorder=7)
        p.scale = (su, sf)
    c0 = contacts[0]
    ax1.set_title(f"mu = {c0.friction:g}, F = {_quantity(c0.normal_force, 'N')}, "
                  f"d = {_quantity(c0.depth, 'm')}: partial slip up to gross slip",
                  fontsize=9)
    ax2.set_title(f"fretting loop, amplitude u0 = {_quantity(u0, 'm')} (Masing)",
                  fontsize=9)
    for ax in (ax1, ax2):
        ax.set_xlabel(f"tangential shift u [{uu}]")
        ax.set_ylabel(f"tangential force F_t [{uf}]")
        ax.grid(True, lw=0.3)
        handles = ax.lines
        texts = [getattr(h, "_legend_text", h.get_label()) for h in handles]
        keep = [k for k, t in enumerate(texts) if not t.startswith("_")]
        _legend(ax, [handles[k] for k in keep], [texts[k] for k in keep])
    return fig


# --------------------------------------------------------------------------------------
# subsurface stresses
# --------------------------------------------------------------------------------------
_MEASURE_NAMES = {"tresca": "Tresca (max. shear)", "von_mises": "von Mises",
                  "orthogonal_shear": "orthogonal shear |tau_yz|"}


@register("stresses")
def stresses(result, *, measure="von_mises", case=None, n=121, fig=None):
    """Subsurface stresses: the worst section's field, the maxima along the roller, and
    the case-hardening check.

    Panel 1: the measure on the section across the roller at the worst slice
    (:meth:`linecontact.stresses.SubsurfaceStresses.section`, the plane-strain strip
    of that slice), filled contours over y (across) and z (depth, downwards), the
    worst point (:attr:`~linecontact.stresses.SubsurfaceStresses.worst`, 3D-corrected
    where the result is) marked with its value. Panel 2: the maximum below each slice
    (``value``) along the roller and, with a case check, the allowable stress at the
    depth of each slice's maximum (the check's allowable against depth,
    interpolated). Panel 3 (with a case check): the stress envelope and the allowable
    against depth (:class:`~linecontact.stresses.CaseCheck`), the largest ratio
    marked.

    Parameters
    ----------
    result : linecontact.stresses.SubsurfaceStresses
        From :func:`~linecontact.stresses.roller_stresses` or
        :func:`~linecontact.stresses.line_contact_stresses`.
    measure : {"von_mises", "tresca", "orthogonal_shear"}, optional
        The measure drawn.
    case : linecontact.stresses.CaseCheck, optional
        The case-hardening check of this result (:func:`~linecontact.stresses.case_check`)
        with the same measure.
    n : int, optional
        Grid points across and in depth of the section, 11 <= n [-].
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        Panel 1: the contours (``axes[0].collections[0]``), the marker line
        ``"maximum"`` at (y, z) of the worst; panel 2: line ``"maximum below each
        slice"`` (x, value) and ``"allowable at that depth"``; panel 3: lines
        ``"stress envelope"`` and ``"allowable"`` (depth, stress). ``line.scale``:
        the factors from SI to the axis units.

    Notes
    -----
    The section's field is the plane-strain strip; the marked maximum is the
    result's worst (with the 3D correction where applied, its position from the 3D
    search), so the two may differ by the correction (up to 5 %; docs/stresses.md).

    Examples
    --------
    >>> from linecontact.stresses import line_contact_stresses
    >>> s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9)
    >>> ax = stresses(s, measure="tresca").axes[0]
    >>> m = [ln for ln in ax.lines if ln.get_label() == "maximum"][0]
    >>> f"{m.get_ydata()[0]:.1f} {ax.get_ylabel()}"
    '58.4 depth z [µm]'
    """
    from .stresses import MEASURES

    if measure not in MEASURES:
        raise UnknownNameError("measure", measure, list(MEASURES))
    if case is not None and case.measure != measure:
        raise OutOfRangeError("case", case.measure, f"a check of measure {measure!r}",
                              hint="case_check(..., measure=...) and measure= must match")
    n = int(n)
    if n < 11:
        raise OutOfRangeError("n", n, "[11, inf)")
    w = result.worst[measure]
    k = int(w["slice"])
    b = float(result.half_width[k])
    y = np.linspace(-2.0 * b, 2.0 * b, n)
    z = np.linspace(0.0, max(2.0 * b, 1.6 * w["z"]), n)
    field = result.section(w["x"], y, z).measure(measure)          # (ny, nz)
    sl, ul = engineering_unit(np.concatenate([y, z]), "m")
    values = [field, [w["value"]], result.value[measure]]
    if case is not None:
        values += [case.stress, case.allowable]
    ss, us = engineering_unit(np.concatenate([np.ravel(v) for v in values]), "Pa")
    fig, axes = _new(fig, 3 if case is not None else 2)
    ax = axes[0]
    cs = ax.contourf(y * sl, z * sl, field.T * ss, levels=14, cmap="magma_r")
    ax.figure.colorbar(cs, ax=ax, label=f"{_MEASURE_NAMES[measure]} [{us}]")
    ax.contour(y * sl, z * sl, field.T * ss, levels=cs.levels, colors="k",
               linewidths=0.3)
    mk, = ax.plot([w["y"] * sl], [w["z"] * sl], ls="none", marker="X", ms=10,
                  color="C0", mec="w", label="maximum", zorder=6)
    mk.scale = (sl, sl)
    held = measure in getattr(result, "withheld", {})    # edge loaded: not converged
    ax.annotate(f"max {_quantity(w['value'], 'Pa')}\n({result.method})" if not held else
                f"max {_quantity(w['value'], 'Pa')} at this slice width\n(edge loaded: "
                "not converged, grows as the slices are refined)",
                (w["y"] * sl, w["z"] * sl), xytext=(8, 8), textcoords="offset points",
                fontsize=7, color="C0")
    ax.set_ylim(z[-1] * sl, 0.0)                                   # depth downwards
    ax.set_xlabel(f"y across the contact [{ul}]")
    ax.set_ylabel(f"depth z [{ul}]")
    ax.set_title(f"section at x = {_quantity(w['x'], 'm')} (slice {k}), "
                 f"b = {_quantity(b, 'm')}, mu = {result.friction:g}", fontsize=9)
    ax2 = axes[1]
    x = np.asarray(result.x, dtype=float)
    sx, ux = engineering_unit(x if np.any(x) else [b], "m")
    line, = ax2.plot(x * sx, result.value[measure] * ss, label="maximum below each slice",
                     markevery=max(1, x.size // 15), **_style(0))
    line.scale = (sx, ss)
    wk, = ax2.plot([w["x"] * sx], [w["value"] * ss], ls="none", marker="X", ms=10,
                   color="C0", mec="k", label=f"worst ({result.method})", zorder=6)
    wk.scale = (sx, ss)
    if case is not None:
        allow = np.interp(result.depth[measure], case.depths, case.allowable)
        al, = ax2.plot(x * sx, allow * ss, label="allowable at that depth",
                       markevery=max(1, x.size // 15), **_style(3))
        al.scale = (sx, ss)
    ax2.set_xlabel(f"x along the roller [{ux}]")
    ax2.set_ylabel(f"{_MEASURE_NAMES[measure]} [{us}]")
    ax2.set_ylim(bottom=0.0)
    ax2.grid(True, lw=0.3)
    ax2.set_title("maxima along the roller (plane-strain strip per slice)", fontsize=9)
    _legend(ax2)
    if case is not None:
        ax3 = axes[2]
        sd, ud = engineering_unit(case.depths, "m")
        for v, label, i in ((case.stress, "stress envelope (max over y)", 0),
                            (case.allowable, "allowable", 3)):
            ln, = ax3.plot(case.depths * sd, v * ss, label=label,
                           markevery=max(1, case.depths.size // 15), **_style(i))
            ln.scale = (sd, ss)
        j = int(np.argmax(case.ratio))
        mr, = ax3.plot([case.depth_at_max * sd], [case.stress[j] * ss], ls="none",
                       marker="X", ms=10, color="C3", mec="k", zorder=6,
                       label=f"largest ratio {case.max_ratio:.3g}")
        mr.scale = (sd, ss)
        if case.min_case_depth is not None:
            ax3.axvline(case.min_case_depth * sd, color="0.3", ls="--", lw=1,
                        label=f"minimum case depth {_quantity(case.min_case_depth, 'm')}")
        ax3.set_xlabel(f"depth z [{ud}]")
        ax3.set_ylabel(f"stress [{us}]")
        ax3.set_ylim(bottom=0.0)
        ax3.grid(True, lw=0.3)
        ax3.set_title("case-hardening check below the worst slice", fontsize=9)
        _legend(ax3)
    return fig


# --------------------------------------------------------------------------------------
# bearing
# --------------------------------------------------------------------------------------
#: Per-roller quantities of a BearingSolution drawn around the ring, in this order:
#: (attribute, axis name, SI unit). A quantity that is None (not computed) is left
#: out; a later one (film ratio, damage) is one more row.
BEARING_FIELDS = (("roller_loads", "roller load Q", "N"),
                  ("roller_moments", "roller moment M", "N m"),
                  ("roller_tilts", "roller tilt", "rad"))
#: The life panels of a bearing solved at a speed (``solve(..., speed=)``): each roller's
#: film ratio, the smaller of its two contacts' (where the film inputs are given;
#: unloaded rollers, Lambda = inf, are left out), and its share of the L10r damage.
BEARING_LIFE_FIELDS = ((("film_ratio_inner", "film_ratio_outer"), "film ratio Lambda",
                        "-"),
                       ("roller_damage", "damage share", "-"))


@register("bearing")
def bearing(solution, *, fig=None):
    """Roller loads, moments and tilts around the ring of a radial roller bearing.

    One panel per per-roller quantity the solution holds (:data:`BEARING_FIELDS`;
    moments and tilts that are all zero to round-off, as with aligned rings, are left
    out and the title says so; for a solution at a speed, the film ratio and the damage
    share, :data:`BEARING_LIFE_FIELDS`), against the roller's azimuth from the load
    line, the load zone shaded.

    Parameters
    ----------
    solution : linecontact.bearing.BearingSolution
        From :meth:`linecontact.bearing.RadialRollerBearing.solve`.
    fig : matplotlib.figure.Figure or SubFigure, optional
        Where to draw (default a new figure).

    Returns
    -------
    matplotlib.figure.Figure
        One panel per quantity, each a line with markers (the rollers ordered by
        azimuth psi in (-180, 180] deg; ``line.order`` the rollers' indices,
        ``line.scale`` the factor from SI to the axis unit).

    Examples
    --------
    >>> from linecontact.bearing import RadialRollerBearing
    >>> s = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3).solve(10e3)
    >>> ax = bearing(s).axes[0]
    >>> ax.get_ylabel(), f"{ax.lines[0].get_ydata().max():.3f}"
    ('roller load Q [kN]', '2.914')
    """
    if not hasattr(solution, "roller_loads") or not hasattr(solution, "azimuth"):
        raise OutOfRangeError("solution", type(solution).__name__,
                              "a linecontact.bearing.BearingSolution")
    psi = np.degrees(np.angle(np.exp(1j * np.asarray(solution.azimuth, dtype=float))))
    psi = np.where(psi <= -180.0, psi + 360.0, psi)
    order = np.argsort(psi, kind="stable")
    shown, zero = [], []
    # round-off: 1e-12 of the largest roller load times the laminae's span (about the
    # roller length) for a moment, 1e-12 rad for a tilt (a symmetric roller between
    # aligned rings, solved exactly, has moments of 1e-17 Q L); exact zeros elsewhere
    span = 2 * float(np.max(np.abs(solution.slice_x))) if getattr(
        solution, "slice_x", None) is not None and np.size(solution.slice_x) else 0.0
    tiny = {"roller_moments": 1e-12 * float(np.max(solution.roller_loads)) * span,
            "roller_tilts": 1e-12}
    fields = BEARING_FIELDS
    if getattr(solution, "speed", None) is not None:
        fields = fields + BEARING_LIFE_FIELDS
    for attr, name, unit in fields:
        if isinstance(attr, tuple):          # the smaller of two contacts' values
            parts = [getattr(solution, a, None) for a in attr]
            v = None if any(p is None for p in parts) else np.minimum(*parts)
        else:
            v = getattr(solution, attr, None)
        if v is None:
            continue
        v = np.asarray(v, dtype=float)
        v = np.where(np.isfinite(v), v, np.nan)     # Lambda = inf: no film to show
        small = np.abs(v) <= tiny[attr] if attr in tiny else v == 0
        if attr != "roller_loads" and np.all(small):
            zero.append(name.split()[1])            # "moment", "tilt"
            continue
        shown.append((v, name, unit))
    fig, axes = _new(fig, len(shown), sharex=True)
    zone = np.degrees(float(solution.load_zone))
    for i, (ax, (v, name, unit)) in enumerate(zip(axes, shown)):
        s, u = engineering_unit(v, unit)
        line, = ax.plot(psi[order], v[order] * s, label=name, **_style(i))
        line.order, line.scale = order, s
        ax.axvspan(-zone, zone, color="C0", alpha=0.07, lw=0,
                   label=f"load zone \u00b1{zone:.4g} deg")
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_ylabel(f"{name} [{u}]")
        ax.grid(True, lw=0.3)
        _legend(ax)
    axes[-1].set_xlabel("roller azimuth psi from the load line [deg]")
    axes[-1].set_xlim(-180.0, 180.0)
    axes[-1].set_xticks(np.arange(-180, 181, 45))
    title = (f"Z = {psi.size}, F_r = {_quantity(solution.radial_load, 'N')}, "
             f"M = {_quantity(solution.moment, 'N m')}, tilt "
             f"{_quantity(solution.tilt, 'rad', 3)} ({solution.model.split(' (')[0]})")
    if zero:
        title += f"; {' and '.join(zero)} zero"
    axes[0].set_title(title, fontsize=8)
    return fig
