r"""Tangential contact of any model: the Cattaneo-Mindlin laws from the normal law.

The method of dimensionality reduction (Popov & Hess 2015, chapter 4) gives every
normal-contact law F(d) a tangential companion. The 1D springs of the MDR profile carry
a tangential stiffness :math:`G^*\,dx` besides the normal one :math:`E^*\,dx` (G*:
:mod:`linecontact.tangential.moduli`), and each spring sticks while :math:`G^*|u(x)| \le \mu E^*(d - g(x))`. With the shear
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

import numpy as np

from .._numerics import blockwise, out
from ..checks import Interval, check_interval, check_positive
from ..errors import OutOfRangeError, UnknownNameError
from .cylinder_table import _DIRECTIONS, cylinder_stiffness_ratios
from .moduli import _ratio

__all__ = [
    "gross_slip_shift",
    "tangential_stiffness",
    "tangential_force",
    "tangential_shift",
    "FRICTION",
]

FRICTION = Interval("friction", 0.0, np.inf, low_open=True, high_open=True)
_METHODS = ("mdr", "bem")


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

    >>> from linecontact.classical import effective_modulus
    >>> from linecontact.tangential import effective_shear_modulus
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


def _amplitude(amplitude, beyond, gross_slip_shift, hint):
    """A fretting amplitude u0 > 0 [m], checked against the gross-slip shift when
    ``beyond="raise"`` (`hint` ends the refusal: what beyond gross slip means there)."""
    u0 = check_positive("amplitude", amplitude, "m")
    _check_beyond(beyond)
    if beyond == "raise" and np.any(u0 > gross_slip_shift * (1 + 1e-12)):
        raise OutOfRangeError("amplitude", float(np.max(u0)),
                              f"(0, {gross_slip_shift:.6g}] m", unit="m", hint=hint)
    return u0


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
