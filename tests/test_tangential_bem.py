"""Verification of the tangential boundary-element solver (tools.bem.influence's Cerruti
coefficients, tools.bem.tangential) against exact answers: quadrature of Cerruti's
kernel, the nu = 0 identity with the normal problem (any shape), the bonded circular
punch and the Hertz sphere (Mindlin 1949; Mindlin & Deresiewicz 1953), the Masing rule,
grid convergence and self-similarity for the finite cylinder. Each test states the
fact and why its tolerance is what it is; grids are small (seconds in all)."""
import doctest
import warnings

import numpy as np
import pytest
from scipy.integrate import dblquad

from linecontact.tangential import mdr_stiffness_ratio
import tools.bem.influence
import tools.bem.tangential
from tools.bem.cylinder import sweep
from tools.bem.halfspace import DCFFTOperator, SymmetricOperator, unfold
from tools.bem.influence import cerruti_rectangle, rectangle_displacement, shear_integrals
from tools.bem.solver import solve_contact, solve_punch
from tools.bem.tangential import (cylinder_full_stick, cylinder_partial_slip,
                                  normal_force_on_grid,
                                  full_stick_stiffness, load_path, loop_dissipation,
                                  masing_dissipation, shear_modulus_for,
                                  solve_partial_slip, tangential_operator)


# --- influence coefficients ----------------------------------------------------------

def _quad(f, x, y, dx, dy):
    """Adaptive quadrature over the cell, split at the field point when it lies inside
    (the kernel's 1/r singularity then sits at a corner of each piece)."""
    xs = sorted({-dx / 2, dx / 2} | ({x} if abs(x) < dx / 2 else set()))
    ys = sorted({-dy / 2, dy / 2} | ({y} if abs(y) < dy / 2 else set()))
    total = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for a, b in zip(xs[:-1], xs[1:]):
            for c, d in zip(ys[:-1], ys[1:]):
                total += dblquad(f, a, b, c, d, epsabs=1e-15, epsrel=1e-12)[0]
    return total


@pytest.mark.parametrize("x, y, dx, dy", [
    (0.0, 0.0, 1.0, 0.5),       # centre of its own cell
    (0.1, 0.2, 1.0, 0.5),       # inside, off-centre
    (0.5, 0.1, 1.0, 1.0),       # on an edge
    (0.3, -2.0, 1.0, 1.0),      # neighbour of a square cell
    (5.0, 0.1, 2.0, 0.01),      # along a needle-like cell's axis
    (0.2, 40.0, 1.0, 0.02),     # across it, where the log form cancels
    (100.0, 3.0, 1.0, 0.01),    # far field
])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_cerruti_coefficients_equal_quadrature_of_the_point_force_solution(x, y, dx, dy,
                                                                           nu):
    """Johnson (1985) Eq. 3.86: u_x = [(1-nu)/r + nu x^2/r^3]/(2 pi G), u_y likewise with
    y, and the cross term nu x y/r^3/(2 pi G), integrated over a uniformly loaded cell.
    The closed forms agree with adaptive quadrature to 1e-10 (quadrature tolerance
    1e-12; the far-field point loses ~1e-11 to the mixed corner difference, as Love's
    coefficient does)."""
    G = 0.7
    c = 1 / (2 * np.pi * G)

    def r(s, e):
        return np.hypot(x - s, y - e)

    kernels = [
        lambda e, s: c * ((1 - nu) / r(s, e) + nu * (x - s) ** 2 / r(s, e) ** 3),
        lambda e, s: c * ((1 - nu) / r(s, e) + nu * (y - e) ** 2 / r(s, e) ** 3),
        lambda e, s: c * nu * (x - s) * (y - e) / r(s, e) ** 3,
    ]
    closed = cerruti_rectangle(x, y, dx, dy, G, nu)
    scale = abs(closed[0])
    for name, f, k in zip(("K_xx", "K_yy", "K_xy"), kernels, closed):
        exact = _quad(f, x, y, dx, dy)
        assert float(k) == pytest.approx(exact, rel=1e-10, abs=1e-13 * scale), \
            f"{name} at ({x}, {y}) on a {dx} x {dy} cell, nu = {nu}"


def test_at_nu_zero_the_shear_kernel_is_loves_normal_kernel():
    """Cerruti's u_x at nu = 0 is 1/(2 pi G r) = Boussinesq's 1/(pi E* r) with E* = 2G,
    so K_xx = K_yy = Love's coefficient; and K_zz = (1-nu)(F_nu + F_1)/(2 pi G) is Love's
    with E* = 2G/(1-nu) for every nu. Identities of closed forms, summed in another
    order: equal to rounding, which the mixed corner difference amplifies by about
    (r^2/(dx dy)) eps ~ 1e-12 for the thin cell at r ~ 3 (hence rtol 1e-11)."""
    rng = np.random.default_rng(3)
    x, y = rng.normal(0, 3, 50), rng.normal(0, 3, 50)
    for dx, dy in [(1.0, 1.0), (1.0, 0.01), (0.2, 3.0)]:
        kxx, kyy, kxy = cerruti_rectangle(x, y, dx, dy, shear_modulus=0.5, nu=0.0)
        love = rectangle_displacement(x, y, dx, dy, estar=1.0)
        np.testing.assert_allclose(kxx, love, rtol=1e-11)
        np.testing.assert_allclose(kyy, love, rtol=1e-11)
        assert np.all(kxy == 0)
        for nu in (0.25, 0.5):
            fnu, f1 = shear_integrals(x, y, dx, dy)
            kzz = (1 - nu) * (fnu + f1) / (2 * np.pi * 0.35)
            np.testing.assert_allclose(
                kzz, rectangle_displacement(x, y, dx, dy, 2 * 0.35 / (1 - nu)), rtol=1e-11)


def test_k_yy_is_k_xx_with_the_axes_exchanged():
    """Rotating the problem by 90 degrees exchanges x and y: K_yy(x, y; dx, dy) =
    K_xx(y, x; dy, dx) exactly (same terms, rounding)."""
    rng = np.random.default_rng(4)
    x, y = rng.normal(0, 2, 40), rng.normal(0, 2, 40)
    _, kyy, kxy = cerruti_rectangle(x, y, 0.3, 1.7, 1.0, 0.3)
    kxx_t, _, kxy_t = cerruti_rectangle(y, x, 1.7, 0.3, 1.0, 0.3)
    np.testing.assert_allclose(kyy, kxx_t, rtol=1e-14)
    np.testing.assert_allclose(kxy, kxy_t, rtol=1e-14)


def test_material_out_of_range_is_refused():
    from linecontact.errors import OutOfRangeError
    with pytest.raises(OutOfRangeError, match="nu = 0.6"):
        cerruti_rectangle(0.0, 0.0, 1.0, 1.0, 1.0, 0.6)
    with pytest.raises(OutOfRangeError, match="shear_modulus"):
        cerruti_rectangle(0.0, 0.0, 1.0, 1.0, -1.0, 0.3)
    with pytest.raises(ValueError, match="'x', 'y'"):
        tangential_operator(4, 4, 1.0, 1.0, 1.0, 0.3, "z")


# --- operators --------------------------------------------------------------------------

@pytest.mark.parametrize("direction", ["x", "y"])
def test_tangential_operators_equal_direct_summation(direction):
    """The DC-FFT with the shear kernel is the free-space convolution (equal to the
    direct double sum to rounding), and the quarter DCT form equals it on fields even
    in x and y."""
    rng = np.random.default_rng(5)
    nx, ny, dx, dy, G, nu = 8, 6, 0.5, 0.125, 0.8, 0.3
    q = rng.random((nx, ny))
    u = tangential_operator(nx, ny, dx, dy, G, nu, direction, symmetric=False)(q)
    X = np.arange(nx) * dx
    Y = np.arange(ny) * dy
    k = 0 if direction == "x" else 1
    direct = np.array([[np.sum(cerruti_rectangle(X[i] - X[:, None], Y[j] - Y[None, :],
                                                 dx, dy, G, nu)[k] * q)
                        for j in range(ny)] for i in range(nx)])
    np.testing.assert_allclose(u, direct, rtol=1e-12)
    quarter = q[:4, :3]
    us = tangential_operator(4, 3, dx, dy, G, nu, direction)(quarter)
    ud = tangential_operator(8, 6, dx, dy, G, nu, direction, symmetric=False)(unfold(quarter))
    np.testing.assert_allclose(us, ud[4:, 3:], rtol=1e-12)


# --- nu = 0: the tangential problem is the normal one (any shape) ---------------------------

def _irregular_indenter(n=40):
    """A non-symmetric smooth indenter on a full grid: tilted ellipsoid plus a ripple."""
    h = 2.0 / n
    c = (np.arange(n) - n / 2 + 0.5) * h
    X, Y = np.meshgrid(c, c, indexing="ij")
    gap = X ** 2 / 2 + Y ** 2 / 0.8 + 0.3 * X * Y + 0.02 * np.sin(7 * X + 3 * Y) + 0.1 * X
    return gap, h


def test_nu_zero_full_stick_equals_normal_stiffness_for_any_shape():
    """At nu = 0 Cerruti's kernel is Boussinesq's with E* = 2G (Johnson 1985, 3.86), so
    on any contact set k_t = k_n in both directions (Popov & Hess 2015: the MDR is
    exact there). Same discrete system: equal to the solver tolerance 1e-10."""
    gap, h = _irregular_indenter()
    n = gap.shape[0]
    d = 0.05
    opn = DCFFTOperator(n, n, h, h)
    sol = solve_contact(opn, gap - d, d, tol=1e-10)
    assert sol.converged and 20 < sol.contact.sum() < n * n / 2
    kn = solve_punch(opn, sol.contact, tol=1e-11).pressure.sum() * h * h
    for direction in "xy":
        opt = tangential_operator(n, n, h, h, 0.5, 0.0, direction, symmetric=False)
        kt = solve_punch(opt, sol.contact, tol=1e-11).pressure.sum() * h * h
        assert kt == pytest.approx(kn, rel=1e-9), f"nu = 0, {direction}: k_t != k_n"


def test_nu_zero_partial_slip_is_the_difference_of_two_normal_solutions():
    """Ciavarella-Jaeger at nu = 0: q = mu [p(d) - p(d - u/mu)] satisfies the stick and
    slip conditions exactly on the discrete problem too (K_t = K_n), so
    F_t(u) = mu [F(d) - F(d - u/mu)] for any shape (Popov & Hess 2015, ch. 5). Loaded in
    steps from the virgin state up to near gross slip; agreement to the solver
    tolerance (1e-10 of d, relative 1e-7 of F_t)."""
    gap, h = _irregular_indenter()
    n = gap.shape[0]
    d, mu = 0.05, 0.3
    opn = DCFFTOperator(n, n, h, h)
    p = solve_contact(opn, gap - d, d, tol=1e-11).pressure
    F = p.sum() * h * h
    fractions = np.array([0.05, 0.2, 0.4, 0.7, 0.95])
    opt = tangential_operator(n, n, h, h, 0.5, 0.0, "x", symmetric=False)
    states = load_path(opt, p, mu, fractions * mu * d, tol=1e-11)
    for frac, s in zip(fractions, states):
        ft = s.traction.sum() * h * h
        low = solve_contact(opn, gap - d * (1 - frac), d, tol=1e-11).pressure.sum() * h * h
        assert ft == pytest.approx(mu * (F - low), rel=1e-7), f"u/u_gs = {frac}"


def test_nu_zero_oracle_on_the_finite_cylinder():
    """The same identity on the cylinder's adapted grid (the study's path): at nu = 0
    k_t/k_n = 1 across and along the axis to the solver tolerance, and the partial-slip
    curve is mu [F(d) - F(d - u/mu)] from the BEM's own normal solutions."""
    r = cylinder_full_stick(1e-4, nus=(0.0,), n_length=32, n_width=8, tol=1e-10)
    assert r.ratio_across[0] == pytest.approx(1.0, rel=1e-8)
    assert r.ratio_along[0] == pytest.approx(1.0, rel=1e-8)
    curve = cylinder_partial_slip(r.normal, 0.0, "y", [0.1, 0.5, 0.9], mu=0.4, tol=1e-10)
    np.testing.assert_allclose(curve["ft_bem"], curve["ft_mdr"], rtol=1e-6)


# --- bonded punch and Hertz sphere (Mindlin) -------------------------------------------------

def _circle(m, radius=1.0, extent=1.25):
    h = extent * radius / m
    c = (np.arange(m) + 0.5) * h
    return c[:, None] ** 2 + c[None, :] ** 2, h


def test_bonded_circular_punch_tangential_stiffness_is_8Ga_over_2_minus_nu():
    """Mindlin (1949): a bonded rigid circular punch shifted tangentially has
    k_t = 8 G a/(2 - nu) (Johnson 1985, Eq. 7.43), i.e. k_t/k_n = 2(1-nu)/(2-nu)
    exactly. On a staircase footprint (radius of the equal-area circle) the edge
    singularity makes both k_n and k_t first order in h, like the normal punch of
    tests/test_bem.py (measured k_t error 8.5e-3, 4.1e-3, 2.3e-3 at 16, 32, 64 cells per
    1.25 a); the errors nearly cancel in k_t/k_n (measured 3e-4 at 16, 7e-5 at 64)."""
    errs = {0.3: [], 0.5: []}
    ratio_errs = []
    for m in (16, 32):
        r2, h = _circle(m)
        foot = r2 <= 1.0
        a_eq = np.sqrt(4 * foot.sum() * h * h / np.pi)
        kn = 4 * solve_punch(SymmetricOperator(m, m, h, h), foot, tol=1e-10).pressure.sum() * h * h
        for nu in errs:
            G = shear_modulus_for(1.0, nu)
            kt, _ = full_stick_stiffness(foot.astype(float), _grid(m, m, h, h), 1.0, nu,
                                         "x", tol=1e-10)
            errs[nu].append(abs(kt / (8 * G * a_eq / (2 - nu)) - 1))
            ratio_errs.append(abs(kt / kn / mdr_stiffness_ratio(nu) - 1))
    for nu, e in errs.items():
        assert e[-1] < 6e-3, f"nu = {nu}: k_t off by {e[-1]:.2e} on 32 cells"
        assert e[1] < 0.7 * e[0], f"nu = {nu}: no first-order convergence {e}"
    assert max(ratio_errs) < 5e-4, f"k_t/k_n off the exact G*/E* by {max(ratio_errs):.1e}"


def test_square_punch_is_equally_stiff_in_x_and_y():
    """A square footprint is invariant under a 90-degree rotation, which maps a shift
    along x to one along y: k_t,x = k_t,y (same discrete system transposed: to the
    solver tolerance)."""
    m, h = 12, 0.1
    foot = np.ones((m, m))
    kx, _ = full_stick_stiffness(foot, _grid(m, m, h, h), 1.0, 0.4, "x", tol=1e-11)
    ky, _ = full_stick_stiffness(foot, _grid(m, m, h, h), 1.0, 0.4, "y", tol=1e-11)
    assert kx == pytest.approx(ky, rel=1e-9)


def test_bonded_rectangles_approach_the_plane_strain_and_antiplane_limits():
    """A bonded rectangle L x 2b with L >> b: across the long side the 2D (plane strain)
    tangential kernel equals the normal one (k_t/k_n -> 1), along it the antiplane
    kernel is 1/(1-nu) times softer in compliance (k_t/k_n -> 1 - nu) (Johnson 1985,
    sections 2.2 and 2.8). The approach is logarithmic, so the fact checked is the
    ordering: for aspect 1, 4, 16 the ratio across grows and the ratio along falls,
    both starting at the square's value (which lies below the circle's MDR value on
    neither side by more than 2 %) and staying within [1 - nu, 1]."""
    nu = 0.5
    across, along = [], []
    for aspect in (1, 4, 16):
        mx, my = 8 * aspect, 8
        grid = _grid(mx, my, 1.0 / mx * aspect, 1.0 / my)   # square cells, L/2b = aspect
        foot = np.ones((mx, my))
        kn = 4 * solve_punch(SymmetricOperator(mx, my, grid.dx, grid.dy), foot > 0,
                             tol=1e-10).pressure.sum() * grid.cell_area
        across.append(full_stick_stiffness(foot, grid, 1.0, nu, "y", tol=1e-10)[0] / kn)
        along.append(full_stick_stiffness(foot, grid, 1.0, nu, "x", tol=1e-10)[0] / kn)
    assert across[0] == pytest.approx(along[0], rel=1e-9)
    assert across[0] == pytest.approx(mdr_stiffness_ratio(nu), rel=0.02)
    assert across[0] < across[1] < across[2] <= 1.0, across
    assert along[0] > along[1] > along[2] >= 1 - nu, along


def _grid(mx, my, dx, dy):
    from tools.bem.cylinder import Grid
    return Grid(mx, my, dx, dy)


def _hertz(m, d=0.01):
    a = np.sqrt(d)
    r2, h = _circle(m, a)
    sol = solve_contact(SymmetricOperator(m, m, h, h), r2 / 2 - d, d, tol=1e-11)
    return sol.pressure, h, a


@pytest.mark.parametrize("nu", [0.3, 0.5])
def test_hertz_sphere_follows_mindlins_partial_slip_curve(nu):
    """Cattaneo-Mindlin (Johnson 1985, Eq. 7.48): Q(u) = mu P [1 - (1 - u/u_gs)^(3/2)],
    u_gs = 3 mu P (2 - nu)/(16 G a), exact for the one-component (uncoupled) problem
    solved here (the traction difference of two Hertz ellipsoids has a uniform x
    displacement in the stick circle for any nu). Full stick: k_t = 8 G a/(2 - nu).
    The discrete error is that of the Hertz pressure on the grid (at gross slip the
    curve ends at mu F_BEM): measured 6.7e-5 of mu P on 32 cells per 1.25 a, where
    tests/test_bem.py bounds the Hertz force error by 5e-4; the bound 3e-4 leaves 4x
    room. Against mu F_BEM in place of mu P the error must be below 1e-4."""
    m, d, mu = 32, 0.01, 0.4
    p, h, a = _hertz(m, d)
    P = 4 / 3 * d ** 1.5
    F = 4 * p.sum() * h * h
    G = shear_modulus_for(1.0, nu)
    u_gs = 3 * mu * P * (2 - nu) / (16 * G * a)
    op = tangential_operator(m, m, h, h, G, nu, "x")
    frac = np.linspace(0.05, 1.0, 12)
    states = load_path(op, p, mu, frac * u_gs, tol=1e-9)
    Q = np.array([4 * s.traction.sum() * h * h for s in states])
    shape = 1 - (1 - frac) ** 1.5
    err_p = np.abs(Q - mu * P * shape).max() / (mu * P)
    err_f = np.abs(Q - mu * F * shape).max() / (mu * F)
    assert err_p < 3e-4, f"Mindlin curve off by {err_p:.2e} of mu P"
    assert err_f < 1e-4, f"Mindlin curve (scaled to mu F_BEM) off by {err_f:.2e}"
    kt, _ = full_stick_stiffness(p, _grid(m, m, h, h), 1.0, nu, "x", tol=1e-10)
    assert kt == pytest.approx(8 * G * a / (2 - nu), rel=3e-3)


def test_partial_slip_solution_satisfies_coulombs_law():
    """The optimality conditions of the step problem are Coulomb's law: |q| <= mu p
    everywhere, u = shift (stick) where |q| < mu p, u <= shift where q = mu p (slip in
    the direction of the traction), q = 0 off the contact set."""
    p, h, a = _hertz(20)
    mu, nu = 0.5, 0.3
    op = tangential_operator(20, 20, h, h, shear_modulus_for(1.0, nu), nu, "x")
    shift = 0.4 * 3 * mu * (4 / 3 * 0.01 ** 1.5) * (2 - nu) / (16 * 0.35 * a)
    tol = 1e-9
    s = solve_partial_slip(op, p, mu, shift, tol=tol)
    assert s.converged
    c = p > 0
    assert np.all(np.abs(s.traction) <= mu * p * (1 + 1e-12))
    assert np.all(s.traction[~c] == 0)
    assert np.abs(s.displacement[s.stick] - shift).max() <= tol * shift
    slip = c & ~s.stick
    assert slip.any() and s.stick.any()
    assert np.all(s.displacement[slip] <= shift * (1 + tol))
    assert np.all(s.traction[slip] > 0)


def test_unloading_follows_the_masing_rule_and_mindlin_deresiewicz_dissipation():
    """Masing's rule (Mindlin & Deresiewicz 1953; holds exactly for the uncoupled
    problem with fixed p): unloading from (u0, F0), F(u) = F0 - 2 f((u0 - u)/2), f the
    monotonic curve; checked on the same grid to the solver tolerance. The loop area
    from a full BEM cycle matches Mindlin-Deresiewicz's closed form
    W = 9 mu^2 P^2 (2-nu)/(10 G a) [1 - (1 - Q0/mu P)^(5/3) - 5 Q0/(6 mu P)
    (1 + (1 - Q0/mu P)^(2/3))] within 1 % (trapezoid rule on 16 steps per branch:
    second order, measured 0.2 %; Hertz discretisation 1e-4) and the Masing integral
    8 int f - 4 u0 f(u0) of the monotonic curve to the same accuracy."""
    m, d, mu, nu = 20, 0.01, 0.4, 0.3
    p, h, a = _hertz(m, d)
    G = shear_modulus_for(1.0, nu)
    P = 4 / 3 * d ** 1.5
    u_gs = 3 * mu * P * (2 - nu) / (16 * G * a)
    op = tangential_operator(m, m, h, h, G, nu, "x")
    n = 8
    u0 = 0.6 * u_gs
    du = u0 / n
    area = 4 * h * h
    half = load_path(op, p, mu, du / 2 * np.arange(1, 2 * n + 1), tol=1e-11)
    f_half = np.array([s.traction.sum() * area for s in half])
    mono = half[1::2]                                  # shifts du, 2 du, ..., u0
    f = f_half[1::2]
    down = u0 - du * np.arange(1, 2 * n + 1)           # to -u0
    unload = load_path(op, p, mu, down, tol=1e-11, previous=mono[-1])
    fd = np.array([s.traction.sum() * area for s in unload])
    np.testing.assert_allclose(fd, f[-1] - 2 * f_half, atol=1e-8 * mu * P)
    up = -u0 + du * np.arange(1, 2 * n + 1)
    reload = load_path(op, p, mu, up, tol=1e-11, previous=unload[-1])
    fu = np.array([s.traction.sum() * area for s in reload])
    path_u = np.concatenate([[u0], down, up])
    path_f = np.concatenate([[f[-1]], fd, fu])
    W = loop_dissipation(path_u, path_f)
    Q0 = f[-1] / (mu * P)
    W_md = (9 * mu ** 2 * P ** 2 * (2 - nu) / (10 * G * a)
            * (1 - (1 - Q0) ** (5 / 3) - 5 * Q0 / 6 * (1 + (1 - Q0) ** (2 / 3))))
    assert W == pytest.approx(W_md, rel=0.01)
    W_masing = masing_dissipation(np.concatenate([[0], du / 2 * np.arange(1, 2 * n + 1)]),
                                  np.concatenate([[0], f_half]))
    assert W_masing == pytest.approx(W_md, rel=0.01)
    assert fu[-1] == pytest.approx(f[-1], rel=1e-8), "the loop does not close"


# --- the finite cylinder ------------------------------------------------------------------

def test_cylinder_full_stick_ratio_converges_with_the_grid():
    """k_t/k_n of the cylinder at N and 2N cells along the half-length (and across the
    contact width): both are punch problems on the same contact set, so the edge
    singularities largely cancel; the change is below 2e-3 (measured ~1e-4 for
    32 -> 64 along; see tables/tangential_cylinder.csv for the study's grids)."""
    a = cylinder_full_stick(1e-3, nus=(0.3, 0.5), n_length=32, n_width=8, tol=1e-9)
    b = cylinder_full_stick(1e-3, nus=(0.3, 0.5), n_length=64, n_width=16, tol=1e-9)
    for name in ("ratio_across", "ratio_along"):
        change = np.abs(getattr(a, name) / getattr(b, name) - 1).max()
        assert change < 2e-3, f"{name} changed by {change:.2e} from N to 2N"
    # the direction dependence the MDR misses: stiffer across, softer along
    mdr = mdr_stiffness_ratio(b.nu)
    assert np.all(b.ratio_across > mdr) and np.all(b.ratio_along < mdr)


def test_cylinder_ratio_is_self_similar_in_d_tilde():
    """With the parabolic gap the problem depends on d~ = d R/L^2 alone (docs/theory.md,
    section 'Self-similarity'), in physical units too: L/R = 1 and 10 with the same d~,
    different R and E*, on grids that scale with L (tools.bem.cylinder.sweep) give the same
    k_t/k_n to the solver tolerance."""
    d_tilde, nu = 2e-3, 0.3
    out = []
    for l_over_r, radius, estar in [(1.0, 0.01, 2.3e11), (10.0, 0.002, 5e9)]:
        L = l_over_r * radius
        d = d_tilde * L ** 2 / radius
        s = sweep(l_over_r, n=(32, 16), steps=1, d_max_over_r=d / radius, radius=radius,
                  estar=estar, tol=1e-11, fields=True, progress=False, backend="scipy")
        quarter = s.pressure[0][16:, 8:]
        kn = s.stiffness[0]
        ky, _ = full_stick_stiffness(quarter, s.grid, estar, nu, "y", tol=1e-11)
        kx, _ = full_stick_stiffness(quarter, s.grid, estar, nu, "x", tol=1e-11)
        out.append((ky / kn, kx / kn))
    np.testing.assert_allclose(out[0], out[1], rtol=1e-8)


def test_tool_docstring_examples_run():
    """The Examples blocks of the two tool modules are doctests (tools/ is outside the
    default doctest paths)."""
    for module in (tools.bem.influence, tools.bem.tangential):
        result = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
        assert result.failed == 0, f"{module.__name__}: {result.failed} doctest failures"


def test_the_neglected_cross_coupling_changes_the_cylinders_stiffness_by_under_1e_3():
    """One traction component per shift (the slip-parallel assumption) against the
    two-component full-stick problem with Cerruti's K_xy (u_y = 0 imposed as well):
    identical at nu = 0 (K_xy = 0), and for the cylinder's contact the coupling changes
    k_t by less than 1e-3 at nu = 0.5, where it is largest (measured 8e-4 at d~ = 1e-3;
    the cross term is odd, so it acts only through the second order)."""
    from tools.bem.tangential import coupled_full_stick
    from tools.bem.cylinder import solve_depth
    r = solve_depth(1e-3, 24, 8, tol=1e-10, fields=True)
    g = r.grid
    full = unfold(r.pressure) > 0
    for nu, bound in [(0.0, 1e-8), (0.5, 1e-3)]:
        kx, ky = coupled_full_stick(full, g.dx, g.dy, 1.0, nu)
        ux, _ = full_stick_stiffness(r.pressure, g, 1.0, nu, "x", tol=1e-10)
        uy, _ = full_stick_stiffness(r.pressure, g, 1.0, nu, "y", tol=1e-10)
        assert abs(kx / ux - 1) < bound and abs(ky / uy - 1) < bound, (nu, kx / ux, ky / uy)


# --- the shipped table ----------------------------------------------------------------------

def _shipped():
    from linecontact.tables import read_table
    return read_table("tangential_cylinder")


def test_shipped_table_has_the_contract_columns_and_its_exact_rows():
    """tables/tangential_cylinder.csv: the columns the runtime reads (nu, d_tilde,
    kt_kn_across, kt_kn_along), the MDR column equal to 2(1-nu)/(2-nu), the nu = 0 rows
    equal to 1 (exact oracle, to the solver tolerance), the MDR error column consistent
    with the others, and the grid convergence within a tenth of the 1 % target."""
    t = _shipped()
    c = t.columns
    for name in ("nu", "d_tilde", "kt_kn_across", "kt_kn_along"):
        assert name in c, f"contract column {name} missing"
    np.testing.assert_allclose(c["kt_kn_mdr"], mdr_stiffness_ratio(c["nu"]), rtol=1e-15)
    zero = c["nu"] == 0
    assert zero.any()
    np.testing.assert_allclose(c["kt_kn_across"][zero], 1.0, atol=1e-6)
    np.testing.assert_allclose(c["kt_kn_along"][zero], 1.0, atol=1e-6)
    np.testing.assert_allclose(c["mdr_err_across"], c["kt_kn_mdr"] / c["kt_kn_across"] - 1,
                               rtol=1e-12)
    # N -> 2N: median 4e-5, largest 1.0e-3 (nu = 0.5, d~ = 4.7, a contact five times
    # wider than long), 3.6e-4 for d~ <= 0.15; a tenth of the runtime's 1 % target
    assert np.abs(c["grid_change_across"]).max() < 2e-3
    assert np.abs(c["grid_change_along"]).max() < 2e-3
    # one row per (nu, d_tilde), every nu on the same depths
    pairs = set(zip(c["nu"], c["d_tilde"]))
    assert len(pairs) == len(c["nu"])
    depths = [np.sort(c["d_tilde"][c["nu"] == nu]) for nu in np.unique(c["nu"])]
    assert all(np.array_equal(depths[0], d) for d in depths)


def test_shipped_table_direction_dependence_has_the_2d_limits_signs():
    """While the contact is longer along the axis than wide (d~ <= 0.1: half-width
    b < L/2), k_t/k_n across the axis lies between the MDR value and the plane-strain
    limit 1, along it between the antiplane limit 1 - nu and the MDR value, and both
    move away from the MDR value as d~ falls (a long strip). At the largest d~ the
    contact is wider than long (b ~ sqrt(2 d~) L = 5.5 L at d~ = 15) and the roles
    swap: across below the MDR value, along above it."""
    c = _shipped().columns
    for nu in np.unique(c["nu"]):
        if nu == 0:
            continue
        sel = c["nu"] == nu
        order = np.argsort(c["d_tilde"][sel])
        d = c["d_tilde"][sel][order]
        across = c["kt_kn_across"][sel][order]
        along = c["kt_kn_along"][sel][order]
        strip = d <= 0.1
        assert np.all((across[strip] > mdr_stiffness_ratio(nu)) & (across[strip] < 1)), nu
        assert np.all((along[strip] < mdr_stiffness_ratio(nu)) & (along[strip] > 1 - nu)), nu
        assert np.all(np.diff(across[strip]) < 0) and np.all(np.diff(along[strip]) > 0)
        assert across[-1] < mdr_stiffness_ratio(nu) < along[-1], nu


@pytest.mark.slow
def test_study_recipe_reproduces_a_shipped_row():
    """Regression against the shipped table: the study's task for one depth, with the
    grid read back from the header, gives the shipped k_t/k_n (same discrete problem:
    agreement to the solver tolerance, 1e-6)."""
    import re
    from tools.studies.tangential_study import solve_task
    t = _shipped()
    grid = t.meta["grid"]
    nl, nw = (int(v) for v in re.search(r"N = (\d+) cells along the half-length and (\d+)",
                                         grid).groups())
    sl, sw = (int(v) for v in re.search(r"partial slip on (\d+) along the half-length and "
                                        r"(\d+)", grid).groups())
    c = t.columns
    d = float(np.unique(c["d_tilde"])[len(np.unique(c["d_tilde"])) // 2])
    nus = [float(v) for v in np.unique(c["nu"])]
    tol = float(t.meta["tolerance"].split()[0])
    r = solve_task(dict(key="check", d_tilde=d, nus=nus, n_length=nl, n_width=nw,
                        slip_points=24, slip_depths=32, tol=tol, slip_n_length=sl,
                        slip_n_width=sw))
    for i, nu in enumerate(nus):
        row = (c["d_tilde"] == d) & (c["nu"] == nu)
        assert r["across_2N"][i] == pytest.approx(c["kt_kn_across"][row][0], rel=1e-6)
        assert r["along_2N"][i] == pytest.approx(c["kt_kn_along"][row][0], rel=1e-6)


# --- the runtime's use of the table against direct BEM solutions (issue 10, item 5) -----------

OFF_NODE = [(0.35, 2e-5), (0.45, 3e-2), (0.2, 5e-9), (0.27, 7e-4), (0.1, 1e-6)]


@pytest.mark.parametrize("nu, d_tilde", OFF_NODE)
def test_runtime_full_stick_ratio_off_the_table_nodes_is_within_1_percent_of_the_bem(
        nu, d_tilde):
    """linecontact.tangential interpolates the shipped table in (nu, ln d~); at points
    between its nodes a direct BEM solve (128/16 cells, whose own grid error is ~2e-4)
    must agree within the issue's 1 % target. Measured at these points: at most 6e-4
    (nu = 0.45, d~ = 3e-2, along), 2.2e-4 at nu = 0.1 between the nodes 0 and 0.25."""
    from linecontact.tangential import cylinder_tangential_table
    t = cylinder_tangential_table()
    r = cylinder_full_stick(d_tilde, (nu,), 128, 16, tol=1e-9)
    assert t.ratio("across", nu, d_tilde) == pytest.approx(r.ratio_across[0], rel=0.01)
    assert t.ratio("along", nu, d_tilde) == pytest.approx(r.ratio_along[0], rel=0.01)


@pytest.mark.parametrize("direction, side", [("y", "across"), ("x", "along")])
def test_runtime_partial_slip_law_off_the_nodes_is_within_2_percent_of_the_bem(direction,
                                                                              side):
    """The runtime's partial-slip law for the cylinder (linecontact.tangential,
    method='bem'): the MDR law with the table's k_t/k_n in place of G*/E*, its shift
    scaled by the table's shift_ratio factor interpolated linearly in Q = F_t/(mu F).
    Against the BEM curve at an off-node (nu, d~), on the same grid (so that the laws
    and the BEM share F(d')): the force error over the whole curve must stay within the
    issue's 2 % of mu F for 0.02 <= Q <= 0.99 (measured at nu = 0.35, d~ = 2e-5 on a
    64/16 grid: 0.67 % across, 0.19 % along; without the shift correction 0.63 % and
    0.44 %: across, the correction measured on the table's 128/16 grid does not
    improve this coarser grid's curve)."""
    from scipy.interpolate import CubicSpline, PchipInterpolator
    from scipy.optimize import brentq
    from linecontact.tangential import cylinder_tangential_table
    from tools.studies.tangential_study import partial_slip_measures
    nu, d = 0.35, 2e-5
    t = cylinder_tangential_table()
    r = cylinder_full_stick(d, (nu,), 64, 16, tol=1e-9)
    n = r.normal
    J = 32
    dp = d * np.arange(J, 0, -1) / J
    Fd = normal_force_on_grid(n.grid, dp, tol=1e-9)
    f_of = CubicSpline(np.r_[0.0, dp[::-1]], np.r_[0.0, Fd[::-1]])
    F = 4 * n.pressure.sum() * n.grid.cell_area
    kappa = float(t.ratio(side, nu, d))
    m = partial_slip_measures(n, nu, direction, kappa, 24, J, 1e-9, f_of)
    bem = PchipInterpolator(m["u"], m["f"])
    qs, cs = t.shift_correction(side, nu, d)
    errs = []
    for corrected in (True, False):
        worst = 0.0
        for q in np.linspace(0.02, 0.99, 50):
            dprime = brentq(lambda x: f_of(x) - (1 - q) * F, 0.0, d, xtol=1e-15)
            u = (d - dprime) / kappa * (np.interp(q, qs, cs) if corrected else 1.0)
            worst = max(worst, abs(float(bem(u)) - q))
        errs.append(worst)
    assert errs[0] < 0.02, f"corrected law off the BEM by {errs[0]:.2%} of mu F"
    assert errs[1] < 0.02, f"uncorrected law off the BEM by {errs[1]:.2%} of mu F"


def test_study_command_on_tiny_grids_keeps_the_exact_nu_zero_rows(tmp_path):
    """`build_tables tangential` end to end on tiny grids: at nu = 0 Cerruti's kernel is
    Love's with E* = 2G (Johnson 1985, section 3.6), so k_t/k_n = 1 exactly on any grid,
    up to the solver tolerance 1e-8 (asserted to 1e-6); the header records the run."""
    from linecontact.tables import read_table
    from tools.build_tables import main as build_tables
    assert build_tables(["tangential", "--d-min", "1e-3", "--d-max", "1e-2",
                         "--per-decade", "1", "--nu", "0", "0.5", "--n-length", "8",
                         "--n-width", "4", "--slip-n-length", "8", "--slip-n-width", "4",
                         "--slip-points", "4", "--slip-depths", "4", "--workers", "1",
                         "--no-progress", "--out", str(tmp_path)]) == 0
    t = read_table("tangential_cylinder", directory=tmp_path)
    c = t.columns
    zero = c["nu"] == 0
    assert zero.sum() == 2 and (~zero).sum() == 2
    np.testing.assert_allclose(c["kt_kn_across"][zero], 1.0, atol=1e-6)
    np.testing.assert_allclose(c["kt_kn_along"][zero], 1.0, atol=1e-6)
    assert t.meta["wall_time"].split(" with ")[0].endswith("s for 2 depths")


def test_normal_force_on_grid_refuses_an_unconverged_depth():
    """F(d') feeds the partial-slip laws of the study: a contact solution that misses
    its tolerance (here an unreachable 1e-30, below rounding) raises instead of passing
    its force on; at the default tolerance the same depths give F > 0 growing with d'."""
    from tools.bem.cylinder import Grid
    from tools.bem.solver import ConvergenceError
    g = Grid(8, 8, 0.5 / 8, 0.2 / 8)
    F = normal_force_on_grid(g, [0.0, 0.01, 0.02])
    assert F[0] == 0 and 0 < F[1] < F[2]
    with pytest.raises(ConvergenceError, match=r"d' = 0.01 m.*tol = 1e-30"):
        normal_force_on_grid(g, [0.01], tol=1e-30)
