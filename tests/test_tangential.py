"""Tangential contact (linecontact.tangential): exact oracles of the MDR's tangential laws.

Facts checked, each with its source:
- at nu = 0 the tangential problem is the normal one (G* = E*), so k_t = k_n and
  F_t(u) = mu [F(d) - F(d - u/mu)] for every model (Popov & Hess 2015, ch. 4);
- the Hertz sphere through the same generic code gives Mindlin's (1949) u(Q), k_t and
  stick radius, and the Mindlin-Deresiewicz (1953) energy per cycle (Johnson 1985,
  section 7.2, with the compliance (2-nu1)/G1 + (2-nu2)/G2 = 4/G*);
- a flat punch (F linear in d) has a linear tangential law up to gross slip and no
  dissipation below it (a linear Masing loop encloses no area);
- the Masing loop closes at (-u0, -F0) and its area is the energy formula;
- the BEM table loader reproduces its nodes, refuses points outside its grid, and
  applies an optional partial-slip correction as documented.
"""
import math

import numpy as np
import pytest

from linecontact.classical import effective_modulus
from linecontact.errors import OutOfRangeError, UnknownNameError
from linecontact.models import standard_models
from linecontact.tables import TableError, read_table, write_table
from linecontact.tangential import (CylinderTangentialTable, TangentialContact,
                                    cylinder_stiffness_ratios, effective_shear_modulus,
                                    equivalent_poisson, gross_slip_shift, shear_modulus,
                                    shear_ratio, tangential_force, tangential_shift,
                                    tangential_stiffness)

from oracle_laws import FlatPunch, HertzSphere  # tests/oracle_laws.py


E, NU, R = 210e9, 0.3, 5e-3
ESTAR = effective_modulus(E, NU)
GSTAR = effective_shear_modulus(E, NU)
G = shear_modulus(E, NU)
MU = 0.3


# ---- moduli ------------------------------------------------------------------------
def test_effective_shear_modulus_rigid_and_identical_bodies():
    """G* = 4G/(2-nu) with a rigid second body and 2G/(2-nu) for two identical bodies
    (the definition 1/G* = sum (2-nu_i)/(4G_i)); rounding only, rtol 1e-14."""
    assert GSTAR == pytest.approx(4 * G / (2 - NU), rel=1e-14, abs=0)
    assert effective_shear_modulus(E, NU, E, NU) == pytest.approx(2 * G / (2 - NU), rel=1e-14, abs=0)
    assert shear_ratio(E, NU) == pytest.approx(2 * (1 - NU) / (2 - NU), rel=1e-14, abs=0)
    assert shear_ratio(E, 0.0) == pytest.approx(1.0, rel=1e-15, abs=0)


def test_second_body_needs_its_poisson_ratio():
    """An elastic second body without its Poisson ratio is refused by G* and G*/E* as by
    E* (the rule of linecontact.classical.effective_modulus): no silent nu2 = 0, which
    would make G* of steel on aluminium (nu2 = 0.33) 8.1 % too high; a rigid one needs
    none."""
    for f in (effective_shear_modulus, shear_ratio):
        with pytest.raises(OutOfRangeError, match="poisson2"):
            f(E, NU, 70e9)
        assert f(E, NU, np.inf) == f(E, NU)
    with pytest.raises(OutOfRangeError, match="rigid"):
        effective_shear_modulus(np.inf, NU, np.inf, NU)


def test_equivalent_poisson_is_the_one_body_problem():
    """Two bodies act as one with 1/G = sum 1/G_i, 1-nu = sum((1-nu_i)/G_i)/sum(1/G_i)
    (the Boussinesq-Cerruti kernels add): its G*/E* equals the pair's, rtol 1e-13."""
    E1, n1, E2, n2 = 210e9, 0.3, 70e9, 0.33
    G1, G2 = shear_modulus(E1, n1), shear_modulus(E2, n2)
    nu = 1 - ((1 - n1) / G1 + (1 - n2) / G2) / (1 / G1 + 1 / G2)
    ratio = shear_ratio(E1, n1, E2, n2)
    assert equivalent_poisson(ratio, 1.0) == pytest.approx(nu, rel=1e-13, abs=0)
    with pytest.raises(OutOfRangeError, match="gstar/estar"):
        equivalent_poisson(0.5, 1.0)          # G*/E* = 0.5 needs nu > 0.5


# ---- nu = 0: the tangential problem is the normal one --------------------------------
@pytest.mark.parametrize("model", standard_models(5e-3, 25e-3, 115.38e9),
                         ids=lambda m: m.label)
def test_nu_zero_tangential_equals_normal_for_every_model(model):
    """At nu = 0, G* = E*: k_t = k_n and F_t = mu [F(d) - F(d - u/mu)] exactly, for any
    shape (Popov & Hess 2015). Same floating-point operations: rtol 1e-14."""
    try:
        model.check_applicable()
        d = np.array([0.3e-6, 1e-6, 3e-6])
        F = model.force(d)
    except OutOfRangeError:
        pytest.skip(f"{model.label} does not apply to this cylinder")
    gstar = effective_shear_modulus(model.estar, 0.0)   # rigid roller on a nu = 0 body
    assert gstar == pytest.approx(model.estar, rel=1e-15, abs=0)
    assert tangential_stiffness(model, d, gstar) == pytest.approx(model.stiffness(d),
                                                                  rel=1e-14, abs=0)
    u = np.array([0.1, 0.5, 0.99]) * MU * d
    expected = MU * (F - model.force(d - u / MU))
    assert tangential_force(model, d, u, MU, gstar) == pytest.approx(expected, rel=1e-12, abs=0)
    # gross slip at u* = mu d, where F_t = mu F
    assert tangential_force(model, d, MU * d, MU, gstar) == pytest.approx(MU * F, rel=1e-14, abs=0)


# ---- the Hertz sphere: Mindlin and Mindlin-Deresiewicz ---------------------------------
def _sphere(P=100.0):
    m = HertzSphere(R, R, ESTAR)
    return m, TangentialContact(m, MU, GSTAR, force=P)


def test_sphere_full_stick_stiffness_is_mindlins():
    """Mindlin (1949): k_t = 8 G a/(2 - nu) for a rigid sphere on (G, nu); the generic
    k_t = (G*/E*) k_n reproduces it to rounding (rtol 1e-13)."""
    m, c = _sphere()
    a = math.sqrt(R * c.depth)
    assert c.stiffness == pytest.approx(8 * G * a / (2 - NU), rel=1e-13, abs=0)


def test_sphere_shift_is_mindlins_law():
    """Mindlin (1949): u(Q) = 3 mu P (2-nu)/(16 G a) [1 - (1 - Q/(mu P))^(2/3)] and the
    stick radius c = a (1 - Q/(mu P))^(1/3); closed forms of the same law: rtol 1e-11."""
    m, c = _sphere(P=250.0)
    P = c.normal_force
    a = math.sqrt(R * c.depth)
    Q = np.array([1e-4, 0.1, 0.5, 0.9, 0.999, 1.0]) * MU * P
    u_mindlin = 3 * MU * P * (2 - NU) / (16 * G * a) * (1 - (1 - Q / (MU * P)) ** (2 / 3))
    assert c.shift(Q) == pytest.approx(u_mindlin, rel=1e-11, abs=0)
    assert c.force(u_mindlin) == pytest.approx(Q, rel=1e-10, abs=0)
    assert c.gross_slip_shift == pytest.approx(u_mindlin[-1], rel=1e-12, abs=0)
    assert c.stick_radius(u_mindlin[:-1]) == pytest.approx(
        a * (1 - Q[:-1] / (MU * P)) ** (1 / 3), rel=1e-10, abs=0)
    assert c.stick_radius(u_mindlin[-1]) == 0.0
    # odd in the shift
    assert c.force(-u_mindlin[2]) == pytest.approx(-Q[2], rel=1e-10, abs=0)


def test_vectorised_shift_is_mindlins_law_and_inverts_the_force():
    """tangential_shift (vectorised over depth and force) gives Mindlin's u(Q) for the
    sphere and inverts tangential_force for a cylinder model (rtol 1e-11)."""
    m = HertzSphere(R, R, ESTAR)
    d = np.array([[1e-6], [3e-6]])
    P = m.force(d)
    a = np.sqrt(R * d)
    Q = np.array([0.1, 0.6, 1.0]) * MU * P
    u = 3 * MU * P * (2 - NU) / (16 * G * a) * (1 - (1 - Q / (MU * P)) ** (2 / 3))
    assert tangential_shift(m, d, Q, MU, GSTAR) == pytest.approx(u, rel=1e-11, abs=0)
    cyl = standard_models(5e-3, 10e-3, ESTAR)[0]
    u = np.array([0.2, 0.7]) * gross_slip_shift(2e-6, MU, GSTAR, ESTAR)
    Ft = tangential_force(cyl, 2e-6, u, MU, GSTAR)
    assert tangential_shift(cyl, 2e-6, Ft, MU, GSTAR) == pytest.approx(u, rel=1e-11, abs=0)
    with pytest.raises(OutOfRangeError, match="gross slip"):
        tangential_shift(cyl, 2e-6, 1.01 * MU * cyl.force(2e-6), MU, GSTAR)


def _mindlin_deresiewicz(P, a, Qs):
    """Energy per cycle: 9 mu^2 P^2/(10 a) [(2-nu1)/G1 + (2-nu2)/G2]
    {1 - (1 - q)^(5/3) - (5 q/6)[1 + (1 - q)^(2/3)]}, q = Q*/(mu P) (Johnson 1985,
    section 7.2; the compliance sum is 4/G*). The braces are O(q^3) from O(1) terms:
    evaluated in extended precision (long double) to keep the oracle exact to ~1e-13
    at q = 0.01 (in double it would err by 2e-9 there)."""
    q = np.asarray(Qs, dtype=np.longdouble) / np.longdouble(MU * P)
    one = np.longdouble(1)
    braces = (one - (one - q) ** (one * 5 / 3)
              - 5 * q / 6 * (one + (one - q) ** (one * 2 / 3)))
    return (9 * MU ** 2 * P ** 2 / (10 * a) * (4 / GSTAR) * braces).astype(float)


def test_sphere_dissipation_is_mindlin_deresiewicz():
    """Masing energy W = 8 int f - 4 u0 f(u0) (by parts, 64-point Gauss-Legendre)
    against the Mindlin-Deresiewicz closed form from q = 0.01 (W ~ q^3: tests the
    cancellation) to gross slip (the quadrature's endpoint); measured <= 2e-13, asserted
    1e-11 relative."""
    m, c = _sphere(P=250.0)
    P, a = c.normal_force, math.sqrt(R * c.depth)
    Qs = np.array([0.01, 0.1, 0.5, 0.9, 0.999, 1.0]) * MU * P
    u0 = c.shift(Qs)
    W = c.dissipated_energy(u0)
    assert W == pytest.approx(_mindlin_deresiewicz(P, a, Qs), rel=1e-11, abs=0)


def test_masing_loop_closes_and_encloses_the_dissipated_energy():
    """The Masing branches meet at (+-u0, +-F0) (rtol 1e-12) and the trapezoidal area
    of a 4001-point loop (the cycle's work, integral of F_t du) equals W to the trapezoid rule's error (2e-6 relative)."""
    m, c = _sphere()
    u0 = 0.6 * c.gross_slip_shift
    F0 = c.force(u0)
    assert c.unloading(-u0, u0) == pytest.approx(-F0, rel=1e-12, abs=0)
    assert c.reloading(u0, u0) == pytest.approx(F0, rel=1e-12, abs=0)
    assert c.unloading(u0, u0) == pytest.approx(F0, rel=1e-12, abs=0)
    u, ft = c.loop(u0, n=2001)
    area = np.trapezoid(ft, u)   # work done on the contact over the cycle, closed loop
    assert area == pytest.approx(c.dissipated_energy(u0), rel=2e-6, abs=0)


# ---- flat punch: linear law ------------------------------------------------------------
def test_flat_punch_tangential_law_is_linear_up_to_gross_slip():
    """F linear in d: F_t = 2 G* a u up to u* = mu E* d/G*, no energy dissipated below
    gross slip; beyond it (saturate) the Coulomb rectangle 4 mu F (u0 - u*) (exact
    arithmetic of linear laws: rtol 1e-12, absolute 1e-12 mu F u* for W = 0)."""
    a = 2e-3
    m = FlatPunch(1.0, a, ESTAR)
    d = 1e-6
    c = TangentialContact(m, MU, GSTAR, depth=d)
    ustar = gross_slip_shift(d, MU, GSTAR, ESTAR)
    assert c.gross_slip_shift == pytest.approx(ustar, rel=1e-14, abs=0)
    u = np.linspace(0.0, 1.0, 11) * ustar
    assert c.force(u) == pytest.approx(2 * GSTAR * a * u, rel=1e-12, abs=0)
    assert c.stiffness == pytest.approx(2 * GSTAR * a, rel=1e-14, abs=0)
    scale = MU * c.normal_force * ustar
    assert abs(c.dissipated_energy(0.7 * ustar)) < 1e-12 * scale
    W = c.dissipated_energy(1.5 * ustar, beyond="saturate")
    assert W == pytest.approx(4 * MU * c.normal_force * 0.5 * ustar, rel=1e-10, abs=0)


# ---- gross slip policy, normal force input ---------------------------------------------
def test_beyond_gross_slip_is_refused_or_saturated_on_request():
    """Never silent: u > u* raises OutOfRangeError naming the shift; beyond='saturate'
    gives mu F; F_t > mu F has no static solution and is refused."""
    m, c = _sphere()
    with pytest.raises(OutOfRangeError, match="shift"):
        c.force(1.01 * c.gross_slip_shift)
    assert c.force(2 * c.gross_slip_shift, beyond="saturate") == pytest.approx(
        c.gross_slip_force, rel=1e-15, abs=0)
    with pytest.raises(OutOfRangeError, match="tangential_force"):
        c.shift(1.01 * c.gross_slip_force)
    with pytest.raises(OutOfRangeError, match="amplitude"):
        c.dissipated_energy(1.1 * c.gross_slip_shift)
    states = c.slip_state([0.0, 0.5 * c.gross_slip_shift, c.gross_slip_shift])
    assert list(states) == ["stick", "partial slip", "gross slip"]


def test_constant_force_is_constant_depth_at_d_of_F():
    """Uncoupled problems: at constant normal force the law is that at d = d(F) (same
    numbers: rtol 1e-13)."""
    m = standard_models(5e-3, 10e-3, ESTAR)[0]
    by_force = TangentialContact(m, MU, GSTAR, force=2e3)
    by_depth = TangentialContact(m, MU, GSTAR, depth=m.depth(2e3))
    u = np.array([0.1, 0.5, 0.9]) * by_depth.gross_slip_shift
    assert by_force.force(u) == pytest.approx(by_depth.force(u), rel=1e-13, abs=0)


# ---- BEM table loader --------------------------------------------------------------------
META = dict(title="test table", source="tests/test_tangential.py", units="[-]",
            generated_by="pytest", date="2026-01-01", version="0", accuracy="made up")


def _write(tmp_path, extra=None, nus=(0.0, 0.25, 0.5), dts=(1e-5, 1e-4, 1e-3, 1e-2)):
    nu, dt = np.meshgrid(nus, dts, indexing="ij")
    nu, dt = nu.ravel(), dt.ravel()
    mdr = 2 * (1 - nu) / (2 - nu)
    # a smooth made-up correction, exactly 1 at nu = 0
    across = mdr * (1 + 0.4 * nu * (1 - 0.1 * np.log10(dt)))
    along = mdr * (1 - 0.3 * nu)
    cols = dict(nu=nu, d_tilde=dt, kt_kn_across=across, kt_kn_along=along)
    if extra:
        cols.update({k: np.full(nu.shape, v) for k, v in extra.items()})
    write_table(tmp_path / "tc.csv", META, cols)
    return CylinderTangentialTable(read_table("tc", directory=tmp_path)), cols


def test_table_reproduces_its_nodes_and_refuses_outside(tmp_path):
    """Interpolation is exact at the grid nodes (rtol 1e-12); nu = 0 gives 1; a point
    outside the (nu, d~) grid raises OutOfRangeError naming it."""
    t, cols = _write(tmp_path)
    for i in range(len(cols["nu"])):
        assert t.ratio("across", cols["nu"][i], cols["d_tilde"][i]) == pytest.approx(
            cols["kt_kn_across"][i], rel=1e-12, abs=0)
        assert t.ratio("along", cols["nu"][i], cols["d_tilde"][i]) == pytest.approx(
            cols["kt_kn_along"][i], rel=1e-12, abs=0)
    assert t.ratio("across", 0.0, 3e-4) == pytest.approx(1.0, rel=1e-14, abs=0)
    with pytest.raises(OutOfRangeError, match="d_tilde"):
        t.ratio("across", 0.3, 2e-2)
    with pytest.raises(OutOfRangeError, match="nu"):
        t.ratio("along", 0.6, 1e-3)
    with pytest.raises(UnknownNameError, match="direction"):
        t.ratio("diagonal", 0.3, 1e-3)


def test_table_interpolation_between_nodes_is_well_inside_one_percent(tmp_path):
    """The issue's target is 1 % against the BEM; the interpolation's own share, on a
    study-like grid (nu step 0.1, 2 points per decade of d~), for factors shaped like
    the strip limits (2-nu)/(2(1-nu)) across and (2-nu)/2 along times a smooth
    function of ln d~, must be below 0.1 % at the cell centres."""
    nus = np.round(np.arange(0.0, 0.51, 0.1), 12)
    dts = 10.0 ** np.arange(-6.0, -0.49, 0.5)

    def factors(nu, dt):
        shape = 1 + 0.05 * np.tanh(np.log10(dt) + 3)
        across = 1 + ((2 - nu) / (2 * (1 - nu)) - 1) * shape
        along = 1 + ((2 - nu) / 2 - 1) * shape
        return across, along

    nu, dt = np.meshgrid(nus, dts, indexing="ij")
    nu, dt = nu.ravel(), dt.ravel()
    mdr = 2 * (1 - nu) / (2 - nu)
    fa, fl = factors(nu, dt)
    write_table(tmp_path / "smooth.csv", META, dict(nu=nu, d_tilde=dt, kt_kn_across=mdr * fa,
                                                  kt_kn_along=mdr * fl))
    t = CylinderTangentialTable(read_table("smooth", directory=tmp_path))
    mid_nu = 0.5 * (nus[1:] + nus[:-1])
    mid_dt = np.sqrt(dts[1:] * dts[:-1])
    mn, md = np.meshgrid(mid_nu, mid_dt, indexing="ij")
    fa, fl = factors(mn, md)
    mdr = 2 * (1 - mn) / (2 - mn)
    # measured: 2.9e-4 across (the 1/(1-nu) growth near 0.5), less along
    assert np.max(np.abs(t.ratio("across", mn, md) / (mdr * fa) - 1)) < 1e-3
    assert np.max(np.abs(t.ratio("along", mn, md) / (mdr * fl) - 1)) < 1e-3


def test_table_must_be_a_full_grid(tmp_path):
    """A ragged (nu, d~) set or a missing column is refused (TableError)."""
    cols = dict(nu=[0, 0, 0.5], d_tilde=[1e-4, 1e-3, 1e-4], kt_kn_across=[1, 1, 1],
                kt_kn_along=[1, 1, 1])
    write_table(tmp_path / "bad.csv", META, cols)
    with pytest.raises(TableError, match="regular grid"):
        CylinderTangentialTable(read_table("bad", directory=tmp_path))
    write_table(tmp_path / "bad2.csv", META, dict(nu=[0, 0.5], d_tilde=[1e-4, 1e-4]))
    with pytest.raises(TableError, match="kt_kn_across"):
        CylinderTangentialTable(read_table("bad2", directory=tmp_path))


def test_bem_method_uses_the_table_ratio_and_reports_the_mdr_error(tmp_path):
    """method='bem': k_t = (table ratio) k_n in each direction, the law reaches mu F at
    u* = mu d / ratio, and the MDR's error is MDR/BEM - 1 (rtol 1e-12)."""
    t, _ = _write(tmp_path)
    m = standard_models(5e-3, 10e-3, ESTAR)[0]      # straight cylinder, d~ = d R/L^2
    d = 2e-6
    r = cylinder_stiffness_ratios(m, d, GSTAR, table=t)
    assert r["d_tilde"] == pytest.approx(d * 5e-3 / 10e-3 ** 2, rel=1e-14, abs=0)
    assert r["nu"] == pytest.approx(NU, rel=1e-12, abs=0)
    for direction in ("across", "along"):
        c = TangentialContact(m, MU, GSTAR, depth=d, method="bem", direction=direction,
                              table=t)
        assert c.stiffness == pytest.approx(r[direction] * m.stiffness(d), rel=1e-12, abs=0)
        assert c.force(c.gross_slip_shift) == pytest.approx(MU * m.force(d), rel=1e-12, abs=0)
        assert r[f"mdr_error_{direction}"] == pytest.approx(
            shear_ratio(E, NU) / r[direction] - 1, rel=1e-12, abs=0)
    with pytest.raises(OutOfRangeError, match="model"):
        cylinder_stiffness_ratios(HertzSphere(R, R, ESTAR), d, GSTAR, table=t)
    assert "slip_error_across" not in r


def test_measured_slip_error_is_reported_when_the_table_has_it(tmp_path):
    """Columns ft_err_scaled_{across,along} (the study's measured partial-slip error)
    come back interpolated; a constant column is reproduced exactly (rtol 1e-12)."""
    t, _ = _write(tmp_path, {"ft_err_scaled_across": 0.012, "ft_err_scaled_along": 0.007})
    m = standard_models(5e-3, 10e-3, ESTAR)[0]
    r = cylinder_stiffness_ratios(m, 2e-6, GSTAR, table=t)
    assert r["slip_error_across"] == pytest.approx(0.012, rel=1e-12, abs=0)
    assert r["slip_error_along"] == pytest.approx(0.007, rel=1e-12, abs=0)
    with pytest.raises(UnknownNameError, match="column"):
        t.value("no_such_column", 0.3, 1e-4)


def test_optional_slip_correction_scales_the_shift(tmp_path):
    """Columns shift_ratio_{dir}_q{Q}: the shift at load fraction Q is the
    stiffness-corrected law's times the factor, linear in Q between nodes from 1 at 0;
    force(shift(F_t)) returns F_t (bisection to 2^-60: rtol 1e-12)."""
    extra = {"shift_ratio_across_q0.5": 1.1, "shift_ratio_across_q1": 1.2,
             "shift_ratio_along_q0.5": 0.9, "shift_ratio_along_q1": 0.95}
    t, _ = _write(tmp_path, extra)
    assert t.has_slip_correction
    m = standard_models(5e-3, 10e-3, ESTAR)[0]
    bem = TangentialContact(m, MU, GSTAR, force=1e3, method="bem", table=t)
    plain = TangentialContact(m, MU, GSTAR, force=1e3, method="bem", table=t,
                              slip_correction=False)
    Ft = np.array([0.25, 0.5, 1.0]) * bem.gross_slip_force
    assert bem.shift(Ft) == pytest.approx(plain.shift(Ft) * [1.05, 1.1, 1.2], rel=1e-12, abs=0)
    assert bem.force(bem.shift(Ft)) == pytest.approx(Ft, rel=1e-12, abs=0)
    # the vectorised factor is the same piecewise-linear interpolation in Q
    q = np.array([0.0, 0.2, 0.5, 0.8, 1.0])
    assert t.shift_factor("across", 0.3, 1e-3, q) == pytest.approx(
        np.interp(q, *t.shift_correction("across", 0.3, 1e-3)), rel=1e-14, abs=0)
    assert bem.gross_slip_shift == pytest.approx(1.2 * plain.gross_slip_shift, rel=1e-12, abs=0)
    # the Masing energy of the corrected law, by direct quadrature, against the
    # trapezoidal area of its loop (2001 points per branch: 1e-5 relative)
    u0 = 0.5 * bem.gross_slip_shift
    u, ft = bem.loop(u0, n=2001)
    assert np.trapezoid(ft, u) == pytest.approx(bem.dissipated_energy(u0), rel=1e-5, abs=0)


def test_shipped_table_at_nu_zero_is_the_normal_problem():
    """If the BEM study's table is installed: at nu = 0 the BEM's tangential kernel is
    the normal one, so k_t/k_n = 1 in both directions (to the table's stated solver
    tolerance, taken as 1e-3)."""
    try:
        t = CylinderTangentialTable(read_table("tangential_cylinder"))
    except FileNotFoundError:
        pytest.skip("tables/tangential_cylinder.csv not generated yet")
    if t.nus[0] != 0.0:
        pytest.skip("the table has no nu = 0 row")
    for dt in t.d_tildes:
        assert t.ratio("across", 0.0, dt) == pytest.approx(1.0, abs=1e-3)
        assert t.ratio("along", 0.0, dt) == pytest.approx(1.0, abs=1e-3)


def test_shipped_table_meets_the_one_percent_target_between_its_nodes():
    """Issue 10's target: the runtime's full-stick k_t/k_n within 1 % of the BEM. An
    independent BEM solve (tools.bem.tangential, the study's N grid) at points between
    the table's nodes in both nu and d~: measured worst 1.0e-4; asserted 3e-3 = the
    table's N-to-2N grid change (1e-3) plus interpolation, with margin."""
    try:
        t = CylinderTangentialTable(read_table("tangential_cylinder"))
    except FileNotFoundError:
        pytest.skip("tables/tangential_cylinder.csv not generated yet")
    from tools.bem.tangential import cylinder_full_stick

    nus = (0.2, 0.35, 0.45)
    for dt in (5.5e-6, 0.56):
        r = cylinder_full_stick(dt, nus=nus, n_length=256, n_width=32)
        for i, nu in enumerate(nus):
            assert t.ratio("across", nu, dt) == pytest.approx(r.ratio_across[i], rel=3e-3,
                                                              abs=0)
            assert t.ratio("along", nu, dt) == pytest.approx(r.ratio_along[i], rel=3e-3,
                                                             abs=0)


def test_corrected_law_reproduces_the_bem_fretting_energy():
    """With the shipped table's slip correction, the runtime's Masing energy at
    u0 = half the stiffness-scaled law's gross-slip shift relative to that law's equals
    the study's W_BEM/W_scaled (the uncorrected law is off by 4-7 % there); measured
    within 0.5 %, asserted 1 % (the study's partial-slip grid differs from the table's
    full-stick grid by up to 1e-3 in k_t, and its W is a quadrature of 24 steps)."""
    try:
        t = CylinderTangentialTable(read_table("tangential_cylinder"))
    except FileNotFoundError:
        pytest.skip("tables/tangential_cylinder.csv not generated yet")
    m = standard_models(5e-3, 10e-3, ESTAR)[0]
    for dt in (1.08e-8, 1.2e-5, 1.34e-2):
        d = dt * 10e-3 ** 2 / 5e-3
        for side in ("across", "along"):
            corr = TangentialContact(m, MU, GSTAR, depth=d, method="bem", direction=side,
                                     table=t)
            plain = TangentialContact(m, MU, GSTAR, depth=d, method="bem", direction=side,
                                      table=t, slip_correction=False)
            u0 = 0.5 * plain.gross_slip_shift
            ratio = corr.dissipated_energy(u0) / plain.dissipated_energy(u0)
            assert ratio == pytest.approx(t.value(f"w_ratio_scaled_{side}", NU, dt),
                                          rel=1e-2, abs=0), (dt, side)
