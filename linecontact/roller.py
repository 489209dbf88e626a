r"""Profiled and tilted rollers on a flat: coupled slices with Hertz strips (runtime model).

A rigid roller (radius R across its axis, length L, axis x, |x| <= L/2) with a profile
drop P(x) (:mod:`linecontact.profiles`) and a tilt theta is pressed by a depth d into an
elastic half-space of effective modulus E*; the gap is

.. math:: h(x, y) = \frac{y^2}{2R} + P(x) - \theta x .

On a raceway, R is the effective radius across the axis (1/R = 1/R_roller + 1/R_race,
the race radius negative for an outer ring) and the profile drops of both bodies add.

Method (coupled slices)
-----------------------
The roller is cut into n slices of width w = L/n centred at x_k. Slice k carries a line
load q_k spread across y as a Hertz (semi-elliptical) strip of half-width b_k,

.. math:: p(x, y) = \frac{2 q_k}{\pi b_k}\sqrt{1 - y^2/b_k^2},
          \qquad |x - x_k| < w/2,

and the two unknowns (q_k, b_k) of each loaded slice satisfy two conditions on its
centre line, with the surface displacement u of the whole pressure field (Boussinesq,
:math:`u = (\pi E^*)^{-1}\iint p/r\,dA`):

.. math::

    u(x_k, 0) = d + \theta x_k - P(x_k), \qquad
    \frac{\partial^2 u}{\partial y^2}(x_k, 0) = -\frac{1}{R}.

The influence of strip i on slice k is exact for the semi-elliptical strip, not a
point-load approximation:

.. math::

    u(x_k, 0) = \sum_i \frac{q_i}{\pi E^*}\left[a(\tau^+_{ki}) - a(\tau^-_{ki})\right],
    \qquad a(\tau) = \frac{4}{\pi}\int_0^1 \sqrt{1 - s^2}\,
                     \operatorname{asinh}\frac{\tau}{s}\,ds,

    \frac{\partial^2 u}{\partial y^2}(x_k, 0) = \sum_i \frac{q_i}{\pi E^* b_i^2}
    \left[\hat p(\tau^+_{ki}) - \hat p(\tau^-_{ki}) - 4\delta_{ki}\right],

with :math:`\tau^\pm_{ki} = (x_k - x_i \pm w/2)/b_i` and :math:`\hat p` the y-average
over the strip of the curvature of :math:`\int dx'/r` (module function
:func:`strip_influence`). The term :math:`-4\delta_{ki}` is the 2D Hertz curvature of the
strip's own (infinite) line contact, :math:`-4q/(\pi E^* b^2) = -1/R` in plane strain
(Johnson 1985, section 4.3); the rest corrects it for the strip's finite length and
adds the neighbours. For a circular crown this discretises the exact Hertz solution
(whose cross-sections are semi-ellipses), so it converges to it as w -> 0; with the
curvature condition replaced by the 2D relation :math:`b_k^2 = 4Rq_k/(\pi E^*)` it
would be the classical slice model with influence coefficients (Reusner 1977; de Mul,
Kalker & Fredriksson 1986; Teutsch & Sauer 2004; Fujiwara & Kawase 2006), which
converges to a contact off exact Hertz by 0.4-0.9 % in p0, 0.4-1.1 % in b and 0.07-0.2 %
in the approach for the crowns of the tests (measured with this code; 2D instead of 3D
curvature of the cross-sections).

The complementarity conditions (q_k >= 0, no interpenetration where q_k = 0) are solved
by Newton's method on (q_k, q_k/b_k^2) with an active set; force and moment control
wrap it in a Newton iteration on d and theta using the exact stiffness matrix
(implicit differentiation of the converged equations).

Accuracy (measured, tests/test_roller.py and docs/profiled_rollers.md): circular crown
against exact Hertz within 0.01 % in approach, p0, b and stiffness and 0.25 % in the
contact half-length at 100 slices, converging at second order in the slice width; a
straight roller within 0.4 % of the universal curve at 100 slices for d R/L^2 <= 4e-3
(0.65 % for a short, deeply pressed roller, L/R = 0.2 at d R/L^2 = 0.04), approaching
it from below as about n^(-0.75) (the end singularity).

Edge loading: on a half-space the pressure at a sharp roller end touched by the contact
is singular (a rigid flat-ended punch, Johnson 1985 section 5.6); the per-slice peak
there grows without bound as the slices are refined. The solution then reports
``edge_loaded = True`` and ``p_max = None`` with a message, never a grid-dependent
number.

Measured range: ``tables/roller_accuracy.csv`` (tools/studies/roller_study.py) maps this
model's error against a 3D boundary-element solution over L/D, the mean line load
q/(E* D) (D = 2R), the tilt, the tilt's drop over the approach and the profile; its
header states that range as data (``covered_*`` fields) and the largest errors inside it
(``runtime_error_*``). Every coupled-slice solution carries a note (``notes``) that
states those errors when the case lies inside the range, or names the quantity outside
it (read once, on the first solve).

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   3.2 (Boussinesq), 4.2 (Hertz), 4.3 (line contact), 5.6 (end effects).
.. [2] H. Reusner, "Druckflaechenbelastung und Oberflaechenverschiebung im
   Waelzkontakt von Rotationskoerpern", Dissertation, Karlsruhe (1977).
.. [3] J. M. de Mul, J. J. Kalker, B. Fredriksson, "The contact between arbitrarily
   curved bodies of finite dimensions", J. Tribology 108 (1986) 140-148.
.. [4] R. Teutsch, B. Sauer, "An alternative slicing technique to consider pressure
   concentrations in non-Hertzian line contacts", J. Tribology 126 (2004) 436-442.
.. [5] H. Fujiwara, T. Kawase, "Logarithmic profiles of rollers in roller bearings and
   optimization of the profiles", Proc. JSME C 72 (2006) 3022-3029.
.. [6] ISO/TS 16281:2008, Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded bearings (slicing method).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._numerics import NotAKnotSpline
from .models import ContactModel, register
from .profiles import Profile, StraightProfile, parse_profile
from .validity import (Interval, OutOfRangeError, check_interval, check_positive, out)

__all__ = [
    "RollerSolution",
    "ProfiledRoller",
    "roller_contact",
    "iso_slicing",
    "ProfiledRollerModel",
    "ISOSlicingModel",
    "strip_influence",
    "N_SLICES",
    "ISO_MIN_SLICES",
    "TILT_RANGE",
]

#: Slice counts accepted by the coupled-slice model.
N_SLICES = Interval("n_slices", 10, 4000)
#: ISO/TS 16281 asks for at least 30 slices.
ISO_MIN_SLICES = 30
#: Tilts accepted (the gap linearises the tilt: theta x for small angles).
TILT_RANGE = Interval("tilt", -0.1, 0.1, low_open=True, high_open=True, unit="rad")


class ConvergenceError(RuntimeError):
    """The slice equations did not converge (reported, never hidden)."""


# --------------------------------------------------------------------------------------
# The strip functions a, tau a', p^, tau p^' (exact for a semi-elliptical strip)
# --------------------------------------------------------------------------------------
_C0 = 0.5 + math.log(2.0)       # a(tau) - ln(2 tau) -> C0 as tau -> inf
_TAU_SERIES = 2.5               # series for tau >= this, quadrature below
_NTERMS = 28


def _series_coefficients():
    from math import lgamma
    k = np.arange(1, _NTERMS + 1)
    # M_k = (4/pi) int_0^1 s^2k sqrt(1 - s^2) ds = (2/pi) Gamma(k+1/2) Gamma(3/2)/Gamma(k+2)
    M = np.array([(2 / math.pi) * math.exp(lgamma(j + 0.5) + lgamma(1.5) - lgamma(j + 2))
                  for j in range(_NTERMS + 1)])
    # asinh z = ln 2z + sum_k (-1)^(k+1) C(2k, k) / (4^k 2k) z^(-2k)
    alpha = np.array([(-1.0) ** (j + 1) * math.exp(lgamma(2 * j + 1) - 2 * lgamma(j + 1)
                                                   - j * math.log(4)) / (2 * j) * M[j]
                      for j in k])

    def binom(a, j):
        v = 1.0
        for t in range(j):
            v *= (a - t) / (t + 1)
        return v

    # P(tau, s) - 1/s^2 = (1/s^2)[(1 + 2e)(1 + e)^(-3/2) - 1], e = s^2/tau^2
    gamma = np.array([(binom(-1.5, j) + 2 * binom(-1.5, j - 1)) * M[j - 1] for j in k])
    return alpha, gamma


_ALPHA, _GAMMA = _series_coefficients()
_GL_X, _GL_W = np.polynomial.legendre.leggauss(40)


def _series(coef, u):
    s = np.zeros_like(u)
    d = np.zeros_like(u)
    for j in range(len(coef) - 1, -1, -1):
        s = s * u + coef[j]
        d = d * u + (j + 1) * coef[j]
    return s * u, d * u


def _near(tau):
    """Quadrature for 0 < tau < 2.5 in phi (s = sin phi), graded by phi = tau sinh(t)."""
    t = tau[:, None]
    T = np.arcsinh(np.pi / (2 * t))
    tt = 0.5 * T * (_GL_X + 1)
    phi = t * np.sinh(tt)
    w = (0.5 * T * _GL_W) * t * np.cosh(tt) * (4 / np.pi) * np.cos(phi) ** 2
    s2 = np.sin(phi) ** 2
    t2 = t * t
    rho2 = s2 + t2
    rho = np.sqrt(rho2)
    a = _C0 + np.sum(w * np.log(t + rho), -1)
    ta = tau * np.sum(w / rho, -1)
    f = (t2 * t2 + s2 * t2 - s2 * s2) / ((t * t2 + 2 * s2 * t + rho2 * rho) * rho2 * rho)
    p = np.sum(w * f, -1)
    tp = tau * np.sum(w * (2 * s2 - t2) / (rho2 * rho2 * rho), -1)
    return a - np.log(2 * tau), ta, p, tp


_TAB_MIN = 1e-4
_TAB_MAX = 64.0
_NEAR_TABLE = []


def _near_table():
    """Cubic spline in ln(tau) of the four functions over [1e-4, 64] (built once).

    2701 nodes, h = 0.005 in ln tau, values from the quadrature (tau < 2.5) and the
    series (tau >= 2.5): interpolation error below 1e-10 of the function's scale
    (checked against the direct evaluation in tests). Evaluating the spline is several
    times cheaper than the 28-term series or the quadrature. Returns a function of
    ln(tau) (1D array) giving an array of shape (len, 4).

    The spline is the not-a-knot cubic (de Boor, A Practical Guide to Splines, 1978,
    chapter IV; what scipy's CubicSpline builds by default) of
    :class:`linecontact._numerics.NotAKnotSpline`, whose coefficients are taken here and
    evaluated by indexing the uniform grid (no search, no scipy import: the first solve
    of a process stays fast).
    """
    if not _NEAR_TABLE:
        n = 2701
        z0, z1 = math.log(_TAB_MIN), math.log(_TAB_MAX)
        z = np.linspace(z0, z1, n)
        h = (z1 - z0) / (n - 1)
        y = np.column_stack(_direct(np.exp(z)))             # (n, 4)
        # (segment, power, function), lowest power first
        c = np.stack([NotAKnotSpline(z, y[:, j]).c[::-1].T for j in range(4)], axis=-1)

        def spline(zq):
            i = np.clip(((zq - z0) / h).astype(np.intp), 0, n - 2)
            t = (zq - (z0 + i * h))[:, None]
            ci = c[i]
            return ((ci[:, 3] * t + ci[:, 2]) * t + ci[:, 1]) * t + ci[:, 0]

        _NEAR_TABLE.append(spline)
    return _NEAR_TABLE[0]


def _direct(flat):
    """The four functions by series (tau >= 2.5) or quadrature (below), 1D input."""
    r = np.empty_like(flat)
    ta = np.empty_like(flat)
    p = np.empty_like(flat)
    tp = np.empty_like(flat)
    # fewer series terms where tau is large (1e-16 relative in each band)
    for lo, hi, nt in ((_TAU_SERIES, 6.0, _NTERMS), (6.0, 30.0, 12), (30.0, np.inf, 6)):
        band = (flat >= lo) & (flat < hi)
        if not np.any(band):
            continue
        u = 1.0 / flat[band] ** 2
        s, ds = _series(_ALPHA[:nt], u)
        r[band] = _C0 + s
        ta[band] = 1.0 - 2 * ds
        s, ds = _series(_GAMMA[:nt], u)
        p[band] = s
        tp[band] = -2 * ds
    near = flat < _TAU_SERIES
    if np.any(near):
        r[near], ta[near], p[near], tp[near] = _near(flat[near])
    return r, ta, p, tp


def strip_influence(tau, direct=False):
    r"""The four functions of a semi-elliptical strip used by the coupled-slice model.

    For a line load q on |x'| < X, spread over |y'| < b as :math:`(2q/\pi b)
    \sqrt{1 - y'^2/b^2}`, the displacement and its y-curvature on the strip's centre line
    at distance t from one end follow from (with :math:`\tau = t/b`, s = y'/b)

    .. math::

        a(\tau) = \frac{4}{\pi}\int_0^1\sqrt{1-s^2}\,\operatorname{asinh}(\tau/s)\,ds,
        \qquad
        \hat p(\tau) = \frac{4}{\pi}\int_0^1\sqrt{1-s^2}\left[
            \frac{\tau(\tau^2 + 2s^2)}{s^2(\tau^2+s^2)^{3/2}} - \frac{1}{s^2}\right]ds .

    Parameters
    ----------
    tau : float or array_like
        t/b > 0 [-].
    direct : bool, optional
        Evaluate by series/quadrature instead of the cached spline table [-].

    Returns
    -------
    tuple of ndarray
        :math:`a(\tau) - \ln 2\tau`, :math:`\tau a'(\tau)`, :math:`\hat p(\tau)`,
        :math:`\tau \hat p'(\tau)` [-].

    Notes
    -----
    For tau >= 2.5 from the convergent series in :math:`\tau^{-2}` (the asinh and
    binomial series integrated against the semi-ellipse's moments
    :math:`M_k = (2/\pi)\Gamma(k+1/2)\Gamma(3/2)/\Gamma(k+2)`, 28 terms); below by
    40-point Gauss-Legendre quadrature in :math:`\varphi` (s = sin phi) graded as
    :math:`\varphi = \tau\sinh t`: relative accuracy 1e-13 for tau >= 0.01 and 1e-8
    down to tau = 1e-4 (checked against adaptive quadrature in tests). For
    1e-4 <= tau < 64 the default reads a cubic spline in ln tau of those values (error
    below 1e-10 of each function's scale). Large tau:
    :math:`a - \ln 2\tau \to 1/2 + \ln 2`, :math:`\hat p \to 1/(2\tau^2)`.

    Examples
    --------
    >>> r, ta, p, tp = strip_influence([0.5, 10.0])
    >>> [round(float(v), 6) for v in r], [round(float(v), 6) for v in p]
    ([1.355305, 1.193771], [0.714725, 0.004972])

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), Eq. 3.19 (Boussinesq) and section 4.3.
    """
    tau = check_interval("tau", tau, 0.0, np.inf, low_open=True, high_open=True)
    flat = np.atleast_1d(tau).ravel()
    vals = _direct(flat) if direct else _strip(flat)
    return tuple(v.reshape(np.shape(tau)) for v in vals)


def _strip(flat):
    """strip_influence without input checks (1D array of tau > 0)."""
    r, ta, p, tp = np.empty((4, flat.size))
    tab = (flat >= _TAB_MIN) & (flat < _TAB_MAX)
    if np.all(tab):
        return _near_table()(np.log(flat)).T
    if np.any(tab):
        r[tab], ta[tab], p[tab], tp[tab] = _near_table()(np.log(flat[tab])).T
    rest = ~tab
    r[rest], ta[rest], p[rest], tp[rest] = _direct(flat[rest])
    return r, ta, p, tp


# --------------------------------------------------------------------------------------
# The slice equations
# --------------------------------------------------------------------------------------
class _Slices:
    """Slice geometry and the Newton / active-set solver in scaled variables.

    Unknowns per loaded slice: qt = q/(pi E*) [m] and c = qt/b^2 [1/m].
    """

    def __init__(self, radius, estar, x_lo, x_hi, n, drop):
        self.R = radius
        self.E = estar
        self.n = n
        self.lo, self.hi = x_lo, x_hi
        self.dlo = self.dhi = (0.0, 0.0)       # d(lo, hi)/d(d, theta), set by the owner
        self.w = (x_hi - x_lo) / n
        self.x = x_lo + self.w * (np.arange(n) + 0.5)
        self.P = drop(self.x)
        j = np.arange(n)
        self.logj = np.log(2 * j + 1.0)
        self.iterations = 0

    def kernels(self, S, b, targets=None):
        """A, D and their b-derivative parts for targets T (default S) and sources S."""
        T = S if targets is None else targets
        span = int(max(T.max(), S.max()) - min(T.min(), S.min()))
        j = np.arange(span + 1)[:, None]
        shape = (span + 1, len(S))
        r, ta, p, tp = (v.reshape(shape) for v in
                        _strip(((j + 0.5) * self.w / b[None, :]).ravel()))
        # a(tau_j) = ln(2j + 1) + ln(w/b) + r(tau_j); columns of differences G[j] - G[j-1]
        # (j >= 1) and the self term 2 G[0]
        G = np.empty((4, span + 1, len(S)))
        rho = np.log(self.w / b)[None, :] + r
        for g, v in ((G[0], rho), (G[1], p), (G[2], ta), (G[3], tp)):
            g[1:] = v[1:] - v[:-1]
            g[0] = 2 * v[0]
        G[0, 1:] += (self.logj[1:span + 1] - self.logj[:span])[:, None]
        G[1, 0] -= 4.0
        m = np.abs(T[:, None] - S[None, :])
        cols = np.arange(len(S))[None, :]
        A, D, EA, ED = G[:, m, cols]
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
            # fraction to the boundary: q and c = q/b^2 stay positive
            alpha = 1.0
            hit_q = qs + dq <= 0.05 * qs
            if np.any(hit_q):
                alpha = min(alpha, float(np.min(0.95 * qs[hit_q] / -dq[hit_q])))
            hit_c = cs + dc <= 0.2 * cs
            if np.any(hit_c):
                alpha = min(alpha, float(np.min(0.8 * cs[hit_c] / -dc[hit_c])))
            q[S] = qs + alpha * dq
            c[S] = cs + alpha * dc
            if alpha == 1.0:
                blocked[S] = 0
                if np.max(np.abs(dq)) <= tol * qsc and np.max(np.abs(dc)) * R <= tol:
                    return S
                continue
            blocked[S[hit_q]] += 1
            blocked[S[~hit_q]] = 0
            leave = (blocked[S] >= 3) | (q[S] <= 1e-12 * qsc)
            if np.any(leave):
                q[S[leave]] = 0.0
                blocked[S[leave]] = 0
                S = S[~leave]
                if len(S) == 0:
                    raise ConvergenceError("every slice left the contact")
        raise ConvergenceError("Newton iteration on the slice loads did not converge "
                               "in 400 steps")

    def solve(self, d, theta, warm=None, tol=1e-11):
        """Active-set solution at depth d and tilt theta; returns (S, q, c)."""
        n, R = self.n, self.R
        over = d + theta * self.x - self.P
        S = np.flatnonzero(over > 0)
        none_in_contact = ConvergenceError(
            f"no slice is in contact at d = {d:.6g} m: the contact is narrower than one "
            "slice (too small a load for the slicing)")
        if S.size == 0:  # e.g. d - d0 below the rounding of d (a force of 1e-300 N)
            raise none_in_contact
        q = np.zeros(n)
        c = np.full(n, 1.0 / (4 * R))
        if warm is not None and np.any(warm[0][S] > 0):
            q[S] = warm[0][S]
            c[S] = np.where(warm[0][S] > 0, warm[1][S], c[S])
            S = S[q[S] > 0]
        else:
            # cold start: the linear problem with frozen strip widths, twice (the second
            # time with the plane-strain widths b^2 = 4 R q/(pi E*) of the first answer)
            b0 = np.sqrt(R * over[S])
            for sweep in range(2):
                for _ in range(n):
                    qs = np.linalg.solve(self.kernels(S, b0)[0], over[S])
                    if np.all(qs > 0):
                        break
                    S, b0 = S[qs > 0], b0[qs > 0]
                    if S.size == 0:
                        raise none_in_contact
                b0 = np.sqrt(4 * R * qs)
            q[S] = qs
        for _ in range(n + 1):
            S = self.newton(S, q, c, over, tol)
            rest = np.setdiff1d(np.arange(n), S)
            if len(rest) == 0:
                break
            A = self.kernels(S, np.sqrt(q[S] / c[S]), targets=rest)[0]
            pen = over[rest] - A @ q[S]
            add = pen > tol * np.max(over)
            if not np.any(add):
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
        ns, n, w = len(S), self.n, self.w
        qs, cs, xs = q[S], c[S], self.x[S]
        k = S + 0.5
        # columns: d, theta, lo, hi ; rows: -dR/dp
        rhs = np.zeros((2 * ns, 4))
        rhs[:ns, 0] = 1.0
        rhs[:ns, 1] = xs
        dlnw = np.array([-1.0, 1.0]) / (n * w)                 # d ln w / d(lo, hi)
        dx = np.stack([1.0 - k / n, k / n], axis=1)            # d x_k / d(lo, hi)
        ea_q, ed_c = EA @ qs, ED @ cs
        for g in range(2):
            rhs[:ns, 2 + g] = -(ea_q * dlnw[g] - (th - slope[S]) * dx[:, g])
            rhs[ns:, 2 + g] = -ed_c * dlnw[g]
        qsc = np.max(qs)
        colsc = np.concatenate([np.full(ns, qsc), np.full(ns, 1.0 / self.R)])
        rowsc = np.concatenate([np.full(ns, 1.0 / qsc), np.full(ns, self.R)])
        z = np.linalg.solve(J * rowsc[:, None] * colsc[None, :], rhs * rowsc[:, None])
        dq = z[:ns] * qsc                                     # d qt / d(d, th, lo, hi)
        dw = np.array([0.0, 0.0, -1.0 / n, 1.0 / n])
        dxk = np.zeros((ns, 4))
        dxk[:, 2:] = dx
        dF = w * dq.sum(0) + dw * qs.sum()
        dM = w * (xs[:, None] * dq).sum(0) + dw * (qs * xs).sum() + w * (qs[:, None] * dxk).sum(0)
        G = np.array([[1.0, 0.0], [0.0, 1.0], self.dlo, self.dhi])   # d(d, th, lo, hi)/d(d, th)
        return math.pi * self.E * np.array([dF @ G, dM @ G])


# --------------------------------------------------------------------------------------
# Where the model's error is known: the header of tables/roller_accuracy.csv
# --------------------------------------------------------------------------------------
_COVERAGE = []
_ACCURACY_TABLE = "roller_accuracy"
#: relative slack on the covered bounds (the header prints 6 significant digits)
_COVER_SLACK = 1e-5


def _coverage():
    """The covered_* and runtime_error_* fields of tables/roller_accuracy.csv, parsed
    once on first use (None if the table or the fields are missing)."""
    if not _COVERAGE:
        from .tables import read_table
        try:
            meta = read_table(_ACCURACY_TABLE).meta

            def pair(key):
                lo, hi = (float(v) for v in meta[key].split(","))
                return lo, hi

            def errors(key):
                return {k: float(v) for k, v in
                        (item.split() for item in meta[key].split(","))}

            cov = dict(
                l_over_d=pair("covered_l_over_d"),
                line_load=pair("covered_line_load_over_estar_d"),
                given_tilt=pair("covered_given_tilt_rad"),
                free_tilt=pair("covered_free_tilt_rad"),
                tilt_drop=pair("covered_tilt_drop_over_approach"),
                profiles=tuple(k.strip() for k in meta["covered_profiles"].split(",")),
                off=errors("runtime_error_off_ends"),
                edge=errors("runtime_error_edge_loaded"))
        except (FileNotFoundError, KeyError, ValueError):
            cov = None
        _COVERAGE.append(cov)
    return _COVERAGE[0]


def _pct(v):
    return f"{100 * v:.2g} %"


def _coverage_note(radius, length, estar, profile_key, force, tilt, approach,
                   free_tilt=False, edge_loaded=False, n_slices=100):
    """The note on where a coupled-slice case lies relative to the range measured in
    tables/roller_accuracy.csv (L/D with D = 2R, F/(L E* D), |theta| given or free,
    the tilt drop |theta| L/2 over the largest rigid overlap `approach` [m], the profile
    key, n_slices >= 100): names each quantity outside, and states the table's largest
    errors (off the ends, or edge loaded). Bounds with a relative slack of 1e-5 (the
    header prints 6 digits)."""
    cov = _coverage()
    where = "the 3D BEM (tables/roller_accuracy.csv)"
    if cov is None:
        return (f"this model's error against {where} is not known here: the table or "
                "its covered_* fields are missing")
    D = 2 * radius
    th = abs(tilt)
    tkey, tname = ("free_tilt", "zero-moment tilt") if free_tilt else (
        "given_tilt", "tilt")
    drop = th * length / 2 / approach if approach > 0 else (0.0 if th == 0 else math.inf)
    checks = [("L/D", length / D, cov["l_over_d"], ""),
              ("mean line load q/(E* D)", force / (length * estar * D), cov["line_load"],
               ""),
              (f"|{tname}|", th, cov[tkey], " rad"),
              ("tilt drop |theta| L/2 over the approach", drop, cov["tilt_drop"], "")]
    outside = [f"{name} = {v:.2g}{u} (measured {lo:.2g}-{hi:.2g}{u})"
               for name, v, (lo, hi), u in checks
               if not lo * (1 - _COVER_SLACK) <= v <= hi * (1 + _COVER_SLACK)]
    if profile_key not in cov["profiles"]:
        outside.append(f"profile '{profile_key}' (measured: "
                       f"{', '.join(cov['profiles'])})")
    if n_slices < 100:
        outside.append(f"n_slices = {n_slices} (measured with 100)")
    off, edge = cov["off"], cov["edge"]
    if edge_loaded:
        errs = (f"edge loaded: deflection {_pct(edge['depth'])}, moment "
                f"{_pct(edge['moment'])}, zero-moment tilt {_pct(edge['tilt'])} (peak "
                "pressure singular, not reported)")
    else:
        errs = (f"contact off the ends: deflection {_pct(off['depth'])}, moment "
                f"{_pct(off['moment'])} (tilted), peak pressure {_pct(off['p_max'])}, "
                f"zero-moment tilt {_pct(off['tilt'])}")
    if outside:
        return (f"{'; '.join(outside)}: outside the range where this model's error was "
                f"measured against {where}; inside it the largest errors are, {errs}")
    inside = f"L/D = {length / D:.2g} and mean line load q/(E* D) = " \
             f"{force / (length * estar * D):.2g}"
    return (f"{inside} are inside the range where this model's error was measured "
            f"against {where}: largest errors there, {errs}")


@dataclass(frozen=True)
class RollerSolution:
    """The state of a profiled, tilted roller in contact: loads, stiffness, pressure.

    Returned by :meth:`ProfiledRoller.at_depth`, :meth:`ProfiledRoller.at_force`,
    :func:`roller_contact` and :func:`iso_slicing`; not built by hand.

    .. math:: F = \\sum_k q_k w, \\qquad M = \\sum_k q_k x_k w

    Parameters
    ----------
    depth : float
        Depth (approach) d of the roller point x = 0 [m].
    tilt : float
        Tilt theta, positive when the +x end goes deeper [rad].
    force : float
        Normal force F [N].
    moment : float
        Moment about x = 0, positive when +x carries more [N m].
    stiffness : float
        dF/dd at fixed tilt [N/m].
    tilt_stiffness : float
        dM/dtheta at fixed depth [N m/rad].
    stiffness_matrix : ndarray
        [[dF/dd, dF/dtheta], [dM/dd, dM/dtheta]] [N/m, N/rad; N, N m/rad].
    x : ndarray
        Slice centres [m].
    q : ndarray
        Line load q(x_k), 0 outside the contact [N/m].
    half_width : ndarray
        Contact half-width b_k across the roller, 0 outside the contact [m].
    pressure : ndarray
        Peak pressure of each slice, 2 q_k/(pi b_k) [Pa].
    p_max : float or None
        Peak pressure, interpolated between slices; None when edge loaded [Pa].
    x_at_p_max : float
        Where the peak sits, the loaded end when edge loaded [m].
    contact_start : float
        Start of the contact along x, where q falls to zero [m].
    contact_end : float
        End of the contact along x [m].
    contact_length : float
        contact_end - contact_start [m].
    edge_loaded : bool
        True if the contact reaches an end of the roller (within a slice width or
        L/1000 of it).
    edge : str or None
        ``"-x"``, ``"+x"``, ``"both"`` or None.
    message : str
        What p_max means here, or why it is None.
    method : str
        ``"coupled slices"`` or ``"ISO/TS 16281 slicing"``.
    n_slices : int
        Number of slices [-].
    iterations : int
        Newton iterations used [-].
    notes : tuple of str
        Warnings about the validity of this solution.
    p_max_resolved : bool
        False if the peak sits within two slices of the contact's end (a concentration
        narrower than the slices, e.g. at a sharp relief): then p_max is not converged.

    Notes
    -----
    Valid as the model that produced it (see :class:`ProfiledRoller`): |theta| < 0.1
    rad, b << R; q, half_width and pressure are per slice, 0 <= q < inf.

    Examples
    --------
    >>> s = roller_contact(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5", force=1000.0)
    >>> f"{s.force:.0f} N, {abs(s.moment):.0f} N m, {s.contact_length * 1e3:.1f} mm"
    '1000 N, 0 N m, 4.6 mm'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2 (Hertz pressure across).
    """

    depth: float
    tilt: float
    force: float
    moment: float
    stiffness: float
    tilt_stiffness: float
    stiffness_matrix: np.ndarray
    x: np.ndarray
    q: np.ndarray
    half_width: np.ndarray
    pressure: np.ndarray
    p_max: object
    x_at_p_max: float
    contact_start: float
    contact_end: float
    contact_length: float
    edge_loaded: bool
    edge: object
    message: str
    method: str
    n_slices: int
    iterations: int = 0
    notes: tuple = field(default_factory=tuple)
    p_max_resolved: bool = True

    def to_dict(self, arrays=True):
        """Plain-Python dict (for JSON): scalars in SI, arrays as lists if `arrays`.

        Returns
        -------
        dict
            Keys as the attributes, with units in ``"units"``.

        Examples
        --------
        >>> s = roller_contact(5e-3, 10e-3, 115.385e9, "circular:Rc=0.1", force=500.0)
        >>> sorted(s.to_dict(arrays=False))[:4]
        ['contact_end', 'contact_length', 'contact_start', 'depth']
        """
        d = {}
        for k, v in self.__dict__.items():
            if isinstance(v, np.ndarray):
                if arrays:
                    d[k] = v.tolist()
            elif isinstance(v, tuple):
                d[k] = list(v)
            else:
                d[k] = v
        d["units"] = {"depth": "m", "tilt": "rad", "force": "N", "moment": "N m",
                      "stiffness": "N/m", "tilt_stiffness": "N m/rad", "x": "m",
                      "q": "N/m", "half_width": "m", "pressure": "Pa", "p_max": "Pa",
                      "x_at_p_max": "m", "contact_start": "m", "contact_end": "m",
                      "contact_length": "m"}
        return d


def _contact_extent(x, q, w, L, lo=None, hi=None):
    """Ends of the contact from the loaded slices, q extrapolated to zero."""
    on = np.flatnonzero(q > 0)
    i0, i1 = on[0], on[-1]
    n = len(x)

    def end(i, step):
        # q near a smooth contact edge falls linearly; use the last three loaded slices
        idx = [i - step * k for k in range(3)]
        if not all(0 <= j < n and q[j] > 0 for j in idx):
            idx = idx[:2] if all(0 <= j < n and q[j] > 0 for j in idx[:2]) else idx[:1]
        if len(idx) == 1:
            return x[i] + step * w / 2
        coef = np.polyfit(x[idx], q[idx], len(idx) - 1)
        roots = np.roots(coef)
        roots = roots[np.isreal(roots)].real
        lo, hi = sorted((x[i], x[i] + step * w))
        roots = roots[(roots >= lo) & (roots <= hi)]
        if len(roots) == 0:
            return x[i] + step * w / 2
        return float(roots[np.argmin(np.abs(roots - x[i]))])

    lo = -L / 2 if lo is None else lo
    hi = L / 2 if hi is None else hi
    start = lo if i0 == 0 else end(i0, -1)
    stop = hi if i1 == n - 1 else end(i1, +1)
    tol = 1e-9 * L
    return start, stop, i0 == 0 and lo <= -L / 2 + tol, i1 == n - 1 and hi >= L / 2 - tol


def _peak(x, p):
    """Peak of p over the slices, refined by a parabola through p^2 (exact for Hertz)."""
    k = int(np.argmax(p))
    if 0 < k < len(x) - 1 and p[k - 1] > 0 and p[k + 1] > 0:
        y0, y1, y2 = p[k - 1] ** 2, p[k] ** 2, p[k + 1] ** 2
        den = y0 - 2 * y1 + y2
        if den < 0:
            h = x[1] - x[0]
            s = 0.5 * (y0 - y2) / den
            return math.sqrt(y1 - 0.25 * (y0 - y2) * s), float(x[k] + s * h)
    return float(p[k]), float(x[k])


class ProfiledRoller:
    """A profiled roller on a flat (or a raceway via R), solved by coupled slices.

    .. math:: h(x, y) = y^2/(2R) + P(x) - \\theta x

    The n slices span the interval where the rigid bodies overlap,
    {x : d + theta x - P(x) > 0} (clipped to the roller): on a half-space the surface
    displacement is positive wherever there is pressure, so the contact lies inside
    that interval, and the slices resolve the contact, not the whole roller.

    Parameters
    ----------
    radius : float
        Radius R across the axis, or the effective radius against a raceway,
        0 < R < inf [m].
    length : float
        Roller length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].
    profile : Profile or str or None, optional
        Profile drop (:mod:`linecontact.profiles`), a spec such as
        ``"circular:Rc=500mm"`` (see :func:`~linecontact.profiles.parse_profile`), or
        None for a straight roller. A spec is read with this R: ``"iso16281"`` without
        ``D=`` takes D = 2R, the roller's diameter only on a flat; against a raceway
        write ``"iso16281:D=..."``.
    n_slices : int, optional
        Number of slices n, 10 <= n <= 4000 [-] (default 100).

    Notes
    -----
    Valid for small contacts (b << R, depth << R) and tilts |theta| < 0.1 rad. The
    profile must cover -L/2 <= x <= L/2. The overlap interval is found on a grid of
    16 n + 1 points along the roller. Accuracy: see the module docstring.

    Examples
    --------
    Crowned roller, R = 10 mm, Rc = 500 mm, L = 20 mm, steel, 1 kN (exact Hertz: approach
    7.024 um, p0 1102 MPa):

    >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
    >>> s = r.at_force(1000.0)
    >>> f"{s.depth * 1e6:.3f} um, {s.p_max / 1e6:.0f} MPa, edge loaded: {s.edge_loaded}"
    '7.024 um, 1102 MPa, edge loaded: False'

    References
    ----------
    See the module docstring.
    """

    def __init__(self, radius, length, estar, profile=None, n_slices=100):
        self.radius = float(check_positive("radius", radius, "m"))
        self.length = float(check_positive("length", length, "m"))
        self.estar = float(check_positive("estar", estar, "Pa"))
        n = N_SLICES.check(n_slices).item()
        if n != int(n):
            raise OutOfRangeError("n_slices", n_slices, "an integer in [10, 4000]")
        self.n_slices = int(n)
        self.profile = _profile(profile, self.radius, self.length, self.estar)
        L = self.length
        self._fx = np.linspace(-L / 2, L / 2, 16 * self.n_slices + 1)
        self._fP = _drop_at(self.profile, L, self._fx, ends_may_be_inf=True)
        self._warm = None
        self._memo = None
        self.iterations = 0

    def first_contact_depth(self, tilt=0.0):
        """Depth of first contact, min over x of P(x) - theta x [m] (on the 16 n + 1 grid).

        .. math:: d_0 = \\min_x \\left[P(x) - \\theta x\\right]

        Parameters
        ----------
        tilt : float, optional
            Tilt theta [rad].

        Returns
        -------
        float
            d0 [m]; no contact for d <= d0.

        Notes
        -----
        The minimum over a grid of 16 n + 1 points, refined by the parabola through the
        three smallest values (exact for a circular crown).

        Examples
        --------
        >>> r = ProfiledRoller(5e-3, 10e-3, 1e11, "circular:Rc=0.1", n_slices=10)
        >>> r.first_contact_depth(), f"{r.first_contact_depth(1e-3) * 1e6:.3f} um"
        (0.0, '-0.050 um')
        """
        th = TILT_RANGE.check(tilt).item()
        h = self._fP - th * self._fx
        k = int(np.argmin(h))
        hmin = float(h[k])
        if 0 < k < len(h) - 1 and np.all(np.isfinite(h[k - 1:k + 2])):
            den = h[k - 1] - 2 * h[k] + h[k + 1]
            corr = (h[k + 1] - h[k - 1]) ** 2 / (8 * den) if den > 0 else 0.0
            if corr > 1e-12 * max(abs(h[k - 1]), abs(h[k + 1])):
                # vertex of the parabola through the three smallest values
                hmin = float(h[k] - corr)
        return hmin

    def _grid(self, d, th):
        """Slices over the overlap interval, its ends interpolated between grid points.

        The ends move continuously (piecewise linearly) with d and theta, so that F(d)
        is continuous; their derivatives enter the stiffness matrix.
        """
        fx = self._fx
        over = d + th * fx - self._fP
        on = np.flatnonzero(over > 0)
        dlo = dhi = (0.0, 0.0)
        if len(on) == 0:
            k = int(np.argmax(over))
            lo, hi = fx[max(k - 1, 0)], fx[min(k + 1, len(fx) - 1)]
        else:
            i, j = on[0], on[-1]
            lo, hi = fx[0], fx[-1]
            h = fx[1] - fx[0]
            if i > 0 and np.isfinite(over[i - 1]):
                o0, o1, x0, x1 = over[i - 1], over[i], fx[i - 1], fx[i]
                delta = o1 - o0
                lo = x0 + h * (-o0 / delta)
                dlo = (-h / delta, h * (-x0 * delta + o0 * (x1 - x0)) / delta**2)
            elif i > 0:
                lo = fx[i]
            if j < len(fx) - 1 and np.isfinite(over[j + 1]):
                o0, o1, x0, x1 = over[j], over[j + 1], fx[j], fx[j + 1]
                delta = o0 - o1
                hi = x0 + h * (o0 / delta)
                dhi = (h / delta, h * (x0 * delta - o0 * (x0 - x1)) / delta**2)
            elif j < len(fx) - 1:
                hi = fx[j]
        s = _Slices(self.radius, self.estar, float(lo), float(hi), self.n_slices,
                    lambda x: _drop_at(self.profile, self.length, x))
        s.dlo, s.dhi = dlo, dhi
        return s

    def _slope(self, x):
        """dP/dx at the slice centres by central differences (step 1e-7 L, inside)."""
        h = 1e-7 * self.length
        lo, hi = -self.length / 2, self.length / 2
        xp, xm = np.minimum(x + h, hi), np.maximum(x - h, lo)
        return (_drop_at(self.profile, self.length, xp)
                - _drop_at(self.profile, self.length, xm)) / (xp - xm)

    # -- depth control ---------------------------------------------------------------
    def at_depth(self, depth, tilt=0.0):
        """Solve at depth d and tilt theta.

        .. math:: u(x_k, 0) = d + \\theta x_k - P(x_k) \\text{ on loaded slices}

        Parameters
        ----------
        depth : float
            Depth d of the roller point x = 0 [m]; must exceed
            :meth:`first_contact_depth` (else there is no contact).
        tilt : float, optional
            Tilt theta, |theta| < 0.1 [rad].

        Returns
        -------
        RollerSolution

        Raises
        ------
        OutOfRangeError
            A depth at or below first contact (no contact at all), or a bad tilt.

        Examples
        --------
        >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
        >>> f"{r.at_depth(7.0244e-6).force:.0f} N"
        '1000 N'
        """
        th = TILT_RANGE.check(tilt).item()
        d0 = self.first_contact_depth(th)
        d = check_interval("depth", depth, d0, np.inf, low_open=True, high_open=True,
                           unit="m", hint=f"at tilt {th:.6g} rad the roller first touches "
                                          f"at depth {d0:.6g} m; at or below it there is "
                                          "no contact").item()
        return self._solution(*self._forces(d, th))

    def _forces(self, d, th, tol=1e-11):
        s = self._grid(d, th)
        e = float(np.max(d + th * s.x - s.P))          # largest overlap on the slices
        warm = None
        if self._warm is not None:
            # the last solution, mapped onto this grid by the relative position in the
            # overlap interval and scaled with the largest overlap (q ~ overlap)
            xi_o, qo, co, eo = self._warm
            ratio = e / eo if eo > 0 else 0.0
            if 0.5 < ratio < 2.0:
                xi = (s.x - s.lo) / (s.hi - s.lo)
                warm = (np.interp(xi, xi_o, qo, left=0.0, right=0.0) * ratio,
                        np.interp(xi, xi_o, co))
        S, q, c = s.solve(d, th, warm=warm, tol=tol)
        self._warm = ((s.x - s.lo) / (s.hi - s.lo), q.copy(), c.copy(), e)
        self.iterations += s.iterations
        scale = math.pi * self.estar * s.w
        F = scale * q.sum()
        M = scale * (q * s.x).sum()
        K = s.sensitivities(S, q, c, th, self._slope(s.x))
        return d, th, F, M, K, (s, S, q, c)

    def _solution(self, d, th, F, M, K, state, free_tilt=False):
        s, S, q, c = state
        qN = math.pi * self.estar * q
        b = np.zeros_like(q)
        b[S] = np.sqrt(q[S] / c[S])
        p = np.zeros_like(q)
        p[S] = 2.0 * self.estar * np.sqrt(q[S] * c[S])       # 2 q/(pi b)
        start, stop, lo_edge, hi_edge = _contact_extent(s.x, q, s.w, self.length,
                                                        s.lo, s.hi)
        # within a slice width (or L/1000) of an end counts as reaching it: a log
        # profile's contact approaches the end without touching it exactly
        near = max(s.w, 1e-3 * self.length)
        lo_edge = lo_edge or start <= -self.length / 2 + near
        hi_edge = hi_edge or stop >= self.length / 2 - near
        # an end where the drop is infinite (Lundberg, ISO/TS 16281: ln 1/(1 - (2x/L)^2))
        # is never reached: the rigid overlap ends before it, the contact with it, and the
        # pressure stays finite (3D BEM, Lundberg at its design load, R 5 mm, L 10 mm,
        # 1 kN: contact ends 9.8 um before each end, peak 972 MPa 28 um from it, converged
        # from 1024 to 4096 cells; docs/profiled_rollers.md). A contact reaching the last
        # slice there is an end zone narrower than the slices: p_max unresolved, below.
        inf_lo, inf_hi = (not np.isfinite(self._fP[0]), not np.isfinite(self._fP[-1]))
        on = np.flatnonzero(q > 0)
        end_zone = ((inf_lo and lo_edge and on[0] == 0)
                    or (inf_hi and hi_edge and on[-1] == len(q) - 1))
        lo_edge = lo_edge and not inf_lo
        hi_edge = hi_edge and not inf_hi
        edge = {(True, True): "both", (True, False): "-x", (False, True): "+x"}.get(
            (lo_edge, hi_edge))
        notes = []
        resolved = False
        if edge is None:
            pm, xm = _peak(s.x, p)
            k = int(np.argmax(p))
            resolved = bool(on[0] + 2 <= k <= on[-1] - 2) and not end_zone
            msg = ("peak of the Hertz strips (coupled slices, interpolated); the contact "
                   "stays inside the roller")
            if end_zone:
                # the largest slice pressure, not the parabola through p^2 (exact for a
                # Hertz peak, it overshoots a peak narrower than the slices: ISO/TS
                # 16281 profile, L 14 mm, D 10 mm, 300 N/mm, 2 mrad, 100 slices: 2545
                # MPa against the slice's 2434 and the converged BEM's 2363 (tables/
                # roller_accuracy.csv; 200 slices 2362)
                pm, xm = float(p[k]), float(s.x[k])
                msg += ("; it ends within the last slice before a roller end where the "
                        "profile's drop is infinite (never reached, the pressure stays "
                        "finite): that end zone and any peak in it are narrower than the "
                        "slices, not converged, refine n_slices")
            elif not resolved:
                msg += ("; the peak sits at the end of the contact, a concentration "
                        "narrower than a few slices: not converged, refine n_slices")
        else:
            pm = None
            xm = {"-x": -self.length / 2, "+x": self.length / 2}.get(edge, self.length / 2)
            msg = ("edge loaded: the contact reaches the roller end ({}), where the "
                   "pressure on a half-space is singular; a peak pressure there depends "
                   "on the slice width and is not reported").format(edge)
        if np.max(b) > 0.1 * self.radius:
            notes.append(f"contact half-width b = {np.max(b):.3g} m exceeds 0.1 R: the "
                         "parabolic gap y^2/(2R) is inaccurate")
        with np.errstate(invalid="ignore"):
            approach = float(np.max(d + th * self._fx - self._fP))
        notes.append(_coverage_note(self.radius, self.length, self.estar,
                                    self.profile.key, F, th, approach, free_tilt,
                                    edge is not None, self.n_slices))
        its, self.iterations = self.iterations, 0
        return RollerSolution(
            depth=float(d), tilt=float(th), force=float(F), moment=float(M),
            stiffness=float(K[0, 0]), tilt_stiffness=float(K[1, 1]), stiffness_matrix=K,
            x=s.x.copy(), q=qN, half_width=b, pressure=p, p_max=pm, x_at_p_max=xm,
            contact_start=start, contact_end=stop, contact_length=stop - start,
            edge_loaded=edge is not None, edge=edge, message=msg, method="coupled slices",
            n_slices=self.n_slices, iterations=its, notes=tuple(notes),
            p_max_resolved=resolved)

    # -- force control -----------------------------------------------------------------
    def _depth_at_force(self, F0, th, tol):
        """Newton on ln(d - d0) for F(d) = F0 at fixed tilt (F increases with d)."""
        d0 = self.first_contact_depth(th)
        L, R, E = self.length, self.radius, self.estar
        if self._memo is not None and self._memo[0] == th:
            # from the last solution of this roller: F ~ e^slope
            _, e_last, F_last, slope = self._memo
            e = e_last * (F0 / F_last) ** (1.0 / slope)
        else:
            # the straight roller's 2D estimate (a lower bound for a profiled roller)
            e = F0 / (math.pi * E * L) * max(
                1.0 + math.log(max(math.pi * E * L**3 / (R * F0), math.e)), 2.0)
        lo, hi = 0.0, math.inf
        err = 0.0 if self._memo is not None else math.inf   # a memo start is close
        for _ in range(100):
            # solve loosely while far from the force (inexact Newton), tightly near it
            inner = 1e-11 if err < 1e-3 else 1e-7
            st = self._forces(d0 + e, th, tol=inner)
            F, K = st[2], st[4]
            slope = min(max(K[0, 0] * e / F, 0.5), 3.0)  # d ln F/d ln e, 1 to about 1.5
            err = abs(F / F0 - 1)
            if err <= tol:
                if inner == 1e-11:
                    self._memo = (th, e, F, slope)
                    return st
                continue                      # the same depth once more, solved tightly
            if F < F0:
                lo = max(lo, e)
            else:
                hi = min(hi, e)
            en = e * (F0 / F) ** (1.0 / slope)
            if not lo < en < hi:
                en = math.sqrt(lo * hi) if (lo > 0 and math.isfinite(hi)) else (
                    e * 4 if F < F0 else e / 4)
            e = en
        raise ConvergenceError(f"no depth found for force {F0:g} N")

    def at_force(self, force, tilt=None, tol=1e-10):
        """Solve at force F, with a given tilt or (tilt=None) at zero moment.

        .. math:: \\sum_k q_k w = F, \\qquad \\sum_k q_k x_k w = 0 \\text{ (tilt free)}

        Parameters
        ----------
        force : float
            Normal force F, 0 < F < inf [N].
        tilt : float or None, optional
            Tilt theta [rad], |theta| < 0.1; None (default) solves for the tilt at
            which the moment about x = 0 vanishes (a roller free to tilt).
        tol : float, optional
            Relative tolerance on F (and on M/(F L)) [-].

        Returns
        -------
        RollerSolution

        Examples
        --------
        >>> r = ProfiledRoller(10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
        >>> s = r.at_force(1000.0, tilt=2e-3)      # contact moves to x* = Rc theta = 1 mm
        >>> f"M/F = {s.moment / s.force * 1e3:.3f} mm"
        'M/F = 1.000 mm'
        """
        F0 = float(check_positive("force", force, "N"))
        if tilt is not None:
            th = TILT_RANGE.check(tilt).item()
            return self._solution(*self._depth_at_force(F0, th, tol))
        L = self.length
        st = self._depth_at_force(F0, 0.0, tol)
        free = self._free_tilt(F0, st, tol)
        if free is not None:
            return self._solution(*free, free_tilt=True)
        th = 0.0
        for _ in range(60):
            st = self._depth_at_force(F0, th, tol)
            M, K = st[3], st[4]
            if abs(M) <= tol * F0 * L:
                return self._solution(*st, free_tilt=True)
            kmt = K[1, 1] - K[1, 0] * K[0, 1] / K[0, 0]     # dM/dtheta at constant F
            step = -M / kmt
            while abs(th + step) >= TILT_RANGE.high:
                step /= 2
            th = th + step
        raise ConvergenceError(f"no zero-moment tilt found for force {F0:g} N")

    def _free_tilt(self, F0, st, tol, steps=12):
        """Newton on (d, theta) together for F = F0 and M = 0 from the aligned solution
        `st` (its step from the exact 2x2 stiffness matrix), one slice solve per step;
        None if it leaves the admissible region or does not converge (the caller then
        iterates on theta with F solved at each tilt, slower but safe)."""
        L = self.length
        d, th = st[0], st[1]
        for _ in range(steps):
            F, M, K = st[2], st[3], st[4]
            if abs(F / F0 - 1) <= tol and abs(M) <= tol * F0 * L:
                return st
            try:
                dd, dth = np.linalg.solve(K, [F0 - F, -M])
            except np.linalg.LinAlgError:
                return None
            th_new = th + dth
            if not abs(th_new) < TILT_RANGE.high:
                return None
            d0 = self.first_contact_depth(th_new)
            d_new = d + dd
            if d_new <= d0:
                # keep the overlap positive: halve the distance to first contact
                d_new = d0 + 0.5 * (d - self.first_contact_depth(th))
            d, th = d_new, th_new
            st = self._forces(d, th)
        return None


def _profile(profile, radius, length, estar):
    if profile is None:
        return StraightProfile(length)
    if isinstance(profile, str):
        return parse_profile(profile, length=length, radius=radius, estar=estar)
    if not isinstance(profile, Profile):
        raise OutOfRangeError("profile", repr(profile),
                              "a linecontact.profiles.Profile, a profile spec or None")
    return profile


def _drop_at(profile, length, x, ends_may_be_inf=False):
    """P at x, checking that the profile covers the roller and the drop is >= 0."""
    tol = 1e-12 * length
    if profile.x_min > -length / 2 + tol or profile.x_max < length / 2 - tol:
        raise OutOfRangeError("profile", profile.label,
                              f"a profile covering [{-length / 2:.6g}, {length / 2:.6g}] m",
                              hint=f"it covers [{profile.x_min:.6g}, {profile.x_max:.6g}] m")
    P = np.asarray(profile.drop(np.clip(x, profile.x_min, profile.x_max)), dtype=float)
    ok = np.isfinite(P) & (P >= 0)
    if ends_may_be_inf:
        ok |= np.isposinf(P) & (np.abs(x) >= length / 2 * (1 - 1e-12))
    if not np.all(ok):
        i = int(np.flatnonzero(~ok)[0])
        raise OutOfRangeError("profile drop", float(P[i]), "[0, inf) m", unit="m",
                              where=f"at x = {x[i]:.6g} m")
    return P


def roller_contact(radius, length, estar, profile=None, *, depth=None, force=None,
                   tilt=None, n_slices=100):
    """Solve a profiled, tilted roller on a flat at a depth or a force (coupled slices).

    .. math:: h(x, y) = y^2/(2R) + P(x) - \\theta x

    Give exactly one of `depth` (with `tilt`, default 0) or `force` (with `tilt`, or
    without it for zero moment).

    Parameters
    ----------
    radius : float
        Radius across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    profile : Profile or str or None
        Profile drop or spec (None: straight) [-].
    depth : float, optional
        Depth d [m].
    force : float, optional
        Force F [N].
    tilt : float, optional
        Tilt theta [rad].
    n_slices : int, optional
        Number of slices [-] (default 100).

    Returns
    -------
    RollerSolution

    Raises
    ------
    OutOfRangeError
        Bad input (see :class:`ProfiledRoller`), neither or both of depth and force.

    Notes
    -----
    Valid for |theta| < 0.1 rad, b << R, 10 <= n_slices <= 4000; accuracy in the module
    docstring.

    Examples
    --------
    >>> s = roller_contact(10e-3, 20e-3, 115.385e9, "circular:Rc=0.2", force=2000.0)
    >>> f"{s.depth * 1e6:.2f} um, b {s.half_width.max() * 1e3:.4f} mm"
    '13.92 um, b 0.2861 mm'

    References
    ----------
    See the module docstring.
    """
    if (depth is None) == (force is None):
        raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                              "exactly one of depth, force")
    r = ProfiledRoller(radius, length, estar, profile, n_slices=n_slices)
    if depth is not None:
        return r.at_depth(depth, 0.0 if tilt is None else tilt)
    return r.at_force(force, tilt)


# --------------------------------------------------------------------------------------
# ISO/TS 16281 slicing (uncoupled slices), for comparison
# --------------------------------------------------------------------------------------
def _iso_state(P, x, L, E, n, d, th):
    from .classical import iso16281_force
    delta = d + x * math.tan(th) - P
    on = delta > 0
    Q = np.zeros_like(delta)
    if np.any(on):
        Q[on] = iso16281_force(delta[on], L, E) / n
    k = np.zeros_like(delta)
    k[on] = (10.0 / 9.0) * Q[on] / delta[on]       # dQ_k/d(delta_k)
    sec2 = 1.0 / math.cos(th) ** 2
    K = np.array([[k.sum(), (k * x).sum() * sec2],
                  [(k * x).sum(), (k * x * x).sum() * sec2]])
    return Q, float(Q.sum()), float((Q * x).sum()), K


def iso_slicing(radius, length, estar, profile=None, *, depth=None, force=None, tilt=None,
                n_slices=30):
    """ISO/TS 16281 slicing: uncoupled nonlinear slice springs with the misalignment term.

    .. math::

        Q_k = \\frac{c}{n}\\,\\delta_k^{10/9},\\qquad
        \\delta_k = d + x_k\\tan\\theta - P(x_k) \\;(> 0),\\qquad
        F = \\sum_k Q_k,\\quad M = \\sum_k Q_k x_k

    where c reproduces the standard's one-contact formula
    d [mm] = 3.97e-5 F[N]^0.9 / L[mm]^0.8 for a straight roller
    (:func:`linecontact.classical.iso16281_force`, the same constant), so uniform
    deflection gives the whole-roller formula exactly.

    Parameters
    ----------
    radius : float
        Radius across the axis R [m] (only for the Hertz half-width and pressure of
        each slice, b = sqrt(4 R q/(pi E*)), p = 2q/(pi b)).
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa]; steel only (the constant is empirical).
    profile : Profile or str or None
        Profile drop (None: straight) [-].
    depth, force : float
        Exactly one: depth d [m] or force F [N].
    tilt : float or None
        Tilt theta [rad] (sign as the coupled model: positive loads +x); with `force`,
        None solves for zero moment.
    n_slices : int
        n >= 30 as the standard asks [-] (default 30).

    Returns
    -------
    RollerSolution
        With method ``"ISO/TS 16281 slicing"``; ``p_max`` is the largest slice pressure
        (the method has no edge peak; ``edge_loaded`` still says if an end is loaded).

    Raises
    ------
    OutOfRangeError
        Non-steel E*, n < 30, no contact, bad input.

    Notes
    -----
    Valid for steel on steel (E* within 10 % of 115.38 GPa), |theta| < 0.1 rad. The
    slices do not interact: no edge peaks, and a crowned roller's deflection differs
    from exact Hertz (measured in tests/test_roller.py). The tilt sign follows this
    module (positive theta brings the +x end closer); the standard writes the
    misalignment term with its own sign convention.

    Examples
    --------
    A straight steel roller: uniform deflection, so the whole-roller formula
    (3.153 um at 1 kN, L = 10 mm):

    >>> s = iso_slicing(5e-3, 10e-3, 115.38e9, force=1e3)
    >>> f"{s.depth * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    ISO/TS 16281:2008 (slicing method); Palmgren (1959).
    """
    from .classical import STEEL_ESTAR_RANGE, _STEEL_HINT
    R = float(check_positive("radius", radius, "m"))
    L = float(check_positive("length", length, "m"))
    E = float(check_positive("estar", estar, "Pa"))
    STEEL_ESTAR_RANGE.check(E, hint=_STEEL_HINT)
    n = check_interval("n_slices", n_slices, ISO_MIN_SLICES, N_SLICES.high,
                       hint="ISO/TS 16281 asks for at least 30 slices").item()
    n = int(n)
    prof = _profile(profile, R, L, E)
    w = L / n
    x = -L / 2 + w * (np.arange(n) + 0.5)
    P = _drop_at(prof, L, x)
    if (depth is None) == (force is None):
        raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                              "exactly one of depth, force")

    def d_first(th):
        return float(np.min(P - x * math.tan(th)))

    if depth is not None:
        th = 0.0 if tilt is None else TILT_RANGE.check(tilt).item()
        d0 = d_first(th)
        d = check_interval("depth", depth, d0, np.inf, low_open=True, high_open=True,
                           unit="m", hint=f"no contact at or below {d0:.6g} m").item()
    else:
        from scipy.optimize import brentq
        F0 = float(check_positive("force", force, "N"))

        def depth_at(th):
            d0 = d_first(th)
            hi = 1e-9 * L
            while _iso_state(P, x, L, E, n, d0 + hi, th)[1] < F0:
                hi *= 4
            return brentq(lambda e: _iso_state(P, x, L, E, n, d0 + e, th)[1] - F0,
                          0.0, hi, xtol=1e-15 * L, rtol=1e-14, maxiter=200) + d0

        if tilt is not None:
            th = TILT_RANGE.check(tilt).item()
        else:
            def moment(th):
                return _iso_state(P, x, L, E, n, depth_at(th), th)[2]
            m0 = moment(0.0)
            if m0 == 0.0:
                th = 0.0
            else:
                # M increases with theta at constant F; bracket the root
                step = -math.copysign(1e-6, m0)
                while moment(step) * m0 > 0:
                    step *= 4
                    if abs(step) >= TILT_RANGE.high:
                        raise OutOfRangeError("force", F0, "a load with a zero-moment tilt "
                                              "below 0.1 rad", unit="N")
                th = brentq(moment, min(0.0, step), max(0.0, step), xtol=1e-15,
                            rtol=1e-13, maxiter=200)
        d = depth_at(th)
    Q, F, M, K = _iso_state(P, x, L, E, n, d, th)
    q = Q / w
    b = np.sqrt(4 * R * q / (math.pi * E))
    p = np.where(q > 0, 2 * q / (math.pi * np.where(b > 0, b, 1.0)), 0.0)
    start, stop, lo_edge, hi_edge = _contact_extent(x, Q, w, L)
    edge = {(True, True): "both", (True, False): "-x", (False, True): "+x"}.get(
        (lo_edge, hi_edge))
    pm, xm = _peak(x, p)
    msg = ("largest slice pressure of uncoupled 2D Hertz slices (ISO/TS 16281); the "
           "method has no edge peak")
    if edge is not None:
        msg += f"; the contact reaches the roller end ({edge}), where the true pressure " \
               "is singular"
    return RollerSolution(
        depth=float(d), tilt=float(th), force=F, moment=M, stiffness=float(K[0, 0]),
        tilt_stiffness=float(K[1, 1]), stiffness_matrix=K, x=x, q=q, half_width=b,
        pressure=p, p_max=pm, x_at_p_max=xm, contact_start=start, contact_end=stop,
        contact_length=stop - start, edge_loaded=edge is not None, edge=edge,
        message=msg, method="ISO/TS 16281 slicing", n_slices=n)


# --------------------------------------------------------------------------------------
# The two as ContactModels (force(depth), depth(force), stiffness(depth) at a fixed tilt)
# --------------------------------------------------------------------------------------
def _each(values, fn):
    """fn(one value) over an array of values, same shape (one slice solve per value)."""
    v = np.asarray(values, dtype=float)
    res = np.array([fn(float(e)) for e in v.ravel()]).reshape(v.shape)
    return out(res)


class _SolvedRoller(ContactModel):
    """The contact law of a roller model from its solutions (``at_depth``,
    ``at_force`` returning :class:`RollerSolution`): one solve per value, each giving
    force, depth and stiffness together. Subclasses set :attr:`axial_profile` and
    :attr:`n_slices`, and name themselves with ``_name`` and ``_slices``."""

    _name = ""
    _slices = "slices"

    def __init__(self, radius, length, estar, tilt=0.0):
        super().__init__(radius, length, estar)
        self.tilt = TILT_RANGE.check(tilt).item()

    @property
    def label(self):
        s = f"{self._name} ({self.axial_profile.label}"
        if self.tilt:
            s += f", tilt {self.tilt * 1e3:.4g} mrad"
        return s + f", {self.n_slices} {self._slices})"

    def force(self, depth):
        return _each(depth, lambda d: self.at_depth(d).force)

    def depth(self, force):
        F = check_positive("force", force, "N")
        return _each(F, lambda f: self.at_force(f).depth)

    def stiffness(self, depth):
        return _each(depth, lambda d: self.at_depth(d).stiffness)

    def stiffness_at_force(self, force):
        F = check_positive("force", force, "N")
        return _each(F, lambda f: self.at_force(f).stiffness)


@register
class ProfiledRollerModel(_SolvedRoller):
    """A profiled, tilted roller as a contact law: coupled slices at a fixed tilt.

    .. math:: F(d) = \\sum_k q_k(d, \\theta)\\,w, \\qquad k(d) = \\partial F/\\partial d

    Parameters
    ----------
    radius : float
        Radius across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    profile : Profile or str or None, optional
        Profile drop or spec (None: straight) [-].
    tilt : float, optional
        Tilt theta [rad], held fixed (default 0).
    n_slices : int, optional
        Number of slices [-] (default 100).

    Notes
    -----
    The roller's profile drop is :attr:`axial_profile` (``profile()`` is the
    ContactModel's MDR profile, which this model does not have).
    ``depth`` is the depth d of the roller point x = 0 (as in :class:`RollerSolution`);
    it must exceed the first-contact depth min_x(P - theta x), which is negative for a
    tilted roller. :meth:`at_depth` and :meth:`at_force` return the full
    :class:`RollerSolution` (moment, q(x), peak pressure, edge loading). Validity and
    accuracy as :class:`ProfiledRoller`.

    Examples
    --------
    >>> m = ProfiledRollerModel(10e-3, 20e-3, 115.385e9, profile="circular:Rc=0.5")
    >>> f"{m.depth(1000.0) * 1e6:.2f} um", m.key
    ('7.02 um', 'profiled-roller')

    References
    ----------
    See :mod:`linecontact.roller`.
    """

    key = "profiled-roller"
    no_profile_reason = ("a coupled-slice solution of a profiled roller, not a "
                         "plane MDR contact; its axial drop is axial_profile")

    _name = "Profiled roller"
    _slices = "coupled slices"

    def __init__(self, radius, length, estar, profile=None, tilt=0.0, n_slices=100):
        super().__init__(radius, length, estar, tilt)
        self.roller = ProfiledRoller(self.radius, self.length, self.estar, profile,
                                     n_slices=n_slices)
        self.axial_profile = self.roller.profile
        self.n_slices = self.roller.n_slices

    @property
    def provenance(self):
        return {"model": self.label, "method": "coupled slices with Hertz strips "
                "(linecontact.roller)", "profile": self.axial_profile.provenance,
                "tilt_rad": self.tilt, "n_slices": self.n_slices}

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m] and this model's tilt."""
        return self.roller.at_depth(depth, self.tilt)

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N] and this model's tilt."""
        return self.roller.at_force(force, self.tilt)



@register
class ISOSlicingModel(_SolvedRoller):
    """ISO/TS 16281 slicing of a profiled, tilted roller as a contact law (steel only).

    .. math:: F(d) = \\sum_k \\frac{c}{n}\\,(d + x_k\\tan\\theta - P(x_k))_+^{10/9}

    Parameters
    ----------
    radius, length : float
        R, L [m].
    estar : float
        E* [Pa] (steel only).
    profile : Profile or str or None, optional
        Profile drop or spec [-].
    tilt : float, optional
        Tilt theta [rad] (default 0).
    n_slices : int, optional
        n >= 30 [-] (default 30).

    Notes
    -----
    See :func:`iso_slicing`. Valid for steel on steel only.

    Examples
    --------
    >>> m = ISOSlicingModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    ISO/TS 16281:2008.
    """

    key = "iso16281-slicing"
    no_profile_reason = "uncoupled slices, each with the empirical ISO/TS 16281 law"

    _name = "ISO/TS 16281 slicing"

    def __init__(self, radius, length, estar, profile=None, tilt=0.0, n_slices=30):
        super().__init__(radius, length, estar, tilt)
        self.n_slices = n_slices
        self.axial_profile = _profile(profile, self.radius, self.length, self.estar)

    @property
    def provenance(self):
        return {"model": self.label, "method": "ISO/TS 16281:2008 slicing, uncoupled "
                "slices", "profile": self.axial_profile.provenance, "tilt_rad": self.tilt}

    def check_applicable(self):
        from .classical import STEEL_ESTAR_RANGE, _STEEL_HINT
        STEEL_ESTAR_RANGE.check(self.estar, hint=_STEEL_HINT)

    def _solve(self, **kw):
        return iso_slicing(self.radius, self.length, self.estar, self.axial_profile,
                           tilt=self.tilt, n_slices=self.n_slices, **kw)

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m]."""
        return self._solve(depth=depth)

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N]."""
        return self._solve(force=force)

