"""Compiled loops of the coupled-slice equations (numba, optional; ``engine="numba"``).

:meth:`SliceEquations.kernels <linecontact.roller.slices.SliceEquations.kernels>` and
:meth:`~linecontact.roller.slices.SliceEquations.linearised` as one pass over the
(target, source) pairs each, with the arithmetic of the numpy code in
:mod:`linecontact.roller.slices`, which stays the reference and the fallback: the same
cached unit geometry (near and far edge distances, their log ratio, the far-field
power differences G), the same series coefficients
(:func:`~linecontact.roller.kernel.far_field_coefficients`) and the same cubic spline
(:func:`~linecontact.roller.kernel.spline_table`), the same split into far field,
near band and diagonal. Two differences, both below 1e-15 of each matrix's scale:
sums run in another order, and the far-field sum of a pair stops once the next
power of (b/t)^2 at its near edge is below 1e-18 (the numpy code always takes all
14 terms; at t/b = 3 it needs them, from t/b = 30 four do). Rows that are only
targets (not loaded) get A alone, and the Jacobian, residual and grid terms are
assembled in the same pass, without the four intermediate matrices.

A spline argument outside the table (tau < 1e-4 or >= 1e4, which the numpy code
evaluates by series or quadrature) makes a function return False: the caller then
takes the numpy path for that call.

Imported only when the compiled engine is asked for (importing numba costs a few
hundred ms; the compiled code is cached on disk next to this file, or in numba's
user-wide cache where the package is read-only; docs/profiled_rollers.md, "Engines").
"""
from __future__ import annotations

import warnings

import numba
import numpy as np

from .kernel import spline_table

__all__ = []

#: the far-field sum of a pair stops after the term j at which x^(j + 1) < FAR_STOP,
#: x = (b/t)^2 at the near edge (every coefficient is below 1.3 in magnitude)
FAR_STOP = 1e-18


def _jit(fn):
    """njit with an on-disk cache; without one where numba finds no writable place
    (a read-only install and cache directory): then every process compiles again
    (seconds), said once by a warning."""
    try:
        return numba.njit(cache=True, nogil=True)(fn)
    except RuntimeError as err:              # numba: "no locator available"
        warnings.warn(f"linecontact: the compiled roller kernels cannot be cached ({err}); "
                      "each process compiles them again (set NUMBA_CACHE_DIR to a "
                      "writable directory)", RuntimeWarning, stacklevel=2)
        return numba.njit(cache=False, nogil=True)(fn)


def _far_powers(b, span, fc):
    """C[i, j, f] = beta_i^(j+1) fc[j, f], beta = (b/span)^2 (the far-field series of
    source i in its unit-geometry powers)."""
    ns, K = b.shape[0], fc.shape[0]
    C = np.empty((ns, K, 4))
    for i in range(ns):
        beta = (b[i] * (1.0 / span)) ** 2
        bp = 1.0
        for j in range(K):
            bp *= beta
            for f in range(4):
                C[i, j, f] = bp * fc[j, f]
    return C


_far_powers = _jit(_far_powers)


def _fill(S, T, full, b, span, dg, tn, tf, lr, G, fc, far, tmin, tmax, coef, z0, ih, h,
          A, EA, D, ED):
    """A[kt, s] for target T[kt] and source S[s], and EA, D, ED on the rows with
    full[kt] (kernels(); one loop, no calls per pair: numba counts references at each
    call that passes arrays, which costs more than the pair). False where a spline
    argument leaves the table [tmin, tmax)."""
    ns, nt = S.shape[0], T.shape[0]
    nseg = coef.shape[2]
    C = _far_powers(b, span, fc) if far else np.zeros((ns, 1, 4))
    K = G.shape[2]
    for s in range(ns):
        si = S[s]
        bi = b[s]
        ibi = span / bi
        thr = 3.0 * (1.0 / ibi)
        for kt in range(nt):
            k = T[kt]
            fk = full[kt]
            if k == si:                               # the diagonal: tau = w/2b
                ntau = 1
                tau0 = (0.5 * span) * dg[si] / bi
                tau1 = tau0
            else:
                tnk = tn[k, si]
                if far and not (tnk < thr):
                    # the far field: sum over j of G[si, k, j] C[s, j, f], until the
                    # next power of (b/t)^2 is negligible
                    x = 1.0 / (tnk * ibi)
                    x = x * x
                    xp = x
                    a = ea = d = ed = 0.0
                    for j in range(K):
                        g = G[si, k, j]
                        a += g * C[s, j, 0]
                        if fk:
                            ea += g * C[s, j, 1]
                            d += g * C[s, j, 2]
                            ed += g * C[s, j, 3]
                        xp *= x
                        if xp < FAR_STOP:
                            break
                    A[kt, s] = lr[k, si] + a
                    if fk:
                        EA[kt, s] = ea
                        D[kt, s] = d
                        ED[kt, s] = ed
                    continue
                # the near band (every pair without the far field): both edges
                ntau = 2
                tau0 = tf[k, si] * ibi
                tau1 = tnk * ibi
            r = ta = p = tp = 0.0
            for e in range(ntau):
                tau = tau0 if e == 0 else tau1
                if not (tmin <= tau < tmax):
                    return False
                sg = 1.0 if e == 0 else -1.0
                u = (np.log(tau) - z0) * ih
                i = int(u)
                if i > nseg - 1:
                    i = nseg - 1
                t = (u - i) * h
                r += sg * (((coef[3, 0, i] * t + coef[2, 0, i]) * t + coef[1, 0, i]) * t
                           + coef[0, 0, i])
                if fk:
                    ta += sg * (((coef[3, 1, i] * t + coef[2, 1, i]) * t + coef[1, 1, i])
                                * t + coef[0, 1, i])
                    p += sg * (((coef[3, 2, i] * t + coef[2, 2, i]) * t + coef[1, 2, i])
                               * t + coef[0, 2, i])
                    tp += sg * (((coef[3, 3, i] * t + coef[2, 3, i]) * t + coef[1, 3, i])
                                * t + coef[0, 3, i])
            if ntau == 1:
                A[kt, s] = 2.0 * (np.log(span * dg[si] / bi) + r)
                if fk:
                    EA[kt, s] = 2.0 * ta
                    D[kt, s] = 2.0 * p - 4.0
                    ED[kt, s] = 2.0 * tp
            else:
                A[kt, s] = lr[k, si] + r
                if fk:
                    EA[kt, s] = ta
                    D[kt, s] = p
                    ED[kt, s] = tp
    return True


_fill = _jit(_fill)


def _linearised(S, T, pos, q, c, over, R, span, x, m, dg, slope, theta, dlo, dhi,
                tn, tf, lr, G, fc, far, tmin, tmax, coef, z0, ih, h,
                res, J, rhs, gap, grid):
    """res, J, rhs, gap and grid of SliceEquations.linearised, filled in place; pos[kt]
    is the position of target T[kt] among S, or -1 (only A on those rows)."""
    ns = S.shape[0]
    nt = T.shape[0]
    qs = np.empty(ns)
    cs = np.empty(ns)
    b = np.empty(ns)
    bb = np.empty(ns)
    for s in range(ns):
        qs[s] = q[S[s]]
        cs[s] = c[S[s]]
        bb[s] = qs[s] / cs[s]
        b[s] = np.sqrt(bb[s])
    full = pos >= 0
    A = np.empty((nt, ns))
    EA = np.empty((nt, ns))
    D = np.empty((nt, ns))
    ED = np.empty((nt, ns))
    if not _fill(S, T, full, b, span, dg, tn, tf, lr, G, fc, far, tmin, tmax, coef,
                 z0, ih, h, A, EA, D, ED):
        return False
    for kt in range(nt):
        k = T[kt]
        p = pos[kt]
        aq = 0.0
        for s in range(ns):
            aq += A[kt, s] * qs[s]
        gap[kt] = over[k] - aq
        if p < 0:
            continue
        dc = 0.0
        eaq = 0.0
        edc = 0.0
        for s in range(ns):
            ea = EA[kt, s]
            ed = ED[kt, s]
            d = D[kt, s]
            dc += d * cs[s]
            eaq += ea * qs[s]
            edc += ed * cs[s]
            J[p, s] = A[kt, s] + (-0.5) * ea
            J[p, ns + s] = ea * (0.5 * bb[s])
            J[ns + p, s] = ed * (-0.5 / bb[s])
            J[ns + p, ns + s] = ed * 0.5 + d
        res[p] = -gap[kt]
        res[ns + p] = dc + 1.0 / R
        # -dR/d(d, theta) with the grid's motion (as the numpy code)
        ts = theta - slope[k]
        for g in range(2):
            rhs[p, g] = (m[k] * (dhi[g] - dlo[g]) + dlo[g]) * ts
            rhs[p, g] -= eaq * ((dhi[g] - dlo[g]) / span)
            rhs[ns + p, g] = edc * (-((dhi[g] - dlo[g]) / span))
        rhs[p, 0] += 1.0
        rhs[p, 1] += x[k]
    # d(w.q, (w x).q)/d(d, theta) at fixed q
    dq = 0.0
    dxq = 0.0
    wqs = 0.0
    wm = 0.0
    for s in range(ns):
        si = S[s]
        dq += dg[si] * qs[s]
        dxq += (dg[si] * qs[s]) * x[si]
        wq = (span * dg[si]) * qs[s]
        wqs += wq
        wm += wq * m[si]
    w1m = wqs - wm
    dw0 = -dxq + w1m
    dw1 = dxq + wm
    for g in range(2):
        grid[0, g] = dq * (dhi[g] - dlo[g])
        grid[1, g] = dw0 * dlo[g] + dw1 * dhi[g]
    return True


_linearised = _jit(_linearised)


_TABLE = []


def table():
    """tau_min, tau_max, coef, z0, 1/h, h of the spline table (built once)."""
    if not _TABLE:
        t = spline_table()
        _TABLE.append((float(t.tau_min), float(t.tau_max), t.coef, float(t.z0),
                       1.0 / t.h, float(t.h)))
    return _TABLE[0]


_NO_G = np.zeros((1, 1, 1))


def kernels(S, T, b, span, dg, tn, tf, lr, G, fc, a_only):
    """A, D, EA, ED (the others None with a_only) for targets T and sources S, or
    None where a spline argument leaves the table. G None: every pair from the table."""
    nt, ns = len(T), len(S)
    A = np.empty((nt, ns))
    EA, D, ED = (A, A, A) if a_only else (np.empty((nt, ns)) for _ in range(3))
    far = G is not None
    full = np.full(nt, not a_only)
    if not _fill(S, T, full, b, span, dg, tn, tf, lr, G if far else _NO_G, fc, far,
                 *table(), A, EA, D, ED):
        return None
    return (A, None, None, None) if a_only else (A, D, EA, ED)


def linearised(S, T, pos, q, c, over, R, span, x, m, dg, slope, theta, dlo, dhi,
               tn, tf, lr, G, fc):
    """(res, J, rhs, gap, grid) of SliceEquations.linearised, or None where a spline
    argument leaves the table."""
    ns, nt = len(S), len(T)
    res = np.empty(2 * ns)
    J = np.empty((2 * ns, 2 * ns))
    rhs = np.empty((2 * ns, 2))
    gap = np.empty(nt)
    grid = np.empty((2, 2))
    far = G is not None
    if not _linearised(S, T, pos, q, c, over, R, span, x, m, dg, slope, float(theta),
                       np.asarray(dlo, float), np.asarray(dhi, float), tn, tf, lr,
                       G if far else _NO_G, fc, far, *table(), res, J, rhs, gap, grid):
        return None
    return res, J, rhs, gap, grid
