"""Influence coefficients of the elastic half-space for uniform pressure on a rectangle.

Love (1929); Johnson, *Contact Mechanics* (1985), Eq. (3.25). The normal surface
displacement at (x, y) due to a unit pressure on the rectangle |x'| <= a, |y'| <= b is

.. math::

    u_z(x, y) = \\frac{1}{\\pi E^*} \\int_{-a}^{a}\\int_{-b}^{b}
        \\frac{d\\xi\\, d\\eta}{\\sqrt{(x-\\xi)^2 + (y-\\eta)^2}}
      = \\frac{1}{\\pi E^*} \\left[P(x+a, y+b) - P(x+a, y-b) - P(x-a, y+b) + P(x-a, y-b)\\right]

with the primitive :math:`P(X, Y) = X\\,\\mathrm{asinh}(Y/|X|) + Y\\,\\mathrm{asinh}(X/|Y|)`
(and P = 0 on the axes). Johnson prints the same result with logarithms,
X ln(Y + r) + Y ln(X + r); that form loses all digits where Y + r cancels
(Y < 0, |X| << |Y|). ln(Y + r) = asinh(Y/|X|) + ln|X|, and the ln|X| part depends
on X alone, so it drops out of the mixed difference: the asinh form is exact and
has no cancellation inside a term.

E* is the effective modulus, 1/E* = (1 - nu^2)/E for one elastic body (Li & Popov
2017, Eq. 3).
"""
from __future__ import annotations

import numpy as np


def _primitive_terms(X, Y):
    """The two terms X asinh(Y/|X|) and Y asinh(X/|Y|) of P(X, Y), each 0 on the axis
    where it vanishes in the limit."""
    X = np.asarray(X, dtype=float)
    Y = np.asarray(Y, dtype=float)
    absX = np.abs(X)
    absY = np.abs(Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(absX > 0, X * np.arcsinh(Y / np.where(absX > 0, absX, 1.0)), 0.0)
        t2 = np.where(absY > 0, Y * np.arcsinh(X / np.where(absY > 0, absY, 1.0)), 0.0)
    return t1, t2


def _primitive(X, Y):
    """P(X, Y) with P = 0 where X = 0 or Y = 0 (its limit there)."""
    t1, t2 = _primitive_terms(X, Y)
    return t1 + t2


def rectangle_displacement(x, y, dx, dy, estar=1.0):
    """Surface displacement under unit pressure on a dx-by-dy rectangle centred at 0.

    Parameters
    ----------
    x, y : array_like
        Field point relative to the centre of the cell [m].
    dx, dy : float
        Cell sides along x and y [m]; need not be equal.
    estar : float
        Effective modulus E* [Pa].

    Returns
    -------
    ndarray
        Displacement per unit pressure [m/Pa], positive into the body.

    Examples
    --------
    The centre of a square cell of side h: 4 ln(1 + sqrt 2)/pi * h/E*.

    >>> import numpy as np
    >>> float(rectangle_displacement(0.0, 0.0, 1.0, 1.0))  # doctest: +ELLIPSIS
    1.12219...
    >>> float(4 * np.log(1 + np.sqrt(2)) / np.pi)  # doctest: +ELLIPSIS
    1.12219...
    """
    a = 0.5 * dx
    b = 0.5 * dy
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    s = (_primitive(x + a, y + b) - _primitive(x + a, y - b)
         - _primitive(x - a, y + b) + _primitive(x - a, y - b))
    return s / (np.pi * estar)


def kernel_offsets(nx, ny, dx, dy, estar=1.0):
    """Influence coefficients K[i, j] for cell offsets i = 0..nx, j = 0..ny.

    K[i, j] is the displacement at the centre of a cell shifted by (i dx, j dy) from a
    loaded cell, per unit pressure [m/Pa]. The kernel is even in both offsets, so these
    values define it for negative offsets too.
    """
    i = np.arange(nx + 1) * dx
    j = np.arange(ny + 1) * dy
    return rectangle_displacement(i[:, None], j[None, :], dx, dy, estar)


# --- uniform shear traction on a rectangle (Cerruti) -------------------------------------

def _check_material(shear_modulus, nu):
    from linecontact.errors import OutOfRangeError
    if not (np.isfinite(shear_modulus) and shear_modulus > 0):
        raise OutOfRangeError("shear_modulus", shear_modulus, "(0, inf) Pa", unit="Pa")
    if not (np.isfinite(nu) and 0.0 <= nu <= 0.5):
        raise OutOfRangeError("nu", nu, "[0, 0.5]",
                              hint="Poisson's ratio of an isotropic solid in contact "
                                   "mechanics (negative values are not supported)")


def shear_integrals(x, y, dx, dy):
    r"""The two integrals of a uniform shear traction on a dx-by-dy rectangle.

    .. math::

        F_\nu(x, y) = \iint_{cell} \frac{(y-\eta)^2}{r^3}\,d\xi\,d\eta, \qquad
        F_1(x, y)   = \iint_{cell} \frac{(x-\xi)^2}{r^3}\,d\xi\,d\eta,

    r the distance from (xi, eta) to the field point. With the corner offsets
    k, l = x -+ dx/2 ... (k = x + dx/2, l = x - dx/2, m = y + dy/2, n = y - dy/2),
    Pohrt & Li (2014) write them as
    F_nu = k ln[(m + r_km)/(n + r_kn)] + l ln[(n + r_ln)/(m + r_lm)] and
    F_1 = m ln[(k + r_km)/(l + r_lm)] + n ln[(l + r_ln)/(k + r_kn)]; here each is the
    mixed corner difference of X asinh(Y/|X|) and of Y asinh(X/|Y|), the two terms of
    Love's primitive (module docstring): the same numbers without the cancellation of
    the log form. F_nu + F_1 is the integral of 1/r (Love's).

    Parameters
    ----------
    x, y : array_like
        Field point relative to the centre of the cell [m].
    dx, dy : float
        Cell sides along x and y [m].

    Returns
    -------
    (ndarray, ndarray)
        F_nu and F_1 [m].

    Notes
    -----
    Exact for any field point, inside or outside the cell, and any aspect ratio;
    relative rounding grows as (distance/cell size)^2 in the far field, as for Love's.

    Examples
    --------
    At the centre of a square the two are equal, each half of Love's integral
    4 ln(1 + sqrt 2) h:

    >>> fnu, f1 = shear_integrals(0.0, 0.0, 1.0, 1.0)
    >>> round(float(fnu), 12) == round(float(f1), 12), round(float(fnu + f1), 6)
    (True, 3.525494)

    References
    ----------
    Pohrt, R. and Li, Q. (2014), Complete boundary element formulation for normal and
    tangential contact problems, Physical Mesomechanics 17:334-340 (several printed
    prefactors there lack a factor pi). Johnson, K. L. (1985), Contact Mechanics,
    section 3.6 (Cerruti).
    """
    a = 0.5 * dx
    b = 0.5 * dy
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    km, kn, lm, ln = ((x + a, y + b), (x + a, y - b), (x - a, y + b), (x - a, y - b))
    terms = [_primitive_terms(*c) for c in (km, kn, lm, ln)]
    f_nu = terms[0][0] - terms[1][0] - terms[2][0] + terms[3][0]
    f_1 = terms[0][1] - terms[1][1] - terms[2][1] + terms[3][1]
    return f_nu, f_1


def _cross_integral(x, y, dx, dy):
    """integral of (x-xi)(y-eta)/r^3 over the cell, = -(r_km - r_kn - r_lm + r_ln), in
    a form with no cancellation: every difference of distances rewritten as
    (s1^2 - s2^2)/(r1 + r2)."""
    a = 0.5 * dx
    b = 0.5 * dy
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    k, l, m, n = x + a, x - a, y + b, y - b
    rkm, rkn, rlm, rln = np.hypot(k, m), np.hypot(k, n), np.hypot(l, m), np.hypot(l, n)
    return (dx * dy * (2 * x) * (2 * y) * (1.0 / (rlm + rkm) + 1.0 / (rln + rkn))
            / ((rkm + rkn) * (rlm + rln)))


def cerruti_rectangle(x, y, dx, dy, shear_modulus=1.0, nu=0.0):
    r"""Surface displacements under a unit shear traction on a dx-by-dy rectangle.

    Cerruti's point-force solution (Johnson 1985, Eq. 3.86a,b), integrated over a
    uniformly loaded cell centred at the origin:

    .. math::

        u_x = \frac{q_x}{2\pi G}\iint\left[\frac{1-\nu}{r} + \frac{\nu (x-\xi)^2}{r^3}\right]
            = \frac{(1-\nu) F_\nu + F_1}{2\pi G} q_x,

        u_y = \frac{(1-\nu) F_1 + F_\nu}{2\pi G} q_y, \qquad
        u_y|_{q_x} = u_x|_{q_y} = \frac{\nu}{2\pi G}\iint\frac{(x-\xi)(y-\eta)}{r^3}\,q,

    with F_nu, F_1 of :func:`shear_integrals`. The normal displacement that a shear
    traction also causes, (1 - 2 nu)/(4 pi G) (x - xi)/r^2, is left out: the uncoupled
    (Goodman 1962) approximation of tools.bem.tangential. At nu = 0 K_xx = K_yy =
    (F_nu + F_1)/(2 pi G) is Love's normal coefficient with E* = 2 G (and K_zz =
    (1 - nu)(F_nu + F_1)/(2 pi G) is Love's for every nu).

    Parameters
    ----------
    x, y : array_like
        Field point relative to the centre of the cell [m].
    dx, dy : float
        Cell sides along x and y [m].
    shear_modulus : float
        Shear modulus G of the half-space [Pa].
    nu : float
        Poisson's ratio [-], 0 <= nu <= 0.5.

    Returns
    -------
    (ndarray, ndarray, ndarray)
        K_xx (u_x per unit q_x), K_yy (u_y per unit q_y), K_xy (u_y per unit q_x, equal
        to u_x per unit q_y) [m/Pa].

    Notes
    -----
    Exact (closed form) for any field point and cell aspect ratio; a rigid body rotation
    and translation of the half-space are fixed as in Boussinesq-Cerruti (displacements
    vanish at infinity). Valid for 0 <= nu <= 0.5.

    Examples
    --------
    At nu = 0 the centre of a square cell moves as under Love's pressure with E* = 2G:

    >>> kxx, kyy, kxy = cerruti_rectangle(0.0, 0.0, 1.0, 1.0, shear_modulus=0.5, nu=0.0)
    >>> float(kxx) == float(kyy), round(float(kxx), 6), float(kxy)
    (True, 1.1222, 0.0)

    References
    ----------
    Johnson, K. L. (1985), Contact Mechanics, Cambridge University Press, section 3.6.
    Pohrt, R. and Li, Q. (2014), Physical Mesomechanics 17:334-340 (printed prefactors
    of several coefficients lack a factor pi). Goodman, L. E. (1962), Contact stress
    analysis of normally loaded rough spheres, J. Appl. Mech. 29:515-522.
    """
    _check_material(shear_modulus, nu)
    f_nu, f_1 = shear_integrals(x, y, dx, dy)
    c = 1.0 / (2 * np.pi * shear_modulus)
    kxx = c * ((1 - nu) * f_nu + f_1)
    kyy = c * ((1 - nu) * f_1 + f_nu)
    kxy = c * nu * _cross_integral(x, y, dx, dy)
    return kxx, kyy, kxy


def cerruti_kernel_offsets(nx, ny, dx, dy, shear_modulus=1.0, nu=0.0, component="xx"):
    """Tangential influence coefficients K[i, j] for cell offsets i = 0..nx, j = 0..ny.

    The counterpart of :func:`kernel_offsets` for a shear traction: the displacement
    along the traction at the centre of a cell shifted by (i dx, j dy) from the loaded
    one [m/Pa]. ``component`` 'xx' (traction and displacement along x) or 'yy' (along
    y); both are even in each offset, so these values define the whole kernel, and the
    operators of tools.bem.halfspace can use them (tools.bem.tangential).
    """
    i = np.arange(nx + 1) * dx
    j = np.arange(ny + 1) * dy
    kxx, kyy, _ = cerruti_rectangle(i[:, None], j[None, :], dx, dy, shear_modulus, nu)
    if component == "xx":
        return kxx
    if component == "yy":
        return kyy
    raise ValueError(f"component = {component!r} is not one of 'xx', 'yy'")
