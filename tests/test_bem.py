"""Verification of the boundary-element solver in tools/ against exact answers
(docs/theory.md, section 'Verification'). Each test states the fact it checks and why its tolerance is what
it is; grids are small so the whole file runs in seconds."""
import numpy as np
import pytest
from scipy.integrate import dblquad

from tools.bem.cylinder import solve_depth, sweep
from tools.bem.halfspace import DCFFTOperator, SymmetricOperator, unfold
from tools.bem.influence import kernel_offsets, rectangle_displacement
from tools.bem.solver import ConvergenceError, solve_contact, solve_punch


# --- influence coefficients -------------------------------------------------------

def test_love_centre_coefficient_of_a_square_cell():
    """Love (1929): the centre of a uniformly loaded square of side h sinks by
    4 ln(1 + sqrt 2)/pi * h p/E*. Closed form: agreement to rounding."""
    for h, estar in [(1.0, 1.0), (2e-3, 1.15e11)]:
        exact = 4 * np.log(1 + np.sqrt(2)) / np.pi * h / estar
        assert rectangle_displacement(0.0, 0.0, h, h, estar) == pytest.approx(exact, rel=1e-14)


@pytest.mark.parametrize("x, y, dx, dy", [
    (0.3, -2.0, 1.0, 1.0),      # neighbour of a square cell
    (5.0, 0.1, 2.0, 0.01),      # along a needle-like cell's axis
    (0.2, 40.0, 1.0, 0.02),     # across it, where Johnson's log form cancels
    (100.0, 3.0, 1.0, 0.01),    # far field
])
def test_love_rectangle_equals_quadrature_of_boussinesq(x, y, dx, dy):
    """Johnson Eq. 3.25 is the integral of Boussinesq's 1/(pi E* r) over the cell;
    adaptive quadrature of that integral agrees to 1e-9 (quadrature tolerance),
    also for cells 100 times longer than wide."""
    exact = dblquad(lambda eta, xi: 1 / (np.pi * np.hypot(x - xi, y - eta)),
                    -dx / 2, dx / 2, -dy / 2, dy / 2, epsabs=1e-14, epsrel=1e-11)[0]
    assert rectangle_displacement(x, y, dx, dy) == pytest.approx(exact, rel=1e-9)


# --- operators ----------------------------------------------------------------------

def test_dcfft_equals_direct_summation():
    """DC-FFT with zero padding is the free-space (non-periodic) convolution: equal to
    the direct double sum over cells to rounding."""
    rng = np.random.default_rng(1)
    nx, ny, dx, dy = 9, 6, 0.5, 0.125
    p = rng.random((nx, ny))
    u = DCFFTOperator(nx, ny, dx, dy, backend="scipy")(p)
    X = np.arange(nx) * dx
    Y = np.arange(ny) * dy
    direct = np.array([[np.sum(rectangle_displacement(X[i] - X[:, None], Y[j] - Y[None, :],
                                                      dx, dy) * p)
                        for j in range(ny)] for i in range(nx)])
    np.testing.assert_allclose(u, direct, rtol=1e-12)


@pytest.mark.parametrize("backend", ["scipy", "pyfftw"])
def test_symmetric_operator_equals_dcfft_on_mirror_symmetric_fields(backend):
    """For a field even in x and y, the quarter-grid DCT form is the same linear
    convolution as the full DC-FFT (exact identity, so agreement to rounding)."""
    if backend == "pyfftw":
        pytest.importorskip("pyfftw")
    rng = np.random.default_rng(2)
    mx, my, dx, dy = 13, 7, 0.3, 0.01
    q = rng.random((mx, my))
    # one thread, as the studies run it (measuring 2-thread FFTW plans takes seconds
    # when the cores are busy)
    us = SymmetricOperator(mx, my, dx, dy, backend=backend, workers=1)(q)
    ud = DCFFTOperator(2 * mx, 2 * my, dx, dy, backend="scipy")(unfold(q))
    np.testing.assert_allclose(us, ud[mx:, my:], rtol=1e-12, atol=1e-15 * np.abs(ud).max())


@pytest.mark.parametrize("backend", ["scipy", "pyfftw"])
def test_operators_take_another_kernel(backend):
    """kernel= replaces Love's kernel (how tools.bem.tangential builds Cerruti's
    operators): Love's with E* = 1/2 given explicitly gives twice the default E* = 1
    field, since Love's coefficients scale as 1/E* (exact, so agreement to rounding);
    a kernel of the wrong size is refused, naming the size needed."""
    if backend == "pyfftw":
        pytest.importorskip("pyfftw")
    rng = np.random.default_rng(3)
    mx, my, dx, dy = 5, 4, 0.3, 0.1
    q = rng.random((mx, my))
    for cls, m in ((SymmetricOperator, 2), (DCFFTOperator, 1)):
        k = kernel_offsets(m * mx, m * my, dx, dy, estar=0.5)
        u = cls(mx, my, dx, dy, backend=backend, workers=1, kernel=k)(q)
        u1 = cls(mx, my, dx, dy, backend=backend, workers=1)(q)
        np.testing.assert_allclose(u, 2 * u1, rtol=1e-12)
        with pytest.raises(ValueError, match=r"kernel shape.*\(%d, %d\)" % (m * mx + 1,
                                                                              m * my + 1)):
            cls(mx, my, dx, dy, backend=backend, kernel=k[:-1])


def test_unknown_backend_lists_the_valid_ones():
    with pytest.raises(ValueError, match="scipy.*pyfftw"):
        SymmetricOperator(4, 4, 1.0, 1.0, backend="cufft")


# --- contact solver against exact solutions ---------------------------------------------

def _sphere(m, R=1.0, d=0.01, extent=1.6):
    a = np.sqrt(R * d)
    h = extent * a / m
    c = (np.arange(m) + 0.5) * h
    r2 = c[:, None] ** 2 + c[None, :] ** 2
    return SymmetricOperator(m, m, h, h, backend="scipy"), r2, h, a


def test_hertz_sphere_force_converges_to_the_exact_law():
    """Hertz: F = 4/3 E* sqrt(R) d^1.5. With 20 and 40 cells across the contact radius
    the error is below 5e-4 and 1.5e-4, and it falls with refinement (measured:
    2.1e-4 and 4.7e-5, second order)."""
    R, d = 1.0, 0.01
    errs = []
    for m, bound in [(32, 5e-4), (64, 1.5e-4)]:
        op, r2, h, _ = _sphere(m, R, d)
        sol = solve_contact(op, r2 / (2 * R) - d, d, tol=1e-8)
        assert sol.converged, f"solver did not converge on {m}^2: error {sol.error}"
        F = 4 * sol.pressure.sum() * h * h
        errs.append(abs(F / (4 / 3 * np.sqrt(R) * d ** 1.5) - 1))
        assert errs[-1] < bound, f"Hertz force off by {errs[-1]:.2e} on a {m}^2 quarter"
    assert errs[1] < errs[0] / 2.5, f"Hertz error does not fall with the grid: {errs}"


def test_circular_flat_punch_stiffness_is_2_estar_a_with_first_order_convergence():
    """A rigid circular flat punch: k = 2 E* a. On a staircase footprint the radius is
    that of the equal-area circle; the edge singularity p ~ 1/sqrt(a - r) limits
    piecewise-constant cells to first order, so the error halves with h (measured
    1.15e-2, 5.8e-3, 2.9e-3 at 16, 32, 64 cells per radius/1.6)."""
    errs = []
    for m in (16, 32, 64):
        op, r2, h, a = _sphere(m)
        foot = r2 <= a * a
        sol = solve_punch(op, foot, tol=1e-9)
        assert sol.converged
        k = 4 * sol.pressure.sum() * h * h
        a_eq = np.sqrt(4 * foot.sum() * h * h / np.pi)
        errs.append(abs(k / (2 * a_eq) - 1))
    assert errs[-1] < 4e-3, f"punch stiffness off by {errs[-1]:.2e}"
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all((orders > 0.8) & (orders < 1.3)), f"convergence orders {orders}, expected ~1"


def test_punch_stiffness_is_the_derivative_of_the_contact_force():
    """With the contact set held fixed, F(d) of the discrete problem is linear in d
    with slope K_SS^-1 1: the punch force at unit depth. A depth step small enough not
    to change the contact set must reproduce it (to the solver tolerance)."""
    op, r2, h, a = _sphere(24)
    d = 0.01
    s1 = solve_contact(op, r2 / 2 - d, d, tol=1e-11)
    s2 = solve_contact(op, r2 / 2 - d * (1 + 1e-7), d, tol=1e-11, p0=s1.pressure)
    assert np.array_equal(s1.contact, s2.contact)
    slope = 4 * (s2.pressure.sum() - s1.pressure.sum()) * h * h / (d * 1e-7)
    k = 4 * solve_punch(op, s1.contact, tol=1e-11).pressure.sum() * h * h
    assert slope == pytest.approx(k, rel=1e-4)


def test_contact_solution_satisfies_the_complementarity_conditions():
    """Signorini conditions: p >= 0 everywhere, gap = 0 (to tol d) on the contact set,
    gap >= -tol d outside it."""
    op, r2, h, a = _sphere(20)
    d, tol = 0.01, 1e-7
    sol = solve_contact(op, r2 / 2 - d, d, tol=tol)
    gap = sol.displacement + r2 / 2 - d
    assert (sol.pressure >= 0).all()
    assert np.abs(gap[sol.contact]).max() <= tol * d
    assert gap[~sol.contact].min() >= -tol * d


def test_a_run_that_does_not_converge_says_so():
    """The solver never passes off an unconverged state: too few iterations give
    converged = False, and the sweep driver raises."""
    op, r2, h, a = _sphere(32)
    sol = solve_contact(op, r2 / 2 - 0.01, 0.01, tol=1e-12, maxiter=3)
    assert not sol.converged and sol.error > 1e-12
    with pytest.raises(ConvergenceError, match="L/R = 5"):
        import tools.bem.cylinder as cyl
        orig = cyl.solve_contact
        try:
            cyl.solve_contact = lambda *a, **k: orig(*a, **{**k, "maxiter": 2})
            sweep(5, n=16, steps=2, progress=False)
        finally:
            cyl.solve_contact = orig


# --- the finite cylinder ------------------------------------------------------------------

def test_cylinder_pressure_field_is_mirror_symmetric():
    """The cylinder is symmetric about x = 0 and y = 0, so the full (non-symmetric)
    DC-FFT solution is even in x and y, and equals the quarter solution unfolded."""
    R, L, d = 1.0, 2.0, 0.02
    nx, ny = 24, 16
    Y = np.sqrt(2 * R * d)
    dx, dy = L / nx, 2 * Y / ny
    y = (np.arange(ny) - ny / 2 + 0.5) * dy
    sep = np.broadcast_to(y ** 2 / (2 * R) - d, (nx, ny))
    full = solve_contact(DCFFTOperator(nx, ny, dx, dy, backend="scipy"), sep, d, tol=1e-10)
    p = full.pressure
    scale = p.max()
    np.testing.assert_allclose(p, p[::-1, :], atol=1e-8 * scale)
    np.testing.assert_allclose(p, p[:, ::-1], atol=1e-8 * scale)
    quarter = solve_contact(SymmetricOperator(nx // 2, ny // 2, dx, dy, backend="scipy"),
                            sep[nx // 2:, ny // 2:], d, tol=1e-10)
    np.testing.assert_allclose(unfold(quarter.pressure), p, atol=1e-7 * scale)
    # the pressure peaks at the flat ends (Li & Popov 2017, Fig. 2)
    line = p[:, ny // 2]
    assert line[0] > 1.2 * line[nx // 2]


def test_cylinder_force_converges_with_the_grid():
    """F(d) at L/R = 5 on N^2 and 2N^2 grids: the change is below 0.5 % and shrinks
    under refinement (measured 0.31 % for 32->64 and 0.18 % for 64->128: order ~0.8,
    set by the pressure singularity at the flat ends)."""
    a, b, c = (sweep(5, n=n, steps=4, progress=False, backend="scipy") for n in (32, 64, 128))
    change1 = np.max(np.abs(a.force / b.force - 1))
    change2 = np.max(np.abs(b.force / c.force - 1))
    assert change1 < 5e-3, f"32 -> 64 changed F by {change1:.2e}"
    assert change2 < 0.8 * change1, f"no convergence: {change1:.2e} then {change2:.2e}"


def test_universal_scaling_holds_in_the_bem():
    """docs/theory.md, section 'Self-similarity': with h = y^2/(2R) the problem depends on d R/L^2 alone, so
    F R/(E* L^3) at equal d R/L^2 is the same for any L/R, E*, R when the grid scales
    with the problem (identical discrete systems: agreement to solver tolerance)."""
    base = sweep(2.0, n=(24, 16), steps=2, d_max_over_r=0.02, progress=False,
                 backend="scipy", tol=1e-9)
    # L/R = 0.5 with the same d R / L^2: d_max/R = 0.02 * (0.5/2)^2
    other = sweep(0.5, n=(24, 16), steps=2, d_max_over_r=0.02 / 16, radius=3.0,
                  estar=7.0, progress=False, backend="scipy", tol=1e-9)
    psi_base = base.force * base.radius / (base.estar * (2.0 * base.radius) ** 3)
    psi_other = other.force * other.radius / (other.estar * (0.5 * other.radius) ** 3)
    np.testing.assert_allclose(psi_other, psi_base, rtol=1e-7)


def test_adapted_depth_resolves_a_strip_thousands_of_times_longer_than_wide():
    """At d~ = 1e-9 the contact is ~1e-5 L wide; the adapted grid still puts n_width
    cells across it, and the force is within 0.1 % of its value on a grid twice as fine
    in both directions (measured 1.1e-4)."""
    a = solve_depth(1e-9, n_length=64, n_width=16)
    b = solve_depth(1e-9, n_length=128, n_width=32)
    assert a.grid.dx / a.grid.dy > 1000
    assert a.half_width_max < 1e-4
    assert abs(a.force / b.force - 1) < 1e-3


def test_no_overlap_means_no_contact_and_nan_never_passes():
    """A depth that does not reach the surface gives p = 0 exactly (not NaN reported as
    converged), and a non-finite gap before loading is refused."""
    op, r2, h, a = _sphere(8)
    sol = solve_contact(op, r2 / 2 + 1e-3, 1e-3)
    assert sol.converged and not sol.contact.any() and np.all(sol.pressure == 0)
    bad = r2 / 2 - 0.01
    bad[0, 0] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        solve_contact(op, bad, 0.01)


# --- the work-saving devices of the sweep (issue 20) -------------------------------

@pytest.mark.parametrize("mx, my", [(5, 7), (12, 4)])
def test_column_sums_equal_the_transform(mx, my):
    """SymmetricOperator.add_columns adds K x for an x on a few cells by summing the
    kernel's columns (each cell with its three mirror images) instead of the cosine
    transforms: the same linear map, so equal to rounding (1e-13 of the result),
    corner and edge cells included."""
    rng = np.random.default_rng(1)
    op = SymmetricOperator(mx, my, 0.3, 0.7, backend="scipy")
    u0 = rng.random((mx, my))
    cells = np.array([0, my - 1, (mx - 1) * my, mx * my - 1, my + 2])
    values = rng.standard_normal(cells.size)
    x = np.zeros(mx * my)
    x[cells] = values
    expected = u0 + op(x.reshape(mx, my))
    got = op.add_columns(u0.copy(), cells, values)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13 * np.abs(expected).max())


def test_a_known_start_displacement_and_an_unverified_pass_give_the_same_solution():
    """bounded_cg with kx0 = K x0 (the start's displacement known, its projection on
    p >= 0 corrected) and with verify=False (the caller checks) solves the same
    problem: the pressures agree with a plain solve to the tolerance's effect (a gap
    error of tol d moves p by about tol times its size), and the unverified pass, once
    checked on a fresh K p, meets the tolerance."""
    op, r2, h, a = _sphere(20)
    d, tol = 0.01, 1e-9
    ref = solve_contact(op, r2 / 2 - d, d, tol=tol)
    start = 1.3 * ref.pressure - 0.2 * ref.pressure.max()   # negative in places
    kstart = op(start)
    warm = solve_contact(op, r2 / 2 - d, d, tol=tol, p0=start, kp0=kstart)
    assert warm.converged
    np.testing.assert_allclose(warm.pressure, ref.pressure, atol=1e-6 * ref.pressure.max())
    quick = solve_contact(op, r2 / 2 - d, d, tol=tol, p0=start, kp0=kstart, verify=False)
    gap = op(quick.pressure) + r2 / 2 - d
    assert np.abs(gap[quick.pressure > 0]).max() <= 10 * tol * d
    assert gap[quick.pressure == 0].min() >= -10 * tol * d


def test_the_sweep_on_narrower_strips_solves_the_same_problem():
    """The sweep's savings (the contact iterated on the rows it reaches and checked on
    the overlap strip, the punch on its footprint's rows, starts without an operator
    application) leave the discrete problem unchanged: F and k agree with the plain
    Polonsky-Keer iteration on the whole grid (precondition=False, windows=0) to what
    the tolerance 1e-8 allows (a few 1e-7 relative in k: a punch's error of tol in
    displacement)."""
    new = sweep(3, n=32, steps=12, progress=False, backend="scipy", tol=1e-8)
    old = sweep(3, n=32, steps=12, progress=False, backend="scipy", tol=1e-8,
                precondition=False, windows=0)
    np.testing.assert_allclose(new.force, old.force, rtol=1e-7)
    np.testing.assert_allclose(new.stiffness, old.stiffness, rtol=1e-6)
