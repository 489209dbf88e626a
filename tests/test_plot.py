"""Figures (linecontact/plot.py): the plotted data are the library's numbers.

Facts checked (the data on the axes, not pixels; each drawn line's data read back with
``Line2D.get_xydata`` and divided by the axis' SI factor, ``line.scale``):
- the SI prefix of an axis puts the largest magnitude in [1, 1000) (a 1e-4 N force
  is 100 uN, a soft contact's force in mN), lengths never in km;
- F(d): each line is the model's own F at the plotted depths, NaN exactly where the
  model refuses (its validity range: Li-Popov Eq. 11 needs L/R >= 5, Palmgren needs
  steel); each of the eleven standard laws has its own (colour, marker, dash); the
  line carries the model's measured error; computed points keep their model's style;
- q(x): the line is the solution's q (its integral is the force: equilibrium), the
  roller's ends are at -L/2 and L/2, the contact's ends at contact_start/end; the
  profile line is the profile's drop P(x) and the approach lines d + theta x;
- the pressure map's slices integrate back to q (pi b p0 / 2 per slice);
- adhesion: approach and retraction are the hysteresis arrays, the pull-off markers
  sit at pull_off('depth') and pull_off('force'), the 2D JKR line at L F_c,2D/L and
  the BEM's at the table's pull-off;
- creep: the history and the response are the CreepResult's arrays, creep and
  relaxation told apart;
- tangential: the loop is closed, odd-symmetric (Masing) and passes through
  (u0, F_t(u0)); the loading curve ends at gross slip (u*, mu F), for each direction;
- stresses: the worst point is marked at the result's (y, z), the along-roller line
  is the per-slice maximum, the allowable line is the case check's allowable at each
  slice's depth of maximum, the case panel holds the check's arrays;
- bearing: each panel is the per-roller array ordered by azimuth; moments and tilts
  zero to round-off (a law; symmetric rollers between aligned rings, solved exactly:
  1e-17 Q L) are left out;
- every axis has a unit in brackets; every legend lies outside its axes (no overlap
  with the data area); panels() stacks the parts' axes;
- PNG, SVG and PDF files are written (their magic bytes), another extension is
  refused naming the valid ones;
- importing linecontact.plot does not import matplotlib, and without matplotlib a
  figure function says how to install it.
"""
from __future__ import annotations

import math
import re
import subprocess
import sys
from functools import partial

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from linecontact import plot
from linecontact.adhesion import AdhesiveContact, CylinderAdhesion
from linecontact.bearing import RadialRollerBearing
from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
from linecontact.models import get_model, standard_models
from linecontact.stresses import (HardnessProfile, case_check, line_contact_stresses,
                                  roller_stresses)
from linecontact.tangential import TangentialContact
from linecontact.errors import OutOfRangeError, UnknownNameError
from linecontact.viscoelastic import StandardLinearSolid

ESTAR = 115.38e9
#: units an axis may carry: an SI unit with a prefix, a compound, or a plain name
UNIT = re.compile(r"\[(?:[pnµmkMGT]?(?:m|N|Pa|J|s|rad)(?:/m|/mm| m)?|deg|-|HV)\]$")


def _lines(ax):
    return {ln.get_label(): ln for ln in ax.lines}


def _si(line):
    """The line's data back in SI (divided by the axis factors)."""
    sx, sy = line.scale
    xy = line.get_xydata()
    return xy[:, 0] / sx, xy[:, 1] / sy


def _check_readable(fig):
    """Every data axis has units on both axes (colour bars their label), and every
    legend lies outside its axes: their rendered boxes do not overlap."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()                                   # the constrained layout, as saved
    renderer = canvas.get_renderer()
    for ax in fig.axes:
        if ax.get_label() == "<colorbar>":
            assert UNIT.search(ax.get_ylabel()), ax.get_ylabel()
            continue
        if ax.get_xlabel():                    # shared x: the label on the last panel
            assert UNIT.search(ax.get_xlabel()), ax.get_xlabel()
        assert UNIT.search(ax.get_ylabel()), ax.get_ylabel()
        leg = ax.get_legend()
        if leg is not None:
            a, b = ax.get_window_extent(renderer), leg.get_window_extent(renderer)
            assert b.x0 >= a.x1 or b.x1 <= a.x0 or b.y0 >= a.y1 or b.y1 <= a.y0, \
                f"legend over the data of {ax.get_title()!r}"


# --------------------------------------------------------------------------------------
# units
# --------------------------------------------------------------------------------------
@pytest.mark.parametrize("value, unit, expected", [
    (1e-4, "N", "µN"), (2.5e-3, "N", "mN"), (1.0, "N", "N"), (999.0, "N", "N"),
    (1e3, "N", "kN"), (6.7e4, "Pa", "kPa"), (115e9, "Pa", "GPa"), (2e5, "N/m", "kN/m"),
    (7e-6, "m", "µm"), (5e-3, "m", "mm"), (3e3, "m", "m"), (1e-3, "rad", "mrad"),
    (120.0, "s", "s"), (5e-8, "J", "nJ"), (0.0, "N", "N"), (1.0, "-", "-")])
def test_engineering_unit_fits_the_magnitude(value, unit, expected):
    """The prefix puts the largest |value| in [1, 1000) (no km, ks: lengths and
    times stay in their base unit above it); non-SI units are left alone."""
    f, u = plot.engineering_unit([0.0, -value, np.nan], unit)
    assert u == expected
    if value and expected not in ("m", "s", "-"):
        assert 1.0 <= value * f < 1000.0


# --------------------------------------------------------------------------------------
# F(d)
# --------------------------------------------------------------------------------------
def test_force_depth_lines_are_the_models_values_where_they_answer():
    models = standard_models(5e-3, 10e-3, ESTAR)           # L/R = 2
    fig = plot.force_depth(models)
    lines = _lines(fig.axes[0])
    assert list(lines) == [m.label for m in models]
    uni = lines["Universal curve (BEM)"]
    d, F = _si(uni)
    assert d[0] == pytest.approx(5e-9) and d[-1] == pytest.approx(0.15 * 5e-3)
    np.testing.assert_allclose(F, models[0].force(d), rtol=1e-12,
                               err_msg="the universal curve's line is its F(d)")
    # Eq. 11 holds for L/R >= 5 only: at L/R = 2 it refuses every depth, drawn nowhere
    assert np.all(np.isnan(lines["Li-Popov (Eq. 11)"].get_ydata()))
    spline = lines["Li-Popov (Table 1 spline)"]
    assert spline.measured_error == models[1].measured_error
    assert "against the BEM" in spline.measured_error
    styles = {(ln.get_color(), ln.get_marker(), ln.get_linestyle()) for ln in lines.values()}
    assert len(styles) == len(models), "each model its own colour, marker and dash"
    assert fig.axes[0].get_ylabel() == "force F [kN]"
    _check_readable(fig)


def test_force_depth_soft_contact_in_millinewton():
    """A hydrogel roller (E* = 67 kPa) pressed to 50 um carries 3.2 mN: the
    axis says mN (not 0.0001 kN), the title's modulus kPa."""
    m = get_model("universal", 1e-3, 2e-3, 6.7e4)
    ax = plot.force_depth([m], depth=np.geomspace(1e-7, 5e-5, 20)).axes[0]
    assert ax.get_ylabel() == "force F [mN]" and "E* = 67 kPa" in ax.get_title()
    assert ax.get_xlabel() == "depth d [µm]"


def test_force_depth_steel_only_laws_vanish_for_another_material():
    """Palmgren's law is for steel: for E* = 10 GPa it is not drawn at all, while the
    universal curve (any E*) is."""
    models = [get_model("universal", 5e-3, 10e-3, 10e9),
              get_model("palmgren", 5e-3, 10e-3, 10e9)]
    ys = [ln.get_ydata() for ln in plot.force_depth(models).axes[0].lines]
    assert np.all(np.isfinite(ys[0])) and np.all(np.isnan(ys[1]))


def test_force_depth_marks_points_and_refuses_nonsense():
    m = get_model("universal", 5e-3, 10e-3, ESTAR)
    d = float(m.depth(1e3))
    fig = plot.force_depth([m], points=[(d, 1e3), (math.nan, 1.0)])
    pts = _lines(fig.axes[0])["computed"]
    assert np.allclose(np.column_stack(_si(pts)), [[d, 1e3]], rtol=1e-12)
    # per model: in the model's own colour and marker
    m2 = get_model("johnson", 5e-3, 10e-3, ESTAR)
    fig = plot.force_depth([m, m2], points={m2.label: [(d, 2e3)]})
    lines = _lines(fig.axes[0])
    pts = lines[f"{m2.label}: computed"]
    assert pts.get_color() == lines[m2.label].get_color()
    assert pts.get_marker() == lines[m2.label].get_marker()
    with pytest.raises(OutOfRangeError, match="points"):
        plot.force_depth([m], points={"no such model": [(d, 1.0)]})
    with pytest.raises(OutOfRangeError, match="depth"):
        plot.force_depth([m], depth=[-1e-6, 1e-6])
    with pytest.raises(OutOfRangeError, match="models"):
        plot.force_depth([])


# --------------------------------------------------------------------------------------
# profiled rollers
# --------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def crowned():
    c = Contact(Roller(5e-3, 14e-3, crown_radius=0.5, tilt=1e-3), estar=ESTAR)
    return c, c.normal(force=2e3)


def test_line_load_is_q_balances_the_force_and_marks_the_ends(crowned):
    c, r = crowned
    sol = r.solutions[0]
    fig = plot.line_load(r, c)
    lines = _lines(fig.axes[0])
    line = lines[f"q(x), {sol.method}"]
    x, q = _si(line)
    np.testing.assert_allclose(x, sol.x, rtol=1e-12)
    np.testing.assert_allclose(q, sol.q, rtol=1e-12)
    assert np.sum(q * sol.width) == pytest.approx(2e3, rel=1e-9), "sum q w = F"
    ends = sorted(ln.get_xdata()[0] / line.scale[0] for ln in fig.axes[0].lines
                  if ln.get_label().endswith("roller ends"))
    assert ends == pytest.approx([-7e-3, 7e-3], rel=1e-12)
    ce = _si(lines["contact ends"])
    assert ce[0] == pytest.approx([sol.contact_start, sol.contact_end], rel=1e-12)
    assert np.all(ce[1] == 0)
    _check_readable(fig)
    with pytest.raises(OutOfRangeError, match="profiled roller"):
        plot.line_load(Contact(Roller(5e-3, 10e-3), estar=ESTAR).normal(force=1e3))


def test_profiled_roller_draws_the_profile_and_the_approach(crowned):
    c, r = crowned
    sols = [r, c.normal(force=5e3)]
    fig = plot.profiled_roller(sols, c)
    assert len(fig.axes) == 2
    lines = _lines(fig.axes[1])
    x, P = _si(lines["profile drop P(x)"])
    assert x[0] == pytest.approx(-7e-3, rel=1e-6) and x[-1] == pytest.approx(7e-3, rel=1e-6)
    np.testing.assert_allclose(P, c.profile.drop(x), rtol=1e-9, atol=1e-15)
    approach = [ln for ln in fig.axes[1].lines if ln.get_label().startswith("d + ")]
    assert len(approach) == 2
    for ln, s in zip(approach, sols):
        xa, a = _si(ln)
        sol = s.solutions[0]
        np.testing.assert_allclose(a, sol.depth + sol.tilt * xa, rtol=1e-9)
    assert len([ln for ln in fig.axes[0].lines if ln.get_label().startswith("F = ")]) == 2
    _check_readable(fig)


def test_pressure_map_slices_integrate_to_q(crowned):
    """Each slice is a Hertz ellipse: its integral over y is pi b p0 / 2 = q (checked
    with a fine y grid by the trapezoid rule: 1e-3 relative on the loaded slices)."""
    _, r = crowned
    sol = r.solutions[0]
    x, y, p = plot.pressure_field(r, ny=4001)
    loaded = sol.q > 0.01 * sol.q.max()
    q_back = np.trapezoid(p, y, axis=0) if hasattr(np, "trapezoid") else np.trapz(p, y, axis=0)
    np.testing.assert_allclose(q_back[loaded], sol.q[loaded], rtol=1e-3)
    fig = plot.pressure_map(r)
    assert fig.axes[1].get_ylabel() == "pressure p [GPa]"
    assert fig.axes[0].collections[0].get_array().max() == pytest.approx(
        np.nanmax(sol.pressure) * 1e-9, rel=1e-3)
    _check_readable(fig)


# --------------------------------------------------------------------------------------
# adhesion
# --------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def hydrogel():
    return CylinderAdhesion(get_model("universal", 1e-3, 2e-3, 6.7e4), 0.05)


def test_adhesion_curves_pull_off_and_references(hydrogel):
    c = hydrogel
    loop = c.mdr.hysteresis(30e-6, n=41)
    fig = plot.adhesion(c, loop=loop)
    ax = fig.axes[0]
    lines = _lines(ax)
    for branch in ("approach", "retraction"):
        d, F = _si(lines[branch])
        np.testing.assert_allclose(d, loop[f"{branch}_depth"], rtol=1e-12, atol=1e-18)
        np.testing.assert_allclose(F, loop[f"{branch}_force"], rtol=1e-12, atol=1e-18)
    for control in ("depth", "force"):
        off = c.mdr.pull_off(control)
        d, F = _si(lines[f"pull-off, {control} control (MDR)"])
        assert (d[0], F[0]) == pytest.approx((off["depth"], off["force"]), rel=1e-12)
    # the depth-controlled pull-off is where the retraction jumps off
    assert _si(lines["retraction"])[1][-1] == pytest.approx(c.mdr.pull_off("depth")["force"],
                                                            rel=1e-9)
    sf = lines["approach"].scale[1]
    assert lines["2D JKR pull-off"].get_ydata()[0] / sf == pytest.approx(c.pull_off_2d,
                                                                          rel=1e-12)
    assert lines["finite roller (BEM), force control"].get_ydata()[0] / sf == \
        pytest.approx(c.pull_off("force")["force"], rel=1e-12)
    bem = c.pull_off("depth")
    d, F = _si(lines["finite roller (BEM), depth control"])
    assert (d[0], F[0]) == pytest.approx((bem["depth"], bem["force"]), rel=1e-12)
    assert ax.get_ylabel() == "force F [mN]", "a soft contact's force in mN"
    _check_readable(fig)


def test_adhesion_of_a_sphere_marks_the_jkr_pull_off():
    """The JKR sphere: the force-controlled pull-off is -1.5 pi w R (exact for the
    rule of Hess), marked on the curve; no cylinder references."""
    R, E, w = 10e-3, 1e6, 0.05
    fig = plot.adhesion(AdhesiveContact(lambda x: x**2 / R, E, w), 50e-6, n=31)
    lines = _lines(fig.axes[0])
    F = _si(lines["pull-off, force control"])[1][0]
    assert F == pytest.approx(-1.5 * np.pi * w * R, rel=1e-9)
    assert "2D JKR pull-off" not in lines
    with pytest.raises(OutOfRangeError, match="depth_max"):
        plot.adhesion(AdhesiveContact(lambda x: x**2 / R, E, w))


# --------------------------------------------------------------------------------------
# creep and relaxation
# --------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def visco():
    return Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                   material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))


def test_creep_draws_the_history_and_the_depth(visco):
    t = np.linspace(0, 60, 13)
    r = visco.creep(t, force=1e3 * np.minimum(t / 10, 1))
    fig = plot.creep(r)
    top, bottom = _lines(fig.axes[0]), _lines(fig.axes[1])
    np.testing.assert_allclose(np.column_stack(_si(top["force history"])),
                               np.column_stack([t, r.force]), rtol=1e-12)
    np.testing.assert_allclose(np.column_stack(_si(bottom["depth"])),
                               np.column_stack([t, r.depth]), rtol=1e-12)
    lt = bottom["long-term depth"].get_ydata()[0] / bottom["depth"].scale[1]
    assert lt == pytest.approx(r.long_term_depth, rel=1e-12)
    _check_readable(fig)


def test_relaxation_draws_the_depth_history_and_the_force(visco):
    t = np.linspace(0, 60, 7)
    r = visco.relaxation_history(t, depth=2e-6)
    fig = plot.creep(r)
    top, bottom = _lines(fig.axes[0]), _lines(fig.axes[1])
    np.testing.assert_allclose(_si(top["depth history"])[1], r.depth, rtol=1e-12)
    np.testing.assert_allclose(_si(bottom["force"])[1], r.force, rtol=1e-12)
    assert "long-term depth" not in bottom
    # told explicitly, the same result is drawn as creep
    assert "force history" in _lines(plot.creep(r, given="force").axes[0])
    with pytest.raises(UnknownNameError, match="given"):
        plot.creep(r, given="time")


# --------------------------------------------------------------------------------------
# tangential
# --------------------------------------------------------------------------------------
def test_hysteresis_loop_is_closed_symmetric_and_on_the_law():
    c = TangentialContact(get_model("universal", 5e-3, 10e-3, ESTAR), 0.1, 0.8 * ESTAR,
                          force=1e3)
    u0 = 0.7 * c.gross_slip_shift
    fig = plot.hysteresis(c, u0, n=51, points=[(0.5 * u0, float(c.force(0.5 * u0)))])
    mono, loops = _lines(fig.axes[0]), _lines(fig.axes[1])
    u, f = _si(loops["MDR (G*/E*): loop"])
    assert len(u) == 2 * 51 - 1
    assert f[0] == pytest.approx(f[-1], rel=1e-12), "closed loop"
    assert f[0] == pytest.approx(float(c.force(u0)), rel=1e-12)
    assert f[50] == pytest.approx(-f[0], rel=1e-9), "odd symmetry at -u0"
    u, f = _si(mono["MDR (G*/E*): partial slip"])
    assert u[-1] == pytest.approx(c.gross_slip_shift, rel=1e-12)
    np.testing.assert_allclose(f, c.force(u), rtol=1e-12)
    g = _si(mono["MDR (G*/E*): gross slip"])
    assert (g[0][0], g[1][0]) == pytest.approx((c.gross_slip_shift, 0.1 * 1e3), rel=1e-12)
    assert _si(mono["computed"])[0][0] == pytest.approx(0.5 * u0, rel=1e-12)
    _check_readable(fig)
    with pytest.raises(OutOfRangeError, match="amplitude"):
        plot.hysteresis(c, 2 * c.gross_slip_shift)


def test_hysteresis_across_and_along():
    """The BEM law per direction: one loop each, each on its own law."""
    m = get_model("universal", 5e-3, 10e-3, ESTAR)
    cs = [TangentialContact(m, 0.1, 0.8 * ESTAR, force=1e3, method="bem", direction=d)
          for d in ("across", "along")]
    u0 = 0.5 * min(c.gross_slip_shift for c in cs)
    fig = plot.hysteresis(cs, u0, n=21)
    loops = _lines(fig.axes[1])
    for c in cs:
        u, f = _si(loops[f"{c.direction} (BEM): loop"])
        np.testing.assert_allclose(f, c.loop(u0, 21)[1], rtol=1e-12)
    assert len({ln.get_color() for ln in fig.axes[1].lines}) == 2


# --------------------------------------------------------------------------------------
# stresses
# --------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def roller_field(crowned):
    _, r = crowned
    s = roller_stresses(r.solutions[0])
    return s, case_check(s, HardnessProfile(700.0, 0.3e-3, 350.0))


def test_stresses_field_maximum_along_and_case(roller_field):
    s, check = roller_field
    fig = plot.stresses(s, case=check, n=41)
    section, along, case = fig.axes[0], fig.axes[1], fig.axes[2]
    w = s.worst["von_mises"]
    y, z = _si(_lines(section)["maximum"])
    assert (y[0], z[0]) == pytest.approx((w["y"], w["z"]), rel=1e-12, abs=1e-15)
    lo, hi = sorted(section.get_ylim())
    assert lo == 0.0 and hi / _lines(section)["maximum"].scale[1] >= w["z"], \
        "the depth axis reaches below the maximum"
    field = section.collections[0]
    assert field.get_array() is not None or len(field.get_paths())   # contours drawn
    lines = _lines(along)
    x, v = _si(lines["maximum below each slice"])
    np.testing.assert_allclose(x, s.x, rtol=1e-12)
    np.testing.assert_allclose(v, s.value["von_mises"], rtol=1e-12)
    _, allow = _si(lines["allowable at that depth"])
    np.testing.assert_allclose(allow, np.interp(s.depth["von_mises"], check.depths,
                                                check.allowable), rtol=1e-12)
    lines = _lines(case)
    np.testing.assert_allclose(np.column_stack(_si(lines["allowable"])),
                               np.column_stack([check.depths, check.allowable]), rtol=1e-12)
    env = [ln for ln in case.lines if ln.get_label().startswith("stress envelope")][0]
    np.testing.assert_allclose(_si(env)[1], check.stress, rtol=1e-12)
    _check_readable(fig)


def test_stresses_refuses_a_mismatched_case_and_draws_a_line_contact(roller_field):
    s, check = roller_field
    with pytest.raises(OutOfRangeError, match="case"):
        plot.stresses(s, measure="tresca", case=check)
    with pytest.raises(UnknownNameError, match="measure"):
        plot.stresses(s, measure="rankine")
    one = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9)
    fig = plot.stresses(one, measure="tresca", n=21)
    assert len(fig.axes) == 3                    # section + colour bar, along
    z = _si(_lines(fig.axes[0])["maximum"])[1][0]
    assert z == pytest.approx(one.worst["tresca"]["z"], rel=1e-12)


# --------------------------------------------------------------------------------------
# bearing
# --------------------------------------------------------------------------------------
def test_bearing_panels_are_the_roller_arrays():
    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, profile="circular:Rc=0.3")
    s = b.solve(10e3, misalignment=1e-3)
    fig = plot.bearing(s)
    assert len(fig.axes) == 3
    for ax, attr in zip(fig.axes, ("roller_loads", "roller_moments", "roller_tilts")):
        line = ax.lines[0]
        np.testing.assert_allclose(line.get_ydata() / line.scale,
                                   getattr(s, attr)[line.order], rtol=1e-12)
        assert np.all(np.diff(line.get_xdata()) > 0), "ordered by azimuth"
    assert fig.axes[0].get_ylabel() == "roller load Q [kN]"
    _check_readable(fig)
    law = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3).solve(10e3)
    fig = plot.bearing(law)
    assert len(fig.axes) == 1 and "moment and tilt zero" in fig.axes[0].get_title()
    aligned = b.solve(10e3)
    assert np.max(np.abs(aligned.roller_moments)) < 1e-12 * 10e3 * 11e-3
    fig = plot.bearing(aligned)
    assert len(fig.axes) == 1 and "moment and tilt zero" in fig.axes[0].get_title()


def test_bearing_at_a_speed_adds_film_ratio_and_damage_panels():
    """Solved at a speed with the film inputs: each roller's Lambda (the smaller of its
    two contacts'; unloaded rollers, Lambda = inf, not drawn) and its damage share."""
    b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3, 40e-6, viscosity=20.7e-6,
                            density=860.0, pressure_viscosity=2e-8,
                            roughness_roller=0.1e-6, roughness_raceway=0.15e-6)
    s = b.solve(10e3, speed=157.08)
    fig = plot.bearing(s)
    assert [ax.get_ylabel() for ax in fig.axes] == [
        "roller load Q [kN]", "film ratio Lambda [-]", "damage share [-]"]
    lam = np.minimum(s.film_ratio_inner, s.film_ratio_outer)[fig.axes[1].lines[0].order]
    y = fig.axes[1].lines[0].get_ydata()
    np.testing.assert_allclose(y[np.isfinite(lam)], lam[np.isfinite(lam)], rtol=1e-12)
    assert np.all(np.isnan(y[~np.isfinite(lam)]))
    d = fig.axes[2].lines[0]
    np.testing.assert_allclose(d.get_ydata(), s.roller_damage[d.order], rtol=1e-12)
    _check_readable(fig)


# --------------------------------------------------------------------------------------
# several results, files, the optional dependency
# --------------------------------------------------------------------------------------
def test_panels_stack_the_parts(crowned, visco, tmp_path):
    c, r = crowned
    cr = visco.creep([0.0, 10.0, 30.0], force=1e3)
    fig = plot.panels(partial(plot.line_load, r, c), partial(plot.creep, cr),
                      title="two results")
    data_axes = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
    assert len(data_axes) == 3, "q(x) and the creep's two panels"
    np.testing.assert_allclose(_si(data_axes[0].lines[0])[1], r.solutions[0].q, rtol=1e-12)
    assert fig.get_size_inches()[1] == pytest.approx(3 * plot._PANEL + 0.3)
    _check_readable(fig)
    assert [p.suffix for p in plot.save_all(fig, tmp_path / "both")] == [".png", ".svg"]
    with pytest.raises(OutOfRangeError, match="draw"):
        plot.panels()
    with pytest.raises(OutOfRangeError, match="draw"):
        plot.panels(r)


def _every_figure():
    """One figure of each kind, small (for the file test)."""
    c = Contact(Roller(5e-3, 14e-3, crown_radius=0.5), estar=ESTAR)
    r = c.normal(force=1e3)
    s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9)
    vc = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                 material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    tc = TangentialContact(get_model("universal", 5e-3, 10e-3, ESTAR), 0.1, 0.8 * ESTAR,
                           force=1e3)
    return {
        "force-depth": lambda: plot.force_depth([get_model("universal", 5e-3, 10e-3, ESTAR)]),
        "line-load": lambda: plot.line_load(r, c),
        "profiled-roller": lambda: plot.profiled_roller(r, c),
        "pressure-map": lambda: plot.pressure_map(r),
        "adhesion": lambda: plot.adhesion(AdhesiveContact(lambda x: x**2 / 1e-2, 1e6, 0.05),
                                          50e-6, n=21),
        "creep": lambda: plot.creep(vc.creep([0.0, 10.0], force=1e3)),
        "hysteresis": lambda: plot.hysteresis(tc, 0.5 * tc.gross_slip_shift, n=11),
        "stresses": lambda: plot.stresses(s, n=21),
        "bearing": lambda: plot.bearing(RadialRollerBearing(14, 70e-3, 11e-3, 11e-3)
                                        .solve(10e3)),
    }


def test_every_registered_figure_is_written_as_png_and_svg(tmp_path):
    figures = _every_figure()
    assert sorted(figures) == sorted(plot.PLOTS), "a test case for each registered figure"
    for name, make in figures.items():
        png, svg = plot.save_all(make(), tmp_path / name)
        assert png.read_bytes().startswith(b"\x89PNG"), name
        assert svg.read_bytes().startswith(b"<?xml") and b"<svg" in svg.read_bytes(), name


@pytest.mark.parametrize("ext, magic", [("png", b"\x89PNG"), ("svg", b"<?xml"),
                                        ("pdf", b"%PDF")])
def test_files_are_written(tmp_path, ext, magic):
    fig = plot.force_depth([get_model("universal", 5e-3, 10e-3, ESTAR)])
    path = plot.save(fig, tmp_path / f"fd.{ext}")
    assert path.read_bytes().startswith(magic)


def test_bad_extension_refused(tmp_path):
    fig = plot.force_depth([get_model("universal", 5e-3, 10e-3, ESTAR)])
    with pytest.raises(OutOfRangeError, match=r"\.png, \.svg or \.pdf"):
        plot.save(fig, tmp_path / "fd.gif")


def test_matplotlib_is_optional():
    """Import without matplotlib loaded; a figure without matplotlib names the extra."""
    code = ("import sys; sys.modules['matplotlib'] = None\n"
            "import linecontact.plot as p\n"
            "from linecontact.models import get_model\n"
            "try:\n"
            "    p.force_depth([get_model('universal', 5e-3, 1e-2, 1e11)])\n"
            "except p.MissingDependencyError as e:\n"
            "    print('MISSING', e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert "MISSING" in out.stdout and "linecontact[plot]" in out.stdout, out.stderr
    code = "import sys, linecontact.plot; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert out.stdout.strip() == "False"


def test_calc_plot_option(tmp_path, capsys):
    """`linecontact calc ... --plot FILE` writes the figure beside the table; a bad
    extension or a CSV batch is refused with one line and status 2 (nothing drawn)."""
    from linecontact.calc.cli import main
    case = ["calc", "--radius", "5mm", "--length", "14mm", "--estar", "115GPa"]
    out = tmp_path / "case.svg"
    assert main(case + ["--load", "100N:1kN:3", "--crown-radius", "500mm",
                        "--plot", str(out)]) == 0
    assert out.read_bytes().startswith(b"<?xml") and b"line load" in out.read_bytes()
    capsys.readouterr()
    assert main(case + ["--load", "1kN", "--plot", str(tmp_path / "x.gif")]) == 2
    assert "--plot = " in capsys.readouterr().err
    csv = tmp_path / "cases.csv"
    csv.write_text("load\n1kN\n")
    assert main(case + [str(csv), "--plot", str(tmp_path / "b.png")]) == 2
    assert "not a CSV batch" in capsys.readouterr().err
    assert not (tmp_path / "b.png").exists()
