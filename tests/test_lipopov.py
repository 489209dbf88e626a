"""Li-Popov model (Li & Popov 2017, Eqs. 7, 9, 11, 12): closed forms, coefficient sets.

Each test states the fact it checks in its docstring and assertion message.
"""
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.interpolate import CubicSpline
from scipy.special import lambertw

from linecontact._numerics import NotAKnotSpline, lambertw_m1, log1p_excess_root

from linecontact.errors import OutOfRangeError
from linecontact.lipopov import (ALPHA_EQ11, BETA_EQ11, available_coefficient_sets,
                                 coefficient_set, dimensionless_profile,
                                 lipopov_coefficients, lipopov_contact_radius,
                                 lipopov_depth, lipopov_depth_limit, lipopov_force,
                                 lipopov_force_limit, lipopov_profile, lipopov_stiffness,
                                 lipopov_stiffness_at_force)
from linecontact.tables import read_table

STEEL_ESTAR = 210e9 / (2 * (1 - 0.3**2))

# Li & Popov 2017, Table 1, as printed in the paper, typed here independently of
# tables/lipopov_published.csv: a literature fixture.
TABLE_1 = [
    (0.1, 3.8695, 17.1183), (0.2, 2.8664, 6.6132), (0.3, 2.4734, 3.9560),
    (0.4, 2.2714, 2.8770), (0.5, 2.1455, 2.2975), (0.6, 2.0528, 1.9139),
    (0.7, 1.9928, 1.6847), (0.8, 1.9400, 1.4963), (0.9, 1.8996, 1.3589),
    (1.0, 1.8668, 1.2517), (2, 1.7086, 0.7936), (3, 1.6518, 0.6495),
    (4, 1.6231, 0.5799), (5, 1.6048, 0.5376), (6, 1.5930, 0.5091),
]

alphas = st.floats(0.5, 5.0)
betas = st.floats(0.1, 20.0)
ratios = st.floats(1e-10, 1 - 1e-6)          # d / (beta L^2/R)
lengths = st.floats(1e-4, 1.0)
radii = st.floats(1e-4, 1.0)


def _geom(R, L, a, b, E=STEEL_ESTAR):
    return dict(radius=R, length=L, estar=E, alpha=a, beta=b)


# ---- closed forms derived from Eq. 7 -------------------------------------------------
@given(u=st.floats(0.01, 50.0), a=alphas, b=betas)
def test_force_closed_form_is_the_mdr_integral_of_eq7(u, a, b):
    """F = 2 alpha beta E* L^3/R exp(-u) equals 2E* int_0^a (d - g) dx with g of Eq. 7,
    a = alpha L / u and d = g(a) (Li & Popov (2017), Eq. 7 integrated by the MDR rules,
    docs/theory.md, section 'MDR'; derived in linecontact/lipopov.py, checked here by
    quadrature)."""
    R, L, E = 5e-3, 10e-3, STEEL_ESTAR
    a_c = a * L / u
    g = lambda x: lipopov_profile(x, R, L, alpha=a, beta=b)
    d = g(a_c)
    assert d == pytest.approx(b * L**2 / R * (u + 1) * math.exp(-u), rel=1e-12), \
        "d = g(a) = beta L^2/R (u+1) exp(-u)"
    integral, _ = quad(lambda x: d - g(x), 0, a_c, epsabs=0, epsrel=1e-12, limit=200)
    F_quad = 2 * E * integral
    F_closed = 2 * a * b * E * L**3 / R * math.exp(-u)
    assert F_quad == pytest.approx(F_closed, rel=1e-8), \
        "MDR quadrature of Eq. 7 must equal the closed form F = 2 alpha beta E* L^3/R e^-u"
    if d < b * L**2 / R:
        assert lipopov_force(d, R, L, E, alpha=a, beta=b) == pytest.approx(F_closed, rel=1e-9)


@given(D=ratios, a=alphas, b=betas, R=radii, L=lengths)
def test_depth_of_force_inverts_force_of_depth(D, a, b, R, L):
    """Round trip: d(F(d)) = d over 10 decades of d / (beta L^2/R) (Lambert W_-1 branch)."""
    d = D * b * L**2 / R
    F = lipopov_force(d, **_geom(R, L, a, b))
    assert lipopov_depth(F, **_geom(R, L, a, b)) == pytest.approx(d, rel=1e-9), \
        "lipopov_depth must invert lipopov_force"


@given(D=st.floats(1e-9, 0.99), a=alphas, b=betas)
def test_stiffness_is_the_derivative_of_force(D, a, b):
    """k(d) = dF/dd: the closed form 2 E* a equals a central difference of F(d)."""
    R, L = 5e-3, 10e-3
    g = _geom(R, L, a, b)
    d = D * b * L**2 / R
    h = 1e-6 * d
    numeric = (lipopov_force(d + h, **g) - lipopov_force(d - h, **g)) / (2 * h)
    assert lipopov_stiffness(d, **g) == pytest.approx(numeric, rel=1e-6), \
        "stiffness must equal the numerical derivative of force"


@given(D=st.floats(1e-9, 0.99), a=alphas, b=betas)
def test_stiffness_at_force_and_contact_radius_agree(D, a, b):
    """k(F(d)) = k(d) and k = 2 E* a(d) with g(a) = d (MDR rules)."""
    R, L, E = 5e-3, 10e-3, STEEL_ESTAR
    g = _geom(R, L, a, b)
    d = D * b * L**2 / R
    k = lipopov_stiffness(d, **g)
    assert lipopov_stiffness_at_force(lipopov_force(d, **g), **g) == pytest.approx(k, rel=1e-9)
    radius = lipopov_contact_radius(d, R, L, alpha=a, beta=b)
    assert 2 * E * radius == pytest.approx(k, rel=1e-12), "k = 2 E* a"
    assert lipopov_profile(radius, R, L, alpha=a, beta=b) == pytest.approx(d, rel=1e-9), \
        "the MDR contact radius solves g(a) = d"


def test_eq2_is_the_lipopov_form_with_alpha_pi_over_2_and_beta_1():
    """Eliminating a: d = F/(2 alpha L E*) (1 + ln(2 alpha beta E* L^3/(R F))); with
    alpha = pi/2, beta = 1 this is Puttock & Thwaite's Eq. 2, typed here independently."""
    R, L, E = 5e-3, 10e-3, STEEL_ESTAR
    F = np.geomspace(1e-3, 1e6, 25)
    eq2 = F / (math.pi * L * E) * (1 + np.log(math.pi * E * L**3 / (R * F)))
    d = lipopov_depth(F, R, L, E, alpha=math.pi / 2, beta=1.0)
    np.testing.assert_allclose(d, eq2, rtol=1e-13,
                               err_msg="Eq. 2 = Li-Popov with alpha = pi/2, beta = 1")


def test_sanity_figure_eq11_steel_roller():
    """Issue sanity figure: steel on steel, R = 5 mm, L = 10 mm, 1 kN, Eq. 11 constants:
    d is about 3.15 um (the formula; the model refuses Eq. 11 at L/R = 2 unless asked)."""
    d = lipopov_depth(1e3, 5e-3, 10e-3, STEEL_ESTAR, alpha=ALPHA_EQ11, beta=BETA_EQ11)
    assert d == pytest.approx(3.15e-6, abs=0.005e-6)


def test_profile_is_monotone_bounded_and_dimensionless_form_matches():
    """Eq. 7 rises from g(0) = 0 to below beta L^2/R; g R/L^2 equals Eq. 9 at x/L."""
    R, L, a, b = 5e-3, 10e-3, 1.7, 0.8
    x = np.concatenate([[0.0], np.geomspace(1e-6 * L, 1e4 * L, 400)])
    g = lipopov_profile(x, R, L, alpha=a, beta=b)
    assert g[0] == 0.0, "g(0) = 0"
    assert np.all(np.diff(g) >= 0) and np.all(np.diff(g[g > 0]) > 0), "g increases"
    assert np.all(g < lipopov_depth_limit(R, L, b)), "g < beta L^2/R"
    np.testing.assert_allclose(g * R / L**2, dimensionless_profile(x / L, a, b), rtol=1e-14,
                               atol=1e-300)


def test_force_and_stiffness_increase_with_depth():
    """Monotonicity: F(d) and k(d) increase strictly over the whole admissible range."""
    R, L, a, b = 5e-3, 10e-3, ALPHA_EQ11, BETA_EQ11
    d = np.geomspace(1e-12, 0.999, 300) * b * L**2 / R
    F = lipopov_force(d, R, L, STEEL_ESTAR, alpha=a, beta=b)
    k = lipopov_stiffness(d, R, L, STEEL_ESTAR, alpha=a, beta=b)
    assert np.all(np.diff(F) > 0), "F increases with d"
    assert np.all(np.diff(k) > 0), "k increases with d (F convex)"
    assert F[-1] < lipopov_force_limit(R, L, STEEL_ESTAR, alpha=a, beta=b), "F < F_max"


@given(lam=st.floats(1e-3, 1e3), D=st.floats(1e-8, 0.9))
def test_scaling_law(lam, D):
    """Self-similarity: F(lambda R, lambda L, lambda d) = lambda^2 F(R, L, d) at fixed E*."""
    R, L, E, a, b = 5e-3, 10e-3, STEEL_ESTAR, 1.7, 0.8
    d = D * b * L**2 / R
    F1 = lipopov_force(d, R, L, E, alpha=a, beta=b)
    F2 = lipopov_force(lam * d, lam * R, lam * L, E, alpha=a, beta=b)
    assert F2 == pytest.approx(lam**2 * F1, rel=1e-9)


# ---- validity --------------------------------------------------------------------------
def test_depth_at_or_beyond_the_bound_raises():
    """g < beta L^2/R, so d >= beta L^2/R has no solution: OutOfRangeError naming depth."""
    R, L, a, b = 5e-3, 10e-3, ALPHA_EQ11, BETA_EQ11
    bound = b * L**2 / R
    for d in (bound, 1.5 * bound):
        with pytest.raises(OutOfRangeError) as err:
            lipopov_force(d, R, L, STEEL_ESTAR, alpha=a, beta=b)
        assert err.value.parameter == "depth" and err.value.value == d
        assert f"{bound:.6g}" in err.value.valid and "beta L^2/R" in str(err.value)
    with pytest.raises(OutOfRangeError, match="force"):
        lipopov_depth(lipopov_force_limit(R, L, STEEL_ESTAR, alpha=a, beta=b), R, L,
                      STEEL_ESTAR, alpha=a, beta=b)


@pytest.mark.parametrize("name, value", [("depth", 0.0), ("depth", -1e-6),
                                         ("depth", np.nan), ("radius", -5e-3),
                                         ("length", np.inf), ("estar", 0.0)])
def test_bad_inputs_raise_naming_the_parameter(name, value):
    """Non-positive or non-finite sizes, moduli, depths raise OutOfRangeError (a
    ValueError) whose message names the parameter, its value and the valid range."""
    args = dict(depth=1e-6, radius=5e-3, length=10e-3, estar=STEEL_ESTAR)
    args[name] = value
    with pytest.raises(ValueError) as err:
        lipopov_force(args["depth"], args["radius"], args["length"], args["estar"],
                      alpha=1.6, beta=0.5)
    assert isinstance(err.value, OutOfRangeError)
    assert str(err.value).startswith(f"{name} = ") and "valid range" in str(err.value)


def test_array_input_reports_the_offending_element():
    """An array with one bad element raises, naming that element (nothing is skipped)."""
    with pytest.raises(OutOfRangeError, match=r"element \[2\]"):
        lipopov_force([1e-6, 2e-6, -1.0], 5e-3, 10e-3, STEEL_ESTAR, alpha=1.6, beta=0.5)


def test_vectorised_broadcast():
    """Arrays broadcast: a depth vector against a radius column gives a 2D result."""
    d = np.array([1e-6, 2e-6, 3e-6])
    R = np.array([[4e-3], [5e-3]])
    F = lipopov_force(d, R, 10e-3, STEEL_ESTAR, alpha=1.6, beta=0.5)
    assert F.shape == (2, 3)
    assert F[1, 2] == lipopov_force(3e-6, 5e-3, 10e-3, STEEL_ESTAR, alpha=1.6, beta=0.5)


# ---- coefficient sets --------------------------------------------------------------------
def test_published_spline_reproduces_table1_at_its_knots():
    """The 'published' set passes through every row of Li & Popov Table 1 (literature
    values typed independently here)."""
    q, a, b = map(np.array, zip(*TABLE_1))
    alpha, beta = lipopov_coefficients(q, "published")
    np.testing.assert_allclose(alpha, a, rtol=1e-12, err_msg="alpha at Table 1 knots")
    np.testing.assert_allclose(beta, b, rtol=1e-12, err_msg="beta at Table 1 knots")


def test_shipped_table_equals_table1_and_runtime_spline_is_refit_from_it():
    """Data and code cannot drift: the CSV holds Table 1 exactly, and a spline refit from
    the CSV (CubicSpline in log L/R) equals the runtime one between the knots."""
    t = read_table("lipopov_published")
    np.testing.assert_array_equal(
        np.column_stack([t.columns["L_over_R"], t.columns["alpha"], t.columns["beta"]]),
        np.array(TABLE_1))
    lq = np.log(t.columns["L_over_R"])
    q = np.geomspace(0.1, 6, 500)
    alpha, beta = lipopov_coefficients(q, "published")
    np.testing.assert_allclose(alpha, CubicSpline(lq, t.columns["alpha"])(np.log(q)), rtol=1e-13)
    np.testing.assert_allclose(beta, CubicSpline(lq, t.columns["beta"])(np.log(q)), rtol=1e-13)


def test_published_spline_is_smooth_monotone_and_positive():
    """Between the knots the spline neither overshoots nor turns: alpha and beta fall
    monotonically with L/R on [0.1, 6] and stay within the table's extremes."""
    q = np.geomspace(0.1, 6, 5000)
    alpha, beta = lipopov_coefficients(q, "published")
    assert np.all(np.diff(alpha) < 0) and np.all(np.diff(beta) < 0)
    assert alpha.min() >= 1.5930 - 1e-12 and beta.min() >= 0.5091 - 1e-12


@pytest.mark.parametrize("q", [0.05, 0.0999, 6.001, 20.0])
def test_published_refuses_L_over_R_outside_0p1_to_6(q):
    """L/R outside Table 1's range [0.1, 6] raises (no silent extrapolation)."""
    with pytest.raises(OutOfRangeError) as err:
        lipopov_coefficients(q, "published")
    assert err.value.parameter == "L/R" and err.value.valid == "[0.1, 6]"
    assert "eq11" in str(err.value), "the message points to the other sets"


def test_eq11_constants_and_range():
    """Eq. 11/12: alpha = pi/2, beta = 0.4573 (not the text's 0.4537), for L/R >= 5."""
    assert lipopov_coefficients(50.0, "eq11") == (math.pi / 2, 0.4573)
    with pytest.raises(OutOfRangeError, match=r"L/R = 4.9 is outside the valid range \[5, inf\)"):
        lipopov_coefficients(4.9, "eq11")
    assert lipopov_coefficients(2.0, "eq11", extrapolate=True) == (math.pi / 2, 0.4573), \
        "extrapolation only on explicit request"


def test_table1_and_eq11_disagree_at_L_over_R_5_and_6():
    """Regression figures (pinned, documented in lipopov and tables/README.md): Table 1
    and Eq. 11 differ at L/R = 5; for R = 5 mm, L = 25 mm, steel, the Table 1 depth is
    0.9 % smaller at 1 kN and 0.6 % smaller at 10 kN than the Eq. 11 depth."""
    for q in (5.0, 6.0):
        pub = lipopov_coefficients(q, "published")
        eq11 = lipopov_coefficients(q, "eq11")
        assert pub[1] > eq11[1] * 1.1, "beta: Table 1 > Eq. 11 by more than 10 %"
    a, b = lipopov_coefficients(5.0, "published")
    for F, rel in ((1e3, -0.0085), (1e4, -0.0061)):
        dp = lipopov_depth(F, 5e-3, 25e-3, STEEL_ESTAR, alpha=a, beta=b)
        de = lipopov_depth(F, 5e-3, 25e-3, STEEL_ESTAR, alpha=ALPHA_EQ11, beta=BETA_EQ11)
        assert dp / de - 1 == pytest.approx(rel, abs=0.0002)


def test_unknown_coefficient_set_lists_the_valid_ones():
    """An unknown set name raises UnknownNameError listing 'eq11' and 'published'."""
    from linecontact.errors import UnknownNameError

    with pytest.raises(UnknownNameError) as err:
        coefficient_set("tabel1")
    assert err.value.parameter == "coefficients"
    assert "eq11" in err.value.valid and "'published'" in str(err.value)
    assert available_coefficient_sets()[:2] == ["eq11", "published"]


def test_published_set_provenance():
    """The published set says where it comes from: 'published, Li & Popov 2017, Table 1'."""
    prov = coefficient_set("published").provenance
    assert prov["provenance"] == "published, Li & Popov 2017, Table 1"
    assert "doi:10.22190/FUME170222003L" in prov["source"]


def test_L_over_R_at_a_range_end_survives_rounding():
    """L/R computed with rounding just outside a closed end (within 1e-12 relative) counts
    as the end: (1.902 * 25 mm)/(1.902 * 5 mm) < 5 still gets the Eq. 11 constants;
    1e-9 outside is refused."""
    q = (1.902029412465036 * 25e-3) / (1.902029412465036 * 5e-3)
    assert q < 5.0
    assert lipopov_coefficients(q, "eq11") == (math.pi / 2, 0.4573)
    assert lipopov_coefficients(6.0 * (1 + 1e-13), "published")[1] == pytest.approx(0.5091)
    with pytest.raises(OutOfRangeError):
        lipopov_coefficients(5.0 * (1 - 1e-9), "eq11")


# ---- the numpy spline and W_-1 that replace scipy at run time -----------------------------
@pytest.mark.parametrize("n", [2, 3, 4, 5, 15, 123])
def test_numpy_spline_is_scipys_not_a_knot_spline(n):
    """NotAKnotSpline is scipy's CubicSpline (default not-a-knot ends, also its 2- and
    3-point special cases): coefficients and values, first and second derivatives agree
    to 1e-12 of the largest magnitude on random, unevenly spaced knots, inside the knots
    and on the continued end polynomials. The tolerance is the conditioning of the slope
    system (knot spacings down to ~1e-3 of the span) times rounding, with a margin."""
    rng = np.random.default_rng(n)
    x = np.sort(rng.uniform(-3.0, 3.0, n))
    y = rng.normal(size=n)
    ref, got = CubicSpline(x, y), NotAKnotSpline(x, y)
    np.testing.assert_allclose(got.c, ref.c, rtol=0, atol=1e-12 * np.abs(ref.c).max())
    xq = np.linspace(x[0] - 0.5, x[-1] + 0.5, 3001)
    for nu in (0, 1, 2):
        r = ref(xq, nu)
        np.testing.assert_allclose(got(xq, nu), r, rtol=0, atol=1e-12 * np.abs(r).max(),
                                   err_msg=f"derivative order {nu}")


def test_numpy_lambert_w_minus_1_agrees_with_scipy():
    """lambertw_m1 equals scipy.special.lambertw(x, k=-1) to 1e-12 relative over
    x = -D/e, D from 1e-300 to 1 - 1e-6. Nearer the branch point x = -1/e no
    implementation can agree to 1e-12: the rounding of x alone moves W by eps/|1 + W|
    relative (dW/dx = W / (x (1 + W))), 1.6e-12 at D = 1 - 1e-8; at 1 - 1e-6 it is
    1.6e-13. The next test covers that end in a well-conditioned variable."""
    D = np.concatenate([np.geomspace(1e-300, 0.5, 3000), 1 - np.geomspace(0.5, 1e-6, 3000)])
    x = -D / np.e
    np.testing.assert_allclose(lambertw_m1(x), lambertw(x, k=-1).real, rtol=1e-12)


def test_numpy_lambert_w_solves_its_equation_to_rounding_near_the_branch_point():
    """Where D = (u+1) e^-u -> 1 the root u of u - ln(1+u) = -ln D is found to rounding:
    the residual is below 1e-14 relative to t, from t = 1e-30 to 700 (D from 1e-304 to
    1 - 1e-30), and t = 0 gives u = 0 (D = 1: the depth bound). 1e-14: the residual is
    itself evaluated with the series below u = 0.3 and as u - log1p(u) above, which
    loses up to ~15 ulp to cancellation at u = 0.3 (t = 0.038)."""
    from linecontact._numerics import _excess
    t = np.concatenate([np.geomspace(1e-30, 700, 4000), [0.0]])
    u = log1p_excess_root(t)
    np.testing.assert_allclose(_excess(u[:-1]), t[:-1], rtol=1e-14)
    assert u[-1] == 0.0 and np.all(u[:-1] > 0)
    one_by_one = np.array([float(log1p_excess_root(x)) for x in t[::40]])
    np.testing.assert_allclose(one_by_one, u[::40], rtol=2e-15,
                               err_msg="the scalar path is the array path (to rounding)")
    with pytest.raises(ValueError):
        lambertw_m1(0.1)


def test_blockwise_halley_root_equals_the_newton_reference():
    """The array root (two Halley steps per block from the series or fixed-point start)
    equals the reference Newton iteration run to convergence in Python floats to 2e-15
    relative (a few ulp: both are at rounding) over the whole valid range t = 0 to
    1.7e308, including both ends, the start switches at t = 0.04 and 2 and their
    neighbours, and across block boundaries (a mixed array longer than one block)."""
    from linecontact._numerics import BLOCK, _root_scalar
    edges = np.array([0.04, 2.0])
    t = np.concatenate([[0.0, 5e-324, 1e-300], np.geomspace(1e-300, 1.7e308, 3 * BLOCK),
                        edges, np.nextafter(edges, 0), np.nextafter(edges, 3),
                        [1.7e308]])
    u = log1p_excess_root(t)
    ref = np.array([_root_scalar(float(x)) for x in t])
    assert u[0] == 0.0
    np.testing.assert_allclose(u[1:], ref[1:], rtol=2e-15)


def test_force_of_one_cylinder_is_exact_to_its_conditioning():
    """lipopov_force for one cylinder (the fused blockwise path of the models' F(d),
    issue 20) and for an array of radii (the general path) against the closed form
    evaluated in extended precision (np.longdouble, eps 1.1e-19, Newton to convergence)
    from the same float64 depths: the relative error stays within 4 eps times the
    problem's condition number max(1, t) + (1 + u)/u (the rounding of t = -ln D moves u
    by eps max(1, t), the rounding of D by eps (1 + u)/u; measured 1.24 and 1.07), over
    D = d R/(beta L^2) from 1e-300 to 1 - 1e-12."""
    ld = np.longdouble
    if np.finfo(ld).eps > 1e-18:
        pytest.skip("no extended precision on this platform")
    R, L, E, a, b = 5e-3, 10e-3, 115.38e9, 1.7086, 0.7936
    D = np.concatenate([np.geomspace(1e-300, 1e-3, 20000),
                        1 - np.geomspace(1e-12, 1 - 1e-3, 20000)])
    d = D * b * L**2 / R
    Dl = d.astype(ld) * ld(R) / (ld(b) * ld(L) ** 2)
    t = -np.log(Dl)
    u = np.where(t < 1, np.sqrt(2 * t), t + np.log1p(t + np.log1p(t)))
    for _ in range(60):
        u = u - (u - np.log1p(u) - t) * (1 + u) / u
    exact = 2 * ld(a) * ld(b) * ld(E) * ld(L) ** 3 / ld(R) * np.exp(-u)
    cond = np.maximum(1.0, t.astype(float)) + (1 + u.astype(float)) / u.astype(float)
    eps = np.finfo(float).eps
    for radius in (R, np.full(d.shape, R)):
        F = lipopov_force(d, radius, L, E, alpha=a, beta=b)
        err = np.abs(F.astype(ld) / exact - 1).astype(float)
        assert np.all(err <= 4 * eps * cond), float(np.max(err / (eps * cond)))


def test_an_unchecked_root_outside_its_range_is_nan_not_leftover_memory():
    """log1p_excess_root(checked=False) trusts its caller's range; a t outside it (< 0,
    NaN: no root) must still come out NaN, never whatever the result's memory held,
    while the values in range keep their roots (u(1) = 2.1461932206205825...)."""
    for _ in range(20):           # fresh allocations, reusing freed blocks of values
        np.full(8, 123.0).sum()
        u = log1p_excess_root(np.array([-0.5, np.nan, -1e-300, 1.0, 0.0]), checked=False)
        assert np.all(np.isnan(u[:3])), u
        assert u[3] == pytest.approx(2.1461932206205825, rel=1e-15) and u[4] == 0.0
