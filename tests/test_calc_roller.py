"""The calculator's profiled-roller options (``linecontact calc --crown-radius``,
``--profile``, ``--tilt``; linecontact.calc_roller), called in process through
linecontact.cli.main.

Each test states the fact it checks and why its tolerance.
"""
from __future__ import annotations

import json

import pytest

from linecontact.hertz import hertz_contact

CROWN = ["calc", "--radius", "10mm", "--length", "20mm", "--estar", "115.385GPa"]
ROLLER = ["calc", "--radius", "5mm", "--length", "10mm", "--modulus", "210GPa",
          "--poisson", "0.3"]


def _main(capsys, *argv):
    from linecontact.cli import main

    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _json(capsys, *argv):
    status, out, err = _main(capsys, *argv, "--json", "--si")
    assert status == 0, err
    return json.loads(out)


def test_crown_radius_prints_the_hertz_contact(capsys):
    """--crown-radius adds the profiled-roller rows beside the straight ones: for a
    crown that stays inside the roller they are the Hertz contact, approach 7.024 um
    and p0 1102 MPa (R 10 mm, Rc 500 mm, 1 kN, printed to 4 digits: 7.024 and 1102),
    not edge loaded; ISO/TS 16281 slicing follows as its own row."""
    status, out, err = _main(capsys, *CROWN, "--load", "1kN", "--crown-radius", "500mm")
    assert status == 0, err
    lines = [ln for ln in out.splitlines() if ln.startswith("Profiled roller")]
    assert len(lines) == 1
    row = lines[0].split()
    h = hertz_contact(1000.0, 0.5, 0.01, 115.385e9)
    assert f"{h.approach * 1e6:.4g}" in row and f"{h.p0 / 1e6:.4g}" in row
    assert "ISO/TS 16281 slicing (circular crown (Rc = 500 mm))" in out
    assert "Universal curve" in out or "Li-Popov" in out     # the straight rows are kept


def test_json_carries_q_of_x(capsys):
    """--json gives each profiled-roller row its line load q(x) on the slices: it
    integrates to the force (sum q w = F, exact for the slice model up to the force
    tolerance 1e-10), with the tilt in radians and the stiffness matrix."""
    doc = _json(capsys, *ROLLER, "--load", "1kN", "--profile", "iso16281", "--tilt",
                "0.5mrad")
    blocks = doc["profiled_roller"]
    assert [b["label"].split(" (")[0] for b in blocks] == ["Profiled roller",
                                                           "ISO/TS 16281 slicing"]
    row = blocks[0]["rows"][0]
    x, q = row["x"], row["q"]
    assert len(x) == len(q) == 100
    w = x[1] - x[0]
    assert sum(q) * w == pytest.approx(1000.0, rel=1e-9)
    assert row["tilt"] == pytest.approx(5e-4, rel=1e-12)
    assert row["force"] == pytest.approx(1000.0, rel=1e-9)
    assert len(row["stiffness_matrix"]) == 2 and row["moment"] > 0


def test_straight_roller_reports_edge_loading_not_a_number(capsys):
    """A straight roller (--tilt only) is edge loaded: its peak pressure is singular on
    a half-space, so the profiled row prints '-' for p max, 'both ends' for the edge,
    and says why; the JSON has p_max null and edge_loaded true."""
    status, out, err = _main(capsys, *ROLLER, "--load", "1kN", "--tilt", "0")
    assert status == 0, err
    row = next(ln for ln in out.splitlines() if ln.startswith("Profiled roller"))
    assert "both ends" in row and "singular" in row
    doc = _json(capsys, *ROLLER, "--load", "1kN", "--tilt", "0")
    r = doc["profiled_roller"][0]["rows"][0]
    assert r["p_max"] is None and r["edge_loaded"] is True


def test_sweep_gives_one_profiled_row_per_value(capsys):
    """A load sweep gives one profiled-roller row per load; the depth increases with
    the load (F(d) is increasing)."""
    doc = _json(capsys, *ROLLER, "--load", "0.5kN:2kN:3", "--crown-radius", "200mm")
    rows = doc["profiled_roller"][0]["rows"]
    assert len(rows) == 3
    depths = [r["depth"] for r in rows]
    assert depths == sorted(depths) and depths[0] > 0


@pytest.mark.parametrize("argv, name", [
    (["--profile", "cone"], "profile"),
    (["--crown-radius", "-5mm"], "--crown-radius"),
    (["--crown-radius", "0"], "--crown-radius"),
    (["--tilt", "5furlong"], "--tilt"),
    (["--tilt", "10deg"], "--tilt"),
    (["--crown-radius", "0.5", "--profile", "iso16281"], "--crown-radius"),
    (["--profile", "circular:Rc=-1"], "Rc"),
    (["--profile", "file:/nonexistent/p.csv"], "profile file"),
])
def test_bad_profile_input_is_one_line_exit_2(capsys, argv, name):
    """Bad profile input (unknown name, crown radius <= 0, an angle that is not one or
    beyond 0.1 rad, two profiles at once, a missing file) exits with status 2 and one
    line on stderr naming the parameter and the valid range; nothing on stdout."""
    status, out, err = _main(capsys, *ROLLER, "--load", "1kN", *argv)
    assert status == 2 and out == ""
    assert err.count("\n") == 1 and name in err and "valid" in err


def test_no_contact_and_whole_roller_are_refused(capsys, tmp_path):
    """A depth at which the roller does not touch at all (a measured profile whose
    smallest drop, 2 um, exceeds the depth, 1 um), and the profile options with the
    raceways (a whole roller), exit 2 with one line naming the parameter."""
    f = tmp_path / "p.csv"
    f.write_text("x,drop\n-0.005,3e-6\n0,2e-6\n0.005,3e-6\n")
    status, _, err = _main(capsys, *ROLLER, "--depth", "1um", "--profile", f"file:{f}")
    assert status == 2 and err.count("\n") == 1 and "depth" in err
    status, _, err = _main(capsys, *ROLLER, "--load", "1kN", "--crown-radius", "0.1",
                           "--inner-raceway", "20mm", "--outer-raceway", "30mm")
    assert status == 2 and "whole roller" in err


def test_batch_refuses_profile_columns(capsys, tmp_path):
    """A CSV batch with a profile column computes its other rows and refuses the
    profiled ones in their error cell (profiled rollers are one case or a sweep), exit
    status 2 as for any failed row."""
    f = tmp_path / "cases.csv"
    f.write_text("radius,length,estar,load,crown_radius\n5mm,10mm,115GPa,1kN,0.1\n"
                 "5mm,10mm,115GPa,1kN,\n")
    status, out, err = _main(capsys, "calc", str(f))
    assert status == 2
    rows = out.strip().splitlines()
    assert "not computed in a batch" in rows[1] and rows[2].split(",")[-1] == ""
