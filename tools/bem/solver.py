"""Contact solvers on a half-space operator (unit-free).

``solve_contact``
    Frictionless, non-adhesive normal contact under displacement control: find cell
    pressures p >= 0 such that the gap g = K p + s (s = h - d, the gap before
    deformation) satisfies g >= 0, p g = 0. The constrained conjugate-gradient method
    of Polonsky & Keer (1999, Wear 231:206-219), in its displacement-controlled form:
    the load-balance step of the original (which corrects the mean gap for a given
    total force) is dropped, because the rigid-body approach d is given.

    Convergence, in physical terms: the largest |gap| over the contact set and the
    largest penetration outside it are both at most ``tol * scale`` (scale: the
    depth d), evaluated on a freshly computed displacement K p.

``solve_punch``
    A rigid flat punch with a given footprint S at unit depth: K_SS p = 1 on S,
    p = 0 elsewhere, by plain conjugate gradients (K_SS is symmetric positive
    definite). Its force is the stiffness dF/dd of the contact problem whose contact
    set is S: d(K_SS^-1 (d - h)) / dd = K_SS^-1 1. Converged when the largest
    displacement error on S is at most ``tol`` (relative to the unit depth).

The operator is any callable p -> K p on a fixed grid (see tools.bem.halfspace); the
solvers do not know units, cell sizes or symmetry.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def _dot(a, b):
    """Inner product without BLAS: OpenBLAS's threads busy-wait between the many short
    calls of a CG loop and collapse when the cores are shared (measured 20x slower
    under load)."""
    return float(np.einsum("i,i->", a, b))


def _violation(g, free, at_lo, at_hi):
    """Largest violation of the optimality conditions of min 1/2 x.Kx - b.x on
    lo <= x <= hi, with g = K x - b: |g| on the free cells, the gradient pushing a cell
    at its lower bound down (g < 0 there: a penetration) or one at its upper bound up;
    NaN if any gradient is NaN (so that a NaN state never passes: NaN <= tol is False)."""
    return float(np.max([np.abs(g[free]).max(initial=0.0), -g[at_lo].min(initial=0.0),
                         g[at_hi].max(initial=0.0),
                         0.0 if np.all(np.isfinite(g)) else np.nan]))


@dataclass
class BoundedCGResult:
    """Result of :func:`bounded_cg`."""

    x: np.ndarray          #: the minimiser (pressures or tractions) [Pa]
    kx: np.ndarray         #: K x, freshly computed [m]
    free: np.ndarray       #: bool: cells strictly inside their bounds
    iterations: int        #: operator applications (preconditioner applications not counted)
    preconditioner_calls: int  #: preconditioner applications
    converged: bool
    error: float           #: largest violation of the optimality conditions [m]


def bounded_cg(op, b, lower, upper, x0=None, tol=1e-8, maxiter=None,
               precondition=True):
    """min 1/2 x.Kx - b.x over lower <= x <= upper: the one conjugate-gradient core of
    the normal, punch and tangential solvers.

    The bound-constrained conjugate gradients of Polonsky & Keer (1999): CG steps on
    the free cells (strictly inside their bounds), the iterate projected onto the
    bounds after each step, cells released from a bound where the gradient points
    inwards (the conjugacy is then restarted); the gradient g = K x - b is updated as
    g - tau K t while no cell changes its state and recomputed from K x otherwise. With a
    preconditioner M ~ K^-1 (``op.precondition``, the circulant inverse of the
    half-space operator, tools.bem.halfspace) the direction is the preconditioned
    gradient restricted to the free cells, as in Vollebregt's preconditioned
    bound-constrained CG (2014): K is a first-order smoothing operator (its symbol
    ~ 1/|k|), so plain CG needs a number of steps growing with the grid; with its
    inverse as preconditioner the count is nearly independent of the grid.

    Converged when the largest violation of the optimality conditions (|g| on the free
    cells; g < 0 at a lower bound; g > 0 at an upper bound) is at most ``tol``, evaluated
    on a freshly computed K x. Cells with lower == upper are fixed.

    Parameters
    ----------
    op : callable
        x -> K x, symmetric positive definite; its ``precondition`` method (optional)
        applies M ~ K^-1.
    b : ndarray
        Linear term [m].
    lower, upper : ndarray or float
        Bounds (may be -inf / +inf) [Pa].
    x0 : ndarray, optional
        Start (projected on the bounds); default 0 projected.
    tol : float
        Absolute tolerance on the violation [m].
    maxiter : int, optional
        Operator applications allowed; default 50 + 10 sqrt(cells).
    precondition : bool
        Use ``op.precondition`` when the operator has one.

    Returns
    -------
    BoundedCGResult

    References
    ----------
    Polonsky & Keer (1999), Wear 231:206-219; Vollebregt (2014), J. Optim. Theory Appl.
    162:931-953 (bound-constrained CG with a preconditioner).
    """
    b = np.asarray(b, dtype=float)
    lo = np.broadcast_to(np.asarray(lower, dtype=float), b.shape)
    hi = np.broadcast_to(np.asarray(upper, dtype=float), b.shape)
    movable = lo < hi
    if maxiter is None:
        maxiter = 50 + int(10 * np.sqrt(b.size))
    M = getattr(op, "precondition", None) if precondition else None
    x = np.zeros(b.shape) if x0 is None else np.asarray(x0, dtype=float).copy()
    np.clip(x, lo, hi, out=x)
    u = op(x)
    napply = 1
    nprec = 0
    t = np.zeros_like(x)
    rho_old = 1.0
    restart = True
    err = np.inf
    kdiag = None
    while napply < maxiter:
        g = u - b
        free = movable & (x > lo) & (x < hi)
        at_lo = movable & ~free & (x <= lo)
        at_hi = movable & ~free & (x >= hi)
        err = _violation(g, free, at_lo, at_hi)
        if not err > tol:       # converged (NaN stops below)
            break
        if not np.isfinite(err):
            break
        release = (at_lo & (g < 0)) | (at_hi & (g > 0))
        jacobi = None
        if release.any():
            restart = True
        active = free | release
        ga = np.where(active, g, 0.0)
        if M is not None:
            z = M(ga)
            nprec += 1
            z[~active] = 0.0
            if release.any():
                # a released cell joins the free set only where the preconditioned
                # direction moves it off its bound (-z has the sign of -g there);
                # the others wait for a later iteration. If none would move, they
                # take the single-cell (Jacobi) step instead.
                wrong = release & (z * g <= 0)
                if wrong.all(where=release):
                    jacobi = release
                z[wrong] = 0.0
                ga[wrong] = 0.0
        else:
            z = ga
        rho = _dot(ga.ravel(), z.ravel())
        if restart or rho_old <= 0:
            t = z
        else:
            t = np.where(active, z + (rho / rho_old) * t, 0.0)
        rho_old = rho
        restart = False
        r = op(t)
        napply += 1
        tr = _dot(t.ravel(), r.ravel())
        if tr > 0:
            tau = _dot(ga.ravel(), t.ravel()) / tr
        elif tr == 0 and jacobi is not None:
            tau = 0.0          # nothing free: only the Jacobi release moves
        else:
            break
        x_new = x - tau * t
        if jacobi is not None:
            if kdiag is None:
                kdiag = _diagonal(op, b.shape)
            x_new[jacobi] = x[jacobi] - g[jacobi] / kdiag
        clipped = (x_new < lo) | (x_new > hi)
        np.clip(x_new, lo, hi, out=x_new)
        x = x_new
        if clipped.any() or jacobi is not None:
            u = op(x)
            napply += 1
        else:
            u = u - tau * r
    u = op(x)
    g = u - b
    free = movable & (x > lo) & (x < hi)
    err = _violation(g, free, movable & ~free & (x <= lo), movable & ~free & (x >= hi))
    return BoundedCGResult(x, u, free, napply + 1, nprec, bool(err <= tol), float(err))


def _diagonal(op, shape):
    """K_00, the self-influence of a cell (every cell has the same on a uniform grid)."""
    e = np.zeros(shape)
    e[(0,) * len(shape)] = 1.0
    return float(op(e)[(0,) * len(shape)])


class ConvergenceError(RuntimeError):
    """A solver stopped at its iteration limit without meeting its tolerance."""


@dataclass
class Solution:
    """Result of a solver on the operator's grid."""

    pressure: np.ndarray      #: cell pressures [Pa] (operator units)
    displacement: np.ndarray  #: K p at the cell centres [m]
    contact: np.ndarray       #: boolean contact set (p > 0)
    iterations: int           #: operator applications used
    converged: bool           #: tolerance met
    error: float              #: achieved error, same measure as tol
    tol: float                #: requested tolerance


def solve_contact(op, separation, scale, tol=1e-6, p0=None, maxiter=None,
                  precondition=True):
    """Polonsky-Keer CG for p >= 0, g = K p + separation >= 0, p g = 0.

    Parameters
    ----------
    op : callable
        Half-space operator, pressure -> displacement.
    separation : ndarray
        Gap before deformation, h - d, at the cell centres [m]; negative where the
        rigid indenter overlaps the undeformed surface.
    scale : float
        Length that sets the tolerance, normally the depth d [m].
    tol : float
        Relative tolerance on the gap in contact and on the penetration outside it.
    p0 : ndarray, optional
        Initial pressures (e.g. the previous load step). Negative values are cut.
        Default: a small uniform pressure where separation < 0.
    maxiter : int, optional
        Operator applications allowed; default 50 + 10 * sqrt(cells).
    precondition : bool
        Precondition with ``op.precondition`` when the operator has one
        (:func:`bounded_cg`); False: the plain Polonsky-Keer iteration.

    Returns
    -------
    Solution
    """
    s = np.asarray(separation, dtype=float)
    if not np.all(np.isfinite(s)):
        raise ValueError("separation has non-finite values")
    if not np.any(s < 0):
        # the indenter does not reach the surface: no contact, exactly
        zero = np.zeros_like(s)
        return Solution(zero, zero.copy(), zero > 0, 0, True, 0.0, tol)
    napply = 0
    if p0 is None:
        p = np.where(s < 0, 1e-3, 0.0)
        u = op(p)
        napply = 1
        # scale the start so that the mean displacement matches the mean interference
        inside = s < 0
        p *= max(-s[inside].mean(), 1e-300) / max(u[inside].mean(), 1e-300)
    else:
        p = np.maximum(np.asarray(p0, dtype=float), 0.0)
    if maxiter is not None:
        maxiter = maxiter - napply
    res = bounded_cg(op, -s, 0.0, np.inf, p, tol=tol * scale, maxiter=maxiter,
                     precondition=precondition)
    return Solution(res.x, res.kx, res.x > 0, napply + res.iterations, res.converged,
                    float(res.error / scale), tol)


def solve_punch(op, footprint, tol=1e-8, p0=None, maxiter=None, precondition=True):
    """Pressures of a rigid flat punch of the given footprint at unit depth.

    Parameters
    ----------
    op : callable
        Half-space operator.
    footprint : ndarray of bool
        Cells in contact.
    tol : float
        Largest displacement error on the footprint, relative to the unit depth.
    p0 : ndarray, optional
        Initial pressures (e.g. contact pressure / depth).
    maxiter : int, optional
        Operator applications allowed; default 50 + 10 * sqrt(cells).
    precondition : bool
        Precondition with ``op.precondition`` when the operator has one
        (:func:`bounded_cg`); False: the plain Polonsky-Keer iteration.

    Returns
    -------
    Solution
        ``pressure.sum() * cell area`` is the punch force at unit depth, i.e. the
        stiffness [N/m] (operator units).
    """
    S = np.asarray(footprint, dtype=bool)
    p = np.zeros(S.shape) if p0 is None else np.where(S, p0, 0.0)
    if not S.any():
        return Solution(p, np.zeros_like(p), S, 0, True, 0.0, tol)
    big = np.where(S, np.inf, 0.0)
    res = bounded_cg(op, S.astype(float), -big, big, p, tol=tol, maxiter=maxiter,
                     precondition=precondition)
    return Solution(res.x, res.kx, S, res.iterations, res.converged, res.error, tol)
