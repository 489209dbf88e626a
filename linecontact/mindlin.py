r"""Mindlin's tangential contact of a Hertz ellipse: stiffness by direction, partial slip.

A tangential force Q on a Hertz contact ellipse (semi-axes a along x, b along y) in the
direction of one of its axes, the normal force P held (the normal and tangential
problems uncoupled: Goodman's approximation, exact for elastically similar bodies).

**Full stick** (Mindlin 1949; Johnson 1985, section 7.2, Eq. 7.41-7.44). The traction
:math:`q = Q/(2\pi a b)\,(1 - x^2/a^2 - y^2/b^2)^{-1/2}` parallel to Q displaces the
whole ellipse rigidly. With the larger semi-axis :math:`a_1 = \max(a, b)`, the
eccentricity :math:`e = \sqrt{1 - b_1^2/a_1^2}`, the complete elliptic integrals K(e),
E(e) and the Cerruti kernel summed over the two bodies,

.. math::

    \delta = \frac{Q}{2\pi a_1}\left[c_G K(e) - c_\nu J\right],\qquad
    c_G = \frac{1}{G_1} + \frac{1}{G_2},\quad c_\nu = \frac{\nu_1}{G_1} + \frac{\nu_2}{G_2},

    J_{major} = \frac{E(e) - (1-e^2) K(e)}{e^2},\qquad
    J_{minor} = \frac{K(e) - E(e)}{e^2}

(Q along the major or the minor axis), so :math:`k_t = Q/\delta`. Both
:math:`c_G = 4/G^* - 2/E^*` and :math:`c_\nu = 4/G^* - 4/E^*` follow from the package's
effective moduli (:func:`linecontact.tangential.effective_shear_modulus`,
:func:`linecontact.classical.effective_modulus`), which is how they are given here.
At e = 0 (a circle) both J are pi/4 and :math:`k_t = 2 G^* a`, the sphere's value
(Mindlin 1949). The contact is stiffer across its long axis than along it. Against the
Hertz normal stiffness :math:`k_n = \pi a_1 E^*/K(e)` the ratio

.. math:: \frac{k_t}{k_n} = \frac{2 K(e)}{E^*\left[c_G K(e) - c_\nu J\right]}
          = \frac{2 r K}{(4 - 2r) K - (4 - 4r) J}, \qquad r = \frac{G^*}{E^*}

depends on the radii's ratio and the moduli alone, not on the load.

**Partial slip** (Cattaneo 1938, Mindlin 1949; for the ellipse Mindlin 1949 and
Deresiewicz 1957): the stick zone is an ellipse similar to the contact, of semi-axes
:math:`(a', b') = (a, b)\,(1 - Q/\mu P)^{1/3}`, and

.. math::

    \delta(Q) = \delta^*\left[1 - \left(1 - \frac{Q}{\mu P}\right)^{2/3}\right],\qquad
    \delta^* = \frac{3\mu P}{2 k_t},

the sphere's law with the ellipse's k_t in the direction of Q.

**Fretting** (Mindlin & Deresiewicz 1953): from (delta_0, Q*) the unloading and
reloading branches follow Masing's rule, :math:`Q = Q^* - 2 f((\delta_0 - \delta)/2)`
and :math:`Q = -Q^* + 2 f((\delta_0 + \delta)/2)`, f the monotonic law, and the energy
dissipated per cycle is

.. math:: W = \frac{36 \mu^2 P^2}{5 k_t}\left[1 - \left(1 - \frac{Q^*}{\mu P}\right)^{5/3}
          - \frac{5 Q^*}{6 \mu P}\left(1 + \left(1 - \frac{Q^*}{\mu P}\right)^{2/3}\right)
          \right]

(Johnson 1985, Eq. 7.60 with the sphere's :math:`k_t = 8 G a/(2-\nu)`).

The slip in the annulus is taken parallel to Q, as in Mindlin's solution; the small
transverse slip it neglects is discussed by Johnson (1985, section 7.2).

References
----------
.. [1] R. D. Mindlin, Compliance of elastic bodies in contact, J. Appl. Mech. 16 (1949)
   259-268.
.. [2] R. D. Mindlin, H. Deresiewicz, Elastic spheres in contact under varying oblique
   forces, J. Appl. Mech. 20 (1953) 327-344.
.. [3] H. Deresiewicz, Oblique contact of nonspherical elastic bodies, J. Appl. Mech. 24
   (1957) 623-624.
.. [4] C. Cattaneo, Sul contatto di due corpi elastici: distribuzione locale degli
   sforzi, Rend. Accad. Naz. Lincei 27 (1938) 342-348, 434-436, 474-478.
.. [5] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections 4.2
   and 7.2.
"""
from __future__ import annotations

import math

import numpy as np

from ._numerics import out
from .checks import check_interval, check_positive
from .errors import OutOfRangeError, UnknownNameError
from .hertz import _KE, hertz_contact, hertz_eccentricity
from .tangential import FRICTION
from .tangential.laws import _amplitude, _check_beyond
from .tangential.moduli import _ratio

__all__ = [
    "DIRECTIONS",
    "stiffness_factors",
    "full_stick_stiffness",
    "stiffness_ratio",
    "equivalent_axes_ratio",
    "equivalent_ellipse_ratio",
    "slip_shift",
    "slip_force",
    "stick_fraction",
    "dissipated_energy",
    "EllipticalTangentialContact",
]

#: Directions of the tangential force: along x (the semi-axis a of
#: :func:`linecontact.hertz.hertz_contact`'s radius_x) or along y.
DIRECTIONS = ("x", "y")

#: Below this load fraction Q*/(mu P) the energy's bracket is summed as its power series
#: (the closed form cancels like q^3 there).
_SERIES_Q = 0.1
_SERIES_TERMS = 40


def _moduli(gstar, estar):
    """c_G = sum 1/G_i and c_nu = sum nu_i/G_i [1/Pa] from G* and E* (checked)."""
    _ratio(gstar, estar)    # G*, E* > 0 and G*/E* in [2/3, 1]: the tangential laws' check
    g, e = np.asarray(gstar, dtype=float), np.asarray(estar, dtype=float)
    return 4.0 / g - 2.0 / e, 4.0 / g - 4.0 / e


def _direction(direction):
    if direction not in DIRECTIONS:
        raise UnknownNameError("direction", direction, DIRECTIONS)
    return direction


def stiffness_factors(kprime):
    r"""K(e), J_major and J_minor of Mindlin's compliance of an ellipse of axes' ratio k'.

    .. math::

        J_{major} = \frac{E(e) - k'^2 K(e)}{e^2},\qquad
        J_{minor} = \frac{K(e) - E(e)}{e^2},\qquad e^2 = 1 - k'^2

    Parameters
    ----------
    kprime : float
        Smaller over larger semi-axis b/a, 0 < k' <= 1 [-].

    Returns
    -------
    (float, float, float)
        K(e), J_major (Q along the larger semi-axis), J_minor (along the smaller) [-].

    Notes
    -----
    Valid for 0 < k' <= 1; at k' = 1 (a circle) K = pi/2 and both J = pi/4. Evaluated
    with the elliptic integrals of :mod:`linecontact.hertz` (power series near the
    circle, where K - E loses digits).

    Examples
    --------
    >>> K, Jmaj, Jmin = stiffness_factors(1.0)
    >>> f"{K:.6f} {Jmaj:.6f} {Jmin:.6f}"
    '1.570796 0.785398 0.785398'

    References
    ----------
    R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268; K. L. Johnson, Contact Mechanics
    (1985), section 7.2.
    """
    k = float(check_interval("kprime", kprime, 0.0, 1.0, low_open=True))
    m = (1.0 - k) * (1.0 + k)
    if m == 0.0:
        return math.pi / 2, math.pi / 4, math.pi / 4
    K, _, KmE = _KE(k)
    j_minor = KmE / m
    return K, K - j_minor, j_minor


def _compliance(semi_x, semi_y, cg, cnu, direction):
    """delta/Q [m/N] of the ellipse with semi-axes semi_x (along x), semi_y (along y)."""
    sx, sy, cg, cnu = np.broadcast_arrays(np.asarray(semi_x, float), np.asarray(semi_y, float),
                                          np.asarray(cg, float), np.asarray(cnu, float))
    res = np.empty(sx.shape)
    for i in np.ndindex(*sx.shape):
        big, small = max(sx[i], sy[i]), min(sx[i], sy[i])
        K, jmaj, jmin = stiffness_factors(small / big)
        J = jmaj if (sx[i] >= sy[i]) == (direction == "x") else jmin
        res[i] = (cg[i] * K - cnu[i] * J) / (2.0 * math.pi * big)
    return res


def full_stick_stiffness(semi_x, semi_y, gstar, estar, direction):
    r"""Full-stick tangential stiffness k_t of a Hertz ellipse in the direction of an axis.

    .. math:: k_t = \frac{2\pi a_1}{c_G K(e) - c_\nu J}, \qquad
              c_G = \frac{4}{G^*} - \frac{2}{E^*}, \quad c_\nu = \frac{4}{G^*} - \frac{4}{E^*}

    (a_1 the larger semi-axis; J = J_major or J_minor, :func:`stiffness_factors`).

    Parameters
    ----------
    semi_x : float or array_like
        Semi-axis of the contact ellipse along x [m].
    semi_y : float or array_like
        Semi-axis along y [m].
    gstar : float
        Effective shear modulus G* (:func:`linecontact.tangential.effective_shear_modulus`)
        [Pa].
    estar : float
        Effective modulus E* (:func:`linecontact.classical.effective_modulus`) [Pa].
    direction : {"x", "y"}
        Direction of the tangential force.

    Returns
    -------
    float or ndarray
        k_t [N/m].

    Notes
    -----
    Valid for semi-axes 0 < a, b < inf, 2/3 <= G*/E* <= 1 (Poisson ratios in
    [0, 0.5]); linear elasticity, half-spaces, uncoupled normal and tangential problems.

    Examples
    --------
    Steel on steel (E* = 115.4 GPa, G* = 95.02 GPa), R = 10 mm, crown radius 500 mm,
    1 kN: across the roller (y) and along it (x):

    >>> from linecontact.hertz import hertz_contact
    >>> h = hertz_contact(1e3, 0.5, 0.01, 115.385e9)
    >>> kx = full_stick_stiffness(h.a, h.b, 95.0226e9, 115.385e9, "x")
    >>> ky = full_stick_stiffness(h.a, h.b, 95.0226e9, 115.385e9, "y")
    >>> f"across {ky / 1e6:.1f} N/um, along {kx / 1e6:.1f} N/um"
    'across 192.5 N/um, along 161.9 N/um'

    References
    ----------
    R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268; K. L. Johnson, Contact Mechanics
    (1985), section 7.2.
    """
    a = check_positive("semi_x", semi_x, "m")
    b = check_positive("semi_y", semi_y, "m")
    cg, cnu = _moduli(gstar, estar)
    return out(1.0 / _compliance(a, b, cg, cnu, _direction(direction)))


def stiffness_ratio(radius_x, radius_y, gstar, estar, direction):
    r"""Mindlin's k_t over Hertz's k_n of an elliptical contact (independent of the load).

    .. math:: \frac{k_t}{k_n} = \frac{2 r K(e)}{(4 - 2r) K(e) - (4 - 4r) J},
              \qquad r = \frac{G^*}{E^*}

    with e from the radii (:func:`linecontact.hertz.hertz_eccentricity`) and J for the
    axis along `direction` (:func:`stiffness_factors`); :math:`k_n = \pi a_1 E^*/K(e)`.

    Parameters
    ----------
    radius_x : float
        Principal relative radius of curvature along x (a crowned roller: Rc) [m].
    radius_y : float
        Principal relative radius of curvature along y (a crowned roller: its
        effective radius) [m].
    gstar : float
        Effective shear modulus G* [Pa].
    estar : float
        Effective modulus E* [Pa].
    direction : {"x", "y"}
        Direction of the tangential force.

    Returns
    -------
    float
        k_t/k_n [-]; G*/E* for equal radii (the sphere).

    Notes
    -----
    Valid for radii 0 < R < inf with a ratio up to 1e7 (:data:`linecontact.hertz.
    RADIUS_RATIO`) and 2/3 <= G*/E* <= 1.

    Examples
    --------
    >>> f"{stiffness_ratio(0.5, 0.01, 95.0226e9, 115.385e9, 'y'):.4f}"
    '0.9013'
    >>> f"{stiffness_ratio(0.01, 0.01, 95.0226e9, 115.385e9, 'y'):.4f}"
    '0.8235'

    References
    ----------
    R. D. Mindlin (1949); K. L. Johnson, Contact Mechanics (1985), sections 4.2, 7.2.
    """
    rx = float(check_positive("radius_x", radius_x, "m"))
    ry = float(check_positive("radius_y", radius_y, "m"))
    cg, cnu = _moduli(gstar, estar)
    k, _ = hertz_eccentricity(rx, ry)
    K, jmaj, jmin = stiffness_factors(k)
    # x is the major axis where radius_x >= radius_y (hertz_contact's convention)
    J = jmaj if (rx >= ry) == (_direction(direction) == "x") else jmin
    return float(2.0 * K / (float(estar) * (float(cg) * K - float(cnu) * J)))


#: Smallest axes' ratio b/a of the equivalent ellipse searched (K(e) = 30.0 there: a
#: footprint 2.5e12 times longer than wide).
_KPRIME_MIN = 1e-12


def equivalent_axes_ratio(half_length, normal_stiffness, estar):
    r"""Axes' ratio k' = b/a of the ellipse of semi-axis a and flat-punch stiffness k_n.

    .. math:: k_n = \frac{\pi a E^*}{K(e)}, \qquad e^2 = 1 - k'^2

    (the normal stiffness of a Hertz ellipse, Johnson 1985 section 4.2, equal to that of
    the rigid flat elliptical punch on the same footprint), solved for k' given the
    footprint's half-length a along the roller and its normal stiffness k_n.

    Parameters
    ----------
    half_length : float
        Half-length a of the contact footprint along the roller axis [m].
    normal_stiffness : float
        Normal stiffness k_n = dF/dd of the contact, its footprint held [N/m].
    estar : float
        Effective modulus E* [Pa].

    Returns
    -------
    float
        k' = b/a [-], in [1e-12, 1].

    Raises
    ------
    OutOfRangeError
        k_n >= 2 a E* (the footprint is as stiff as the disc of radius a or stiffer: it
        is not elongated along the axis) or k' below 1e-12.

    Notes
    -----
    Valid for footprints longer along the axis than across it. K(e) varies like
    ln(4/k'), so the stiffness fixes the equivalent width through a logarithm.

    Examples
    --------
    A Hertz ellipse is its own equivalent ellipse (R 10 mm, crown 500 mm, 1 kN):

    >>> from linecontact.hertz import hertz_contact
    >>> h = hertz_contact(1e3, 0.5, 0.01, 115.385e9)
    >>> K = stiffness_factors(h.b / h.a)[0]
    >>> kp = equivalent_axes_ratio(h.a, math.pi * h.a * 115.385e9 / K, 115.385e9)
    >>> f"{kp:.6f} {h.b / h.a:.6f}"
    '0.082842 0.082842'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2 (Eq. 4.39 with the Hertz
    ellipse's compliance); R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268.
    """
    from scipy.optimize import brentq

    a = float(check_positive("half_length", half_length, "m"))
    kn = float(check_positive("normal_stiffness", normal_stiffness, "N/m"))
    e = float(check_positive("estar", estar, "Pa"))
    target = math.pi * a * e / kn
    k_lo = stiffness_factors(_KPRIME_MIN)[0]
    if not math.pi / 2 < target <= k_lo:
        raise OutOfRangeError("normal_stiffness", kn,
                              f"({math.pi * a * e / k_lo:.6g}, {2 * a * e:.6g}) N/m",
                              unit="N/m", where=f"half-length {a:.6g} m, E* {e:.6g} Pa",
                              hint="the equivalent ellipse needs a footprint longer "
                                   "along the axis than across it")
    if target == math.pi / 2:
        return 1.0
    return math.exp(brentq(lambda t: stiffness_factors(math.exp(t))[0] - target,
                           math.log(_KPRIME_MIN), 0.0, xtol=1e-14, rtol=1e-14))


def equivalent_ellipse_ratio(half_length, normal_stiffness, gstar, estar, direction):
    r"""k_t/k_n of any elongated footprint: Mindlin's ratio of its equivalent ellipse.

    .. math:: \frac{k_t}{k_n} = \frac{2 r K(e)}{(4 - 2r) K(e) - (4 - 4r) J},
              \qquad \frac{\pi a E^*}{K(e)} = k_n, \quad r = \frac{G^*}{E^*}

    Mindlin's ratio (:func:`stiffness_ratio`) of the ellipse with the footprint's
    half-length a along the axis (x) and the normal stiffness k_n of the footprint
    (:func:`equivalent_axes_ratio`). Both stiffnesses are those of flat punches on the
    same footprint (full stick); on an elongated footprint they are set by the
    footprint's length and, through the logarithm K(e), its width, which the ellipse
    matches. For a Hertz ellipse it is Mindlin's ratio exactly.

    Parameters
    ----------
    half_length : float
        Half-length a of the footprint along the axis [m].
    normal_stiffness : float
        Its normal stiffness k_n [N/m].
    gstar : float
        Effective shear modulus G* [Pa].
    estar : float
        Effective modulus E* [Pa].
    direction : {"x", "y"}
        Tangential force along the axis (x, "along") or across it (y, "across").

    Returns
    -------
    float
        k_t/k_n [-].

    Notes
    -----
    Valid for footprints longer along the axis than across it, 2/3 <= G*/E* <= 1.
    Its error for the footprints of crowned, logarithmic, end-relieved and straight
    rollers against the 3D tangential boundary-element solution is measured in
    tables/tangential_profiles.csv (within 0.33 % there, 0.43 % with the BEM's grid
    error; L/D 1-3, q/(E* D) 1e-4 to 2e-3, nu 0-0.5).

    Examples
    --------
    >>> from linecontact.hertz import hertz_contact
    >>> h = hertz_contact(1e3, 0.5, 0.01, 115.385e9)
    >>> kn = math.pi * h.a * 115.385e9 / stiffness_factors(h.b / h.a)[0]
    >>> r = equivalent_ellipse_ratio(h.a, kn, 95.0226e9, 115.385e9, "y")
    >>> f"{r:.4f} {stiffness_ratio(0.5, 0.01, 95.0226e9, 115.385e9, 'y'):.4f}"
    '0.9013 0.9013'

    References
    ----------
    R. D. Mindlin (1949); K. L. Johnson, Contact Mechanics (1985), sections 4.2, 7.2.
    """
    cg, cnu = _moduli(gstar, estar)
    kp = equivalent_axes_ratio(half_length, normal_stiffness, estar)
    K, jmaj, jmin = stiffness_factors(kp)
    J = jmaj if _direction(direction) == "x" else jmin
    return float(2.0 * K / (float(estar) * (float(cg) * K - float(cnu) * J)))


def _load_fraction(Q, normal_force, friction):
    P = check_positive("normal_force", normal_force, "N")
    mu = FRICTION.check(friction, name="friction")
    Q = np.asarray(Q, dtype=float)
    fmax = mu * P
    check_interval("tangential_force", np.abs(Q), 0.0, fmax * (1 + 1e-12), unit="N",
                   hint="more than mu P: the contact slides (gross slip), no static "
                        "equilibrium")
    return np.minimum(np.abs(Q) / fmax, 1.0), np.sign(Q), mu, P


def slip_shift(tangential_force, normal_force, friction, stiffness):
    r"""Tangential shift of the Cattaneo-Mindlin law of an ellipse under a force Q.

    .. math:: \delta = \frac{3\mu P}{2 k_t}\left[1 - \left(1 - \frac{|Q|}{\mu P}\right)
              ^{2/3}\right]\operatorname{sign} Q

    Parameters
    ----------
    tangential_force : float or array_like
        Tangential force Q along one axis, |Q| <= mu P [N].
    normal_force : float or array_like
        Normal force P, held [N].
    friction : float or array_like
        Coulomb friction coefficient mu [-].
    stiffness : float or array_like
        Full-stick stiffness k_t in the direction of Q (:func:`full_stick_stiffness`)
        [N/m].

    Returns
    -------
    float or ndarray
        delta [m]; 3 mu P/(2 k_t) at gross slip.

    Raises
    ------
    OutOfRangeError
        |Q| > mu P (gross slip: no static shift).

    Notes
    -----
    Valid for 0 <= |Q| <= mu P, mu > 0, P > 0, k_t > 0.

    Examples
    --------
    >>> f"{slip_shift(50.0, 1e3, 0.1, 192.5e6) * 1e9:.1f} nm"
    '288.3 nm'

    References
    ----------
    C. Cattaneo (1938); R. D. Mindlin (1949); K. L. Johnson, Contact Mechanics (1985),
    section 7.2.
    """
    q, sign, mu, P = _load_fraction(tangential_force, normal_force, friction)
    k = check_positive("stiffness", stiffness, "N/m")
    # 1 - (1 - q)^(2/3) without cancellation at small q
    with np.errstate(divide="ignore"):      # q = 1: log1p(-1) = -inf, expm1 -> -1
        return out(sign * 1.5 * mu * P / k * -np.expm1(np.log1p(-q) * (2.0 / 3.0)))


def slip_force(shift, normal_force, friction, stiffness, *, beyond="raise"):
    r"""Tangential force of the Cattaneo-Mindlin law of an ellipse under a shift delta.

    .. math:: Q = \mu P\left[1 - \left(1 - \frac{|\delta|}{\delta^*}\right)^{3/2}\right]
              \operatorname{sign}\delta, \qquad \delta^* = \frac{3\mu P}{2 k_t}

    Parameters
    ----------
    shift : float or array_like
        Monotonic tangential shift delta from the unloaded state [m].
    normal_force : float or array_like
        Normal force P, held [N].
    friction : float or array_like
        Coulomb friction coefficient mu [-].
    stiffness : float or array_like
        Full-stick stiffness k_t in the direction of the shift [N/m].
    beyond : {"raise", "saturate"}, optional
        Beyond gross slip (|delta| > delta*): refuse (default) or return mu P.

    Returns
    -------
    float or ndarray
        Q [N].

    Notes
    -----
    Valid for |delta| <= delta* (any delta with ``beyond="saturate"``), mu > 0, P > 0.

    Examples
    --------
    >>> u = slip_shift(50.0, 1e3, 0.1, 192.5e6)
    >>> f"{slip_force(u, 1e3, 0.1, 192.5e6):.6f} N"
    '50.000000 N'

    References
    ----------
    C. Cattaneo (1938); R. D. Mindlin (1949); K. L. Johnson, Contact Mechanics (1985),
    section 7.2.
    """
    _check_beyond(beyond)
    P = check_positive("normal_force", normal_force, "N")
    mu = FRICTION.check(friction, name="friction")
    k = check_positive("stiffness", stiffness, "N/m")
    u = np.asarray(shift, dtype=float)
    if not np.all(np.isfinite(u)):
        raise OutOfRangeError("shift", "a non-finite value", "finite values", unit="m")
    ustar = 1.5 * mu * P / k
    x = np.abs(u) / ustar
    if beyond == "raise" and np.any(x > 1 + 1e-12):
        raise OutOfRangeError("shift", float(np.max(np.abs(u))),
                              f"|shift| <= delta* = {float(np.max(ustar)):.6g} m", unit="m",
                              hint="beyond gross slip the contact slides at mu P; "
                                   "beyond='saturate' returns that force")
    with np.errstate(divide="ignore"):      # gross slip: log1p(-1) = -inf
        return out(np.sign(u) * mu * P * -np.expm1(1.5 * np.log1p(-np.minimum(x, 1.0))))


def stick_fraction(tangential_force, normal_force, friction):
    r"""Size of the stick ellipse over the contact's, a'/a = b'/b (Mindlin 1949).

    .. math:: \frac{a'}{a} = \frac{b'}{b} = \left(1 - \frac{|Q|}{\mu P}\right)^{1/3}

    Parameters
    ----------
    tangential_force : float or array_like
        Tangential force Q, |Q| <= mu P [N].
    normal_force : float or array_like
        Normal force P [N].
    friction : float or array_like
        Coulomb friction coefficient mu [-].

    Returns
    -------
    float or ndarray
        a'/a [-]: 1 in full stick, 0 at gross slip.

    Notes
    -----
    Valid for 0 <= |Q| <= mu P, mu > 0, P > 0.

    Examples
    --------
    >>> f"{stick_fraction(87.5, 1e3, 0.1):.3f}"
    '0.500'

    References
    ----------
    R. D. Mindlin (1949); K. L. Johnson, Contact Mechanics (1985), section 7.2.
    """
    q, _, _, _ = _load_fraction(tangential_force, normal_force, friction)
    return out(np.cbrt(1.0 - q))


def _binom(alpha, n):
    c = 1.0
    for i in range(n):
        c *= (alpha - i) / (i + 1)
    return c


#: Coefficients of q^n of the energy's bracket 1 - t^(5/3) - (5q/6)(1 + t^(2/3)),
#: t = 1 - q, from the binomial series (the terms up to q^2 vanish; q^3: 5/162).
_BRACKET = np.array([0.0] * 3 + [
    -_binom(5 / 3, n) * (-1) ** n - 5 / 6 * _binom(2 / 3, n - 1) * (-1) ** (n - 1)
    for n in range(3, _SERIES_TERMS)])


def _bracket(q):
    q = np.asarray(q, dtype=float)
    t = 1.0 - q
    closed = 1.0 - t ** (5 / 3) - 5 * q / 6 * (1.0 + t ** (2 / 3))
    series = np.polynomial.polynomial.polyval(q, _BRACKET)
    return np.where(q < _SERIES_Q, series, closed)


def dissipated_energy(amplitude_force, normal_force, friction, stiffness):
    r"""Energy dissipated per fretting cycle of amplitude Q* (Mindlin & Deresiewicz 1953).

    .. math:: W = \frac{36\mu^2P^2}{5k_t}\left[1 - \left(1 - \frac{Q^*}{\mu P}\right)^{5/3}
              - \frac{5Q^*}{6\mu P}\left(1 + \left(1 - \frac{Q^*}{\mu P}\right)^{2/3}
              \right)\right]

    Parameters
    ----------
    amplitude_force : float or array_like
        Amplitude Q* of the tangential force, 0 <= Q* <= mu P [N].
    normal_force : float or array_like
        Normal force P, held [N].
    friction : float or array_like
        Coulomb friction coefficient mu [-].
    stiffness : float or array_like
        Full-stick stiffness k_t in the direction of Q [N/m].

    Returns
    -------
    float or ndarray
        W [J]; :math:`2 Q^{*3}/(9 k_t \mu P)` at small amplitude.

    Notes
    -----
    Valid for 0 <= Q* <= mu P, mu > 0, P > 0. Below Q*/(mu P) = 0.1 the bracket is
    summed as its binomial series (40 terms), where the closed form cancels.

    Examples
    --------
    >>> f"{dissipated_energy(50.0, 1e3, 0.1, 192.5e6) * 1e9:.3f} nJ"
    '2195.352 nJ'

    References
    ----------
    R. D. Mindlin, H. Deresiewicz, J. Appl. Mech. 20 (1953) 327-344; K. L. Johnson,
    Contact Mechanics (1985), Eq. 7.60.
    """
    q, _, mu, P = _load_fraction(amplitude_force, normal_force, friction)
    k = check_positive("stiffness", stiffness, "N/m")
    return out(36.0 * (mu * P) ** 2 / (5.0 * k) * _bracket(q))


class EllipticalTangentialContact:
    r"""A Hertz elliptical contact under a tangential load along one axis (Mindlin).

    The normal force P is held; the tangential force Q or shift delta acts along
    `direction` ("x": along the semi-axis of `radius_x`; "y").

    .. math::

        k_t = \frac{2\pi a_1}{c_G K - c_\nu J},\quad
        \delta(Q) = \frac{3\mu P}{2k_t}\left[1 - \left(1 - \frac{Q}{\mu P}\right)^{2/3}
        \right],\quad Q^{\downarrow} = Q^* - 2 f\!\left(\frac{\delta_0 - \delta}{2}\right)

    Parameters
    ----------
    force : float
        Normal force P [N].
    radius_x : float
        Principal relative radius of curvature along x (crowned roller: Rc) [m].
    radius_y : float
        Principal relative radius of curvature along y (crowned roller: R) [m].
    estar : float
        Effective modulus E* [Pa].
    gstar : float
        Effective shear modulus G* [Pa].
    friction : float
        Coulomb friction coefficient mu [-].
    direction : {"x", "y"}, optional
        Direction of the tangential load (default "y": across a crowned roller).

    Notes
    -----
    Valid for P > 0, the radii of :func:`linecontact.hertz.hertz_contact`,
    2/3 <= G*/E* <= 1, mu > 0; the ellipse inside both bodies.

    Examples
    --------
    >>> c = EllipticalTangentialContact(1e3, 0.5, 0.01, 115.385e9, 95.0226e9, 0.1)
    >>> f"{c.stiffness / 1e6:.1f} N/um, delta* {c.gross_slip_shift * 1e9:.0f} nm"
    '192.5 N/um, delta* 779 nm'
    >>> f"{c.shift(50.0) * 1e9:.1f} nm, stick a'/a {c.stick_fraction(50.0):.3f}"
    "288.4 nm, stick a'/a 0.794"

    References
    ----------
    R. D. Mindlin (1949); R. D. Mindlin, H. Deresiewicz (1953); H. Deresiewicz (1957);
    K. L. Johnson, Contact Mechanics (1985), section 7.2.
    """

    def __init__(self, force, radius_x, radius_y, estar, gstar, friction, direction="y"):
        self.normal_force = float(check_positive("force", force, "N"))
        self.friction = float(FRICTION.check(friction, name="friction"))
        self.direction = _direction(direction)
        self.hertz = hertz_contact(self.normal_force, radius_x, radius_y, estar)
        h = self.hertz
        sx, sy = (h.b, h.a) if h.swapped else (h.a, h.b)
        #: Semi-axes of the contact ellipse along x and y [m].
        self.semi_axes = (float(sx), float(sy))
        #: Full-stick tangential stiffness k_t in `direction` [N/m].
        self.stiffness = float(full_stick_stiffness(sx, sy, gstar, estar, direction))
        #: Hertz's normal stiffness k_n [N/m].
        self.normal_stiffness = float(h.stiffness)
        #: Hertz's approach delta [m] (the normal state held).
        self.depth = float(h.approach)
        #: The law's name, as :class:`linecontact.tangential.TangentialContact`'s.
        self.method = "mindlin"

    @property
    def ratio(self):
        """k_t/k_n [-]."""
        return self.stiffness / self.normal_stiffness

    @property
    def gross_slip_force(self):
        """mu P [N]."""
        return self.friction * self.normal_force

    @property
    def gross_slip_shift(self):
        """delta* = 3 mu P/(2 k_t) [m]."""
        return 1.5 * self.gross_slip_force / self.stiffness

    def shift(self, tangential_force):
        """delta(Q) [m] for |Q| <= mu P [N] (:func:`slip_shift`)."""
        return slip_shift(tangential_force, self.normal_force, self.friction,
                          self.stiffness)

    def force(self, shift, *, beyond="raise"):
        """Q(delta) [N] for a monotonic shift delta [m] (:func:`slip_force`)."""
        return slip_force(shift, self.normal_force, self.friction, self.stiffness,
                          beyond=beyond)

    def stick_fraction(self, tangential_force):
        """a'/a of the stick ellipse under Q [N] (:func:`stick_fraction`)."""
        return stick_fraction(tangential_force, self.normal_force, self.friction)

    def unloading(self, shift, amplitude, *, beyond="raise"):
        """Unloading branch from (delta0, Q*): Q = Q* - 2 f((delta0 - delta)/2) [N];
        `shift` delta in [-delta0, delta0], `amplitude` delta0 <= delta* [m] (beyond
        with ``beyond="saturate"``: f saturates at mu P, Coulomb sliding)."""
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        return out(self.force(u0, beyond=beyond)
                   - 2 * np.asarray(self.force((u0 - u) / 2, beyond=beyond)))

    def reloading(self, shift, amplitude, *, beyond="raise"):
        """Reloading branch from (-delta0, -Q*): Q = -Q* + 2 f((delta0 + delta)/2) [N]."""
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        return out(-self.force(u0, beyond=beyond)
                   + 2 * np.asarray(self.force((u0 + u) / 2, beyond=beyond)))

    def loop(self, amplitude, n=101, *, beyond="raise"):
        """Closed fretting loop of amplitude delta0 [m]: (delta [m], Q [N]), 2n - 1 points."""
        u0 = float(self._amplitude(amplitude, beyond))
        down = np.linspace(u0, -u0, int(n))
        up = down[::-1][1:]
        return (np.concatenate([down, up]),
                np.concatenate([self.unloading(down, u0, beyond=beyond),
                                self.reloading(up, u0, beyond=beyond)]))

    def dissipated_energy(self, amplitude, *, beyond="raise"):
        """Energy per cycle W [J] of shift amplitude delta0 <= delta* [m]
        (:func:`dissipated_energy` at Q* = f(delta0)); beyond gross slip (``beyond=
        "saturate"``) the sliding adds 4 mu P (delta0 - delta*)."""
        u0 = self._amplitude(amplitude, beyond)
        ustar = self.gross_slip_shift
        W = dissipated_energy(self.force(np.minimum(u0, ustar)), self.normal_force,
                              self.friction, self.stiffness)
        return out(W + 4 * self.gross_slip_force * np.maximum(u0 - ustar, 0.0))

    def _amplitude(self, amplitude, beyond="raise"):
        return _amplitude(amplitude, beyond, self.gross_slip_shift,
                          "beyond gross slip the contact slides; beyond='saturate' "
                          "adds the sliding part")
