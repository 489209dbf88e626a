r"""Roller profiles: the axial drop P(x) >= 0 of a crowned, relieved or log-profiled roller.

The gap between a roller (radius R across its axis, length L along it, axis x,
|x| <= L/2) and a flat is

.. math:: h(x, y) = \frac{y^2}{2R} + P(x) - \theta x

for a profile drop P(x) >= 0 (zero where the roller is straight) and a tilt theta of the
axis (positive theta brings the +x end closer). Each profile here is an object with
``drop(x)`` [m], its validity range as data and its reference; asymmetric profiles are
allowed (the user table, an offset crown). :func:`parse_profile` builds one from the
command-line form ``NAME[:opt=val,...]``.

=================  ===============================================  ==================
key                drop P(x)                                        source
=================  ===============================================  ==================
``straight``       0                                                 -
``end-relief``     corner radius r over the last l: r - sqrt(r^2 -   ISO 3096, ISO 12297
                   s^2); dub-off: s tan(alpha); s = |x| - (L/2 - l)  (roller geometry)
``circular``       (x - x0)^2 / (2 Rc)                               Johnson (1985) 4.2
``iso16281``       0.00035 D ln[1/(1 - (2x/L)^2)] (L <= 2.5 D);      ISO 16281:2025
                   flat middle and 0.0005 D ln[1/(1 - t^2)] (L > 2.5 D)
``lundberg``       F0/(pi L E*) ln[1/(1 - (2x/L)^2)]                 Lundberg (1939)
``johns-gohar``    F0/(pi L E*) ln[1/(1 - (1 - 0.3033 b/a)(x/a)^2)]  Johns & Gohar (1981)
``file:PATH.csv``  linear interpolation of a table (x, drop)        user data
=================  ===============================================  ==================

The two logarithmic profiles of ISO 16281 and Lundberg are infinite at x = +-L/2
(``drop`` returns ``inf`` there, which is the formula, not an error); the slice models
evaluate them at slice centres only, which lie inside.

References
----------
.. [1] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem Gebiete
   des Ingenieurwesens 10 (1939) 201-211.
.. [2] P. M. Johns, R. Gohar, "Roller bearings under radial and eccentric loads",
   Tribology International 14 (1981) 131-136.
.. [3] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded rolling bearings (reference roller profile).
.. [4] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 4.2.
"""
from __future__ import annotations

import functools
import math
import re
from pathlib import Path

import numpy as np

from .checks import Interval, check_interval, check_positive
from .errors import OutOfRangeError, UnknownNameError

__all__ = [
    "Profile",
    "StraightProfile",
    "EndReliefProfile",
    "CircularCrownProfile",
    "ISO16281Profile",
    "LundbergProfile",
    "JohnsGoharProfile",
    "TabulatedProfile",
    "PROFILE_KEYS",
    "JOHNS_GOHAR_C",
    "ISO16281_SHORT",
    "ISO16281_LONG",
    "parse_profile",
    "parse_angle",
    "TILT_RANGE",
    "FREE_TILT",
    "is_free_tilt",
]

#: Tilts theta of the roller's axis accepted by the roller models (the gap linearises
#: the tilt, theta x, for small angles) [rad].
TILT_RANGE = Interval("tilt", -0.1, 0.1, low_open=True, high_open=True, unit="rad")
#: The tilt value that asks for the roller's moment equilibrium (zero moment about its
#: centre); a number holds the tilt, 0 (the default everywhere) keeps it aligned.
FREE_TILT = "free"

#: The constant of the Johns-Gohar profile, (1 - C b/a) (Johns & Gohar 1981).
JOHNS_GOHAR_C = 0.3033
#: ISO 16281 reference profile coefficient for L <= 2.5 D (drop = c D ln ...).
ISO16281_SHORT = 0.00035
#: ISO 16281 reference profile coefficient for L > 2.5 D (outside the flat middle).
ISO16281_LONG = 0.0005

# a relative allowance at the ends of the x range, for slice centres computed in
# floating point (never used to accept a value beyond rounding)
_XTOL = 1e-12


def _scalar_positive(name, value, unit):
    v = check_positive(name, value, unit)
    if v.ndim:
        raise OutOfRangeError(name, f"an array of shape {v.shape}",
                              f"a single number in (0, inf) {unit}")
    return float(v)


class Profile:
    """Base class: a drop P(x) >= 0 [m] along the roller axis over x_min <= x <= x_max.

    Subclasses set :attr:`key`, :attr:`reference`, the range ``x_min``, ``x_max`` and
    implement :meth:`_drop` (array in, array out, for x inside the range).

    Attributes
    ----------
    length : float or None
        Roller length L the profile was built for [m] (None for a user table).
    x_min, x_max : float
        The range of x over which ``drop`` is defined [m].

    Examples
    --------
    >>> p = StraightProfile(10e-3)
    >>> isinstance(p, Profile), p.x_min, p.x_max
    (True, -0.005, 0.005)
    """

    key = ""
    reference = ""
    length = None
    x_min = -math.inf
    x_max = math.inf

    def drop(self, x):
        r"""Profile drop P(x) [m] at axial positions x [m] inside the profile's range.

        .. math:: P(x) \ge 0

        Parameters
        ----------
        x : float or array_like
            Axial position(s), x_min <= x <= x_max [m].

        Returns
        -------
        float or ndarray
            P(x) [m]; ``inf`` only where a logarithmic profile reaches the roller end.

        Raises
        ------
        OutOfRangeError
            For x outside [x_min, x_max] or NaN.

        Examples
        --------
        >>> CircularCrownProfile(20e-3, crown_radius=0.5).drop([0.0, 5e-3]) * 1e6
        array([ 0., 25.])
        """
        span = self.x_max - self.x_min
        tol = _XTOL * (span if math.isfinite(span) else 1.0)
        xv = check_interval("x", x, self.x_min - tol, self.x_max + tol, unit="m",
                            hint=f"the {self.label} profile is defined over "
                                 f"[{self.x_min:.6g}, {self.x_max:.6g}] m")
        # rounding allowance only (tol above); minimum/maximum: np.clip costs several
        # times more on the few points of a roller solve
        xv = np.minimum(np.maximum(xv, self.x_min), self.x_max)
        with np.errstate(divide="ignore"):
            d = np.asarray(self._drop(xv), dtype=float)
        if d.ndim == 0:
            return float(d)
        return d

    def _drop(self, x):
        raise NotImplementedError

    @property
    def label(self):
        """Human-readable name with its parameters."""
        return self.key

    @property
    def provenance(self):
        """What the profile is and where it comes from (for reports and JSON)."""
        return {"profile": self.label, "reference": self.reference}

    def __repr__(self):
        return f"<{type(self).__name__} {self.label}>"


def _symmetric_range(obj, length):
    obj.length = _scalar_positive("length", length, "m")
    obj.x_min = -obj.length / 2
    obj.x_max = obj.length / 2


class StraightProfile(Profile):
    """A straight (cylindrical) roller: P(x) = 0 over |x| <= L/2.

    .. math:: P(x) = 0

    Parameters
    ----------
    length : float
        Roller length L, 0 < L < inf [m].

    Notes
    -----
    On a half-space the pressure at the sharp ends of a straight roller is singular
    (a rigid flat-ended punch); the roller models report that as edge loading.

    Examples
    --------
    >>> StraightProfile(10e-3).drop(4e-3)
    0.0

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 5.6 (finite line contact).
    """

    key = "straight"
    reference = "no profile"

    def __init__(self, length):
        _symmetric_range(self, length)

    def _drop(self, x):
        return np.zeros_like(x)

    def _drop_slope(self, x):
        """The drop and dP/dx = 0 (drop_slope_inside)."""
        return np.zeros_like(x), np.zeros_like(x)

    @property
    def label(self):
        return "straight"


class EndReliefProfile(Profile):
    r"""A straight roller with relieved ends: a corner radius or a straight dub-off.

    Over the relief length l at each end, with :math:`s = |x| - (L/2 - l) > 0`:

    .. math::

        P = r - \sqrt{r^2 - s^2} \quad\text{(corner radius r, l <= r)}, \qquad
        P = s \tan\alpha = s\,\frac{\Delta}{l} \quad\text{(dub-off)}

    and P = 0 over the straight middle |x| <= L/2 - l.

    Parameters
    ----------
    length : float
        Roller length L [m].
    corner_radius : float, optional
        Radius r of the relief arc (tangent to the straight part), 0 < r [m].
    relief_length : float, optional
        Axial length l of each relief, 0 < l <= L/2 [m]; with a corner radius it
        defaults to r (a quarter circle reaching the end face), and must be <= r.
    relief_angle : float, optional
        Dub-off angle alpha, 0 < alpha < pi/2 [rad] (needs ``relief_length``).
    relief_drop : float, optional
        Dub-off drop Delta at the end face, 0 < Delta [m] (needs ``relief_length``;
        instead of ``relief_angle``).

    Notes
    -----
    Give either ``corner_radius`` (and optionally ``relief_length``) or
    ``relief_length`` with exactly one of ``relief_angle``, ``relief_drop``. The arc's
    slope at the end is finite for l < r; the profile has a slope discontinuity where a
    dub-off starts, which concentrates pressure there (as in practice).

    Examples
    --------
    >>> p = EndReliefProfile(10e-3, corner_radius=1e-3)
    >>> f"{p.drop(4.5e-3) * 1e6:.1f} um"
    '134.0 um'
    >>> d = EndReliefProfile(10e-3, relief_length=1e-3, relief_drop=5e-6)
    >>> f"{d.drop(5e-3) * 1e6:.1f} um, {d.drop(4e-3):.1f}"
    '5.0 um, 0.0'

    References
    ----------
    ISO 3096 / ISO 12297 (roller end geometry); Johns & Gohar (1981) on end relief.
    """

    key = "end-relief"
    reference = "straight roller with end relief (corner radius or dub-off)"

    def __init__(self, length, corner_radius=None, relief_length=None, relief_angle=None,
                 relief_drop=None):
        _symmetric_range(self, length)
        half = self.length / 2
        self.corner_radius = None
        self.slope = None
        if corner_radius is not None:
            if relief_angle is not None or relief_drop is not None:
                raise OutOfRangeError("relief_angle", relief_angle or relief_drop,
                                      "not given with corner_radius",
                                      hint="a relief is either an arc or a dub-off")
            r = _scalar_positive("corner_radius", corner_radius, "m")
            lr = r if relief_length is None else _scalar_positive(
                "relief_length", relief_length, "m")
            check_interval("relief_length", lr, 0.0, min(r, half), low_open=True,
                           unit="m", hint="the arc relief is at most a quarter circle "
                                          "(l <= r) and at most half the roller")
            self.corner_radius = r
            self.relief_length = float(lr)
        else:
            if relief_length is None:
                raise OutOfRangeError("relief_length", "missing",
                                      f"(0, {half:.6g}] m",
                                      hint="give corner_radius, or relief_length with "
                                           "relief_angle or relief_drop")
            lr = float(check_interval("relief_length", relief_length, 0.0, half,
                                      low_open=True, unit="m"))
            if (relief_angle is None) == (relief_drop is None):
                raise OutOfRangeError("relief_angle", "missing" if relief_angle is None
                                      else relief_angle, "exactly one of relief_angle, "
                                      "relief_drop", hint="a dub-off needs its angle or "
                                                          "its end drop")
            if relief_angle is not None:
                a = float(check_interval("relief_angle", relief_angle, 0.0, math.pi / 2,
                                         low_open=True, high_open=True, unit="rad"))
                self.slope = math.tan(a)
            else:
                self.slope = _scalar_positive("relief_drop", relief_drop, "m") / lr
            self.relief_length = lr

    def _drop(self, x):
        s = np.maximum(np.abs(x) - (self.length / 2 - self.relief_length), 0.0)
        if self.corner_radius is not None:
            r = self.corner_radius
            # r - sqrt(r^2 - s^2) without cancellation
            return s * s / (r + np.sqrt(np.maximum(r * r - s * s, 0.0)))
        return self.slope * s

    @property
    def label(self):
        if self.corner_radius is not None:
            return (f"end relief (r = {self.corner_radius * 1e3:.4g} mm over "
                    f"{self.relief_length * 1e3:.4g} mm)")
        return (f"end relief (dub-off {math.degrees(math.atan(self.slope)):.4g} deg over "
                f"{self.relief_length * 1e3:.4g} mm)")


class CircularCrownProfile(Profile):
    r"""A crowned roller: circular crown of radius Rc (parabolic form), apex at x0.

    .. math:: P(x) = \frac{(x - x_0)^2}{2 R_c}

    On a flat, while the contact stays inside the roller, this is the Hertz elliptical
    contact with principal radii Rc (along x) and R (across), see
    :mod:`linecontact.hertz`.

    Parameters
    ----------
    length : float
        Roller length L [m].
    crown_radius : float
        Crown radius Rc, 0 < Rc < inf [m].
    offset : float, optional
        Axial position x0 of the crown apex, |x0| < L/2 [m] (default 0; nonzero makes
        the profile asymmetric).

    Notes
    -----
    The parabola stands in for the arc Rc - sqrt(Rc^2 - x^2); they differ by
    x^4/(8 Rc^3), a fraction x^2/(4 Rc^2) of the drop (below 0.25 % for L/2 <= Rc/10).

    Examples
    --------
    >>> f"{CircularCrownProfile(20e-3, 0.5).drop(10e-3) * 1e6:.0f} um"
    '100 um'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """

    key = "circular"
    reference = "circular crown, parabolic form (Johnson 1985, section 4.2)"

    def __init__(self, length, crown_radius, offset=0.0):
        _symmetric_range(self, length)
        self.crown_radius = _scalar_positive("crown_radius", crown_radius, "m")
        self.offset = float(check_interval("offset", offset, -self.length / 2,
                                           self.length / 2, low_open=True,
                                           high_open=True, unit="m"))

    def _drop(self, x):
        return (x - self.offset) ** 2 / (2 * self.crown_radius)

    def _drop_slope(self, x):
        """The drop (the floats of _drop) and dP/dx = (x - x0)/Rc (drop_slope_inside)."""
        u = x - self.offset
        return u ** 2 / (2 * self.crown_radius), u / self.crown_radius

    @property
    def label(self):
        s = f"circular crown (Rc = {self.crown_radius * 1e3:.6g} mm"
        if self.offset:
            s += f", apex at x = {self.offset * 1e3:.4g} mm"
        return s + ")"


def _log_drop(coef, t):
    """coef * ln[1/(1 - t^2)] for |t| <= 1 (inf at |t| = 1), without cancellation."""
    return -coef * np.log1p(-(t * t))


def _log_drop_slope(coef, t, dt):
    """_log_drop(coef, t) (the same floats) and its derivative 2 coef t/(1 - t^2) dt
    with respect to x, for |t| < 1 and dt = dt/dx (a number)."""
    tt = t * t
    return -coef * np.log1p(-tt), (2 * coef * dt) * t / (1 - tt)


class ISO16281Profile(Profile):
    r"""The ISO 16281 reference logarithmic roller profile (both branches).

    With D the roller diameter:

    .. math::

        L \le 2.5 D:\quad P(x) = 0.00035\,D\,\ln\frac{1}{1 - (2x/L)^2}

        L > 2.5 D:\quad P(x) = 0 \text{ for } |x| \le \frac{L - 2.5 D}{2},\ \text{else }
        0.0005\,D\,\ln\frac{1}{1 - t^2},\quad t = \frac{2|x| - L + 2.5 D}{2.5 D}

    Parameters
    ----------
    length : float
        Roller length L (the effective length of the standard) [m].
    diameter : float
        Roller diameter D = 2R, 0 < D < inf [m].

    Notes
    -----
    Infinite at the roller ends (``drop(+-L/2)`` is ``inf``), as the formula. The drop
    is independent of load and material: it is the standard's reference shape for
    steel rollers, used with its slicing method (:func:`linecontact.roller.iso_slicing`).

    Examples
    --------
    >>> p = ISO16281Profile(10e-3, 10e-3)
    >>> f"{p.drop(4e-3) * 1e6:.3f} um"
    '3.576 um'
    >>> q = ISO16281Profile(40e-3, 10e-3)        # L > 2.5 D: flat middle of 15 mm
    >>> q.drop(7e-3), f"{q.drop(15e-3) * 1e6:.3f} um"
    (0.0, '2.231 um')

    References
    ----------
    ISO 16281:2025, section on the roller profile; Lundberg (1939).
    """

    key = "iso16281"
    reference = "ISO 16281:2025 reference roller profile"

    def __init__(self, length, diameter):
        _symmetric_range(self, length)
        self.diameter = _scalar_positive("diameter", diameter, "m")

    @property
    def long(self):
        """True for the L > 2.5 D branch (flat middle)."""
        return self.length > 2.5 * self.diameter

    def _drop(self, x):
        L, D = self.length, self.diameter
        if not self.long:
            return _log_drop(ISO16281_SHORT * D, 2 * x / L)
        t = np.maximum(2 * np.abs(x) - L + 2.5 * D, 0.0) / (2.5 * D)
        return _log_drop(ISO16281_LONG * D, t)

    def _drop_slope(self, x):
        """The drop (the floats of _drop) and dP/dx, for |x| < L/2 (drop_slope_inside):
        dP/dt dt/dx with dt/dx = 2/L, or sign(x) 2/(2.5 D) outside the flat middle."""
        L, D = self.length, self.diameter
        if not self.long:
            return _log_drop_slope(ISO16281_SHORT * D, 2 * x / L, 2 / L)
        t = np.maximum(2 * np.abs(x) - L + 2.5 * D, 0.0) / (2.5 * D)
        P, slope = _log_drop_slope(ISO16281_LONG * D, t, 2 / (2.5 * D))
        slope *= np.sign(x)
        return P, slope

    @property
    def label(self):
        branch = "L > 2.5 D, flat middle" if self.long else "L <= 2.5 D"
        return f"ISO 16281 (D = {self.diameter * 1e3:.4g} mm, {branch})"


class LundbergProfile(Profile):
    r"""Lundberg's logarithmic profile for a design load F0.

    .. math:: P(x) = \frac{F_0}{\pi L E^*}\ln\frac{1}{1 - (2x/L)^2}

    Under the design load the line load of a roller with this profile is uniform,
    q = F0/L, in Lundberg's half-space approximation.

    Parameters
    ----------
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].
    design_force : float
        Design load F0, 0 < F0 < inf [N].

    Notes
    -----
    Infinite at x = +-L/2 (the formula). Bearing texts write the factor 2F0/(pi L E')
    with E' = 2E*; it is the same.

    Examples
    --------
    >>> p = LundbergProfile(10e-3, 115.385e9, 1e3)
    >>> f"{p.drop(4e-3) * 1e6:.4f} um"
    '0.2818 um'

    References
    ----------
    G. Lundberg (1939), Forschung auf dem Gebiete des Ingenieurwesens 10, 201-211.
    """

    key = "lundberg"
    reference = "Lundberg (1939), logarithmic profile for a design load"

    def __init__(self, length, estar, design_force):
        _symmetric_range(self, length)
        self.estar = _scalar_positive("estar", estar, "Pa")
        self.design_force = _scalar_positive("design_force", design_force, "N")

    @property
    def coefficient(self):
        """F0/(pi L E*) [m]."""
        return self.design_force / (math.pi * self.length * self.estar)

    def _drop(self, x):
        return _log_drop(self.coefficient, 2 * x / self.length)

    def _drop_slope(self, x):
        """The drop (the floats of _drop) and dP/dx = dP/dt 2/L, for |x| < L/2
        (drop_slope_inside)."""
        return _log_drop_slope(self.coefficient, 2 * x / self.length, 2 / self.length)

    @property
    def label(self):
        return f"Lundberg (F0 = {self.design_force:.6g} N)"


class JohnsGoharProfile(Profile):
    r"""The Johns-Gohar logarithmic profile: Lundberg's with a finite drop at the ends.

    .. math::

        P(x) = \frac{F_0}{\pi L E^*}\ln\frac{1}{1 - (1 - 0.3033\,b/a)(x/a)^2},\qquad
        a = \frac{L}{2},\quad b = \sqrt{\frac{4 R F_0}{\pi E^* L}}

    (b is the Hertz half-width of the roller under the design load, Li & Popov 2017
    Eq. 1.)

    Parameters
    ----------
    length : float
        Roller length L [m].
    radius : float
        Roller radius R (or the effective radius against the raceway) [m].
    estar : float
        Effective modulus E* [Pa].
    design_force : float
        Design load F0, 0 < F0 [N]; needs b < a/0.3033.

    Notes
    -----
    The end drop is (F0/(pi L E*)) ln(a/(0.3033 b)), finite. Johns & Gohar write the
    factor as 2Q/(pi l E') with E' = 2E*.

    Examples
    --------
    >>> p = JohnsGoharProfile(10e-3, 5e-3, 115.385e9, 1e3)
    >>> f"{p.drop(5e-3) * 1e6:.3f} um"
    '1.490 um'

    References
    ----------
    P. M. Johns, R. Gohar (1981), Tribology International 14, 131-136.
    """

    key = "johns-gohar"
    reference = "Johns & Gohar (1981), logarithmic profile with finite end drop"

    def __init__(self, length, radius, estar, design_force):
        _symmetric_range(self, length)
        self.radius = _scalar_positive("radius", radius, "m")
        self.estar = _scalar_positive("estar", estar, "Pa")
        self.design_force = _scalar_positive("design_force", design_force, "N")
        a = self.length / 2
        from .classical import hertz_half_width
        b = float(hertz_half_width(self.design_force, self.radius, self.length,
                                   self.estar))
        if not JOHNS_GOHAR_C * b < a:
            raise OutOfRangeError("design_force", self.design_force,
                                  f"(0, {math.pi * self.estar * self.length * (a / JOHNS_GOHAR_C) ** 2 / (4 * self.radius):.6g}) N",
                                  unit="N", hint="the profile needs 0.3033 b < L/2")
        self.half_width = b
        self.factor = 1.0 - JOHNS_GOHAR_C * b / a

    @property
    def coefficient(self):
        """F0/(pi L E*) [m]."""
        return self.design_force / (math.pi * self.length * self.estar)

    def _drop(self, x):
        a = self.length / 2
        return -self.coefficient * np.log1p(-self.factor * (x / a) ** 2)

    def _drop_slope(self, x):
        """The drop (the floats of _drop) and dP/dx = 2 c f (x/a)/(a (1 - f (x/a)^2))
        (drop_slope_inside)."""
        a = self.length / 2
        u = x / a
        fu2 = self.factor * u ** 2
        c = self.coefficient
        return -c * np.log1p(-fu2), (2 * c * self.factor / a) * u / (1 - fu2)

    @property
    def label(self):
        return f"Johns-Gohar (F0 = {self.design_force:.6g} N)"


class TabulatedProfile(Profile):
    """A user profile from a table of (x, drop), linearly interpolated.

    .. math:: P(x) = P_i + (P_{i+1} - P_i)\\frac{x - x_i}{x_{i+1} - x_i},
              \\quad x_i \\le x \\le x_{i+1}

    Parameters
    ----------
    x : array_like
        Axial positions, strictly increasing, finite, at least 2 [m].
    drop : array_like
        Drops P_i >= 0, finite, one per x [m].
    source : str, optional
        Where the table came from (a file name), for labels.

    Raises
    ------
    OutOfRangeError
        x not strictly increasing, a NaN or infinite value, a negative drop, fewer than
        2 points. Evaluation outside [x_0, x_N] is refused (no extrapolation).

    Notes
    -----
    Asymmetric tables are allowed. The roller model needs the table to cover the
    roller, -L/2 <= x <= L/2; the profile is used as given (the roller's first contact
    is at the smallest drop minus the tilt term).

    Examples
    --------
    >>> p = TabulatedProfile([-5e-3, 0.0, 5e-3], [2e-6, 0.0, 1e-6])
    >>> f"{p.drop(2.5e-3) * 1e6:.2f} um"
    '0.50 um'
    >>> p.drop(6e-3)
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: x = 0.006 m is outside the valid range [-0.005, 0.005] m; ...

    References
    ----------
    User data; linear interpolation (numpy.interp).
    """

    key = "file"
    reference = "user table (x, drop), linear interpolation"

    def __init__(self, x, drop, source="table"):
        xv = np.asarray(x, dtype=float).ravel()
        dv = np.asarray(drop, dtype=float).ravel()
        if xv.size != dv.size:
            raise OutOfRangeError("drop", f"{dv.size} values",
                                  f"one drop per x ({xv.size} values)")
        if xv.size < 2:
            raise OutOfRangeError("x", f"{xv.size} point(s)", "at least 2 points")
        for name, v in (("x", xv), ("drop", dv)):
            bad = ~np.isfinite(v)
            if np.any(bad):
                i = int(np.flatnonzero(bad)[0])
                raise OutOfRangeError(name, float(v[i]), "finite numbers", unit="m",
                                      where=f"row {i + 1} of {source}")
        neg = dv < 0
        if np.any(neg):
            i = int(np.flatnonzero(neg)[0])
            raise OutOfRangeError("drop", float(dv[i]), "[0, inf) m", unit="m",
                                  where=f"row {i + 1} of {source}",
                                  hint="a profile drop is material removed, never negative")
        steps = np.diff(xv)
        if np.any(steps <= 0):
            i = int(np.flatnonzero(steps <= 0)[0]) + 1
            raise OutOfRangeError("x", float(xv[i]), f"(> {xv[i - 1]:.6g}) m", unit="m",
                                  where=f"row {i + 1} of {source}",
                                  hint="x must increase strictly (monotone, no repeats)")
        self.x = xv
        self.values = dv
        self.source = str(source)
        self.x_min = float(xv[0])
        self.x_max = float(xv[-1])

    @classmethod
    def from_csv(cls, path):
        """Read a profile from a CSV file of two columns x [m], drop [m].

        Lines starting with '#' are comments; one optional header row of non-numeric
        names is skipped; separators ',' or ';' or whitespace. Each cell follows the
        calculator's input rule (:func:`linecontact._units.parse_quantity`): a number
        with at most one unit name, bare = m (``5mm``, ``1um``); non-ASCII digits,
        ``1_000``, ``nan`` and ``inf`` are refused.

        Parameters
        ----------
        path : str or path-like
            The CSV file.

        Returns
        -------
        TabulatedProfile

        Raises
        ------
        OutOfRangeError
            Unreadable file, a row that is not two numbers, or the checks of the class.

        Examples
        --------
        >>> import tempfile, os
        >>> f = os.path.join(tempfile.mkdtemp(), "p.csv")
        >>> _ = open(f, "w").write("x,drop\\n-0.005,1e-6\\n0,0\\n0.005,1e-6\\n")
        >>> TabulatedProfile.from_csv(f).drop(0.0)
        0.0
        """
        p = Path(path)
        try:
            text = p.read_text(encoding="utf-8")
        except OSError as exc:
            raise OutOfRangeError("profile file", str(p), "a readable CSV file of x, drop",
                                  hint=exc.strerror or str(exc)) from None
        except UnicodeDecodeError as exc:
            raise OutOfRangeError("profile file", str(p), "a UTF-8 text CSV file of x, drop",
                                  hint=f"not UTF-8 text ({exc.reason} at byte "
                                  f"{exc.start})") from None
        except ValueError as exc:  # a path the OS cannot take (an embedded NUL)
            raise OutOfRangeError("profile file", str(p), "a readable CSV file of x, drop",
                                  hint=f"not a usable path ({exc})") from None
        xs, ds = [], []
        header_seen = False
        for lineno, line in enumerate(text.splitlines(), start=1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            fields = [f for f in re.split(r"[,;\s]+", s) if f]
            # each cell by the package's one input rule (linecontact._units: a number
            # with at most one unit name, bare = m); a first row with no number at all
            # is the header
            parsed = [_file_length(f) for f in fields]
            if any(isinstance(v, str) for v in parsed):
                if not header_seen and not xs and all(isinstance(v, str) for v in parsed):
                    header_seen = True
                    continue
                why = next(v for v in parsed if isinstance(v, str))
                raise OutOfRangeError("profile file", f"{p.name} line {lineno}: {s!r}",
                                      "rows of two lengths x, drop (bare numbers in m)",
                                      hint=why)
            vals = parsed
            if len(vals) != 2:
                raise OutOfRangeError("profile file", f"{p.name} line {lineno}: {s!r}",
                                      "rows of two numbers x [m], drop [m]")
            xs.append(vals[0])
            ds.append(vals[1])
        return cls(xs, ds, source=p.name)

    def _drop(self, x):
        return np.interp(x, self.x, self.values)

    @property
    def label(self):
        return f"table {self.source} ({self.x.size} points)"


#: Keys understood by :func:`parse_profile` (``file`` as ``file:PATH.csv``).
PROFILE_KEYS = ("straight", "end-relief", "circular", "iso16281", "lundberg",
                "johns-gohar", "file")

def parse_angle(text, parameter="tilt"):
    """Parse an angle with an optional unit into radians: "1mrad", "0.05deg", "0.001".

    .. math:: \\theta\\,[\\mathrm{rad}] = \\text{value} \\times \\text{unit factor}

    Parameters
    ----------
    text : str or float
        A number (radians) or a number followed by one unit name: rad, mrad, urad,
        deg, or any other angle unit pint knows (linecontact._units) [-].
    parameter : str, optional
        Name used in the error message [-].

    Returns
    -------
    float
        The angle [rad].

    Raises
    ------
    OutOfRangeError
        Not a finite number with one of the units above, or |angle| >= 0.1 rad (beyond
        the small-tilt geometry h = ... - theta x of the roller models).

    Notes
    -----
    Valid for |angle| < 0.1 rad (5.7 deg): the roller models linearise the tilt.

    Examples
    --------
    >>> parse_angle("1mrad"), round(parse_angle("0.05deg"), 9), parse_angle(0.002)
    (0.001, 0.000872665, 0.002)

    References
    ----------
    SI brochure (radian); 1 deg = pi/180 rad.
    """
    if isinstance(text, (int, float, np.floating)):
        value, typed = float(text), repr(text)
    else:   # the package's one input grammar: a number and at most one unit name
        from ._units import InputError, parse_quantity
        typed = str(text)
        try:
            value = parse_quantity(parameter, typed, "angle", positive=False)
        except InputError as exc:
            raise OutOfRangeError(parameter, typed, exc.valid, hint=exc.reason) from None
    if not math.isfinite(value) or abs(value) >= 0.1:
        raise OutOfRangeError(parameter, typed, "(-0.1, 0.1) rad",
                              hint="the roller models linearise the tilt (small angles)")
    return value


def _file_length(text):
    """A cell of a profile file in m by the one input rule, or why not (a str)."""
    from ._units import InputError, parse_quantity

    try:
        return parse_quantity("cell", text, "length", positive=False)
    except InputError as exc:
        return f"{text!r}: {exc.reason}"


#: Profile options that may be negative (an offset crown may sit on either side).
_SIGNED_OPTIONS = ("offset",)


def _opt_value(key, text, kind, positive=True):
    """An option value: a number with at most one unit name (length/force/angle), by the
    package's one input grammar (linecontact._units; a bare number is SI), > 0 unless
    the option is signed. Further ranges are checked by the profile that takes it."""
    if kind == "angle":
        return parse_angle(text, parameter=key)
    from ._units import InputError, parse_quantity
    try:
        return parse_quantity(key, text, kind, positive=positive)
    except InputError as exc:
        raise OutOfRangeError(key, text, exc.valid, hint=exc.reason) from None


# name -> {option aliases -> (keyword, kind)}
_OPTIONS = {
    "straight": {},
    "end-relief": {"r": ("corner_radius", "length"), "corner_radius": ("corner_radius", "length"),
                   "l": ("relief_length", "length"), "relief_length": ("relief_length", "length"),
                   "angle": ("relief_angle", "angle"), "relief_angle": ("relief_angle", "angle"),
                   "drop": ("relief_drop", "length"), "relief_drop": ("relief_drop", "length")},
    "circular": {"Rc": ("crown_radius", "length"), "rc": ("crown_radius", "length"),
                 "crown_radius": ("crown_radius", "length"),
                 "x0": ("offset", "length"), "offset": ("offset", "length")},
    "iso16281": {"D": ("diameter", "length"), "d": ("diameter", "length"),
                 "diameter": ("diameter", "length")},
    "lundberg": {"F0": ("design_force", "force"), "f0": ("design_force", "force"),
                 "design_force": ("design_force", "force")},
    "johns-gohar": {"F0": ("design_force", "force"), "f0": ("design_force", "force"),
                    "design_force": ("design_force", "force")},
}


def parse_profile(spec, *, length, radius=None, estar=None, design_force=None,
                  crown_radius=None, diameter=None):
    """Build a profile from its command-line form ``NAME[:opt=val,...]``.

    ``straight``; ``end-relief:r=1mm[,l=0.8mm]`` or ``end-relief:l=1mm,angle=0.1deg``
    (or ``drop=5um``); ``circular:Rc=500mm[,x0=1mm]``; ``iso16281[:D=10mm]`` (default
    `diameter`, else 2 `radius`); ``lundberg[:F0=5kN]`` and ``johns-gohar[:F0=5kN]`` (default F0 =
    ``design_force``, e.g. the load being computed); ``file:PATH.csv``.

    .. math:: P(x) \\text{ as in the profile classes of this module}

    Parameters
    ----------
    spec : str
        The profile specification.
    length : float
        Roller length L [m].
    radius : float, optional
        Radius R across the axis as the contact sees it (the effective radius against
        a raceway): johns-gohar's Hertz half-width b, and iso16281's default D = 2R
        when `diameter` is not given [m].
    estar : float, optional
        Effective modulus E* (for lundberg, johns-gohar) [Pa].
    design_force : float, optional
        Default design load F0 for lundberg and johns-gohar [N].
    crown_radius : float, optional
        Default Rc for ``circular`` without ``Rc=`` [m].
    diameter : float, optional
        The roller's own diameter D, default for ``iso16281`` without ``D=``; give it
        when `radius` is an effective radius against a raceway (2 R_eff is not the
        roller's diameter, and the reference profile scales with D) [m].

    Returns
    -------
    Profile

    Raises
    ------
    OutOfRangeError
        Unknown name (the message lists the valid ones), unknown or repeated option, a
        value that is not a number with a fitting unit, a missing required value, or a
        value outside the profile's range. One line, naming the parameter, the value and
        the valid range.

    Notes
    -----
    Option values are SI numbers or numbers with a unit (``500mm``, ``5kN``,
    ``0.1deg``). Valid names: straight, end-relief, circular, iso16281, lundberg,
    johns-gohar, file:PATH.csv.

    Examples
    --------
    >>> parse_profile("circular:Rc=0.5", length=20e-3).label
    'circular crown (Rc = 500 mm)'
    >>> parse_profile("iso16281", length=10e-3, radius=5e-3).label
    'ISO 16281 (D = 10 mm, L <= 2.5 D)'
    >>> parse_profile("cone", length=10e-3)
    Traceback (most recent call last):
    ...
    linecontact.errors.UnknownNameError: profile = 'cone' is not a known name; valid: 'straight', 'end-relief', 'circular', 'iso16281', 'lundberg', 'johns-gohar', 'file:PATH.csv'

    References
    ----------
    See the module docstring for each profile's source.
    """
    valid_names = [k if k != "file" else "file:PATH.csv" for k in PROFILE_KEYS]
    if not isinstance(spec, str) or not spec.strip():
        raise UnknownNameError("profile", str(spec), valid_names)
    spec = spec.strip()
    name, _, rest = spec.partition(":")
    name = name.strip().lower()
    if name == "file":
        if not rest.strip():
            raise OutOfRangeError("profile", spec, "file:PATH.csv",
                                  hint="give the path of a CSV of x [m], drop [m]")
        prof = TabulatedProfile.from_csv(rest.strip())
        return prof
    if name not in _OPTIONS:
        raise UnknownNameError("profile", spec.split(":")[0], valid_names)
    aliases = _OPTIONS[name]
    kw = {}
    if rest.strip():
        for item in rest.split(","):
            key, eq, val = item.partition("=")
            key = key.strip()
            if not eq or not val.strip():
                raise OutOfRangeError(f"profile option {key or item!r}", item.strip(),
                                      "opt=value", hint=f"in {spec!r}")
            if key not in aliases:
                opts = sorted({a for a in aliases}) or ["none"]
                raise UnknownNameError(f"{name} option", key, opts)
            kwname, kind = aliases[key]
            if kwname in kw:
                raise OutOfRangeError(f"{name} option", key, "each option once")
            kw[kwname] = _opt_value(key, val.strip(), kind,
                                    positive=kwname not in _SIGNED_OPTIONS)

    def need(what, value, unit):
        if value is None:
            raise OutOfRangeError(what, "missing", f"(0, inf) {unit}",
                                  hint=f"the {name} profile needs it")
        return value

    if name == "straight":
        return StraightProfile(length)
    if name == "end-relief":
        return EndReliefProfile(length, **kw)
    if name == "circular":
        kw.setdefault("crown_radius", crown_radius)
        need("crown_radius", kw["crown_radius"], "m")
        return CircularCrownProfile(length, **kw)
    if name == "iso16281":
        if "diameter" not in kw:
            kw["diameter"] = (diameter if diameter is not None
                              else 2 * need("radius", radius, "m"))
        return ISO16281Profile(length, **kw)
    kw.setdefault("design_force", design_force)
    need("design_force", kw["design_force"], "N")
    need("estar", estar, "Pa")
    if name == "lundberg":
        return LundbergProfile(length, estar, **kw)
    return JohnsGoharProfile(length, need("radius", radius, "m"), estar, **kw)


def as_profile(profile, radius, length, estar):
    """A roller's profile from a :class:`Profile`, a spec (:func:`parse_profile`, read
    with this R, L, E*) or None (straight); anything else is refused."""
    if profile is None:
        return StraightProfile(length)
    if isinstance(profile, str):
        return parse_profile(profile, length=length, radius=radius, estar=estar)
    if not isinstance(profile, Profile):
        raise OutOfRangeError("profile", repr(profile),
                              "a linecontact.profiles.Profile, a profile spec or None")
    return profile


def roller_drop(profile, length, x, ends_may_be_inf=False):
    """The drop P(x) [m] of `profile` on a roller of length L, checking that the profile
    covers -L/2 <= x <= L/2 and that the drop is finite and >= 0 (or +inf exactly at an
    end, where a logarithmic profile is infinite, if `ends_may_be_inf`)."""
    tol = 1e-12 * length
    if profile.x_min > -length / 2 + tol or profile.x_max < length / 2 - tol:
        raise OutOfRangeError("profile", profile.label,
                              f"a profile covering [{-length / 2:.6g}, {length / 2:.6g}] m",
                              hint=f"it covers [{profile.x_min:.6g}, {profile.x_max:.6g}] m")
    xc = np.minimum(np.maximum(x, profile.x_min), profile.x_max)
    if type(profile).drop is Profile.drop:
        # x is inside the profile's range (clamped above): its formula directly, without
        # the public method's range check (the slice solver asks at every step)
        with np.errstate(divide="ignore"):
            P = np.asarray(profile._drop(xc), dtype=float)
    else:
        P = np.asarray(profile.drop(xc), dtype=float)
    if not ends_may_be_inf and P.size and P.min() >= 0 and P.max() < np.inf:
        # finite and >= 0 everywhere, in two reductions (NaN fails both tests): the
        # slice solver asks at every regrid, and the masks below cost more calls
        return P
    ok = np.isfinite(P) & (P >= 0)
    if ends_may_be_inf:
        ok |= np.isposinf(P) & (np.abs(x) >= length / 2 * (1 - 1e-12))
    if not ok.all():
        i = int(np.flatnonzero(~ok)[0])
        raise OutOfRangeError("profile drop", float(P[i]), "[0, inf) m", unit="m",
                              where=f"at x = {x[i]:.6g} m")
    return P


#: The profile classes whose drop, by its formula and the checks of its constructor,
#: is finite and >= 0 at every x strictly inside a roller it covers (the logarithmic
#: ones are infinite only at the ends): :func:`drop_inside` evaluates them without
#: roller_drop's range clamp and checks, and :func:`profile_identity` names them by
#: their parameters.
_FORMULA_PROFILES = (StraightProfile, EndReliefProfile, CircularCrownProfile,
                     ISO16281Profile, LundbergProfile, JohnsGoharProfile,
                     TabulatedProfile)


def drop_inside(profile, length):
    """A callable x -> P(x) [m] for points strictly inside a roller of length L
    (|x| < L/2) that `profile` covers (checked before by :func:`roller_drop`): for the
    profiles of this module (the exact classes, not subclasses) their formula directly,
    the same floats as roller_drop without its clamp (an identity inside) and its
    finite, >= 0 check (true of the formula there); for any other profile
    roller_drop itself, checks included. The roller solver evaluates the drop at every
    regrid, on some 150 points, where those calls cost more than the formula."""
    if type(profile) in _FORMULA_PROFILES:
        return profile._drop
    # (a partial, not a closure: a roller holding it pickles, to a process pool's
    # workers, with a user's profile class too)
    return functools.partial(roller_drop, profile, length)


#: The profile classes with a smooth drop inside the roller whose derivative
#: :func:`drop_slope_inside` gives in closed form (an end relief's kink and a table's
#: knots are left to differences).
_SLOPE_PROFILES = (StraightProfile, CircularCrownProfile, ISO16281Profile,
                   LundbergProfile, JohnsGoharProfile)


def drop_slope_inside(profile):
    """A callable x -> (P(x), dP/dx) [m, -] for points strictly inside a roller the
    profile covers (as :func:`drop_inside`), the drop the same floats as drop_inside's
    and the slope in closed form, for the smooth profiles of this module (exact
    classes: straight, circular, iso16281, lundberg, johns-gohar); None for the others
    (the roller solver then takes central differences of the drop)."""
    if type(profile) in _SLOPE_PROFILES:
        return profile._drop_slope
    return None


def profile_identity(profile):
    """A hashable key that equals another profile's exactly when both are of the same
    class of this module and hold equal parameters (so that their drops are the same
    floats), or None for a profile without one (a table, a user's class): a key for
    caching what depends on the drop alone. Read at each call: a profile whose
    parameters were changed in place gets a new key."""
    if type(profile) not in _FORMULA_PROFILES:
        return None
    key = (type(profile),) + tuple(sorted(vars(profile).items()))
    try:
        hash(key)
    except TypeError:            # an array parameter (a table)
        return None
    return key


def is_free_tilt(tilt):
    """Whether a tilt argument asks for moment equilibrium (``"free"``) or holds a
    number; any other word, and None, is refused.

    Parameters
    ----------
    tilt : float or str
        A tilt theta [rad] (a number, checked where it is used) or ``"free"``.

    Returns
    -------
    bool
        True for ``"free"``.

    Raises
    ------
    UnknownNameError
        Another word, or None (ambiguous: give 0 for an aligned roller or ``"free"``).

    Notes
    -----
    Valid for any input (a classification); the range |theta| < 0.1 rad is checked by
    :data:`TILT_RANGE` where the number is used.

    Examples
    --------
    >>> is_free_tilt("free"), is_free_tilt(0.0), is_free_tilt(1e-3)
    (True, False, False)
    """
    if isinstance(tilt, str):
        if tilt == FREE_TILT:
            return True
        raise UnknownNameError("tilt", tilt, [FREE_TILT, "a number [rad]"])
    if tilt is None:
        raise UnknownNameError("tilt", None, [FREE_TILT, "a number [rad]"],
                               hint="0 for an aligned roller, 'free' for moment "
                                    "equilibrium")
    return False
