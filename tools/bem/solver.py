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


def _gap_error(g, S):
    """Largest |gap| on the contact set and largest penetration outside it; NaN if any
    gap is NaN (so that a NaN state can never pass as converged: NaN <= tol is False)."""
    return float(np.max([np.abs(g[S]).max(initial=0.0), -g[~S].min(initial=0.0),
                         0.0 if np.all(np.isfinite(g)) else np.nan]))


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


def solve_contact(op, separation, scale, tol=1e-6, p0=None, maxiter=None):
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

    Returns
    -------
    Solution
    """
    s = np.asarray(separation, dtype=float)
    if not np.all(np.isfinite(s)):
        raise ValueError("separation has non-finite values")
    if maxiter is None:
        maxiter = 50 + int(10 * np.sqrt(s.size))
    if not np.any(s < 0):
        # the indenter does not reach the surface: no contact, exactly
        zero = np.zeros_like(s)
        return Solution(zero, zero.copy(), zero > 0, 0, True, 0.0, tol)
    if p0 is None:
        p = np.where(s < 0, 1e-3, 0.0)
        u = op(p)
        # scale the start so that the mean displacement matches the mean interference
        inside = s < 0
        p *= max(-s[inside].mean(), 1e-300) / max(u[inside].mean(), 1e-300)
    else:
        p = np.maximum(np.asarray(p0, dtype=float), 0.0)
    u = op(p)
    napply = 1
    t = np.zeros_like(p)
    g_old = 1.0
    delta = 0.0
    tol_abs = tol * scale
    err = np.inf
    while napply < maxiter:
        g = u + s
        S = p > 0
        err = _gap_error(g, S)
        if err <= tol_abs:
            break
        G = _dot(g[S], g[S])
        if delta > 0:
            t = np.where(S, g + delta * (G / g_old) * t, 0.0)
        else:
            t = np.where(S, g, 0.0)
        g_old = G
        r = op(t)
        napply += 1
        rS = _dot(r[S], t[S])
        if rS <= 0:
            break
        tau = _dot(g[S], t[S]) / rS
        p_new = p - tau * t
        clipped = p_new < 0
        p_new[clipped] = 0.0
        overlap = (~S) & (g < 0)
        if overlap.any():
            p_new[overlap] = -tau * g[overlap]
            delta = 0.0
        else:
            delta = 1.0
        if clipped.any() or overlap.any():
            p = p_new
            u = op(p)
            napply += 1
        else:
            # active set unchanged: K p_new = u - tau K t exactly
            p = p_new
            u = u - tau * r
    # final check on a freshly computed displacement
    u = op(p)
    g = u + s
    S = p > 0
    err = _gap_error(g, S)
    return Solution(p, u, S, napply + 1, bool(err <= tol_abs), float(err / scale), tol)


def solve_punch(op, footprint, tol=1e-8, p0=None, maxiter=None):
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

    Returns
    -------
    Solution
        ``pressure.sum() * cell area`` is the punch force at unit depth, i.e. the
        stiffness [N/m] (operator units).
    """
    S = np.asarray(footprint, dtype=bool)
    if maxiter is None:
        maxiter = 50 + int(10 * np.sqrt(S.size))
    p = np.zeros(S.shape) if p0 is None else np.where(S, p0, 0.0)
    if not S.any():
        return Solution(p, np.zeros_like(p), S, 0, True, 0.0, tol)
    u = op(p)
    napply = 1
    res = np.where(S, 1.0 - u, 0.0)
    z = res.copy()
    rr = _dot(res[S], res[S])
    err = np.abs(res[S]).max()
    while err > tol and napply < maxiter:
        q = np.where(S, op(z), 0.0)
        napply += 1
        alpha = rr / _dot(z[S], q[S])
        p += alpha * z
        res -= alpha * q
        rr_new = _dot(res[S], res[S])
        z = res + (rr_new / rr) * z
        rr = rr_new
        err = np.abs(res[S]).max()
    u = op(p)
    err = float(np.abs(1.0 - u[S]).max())
    return Solution(p, u, S, napply + 1, bool(err <= tol), err, tol)
