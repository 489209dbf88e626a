"""The paper's study rerun (tools/studies/paper_study.py and the modules it is split into:
paper_sweep, paper_fit, paper_tables, paper_compare) and its shipped tables.

Facts checked:
- the regenerated coefficients the runtime uses are the cubic spline in log(L/R) through
  the rows of tables/lipopov_regenerated.csv, nothing else (data and code cannot drift);
- the errors that table states are those of its alpha, beta against the shipped BEM
  curves, recomputed here from tables/bem_paper_curves.csv;
- the fit is exact on exact data: points sampled from Eq. 9 give back alpha, beta;
- a coarse one-L/R run works end to end into a folder of one's choosing, writes
  self-describing tables (version = the code version, as in every table), and its fit
  reproduces its own BEM points within the error it states; resumed from its
  checkpoint it runs no sweep again and writes the same table.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from linecontact.lipopov import (coefficient_set, dimensionless_force,
                                 dimensionless_stiffness)
from linecontact.tables import REQUIRED_KEYS, read_table
from tools.studies import paper_compare, paper_fit, paper_study
from tools.build_tables import main as build_tables
from tools.studies.paper_tables import CURVES, PUBLISHED_ERRORS, RESIDUAL_COMPARISON
from tools.studies.runner import code_version

REGEN = "lipopov_regenerated"


@pytest.fixture(scope="module")
def regenerated():
    return read_table(REGEN)


@pytest.fixture(scope="module")
def curves():
    return read_table(CURVES)


def test_runtime_uses_the_spline_through_the_shipped_rows(regenerated):
    """coefficient_set('regenerated') is the not-a-knot cubic spline in log(L/R) through
    the CSV rows: rebuilt here from the file, it agrees to rounding everywhere."""
    c = regenerated.columns
    lq = np.log(c["L_over_R"])
    alpha, beta = CubicSpline(lq, c["alpha"]), CubicSpline(lq, c["beta"])
    runtime = coefficient_set("regenerated")
    assert runtime.valid.low == c["L_over_R"].min()
    assert runtime.valid.high == c["L_over_R"].max()
    q = np.geomspace(c["L_over_R"].min(), c["L_over_R"].max(), 997)
    a, b = runtime(q)
    np.testing.assert_allclose(a, alpha(np.log(q)), rtol=1e-13)
    np.testing.assert_allclose(b, beta(np.log(q)), rtol=1e-13)
    # and it passes through every row
    a, b = runtime(c["L_over_R"])
    np.testing.assert_allclose(a, c["alpha"], rtol=1e-13)
    np.testing.assert_allclose(b, c["beta"], rtol=1e-13)


def test_regenerated_table_describes_itself(regenerated):
    meta = regenerated.meta
    for key in REQUIRED_KEYS + ("grid", "tolerance", "residual", "wall_time"):
        assert meta.get(key), f"metadata {key!r} missing from {regenerated.path}"
    assert "build_tables paper" in meta["generated_by"]


def test_stated_errors_are_those_of_the_shipped_curves(regenerated, curves):
    """max_rel_err_F, max_rel_err_k of every row are recomputed from the raw BEM curves
    with the row's alpha, beta through the runtime's closed forms."""
    points = paper_fit.points_from_curves(curves.columns)
    c = regenerated.columns
    assert sorted(points) == sorted(c["L_over_R"].tolist())
    for q, a, b, eF, ek in zip(c["L_over_R"], c["alpha"], c["beta"], c["max_rel_err_F"],
                               c["max_rel_err_k"]):
        got = paper_fit.errors(points[float(q)], a, b)
        np.testing.assert_allclose(got, (eF, ek), rtol=1e-9,
                                   err_msg=f"errors of the row L/R = {q:g}")


def test_curves_cover_the_paper_study(curves):
    """29 L/R, 0.1..1.0 and 2..20, depths up to 0.15 R (Li & Popov 2017, section 3)."""
    c = curves.columns
    np.testing.assert_allclose(np.unique(c["L_over_R"]), paper_study.PAPER_L_OVER_R)
    np.testing.assert_allclose(c["d_over_R"].max(), 0.15)
    # self-similar columns are the SI ones rescaled (Li & Popov 2017, Eq. 8)
    L = c["L_over_R"]
    np.testing.assert_allclose(c["d_tilde"], c["d_over_R"] / L**2, rtol=1e-12)
    np.testing.assert_allclose(c["F_tilde"], c["F_over_EstarR2"] / L**3, rtol=1e-12)
    np.testing.assert_allclose(c["x_tilde"], c["k_over_EstarR"] / (2 * L), rtol=1e-12)


@pytest.mark.parametrize("residual", list(paper_fit.RESIDUALS))
def test_fit_is_exact_on_exact_data(residual):
    """Points sampled from Eq. 9 itself are fitted back to their alpha, beta."""
    alpha, beta, L = 1.7086, 0.7936, 2.0
    d = np.linspace(0.0015, 0.15, 40) / L**2          # d~ of the paper's steps
    F = dimensionless_force(d, alpha, beta)
    k = dimensionless_stiffness(d, alpha, beta)
    pts = dict(d=d, F=F, k=k, x=k / 2, g=d.copy(), L=L)
    a, b = paper_fit.fit(pts, residual, start=(1.5, 1.0))
    assert a == pytest.approx(alpha, rel=1e-6)
    assert b == pytest.approx(beta, rel=1e-6)
    assert max(paper_fit.errors(pts, a, b)) < 1e-6


def test_coarse_run_end_to_end(tmp_path):
    """One L/R on a 32 x 32 grid, 10 steps: tables written into tmp_path, readable,
    self-describing, and the fit reproduces its own BEM points within the errors the
    table states (which are small: the form of Eq. 9 fits a coarse curve too)."""
    out = tmp_path / "study"
    run = ["paper", "--l-over-r", "2", "--n", "32", "--steps", "10", "--workers", "1",
           "--no-progress", "--out", str(out), "--checkpoint", str(tmp_path / "ck")]
    assert build_tables(run) == 0
    reg = read_table(REGEN, directory=out)
    assert reg.meta["version"] == code_version() and "code_version" not in reg.meta
    cur = read_table(CURVES, directory=out)
    assert "--n 32" in reg.meta["generated_by"]
    assert "32 x 32" in reg.meta["grid"]
    assert len(cur) == 10
    pts = paper_fit.points_from_curves(cur.columns)[2.0]
    (a,), (b,) = reg.columns["alpha"], reg.columns["beta"]
    eF, ek = paper_fit.errors(pts, a, b)
    assert eF <= reg.columns["max_rel_err_F"][0] * (1 + 1e-9)
    assert ek <= reg.columns["max_rel_err_k"][0] * (1 + 1e-9)
    assert max(eF, ek) < 0.05, "Eq. 9 should fit one coarse BEM curve within 5 %"
    # the published errors and the residual comparison are written beside it
    pub = read_table(PUBLISHED_ERRORS, directory=out).columns
    assert pub["L_over_R"].tolist() == [2.0]
    comp = read_table(RESIDUAL_COMPARISON, directory=out).columns
    assert len(comp["residual"]) == len(paper_fit.RESIDUALS)
    # refitting from the saved curves gives the same table rows
    out2 = tmp_path / "refit"
    build_tables(["paper", "--from-curves", str(out / f"{CURVES}.csv"),
                  "--out", str(out2)])
    again = read_table(REGEN, directory=out2).columns
    np.testing.assert_allclose(again["alpha"], reg.columns["alpha"], rtol=1e-8)
    # resumed from the checkpoint: no sweep runs again, the same rows are written
    assert build_tables(run + ["--resume"]) == 0
    resumed = read_table(REGEN, directory=out)
    assert ("for 1 L/R with 1 process (local dask cluster); 1 of them resumed from an "
            "earlier run's checkpoints (not in this wall time)") in resumed.meta["wall_time"]
    np.testing.assert_array_equal(resumed.columns["alpha"], reg.columns["alpha"])
    # a run compared with itself has not changed
    assert paper_compare.compare_curves(out, out)[2.0] == (0.0, 0.0, 0.0)


@pytest.mark.slow
def test_shipped_curve_reproduces_at_l_over_r_5(curves):
    """Rerunning L/R = 5 on the shipped grid gives the shipped F(d) to within the solver
    tolerance (a regression check of the BEM and of the table; about a minute)."""
    from tools.bem.cylinder import sweep
    c = curves.columns
    m = c["L_over_R"] == 5.0
    res = sweep(5.0, n=512, steps=100, d_max_over_r=0.15, tol=1e-6, workers=1,
                progress=False)
    np.testing.assert_allclose(res.force, c["F_over_EstarR2"][m], rtol=1e-4)
    np.testing.assert_allclose(res.stiffness, c["k_over_EstarR"][m], rtol=1e-4)
