"""Figures (linecontact/plot.py): the plotted data are the library's numbers.

Facts checked (the data on the axes, not pixels):
- F(d): each line is the model's own F at the plotted depths, NaN exactly where the
  model refuses (its validity range: Li-Popov Eq. 11 needs L/R >= 5, Palmgren needs
  steel), and the line carries the model's measured error;
- q(x): the line is the solution's q, and its integral is the force (equilibrium);
- the pressure map's slices integrate back to q (pi b p0 / 2 per slice);
- the hysteresis loop is closed, odd-symmetric (Masing) and passes through
  (u0, F_t(u0)) of the monotonic law;
- the creep line is the CreepResult's d(t);
- PNG, SVG and PDF files are written (their magic bytes), another extension is
  refused naming the valid ones;
- importing linecontact.plot does not import matplotlib, and without matplotlib a
  figure function says how to install it.
"""
from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from linecontact import plot
from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
from linecontact.errors import OutOfRangeError
from linecontact.models import get_model, standard_models
from linecontact.tangential import TangentialContact
from linecontact.viscoelastic import StandardLinearSolid

ESTAR = 115.38e9


def test_force_depth_lines_are_the_models_values_where_they_answer():
    models = standard_models(5e-3, 10e-3, ESTAR)           # L/R = 2
    fig = plot.force_depth(models)
    lines = {ln.get_label(): ln for ln in fig.axes[0].lines}
    assert list(lines) == [m.label for m in models]
    uni = lines["Universal curve (BEM)"]
    d = np.asarray(uni.get_xdata()) * 1e-6
    assert d[0] == pytest.approx(5e-9) and d[-1] == pytest.approx(0.15 * 5e-3)
    np.testing.assert_allclose(uni.get_ydata(), models[0].force(d), rtol=1e-12,
                               err_msg="the universal curve's line is its F(d)")
    # Eq. 11 holds for L/R >= 5 only: at L/R = 2 it refuses every depth, drawn nowhere
    assert np.all(np.isnan(lines["Li-Popov (Eq. 11)"].get_ydata()))
    spline = lines["Li-Popov (Table 1 spline)"]
    assert spline.measured_error == models[1].measured_error
    assert "against the BEM" in spline.measured_error


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
    pts = [ln for ln in fig.axes[0].lines if ln.get_label() == "computed"][0]
    assert pts.get_xdata().tolist() == [d * 1e6] and pts.get_ydata().tolist() == [1e3]
    with pytest.raises(OutOfRangeError, match="depth"):
        plot.force_depth([m], depth=[-1e-6, 1e-6])
    with pytest.raises(OutOfRangeError, match="models"):
        plot.force_depth([])


def _profiled(tilt=0.0):
    c = Contact(Roller(5e-3, 14e-3, crown_radius=0.5, tilt=tilt), estar=ESTAR)
    return c.normal(force=2e3)


def test_line_load_is_q_and_balances_the_force():
    r = _profiled()
    sol = r.solutions[0]
    line = plot.line_load(r).axes[0].lines[0]
    np.testing.assert_array_equal(line.get_xdata(), sol.x * 1e3)
    np.testing.assert_array_equal(line.get_ydata(), sol.q * 1e-3)
    w = sol.width                                        # graded slices
    assert np.sum(sol.q * w) == pytest.approx(2e3, rel=1e-9), "sum q w = F"


def test_pressure_map_slices_integrate_to_q():
    """Each slice is a Hertz ellipse: its integral over y is pi b p0 / 2 = q (checked
    with a fine y grid by the trapezoid rule: 1e-3 relative on the loaded slices)."""
    r = _profiled()
    sol = r.solutions[0]
    x, y, p = plot.pressure_field(r, ny=4001)
    loaded = sol.q > 0.01 * sol.q.max()
    q_back = np.trapezoid(p, y, axis=0) if hasattr(np, "trapezoid") else np.trapz(p, y, axis=0)
    np.testing.assert_allclose(q_back[loaded], sol.q[loaded], rtol=1e-3)
    fig = plot.pressure_map(r)
    assert fig.axes[0].collections[0].get_array().max() == pytest.approx(
        np.nanmax(sol.pressure) * 1e-6, rel=1e-3)
    with pytest.raises(OutOfRangeError, match="profiled roller"):
        plot.line_load(Contact(Roller(5e-3, 10e-3), estar=ESTAR).normal(force=1e3))


def test_hysteresis_loop_is_closed_symmetric_and_on_the_law():
    c = TangentialContact(get_model("universal", 5e-3, 10e-3, ESTAR), 0.1, 0.8 * ESTAR,
                          force=1e3)
    u0 = 0.7 * c.gross_slip_shift
    lines = {ln.get_label(): ln for ln in plot.hysteresis(c, u0, n=51).axes[0].lines}
    u, f = lines["loop"].get_xdata() * 1e-9, lines["loop"].get_ydata()
    assert len(u) == 2 * 51 - 1
    assert f[0] == pytest.approx(f[-1], rel=1e-12), "closed loop"
    assert f[0] == pytest.approx(float(c.force(u0)), rel=1e-12)
    assert f[50] == pytest.approx(-f[0], rel=1e-9), "odd symmetry at -u0"
    with pytest.raises(OutOfRangeError, match="amplitude"):
        plot.hysteresis(c, 2 * c.gross_slip_shift)


def test_creep_line_is_the_history():
    c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    r = c.creep(np.linspace(0, 60, 4), force=1e3)
    line = plot.creep(r).axes[0].lines[0]
    np.testing.assert_array_equal(line.get_ydata(), np.asarray(r.depth) * 1e6)


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
