r"""Figures of the library's results: the pictures an engineer would rather look at.

Each function draws one result of the library on a matplotlib ``Axes`` (a new figure
when none is given) and returns the ``Figure``; :func:`save` writes it as PNG, SVG or
PDF. Nothing here computes physics of its own: the curves are the values the library
returns (the models' F(d), a roller solution's q(x) and slice pressures, a tangential
contact's Masing loop, a creep history), so a figure shows exactly what the numbers
are.

- :func:`force_depth`: F(d) of several contact laws for one cylinder, each drawn only
  where it answers (its validity range), its measured error against the 3D BEM in the
  legend (tables/model_accuracy.csv), and optionally computed points on top;
- :func:`line_load`: the line load q(x) along a profiled roller;
- :func:`pressure_map`: the contact pressure p(x, y) of a profiled roller, each slice
  the plane-strain Hertz ellipse of its own load (:func:`pressure_field`);
- :func:`hysteresis`: the tangential force-shift loop of a contact (Masing);
- :func:`creep`: the depth d(t) (and force) of a viscoelastic contact.

A feature that lands later (the subsurface stress section, a bearing's load
distribution) adds its figure with :func:`register`; :data:`PLOTS` lists them all by
name.

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

from .errors import OutOfRangeError, UnknownNameError

__all__ = ["force_depth", "line_load", "pressure_field", "pressure_map", "hysteresis",
           "creep", "save", "register", "PLOTS", "FORMATS", "MissingDependencyError"]

#: File formats :func:`save` writes (by the file's extension).
FORMATS = ("png", "svg", "pdf")

#: Every figure by name: name -> function (a later feature adds its own, see register).
PLOTS: dict = {}


class MissingDependencyError(ImportError):
    """matplotlib is not installed: the message says how to install it."""


def register(name):
    """Decorator adding a figure function to :data:`PLOTS` under `name`.

    Parameters
    ----------
    name : str
        The figure's name (e.g. ``"stress-section"``); must be new.

    Returns
    -------
    callable
        The decorator (it returns the function unchanged).

    Examples
    --------
    >>> sorted(PLOTS)[:3]
    ['creep', 'force-depth', 'hysteresis']
    """
    def deco(func):
        if name in PLOTS:
            raise ValueError(f"plot {name!r} is already registered")
        PLOTS[name] = func
        return func
    return deco


def _figure(ax, nrows=1):
    """(figure, axes): the figure of `ax`, or a new one (no pyplot)."""
    try:
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - exercised with matplotlib hidden
        raise MissingDependencyError(
            "linecontact.plot needs matplotlib, which is not installed: "
            "pip install 'linecontact[plot]' (or pip install matplotlib)") from exc
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=(6.4, 4.4 * nrows), layout="constrained")
    return fig, fig.subplots(nrows, 1)


def save(fig, path):
    """Write `fig` to `path`; the format is the extension (png, svg or pdf).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or path
        Output file, ending in .png, .svg or .pdf.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    OutOfRangeError
        Another extension (naming it and the valid ones).

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
    fig.savefig(path, format=ext, dpi=150)
    return path


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


@register("force-depth")
def force_depth(models, depth=None, *, points=None, ax=None):
    r"""F(d) of contact laws for one cylinder, each where it answers, with its error.

    Each model is evaluated on the depth grid; where it refuses (outside its range of
    L/R, depth or material) nothing is drawn, so a curve's extent IS its validity range.
    The legend gives each model's measured error against the 3D boundary-element
    reference (:attr:`linecontact.models.ContactModel.measured_error`, from
    tables/model_accuracy.csv) where the accuracy study covers it.

    Parameters
    ----------
    models : sequence of linecontact.models.ContactModel
        The laws, e.g. :func:`linecontact.models.standard_models` (R, L, E*).
    depth : array_like, optional
        Depths d, 0 < d [m]; default 200 values spaced geometrically from 1e-6 R to
        0.15 R (the geometry every model shares) of the first model.
    points : sequence of (depth, force), optional
        Computed states to mark on the curves (e.g. a calculator's rows), d [m] and
        F [N] (NaN pairs are skipped).
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        Log-log axes, d in um and F in N; one line per model with the model's label
        (``line.get_xdata()``: d [um], ``get_ydata()``: F [N], NaN where refused).

    Notes
    -----
    Valid where each model is (its own checks decide); depths must be positive.

    Examples
    --------
    >>> from linecontact.models import standard_models
    >>> fig = force_depth(standard_models(5e-3, 10e-3, 115.38e9)[:2])
    >>> [line.get_label() for line in fig.axes[0].lines]
    ['Universal curve (BEM)', 'Li-Popov (Table 1 spline)']
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
    fig, ax = _figure(ax)
    handles, texts = [], []
    for m in models:
        F = _answer(m.force, d)
        err = m.measured_error
        line, = ax.plot(d * 1e6, F, label=m.label)
        line.measured_error = err           # kept with the line for readers and tests
        handles.append(line)
        texts.append(m.label + (f": {_short_error(err)}" if err else ""))
    if points:
        pts = np.array([(float(a), float(b)) for a, b in points], dtype=float)
        pts = pts[np.all(np.isfinite(pts), axis=1)]
        if pts.size:
            handles += ax.plot(pts[:, 0] * 1e6, pts[:, 1], "o", color="k", ms=4,
                               label="computed", zorder=5)
            texts.append("computed")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("depth d [um]")
    ax.set_ylabel("force F [N]")
    m0 = models[0]
    ax.set_title(f"R = {m0.radius * 1e3:.4g} mm, L = {m0.length * 1e3:.4g} mm, "
                 f"E* = {m0.estar / 1e9:.4g} GPa", fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(handles, texts, fontsize=6, loc="lower right",
              title="measured error against the 3D BEM (tables/model_accuracy.csv)",
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


@register("line-load")
def line_load(result, *, ax=None):
    """The line load q(x) along a profiled roller.

    Parameters
    ----------
    result : linecontact.roller.RollerSolution or linecontact.contact.ContactResult
        A profiled roller at one load (a ContactResult of ``model="profiled-roller"``
        or ``"iso16281-slicing"``).
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        One line: x [mm] against q [N/mm], the solution's slice values.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> r = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9).normal(force=1e3)
    >>> line = line_load(r).axes[0].lines[0]
    >>> w = r.solutions[0].width * 1e3                   # slice widths [mm]
    >>> f"{np.sum(line.get_ydata() * w):.0f} N"
    '1000 N'
    """
    sol = _solution(result)
    fig, ax = _figure(ax)
    ax.plot(np.asarray(sol.x) * 1e3, np.asarray(sol.q) * 1e-3, label=sol.method)
    ax.set_xlabel("x along the roller [mm]")
    ax.set_ylabel("line load q [N/mm]")
    ax.set_title(f"{sol.method}: F = {sol.force:.4g} N, d = {sol.depth * 1e6:.4g} um, "
                 f"tilt {sol.tilt * 1e3:.3g} mrad", fontsize=9)
    ax.grid(True, lw=0.3)
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
def pressure_map(result, *, ny=81, ax=None):
    """The pressure map p(x, y) of a profiled roller (:func:`pressure_field`).

    Parameters
    ----------
    result : linecontact.roller.RollerSolution or linecontact.contact.ContactResult
        A profiled roller at one load.
    ny : int
        Points across the contact, 3 <= ny [-].
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        A colour map of p [MPa] over x [mm] (along) and y [mm] (across), with a colour
        bar; ``fig.axes[0].collections[0].get_array()`` holds p [MPa].

    Notes
    -----
    Valid as :func:`pressure_field`.

    Examples
    --------
    >>> from linecontact.contact import Contact, Roller
    >>> r = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9).normal(force=1e3)
    >>> f"{pressure_map(r).axes[0].collections[0].get_array().max():.0f} MPa"
    '1521 MPa'
    """
    x, y, p = pressure_field(result, ny)
    fig, ax = _figure(ax)
    mesh = ax.pcolormesh(x * 1e3, y * 1e3, p * 1e-6, shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="pressure p [MPa]")
    ax.set_xlabel("x along the roller [mm]")
    ax.set_ylabel("y across [mm]")
    sol = _solution(result)
    ax.set_title(f"{sol.method}: slice pressure, peak {np.nanmax(p) / 1e6:.4g} MPa",
                 fontsize=9)
    return fig


@register("hysteresis")
def hysteresis(contact, amplitude, *, n=101, beyond="raise", ax=None):
    """The tangential hysteresis loop F_t(u) of a contact under a cyclic shift.

    The loop is :meth:`linecontact.tangential.TangentialContact.loop` (Masing's rule on
    the contact's monotonic law, Cattaneo-Mindlin by the MDR); the monotonic loading
    curve from the unloaded state is drawn beside it.

    Parameters
    ----------
    contact : linecontact.tangential.TangentialContact
        The contact at its normal load, with its friction coefficient.
    amplitude : float
        Shift amplitude u0, 0 < u0 <= u* (the gross-slip shift) unless ``beyond`` is
        ``"saturate"`` [m].
    n : int
        Points per branch, 2 <= n [-].
    beyond : {"raise", "saturate"}
        Beyond gross slip: refuse, or add the sliding (Coulomb) part.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        Lines ``"loop"`` (u [nm], F_t [N], 2n - 1 points, closed) and ``"loading"``.

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
    >>> loop = hysteresis(c, u0).axes[0].lines[0]            # closed, through (u0, F(u0))
    >>> f"{loop.get_ydata()[0]:.2f} N", f"{loop.get_ydata()[-1]:.2f} N", f"{c.force(u0):.2f} N"
    ('53.15 N', '53.15 N', '53.15 N')
    """
    u, ft = contact.loop(amplitude, n, beyond=beyond)
    u0 = float(amplitude)
    up = np.linspace(0.0, u0, int(n))
    f_up = np.asarray(contact.force(up, beyond=beyond), dtype=float)
    fig, ax = _figure(ax)
    ax.plot(u * 1e9, ft, label="loop")
    ax.plot(up * 1e9, f_up, "--", lw=0.8, label="loading")
    ax.axhline(contact.gross_slip_force, color="0.6", lw=0.5)
    ax.axhline(-contact.gross_slip_force, color="0.6", lw=0.5)
    ax.set_xlabel("tangential shift u [nm]")
    ax.set_ylabel("tangential force F_t [N]")
    ax.set_title(f"mu = {contact.friction:g}, F = {contact.normal_force:.4g} N; "
                 f"dissipated {contact.dissipated_energy(u0, beyond=beyond) * 1e9:.4g} nJ"
                 " per cycle", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
    return fig


@register("creep")
def creep(result, *, ax=None):
    """The depth d(t) of a viscoelastic contact (and its force history on a second axis).

    Parameters
    ----------
    result : linecontact.contact.CreepResult
        From :meth:`linecontact.contact.Contact.creep` or
        :meth:`~linecontact.contact.Contact.relaxation_history`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.figure.Figure
        Line ``"depth"`` (t [s], d [um]) on the first axes, ``"force"`` (t [s], F [N])
        on a twin axis; the long-term depth as a dotted line where it is defined.

    Examples
    --------
    >>> import math
    >>> from linecontact.contact import Contact, Roller, Elastic, Viscoelastic
    >>> from linecontact.viscoelastic import StandardLinearSolid
    >>> c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
    ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    >>> line = creep(c.creep([0.0, 10.0, 30.0], force=1e3)).axes[0].lines[0]
    >>> [f"{d:.2f}" for d in line.get_ydata()]          # d [um]
    ['82.58', '122.15', '168.03']
    """
    t = np.asarray(result.time, dtype=float)
    if t.size == 0 or not hasattr(result, "long_term_depth"):
        raise UnknownNameError("result", type(result).__name__, ["CreepResult"])
    fig, ax = _figure(ax)
    ax.plot(t, np.asarray(result.depth, dtype=float) * 1e6, label="depth")
    if result.long_term_depth is not None:
        ax.axhline(result.long_term_depth * 1e6, ls=":", color="0.4",
                   label="long-term depth")
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("depth d [um]")
    ax2 = ax.twinx()
    ax2.plot(t, np.asarray(result.force, dtype=float), color="C1", lw=0.8, label="force")
    ax2.set_ylabel("force F [N]")
    ax.set_title(f"{result.model}: creep (Lee & Radok)", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="lower right")
    return fig
