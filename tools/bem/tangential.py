"""Tangential contact on the elastic half-space: full stick and Coulomb partial slip.

The uncoupled (Goodman 1962) approximation
------------------------------------------
A shear traction on the surface of a half-space also moves it normally, by
(1 - 2 nu)/(4 pi G) (x - xi)/r^2 per unit force (Johnson 1985, Eq. 3.86c), and a
pressure moves it tangentially. This module neglects both couplings: the normal
pressure p and contact set are those of the frictionless normal problem
(tools.bem.solver, tools.bem.cylinder) and stay fixed while the tangential load acts. The
approximation is exact for nu = 0.5 (incompressible half-space) and for two bodies of
the same material (quasi-identical bodies: the coupling terms cancel), and it is the
assumption of Cattaneo-Mindlin theory and of the MDR's tangential rules (Popov & Hess
2015). One traction component is solved at a time, parallel to the rigid shift
(``direction`` 'x' or 'y'; the other component is zero): Mindlin's "slip parallel to
the load" assumption. For the circle it is exact in full stick (Mindlin 1949: the
bonded circular punch has q_y = 0) and in the stick zone of Cattaneo-Mindlin partial
slip; elsewhere the cross coefficient K_xy of tools.bem.influence is the neglected part.
:func:`coupled_full_stick` solves the two-component full-stick problem (u_y = 0
imposed as well): on the finite cylinder it changed k_t by less than 1e-3 (measured
2e-4 to 8e-4 at d~ = 1e-3, 1e-6 at d~ = 1e-6, nu = 0.3 and 0.5, 96-cell grids;
tests/test_tangential_bem.py).

The discrete problem
--------------------
Cells of a grid carry uniform shear tractions q; the displacement at the cell centres
along the shift is u = K q, K the Cerruti rectangle coefficients
(tools.bem.influence.cerruti_rectangle, K_xx for 'x', K_yy for 'y'), applied by the same
FFT machinery as the normal problem (tools.bem.halfspace: the DC-FFT for any field, the
mirror-symmetric DCT form for fields even in x and y: a uniform shift of a contact set
with both mirror planes gives an even traction, since K_xx and K_yy are even).

Full stick: the contact set S moves rigidly by the shift delta, K_SS q = delta on S.
That is the flat-punch problem with the tangential kernel, solved by
tools.bem.solver.solve_punch; the tangential stiffness k_t = sum(q) A_cell / delta.

Partial slip with Coulomb friction, |q| <= mu p, under a shift history delta_1,
delta_2, ... (each step from the state of the previous one: memory, so unloading and
reloading give hysteresis loops): with s the accumulated slip (s = delta - u on the
contact set), step n solves the bound-constrained quadratic problem

    minimise  1/2 q.K q - q.(delta_n - s_{n-1})   subject to  -mu p <= q <= mu p,

whose optimality conditions are exactly Coulomb's law for the increment: where
|q| < mu p the slip does not change (stick), where q = +mu p (-mu p) the slip
increment s_n - s_{n-1} is >= 0 (<= 0), i.e. the friction traction opposes the
relative motion. ``solve_partial_slip`` solves it by a projected conjugate-gradient
method with both bounds (the constrained CG of Polonsky & Keer 1999, generalised from
one bound p >= 0 to two); convergence is judged on the optimality conditions in
displacement units.

References
----------
Goodman, L. E. (1962), J. Appl. Mech. 29:515-522. Johnson, K. L. (1985), Contact
Mechanics, sections 3.6 and 7.1-7.2 (Cerruti; Cattaneo-Mindlin). Mindlin, R. D.
(1949), J. Appl. Mech. 16:259-268. Polonsky, I. A. and Keer, L. M. (1999), Wear
231:206-219. Pohrt, R. and Li, Q. (2014), Phys. Mesomech. 17:334-340. Popov, V. L. and
Hess, M. (2015), Method of Dimensionality Reduction in Contact Mechanics and Friction,
Springer, chapters 4 and 5.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from linecontact.tangential import mdr_stiffness_ratio

from .halfspace import DCFFTOperator, SymmetricOperator, unfold
from .influence import cerruti_kernel_offsets
from .solver import bounded_cg, solve_contact, solve_punch

DIRECTIONS = ("x", "y")


def _component(direction):
    if direction not in DIRECTIONS:
        raise ValueError(f"direction = {direction!r} is not one of {DIRECTIONS} "
                         "('x': along the cylinder axis, 'y': across it)")
    return "xx" if direction == "x" else "yy"


def shear_modulus_for(estar, nu):
    """Shear modulus G of the elastic half-space whose E* (rigid indenter) is estar.

    .. math:: E^* = \\frac{E}{1-\\nu^2} = \\frac{2G}{1-\\nu}, \\qquad G = \\frac{(1-\\nu) E^*}{2}

    Parameters
    ----------
    estar : float
        Effective modulus E* [Pa].
    nu : float
        Poisson's ratio [-].

    Returns
    -------
    float
        G [Pa].

    Examples
    --------
    >>> shear_modulus_for(1.0, 0.3)
    0.35

    References
    ----------
    Johnson (1985), Contact Mechanics, section 4.2 (E* of one elastic body).
    """
    return 0.5 * (1.0 - nu) * estar


def tangential_operator(nx, ny, dx, dy, shear_modulus, nu, direction, symmetric=True,
                        backend="scipy", workers=None):
    """Free-space tangential operator q -> u along ``direction`` on a grid of cells.

    The operators of tools.bem.halfspace (DC-FFT, or its mirror-symmetric DCT form on one
    quarter when ``symmetric``) with Cerruti's K_xx or K_yy in place of Love's kernel:
    u_i = sum_j K(x_i - x_j) q_j (tools.bem.influence.cerruti_rectangle).

    Parameters
    ----------
    nx, ny : int
        Cells along x and y (of the quarter when ``symmetric``).
    dx, dy : float
        Cell sides [m].
    shear_modulus : float
        G [Pa].
    nu : float
        Poisson's ratio [-].
    direction : {'x', 'y'}
        Traction and displacement component.
    symmetric : bool
        Quarter operator for fields even in x and y (default) or full DC-FFT.

    Returns
    -------
    callable
        ndarray [Pa] -> ndarray [m].

    Notes
    -----
    Exact free-space convolution (zero padding); any cell aspect ratio; 0 <= nu <= 0.5.

    Examples
    --------
    At nu = 0 the operator equals the normal one with E* = 2G:

    >>> from tools.bem.halfspace import SymmetricOperator
    >>> q = np.ones((4, 3))
    >>> ut = tangential_operator(4, 3, 1.0, 0.5, 0.5, 0.0, "x")(q)
    >>> un = SymmetricOperator(4, 3, 1.0, 0.5, estar=1.0)(q)
    >>> bool(np.allclose(ut, un, rtol=1e-12))
    True

    References
    ----------
    Liu, Wang & Liu (2000), Wear 243:101-111 (DC-FFT); Johnson (1985), section 3.6.
    """
    comp = _component(direction)
    cls, m = (SymmetricOperator, 2) if symmetric else (DCFFTOperator, 1)
    kernel = cerruti_kernel_offsets(m * nx, m * ny, dx, dy, shear_modulus, nu, comp)
    op = cls(nx, ny, dx, dy, backend=backend, workers=workers, kernel=kernel)
    op.shear_modulus, op.nu, op.direction = float(shear_modulus), float(nu), direction
    return op


@dataclass
class SlipSolution:
    """State after one tangential load step on an operator's grid."""

    traction: np.ndarray      #: q [Pa] (operator units)
    displacement: np.ndarray  #: u = K q at the cell centres [m]
    slip: np.ndarray          #: accumulated slip s = shift - u on the contact set [m]
    stick: np.ndarray         #: bool: contact cells with |q| < mu p (not at a bound)
    shift: float              #: rigid shift delta [m]
    iterations: int           #: operator applications
    converged: bool
    error: float              #: largest violation of the optimality conditions / scale
    tol: float


def solve_partial_slip(op, pressure, mu, shift, previous=None, tol=1e-8, scale=None,
                       maxiter=None, precondition=True):
    """One load step of Coulomb partial slip: |q| <= mu p, slip memory from ``previous``.

    Minimises 1/2 q.K q - q.(shift - s_prev) over -mu p <= q <= mu p (module
    docstring), by conjugate gradients on the cells strictly inside their bounds,
    with the bounds enforced by projection and cells released from a bound when the
    gradient points inwards (Polonsky & Keer 1999, generalised to two bounds): the
    conjugate-gradient core shared with the normal solver, tools.bem.solver.bounded_cg,
    preconditioned by the operator's circulant inverse when it has one.

    .. math:: u = \\delta - s_{prev} \\; (|q| < \\mu p), \\qquad
              \\mathrm{sign}(\\Delta s) = \\mathrm{sign}(q) \\; (|q| = \\mu p)

    Parameters
    ----------
    op : callable
        Tangential operator q -> u (:func:`tangential_operator`) [Pa -> m].
    pressure : ndarray
        Normal pressure on the same grid [Pa]; its support is the contact set.
    mu : float
        Coefficient of friction [-], > 0.
    shift : float
        Rigid tangential shift of the indenter [m].
    previous : SlipSolution, optional
        State of the previous step (default: virgin state, no slip, q = 0).
    tol : float
        Convergence: largest violation of the optimality conditions (displacement
        error in stick, wrong-signed displacement gap in slip), relative to ``scale``.
    scale : float, optional
        Displacement scale of the tolerance [m]; default the larger of |shift| and the
        change of shift from the previous step.
    maxiter : int, optional
        Operator applications allowed; default 200 + 20 sqrt(cells).
    precondition : bool
        Use the operator's preconditioner (default) or the plain iteration.

    Returns
    -------
    SlipSolution

    Notes
    -----
    Uncoupled (Goodman) approximation: p is fixed. Valid for any mu > 0 and shift;
    beyond gross slip q = +-mu p everywhere.

    Examples
    --------
    A 1-cell grid: the traction is the stick value delta/K_00 capped at mu p.

    >>> op = lambda q: 2.0 * q
    >>> s = solve_partial_slip(op, np.array([[1.0]]), 0.5, 0.4)
    >>> round(float(s.traction[0, 0]), 12), bool(s.stick[0, 0])
    (0.2, True)
    >>> float(solve_partial_slip(op, np.array([[1.0]]), 0.5, 3.0).traction[0, 0])
    0.5

    References
    ----------
    Polonsky & Keer (1999), Wear 231:206-219; Johnson (1985), section 7.2; Popov & Hess
    (2015), chapter 5.
    """
    p = np.asarray(pressure, dtype=float)
    if not mu > 0:
        raise ValueError(f"mu = {mu} must be > 0")
    contact = p > 0
    hi = np.where(contact, mu * p, 0.0)
    lo = -hi
    if previous is None:
        s_prev = np.zeros_like(p)
        q = np.zeros_like(p)
        dshift = abs(shift)
    else:
        s_prev = previous.slip
        q = np.clip(previous.traction, lo, hi)
        dshift = abs(shift - previous.shift)
    b = np.where(contact, shift - s_prev, 0.0)
    if scale is None:
        scale = max(abs(shift), dshift)
    scale = scale if scale > 0 else 1.0
    tol_abs = tol * scale
    if maxiter is None:
        maxiter = 200 + int(20 * np.sqrt(p.size))
    if not contact.any():
        zero = np.zeros_like(p)
        return SlipSolution(zero, zero.copy(), zero.copy(), contact, float(shift), 0,
                            True, 0.0, tol)
    res = bounded_cg(op, b, lo, hi, q, tol=tol_abs, maxiter=maxiter,
                     precondition=precondition)
    q, u = res.x, res.kx
    slip = np.where(contact, shift - u, 0.0)
    return SlipSolution(q, u, slip, res.free, float(shift), res.iterations,
                        res.converged, float(res.error / scale), tol)


def load_path(op, pressure, mu, shifts, tol=1e-8, scale=None, previous=None):
    """Partial slip along a history of shifts, each step from the previous state.

    Monotonic loading: increasing ``shifts``; a fretting cycle: 0 -> u0 -> -u0 -> u0.

    Parameters
    ----------
    op, pressure, mu, tol :
        As :func:`solve_partial_slip`.
    shifts : sequence of float
        Rigid shifts delta_1, delta_2, ... [m].
    scale : float, optional
        Displacement scale of the tolerance [m]; default the largest |shift|.
    previous : SlipSolution, optional
        Starting state (default virgin).

    Returns
    -------
    list of SlipSolution
        One per shift; raises ConvergenceError if a step does not converge.

    Notes
    -----
    Coulomb's law with memory for the uncoupled problem; any shift history. Each step
    uses the previous traction as its start, so small steps cost few iterations.

    Examples
    --------
    One cell, K = 2, p = 1, mu = 0.5: stick up to shift 1 (q = shift/2), slip beyond
    (q = 0.5, slip 0.4 at shift 1.4), and on reversal the traction falls with the
    stick slope again from there:

    >>> op = lambda q: 2.0 * q
    >>> path = load_path(op, np.array([[1.0]]), 0.5, [0.6, 1.4, 1.0])
    >>> [round(float(s.traction[0, 0]), 12) for s in path]
    [0.3, 0.5, 0.3]

    References
    ----------
    Mindlin & Deresiewicz (1953), J. Appl. Mech. 20:327-344.
    """
    from .solver import ConvergenceError
    shifts = np.asarray(shifts, dtype=float)
    scale = float(np.abs(shifts).max()) if scale is None else scale
    out = []
    state = previous
    for delta in shifts:
        state = solve_partial_slip(op, pressure, mu, float(delta), state, tol=tol,
                                   scale=scale)
        if not state.converged:
            raise ConvergenceError(f"partial slip at shift {delta:.6g}: optimality "
                                   f"error {state.error:.3g} > tol = {tol:g} after "
                                   f"{state.iterations} operator applications")
        out.append(state)
    return out


def loop_dissipation(shifts, forces):
    """Energy dissipated around a closed load path: the loop area.

    .. math:: W = \\oint F_t \\, d\\delta \\approx \\sum_i \\tfrac12 (F_i + F_{i+1})
              (\\delta_{i+1} - \\delta_i)

    Parameters
    ----------
    shifts : array_like
        Shifts along the path, first point = last point [m].
    forces : array_like
        Tangential force at each shift [N].

    Returns
    -------
    float
        Dissipated energy per cycle [J] (trapezoid rule; second order in the step).

    Examples
    --------
    A rigid-plastic square loop of force +-1 and amplitude 1 dissipates 4:

    >>> loop_dissipation([-1, 1, 1, -1, -1], [1, 1, -1, -1, 1])
    4.0

    References
    ----------
    Johnson (1985), section 7.3 (oscillating tangential force).
    """
    s = np.asarray(shifts, dtype=float)
    f = np.asarray(forces, dtype=float)
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(s)))


def masing_dissipation(u, f):
    """Dissipation per cycle of amplitude u[-1] from the monotonic law (Masing rule).

    .. math:: W = 8 \\int_0^{u_0} f(s)\\, ds - 4 u_0 f(u_0)

    Parameters
    ----------
    u : array_like
        Shifts from 0 to the amplitude u0, increasing, u[0] = 0 [m].
    f : array_like
        Monotonic tangential force f(u) [N], f(0) = 0.

    Returns
    -------
    float
        W [J] (trapezoid rule).

    Examples
    --------
    A linear law dissipates nothing:

    >>> masing_dissipation([0, 1, 2], [0, 3, 6])
    0.0

    References
    ----------
    Mindlin & Deresiewicz (1953), J. Appl. Mech. 20:327; Popov & Hess (2015), ch. 5.
    """
    u = np.asarray(u, dtype=float)
    f = np.asarray(f, dtype=float)
    return float(8 * np.trapezoid(f, u) - 4 * u[-1] * f[-1])


# --- the finite cylinder --------------------------------------------------------------

@dataclass
class CylinderTangential:
    """Full-stick tangential stiffness of the finite cylinder at one d~ (L = R = E* = 1:
    stiffnesses are k/(E* L))."""

    d_tilde: float
    nu: np.ndarray            #: Poisson's ratios
    kn: float                 #: normal stiffness Psi' = k_n/(E* L), punch on the set
    kt_across: np.ndarray     #: k_t/(E* L), shift across the axis (y), per nu
    kt_along: np.ndarray      #: k_t/(E* L), shift along the axis (x), per nu
    normal: object            #: tools.bem.cylinder.DepthResult (with the pressure field)
    iterations: int
    wall_time: float

    @property
    def ratio_across(self):
        return self.kt_across / self.kn

    @property
    def ratio_along(self):
        return self.kt_along / self.kn


def full_stick_stiffness(pressure, grid, estar, nu, direction, tol=1e-8, backend="scipy",
                         workers=None, p0=None):
    """Full-stick tangential stiffness of a contact set with both mirror planes.

    .. math:: k_t = \\frac{1}{\\delta} \\sum_{S} q\\, A_{cell}, \\qquad K_{SS}\\, q = \\delta

    Parameters
    ----------
    pressure : ndarray
        Quarter pressure field (x > 0, y > 0); its support is the contact set [Pa].
    grid : tools.bem.cylinder.Grid
        The quarter grid (cells mx x my, sides dx, dy [m]).
    estar : float
        E* of the normal problem [Pa]; G = (1 - nu) E*/2 (rigid indenter).
    nu : float
        Poisson's ratio [-].
    direction : {'x', 'y'}
        Shift along x or y.
    tol : float
        Largest displacement error on the contact set relative to the shift.

    Returns
    -------
    (float, tools.bem.solver.Solution)
        k_t [N/m] of the full (four-quarter) contact, and the solver result.

    Notes
    -----
    Uncoupled (Goodman) approximation, one traction component (module docstring);
    0 <= nu <= 0.5; the field must be even in x and y (both mirror planes).

    Examples
    --------
    At nu = 0, k_t equals the normal flat-punch stiffness on the same set:

    >>> from tools.bem.cylinder import Grid
    >>> from tools.bem.halfspace import SymmetricOperator
    >>> g = Grid(6, 6, 0.1, 0.1)
    >>> kt, _ = full_stick_stiffness(np.ones((6, 6)), g, 1.0, 0.0, "x", tol=1e-12)
    >>> kn = 4 * solve_punch(SymmetricOperator(6, 6, 0.1, 0.1), np.ones((6, 6)) > 0,
    ...                      tol=1e-12).pressure.sum() * g.cell_area
    >>> bool(abs(kt / kn - 1) < 1e-10)
    True

    References
    ----------
    Mindlin (1949), J. Appl. Mech. 16:259-268 (bonded punch); Johnson (1985), Eq. 7.43.
    """
    from .solver import ConvergenceError
    op = tangential_operator(grid.mx, grid.my, grid.dx, grid.dy,
                             shear_modulus_for(estar, nu), nu, direction, True, backend,
                             workers)
    S = np.asarray(pressure) > 0
    sol = solve_punch(op, S, tol=tol, p0=p0)
    if not sol.converged:
        raise ConvergenceError(f"full stick ({direction}, nu = {nu}): displacement error "
                               f"{sol.error:.3g} > tol = {tol:g}")
    return 4 * sol.pressure.sum() * grid.cell_area, sol


def coupled_full_stick(contact, dx, dy, estar, nu, tol=1e-10, maxiter=5000):
    """Full-stick stiffness with both traction components: u = (delta, 0) on the set.

    The check of the one-component approximation: solve
    [K_xx K_xy; K_xy K_yy] [q_x; q_y] = [delta; 0] (shift along x) and
    [.; .] = [0; delta] (along y) on the contact set by conjugate gradients (the block
    matrix is symmetric positive definite), with the full DC-FFT (q_y is odd when q_x
    is even, so the mirror-symmetric form does not apply).

    .. math:: k_{t,x} = \\frac{1}{\\delta}\\sum_S q_x A_{cell}, \\qquad
              k_{t,y} = \\frac{1}{\\delta}\\sum_S q_y A_{cell}

    Parameters
    ----------
    contact : ndarray of bool
        Contact set on the full grid (nx x ny cells).
    dx, dy : float
        Cell sides [m].
    estar : float
        E* [Pa]; G = (1 - nu) E*/2.
    nu : float
        Poisson's ratio [-].
    tol : float
        Relative residual of CG [-].

    Returns
    -------
    (float, float)
        k_t along x and along y [N/m], both components of the traction solved for.

    Notes
    -----
    Exact for the uncoupled (Goodman) problem with both tangential components; at
    nu = 0 K_xy = 0 and it equals :func:`full_stick_stiffness`.

    Examples
    --------
    >>> contact = np.ones((4, 4), dtype=bool)
    >>> kx, ky = coupled_full_stick(contact, 0.25, 0.25, 1.0, 0.4)
    >>> bool(abs(kx / ky - 1) < 1e-8)     # a square: the same both ways
    True

    References
    ----------
    Johnson (1985), Eq. 3.86 (Cerruti); Pohrt & Li (2014), Phys. Mesomech. 17:334.
    """
    import scipy.fft as sfft
    from scipy.sparse.linalg import LinearOperator, cg

    from .influence import cerruti_rectangle
    S = np.asarray(contact, dtype=bool)
    nx, ny = S.shape
    ox = np.concatenate([np.arange(nx + 1), -np.arange(nx - 1, 0, -1)]) * dx
    oy = np.concatenate([np.arange(ny + 1), -np.arange(ny - 1, 0, -1)]) * dy
    kernels = cerruti_rectangle(ox[:, None], oy[None, :], dx, dy,
                                shear_modulus_for(estar, nu), nu)
    hxx, hyy, hxy = (sfft.rfft2(k) for k in kernels)
    n = int(S.sum())
    pad = np.zeros((2 * nx, 2 * ny))

    def conv(h, q):
        pad[:nx, :ny] = q
        return sfft.irfft2(h * sfft.rfft2(pad), s=pad.shape)[:nx, :ny]

    def matvec(v):
        qx = np.zeros((nx, ny))
        qy = np.zeros((nx, ny))
        qx[S] = v[:n]
        qy[S] = v[n:]
        return np.concatenate([(conv(hxx, qx) + conv(hxy, qy))[S],
                               (conv(hxy, qx) + conv(hyy, qy))[S]])

    A = LinearOperator((2 * n, 2 * n), matvec=matvec)
    out = []
    for first in (True, False):
        b = np.zeros(2 * n)
        b[:n] = 1.0 if first else 0.0
        b[n:] = 0.0 if first else 1.0
        sol, info = cg(A, b, rtol=tol, maxiter=maxiter)
        if info != 0:
            from .solver import ConvergenceError
            raise ConvergenceError(f"coupled full stick: CG stopped with info = {info}")
        out.append((sol[:n] if first else sol[n:]).sum() * dx * dy)
    return out[0], out[1]


def cylinder_full_stick(d_tilde, nus=(0.0, 0.25, 0.3, 0.4, 0.5), n_length=128,
                        n_width=16, tol=1e-8, workers=1):
    """k_t/k_n of the finite cylinder in both directions at one d~ = d R/L^2.

    Normal contact on the adapted grid of tools.bem.cylinder.solve_depth (L = R = E* = 1),
    then, on its contact set, the flat-punch problems with Love's kernel (k_n) and
    Cerruti's K_yy (across) and K_xx (along) for every nu.

    Parameters
    ----------
    d_tilde : float
        Dimensionless depth d R/L^2 [-].
    nus : sequence of float
        Poisson's ratios [-].
    n_length, n_width : int
        Cells along the half-length and across the contact half-width.
    tol : float
        Solver tolerance (gap / displacement error relative to d or the unit shift).

    Returns
    -------
    CylinderTangential

    Notes
    -----
    Valid where the parabolic gap is (d << R) and within the uncoupled approximation;
    any d~ > 0 (each depth on its own grid). Discretisation: see
    tables/tangential_cylinder.csv (change from N = 256/32 to 2N: median 4e-5, at
    most 1e-3).

    Examples
    --------
    >>> r = cylinder_full_stick(1e-3, nus=(0.0,), n_length=16, n_width=8)
    >>> bool(abs(r.ratio_across[0] - 1) < 1e-6)    # nu = 0: k_t = k_n exactly
    True

    References
    ----------
    Li & Popov (2017), section 2 (the finite cylinder); Goodman (1962).
    """
    from .cylinder import solve_depth
    t0 = time.perf_counter()
    res = solve_depth(d_tilde, n_length, n_width, tol=tol, workers=workers, fields=True)
    its = res.iterations
    kt = {"x": [], "y": []}
    for direction in ("y", "x"):
        prev = None
        for nu in nus:
            k, sol = full_stick_stiffness(res.pressure, res.grid, 1.0, nu, direction,
                                          tol=tol, workers=workers, p0=prev)
            prev = sol.pressure
            its += sol.iterations
            kt[direction].append(k)
    return CylinderTangential(float(d_tilde), np.asarray(nus, float), res.stiffness,
                              np.array(kt["y"]), np.array(kt["x"]), res, its,
                              time.perf_counter() - t0)


def normal_force_on_grid(grid, depths, estar=1.0, radius=1.0, tol=1e-9, workers=1):
    """F(d') of the cylinder on a fixed quarter grid, for the MDR's partial-slip law.

    Parameters
    ----------
    grid : tools.bem.cylinder.Grid
        Quarter grid [m].
    depths : sequence of float
        Depths d' [m], each solved warm-started from the previous (deepest first is
        not required).
    estar, radius : float
        E* [Pa] and R [m].

    Returns
    -------
    ndarray
        F(d') [N] (four quarters).

    Raises
    ------
    ConvergenceError
        A depth whose contact solution misses `tol` (its force would be wrong).

    Notes
    -----
    F(d') on the grid of the deepest depth: contacts at d' < d are resolved by fewer
    cells (the laws of the study are compared with the BEM on the same grid).

    Examples
    --------
    >>> from tools.bem.cylinder import Grid
    >>> g = Grid(8, 8, 0.5 / 8, 0.2 / 8)
    >>> F = normal_force_on_grid(g, [0.0, 0.01, 0.02])
    >>> bool(F[0] == 0 and 0 < F[1] < F[2])
    True

    References
    ----------
    Polonsky & Keer (1999) (solver); Li & Popov (2017), section 2.
    """
    op = SymmetricOperator(grid.mx, grid.my, grid.dx, grid.dy, estar, "scipy", workers)
    h = np.broadcast_to(grid.y ** 2 / (2 * radius), (grid.mx, grid.my))
    out = []
    p0 = None
    for d in depths:
        if d <= 0:
            out.append(0.0)
            continue
        sol = solve_contact(op, h - d, d, tol=tol, p0=p0)
        if not sol.converged:
            from .solver import ConvergenceError
            raise ConvergenceError(f"normal contact at d' = {d:.6g} m: gap error "
                                   f"{sol.error:.3g} d > tol = {tol:g} d on "
                                   f"{grid.describe()}")
        p0 = sol.pressure if sol.pressure.any() else None
        out.append(4 * sol.pressure.sum() * grid.cell_area)
    return np.array(out)


def cylinder_partial_slip(normal, nu, direction, fractions, mu=1.0, tol=1e-8, workers=1,
                          cycle=False):
    """Monotonic partial-slip curve of the cylinder (and optionally one full cycle).

    Shifts are fractions of the MDR's gross-slip shift u_gs = mu E* d/G* (Popov & Hess
    2015, ch. 5). The BEM curve is compared with the MDR's law
    F_t = mu [F(d) - F(d - G* u/(mu E*))], F(d') from the BEM on the same grid.

    Parameters
    ----------
    normal : tools.bem.cylinder.DepthResult
        Normal solution with its quarter pressure field (L = R = E* = 1).
    nu : float
        Poisson's ratio [-].
    direction : {'x', 'y'}
    fractions : sequence of float
        Shifts / u_gs, increasing, > 0 [-].
    mu : float
        Friction coefficient [-] (the curves scale with it exactly).
    cycle : bool
        Also run unloading to -u_max and reloading to +u_max (Masing check).

    Returns
    -------
    dict
        'u' shifts / u_gs, 'ft_bem', 'ft_mdr' forces / (mu F), 'force' F(d)
        (dimensionless), and with ``cycle`` 'loop_u', 'loop_f'.

    Notes
    -----
    Uncoupled (Goodman), Coulomb friction with one traction component; at nu = 0 the
    BEM curve equals the MDR law exactly (tests/test_tangential_bem.py).

    Examples
    --------
    >>> r = cylinder_full_stick(1e-3, nus=(0.0,), n_length=16, n_width=8)
    >>> c = cylinder_partial_slip(r.normal, 0.0, "y", [0.5])
    >>> bool(abs(c["ft_bem"][0] - c["ft_mdr"][0]) < 1e-6)
    True

    References
    ----------
    Popov & Hess (2015), chapter 5 (the MDR's partial slip); Johnson (1985), 7.2.
    """
    grid = normal.grid
    p = normal.pressure
    d = normal.d_tilde
    F = 4 * p.sum() * grid.cell_area
    gstar = mdr_stiffness_ratio(nu)     # G*/E*, E* = 1
    u_gs = mu * d / gstar
    op = tangential_operator(grid.mx, grid.my, grid.dx, grid.dy, shear_modulus_for(1.0, nu),
                             nu, direction, True, "scipy", workers)
    shifts = u_gs * np.asarray(fractions, dtype=float)
    states = load_path(op, p, mu, shifts, tol=tol, scale=u_gs)
    ft = np.array([4 * s.traction.sum() * grid.cell_area for s in states])
    dprime = d - gstar * shifts / mu
    f_low = normal_force_on_grid(grid, np.maximum(dprime, 0.0), tol=tol, workers=workers)
    out = dict(u=np.asarray(fractions, float), ft_bem=ft / (mu * F),
               ft_mdr=(F - f_low) / F, force=F, iterations=sum(s.iterations for s in states))
    if cycle:
        u0 = shifts[-1]
        n = len(shifts)
        down = np.linspace(u0, -u0, 2 * n + 1)[1:]
        up = np.linspace(-u0, u0, 2 * n + 1)[1:]
        path = np.concatenate([down, up])
        loop = load_path(op, p, mu, path, tol=tol, scale=u_gs, previous=states[-1])
        out["loop_u"] = np.concatenate([[u0], path]) / u_gs
        out["loop_f"] = np.concatenate(
            [[ft[-1]], [4 * s.traction.sum() * grid.cell_area for s in loop]]) / (mu * F)
    return out


__all__ = ["DIRECTIONS", "shear_modulus_for", "tangential_operator",
           "SlipSolution", "solve_partial_slip", "load_path", "loop_dissipation",
           "masing_dissipation", "CylinderTangential", "full_stick_stiffness",
           "coupled_full_stick",
           "cylinder_full_stick", "normal_force_on_grid", "cylinder_partial_slip",
           "unfold"]
