"""Compiled loops of the coupled-slice equations (numba, optional; ``engine="numba"``).

:meth:`SliceEquations.kernels <linecontact.roller.slices.SliceEquations.kernels>` and
:meth:`~linecontact.roller.slices.SliceEquations.linearised` as loops over the source
slices, each source's column of all four kernels at once, with the arithmetic of the
numpy code in
:mod:`linecontact.roller.slices`, which stays the reference and the fallback: the same
cached unit geometry (near and far edge distances, their log ratio, the far-field
power differences G), the same series coefficients
(:func:`~linecontact.roller.kernel.far_field_coefficients`) and the same cubic spline
(:func:`~linecontact.roller.kernel.spline_table`), the same split into far field,
near band and diagonal. Two differences, both at the level of rounding (below
2e-15 of each matrix's scale): sums run in another order (the far-field series, all
14 terms, over every target in contiguous loops that numba vectorises, the near
band's entries then overwritten), and the spline's ln(t/b) is ln t + ln(span/b) with
ln t cached (one log per source, not two per pair). The Jacobian, residual and grid
terms are assembled from each source's column as it is computed, without the four
intermediate matrices. The spline's coefficients are kept as (segment, power,
function): a point's sixteen in two cache lines.

Beyond the table (tau >= 1e4: a strip far narrower than the slices, a slice about to
leave the contact) the strip functions come from their series, as in the numpy code;
below it (tau < 1e-4, a strip thousands of slices wide: the quadrature) a function
returns False and the caller takes the numpy path for that call.

Imported only when the compiled engine is asked for (importing numba costs a few
hundred ms; the compiled code is cached on disk next to this file, or in numba's
user-wide cache where the package is read-only; docs/profiled_rollers.md, "Engines").
"""
from __future__ import annotations

import math
import warnings

import numba
import numpy as np
# numba's np.linalg.solve calls LAPACK through scipy's bindings, in scipy's own BLAS
# library: loaded now, so that the one-BLAS-thread guard of the slice solvers
# (_numerics.serial_blas) finds and limits it as it does numpy's
import scipy.linalg.cython_lapack  # noqa: F401

from .._numerics import rescan_blas
from ._layout import table, transposed
from .kernel import R_INF

rescan_blas()

__all__ = []

#: the series of a near-band pair beyond the spline table (t/b >= tau_max = 1e4) stops
#: once the next power of x = (b/t)^2 is below FAR_STOP (a term x^(j + 1) times a
#: coefficient below 1.3 in magnitude); the far field takes every term
FAR_STOP = 1e-18


_UNCACHED = []


def _jit(fn):
    """njit with an on-disk cache (next to this file, else numba's user-wide cache
    directory); without one where numba finds no writable place (a read-only install
    and home): then every process compiles again (seconds), said once by a warning."""
    try:
        return numba.njit(cache=True, nogil=True)(fn)
    except RuntimeError as err:              # numba: "no locator available"
        if not _UNCACHED:
            warnings.warn(f"linecontact: the compiled roller kernels cannot be cached "
                          f"({err}); each process compiles them again, a few seconds "
                          "(set NUMBA_CACHE_DIR to a writable directory)", RuntimeWarning,
                          stacklevel=2)
        _UNCACHED.append(fn.__name__)
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


def _column(si, bi, Cs, n, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far, full, tmin,
            tmax, coef, z0, ih, h, W):
    """The four kernels of source slice si (strip half-width bi, far-field series
    coefficients Cs = C[s]) at every slice k: W[f, k] for f = A, EA, D, ED (the far
    field of A alone unless `full`: W[1:] then undefined there). tn, tf, lr,
    their logs ltn, ltf and Gt are indexed [source, target] (transposed); the spline's
    ln(t/b) is ln t + ln(span/b), one log per source. At t/b >= tmax (a strip far
    narrower than the slices: a slice about to leave the contact) the four functions
    come from their series in (b/t)^2 (fc, as the numpy code's strip_values does);
    returns False where t/b < tmin (the quadrature: then the numpy code).

    The near band, {k : tn[si, k] < 3 b/span} (the numpy code's test), is an interval
    [kl, kr] around si, since tn grows away from the source; outside it the far-field
    series, all its terms as in the numpy code."""
    nseg = coef.shape[0]
    ibi = span / bi
    thr = 3.0 * (1.0 / ibi)
    tnr = tn[si]
    kl, kr = 0, n - 1
    if far:
        kl = si
        while kl > 0 and tnr[kl - 1] < thr:
            kl -= 1
        kr = si
        while kr < n - 1 and tnr[kr + 1] < thr:
            kr += 1
        K = Gt.shape[1]
        g = Gt[si]
        # the far-field series, every term j in turn, over every target: contiguous
        # loops of n (which numba vectorises; over the far targets alone, runs of a
        # few slices each side, they ran as scalars); the near band's entries are
        # overwritten below
        w0, w1, w2, w3 = W[0], W[1], W[2], W[3]
        for j in range(K):
            gj = g[j]
            c0, c1, c2, c3 = Cs[j, 0], Cs[j, 1], Cs[j, 2], Cs[j, 3]
            if j == 0:
                for k in range(n):
                    w0[k] = gj[k] * c0
                if full:
                    for k in range(n):
                        w1[k] = gj[k] * c1
                        w2[k] = gj[k] * c2
                        w3[k] = gj[k] * c3
                continue
            if not full:
                for k in range(n):
                    w0[k] += gj[k] * c0
                continue
            for k in range(n):
                w0[k] += gj[k] * c0
                w1[k] += gj[k] * c1
                w2[k] += gj[k] * c2
                w3[k] += gj[k] * c3
        lrr = lr[si]
        for k in range(n):
            w0[k] = lrr[k] + w0[k]
    # the near band (every pair without the far field) at both edges, the diagonal at
    # tau = w/2b
    tfr = tf[si]
    ltnr = ltn[si]
    ltfr = ltf[si]
    lib = np.log(ibi)
    for k in range(kl, kr + 1):
        if k == si:
            ntau = 1
            tau0 = (0.5 * span) * dg[si] / bi
            tau1 = tau0
            z0k = np.log(tau0)
            z1k = z0k
        else:
            ntau = 2
            tau0 = tfr[k] * ibi
            tau1 = tnr[k] * ibi
            z0k = ltfr[k] + lib
            z1k = ltnr[k] + lib
        r = ta = p = tp = 0.0
        for e in range(ntau):
            tau = tau0 if e == 0 else tau1
            sg = 1.0 if e == 0 else -1.0
            if tau >= tmax:
                x = 1.0 / (tau * tau)
                xp = 1.0
                sr = sta = sp = stp = 0.0
                for j in range(fc.shape[0]):
                    xp *= x
                    sr += fc[j, 0] * xp
                    sta += fc[j, 1] * xp
                    sp += fc[j, 2] * xp
                    stp += fc[j, 3] * xp
                    if xp * x < FAR_STOP:
                        break
                r += sg * (R_INF + sr)
                ta += sg * (1.0 + sta)
                p += sg * sp
                tp += sg * stp
                continue
            if not tmin <= tau:
                return False
            u = ((z0k if e == 0 else z1k) - z0) * ih
            i = int(u)
            if i > nseg - 1:
                i = nseg - 1
            t = (u - i) * h
            r += sg * (((coef[i, 3, 0] * t + coef[i, 2, 0]) * t + coef[i, 1, 0]) * t
                       + coef[i, 0, 0])
            ta += sg * (((coef[i, 3, 1] * t + coef[i, 2, 1]) * t + coef[i, 1, 1]) * t
                        + coef[i, 0, 1])
            p += sg * (((coef[i, 3, 2] * t + coef[i, 2, 2]) * t + coef[i, 1, 2]) * t
                       + coef[i, 0, 2])
            tp += sg * (((coef[i, 3, 3] * t + coef[i, 2, 3]) * t + coef[i, 1, 3]) * t
                        + coef[i, 0, 3])
        if ntau == 1:
            W[0, k] = 2.0 * (np.log(span * dg[si] / bi) + r)
            W[1, k] = 2.0 * ta
            W[2, k] = 2.0 * p - 4.0
            W[3, k] = 2.0 * tp
        else:
            W[0, k] = lr[si, k] + r
            W[1, k] = ta
            W[2, k] = p
            W[3, k] = tp
    return True


_column = _jit(_column)


def _kernels(S, T, b, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far, tmin, tmax,
             coef, z0, ih, h, A, EA, D, ED):
    """A (and EA, D, ED where they are other arrays than A), (len(T), len(S)), Fortran
    order: kernels(). False where a spline argument leaves the table."""
    n = tn.shape[0]
    ns, nt = S.shape[0], T.shape[0]
    C = _far_powers(b, span, fc) if far else np.zeros((ns, 1, 4))
    W = np.empty((4, n))
    full = EA.shape[0] > 0
    for s in range(ns):
        if not _column(S[s], b[s], C[s], n, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far,
                       full, tmin, tmax, coef, z0, ih, h, W):
            return False
        for kt in range(nt):
            A[kt, s] = W[0, T[kt]]
        if full:
            for kt in range(nt):
                k = T[kt]
                EA[kt, s] = W[1, k]
                D[kt, s] = W[2, k]
                ED[kt, s] = W[3, k]
    return True


_kernels = _jit(_kernels)


def _linearised(S, T, spos, q, c, over, R, span, x, m, dg, slope, theta, dlo, dhi,
                tn, tf, lr, ltn, ltf, Gt, fc, far, tmin, tmax, coef, z0, ih, h,
                res, J, rhs, gap, grid):
    """res, J (Fortran order), rhs, gap and grid of SliceEquations.linearised, filled
    in place, one source column at a time; spos[p] is the position of S[p] among the
    targets T."""
    n = tn.shape[0]
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
    C = _far_powers(b, span, fc) if far else np.zeros((ns, 1, 4))
    W = np.empty((4, n))
    aq = np.zeros(nt)
    dc = np.zeros(ns)
    eaq = np.zeros(ns)
    edc = np.zeros(ns)
    contiguous = S[ns - 1] - S[0] + 1 == ns
    for s in range(ns):
        if not _column(S[s], b[s], C[s], n, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far,
                       True, tmin, tmax, coef, z0, ih, h, W):
            return False
        qv = qs[s]
        cv = cs[s]
        hb = 0.5 * bb[s]
        mhb = -0.5 / bb[s]
        if nt == n:                                  # every slice a target: T[k] = k
            w0 = W[0]
            for k in range(n):
                aq[k] += w0[k] * qv
        else:
            for kt in range(nt):
                aq[kt] += W[0, T[kt]] * qv
        if contiguous:
            # the rows of S are one run of targets: contiguous views (vectorised)
            wa, wea = W[0, S[0]:S[0] + ns], W[1, S[0]:S[0] + ns]
            wd, wed = W[2, S[0]:S[0] + ns], W[3, S[0]:S[0] + ns]
            j00, j10 = J[:ns, s], J[ns:, s]
            j01, j11 = J[:ns, ns + s], J[ns:, ns + s]
            for p in range(ns):
                ea = wea[p]
                ed = wed[p]
                d = wd[p]
                j00[p] = wa[p] + (-0.5) * ea
                j10[p] = ed * mhb
                j01[p] = ea * hb
                j11[p] = ed * 0.5 + d
                dc[p] += d * cv
                eaq[p] += ea * qv
                edc[p] += ed * cv
            continue
        for p in range(ns):
            k = S[p]
            a = W[0, k]
            ea = W[1, k]
            d = W[2, k]
            ed = W[3, k]
            J[p, s] = a + (-0.5) * ea
            J[ns + p, s] = ed * mhb
            J[p, ns + s] = ea * hb
            J[ns + p, ns + s] = ed * 0.5 + d
            dc[p] += d * cv
            eaq[p] += ea * qv
            edc[p] += ed * cv
    for kt in range(nt):
        gap[kt] = over[T[kt]] - aq[kt]
    for p in range(ns):
        k = S[p]
        res[p] = -gap[spos[p]]
        res[ns + p] = dc[p] + 1.0 / R
        # -dR/d(d, theta) with the grid's motion (as the numpy code)
        ts = theta - slope[k]
        for g in range(2):
            rhs[p, g] = (m[k] * (dhi[g] - dlo[g]) + dlo[g]) * ts
            rhs[p, g] -= eaq[p] * ((dhi[g] - dlo[g]) / span)
            rhs[ns + p, g] = edc[p] * (-((dhi[g] - dlo[g]) / span))
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


def kernels(S, T, b, span, dg, tn, tf, lr, G, fc, a_only):
    """A, D, EA, ED (the others None with a_only) for targets T and sources S, or
    None where a spline argument leaves the table. G None: every pair from the table."""
    nt, ns = len(T), len(S)
    A = np.empty((nt, ns), order="F")
    if a_only:
        EA = D = ED = np.empty((0, 0), order="F")
    else:
        EA, D, ED = (np.empty((nt, ns), order="F") for _ in range(3))
    tn, tf, lr, ltn, ltf, Gt = transposed(tn, tf, lr, G)
    if not _kernels(S, T, b, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, G is not None,
                    *table(), A, EA, D, ED):
        return None
    return (A, None, None, None) if a_only else (A, D, EA, ED)


def linearised(S, T, spos, q, c, over, R, span, x, m, dg, slope, theta, dlo, dhi,
               tn, tf, lr, G, fc):
    """(res, J, rhs, gap, grid) of SliceEquations.linearised (J in Fortran order), or
    None where a spline argument leaves the table."""
    ns, nt = len(S), len(T)
    res = np.empty(2 * ns)
    J = np.empty((2 * ns, 2 * ns), order="F")
    rhs = np.empty((2 * ns, 2))
    gap = np.empty(nt)
    grid = np.empty((2, 2))
    tn, tf, lr, ltn, ltf, Gt = transposed(tn, tf, lr, G)
    if not _linearised(S, T, spos, q, c, over, R, span, x, m, dg, slope, float(theta),
                       np.asarray(dlo, float), np.asarray(dhi, float), tn, tf, lr, ltn,
                       ltf, Gt, fc, G is not None, *table(), res, J, rhs, gap,
                       grid):
        return None
    return res, J, rhs, gap, grid


# -- the bordered Newton step's small arithmetic (SliceEquations.bordered) ------------
# the numpy code there stays the reference: the same products by the same scalars
# (computed by the caller), the sums over the loaded slices in another order

def _scaled_system(J, res, rhs, ns, f_hi, f_lo, g_q, h_q, R, B):
    """J's off-diagonal blocks scaled in place (J[:ns, ns:] * f_hi, J[ns:, :ns] *
    f_lo) and the right-hand sides B (2 ns x 3): -res scaled (g_q = -1/qsc on the
    load rows, -R on the curvature rows), then rhs scaled (h_q = 1/qsc, R)."""
    n2 = 2 * ns
    for j in range(ns, n2):
        for i in range(ns):
            J[i, j] *= f_hi
    for j in range(ns):
        for i in range(ns, n2):
            J[i, j] *= f_lo
    for i in range(ns):
        B[i, 0] = res[i] * g_q
        B[i, 1] = rhs[i, 0] * h_q
        B[i, 2] = rhs[i, 1] * h_q
    mR = -R
    for i in range(ns, n2):
        B[i, 0] = res[i] * mR
        B[i, 1] = rhs[i, 0] * R
        B[i, 2] = rhs[i, 1] * R


_scaled_system = _jit(_scaled_system)


def scaled_system(J, res, rhs, ns, qsc, R):
    """The scaled Newton system of SliceEquations.bordered: J scaled in place, B new."""
    B = np.empty((2 * ns, 3))
    _scaled_system(J, res, rhs, ns, 1.0 / (qsc * R), qsc * R, -1.0 / qsc, 1.0 / qsc,
                   float(R), B)
    return B


def _bordered_sums(z, ns, qsc, r_inv, w, x, S, qs, Wz):
    """z unscaled in place (load rows times qsc, curvature rows times 1/R), and the
    force and moment rows: returns (w.q, (w x).q) over the loaded slices S, Wz (2 x 3)
    = those rows times z's load part."""
    n2 = 2 * ns
    for j in range(3):
        for i in range(ns):
            z[i, j] *= qsc
        for i in range(ns, n2):
            z[i, j] *= r_inv
    wq = 0.0
    wxq = 0.0
    for j in range(3):
        Wz[0, j] = 0.0
        Wz[1, j] = 0.0
    for i in range(ns):
        wi = w[S[i]]
        wx = wi * x[S[i]]
        wq += wi * qs[i]
        wxq += wx * qs[i]
        for j in range(3):
            Wz[0, j] += wi * z[i, j]
            Wz[1, j] += wx * z[i, j]
    return wq, wxq


_bordered_sums = _jit(_bordered_sums)


def bordered_sums(z, ns, qsc, R, w, x, S, qs):
    """(w.q, (w x).q, Wz) of SliceEquations.bordered, z unscaled in place."""
    Wz = np.empty((2, 3))
    wq, wxq = _bordered_sums(z, ns, qsc, 1.0 / R, w, x, S, qs, Wz)
    return wq, wxq, Wz


def _step_out(z, s0, s1, ns, qs, dz, out):
    """The step dz = z[:, 0] + z[:, 1:] (s0, s1) and the mask of the loaded slices it
    drives below zero (q + dq < 0); returns how many."""
    for i in range(2 * ns):
        dz[i] = z[i, 0] + (z[i, 1] * s0 + z[i, 2] * s1)
    k = 0
    for i in range(ns):
        out[i] = qs[i] + dz[i] < 0.0
        if out[i]:
            k += 1
    return k


_step_out = _jit(_step_out)


def step_out(z, s0, s1, ns, qs):
    """(dz, out, count) of SliceEquations.bordered's step."""
    dz = np.empty(2 * ns)
    out = np.empty(ns, dtype=np.bool_)
    k = _step_out(z, float(s0), float(s1), ns, qs, dz, out)
    return dz, out, k


def _step_update(q, c, S, qs, cs, dq, dc, over, x, s0, s1, hit_q, res):
    """The damped update of SliceEquations.bordered: alpha from the fraction to the
    boundary (q to no less than 5 %, c to 20 % of its value; hit_q marks the slices
    whose q limited it) and from the overlap (no step lowers it by more than half its
    largest value); q[S], c[S] updated in place; res = (alpha, largest overlap,
    largest |dq|, largest |dc|)."""
    ns = S.shape[0]
    alpha = 1.0
    for i in range(ns):
        hit_q[i] = qs[i] + dq[i] <= 0.05 * qs[i]
        if hit_q[i]:
            a = 0.95 * qs[i] / -dq[i]
            if a < alpha:
                alpha = a
    amin = np.inf
    for i in range(ns):
        if cs[i] + dc[i] <= 0.2 * cs[i]:
            a = 0.8 * cs[i] / -dc[i]
            if a < amin:
                amin = a
    if amin < alpha:
        alpha = amin
    dmax = over[0]
    for i in range(1, over.shape[0]):
        if over[i] > dmax:
            dmax = over[i]
    if s1 != 0.0:
        lowest = np.inf
        for i in range(ns):
            v = s0 + s1 * x[S[i]]
            if v < lowest:
                lowest = v
        drop = -lowest
    else:
        drop = -s0
    if drop > 0.5 * dmax:
        a = 0.5 * dmax / drop
        if a < alpha:
            alpha = a
    dqmax = 0.0
    dcmax = 0.0
    for i in range(ns):
        if alpha == 1.0:
            q[S[i]] = qs[i] + dq[i]
            c[S[i]] = cs[i] + dc[i]
        else:
            q[S[i]] = qs[i] + alpha * dq[i]
            c[S[i]] = cs[i] + alpha * dc[i]
        if abs(dq[i]) > dqmax:
            dqmax = abs(dq[i])
        if abs(dc[i]) > dcmax:
            dcmax = abs(dc[i])
    res[0] = alpha
    res[1] = dmax
    res[2] = dqmax
    res[3] = dcmax


_step_update = _jit(_step_update)


def step_update(q, c, S, qs, cs, dq, dc, over, x, s0, s1):
    """(alpha, hit_q, largest overlap, largest |dq|, largest |dc|) of
    SliceEquations.bordered's damped update, q and c updated in place."""
    hit_q = np.empty(len(S), dtype=np.bool_)
    res = np.empty(4)
    _step_update(q, c, S, qs, cs, dq, dc, over, x, float(s0), float(s1), hit_q, res)
    return float(res[0]), hit_q, float(res[1]), float(res[2]), float(res[3])


def _solve(J, B):
    """np.linalg.solve in compiled code: numba's binding of LAPACK's gesv (the LU
    factorisation with partial pivoting numpy's solve calls, from scipy's LAPACK)."""
    return np.linalg.solve(J, B)


_solve = _jit(_solve)


def solve(J, B):
    """np.linalg.solve(J, B) for the compiled engine's dense solves (the Newton step's
    and the cold start's): the same LAPACK routine without numpy's per-call overhead
    (about 5-10 us a call, 14-16 calls a solve). Where numba refuses the system (a
    singular matrix, or an entry that is not finite: numba checks, numpy does not),
    numpy's solve answers, so that the caller sees what the numpy engine would."""
    try:
        return _solve(J, B)
    except np.linalg.LinAlgError:
        return np.linalg.solve(J, B)


def _solve_sums(J, B, ns, qsc, r_inv, w, x, S, qs, Wz, sums):
    z = np.linalg.solve(J, B)
    sums[0], sums[1] = _bordered_sums(z, ns, qsc, r_inv, w, x, S, qs, Wz)
    return z


_solve_sums = _jit(_solve_sums)


def solve_sums(J, B, ns, qsc, R, w, x, S, qs):
    """(z, w.q, (w x).q, Wz) of SliceEquations.bordered's step in one compiled call:
    the dense solve (:func:`solve`) and :func:`bordered_sums`."""
    Wz = np.empty((2, 3))
    sums = np.empty(2)
    try:
        z = _solve_sums(J, B, ns, qsc, 1.0 / R, w, x, S, qs, Wz, sums)
    except np.linalg.LinAlgError:
        z = np.linalg.solve(J, B)
        return (z,) + bordered_sums(z, ns, qsc, R, w, x, S, qs)
    return z, float(sums[0]), float(sums[1]), Wz


def _quotient(num, k):
    """num / k as numpy's float division answers it, k = 0 included (+-inf, NaN for
    0/0: num * inf * sign(k)); numba's compiled division raises ZeroDivisionError
    there."""
    if k == 0.0:
        return num * np.inf * math.copysign(1.0, k)
    return num / k


_quotient = _jit(_quotient)


def _newton_step(J, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, target, mode, q, c,
                 over, B, Kout, st, hit_q, upd):
    """One bordered Newton step after the linearisation, in one call: the scaled system
    (_scaled_system), its dense solve and sums (_solve_sums), K = Wz[:, 1:] + grid (in
    Kout), the step in (d, theta) as SliceEquations.bordered computes it (mode 1: the
    force row, 2: the moment row, 3: both by Cramer's rule, 0: none; target = F/(pi E*);
    st[:2]), the step dz and its mask of slices driven below zero (_step_out), and,
    where no slice leaves, the damped update of q and c (_step_update: upd = alpha,
    largest overlap, largest |dq|, largest |dc|). Returns (status, z, dz, out): status
    0 the update done; 1 slices leave (nout > 0 and ns > 2: the caller removes them
    and solves again, as in the numpy code); 2 Cramer's determinant is zero or not
    finite (the caller solves the 2 x 2 system with numpy, st[2:4] holding its
    right-hand side; dz and out are then empty)."""
    n2 = 2 * ns
    _scaled_system(J, res, rhs, ns, 1.0 / (qsc * R), qsc * R, -1.0 / qsc, 1.0 / qsc, R, B)
    z = np.linalg.solve(J, B)
    Wz = np.empty((2, 3))
    wq, wxq = _bordered_sums(z, ns, qsc, 1.0 / R, w, x, S, qs, Wz)
    for i in range(2):
        for j in range(2):
            Kout[i, j] = Wz[i, j + 1] + grid[i, j]
    lin0 = Wz[0, 0]
    lin1 = Wz[1, 0]
    s0 = 0.0
    s1 = 0.0
    if mode == 3:
        r0 = target - wq - lin0
        r1 = -wxq - lin1
        k00, k01, k10, k11 = Kout[0, 0], Kout[0, 1], Kout[1, 0], Kout[1, 1]
        det = k00 * k11 - k01 * k10
        if det == 0.0 or not np.isfinite(det):
            st[2] = r0
            st[3] = r1
            return 2, z, np.empty(0), np.empty(0, np.bool_)
        s0 = (r0 * k11 - k01 * r1) / det
        s1 = (k00 * r1 - k10 * r0) / det
    elif mode == 1:
        s0 = _quotient(target - wq - lin0, Kout[0, 0])
    elif mode == 2:
        s1 = _quotient(-wxq - lin1, Kout[1, 1])
    st[0] = s0
    st[1] = s1
    dz = np.empty(n2)
    out = np.empty(ns, np.bool_)
    nout = _step_out(z, s0, s1, ns, qs, dz, out)
    if nout > 0 and ns > 2:
        return 1, z, dz, out
    _step_update(q, c, S, qs, cs, dz[:ns], dz[ns:], over, x, s0, s1, hit_q, upd)
    return 0, z, dz, out


_newton_step = _jit(_newton_step)


def newton_step(J, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs, target, mode, q, c,
                over):
    """One step of SliceEquations.bordered after the linearisation in one compiled
    call (_newton_step): (status, B, z, K, step, dz, out, hit_q, upd), B the scaled
    right-hand sides (J scaled in place), step[:2] the step in (d, theta) (status 2:
    step[2:] the right-hand side of the 2 x 2 system), upd = (alpha, largest overlap,
    largest |dq|, largest |dc|) where status is 0. (None, B) where numba refuses the
    dense system (singular, not finite): J and B are scaled, and the caller's numpy
    solve answers as the numpy engine would."""
    B = np.empty((2 * ns, 3))
    K = np.empty((2, 2))
    st = np.empty(4)
    hit_q = np.empty(ns, np.bool_)
    upd = np.empty(4)
    try:
        status, z, dz, out = _newton_step(J, res, rhs, grid, ns, qsc, R, w, x, S, qs, cs,
                                          target, mode, q, c, over, B, K, st, hit_q, upd)
    except np.linalg.LinAlgError:
        return None, B
    return status, B, z, K, st, dz, out, hit_q, upd


def _start_solve(M, rhs, ns, nb, keep):
    """The cold start's active-set loop on the bordered frozen-width system M z = rhs
    (ns slice rows, nb border rows last): solved, the slices with z <= 0 removed (their
    rows and columns: the same submatrix as numpy's take), again until every load is
    positive; keep[:k] the kept slices' indices. Returns (z, k); k = 0: none left."""
    n = ns
    for i in range(ns):
        keep[i] = i
    while True:
        z = np.linalg.solve(M, rhs)
        k = 0
        for i in range(n):
            if z[i] > 0.0:
                k += 1
        if k == n or k == 0:
            return z, k
        rows = np.empty(k + nb, np.int64)
        j = 0
        for i in range(n):
            if z[i] > 0.0:
                rows[j] = i
                keep[j] = keep[i]
                j += 1
        for i in range(nb):
            rows[k + i] = n + i
        m = k + nb
        M2 = np.empty((m, m))
        r2 = np.empty(m)
        for a in range(m):
            r2[a] = rhs[rows[a]]
            for b in range(m):
                M2[a, b] = M[rows[a], rows[b]]
        M, rhs, n = M2, r2, k


_start_solve = _jit(_start_solve)


def start_solve(M, rhs, ns, nb):
    """(z, kept slice indices, their count) of SliceEquations.start_at_force's active-set
    loop in one compiled call, or None where numba refuses a system (singular, not
    finite): the caller then runs its numpy loop, which answers as the numpy engine."""
    keep = np.empty(ns, np.int64)
    try:
        z, k = _start_solve(M, rhs, ns, nb, keep)
    except np.linalg.LinAlgError:
        return None
    return z, keep[:k], k
