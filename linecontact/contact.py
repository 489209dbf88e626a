r"""One roller contact described completely, its parts composed: the library's front door.

A :class:`Contact` is built from four parts and answers every question about it:

- the **roller** (:class:`Roller`): radius or diameter, length, axial profile (a crown
  radius is a circular profile), tilt (a number, 0 by default: aligned; or ``"free"``:
  moment equilibrium);
- the **counter-body**: :class:`Flat`, :class:`Convex` or :class:`Concave` (a radius or a
  diameter), or the inner and outer raceway of a radial bearing
  (:class:`~linecontact.raceway.Raceways`: the whole roller, two contacts in series);
- the **materials**: :class:`Elastic` roller and counter-body (a rigid one has an
  infinite modulus), or one of them :class:`Viscoelastic` against an elastic one, or
  simply the effective modulus ``estar``;
- the **loading**, given to the methods: a normal force or depth
  (:meth:`Contact.normal`), a tangential force or shift with a friction coefficient
  (:meth:`Contact.tangential`), a time history (:meth:`Contact.creep`,
  :meth:`Contact.relaxation_history`).

Each output is computed from that combination: a profiled roller by coupled slices
(:mod:`linecontact.roller`), a straight aligned one by a contact law
(:mod:`linecontact.models`, the universal curve by default); the tangential law of a
contact from its own normal law F(d) by the method of dimensionality reduction
(:mod:`linecontact.tangential`: :math:`k_t = (G^*/E^*)\,k_n`,
:math:`F_t(u) = \mu[F(d) - F(d - G^* u/(\mu E^*))]`); creep and relaxation from the same
law by Lee & Radok's correspondence (:mod:`linecontact.viscoelastic`); the whole roller
between raceways from its two contacts (:mod:`linecontact.raceway`). An output the
physics or the methods here do not define for a combination is refused: a result field
is None and :meth:`ContactResult.get` raises :class:`~linecontact.errors.CombinationError`
with the reason, and a combination that defines nothing is refused when the
:class:`Contact` is built or the method called. The depth of a contact is its approach
at the roller's centre (x = 0); ``approach`` is measured from first contact (they differ
for a tilted roller).

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
   Friction, Springer (2015), chapters 3-4 (tangential law from the normal law).
.. [2] E. H. Lee, J. R. M. Radok, The contact problem for viscoelastic bodies, J. Appl.
   Mech. 27 (1960) 438-444.
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   4.2 (two cylinders), 7 (tangential loading).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._numerics import out
from .checks import check_positive
from .errors import CombinationError, OutOfRangeError, UnknownNameError
from .models import ContactModel
from .profiles import FREE_TILT, TILT_RANGE, CircularCrownProfile, as_profile, is_free_tilt
from .raceway import SLICE_MODELS, Raceways, roller_between_raceways

__all__ = [
    "Roller",
    "Flat",
    "Convex",
    "Concave",
    "Raceways",
    "Elastic",
    "Viscoelastic",
    "Contact",
    "ContactResult",
    "TangentialResult",
    "CreepResult",
    "FREE",
]

#: The tilt value asking for moment equilibrium.
FREE = FREE_TILT
#: Law used for a straight, aligned roller when no model is named.
DEFAULT_LAW = "universal"
#: Model used for a profiled or tilted roller when no model is named.
DEFAULT_SLICES = "profiled-roller"


def _radius(name, radius, diameter):
    if (radius is None) == (diameter is None):
        raise CombinationError({f"{name}radius": radius, f"{name}diameter": diameter},
                               "give a radius or a diameter, exactly one")
    if radius is not None:
        return float(check_positive(f"{name}radius", radius, "m"))
    return 0.5 * float(check_positive(f"{name}diameter", diameter, "m"))


def _tilt(tilt):
    return FREE if is_free_tilt(tilt) else TILT_RANGE.check(tilt).item()


# --------------------------------------------------------------------------------------
# the parts
# --------------------------------------------------------------------------------------
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
        return 1.0 / (1.0 / roller_radius + 1.0 / self.radius)


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
        return 1.0 / (1.0 / roller_radius - 1.0 / self.radius)


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
        from .checks import POISSON_RATIO
        from .classical import MODULUS_OR_RIGID

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


# --------------------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------------------
class _Result:
    """get(name): the value, or CombinationError with the reason it is not defined."""

    def get(self, name):
        """The output `name`, or :class:`CombinationError` saying why it is not defined.

        Parameters
        ----------
        name : str
            An attribute of this result.

        Returns
        -------
        object
            Its value.

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9)
        >>> c.normal(force=1e3).get("q")
        Traceback (most recent call last):
        ...
        linecontact.errors.CombinationError: model = 'universal', output = 'q': a straight-cylinder law gives F(d), not the load along the roller; use model='profiled-roller' (coupled slices)
        """
        if name not in self.__dataclass_fields__:
            raise UnknownNameError("output", name, list(self.__dataclass_fields__))
        value = getattr(self, name)
        if value is None and name in self.reasons:
            raise CombinationError(self.reasons[name][0] | {"output": name},
                                   self.reasons[name][1])
        return value

    def to_dict(self):
        """Every output by name (:func:`linecontact.tabular.to_dict`)."""
        from .tabular import to_dict
        return to_dict(self)

    def to_frame(self):
        """A pandas DataFrame, one row per load or time (:func:`linecontact.tabular.to_frame`)."""
        from .tabular import to_frame
        return to_frame(self)

    def _repr_html_(self):
        """The table Jupyter shows (:func:`linecontact.tabular.html_table`)."""
        from .tabular import html_table
        return html_table(self)


@dataclass(frozen=True)
class ContactResult(_Result):
    """The normal state of a composed contact (scalars, or arrays over the loads).

    Built by :meth:`Contact.normal`; not by hand. A field that this combination does not
    define is None and :attr:`reasons` says why (:meth:`get` raises with it).

    Parameters
    ----------
    force : float or ndarray
        Normal force F [N].
    depth : float or ndarray
        Depth at the roller's centre (between raceways: the ring approach) [m].
    approach : float or ndarray
        Depth beyond first contact (equal to depth unless tilted) [m].
    stiffness : float or ndarray
        dF/dd (tilt held, or free with the moment balance kept) [N/m].
    moment : float or ndarray
        Moment about the roller's centre (between raceways: the one that holds the
        roller at its tilt) [N m].
    tilt : float or ndarray
        Roller tilt [rad].
    tilt_stiffness : float or ndarray or None
        dM/dtheta at constant force [N m/rad].
    x : ndarray or None
        Slice centres along the axis (one load) [m].
    q : ndarray or None
        Line load q(x) (one load) [N/m].
    peak_pressure : float or ndarray or None
        Peak pressure (a law: plane-strain Hertz p0; slices: the model's peak) [Pa].
    half_width : float or ndarray or None
        Largest contact half-width b across the roller [m].
    model : str
        The law or slice method used.
    notes : tuple of str
        Validity notes.
    reasons : dict
        Output name -> (parameters, reason) for each field that is None.
    solutions : tuple
        The underlying :class:`~linecontact.roller.RollerSolution` or
        :class:`~linecontact.raceway.RacewaySolution` per load (empty for a law on one
        contact).

    Notes
    -----
    Valid as the model that produced it.

    Examples
    --------
    >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), estar=115.38e9, n_slices=40)
    >>> r = c.normal(force=1e3)
    >>> f"{r.depth * 1e6:.3f} um, p0 {r.peak_pressure / 1e6:.0f} MPa", r.model
    ('7.430 um, p0 1522 MPa', 'profiled-roller')
    """

    force: object
    depth: object
    approach: object
    stiffness: object
    moment: object
    tilt: object
    tilt_stiffness: object
    x: object
    q: object
    peak_pressure: object
    half_width: object
    model: str
    notes: tuple = ()
    reasons: dict = field(default_factory=dict)
    solutions: tuple = ()


@dataclass(frozen=True)
class TangentialResult(_Result):
    """The tangential state of a composed contact (Cattaneo-Mindlin by the MDR).

    Built by :meth:`Contact.tangential`; not by hand.

    Parameters
    ----------
    normal : ContactResult
        The normal state (held while the tangential load acts).
    friction : float
        Coulomb friction coefficient mu [-].
    shear_ratio : float
        G*/E* [-].
    stiffness : float or ndarray
        Full-stick tangential stiffness k_t = (G*/E*) k_n [N/m].
    tangential_force : float or ndarray or None
        Tangential force Q [N] (signed).
    shift : float or ndarray or None
        Tangential shift u [m] (signed as Q); None beyond gross slip.
    slip_fraction : float or ndarray or None
        |Q|/(mu F) [-]: below 1 partial slip, 1 gross slip.
    state : str or ndarray
        ``"stick"``, ``"partial slip"`` or ``"gross slip"``.
    gross_slip_force : float or ndarray
        mu F [N].
    gross_slip_shift : float or ndarray
        u* = mu E* d/G* (d the approach) [m] (with the BEM table's correction for
        ``method="bem"``).
    reasons : dict
        Output name -> (parameters, reason) for each None field.
    method : str
        ``"mdr"`` or ``"bem"``.
    stiffness_ratio : float or ndarray
        k_t/k_n used: G*/E*, or the BEM table's ratio in the direction asked [-].

    Notes
    -----
    Valid under the Cattaneo-Mindlin assumptions (uncoupled normal and tangential
    problems; see :mod:`linecontact.tangential`), exact for any shape at nu = 0.

    Examples
    --------
    >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), material1=Elastic(210e9, 0.3),
    ...             material2=Elastic(210e9, 0.3), n_slices=40)
    >>> t = c.tangential(0.15, force=1e3, tangential_force=-50.0)
    >>> t.state, f"{t.shift * 1e9:.1f} nm"
    ('partial slip', '-320.5 nm')
    """

    normal: object
    friction: float
    shear_ratio: float
    stiffness: object
    tangential_force: object
    shift: object
    slip_fraction: object
    state: object
    gross_slip_force: object
    gross_slip_shift: object
    reasons: dict = field(default_factory=dict)
    method: str = "mdr"
    stiffness_ratio: object = None


@dataclass(frozen=True)
class CreepResult(_Result):
    """A time history of a composed contact with a viscoelastic body.

    Built by :meth:`Contact.creep` and :meth:`Contact.relaxation_history`; not by hand.

    Parameters
    ----------
    time : ndarray
        Sample times [s].
    force : ndarray
        Normal force F(t) [N].
    depth : ndarray
        Depth d(t) at the roller's centre (between raceways: the ring approach) [m].
    long_term_depth : float or None
        Depth under the final force at t -> inf (creep only) [m].
    model : str
        The law used.
    reasons : dict
        Output name -> (parameters, reason) for each None field.

    Notes
    -----
    Valid while the contact grows (Lee & Radok 1960).

    Examples
    --------
    >>> from linecontact.viscoelastic import StandardLinearSolid
    >>> c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
    ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
    >>> r = c.creep([0.0, 30.0], force=1e3)
    >>> [f"{d * 1e6:.2f} um" for d in r.depth]
    ['82.58 um', '168.03 um']
    """

    time: object
    force: object
    depth: object
    long_term_depth: object
    model: str
    reasons: dict = field(default_factory=dict)


# --------------------------------------------------------------------------------------
# a slice model as a contact law in the approach (for the tangential and creep laws)
# --------------------------------------------------------------------------------------
class _ApproachLaw(ContactModel):
    """F(e) of a slice-solved roller at a fixed tilt, e = depth - first-contact depth, so
    that F(0) = 0 as the MDR and Lee-Radok laws take it (not registered)."""

    key = "approach-law"

    def __init__(self, roller, tilt, solver):
        super().__init__(roller.radius, roller.length, roller.estar)
        self.roller, self.tilt, self.solver = roller, tilt, solver
        self.d0 = roller.first_contact_depth(tilt)

    @property
    def label(self):
        return f"{self.solver} (tilt {self.tilt:g} rad), approach from first contact"

    @property
    def provenance(self):
        return {"model": self.label}

    def _each(self, values, fn):
        v = np.asarray(values, dtype=float)
        return out(np.array([fn(float(e)) for e in v.ravel()]).reshape(v.shape))

    def force(self, depth):
        return self._each(depth, lambda e: self.roller.at_depth(self.d0 + e,
                                                                self.tilt).force)

    def depth(self, force):
        return self._each(force, lambda f: self.roller.at_force(f, self.tilt).depth
                          - self.d0)

    def stiffness(self, depth):
        return self._each(depth, lambda e: self.roller.at_depth(self.d0 + e,
                                                                self.tilt).stiffness)


def _split(sol):
    """A RacewaySolution over an array of loads as one RacewaySolution per load."""
    from dataclasses import fields, replace

    arrays = {f.name: np.asarray(getattr(sol, f.name)) for f in fields(sol)
              if isinstance(getattr(sol, f.name), np.ndarray)}
    shape = np.shape(sol.force)
    return tuple(replace(sol, **{k: float(v[idx]) for k, v in arrays.items()})
                 for idx in np.ndindex(*shape))


# --------------------------------------------------------------------------------------
class Contact:
    """A roller against a counter-body, of given materials: every output of the contact.

    Parameters
    ----------
    roller : Roller
        The roller (radius, length, profile, tilt).
    counterbody : Flat or Convex or Concave or Raceways, optional
        The counter-body (default :class:`Flat`).
    material1 : Elastic or Viscoelastic, optional
        The roller's material.
    material2 : Elastic or Viscoelastic, optional
        The counter-body's material (the rings' between raceways).
    estar : float, optional
        The effective modulus E* instead of the two materials (no G*: no tangential
        law) [Pa].
    model : str, optional
        The contact law (a key of :func:`linecontact.models.available_models`); default
        ``"universal"`` for a straight, aligned roller and ``"profiled-roller"``
        (coupled slices) for a profiled or tilted one.
    n_slices : int, optional
        Slices of a slice model (default: the model's) [-].
    **options
        Options of the law (e.g. ``c=0.72`` for Johnson's).

    Raises
    ------
    CombinationError
        A combination not defined: both materials viscoelastic; a profile or tilt with
        a straight-cylinder law; materials and estar together; a concave body or
        raceways that do not fit the roller.
    UnknownNameError
        An unknown model key.

    Attributes
    ----------
    estar : float
        E* [Pa] (instantaneous, E*(0), with a viscoelastic body).
    gstar : float or None
        G* [Pa]; None when the contact was given by estar or is viscoelastic.
    relaxation : PronySeries or None
        E*(t) with a viscoelastic body.
    radius : float or None
        Effective radius of the single contact [m] (None between raceways).
    profile : Profile
        The roller's profile, read.
    tilt : float or str
        The roller's tilt [rad] or ``"free"``.
    model : str
        The model used; ``sliced`` True for a slice model, ``raceways`` True between
        raceways; ``n_slices`` and ``options`` as given.

    Notes
    -----
    Valid within the parts' ranges (0 < R, L, E* < inf, |theta| < 0.1 rad) and the
    model's. With a viscoelastic body the instantaneous modulus E*(0) gives the
    instantaneous response (:meth:`normal`), and its relaxation the histories.

    Examples
    --------
    The crowned cam follower of docs/composition.md (steel on steel):

    >>> steel = Elastic(210e9, 0.3)
    >>> c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), steel, steel,
    ...             n_slices=40)
    >>> r = c.normal(force=2e3)
    >>> f"{r.depth * 1e6:.2f} um, k {r.stiffness / 1e6:.0f} N/um"
    '13.21 um, k 227 N/um'
    """

    def __init__(self, roller, counterbody=None, material1=None, material2=None, *,
                 estar=None, model=None, n_slices=None, **options):
        from .classical import effective_modulus
        from .models import available_models

        if not isinstance(roller, Roller):
            raise OutOfRangeError("roller", repr(roller), "a linecontact.contact.Roller")
        self.roller = roller
        self.counterbody = Flat() if counterbody is None else counterbody
        if not isinstance(self.counterbody, (Flat, Convex, Concave, Raceways)):
            raise OutOfRangeError("counterbody", repr(counterbody),
                                  "Flat(), Convex(R), Concave(R) or Raceways(Ri, Ro)")
        self.raceways = isinstance(self.counterbody, Raceways)
        # materials -> E* (instantaneous), G*, the relaxation of E*
        self.relaxation = None
        self.gstar = None
        if estar is not None:
            if material1 is not None or material2 is not None:
                raise CombinationError({"estar": estar, "material1": repr(material1),
                                        "material2": repr(material2)},
                                       "give the materials or estar, not both")
            self.estar = float(check_positive("estar", estar, "Pa"))
        else:
            if material1 is None or material2 is None:
                raise CombinationError({"material1": repr(material1),
                                        "material2": repr(material2)},
                                       "give both materials (Elastic(math.inf) for a "
                                       "rigid one) or the effective modulus estar")
            self._materials(material1, material2, effective_modulus)
        R1, L = roller.radius, roller.length
        self.profile = as_profile(roller.profile, R1, L, self.estar)
        self.tilt = roller.tilt
        straight = type(self.profile).__name__ == "StraightProfile"
        misaligned = self.raceways and self.counterbody.misalignment != 0.0
        plain = straight and self.tilt in (0.0, FREE) and not misaligned
        self.model = model if model is not None else (DEFAULT_LAW if plain
                                                      else DEFAULT_SLICES)
        if self.model not in available_models():
            raise UnknownNameError("model", self.model, available_models())
        self.sliced = self.model in SLICE_MODELS
        if not self.sliced and not plain:
            raise CombinationError(
                {"model": self.model, "profile": self.profile.label,
                 "tilt": self.tilt},
                "a straight-cylinder law has no profile or tilt; use "
                "model='profiled-roller' (coupled slices)")
        if self.sliced and options:
            raise CombinationError({"model": self.model, "options": sorted(options)},
                                   "a slice model takes no law options")
        self.n_slices = n_slices
        self.options = options
        if self.raceways:
            self.counterbody.check_fit(R1)
            self.radius = None
        else:
            self.radius = self.counterbody.effective_radius(R1)
        self._law = None
        self._slices = None

    def _materials(self, m1, m2, effective_modulus):
        from .viscoelastic import effective_relaxation

        for name, m in (("material1", m1), ("material2", m2)):
            if not isinstance(m, (Elastic, Viscoelastic)):
                raise OutOfRangeError(name, repr(m), "Elastic(E, nu) or Viscoelastic("
                                                     "relaxation, nu)")
        visco = [isinstance(m, Viscoelastic) for m in (m1, m2)]
        if all(visco):
            raise CombinationError({"material1": "Viscoelastic", "material2":
                                    "Viscoelastic"}, "the correspondence principle is "
                                   "applied here to one viscoelastic body against an "
                                   "elastic one")
        if any(visco):
            v, e = (m1, m2) if visco[0] else (m2, m1)
            self.relaxation = effective_relaxation(v.relaxation, v.poisson, e.modulus,
                                                   e.poisson)
            self.estar = float(self.relaxation.instantaneous)
            self.viscoelastic = "material1" if visco[0] else "material2"
            return
        self.viscoelastic = None
        if math.isinf(m1.modulus) and math.isinf(m2.modulus):
            raise CombinationError({"material1": "rigid", "material2": "rigid"},
                                   "two rigid bodies have no contact stiffness")
        self.estar = 1.0 / (m1.compliance + m2.compliance)
        self.gstar = 1.0 / (m1.shear_compliance + m2.shear_compliance)

    # ---- the models ------------------------------------------------------------------
    def law(self):
        """The normal contact law of a single contact as a
        :class:`~linecontact.models.ContactModel` in the approach (F(0) = 0).

        Returns
        -------
        ContactModel
            The registered law (straight, aligned), or the slice model at this tilt
            with the depth measured from first contact.

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9)
        >>> c.law().key
        'universal'
        """
        return self._law_for("the contact law")

    def _law_for(self, what):
        if self.raceways:
            raise CombinationError({"counterbody": "Raceways"},
                                   "a whole roller has two contact laws in series; "
                                   "ask normal(), or Contact with Convex/Concave for "
                                   "one contact")
        if self._law is None:
            from .models import get_model

            if not self.sliced:
                self._law = get_model(self.model, self.radius, self.roller.length,
                                      self.estar, **self.options)
            else:
                tilt = self._fixed_tilt(what)
                self._law = _ApproachLaw(self._slice_roller(), tilt, self.model)
        return self._law

    def _slice_roller(self):
        from .roller import ProfiledRoller
        from .roller.slices import DEFAULT_N_SLICES

        if self.model != "profiled-roller":
            raise CombinationError({"model": self.model}, "the tangential and creep "
                                   "laws use the coupled-slice model; use "
                                   "model='profiled-roller'")
        if self._slices is None:
            self._slices = ProfiledRoller(self.radius, self.roller.length, self.estar,
                                          self.profile,
                                          n_slices=self.n_slices or DEFAULT_N_SLICES)
        return self._slices

    def _fixed_tilt(self, what):
        """The tilt to hold for a law: the given one, or a free tilt that symmetry makes
        zero at every load (a profile with P(-x) = P(x))."""
        if self.tilt != FREE:
            return self.tilt
        from .profiles import roller_drop

        L = self.roller.length
        x = np.linspace(-L / 2, L / 2, 401)[1:-1]
        P = roller_drop(self.profile, L, x)
        if np.allclose(P, P[::-1], rtol=1e-9, atol=1e-15 * L):
            return 0.0
        raise CombinationError(
            {"tilt": FREE, "profile": self.profile.label},
            f"{what} needs a contact geometry fixed while it is loaded, and the free tilt "
            "of an asymmetric profile changes with the load: give the tilt as a number "
            "(normal(force=F).tilt at your load)")

    # ---- normal ----------------------------------------------------------------------
    def normal(self, *, force=None, depth=None):
        """The normal state at a force or a depth.

        Parameters
        ----------
        force : float or array_like, optional
            Normal force F > 0 [N].
        depth : float or array_like, optional
            Depth at the roller's centre (between raceways: the ring approach), instead
            of `force` [m].

        Returns
        -------
        ContactResult

        Raises
        ------
        CombinationError
            Neither or both of force and depth.

        Notes
        -----
        Valid within the model's range. A law is evaluated on the whole array at once;
        a slice model solves each value.

        Examples
        --------
        >>> c = Contact(Roller(5e-3, 10e-3), estar=115.38e9)
        >>> f"{c.normal(force=1e3).depth * 1e6:.3f} um"
        '3.154 um'
        """
        if (force is None) == (depth is None):
            raise CombinationError({"force": force, "depth": depth},
                                   "give exactly one of force and depth")
        if self.raceways:
            return self._raceways(force, depth)
        if not self.sliced:
            return self._law_normal(force, depth)
        return self._slices_normal(force, depth)

    def _law_normal(self, force, depth):
        from .classical import hertz_half_width, hertz_peak_pressure

        m = self.law()
        m.check_applicable()
        r = m.evaluate(force=force) if force is not None else m.evaluate(depth=depth)
        F = r["force"]
        zero = out(np.zeros(np.shape(F)))
        why = ({"model": self.model}, "a straight-cylinder law gives F(d), not the load "
               "along the roller; use model='profiled-roller' (coupled slices)")
        return ContactResult(
            force=F, depth=r["depth"], approach=r["depth"], stiffness=r["stiffness"],
            moment=zero, tilt=zero, tilt_stiffness=None, x=None, q=None,
            peak_pressure=hertz_peak_pressure(F, self.radius, self.roller.length,
                                              self.estar),
            half_width=hertz_half_width(F, self.radius, self.roller.length, self.estar),
            model=self.model,
            reasons={"tilt_stiffness": (why[0], "a straight-cylinder law has no tilt "
                                        "stiffness; use model='profiled-roller'"),
                     "x": why, "q": why})

    def _solve_one(self, force, depth):
        from .roller import iso_slicing

        if self.model == "iso16281-slicing":
            return iso_slicing(self.radius, self.roller.length, self.estar, self.profile,
                               force=force, depth=depth, tilt=self.tilt,
                               n_slices=self.n_slices or 30)
        r = self._slice_roller()
        if force is not None:
            return r.at_force(force, self.tilt)
        return r.at_depth(depth, self.tilt)

    def _slices_normal(self, force, depth):
        given = force if force is not None else depth
        vals = np.asarray(given, dtype=float)
        flat = vals.ravel()
        # in increasing order, so that each slice solve starts from its neighbour's
        # (the coupled-slice roller keeps its last solution)
        sols = [None] * flat.size
        for k in np.argsort(flat, kind="stable"):
            v = float(flat[k])
            sols[k] = (self._solve_one(v, None) if force is not None
                       else self._solve_one(None, v))
        sols = tuple(sols)

        def arr(fn):
            return out(np.array([fn(s) for s in sols]).reshape(vals.shape))

        one = vals.ndim == 0
        p = [s.p_max for s in sols]
        reasons = {}
        if any(v is None for v in p):
            reasons["peak_pressure"] = ({"profile": self.profile.label},
                                        sols[[v is None for v in p].index(True)].message)
        if not one:
            why = ({"force" if force is not None else "depth": "an array"},
                   "q(x) is given for one load at a time (see solutions)")
            reasons.update(x=why, q=why)
        d0 = [self._slice_first_contact(s.tilt) for s in sols]
        notes = tuple(dict.fromkeys(n for s in sols for n in s.notes))
        return ContactResult(
            force=arr(lambda s: s.force), depth=arr(lambda s: s.depth),
            approach=out(np.array([s.depth - z for s, z in zip(sols, d0)]).reshape(
                vals.shape)),
            stiffness=arr(lambda s: self._free_stiffness(s)),
            moment=arr(lambda s: s.moment), tilt=arr(lambda s: s.tilt),
            tilt_stiffness=arr(lambda s: s.stiffness_matrix[1, 1]
                               - s.stiffness_matrix[1, 0] * s.stiffness_matrix[0, 1]
                               / s.stiffness_matrix[0, 0]),
            x=sols[0].x if one else None, q=sols[0].q if one else None,
            peak_pressure=(None if "peak_pressure" in reasons else
                           arr(lambda s: s.p_max)),
            half_width=arr(lambda s: float(np.max(s.half_width))),
            model=self.model, notes=notes, reasons=reasons, solutions=sols)

    def _slice_first_contact(self, tilt):
        if self.model == "profiled-roller":
            return self._slice_roller().first_contact_depth(tilt)
        from .profiles import roller_drop

        L, n = self.roller.length, self.n_slices or 30
        x = -L / 2 + L / n * (np.arange(n) + 0.5)
        return float(np.min(roller_drop(self.profile, L, x) - x * math.tan(tilt)))

    def _free_stiffness(self, s):
        """dF/dd: at the held tilt, or with the tilt free (M = 0 kept)."""
        K = s.stiffness_matrix
        if self.tilt != FREE:
            return float(K[0, 0])
        return float(K[0, 0] - K[0, 1] * K[1, 0] / K[1, 1])

    def _raceways(self, force, depth):
        kw = dict(model=self.model, profile=self.profile, tilt=self.tilt,
                  n_slices=self.n_slices, **self.options)
        if not self.sliced or np.ndim(force if force is not None else depth) == 0:
            vals = [force if force is not None else depth]
            one = True
        else:
            vals = list(np.asarray(force if force is not None else depth, float).ravel())
            one = False
        sols = tuple(roller_between_raceways(
            self.roller.radius, self.roller.length, self.estar, self.counterbody,
            **({"force": v} if force is not None else {"deflection": v}), **kw)
            for v in vals)

        s0 = sols[0]

        def arr(name):
            if one:
                return getattr(s0, name)
            return out(np.array([getattr(s, name) for s in sols]))

        if one and np.ndim(s0.force):
            sols = _split(s0)       # one solution per load, as for a slice model
        reasons = {}
        why_q = ({"counterbody": "Raceways"}, "a whole roller has two load distributions: "
                 "see solutions[i].inner.q and .outer.q")
        reasons.update(x=why_q, q=why_q)
        p = None
        if self.sliced:
            pk = [max((v for v in (s.peak_pressure_inner, s.peak_pressure_outer)
                       if v is not None), default=None) for s in sols]
            if all(v is not None for v in pk):
                p = pk[0] if one else out(np.array(pk))
            else:
                reasons["peak_pressure"] = ({"profile": self.profile.label},
                                            "a contact is edge loaded: its peak pressure "
                                            "is singular (see solutions)")
        else:
            p = np.maximum(s0.peak_pressure_inner, s0.peak_pressure_outer)
        if s0.tilt_stiffness is None:
            reasons["tilt_stiffness"] = ({"model": self.model}, "a straight-cylinder law "
                                         "has no tilt stiffness; use "
                                         "model='profiled-roller'")
        half = None
        reasons["half_width"] = ({"counterbody": "Raceways"},
                                 "two contacts, two half-widths (see solutions)")
        return ContactResult(
            force=arr("force"), depth=arr("deflection"), approach=arr("deflection"),
            stiffness=arr("stiffness"), moment=arr("moment"), tilt=arr("tilt"),
            tilt_stiffness=None if s0.tilt_stiffness is None else arr("tilt_stiffness"),
            x=None, q=None, peak_pressure=p, half_width=half, model=s0.model,
            notes=tuple(dict.fromkeys(n for s in sols for n in s.notes)),
            reasons=reasons, solutions=sols)

    # ---- tangential ------------------------------------------------------------------
    def tangential(self, friction, *, force=None, depth=None, tangential_force=None,
                   shift=None, method="mdr", direction="across"):
        r"""The tangential state under a tangential force or shift (Cattaneo-Mindlin, MDR).

        .. math:: k_t = \frac{G^*}{E^*}\,k_n, \qquad
                  F_t(u) = \mu\left[F(e) - F\!\left(e - \frac{G^* u}{\mu E^*}\right)
                  \right]

        with F(e) this contact's own normal law in the approach e (a crowned roller's
        from its coupled slices).

        Parameters
        ----------
        friction : float
            Coulomb friction coefficient mu > 0 [-].
        force : float or array_like, optional
            Normal force F, held [N].
        depth : float or array_like, optional
            Normal depth at the roller's centre, held, instead of `force` [m].
        tangential_force : float or array_like, optional
            Tangential force Q, either sign (the sign is the direction) [N].
        shift : float or array_like, optional
            Tangential shift u instead of Q, either sign [m].
        method : {"mdr", "bem"}, optional
            ``"mdr"`` (default): the ratio G*/E*; ``"bem"``: a straight cylinder's
            direction-dependent k_t/k_n and partial-slip correction from the BEM table
            (:class:`linecontact.tangential.TangentialContact`; straight-cylinder
            laws only).
        direction : {"across", "along"}, optional
            With ``method="bem"``: the shift across the axis (rolling direction) or
            along it.

        Returns
        -------
        TangentialResult

        Raises
        ------
        CombinationError
            No G* (the contact was given by estar), a viscoelastic body, raceways,
            a free tilt that is not zero, both Q and u.

        Notes
        -----
        Valid for mu > 0 and the model's range, under the assumptions of
        :mod:`linecontact.tangential` (exact at nu = 0 for any shape). |Q| > mu F is
        gross slip: the shift is None with the reason. A shift beyond u* is refused.

        Examples
        --------
        >>> steel = Elastic(210e9, 0.3)
        >>> c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), steel, steel,
        ...             n_slices=40)
        >>> t = c.tangential(0.15, force=2e3, tangential_force=100.0)
        >>> f"k_t {t.stiffness / 1e6:.0f} N/um, {t.state}"
        'k_t 187 N/um, partial slip'

        References
        ----------
        Popov & Hess (2015), chapter 4; C. Cattaneo (1938); R. D. Mindlin (1949).
        """
        from . import tangential as tg

        if self.raceways:
            raise CombinationError({"counterbody": "Raceways", "friction": friction},
                                   "the traction of a whole roller between raceways "
                                   "splits between its two contacts by its rolling, "
                                   "which is not modelled; compute one contact")
        if self.relaxation is not None:
            raise CombinationError({self.viscoelastic: "Viscoelastic",
                                    "friction": friction},
                                   "the tangential law of a viscoelastic contact (G*(t)) "
                                   "is not modelled")
        if self.gstar is None:
            raise CombinationError({"estar": self.estar, "friction": friction},
                                   "G* needs the bodies' Poisson ratios: give "
                                   "material1 and material2", unit={"estar": "Pa"})
        if tangential_force is not None and shift is not None:
            raise CombinationError({"tangential_force": tangential_force,
                                    "shift": shift},
                                   "give a tangential force or a shift, not both")
        mu = tg.FRICTION.check(friction, name="friction")
        if method not in ("mdr", "bem"):
            raise UnknownNameError("method", method, ("mdr", "bem"))
        if method == "bem":
            if self.sliced or self.model not in tg.STRAIGHT_CYLINDER_MODELS:
                raise CombinationError({"method": "bem", "model": self.model,
                                        "profile": self.profile.label},
                                       "the BEM table is for a straight, aligned "
                                       "cylinder; use method='mdr'")
            return self._tangential_bem(mu, force, depth, tangential_force, shift,
                                        direction)
        n = self.normal(force=force, depth=depth)
        law = self._law_for("the tangential law")
        e = np.asarray(n.approach, dtype=float)
        F = np.asarray(n.force, dtype=float)
        r = float(tg.SHEAR_RATIO.check(self.gstar / self.estar, name="gstar/estar"))
        kt = out(r * np.asarray(n.stiffness))
        ustar = out(mu * e / r)
        reasons = {}
        Q = u = frac = None
        state = "stick"
        if tangential_force is not None:
            Q = np.asarray(tangential_force, dtype=float)
            frac = np.abs(Q) / (mu * F)
            slide = frac > 1 + 1e-12
            u = np.full(np.broadcast(Q, F).shape, np.nan)
            ok = ~np.broadcast_to(slide, u.shape)
            if np.any(ok):
                eb, Qb = np.broadcast_arrays(e, Q)
                u[ok] = tg.tangential_shift(law, eb[ok], Qb[ok], mu, self.gstar)
            state = np.where(slide, "gross slip", np.where(
                frac >= 1 - 1e-12, "gross slip", np.where(Q == 0, "stick",
                                                          "partial slip")))
            if np.any(slide):
                reasons["shift"] = ({"tangential_force": float(np.max(np.abs(Q))),
                                     "friction": float(mu)},
                                    "beyond mu F the contact slides: no static shift")
                u = None if u.size == 1 else out(u)
            else:
                u = out(u)
            Q, frac = out(Q), out(frac)
        elif shift is not None:
            u = np.asarray(shift, dtype=float)
            Q = out(tg.tangential_force(law, e, u, mu, self.gstar))
            frac = out(np.abs(np.asarray(Q)) / (mu * F))
            state = np.where(np.asarray(frac) >= 1 - 1e-12, "gross slip",
                             np.where(u == 0, "stick", "partial slip"))
            u = out(u)
        else:
            why = ({"tangential_force": None, "shift": None},
                   "no tangential load given")
            reasons.update(tangential_force=why, shift=why, slip_fraction=why)
        if isinstance(state, np.ndarray) and state.ndim == 0:
            state = str(state)
        return TangentialResult(
            normal=n, friction=float(mu), shear_ratio=float(r), stiffness=kt,
            tangential_force=Q, shift=u, slip_fraction=frac, state=state,
            gross_slip_force=out(mu * F), gross_slip_shift=ustar, reasons=reasons,
            method="mdr", stiffness_ratio=float(r))

    def _tangential_bem(self, mu, force, depth, Q, u, direction):
        """Contact.tangential with the BEM table's ratio and slip correction, one
        TangentialContact per normal load."""
        from . import tangential as tg

        n = self.normal(force=force, depth=depth)
        law = self._law_for("the tangential law")
        e = np.atleast_1d(np.asarray(n.approach, dtype=float))
        F = np.atleast_1d(np.asarray(n.force, dtype=float))
        shape = np.shape(n.force)
        Qb = None if Q is None else np.broadcast_to(np.asarray(Q, float), e.shape)
        ub = None if u is None else np.broadcast_to(np.asarray(u, float), e.shape)
        cols = {k: np.full(e.shape, np.nan) for k in ("kt", "ratio", "Q", "u", "ustar")}
        states = []
        reasons = {}
        for k in range(e.size):
            tc = tg.TangentialContact(law, mu, self.gstar, depth=float(e[k]),
                                      method="bem", direction=direction)
            cols["kt"][k], cols["ratio"][k] = tc.stiffness, tc.ratio
            cols["ustar"][k] = tc.gross_slip_shift
            if Qb is not None:
                cols["Q"][k] = Qb[k]
                if abs(Qb[k]) <= mu * F[k] * (1 + 1e-12):
                    cols["u"][k] = tc.shift(float(Qb[k]))
                else:
                    reasons["shift"] = ({"tangential_force": float(Qb[k]),
                                         "friction": float(mu)},
                                        "beyond mu F the contact slides: no static shift")
            elif ub is not None:
                cols["u"][k] = ub[k]
                cols["Q"][k] = tc.force(float(ub[k]))
            frac = abs(cols["Q"][k]) / (mu * F[k]) if Qb is not None or ub is not None \
                else 0.0
            states.append("gross slip" if frac >= 1 - 1e-12 else
                          "stick" if frac == 0 else "partial slip")

        def shaped(v):
            return out(v.reshape(shape))

        loaded = Qb is not None or ub is not None
        if not loaded:
            why = ({"tangential_force": None, "shift": None}, "no tangential load given")
            reasons.update(tangential_force=why, shift=why, slip_fraction=why)
        state = states[0] if not shape else np.array(states).reshape(shape)
        shift_out = None if "shift" in reasons else (shaped(cols["u"]) if loaded
                                                     else None)
        return TangentialResult(
            normal=n, friction=float(mu),
            shear_ratio=float(tg.SHEAR_RATIO.check(self.gstar / self.estar,
                                                   name="gstar/estar")),
            stiffness=shaped(cols["kt"]),
            tangential_force=shaped(cols["Q"]) if loaded else None, shift=shift_out,
            slip_fraction=shaped(np.abs(cols["Q"]) / (mu * F)) if loaded else None,
            state=state, gross_slip_force=shaped(mu * F),
            gross_slip_shift=shaped(cols["ustar"]), reasons=reasons, method="bem",
            stiffness_ratio=shaped(cols["ratio"]))

    # ---- time ------------------------------------------------------------------------
    def _visco(self, what, whole=False):
        """The laws of the contacts whose Lee-Radok history is asked: one, or the two of
        a whole roller (creep only: a held force passes through both)."""
        if self.relaxation is None:
            raise CombinationError({"material1": "Elastic", "material2": "Elastic"},
                                   f"{what} needs a viscoelastic body")
        if not self.raceways:
            return [self._law_for(what)]
        if not whole:
            raise CombinationError({"counterbody": "Raceways", self.viscoelastic:
                                    "Viscoelastic"},
                                   f"{what} of a whole roller between raceways (a held "
                                   "ring approach shared by two relaxing contacts) is "
                                   "not modelled; ask creep under a held force")
        from .models import get_model

        radii = self.counterbody.effective_radii(self.roller.radius)
        if not self.sliced:
            return [get_model(self.model, R, self.roller.length, self.estar,
                              **self.options) for R in radii]
        psi = self.counterbody.misalignment
        if self.tilt == FREE and psi != 0.0:
            raise CombinationError({"tilt": FREE, "misalignment": psi},
                                   f"{what} needs each contact's geometry fixed while it "
                                   "is loaded; the free tilt between misaligned rings "
                                   "changes with the load: give the tilt as a number",
                                   unit={"misalignment": "rad"})
        th = self._fixed_tilt(what)
        from .roller import ProfiledRoller
        from .roller.slices import DEFAULT_N_SLICES

        if self.model != "profiled-roller":
            raise CombinationError({"model": self.model}, "the creep laws use the "
                                   "coupled-slice model; use model='profiled-roller'")
        return [_ApproachLaw(ProfiledRoller(R, self.roller.length, self.estar,
                                            self.profile,
                                            n_slices=self.n_slices or DEFAULT_N_SLICES), t,
                             self.model) for R, t in zip(radii, (th, psi - th))]

    def creep(self, time, *, force):
        r"""Depth under a held force or a force history (Lee & Radok's creep).

        .. math:: F_1\bigl(e(t)\bigr) = \int_{0^-}^t J^*(t - t')\,\dot F(t')\,dt'

        Parameters
        ----------
        time : array_like
            Sample times t_0 <= t_1 <= ... [s].
        force : float or array_like
            Force applied at t_0 and held, or one per sample [N].

        Returns
        -------
        CreepResult

        Notes
        -----
        Valid while the depth grows (refused otherwise, see
        :func:`linecontact.viscoelastic.creep_depth`), a fixed tilt (a free one only
        where it is zero). Between raceways the two contacts creep in series under the
        same force: their depths add (the ring approach). A depth d(t) beyond the law's
        range is refused naming the first time at which it leaves the range; where only
        the long-term depth is beyond it, the history is returned with
        ``long_term_depth`` None and its reason in ``reasons["long_term_depth"]``.

        Examples
        --------
        >>> from linecontact.viscoelastic import StandardLinearSolid
        >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.2), material1=Elastic(210e9, 0.3),
        ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.4),
        ...             n_slices=40)
        >>> r = c.creep([0.0, 1e4], force=100.0)
        >>> f"{r.depth[1] / r.depth[0]:.3f}"
        '2.066'

        References
        ----------
        E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444.
        """
        from .viscoelastic import creep_depth

        laws = self._visco("creep", whole=True)
        t = np.asarray(time, dtype=float)
        F = np.broadcast_to(np.asarray(force, dtype=float), t.shape).astype(float)
        jinf = self.relaxation.creep_terms[0]
        depth, long_term, reasons = np.zeros(t.shape), 0.0, {}
        for law in laws:                                # contacts in series: depths add
            d0 = getattr(law, "d0", 0.0)
            depth += creep_depth(law, self.relaxation, t, F) + d0
            if long_term is None:
                continue
            try:
                long_term += (float(law.depth(F[-1] * jinf * self.estar)) if F[-1] > 0
                              else 0.0) + d0
            except OutOfRangeError as exc:  # d(t) is within the range, d(inf) is not
                long_term = None
                shown = (f"{exc.value:.6g}" if isinstance(exc.value, float)
                         else str(exc.value))
                reasons["long_term_depth"] = (
                    {"force": float(F[-1])},
                    "beyond the model's range: its elastic-equivalent force F E*_0/E*_inf "
                    f"= {shown} {exc.unit} is outside {exc.valid}".replace("  ", " "))
        return CreepResult(time=t, force=F, depth=out(depth), long_term_depth=long_term,
                           model=self.model, reasons=reasons)

    def relaxation_history(self, time, *, depth):
        r"""Force under a held depth or a depth history (Lee & Radok's relaxation).

        .. math:: F(t) = \int_{0^-}^t E^*(t - t')\,\frac{d}{dt'}F_1\bigl(e(t')\bigr)\,dt'

        Parameters
        ----------
        time : array_like
            Sample times [s].
        depth : float or array_like
            Depth at the roller's centre, applied at t_0 and held, or one per sample
            (non-decreasing) [m].

        Returns
        -------
        CreepResult

        Notes
        -----
        Valid for a non-decreasing depth (a growing contact).

        Examples
        --------
        >>> from linecontact.viscoelastic import StandardLinearSolid
        >>> c = Contact(Roller(5e-3, 10e-3), material1=Elastic(math.inf),
        ...             material2=Viscoelastic(StandardLinearSolid(3e9, 1e9, 10.0), 0.0))
        >>> r = c.relaxation_history([0.0, 1e4], depth=2e-6)
        >>> f"{r.force[1] / r.force[0]:.4f}"
        '0.3333'

        References
        ----------
        E. H. Lee, J. R. M. Radok, J. Appl. Mech. 27 (1960) 438-444.
        """
        from .viscoelastic import force_history

        law = self._visco("relaxation")[0]
        t = np.asarray(time, dtype=float)
        d = np.broadcast_to(np.asarray(depth, dtype=float), t.shape).astype(float)
        d0 = getattr(law, "d0", 0.0)
        F = force_history(law, self.relaxation, t, d - d0)
        why = ({"depth": "given"}, "the depth is prescribed: no long-term creep depth")
        return CreepResult(time=t, force=out(F), depth=d, long_term_depth=None,
                           model=self.model, reasons={"long_term_depth": why})
