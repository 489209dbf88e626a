r"""Tangential contact of any model: full stick, Cattaneo-Mindlin partial slip, fretting.

The method of dimensionality reduction (Popov & Hess 2015, chapter 4) gives every
normal-contact law F(d) a tangential companion. The 1D springs of the MDR profile carry
a tangential stiffness :math:`G^*\,dx` besides the normal one :math:`E^*\,dx`, with

.. math::

    \frac{1}{G^*} = \frac{2-\nu_1}{4G_1} + \frac{2-\nu_2}{4G_2}, \qquad
    G_i = \frac{E_i}{2(1+\nu_i)},

and each spring sticks while :math:`G^*|u(x)| \le \mu E^*(d - g(x))`. With the shear
ratio :math:`r = G^*/E^*` and the friction coefficient :math:`\mu` this gives, from the
normal law alone (no profile needed):

- full stick: :math:`k_t = r\,k_n(d)`;
- monotonic shift u at constant normal depth d (Cattaneo 1938, Mindlin 1949):
  :math:`F_t(u) = \mu\,[F(d) - F(d - r u/\mu)]` up to gross slip at
  :math:`u^* = \mu d/r`, where :math:`F_t = \mu F(d)`; at constant normal force the
  same law holds at :math:`d = d(F)` (the normal and tangential problems are
  uncoupled, Goodman's approximation);
- unloading from :math:`(u_0, F_0)` and reloading by the Masing rule
  (Mindlin & Deresiewicz 1953): :math:`F_t = F_0 - 2 f((u_0 - u)/2)` and
  :math:`F_t = -F_0 + 2 f((u_0 + u)/2)`, f the monotonic law;
- energy dissipated per full cycle of amplitude :math:`u_0` (fretting):
  :math:`W = 8\int_0^{u_0} f(s)\,ds - 4 u_0 f(u_0)`.

Where these are exact, and where not
------------------------------------
Exact for axisymmetric contacts (a sphere gives Mindlin's and Mindlin-Deresiewicz's
results, which the tests check) under the Cattaneo-Mindlin assumptions: the normal
and tangential problems uncoupled (exact for elastically similar bodies, or with
:math:`(1-2\nu_1)/G_1 = (1-2\nu_2)/G_2`; for a rigid indenter on a compressible body it
is Goodman's approximation) and the slip parallel to the load. At :math:`\nu = 0`
(:math:`G^* = E^*`) the tangential kernel equals the normal one and the laws hold
exactly for *any* shape. For an elongated contact (a finite roller) the true full-stick
stiffness depends on the direction of the shift; ``method="bem"`` reads it from the
boundary-element table ``tables/tangential_cylinder.csv`` (across the axis, the
rolling direction, and along it), and the partial-slip law then uses that stiffness
ratio in place of :math:`G^*/E^*` (and the table's partial-slip correction, if the
table carries one). See docs/tangential.md for the measured error of the plain MDR.

All functions take SI units (m, N, Pa) and broadcast over numpy arrays.

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapters 3-4.
.. [2] C. Cattaneo, Sul contatto di due corpi elastici: distribuzione locale degli
   sforzi, Rend. Accad. Naz. Lincei 27 (1938) 342-348, 434-436, 474-478.
.. [3] R. D. Mindlin, Compliance of elastic bodies in contact, J. Appl. Mech. 16
   (1949) 259-268.
.. [4] R. D. Mindlin, H. Deresiewicz, Elastic spheres in contact under varying oblique
   forces, J. Appl. Mech. 20 (1953) 327-344.
.. [5] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 7.
.. [6] L. E. Goodman, Contact stress analysis of normally loaded rough spheres, J. Appl.
   Mech. 29 (1962) 515-522.
"""
from __future__ import annotations

import functools
import re

import numpy as np

from ._numerics import BLOCK, UniformHermite, blockwise
from .classical import MODULUS_OR_RIGID, effective_modulus, two_bodies
from .tables import TableError, read_table
from .validity import (POISSON_RATIO, Interval, OutOfRangeError, UnknownNameError,
                       check_interval, check_positive, document, out)

__all__ = [
    "shear_modulus",
    "effective_shear_modulus",
    "shear_ratio",
    "equivalent_poisson",
    "mdr_stiffness_ratio",
    "gross_slip_shift",
    "tangential_stiffness",
    "tangential_force",
    "tangential_shift",
    "TangentialContact",
    "CylinderTangentialTable",
    "cylinder_tangential_table",
    "cylinder_stiffness_ratios",
    "STRAIGHT_CYLINDER_MODELS",
    "TANGENTIAL_TABLE",
]

#: Name of the BEM table of the finite cylinder's tangential stiffness (tables/).
TANGENTIAL_TABLE = "tangential_cylinder"

#: Models of a straight (unprofiled, aligned) cylinder, to which the BEM table applies.
STRAIGHT_CYLINDER_MODELS = frozenset({"universal", "li-popov", "puttock-thwaite",
                                      "johnson", "kunz", "palmgren", "iso16281"})

#: G*/E* for Poisson ratios in [0, 0.5]: 2(1-nu)/(2-nu) lies in [2/3, 1].
SHEAR_RATIO = Interval("gstar/estar", 2.0 / 3.0, 1.0, unit="", rtol=1e-12)
FRICTION = Interval("friction", 0.0, np.inf, low_open=True, high_open=True)
_DIRECTIONS = ("across", "along")
_METHODS = ("mdr", "bem")
_GL_T, _GL_W = np.polynomial.legendre.leggauss(64)


# --------------------------------------------------------------------------------------
# moduli
# --------------------------------------------------------------------------------------
@document(E=MODULUS_OR_RIGID, NU=POISSON_RATIO)
def shear_modulus(modulus, poisson):
    r"""Shear modulus of an isotropic elastic body, :math:`G = E/(2(1+\nu))`.

    Parameters
    ----------
    modulus : float or array_like
        Young's modulus E, ``inf`` for a rigid body [Pa].
    poisson : float or array_like
        Poisson ratio nu [-].

    Returns
    -------
    float or ndarray
        G [Pa].

    Notes
    -----
    Valid for %(E)s and %(NU)s.

    Examples
    --------
    >>> f"{shear_modulus(210e9, 0.3) / 1e9:.2f} GPa"
    '80.77 GPa'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 2.
    """
    E = MODULUS_OR_RIGID.check(modulus, name="modulus")
    nu = POISSON_RATIO.check(poisson, name="poisson")
    return out(E / (2.0 * (1.0 + nu)))


@document(E=MODULUS_OR_RIGID, NU=POISSON_RATIO)
def effective_shear_modulus(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    r"""Effective tangential modulus G* of two bodies (Popov & Hess 2015, chapter 4).

    .. math::
        \frac{1}{G^*} = \frac{2-\nu_1}{4G_1} + \frac{2-\nu_2}{4G_2}, \qquad
        G_i = \frac{E_i}{2(1+\nu_i)}

    Parameters
    ----------
    modulus1 : float or array_like
        Young's modulus E1 of the first body [Pa].
    poisson1 : float or array_like
        Poisson ratio nu1 of the first body [-].
    modulus2 : float or array_like, optional
        Young's modulus E2 of the second body, ``inf`` (default) for a rigid body [Pa].
    poisson2 : float or array_like, optional
        Poisson ratio nu2 of the second body; required with a finite `modulus2` (as in
        :func:`linecontact.classical.effective_modulus`), ignored for a rigid one [-].

    Returns
    -------
    float or ndarray
        G* [Pa]. For a rigid second body G* = 4 G1/(2 - nu1).

    Raises
    ------
    OutOfRangeError
        A modulus or Poisson ratio outside its range, a finite `modulus2` without
        `poisson2`, or both bodies rigid.

    Notes
    -----
    Valid for %(E)s (``inf`` = rigid) and %(NU)s for each body, not both rigid.
    With :func:`linecontact.classical.effective_modulus` the ratio G*/E* lies in
    [2/3, 1]; it is 2(1-nu)/(2-nu) for a rigid indenter (0.8235 at nu = 0.3).

    Examples
    --------
    Rigid roller on steel, and steel on steel:

    >>> f"{effective_shear_modulus(210e9, 0.3) / 1e9:.2f} GPa"
    '190.05 GPa'
    >>> f"{effective_shear_modulus(210e9, 0.3, 210e9, 0.3) / 1e9:.2f} GPa"
    '95.02 GPa'

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015); R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268.
    """
    E1, nu1, E2, nu2 = two_bodies(modulus1, poisson1, modulus2, poisson2)
    compliance = (2 - nu1) * (1 + nu1) / (2 * E1) + (2 - nu2) * (1 + nu2) / (2 * E2)
    return out(1.0 / compliance)


def shear_ratio(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    r"""The MDR's shear ratio G*/E* of two bodies, :math:`2(1-\nu)/(2-\nu)` if one is rigid.

    .. math::
        \frac{G^*}{E^*} = \frac{(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2}
                               {(2-\nu_1)(1+\nu_1)/(2E_1) + (2-\nu_2)(1+\nu_2)/(2E_2)}

    Parameters
    ----------
    modulus1, modulus2 : float or array_like
        Young's moduli, ``inf`` for a rigid body (not both) [Pa].
    poisson1, poisson2 : float or array_like
        Poisson ratios in [0, 0.5] [-].

    Returns
    -------
    float or ndarray
        G*/E* in [2/3, 1] [-].

    Notes
    -----
    Valid for moduli in (0, inf] Pa and Poisson ratios in [0, 0.5]. It is 1 at
    nu = 0, where the tangential problem is the normal one.

    Examples
    --------
    >>> f"{shear_ratio(210e9, 0.3):.4f}", f"{shear_ratio(210e9, 0.0):.4f}"
    ('0.8235', '1.0000')

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015).
    """
    g = effective_shear_modulus(modulus1, poisson1, modulus2, poisson2)
    e = effective_modulus(modulus1, poisson1, modulus2, poisson2)
    return out(np.asarray(g) / np.asarray(e))


def equivalent_poisson(gstar, estar):
    r"""Poisson ratio of the one-body problem with the same G*/E*: :math:`2(1-r)/(2-r)`.

    .. math::
        r = \frac{G^*}{E^*} = \frac{2(1-\nu)}{2-\nu}
        \;\Longleftrightarrow\; \nu = \frac{2(1-r)}{2-r}

    In the uncoupled (Goodman) problem two bodies act as one half-space with
    :math:`1/G = \sum 1/G_i` and :math:`1-\nu = \sum[(1-\nu_i)/G_i] / \sum 1/G_i`
    (both the normal and the tangential Boussinesq-Cerruti kernels add up that way),
    and that body has the same G*/E*. This is the Poisson ratio at which the cylinder's
    BEM table is read.

    Parameters
    ----------
    gstar : float or array_like
        Effective shear modulus G* [Pa].
    estar : float or array_like
        Effective modulus E* [Pa].

    Returns
    -------
    float or ndarray
        The equivalent Poisson ratio [-], in [0, 0.5].

    Notes
    -----
    Valid for 2/3 <= G*/E* <= 1 (Poisson ratios of both bodies in [0, 0.5]).

    Examples
    --------
    >>> f"{equivalent_poisson(shear_ratio(210e9, 0.3), 1.0):.6f}"
    '0.300000'
    >>> f"{equivalent_poisson(shear_ratio(210e9, 0.3, 70e9, 0.33), 1.0):.4f}"
    '0.3226'

    References
    ----------
    L. E. Goodman, J. Appl. Mech. 29 (1962) 515-522; K. L. Johnson, Contact
    Mechanics (1985), section 7.1.
    """
    r = _ratio(gstar, estar)
    return out(2.0 * (1.0 - r) / (2.0 - r))


@document(NU=POISSON_RATIO)
def mdr_stiffness_ratio(poisson):
    r"""The MDR's full-stick k_t/k_n = G*/E* = 2(1-nu)/(2-nu) of one elastic body.

    .. math:: \frac{k_t}{k_n} = \frac{2(1-\nu)}{2-\nu}

    Parameters
    ----------
    poisson : float or array_like
        Poisson ratio nu (or :func:`equivalent_poisson` of two bodies) [-].

    Returns
    -------
    float or ndarray
        k_t/k_n [-].

    Notes
    -----
    Valid for %(NU)s. Exact for axisymmetric contacts; for an elongated one the
    true ratio depends on the direction (see :func:`cylinder_stiffness_ratios`).

    Examples
    --------
    >>> f"{mdr_stiffness_ratio(0.3):.4f}", f"{mdr_stiffness_ratio(0.0):.4f}"
    ('0.8235', '1.0000')

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015).
    """
    nu = POISSON_RATIO.check(poisson, name="poisson")
    return out(2.0 * (1.0 - nu) / (2.0 - nu))


def _ratio(gstar, estar):
    g = check_positive("gstar", gstar, "Pa")
    e = check_positive("estar", estar, "Pa")
    return SHEAR_RATIO.check(g / e, hint="G*/E* of bodies with Poisson ratios in [0, 0.5] "
                                         "(effective_shear_modulus, effective_modulus)")


# --------------------------------------------------------------------------------------
# the generic laws
# --------------------------------------------------------------------------------------
def _law(model, depth):
    """F(z) of the model with F(0) = 0 (every contact law starts at zero force)."""
    check = getattr(model, "check_starts_at_zero", None)
    if check is not None:
        check()
    z = np.asarray(depth, dtype=float)
    if z.ndim == 0:
        return np.asarray(model.force(z) if z > 0 else 0.0, dtype=float)
    pos = z > 0
    if pos.all():
        return np.asarray(model.force(z), dtype=float)
    if not pos.any():
        return np.zeros(z.shape)
    # one evaluation over the whole array (a positive depth stands in where z <= 0,
    # then zeroed), cheaper than gathering and scattering the positive elements
    res = np.asarray(model.force(np.where(pos, z, z.max())), dtype=float)
    res[~pos] = 0.0
    return res


def _friction(friction):
    return FRICTION.check(friction, name="friction")


def gross_slip_shift(depth, friction, gstar, estar):
    r"""Tangential shift at which the whole contact slides: :math:`u^* = \mu E^* d/G^*`.

    .. math:: u^* = \frac{\mu E^* d}{G^*}

    Parameters
    ----------
    depth : float or array_like
        Normal depth d [m].
    friction : float or array_like
        Coulomb friction coefficient mu [-].
    gstar : float or array_like
        Effective shear modulus G* (:func:`effective_shear_modulus`) [Pa].
    estar : float or array_like
        Effective modulus E* [Pa].

    Returns
    -------
    float or ndarray
        u* [m], the same for every shape (the outermost MDR spring sticks until then).

    Notes
    -----
    Valid for d > 0, mu > 0, 2/3 <= G*/E* <= 1 (Poisson ratios in [0, 0.5]).

    Examples
    --------
    >>> f"{gross_slip_shift(2e-6, 0.1, 190.05e9, 230.77e9) * 1e9:.1f} nm"
    '242.9 nm'

    References
    ----------
    R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268; Popov & Hess (2015), chapter 4.
    """
    d = check_positive("depth", depth, "m")
    mu = _friction(friction)
    r = _ratio(gstar, estar)
    return out(mu * d / r)


def tangential_stiffness(model, depth, gstar, *, method="mdr", direction="across"):
    r"""Full-stick tangential stiffness of any model, :math:`k_t = (G^*/E^*)\,k_n(d)`.

    .. math:: k_t = \frac{G^*}{E^*}\,k_n(d) = 2 G^* a(d)

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model (its E* is the E* above).
    depth : float or array_like
        Normal depth d [m].
    gstar : float
        Effective shear modulus G* (:func:`effective_shear_modulus`) [Pa].
    method : {"mdr", "bem"}, optional
        ``"mdr"`` (default): the MDR ratio G*/E*, exact for axisymmetric contacts;
        ``"bem"``: the finite cylinder's direction-dependent ratio from the BEM table
        (straight-cylinder models only, see :func:`cylinder_stiffness_ratios`).
    direction : {"across", "along"}, optional
        With ``method="bem"``: shift across the axis (rolling direction, default) or
        along it.

    Returns
    -------
    float or ndarray
        k_t [N/m].

    Notes
    -----
    Valid where the model is (its depth range), for 2/3 <= G*/E* <= 1; with
    ``method="bem"`` also inside the table's range of nu and d R/L^2.

    Examples
    --------
    Linear (flat-punch-like) law of Kunz, rigid roller on steel (k_t/k_n = 0.8235):

    >>> from linecontact.models import get_model
    >>> m = get_model("kunz", 5e-3, 10e-3, effective_modulus(210e9, 0.3))
    >>> g = effective_shear_modulus(210e9, 0.3)
    >>> f"{tangential_stiffness(m, 1e-6, g) / m.stiffness(1e-6):.4f}"
    '0.8235'

    References
    ----------
    Popov & Hess (2015), chapter 4; R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268.
    """
    ratio = _stiffness_ratio(model, depth, gstar, method, direction)
    return out(ratio * np.asarray(model.stiffness(depth)))


def _stiffness_ratio(model, depth, gstar, method, direction):
    if method not in _METHODS:
        raise UnknownNameError("method", method, _METHODS)
    if method == "mdr":
        return _ratio(gstar, model.estar)
    if direction not in _DIRECTIONS:
        raise UnknownNameError("direction", direction, _DIRECTIONS)
    return cylinder_stiffness_ratios(model, depth, gstar)[direction]


def tangential_force(model, depth, shift, friction, gstar, *, beyond="raise", ratio=None):
    r"""Cattaneo-Mindlin tangential force of any model at constant normal depth.

    .. math::
        F_t(u) = \mu\left[F(d) - F\!\left(d - \frac{G^* u}{\mu E^*}\right)\right],
        \qquad |u| \le u^* = \frac{\mu E^* d}{G^*}

    (odd in u: a shift in the negative direction gives the negative force).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model F(d).
    depth : float or array_like
        Normal depth d, held constant while shifting [m].
    shift : float or array_like
        Monotonic tangential shift u from the unloaded state; broadcasts with depth [m].
    friction : float
        Coulomb friction coefficient mu [-].
    gstar : float
        Effective shear modulus G* [Pa].
    beyond : {"raise", "saturate"}, optional
        Beyond gross slip (|u| > u*): ``"raise"`` (default) refuses with
        :class:`OutOfRangeError`; ``"saturate"`` returns the sliding force mu F(d).
    ratio : float or array_like, optional
        Stiffness ratio k_t/k_n to use instead of G*/E* (e.g. Mindlin's for an
        elliptical contact, :func:`linecontact.mindlin.stiffness_ratio`) [-].

    Returns
    -------
    float or ndarray
        F_t [N].

    Notes
    -----
    Valid for |u| <= u* (all u with ``beyond="saturate"``), mu > 0,
    2/3 <= G*/E* <= 1, and the model's depth range. Exact for axisymmetric contacts
    (uncoupled normal and tangential problems) and for any shape at nu = 0.

    Examples
    --------
    A linear law F = k d gives a linear tangential law up to gross slip:

    >>> from linecontact.models import get_model
    >>> m = get_model("kunz", 5e-3, 10e-3, 1e11)
    >>> f"{tangential_force(m, 1e-6, 0.05e-6, 0.2, 1e11) / (0.2 * m.force(1e-6)):.3f}"
    '0.250'

    References
    ----------
    C. Cattaneo (1938); R. D. Mindlin (1949); Popov & Hess (2015), chapter 4.
    """
    d = check_positive("depth", depth, "m")
    r = _ratio(gstar, model.estar) if ratio is None else check_positive("ratio", ratio)
    return out(_ft(model, d, shift, _friction(friction), r, beyond))


def tangential_shift(model, depth, tangential_force, friction, gstar, *, ratio=None):
    r"""Shift u(F_t) of the Cattaneo-Mindlin law of any model at constant normal depth.

    .. math::
        u = \frac{\mu}{r}\left[d - d\!\left(F(d) - \frac{|F_t|}{\mu}\right)\right]
            \operatorname{sign} F_t, \qquad r = \frac{G^*}{E^*}

    the inverse of :func:`tangential_force` through the model's d(F); u* = mu d/r at
    |F_t| = mu F(d).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model.
    depth : float or array_like
        Normal depth d [m].
    tangential_force : float or array_like
        Tangential force F_t, |F_t| <= mu F(d); broadcasts with depth [N].
    friction : float or array_like
        Coulomb friction coefficient mu [-].
    gstar : float
        Effective shear modulus G* [Pa].
    ratio : float or array_like, optional
        Stiffness ratio k_t/k_n to use instead of G*/E* (e.g. the cylinder's BEM
        value in one direction, :func:`cylinder_stiffness_ratios`) [-].

    Returns
    -------
    float or ndarray
        u [m].

    Raises
    ------
    OutOfRangeError
        |F_t| > mu F(d): no static equilibrium, the contact slides (gross slip).

    Notes
    -----
    Valid for |F_t| <= mu F(d), mu > 0, 2/3 <= G*/E* <= 1 and the model's depth range.
    Exact for axisymmetric contacts and for any shape at nu = 0.

    Examples
    --------
    >>> from linecontact.models import get_model
    >>> m = get_model("kunz", 5e-3, 10e-3, 1e11)
    >>> u = tangential_shift(m, 1e-6, 0.25 * 0.2 * m.force(1e-6), 0.2, 1e11)
    >>> f"{u * 1e9:.1f} nm"
    '50.0 nm'

    References
    ----------
    R. D. Mindlin (1949); Popov & Hess (2015), chapter 4.
    """
    d = check_positive("depth", depth, "m")
    mu = _friction(friction)
    r = _ratio(gstar, model.estar) if ratio is None else check_positive("ratio", ratio)
    Ft = np.asarray(tangential_force, dtype=float)
    d, Ft, mu, r = np.broadcast_arrays(d, Ft, mu, r)
    F = _law(model, d)
    fmax = mu * F
    check_interval("tangential_force", np.abs(Ft), 0.0, fmax * (1 + 1e-12), unit="N",
                   hint="more than mu F: the contact slides (gross slip), no static "
                        "equilibrium")
    rest = F - np.minimum(np.abs(Ft), fmax) / mu
    z = np.zeros(rest.shape)
    pos = rest > F * 1e-15
    if np.any(pos):
        z[pos] = model.depth(rest[pos])
    return out(np.sign(Ft) * mu * (d - np.minimum(z, d)) / r)


def _check_beyond(beyond):
    if beyond not in ("raise", "saturate"):
        raise UnknownNameError("beyond", beyond, ("raise", "saturate"))


def _ft(model, d, shift, mu, r, beyond):
    """F_t(u) = mu [F(d) - F(d - r|u|/mu)] sign(u) with the gross-slip policy."""
    _check_beyond(beyond)
    u = np.asarray(shift, dtype=float)
    if (u.ndim and u.size and np.ndim(d) == 0 and np.ndim(mu) == 0 and np.ndim(r) == 0
            and np.isfinite(u.min()) and np.isfinite(u.max())):
        # one depth, friction and ratio (a TangentialContact): the same steps as below,
        # in blocks (cache-resident temporaries), F(d) evaluated once
        ustar = mu * d / r
        if not (beyond == "raise" and max(-u.min(), u.max()) > ustar * (1 + 1e-12)):
            law_d = _law(model, d)

            def chain(ub):
                z = np.minimum(np.abs(ub), ustar)
                z *= r
                z /= mu
                np.subtract(d, z, out=z)
                np.maximum(z, 0.0, out=z)
                ft = law_d - _law(model, z)
                ft *= mu
                ft *= np.sign(ub)
                return ft

            return blockwise(chain, u)
    if not np.all(np.isfinite(u)):
        raise OutOfRangeError("shift", float(u[~np.isfinite(u)].flat[0]) if u.ndim
                              else float(u), "finite values", unit="m")
    law_d = _law(model, d)          # F(d) before broadcasting: once per depth
    d, u, mu, r = np.broadcast_arrays(d, u, mu, r)
    ustar = mu * d / r
    a = np.abs(u)
    over = a > ustar * (1 + 1e-12)
    if beyond == "raise" and np.any(over):
        i = np.argwhere(over)[0] if over.ndim else ()
        i = tuple(int(k) for k in i)
        raise OutOfRangeError(
            "shift", float(u[i]), f"[-{ustar[i]:.6g}, {ustar[i]:.6g}] m", unit="m",
            hint="beyond gross slip u* = mu E* d/G* the contact slides at mu F(d); "
                 "beyond='saturate' returns that force")
    z = np.maximum(d - r * np.minimum(a, ustar) / mu, 0.0)
    ft = mu * (law_d - _law(model, z))
    return np.sign(u) * ft


# --------------------------------------------------------------------------------------
#: Arrays from this many elements on use the tabulated laws of TangentialContact (built
#: once per contact, about as costly as the direct evaluation of this many elements).
_TABLE_MIN = 1 << 15
#: Nodes of those tables, and the largest difference from the direct evaluation at the
#: cells' midpoints (over mu F, or over u*) with which a table is used.
_TABLE_NODES = 4097
_TABLE_TOL = 1e-12


class _EndTable:
    r"""A function y(x) on [0, 1] as a cubic Hermite table in :math:`s = (1-x)^{1/4}`.

    The partial-slip laws are smooth in the load fraction except at x = 1 (gross slip),
    where the depth of the rest d(F (1 - q)) goes to zero and the normal stiffness with
    it (logarithmically for a line contact, as a power for a power law): in
    :math:`1 - x = s^4` that end becomes smooth to high order, and equal steps in s
    crowd the nodes towards it. Cells holding a kink of the slip correction (its
    linear interpolation in q) are marked and evaluated directly, as is every element
    if the table misses the direct values at the cells' midpoints by more than `tol`.
    """

    def __init__(self, nodes_fun, exact, kinks, nodes=_TABLE_NODES, tol=_TABLE_TOL):
        s = np.linspace(0.0, 1.0, nodes)
        x = 1.0 - s ** 4
        x[0], x[-1] = 1.0, 0.0
        y, dydx = nodes_fun(x[1:])                       # x < 1: finite slopes
        y = np.concatenate([[float(exact(np.ones(1))[0])], y])
        slopes = np.concatenate([[0.0], -4.0 * s[1:] ** 3 * dydx])   # dy/ds, 0 at s = 0
        self.poly = UniformHermite(y, slopes)
        self.exact = exact
        bad = np.zeros(nodes - 1, dtype=bool)
        for xk in kinks:
            if 0.0 < xk < 1.0:
                t = (1.0 - xk) ** 0.25 * (nodes - 1)
                bad[min(int(np.floor(t)), nodes - 2)] = True
                bad[min(max(int(np.ceil(t)) - 1, 0), nodes - 2)] = True
        self.bad = bad
        sm = (np.arange(nodes - 1) + 0.5) / (nodes - 1)
        good = ~bad
        ym = self.poly(sm[good])
        #: Largest difference from the direct evaluation at the cells' midpoints.
        self.error = float(np.max(np.abs(ym - exact(1.0 - sm[good] ** 4)))) if good.any() \
            else 0.0
        self.usable = bool(self.error <= tol)

    def __call__(self, v, v_end, y_end):
        """The odd law y_end y(min(|v|/v_end, 1)) sign(v) of an array v, in blocks of
        BLOCK elements (v_end: where the law ends, gross slip; y_end: its value there).
        The marked cells' elements are evaluated directly, all together after the
        blocks."""
        poly, bad = self.poly, self.bad
        v = np.asarray(v, dtype=float)

        def pre(vb):                  # x = |v|/v_end, 1 from gross slip on
            x = np.abs(vb)
            x /= v_end
            return np.minimum(x, 1.0, out=x)

        def post(y, vb):
            y *= y_end
            y *= np.sign(vb)
            return y

        flat = v.ravel()
        res = np.empty(flat.size)
        redo = []
        for k in range(0, flat.size, BLOCK):
            vb = flat[k:k + BLOCK]
            s = pre(vb)
            np.subtract(1.0, s, out=s)
            np.maximum(s, 0.0, out=s)
            np.sqrt(s, out=s)
            np.sqrt(s, out=s)
            y, i = poly.evaluate(s)
            res[k:k + BLOCK] = post(y, vb)
            marked = np.flatnonzero(bad.take(i))
            if marked.size:
                redo.append(marked + k)
        if redo:
            j = np.concatenate(redo)
            res[j] = post(self.exact(pre(flat[j])), flat[j])
        return res.reshape(v.shape)


# --------------------------------------------------------------------------------------
class TangentialContact:
    r"""One normal contact state under tangential load: stick, partial slip, fretting.

    The normal depth d (or force F, converted with the model's d(F)) is held constant
    while the tangential shift u varies; the normal and tangential problems are
    uncoupled (Goodman). With the stiffness ratio r (= G*/E* for the MDR, or the BEM
    table's direction-dependent k_t/k_n of the cylinder):

    .. math::

        f(u) = \mu\,[F(d) - F(d - r u/\mu)],\quad k_t = r k_n(d),\quad
        u^* = \mu d/r,

        F_t^{\downarrow}(u) = F_0 - 2f\!\left(\tfrac{u_0-u}{2}\right),\quad
        F_t^{\uparrow}(u) = -F_0 + 2f\!\left(\tfrac{u_0+u}{2}\right),\quad
        W = 8\int_0^{u_0} f\,ds - 4u_0 f(u_0).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        Any normal-contact model.
    friction : float
        Coulomb friction coefficient mu [-].
    gstar : float
        Effective shear modulus G* (:func:`effective_shear_modulus`) [Pa].
    depth : float, optional
        Normal depth d (give depth or force) [m].
    force : float, optional
        Normal force F; the depth is the model's d(F) [N].
    method : {"mdr", "bem"}, optional
        ``"mdr"`` (default): r = G*/E*. ``"bem"``: r = the cylinder's k_t/k_n in
        `direction` from the BEM table (straight-cylinder models only), and the
        table's partial-slip correction if it carries one and `slip_correction`.
    direction : {"across", "along"}, optional
        With ``method="bem"``: across the axis (rolling direction, default) or along.
    slip_correction : bool, optional
        With ``method="bem"``: apply the table's partial-slip correction when the table
        has one (default True); without one the law is the stiffness-corrected MDR law.
    table : CylinderTangentialTable, optional
        The BEM table (default :func:`cylinder_tangential_table`).

    Notes
    -----
    Valid for 0 < |u| <= u* (beyond: ``beyond="saturate"`` on request), mu > 0,
    2/3 <= G*/E* <= 1 (Poisson ratios in [0, 0.5]), and in the model's depth range.
    Exact for axisymmetric shapes and for any shape at nu = 0; for the finite cylinder
    see docs/tangential.md for the MDR's measured error and ``method="bem"``.
    Energies are integrated, in the form :math:`W = 4r\int_0^{u_0} (u_0 - 2s)
    [k_n(d - rs/\mu) - k_n(d)]\,ds` (by parts; free of the cancellation of the
    :math:`O(u_0^2)` terms), by 64-point Gauss-Legendre quadrature in
    :math:`s = u_0(1 - t^2)`, smooth at gross slip where the normal stiffness starts
    from zero; they need the model's k_n to be the derivative of its F. Against
    Mindlin-Deresiewicz's closed form for the sphere the relative error is below 1e-11
    for Q*/(mu P) from 0.01 to 1 (tests/test_tangential.py).

    Examples
    --------
    Rigid roller (R = 5 mm, L = 10 mm) on steel, 1 kN normal load, mu = 0.1:

    >>> from linecontact.models import get_model
    >>> E = effective_modulus(210e9, 0.3); G = effective_shear_modulus(210e9, 0.3)
    >>> c = TangentialContact(get_model("universal", 5e-3, 10e-3, E), 0.1, G, force=1e3)
    >>> f"{c.stiffness / 1e6:.1f} N/um", f"{c.gross_slip_shift * 1e9:.1f} nm"
    ('536.7 N/um', '203.3 nm')
    >>> f"{c.force(0.5 * c.gross_slip_shift):.2f} N", str(c.slip_state(1e-7))
    ('52.96 N', 'partial slip')
    >>> f"{c.dissipated_energy(50e-9) * 1e9:.2f} nJ"
    '24.20 nJ'

    References
    ----------
    C. Cattaneo (1938); R. D. Mindlin (1949); R. D. Mindlin, H. Deresiewicz (1953);
    K. L. Johnson, Contact Mechanics (1985), section 7.2; Popov & Hess (2015), ch. 4.
    """

    def __init__(self, model, friction, gstar, *, depth=None, force=None, method="mdr",
                 direction="across", slip_correction=True, table=None):
        if (depth is None) == (force is None):
            raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                                  "exactly one of depth, force")
        self.model = model
        self.friction = float(_scalar_check(_friction(friction), "friction"))
        self.gstar = float(_scalar_check(check_positive("gstar", gstar, "Pa"), "gstar"))
        if depth is None:
            self.normal_force = float(_scalar_check(check_positive("force", force, "N"),
                                                    "force"))
            self.depth = float(model.depth(self.normal_force))
        else:
            self.depth = float(_scalar_check(check_positive("depth", depth, "m"), "depth"))
            self.normal_force = float(model.force(self.depth))
        if method not in _METHODS:
            raise UnknownNameError("method", method, _METHODS)
        self.method = method
        self.direction = direction
        self.mdr_ratio = float(_ratio(self.gstar, model.estar))
        self._correction = None
        if method == "mdr":
            self.ratio = self.mdr_ratio
        else:
            if direction not in _DIRECTIONS:
                raise UnknownNameError("direction", direction, _DIRECTIONS)
            table = table if table is not None else cylinder_tangential_table()
            ratios = cylinder_stiffness_ratios(model, self.depth, self.gstar, table=table)
            self.ratio = float(ratios[direction])
            if slip_correction:
                self._correction = table.shift_correction(
                    direction, float(ratios["nu"]), float(ratios["d_tilde"]))

    #: Attributes the cached laws (the tables of :meth:`_table`, the nodes of
    #: :meth:`_q_of_shift_reference`) are built from: assigning one drops the caches, so
    #: they are rebuilt from the new settings on next use (never evaluated stale).
    _CACHE_INPUTS = frozenset({"model", "friction", "gstar", "depth", "normal_force",
                               "ratio", "_correction"})

    def __setattr__(self, name, value):
        if name in self._CACHE_INPUTS:
            for cache in ("_tables", "_q_nodes", "_u_nodes"):
                self.__dict__.pop(cache, None)
        object.__setattr__(self, name, value)

    # -- single numbers ------------------------------------------------------------
    @property
    def normal_stiffness(self):
        """Normal stiffness k_n = dF/dd at the depth [N/m]."""
        return float(self.model.stiffness(self.depth))

    @property
    def stiffness(self):
        """Full-stick tangential stiffness k_t = r k_n [N/m]."""
        return self.ratio * self.normal_stiffness

    @property
    def gross_slip_shift(self):
        """Shift at gross slip u* = c(1) mu d / r [m] (c(1): the BEM table's slip
        correction at gross slip with ``method="bem"``, else 1)."""
        return self.friction * self.depth / self.ratio * self._q_factor(1.0)

    @property
    def gross_slip_force(self):
        """Sliding force mu F [N]."""
        return self.friction * self.normal_force

    # -- monotonic loading ---------------------------------------------------------
    def _q_factor(self, q):
        """Slip correction: BEM shift / law shift at load fraction q (1 without one)."""
        if self._correction is None:
            return np.ones_like(np.asarray(q, dtype=float)) if np.ndim(q) else 1.0
        qs, cs = self._correction
        return np.interp(q, qs, cs)

    def _law_force(self, shift, beyond):
        return _ft(self.model, self.depth, shift, self.friction, self.ratio, beyond)

    def _law_shift(self, q):
        """Law shift at load fraction q in [0, 1]: d - r u/mu = d(F(1 - q))."""
        q = np.asarray(q, dtype=float)
        rest = self.normal_force * (1.0 - q)
        pos = rest > 0
        if q.ndim == 0:
            z = self.model.depth(rest) if pos else 0.0
        elif pos.all():
            z = self.model.depth(rest)
        else:
            # one evaluation over the whole array (the full normal force stands in
            # where nothing is left, then zeroed): no gather and scatter
            z = np.asarray(self.model.depth(np.where(pos, rest, self.normal_force)),
                           dtype=float)
            z[~pos] = 0.0
        return self.friction * (self.depth - z) / self.ratio

    def force(self, shift, *, beyond="raise"):
        r"""Tangential force F_t(u) [N] under a monotonic shift u [m] from zero.

        ``beyond="saturate"`` returns mu F beyond gross slip (|u| > u*) instead of
        raising :class:`OutOfRangeError`. With a slip correction, arrays of 32768 values
        or more are evaluated by a table built once per contact, equal to the root to
        1e-12 mu F (docs/tangential.md).
        """
        if self._correction is None:
            return out(self._law_force(shift, beyond))
        _check_beyond(beyond)
        u = np.asarray(shift, dtype=float)
        ustar = self.gross_slip_shift
        if u.size >= _TABLE_MIN and np.isfinite(u.min()) and np.isfinite(u.max()):
            table = self._table("force")
            if table is not None:
                top = max(-float(u.min()), float(u.max()))
                if beyond == "raise" and top > ustar * (1 + 1e-12):
                    raise OutOfRangeError("shift", top, f"[-{ustar:.6g}, {ustar:.6g}] m",
                                          unit="m", hint="beyond gross slip; "
                                                         "beyond='saturate'")
                return out(table(u, ustar, self.gross_slip_force))
        a = np.abs(u)
        if beyond == "raise" and np.any(a > ustar * (1 + 1e-12)):
            raise OutOfRangeError("shift", float(a.max()), f"[-{ustar:.6g}, {ustar:.6g}] m",
                                  unit="m", hint="beyond gross slip; beyond='saturate'")
        q = np.where(a >= ustar, 1.0, self._q_of_shift_reference(np.minimum(a, ustar)))
        return out(np.sign(u) * q * self.gross_slip_force)

    def _corrected_shift(self, q):
        return self._law_shift(q) * self._q_factor(q)

    def _shift_slope(self, q):
        """da/dq of the shift a(q) = u_law(q) c(q) for q in [0, 1) (c' of the segment of
        the slip correction to the right of q): du_law/dq = (mu/r) F / k_n(d(F(1-q)))."""
        q = np.asarray(q, dtype=float)
        z = np.asarray(self.model.depth(self.normal_force * (1.0 - q)), dtype=float)
        k = np.asarray(self.model.stiffness(z), dtype=float)
        dlaw = self.friction * self.normal_force / (self.ratio * k)
        if self._correction is None:
            return dlaw
        qs, cs = self._correction
        j = np.clip(np.searchsorted(qs, q, side="right") - 1, 0, qs.size - 2)
        law = self.friction * (self.depth - z) / self.ratio
        return dlaw * self._q_factor(q) + law * (cs[j + 1] - cs[j]) / (qs[j + 1] - qs[j])

    def _kinks(self):
        """Load fractions of the slip correction's kinks (none without one)."""
        return () if self._correction is None else tuple(self._correction[0][1:-1])

    def _table(self, which):
        """The tabulated law ("shift": u(q)/u*, "force": q(u/u*)), built once, or None
        where it does not reproduce the direct evaluation to _TABLE_TOL."""
        tables = self.__dict__.setdefault("_tables", {})
        if which not in tables:
            try:
                tables[which] = self._build_table(which)
            except (ValueError, ArithmeticError):
                # a model that cannot be evaluated at the table's nodes (e.g. at the
                # tiny rests near gross slip): the direct evaluation stays
                tables[which] = None
        return tables[which]

    def _build_table(self, which):
        ustar = self.gross_slip_shift
        if which == "shift":
            def nodes_fun(q):
                return self._corrected_shift(q) / ustar, self._shift_slope(q) / ustar

            table = _EndTable(nodes_fun, lambda q: self._corrected_shift(q) / ustar,
                              self._kinks())
        else:
            def nodes_fun(x):
                q = self._q_of_shift_reference(x * ustar)
                return q, ustar / self._shift_slope(q)

            def exact(x):                     # q = 1 at gross slip, as force() has it
                return np.where(x >= 1.0, 1.0, self._q_of_shift_reference(x * ustar))

            kinks = [float(self._corrected_shift(qk)) / ustar for qk in self._kinks()]
            table = _EndTable(nodes_fun, exact, kinks)
        return table if table.usable else None

    def _q_of_shift_reference(self, a):
        """q with u_law(q) c(q) = a (an increasing function of q on [0, 1]).

        A tabulated inverse brackets each root between two of 1025 nodes (one sorted
        search); the Illinois variant of regula falsi then converges superlinearly
        inside the bracket (each step one evaluation of the law over the array), to
        |bracket| <= 1e-15 or |u(q) - a| <= 1e-15 u*, where a bisection took 60 steps.
        """
        if not hasattr(self, "_q_nodes"):
            # nodes dense near q = 1, where d(F(1 - q)) varies fastest
            s = np.linspace(0.0, 1.0, 1025)
            self._q_nodes = 1.0 - (1.0 - s) ** 2
            self._u_nodes = np.maximum.accumulate(self._corrected_shift(self._q_nodes))
        qn, un = self._q_nodes, self._u_nodes
        flat = np.asarray(a, dtype=float).ravel()
        j = np.clip(np.searchsorted(un, flat, side="right") - 1, 0, qn.size - 2)
        lo, hi = qn[j].copy(), qn[j + 1].copy()
        flo, fhi = un[j] - flat, un[j + 1] - flat
        side = np.zeros(flat.shape, dtype=np.int8)
        eps = 1e-15 * max(un[-1], np.finfo(float).tiny)
        # first estimate: the table's linear inverse
        du = un[j + 1] - un[j]
        q = np.clip(lo + (flat - un[j]) * (hi - lo) / np.where(du > 0, du, 1.0), lo, hi)
        act = np.arange(flat.size)          # cells not yet converged
        for _ in range(100):
            f = self._corrected_shift(q[act]) - flat[act]
            done = (np.abs(f) <= eps) | (hi[act] - lo[act] <= 1e-15)
            keep = ~done
            act, f = act[keep], f[keep]
            if act.size == 0:
                break
            left = f < 0                     # root in (q, hi]
            l_, h_, fl, fh, sd, qa = lo[act], hi[act], flo[act], fhi[act], side[act], q[act]
            # Illinois: halve the value kept at the end that stays twice in a row
            fh = np.where(left & (sd == 1), 0.5 * fh, fh)
            fl = np.where(~left & (sd == -1), 0.5 * fl, fl)
            l_ = np.where(left, qa, l_)
            fl = np.where(left, f, fl)
            h_ = np.where(left, h_, qa)
            fh = np.where(left, fh, f)
            lo[act], hi[act], flo[act], fhi[act] = l_, h_, fl, fh
            side[act] = np.where(left, 1, -1)
            denom = fh - fl
            qn = np.where(denom > 0, l_ - fl * (h_ - l_) / np.where(denom > 0, denom, 1.0),
                          0.5 * (l_ + h_))
            q[act] = np.clip(qn, l_, h_)
        return q.reshape(np.shape(a))

    def shift(self, tangential_force):
        r"""Inverse law u(F_t) [m] for |F_t| <= mu F [N] (u* at mu F; beyond: refused).

        .. math:: u = c(q)\,\frac{\mu}{r}\left[d - d\!\left(F - |F_t|/\mu\right)\right]
                  \operatorname{sign} F_t, \qquad q = \frac{|F_t|}{\mu F}

        with c the BEM table's slip correction (``method="bem"``), else c = 1.
        """
        Ft = np.asarray(tangential_force, dtype=float)
        fmax = self.gross_slip_force
        check_interval("tangential_force", Ft, -fmax * (1 + 1e-12), fmax * (1 + 1e-12),
                       unit="N", hint="more than mu F: the contact slides (no static "
                                      "equilibrium)")
        if Ft.size >= _TABLE_MIN:
            table = self._table("shift")
            if table is not None:
                return out(table(Ft, fmax, self.gross_slip_shift))

        def chain(fb):
            q = np.minimum(np.abs(fb) / fmax, 1.0)
            return np.sign(fb) * self._law_shift(q) * self._q_factor(q)

        return out(blockwise(chain, Ft))

    def stick_radius(self, shift):
        r"""MDR stick radius c = a(z) [m] with F(z) = F - |F_t(u)|/mu (0 at gross slip).

        The radius of the stick zone of the MDR profile, exact for axisymmetric
        contacts; `shift` u [m], beyond gross slip refused.
        """
        q = np.abs(np.asarray(self.force(shift), dtype=float)) / self.gross_slip_force
        rest = self.normal_force * (1.0 - q)
        res = np.zeros(q.shape)
        pos = rest > self.normal_force * 1e-14
        if np.any(pos):
            res[pos] = self.model.contact_radius(self.model.depth(rest[pos]))
        return out(res)

    def slip_state(self, shift):
        """``"stick"`` (u = 0), ``"partial slip"`` (0 < |u| < u*) or ``"gross slip"``."""
        a = np.abs(np.asarray(shift, dtype=float))
        state = np.where(a == 0, "stick",
                         np.where(a < self.gross_slip_shift, "partial slip", "gross slip"))
        return state[()] if state.ndim == 0 else state

    # -- cyclic loading (Masing) ----------------------------------------------------
    def _amplitude(self, amplitude, beyond):
        u0 = check_positive("amplitude", amplitude, "m")
        _check_beyond(beyond)
        if beyond == "raise" and np.any(u0 > self.gross_slip_shift * (1 + 1e-12)):
            raise OutOfRangeError("amplitude", float(np.max(u0)),
                                  f"(0, {self.gross_slip_shift:.6g}] m", unit="m",
                                  hint="beyond gross slip; beyond='saturate' adds the "
                                       "sliding (Coulomb) part of the loop")
        return u0

    def unloading(self, shift, amplitude, *, beyond="raise"):
        r"""Masing unloading branch from (u0, F0): F_t = F0 - 2 f((u0 - u)/2) [N].

        `shift` u in [-u0, u0] [m], `amplitude` u0 [m].
        """
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        F0 = self.force(u0, beyond=beyond)
        return out(F0 - 2 * np.asarray(self.force((u0 - u) / 2, beyond=beyond)))

    def reloading(self, shift, amplitude, *, beyond="raise"):
        r"""Masing reloading branch from (-u0, -F0): F_t = -F0 + 2 f((u0 + u)/2) [N]."""
        u0 = self._amplitude(amplitude, beyond)
        u = check_interval("shift", shift, -u0 * (1 + 1e-12), u0 * (1 + 1e-12), unit="m")
        F0 = self.force(u0, beyond=beyond)
        return out(-F0 + 2 * np.asarray(self.force((u0 + u) / 2, beyond=beyond)))

    def loop(self, amplitude, n=101, *, beyond="raise"):
        """Closed hysteresis loop of amplitude u0 [m]: (u [m], F_t [N]), 2n - 1 points.

        Unloading from (u0, F0) to (-u0, -F0), then reloading back to (u0, F0).
        """
        u0 = float(_scalar_check(self._amplitude(amplitude, beyond), "amplitude"))
        down = np.linspace(u0, -u0, int(n))
        up = down[::-1][1:]
        u = np.concatenate([down, up])
        ft = np.concatenate([self.unloading(down, u0, beyond=beyond),
                             self.reloading(up, u0, beyond=beyond)])
        return u, ft

    def _masing_energy(self, amplitude):
        """W [J] for amplitudes u0 <= u* [m], law without slip correction.

        Integrating by parts, W = 8 int_0^u0 f - 4 u0 f(u0) = 4 int_0^u0 (u0 - 2s) f'(s) ds
        with f'(s) = r k_n(d - r s/mu); as int_0^u0 (u0 - 2s) ds = 0, k_n(d) may be
        subtracted, which removes the cancellation of the O(u0^2) terms (W ~ u0^3 at
        small amplitude). 64-point Gauss-Legendre in s = u0 (1 - t^2), smooth at
        s = u* where k_n(z) ~ sqrt(z) (sphere) starts.
        """
        u0 = np.asarray(amplitude, dtype=float)
        mu, r, d = self.friction, self.ratio, self.depth
        t = 0.5 * (_GL_T + 1.0)
        w = 0.5 * _GL_W
        u = u0[..., None]
        s = u * (1.0 - t ** 2)
        z = np.maximum(d - r * s / mu, 0.0)
        kz = np.zeros(z.shape)
        pos = z > 0
        kz[pos] = self.model.stiffness(z[pos])
        kd = float(self.model.stiffness(d))
        integrand = (u - 2 * s) * (kz - kd) * 2 * u * t
        return 4 * r * np.sum(integrand * w, axis=-1)

    def _masing_energy_direct(self, amplitude):
        """W = 8 int_0^u0 f - 4 u0 f(u0) [J] by quadrature of f itself (any law, e.g. with
        the BEM slip correction; relative cancellation ~ u*/u0 at small amplitude)."""
        u0 = np.asarray(amplitude, dtype=float)
        t = 0.5 * (_GL_T + 1.0)
        w = 0.5 * _GL_W
        u = u0[..., None]
        s = u * (1.0 - t ** 2)
        f = np.asarray(self.force(s))
        integral = np.sum(f * 2 * u * t * w, axis=-1)
        return 8 * integral - 4 * u0 * np.asarray(self.force(u0))

    def dissipated_energy(self, amplitude, *, beyond="raise"):
        r"""Energy dissipated per full cycle of amplitude u0 [m]: W [J] (Masing).

        .. math:: W = 8\int_0^{u_0} f(s)\,ds - 4 u_0 f(u_0)

        Beyond gross slip (``beyond="saturate"``) the sliding part adds
        4 mu F (u0 - u*). With a BEM slip correction the formula is integrated with
        the corrected f directly.
        """
        u0 = self._amplitude(amplitude, beyond)
        ustar = self.gross_slip_shift
        if self._correction is None:
            W = self._masing_energy(np.minimum(u0, ustar))
        else:
            W = self._masing_energy_direct(np.minimum(u0, ustar))
        W = W + 4 * self.gross_slip_force * np.maximum(u0 - ustar, 0.0)
        return out(W)


def _scalar_check(value, name):
    v = np.asarray(value)
    if v.ndim:
        raise OutOfRangeError(name, f"an array of shape {v.shape}", "a single number",
                              hint="one TangentialContact per normal state; its methods "
                                   "are vectorised over the shift")
    return v


# --------------------------------------------------------------------------------------
# the finite cylinder's BEM table
# --------------------------------------------------------------------------------------
_SHIFT_COLUMN = re.compile(r"^shift_ratio_(across|along)_q([0-9.]+)$")


class CylinderTangentialTable:
    r"""The BEM table of the finite cylinder's full-stick k_t/k_n, interpolated.

    The table (``tables/tangential_cylinder.csv``, written by
    ``python -m tools.build_tables`` from the tangential BEM study) has one row per
    (nu, d~ = d R/L^2) on a regular grid, with columns ``nu``, ``d_tilde``,
    ``kt_kn_across`` (shift across the axis, the rolling direction) and
    ``kt_kn_along`` (along the axis) [-]. The self-similarity of the parabolic-gap
    cylinder (docs/theory.md, section 'Self-similarity') makes the ratios functions of
    (nu, d~) alone, for any L/R.

    Interpolated is the correction factor of the MDR, :math:`c = (k_t/k_n) /
    [2(1-\nu)/(2-\nu)]` (exactly 1 at nu = 0, smooth in nu), by the interpolating
    tensor-product spline in (nu, ln d~) (bicubic with 4 or more values per axis; of
    degree n - 1 with n = 2 or 3 values). It passes through every node. Points outside
    the grid are refused.

    Optional partial-slip correction: columns ``shift_ratio_{across|along}_q{Q}``
    (e.g. ``shift_ratio_across_q0.5``) give the BEM's tangential shift over the
    stiffness-corrected law's (:class:`TangentialContact` with this ratio) at the load
    fraction F_t/(mu F) = Q in (0, 1]; between Q values the factor is interpolated
    linearly, from 1 at Q = 0 (equal full-stick stiffness). Without such columns the
    runtime uses the stiffness-corrected law.

    Parameters
    ----------
    table : linecontact.tables.Table
        The table as read by :func:`linecontact.tables.read_table`.

    Notes
    -----
    Valid inside the table's grid: its nu and d~ ranges (the header states grid,
    tolerance and L/R used).

    Examples
    --------
    >>> import os, tempfile
    >>> from linecontact.tables import read_table, write_table
    >>> meta = dict(title="demo", source="doctest", units="[-]", generated_by="doctest",
    ...             date="2026-01-01", version="0", accuracy="none")
    >>> cols = dict(nu=[0, 0, 0.5, 0.5], d_tilde=[1e-4, 1e-2, 1e-4, 1e-2],
    ...             kt_kn_across=[1, 1, 0.8, 0.9], kt_kn_along=[1, 1, 0.6, 0.6])
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_table(os.path.join(d, "t.csv"), meta, cols)
    ...     t = CylinderTangentialTable(read_table("t", directory=d))
    >>> f"{t.ratio('along', 0.25, 1e-3):.4f}"
    '0.8143'

    References
    ----------
    Popov & Hess (2015), chapter 4 (the MDR value the factor refers to).
    """

    def __init__(self, table):
        cols = table.columns
        where = str(table.path) if table.path is not None else "table"
        for name in ("nu", "d_tilde", "kt_kn_across", "kt_kn_along"):
            if name not in cols:
                raise TableError(f"{where}: no column {name!r}")
        self.table = table
        nu, dt = cols["nu"], cols["d_tilde"]
        self.nus = np.unique(nu)
        self.d_tildes = np.unique(dt)
        n1, n2 = self.nus.size, self.d_tildes.size
        if n1 * n2 != nu.size or n1 < 2 or n2 < 2:
            raise TableError(f"{where}: (nu, d_tilde) must form a full regular grid of at "
                             f"least 2 x 2 points; got {nu.size} rows for {n1} nu and "
                             f"{n2} d_tilde values")
        if np.any(self.d_tildes <= 0) or np.any(self.nus < 0) or np.any(self.nus > 0.5):
            raise TableError(f"{where}: nu must lie in [0, 0.5] and d_tilde be > 0")
        order = np.lexsort((dt, nu))
        self._grid = {}
        mdr = 2 * (1 - nu[order]) / (2 - nu[order])
        for name in cols:
            if name in ("nu", "d_tilde"):
                continue
            vals = cols[name][order].reshape(n1, n2)
            if name.startswith("kt_kn_"):
                vals = vals / mdr.reshape(n1, n2)
            self._grid[name] = vals
        self.nu_range = Interval("nu", float(self.nus[0]), float(self.nus[-1]))
        self.d_tilde_range = Interval("d_tilde", float(self.d_tildes[0]),
                                      float(self.d_tildes[-1]), rtol=1e-12)
        from scipy.interpolate import RectBivariateSpline

        z = np.log(self.d_tildes)
        kx, ky = min(3, n1 - 1), min(3, n2 - 1)
        self._splines = {name: RectBivariateSpline(self.nus, z, vals, kx=kx, ky=ky, s=0)
                         for name, vals in self._grid.items()}
        self._shift_q = {}
        for name in cols:
            m = _SHIFT_COLUMN.match(name)
            if m:
                self._shift_q.setdefault(m.group(1), []).append((float(m.group(2)), name))
        for direction, items in self._shift_q.items():
            items.sort()
            if not all(0 < q <= 1 for q, _ in items):
                raise TableError(f"{where}: shift_ratio columns need 0 < Q <= 1")

    @property
    def provenance(self):
        """The table's metadata (title, source, generated_by, grid, accuracy, ...)."""
        return dict(self.table.meta)

    def _interp(self, name, nu, d_tilde):
        nu = self.nu_range.check(nu, hint="outside the BEM table of the cylinder")
        dt = self.d_tilde_range.check(d_tilde, name="d_tilde",
                                      hint="d R/L^2 outside the BEM table of the cylinder")
        nu, dt = np.broadcast_arrays(nu, dt)
        res = self._splines[name].ev(nu.ravel(), np.log(dt.ravel()))
        return res.reshape(nu.shape)

    def ratio(self, direction, nu, d_tilde):
        """Full-stick k_t/k_n [-] in `direction` ("across"/"along") at (nu, d~)."""
        if direction not in _DIRECTIONS:
            raise UnknownNameError("direction", direction, _DIRECTIONS)
        c = self._interp(f"kt_kn_{direction}", nu, d_tilde)
        nu = np.asarray(nu, dtype=float)
        return out(c * 2 * (1 - nu) / (2 - nu))

    def value(self, column, nu, d_tilde):
        """Any column of the table [its unit] interpolated at (nu, d~) (e.g. the study's
        measured partial-slip error ``ft_err_scaled_across``)."""
        if column not in self._grid:
            raise UnknownNameError("column", column, list(self._grid))
        v = self._interp(column, nu, d_tilde)
        if column.startswith("kt_kn_"):
            nu = np.asarray(nu, dtype=float)
            v = v * 2 * (1 - nu) / (2 - nu)
        return out(v)

    @property
    def has_slip_correction(self):
        """True if the table carries a partial-slip correction (both directions)."""
        return all(d in self._shift_q for d in _DIRECTIONS)

    def _interp_many(self, names, nu, d_tilde):
        """Several columns at the same points (one range check): shape (len(names), ...)."""
        nu = self.nu_range.check(nu, hint="outside the BEM table of the cylinder")
        dt = self.d_tilde_range.check(d_tilde, name="d_tilde",
                                      hint="d R/L^2 outside the BEM table of the cylinder")
        nu, dt = np.broadcast_arrays(nu, dt)
        x, z = nu.ravel(), np.log(dt.ravel())
        return np.array([self._splines[n].ev(x, z).reshape(nu.shape) for n in names])

    def shift_correction(self, direction, nu, d_tilde):
        """(Q nodes, shift factors) at (nu, d~) including (0, 1), or None if absent."""
        items = self._shift_q.get(direction)
        if not items:
            return None
        qs = [0.0] + [q for q, _ in items]
        cs = [1.0] + list(self._interp_many([name for _, name in items], nu, d_tilde))
        return np.array(qs), np.array(cs, dtype=float)

    def shift_factor(self, direction, nu, d_tilde, q):
        """The partial-slip shift factor c(q) [-] at load fractions q in [0, 1] (1 where
        the table has no correction), vectorised over (nu, d~, q)."""
        items = self._shift_q.get(direction)
        nu, dt, q = np.broadcast_arrays(np.asarray(nu, float), np.asarray(d_tilde, float),
                                        np.asarray(q, float))
        if not items:
            return out(np.ones(q.shape))
        qs = np.array([0.0] + [qq for qq, _ in items])
        cs = self._interp_many([name for _, name in items], nu, dt)     # (nQ, ...)
        cs = np.concatenate([np.ones((1,) + nu.shape), cs]).reshape(qs.size, -1)
        qf = np.clip(q.ravel(), 0.0, 1.0)
        j = np.clip(np.searchsorted(qs, qf, side="right") - 1, 0, qs.size - 2)
        cols = np.arange(qf.size)
        w = (qf - qs[j]) / (qs[j + 1] - qs[j])
        res = cs[j, cols] * (1 - w) + cs[j + 1, cols] * w
        return out(res.reshape(q.shape))


@functools.lru_cache(maxsize=None)
def _cached_table(name):
    return CylinderTangentialTable(read_table(name))


def cylinder_tangential_table(name=TANGENTIAL_TABLE, directory=None):
    r"""The :class:`CylinderTangentialTable` of ``tables/<name>.csv`` (cached).

    .. math:: \frac{k_t}{k_n} = c(\nu, \ln\tilde d)\,\frac{2(1-\nu)}{2-\nu}

    with c the table's correction factor of the MDR, interpolated.

    Parameters
    ----------
    name : str, optional
        Table stem (default ``"tangential_cylinder"``).
    directory : path-like, optional
        Read from this folder instead of ``tables/`` (not cached).

    Returns
    -------
    CylinderTangentialTable

    Raises
    ------
    FileNotFoundError
        The table is not there (the BEM study has not been run).

    Notes
    -----
    Valid for tables with the columns nu, d_tilde, kt_kn_across, kt_kn_along on a
    regular (nu, d~) grid.

    Examples
    --------
    >>> cylinder_tangential_table("no_such_table")
    Traceback (most recent call last):
    ...
    FileNotFoundError: table 'no_such_table' not found in ...

    References
    ----------
    Popov & Hess (2015), chapter 4.
    """
    if directory is not None:
        return CylinderTangentialTable(read_table(name, directory=directory))
    return _cached_table(name)


def cylinder_stiffness_ratios(model, depth, gstar, *, table=None):
    r"""The finite cylinder's full-stick k_t/k_n across and along the axis, and the MDR's.

    .. math::

        \frac{k_t}{k_n}\Big|_{dir} = T_{dir}\!\left(\nu_{eq}, \frac{dR}{L^2}\right),
        \qquad \frac{k_t}{k_n}\Big|_{MDR} = \frac{G^*}{E^*}
        = \frac{2(1-\nu_{eq})}{2-\nu_{eq}}

    with T the BEM table and :math:`\nu_{eq}` = :func:`equivalent_poisson` (G*, E*).

    Parameters
    ----------
    model : linecontact.models.ContactModel
        A straight-cylinder model (:data:`STRAIGHT_CYLINDER_MODELS`); its R, L and E*
        are used.
    depth : float or array_like
        Normal depth d [m].
    gstar : float
        Effective shear modulus G* [Pa].
    table : CylinderTangentialTable, optional
        Default :func:`cylinder_tangential_table`.

    Returns
    -------
    dict
        ``across``, ``along``, ``mdr`` (k_t/k_n [-]), ``mdr_error_across``,
        ``mdr_error_along`` (MDR/BEM - 1 [-]), ``nu`` and ``d_tilde`` [-]; if the table
        has the study's columns ``ft_err_scaled_{across,along}``, also
        ``slip_error_across``, ``slip_error_along``: the largest difference between
        the BEM's partial-slip curve and the law with this ratio, over mu F [-].

    Notes
    -----
    Valid inside the table's (nu, d R/L^2) grid; refused outside. The ratios belong
    to the BEM's normal contact of a rigid straight cylinder with the parabolic gap
    (d/R <= 0.15 in the study), any L/R.

    Examples
    --------
    With a made-up 2 x 2 table (the shipped one comes from the BEM study):

    >>> import os, tempfile
    >>> from linecontact.models import get_model
    >>> from linecontact.tables import read_table, write_table
    >>> meta = dict(title="demo", source="doctest", units="[-]", generated_by="doctest",
    ...             date="2026-01-01", version="0", accuracy="none")
    >>> cols = dict(nu=[0, 0, 0.5, 0.5], d_tilde=[1e-4, 1e-2, 1e-4, 1e-2],
    ...             kt_kn_across=[1, 1, 0.8, 0.9], kt_kn_along=[1, 1, 0.6, 0.6])
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_table(os.path.join(d, "t.csv"), meta, cols)
    ...     t = CylinderTangentialTable(read_table("t", directory=d))
    >>> m = get_model("kunz", 5e-3, 10e-3, effective_modulus(210e9, 0.3))
    >>> r = cylinder_stiffness_ratios(m, 1e-5, effective_shear_modulus(210e9, 0.3), table=t)
    >>> f"{r['across']:.4f} {r['along']:.4f} {r['mdr']:.4f} d~ = {r['d_tilde']:.0e}"
    '0.9483 0.7741 0.8235 d~ = 5e-04'

    References
    ----------
    Popov & Hess (2015), chapter 4 (MDR value); the BEM table's header (its source).
    """
    key = getattr(model, "key", "")
    if key not in STRAIGHT_CYLINDER_MODELS:
        raise OutOfRangeError("model", key or type(model).__name__,
                              "one of " + ", ".join(sorted(STRAIGHT_CYLINDER_MODELS)),
                              hint="the BEM table is for a straight, aligned cylinder; "
                                   "use method='mdr' for other shapes")
    table = table if table is not None else cylinder_tangential_table()
    d = check_positive("depth", depth, "m")
    nu = equivalent_poisson(gstar, model.estar)
    d_tilde = d * model.radius / model.length ** 2
    across = table.ratio("across", nu, d_tilde)
    along = table.ratio("along", nu, d_tilde)
    mdr = mdr_stiffness_ratio(nu)
    res = {"across": across, "along": along, "mdr": out(np.broadcast_to(mdr, np.shape(d))),
           "mdr_error_across": out(mdr / np.asarray(across) - 1),
           "mdr_error_along": out(mdr / np.asarray(along) - 1),
           "nu": nu, "d_tilde": out(d_tilde)}
    for side in _DIRECTIONS:   # the study's measured error of the partial-slip law
        column = f"ft_err_scaled_{side}"
        if column in table._grid:
            res[f"slip_error_{side}"] = table.value(column, nu, d_tilde)
    return res


# An unknown keyword names the valid ones and the close match (docs/inputs.md).
from .validity import refuse_unknown_keywords  # noqa: E402
refuse_unknown_keywords(globals())
