"""The one door from a slice model's name to the solver of one roller contact.

Every caller that solves a roller contact by slices (:class:`linecontact.contact.Contact`,
:func:`linecontact.raceway.roller_between_raceways`, the bearing's sliced and tilted
paths, the registered laws of :mod:`linecontact.roller.laws`) asks :func:`slice_solver`
with the model's name, the roller (radius of the contact, length, axial profile) and the
counter-body's modulus, and gets an object with the same three methods whichever the
method:

- ``at_depth(depth, tilt)`` and ``at_force(force, tilt)`` -> :class:`RollerSolution`;
- ``first_contact_depth(tilt)`` -> the depth d_0 [m] below which nothing touches.

The slice counts when none is given are owned here, one per method
(:data:`DEFAULT_SLICES`): the coupled slices' converged count
(:data:`linecontact.roller.slices.DEFAULT_N_SLICES`, chosen by a convergence study over
tables/roller_accuracy.csv, docs/profiled_rollers.md "Slice convergence") and ISO 16281's
count (its minimum, :data:`linecontact.roller.iso.ISO_MIN_SLICES`: the standard's method
as it states it).
"""
from __future__ import annotations

import math

import numpy as np

from ..models import DEFAULT_SLICE_MODEL, SLICE_MODELS
from ..errors import UnknownNameError
from .iso import ISO_MIN_SLICES, iso_slicing
from .model import ProfiledRoller
from .slices import DEFAULT_N_SLICES

__all__ = ["SLICE_MODELS", "DEFAULT_SLICE_MODEL", "DEFAULT_SLICES", "default_n_slices",
           "slice_solver", "ISOSlices"]

#: The slice count of each slice model when none is given [-]: coupled slices converged
#: (docs/profiled_rollers.md, "Slice convergence"), ISO 16281 at the standard's count.
DEFAULT_SLICES = {"profiled-roller": DEFAULT_N_SLICES,
                  "iso16281-slicing": ISO_MIN_SLICES}


def default_n_slices(model):
    """The slice count of a slice model when none is given [-].

    Parameters
    ----------
    model : str
        A key of :data:`SLICE_MODELS`.

    Returns
    -------
    int
        50 for ``"profiled-roller"`` (coupled slices), 30 for ``"iso16281-slicing"``.

    Raises
    ------
    UnknownNameError
        A model that is not a slice model.

    Examples
    --------
    >>> default_n_slices("profiled-roller"), default_n_slices("iso16281-slicing")
    (50, 30)
    """
    if model not in DEFAULT_SLICES:
        raise UnknownNameError("model", model, list(SLICE_MODELS))
    return DEFAULT_SLICES[model]


class ISOSlices:
    """One contact under ISO 16281 slicing with the interface of :class:`ProfiledRoller`
    (:func:`iso_slicing` at each call: the slices are uncoupled, nothing to keep).

    Parameters
    ----------
    radius, length : float
        Radius R of the contact and roller length L [m].
    estar : float
        E* [Pa] (steel only, checked at each solve).
    profile : Profile or str or None
        The roller's axial profile (None: straight).
    n_slices : int
        n >= 30 [-].

    Examples
    --------
    >>> s = ISOSlices(5e-3, 10e-3, 115.38e9, None, 30)
    >>> f"{s.at_force(1e3, 0.0).depth * 1e6:.3f} um", s.first_contact_depth(0.0)
    ('3.153 um', 0.0)
    """

    def __init__(self, radius, length, estar, profile, n_slices):
        self.radius, self.length, self.estar = radius, length, estar
        self.profile, self.n_slices = profile, n_slices

    def at_depth(self, depth, tilt=0.0):
        """:class:`RollerSolution` at depth d [m] and tilt theta [rad]."""
        return iso_slicing(self.radius, self.length, self.estar, self.profile,
                           depth=depth, tilt=tilt, n_slices=self.n_slices)

    def at_force(self, force, tilt=0.0):
        """:class:`RollerSolution` at force F [N] and tilt theta [rad]."""
        return iso_slicing(self.radius, self.length, self.estar, self.profile,
                           force=force, tilt=tilt, n_slices=self.n_slices)

    def first_contact_depth(self, tilt=0.0):
        """d_0 = min_k [P(x_k) - x_k tan theta] on the slice centres x_k [m]."""
        from ..profiles import as_profile, roller_drop

        L, n = self.length, self.n_slices
        x = -L / 2 + L / n * (np.arange(n) + 0.5)
        P = roller_drop(as_profile(self.profile, self.radius, L, self.estar), L, x)
        return float(np.min(P - x * math.tan(tilt)))


def slice_solver(model, radius, length, estar, profile=None, *, n_slices=None):
    """The solver of one roller contact by slices, from the slice model's name.

    Parameters
    ----------
    model : str
        ``"profiled-roller"`` (coupled slices, :class:`ProfiledRoller`) or
        ``"iso16281-slicing"`` (ISO 16281's uncoupled slices, :class:`ISOSlices`).
    radius : float
        Radius R of the contact (the effective radius against a curved body) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* of roller and counter-body [Pa].
    profile : Profile or str or None, optional
        The roller's axial profile, read by the caller with the roller's own radius
        (a spec is read here with `radius`); None: straight.
    n_slices : int or None, optional
        Slices [-]; None: the model's default (:func:`default_n_slices`).

    Returns
    -------
    ProfiledRoller or ISOSlices
        ``at_depth(d, tilt)``, ``at_force(F, tilt)``, ``first_contact_depth(tilt)``.

    Raises
    ------
    UnknownNameError
        A model that is not a slice model.

    Examples
    --------
    >>> r = slice_solver("profiled-roller", 10e-3, 20e-3, 115.385e9, "circular:Rc=0.5")
    >>> r.n_slices, f"{r.at_force(1e3, 0.0).depth * 1e6:.3f} um"
    (50, '7.024 um')
    """
    n = default_n_slices(model) if n_slices is None else n_slices
    if model == "profiled-roller":
        return ProfiledRoller(radius, length, estar, profile, n_slices=n)
    return ISOSlices(radius, length, estar, profile, n)
