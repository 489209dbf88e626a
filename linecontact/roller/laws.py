"""The two roller models as contact laws (:class:`linecontact.models.ContactModel`):
force(depth), depth(force), stiffness(depth) at a fixed tilt, registered under the keys
``profiled-roller`` and ``iso16281-slicing``.
"""
from __future__ import annotations

import numpy as np

from ..models import ContactModel, register
from ..profiles import as_profile
from ..validity import check_positive, out
from .iso import iso_slicing
from .model import ProfiledRoller
from .slices import TILT_RANGE

__all__ = ["ProfiledRollerModel", "ISOSlicingModel"]


def _each(values, fn):
    """fn(one value) over an array of values, same shape (one slice solve per value)."""
    v = np.asarray(values, dtype=float)
    res = np.array([fn(float(e)) for e in v.ravel()]).reshape(v.shape)
    return out(res)


class _SolvedRoller(ContactModel):
    """The contact law of a roller model from its solutions (``at_depth``,
    ``at_force`` returning :class:`RollerSolution`): one solve per value, each giving
    force, depth and stiffness together. Subclasses set :attr:`axial_profile` and
    :attr:`n_slices`, and name themselves with ``_name`` and ``_slices``."""

    _name = ""
    _slices = "slices"

    def __init__(self, radius, length, estar, tilt=0.0):
        super().__init__(radius, length, estar)
        self.tilt = TILT_RANGE.check(tilt).item()

    @property
    def first_contact_depth(self):
        """Depth of the roller's centre at first contact at this tilt [m]."""
        from ..profiles import roller_drop

        if isinstance(self, ProfiledRollerModel):
            return self.roller.first_contact_depth(self.tilt)
        L, n = self.length, self.n_slices
        x = -L / 2 + L / n * (np.arange(n) + 0.5)
        return float(np.min(roller_drop(self.axial_profile, L, x) - x * np.tan(self.tilt)))

    @property
    def label(self):
        s = f"{self._name} ({self.axial_profile.label}"
        if self.tilt:
            s += f", tilt {self.tilt * 1e3:.4g} mrad"
        return s + f", {self.n_slices} {self._slices})"

    def force(self, depth):
        return _each(depth, lambda d: self.at_depth(d).force)

    def depth(self, force):
        F = check_positive("force", force, "N")
        return _each(F, lambda f: self.at_force(f).depth)

    def stiffness(self, depth):
        return _each(depth, lambda d: self.at_depth(d).stiffness)

    def stiffness_at_force(self, force):
        F = check_positive("force", force, "N")
        return _each(F, lambda f: self.at_force(f).stiffness)


@register
class ProfiledRollerModel(_SolvedRoller):
    """A profiled, tilted roller as a contact law: coupled slices at a fixed tilt.

    .. math:: F(d) = \\sum_k q_k(d, \\theta)\\,w, \\qquad k(d) = \\partial F/\\partial d

    Parameters
    ----------
    radius : float
        Radius across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    profile : Profile or str or None, optional
        Profile drop or spec (None: straight) [-].
    tilt : float, optional
        Tilt theta [rad], held fixed (default 0).
    n_slices : int, optional
        Number of slices [-] (default 100).

    Notes
    -----
    The roller's profile drop is :attr:`axial_profile` (``profile()`` is the
    ContactModel's MDR profile, which this model does not have).
    ``depth`` is the depth d of the roller point x = 0 (as in :class:`RollerSolution`);
    it must exceed the first-contact depth min_x(P - theta x), which is negative for a
    tilted roller. :meth:`at_depth` and :meth:`at_force` return the full
    :class:`RollerSolution` (moment, q(x), peak pressure, edge loading). Validity and
    accuracy as :class:`ProfiledRoller`.

    Examples
    --------
    >>> m = ProfiledRollerModel(10e-3, 20e-3, 115.385e9, profile="circular:Rc=0.5")
    >>> f"{m.depth(1000.0) * 1e6:.2f} um", m.key
    ('7.02 um', 'profiled-roller')

    References
    ----------
    See :mod:`linecontact.roller`.
    """

    key = "profiled-roller"
    no_profile_reason = ("a coupled-slice solution of a profiled roller, not a "
                         "plane MDR contact; its axial drop is axial_profile")

    _name = "Profiled roller"
    _slices = "coupled slices"

    def __init__(self, radius, length, estar, profile=None, tilt=0.0, n_slices=100):
        super().__init__(radius, length, estar, tilt)
        self.roller = ProfiledRoller(self.radius, self.length, self.estar, profile,
                                     n_slices=n_slices)
        self.axial_profile = self.roller.profile
        self.n_slices = self.roller.n_slices

    @property
    def provenance(self):
        return {"model": self.label, "method": "coupled slices with Hertz strips "
                "(linecontact.roller)", "profile": self.axial_profile.provenance,
                "tilt_rad": self.tilt, "n_slices": self.n_slices}

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m] and this model's tilt."""
        return self.roller.at_depth(depth, self.tilt)

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N] and this model's tilt."""
        return self.roller.at_force(force, self.tilt)


@register
class ISOSlicingModel(_SolvedRoller):
    """ISO 16281 slicing of a profiled, tilted roller as a contact law (steel only).

    .. math:: F(d) = \\sum_k \\frac{c}{n}\\,(d + x_k\\tan\\theta - P(x_k))_+^{10/9}

    Parameters
    ----------
    radius, length : float
        R, L [m].
    estar : float
        E* [Pa] (steel only).
    profile : Profile or str or None, optional
        Profile drop or spec [-].
    tilt : float, optional
        Tilt theta [rad] (default 0).
    n_slices : int, optional
        n >= 30 [-] (default 30).

    Notes
    -----
    See :func:`iso_slicing`. Valid for steel on steel only.

    Examples
    --------
    >>> m = ISOSlicingModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    ISO 16281:2025.
    """

    key = "iso16281-slicing"
    no_profile_reason = "uncoupled slices, each with the empirical ISO 16281 law"

    _name = "ISO 16281 slicing"

    def __init__(self, radius, length, estar, profile=None, tilt=0.0, n_slices=30):
        super().__init__(radius, length, estar, tilt)
        self.n_slices = n_slices
        self.axial_profile = as_profile(profile, self.radius, self.length, self.estar)

    @property
    def provenance(self):
        return {"model": self.label, "method": "ISO 16281:2025 slicing, uncoupled "
                "slices", "profile": self.axial_profile.provenance, "tilt_rad": self.tilt}

    def check_applicable(self):
        from ..classical import STEEL_ESTAR_RANGE, STEEL_HINT
        STEEL_ESTAR_RANGE.check(self.estar, hint=STEEL_HINT)

    def _solve(self, **kw):
        return iso_slicing(self.radius, self.length, self.estar, self.axial_profile,
                           tilt=self.tilt, n_slices=self.n_slices, **kw)

    def at_depth(self, depth):
        """:class:`RollerSolution` at depth d [m]."""
        return self._solve(depth=depth)

    def at_force(self, force):
        """:class:`RollerSolution` at force F [N]."""
        return self._solve(force=force)
