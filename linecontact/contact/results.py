"""The results of a :class:`~linecontact.contact.Contact`: the normal state
(:class:`ContactResult`), the tangential state (:class:`TangentialResult`) and the
creep history (:class:`CreepResult`); an output not defined for the combination is None
and :meth:`~ContactResult.get` says why.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import CombinationError, UnknownNameError

__all__ = ["ContactResult", "TangentialResult", "CreepResult"]


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
        >>> from linecontact.contact import Contact, Roller
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
        from ..tabular import to_dict
        return to_dict(self)

    def to_frame(self):
        """A pandas DataFrame, one row per load or time (:func:`linecontact.tabular.to_frame`)."""
        from ..tabular import to_frame
        return to_frame(self)

    def _repr_html_(self):
        """The table Jupyter shows (:func:`linecontact.tabular.html_table`)."""
        from ..tabular import html_table
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
    >>> from linecontact.contact import Contact, Roller
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
    """The tangential state of a composed contact (Cattaneo-Mindlin: MDR, BEM or Mindlin).

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
        Full-stick tangential stiffness k_t = r k_n, r = `stiffness_ratio` [N/m].
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
        ``"mdr"``, ``"bem"``, ``"mindlin"`` or ``"ellipse"`` (the equivalent ellipse
        of a profiled roller's footprint).
    stiffness_ratio : float or ndarray
        k_t/k_n used: G*/E*, the BEM table's ratio, Mindlin's elliptical ratio or the
        equivalent ellipse's in the direction asked [-].
    direction : str or None
        ``"across"`` or ``"along"`` the roller's axis for a direction-dependent law
        (``method="bem"``, ``"mindlin"`` or ``"ellipse"``); None for the MDR's, the
        same in every direction.
    notes : tuple of str
        Validity notes (e.g. loads at which a crowned roller's ellipse reaches its ends).

    Notes
    -----
    Valid under the Cattaneo-Mindlin assumptions (uncoupled normal and tangential
    problems; see :mod:`linecontact.tangential`), exact for any shape at nu = 0.

    Examples
    --------
    >>> from linecontact.contact import Contact, Elastic, Roller
    >>> c = Contact(Roller(5e-3, 10e-3, crown_radius=0.5), material1=Elastic(210e9, 0.3),
    ...             material2=Elastic(210e9, 0.3), n_slices=40)
    >>> t = c.tangential(0.15, force=1e3, tangential_force=-50.0)
    >>> t.state, f"{t.shift * 1e9:.1f} nm"
    ('partial slip', '-290.2 nm')
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
    direction: object = None
    notes: tuple = ()


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
    >>> import math
    >>> from linecontact.contact import Contact, Elastic, Roller, Viscoelastic
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
