/*
 * The two hot loops of the coupled-slice equations in C99 (engine "c"): the kernels
 * A, EA, D, ED of SliceEquations.kernels and the residual, Jacobian and grid terms of
 * SliceEquations.linearised (linecontact/roller/slices.py, the numpy reference), with
 * the same series coefficients, spline table and cached geometry
 * (linecontact/roller/_layout.py), one source slice at a time: the far-field series (all its terms, every target), the near band from the cubic
 * spline table of the strip functions (kernel.spline_table), the diagonal; beyond the
 * table (tau >= tau_max) the series in (b/t)^2, below it (tau < tau_min) a call
 * returns False and the caller takes the numpy path. Also the bordered Newton step's
 * small arithmetic around numpy's dense solve (SliceEquations.bordered's lines: the
 * scaled system, the force and moment sums, the step, its mask and the damped
 * update), which numpy's many small array operations made cost more than the loops
 * above. Results agree with numpy's to rounding (the order of sums differs;
 * tests/test_slice_kernels_c_equal_numpy.py).
 *
 * IEEE double arithmetic: built without -ffast-math and with -ffp-contract=off (no
 * fused multiply-adds), so that every operation rounds as numpy's does.
 *
 * Arrays come through the buffer protocol (no numpy headers at build time): each is
 * checked to be C-contiguous, of item size 8 and of the right kind (float64 'd' or
 * int64 'q'/'l') and length, and every slice index to lie in range, before any is
 * read; a mismatch raises ValueError. The Python wrapper (_cengine.py) allocates the
 * outputs (matrices in Fortran order: passed here as their C-order transposes). The
 * loops run without the GIL, with their scratch memory per call (thread-safe).
 *
 * This file and linecontact/_cstresses.c (the stresses' corner sums) are the two
 * sources of the one extension module linecontact._ckernels (setup.py); its PyInit is
 * here, at the end.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(_MSC_VER)
/* no fused multiply-adds (before VS2022 /fp:precise alone allowed them under /arch:AVX2) */
#pragma fp_contract(off)
#endif

/* the series of a near-band pair beyond the spline table stops once the next power of
 * x = (b/t)^2 is below FAR_STOP (numpy sums a fixed number of terms: the same to
 * rounding of the matrix, docs/profiled_rollers.md, "Engines"); the far field takes
 * every term */
#define FAR_STOP 1e-18

/* the spline table (set once per process by set_table): coef[(segment * 4 + power) * 4 + function] */
static struct {
    double *coef;
    Py_ssize_t nseg;
    double tmin, tmax, z0, ih, h, r_inf;
} TAB = {NULL, 0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

/* ---------------------------------------------------------------------------------- */
/* the loops (no Python objects: they run without the GIL)                            */

typedef struct {
    Py_ssize_t n, K, nfc;           /* slices, far-field powers, series terms */
    double span;
    const double *dg, *tn, *tf, *lr, *ltn, *ltf, *Gt, *fc;
    int far;
} Geometry;

/* C[i, j, f] = beta_i^(j+1) fc[j, f], beta = (b/span)^2 */
static void far_powers(const double *b, Py_ssize_t ns, double span, const double *fc,
                       Py_ssize_t K, double *C)
{
    for (Py_ssize_t i = 0; i < ns; i++) {
        double bs = b[i] * (1.0 / span);
        double beta = bs * bs;
        double bp = 1.0;
        for (Py_ssize_t j = 0; j < K; j++) {
            bp *= beta;
            for (int f = 0; f < 4; f++)
                C[(i * K + j) * 4 + f] = bp * fc[j * 4 + f];
        }
    }
}

/* the four kernels of source slice si (half-width bi, far-field coefficients Cs) at
 * every slice k: W[f * n + k], f = A, EA, D, ED (W[1:] undefined off the near band
 * unless full); 0 where a spline argument falls below the table */
static int column(const Geometry *g, Py_ssize_t si, double bi, const double *Cs,
                  int full, double *W)
{
    const Py_ssize_t n = g->n;
    const double span = g->span;
    const double *coef = TAB.coef;
    const Py_ssize_t nseg = TAB.nseg;
    const double tmin = TAB.tmin, tmax = TAB.tmax, z0 = TAB.z0, ih = TAB.ih, h = TAB.h;
    double ibi = span / bi;
    double thr = 3.0 * (1.0 / ibi);
    const double *tnr = g->tn + si * n;
    Py_ssize_t kl = 0, kr = n - 1;
    double *w0 = W, *w1 = W + n, *w2 = W + 2 * n, *w3 = W + 3 * n;
    if (g->far) {
        kl = si;
        while (kl > 0 && tnr[kl - 1] < thr)
            kl--;
        kr = si;
        while (kr < n - 1 && tnr[kr + 1] < thr)
            kr++;
        const Py_ssize_t K = g->K;
        const double *gs = g->Gt + si * K * n;
        /* the far-field series, every term j in turn, over every target; the near
         * band's entries are overwritten below */
        for (Py_ssize_t j = 0; j < K; j++) {
            const double *gj = gs + j * n;
            const double c0 = Cs[j * 4], c1 = Cs[j * 4 + 1], c2 = Cs[j * 4 + 2],
                         c3 = Cs[j * 4 + 3];
            if (j == 0) {
                for (Py_ssize_t k = 0; k < n; k++)
                    w0[k] = gj[k] * c0;
                if (full)
                    for (Py_ssize_t k = 0; k < n; k++) {
                        w1[k] = gj[k] * c1;
                        w2[k] = gj[k] * c2;
                        w3[k] = gj[k] * c3;
                    }
                continue;
            }
            if (!full) {
                for (Py_ssize_t k = 0; k < n; k++)
                    w0[k] += gj[k] * c0;
                continue;
            }
            for (Py_ssize_t k = 0; k < n; k++) {
                w0[k] += gj[k] * c0;
                w1[k] += gj[k] * c1;
                w2[k] += gj[k] * c2;
                w3[k] += gj[k] * c3;
            }
        }
        const double *lrr = g->lr + si * n;
        for (Py_ssize_t k = 0; k < n; k++)
            w0[k] = lrr[k] + w0[k];
    }
    /* the near band (every pair without the far field) at both edges, the diagonal at
     * tau = w/2b */
    const double *tfr = g->tf + si * n, *ltnr = g->ltn + si * n, *ltfr = g->ltf + si * n;
    const double *fc = g->fc;
    const Py_ssize_t nfc = g->nfc;
    double lib = log(ibi);
    for (Py_ssize_t k = kl; k <= kr; k++) {
        int ntau;
        double tau0, tau1, z0k, z1k;
        if (k == si) {
            ntau = 1;
            tau0 = (0.5 * span) * g->dg[si] / bi;
            tau1 = tau0;
            z0k = log(tau0);
            z1k = z0k;
        } else {
            ntau = 2;
            tau0 = tfr[k] * ibi;
            tau1 = tnr[k] * ibi;
            z0k = ltfr[k] + lib;
            z1k = ltnr[k] + lib;
        }
        double r = 0.0, ta = 0.0, p = 0.0, tp = 0.0;
        for (int e = 0; e < ntau; e++) {
            double tau = e == 0 ? tau0 : tau1;
            double sg = e == 0 ? 1.0 : -1.0;
            if (tau >= tmax) {
                double x = 1.0 / (tau * tau);
                double xp = 1.0;
                double sr = 0.0, sta = 0.0, sp = 0.0, stp = 0.0;
                for (Py_ssize_t j = 0; j < nfc; j++) {
                    xp *= x;
                    sr += fc[j * 4] * xp;
                    sta += fc[j * 4 + 1] * xp;
                    sp += fc[j * 4 + 2] * xp;
                    stp += fc[j * 4 + 3] * xp;
                    if (xp * x < FAR_STOP)
                        break;
                }
                r += sg * (TAB.r_inf + sr);
                ta += sg * (1.0 + sta);
                p += sg * sp;
                tp += sg * stp;
                continue;
            }
            if (!(tmin <= tau))          /* (NaN included) */
                return 0;
            double u = ((e == 0 ? z0k : z1k) - z0) * ih;
            Py_ssize_t i = (Py_ssize_t)u;
            if (i > nseg - 1)
                i = nseg - 1;
            double t = (u - (double)i) * h;
            const double *c = coef + i * 16;    /* c[power * 4 + function] */
            r += sg * (((c[12] * t + c[8]) * t + c[4]) * t + c[0]);
            ta += sg * (((c[13] * t + c[9]) * t + c[5]) * t + c[1]);
            p += sg * (((c[14] * t + c[10]) * t + c[6]) * t + c[2]);
            tp += sg * (((c[15] * t + c[11]) * t + c[7]) * t + c[3]);
        }
        if (ntau == 1) {
            w0[k] = 2.0 * (log(span * g->dg[si] / bi) + r);
            w1[k] = 2.0 * ta;
            w2[k] = 2.0 * p - 4.0;
            w3[k] = 2.0 * tp;
        } else {
            w0[k] = g->lr[si * n + k] + r;
            w1[k] = ta;
            w2[k] = p;
            w3[k] = tp;
        }
    }
    return 1;
}

/* SliceEquations.kernels; At, EAt, Dt, EDt are (ns, nt) C order (the transposes of the
 * Fortran-order (nt, ns) matrices); EAt NULL: A alone. Returns 1, 0 (below the table)
 * or -1 (out of memory). */
static int kernels_loop(const Geometry *g, const int64_t *S, Py_ssize_t ns,
                        const int64_t *T, Py_ssize_t nt, const double *b, double *At,
                        double *EAt, double *Dt, double *EDt)
{
    const Py_ssize_t n = g->n, K = g->far ? g->K : 1;
    const int full = EAt != NULL;
    double *C = malloc(sizeof(double) * (size_t)(ns * K * 4 + 4 * n));
    if (C == NULL)
        return -1;
    double *W = C + ns * K * 4;
    if (g->far)
        far_powers(b, ns, g->span, g->fc, K, C);
    else
        memset(C, 0, sizeof(double) * (size_t)(ns * K * 4));
    int ok = 1;
    for (Py_ssize_t s = 0; s < ns && ok; s++) {
        if (!column(g, (Py_ssize_t)S[s], b[s], C + s * K * 4, full, W)) {
            ok = 0;
            break;
        }
        for (Py_ssize_t kt = 0; kt < nt; kt++)
            At[s * nt + kt] = W[T[kt]];
        if (full)
            for (Py_ssize_t kt = 0; kt < nt; kt++) {
                Py_ssize_t k = (Py_ssize_t)T[kt];
                EAt[s * nt + kt] = W[n + k];
                Dt[s * nt + kt] = W[2 * n + k];
                EDt[s * nt + kt] = W[3 * n + k];
            }
    }
    free(C);
    return ok;
}

typedef struct {
    const int64_t *S, *T, *spos;
    Py_ssize_t ns, nt;
    const double *q, *c, *over, *x, *m, *slope;
    double R, theta, dlo[2], dhi[2];
} State;

/* SliceEquations.linearised: res (2 ns), Jt (the C-order transpose of the Fortran-order
 * J, 2 ns x 2 ns), rhs (2 ns x 2), gap (nt), grid (2 x 2). Returns 1, 0 or -1. */
static int linearised_loop(const Geometry *g, const State *st, double *res, double *Jt,
                           double *rhs, double *gap, double *grid)
{
    const Py_ssize_t n = g->n, ns = st->ns, nt = st->nt, n2 = 2 * ns;
    const Py_ssize_t K = g->far ? g->K : 1;
    const int64_t *S = st->S, *T = st->T;
    const double span = g->span;
    double *mem = malloc(sizeof(double) * (size_t)(7 * ns + nt + ns * K * 4 + 4 * n));
    if (mem == NULL)
        return -1;
    double *qs = mem, *cs = qs + ns, *b = cs + ns, *bb = b + ns, *dc = bb + ns,
           *eaq = dc + ns, *edc = eaq + ns, *aq = edc + ns, *C = aq + nt,
           *W = C + ns * K * 4;
    for (Py_ssize_t s = 0; s < ns; s++) {
        qs[s] = st->q[S[s]];
        cs[s] = st->c[S[s]];
        bb[s] = qs[s] / cs[s];
        b[s] = sqrt(bb[s]);
        dc[s] = eaq[s] = edc[s] = 0.0;
    }
    for (Py_ssize_t kt = 0; kt < nt; kt++)
        aq[kt] = 0.0;
    if (g->far)
        far_powers(b, ns, span, g->fc, K, C);
    else
        memset(C, 0, sizeof(double) * (size_t)(ns * K * 4));
    for (Py_ssize_t s = 0; s < ns; s++) {
        if (!column(g, (Py_ssize_t)S[s], b[s], C + s * K * 4, 1, W)) {
            free(mem);
            return 0;
        }
        const double qv = qs[s], cv = cs[s];
        const double hb = 0.5 * bb[s];
        const double mhb = -0.5 / bb[s];
        for (Py_ssize_t kt = 0; kt < nt; kt++)
            aq[kt] += W[T[kt]] * qv;
        /* columns s and ns + s of J: rows s * n2 and (ns + s) * n2 of Jt */
        double *j0 = Jt + s * n2, *j1 = Jt + (ns + s) * n2;
        for (Py_ssize_t p = 0; p < ns; p++) {
            const Py_ssize_t k = (Py_ssize_t)S[p];
            const double a = W[k], ea = W[n + k], d = W[2 * n + k], ed = W[3 * n + k];
            j0[p] = a + (-0.5) * ea;
            j0[ns + p] = ed * mhb;
            j1[p] = ea * hb;
            j1[ns + p] = ed * 0.5 + d;
            dc[p] += d * cv;
            eaq[p] += ea * qv;
            edc[p] += ed * cv;
        }
    }
    for (Py_ssize_t kt = 0; kt < nt; kt++)
        gap[kt] = st->over[T[kt]] - aq[kt];
    const double *dlo = st->dlo, *dhi = st->dhi;
    for (Py_ssize_t p = 0; p < ns; p++) {
        const Py_ssize_t k = (Py_ssize_t)S[p];
        res[p] = -gap[st->spos[p]];
        res[ns + p] = dc[p] + 1.0 / st->R;
        /* -dR/d(d, theta) with the grid's motion (as the numpy code) */
        const double ts = st->theta - st->slope[k];
        for (int gi = 0; gi < 2; gi++) {
            rhs[p * 2 + gi] = (st->m[k] * (dhi[gi] - dlo[gi]) + dlo[gi]) * ts;
            rhs[p * 2 + gi] -= eaq[p] * ((dhi[gi] - dlo[gi]) / span);
            rhs[(ns + p) * 2 + gi] = edc[p] * (-((dhi[gi] - dlo[gi]) / span));
        }
        rhs[p * 2] += 1.0;
        rhs[p * 2 + 1] += st->x[k];
    }
    /* d(w.q, (w x).q)/d(d, theta) at fixed q */
    double dq = 0.0, dxq = 0.0, wqs = 0.0, wm = 0.0;
    for (Py_ssize_t s = 0; s < ns; s++) {
        const Py_ssize_t si = (Py_ssize_t)S[s];
        dq += g->dg[si] * qs[s];
        dxq += (g->dg[si] * qs[s]) * st->x[si];
        double wq = (span * g->dg[si]) * qs[s];
        wqs += wq;
        wm += wq * st->m[si];
    }
    const double w1m = wqs - wm;
    const double dw0 = -dxq + w1m;
    const double dw1 = dxq + wm;
    for (int gi = 0; gi < 2; gi++) {
        grid[gi] = dq * (dhi[gi] - dlo[gi]);
        grid[2 + gi] = dw0 * dlo[gi] + dw1 * dhi[gi];
    }
    free(mem);
    return 1;
}

/* ---------------------------------------------------------------------------------- */
/* the bordered Newton step's small arithmetic around numpy's dense solve
 * (SliceEquations.bordered's lines, in the same order)                              */

/* J's off-diagonal blocks scaled in place, J[i, j] at J[i * si + j * sj], and the
 * right-hand sides B (2 ns x 3, C order) */
static void scaled_system_loop(double *J, Py_ssize_t si, Py_ssize_t sj, const double *res,
                               const double *rhs, Py_ssize_t ns, double f_hi, double f_lo,
                               double g_q, double h_q, double R, double *B)
{
    const Py_ssize_t n2 = 2 * ns;
    for (Py_ssize_t j = ns; j < n2; j++)
        for (Py_ssize_t i = 0; i < ns; i++)
            J[i * si + j * sj] *= f_hi;
    for (Py_ssize_t j = 0; j < ns; j++)
        for (Py_ssize_t i = ns; i < n2; i++)
            J[i * si + j * sj] *= f_lo;
    for (Py_ssize_t i = 0; i < ns; i++) {
        B[i * 3] = res[i] * g_q;
        B[i * 3 + 1] = rhs[i * 2] * h_q;
        B[i * 3 + 2] = rhs[i * 2 + 1] * h_q;
    }
    const double mR = -R;
    for (Py_ssize_t i = ns; i < n2; i++) {
        B[i * 3] = res[i] * mR;
        B[i * 3 + 1] = rhs[i * 2] * R;
        B[i * 3 + 2] = rhs[i * 2 + 1] * R;
    }
}

/* z (2 ns x 3, C order) unscaled in place; the force and moment rows: sums[0] = w.q,
 * sums[1] = (w x).q over S, Wz (2 x 3) those rows times z's load part */
static void bordered_sums_loop(double *z, Py_ssize_t ns, double qsc, double r_inv,
                               const double *w, const double *x, const int64_t *S,
                               const double *qs, double *Wz, double *sums)
{
    const Py_ssize_t n2 = 2 * ns;
    for (int j = 0; j < 3; j++) {
        for (Py_ssize_t i = 0; i < ns; i++)
            z[i * 3 + j] *= qsc;
        for (Py_ssize_t i = ns; i < n2; i++)
            z[i * 3 + j] *= r_inv;
    }
    double wq = 0.0, wxq = 0.0;
    for (int j = 0; j < 6; j++)
        Wz[j] = 0.0;
    for (Py_ssize_t i = 0; i < ns; i++) {
        const double wi = w[S[i]];
        const double wx = wi * x[S[i]];
        wq += wi * qs[i];
        wxq += wx * qs[i];
        for (int j = 0; j < 3; j++) {
            Wz[j] += wi * z[i * 3 + j];
            Wz[3 + j] += wx * z[i * 3 + j];
        }
    }
    sums[0] = wq;
    sums[1] = wxq;
}

/* the step dz = z[:, 0] + z[:, 1:] (s0, s1) and the mask of the loaded slices it drives
 * below zero; returns how many */
static Py_ssize_t step_out_loop(const double *z, double s0, double s1, Py_ssize_t ns,
                                const double *qs, double *dz, char *out)
{
    for (Py_ssize_t i = 0; i < 2 * ns; i++)
        dz[i] = z[i * 3] + (z[i * 3 + 1] * s0 + z[i * 3 + 2] * s1);
    Py_ssize_t k = 0;
    for (Py_ssize_t i = 0; i < ns; i++) {
        out[i] = qs[i] + dz[i] < 0.0;
        if (out[i])
            k++;
    }
    return k;
}

/* the damped update: q[S], c[S] in place; res = (alpha,
 * largest overlap, largest |dq|, largest |dc|) */
static void step_update_loop(double *q, double *c, const int64_t *S, Py_ssize_t ns,
                             const double *qs, const double *cs, const double *dq,
                             const double *dc, const double *over, Py_ssize_t n,
                             const double *x, double s0, double s1, char *hit_q,
                             double *res)
{
    double alpha = 1.0;
    for (Py_ssize_t i = 0; i < ns; i++) {
        hit_q[i] = qs[i] + dq[i] <= 0.05 * qs[i];
        if (hit_q[i]) {
            double a = 0.95 * qs[i] / -dq[i];
            if (a < alpha)
                alpha = a;
        }
    }
    double amin = INFINITY;
    for (Py_ssize_t i = 0; i < ns; i++)
        if (cs[i] + dc[i] <= 0.2 * cs[i]) {
            double a = 0.8 * cs[i] / -dc[i];
            if (a < amin)
                amin = a;
        }
    if (amin < alpha)
        alpha = amin;
    double dmax = over[0];
    for (Py_ssize_t i = 1; i < n; i++)
        if (over[i] > dmax)
            dmax = over[i];
    double drop;
    if (s1 != 0.0) {
        double lowest = INFINITY;
        for (Py_ssize_t i = 0; i < ns; i++) {
            double v = s0 + s1 * x[S[i]];
            if (v < lowest)
                lowest = v;
        }
        drop = -lowest;
    } else
        drop = -s0;
    if (drop > 0.5 * dmax) {
        double a = 0.5 * dmax / drop;
        if (a < alpha)
            alpha = a;
    }
    double dqmax = 0.0, dcmax = 0.0;
    for (Py_ssize_t i = 0; i < ns; i++) {
        if (alpha == 1.0) {
            q[S[i]] = qs[i] + dq[i];
            c[S[i]] = cs[i] + dc[i];
        } else {
            q[S[i]] = qs[i] + alpha * dq[i];
            c[S[i]] = cs[i] + alpha * dc[i];
        }
        if (fabs(dq[i]) > dqmax)
            dqmax = fabs(dq[i]);
        if (fabs(dc[i]) > dcmax)
            dcmax = fabs(dc[i]);
    }
    res[0] = alpha;
    res[1] = dmax;
    res[2] = dqmax;
    res[3] = dcmax;
}

/* num / k as numpy's float division answers it, k = 0 included */
static double quotient(double num, double k)
{
    if (k == 0.0)
        return num * INFINITY * copysign(1.0, k);
    return num / k;
}

typedef struct {
    double *z;
    const double *grid, *w, *x, *qs, *cs, *over;
    const int64_t *S;
    double *q, *c, *K, *st, *dz, *upd;
    char *out, *hit_q;
    Py_ssize_t ns, n;
    double qsc, r_inv, target;
    int mode;
} Step;

/* the bordered Newton step after its dense solve: the sums, K = Wz[:, 1:] + grid, the
 * step in (d, theta) of each mode, its mask and, where no slice leaves, the damped
 * update. Returns the status: 0 updated, 1 slices leave, 2 Cramer's determinant zero
 * or not finite (st[2:4] the 2 x 2 system's right-hand side). */
static int newton_after_loop(const Step *p)
{
    double Wz[6], sums[2];
    const Py_ssize_t ns = p->ns;
    bordered_sums_loop(p->z, ns, p->qsc, p->r_inv, p->w, p->x, p->S, p->qs, Wz, sums);
    const double wq = sums[0], wxq = sums[1];
    double *K = p->K;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            K[i * 2 + j] = Wz[i * 3 + j + 1] + p->grid[i * 2 + j];
    const double lin0 = Wz[0], lin1 = Wz[3];
    double s0 = 0.0, s1 = 0.0;
    if (p->mode == 3) {
        double r0 = p->target - wq - lin0;
        double r1 = -wxq - lin1;
        double k00 = K[0], k01 = K[1], k10 = K[2], k11 = K[3];
        double det = k00 * k11 - k01 * k10;
        if (det == 0.0 || !isfinite(det)) {
            p->st[2] = r0;
            p->st[3] = r1;
            return 2;
        }
        s0 = (r0 * k11 - k01 * r1) / det;
        s1 = (k00 * r1 - k10 * r0) / det;
    } else if (p->mode == 1)
        s0 = quotient(p->target - wq - lin0, K[0]);
    else if (p->mode == 2)
        s1 = quotient(-wxq - lin1, K[3]);
    p->st[0] = s0;
    p->st[1] = s1;
    Py_ssize_t nout = step_out_loop(p->z, s0, s1, ns, p->qs, p->dz, p->out);
    if (nout > 0 && ns > 2)
        return 1;
    step_update_loop(p->q, p->c, p->S, ns, p->qs, p->cs, p->dz, p->dz + ns, p->over, p->n,
                     p->x, s0, s1, p->hit_q, p->upd);
    return 0;
}

/* ---------------------------------------------------------------------------------- */
/* argument checks                                                                    */

#define MAXBUF 32

typedef struct {
    Py_buffer v[MAXBUF];
    int count;
} Buffers;

static void release(Buffers *bs)
{
    for (int i = 0; i < bs->count; i++)
        PyBuffer_Release(&bs->v[i]);
    bs->count = 0;
}

/* the buffer of `obj` (C-contiguous, kind 'd' float64, 'i' int64 or 'b' bool, exactly
 * `len` items unless len < 0), or NULL with ValueError set */
static void *take(Buffers *bs, PyObject *obj, const char *name, char kind,
                  Py_ssize_t len, int writable)
{
    Py_buffer *v = &bs->v[bs->count];
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, v, flags) < 0) {
        PyErr_Clear();
        PyErr_Format(PyExc_ValueError, "_ckernels: %s must be a C-contiguous%s array "
                     "of %s", name, writable ? " writable" : "",
                     kind == 'd' ? "float64" : kind == 'b' ? "bool" : "int64");
        return NULL;
    }
    bs->count++;
    const char *f = v->format == NULL ? "B" : v->format;
    if (*f == '@' || *f == '=' || *f == '<')
        f++;
    const Py_ssize_t size = kind == 'b' ? 1 : 8;
    int fmt_ok = kind == 'd' ? strcmp(f, "d") == 0
                 : kind == 'b' ? strcmp(f, "?") == 0
                               : (strcmp(f, "q") == 0 || strcmp(f, "l") == 0);
    if (v->itemsize != size || !fmt_ok) {
        PyErr_Format(PyExc_ValueError, "_ckernels: %s must hold %s (got format '%s', "
                     "item size %zd)", name,
                     kind == 'd' ? "float64" : kind == 'b' ? "bool" : "int64",
                     v->format == NULL ? "B" : v->format, v->itemsize);
        return NULL;
    }
    Py_ssize_t got = v->len / size;
    if (len >= 0 && got != len) {
        PyErr_Format(PyExc_ValueError, "_ckernels: %s has %zd items, %zd expected", name,
                     got, len);
        return NULL;
    }
    return v->buf;
}

static Py_ssize_t items(Buffers *bs)
{
    return bs->v[bs->count - 1].len / 8;
}

/* every index in [0, bound) */
static int in_range(const int64_t *ix, Py_ssize_t len, Py_ssize_t bound, const char *name)
{
    for (Py_ssize_t i = 0; i < len; i++)
        if (ix[i] < 0 || ix[i] >= bound) {
            PyErr_Format(PyExc_ValueError, "_ckernels: %s[%zd] = %lld is outside "
                         "[0, %zd)", name, i, (long long)ix[i], bound);
            return 0;
        }
    return 1;
}

/* a slice count passed as a number (ns): the arrays are sized by it, and a length below
 * zero means "any" to take(), so it must lie in [0, MAX_COUNT] (MAX_COUNT keeps products
 * such as (2 ns)^2 within Py_ssize_t) */
#define MAX_COUNT ((Py_ssize_t)1 << 24)

static int count_ok(Py_ssize_t ns)
{
    if (ns < 0 || ns > MAX_COUNT) {
        PyErr_Format(PyExc_ValueError, "_ckernels: ns = %zd is outside [0, %zd]", ns,
                     MAX_COUNT);
        return 0;
    }
    return 1;
}

/* the geometry arguments: dg (n), tn, tf, lr, ltn, ltf (n x n), Gt (n x K x n, or
 * anything where not far), fc (nfc x 4; K = nfc where far) */
static int geometry(Buffers *bs, Geometry *g, double span, PyObject *dg, PyObject *tn,
                    PyObject *tf, PyObject *lr, PyObject *ltn, PyObject *ltf,
                    PyObject *Gt, PyObject *fc, int far)
{
    if (TAB.coef == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "_ckernels: set_table() was not called");
        return 0;
    }
    g->span = span;
    g->far = far;
    if (!(g->dg = take(bs, dg, "dg", 'd', -1, 0)))
        return 0;
    Py_ssize_t n = g->n = items(bs);
    if (!(g->tn = take(bs, tn, "tn", 'd', n * n, 0))
        || !(g->tf = take(bs, tf, "tf", 'd', n * n, 0))
        || !(g->lr = take(bs, lr, "lr", 'd', n * n, 0))
        || !(g->ltn = take(bs, ltn, "ltn", 'd', n * n, 0))
        || !(g->ltf = take(bs, ltf, "ltf", 'd', n * n, 0))
        || !(g->fc = take(bs, fc, "fc", 'd', -1, 0)))
        return 0;
    Py_ssize_t nfc = items(bs);
    if (nfc % 4 != 0 || nfc == 0) {
        PyErr_SetString(PyExc_ValueError, "_ckernels: fc must be (terms, 4)");
        return 0;
    }
    g->nfc = nfc / 4;
    g->K = g->nfc;
    if (!(g->Gt = take(bs, Gt, "Gt", 'd', far ? n * g->K * n : -1, 0)))
        return 0;
    return 1;
}

/* ---------------------------------------------------------------------------------- */
/* the functions                                                                      */

static PyObject *set_table(PyObject *self, PyObject *args)
{
    PyObject *coef;
    double tmin, tmax, z0, ih, h, r_inf;
    if (!PyArg_ParseTuple(args, "Odddddd:set_table", &coef, &tmin, &tmax, &z0, &ih, &h,
                          &r_inf))
        return NULL;
    if (TAB.coef != NULL)      /* set once: the loops read it without the GIL */
        Py_RETURN_FALSE;
    Buffers bs = {.count = 0};
    const double *c = take(&bs, coef, "coef", 'd', -1, 0);
    if (c == NULL) {
        release(&bs);
        return NULL;
    }
    Py_ssize_t len = items(&bs);
    if (len % 16 != 0 || len == 0) {
        release(&bs);
        PyErr_SetString(PyExc_ValueError, "_ckernels: coef must be (segments, 4, 4)");
        return NULL;
    }
    double *copy = malloc(sizeof(double) * (size_t)len);
    if (copy == NULL) {
        release(&bs);
        return PyErr_NoMemory();
    }
    memcpy(copy, c, sizeof(double) * (size_t)len);
    release(&bs);
    TAB.nseg = len / 16;
    TAB.tmin = tmin;
    TAB.tmax = tmax;
    TAB.z0 = z0;
    TAB.ih = ih;
    TAB.h = h;
    TAB.r_inf = r_inf;
    TAB.coef = copy;
    Py_RETURN_TRUE;
}

static PyObject *result(int ok)
{
    if (ok < 0)
        return PyErr_NoMemory();
    return PyBool_FromLong(ok);
}

static PyObject *kernels(PyObject *self, PyObject *args)
{
    PyObject *S, *T, *b, *dg, *tn, *tf, *lr, *ltn, *ltf, *Gt, *fc, *A, *EA, *D, *ED;
    double span;
    int far;
    if (!PyArg_ParseTuple(args, "OOOdOOOOOOOOpOOOO:kernels", &S, &T, &b, &span, &dg, &tn,
                          &tf, &lr, &ltn, &ltf, &Gt, &fc, &far, &A, &EA, &D, &ED))
        return NULL;
    Buffers bs = {.count = 0};
    Geometry g;
    const int64_t *s_, *t_;
    const double *b_;
    double *a_, *ea_ = NULL, *d_ = NULL, *ed_ = NULL;
    Py_ssize_t ns, nt;
    int ok = -2;
    if (!geometry(&bs, &g, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far))
        goto done;
    if (!(s_ = take(&bs, S, "S", 'i', -1, 0)))
        goto done;
    ns = items(&bs);
    if (!(t_ = take(&bs, T, "T", 'i', -1, 0)))
        goto done;
    nt = items(&bs);
    if (!in_range(s_, ns, g.n, "S") || !in_range(t_, nt, g.n, "T"))
        goto done;
    if (!(b_ = take(&bs, b, "b", 'd', ns, 0)) || !(a_ = take(&bs, A, "A", 'd', ns * nt, 1)))
        goto done;
    if (EA != Py_None) {
        if (!(ea_ = take(&bs, EA, "EA", 'd', ns * nt, 1))
            || !(d_ = take(&bs, D, "D", 'd', ns * nt, 1))
            || !(ed_ = take(&bs, ED, "ED", 'd', ns * nt, 1)))
            goto done;
    }
    Py_BEGIN_ALLOW_THREADS
    ok = kernels_loop(&g, s_, ns, t_, nt, b_, a_, ea_, d_, ed_);
    Py_END_ALLOW_THREADS
done:
    release(&bs);
    if (ok == -2)
        return NULL;
    return result(ok);
}

static PyObject *linearised(PyObject *self, PyObject *args)
{
    PyObject *S, *T, *spos, *q, *c, *over, *x, *m, *dg, *slope, *tn, *tf, *lr, *ltn, *ltf,
        *Gt, *fc, *res, *J, *rhs, *gap, *grid;
    double span;
    int far;
    State st;
    if (!PyArg_ParseTuple(args, "OOOOOOddOOOOdddddOOOOOOOpOOOOO:linearised", &S, &T,
                          &spos, &q, &c, &over, &st.R, &span, &x, &m, &dg, &slope,
                          &st.theta, &st.dlo[0], &st.dlo[1], &st.dhi[0], &st.dhi[1],
                          &tn, &tf, &lr, &ltn, &ltf, &Gt, &fc, &far, &res, &J, &rhs, &gap,
                          &grid))
        return NULL;
    Buffers bs = {.count = 0};
    Geometry g;
    double *res_, *J_, *rhs_, *gap_, *grid_;
    int ok = -2;
    if (!geometry(&bs, &g, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far))
        goto done;
    const Py_ssize_t n = g.n;
    if (!(st.S = take(&bs, S, "S", 'i', -1, 0)))
        goto done;
    st.ns = items(&bs);
    if (!(st.T = take(&bs, T, "T", 'i', -1, 0)))
        goto done;
    st.nt = items(&bs);
    if (st.ns == 0) {
        PyErr_SetString(PyExc_ValueError, "_ckernels: S is empty");
        goto done;
    }
    if (!(st.spos = take(&bs, spos, "spos", 'i', st.ns, 0)))
        goto done;
    if (!in_range(st.S, st.ns, n, "S") || !in_range(st.T, st.nt, n, "T")
        || !in_range(st.spos, st.ns, st.nt, "spos"))
        goto done;
    if (!(st.q = take(&bs, q, "q", 'd', n, 0)) || !(st.c = take(&bs, c, "c", 'd', n, 0))
        || !(st.over = take(&bs, over, "over", 'd', n, 0))
        || !(st.x = take(&bs, x, "x", 'd', n, 0)) || !(st.m = take(&bs, m, "m", 'd', n, 0))
        || !(st.slope = take(&bs, slope, "slope", 'd', n, 0)))
        goto done;
    const Py_ssize_t n2 = 2 * st.ns;
    if (!(res_ = take(&bs, res, "res", 'd', n2, 1))
        || !(J_ = take(&bs, J, "J", 'd', n2 * n2, 1))
        || !(rhs_ = take(&bs, rhs, "rhs", 'd', n2 * 2, 1))
        || !(gap_ = take(&bs, gap, "gap", 'd', st.nt, 1))
        || !(grid_ = take(&bs, grid, "grid", 'd', 4, 1)))
        goto done;
    Py_BEGIN_ALLOW_THREADS
    ok = linearised_loop(&g, &st, res_, J_, rhs_, gap_, grid_);
    Py_END_ALLOW_THREADS
done:
    release(&bs);
    if (ok == -2)
        return NULL;
    return result(ok);
}

/* the slice arrays of the step: w, x (n), S (ns, in [0, n)), qs (ns) */
static int step_slices(Buffers *bs, PyObject *w, PyObject *x, PyObject *S, PyObject *qs,
                       Py_ssize_t ns, const double **w_, const double **x_,
                       const int64_t **S_, const double **qs_, Py_ssize_t *n)
{
    if (!(*w_ = take(bs, w, "w", 'd', -1, 0)))
        return 0;
    *n = items(bs);
    if (!(*x_ = take(bs, x, "x", 'd', *n, 0)) || !(*S_ = take(bs, S, "S", 'i', ns, 0))
        || !(*qs_ = take(bs, qs, "qs", 'd', ns, 0)))
        return 0;
    return in_range(*S_, ns, *n, "S");
}

static PyObject *scaled_system(PyObject *self, PyObject *args)
{
    PyObject *J, *res, *rhs, *B;
    Py_ssize_t ns;
    int fortran;
    double f_hi, f_lo, g_q, h_q, R;
    if (!PyArg_ParseTuple(args, "OpOOndddddO:scaled_system", &J, &fortran, &res, &rhs, &ns,
                          &f_hi, &f_lo, &g_q, &h_q, &R, &B))
        return NULL;
    Buffers bs = {.count = 0};
    double *J_, *B_;
    const double *res_, *rhs_;
    const Py_ssize_t n2 = ns > 0 && ns <= MAX_COUNT ? 2 * ns : 0;   /* (checked below) */
    PyObject *ret = NULL;
    if (ns > 0 && count_ok(ns) && (J_ = take(&bs, J, "J", 'd', n2 * n2, 1))
        && (res_ = take(&bs, res, "res", 'd', n2, 0))
        && (rhs_ = take(&bs, rhs, "rhs", 'd', n2 * 2, 0))
        && (B_ = take(&bs, B, "B", 'd', n2 * 3, 1))) {
        /* J[i, j]: the buffer of J.T (Fortran-order J) or of J (C order) */
        scaled_system_loop(J_, fortran ? 1 : n2, fortran ? n2 : 1, res_, rhs_, ns, f_hi,
                           f_lo, g_q, h_q, R, B_);
        ret = Py_None;
        Py_INCREF(ret);
    } else if (!PyErr_Occurred())
        PyErr_SetString(PyExc_ValueError, "_ckernels: ns must be positive");
    release(&bs);
    return ret;
}

static PyObject *bordered_sums(PyObject *self, PyObject *args)
{
    PyObject *z, *w, *x, *S, *qs, *Wz;
    Py_ssize_t ns, n;
    double qsc, r_inv;
    if (!PyArg_ParseTuple(args, "OnddOOOOO:bordered_sums", &z, &ns, &qsc, &r_inv, &w, &x,
                          &S, &qs, &Wz))
        return NULL;
    Buffers bs = {.count = 0};
    double *z_, *Wz_, sums[2];
    const double *w_, *x_, *qs_;
    const int64_t *S_;
    PyObject *ret = NULL;
    if (count_ok(ns) && (z_ = take(&bs, z, "z", 'd', 2 * ns * 3, 1))
        && step_slices(&bs, w, x, S, qs, ns, &w_, &x_, &S_, &qs_, &n)
        && (Wz_ = take(&bs, Wz, "Wz", 'd', 6, 1))) {
        bordered_sums_loop(z_, ns, qsc, r_inv, w_, x_, S_, qs_, Wz_, sums);
        ret = Py_BuildValue("dd", sums[0], sums[1]);
    }
    release(&bs);
    return ret;
}

static PyObject *step_out(PyObject *self, PyObject *args)
{
    PyObject *z, *qs, *dz, *out;
    Py_ssize_t ns;
    double s0, s1;
    if (!PyArg_ParseTuple(args, "OddnOOO:step_out", &z, &s0, &s1, &ns, &qs, &dz, &out))
        return NULL;
    Buffers bs = {.count = 0};
    const double *z_, *qs_;
    double *dz_;
    char *out_;
    PyObject *ret = NULL;
    if (count_ok(ns) && (z_ = take(&bs, z, "z", 'd', 2 * ns * 3, 0))
        && (qs_ = take(&bs, qs, "qs", 'd', ns, 0))
        && (dz_ = take(&bs, dz, "dz", 'd', 2 * ns, 1))
        && (out_ = take(&bs, out, "out", 'b', ns, 1)))
        ret = PyLong_FromSsize_t(step_out_loop(z_, s0, s1, ns, qs_, dz_, out_));
    release(&bs);
    return ret;
}

static PyObject *step_update(PyObject *self, PyObject *args)
{
    PyObject *q, *c, *S, *qs, *cs, *dq, *dc, *over, *x, *hit_q, *res;
    double s0, s1;
    if (!PyArg_ParseTuple(args, "OOOOOOOOOddOO:step_update", &q, &c, &S, &qs, &cs, &dq,
                          &dc, &over, &x, &s0, &s1, &hit_q, &res))
        return NULL;
    Buffers bs = {.count = 0};
    double *q_, *c_, *res_;
    const double *qs_, *cs_, *dq_, *dc_, *over_, *x_;
    const int64_t *S_;
    char *hit_;
    Py_ssize_t n, ns;
    PyObject *ret = NULL;
    if ((q_ = take(&bs, q, "q", 'd', -1, 1)) && (n = items(&bs)) > 0
        && (c_ = take(&bs, c, "c", 'd', n, 1)) && (over_ = take(&bs, over, "over", 'd', n, 0))
        && (x_ = take(&bs, x, "x", 'd', n, 0)) && (S_ = take(&bs, S, "S", 'i', -1, 0))
        && (ns = items(&bs)) >= 0 && in_range(S_, ns, n, "S")
        && (qs_ = take(&bs, qs, "qs", 'd', ns, 0)) && (cs_ = take(&bs, cs, "cs", 'd', ns, 0))
        && (dq_ = take(&bs, dq, "dq", 'd', ns, 0)) && (dc_ = take(&bs, dc, "dc", 'd', ns, 0))
        && (hit_ = take(&bs, hit_q, "hit_q", 'b', ns, 1))
        && (res_ = take(&bs, res, "res", 'd', 4, 1))) {
        step_update_loop(q_, c_, S_, ns, qs_, cs_, dq_, dc_, over_, n, x_, s0, s1, hit_, res_);
        ret = Py_None;
        Py_INCREF(ret);
    } else if (!PyErr_Occurred())
        PyErr_SetString(PyExc_ValueError, "_ckernels: q is empty");
    release(&bs);
    return ret;
}

static PyObject *newton_after(PyObject *self, PyObject *args)
{
    PyObject *z, *grid, *w, *x, *S, *qs, *cs, *q, *c, *over, *K, *st, *dz, *out, *hit_q,
        *upd;
    Step p;
    if (!PyArg_ParseTuple(args, "OOnddOOOOOdiOOOOOOOOO:newton_after", &z, &grid, &p.ns,
                          &p.qsc, &p.r_inv, &w, &x, &S, &qs, &cs, &p.target, &p.mode, &q,
                          &c, &over, &K, &st, &dz, &out, &hit_q, &upd))
        return NULL;
    Buffers bs = {.count = 0};
    const Py_ssize_t ns = p.ns;
    PyObject *ret = NULL;
    if (count_ok(ns) && (p.z = take(&bs, z, "z", 'd', 2 * ns * 3, 1))
        && (p.grid = take(&bs, grid, "grid", 'd', 4, 0))
        && step_slices(&bs, w, x, S, qs, ns, &p.w, &p.x, &p.S, &p.qs, &p.n)
        && (p.cs = take(&bs, cs, "cs", 'd', ns, 0))
        && (p.q = take(&bs, q, "q", 'd', p.n, 1)) && (p.c = take(&bs, c, "c", 'd', p.n, 1))
        && (p.over = take(&bs, over, "over", 'd', p.n, 0))
        && (p.K = take(&bs, K, "K", 'd', 4, 1)) && (p.st = take(&bs, st, "st", 'd', 4, 1))
        && (p.dz = take(&bs, dz, "dz", 'd', 2 * ns, 1))
        && (p.out = take(&bs, out, "out", 'b', ns, 1))
        && (p.hit_q = take(&bs, hit_q, "hit_q", 'b', ns, 1))
        && (p.upd = take(&bs, upd, "upd", 'd', 4, 1))) {
        if (p.n == 0)
            PyErr_SetString(PyExc_ValueError, "_ckernels: w is empty");
        else
            ret = PyLong_FromLong(newton_after_loop(&p));
    }
    release(&bs);
    return ret;
}

static PyMethodDef methods[] = {
    {"set_table", set_table, METH_VARARGS,
     "set_table(coef, tau_min, tau_max, z0, 1/h, h, r_inf) -> bool: the spline "
     "table (coef (segment, power, function) float64) and the series' constant, "
     "copied; once per process (False, unchanged, where it was set before)."},
    {"kernels", kernels, METH_VARARGS,
     "kernels(S, T, b, span, dg, tn, tf, lr, ltn, ltf, Gt, fc, far, A, EA, D, ED) -> "
     "bool: the kernels into A (EA, D, ED unless EA is None), each (ns, nt) C order; "
     "False where a spline argument falls below the table."},
    {"linearised", linearised, METH_VARARGS,
     "linearised(S, T, spos, q, c, over, R, span, x, m, dg, slope, theta, dlo0, dlo1, "
     "dhi0, dhi1, tn, tf, lr, ltn, ltf, Gt, fc, far, res, J, rhs, gap, grid) -> bool: "
     "SliceEquations.linearised's outputs filled (J as its C-order transpose)."},
    {"scaled_system", scaled_system, METH_VARARGS,
     "scaled_system(J, fortran, res, rhs, ns, f_hi, f_lo, g_q, h_q, R, B): the Newton "
     "step's scaled system, J (the buffer of J.T where fortran) scaled in place, B filled."},
    {"bordered_sums", bordered_sums, METH_VARARGS,
     "bordered_sums(z, ns, qsc, 1/R, w, x, S, qs, Wz) -> (w.q, (w x).q): z unscaled in "
     "place, Wz (2 x 3) filled."},
    {"step_out", step_out, METH_VARARGS,
     "step_out(z, s0, s1, ns, qs, dz, out) -> count: the step and its mask."},
    {"step_update", step_update, METH_VARARGS,
     "step_update(q, c, S, qs, cs, dq, dc, over, x, s0, s1, hit_q, res): the damped "
     "update in place; res = (alpha, largest overlap, largest |dq|, largest |dc|)."},
    {"newton_after", newton_after, METH_VARARGS,
     "newton_after(z, grid, ns, qsc, 1/R, w, x, S, qs, cs, target, mode, q, c, over, K, "
     "st, dz, out, hit_q, upd) -> status: the Newton step after its dense solve."},
    {NULL, NULL, 0, NULL}};

/* the stresses' corner sums (linecontact/_cstresses.c, the other source of this module) */
extern PyMethodDef lc_stress_methods[];

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_ckernels",
    "The compiled engine: the coupled-slice kernels and linearisation (engine 'c'; "
    "linecontact/roller/_cengine.py wraps them) and the stresses' corner sums "
    "(love_sums, corners; linecontact/stresses/love.py wraps them), in C.", -1, methods};

/* the SHA-256 of both sources as setup.py read them (linecontact/_engine.py compares it
 * with the files beside the built module: a stale build is not used) */
#ifndef LC_SOURCE_SHA256
#define LC_SOURCE_SHA256 ""
#endif

PyMODINIT_FUNC PyInit__ckernels(void)
{
    PyObject *m = PyModule_Create(&module);
    if (m != NULL && (PyModule_AddFunctions(m, lc_stress_methods) < 0
                      || PyModule_AddStringConstant(m, "SOURCE_SHA256",
                                                    LC_SOURCE_SHA256) < 0)) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
