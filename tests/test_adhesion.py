"""The rule of Hess (linecontact.adhesion) against exact oracles.

- JKR sphere (Johnson, Kendall & Roberts 1971) through the generic code, g = x^2/R:
  pull-off 1.5 pi w R (force control), 5/6 pi w R (depth control), zero-load radius
  a0 = (9 pi w R^2/(2 E*))^(1/3), and the JKR force-depth law on both branches;
- Kendall's punch (1971): F = -sqrt(8 pi a^3 E* w);
- w = 0: the non-adhesive law exactly;
- the 2D JKR cylinder (Barquins 1988): its pull-off is the minimum of its F/L(b);
- the finite cylinder's corrected law tends to the 2D JKR value per length (long roller).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.adhesion import (AdhesiveContact, CylinderAdhesion,
                                  jkr_cylinder_force_per_length, jkr_cylinder_pull_off,
                                  tabor_note, tabor_parameter)
from linecontact.errors import OutOfRangeError
from linecontact.models import get_model

R, E, W = 10e-3, 1.5e6, 0.04


def sphere(work=W, closed=False):
    nf = (lambda a: 4 * E * np.asarray(a) ** 3 / (3 * R)) if closed else None
    return AdhesiveContact(lambda x: x ** 2 / R, E, work, normal_force=nf)


@pytest.mark.parametrize("closed", [False, True])
def test_jkr_sphere_pull_off_both_controls(closed):
    """JKR: -3/2 pi w R under force control, -5/6 pi w R under depth control, for the
    quadrature F_N and the closed form alike (to 1e-9: Brent's tolerance 1e-12 in a at a
    stationary point)."""
    c = sphere(closed=closed)
    assert c.pull_off("force")["force"] == pytest.approx(-1.5 * math.pi * W * R, rel=1e-9)
    assert c.pull_off("depth")["force"] == pytest.approx(-5 / 6 * math.pi * W * R, rel=1e-8)


def test_jkr_sphere_radii_and_depths():
    """JKR radii: a_c^3 = 9 pi w R^2/(8 E*) at force-controlled pull-off, a0^3 = 4 a_c^3 at
    zero load, a_d^3 = a_c^3/9 at depth-controlled pull-off, where d = -3 a_d^2/R."""
    c = sphere()
    ac3 = 9 * math.pi * W * R ** 2 / (8 * E)
    assert c.pull_off("force")["contact_radius"] ** 3 == pytest.approx(ac3, rel=1e-9)
    assert c.zero_load()["contact_radius"] ** 3 == pytest.approx(4 * ac3, rel=1e-12)
    off = c.pull_off("depth")
    assert off["contact_radius"] ** 3 == pytest.approx(ac3 / 9, rel=1e-8)
    assert off["depth"] == pytest.approx(-3 * off["contact_radius"] ** 2 / R, rel=1e-8)


def test_jkr_sphere_force_depth_both_branches():
    """At any depth the force on either branch satisfies JKR's parametric law
    F = 4E* a^3/(3R) - sqrt(8 pi a^3 E* w), d = a^2/R - sqrt(2 pi a w/E*) (to 1e-10)."""
    c = sphere()
    d_off = c.pull_off("depth")["depth"]
    for branch, depths in (("stable", np.linspace(d_off * 0.999, 5e-5, 7)),
                           ("unstable", np.linspace(d_off * 0.999, d_off * 0.01, 5))):
        a = np.asarray(c.radius_at_depth(depths, branch))
        assert np.allclose(a ** 2 / R - np.sqrt(2 * math.pi * a * W / E), depths,
                           rtol=1e-10, atol=1e-20)
        F = np.asarray(c.force_at_depth(depths, branch))
        assert np.allclose(F, 4 * E * a ** 3 / (3 * R) - np.sqrt(8 * math.pi * a ** 3 * E * W),
                           rtol=1e-9)
    with pytest.raises(OutOfRangeError, match="depth"):
        c.force_at_depth(1.01 * d_off)


def test_kendall_punch():
    """A flat punch of radius a (g = 0 for x < a): the rule of Hess gives Kendall's
    pull-off F = -sqrt(8 pi a^3 E* w) at the contact radius a (F_N(a) = 0)."""
    a = 2e-3
    c = AdhesiveContact(lambda x: 0.0 if x <= a else 1.0, E, W)
    assert c.force(a) == pytest.approx(-math.sqrt(8 * math.pi * a ** 3 * E * W), rel=1e-12)
    # the edge springs detach at d = -sqrt(2 pi a w/E*): F = 2 E* a d there, the same value
    assert 2 * E * a * c.depth(a) == pytest.approx(c.force(a), rel=1e-12)


def test_zero_work_is_the_non_adhesive_law():
    """w = 0: F(d) on the (one) branch equals the model's own F(d) to rounding, and there
    is no pull-off."""
    m = get_model("universal", 5e-3, 10e-3, 2.7e6)
    c = AdhesiveContact.from_model(m, 0.0)
    d = np.array([1e-7, 1e-6, 1e-5])
    assert np.allclose(c.force_at_depth(d), m.force(d), rtol=1e-10)
    s = sphere(work=0.0)
    assert s.force_at_depth(1e-6) == pytest.approx(4 / 3 * E * math.sqrt(R) * 1e-9, rel=1e-9)
    with pytest.raises(OutOfRangeError, match="work"):
        s.pull_off("force")


def test_hysteresis_energy_of_jkr_sphere():
    """The energy lost per depth-controlled cycle is the area between the curves: the
    integral of -F over the stable branch from the pull-off depth to 0, here checked
    against an independent quadrature in a of the closed-form JKR law (to 1e-4)."""
    from scipy.integrate import quad

    c = sphere()
    h = c.hysteresis(5e-5)
    ad = c.pull_off("depth")["contact_radius"]
    a0 = float(c.radius_at_depth(0.0))

    def integrand(a):
        F = 4 * E * a ** 3 / (3 * R) - math.sqrt(8 * math.pi * a ** 3 * E * W)
        dd = 2 * a / R - 0.5 * math.sqrt(2 * math.pi * W / (E * a))
        return -F * dd

    ref, _ = quad(integrand, ad, a0, epsrel=1e-12)
    assert h["energy"] == pytest.approx(ref, rel=1e-4)
    assert h["approach_force"][0] == 0 and h["retraction_force"][-1] < 0


def test_2d_jkr_pull_off_is_the_minimum_of_its_law():
    """Barquins' pull-off F_c/L = -3 (pi E* R w^2/16)^(1/3) at b_c = (2 R^2 w/(pi E*))^(1/3)
    is the minimum of F/L(b) = pi E* b^2/(4R) - sqrt(2 pi E* w b)."""
    from scipy.optimize import minimize_scalar

    F, b = jkr_cylinder_pull_off(R, E, W)
    res = minimize_scalar(lambda x: jkr_cylinder_force_per_length(x * b, R, E, W),
                          bounds=(0.1, 10), method="bounded", options={"xatol": 1e-10})
    assert res.x == pytest.approx(1.0, rel=1e-6)
    assert res.fun == pytest.approx(F, rel=1e-12)


def test_long_roller_below_the_table_gets_the_end_model_and_the_mdr_its_error():
    """A long roller (s = b_c/L = 1e-3, below the BEM table): the pull-off is the long
    roller's end model (method 'end-model', tables/adhesion_long_roller.csv, with its
    stated error; tests/test_adhesion_long.py), below the 2D JKR value times L (the ends
    peel first); method='mdr' gives the rule of Hess by name with its error against it.
    The plain rule misses by more than 10 % (its edge term scales with the MDR
    half-length ~ L, not with b; its pull-off lies beyond d = 0.15 R here, so the model
    is asked with extrapolate=True). Below s = 1e-3 the pull-off is refused with the
    parameter and the range named, and the rule of Hess has no measured error (NaN)."""
    Rr, L, Ee = 1e-3, 0.2, 2.7e6
    w = math.pi / 2 * 1e-3 ** 3 * Ee * L ** 3 / Rr ** 2
    c = CylinderAdhesion(get_model("universal", Rr, L, Ee, extrapolate=True), w)
    assert c.s == pytest.approx(1e-3, rel=1e-9)
    r = c.pull_off("force")
    assert r["method"] == "end-model" and 0 < r["error"] < 0.06   # stated 5.6 % at 1e-3
    assert 0.5 < r["ratio"] < 1 and r["pull_off_2d"] == c.pull_off_2d
    res = c.pull_off("force", method="mdr")
    assert res["method"] == "mdr"
    assert res["error"] == pytest.approx(res["force"] / r["force"] - 1, rel=1e-12)
    F2, _ = jkr_cylinder_pull_off(Rr, Ee, w)
    assert res["force"] == pytest.approx(c.mdr.pull_off("force")["force"], rel=1e-12)
    assert abs(res["force"] / L / F2 - 1) > 0.1
    c2 = CylinderAdhesion(get_model("universal", Rr, L, Ee, extrapolate=True), w / 8)
    with pytest.raises(OutOfRangeError, match="work.*below the long roller's table"):
        c2.pull_off("force")
    assert math.isnan(c2.pull_off("force", method="mdr")["error"])


def test_corrected_values_are_the_table_at_its_nodes():
    """At every row of the table the corrected pull-off (both controls) is the row's
    ratio times the 2D JKR value of the length, and method='mdr' carries the row's
    measured MDR error (PCHIP passes through its nodes: to 1e-12)."""
    from linecontact.tables import read_table

    cols = read_table("adhesion_cylinder").columns
    m = get_model("universal", 1.0, 1.0, 1.0, extrapolate=True)
    for i, si in enumerate(cols["s"]):
        c = CylinderAdhesion(m, math.pi / 2 * si ** 3)
        for ctl in ("force", "depth"):
            r = c.pull_off(ctl)
            assert r["ratio"] == pytest.approx(cols[f"ratio_{ctl}"][i], rel=1e-12)
            assert r["force"] == pytest.approx(r["ratio"] * c.pull_off_2d, rel=1e-12)
            e = c.pull_off(ctl, method="mdr")["error"]
            assert e == pytest.approx(cols[f"mdr_err_{ctl}"][i], rel=1e-9, abs=1e-12)


def test_mdr_error_is_the_row_models_own():
    """The MDR's error is this model's rule of Hess against the BEM value (mdr/BEM - 1
    to 1e-12), not the universal curve's table column reused for every model: at one
    s, Puttock-Thwaite's MDR pulls off about 20 % away from the universal curve's, and
    so must its error."""
    E = 6.7e4
    errs = {}
    for key in ("universal", "puttock-thwaite"):
        c = CylinderAdhesion(get_model(key, 1e-3, 2e-3, E), 0.05)
        r = c.pull_off("force")
        m = c.pull_off("force", method="mdr")
        assert m["error"] == pytest.approx(m["force"] / r["force"] - 1, rel=1e-12)
        assert r["mdr_error"] == pytest.approx(m["error"], rel=1e-12)
        errs[key] = m["error"]
    assert abs(errs["universal"] - errs["puttock-thwaite"]) > 0.1, errs


def test_cylinder_table_refuses_beyond_its_end_and_other_shapes():
    """s beyond the table's largest value and a model without the cylinder's geometry
    are refused with the parameter named."""
    m = get_model("universal", 1e-3, 1e-3, 1e6)
    with pytest.raises(OutOfRangeError, match="work"):
        CylinderAdhesion(m, 1e3)
    with pytest.raises(OutOfRangeError, match="model"):
        CylinderAdhesion(get_model("kunz", 1e-3, 1e-3, 1e6), 0.01)


def test_tabor_parameter_and_regimes():
    """mu_T = (R w^2/(E*^2 z0^3))^(1/3); the note names JKR above 5 and DMT below 1."""
    assert tabor_parameter(1.0, 1.0, 1.0, z0=1.0) == pytest.approx(1.0)
    assert tabor_parameter(8.0, 1.0, 1.0, z0=1.0) == pytest.approx(2.0)
    assert "JKR regime" in tabor_note(10.0)
    assert "DMT-like" in tabor_note(0.5)


def test_viscoelastic_limits_and_refusal():
    """Relaxed and instantaneous limits are JKR with E*(inf) and E*(0) (the sphere's
    pull-off does not depend on E*, its zero-load radius does); any rate in between is
    refused with the reason."""
    from linecontact.contact import Viscoelastic
    from linecontact.viscoelastic import StandardLinearSolid

    sls = StandardLinearSolid(3e6, 1e6, 0.1)
    c = sphere()
    for limit, E in (("relaxed", 1e6), ("instantaneous", 3e6)):
        v = c.viscoelastic_limit(Viscoelastic(sls, 0.0), limit)  # nu = 0, rigid: E* = E
        assert v.estar == pytest.approx(E)
        assert v.pull_off("force")["force"] == pytest.approx(-1.5 * math.pi * W * R, rel=1e-9)
        assert v.zero_load()["contact_radius"] ** 3 == pytest.approx(
            9 * math.pi * W * R ** 2 / (2 * E), rel=1e-10)
    with pytest.raises(OutOfRangeError, match="crack-tip"):
        c.viscoelastic_limit(Viscoelastic(sls, 0.0), "1 mm/s")


@pytest.mark.parametrize("nu1,E2,nu2", [(0.5, np.inf, None), (0.4, 210e9, 0.3),
                                        (0.3, 5e6, 0.45)])
def test_viscoelastic_limit_uses_the_effective_modulus_of_the_pair(nu1, E2, nu2):
    """The limits are JKR with the EFFECTIVE modulus: 1/E* = (1 - nu1^2)/E1 +
    (1 - nu2^2)/E2 at t = 0 and t = inf (Johnson 1985, Eq. 4.22; Lee & Radok 1960:
    the compliances add at every time, so at both ends), to 1e-12 (the series of
    effective_relaxation is computed by root finding to machine precision); a bare
    Prony series (perhaps the body's own E(t)) is refused, never read as E*."""
    from linecontact.contact import Elastic, Viscoelastic
    from linecontact.viscoelastic import StandardLinearSolid, effective_relaxation

    sls = StandardLinearSolid(3e6, 1e6, 0.1)
    counter = None if np.isinf(E2) else Elastic(E2, nu2)
    c = sphere()
    for limit, E1 in (("relaxed", 1e6), ("instantaneous", 3e6)):
        expected = 1 / ((1 - nu1**2) / E1 + (0 if counter is None else (1 - nu2**2) / E2))
        v = c.viscoelastic_limit(Viscoelastic(sls, nu1), limit, counter)
        assert v.estar == pytest.approx(expected, rel=1e-12)
        # the effective E*(t) of the library's own function gives the same
        eff = effective_relaxation(sls, nu1, E2, nu2)
        assert c.viscoelastic_limit(eff, limit).estar == v.estar
    with pytest.raises(OutOfRangeError, match="material.*own E\\(t\\)"):
        c.viscoelastic_limit(sls, "relaxed")
    with pytest.raises(OutOfRangeError, match="counterbody"):
        c.viscoelastic_limit(effective_relaxation(sls, nu1), "relaxed", Elastic(E2, nu2))


def test_depth_at_force_inverts_force_at_depth():
    """On the stable branch d(F(d)) = d (the two are inverses, to 1e-9), including at
    zero and negative forces down to the force-controlled pull-off."""
    c = sphere()
    d = np.array([c.pull_off("force")["depth"] * 0.9, 0.0, 3e-5])
    F = np.asarray(c.force_at_depth(d))
    assert np.allclose(c.depth_at_force(F), d, rtol=1e-9, atol=1e-15)
    with pytest.raises(OutOfRangeError, match="force"):
        c.depth_at_force(1.01 * c.pull_off("force")["force"])


def test_unknown_control_or_method_is_an_unknown_name():
    """A control or method that is not one of the names is an UnknownNameError listing
    the names (a name has no range), the project's rule for every named option."""
    from linecontact.adhesion import CylinderAdhesion
    from linecontact.errors import UnknownNameError
    from linecontact.models import get_model

    c = CylinderAdhesion(get_model("universal", 1e-3, 2e-3, 6.7e4), 0.05)
    with pytest.raises(UnknownNameError, match="'bem', 'mdr'"):
        c.pull_off("force", method="x")
    with pytest.raises(UnknownNameError, match="'force', 'depth'"):
        c.pull_off("forse")
    with pytest.raises(UnknownNameError, match="'force', 'depth'"):
        c.mdr.pull_off("forse")


@pytest.mark.parametrize("R,E,w", [(1e-3, 1e6, 0.05), (5e-3, 2e9, 0.1), (0.1, 1e5, 1.0)])
def test_2d_jkr_zero_load_half_width_is_the_root_of_the_force(R, E, w):
    """b_0 = (32 R^2 w/(pi E*))^(1/3) is where the 2D JKR force per length vanishes,
    pi E* b^2/(4R) = sqrt(2 pi E* w b) (its two terms equal to 1e-14, round-off of a
    cube root), and 16^(1/3) times the pull-off half-width b_c (Barquins 1988)."""
    from linecontact.adhesion import (jkr_cylinder_pull_off,
                                      jkr_cylinder_zero_load_half_width)

    b0 = jkr_cylinder_zero_load_half_width(R, E, w)
    assert math.pi * E * b0 ** 2 / (4 * R) == pytest.approx(
        math.sqrt(2 * math.pi * E * w * b0), rel=1e-14)
    assert b0 == pytest.approx(16 ** (1 / 3) * jkr_cylinder_pull_off(R, E, w)[1],
                               rel=1e-14)
    assert jkr_cylinder_zero_load_half_width(R, E, 0.0) == 0.0
