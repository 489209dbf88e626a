"""``linecontact calc ... --plot FILE``: every kind of result drawn from the command line,
and the adhesive curve (zero and tensile loads) in the calculator.

Run in-process through linecontact.calc.cli.main; the figure the command saves is kept
(``linecontact.plot.save`` wrapped) so that its drawn lines are read back
(``Line2D.get_xydata`` divided by the axis' SI factor ``line.scale``, as in
tests/test_plot.py). Facts checked:

- each result kind (F(d) of every model, a profiled roller's q(x), the adhesive cycle,
  creep, relaxation, the tangential loop across and along, the stresses, a roller
  between raceways) writes a PNG and an SVG (their magic bytes), and the figure holds
  the curves it claims, with the library's numbers: the computed points of each model
  are that model's F(d) at the row's depth (rtol 1e-12: the same function); q(x) is
  the library's solution of the roller (rtol 1e-12) and sum q w = F (equilibrium of
  the slices, 1e-9); the adhesive curves are AdhesiveContact.hysteresis of the
  row's model and the pull-off marker its pull_off (rtol 1e-12); the creep depth is
  Contact.creep at the drawn times (rtol 1e-12); the tangential rows' (u, Q) are
  marked on their loading curve and the loop reaches the largest computed shift; the
  stress maximum marked is the table's von Mises maximum (rtol 1e-12);
- several results at once are one figure with a band per kind (the panels' count);
- a result without a figure is said in one line on stderr;
- with --work-of-adhesion a zero or tensile load is on the stable branch: its depth is
  AdhesiveContact.depth_at_force of the row's model (rtol 1e-12; at zero load
  zero_load()['depth'] to 1e-9, two root solves), the row says its branch; a load
  beyond the pull-off is refused with the pull-off in the message (exit status 2);
  without adhesion a load <= 0 is refused naming --work-of-adhesion; a depth sweep
  through zero gives the retraction branch down to the depth-controlled pull-off and
  the approach's F = 0 before first contact.
"""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

pytest.importorskip("matplotlib")

from linecontact import plot
from linecontact.adhesion import AdhesiveContact
from linecontact.calc.cli import main
from linecontact.classical import effective_modulus
from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
from linecontact.models import get_model
from linecontact.viscoelastic import StandardLinearSolid

STEEL = ["--modulus", "210GPa", "--poisson", "0.3"]
ROLLER = ["calc", "--radius", "5mm", "--length", "10mm"]
MAGIC = {"png": b"\x89PNG", "svg": b"<?xml"}


@pytest.fixture
def drawn(monkeypatch):
    """The figures the command saved (the Figure objects, in order)."""
    figures = []
    save = plot.save

    def keep(fig, path, **kw):
        figures.append(fig)
        return save(fig, path, **kw)

    monkeypatch.setattr(plot, "save", keep)
    return figures


def _run(capsys, argv, tmp_path, ext="png", status=0):
    path = tmp_path / f"fig.{ext}"
    assert main(argv + ["--plot", str(path)]) == status, capsys.readouterr().err
    out, err = capsys.readouterr()
    if status == 0:
        assert path.read_bytes().startswith(MAGIC[ext])
    return out, err


def _json(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _lines(fig):
    return {ln.get_label(): ln for ax in fig.axes for ln in ax.lines}


def _si(line):
    sx, sy = line.scale
    xy = line.get_xydata()
    return xy[:, 0] / sx, xy[:, 1] / sy


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_force_depth_points_in_each_models_style(capsys, tmp_path, drawn, ext):
    """Each model's computed rows are its own points (its colour and marker), on its
    own F(d): the force given, the depth the model's (same function)."""
    _run(capsys, ROLLER + STEEL + ["--load", "100N:10kN:3", "--model",
                                    "universal,johnson"], tmp_path, ext)
    lines = _lines(drawn[-1])
    E = effective_modulus(210e9, 0.3)
    for key in ("universal", "johnson"):
        m = get_model(key, 5e-3, 10e-3, E)
        pts = lines[f"{m.label}: computed"]
        d, F = _si(pts)
        np.testing.assert_allclose(F, [100.0, 1e3, 1e4], rtol=1e-12)
        np.testing.assert_allclose(d, m.depth(F), rtol=1e-12)
        assert pts.get_color() == lines[m.label].get_color()
        assert pts.get_marker() == lines[m.label].get_marker()


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_profiled_roller_line_load_ends_and_profile(capsys, tmp_path, drawn, ext):
    """q(x) of each row integrates to its force; the roller's ends at +-L/2; the
    profile drop and the approach are drawn."""
    _run(capsys, ROLLER + ["--estar", "115GPa", "--load", "1kN:4kN:2", "--crown-radius",
                           "500mm"], tmp_path, ext)
    fig = drawn[-1]
    lines = _lines(fig)
    c = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115e9)
    for F in (1e3, 4e3):
        sol = c.normal(force=F).solutions[0]
        label = next(k for k in lines if k.startswith(f"F = {F / 1e3:g} kN"))
        x, q = _si(lines[label])
        np.testing.assert_allclose(x, sol.x, rtol=1e-12)
        np.testing.assert_allclose(q, sol.q, rtol=1e-12)
        assert np.sum(q * sol.width) == pytest.approx(F, rel=1e-9), "sum q w = F"
    ends = [ln for ax in fig.axes for ln in ax.lines if ln.get_label() == "roller ends"]
    x_end = ends[0].get_xdata()[0] / lines["profile drop P(x)"].scale[0]
    assert x_end == pytest.approx(-5e-3, rel=1e-12)
    assert "profile drop P(x)" in lines


GEL = ["calc", "--radius", "1mm", "--length", "2mm", "--modulus", "50kPa", "--poisson",
       "0.5", "--model", "universal", "--work-of-adhesion", "50mJ/m^2"]


def _gel_contact():
    return AdhesiveContact.from_model(
        get_model("universal", 1e-3, 2e-3, effective_modulus(5e4, 0.5)), 0.05)


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_adhesion_cycle_pull_off_and_rows(capsys, tmp_path, drawn, ext):
    """A depth sweep from 20 um down to -30 um: the approach and retraction of the
    library's cycle, the pull-offs marked, each row's (d, F on the stable branch)."""
    _run(capsys, GEL + ["--depth", "20um:-30um:6"], tmp_path, ext)
    lines = _lines(drawn[-1])
    c = _gel_contact()
    dmax = _si(lines["retraction"])[0][0]
    assert dmax == pytest.approx(20e-6, rel=1e-12), "the cycle reaches the deepest row"
    loop = c.hysteresis(dmax)
    for branch in ("approach", "retraction"):
        d, F = _si(lines[branch])
        np.testing.assert_allclose(F, loop[f"{branch}_force"], rtol=1e-12, atol=1e-18)
    off = c.pull_off("force")
    d, F = _si(lines["pull-off, force control (MDR)"])
    assert (d[0], F[0]) == pytest.approx((off["depth"], off["force"]), rel=1e-12)
    d, F = _si(lines["computed"])
    np.testing.assert_allclose(F, c.force_at_depth(d), rtol=1e-12)
    assert d.min() == pytest.approx(-30e-6, rel=1e-12)


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_creep_and_relaxation_against_the_history(capsys, tmp_path, drawn, ext):
    """Creep under a held force: d(t) is Contact.creep at the drawn times, up to the
    last --time; relaxation under a held depth: F(t) is relaxation_history's."""
    visco = ["--instantaneous-modulus", "3GPa", "--long-term-modulus", "1GPa",
             "--relaxation-time", "10s", "--poisson", "0.3"]
    c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
                material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.3))
    _run(capsys, ROLLER + visco + ["--load", "1kN", "--time", "0:60s:4"], tmp_path, ext)
    t, d = _si(_lines(drawn[-1])["depth"])
    assert t[-1] == pytest.approx(60.0, rel=1e-12)
    np.testing.assert_allclose(d, c.creep(t, force=1e3).depth, rtol=1e-12)
    _run(capsys, ROLLER + visco + ["--depth", "50um"], tmp_path, ext)
    t, F = _si(_lines(drawn[-1])["force"])
    np.testing.assert_allclose(F, c.relaxation_history(t, depth=50e-6).force, rtol=1e-12)


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_tangential_loop_across_and_along(capsys, tmp_path, drawn, ext):
    """Across and along (the BEM table's law): the loading curves, gross slip and the
    loops; the rows' (u, Q) marked on the loading curve across, the loop's amplitude
    the largest computed shift."""
    doc = _json(capsys, ROLLER + STEEL + ["--model", "universal", "--load", "1kN",
                                          "--friction", "0.2", "--tangential-load",
                                          "20N:150N:3"])
    rows = doc["models"][0]["rows"]
    _run(capsys, ROLLER + STEEL + ["--model", "universal", "--load", "1kN", "--friction",
                                   "0.2", "--tangential-load", "20N:150N:3"], tmp_path, ext)
    lines = _lines(drawn[-1])
    for name in ("across (BEM)", "along (BEM)"):
        assert f"{name}: loop" in lines and f"{name}: gross slip" in lines
    u, Q = _si(lines["computed"])
    np.testing.assert_allclose(Q, [r["tangential_load"] for r in rows], rtol=1e-12)
    np.testing.assert_allclose(u, [r["shift_across"] for r in rows], rtol=1e-12)
    # the computed states lie on the drawn loading curve across (linear interpolation
    # between its 101 points: 1e-3 of the force)
    x, F = _si(lines["across (BEM): partial slip"])
    np.testing.assert_allclose(np.interp(u, x, F), Q, rtol=1e-3)
    ul, _ = _si(lines["across (BEM): loop"])
    assert ul.max() == pytest.approx(max(r["shift_across"] for r in rows), rel=1e-12)


@pytest.mark.parametrize("ext", ["png", "svg"])
def test_stresses_worst_row_and_case(capsys, tmp_path, drawn, ext):
    """The worst row's section with its maximum (the table's von Mises maximum and its
    depth), the maxima along the roller and the allowable of the case check."""
    argv = ROLLER + STEEL + ["--model", "universal", "--load", "1kN:3kN:2", "--stresses",
                             "yes", "--surface-hardness", "700", "--core-hardness",
                             "350", "--case-depth", "0.8mm"]
    rows = _json(capsys, argv)["models"][0]["rows"]
    _, err = _run(capsys, argv, tmp_path, ext)
    lines = _lines(drawn[-1])
    worst = max(rows, key=lambda r: r["von_mises_max"])
    m = next(ln for ax in drawn[-1].axes for ln in ax.lines if ln.get_label() == "maximum")
    assert m.get_ydata()[0] / m.scale[1] == pytest.approx(worst["von_mises_depth"],
                                                          rel=1e-12)
    assert "allowable at that depth" in lines and "allowable" in lines
    assert "worst row (row 2" in err and len(err.strip().splitlines()) == 1


def test_several_results_are_one_figure_with_bands(capsys, tmp_path, drawn):
    """A crowned roller with stresses: F(d), q(x) with the profile, and the stresses,
    one figure (1 + 2 + 3 axes, the colour bar besides)."""
    _run(capsys, ROLLER + STEEL + ["--load", "2kN", "--crown-radius", "500mm",
                                   "--stresses", "yes"], tmp_path)
    fig = drawn[-1]
    assert len(fig.subfigs) == 3
    assert [len([a for a in s.axes if a.get_label() != "<colorbar>"])
            for s in fig.subfigs] == [1, 2, 2]


def test_raceways_draw_each_contact_or_say_why(capsys, tmp_path, drawn):
    """A roller between raceways by slices: q(x) of the inner and the outer contact;
    under a law there is no q(x): one line on stderr, and --plot is refused with one
    line (nothing to draw), status 2."""
    base = ROLLER + STEEL + ["--inner-raceway", "20mm", "--outer-raceway", "30mm",
                             "--load", "2kN"]
    _run(capsys, base + ["--crown-radius", "500mm"], tmp_path)
    titles = [ax.get_title() for ax in drawn[-1].axes]
    assert any(t.startswith("inner contact") for t in titles)
    assert any(t.startswith("outer contact") for t in titles)
    _, err = _run(capsys, base, tmp_path, status=2)
    lines = err.strip().splitlines()
    assert "under a law has no q(x)" in lines[0] and "--plot = " in lines[-1]


# --------------------------------------------------------------------------------------
# the adhesive curve from the command line
# --------------------------------------------------------------------------------------
BIG = ["calc", "--radius", "10mm", "--length", "20mm", "--modulus", "1MPa", "--poisson",
       "0.5", "--model", "universal", "--work-of-adhesion", "50mJ/m^2"]


def _big_contact():
    return AdhesiveContact.from_model(
        get_model("universal", 10e-3, 20e-3, effective_modulus(1e6, 0.5)), 0.05)


def test_tensile_load_on_the_stable_branch(capsys):
    """--load -50mN above the pull-off (Fc = -171 mN here): the depth is the stable
    branch's, the row says it is reached on retraction only."""
    c = _big_contact()
    assert c.pull_off("force")["force"] < -0.05
    row = _json(capsys, BIG + ["--load", "-50mN"])["models"][0]["rows"][0]
    assert row["force"] == -0.05
    assert row["depth_adhesive"] == pytest.approx(c.depth_at_force(-0.05), rel=1e-12)
    assert row["radius_adhesive"] == pytest.approx(
        c.radius_at_depth(row["depth_adhesive"]), rel=1e-12)
    assert row["depth"] is None, "no contact without adhesion"
    assert "retraction only" in row["flags"]


def test_zero_load_with_adhesion(capsys):
    """--load 0 with adhesion: the zero-load state of the rule of Hess."""
    c = _big_contact()
    row = _json(capsys, BIG + ["--load", "0N"])["models"][0]["rows"][0]
    assert row["depth_adhesive"] == pytest.approx(c.zero_load()["depth"], rel=1e-9)
    assert row["depth_adhesive"] == pytest.approx(row["zero_load_depth"], rel=1e-9)


def test_load_beyond_the_pull_off_is_refused_naming_it(capsys):
    """-50 mN on the hydrogel roller (Fc = -2.05 mN): one line, the pull-off in it."""
    Fc = _gel_contact().pull_off("force")["force"]
    assert main(GEL + ["--load", "-50mN"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "--load = '-50mN'" in err and "beyond the pull-off" in err
    assert f"Fc = {Fc * 1e3:.4g} mN" in err, err


def test_load_at_or_below_zero_without_adhesion_is_refused(capsys):
    """Without --work-of-adhesion a load <= 0 has no contact: refused naming it."""
    for value in ("-1N", "0"):
        assert main(ROLLER + STEEL + ["--load", value]) == 2
        err = capsys.readouterr().err.strip()
        assert "not positive" in err and "--work-of-adhesion" in err, err


def test_depth_sweep_gives_retraction_and_approach(capsys):
    """A depth sweep through zero: F adh on the retraction (the stable branch) down to
    the depth-controlled pull-off, 0 below it; F approach 0 before first contact at
    d = 0 and the stable branch after; each row names its branch."""
    c = _gel_contact()
    dc = c.pull_off("depth")["depth"]
    rows = _json(capsys, GEL + ["--depth", "10um:-50um:7"])["models"][0]["rows"]
    for r in rows:
        d = r["depth"] if r["depth"] is not None else None
        assert d is not None
        if d >= dc:
            assert r["force_adhesive"] == pytest.approx(float(c.force_at_depth(d)),
                                                        rel=1e-12)
        else:
            assert r["force_adhesive"] == 0.0 and "below the pull-off depth" in r["flags"]
        if d < 0:
            assert r["force_approach"] == 0.0
            if d >= dc:
                assert "retraction branch" in r["flags"]
        else:
            assert r["force_approach"] == r["force_adhesive"]


def test_load_sweep_past_the_pull_off_keeps_its_rows(capsys, tmp_path, drawn):
    """A load sweep from -5 mN (beyond Fc = -2.05 mN) to 1 mN: the rows beyond say so
    in their note and are left out of the figure, said on stderr; the others are
    drawn on the stable branch (their depth the library's)."""
    out, err = _run(capsys, GEL + ["--load", "-5mN:1mN:4"], tmp_path)
    assert out.count("is beyond the pull-off Fc") == 2
    assert "2 row(s) beyond the pull-off" in err
    d, F = _si(_lines(drawn[-1])["computed"])
    np.testing.assert_allclose(F, [-1e-3, 1e-3], rtol=1e-12)
    np.testing.assert_allclose(d, _gel_contact().depth_at_force(F), rtol=1e-12)


def test_batch_rows_with_and_without_adhesion(tmp_path, capsys):
    """In a CSV batch each row has its own rule: a tensile load with adhesion is
    computed, without it refused in its row, beyond the pull-off refused naming Fc."""
    csv = tmp_path / "cases.csv"
    csv.write_text("load,work_of_adhesion\n-1mN,50mJ/m^2\n-1mN,\n-50mN,50mJ/m^2\n")
    out = tmp_path / "out.csv"
    main(GEL[:-2] + [str(csv), "-o", str(out)])
    capsys.readouterr()
    text = out.read_text()
    assert "not positive" in text and "beyond the pull-off Fc = -2.052 mN" in text
