r"""Adhesive (JKR-type) normal contact of any MDR profile, by the rule of Hess.

In the method of dimensionality reduction (Popov & Hess 2015, chapter 5) the adhesive
contact of half-length a is the non-adhesive one with its two edge springs pulled out
by :math:`\Delta l(a) = \sqrt{2\pi a w/E^*}`, w the work of adhesion:

.. math::

    d(a) = g(a) - \sqrt{\frac{2\pi a w}{E^*}}, \qquad
    F(a) = F_N(a) - \sqrt{8\pi a^3 E^* w}, \qquad
    F_N(a) = 2E^*\int_0^a \bigl(g(a) - g(x)\bigr)\,dx .

:class:`AdhesiveContact` evaluates this for any profile g (or any
:class:`~linecontact.models.ContactModel` with one, :meth:`AdhesiveContact.from_model`):
force against depth on both branches, the pull-off force under force control
(dF/da = 0) and under depth control (dd/da = 0), the state at zero load, and the
approach/retraction hysteresis. The rule is exact for axisymmetric bodies: the JKR
sphere (Johnson, Kendall & Roberts 1971; pull-off :math:`\tfrac32\pi wR` under force
control, :math:`\tfrac56\pi wR` under depth control) and Kendall's flat punch
(:math:`F = -\sqrt{8\pi a^3E^*w}`) come out of the same code.

For an elongated contact it is an approximation, as the MDR's tangential rule is: the
MDR half-length a = k/(2E*) of a long roller is of the order of its length, not of the
strip's half-width b, so the edge term :math:`\sqrt{8\pi a^3E^*w}` misses the 2D JKR
law of the long cylinder (Barquins 1988; Chaudhury et al. 1996), per unit length

.. math::

    \frac{F}{L} = \frac{\pi E^* b^2}{4R} - \sqrt{2\pi E^* w b}, \qquad
    \frac{F_c}{L} = -3\left(\frac{\pi E^* R w^2}{16}\right)^{1/3}
    \ \text{at}\ b_c = \left(\frac{2R^2 w}{\pi E^*}\right)^{1/3} .

:class:`CylinderAdhesion` gives the finite cylinder's pull-off force from the adhesive
boundary-element table ``tables/adhesion_cylinder.csv`` (``python -m tools.build_tables
adhesion``), in the self-similar variables of the parabolic cylinder
(docs/theory.md, section 'Self-similarity'; docs/adhesion.md): with
:math:`\tilde w = wR^2/(E^*L^3)` the ratio of the pull-off force to the 2D JKR value
:math:`F_c/(L\,F_{c,2D}/L)` is one function of :math:`s = b_c/L = (2\tilde w/\pi)^{1/3}`
for every L/R. The 2D law holds per unit length in the middle of a long roller, but the
whole roller's ratio does not tend to 1 as s -> 0: below s of about 0.08 the contact
unzips from its ends before its middle reaches b_c, and the ratio falls with s. Below
the BEM table (s < 0.025, most real rollers) the pull-off comes from
``tables/adhesion_long_roller.csv`` (``python -m tools.build_tables adhesion-long``),
down to s = 1e-3, with its stated error: an end model, the ends peeling when the energy
release rate :math:`G_e = f^2(k\ln(L/b) + c)/(2\pi E^* b)` of the line-loaded strip
(f the middle's tension per unit length, b its half-width) reaches w, k and c fitted
on the BEM, including BEM runs below the table; the ratio falls as
:math:`(4/3)\,16^{1/6}/\sqrt{k\ln(1/s)}` as s -> 0, never to the 2D value
(docs/adhesion.md). The plain MDR value is given beside it, by name
(``method='mdr'``), with its error measured against the same BEM or end model.

JKR needs a large Tabor parameter :math:`\mu_T = (R w^2/(E^{*2} z_0^3))^{1/3}`
(:func:`tabor_parameter`, z0 about 0.3 nm, the range of the surface forces); below
about 1 the contact is DMT-like (Derjaguin, Muller & Toporov 1975) and the JKR results
here overestimate the pull-off's dependence on E* (:func:`tabor_note`).

All functions take SI units: m, N, Pa, J/m^2.

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapter 5 (the rule of Hess).
.. [2] K. L. Johnson, K. Kendall, A. D. Roberts, Surface energy and the contact of
   elastic solids, Proc. R. Soc. Lond. A 324 (1971) 301-313.
.. [3] K. Kendall, The adhesion and surface energy of elastic solids, J. Phys. D 4
   (1971) 1186-1195.
.. [4] M. Barquins, Adherence and rolling kinetics of a rigid cylinder in contact with
   a natural rubber surface, J. Adhesion 26 (1988) 1-12.
.. [5] M. K. Chaudhury, T. Weaver, C. Y. Hui, E. J. Kramer, Adhesive contact of
   cylindrical lens and a flat sheet, J. Appl. Phys. 80 (1996) 30-37.
.. [6] D. Tabor, Surface forces and surface interactions, J. Colloid Interface Sci. 58
   (1977) 2-13.
.. [7] R. Pohrt, V. L. Popov, Adhesive contact simulation of elastic solids using local
   mesh-dependent detachment criterion in boundary elements method, Facta Universitatis,
   Series Mechanical Engineering 13(1) (2015) 3-10.
"""
from __future__ import annotations

import functools

import numpy as np

from ._numerics import out
from .checks import Interval, check_positive, document
from .errors import OutOfRangeError, UnknownNameError
from .tables import TableError, read_table

__all__ = [
    "AdhesiveContact",
    "CylinderAdhesion",
    "tabor_parameter",
    "tabor_note",
    "jkr_cylinder_force_per_length",
    "jkr_cylinder_pull_off",
    "jkr_cylinder_zero_load_half_width",
    "ADHESION_TABLE",
    "LONG_ROLLER_TABLE",
    "CYLINDER_MODELS",
    "TABOR_JKR",
    "TABOR_DMT",
]

#: Name of the BEM table of the finite cylinder's adhesion (tables/).
ADHESION_TABLE = "adhesion_cylinder"

#: Name of the long roller's pull-off table below the BEM table (tables/): the end
#: model calibrated on the BEM (python -m tools.build_tables adhesion-long).
LONG_ROLLER_TABLE = "adhesion_long_roller"

#: Tabor parameter above which the JKR theory holds (Johnson & Greenwood 1997's
#: adhesion map: JKR for mu_T > about 5), and below which the contact is DMT-like.
TABOR_JKR = 5.0
TABOR_DMT = 1.0

_ESTAR = Interval("estar", 0.0, np.inf, low_open=True, high_open=True, unit="Pa")
_WORK = Interval("work", 0.0, np.inf, high_open=True, unit="J/m^2")
_RADIUS = Interval("radius", 0.0, np.inf, low_open=True, high_open=True, unit="m")
_Z0 = Interval("z0", 0.0, np.inf, low_open=True, high_open=True, unit="m")
_CONTROLS = ("force", "depth")
_METHODS = ("bem", "mdr")
_BRANCHES = ("stable", "unstable")
#: Points of the log-spaced scan of a that brackets the extrema before refinement.
_SCAN = 241
#: Depths below which a model's F_N(a) is taken as 0 (subnormal numbers are refused).
_NEGLIGIBLE_DEPTH = 1e-200
_GL_T, _GL_W = np.polynomial.legendre.leggauss(48)


def _one(name, value, interval):
    v = np.asarray(interval.check(value, name=name))
    if v.ndim:
        raise OutOfRangeError(name, f"an array of shape {v.shape}", "a single number")
    return float(v)


# --------------------------------------------------------------------------------------
# Tabor parameter
# --------------------------------------------------------------------------------------
@document(R=_RADIUS, W=_WORK, E=_ESTAR, Z=_Z0)
def tabor_parameter(radius, work, estar, z0=0.3e-9):
    r"""Tabor parameter of an adhesive contact, the JKR/DMT discriminant.

    .. math:: \mu_T = \left(\frac{R\,w^2}{E^{*2} z_0^3}\right)^{1/3}

    Parameters
    ----------
    radius : float or array_like
        Radius of curvature R of the gap across the contact (a roller's radius) [m].
    work : float or array_like
        Work of adhesion w [J/m^2].
    estar : float or array_like
        Effective modulus E* [Pa].
    z0 : float, optional
        Equilibrium spacing of the surface forces, about 0.3 nm (default) [m].

    Returns
    -------
    float or ndarray
        mu_T [-]: JKR holds for mu_T > about 5, DMT below about 1
        (:data:`TABOR_JKR`, :data:`TABOR_DMT`; :func:`tabor_note`).

    Notes
    -----
    Valid for %(R)s, %(W)s, %(E)s and %(Z)s. For a roller the relevant curvature is
    that across the contact strip, R; the length plays no part (the stress field at the
    strip's edge is that of the 2D contact).

    Examples
    --------
    A PDMS roller (E* = 2.7 MPa), R = 1 mm, w = 50 mJ/m^2: deep in the JKR regime; a
    steel fibre (E* = 115 GPa) of R = 1 um with the same w is DMT-like:

    >>> f"{tabor_parameter(1e-3, 0.05, 2.7e6):.0f}", f"{tabor_parameter(1e-6, 0.05, 115e9):.2f}"
    ('2333', '0.19')

    References
    ----------
    .. [1] D. Tabor, Surface forces and surface interactions, J. Colloid Interface
       Sci. 58 (1977) 2-13.
    .. [2] K. L. Johnson, J. A. Greenwood, An adhesion map for the contact of elastic
       spheres, J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    R = _RADIUS.check(radius)
    w = _WORK.check(work)
    E = _ESTAR.check(estar)
    z = _Z0.check(z0)
    return out(np.cbrt(R * w ** 2 / (E ** 2 * z ** 3)))


def tabor_note(mu):
    """The regime of a Tabor parameter in words: JKR, transition or DMT-like.

    Parameters
    ----------
    mu : float
        Tabor parameter mu_T, 0 <= mu_T < inf [-].

    Returns
    -------
    str
        One line; it says where the JKR results do not apply.

    Notes
    -----
    Thresholds :data:`TABOR_JKR` (5) and :data:`TABOR_DMT` (1), after Johnson &
    Greenwood's (1997) adhesion map. Valid for 0 <= mu_T < inf.

    Examples
    --------
    >>> tabor_note(0.2)
    'mu_T = 0.2 < 1: DMT-like, JKR does not apply (its pull-off force is too high by up to 4/3; DMT gives 2 pi w R for a sphere, stiff bodies with long-range forces)'

    References
    ----------
    K. L. Johnson, J. A. Greenwood, J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    m = _one("mu", mu, Interval("mu", 0.0, np.inf, high_open=True))
    if m >= TABOR_JKR:
        return f"mu_T = {m:.3g} >= {TABOR_JKR:g}: JKR regime"
    if m >= TABOR_DMT:
        return (f"mu_T = {m:.3g}: between DMT ({TABOR_DMT:g}) and JKR ({TABOR_JKR:g}); "
                "JKR is approximate (Maugis-Dugdale transition)")
    return (f"mu_T = {m:.3g} < {TABOR_DMT:g}: DMT-like, JKR does not apply (its pull-off "
            "force is too high by up to 4/3; DMT gives 2 pi w R for a sphere, stiff "
            "bodies with long-range forces)")


# --------------------------------------------------------------------------------------
# the rule of Hess for any profile
# --------------------------------------------------------------------------------------
class AdhesiveContact:
    r"""JKR-type adhesive contact of an MDR profile g(x) by the rule of Hess.

    .. math::

        d(a) = g(a) - \sqrt{2\pi a w/E^*}, \qquad
        F(a) = F_N(a) - \sqrt{8\pi a^3 E^* w}

    Parameters
    ----------
    profile : callable
        The MDR profile g(x) [m] at x >= 0 [m]; monotone increasing, g(0) = 0.
    estar : float
        Effective modulus E*, 0 < E* < inf [Pa].
    work : float
        Work of adhesion w, 0 <= w < inf [J/m^2] (0: the non-adhesive law exactly).
    normal_force : callable, optional
        F_N(a) [N] of the non-adhesive contact of half-length a [m], if known in closed
        form (e.g. a model's F(g(a))); default: 2 E* times the integral of g(a) - g(x)
        over 0..a by 48-point Gauss-Legendre quadrature.
    x_max : float, optional
        The largest half-length at which `profile` is defined, 0 < x_max <= inf [m]
        (a tabulated profile's end; default inf).
    x_scale : float, optional
        A typical half-length, where the scan for the extrema starts,
        0 < x_scale < inf [m] (default: the half-length at which the edge stretch
        sqrt(2 pi a w/E*) equals g(a), found by doubling from 1 m).

    Notes
    -----
    Valid for 0 < E* < inf and 0 <= w < inf, for a profile that is monotone and
    convex enough that d(a) has one minimum (true for power laws g = c x^n, n > 1/2,
    and the finite cylinder's). The extrema (pull-off under both controls) are found
    on a log-spaced scan of a over 12 decades around `x_scale` and refined by Brent's
    method to a relative 1e-12 in a; one lying on the scan's end raises
    :class:`~linecontact.errors.OutOfRangeError` (e.g. beyond `x_max`). Exact for
    axisymmetric bodies; for elongated contacts see :class:`CylinderAdhesion`.

    Examples
    --------
    The JKR sphere (g = x^2/R): pull-off 1.5 pi w R under force control, 5/6 pi w R
    under depth control, independent of E*:

    >>> R, E, w = 10e-3, 1e6, 0.05
    >>> c = AdhesiveContact(lambda x: x**2 / R, E, w)
    >>> f"{c.pull_off('force')['force'] / (1.5 * np.pi * w * R):.9f}"
    '-1.000000000'
    >>> f"{c.pull_off('depth')['force'] / (5 / 6 * np.pi * w * R):.7f}"
    '-1.0000000'

    References
    ----------
    .. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015), chapter 5.
    .. [2] K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. Lond. A 324
       (1971) 301-313.
    """

    def __init__(self, profile, estar, work, *, normal_force=None, x_max=np.inf,
                 x_scale=None):
        self.profile = profile
        self.estar = _one("estar", estar, _ESTAR)
        self.work = _one("work", work, _WORK)
        self.x_max = _one("x_max", x_max, Interval("x_max", 0.0, np.inf, low_open=True,
                                                   unit="m"))
        self._normal_force = normal_force
        if x_scale is None:
            x_scale = self._natural_scale()
        self.x_scale = _one("x_scale", x_scale, Interval(
            "x_scale", 0.0, np.inf, low_open=True, high_open=True, unit="m"))

    @classmethod
    def from_model(cls, model, work):
        """The rule of Hess on a model's MDR profile (its own F(d) gives F_N(a)).

        Parameters
        ----------
        model : linecontact.models.ContactModel
            A model with an MDR profile (``model.profile``); a model without one
            raises NotImplementedError with its reason.
        work : float
            Work of adhesion w, 0 <= w < inf [J/m^2].

        Returns
        -------
        AdhesiveContact

        Notes
        -----
        Valid for the model's own range of depth: the half-length is bounded
        (``x_max``) by the model's ``depth_limit`` where it has one (the universal
        curve), else by d = 0.15 R (the parabolic gap's range).

        Examples
        --------
        >>> from linecontact.models import get_model
        >>> m = get_model("universal", 5e-3, 10e-3, 2.7e6)
        >>> c = AdhesiveContact.from_model(m, 0.05)
        >>> f"{c.pull_off('force')['force'] * 1e3:.2f} mN"
        '-86.18 mN'
        """
        model.profile(np.asarray(0.5 * model.radius * 1e-3))   # no profile: raises
        # the model's own depth range bounds the half-length (d/R <= 0.15 or a table's
        # end: UniversalModel.depth_limit)
        d_lim = getattr(model, "depth_limit", 0.15 * model.radius)
        x_max = float(model.contact_radius(d_lim))

        def normal_force(a):
            a = np.asarray(a, dtype=float)
            d = np.asarray(model.profile(a), dtype=float)
            res = np.zeros_like(d)
            pos = d > _NEGLIGIBLE_DEPTH   # below: F_N underflows (cylinder: g ~ e^(-L/a))
            if np.any(pos):
                res[pos] = model.force(d[pos])
            return res

        return cls(model.profile, model.estar, work, normal_force=normal_force,
                   x_max=x_max, x_scale=model.length * 0.05)

    # ---- the law in terms of a ------------------------------------------------------
    def _g(self, a):
        a = np.asarray(a, dtype=float)
        return np.vectorize(lambda v: float(self.profile(v)), otypes=[float])(a) \
            if a.ndim else np.asarray(float(self.profile(float(a))))

    def _natural_scale(self):
        if self.work == 0:
            return 1.0
        a = 1.0
        for _ in range(200):
            if a > self.x_max:
                a = self.x_max / 2
                break
            g = float(self._g(a))
            if g < np.sqrt(2 * np.pi * a * self.work / self.estar):
                break
            a /= 2.0
        return a

    def normal_force(self, a):
        """Non-adhesive force F_N(a) [N] at MDR half-length a [m]."""
        a = check_positive("a", a, "m")
        if self._normal_force is not None:
            return out(np.asarray(self._normal_force(a), dtype=float))
        flat = []
        for av in np.atleast_1d(a).ravel():
            x = 0.5 * av * (_GL_T + 1)
            g = self._g(x)
            flat.append(2 * self.estar * 0.5 * av * float(np.dot(_GL_W, float(self._g(av)) - g)))
        return out(np.array(flat).reshape(np.shape(a)))

    def edge_stretch(self, a):
        """Stretch of the edge springs at detachment, sqrt(2 pi a w/E*) [m], at a [m]."""
        a = check_positive("a", a, "m")
        return out(np.sqrt(2 * np.pi * a * self.work / self.estar))

    def depth(self, a):
        """Depth d(a) = g(a) - sqrt(2 pi a w/E*) [m] at MDR half-length a [m]."""
        a = check_positive("a", a, "m")
        return out(self._g(a) - np.sqrt(2 * np.pi * a * self.work / self.estar))

    def force(self, a):
        """Force F(a) = F_N(a) - sqrt(8 pi a^3 E* w) [N] at MDR half-length a [m]."""
        a = check_positive("a", a, "m")
        return out(np.asarray(self.normal_force(a)) - np.sqrt(8 * np.pi * a ** 3 *
                                                              self.estar * self.work))

    @property
    def _a_top(self):
        """The largest half-length evaluated: just inside x_max (rounding)."""
        return self.x_max * (1 - 1e-9) if np.isfinite(self.x_max) else np.inf

    # ---- extrema ----------------------------------------------------------------------
    def _argmin(self, fun, what):
        from scipy.optimize import minimize_scalar

        lo = self.x_scale * 1e-6
        hi = min(self.x_scale * 1e6, self.x_max * (1 - 1e-9))
        a = np.geomspace(lo, hi, _SCAN)
        v = np.array([float(fun(x)) for x in a])
        i = int(np.argmin(v))
        if i == 0 or i == a.size - 1:
            raise OutOfRangeError(
                "work", self.work, f"a value whose {what} lies inside a = {lo:.3g} .. "
                f"{hi:.3g} m", unit="J/m^2",
                hint="the extremum is at the end of the scan (beyond the profile's end, "
                     "or w = 0: no adhesion, no pull-off)")
        res = minimize_scalar(lambda z: float(fun(np.exp(z))),
                              bracket=(np.log(a[i - 1]), np.log(a[i]), np.log(a[i + 1])),
                              method="brent", tol=1e-12)
        return float(np.exp(res.x))

    @functools.cached_property
    def _a_force(self):
        return self._argmin(self.force, "smallest force")

    @functools.cached_property
    def _a_depth(self):
        return self._argmin(self.depth, "smallest depth")

    def pull_off(self, control="force"):
        """Pull-off state under force or depth control.

        Parameters
        ----------
        control : {'force', 'depth'}
            Force control: the smallest force along the stable branch, dF/da = 0.
            Depth control: the force at the smallest depth, dd/da = 0.

        Returns
        -------
        dict
            ``force`` [N] (negative: tensile), ``depth`` [m], ``contact_radius``: the
            MDR half-length a [m] at the instability.
        """
        if control not in _CONTROLS:
            raise UnknownNameError("control", control, _CONTROLS)
        if self.work == 0:
            raise OutOfRangeError("work", 0.0, "0 < w < inf J/m^2",
                                  hint="without adhesion there is no pull-off force")
        a = self._a_force if control == "force" else self._a_depth
        return {"force": float(self.force(a)), "depth": float(self.depth(a)),
                "contact_radius": a}

    def zero_load(self):
        """MDR half-length and depth at zero force on the stable branch.

        Returns
        -------
        dict
            ``contact_radius`` a0 [m] with F(a0) = 0 and ``depth`` d(a0) [m].
        """
        from scipy.optimize import brentq

        if self.work == 0:
            return {"contact_radius": 0.0, "depth": 0.0}
        lo = self._a_force
        hi = lo
        for _ in range(200):
            hi *= 2
            if hi >= self.x_max:
                hi = self.x_max * (1 - 1e-9)
                break
            if float(self.force(hi)) > 0:
                break
        if float(self.force(hi)) <= 0:
            raise OutOfRangeError("work", self.work, "a value with zero load inside the "
                                  "profile's range", unit="J/m^2",
                                  hint="the zero-load contact lies beyond the profile's end")
        a0 = brentq(lambda x: float(self.force(x)), lo, hi, xtol=lo * 1e-13, rtol=1e-13)
        return {"contact_radius": a0, "depth": float(self.depth(a0))}

    def radius_at_depth(self, depth, branch="stable"):
        """MDR half-length a at depth d on the stable (a > a_d) or unstable branch [m].

        Depths below the depth-controlled pull-off have no contact and raise
        :class:`~linecontact.errors.OutOfRangeError` naming the range.
        """
        from scipy.optimize import brentq

        if branch not in _BRANCHES:
            raise OutOfRangeError("branch", branch, "one of 'stable', 'unstable'")
        d = np.atleast_1d(np.asarray(depth, dtype=float))
        if self.work == 0:
            if branch == "unstable":
                raise OutOfRangeError("branch", branch, "'stable'",
                                      hint="without adhesion there is one branch")
            lo_d, a_d = 0.0, 0.0
        else:
            a_d = self._a_depth
            lo_d = float(self.depth(a_d))
        bad = ~(d >= lo_d) | ~np.isfinite(d)
        if branch == "unstable":
            bad |= d >= 0
        if np.any(bad) or (self.work == 0 and np.any(d <= 0)):
            v = float(d[bad | (d <= 0 if self.work == 0 else bad)][0])
            hi_txt = "0" if branch == "unstable" else "inf"
            raise OutOfRangeError("depth", v, f"{lo_d:.6g} <= d < {hi_txt} m", unit="m",
                                  hint="below the depth-controlled pull-off there is no "
                                       "contact" if self.work else "")
        res = []
        for dv in d:
            if branch == "stable":
                lo = max(a_d, self.x_scale * 1e-9)
                hi = min(lo * 2, self._a_top)
                while float(self.depth(hi)) < dv:
                    if hi >= self._a_top:
                        raise OutOfRangeError("depth", float(dv), f"d <= "
                                              f"{float(self.depth(hi)):.6g} m", unit="m",
                                              hint="the profile's (the model's) range of "
                                                   "depth ends there")
                    hi = min(hi * 2, self._a_top)
                if float(self.depth(lo)) >= dv:
                    res.append(lo)
                    continue
            else:
                lo, hi = self.x_scale * 1e-12, a_d
            res.append(brentq(lambda x: float(self.depth(x)) - dv, lo, hi,
                              xtol=lo * 1e-12, rtol=1e-13))
        return out(np.array(res).reshape(np.shape(depth)))

    def depth_at_force(self, force):
        """Depth d [m] at force F [N] on the force-controlled stable branch (a > a_F).

        Forces below the force-controlled pull-off have no contact and raise
        :class:`~linecontact.errors.OutOfRangeError` naming the range.
        """
        from scipy.optimize import brentq

        F = np.atleast_1d(np.asarray(force, dtype=float))
        if self.work == 0:
            lo_F, a_lo = 0.0, self.x_scale * 1e-9
        else:
            a_lo = self._a_force
            lo_F = float(self.force(a_lo))
        bad = ~(F >= lo_F) | ~np.isfinite(F) | ((F <= 0) if self.work == 0 else False)
        if np.any(bad):
            raise OutOfRangeError("force", float(F[bad][0]), f"{lo_F:.6g} <= F < inf N"
                                  if self.work else "0 < F < inf N", unit="N",
                                  hint="below the force-controlled pull-off there is no "
                                       "contact" if self.work else "")
        res = []
        for Fv in F:
            hi = min(a_lo * 2, self._a_top)
            while float(self.force(hi)) < Fv:
                if hi >= self._a_top:
                    raise OutOfRangeError("force", float(Fv), f"F <= {float(self.force(hi)):.6g}"
                                          " N", unit="N", hint="the profile's (the model's) "
                                          "range of depth ends there")
                hi = min(hi * 2, self._a_top)
            a = a_lo if float(self.force(a_lo)) >= Fv else brentq(
                lambda x: float(self.force(x)) - Fv, a_lo, hi, xtol=a_lo * 1e-12,
                rtol=1e-13)
            res.append(float(self.depth(a)))
        return out(np.array(res).reshape(np.shape(force)))

    def force_at_depth(self, depth, branch="stable"):
        """Force F at depth d [N] on the stable or unstable branch; depth [m]."""
        return self.force(self.radius_at_depth(depth, branch))

    def hysteresis(self, depth_max, n=201):
        """Approach and retraction under depth control, and the energy lost per cycle.

        Approach: no force until first contact at d = 0, where the contact jumps to the
        stable branch (F jumps to F(d = 0) < 0), then the stable branch up to
        `depth_max`. Retraction: the stable branch down to the depth-controlled
        pull-off, where the contact jumps off (F jumps to 0).

        Parameters
        ----------
        depth_max : float
            Deepest point of the cycle, 0 < depth_max < inf [m].
        n : int
            Points per curve (default 201) [-].

        Returns
        -------
        dict
            ``approach_depth``, ``approach_force``, ``retraction_depth``,
            ``retraction_force`` (ndarray, m and N) and ``energy``: the work lost per
            cycle [J], the area between the curves,
            the integral of -F(d) on the stable branch from the pull-off depth to 0.
        """
        dmax = _one("depth_max", depth_max, Interval("depth_max", 0.0, np.inf, True,
                                                     True, "m"))
        if self.work == 0:
            d = np.linspace(0, dmax, n)
            F = np.concatenate([[0.0], self.force_at_depth(d[1:])])
            return {"approach_depth": d, "approach_force": F, "retraction_depth": d[::-1],
                    "retraction_force": F[::-1], "energy": 0.0}
        off = self.pull_off("depth")
        d_ret = np.linspace(dmax, off["depth"], n)
        F_ret = np.asarray(self.force_at_depth(d_ret))
        d_app = np.concatenate([[off["depth"]], np.linspace(0.0, dmax, n)])
        F_app = np.concatenate([[0.0, 0.0], np.asarray(self.force_at_depth(d_app[2:]))])
        d_app = np.concatenate([[off["depth"], 0.0], d_app[2:]])
        # energy: the integral of -F dd over [d_off, 0] on the stable branch, sampled
        # in a (dense near a_d, where dd/da = 0), trapezoidal rule
        a0 = float(self.radius_at_depth(0.0))
        ad = off["contact_radius"]
        a = ad + (a0 - ad) * np.linspace(0.0, 1.0, 4001) ** 2
        dd, FF = np.asarray(self.depth(a)), np.asarray(self.force(a))
        energy = -float(np.sum(0.5 * (FF[1:] + FF[:-1]) * np.diff(dd)))
        return {"approach_depth": d_app, "approach_force": F_app,
                "retraction_depth": d_ret, "retraction_force": F_ret, "energy": energy}

    def viscoelastic_limit(self, material, limit, counterbody=None):
        """The same contact with the relaxed or the instantaneous effective modulus.

        Parameters
        ----------
        material : linecontact.contact.Viscoelastic or linecontact.viscoelastic.PronySeries
            The viscoelastic body, ``Viscoelastic(E(t), nu)`` (its effective modulus
            E*(t) is built with its 1 - nu^2 and the counter-body's compliance,
            :func:`linecontact.viscoelastic.effective_relaxation`), or an effective
            modulus E*(t) that function made (``Contact(...).relaxation``). A bare
            Prony series is refused: it may be a body's own E(t), and reading it as E*
            would drop 1 - nu^2 and the counter-body.
        limit : {'relaxed', 'instantaneous'}
            'relaxed': infinitely slow loading and unloading (E* = E*(inf));
            'instantaneous': infinitely fast (E* = E*(0)).
        counterbody : linecontact.contact.Elastic, optional
            The elastic counter-body of a ``Viscoelastic`` material (default rigid).

        Returns
        -------
        AdhesiveContact

        Raises
        ------
        OutOfRangeError
            A bare Prony series, a counter-body with an effective E*(t), or any other
            `limit`: between the two the pull-off force depends on the speed
            of the receding contact edge through the dissipation at the crack tip
            (Greenwood & Johnson 1981; Persson & Brener 2005), which the
            correspondence principle of linecontact.viscoelastic (valid while the
            contact does not shrink) does not give.
        """
        material = _effective_relaxation(material, counterbody)
        if limit == "relaxed":
            E = material.long_term
        elif limit == "instantaneous":
            E = material.instantaneous
        else:
            raise OutOfRangeError(
                "limit", limit, "'relaxed' or 'instantaneous'",
                hint="a viscoelastic pull-off at a finite rate depends on the crack-tip "
                     "dissipation of the receding edge (Greenwood & Johnson 1981), which "
                     "the correspondence principle (growing contacts only) does not give")
        scale = E / self.estar
        nf = self._normal_force
        return AdhesiveContact(self.profile, E, self.work,
                               normal_force=(None if nf is None
                                             else (lambda a: scale * np.asarray(nf(a)))),
                               x_max=self.x_max, x_scale=self.x_scale)


def _effective_relaxation(material, counterbody):
    """E*(t) of :meth:`AdhesiveContact.viscoelastic_limit`'s material (see there)."""
    from .contact import Elastic, Viscoelastic
    from .viscoelastic import PronySeries, effective_relaxation

    valid = ("Viscoelastic(E(t), nu) with counterbody=Elastic(E2, nu2) (default rigid), "
             "or the effective E*(t) of viscoelastic.effective_relaxation")
    if isinstance(material, Viscoelastic):
        if counterbody is None:
            return effective_relaxation(material.relaxation, material.poisson)
        if not isinstance(counterbody, Elastic):
            raise OutOfRangeError("counterbody", repr(counterbody), "Elastic(E2, nu2)")
        return effective_relaxation(material.relaxation, material.poisson,
                                    counterbody.modulus, counterbody.poisson)
    if isinstance(material, PronySeries) and material.effective:
        if counterbody is not None:
            raise OutOfRangeError("counterbody", repr(counterbody), valid,
                                  hint="an effective E*(t) includes its counter-body")
        return material
    raise OutOfRangeError(
        "material", type(material).__name__, valid,
        hint="a bare relaxation function may be the body's own E(t); E* needs its "
             "1 - nu^2 and the counter-body's compliance")


# --------------------------------------------------------------------------------------
# the 2D JKR cylinder
# --------------------------------------------------------------------------------------
@document(R=_RADIUS, E=_ESTAR, W=_WORK)
def jkr_cylinder_force_per_length(half_width, radius, estar, work):
    r"""Force per unit length of the 2D JKR cylinder at contact half-width b.

    .. math:: \frac{F}{L} = \frac{\pi E^* b^2}{4R} - \sqrt{2\pi E^* w b}

    Parameters
    ----------
    half_width : float or array_like
        Contact half-width b, 0 < b < inf [m].
    radius : float
        Cylinder radius R [m].
    estar : float
        Effective modulus E* [Pa].
    work : float
        Work of adhesion w [J/m^2].

    Returns
    -------
    float or ndarray
        F/L [N/m] (negative: tensile).

    Notes
    -----
    Valid for 0 < b < inf, %(R)s, %(E)s, %(W)s; an infinitely long cylinder in plane
    strain, b << R. At w = 0 it is Hertz's line contact, b = sqrt(4 R F/(pi E* L))
    (Li & Popov 2017, Eq. 1).

    Examples
    --------
    >>> f"{jkr_cylinder_force_per_length(1e-4, 1e-3, 1e6, 0.0):.4f} N/m"
    '7.8540 N/m'

    References
    ----------
    .. [1] M. Barquins, J. Adhesion 26 (1988) 1-12.
    .. [2] M. K. Chaudhury, T. Weaver, C. Y. Hui, E. J. Kramer, J. Appl. Phys. 80
       (1996) 30-37.
    """
    b = check_positive("half_width", half_width, "m")
    R = _RADIUS.check(radius)
    E = _ESTAR.check(estar)
    w = _WORK.check(work)
    return out(np.pi * E * b ** 2 / (4 * R) - np.sqrt(2 * np.pi * E * w * b))


@document(R=_RADIUS, E=_ESTAR)
def jkr_cylinder_pull_off(radius, estar, work):
    r"""Pull-off force per unit length of the 2D JKR cylinder (force control).

    .. math::
        \frac{F_c}{L} = -3\left(\frac{\pi E^* R w^2}{16}\right)^{1/3}, \qquad
        b_c = \left(\frac{2R^2 w}{\pi E^*}\right)^{1/3}

    Parameters
    ----------
    radius : float or array_like
        Cylinder radius R [m].
    estar : float or array_like
        Effective modulus E* [Pa].
    work : float or array_like
        Work of adhesion w, 0 < w < inf [J/m^2].

    Returns
    -------
    force_per_length : float or ndarray
        F_c/L [N/m] (negative).
    half_width : float or ndarray
        b_c [m].

    Notes
    -----
    Valid for %(R)s, %(E)s, 0 < w < inf; plane strain. In 2D the depth is not defined
    (the displacement of a line load is logarithmic), so there is no depth-controlled
    pull-off; a finite roller has one (:class:`CylinderAdhesion`).

    Examples
    --------
    >>> F, b = jkr_cylinder_pull_off(1e-3, 1e6, 0.05)
    >>> f"{F:.4f} N/m at b = {b * 1e6:.2f} um"
    '-2.3665 N/m at b = 31.69 um'

    References
    ----------
    .. [1] M. Barquins, J. Adhesion 26 (1988) 1-12.
    .. [2] M. K. Chaudhury et al., J. Appl. Phys. 80 (1996) 30-37.
    """
    R = _RADIUS.check(radius)
    E = _ESTAR.check(estar)
    w = check_positive("work", work, "J/m^2")
    return out(-3 * np.cbrt(np.pi * E * R * w ** 2 / 16)), out(np.cbrt(2 * R ** 2 * w /
                                                                        (np.pi * E)))


@document(R=_RADIUS, E=_ESTAR, W=_WORK)
def jkr_cylinder_zero_load_half_width(radius, estar, work):
    r"""Contact half-width of the 2D JKR cylinder at zero load.

    .. math:: b_0 = \left(\frac{32 R^2 w}{\pi E^*}\right)^{1/3}

    the root b > 0 of :func:`jkr_cylinder_force_per_length` = 0,
    :math:`\pi E^* b^2/(4R) = \sqrt{2\pi E^* w b}`.

    Parameters
    ----------
    radius : float or array_like
        Cylinder radius R [m].
    estar : float or array_like
        Effective modulus E* [Pa].
    work : float or array_like
        Work of adhesion w [J/m^2].

    Returns
    -------
    float or ndarray
        b_0 [m] (0 without adhesion, w = 0).

    Notes
    -----
    Valid for %(R)s, %(E)s, %(W)s; plane strain, b_0 << R. It is 16^(1/3) = 2.52 times
    the half-width at pull-off, b_c (:func:`jkr_cylinder_pull_off`).

    Examples
    --------
    >>> f"{jkr_cylinder_zero_load_half_width(1e-3, 1e6, 0.05) * 1e6:.2f} um"
    '79.86 um'

    References
    ----------
    .. [1] M. Barquins, J. Adhesion 26 (1988) 1-12.
    .. [2] M. K. Chaudhury et al., J. Appl. Phys. 80 (1996) 30-37.
    """
    R = _RADIUS.check(radius)
    E = _ESTAR.check(estar)
    w = _WORK.check(work)
    return out(np.cbrt(32 * R ** 2 * w / (np.pi * E)))


# --------------------------------------------------------------------------------------
# the finite cylinder: the BEM table
# --------------------------------------------------------------------------------------
#: Models of a straight, aligned cylinder (the BEM table's geometry).
CYLINDER_MODELS = frozenset({"universal", "li-popov", "puttock-thwaite", "johnson"})


@functools.lru_cache(maxsize=None)
def _cached_table(name):
    return read_table(name)


def _table(name, directory, required=("s", "ratio_force", "ratio_depth", "mdr_err_force",
                                     "mdr_err_depth", "d_tilde_off")):
    table = read_table(name, directory=directory) if directory else _cached_table(name)
    for col in required:
        if col not in table.columns:
            raise TableError(f"{table.path}: no column {col!r}")
    s = table.columns["s"]
    if s.size < 2 or np.any(np.diff(s) <= 0) or s[0] <= 0:
        raise TableError(f"{table.path}: s must increase strictly from > 0")
    return table


class CylinderAdhesion:
    r"""Adhesive contact of a finite cylinder: the BEM-corrected pull-off and the MDR's.

    .. math::

        F_c = \rho(s)\,L\,\frac{F_{c,2D}}{L}, \qquad
        \frac{F_{c,2D}}{L} = -3\left(\frac{\pi E^*Rw^2}{16}\right)^{1/3}, \qquad
        s = \frac{b_c}{L} = \left(\frac{2\tilde w}{\pi}\right)^{1/3}, \quad
        \tilde w = \frac{wR^2}{E^*L^3}

    with :math:`\rho(s)` the BEM's ratio (``tables/adhesion_cylinder.csv``), one
    function for every L/R by self-similarity, interpolated by a monotone cubic
    (PCHIP) through its rows.

    Parameters
    ----------
    model : linecontact.models.ContactModel
        A straight-cylinder model (:data:`CYLINDER_MODELS`): its R, L, E* and, for the
        plain MDR values, its MDR profile.
    work : float
        Work of adhesion w, 0 < w < inf [J/m^2].
    table : str, optional
        Table stem (default :data:`ADHESION_TABLE`).
    directory : path-like, optional
        Read the tables from this folder instead of tables/.
    long_table : str, optional
        Stem of the long roller's table below the BEM table (default
        :data:`LONG_ROLLER_TABLE`).

    Notes
    -----
    The corrected values (``method='bem'``) are the BEM table's for s inside its range
    (0.025 <= s <= 0.5: :attr:`s_range`); a larger s is refused here (a disc-like
    contact: the plain rule of Hess is :meth:`AdhesiveContact.from_model`). Below it, down
    to s = 1e-3 (:attr:`long_range`), :meth:`pull_off` gives the long roller's value
    (method 'end-model', :data:`LONG_ROLLER_TABLE`) with its stated error: the ends
    peel first and the ratio keeps falling as s decreases; a smaller s is refused by
    :meth:`pull_off` (the 2D law per unit length of the middle section is
    :func:`jkr_cylinder_pull_off`). ``method='mdr'`` gives the rule of Hess at any s,
    with its error measured against the BEM or the end model, NaN (not measured) below
    both. Accuracy of the tables: their headers' ``accuracy`` lines (docs/adhesion.md).
    JKR itself needs a large Tabor parameter (:attr:`tabor`).

    Examples
    --------
    A hydrogel roller (E* = 67 kPa), R = 1 mm, L = 2 mm, w = 50 mJ/m^2:

    >>> from linecontact.models import get_model
    >>> c = CylinderAdhesion(get_model("universal", 1e-3, 2e-3, 6.7e4), 0.05)
    >>> f"s = {c.s:.3f}; 2D JKR {c.pull_off_2d * 1e3:.3f} mN"
    's = 0.039; 2D JKR -1.922 mN'
    >>> r = c.pull_off("force")
    >>> bool(0.9 < r["ratio"] < 1.0), r["method"]
    (True, 'bem')

    References
    ----------
    .. [1] M. Barquins, J. Adhesion 26 (1988) 1-12.
    .. [2] R. Pohrt, V. L. Popov, Facta Universitatis, Series Mechanical Engineering
       13(1) (2015) 3-10 (the BEM's criterion on curved edges).
    .. [3] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
       and Friction, Springer (2015), chapter 5 (the MDR's rule).
    """

    def __init__(self, model, work, *, table=ADHESION_TABLE, directory=None,
                 long_table=LONG_ROLLER_TABLE):
        key = getattr(model, "key", "")
        if key not in CYLINDER_MODELS:
            raise OutOfRangeError("model", key or type(model).__name__,
                                  "one of " + ", ".join(sorted(CYLINDER_MODELS)),
                                  hint="the BEM table is for a straight, aligned cylinder "
                                       "with an MDR profile; use AdhesiveContact for "
                                       "other shapes")
        self.model = model
        self.work = _one("work", work, Interval("work", 0.0, np.inf, True, True, "J/m^2"))
        self.table = _table(table, directory)
        self._long_name, self._directory = long_table, directory
        R, L, E = model.radius, model.length, model.estar
        self.w_tilde = self.work * R ** 2 / (E * L ** 3)
        self.s = float(np.cbrt(2 * self.w_tilde / np.pi))
        cols = self.table.columns
        s_max = float(cols["s"][-1])
        if self.s > s_max * (1 + 1e-12):
            raise OutOfRangeError(
                "work", self.work, f"0 < w <= {s_max ** 3 * np.pi / 2 * E * L ** 3 / R ** 2:.6g}"
                " J/m^2", unit="J/m^2",
                hint=f"s = b_c/L = {self.s:.3g} > {s_max:g}, the BEM table's end: the "
                     "pull-off contact is wider than the roller is long (a disc-like "
                     "contact; the plain rule of Hess is AdhesiveContact.from_model)")
        self.pull_off_2d_per_length, self.half_width_2d = jkr_cylinder_pull_off(R, E,
                                                                                self.work)

    # ---- table lookups ----------------------------------------------------------------
    def _column(self, column):
        from scipy.interpolate import PchipInterpolator

        cols = self.table.columns
        return float(PchipInterpolator(cols["s"], cols[column])(self.s))

    @property
    def s_range(self):
        """The table's range of s = b_c/L [-]: (smallest, largest)."""
        s = self.table.columns["s"]
        return float(s[0]), float(s[-1])

    @functools.cached_property
    def long_table(self):
        """The long roller's table below the BEM table (:data:`LONG_ROLLER_TABLE`)."""
        return _table(self._long_name, self._directory,
                      ("s", "ratio_force", "error_force", "ratio_depth", "error_depth"))

    @property
    def long_range(self):
        """The long roller's table's range of s = b_c/L [-]: (smallest, largest)."""
        s = self.long_table.columns["s"]
        return float(s[0]), float(s[-1])

    def _long(self, control):
        """(ratio, relative error) of the long roller's table at this s, or None outside
        its range."""
        from scipy.interpolate import PchipInterpolator

        cols = self.long_table.columns
        s_lo, s_hi = self.long_range
        if not s_lo * (1 - 1e-12) <= self.s <= s_hi * (1 + 1e-12):
            return None
        x = np.log(cols["s"])
        r = float(PchipInterpolator(x, cols[f"ratio_{control}"])(np.log(self.s)))
        e = float(PchipInterpolator(x, cols[f"error_{control}"])(np.log(self.s)))
        return r, e / r

    @property
    def in_table(self):
        """True when s lies inside the table's rows."""
        return bool(self.s >= self.table.columns["s"][0] * (1 - 1e-12))

    @property
    def provenance(self):
        """The table's metadata (title, source, generated_by, accuracy, ...)."""
        return dict(self.table.meta)

    @property
    def pull_off_2d(self):
        """The 2D JKR pull-off of the whole length, L F_c,2D/L [N] (force control)."""
        return self.pull_off_2d_per_length * self.model.length

    @functools.cached_property
    def mdr(self):
        """The plain rule of Hess on the model's profile (:class:`AdhesiveContact`)."""
        return AdhesiveContact.from_model(self.model, self.work)

    @property
    def tabor(self):
        """Tabor parameter of the case, z0 = 0.3 nm [-] (:func:`tabor_parameter`)."""
        return tabor_parameter(self.model.radius, self.work, self.model.estar)

    def pull_off(self, control="force", method="bem"):
        """The pull-off force: BEM-corrected (default) or the plain rule of Hess.

        Parameters
        ----------
        control : {'force', 'depth'}
            Force or depth control.
        method : {'bem', 'mdr'}
            'bem': the BEM table's value, and below it (s < :attr:`s_range`'s start)
            the long roller's (the end model calibrated on the BEM,
            :data:`LONG_ROLLER_TABLE`, down to :attr:`long_range`'s start) with its
            stated error; 'mdr': the rule of Hess on the model's MDR profile, with its
            error measured against either.

        Returns
        -------
        dict
            ``force`` [N], ``ratio`` (over the 2D JKR value of the length) [-],
            ``method`` ('bem', 'end-model' or 'mdr'), ``error`` [-]: 0 for 'bem' (the
            BEM's own accuracy is its table's header), the stated relative error for
            'end-model' (the long roller's table's ``error_*`` over its ratio), the
            MDR force over the BEM's or end model's, minus 1, for 'mdr' (NaN where
            neither is given; the BEM table's ``mdr_err_*`` columns are the universal
            curve's); ``pull_off_2d`` [N] (the 2D JKR value times L, beside it);
            ``depth`` [m] (the BEM's depth at the depth-controlled jump-off; NaN under
            force control, with the end model or with 'mdr'), ``in_table`` (bool:
            inside the BEM table); with 'bem' also ``mdr_force`` [N] (NaN where the model
            refuses, the reason in ``mdr_note``) and ``mdr_error`` [-] beside it.

        Raises
        ------
        OutOfRangeError
            method='bem' with s below the long roller's table (``work`` named, with
            the range).
        """
        if control not in _CONTROLS:
            raise UnknownNameError("control", control, _CONTROLS)
        if method not in _METHODS:
            raise UnknownNameError("method", method, _METHODS)
        # the reference: the BEM table inside it, the end model below it (None: neither)
        long = None if self.in_table else self._long(control)
        if self.in_table:
            ratio, kind, error = self._column(f"ratio_{control}"), "bem", 0.0
        elif long is not None:
            (ratio, error), kind = long, "end-model"
        else:
            ratio, kind, error = np.nan, None, np.nan
        ref = ratio * self.pull_off_2d
        # the MDR's error: this model's rule of Hess against the reference (the
        # table's mdr_err_* columns hold the universal curve's only; another model's
        # MDR profile, Li-Popov's or Puttock-Thwaite's, pulls off elsewhere)
        if method == "mdr":
            F = self.mdr.pull_off(control)["force"]
            return {"force": F, "ratio": F / self.pull_off_2d, "method": "mdr",
                    "error": F / ref - 1, "pull_off_2d": self.pull_off_2d,
                    "depth": np.nan, "in_table": self.in_table}
        if kind is None:
            s_min = self.long_range[0]
            R, L, E = self.model.radius, self.model.length, self.model.estar
            raise OutOfRangeError(
                "work", self.work, f"{s_min ** 3 * np.pi / 2 * E * L ** 3 / R ** 2:.6g} <= "
                f"w J/m^2 (s = b_c/L >= {s_min:g})", unit="J/m^2",
                hint=f"s = b_c/L = {self.s:.3g} is below the long roller's table (its "
                     f"end model, calibrated and checked on the BEM, is given for s >= "
                     f"{s_min:g}); the ratio to the 2D JKR value keeps falling there; "
                     "method='mdr' gives the rule of Hess (error not measured there), "
                     "jkr_cylinder_pull_off the 2D law per unit length")
        try:
            mdr, mdr_note = self.mdr.pull_off(control)["force"], ""
        except OutOfRangeError as exc:     # e.g. beyond the model's range of depth
            mdr, mdr_note = np.nan, str(exc).splitlines()[0]
        depth = np.nan
        if control == "depth" and kind == "bem":
            depth = self._column("d_tilde_off") * self.model.length ** 2 / self.model.radius
        return {"force": ref, "ratio": ratio, "method": kind, "error": error,
                "pull_off_2d": self.pull_off_2d, "mdr_force": mdr,
                "mdr_error": mdr / ref - 1, "mdr_note": mdr_note,
                "depth": depth, "in_table": self.in_table}

    def zero_load(self):
        """State at zero load: the 2D JKR half-width and the MDR's half-length and depth.

        Returns
        -------
        dict
            ``half_width_2d`` b0 = (32 R^2 w/(pi E*))^(1/3) [m] (2D JKR, the long-roller
            value), ``mdr_half_length`` a0 [m] and ``mdr_depth`` d0 [m] (the rule of
            Hess; not measured by the BEM).
        """
        R, E = self.model.radius, self.model.estar
        z = self.mdr.zero_load()
        return {"half_width_2d": float(np.cbrt(32 * R ** 2 * self.work / (np.pi * E))),
                "mdr_half_length": z["contact_radius"], "mdr_depth": z["depth"]}
