r"""Viscoelastic normal contact of any model by the correspondence principle.

A linear viscoelastic half-space is described by the relaxation function
:math:`E^*(t)` of its effective modulus (a Prony series, the standard linear solid
being its one-term case) or by the creep function :math:`J^*(t)`, related by the
Volterra equation :math:`\int_0^t E^*(t-s)\,dJ^*(s) = 1`. For any shape with the
elastic law :math:`F = E^* F_1(d)` (F1 the law at unit modulus: the model's
F(d)/E*), Lee & Radok (1960) give, while the contact area does not shrink,

.. math::

    F(t) = \int_{0^-}^t E^*(t-t')\,\frac{d}{dt'}F_1\bigl(d(t')\bigr)\,dt'
    \quad\text{(prescribed depth)},\qquad
    F_1\bigl(d(t)\bigr) = \int_{0^-}^t J^*(t-t')\,\frac{dF}{dt'}\,dt'
    \quad\text{(prescribed force: creep)}.

Both integrals are evaluated by a recursive exponential update, one step per sample
and per Prony term. The prescribed history (the depth, or the force) is taken linear
between the samples, and each step's integral is exact for it: for the force (creep)
in closed form; for the depth, whose law F1(d) is not linear, by a product
integration of the exponential against a polynomial interpolant of F1 on pieces
graded towards d = 0, where F1 is singular (to about 1e-12 for an analytic law,
from the first sample on; a linear interpolation of F1(d(t)) there would miss an O(1)
fraction of every Prony term whose time is not long against the step). A step at the
first sample is exact too. The history is zero before the first time and jumps to
its first value there.

Unloading
---------
When the contact shrinks (the depth decreases) the correspondence principle no longer
holds: the stress under a receding contact edge remembers the earlier, larger contact.
Ting (1966) solved this for axisymmetric indenters (the MDR reproduces it for those),
not for a finite roller. Here a decreasing depth is refused (``unloading="raise"``,
the default) or, on request (``unloading="warn"``), the Lee-Radok integral is
continued with a :class:`RuntimeWarning` naming the first time the contact shrinks:
from there on the values are Lee-Radok's, not the true ones.

Moduli here are those of the effective modulus: for a rigid roller on a viscoelastic
body with a constant Poisson ratio nu, :math:`E^*(t) = E(t)/(1-\nu^2)`
(:meth:`PronySeries.scaled`).

References
----------
.. [1] E. H. Lee, J. R. M. Radok, The contact problem for viscoelastic bodies, J. Appl.
   Mech. 27 (1960) 438-444.
.. [2] T. C. T. Ting, The contact stresses between a rigid indenter and a viscoelastic
   half-space, J. Appl. Mech. 33 (1966) 845-854.
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 6.5.
.. [4] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapter 6.
"""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

from ._numerics import out
from .checks import check_interval, check_positive
from .errors import OutOfRangeError, UnknownNameError

__all__ = [
    "PronySeries",
    "StandardLinearSolid",
    "read_prony_series",
    "force_history",
    "creep_depth",
    "step_creep_depth",
    "effective_relaxation",
]


class PronySeries:
    r"""Relaxation function of the effective modulus as a Prony series.

    .. math::
        E^*(t) = E_\infty + \sum_i E_i\,e^{-t/\tau_i}, \qquad
        J^*(t) = \frac{1}{E_\infty} - \sum_k c_k\,e^{-t/\lambda_k}

    The creep function is the exact solution of the Volterra equation
    :math:`\int_0^t E^*(t-s)\,dJ^*(s) = 1`: in Laplace space
    :math:`\bar J(s) = 1/(s\,h(s))` with :math:`h(s) = s\bar E(s) = E_\infty + \sum_i
    E_i s/(s + 1/\tau_i)`; h has one real root :math:`-1/\lambda_k` below each
    :math:`-1/\tau_i` (h decreases between its poles), found by Brent's method, and
    :math:`c_k = \lambda_k / h'(-1/\lambda_k)` are the residues. The retardation
    times :math:`\lambda_k` interlace the relaxation times, and
    :math:`J^*(0) = 1/E_0`, :math:`E_0 = E_\infty + \sum E_i`.

    Parameters
    ----------
    long_term : float
        Long-term (relaxed) modulus E_inf > 0 [Pa].
    moduli : array_like
        Prony moduli E_i > 0, by keyword only [Pa].
    times : array_like
        Relaxation times tau_i > 0, distinct, by keyword only [s].

    Notes
    -----
    Valid for 0 < E_inf < inf, E_i > 0, 0 < tau_i < inf distinct, t >= 0. A fluid
    (E_inf = 0) is refused: its creep is unbounded. The two lists are keyword-only
    (both are lists of positive numbers, so a swap cannot be caught by their type),
    and lists that look swapped are refused: every modulus below
    ``SWAP_MODULUS * E_inf`` (the series would relax by less than 0.01 % per term:
    numbers of the size of times) while the longest time is at least
    ``SWAP_TIME * E_inf`` in numbers (times in the range of the moduli).

    Examples
    --------
    >>> p = PronySeries(1e9, moduli=[2e9, 1e9], times=[0.1, 10.0])
    >>> f"{p.instantaneous / 1e9:.1f} GPa", f"{p.relaxation(1.0) / 1e9:.4f} GPa"
    ('4.0 GPa', '1.9049 GPa')
    >>> f"{p.creep(0.0) * 1e9:.4f} /GPa", f"{p.creep(1e6) * 1e9:.4f} /GPa"
    ('0.2500 /GPa', '1.0000 /GPa')

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 6.5; E. H. Lee, J. R. M. Radok,
    J. Appl. Mech. 27 (1960) 438-444.
    """

    #: True for the effective modulus E*(t) of a pair of bodies as built by
    #: :func:`effective_relaxation` (a body's E(t) with its 1 - nu^2 and the
    #: counter-body's compliance); False for a series as typed, which may be a body's
    #: own E(t) (what ``AdhesiveContact.viscoelastic_limit`` refuses to guess).
    effective = False

    #: Swapped lists (see Notes): the largest modulus below this fraction of E_inf
    #: [-] while the longest time is at least ``SWAP_TIME * E_inf`` [s/Pa].
    SWAP_MODULUS = 1e-4
    SWAP_TIME = 1e-2

    def __init__(self, long_term, *, moduli, times):
        self._set(long_term, moduli, times, swap_check=True)

    @classmethod
    def _derived(cls, long_term, moduli, times):
        """A series computed from a checked one (scaled, in series): the same checks
        but the swap heuristic, which is for lists typed by a user."""
        series = PronySeries.__new__(PronySeries)
        series._set(long_term, moduli, times, swap_check=False)
        return series

    def _set(self, long_term, moduli, times, swap_check):
        self.long_term = float(_one(check_positive("long_term", long_term, "Pa"),
                                    "long_term"))
        E = np.atleast_1d(np.asarray(moduli, dtype=float))
        tau = np.atleast_1d(np.asarray(times, dtype=float))
        if E.ndim != 1 or E.shape != tau.shape:
            raise OutOfRangeError("moduli", f"{E.size} values for {tau.size} times",
                                  "one modulus per relaxation time")
        check_positive("moduli", E, "Pa")
        check_positive("times", tau, "s")
        if swap_check and (E.max() < self.SWAP_MODULUS * self.long_term
                and tau.max() >= self.SWAP_TIME * self.long_term):
            raise OutOfRangeError(
                "moduli", float(E.max()),
                f"[{self.SWAP_MODULUS * self.long_term:.6g}, inf) Pa for the largest "
                f"term with E_inf = {self.long_term:.6g} Pa", unit="Pa",
                hint=f"the moduli look like times and the times (up to {tau.max():.6g}"
                     " s) like moduli: swapped lists? give moduli=[Pa] and times=[s]")
        if np.unique(tau).size != tau.size:
            raise OutOfRangeError("times", "repeated values", "distinct relaxation times",
                                  hint="merge terms with the same time")
        order = np.argsort(tau)
        self.moduli = E[order]
        self.times = tau[order]
        self._creep = None

    @property
    def instantaneous(self):
        """Instantaneous (glassy) modulus E_0 = E_inf + sum E_i [Pa]."""
        return self.long_term + float(np.sum(self.moduli))

    def scaled(self, factor):
        """The same series times `factor` [-] (e.g. 1/(1 - nu^2) for E -> E*)."""
        f = float(_one(check_positive("factor", factor), "factor"))
        return PronySeries._derived(self.long_term * f, self.moduli * f, self.times)

    def in_series(self, compliance):
        r"""This modulus in series with an elastic compliance b [1/Pa] (0: unchanged).

        In Laplace space the compliances add, :math:`1/h^*(s) = 1/h(s) + b`, so
        :math:`h^* = h/(1 + b h)`: a Prony series again, long-term modulus
        :math:`E_\infty/(1 + b E_\infty)`, one relaxation rate in each interval right
        of each of h's poles, where :math:`h(s) = -1/b` (Brent's method), moduli
        :math:`E'_k = \lambda_k/(b^2 h'(-1/\lambda_k))`. A one-term series has the
        closed form :math:`\tau' = \tau (1 + b E_0)/(1 + b E_\infty)`.
        """
        b = float(_one(check_interval("compliance", compliance, 0.0, np.inf,
                                      high_open=True, unit="1/Pa"), "compliance"))
        if b == 0.0:
            return self
        Einf = self.long_term / (1.0 + b * self.long_term)
        if self.times.size == 1:
            E0 = self.instantaneous / (1.0 + b * self.instantaneous)
            tau = self.times[0] * (1.0 + b * self.instantaneous) / (
                1.0 + b * self.long_term)
            return PronySeries._derived(Einf, [E0 - Einf], [tau])
        from scipy.optimize import brentq

        a = 1.0 / self.times[::-1]            # relaxation rates, increasing
        E = self.moduli[::-1]

        def g(x):                             # h(-x) + 1/b, decreasing between poles
            return self.long_term + np.sum(E * x / (x - a)) + 1.0 / b

        def dh(x):                            # h'(s) at s = -x
            return np.sum(E * a / (a - x) ** 2)

        lows = np.concatenate([[0.0], a[:-1]])
        rates = np.array([brentq(g, lo + 1e-14 * hi if lo else 0.0, hi - 1e-14 * hi,
                                 xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)
                          for lo, hi in zip(lows, a)])
        moduli = np.array([1.0 / (x * b * b * dh(x)) for x in rates])
        return PronySeries._derived(Einf, moduli, 1.0 / rates)

    def relaxation(self, time):
        """Relaxation function E*(t) [Pa] at t >= 0 [s]."""
        t = check_interval("time", time, 0.0, np.inf, high_open=True, unit="s")
        terms = self.moduli * np.exp(-t[..., None] / self.times)
        return out(self.long_term + np.sum(terms, axis=-1))

    @property
    def creep_terms(self):
        """(1/E_inf [1/Pa], c_k [1/Pa], lambda_k [s]) of J*(t) = 1/E_inf - sum c_k e^(-t/lambda_k)."""
        if self._creep is None:
            self._creep = self._invert()
        return self._creep

    def _invert(self):
        from scipy.optimize import brentq

        a = 1.0 / self.times[::-1]            # relaxation rates, increasing
        E = self.moduli[::-1]
        Einf = self.long_term

        def h(x):                             # h(-x) for x > 0, decreasing between poles
            return Einf + np.sum(E * x / (x - a))

        def dh(x):                            # h'(s) at s = -x
            return np.sum(E * a / (a - x) ** 2)

        rates = []
        lows = np.concatenate([[0.0], a[:-1]])
        for lo, hi in zip(lows, a):
            eps = 1e-14 * hi
            rates.append(brentq(h, lo + eps if lo else 0.0, hi - eps, xtol=1e-300,
                                rtol=4 * np.finfo(float).eps, maxiter=500))
        rates = np.array(rates)
        c = np.array([1.0 / (x * dh(x)) for x in rates])
        return 1.0 / Einf, c[::-1], 1.0 / rates[::-1]     # retardation times increasing

    def creep(self, time):
        """Creep function J*(t) [1/Pa] at t >= 0 [s] (exact inversion, see the class)."""
        t = check_interval("time", time, 0.0, np.inf, high_open=True, unit="s")
        jinf, c, lam = self.creep_terms
        return out(jinf - np.sum(c * np.exp(-t[..., None] / lam), axis=-1))

    def __repr__(self):
        return (f"<{type(self).__name__}: E_inf = {self.long_term:g} Pa, "
                f"{self.moduli.size} term(s), E_0 = {self.instantaneous:g} Pa>")


class StandardLinearSolid(PronySeries):
    r"""Standard linear solid (Zener): one Prony term, creep in closed form.

    .. math::
        E^*(t) = E_\infty + (E_0 - E_\infty)\,e^{-t/\tau}, \qquad
        J^*(t) = \frac{1}{E_\infty} - \left(\frac{1}{E_\infty} - \frac{1}{E_0}\right)
                 e^{-t/\tau_r}, \quad \tau_r = \tau\,\frac{E_0}{E_\infty}

    Parameters
    ----------
    instantaneous : float
        Instantaneous modulus E_0 [Pa].
    long_term : float
        Long-term modulus E_inf, 0 < E_inf < E_0 [Pa].
    tau : float
        Relaxation time tau > 0 (at constant strain) [s].

    Notes
    -----
    Valid for 0 < E_inf < E_0 < inf and 0 < tau < inf. The creep (retardation) time
    tau_r = tau E_0/E_inf is longer than the relaxation time.

    Examples
    --------
    POM-like effective moduli, 3 GPa instantaneous, 1 GPa long-term, tau = 10 s:

    >>> m = StandardLinearSolid(3e9, 1e9, 10.0)
    >>> f"{m.retardation_time:.0f} s", f"{m.creep(30.0) * 1e9:.4f} /GPa"
    ('30 s', '0.7547 /GPa')

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 6.5 (eq. 6.49 ff.).
    """

    def __init__(self, instantaneous, long_term, tau):
        E0 = float(_one(check_positive("instantaneous", instantaneous, "Pa"),
                        "instantaneous"))
        Einf = float(_one(check_positive("long_term", long_term, "Pa"), "long_term"))
        if not Einf < E0:
            raise OutOfRangeError("long_term", Einf, f"(0, {E0:.6g}) Pa", unit="Pa",
                                  hint="the long-term modulus must be below the "
                                       "instantaneous one (equal: an elastic body)")
        self._set(Einf, [E0 - Einf], [tau], swap_check=False)  # named scalars: no swap
        self.tau = float(self.times[0])

    def scaled(self, factor):
        """The same solid with both moduli times `factor` [-] (E -> E* = E/(1 - nu^2))."""
        f = float(_one(check_positive("factor", factor), "factor"))
        return StandardLinearSolid(self.instantaneous * f, self.long_term * f, self.tau)

    @property
    def retardation_time(self):
        """Creep time tau_r = tau E_0/E_inf [s]."""
        return self.tau * self.instantaneous / self.long_term

    def creep(self, time):
        """J*(t) [1/Pa], closed form, t >= 0 [s]."""
        t = check_interval("time", time, 0.0, np.inf, high_open=True, unit="s")
        j0, jinf = 1.0 / self.instantaneous, 1.0 / self.long_term
        return out(jinf - (jinf - j0) * np.exp(-t / self.retardation_time))

    @property
    def creep_terms(self):
        j0, jinf = 1.0 / self.instantaneous, 1.0 / self.long_term
        return jinf, np.array([jinf - j0]), np.array([self.retardation_time])


def _one(v, name):
    if np.ndim(v):
        raise OutOfRangeError(name, f"an array of shape {np.shape(v)}", "a single number")
    return v


def read_prony_series(path, long_term=None):
    r"""Read a Prony series from a CSV file with columns ``tau_s`` and ``E_Pa``.

    .. math:: E(t) = E_\infty + \sum_i E_i\,e^{-t/\tau_i}

    File format: optional ``# key: value`` comment lines (among them, optionally,
    ``# E_inf: VALUE``), then a header row naming the columns ``tau_s`` and
    ``E_Pa`` (other columns ignored, case-insensitive), then one row per term. Every
    value follows the calculator's input rule (:func:`linecontact._units.parse_quantity`):
    a number with at most one unit name, bare numbers in SI (s, Pa): ``1e9``,
    ``1 GPa`` and ``1000MPa`` are the same E_inf; a decimal comma, an expression, a
    non-finite or non-positive value is refused, never misread.

    Parameters
    ----------
    path : path-like
        The CSV file.
    long_term : float, optional
        Long-term modulus E_inf, needed if the file has no ``# E_inf:`` line (if
        both are given they must agree to 1e-12) [Pa].

    Returns
    -------
    PronySeries

    Raises
    ------
    OutOfRangeError
        Missing or non-positive values, repeated times, no E_inf.

    Notes
    -----
    Valid for files whose terms satisfy the :class:`PronySeries` ranges
    (tau_s > 0 distinct, E_Pa > 0, E_inf > 0).

    Examples
    --------
    >>> import os, tempfile
    >>> text = "# material: test\n# E_inf: 1e9\ntau_s,E_Pa\n0.1,2e9\n10,1e9\n"
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = os.path.join(d, "prony.csv")
    ...     _ = open(p, "w").write(text)
    ...     s = read_prony_series(p)
    >>> f"{s.instantaneous / 1e9:.1f} GPa", s.times.tolist()
    ('4.0 GPa', [0.1, 10.0])

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 6.5.
    """
    path = Path(path)
    lines = path.read_text(encoding="utf-8-sig").splitlines()
    meta, body = {}, []
    for line in lines:
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            key, sep, value = s[1:].partition(":")
            if sep:
                meta[key.strip().lower()] = value.strip()
            continue
        body.append(s)
    if not body:
        raise OutOfRangeError("prony file", str(path), "a header row and terms")
    names = [c.strip().lower() for c in body[0].split(",")]
    for need in ("tau_s", "e_pa"):
        if need not in names:
            raise OutOfRangeError("prony file", str(path),
                                  "columns tau_s and E_Pa (header row)",
                                  hint=f"the header row is {body[0]!r}")
    it, ie = names.index("tau_s"), names.index("e_pa")
    tau, E = [], []
    for k, row in enumerate(body[1:], start=1):
        cells = [c.strip() for c in row.split(",")]
        if max(it, ie) >= len(cells):
            raise OutOfRangeError("prony file", row, "a value under tau_s and E_Pa in "
                                  "every row", where=f"data row {k}")
        tau.append(_file_value("tau_s", cells[it], "time", f"data row {k}"))
        E.append(_file_value("E_Pa", cells[ie], "pressure", f"data row {k}"))
    if not tau:
        raise OutOfRangeError("prony file", str(path), "at least one term")
    file_einf = None
    for key in ("e_inf", "e_inf_pa"):
        if key in meta:
            file_einf = _file_value("E_inf", meta[key], "pressure", "the '# E_inf' line")
    if long_term is None and file_einf is None:
        raise OutOfRangeError("long_term", "missing", "(0, inf) Pa",
                              hint=f"give it, or write '# E_inf: VALUE' in {path}")
    if long_term is not None and file_einf is not None and not math.isclose(
            float(long_term), file_einf, rel_tol=1e-12):
        raise OutOfRangeError("long_term", float(long_term), f"{file_einf:g} Pa (the "
                              f"file's E_inf)", unit="Pa")
    return PronySeries(long_term if long_term is not None else file_einf,
                       moduli=E, times=tau)


def _file_value(name, text, kind, where):
    """A value of a Prony file in SI by the calculator's input rule (a number with one
    unit name, bare = SI), or OutOfRangeError naming it, its place and the rule."""
    from ._units import InputError, parse_quantity

    try:
        return parse_quantity(name, text, kind)
    except InputError as exc:
        raise OutOfRangeError(name, text, exc.valid, hint=exc.reason, where=where) from None


# --------------------------------------------------------------------------------------
# hereditary integrals
# --------------------------------------------------------------------------------------
def _times(time):
    t = np.asarray(time, dtype=float)
    if t.ndim != 1 or t.size < 1:
        raise OutOfRangeError("time", f"an array of shape {t.shape}",
                              "a 1D array of at least one time", unit="s")
    check_interval("time", t, 0.0, np.inf, high_open=True, unit="s")
    if np.any(np.diff(t) < 0):
        i = int(np.argmax(np.diff(t) < 0)) + 1
        raise OutOfRangeError("time", float(t[i]), f"[{t[i - 1]:.6g}, inf) s", unit="s",
                              where=f"element [{i}]", hint="times must not decrease")
    return t


def _hereditary(kinf, k, theta, t, g, inc=None):
    """y(t_n) = int_{t0-}^{t_n} K(t_n - s) dg(s), K = kinf + sum k_i exp(-t/theta_i),
    g = 0 before t_0 (a step there).

    Per term the memory h_i obeys h_i(t_n) = e^{-x} h_i(t_{n-1}) + inc_i,
    x = dt/theta_i, where inc_i is the integral over the step. Without `inc` g is
    piecewise linear between samples: inc_i = k_i dg (1 - e^{-x})/x (a step where
    dt = 0); `inc` (shape (n - 1, terms)) gives the steps' integrals for any other
    shape of g (:func:`_ramp_increments`). On an even time grid the recursion is a
    first-order linear filter (scipy.signal.lfilter).
    """
    k = np.asarray(k, dtype=float)
    theta = np.asarray(theta, dtype=float)
    dt = np.diff(t)[:, None]
    x = dt / theta
    decay = np.exp(-x)
    if inc is None:
        dg = np.diff(g)[:, None]
        with np.errstate(invalid="ignore", divide="ignore"):
            gain = np.where(x > 0, -np.expm1(-x) / np.where(x > 0, x, 1.0), 1.0)
        inc = k * dg * gain
    h = np.empty((t.size, k.size))
    h[0] = k * g[0]
    if t.size > 1 and np.all(dt == dt[0]):
        from scipy.signal import lfilter

        for i in range(k.size):
            a = decay[0, i]
            b = np.concatenate([[h[0, i]], inc[:, i]])
            h[:, i] = lfilter([1.0], [1.0, -a], b)
    else:
        for n in range(1, t.size):
            h[n] = decay[n - 1] * h[n - 1] + inc[n - 1]
    return kinf * g + h.sum(axis=1)


class _ProductRule:
    """Product integration of int_0^1 e^{-x(1-u)} G'(u) du for every x >= 0.

    G is interpolated by the polynomial P of degree m - 1 through m Chebyshev-Lobatto
    points of [0, 1] (both ends included, so P(1) - P(0) = G(1) - G(0) exactly: a
    linear G is integrated exactly) and the integral of P' against the exponential is
    evaluated without further error: for x <= 16 by Gauss-Legendre with 24 points (the
    exponential's remainder is below 1e-30 there), for x > 16 by repeated integration
    by parts, which for a polynomial ends after m - 1 terms:
    sum_j (-1)^j [P^(j+1)(1) - e^{-x} P^(j+1)(0)] / x^(j+1). The only error left is
    P - G; for an analytic G whose nearest singularity lies D interval lengths from
    the interval, Chebyshev interpolation converges as rho^-m, rho = 1 + 4D +
    sqrt((1 + 4D)^2 - 1): rho = 13.9 at D = 3 (m = 12: 2e-14) and rho = 242 at D = 30
    (m = 6: 5e-15).
    """

    Q, X0 = 24, 16.0

    def __init__(self, m):
        from numpy.polynomial import chebyshev as C

        self.m = m
        z = -np.cos(np.pi * np.arange(m) / (m - 1))        # Lobatto points of [-1, 1]
        self.u = (z + 1) / 2
        inv = np.linalg.inv(C.chebvander(z, m - 1))          # values -> coefficients
        zq, wq = np.polynomial.legendre.leggauss(self.Q)
        self.uq, self.wq = (zq + 1) / 2, wq / 2
        eye = np.eye(m)
        # d/du = 2 d/dz on u = (z + 1)/2
        self.dq = np.array([2 * C.chebval(zq, C.chebder(e)) for e in eye]).T @ inv
        self.d1 = np.array([[2.0**j * C.chebval(1.0, C.chebder(e, j)) for e in eye]
                            for j in range(1, m)]) @ inv
        self.d0 = np.array([[2.0**j * C.chebval(-1.0, C.chebder(e, j)) for e in eye]
                            for j in range(1, m)]) @ inv

    def integrals(self, G, x):
        """int_0^1 e^{-x(1-u)} P'(u) du for pieces G (p, m) and rates x (p,)."""
        out = np.empty(x.shape)
        small = x <= self.X0
        if np.any(small):
            w = self.wq * np.exp(-np.outer(x[small], 1.0 - self.uq))
            out[small] = np.sum(w * (G[small] @ self.dq.T), axis=1)
        big = ~small
        if np.any(big):
            xb = x[big][:, None]
            j = np.arange(self.m - 1)
            sign = np.where(j % 2, -1.0, 1.0)
            at1, at0 = G[big] @ self.d1.T, G[big] @ self.d0.T
            out[big] = np.sum(sign * (at1 - np.exp(-xb) * at0) / xb ** (j + 1), axis=1)
        return out


#: (rule, pieces it serves): m = 12 points for a piece whose distance from d = 0 is
#: 3 to 30 of its lengths, 6 points beyond (the errors of :class:`_ProductRule`).
_RULES = {}
_NEAR, _FAR = 3.0, 30.0


def _rule(m):
    if m not in _RULES:
        _RULES[m] = _ProductRule(m)
    return _RULES[m]


def _ramp_increments(model, t, d, k, theta):
    """Each step's integral int_{t_{n-1}}^{t_n} k_i e^{-(t_n - s)/theta_i} dF1(d(s))
    for a depth d(s) LINEAR between the samples (a ramp), to about 1e-12 for an
    analytic law: shape (n - 1, terms).

    F1(d) is singular at d = 0 (F1 ~ d^(3/2) for a sphere, ~ d/ln(1/d) for a line
    contact), so a linear interpolation of F1(d(s)) over a step that starts at zero
    misses an O(1) fraction of every term whose time is not long against the step
    (0.6 % of the force for a Prony series spanning decades, whatever the step). Each
    step is cut into pieces graded geometrically towards its end nearer to d = 0,
    with depth ratio 1 + 1/3 so that d = 0 stays at least 3 piece lengths from every
    piece, down to 1e-16 of the step's larger depth when it starts at zero (F1 below
    that is below rounding); each piece is integrated by :class:`_ProductRule` and
    carried to the step's end by e^{-(t_n - s_end)/theta}. A step with dt = 0 is a
    jump (k dF1); one with constant depth adds nothing.
    """
    nstep, nterm = t.size - 1, k.size
    inc = np.zeros((nstep, nterm))
    da, db, dt = d[:-1], d[1:], np.diff(t)
    jump = (dt == 0) & (da != db)
    if np.any(jump):
        inc[jump] = k * (_unit_law(model, db[jump]) - _unit_law(model, da[jump]))[:, None]
    ramp = np.flatnonzero((dt > 0) & (da != db))
    if ramp.size == 0:
        return inc
    lo, hi = np.minimum(da[ramp], db[ramp]), np.maximum(da[ramp], db[ramp])
    q = 1.0 + 1.0 / _NEAR
    floor = np.where(lo > 0, lo, hi * 1e-16)
    npieces = np.where(lo >= _NEAR * (hi - lo), 1,
                       np.maximum(1, np.ceil(np.log(hi / floor) / np.log(q)))).astype(int)
    step = np.repeat(np.arange(ramp.size), npieces)
    kk = np.arange(step.size) - np.repeat(np.cumsum(npieces) - npieces, npieces)
    upper = hi[step] * q ** -kk.astype(float)           # piece kk counted from hi
    lower = np.where(kk == npieces[step] - 1, lo[step], upper / q)
    rising = (db > da)[ramp][step]
    start, end = np.where(rising, lower, upper), np.where(rising, upper, lower)
    a, b = da[ramp][step], db[ramp][step]
    span = dt[ramp][step] / (b - a)                     # time per unit depth (signed)
    length = (end - start) * span                       # the piece's duration, > 0
    to_end = (b - end) * span                           # from the piece's end to t_n
    far = lower >= _FAR * (upper - lower)
    part = np.empty((step.size, nterm))
    for m, sel in ((12, ~far), (6, far)):
        if not np.any(sel):
            continue
        rule = _rule(m)
        nodes = start[sel, None] + np.outer(end[sel] - start[sel], rule.u)
        G = _unit_law(model, nodes.ravel()).reshape(nodes.shape)
        for i in range(nterm):
            part[sel, i] = rule.integrals(G, length[sel] / theta[i])
    part *= np.exp(-to_end[:, None] / theta)
    for i in range(nterm):
        inc[ramp, i] = k[i] * np.bincount(step, weights=part[:, i], minlength=ramp.size)
    return inc


def _unit_law(model, depth):
    check = getattr(model, "check_starts_at_zero", None)
    if check is not None:
        check()
    d = np.asarray(depth, dtype=float)
    res = np.zeros(d.shape)
    pos = d > 0
    if np.any(pos):
        res[pos] = np.asarray(model.force(d[pos])) / model.estar
    return res


def _shrinking(t, depth, unloading, what):
    if unloading not in ("raise", "warn"):
        raise UnknownNameError("unloading", unloading, ("raise", "warn"))
    dd = np.diff(depth)
    bad = dd < -1e-12 * np.maximum(np.abs(depth[1:]), np.abs(depth[:-1]))
    if not np.any(bad):
        return
    i = int(np.argmax(bad)) + 1
    msg = (f"the contact shrinks at t = {t[i]:.6g} s ({what}): the correspondence "
           "principle (Lee & Radok 1960) holds only while the contact grows; Ting's "
           "(1966) unloading solution is known for axisymmetric indenters only")
    if unloading == "raise":
        raise OutOfRangeError("depth", float(depth[i]), f"[{depth[i - 1]:.6g}, inf) m",
                              unit="m", where=f"t = {t[i]:.6g} s",
                              hint=msg + "; unloading='warn' continues with Lee-Radok")
    warnings.warn(msg + "; values from there on are Lee-Radok's, not exact",
                  RuntimeWarning, stacklevel=3)


def force_history(model, material, time, depth, *, unloading="raise"):
    r"""Force under a prescribed depth history (Lee & Radok 1960), any model.

    .. math::
        F(t) = \int_{0^-}^{t} E^*(t-t')\,\frac{d}{dt'}F_1\bigl(d(t')\bigr)\,dt',
        \qquad F_1(d) = F_{model}(d)/E^*_{model}

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model; only the shape of its law is used (its E* cancels).
    material : PronySeries
        Relaxation function E*(t) (:class:`StandardLinearSolid` or a Prony series).
    time : array_like
        Sample times t_0 <= t_1 <= ...; the depth is 0 before t_0 [s].
    depth : array_like
        Depth d at those times (same length; a single value = held constant from
        t_0, a step), linear in time between them (a ramp) [m].
    unloading : {"raise", "warn"}, optional
        A decreasing depth (shrinking contact) is refused (default) or continued by
        the Lee-Radok integral with a :class:`RuntimeWarning` (then not exact).

    Returns
    -------
    ndarray
        F(t) [N] at the sample times.

    Notes
    -----
    Valid for non-decreasing depth histories inside the model's depth range.
    Exact for a depth linear between the samples (ramps, steps and holds), from the
    first sample on: to rounding for a linear law, to about 1e-12 for any analytic
    law F1(d) (F1 is interpolated by polynomials on pieces graded geometrically
    towards d = 0, where it is singular, and each piece integrated exactly against
    the exponentials). A step and hold gives the relaxation F = F1(d) E*(t); a
    ramp of the Hertz sphere the closed form of Lee & Radok (1960) in Dawson's
    integral (tested).

    Examples
    --------
    Relaxation of a roller held at 2 um (the force follows E*(t)):

    >>> from linecontact.models import get_model
    >>> m = get_model("kunz", 5e-3, 10e-3, 1.0)
    >>> sls = StandardLinearSolid(3e9, 1e9, 10.0)
    >>> F = force_history(m, sls, [0.0, 10.0, 1e4], 2e-6)
    >>> [f"{f:.2f}" for f in F]
    ['10.50', '6.08', '3.50']

    References
    ----------
    E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444; K. L. Johnson,
    Contact Mechanics (1985), section 6.5.
    """
    t = _times(time)
    d = np.broadcast_to(np.asarray(depth, dtype=float), t.shape).astype(float)
    check_interval("depth", d, 0.0, np.inf, high_open=True, unit="m")
    _shrinking(t, d, unloading, "the prescribed depth decreases")
    g = _unit_law(model, d)
    inc = _ramp_increments(model, t, d, material.moduli, material.times)
    return _hereditary(material.long_term, material.moduli, material.times, t, g, inc)


def creep_depth(model, material, time, force, *, unloading="raise"):
    r"""Depth under a constant force or a force history (creep), any model.

    .. math::
        F_1\bigl(d(t)\bigr) = \int_{0^-}^{t} J^*(t-t')\,\frac{dF}{dt'}\,dt',
        \qquad d(t) = F_1^{-1}(\cdot)

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model; F1 = F/E* of its law, inverted by its d(F).
    material : PronySeries
        The material; its creep function J*(t) is used.
    time : array_like
        Sample times t_0 <= t_1 <= ...; the force is 0 before t_0 [s].
    force : float or array_like
        Normal force F: one value (applied at t_0 and held: creep) or one per
        sample (piecewise linear between samples) [N].
    unloading : {"raise", "warn"}, optional
        A decreasing depth (when the force drops faster than the material creeps) is
        refused (default) or continued by Lee-Radok with a :class:`RuntimeWarning`.

    Returns
    -------
    ndarray
        d(t) [m] at the sample times.

    Notes
    -----
    Valid while the depth does not decrease, forces >= 0, inside the model's depth
    range (the depth grows by up to E_0/E_inf in force-equivalent terms: the model
    must accept the force F E_model*/E_inf). Exact (to rounding) for forces piecewise
    linear between the samples (a step and hold included).

    Examples
    --------
    A rigid roller on a polymer (E*_0 = 3 GPa, E*_inf = 1 GPa, tau = 10 s) under 1 kN:

    >>> from linecontact.models import get_model
    >>> m = get_model("universal", 5e-3, 10e-3, 1e9)
    >>> d = creep_depth(m, StandardLinearSolid(3e9, 1e9, 10.0), [0.0, 30.0, 1e4], 1e3)
    >>> [f"{x * 1e6:.2f} um" for x in d]
    ['82.58 um', '168.03 um', '214.13 um']

    References
    ----------
    E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444; K. L. Johnson,
    Contact Mechanics (1985), section 6.5.
    """
    t = _times(time)
    F = np.broadcast_to(np.asarray(force, dtype=float), t.shape).astype(float)
    check_interval("force", F, 0.0, np.inf, high_open=True, unit="N")
    jinf, c, lam = material.creep_terms
    y = _hereditary(jinf, -c, lam, t, F)              # F1(d(t)) [m^2 ... per unit E*]
    y = np.maximum(y, 0.0) if unloading == "warn" else y
    d = np.zeros(t.shape)
    pos = y > 0
    if np.any(pos):
        try:
            d[pos] = model.depth(y[pos] * model.estar)
        except OutOfRangeError as exc:
            raise _left_range(model, t[pos], y[pos] * model.estar, exc) from None
    _shrinking(t, d, unloading, "the force decreases faster than the material creeps")
    return d


def _left_range(model, times, equivalent, exc):
    """The model's refusal of a creep depth, said at the first time whose
    elastic-equivalent force F1 E*_0 it refuses (earlier samples are within range)."""
    for tk, fk in zip(times.ravel(), equivalent.ravel()):
        try:
            model.depth(float(fk))
        except OutOfRangeError as one:
            hint = "; ".join(h for h in (one.hint, "the creep depth d(t) leaves the "
                                         f"model's range at t = {tk:.6g} s") if h)
            return OutOfRangeError(one.parameter, one.value, one.valid, unit=one.unit,
                                   where=f"at t = {tk:.6g} s",
                                   hint=hint)
    return exc


def step_creep_depth(model, material, force, time):
    r"""Depth at time t under a force F applied at t = 0 and held (creep), vectorised.

    .. math:: d(t) = F_1^{-1}\bigl(F\,J^*(t)\bigr)

    the closed form of Lee & Radok's creep integral for a step (any model, exact while
    the contact grows, which it does under a held force: J* increases).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model; F1 = F/E* of its law, inverted by its d(F).
    material : object
        Anything with ``creep(t)`` returning J*(t) [1/Pa], e.g. a :class:`PronySeries`.
    force : float or array_like
        Held normal force F > 0 [N].
    time : float or array_like
        Time since the load was applied, t >= 0; broadcasts with force [s].

    Returns
    -------
    float or ndarray
        d(t) [m].

    Notes
    -----
    Valid for t >= 0, F > 0 and while F E*_model J*(t) stays inside the model's force
    range (at long times the depth is that of the elastic law at E* = E_inf).

    Examples
    --------
    >>> from linecontact.models import get_model
    >>> m = get_model("universal", 5e-3, 10e-3, 1e9)
    >>> d = step_creep_depth(m, StandardLinearSolid(3e9, 1e9, 10.0), 1e3, [0.0, 30.0])
    >>> [f"{x * 1e6:.2f} um" for x in d]
    ['82.58 um', '168.03 um']

    References
    ----------
    E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444.
    """
    F = check_positive("force", force, "N")
    t = check_interval("time", time, 0.0, np.inf, high_open=True, unit="s")
    F, t = np.broadcast_arrays(F, t)
    J = np.asarray(material.creep(t), dtype=float)
    return out(np.asarray(model.depth(F * J * model.estar), dtype=float))


def effective_relaxation(body, poisson, modulus2=np.inf, poisson2=None):
    r"""Relaxation function E*(t) of the effective modulus: a viscoelastic body against an
    elastic (or rigid) one.

    .. math::

        J^*(t) = (1 - \nu_1^2)\,J_1(t) + \frac{1 - \nu_2^2}{E_2},

    the compliances adding (Li & Popov 2017, Eq. 3, with the correspondence principle
    applied to the viscoelastic body; Lee & Radok 1960), returned as the relaxation
    function of E* (:meth:`PronySeries.in_series`).

    Parameters
    ----------
    body : PronySeries
        Relaxation function E_1(t) of the viscoelastic body's Young's modulus [Pa].
    poisson : float
        Its Poisson ratio nu_1, constant in time, 0 <= nu_1 <= 0.5 [-].
    modulus2 : float, optional
        Young's modulus E_2 of the elastic counter-body, ``inf`` for a rigid one (default)
        [Pa].
    poisson2 : float, optional
        Its Poisson ratio nu_2 (needed unless rigid) [-].

    Returns
    -------
    PronySeries
        E*(t) [Pa]: its ``relaxation`` and ``creep`` give E*(t) and J*(t).

    Notes
    -----
    Valid for a constant Poisson ratio of the viscoelastic body (Lee & Radok's
    correspondence applies to E(t) only then) and 0 < E_2 <= inf.

    Examples
    --------
    A polymer (SLS, 3 GPa to 1 GPa, tau 10 s, nu 0.4) on steel:

    >>> m = effective_relaxation(StandardLinearSolid(3e9, 1e9, 10.0), 0.4, 210e9, 0.3)
    >>> f"{m.instantaneous / 1e9:.4f} GPa", f"{m.long_term / 1e9:.4f} GPa"
    ('3.5170 GPa', '1.1844 GPa')
    >>> f"{1 / m.creep(0.0) / 1e9:.4f} GPa"
    '3.5170 GPa'

    References
    ----------
    E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444; K. L. Johnson, Contact
    Mechanics (1985), section 6.5.
    """
    from .checks import POISSON_RATIO
    from .classical import MODULUS_OR_RIGID

    if not isinstance(body, PronySeries):
        raise OutOfRangeError("body", repr(body), "a linecontact.viscoelastic.PronySeries")
    nu1 = POISSON_RATIO.check(poisson, name="poisson").item()
    E2 = MODULUS_OR_RIGID.check(modulus2, name="modulus2").item()
    if np.isinf(E2):
        b = 0.0
    else:
        if poisson2 is None:
            raise OutOfRangeError("poisson2", "missing", "a number in [0, 0.5] (needed "
                                  "with a finite modulus2)")
        b = (1.0 - POISSON_RATIO.check(poisson2, name="poisson2").item() ** 2) / E2
    series = body.scaled(1.0 / (1.0 - nu1 ** 2)).in_series(b)
    series.effective = True
    return series
