"""Radial roller bearings (linecontact.bearing, ``linecontact bearing``): Stribeck's
load distribution, the load-zone integral, equilibrium, stiffness, rating lives and the
one-line refusals."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from linecontact.bearing import (RadialRollerBearing, basic_rating_life,
                                 dynamic_load_rating, lamina_load_ratings,
                                 load_zone_integral, reference_rating_life)
from linecontact.calc.cli import main
from linecontact.errors import OutOfRangeError

N = 10 / 9


def _jr_quad(eps, n=N):
    """J_r by adaptive quadrature over psi, independent of the module's substitution."""
    lim = math.pi if eps >= 1 else math.acos(1 - 2 * eps)
    f = lambda p: max(0.0, 1 - (1 - math.cos(p)) / (2 * eps)) ** n * math.cos(p)  # noqa
    return quad(f, -lim, lim, limit=200)[0] / (2 * math.pi)


@pytest.mark.parametrize("eps", [0.1, 0.3, 0.5, 0.8, 1.0])
def test_load_zone_integral_against_quadrature(eps):
    """J_r(eps) of Harris equals an independent adaptive quadrature of its definition
    to 1e-8 (the module uses Gauss-Legendre after removing the edge singularity)."""
    assert load_zone_integral(eps) == pytest.approx(_jr_quad(eps), rel=1e-8)


def test_load_zone_integral_stribeck_value():
    """J_r(0.5) = 0.2448 for n = 10/9 (Harris' table), so Z Q_max/F_r -> 4.085."""
    assert round(load_zone_integral(0.5), 4) == 0.2448


def _spring_bearing(Z, clearance=0.0):
    """Z rollers of 10 mm on a pitch circle wide enough for them (d_m sin(pi/Z) > D:
    200 mm up to 62 rollers, 300 mm beyond); the ISO spring law does not depend on d_m."""
    return RadialRollerBearing(Z, 200e-3 if Z <= 62 else 300e-3, 10e-3, 10e-3, clearance,
                               model="iso16281")


def test_stribeck_many_rollers():
    """ISO spring law (Q ~ delta^(10/9)), zero clearance, many rollers: Z Q_max/F_r
    tends to 1/J_r(0.5) = 4.085 (discrete sum -> integral; 1e-3 at Z = 60)."""
    s = _spring_bearing(60).solve(20e3)
    assert 60 * s.max_roller_load / 20e3 == pytest.approx(1 / load_zone_integral(0.5),
                                                          rel=1e-3)


def test_stribeck_small_z_exact_discrete():
    """For Z = 5 the exact discrete equilibrium of a power law with zero clearance is
    Q_j = Q_max cos(psi_j)^n over the loaded rollers and F_r = sum Q_j cos psi_j, so
    Z Q_max/F_r = Z / sum_{cos>0} cos^(n+1) psi_j (= 2.2906...) whatever the law's
    constant: the solver must reproduce it to 1e-9."""
    Z = 5
    psi = 2 * math.pi * np.arange(Z) / Z
    c = np.cos(psi)
    exact = Z / np.sum(c[c > 1e-12] ** (N + 1))
    s = _spring_bearing(Z).solve(5e3)
    assert Z * s.max_roller_load / 5e3 == pytest.approx(exact, rel=1e-9)


@pytest.mark.parametrize("clearance", [20e-6, 60e-6])
def test_load_zone_against_clearance(clearance):
    """With clearance the many-roller solution obeys Harris: eps = (1 - P_d/(2 delta_r))
    /2 from the ring displacement and Q_max = F_r/(Z J_r(eps)) (1e-3 at Z = 80), and the
    load zone psi_l = arccos(P_d/(2 delta_r))."""
    Z, F = 80, 20e3
    s = _spring_bearing(Z, clearance).solve(F)
    eps = 0.5 * (1 - clearance / (2 * s.displacement))
    assert s.epsilon == pytest.approx(eps, rel=1e-12)
    assert Z * s.max_roller_load / F == pytest.approx(1 / _jr_quad(eps), rel=2e-3)
    assert s.load_zone == pytest.approx(math.acos(clearance / (2 * s.displacement)))


@pytest.mark.parametrize("model,clearance", [("universal", 0.0), ("universal", 30e-6),
                                             ("universal", -10e-6), ("iso16281", 15e-6)])
def test_equilibrium_sums_to_the_load(model, clearance):
    """Static equilibrium: sum Q_j cos psi_j = F_r to 1e-9 (after the exact polish),
    every unloaded roller has a gap, every loaded one an approach."""
    b = RadialRollerBearing(18, 90e-3, 12e-3, 14e-3, clearance, model=model)
    s = b.solve(15e3)
    assert s.roller_loads @ np.cos(s.azimuth) == pytest.approx(15e3, rel=1e-9)
    assert np.all((s.roller_loads > 0) == (s.approach > 0))


def test_loads_obey_the_exact_law():
    """Each loaded roller's approach equals the roller law's deflection at its load
    (roller_between_raceways, computed directly) to 1e-9."""
    from linecontact.raceway import roller_between_raceways

    b = RadialRollerBearing(18, 90e-3, 12e-3, 14e-3, 20e-6)
    s = b.solve(15e3)
    on = s.roller_loads > 0
    d = roller_between_raceways(6e-3, 14e-3, b.estar, b.raceways,
                                force=s.roller_loads[on]).deflection
    assert np.allclose(d, s.approach[on], rtol=1e-9)


@pytest.mark.parametrize("clearance", [0.0, 25e-6, -8e-6])
def test_stiffness_equals_finite_differences(clearance):
    """K_rr = sum k_j cos^2 psi_j (1x1, symmetric trivially) equals the central finite
    difference dF_r/d delta_r of two solves at F_r (1 +- 1e-4) to 1e-5 (the FD
    truncation error is O(h^2) ~ 1e-8 away from a load-zone change)."""
    b = RadialRollerBearing(16, 80e-3, 10e-3, 12e-3, clearance)
    F, h = 10e3, 1e-4
    s = b.solve(F)
    K = s.stiffness
    assert K.shape == (1, 1) and np.allclose(K, K.T)
    dp, dm = b.solve(F * (1 + h)).displacement, b.solve(F * (1 - h)).displacement
    assert K[0, 0] == pytest.approx(2 * h * F / (dp - dm), rel=1e-5)


def test_dynamic_load_rating_fc_table():
    """ISO 281's f_c of radial roller bearings at gamma = 0.05, 0.10 (74.1, 84.2 in the
    standard's table), recovered from C_r with b_m = 1, L = D = 1 mm, Z = 1 ... as
    C_r / (L^(7/9) Z^(3/4) D^(29/27))."""
    for g, fc in ((0.05, 74.1), (0.10, 84.2)):
        C = dynamic_load_rating(16, 1e-3 / g, 1e-3, 1e-3, b_m=1.0)
        assert C / 16 ** 0.75 == pytest.approx(fc, abs=0.05)


def test_iso16281_factors_are_the_load_zone_ratios():
    """The ISO 16281 factors 0.378 and 0.364 are the Lundberg-Palmgren ratios
    J_r/J_1 and J_r/J_2 (exponents 4 and 4.5) of the zero-clearance load zone: 0.3764
    and 0.3630 by quadrature, within 0.5 %."""
    jr = load_zone_integral(0.5)
    j1 = (quad(lambda p: math.cos(p) ** (4 * N), -math.pi / 2, math.pi / 2)[0]
          / (2 * math.pi)) ** 0.25
    j2 = (quad(lambda p: math.cos(p) ** (4.5 * N), -math.pi / 2, math.pi / 2)[0]
          / (2 * math.pi)) ** (1 / 4.5)
    assert jr / j1 == pytest.approx(0.378, rel=5e-3)
    assert jr / j2 == pytest.approx(0.364, rel=5e-3)


def test_reference_life_reproduces_iso281_rating():
    """A uniformly loaded, aligned roller set (uniform lamina loads, the Stribeck zone of
    many rollers, zero clearance, the ISO spring) through the ISO 16281 formulas: at
    P = C_r its life is ISO 281's L10 = 1 (within 2 %: the standard's rounded factors
    0.378/0.364 against 0.3764/0.3630), and it scales as (C/P)^4 (line contact), where
    ISO 281 rounds the exponent to 10/3."""
    b = RadialRollerBearing(60, 600e-3, 10e-3, 10e-3, model="iso16281")
    C = b.rating
    lives = {}
    for P in (0.1 * C, 0.2 * C):
        lives[P] = b.solve(P).life_iso16281
    # the life at P = C from the (C/P)^4 scaling of two loads in the law's range
    slope = math.log(lives[0.2 * C] / lives[0.1 * C]) / math.log(2.0)  # d ln L/d ln P
    assert slope == pytest.approx(-4.0, abs=1e-6)
    L_at_C = lives[0.1 * C] * 0.1 ** 4
    assert L_at_C == pytest.approx(basic_rating_life(C, C), rel=0.02)


def test_reference_life_independent_of_laminae():
    """Uniform lamina loads: L10r does not depend on the number of laminae (the lamina
    rating scales as n_s^(-7/9), Lundberg-Palmgren's L^(7/9))."""
    lives = []
    for n in (1, 7, 40):
        q = np.zeros((12, n))
        q[:5] = 3000.0 / n
        lives.append(reference_rating_life(50e3, 60e-3, 10e-3, q, q))
    assert np.allclose(lives, lives[0], rtol=1e-12)
    qi, qe = lamina_load_ratings(50e3, 12, 60e-3, 10e-3, 1)
    assert qi < qe  # the inner (convex) ring is the weaker


def test_profiled_bearing_matches_exact_slice_solves():
    """Crowned rollers (coupled slices, 20 slices for speed): the tabulated equilibrium
    polished with exact roller solves leaves a roller-law residual below the polish's
    tolerance 1e-9, the loads balance F_r to round-off (1e-12: the equilibrium row is
    linear in the loads), and the most loaded roller's lamina loads (20 equal laminae
    over the roller) are a direct slice solve of its two contacts at its load put onto
    the same laminae (to 1e-12 of the peak: the same solve), adding up to the roller
    load to the slice solver's force tolerance 1e-10; its approach is that solve's
    deflection to the polish's 1e-9."""
    from linecontact.raceway import Raceways, roller_between_raceways

    b = RadialRollerBearing(12, 60e-3, 8e-3, 8e-3, profile="circular:Rc=0.5",
                            n_slices=20)
    s = b.solve(5e3)
    assert s.law_error < 1e-9
    assert s.roller_loads @ np.cos(s.azimuth) == pytest.approx(5e3, rel=1e-12)
    j = int(np.argmax(s.roller_loads))
    r = roller_between_raceways(4e-3, 8e-3, b.estar,
                                Raceways(b.raceways.inner, b.raceways.outer),
                                force=s.roller_loads[j], profile="circular:Rc=0.5",
                                tilt=0.0, n_slices=20)
    # the direct solve's slices (over its contact only) summed onto the 20 equal
    # laminae of the roller length
    x, q, w = r.inner.x, r.inner.q, r.inner.width
    cum = np.concatenate([[0.0], np.cumsum(q * w)])
    lam = np.diff(np.interp(np.linspace(-4e-3, 4e-3, 21),
                            np.concatenate([x - w / 2, [x[-1] + w[-1] / 2]]), cum))
    assert s.slice_loads_inner[j].sum() == pytest.approx(s.roller_loads[j], rel=1e-10)
    assert np.allclose(s.slice_loads_inner[j], lam,
                       rtol=0, atol=1e-12 * s.slice_loads_inner[j].max())
    assert s.approach[j] == pytest.approx(r.deflection, rel=1e-9)


@pytest.mark.parametrize("kwargs,name", [
    (dict(rollers=2), "rollers"),
    (dict(pitch_diameter=5e-3), "pitch_diameter"),
    (dict(clearance=12e-3), "clearance"),
])
def test_bad_geometry_refused(kwargs, name):
    """Z < 3, a pitch diameter below the roller's, a clearance beyond the roller: one
    OutOfRangeError naming the parameter."""
    args = dict(rollers=12, pitch_diameter=60e-3, roller_diameter=10e-3, length=10e-3)
    args.update(kwargs)
    with pytest.raises(OutOfRangeError, match=name):
        RadialRollerBearing(**args)


def test_load_lifting_every_roller_refused():
    """A radial load <= 0 lifts every roller: refused with the reason."""
    b = RadialRollerBearing(12, 60e-3, 10e-3, 10e-3)
    with pytest.raises(OutOfRangeError, match="lifts every roller"):
        b.solve(0.0)


def test_cli_table_json_and_errors(capsys, tmp_path):
    """The command prints the table (and JSON whose loads balance F_r), and a bad
    input is one line on stderr with status 2."""
    import json

    base = ["bearing", "--rollers", "14", "--pitch-diameter", "70mm",
            "--roller-diameter", "11mm", "--length", "11mm", "--radial-load", "10kN"]
    assert main(base + ["--clearance", "-5um"]) == 0
    assert "K_rr" in capsys.readouterr().out
    assert main(base + ["--json"]) == 0
    d = json.loads(capsys.readouterr().out)["rows"][0]["solution"]
    assert np.dot(d["roller_loads"], np.cos(d["azimuth"])) == pytest.approx(1e4, rel=1e-9)
    assert main(base + ["--rollers", "2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "rollers" in err[0]
    csv = tmp_path / "b.csv"
    csv.write_text("rollers,pitch_diameter,roller_diameter,length,radial_load\n"
                   "14,70mm,11mm,11mm,10kN\n12,5mm,11mm,11mm,1kN\n")
    assert main(["bearing", str(csv)]) == 2  # the second row fails, the first is written
    out = capsys.readouterr().out.splitlines()
    assert len(out) == 3 and out[1].split(",")[-1] == "" and "pitch_diameter" in out[2]


@pytest.mark.parametrize("extra,says", [
    (["--estar", "115GPa", "--modulus", "210GPa"], "--modulus"),
    (["--modulus2", "200GPa"], "--modulus"),
    (["--modulus", "210GPa"], "--poisson"),
    (["--tilting-moment", "5Nm", "--misalignment", "1mrad"], "--misalignment"),
    (["--rollers", "14.5"], "--rollers"),
    (["--n-slices", "40.5"], "--n-slices"),
    (["--surface-hardness", "700"], "--case-depth"),
])
def test_cli_rules_refuse_with_one_line_naming_the_option(capsys, extra, says):
    """The bearing's input rules (E* or the moduli, a moment or a misalignment, whole
    counts, the case-check inputs together): one line naming the option, status 2,
    nothing silently taken (--n-slices 40.5 was truncated to 40 slices before)."""
    base = {"--rollers": "14", "--pitch-diameter": "70mm", "--roller-diameter": "11mm",
            "--length": "11mm", "--radial-load": "10kN"}
    for k, v in zip(extra[::2], extra[1::2]):
        base[k] = v
    assert main(["bearing", *[x for kv in base.items() for x in kv]]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and says in err[0], err


def test_tabulated_roller_is_roller_between_raceways():
    """The bearing's tabulated (aligned, sliced) path, its equilibrium polished with
    exact roller solves, at its most loaded roller is the per-roller reference:
    roller_between_raceways at that roller's load between the bearing's raceways, free
    to tilt, with the same slice model and count (both from linecontact.roller.solvers)
    is the very solve the bearing keeps (BearingSolution.roller: deflection, tilt,
    moment, peak pressures, equal to the last bit), the roller's approach meets its
    deflection to the polish's tolerance (1e-9 relative), its tilt and moment are that
    solve's (a symmetric profile's tilt exactly 0, the moments 0 to round-off, 1e-12 Q
    L), and the peak pressure and stresses are that solve's."""
    from linecontact.raceway import roller_between_raceways
    from linecontact.stresses import roller_stresses

    b = RadialRollerBearing(12, 60e-3, 8e-3, 10e-3, profile="iso16281")
    s = b.solve(5e3)
    j = int(np.argmax(s.roller_loads))
    Q = s.roller_loads[j]
    r = roller_between_raceways(4e-3, 10e-3, b.estar, b.raceways, force=Q,
                                profile="iso16281", tilt="free")
    assert r.force == Q and r.model == s.model
    for name in ("deflection", "tilt", "moment_inner", "peak_pressure_inner",
                 "peak_pressure_outer", "stiffness"):
        assert getattr(s.roller, name) == getattr(r, name), name
    assert 0 <= s.law_error < 1e-9
    assert r.deflection == pytest.approx(s.approach[j], rel=1e-9)
    assert r.tilt == 0.0 and s.roller_tilts[j] == 0.0
    assert abs(r.moment_inner) < 1e-12 * Q * 10e-3
    assert s.roller_moments[j] == r.moment_inner
    assert s.peak_pressure == max(r.peak_pressure_inner, r.peak_pressure_outer)
    worst = max(roller_stresses(c, poisson=0.3).worst["tresca"]["value"]
                for c in (r.inner, r.outer))
    assert s.stress["tresca"]["value"] == worst


def test_tilted_roller_is_roller_between_raceways():
    """The bearing's tilted path solves each roller between its rings misaligned by
    phi_j = theta cos psi_j, free to tilt: at the most loaded roller it is the same
    solve as roller_between_raceways at that roller's load with the rings misaligned
    by phi_j (both from the same slice solvers): approach and tilt to 1e-9 relative
    (the two Newton solves' tolerances: force and moment balance below 1e-10 of F and
    F L), the roller's moment M_in to 1e-9 of Q L."""
    from linecontact.raceway import Raceways, roller_between_raceways

    b = RadialRollerBearing(12, 60e-3, 8e-3, 10e-3, 20e-6, profile="circular:Rc=0.3")
    s = b.solve(8e3, misalignment=5e-4)
    j = int(np.argmax(s.roller_loads))
    Q, L = s.roller_loads[j], 10e-3
    race = Raceways(b.raceways.inner, b.raceways.outer, fit_tolerance=0.4999,
                    misalignment=s.roller_misalignment[j])
    r = roller_between_raceways(4e-3, L, b.estar, race, force=Q,
                                profile="circular:Rc=0.3", tilt="free")
    assert r.deflection == pytest.approx(s.approach[j], rel=1e-9)
    assert r.tilt == pytest.approx(s.roller_tilts[j], rel=1e-9)
    assert r.moment_inner == pytest.approx(s.roller_moments[j], abs=1e-9 * Q * L)


def test_law_bearing_roller_is_roller_between_raceways():
    """A straight roller under a law (the universal curve): the solution's most loaded
    roller (BearingSolution.roller, taken from the exact polish's own solve of the
    loaded rollers) is roller_between_raceways at Q_max, equal to the last bit (the
    law's elementwise evaluation), its approach meets the deflection to round-off
    (the polish stops at 1e-13), and the stresses are the Hertz strips of that roller
    (the case check's input, roller_stresses)."""
    from linecontact.raceway import roller_between_raceways

    b = RadialRollerBearing(20, 100e-3, 10e-3, 10e-3, 20e-6)
    s = b.solve(10e3)
    r = roller_between_raceways(5e-3, 10e-3, b.estar, b.raceways, force=s.max_roller_load)
    for name in ("force", "deflection", "stiffness", "peak_pressure_inner",
                 "peak_pressure_outer", "depth_inner", "depth_outer"):
        assert getattr(s.roller, name) == getattr(r, name), name
    j = int(np.argmax(s.roller_loads))
    assert s.approach[j] == pytest.approx(r.deflection, rel=1e-12)
    worst = max(st.worst["tresca"]["value"] for st in s.roller_stresses.values())
    assert s.stress["tresca"]["value"] == worst
