r"""Hertz elliptical point contact from the two principal relative radii of curvature.

Two elastic bodies whose gap near first contact is

.. math:: h(x, y) = A x^2 + B y^2, \qquad A = \frac{1}{2 R_x},\quad B = \frac{1}{2 R_y}

(R_x, R_y the principal relative radii of curvature) touch over an ellipse of semi-axes
a (along x) and b (along y) with the Hertz pressure
:math:`p = p_0\sqrt{1 - x^2/a^2 - y^2/b^2}`. With the eccentricity
:math:`e = \sqrt{1 - b^2/a^2}` (a >= b, i.e. R_x >= R_y) and the complete elliptic
integrals K(e), E(e) of the first and second kind (Johnson 1985, section 4.2, Eq. 3.69
and 4.24-4.27):

.. math::

    \frac{B}{A} = \frac{(a/b)^2 E(e) - K(e)}{K(e) - E(e)}, \qquad
    a^3 = \frac{3 F\,[K(e) - E(e)]}{2\pi e^2 E^* A}, \qquad b = a\sqrt{1 - e^2},

    p_0 = \frac{3F}{2\pi a b}, \qquad \delta = \frac{p_0\, b\, K(e)}{E^*}, \qquad
    k = \frac{dF}{d\delta} = \frac{3F}{2\delta}.

The first equation fixes e from the ratio R_x/R_y alone; it is solved here with a
bracketing root finder (Brent) to machine precision, not with the approximate fits of
bearing texts (Hamrock & Brewe 1983). K and E come from :func:`scipy.special.ellipk`,
:func:`scipy.special.ellipkm1` and :func:`scipy.special.ellipe` (imported on first use).

A crowned roller (radius R across, crown radius Rc along its axis) on a flat is this
contact with R_x = Rc, R_y = R while the ellipse stays inside the roller (a < L/2).

References
----------
.. [1] H. Hertz, "Ueber die Beruehrung fester elastischer Koerper", J. reine angew.
   Math. 92 (1882) 156-171.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   3.5 and 4.2.
.. [3] B. J. Hamrock, D. E. Brewe, "Simplified solution for stresses and deformations",
   J. Lubrication Technology 105 (1983) 171-177 (the approximate fits not used here).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._numerics import out
from .checks import (POSITIVE_FORCE, POSITIVE_LENGTH, POSITIVE_MODULUS, Interval,
                     check_positive, document)

__all__ = ["HertzContact", "hertz_eccentricity", "hertz_contact",
           "hertz_contact_at_approach"]

#: Ratio of the two radii accepted (larger over smaller): the elliptic-integral solution
#: is evaluated to machine precision over this range (b/a down to about 1e-4).
RADIUS_RATIO = Interval("radius ratio", 1.0, 1e7, unit="")


def _special():
    from scipy import special
    return special


_SERIES_M = 1e-2
_C = [math.comb(2 * n, n) ** 2 / 16.0 ** n for n in range(12)]


def _KE(kprime):
    """K(e), E(e) with m = e^2 = 1 - k'^2: scipy, or their power series for m < 0.01
    (where K - E would lose digits): K = pi/2 sum c_n m^n, E = pi/2 sum c_n m^n/(1-2n),
    c_n = (C(2n, n)/4^n)^2, truncated at m^12 (error below 1e-24)."""
    m1 = kprime * kprime
    m = (1.0 - kprime) * (1.0 + kprime)
    if m < _SERIES_M:
        K = sum(c * m**n for n, c in enumerate(_C)) * math.pi / 2
        # K - E = pi/2 sum c_n m^n (1 - 1/(1-2n)) = pi/2 sum c_n m^n 2n/(2n-1)
        KmE = sum(c * m**n * 2 * n / (2 * n - 1) for n, c in enumerate(_C) if n) * math.pi / 2
        return K, K - KmE, KmE
    sp = _special()
    K = float(sp.ellipkm1(m1))          # K(m), accurate as m -> 1
    E = float(sp.ellipe(m))
    return K, E, K - E


def _ratio_of_axes(kprime):
    """B/A as a function of k' = b/a in (0, 1), from Johnson (1985) Eq. 4.27."""
    m = (1.0 - kprime) * (1.0 + kprime)
    if m <= 0.0:
        return 1.0
    K, E, KmE = _KE(kprime)
    # E/k'^2 - K = (E - K k'^2)/k'^2 with E - K (1 - m) = K m - (K - E)
    return (K * m - KmE) / (kprime * kprime * KmE)


def hertz_eccentricity(radius_x, radius_y):
    r"""Ratio of the semi-axes b/a and eccentricity e of a Hertz contact ellipse.

    Solves, for :math:`k' = b/a = \sqrt{1 - e^2}`,

    .. math:: \frac{R_x}{R_y} = \frac{E(e)/k'^2 - K(e)}{K(e) - E(e)}

    (Johnson 1985, Eq. 4.27 with B/A = R_x/R_y) by Brent's method on ln k'. The larger
    radius is taken as R_x, so a >= b.

    Parameters
    ----------
    radius_x : float
        Principal relative radius of curvature in the x-z plane, 0 < R_x < inf [m].
    radius_y : float
        Principal relative radius of curvature in the y-z plane, 0 < R_y < inf [m].

    Returns
    -------
    (float, float)
        b/a [-] (the smaller semi-axis over the larger) and e [-].

    Notes
    -----
    Valid for max(R_x, R_y)/min(R_x, R_y) from 1 (a circle, b/a = 1) to 1e7
    (b/a about 1e-4); the equation is solved to a relative tolerance of 1e-14 in b/a.

    Examples
    --------
    A crowned roller, R = 10 mm across, Rc = 500 mm along the axis:

    >>> k, e = hertz_eccentricity(0.5, 0.01)
    >>> f"b/a = {k:.5f}, e = {e:.5f}"
    'b/a = 0.08284, e = 0.99656'
    >>> hertz_eccentricity(0.01, 0.01)
    (1.0, 0.0)

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    rx = float(check_positive("radius_x", radius_x, "m"))
    ry = float(check_positive("radius_y", radius_y, "m"))
    ratio = RADIUS_RATIO.check(max(rx, ry) / min(rx, ry), name="radius_x/radius_y",
                               hint="a contact this slender is a line contact: use a "
                                    "line-contact model").item()
    if ratio == 1.0:
        return 1.0, 0.0
    from scipy.optimize import brentq

    # k' -> 1: B/A -> 1; k' -> 0: B/A ~ 1/(k'^2 ln(4/k')) -> inf; monotone between
    lo = math.log(1e-300 ** 0.25)

    def f(z):
        if z == 0.0:
            return 1.0 - ratio
        return _ratio_of_axes(math.exp(z)) - ratio

    z = brentq(f, lo, 0.0, xtol=1e-16, rtol=1e-15, maxiter=500)
    k = math.exp(z)
    return k, math.sqrt((1.0 - k) * (1.0 + k))


@dataclass(frozen=True)
class HertzContact:
    """The Hertz elliptical contact: semi-axes, peak pressure, approach and stiffness.

    Returned by :func:`hertz_contact` and :func:`hertz_contact_at_approach`.

    .. math:: p_0 = \\frac{3F}{2\\pi a b}, \\qquad k = \\frac{3F}{2\\delta}

    Parameters
    ----------
    force : float or ndarray
        Normal force F [N].
    a : float or ndarray
        Semi-axis along the direction of the larger radius R_x [m].
    b : float or ndarray
        Semi-axis along the direction of the smaller radius R_y [m].
    p0 : float or ndarray
        Peak (central) pressure 3F/(2 pi a b) [Pa].
    approach : float or ndarray
        Mutual approach of distant points delta [m].
    stiffness : float or ndarray
        Contact stiffness dF/d(delta) = 3F/(2 delta) [N/m].
    eccentricity : float
        e = sqrt(1 - b^2/a^2), 0 <= e < 1 [-].
    swapped : bool
        True if radius_y > radius_x was given, so that a lies along y and b along x.

    Notes
    -----
    0 < F < inf, 0 < b <= a; see :func:`hertz_contact` for the validity of the theory.

    Examples
    --------
    >>> h = hertz_contact(2000.0, 0.2, 0.01, 115.385e9)
    >>> f"{h.a * 1e3:.4f} mm, {h.b * 1e3:.4f} mm, e = {h.eccentricity:.4f}"
    '1.9825 mm, 0.2861 mm, e = 0.9895'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """

    force: object
    a: object
    b: object
    p0: object
    approach: object
    stiffness: object
    eccentricity: float
    swapped: bool = False


def _contact(F, rx, ry, E):
    swapped = ry > rx
    big, small = (ry, rx) if swapped else (rx, ry)
    k, e = hertz_eccentricity(big, small)
    A = 1.0 / (2.0 * big)
    if e == 0.0:
        # circle: K - E ~ (pi/4) e^2, so a^3 = 3 F R/(4 E*), delta = a^2/R
        a = np.cbrt(3.0 * F * big / (4.0 * E))
        K = math.pi / 2
    else:
        K, _, KmE = _KE(k)
        a = np.cbrt(3.0 * F * KmE / (2.0 * math.pi * e * e * E * A))
    b = a * k
    p0 = 3.0 * F / (2.0 * math.pi * a * b)
    delta = p0 * b * K / E
    return HertzContact(force=out(F), a=out(a), b=out(b), p0=out(p0),
                        approach=out(delta), stiffness=out(1.5 * F / delta),
                        eccentricity=e, swapped=swapped)


@document(F=POSITIVE_FORCE, R=POSITIVE_LENGTH, E=POSITIVE_MODULUS, RATIO=RADIUS_RATIO)
def hertz_contact(force, radius_x, radius_y, estar):
    r"""Hertz elliptical contact under a force: semi-axes, p0, approach, stiffness.

    .. math::
        a^3 = \frac{3 F [K(e) - E(e)]}{2\pi e^2 E^* A},\quad b = a\sqrt{1-e^2},\quad
        p_0 = \frac{3F}{2\pi a b},\quad \delta = \frac{p_0 b K(e)}{E^*},\quad
        k = \frac{3F}{2\delta}

    with A = 1/(2 R_x) and e from :func:`hertz_eccentricity`.

    Parameters
    ----------
    force : float or array_like
        Normal force F [N].
    radius_x : float
        Principal relative radius of curvature along x (for a crowned roller: the crown
        radius Rc) [m].
    radius_y : float
        Principal relative radius of curvature along y (for a crowned roller: its
        radius R, or the effective radius against a raceway) [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].

    Returns
    -------
    HertzContact
        a, b [m], p0 [Pa], approach [m], stiffness [N/m] (arrays if `force` is one).
        a lies along x unless radius_y > radius_x (then ``swapped`` is True).

    Raises
    ------
    OutOfRangeError
        Non-positive or non-finite input, or a radius ratio outside the range below.

    Notes
    -----
    Valid for %(F)s, %(R)s for both radii, %(E)s, and %(RATIO)s (larger radius over
    smaller). Linear elasticity, frictionless, a and b small against the radii, and the
    ellipse inside both bodies (for a roller: a < L/2).

    Examples
    --------
    Steel on steel (E* = 115.385 GPa), R = 10 mm, crown radius 500 mm, 1 kN:

    >>> h = hertz_contact(1000.0, 0.5, 0.01, 115.385e9)
    >>> f"a {h.a * 1e3:.3f} mm, b {h.b * 1e3:.4f} mm, p0 {h.p0 / 1e6:.0f} MPa"
    'a 2.287 mm, b 0.1895 mm, p0 1102 MPa'
    >>> f"approach {h.approach * 1e6:.2f} um"
    'approach 7.02 um'

    References
    ----------
    H. Hertz (1882); K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    F = check_positive("force", force, "N")
    rx = float(check_positive("radius_x", radius_x, "m"))
    ry = float(check_positive("radius_y", radius_y, "m"))
    E = float(check_positive("estar", estar, "Pa"))
    return _contact(F, rx, ry, E)


@document(D=POSITIVE_LENGTH, R=POSITIVE_LENGTH, E=POSITIVE_MODULUS, RATIO=RADIUS_RATIO)
def hertz_contact_at_approach(approach, radius_x, radius_y, estar):
    r"""Hertz elliptical contact at a given approach (the inverse of the force form).

    .. math:: F = F_1\,(\delta/\delta_1)^{3/2}

    where :math:`\delta_1` is the approach under F_1 = 1 N (F ~ delta^(3/2) exactly).

    Parameters
    ----------
    approach : float or array_like
        Mutual approach delta, 0 < delta < inf [m].
    radius_x, radius_y : float
        Principal relative radii of curvature [m].
    estar : float
        Effective modulus E* [Pa].

    Returns
    -------
    HertzContact
        As :func:`hertz_contact`.

    Notes
    -----
    Valid for %(D)s, %(RATIO)s; see :func:`hertz_contact`.

    Examples
    --------
    >>> h = hertz_contact_at_approach(13.92e-6, 0.2, 0.01, 115.385e9)
    >>> f"{h.force:.0f} N"
    '2000 N'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    d = check_positive("approach", approach, "m")
    rx = float(check_positive("radius_x", radius_x, "m"))
    ry = float(check_positive("radius_y", radius_y, "m"))
    E = float(check_positive("estar", estar, "Pa"))
    unit = _contact(np.asarray(1.0), rx, ry, E)
    F = (d / unit.approach) ** 1.5
    return _contact(F, rx, ry, E)
