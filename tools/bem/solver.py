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
    NaN if any gradient is NaN (so that a NaN state never passes: NaN <= tol is False).
    ``at_lo`` or ``at_hi`` None: no cell is at that bound. Masked reductions, no copies
    (this runs once per iteration on the whole grid)."""
    err = max(float(np.max(g, where=free, initial=0.0)),
              -float(np.min(g, where=free, initial=0.0)))
    if at_lo is not None:
        err = max(err, -float(np.min(g, where=at_lo, initial=0.0)))
    if at_hi is not None:
        err = max(err, float(np.max(g, where=at_hi, initial=0.0)))
    if not np.isfinite(np.add.reduce(g, axis=None)):
        return float("nan")
    return err


def _state(x, movable, lo, hi, has_lo, has_hi):
    """(free, at_lo, at_hi): the movable cells strictly inside their bounds, at or below
    the lower one, at or above the upper one (None where no movable cell has that
    bound)."""
    at_lo = movable & (x <= lo) if has_lo else None
    at_hi = movable & (x >= hi) if has_hi else None
    if at_lo is None and at_hi is None:
        return movable, None, None
    free = movable.copy()
    if at_lo is not None:
        free &= ~at_lo
    if at_hi is not None:
        free &= ~at_hi
    return free, at_lo, at_hi


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
    columns: int = 0       #: single-cell corrections summed directly (``op.add_columns``)


def _correct(op, u, x, changed, delta, limit):
    """u + K (x - x_lin), where x differs from x_lin only on the cells ``changed`` (by
    ``delta`` there): by the operator's direct column sums when they are at most
    ``limit`` cells (``op.add_columns``), else K x afresh. Returns (u, operator
    applications, columns summed, whether u is freshly computed)."""
    n = int(np.count_nonzero(changed))
    if n == 0:
        return u, 0, 0, False
    if n <= limit:
        return op.add_columns(u, np.flatnonzero(changed), delta), 0, n, False
    return op(x), 1, 0, True


def bounded_cg(op, b, lower, upper, x0=None, tol=1e-8, maxiter=None,
               precondition=True, kx0=None, verify=True):
    """min 1/2 x.Kx - b.x over lower <= x <= upper: the one conjugate-gradient core of
    the normal, punch and tangential solvers.

    The bound-constrained conjugate gradients of Polonsky & Keer (1999): CG steps on
    the free cells (strictly inside their bounds), the iterate projected onto the
    bounds after each step, cells released from a bound where the gradient points
    inwards (the conjugacy is then restarted); the gradient g = K x - b is updated as
    g - tau K t, plus, for the few cells a projection moved (typically one to three
    cells along the contact's edge), the kernel's columns summed directly when the
    operator offers it (``op.add_columns``, ``op.sparse_limit`` cells at most), and is
    recomputed from K x otherwise. With a
    preconditioner M ~ K^-1 (``op.precondition``, the circulant inverse of the
    half-space operator, tools.bem.halfspace) the direction is the preconditioned
    gradient restricted to the free cells, as in Vollebregt's preconditioned
    bound-constrained CG (2014): K is a first-order smoothing operator (its symbol
    ~ 1/|k|), so plain CG needs a number of steps growing with the grid; with its
    inverse as preconditioner the count is nearly independent of the grid.

    Converged when the largest violation of the optimality conditions (|g| on the free
    cells; g < 0 at a lower bound; g > 0 at an upper bound) is at most ``tol``, evaluated
    on a freshly computed K x (if the updated gradient met the tolerance and the fresh
    one does not, the iteration goes on from the fresh one). Cells with lower == upper
    are fixed.

    Parameters
    ----------
    op : callable
        x -> K x, symmetric positive definite; its ``precondition`` method (optional)
        applies M ~ K^-1; its ``add_columns(u, cells, values)`` (optional) adds K x for
        an x nonzero on a few cells.
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
    kx0 : ndarray, optional
        K x0 when the caller knows it (e.g. a linear combination of earlier solutions'
        ``kx``), which saves the start's operator application; the projection of x0 on
        the bounds is accounted for.
    verify : bool
        Check convergence on a freshly computed K x (default). False: stop when the
        updated gradient meets the tolerance and return that K x, for a caller that
        verifies the result itself (a first pass on a narrower strip of the grid,
        tools.bem.cylinder.sweep).

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
    has_lo = bool(np.any(movable & (lo > -np.inf)))
    has_hi = bool(np.any(movable & (hi < np.inf)))
    if maxiter is None:
        maxiter = 50 + int(10 * np.sqrt(b.size))
    M = getattr(op, "precondition", None) if precondition else None
    limit = getattr(op, "sparse_limit", 0) if hasattr(op, "add_columns") else 0
    x = np.zeros(b.shape) if x0 is None else np.asarray(x0, dtype=float).copy()
    napply = 0
    ncols = 0
    if kx0 is None:
        np.clip(x, lo, hi, out=x)
        u = op(x)
        napply = 1
        fresh = True
    else:
        u = np.array(kx0, dtype=float)
        if u.shape != b.shape:
            raise ValueError(f"kx0 shape = {u.shape} is not the shape {b.shape} of b")
        xc = np.clip(x, lo, hi)
        changed = xc != x
        u, a, c, fresh = _correct(op, u, xc, changed, xc[changed] - x[changed], limit)
        napply += a
        ncols += c
        x = xc
    nprec = 0
    t = np.zeros_like(x)
    rho_old = 1.0
    restart = True
    err = np.inf
    kdiag = None
    while True:
        g = u - b
        free, at_lo, at_hi = _state(x, movable, lo, hi, has_lo, has_hi)
        err = _violation(g, free, at_lo, at_hi)
        if not err > tol:       # converged (NaN stops below)
            if fresh or not verify:
                break
            u = op(x)           # check on a fresh K x; go on from it if it fails
            napply += 1
            fresh = True
            restart = True
            continue
        if not np.isfinite(err) or napply >= maxiter:
            break
        release = None
        if at_lo is not None:
            release = at_lo & (g < 0)
        if at_hi is not None:
            release = (at_hi & (g > 0)) if release is None else release | (at_hi & (g > 0))
        if release is not None and not release.any():
            release = None
        jacobi = None
        if release is not None:
            restart = True
            active = free | release
        else:
            active = free
        ga = g * active
        if M is not None:
            z = M(ga)
            nprec += 1
            z *= active
            if release is not None:
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
            t *= rho / rho_old
            t += z
            t *= active
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
        if has_lo or has_hi:
            changed = (x_new < lo) | (x_new > hi)
            np.clip(x_new, lo, hi, out=x_new)
        else:
            changed = np.zeros(x.shape, dtype=bool)
        if jacobi is not None:
            changed |= jacobi
        # u = K x_new: K of the CG step, plus K of the cells the projection or the
        # Jacobi step moved off that step
        delta = x_new[changed] - (x[changed] - tau * t[changed])
        x = x_new
        u = u - tau * r
        u, a, c, fresh = _correct(op, u, x, changed, delta, limit)
        napply += a
        ncols += c
    if not fresh and (verify or not err <= tol):
        u = op(x)
        napply += 1
    g = u - b
    free, at_lo, at_hi = _state(x, movable, lo, hi, has_lo, has_hi)
    err = _violation(g, free, at_lo, at_hi)
    return BoundedCGResult(x, u, free, napply, nprec, bool(err <= tol), float(err), ncols)


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
                  precondition=True, kp0=None, verify=True):
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
    kp0 : ndarray, optional
        K p0, when known (a linear combination of earlier solutions' displacements):
        saves an operator application (:func:`bounded_cg`, ``kx0``).
    verify : bool
        False: the tolerance is checked on the updated displacement only, for a caller
        that verifies the result itself (:func:`bounded_cg`).

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
        c = max(-s[inside].mean(), 1e-300) / max(u[inside].mean(), 1e-300)
        p *= c
        kp0 = u * c
    else:
        p = np.asarray(p0, dtype=float)     # bounded_cg cuts the negative values
    if maxiter is not None:
        maxiter = maxiter - napply
    res = bounded_cg(op, -s, 0.0, np.inf, p, tol=tol * scale, maxiter=maxiter,
                     precondition=precondition, kx0=kp0, verify=verify)
    return Solution(res.x, res.kx, res.x > 0, napply + res.iterations, res.converged,
                    float(res.error / scale), tol)


def solve_punch(op, footprint, tol=1e-8, p0=None, maxiter=None, precondition=True,
                kp0=None):
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
    kp0 : ndarray, optional
        K p0, when known (e.g. the previous punch's displacement, p0 its pressure):
        saves an operator application; p0 outside the footprint is set to zero and
        accounted for (:func:`bounded_cg`, ``kx0``).

    Returns
    -------
    Solution
        ``pressure.sum() * cell area`` is the punch force at unit depth, i.e. the
        stiffness [N/m] (operator units).
    """
    S = np.asarray(footprint, dtype=bool)
    if p0 is None:
        p = np.zeros(S.shape)
    elif kp0 is None:
        p = np.where(S, p0, 0.0)
    else:
        p = np.asarray(p0, dtype=float)     # bounded_cg zeroes it outside S
    if not S.any():
        return Solution(np.zeros(S.shape), np.zeros(S.shape), S, 0, True, 0.0, tol)
    big = np.where(S, np.inf, 0.0)
    res = bounded_cg(op, S.astype(float), -big, big, p, tol=tol, maxiter=maxiter,
                     precondition=precondition, kx0=None if p0 is None else kp0)
    return Solution(res.x, res.kx, S, res.iterations, res.converged, res.error, tol)
