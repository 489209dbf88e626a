"""The calculator's tangential and viscoelastic options (linecontact.calc.features.tangential).

Run in-process through linecontact.calc.cli.main (the subprocess tests of the CLI are in
test_cli.py). Facts checked: every printed number is the library's (the same
function, so rtol 1e-12 on the JSON's 17-digit floats); the creep column starts at the
instantaneous depth and ends at the elastic depth at E*_inf (the limits of J*(t));
every bad combination is one line on stderr naming the parameter, exit status 2.
"""
import json

import numpy as np
import pytest

import linecontact.tangential as tg
import linecontact.tangential.cylinder_table as tg_table
from linecontact.calc.cli import main
from linecontact.classical import effective_modulus
from linecontact.models import get_model
from linecontact.tables import read_table, write_table
from linecontact.viscoelastic import StandardLinearSolid, step_creep_depth

CASE = ["calc", "--radius", "5mm", "--length", "10mm", "--load", "1kN",
        "--model", "universal"]
ELASTIC = ["--modulus", "210GPa", "--poisson", "0.3"]
SLS = ["--instantaneous-modulus", "3GPa", "--long-term-modulus", "1GPa",
       "--relaxation-time", "10s", "--poisson", "0.35"]
META = dict(title="test", source="tests", units="[-]", generated_by="pytest",
            date="2026-01-01", version="0", accuracy="made up")


def _json(capsys, argv):
    assert main(argv + ["--json"]) == 0
    return json.loads(capsys.readouterr().out)["models"][0]["rows"]


@pytest.fixture
def table(tmp_path, monkeypatch):
    """A made-up BEM table (across 0.9, along 0.75 at nu = 0.3) in place of the shipped."""
    nus, dts = (0.0, 0.25, 0.3, 0.5), (1e-8, 1e-6, 1e-4, 1e-2)
    nu, dt = (a.ravel() for a in np.meshgrid(nus, dts, indexing="ij"))
    write_table(tmp_path / "t.csv", META, dict(
        nu=nu, d_tilde=dt, kt_kn_across=np.where(nu == 0, 1.0, 0.9),
        kt_kn_along=np.where(nu == 0, 1.0, 0.75)))
    t = tg.CylinderTangentialTable(read_table("t", directory=tmp_path))
    monkeypatch.setattr(tg_table, "_cached_table", lambda name: t)
    return t


def test_friction_columns_are_the_library_values(capsys, table):
    """kt MDR = (G*/E*) k, kt across/along = table ratio x k (rtol 1e-12)."""
    row = _json(capsys, CASE + ELASTIC + ["--friction", "0.1"])[0]
    E = effective_modulus(210e9, 0.3)
    m = get_model("universal", 5e-3, 10e-3, E)
    d = m.depth(1e3)
    k = m.stiffness(d)
    assert row["kt_mdr"] == pytest.approx(tg.shear_ratio(210e9, 0.3) * k, rel=1e-12, abs=0)
    r = tg.cylinder_stiffness_ratios(m, d, tg.effective_shear_modulus(210e9, 0.3))
    assert row["kt_across"] == pytest.approx(r["across"] * k, rel=1e-12, abs=0)
    assert row["kt_along"] == pytest.approx(r["along"] * k, rel=1e-12, abs=0)


def test_tangential_load_sweep_gives_the_shift_and_the_slip_state(capsys, table):
    """u MDR and u across = tangential_shift (rtol 1e-12); Q/(mu F) as given; above
    mu F: gross slip, no shift (null), exit status 0 (a valid answer)."""
    rows = _json(capsys, CASE + ELASTIC + ["--friction", "0.1", "--tangential-load",
                                           "20N:150N:3", "--linear"])
    E = effective_modulus(210e9, 0.3)
    m = get_model("universal", 5e-3, 10e-3, E)
    d = m.depth(1e3)
    G = tg.effective_shear_modulus(210e9, 0.3)
    assert [r["tangential_load"] for r in rows] == [20.0, 85.0, 150.0]
    for r in rows[:2]:
        Q = r["tangential_load"]
        assert r["slip_fraction"] == pytest.approx(Q / 100.0, rel=1e-12, abs=0)
        assert r["shift_mdr"] == pytest.approx(tg.tangential_shift(m, d, Q, 0.1, G),
                                               rel=1e-12, abs=0)
        ratio = tg.cylinder_stiffness_ratios(m, d, G)["across"]
        assert r["shift_across"] == pytest.approx(
            tg.tangential_shift(m, d, Q, 0.1, G, ratio=ratio), rel=1e-12, abs=0)
        assert "partial slip" in r["flags"]
    assert rows[2]["shift_mdr"] is None and "gross slip" in rows[2]["flags"]


def test_shift_with_the_tables_slip_correction_is_the_runtimes(capsys, tmp_path,
                                                                monkeypatch):
    """With shift_ratio columns in the table, u across/along = TangentialContact(...,
    method='bem').shift(Q), the corrected law (rtol 1e-12)."""
    nus, dts = (0.0, 0.25, 0.3, 0.5), (1e-8, 1e-6, 1e-4, 1e-2)
    nu, dt = (a.ravel() for a in np.meshgrid(nus, dts, indexing="ij"))
    cols = dict(nu=nu, d_tilde=dt, kt_kn_across=np.where(nu == 0, 1.0, 0.9),
                kt_kn_along=np.where(nu == 0, 1.0, 0.75))
    for side, c in (("across", 1.07), ("along", 1.02)):
        cols[f"shift_ratio_{side}_q0.5"] = np.full(nu.shape, 1.0 + (c - 1) / 3)
        cols[f"shift_ratio_{side}_q1"] = np.full(nu.shape, c)
    write_table(tmp_path / "t.csv", META, cols)
    t = tg.CylinderTangentialTable(read_table("t", directory=tmp_path))
    monkeypatch.setattr(tg_table, "_cached_table", lambda name: t)
    rows = _json(capsys, CASE + ELASTIC + ["--friction", "0.1", "--tangential-load",
                                           "30N:90N:2", "--linear"])
    m = get_model("universal", 5e-3, 10e-3, effective_modulus(210e9, 0.3))
    G = tg.effective_shear_modulus(210e9, 0.3)
    for side in ("across", "along"):
        c = tg.TangentialContact(m, 0.1, G, force=1e3, method="bem", direction=side)
        for r in rows:
            assert r[f"shift_{side}"] == pytest.approx(c.shift(r["tangential_load"]),
                                                       rel=1e-12, abs=0)


def test_creep_sweep_runs_from_the_instantaneous_to_the_long_term_depth(capsys):
    """d(t) = step_creep_depth with J*(t) = (1 - nu^2) J(t) (rigid roller), rtol 1e-12;
    d(0) = the instantaneous elastic depth (E* from E0) and d(inf) = the elastic depth
    at E*_inf: the limits J*(0) = 1/E*_0, J*(inf) = 1/E*_inf (rtol 1e-12)."""
    rows = _json(capsys, CASE + SLS + ["--time", "0:100s:5", "--linear"])
    nu = 0.35
    E0, Einf = 3e9 / (1 - nu ** 2), 1e9 / (1 - nu ** 2)
    m0 = get_model("universal", 5e-3, 10e-3, E0)
    mat = StandardLinearSolid(3e9, 1e9, 10.0).scaled(1 / (1 - nu ** 2))
    t = np.array([r["time"] for r in rows])
    assert t == pytest.approx([0, 25, 50, 75, 100], rel=1e-15, abs=0)
    d = np.array([r["creep_depth"] for r in rows])
    assert d == pytest.approx(step_creep_depth(m0, mat, 1e3, t), rel=1e-12, abs=0)
    assert d[0] == pytest.approx(rows[0]["depth"], rel=1e-12, abs=0)
    d_inf = get_model("universal", 5e-3, 10e-3, Einf).depth(1e3)
    assert rows[0]["depth_long_term"] == pytest.approx(d_inf, rel=1e-12, abs=0)
    assert np.all(np.diff(d) > 0) and d[-1] < d_inf


def test_creep_beyond_the_models_range_is_a_note_not_a_failure(capsys):
    """A soft body creeping past the universal model's range (d > 0.15 R): those
    times get '-' and the model's message in the note; the others their values."""
    rows = _json(capsys, CASE[:-4] + ["--load", "100N", "--model", "universal",
                                      "--instantaneous-modulus", "30MPa",
                                      "--long-term-modulus", "3MPa",
                                      "--relaxation-time", "10s", "--poisson", "0.45",
                                      "--time", "1s:1000s:3"])
    assert rows[0]["creep_depth"] is not None and rows[0]["creep_depth"] > 0
    assert rows[-1]["creep_depth"] is None
    assert "d(t): beyond the model's range" in rows[-1]["flags"]


def test_prony_file_and_an_elastic_roller(capsys, tmp_path):
    """A Prony CSV, and a steel roller on the polymer: the compliances add,
    J*(t) = (1 - nu1^2) J1(t) + (1 - nu2^2)/E2 (rtol 1e-12)."""
    p = tmp_path / "pom.csv"
    p.write_text("# E_inf: 1e9\ntau_s,E_Pa\n0.1,1e9\n10,1e9\n")
    rows = _json(capsys, CASE + ["--prony", str(p), "--poisson", "0.35", "--modulus2",
                                 "210GPa", "--poisson2", "0.3", "--time", "5s"])
    from linecontact.viscoelastic import read_prony_series

    body = read_prony_series(p)
    c2 = (1 - 0.3 ** 2) / 210e9

    class J:
        def creep(self, t):
            return (1 - 0.35 ** 2) * body.creep(t) + c2

    E0 = effective_modulus(3e9, 0.35, 210e9, 0.3)
    m0 = get_model("universal", 5e-3, 10e-3, E0)
    assert rows[0]["creep_depth"] == pytest.approx(step_creep_depth(m0, J(), 1e3, 5.0),
                                                   rel=1e-12, abs=0)


@pytest.mark.parametrize("extra, parameter", [
    (ELASTIC + ["--time", "10s"], "--time"),
    (ELASTIC + ["--tangential-load", "10N"], "--tangential-load"),
    (["--estar", "115GPa", "--friction", "0.1"], "--friction"),
    (SLS[:4] + ["--poisson", "0.3"], "--relaxation-time"),
    (SLS + ["--modulus", "2GPa"], "--modulus"),
    (SLS + ["--friction", "0.1"], "--friction"),
    (ELASTIC + ["--friction", "0.1", "--inner-raceway", "20mm", "--outer-raceway",
                "30mm"], "--friction"),
    (SLS + ["--time", "5m"], "--time"),
    (SLS + ["--time", "-1s"], "--time"),
    (SLS + ["--time", "-1s:10s:3"], "--time"),
    (["--instantaneous-modulus", "1GPa", "--long-term-modulus", "2GPa",
      "--relaxation-time", "1s", "--poisson", "0.3"], "--long-term-modulus"),
    (["--prony", "/nonexistent/prony.csv", "--poisson", "0.3"], "--prony"),
    (ELASTIC + ["--friction", "0.1", "--tangential-load", "1N:2N:1000", "--load",
                "1kN:2kN:1000"], "--tangential-load"),
])
def test_bad_combinations_are_one_line_errors(capsys, extra, parameter):
    """Each bad combination: exit 2, one line on stderr naming the parameter."""
    argv = CASE + extra
    if "--load" in extra:
        i = argv.index("--load")
        del argv[i:i + 2]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and parameter in err[0], err


PRONY_BODY = "tau_s,E_Pa\n0.1,1e9\n10,1e9\n"


@pytest.mark.parametrize("einf", ["1e9", "1GPa", "1 GPa", "1000MPa", "1e9 Pa"])
def test_prony_values_follow_the_one_input_rule(capsys, tmp_path, einf):
    """'# E_inf: 1GPa' is E_inf = 1e9 Pa, exactly as --modulus 1GPa would be (the same
    parser, linecontact._units.parse_quantity: a number and one unit name, bare = SI):
    the creep depth equals that of the bare-SI file to the last bit (rtol 0: one exact
    factor 1e9). '1 GPa' used to be read as 1 Pa and '1GPa' refused with a garbled
    message."""
    p, ref = tmp_path / "p.csv", tmp_path / "ref.csv"
    p.write_text(f"# E_inf: {einf}\n{PRONY_BODY}")
    ref.write_text(f"# E_inf: 1e9\n{PRONY_BODY}")
    args = ["--poisson", "0.35", "--time", "5s"]
    got = _json(capsys, CASE + ["--prony", str(p)] + args)
    want = _json(capsys, CASE + ["--prony", str(ref)] + args)
    assert got[0]["creep_depth"] == want[0]["creep_depth"] > 0


@pytest.mark.parametrize("text, name, shown", [
    ("# E_inf: 1,5GPa\n" + PRONY_BODY, "E_inf", "'1,5GPa'"),
    ("# E_inf: 1 GPa m\n" + PRONY_BODY, "E_inf", "'1 GPa m'"),
    ("# E_inf: 5mm\n" + PRONY_BODY, "E_inf", "'5mm'"),
    ("# E_inf: inf\n" + PRONY_BODY, "E_inf", "'inf'"),
    ("# E_inf: -1GPa\n" + PRONY_BODY, "E_inf", "'-1GPa'"),
    ("# E_inf: 1e9\ntau_s,E_Pa\n0.1,2 GPa x\n", "E_Pa", "'2 GPa x'"),
    ("# E_inf: 1e9\ntau_s,E_Pa\n1e400,1e9\n", "tau_s", "'1e400'"),
    ("# E_inf: 1e9\ntau_s,E_Pa\nnan,1e9\n", "tau_s", "'nan'"),
    ("# E_inf: 1e9\ntau_s,E_Pa\n0.1\n", "prony file", "'0.1'"),
])
def test_bad_prony_values_are_one_clear_line(capsys, tmp_path, text, name, shown):
    """A refused value in the file: exit 2, one line naming --prony, the file's
    parameter and the value as typed, then one 'valid:' (no nested "is outside the
    valid range ... valid:" as before)."""
    p = tmp_path / "p.csv"
    p.write_text(text)
    assert main(CASE + ["--prony", str(p), "--poisson", "0.35"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert "--prony" in err[0] and f"{name} = {shown}" in err[0], err
    assert err[0].count("valid") == 1 and "outside the valid range" not in err[0], err


def test_crowned_roller_prints_mindlins_values_by_direction(capsys):
    """A crowned roller (issue 32's: R 10 mm, L 20 mm, Rc 500 mm, steel on steel, 1 kN)
    gets kt and u across and along from Contact.tangential's default, Mindlin's ellipse
    (192.5 and 161.9 N/um), and its MDR column unchanged (method="mdr"): the library's
    numbers (rtol 1e-10: the calculator's slice solve stops at its own iterate, 3e-12
    from the library's call here, measured)."""
    from linecontact.contact import Contact, Elastic, Roller

    argv = ["calc", "--radius", "10mm", "--length", "20mm", "--crown-radius", "500mm",
            "--load", "1kN", "--model", "profiled-roller", "--modulus", "210GPa",
            "--poisson", "0.3", "--modulus2", "210GPa", "--poisson2", "0.3",
            "--friction", "0.1", "--tangential-load", "50N"]
    row = _json(capsys, argv)[0]
    steel = Elastic(210e9, 0.3)
    c = Contact(Roller(10e-3, 20e-3, crown_radius=0.5), None, steel, steel)
    mdr = c.tangential(0.1, force=1e3, tangential_force=50.0, method="mdr")
    assert row["kt_mdr"] == pytest.approx(mdr.stiffness, rel=1e-10, abs=0)
    assert row["shift_mdr"] == pytest.approx(mdr.shift, rel=1e-10, abs=0)
    for direction, value in (("across", 192.5), ("along", 161.9)):
        t = c.tangential(0.1, force=1e3, tangential_force=50.0, direction=direction)
        assert row[f"kt_{direction}"] == pytest.approx(t.stiffness, rel=1e-10, abs=0)
        assert row[f"shift_{direction}"] == pytest.approx(t.shift, rel=1e-10, abs=0)
        assert row[f"kt_{direction}"] / 1e6 == pytest.approx(value, abs=0.05)
    assert "Mindlin" in row["flags"]
