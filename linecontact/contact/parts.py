"""The parts a :class:`~linecontact.contact.Contact` is composed of: the roller
(:class:`Roller`), the counter-body (:class:`Flat`, :class:`Convex`, :class:`Concave`;
the raceways of a bearing are :class:`linecontact.raceway.Raceways`) and the materials
(:class:`Elastic`, :class:`Viscoelastic`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..profiles import FREE_TILT, TILT_RANGE, CircularCrownProfile, is_free_tilt
from ..raceway import effective_radius
from ..errors import CombinationError
from ..checks import check_positive

__all__ = ["Roller", "Flat", "Convex", "Concave", "Elastic", "Viscoelastic", "FREE"]

#: The tilt value asking for moment equilibrium.
FREE = FREE_TILT


def _radius(name, radius, diameter):
    if (radius is None) == (diameter is None):
        raise CombinationError({f"{name}radius": radius, f"{name}diameter": diameter},
                               "give a radius or a diameter, exactly one")
    if radius is not None:
        return float(check_positive(f"{name}radius", radius, "m"))
    return 0.5 * float(check_positive(f"{name}diameter", diameter, "m"))


def _tilt(tilt):
    return FREE if is_free_tilt(tilt) else TILT_RANGE.check(tilt).item()


@dataclass(frozen=True, init=False)
class Roller:
    """The roller: radius (or diameter), length, axial profile and tilt.

    Parameters
    ----------
    radius : float, optional
        Radius R1 across the axis, 0 < R1 < inf [m].
    length : float
        Length L, 0 < L < inf [m].
    diameter : float, optional
        Diameter 2 R1 instead of `radius` [m].
    profile : Profile or str or None, optional
        Axial profile drop (:mod:`linecontact.profiles`), a spec such as
        ``"circular:Rc=300mm"`` or ``"iso16281"`` (read with this roller's R1, L), or
        None (straight).
    crown_radius : float, optional
        Crown radius Rc of a circular crown: the same as
        ``profile=CircularCrownProfile(L, Rc)`` (not with `profile`) [m].
    tilt : float or str, optional
        Tilt theta of the axis against the counter-body (the inner raceway between
        raceways), positive when the +x end goes deeper, |theta| < 0.1 [rad]; default
        0 (aligned); ``"free"``: the tilt at which the moment about the roller's centre
        vanishes.

    Notes
    -----
    Valid for 0 < R1, L < inf, |theta| < 0.1 rad. The attributes are SI; ``profile``
    keeps what was given (a spec is read when the contact is built, with its E*).

    Examples
    --------
    >>> Roller(diameter=16e-3, length=12e-3, crown_radius=0.3).profile.label
    'circular crown (Rc = 300 mm)'
    >>> Roller(8e-3, 12e-3).tilt
    0.0
    """

    radius: float
    length: float
    profile: object
    tilt: object

    def __init__(self, radius=None, length=None, *, diameter=None, profile=None,
                 crown_radius=None, tilt=0.0):
        R = _radius("", radius, diameter)
        if length is None:
            raise CombinationError({"length": None}, "the roller's length is needed")
        L = float(check_positive("length", length, "m"))
        if crown_radius is not None:
            if profile is not None:
                raise CombinationError({"profile": str(profile),
                                        "crown_radius": crown_radius},
                                       "a crown radius is a profile: give one of them",
                                       unit={"crown_radius": "m"})
            profile = CircularCrownProfile(L, crown_radius)
        object.__setattr__(self, "radius", R)
        object.__setattr__(self, "length", L)
        object.__setattr__(self, "profile", profile)
        object.__setattr__(self, "tilt", _tilt(tilt))

    @property
    def diameter(self):
        """2 R1 [m]."""
        return 2.0 * self.radius


@dataclass(frozen=True)
class Flat:
    """A flat counter-body (a half-space): the contact's radius is the roller's.

    Examples
    --------
    >>> Flat().effective_radius(5e-3)
    0.005
    """

    def effective_radius(self, roller_radius):
        """R = R1 [m]."""
        return float(roller_radius)


@dataclass(frozen=True, init=False)
class Convex:
    r"""A convex cylindrical counter-body with its axis parallel to the roller's.

    .. math:: \frac{1}{R} = \frac{1}{R_1} + \frac{1}{R_2}

    Parameters
    ----------
    radius : float, optional
        Its radius R2, 0 < R2 < inf [m].
    diameter : float, optional
        Its diameter 2 R2 instead of `radius` [m].

    Notes
    -----
    Valid for 0 < R2 < inf (parallel axes).

    Examples
    --------
    >>> f"{Convex(diameter=50e-3).effective_radius(8e-3) * 1e3:.4f} mm"
    '6.0606 mm'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """

    radius: float

    def __init__(self, radius=None, *, diameter=None):
        object.__setattr__(self, "radius", _radius("", radius, diameter))

    def effective_radius(self, roller_radius):
        """R = 1/(1/R1 + 1/R2) [m]."""
        return effective_radius(roller_radius, self.radius)


@dataclass(frozen=True, init=False)
class Concave:
    r"""A concave cylindrical counter-body (a bore) around the roller, axes parallel.

    .. math:: \frac{1}{R} = \frac{1}{R_1} - \frac{1}{R_2}, \qquad R_2 > R_1

    Parameters
    ----------
    radius : float, optional
        Its radius R2, larger than the roller's [m].
    diameter : float, optional
        Its diameter 2 R2 instead of `radius` [m].

    Notes
    -----
    Valid for R1 < R2 < inf (checked against the roller when the contact is built).

    Examples
    --------
    >>> f"{Concave(25e-3).effective_radius(8e-3) * 1e3:.4f} mm"
    '11.7647 mm'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """

    radius: float

    def __init__(self, radius=None, *, diameter=None):
        object.__setattr__(self, "radius", _radius("", radius, diameter))

    def effective_radius(self, roller_radius):
        """R = 1/(1/R1 - 1/R2) [m]; refused unless R2 > R1."""
        if not self.radius > roller_radius:
            raise CombinationError({"radius": float(roller_radius),
                                    "radius2": self.radius},
                                   "the roller does not fit inside the concave body "
                                   "(its radius must exceed the roller's)",
                                   unit={"radius": "m", "radius2": "m"})
        return effective_radius(roller_radius, -self.radius)


@dataclass(frozen=True, init=False)
class Elastic:
    """An elastic body: Young's modulus (``inf``: rigid) and Poisson ratio.

    Parameters
    ----------
    modulus : float
        Young's modulus E, 0 < E <= inf [Pa].
    poisson : float, optional
        Poisson ratio nu, 0 <= nu <= 0.5 [-]; needed for the effective modulus unless
        rigid (then it does not enter).

    Notes
    -----
    Valid for 0 < E <= inf, 0 <= nu <= 0.5.

    Examples
    --------
    >>> f"{Elastic(210e9, 0.3).compliance:.4e} 1/Pa"
    '4.3333e-12 1/Pa'
    >>> Elastic(math.inf).compliance
    0.0
    """

    modulus: float
    poisson: object

    def __init__(self, modulus, poisson=None):
        from ..classical import MODULUS_OR_RIGID
        from ..checks import POISSON_RATIO

        E = MODULUS_OR_RIGID.check(modulus).item()
        nu = None if poisson is None else POISSON_RATIO.check(poisson).item()
        if nu is None and math.isfinite(E):
            raise CombinationError({"modulus": E, "poisson": None},
                                   "an elastic body's Poisson ratio is needed for E* "
                                   "(or give the contact's estar)", unit={"modulus": "Pa"})
        object.__setattr__(self, "modulus", E)
        object.__setattr__(self, "poisson", nu)

    @property
    def compliance(self):
        """(1 - nu^2)/E [1/Pa], 0 for a rigid body."""
        return 0.0 if math.isinf(self.modulus) else (1 - self.poisson ** 2) / self.modulus

    @property
    def shear_compliance(self):
        """(2 - nu)/(4 G) [1/Pa] (the body's share of 1/G*), 0 for a rigid body."""
        if math.isinf(self.modulus):
            return 0.0
        G = self.modulus / (2 * (1 + self.poisson))
        return (2 - self.poisson) / (4 * G)


@dataclass(frozen=True)
class Viscoelastic:
    """A linear viscoelastic body: the relaxation of its Young's modulus and its Poisson
    ratio (constant in time).

    Parameters
    ----------
    relaxation : PronySeries
        E(t) of the body (:class:`~linecontact.viscoelastic.StandardLinearSolid` or a
        :class:`~linecontact.viscoelastic.PronySeries`) [Pa].
    poisson : float
        Poisson ratio nu, 0 <= nu <= 0.5 [-].

    Notes
    -----
    Valid for a constant Poisson ratio (the correspondence principle then applies to
    E(t)); the counterpart must be elastic.

    Examples
    --------
    >>> from linecontact.viscoelastic import StandardLinearSolid
    >>> Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.4).poisson
    0.4
    """

    relaxation: object
    poisson: float
