/*
 * The weighted corner sums of Love's rectangles (the 3D correction of the subsurface
 * stresses, linecontact/stresses/love.py: _love_weighted, the numpy reference) in C99, one
 * fused loop per point with no temporaries: at each point p (offset py along the
 * slice, depth z > 0) and for the corners c (offsets X_c along the roller, cy_c
 * across, weights w_c), Y = py - cy_c, rho = sqrt(Y^2 + X^2 + z^2) and
 *
 *   out[0] = -sum w arctan(XY/(z rho))          d psi1/dz
 *   out[2] = -sum (X w) Y/(rho (X^2 + z^2))     d2 psi1/dx2
 *   out[3] = -sum (X w) Y/(rho (Y^2 + z^2))     d2 psi1/dy2
 *   out[4] =  sum w / rho                       d2 psi1/dxdy
 *   out[5] = -z sum w Y/(rho (X^2 + z^2))       d2 psi1/dxdz
 *   out[6] = -z sum (X w)/(rho (Y^2 + z^2))     d2 psi1/dydz
 *   out[7] =  sum w arctan(XY/(X^2 + z^2 + z rho))   d2 H1/dx2
 *   out[9] =  sum w log(rho + z)                d2 H1/dxdy
 *   out[1] = -(out[2] + out[3]),  out[8] = -(out[0] + out[7])
 *
 * (the same formulas, reciprocals and harmonic identities as _love_weighted; with
 * `only`, out[6] alone and the others 0, as _love_corner's). The arctangents and the
 * logarithm are written out (Cephes' atan and log: a branch-free range reduction and
 * a rational minimax approximation, accurate to about 2 ulp; S. L. Moshier, Methods
 * and Programs for Mathematical Functions, 1989) so that the compiler can vectorise
 * the loop over the corners; the arctangent's argument is reduced from its numerator
 * and denominator (one division fewer than arctan(n/d)). The corners are summed in
 * LANES interleaved partial sums (a vector's lanes), then those in order: the sums
 * agree with numpy's (whose matrix products sum in their own order) to rounding.
 * Where the compiler supports it (gcc, clang on x86-64 Linux) the loop is compiled
 * for AVX-512, AVX2 and the baseline, picked at load by the processor
 * (target_clones). IEEE arithmetic: no -ffast-math, no fused multiply-adds.
 *
 * Arrays come through the buffer protocol: each is checked to be C-contiguous float64
 * (or writable for the output) of the expected length before any is read; a mismatch
 * raises ValueError. The sum returns False (out untouched beyond what was written)
 * where an input is not finite, a depth is outside (1e-60, 1e60) or an offset's size
 * not below 1e60 (metres: far outside any contact; there an intermediate could
 * leave the normal numbers): the caller then takes the numpy path.
 *
 * One of the two sources of the extension linecontact._ckernels (setup.py; the other,
 * linecontact/roller/_ckernels.c, holds the module's PyInit, which adds this file's
 * functions, lc_stress_methods).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(_MSC_VER)
/* no fused multiply-adds (before VS2022 /fp:precise alone allowed them under /arch:AVX2) */
#pragma fp_contract(off)
#endif

#define LANES 8

/* the helpers inlined into the vectorised loop */
#if defined(__GNUC__)
#define INLINE static inline __attribute__((always_inline))
#else
#define INLINE static inline
#endif

#if defined(__GNUC__) && (defined(__x86_64__) || defined(_M_X64)) && defined(__linux__) \
    && defined(__GLIBC__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#endif
#endif
#ifndef CLONES
#define CLONES
#endif

#define PIO2 1.57079632679489661923
#define PIO4 0.78539816339744830962
#define MOREBITS 6.123233995736765886130e-17
#define T3P8 2.41421356237309504880

/* Cephes' atan (atan.c), its range reduction taken on the numerator and denominator
 * of arctan(n/d), d > 0: the reduced argument x = num/den, the offset y0 + more and
 * the rational P(x^2)/Q(x^2) apart, so that the caller can share one division
 * between several rationals (|x| <= tan(pi/8): 194 < Q < 300) */
typedef struct {
    double x, z, y0, more, p, q;
} Atan;

INLINE Atan atan_parts(double n, double d)
{
    Atan a;
    double an = fabs(n);
    int big = an > T3P8 * d;
    int mid = an > 0.66 * d;
    double num = big ? -d : (mid ? an - d : an);
    double den = big ? an : (mid ? an + d : d);
    a.y0 = big ? PIO2 : (mid ? PIO4 : 0.0);
    a.more = big ? MOREBITS : (mid ? 0.5 * MOREBITS : 0.0);
    a.x = num / den;
    double z = a.z = a.x * a.x;
    a.p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z
            - 7.500855792314704667340e1) * z - 1.228866684490136173410e2) * z
          - 6.485021904942025371773e1;
    a.q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z
            + 4.328810604912902668951e2) * z + 4.853903996359136964868e2) * z
          + 1.945506571482613964425e2;
    return a;
}

/* arctan(n/d) from its parts and P/Q */
INLINE double atan_end(const Atan *a, double pq, double n)
{
    double r = a->x * (a->z * pq) + a->x;
    return copysign(a->y0 + (r + a->more), n);
}

/* Cephes' log (log.c), x a positive normal finite number: its |e| <= 2 branch for
 * every exponent (frexp by bits, the mantissa f + 1 in [sqrt(1/2), sqrt 2)), the
 * rational P(f)/Q(f) apart (8 < Q < 40) */
typedef struct {
    double e, f, p, q;
} Log;

INLINE Log log_parts(double x)
{
    Log g;
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    uint64_t eb = (u >> 52) | UINT64_C(0x4330000000000000);
    double e;
    memcpy(&e, &eb, sizeof e);
    e -= 4503599627370496.0 + 1022.0;            /* the exponent of frexp */
    uint64_t mb = (u & UINT64_C(0x000fffffffffffff)) | UINT64_C(0x3fe0000000000000);
    double m;
    memcpy(&m, &mb, sizeof m);                   /* frexp's mantissa in [0.5, 1) */
    int low = m < 0.70710678118654752440;
    g.e = low ? e - 1.0 : e;
    double f = g.f = low ? (m + m) - 1.0 : m - 1.0;
    g.p = ((((1.01875663804580931796e-4 * f + 4.97494994976747001425e-1) * f
             + 4.70579119878881725854e0) * f + 1.44989225341610930846e1) * f
           + 1.79368678507819816313e1) * f + 7.70838733755885391666e0;
    g.q = ((((f + 1.12873587189167450590e1) * f + 4.52279145837532221105e1) * f
            + 8.29875266912776603211e1) * f + 7.11544750618563894466e1) * f
          + 2.31251620126765340583e1;
    return g;
}

INLINE double log_end(const Log *g, double pq)
{
    double f = g->f, z = f * f;
    double y = f * (z * pq);
    y = y - g->e * 2.121944400546905827679e-4;
    y = y - 0.5 * z;
    double r = f + y;
    return r + g->e * 0.693359375;
}

/* the corner sums at one point: s[0..7] = sum w atan(XY/(z rho)), sum (Xw) Y/(rho a),
 * sum (Xw) Y/(rho b), sum w/rho, sum w Y/(rho a), sum (Xw)/(rho b),
 * sum w atan(XY/(a + z rho)), sum w log(rho + z); a = X^2 + z^2, b = Y^2 + z^2.
 * Four divisions: 1/(rho a b) gives the three reciprocals, 1/(Q1 Q2 Q3) the three
 * rationals (each reciprocal within a few ulp; the rationals are small corrections
 * of the functions, so that their rounding moves the functions by well under an ulp) */
#define NS 8

INLINE void pair(double X, double cy, double w, double yp, double z, double z2,
                        double *acc)
{
    double X2 = X * X;
    double a = X2 + z2;
    double Y = yp - cy;
    double Y2 = Y * Y;
    double b = Y2 + z2;
    double rho = sqrt(Y2 + a);
    double zr = z * rho;
    double XY = X * Y;
    double Xw = X * w;
    double inv = 1.0 / (rho * (a * b));
    double ia = inv * b;                         /* 1/(rho a) */
    double ib = inv * a;                         /* 1/(rho b) */
    double ir = ia * a;                          /* 1/rho */
    Atan t0 = atan_parts(XY, zr);
    Atan t7 = atan_parts(XY, a + zr);
    Log lg = log_parts(rho + z);
    double q01 = t0.q * t7.q;
    double iq = 1.0 / (q01 * lg.q);
    double iq2 = iq * lg.q;                      /* 1/(Q1 Q2) */
    acc[0] += atan_end(&t0, t0.p * (t7.q * iq2), XY) * w;
    acc[1] += (ia * Y) * Xw;
    acc[2] += (ib * Y) * Xw;
    acc[3] += ir * w;
    acc[4] += (ia * Y) * w;
    acc[5] += ib * Xw;
    acc[6] += atan_end(&t7, t7.p * (t0.q * iq2), XY) * w;
    acc[7] += log_end(&lg, lg.p * (q01 * iq)) * w;
}

/* d2 psi1/dydz's sum alone: sum (X w)/(rho (Y^2 + z^2)), rho as _love_corner's */
INLINE double pair_yz(double X, double cy, double w, double yp, double z2)
{
    double Y = yp - cy;
    double Y2 = Y * Y;
    double rho = sqrt((X * X + Y2) + z2);
    return (1.0 / ((Y2 + z2) * rho)) * (X * w);
}

CLONES
static void love_loop(Py_ssize_t nc, const double *X, const double *cy, const double *w,
                      Py_ssize_t npt, const double *py, const double *pz, int only,
                      double *out)
{
    for (Py_ssize_t p = 0; p < npt; p++) {
        const double yp = py[p], z = pz[p], z2 = z * z;
        double s[NS];
        if (only) {
            double acc[LANES] = {0.0};
            Py_ssize_t c = 0;
            for (; c + LANES <= nc; c += LANES)
                for (int l = 0; l < LANES; l++)
                    acc[l] += pair_yz(X[c + l], cy[c + l], w[c + l], yp, z2);
            for (int l = 0; c + l < nc; l++)
                acc[l] += pair_yz(X[c + l], cy[c + l], w[c + l], yp, z2);
            double t = 0.0;
            for (int l = 0; l < LANES; l++)
                t += acc[l];
            for (int f = 0; f < 10; f++)
                out[f * npt + p] = 0.0;
            out[6 * npt + p] = -z * t;
            continue;
        }
        double acc[NS][LANES];
        for (int k = 0; k < NS; k++)
            for (int l = 0; l < LANES; l++)
                acc[k][l] = 0.0;
        Py_ssize_t c = 0;
        for (; c + LANES <= nc; c += LANES) {
            for (int l = 0; l < LANES; l++) {
                double t[NS] = {0.0};
                pair(X[c + l], cy[c + l], w[c + l], yp, z, z2, t);
                for (int k = 0; k < NS; k++)
                    acc[k][l] += t[k];
            }
        }
        for (int l = 0; c + l < nc; l++) {
            double t[NS] = {0.0};
            pair(X[c + l], cy[c + l], w[c + l], yp, z, z2, t);
            for (int k = 0; k < NS; k++)
                acc[k][l] += t[k];
        }
        for (int k = 0; k < NS; k++) {
            double t = 0.0;
            for (int l = 0; l < LANES; l++)
                t += acc[k][l];
            s[k] = t;
        }
        double o0 = -s[0], o2 = -s[1], o3 = -s[2], o7 = s[6];
        out[0 * npt + p] = o0;
        out[1 * npt + p] = -(o2 + o3);
        out[2 * npt + p] = o2;
        out[3 * npt + p] = o3;
        out[4 * npt + p] = s[3];
        out[5 * npt + p] = -z * s[4];
        out[6 * npt + p] = -z * s[5];
        out[7 * npt + p] = o7;
        out[8 * npt + p] = -(o0 + o7);
        out[9 * npt + p] = s[7];
    }
}

/* ---------------------------------------------------------------------------------- */
/* the corners of a slice's pressure difference (stresses._corners_assemble)          */

typedef struct {
    double x, y, w;
    Py_ssize_t i;
} Corner;

static int corner_order(const void *pa, const void *pb)
{
    const Corner *a = pa, *b = pb;
    if (a->x < b->x)
        return -1;
    if (a->x > b->x)
        return 1;
    if (a->y < b->y)
        return -1;
    if (a->y > b->y)
        return 1;
    return (a->i > b->i) - (a->i < b->i);      /* stable, as np.lexsort */
}

/* _corners_assemble's arithmetic in its order: the near grid's mixed differences of
 * the framed cell pressures, the far cells' four corners each, then the corners sorted
 * by (x, y) (stably), those at one place merged (their weights summed in order) and
 * the zero weights dropped. cx, cy, w hold room for every corner; returns how many
 * were kept, -1 where the near grid's corners are not in order (numpy then), -2 where
 * memory ran out */
static Py_ssize_t assemble(Py_ssize_t n, const double *xe, double L, const double *b,
                           const double *p0, const double *q, Py_ssize_t k0, Py_ssize_t i0,
                           Py_ssize_t i1, Py_ssize_t NY, const double *ye,
                           const double *means, double *cx, double *cy, double *w)
{
    const double b0 = b[k0], pk = p0[k0];
    const int lo_ext = i0 == 0, hi_ext = i1 == n - 1;
    const Py_ssize_t rows = i1 - i0 + 1 + lo_ext + hi_ext, NC = NY + 2;
    double *Pp = calloc((size_t)((rows + 2) * NC + rows + 1), sizeof(double));
    if (Pp == NULL)
        return -2;
    double *xs = Pp + (rows + 2) * NC;
    for (Py_ssize_t r = 0; r <= i1 - i0; r++)
        for (Py_ssize_t j = 0; j < NY; j++)
            Pp[(1 + lo_ext + r) * NC + 1 + j] = p0[i0 + r] * means[(1 + r) * NY + j]
                                                - pk * means[j];
    for (Py_ssize_t j = 0; j < NY; j++) {
        if (lo_ext)
            Pp[1 * NC + 1 + j] = -(pk * means[j]);
        if (hi_ext)
            Pp[rows * NC + 1 + j] = -(pk * means[j]);
    }
    for (Py_ssize_t t = 0; t <= i1 - i0 + 1; t++)
        xs[lo_ext + t] = xe[i0 + t];
    if (lo_ext)
        xs[0] = xe[0] - 1e6 * L;
    if (hi_ext)
        xs[rows] = xe[n] + 1e6 * L;
    Py_ssize_t nn = 0;
    int sorted = 1;
    for (Py_ssize_t r = 0; r <= rows; r++) {
        sorted &= r == 0 || xs[r] > xs[r - 1];
        for (Py_ssize_t j = 0; j <= NY; j++, nn++) {
            sorted &= j == 0 || ye[j] > ye[j - 1];
            cx[nn] = xs[r];
            cy[nn] = ye[j];
            w[nn] = ((Pp[(r + 1) * NC + j + 1] - Pp[(r + 1) * NC + j])
                     - Pp[r * NC + j + 1]) + Pp[r * NC + j];
        }
    }
    free(Pp);
    if (!sorted)
        return -1;
    const Py_ssize_t nl = i0, nr = n - 1 - i1;
    const Py_ssize_t m = nl + nr + (1 - lo_ext) + (1 - hi_ext);
    Py_ssize_t k = 0;
    if (m == 0) {
        for (Py_ssize_t i = 0; i < nn; i++)
            if (w[i] != 0.0) {
                cx[k] = cx[i];
                cy[k] = cy[i];
                w[k++] = w[i];
            }
        return k;
    }
    Corner *far = malloc(sizeof(Corner) * (size_t)(4 * m));
    if (far == NULL)
        return -2;
    const double q0 = q[k0];
    for (Py_ssize_t t = 0; t < m; t++) {
        double lo, hi, bf, dq;
        if (t < nl + nr) {
            Py_ssize_t s = t < nl ? t : i1 + 1 + (t - nl);
            lo = xe[s];
            hi = xe[s + 1];
            bf = b[s] > b0 ? b[s] : b0;            /* np.maximum */
            dq = q[s] - q0;
        } else if (t == nl + nr && !lo_ext) {
            lo = xe[0] - 1e6 * L;
            hi = xe[0];
            bf = b0;
            dq = -q0;
        } else {
            lo = xe[n];
            hi = xe[n] + 1e6 * L;
            bf = b0;
            dq = -q0;
        }
        double pm = dq / (2 * bf);
        const double fx[4] = {lo, lo, hi, hi}, fy[4] = {-bf, bf, -bf, bf},
                     fw[4] = {pm, -pm, -pm, pm};
        for (int f = 0; f < 4; f++) {
            Corner *c = &far[f * m + t];
            c->x = fx[f];
            c->y = fy[f];
            c->w = fw[f];
            c->i = nn + f * m + t;
        }
    }
    qsort(far, (size_t)(4 * m), sizeof(Corner), corner_order);
    /* merge the near grid (sorted, before every far corner at one place) with the far
     * corners, summing the weights at one place in that order */
    double *ox = cx, *oy = cy, *ow = w;     /* written behind the near grid's reads */
    double *nx = malloc(sizeof(double) * (size_t)(3 * nn));
    if (nx == NULL) {
        free(far);
        return -2;
    }
    memcpy(nx, cx, sizeof(double) * (size_t)nn);
    memcpy(nx + nn, cy, sizeof(double) * (size_t)nn);
    memcpy(nx + 2 * nn, w, sizeof(double) * (size_t)nn);
    const double *ny = nx + nn, *nw = nx + 2 * nn;
    Py_ssize_t a = 0, f = 0, out = -1;
    double lx = 0.0, ly = 0.0;
    while (a < nn || f < 4 * m) {
        double x, y, wt;
        int near = f >= 4 * m || (a < nn && (nx[a] < far[f].x
                                             || (nx[a] == far[f].x && ny[a] <= far[f].y)));
        if (near) {
            x = nx[a];
            y = ny[a];
            wt = nw[a++];
        } else {
            x = far[f].x;
            y = far[f].y;
            wt = far[f++].w;
        }
        if (out >= 0 && x == lx && y == ly)
            ow[out] += wt;
        else {
            out++;
            ox[out] = lx = x;
            oy[out] = ly = y;
            ow[out] = wt;
        }
    }
    free(nx);
    free(far);
    for (Py_ssize_t i = 0; i <= out; i++)
        if (w[i] != 0.0) {
            cx[k] = cx[i];
            cy[k] = cy[i];
            w[k++] = w[i];
        }
    return k;
}

/* ---------------------------------------------------------------------------------- */
/* argument checks                                                                    */

#define MAXBUF 12

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

/* the buffer of `obj`: C-contiguous float64, exactly `len` items (any where len < 0;
 * then *got holds the count), or NULL with ValueError set */
static double *take(Buffers *bs, PyObject *obj, const char *name, Py_ssize_t len,
                    int writable, Py_ssize_t *got)
{
    if (bs->count >= MAXBUF) {
        PyErr_SetString(PyExc_RuntimeError, "_ckernels: too many buffers");
        return NULL;
    }
    Py_buffer *v = &bs->v[bs->count];
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, v, flags) < 0) {
        PyErr_Clear();
        PyErr_Format(PyExc_ValueError, "_ckernels: %s must be a C-contiguous%s array "
                     "of float64", name, writable ? " writable" : "");
        return NULL;
    }
    bs->count++;
    const char *f = v->format == NULL ? "B" : v->format;
    if (*f == '@' || *f == '=' || *f == '<')
        f++;
    if (v->itemsize != 8 || strcmp(f, "d") != 0) {
        PyErr_Format(PyExc_ValueError, "_ckernels: %s must hold float64 (got format "
                     "'%s', item size %zd)", name, v->format == NULL ? "B" : v->format,
                     v->itemsize);
        return NULL;
    }
    Py_ssize_t n = v->len / 8;
    if (len >= 0 && n != len) {
        PyErr_Format(PyExc_ValueError, "_ckernels: %s has %zd items, %zd expected",
                     name, n, len);
        return NULL;
    }
    if (got != NULL)
        *got = n;
    return (double *)v->buf;
}

static int finite_all(const double *a, Py_ssize_t n)
{
    for (Py_ssize_t i = 0; i < n; i++)
        if (!isfinite(a[i]))
            return 0;
    return 1;
}

static PyObject *love_sums(PyObject *self, PyObject *args)
{
    PyObject *X, *cy, *w, *py, *pz, *out;
    int only;
    if (!PyArg_ParseTuple(args, "OOOOOpO:love_sums", &X, &cy, &w, &py, &pz, &only, &out))
        return NULL;
    Buffers bs = {.count = 0};
    PyObject *ret = NULL;
    Py_ssize_t nc, npt;
    const double *x_, *cy_, *w_, *py_, *pz_;
    double *o_;
    if (!(x_ = take(&bs, X, "X", -1, 0, &nc)) || !(cy_ = take(&bs, cy, "cy", nc, 0, NULL))
        || !(w_ = take(&bs, w, "w", nc, 0, NULL)) || !(py_ = take(&bs, py, "py", -1, 0, &npt))
        || !(pz_ = take(&bs, pz, "pz", npt, 0, NULL)))
        goto done;
    if (npt > PY_SSIZE_T_MAX / 10) {
        PyErr_SetString(PyExc_ValueError, "_ckernels: too many points");
        goto done;
    }
    if (!(o_ = take(&bs, out, "out", 10 * npt, 1, NULL)))
        goto done;
    int ok = finite_all(x_, nc) && finite_all(cy_, nc) && finite_all(w_, nc)
             && finite_all(py_, npt) && finite_all(pz_, npt);
    /* depths and offsets in a range where every intermediate is a normal finite
     * number: 1e-60 < z < 1e60 and |X|, |cy|, |py| < 1e60 keep rho (a)(b) within
     * [1e-300, 3e301] (a = X^2 + z^2, b = Y^2 + z^2) and the logarithm's argument
     * normal */
    for (Py_ssize_t p = 0; ok && p < npt; p++)
        ok = pz_[p] > 1e-60 && pz_[p] < 1e60 && fabs(py_[p]) < 1e60;
    for (Py_ssize_t c = 0; ok && c < nc; c++)
        ok = fabs(x_[c]) < 1e60 && fabs(cy_[c]) < 1e60;
    if (ok) {
        Py_BEGIN_ALLOW_THREADS
        love_loop(nc, x_, cy_, w_, npt, py_, pz_, only, o_);
        Py_END_ALLOW_THREADS
    }
    ret = PyBool_FromLong(ok);
done:
    release(&bs);
    return ret;
}

static PyObject *corners(PyObject *self, PyObject *args)
{
    PyObject *xe, *b, *p0, *q, *ye, *means, *cx, *cy, *w;
    double L;
    Py_ssize_t k0, i0, i1;
    if (!PyArg_ParseTuple(args, "OdOOOnnnOOOOO:corners", &xe, &L, &b, &p0, &q, &k0, &i0,
                          &i1, &ye, &means, &cx, &cy, &w))
        return NULL;
    Buffers bs = {.count = 0};
    PyObject *ret = NULL;
    Py_ssize_t n, ny;
    const double *xe_, *b_, *p0_, *q_, *ye_, *m_;
    double *cx_, *cy_, *w_;
    if (!(b_ = take(&bs, b, "b", -1, 0, &n)) || !(xe_ = take(&bs, xe, "xe", n + 1, 0, NULL))
        || !(p0_ = take(&bs, p0, "p0", n, 0, NULL)) || !(q_ = take(&bs, q, "q", n, 0, NULL))
        || !(ye_ = take(&bs, ye, "ye", -1, 0, &ny)))
        goto done;
    if (n < 1 || ny < 2 || !(0 <= i0 && i0 <= k0 && k0 <= i1 && i1 < n)
        || n > (PY_SSIZE_T_MAX / 8 - 16) / ny) {
        PyErr_Format(PyExc_ValueError, "_ckernels: slices %zd, grid edges %zd and "
                     "0 <= i0 %zd <= k0 %zd <= i1 %zd < n out of range", n, ny, i0, k0, i1);
        goto done;
    }
    const Py_ssize_t NY = ny - 1;
    const Py_ssize_t room = (n + 3) * ny + 4 * (n + 2);
    if (!(m_ = take(&bs, means, "means", (i1 - i0 + 2) * NY, 0, NULL))
        || !(cx_ = take(&bs, cx, "cx", room, 1, NULL))
        || !(cy_ = take(&bs, cy, "cy", room, 1, NULL))
        || !(w_ = take(&bs, w, "w", room, 1, NULL)))
        goto done;
    if (!(finite_all(xe_, n + 1) && finite_all(b_, n) && finite_all(p0_, n)
          && finite_all(q_, n) && finite_all(ye_, ny) && finite_all(m_, (i1 - i0 + 2) * NY)
          && isfinite(L))) {
        ret = PyLong_FromSsize_t(-1);
        goto done;
    }
    Py_ssize_t k;
    Py_BEGIN_ALLOW_THREADS
    k = assemble(n, xe_, L, b_, p0_, q_, k0, i0, i1, NY, ye_, m_, cx_, cy_, w_);
    Py_END_ALLOW_THREADS
    ret = k == -2 ? PyErr_NoMemory() : PyLong_FromSsize_t(k);
done:
    release(&bs);
    return ret;
}

/* this file's functions, added to the one extension module linecontact._ckernels by its
 * PyInit (linecontact/roller/_ckernels.c): one module, two translation units */
PyMethodDef lc_stress_methods[] = {
    {"love_sums", love_sums, METH_VARARGS,
     "love_sums(X, cy, w, py, pz, only, out) -> bool: the weighted corner sums of "
     "Love's rectangles into out (10, len(py)) for corners at (X, cy) with weights w "
     "and points (py, pz); with only, out[6] alone (the others 0). False (out "
     "undefined) where an input is not finite, a depth is not in (1e-60, 1e60) or an "
     "offset's size not below 1e60."},
    {"corners", corners, METH_VARARGS,
     "corners(xe, L, b, p0, q, k0, i0, i1, ye, means, cx, cy, w) -> count: the corners "
     "of slice k0's pressure difference (stresses._corners_assemble) into cx, cy, w "
     "(each (n + 3) len(ye) + 4 (n + 2) long), the first `count` kept; -1 where numpy "
     "is to build them (an input not finite, the grid not increasing)."},
    {NULL, NULL, 0, NULL}};
