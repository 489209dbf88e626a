"""The slice equations of the coupled-slice roller model: slice geometry, the Newton /
active-set solver in scaled variables and the exact stiffness matrix by implicit
differentiation (the method is described in :mod:`linecontact.roller`).
"""
from __future__ import annotations

import math

import numpy as np

from .._numerics import CACHE_BYTES, cache_nbytes
from ..checks import Interval
from ..profiles import TILT_RANGE
from .kernel import far_field_coefficients, strip_values

__all__ = ["ConvergenceError", "N_SLICES", "TILT_RANGE", "SLICE_GRADING"]

#: Slice counts accepted by the coupled-slice model.
N_SLICES = Interval("n_slices", 10, 4000)
#: The default slice count: converged with the default grading and end refinement
#: over tables/roller_accuracy.csv and the range it covers (docs/profiled_rollers.md,
#: "Slice convergence"; tools/benchmarks/bench_roller_default_slices.py)
DEFAULT_N_SLICES = 50


#: Grading of the slice widths accepted: 0 (uniform) <= grading < 1.
SLICE_GRADING = Interval("grading", 0.0, 1.0, high_open=True)


def slice_positions(n, grading, refine=0):
    """Centres and widths of the slices on [0, 1], graded towards both ends.

    The boundaries are g(k/n), k = 0..n, with g(s) = s - beta sin(2 pi s)/(2 pi): the
    end slices are (1 - beta) times the uniform width 1/n and the middle ones
    (1 + beta) times (beta = 0: uniform). With `refine` = l >= 1 the end slices at
    each end (at least :data:`REFINED_SLICES`, W the width of that many) are replaced
    by slices growing geometrically by at most :data:`REFINE_RATIO` from W 2^-(l + 4)
    at the end up to the width of the base slices they meet (:func:`end_refined`):
    where the contact of a logarithmic profile ends microns before the roller end, its
    end zone is narrower than the end slices. Returns the centres (midway between the
    boundaries) and the widths, both as fractions of the interval (n slices, or more
    with refine).
    """
    s = np.arange(n + 1) / n
    g = s - grading * np.sin(2 * np.pi * s) / (2 * np.pi)
    g[0], g[-1] = 0.0, 1.0
    if refine:
        g = end_refined(g, refine)
    return 0.5 * (g[1:] + g[:-1]), np.diff(g)


#: the fewest base slices replaced at each end by a refinement (slice_positions)
REFINED_SLICES = 3
#: the largest ratio of neighbouring widths in a refined end region
REFINE_RATIO = 1.1


def end_refined(g, level):
    """Slice boundaries g (increasing, from 0 to 1) with the end slices at each end
    replaced by k slices whose widths grow geometrically, by a ratio r <=
    REFINE_RATIO, from w_end = W 2^-(level + 4) at the end (W: the width of the last
    REFINED_SLICES base slices), up to the width of the base slice they meet: the
    fewest base slices m >= REFINED_SLICES are replaced (a region of width W_m) for
    which k = ceil(ln(1 + W_m (R - 1)/w_end)/ln R) slices (R = REFINE_RATIO) end no
    narrower than the next base slice over R; r then solves w_end (r^k - 1)/(r - 1) =
    W_m. Neighbouring widths so differ by at most about R (at the default 50 slices at
    most 1.35; with under about 20 base slices the search for m stops at the middle
    and the junction may jump several times in width): a peak where
    the refined slices meet the base ones is resolved (with the three end slices
    alone replaced the junction jumped 3-5 times in width, and a corner relief's peak
    sitting there came out 11 % high and "resolved" at 50 slices)."""
    R = REFINE_RATIO
    n = len(g) - 1
    parts = []
    for side in (0, 1):
        gg = g - g[0] if side == 0 else (g[-1] - g)[::-1]     # distances from that end
        w0 = gg[REFINED_SLICES] * 2.0 ** -(level + 4)
        for m in range(REFINED_SLICES, n // 2):
            span = gg[m]
            k = int(math.ceil(math.log(1 + span * (R - 1) / w0) / math.log(R)))
            if w0 * R ** (k - 1) >= (gg[m + 1] - gg[m]) / R:
                break
        # the ratio r <= R at which k widths from w0 fill span: bisection on r
        lo_r, hi_r = 1.0, R
        for _ in range(60):
            r = 0.5 * (lo_r + hi_r)
            if w0 * (r ** k - 1) / (r - 1) < span:
                lo_r = r
            else:
                hi_r = r
        edges = np.concatenate([[0.0], np.cumsum(w0 * r ** np.arange(k))])
        parts.append((m, edges * (span / edges[-1])))
    (m_lo, e_lo), (m_hi, e_hi) = parts
    return np.concatenate([g[0] + e_lo[:-1], g[m_lo:n + 1 - m_hi],
                           g[-1] - e_hi[::-1][1:]])


_GEOMETRY = {}


def _unit_geometry(n, grading, refine=0):
    """(near, far, ln(far/near)) distances between slice centres and source slice
    edges on the unit interval (n x n; the diagonal: near = far = w/2, log 0), and the
    slice centres and widths (slice_positions), cached per (n, grading, refine)."""
    key = (n, grading, refine)
    # what is built is returned, not read back: another thread may empty the cache
    # in between (the caches are module-wide)
    cached = _GEOMETRY.get(key)
    if cached is None:
        m, dg = slice_positions(n, grading, refine)
        t = np.abs(m[:, None] - m[None, :])
        h = 0.5 * dg[None, :]
        near, far = t - h, t + h
        np.fill_diagonal(near, 0.5 * dg)
        lr = np.log(far / near)
        np.fill_diagonal(lr, 0.0)
        cached = (near, far, lr, m, dg)
        if len(_GEOMETRY) > 16 or cache_nbytes(_GEOMETRY) > CACHE_BYTES:
            _GEOMETRY.clear()
        _GEOMETRY[key] = cached
    return cached


#: The far field of the strip kernel: pairs whose near-edge tau = t/b is at least
#: _TAU_FAR take the first _K_FAR terms of its series in b^2/t^2 (truncation below
#: 4e-15 absolute in each function at tau = 3; kernel.far_field_coefficients), the rest
#: (the near band and the diagonal) the spline table; above _N_FAR slices the
#: n x n x _K_FAR geometry is not stored and every pair reads the table.
_TAU_FAR = 3.0
_K_FAR = 14
_N_FAR = 400
_FAR = {}
_FAR_COEF = far_field_coefficients(_K_FAR)            # (_K_FAR, 4)
_FAR_POW = np.arange(1, _K_FAR + 1)


def _far_geometry(n, grading, refine=0):
    """G[i, k, j] = tf^-2(j+1) - tn^-2(j+1) for source i, target k on the unit interval
    (zero on the diagonal), cached per (n, grading, refine) (up to 8 of them and
    64 MB: an end refinement solves on three more grids)."""
    key = (n, grading, refine)
    G = _FAR.get(key)                # (returned as built: see _unit_geometry)
    if G is None:
        near, far = _unit_geometry(n, grading, refine)[:2]
        n = near.shape[0]                           # the slices, after any refinement
        un, uf = near.T ** -2, far.T ** -2          # (source, target)
        pn, pf = un.copy(), uf.copy()
        G = np.empty((n, n, _K_FAR))
        for j in range(_K_FAR):
            G[:, :, j] = pf - pn
            pn *= un
            pf *= uf
        G[np.arange(n), np.arange(n)] = 0.0
        if len(_FAR) >= 8 or cache_nbytes(_FAR) > 2**26:
            _FAR.clear()
        _FAR[key] = G
    return G


_C_ENGINE = []              # the module _cengine where the C engine runs, else None; once


def c_engine():
    """The C engine (:mod:`linecontact.roller._cengine`, over the extension
    ``linecontact._ckernels``), or None where it does not run here (not built: no C
    compiler at install; a stale build: :func:`linecontact._engine.unavailable` says
    why). Tried once per process; loading it costs a few ms (docs/profiled_rollers.md,
    "Engines")."""
    if not _C_ENGINE:
        from .._engine import ckernels
        if ckernels() is None:
            _C_ENGINE.append(None)
        else:
            from . import _cengine
            _C_ENGINE.append(_cengine)
    return _C_ENGINE[0]


def scaled_system(J, res, rhs, ns, qsc, R):
    """The bordered Newton step's system in scaled unknowns (q/qsc, c R) and rows
    (gap/qsc, curvature R): J's off-diagonal blocks scaled in place, and the
    right-hand sides B = (-res, rhs) scaled likewise (2 ns x 3). The numpy reference
    of _cengine.scaled_system."""
    J[:ns, ns:] *= 1.0 / (qsc * R)
    J[ns:, :ns] *= qsc * R
    B = np.empty((2 * ns, 3))
    np.multiply(res[:ns], -1.0 / qsc, out=B[:ns, 0])
    np.multiply(res[ns:], -R, out=B[ns:, 0])
    np.multiply(rhs[:ns], 1.0 / qsc, out=B[:ns, 1:])
    np.multiply(rhs[ns:], R, out=B[ns:, 1:])
    return B


class ConvergenceError(RuntimeError):
    """The slice equations did not converge (reported, never hidden)."""


def _fraction_to_boundary(qs, cs, dq, dc):
    """The Newton step's fraction alpha <= 1 that keeps the slice loads q and c = q/b^2
    positive (q falls to no less than 5 %, c to no less than 20 % of its value in one
    step), and the slices whose load limited it (`hit_q`)."""
    alpha = 1.0
    hit_q = qs + dq <= 0.05 * qs
    if hit_q.any():
        alpha = min(alpha, float(np.min(0.95 * qs[hit_q] / -dq[hit_q])))
    hit_c = cs + dc <= 0.2 * cs
    if hit_c.any():
        alpha = min(alpha, float(np.min(0.8 * cs[hit_c] / -dc[hit_c])))
    return alpha, hit_q


#: The constant of SliceEquations.bordered's error estimate: after a full Newton step
#: on an unchanged loaded set, the error left in the scaled unknowns (loads over the
#: largest, c R, d and the tilt's travel over the largest overlap) is at most
#: NEWTON_C times :func:`newton_error` of the step. Measured over the 104 cases of
#: tables/roller_accuracy.csv, 200 random cases of the range they cover and the ISO
#: 16281 case of the `roller` benchmark (tools/benchmarks/suite.py; every full step of
#: every solve against the converged state, docs/history.md, "Profiled-roller solve"): at
#: most 10.7 times (either engine, the same step at the rounding floor), so 100 leaves a margin
#: of about ten; the returned state is then within the tolerance of the converged one.
NEWTON_C = 100.0
#: the largest step size (as `small` measures it) at which the estimate is tried: above
#: it the estimate cannot fall below any tolerance in use (it is at least the step's
#: size squared) and is not computed
NEAR_STEP = 1e-5
#: an estimate-ended solve also needs every unloaded slice's gap below -GAP_MARGIN
#: times the step's size times the largest overlap (a gap moves by about the step's
#: size over a step; over the 104 cases the closest was 290 times it)
GAP_MARGIN = 100.0


def newton_error(qs, cs, dq, dc, qsc, R, dd, dth):
    """Newton's quadratic error estimate of the state after the full step (dq, dc, dd,
    dth) from (qs, cs): max_k dq_k^2/(q_k qsc), R dc_k^2/c_k, dd^2, dth^2 (dd, dth: the
    steps in d and in theta times the interval's length, over the largest overlap).

    The slice equations depend on the loads through ln b_k, b_k^2 = q_k/c_k (the strip
    kernel's logarithm): their second derivatives in q_k and c_k scale as 1/q_k and
    1/c_k, so a step leaves a remainder of dq_k^2/q_k and dc_k^2/c_k, which the
    Jacobian maps to an error of the same order. Weighing each slice's step by its own
    load, not by the largest, is what makes the estimate hold where a slice carries
    little (a slice that just joined: its relative step is large). A constant estimated
    from the last two steps instead (the error after a step about C |step|^2, C =
    |step|/|last step|^2) was off by up to 1000 over the table's cases: the contraction
    differs from one step's direction to the next's."""
    wq = float(np.max(dq * dq / qs)) / qsc
    wc = float(np.max(dc * dc / cs)) * R
    return max(wq, wc, dd * dd, dth * dth)


def _drop_blocked(S, q, blocked, hit_q, qsc):
    """The loaded set S after a damped step: a slice whose load limited the step three
    times running, or fell to 1e-12 of the largest `qsc`, leaves the contact (q = 0;
    `q` and the counters `blocked` are updated in place)."""
    blocked[S[hit_q]] += 1
    blocked[S[~hit_q]] = 0
    leave = (blocked[S] >= 3) | (q[S] <= 1e-12 * qsc)
    if leave.any():
        q[S[leave]] = 0.0
        blocked[S[leave]] = 0
        S = S[~leave]
        if len(S) == 0:
            raise ConvergenceError("every slice left the contact")
    return S


#: The sweeps of the cold start (SliceEquations.start_at_force), each a frozen-width
#: linear solve on the grid of the last: over the 104 cases of
#: tables/roller_accuracy.csv 2 sweeps took 1109 Newton steps, 3 took 996, 4 957, 5 913
#: (a sweep costs about half a step: table CPU 2.11, 2.02, 2.09 s for 2, 3, 4; measured
#: while the end refinement still restarted from the loads, docs/history.md,
#: "Profiled-roller solve"); the ISO 16281 case of the `roller` benchmark at a free tilt
#: takes 4 steps after 3 sweeps, 8 after 2.
START_SWEEPS = 3
#: The sweeps of a cold start but the last run on START_COARSE times fewer slices
#: (where that leaves at least 20): the first sweeps only carry the depth, tilt,
#: widths and active set to the last, and on 25 slices instead of 50 their kernels
#: and dense solves cost about a quarter. Over the 104 cases of
#: tables/roller_accuracy.csv 840 Newton steps instead of 827 and 2112 dense solves
#: instead of 2160, CPU within 1-3 % (faster); the ISO 16281 case of
#: the `roller` benchmark the same 6 and 4 steps, 3-7 % less CPU (docs/history.md,
#: "Profiled-roller solve"). Results move within the
#: Newton tolerance (2e-11 of the stiffness, 1e-12 elsewhere).
START_COARSE = 2


def coarse_slices(n):
    """The base slices of a cold start's first sweeps for a grid of n base slices:
    n // START_COARSE where that leaves at least 20, else n."""
    m = n // START_COARSE if START_COARSE > 1 else n
    return m if m >= 20 else n


def _end_runs(S, out):
    """The slices of `out` (a mask over the loaded set S) that reach an end of a run
    of consecutive loaded slices through slices of `out`: where the full step drives
    the last few slices of the contact below zero, all of them are outside it (one by
    one, each would cost a step)."""
    ns = len(S)
    cut = np.flatnonzero(np.diff(S) > 1) + 1
    ends = np.zeros(ns, bool)
    for a, b in zip(np.concatenate([[0], cut]), np.concatenate([cut, [ns]])):
        seg = out[a:b]
        if seg.all():
            ends[a:b] = True
            continue
        ends[a:a + int(np.argmin(seg))] = True
        ends[b - int(np.argmin(seg[::-1])):b] = True
    return ends


def _cramer(K, r):
    """The solution of the 2 x 2 system K s = r by Cramer's rule (a tuple), or None
    where K's determinant is zero or not finite (then np.linalg.solve decides)."""
    k00, k01, k10, k11 = (float(v) for v in K.flat)
    det = k00 * k11 - k01 * k10
    if det == 0.0 or not math.isfinite(det):
        return None
    return ((r[0] * k11 - k01 * r[1]) / det, (k00 * r[1] - k10 * r[0]) / det)


def _unloaded(J, B, out, u, v):
    """The linear system J z = B of a Newton step in scaled unknowns (u = q/qsc
    first, then v = c R) with the slices `out` unloaded: their rows and unknowns
    dropped, and the right-hand side's first column the residual without their loads.
    A source's share of the rows, A(b) q and D(b) c with b^2 = q/c, is homogeneous of
    degree one in its (q, c), so it equals its two Jacobian columns times (u, v): the
    residual a fresh linearisation at q = 0 would give, without new kernels (the
    other columns of B, the grid's motion, keep the leaving slices' small share until
    the next step)."""
    ns = len(out)
    B = B.copy()
    B[:, 0] += J[:, :ns][:, out] @ u[out] + J[:, ns:][:, out] @ v[out]
    keep = np.concatenate([~out, ~out])
    return J[keep][:, keep], B[keep]       # (a quarter of np.ix_'s time)


class SliceEquations:
    """Slice geometry and the Newton / active-set solver in scaled variables.

    Unknowns per loaded slice: qt = q/(pi E*) [m] and c = qt/b^2 [1/m].
    """

    def __init__(self, radius, estar, x_lo, x_hi, n, drop, grading=0.0, refine=0,
                 engine="numpy"):
        self.R = radius
        # "numpy" or "c" (resolved by the owner, ProfiledRoller): who evaluates
        # kernels(), linearised() and the Newton step's arithmetic around its dense
        # solves; the numpy code is the reference and the fallback
        self.engine = engine
        self.E = estar
        self.lo, self.hi = x_lo, x_hi
        self.dlo = self.dhi = (0.0, 0.0)       # d(lo, hi)/d(d, theta), set by the owner
        # slice boundaries lo + (hi - lo) g(k/n), centres midway (slice_positions;
        # refine: the end slices split, n grows)
        self._geometry = (n, grading, refine)        # the key of the cached geometry
        # kernel geometry: for target k and source i the distances from x_k to the source
        # slice's near and far edges, as fractions of the interval (their ratio fixes
        # the log part of the displacement: scale-free, so the same for every grid of
        # this n, grading and refinement; cached)
        self._tnear, self._tfar, self._logratio, self.m, self.dg = _unit_geometry(
            n, grading, refine)
        self.n = len(self.m)
        span = x_hi - x_lo
        self.w = span * self.dg                  # slice widths
        self.x = x_lo + span * self.m
        self.P = drop(self.x)
        self.iterations = 0
        self.span = span
        self.slope_values = None

    def kernels(self, S, b, targets=None, a_only=False):
        """A, D and their b-derivative parts for targets T (default S) and sources S.

        For source i (half-width b_i, width w_i) and target k, with tau = t/b_i at the
        near and far edges of slice i seen from x_k: A = ln(far/near) + r(far) -
        r(near), D = p(far) - p(near), EA and ED the same differences of tau a' and
        tau p'; on the diagonal (the target inside its own slice, tau = +-w_i/2b_i)
        A = 2 ln(w_i/b_i) + 2 r, D = 2 p - 4, EA = 2 tau a', ED = 2 tau p'
        (:func:`linecontact.roller.kernel.strip_influence` for r, p and their
        derivatives).

        Where tau >= 3 at the near edge the four differences are the series in
        (b_i/t)^2 (:func:`linecontact.roller.kernel.far_field_coefficients`), a sum
        over powers of precomputed unit-geometry differences (one small matrix
        product per source); the near band and the diagonal read the spline table.
        With `a_only`, A alone (the others None).
        """
        T = S if targets is None else targets
        if self.engine != "numpy":
            # the C loops (_cengine), the same arithmetic
            jit = c_engine()
            far = self.n <= _N_FAR
            out = jit.kernels(S, T, b, self.span, self.dg, self._tnear, self._tfar,
                              self._logratio,
                              _far_geometry(*self._geometry) if far else None,
                              _FAR_COEF, a_only)
            if out is not None:
                return out
        if self.n > _N_FAR:
            out = self._kernels_table(S, b, T)
            return (out[0], None, None, None) if a_only else out
        n = self.n
        ib = self.span / b
        G = _far_geometry(*self._geometry)
        contiguous = len(S) == S[-1] - S[0] + 1
        cols = slice(S[0], S[-1] + 1) if contiguous else S
        beta = (b * (1.0 / self.span)) ** 2
        coef = _FAR_COEF[:, :1] if a_only else _FAR_COEF
        C = np.power(beta[:, None], _FAR_POW)[:, :, None] * coef        # (ns, K, 4)
        out = np.matmul(G[cols], C)                                         # (ns, n, 4)
        allt = len(T) == n
        if allt:
            out = out.transpose(2, 1, 0)                                    # (4, n, ns)
            tn, tf, lr = self._tnear[:, cols], self._tfar[:, cols], self._logratio[:, cols]
        else:
            out = out[:, T].transpose(2, 1, 0)
            ix = np.ix_(T, S)
            tn, tf, lr = self._tnear[ix], self._tfar[ix], self._logratio[ix]
        A = lr + out[0]
        if a_only:
            EA = D = ED = None
        else:
            EA = out[1].copy()
            D = out[2].copy()
            ED = out[3].copy()
        # the near band: the spline table at both edges; the diagonal: at w_i/2 b_i
        near = tn < _TAU_FAR * (1.0 / ib)
        kk, ii = np.nonzero(near)
        ibi = ib[ii]
        m = len(kk)
        ns = len(S)
        vals = strip_values(np.concatenate([tf[kk, ii] * ibi, tn[kk, ii] * ibi,
                                            (0.5 * self.span) * self.dg[S] / b]))
        r, ta, p, tp = vals[0], vals[1], vals[2], vals[3]
        A[kk, ii] = lr[kk, ii] + (r[:m] - r[m:2 * m])
        if not a_only:
            EA[kk, ii] = ta[:m] - ta[m:2 * m]
            D[kk, ii] = p[:m] - p[m:2 * m]
            ED[kk, ii] = tp[:m] - tp[m:2 * m]
        if allt and contiguous:
            # the diagonal of the loaded rows, a strided view of each matrix
            dA = A[cols].reshape(-1)[::ns + 1]
            views = None if a_only else (D[cols].reshape(-1)[::ns + 1],
                                         EA[cols].reshape(-1)[::ns + 1],
                                         ED[cols].reshape(-1)[::ns + 1])
            kd = idg = None
        else:
            Tk = T if not allt else np.arange(n)
            kd, idg = np.nonzero(Tk[:, None] == S[None, :])
        rd, tad, pd, tpd = r[2 * m:], ta[2 * m:], p[2 * m:], tp[2 * m:]
        if kd is not None:
            rd, tad, pd, tpd = rd[idg], tad[idg], pd[idg], tpd[idg]
            bd, wd = b[idg], self.w[S[idg]]
        else:
            bd, wd = b, self.w[S]
        diagA = 2 * (np.log(wd / bd) + rd)
        if kd is None:
            dA[:] = diagA
            if not a_only:
                views[0][:] = 2 * pd - 4.0
                views[1][:] = 2 * tad
                views[2][:] = 2 * tpd
        else:
            A[kd, idg] = diagA
            if not a_only:
                D[kd, idg] = 2 * pd - 4.0
                EA[kd, idg] = 2 * tad
                ED[kd, idg] = 2 * tpd
        return A, D, EA, ED

    def _kernels_table(self, S, b, T):
        """kernels() with every pair read from the spline table (the reference the
        far-field series is checked against, and the method above _N_FAR slices)."""
        if len(T) == self.n:                   # every slice a target (T = 0..n-1)
            tn, tf, lr = self._tnear[:, S], self._tfar[:, S], self._logratio[:, S]
        else:
            ix = np.ix_(T, S)
            tn, tf, lr = self._tnear[ix], self._tfar[ix], self._logratio[ix]
        nt, ns = tn.shape
        ib = self.span / b
        vals = strip_values(np.concatenate([(tf * ib).ravel(), (tn * ib).ravel()]))
        r, p, ta, tp = (v.reshape(2, nt, ns) for v in
                        (vals[0], vals[2], vals[1], vals[3]))
        A = lr + (r[0] - r[1])
        D = p[0] - p[1]
        EA = ta[0] - ta[1]
        ED = tp[0] - tp[1]
        diag = T[:, None] == S[None, :]
        if diag.any():
            kk, ii = np.nonzero(diag)
            A[kk, ii] = 2 * (np.log(self.w[S[ii]] / b[ii]) + r[1, kk, ii])
            D[kk, ii] = 2 * p[1, kk, ii] - 4.0
            EA[kk, ii] = 2 * ta[1, kk, ii]
            ED[kk, ii] = 2 * tp[1, kk, ii]
        return A, D, EA, ED

    def jacobian(self, S, q, c):
        qs, cs = q[S], c[S]
        b = np.sqrt(qs / cs)
        A, D, EA, ED = self.kernels(S, b)
        ns = len(S)
        J = np.empty((2 * ns, 2 * ns))
        J[:ns, :ns] = A - 0.5 * EA
        J[:ns, ns:] = EA * (0.5 * b * b)[None, :]
        J[ns:, :ns] = -ED * (0.5 / (b * b))[None, :]
        J[ns:, ns:] = D + 0.5 * ED
        self._last_kernels = (A, D, EA, ED)
        return A, D, J

    def newton(self, S, q, c, over, tol):
        """Damped Newton on (q, c) over the slice set S; slices that keep being driven to
        q <= 0 leave S (they are outside the contact)."""
        R = self.R
        blocked = np.zeros(self.n, int)
        for _ in range(400):
            self.iterations += 1
            A, D, J = self.jacobian(S, q, c)
            qs, cs = q[S], c[S]
            ns = len(S)
            res = np.concatenate([A @ qs - over[S], D @ cs + 1.0 / R])
            qsc = np.max(qs)
            colsc = np.concatenate([np.full(ns, qsc), np.full(ns, 1.0 / R)])
            rowsc = np.concatenate([np.full(ns, 1.0 / qsc), np.full(ns, R)])
            step = -np.linalg.solve(J * rowsc[:, None] * colsc[None, :],
                                    res * rowsc) * colsc
            dq, dc = step[:ns], step[ns:]
            alpha, hit_q = _fraction_to_boundary(qs, cs, dq, dc)
            q[S] = qs + alpha * dq
            c[S] = cs + alpha * dc
            if alpha == 1.0:
                blocked[S] = 0
                if np.max(np.abs(dq)) <= tol * qsc and np.max(np.abs(dc)) * R <= tol:
                    return S
                continue
            S = _drop_blocked(S, q, blocked, hit_q, qsc)
        raise ConvergenceError("Newton iteration on the slice loads did not converge "
                               "in 400 steps")

    def solve(self, d, theta, warm=None, tol=1e-11):
        """Active-set solution at depth d and tilt theta; returns (S, q, c)."""
        n, R = self.n, self.R
        over = d + theta * self.x - self.P
        S, q, c = self.start(d, theta, warm)
        for _ in range(n + 1):
            S = self.newton(S, q, c, over, tol)
            rest = np.setdiff1d(np.arange(n), S)
            if len(rest) == 0:
                break
            A = self.kernels(S, np.sqrt(q[S] / c[S]), targets=rest)[0]
            pen = over[rest] - A @ q[S]
            add = pen > tol * np.max(over)
            if not add.any():
                break
            new = rest[add]
            q[new] = pen[add] / 10.0
            c[new] = 1.0 / (4 * R)
            S = np.union1d(S, new)
        else:
            raise ConvergenceError("the active set did not settle")
        return S, q, c

    def sensitivities(self, S, q, c, th, slope):
        """The 2x2 stiffness matrix d(F, M)/d(d, theta) of the discrete model.

        Implicit differentiation of the converged equations R(z; d, theta, lo, hi) = 0
        on the active set, including the motion of the slice grid (its ends lo, hi are
        the overlap ends, which move with d and theta), so that the result is the
        exact derivative of the computed F(d, theta) and M(d, theta).
        """
        _, _, J = self.jacobian(S, q, c)
        A, D, EA, ED = self._last_kernels
        ns = len(S)
        qs, cs, xs, ws = q[S], c[S], self.x[S], self.w[S]
        m = self.m[S]
        # columns: d, theta, lo, hi ; rows: -dR/dp
        rhs = np.zeros((2 * ns, 4))
        rhs[:ns, 0] = 1.0
        rhs[:ns, 1] = xs
        dlnw = np.array([-1.0, 1.0]) / (self.hi - self.lo)    # d ln w_k / d(lo, hi)
        dx = np.stack([1.0 - m, m], axis=1)                    # d x_k / d(lo, hi)
        ea_q, ed_c = EA @ qs, ED @ cs
        for g in range(2):
            rhs[:ns, 2 + g] = -(ea_q * dlnw[g] - (th - slope[S]) * dx[:, g])
            rhs[ns:, 2 + g] = -ed_c * dlnw[g]
        qsc = np.max(qs)
        colsc = np.concatenate([np.full(ns, qsc), np.full(ns, 1.0 / self.R)])
        rowsc = np.concatenate([np.full(ns, 1.0 / qsc), np.full(ns, self.R)])
        z = np.linalg.solve(J * rowsc[:, None] * colsc[None, :], rhs * rowsc[:, None])
        dq = z[:ns] * qsc                                     # d qt / d(d, th, lo, hi)
        dg = self.dg[S]
        dw = np.array([0.0, 0.0, -1.0, 1.0])                  # times dg_k: d w_k
        dxk = np.zeros((ns, 4))
        dxk[:, 2:] = dx
        dF = ws @ dq + dw * (dg @ qs)
        dM = (ws * xs) @ dq + dw * ((dg * qs) @ xs) + (ws * qs) @ dxk
        G = np.array([[1.0, 0.0], [0.0, 1.0], self.dlo, self.dhi])   # d(d, th, lo, hi)/d(d, th)
        return math.pi * self.E * np.array([dF @ G, dM @ G])

    def slope_at_slices(self):
        """dP/dx at the slice centres (``slope_values``, set by the owner with the
        drop: ProfiledRoller._grid)."""
        return self.slope_values

    def start(self, d, theta, warm=None):
        """A first (S, q, c) at depth d and tilt theta: the warm start mapped onto this
        grid, else the linear problem with frozen strip widths, twice (the second time
        with the plane-strain widths b^2 = 4 R q/(pi E*) of the first answer)."""
        n, R = self.n, self.R
        over = d + theta * self.x - self.P
        S = (over > 0).nonzero()[0]
        none_in_contact = ConvergenceError(
            f"no slice is in contact at d = {d:.6g} m: the contact is narrower than one "
            "slice (too small a load for the slicing)")
        if S.size == 0:  # e.g. d - d0 below the rounding of d (a force of 1e-300 N)
            raise none_in_contact
        q = np.zeros(n)
        c = np.full(n, 1.0 / (4 * R))
        if warm is not None and (warm[0][S] > 0).any():
            q[S] = warm[0][S]
            c[S] = np.where(warm[0][S] > 0, warm[1][S], c[S])
            return S[q[S] > 0], q, c
        b0 = np.sqrt(R * over[S])
        for sweep in range(2):
            # the widths are frozen: a slice leaving only removes its row and column
            A = self.kernels(S, b0, a_only=True)[0]
            keep = np.arange(len(S))
            for _ in range(n):
                qs = np.linalg.solve(A[np.ix_(keep, keep)], over[S[keep]])
                if (qs > 0).all():
                    break
                keep = keep[qs > 0]
                if keep.size == 0:
                    raise none_in_contact
            S = S[keep]
            b0 = np.sqrt(4 * R * qs)
        q[S] = qs
        return S, q, c

    def start_at_force(self, regrid, d, theta, force, zero_moment=False, width=None,
                       last_n=None):
        """A cold first (equations, S, q, c, d, theta) for the force `force` [N] (and
        zero moment): the linear problem with frozen strip widths and the force (and
        moment) rows bordering it, so that d (and theta) come out of the same solve,
        :data:`START_SWEEPS` times: each time after the first on the grid of the last
        answer's d and theta, with its plane-strain widths b^2 = 4 R q/(pi E*) mapped
        onto that grid; c = q/b^2 from
        the curvature equations with the same frozen widths (linear in c: over the 104
        cases of tables/roller_accuracy.csv 4 % fewer Newton steps than the plane-strain
        c = 1/(4R), which is kept where that gives c <= 0). Returns None
        where the first answer leaves no contact (the caller then starts at its own
        depth, :meth:`start`). Given `width` (relative positions in the overlap
        interval and strip half-widths there, from a solution nearby), one solve with
        those widths instead. The sweeps before the last run on :data:`START_COARSE`
        times fewer slices (:func:`coarse_slices`; `regrid(d, theta, n)` the grid of n
        base slices; the widths pass between grids by their relative positions, as
        between sweeps), the last on `last_n` base slices (default: this grid's; this
        grid may be the first sweeps' coarse one)."""
        s, R = self, self.R
        nb = 2 if zero_moment else 1
        target = force / (math.pi * self.E)
        sweeps = START_SWEEPS if width is None else 1
        n_full = s._geometry[0] if last_n is None else last_n
        n_coarse = coarse_slices(n_full)
        coarse = width is None and sweeps > 1 and n_coarse < n_full
        if s._geometry[0] != (n_coarse if coarse else n_full):
            s = regrid(d, theta, n_coarse if coarse else n_full)
        for sweep in range(sweeps):
            over = d + theta * s.x - s.P
            S = (over > 0).nonzero()[0]
            if S.size == 0:
                return None
            if width is None:
                b0 = np.sqrt(R * over[S])
            else:
                xi = (s.x[S] - s.lo) / (s.hi - s.lo)
                b0 = np.interp(xi, width[0], width[1])
            # the widths are frozen: a slice leaving only removes its row and column
            last = sweep == sweeps - 1
            A, Dk = s.kernels(S, b0, a_only=not last)[:2]
            ws, xs = s.w[S], s.x[S]
            ns = len(S)
            wm = 1.0 / (ws.sum() / ns)                      # the force row, scaled
            # the bordered matrix of the whole overlap interval, built once a sweep: a
            # slice leaving removes its row and column (the same values as building it
            # anew for the slices left)
            M = np.zeros((ns + nb, ns + nb))
            M[:ns, :ns] = A
            M[:ns, ns] = -1.0
            M[ns, :ns] = ws * wm
            rhs = np.empty(ns + nb)
            rhs[ns] = target * wm
            if zero_moment:
                M[:ns, ns + 1] = -xs
                M[ns + 1, :ns] = M[ns, :ns] * xs
                rhs[:ns] = -s.P[S]
                rhs[ns + 1] = 0.0
            else:
                rhs[:ns] = theta * xs - s.P[S]
            keep = None
            for _ in range(s.n):
                z = np.linalg.solve(M, rhs)
                qs = z[:ns]
                if (qs > 0).all():
                    break
                on = qs > 0
                S, b0 = S[on], b0[on]
                keep = on.nonzero()[0] if keep is None else keep[on]
                if S.size == 0:
                    return None
                rows = np.concatenate([on.nonzero()[0], np.arange(ns, ns + nb)])
                M, rhs = M.take(rows, 0).take(rows, 1), rhs[rows]   # (np.ix_: 5x the time)
                ns = len(S)
            if keep is not None and Dk is not None:
                Dk = Dk.take(keep, 0).take(keep, 1)
            d_new = float(z[ns])
            th_new = float(z[ns + 1]) if zero_moment else theta
            if not (math.isfinite(d_new) and abs(th_new) < TILT_RANGE.high):
                return None
            width = ((s.x[S] - s.lo) / (s.hi - s.lo), np.sqrt(4 * R * qs))
            qrel = qs
            if sweep < sweeps - 1:
                d, theta = d_new, th_new
                s2 = regrid(d, theta, n_coarse if coarse and sweep < sweeps - 2 else n_full)
                s2.iterations = s.iterations
                s = s2
        q = np.zeros(s.n)
        q[S] = qrel
        c = np.full(s.n, 1.0 / (4 * R))
        if Dk is not None:
            # the curvature equations D c = -1/R with the same frozen widths
            cs = np.linalg.solve(Dk, np.full(len(S), -1.0 / R))
            if (cs > 0).all():
                c[S] = cs
        return s, S, q, c, d_new, th_new

    def linearised(self, S, q, c, theta, slope, targets):
        """Residual, Jacobian and grid terms of the slice equations at (q, c) on S.

        Returns the residual res (2 ns), the Jacobian J (2 ns x 2 ns), the columns
        -dR/d(d, theta) at fixed (q, c) with the motion of the grid (2 ns x 2), the
        gaps over the `targets` (overlap minus displacement, for the active set) and
        d(w.q, (w x).q)/d(d, theta) at fixed q (2 x 2): what one Newton step on the
        slice loads together with d and theta needs, and at convergence the implicit
        derivative (:meth:`sensitivities`).
        """
        if self.engine != "numpy":
            spos = S if len(targets) == self.n else np.searchsorted(targets, S)
            far = self.n <= _N_FAR
            out = c_engine().linearised(
                S, targets, spos, q, c, self._over, self.R, self.span, self.x, self.m,
                self.dg, slope, theta, self.dlo, self.dhi, self._tnear, self._tfar,
                self._logratio, _far_geometry(*self._geometry) if far else None,
                _FAR_COEF)
            if out is not None:
                return out
        R = self.R
        qs, cs = q[S], c[S]
        bb = qs / cs
        b = np.sqrt(bb)
        A, D, EA, ED = self.kernels(S, b, targets=targets)
        gap = self._over[targets] - A @ qs
        if len(targets) == self.n:                 # rows of S among the targets
            pos = slice(S[0], S[-1] + 1) if len(S) == S[-1] - S[0] + 1 else S
        else:
            pos = np.searchsorted(targets, S)
        A, D, EA, ED = A[pos], D[pos], EA[pos], ED[pos]
        ns = len(S)
        res = np.empty(2 * ns)
        res[:ns] = gap[pos]
        res[:ns] *= -1.0
        np.matmul(D, cs, out=res[ns:])
        res[ns:] += 1.0 / R
        J = np.empty((2 * ns, 2 * ns))
        np.multiply(EA, -0.5, out=J[:ns, :ns])
        J[:ns, :ns] += A
        np.multiply(EA, 0.5 * bb, out=J[:ns, ns:])
        np.multiply(ED, -0.5 / bb, out=J[ns:, :ns])
        np.multiply(ED, 0.5, out=J[ns:, ns:])
        J[ns:, ns:] += D
        xs, ws, m, dg = self.x[S], self.w[S], self.m[S], self.dg[S]
        # -dR/d(lo, hi) times d(lo, hi)/d(d, theta), with d ln w_k/d(lo, hi) =
        # (-1, 1)/(hi - lo) and d x_k/d(lo, hi) = (1 - m_k, m_k)
        (g00, g01), (g10, g11) = self.dlo, self.dhi
        span = self.hi - self.lo
        gw = np.array([(g10 - g00) / span, (g11 - g01) / span])    # d ln w/d(d, theta)
        ea_q, ed_c = EA @ qs, ED @ cs
        rhs = np.empty((2 * ns, 2))
        ts = theta - slope[S]
        np.multiply.outer(m, [g10 - g00, g11 - g01], out=rhs[:ns])
        rhs[:ns] += [g00, g01]
        rhs[:ns] *= ts[:, None]
        rhs[:ns] -= np.multiply.outer(ea_q, gw)
        np.multiply.outer(ed_c, -gw, out=rhs[ns:])
        rhs[:ns, 0] += 1.0
        rhs[:ns, 1] += xs
        # d(w.q, (w x).q)/d(lo, hi) at fixed q, then by the chain rule
        dq = float(dg @ qs)
        dxq = float((dg * qs) @ xs)
        wq = ws * qs
        wm = float(wq @ m)
        w1m = float(wq.sum()) - wm                             # (ws qs) @ (1 - m)
        dwxq = (-dxq + w1m, dxq + wm)
        grid = np.array([[dq * (g10 - g00), dq * (g11 - g01)],
                         [dwxq[0] * g00 + dwxq[1] * g10, dwxq[0] * g01 + dwxq[1] * g11]])
        return res, J, rhs, gap, grid

    def bordered(self, regrid, S, q, c, d, theta, force=None, zero_moment=False,
                 tol=1e-11, max_steps=60):
        """Newton's method on (q, c) together with d (given force: w.q = F/(pi E*))
        and/or theta (zero moment: (w x).q = 0), the grid rebuilt at every step.

        One dense solve (three right-hand sides) per step replaces the nested
        iteration (an outer Newton on d or theta around a converged inner solve).
        `regrid(d, theta)` returns the SliceEquations of that depth and tilt (the slice
        index k keeps its place in the overlap interval). Damped to keep q, c > 0;
        slices driven to q <= 0 leave; unloaded slices that would interpenetrate
        join. Ends at a full step below `tol` (in loads over the largest, c R, and d
        and theta's travel over the largest overlap), or where Newton's error estimate
        of the state after a full step is below it (:func:`newton_error` times
        NEWTON_C; the steps contracting faster than linearly, no unloaded slice close
        to touching): that state is returned on its own grid. Returns (equations, S,
        q, c, d, theta, F, M, K) with the force and moment of the returned state and
        the stiffness matrix K of the last linearisation (where the estimate ended the
        solve, at the state one full step before: within about sqrt(tol/NEWTON_C)
        relative), or raises ConvergenceError.
        """
        n, R, piE = self.n, self.R, math.pi * self.E
        s = self
        blocked = np.zeros(n, int)
        left_count = np.zeros(n, int)
        everyone = np.arange(n)
        last_size = math.inf            # the last step's size (inf: none, or damped)
        # the grid is that of the current (d, theta) once rebuilt: the one passed in
        # may not be (start_at_force returns its last sweep's grid, built at the sweep
        # before's answer, with that answer's d and theta; a warm start's single sweep
        # is solved on the grid of the depth it started from). A step on such a grid
        # solves equations whose ends are not those of its d and theta: however small,
        # it says nothing of the error of the state on its own grid (a sweep's solve,
        # offset crown at a free tilt, ended on its first step with F off by 1.6e-7)
        own_grid = force is None and not zero_moment
        for _ in range(max_steps):
            s.iterations += 1
            over = d + theta * s.x - s.P
            s._over = over
            slope = s.slope_at_slices()
            res, J, rhs, gap, grid = s.linearised(S, q, c, theta, slope, everyone)
            ns = len(S)
            qs, cs = q[S], c[S]
            qsc = float(qs.max())
            # scaled unknowns (q/qsc, c R) and rows (gap/qsc, curvature R): only the
            # off-diagonal blocks change
            # (the C engine: the same lines in C, numpy's dense solve between them)
            jit = c_engine() if s.engine == "c" else None
            fused = status = None
            if jit is not None:
                # the scaling, dense solve, sums, step, mask and damped update below in
                # one call (_cengine.newton_step: the same arithmetic); it stops where
                # slices leave (status 1) or Cramer's rule fails (2), and the lines
                # below go on from there
                fused = jit.newton_step(
                    J, res, rhs, grid, ns, qsc, R, s.w, s.x, S, qs, cs,
                    0.0 if force is None else force / piE,
                    (force is not None) + 2 * bool(zero_moment), q, c, over)
                B = fused[1]
                if fused[0] is None:         # a singular system: numpy's solve raises
                    fused = None
            else:
                B = scaled_system(J, res, rhs, ns, qsc, R)
            left = None
            while True:
                if fused is not None:
                    status, _, z, K, step, dz, out, hit_q, upd = fused
                    fused = None
                    if status == 2:
                        step = np.linalg.solve(K, step[2:])
                        dz, out, nout = jit.step_out(z, step[0], step[1], ns, qs)
                    else:
                        nout = status        # 1: slices leave (0: the update is done)
                else:
                    status = None
                    if jit is not None:
                        # the dense solve, then the sums in one C call
                        z, wq, wxq, Wz = jit.solve_sums(J, B, ns, qsc, R, s.w, s.x, S, qs)
                    else:
                        z = np.linalg.solve(J, B)
                        z[:ns] *= qsc
                        z[ns:] *= 1.0 / R
                        W = np.empty((2, ns))
                        s.w.take(S, out=W[0])
                        np.multiply(W[0], s.x[S], out=W[1])
                        wq, wxq = W @ qs
                        Wz = W @ z[:ns]
                    # K = d(w.q, (w x).q)/d(d, theta) along the equations (per pi E*)
                    K = Wz[:, 1:] + grid
                    lin = Wz[:, 0]
                    if force is not None and zero_moment:
                        r = (force / piE - wq - lin[0], -wxq - lin[1])
                        # (the C engine: the 2 x 2 system by Cramer's rule,
                        # np.linalg.solve's call costs more than its arithmetic)
                        step = _cramer(K, r) if jit is not None else None
                        if step is None:
                            step = np.linalg.solve(K, np.array(r))
                    elif force is not None:
                        step = np.array([(force / piE - wq - lin[0]) / K[0, 0], 0.0])
                    elif zero_moment:
                        step = np.array([0.0, (-wxq - lin[1]) / K[1, 1]])
                    else:
                        step = np.zeros(2)
                    if jit is not None:
                        dz, out, nout = jit.step_out(z, step[0], step[1], ns, qs)
                    else:
                        dz = z[:, 0] + z[:, 1:] @ step
                dq, dc = dz[:ns], dz[ns:]
                # slices at an end of the loaded set that the full step drives to q < 0
                # are outside the contact: they leave at once (they would only block the
                # step), and the step is solved again without them on the same
                # linearisation (_unloaded: no new kernels; a fresh linearisation for
                # each slice leaving took 22 % more linearisations over the 104 cases
                # of tables/roller_accuracy.csv)
                if status == 0:
                    break
                if jit is None:
                    out = qs + dq < 0
                    nout = out.any()
                if not (nout and ns > 2):
                    break
                out = _end_runs(S, out)
                if not out.any() or out.all():
                    break
                J, B = _unloaded(J, B, out, qs / qsc, cs * R)
                left = S[out] if left is None else np.union1d(left, S[out])
                left_count[S[out]] += 1
                q[S[out]] = 0.0
                S = S[~out]
                ns = len(S)
                qs, cs = q[S], c[S]
            if status == 0:
                # (done in the fused step)
                alpha, dmax, dqmax, dcmax = (float(v) for v in upd)
            elif jit is not None:
                # the same update in one C call (_cengine.step_update)
                alpha, hit_q, dmax, dqmax, dcmax = jit.step_update(
                    q, c, S, qs, cs, dq, dc, over, s.x, step[0], step[1])
            else:
                alpha, hit_q = _fraction_to_boundary(qs, cs, dq, dc)
                # keep the rigid overlap positive: no step lowers it by more than half
                # its largest value (d stays above first contact)
                dmax = float(over.max())
                # (at a given tilt the step in theta is 0: the drop is -step[0])
                drop = -float((step[0] + step[1] * s.x[S]).min()) if step[1] != 0.0 else (
                    -float(step[0]))
                if drop > 0.5 * dmax:
                    alpha = min(alpha, 0.5 * dmax / drop)
                if alpha == 1.0:
                    q[S] = qs + dq
                    c[S] = cs + dc
                else:
                    q[S] = qs + alpha * dq
                    c[S] = cs + alpha * dc
                dqmax = float(np.abs(dq).max())
                dcmax = None
            d = d + alpha * step[0]
            theta = theta + alpha * step[1]
            if not abs(theta) < TILT_RANGE.high:
                raise ConvergenceError("the tilt left the admissible range")
            # the full step's size in the scaled unknowns (loads over the largest, c R,
            # d and the tilt's travel over the interval, over the largest overlap),
            # where it may end the solve (not above NEAR_STEP)
            size = dqmax / qsc if alpha == 1.0 else math.inf
            if size <= NEAR_STEP:
                if dcmax is None:
                    dcmax = float(np.abs(dc).max())
                size = max(size, dcmax * R, abs(step[0]) / dmax,
                           abs(step[1]) * (s.hi - s.lo) / dmax)
            small = size <= tol
            # Newton's own error estimate: a full step on an unchanged loaded set that
            # leaves an error below tol ends the solve without a step to confirm it
            # (newton_error: the state after this step is returned, on its own grid)
            # (and only where the steps contract faster than linearly, size <= the
            # last step's size^1.5: a Newton stalled at its rounding floor, an
            # ill-conditioned system's, is never taken as converged)
            near = (not small and own_grid and left is None and size <= NEAR_STEP
                    and size <= last_size ** 1.5
                    and NEWTON_C * newton_error(qs, cs, dq, dc, qsc, R, step[0] / dmax,
                                                step[1] * (s.hi - s.lo) / dmax) <= tol)
            last_size = size
            if alpha == 1.0:
                blocked[S] = 0
                # the active set is checked once no load changes by more than the
                # largest (not only at convergence: a slice that joins late costs
                # steps; over the 104 cases of tables/roller_accuracy.csv this takes
                # fewer steps than checking from a step of 5 % or 20 % of it)
                if dqmax <= qsc:
                    pen = gap > tol * dmax
                    pen[S] = False
                    if left is not None:      # their gaps are those before they left
                        pen[left] = False
                    add = pen.nonzero()[0]
                    if not small and len(add):
                        # a slice that left three times rejoins only once the others
                        # have converged without it: at a contact end between two
                        # slices (the refined end zones of a logarithmic profile) it
                        # could join and leave for ever (table cases 28 and 45 did so
                        # when a refinement started from the coarser level's loads; a
                        # safeguard now: no step count over the 104 cases changes)
                        add = add[left_count[add] < 3]
                    if near and len(add) == 0:
                        # no unloaded slice within GAP_MARGIN steps of touching: a gap
                        # moves by about the step's size over the step
                        close = gap > -GAP_MARGIN * size * dmax
                        close[S] = False
                        if close.any():
                            near = False
                        elif force is not None or zero_moment:
                            it = s.iterations
                            s = regrid(d, theta)
                            s.iterations = it
                    if len(add) == 0 and (small or near):
                        F = piE * (s.w @ q)
                        M = piE * ((s.w * s.x) @ q)
                        return s, S, q, c, d, theta, F, M, piE * K
                    if len(add):
                        q[add] = gap[add] / 10.0
                        c[add] = 1.0 / (4 * R)
                        S = np.union1d(S, add)
            else:
                S = _drop_blocked(S, q, blocked, hit_q, qsc)
            if force is not None or zero_moment:
                it = s.iterations
                s = regrid(d, theta)
                s.iterations = it
                own_grid = True
                # slices outside the new overlap interval's grid keep their index
        raise ConvergenceError("Newton iteration on the slice loads (bordered) did not "
                               f"converge in {max_steps} steps")
