"""One interface for every line-contact model: force, depth, stiffness, MDR profile.

Each model is a :class:`ContactModel` subclass registered under a key in
:data:`MODELS`; :func:`get_model` builds one by key, :func:`standard_models` builds the
row set the CLI prints. All methods are vectorised over depth or force and use SI
units (m, N, Pa, N/m).

A model is built for one cylinder (radius R, length L, effective modulus E*), which is
checked at construction (positive, finite). Whether the model *applies* to that
cylinder (L/R inside its coefficient table, E* of steel for Palmgren) is checked on
every evaluation, and :meth:`ContactModel.check_applicable` checks it up front; both
raise :class:`~linecontact.errors.OutOfRangeError`. So the full row set can be built
for any cylinder and each row reports its own range.

Keys
----
``"li-popov"``
    Li & Popov (2017) MDR model; option ``coefficients`` = ``"published"`` (Table 1
    spline, default), ``"eq11"`` or a table name (``tables/lipopov_NAME.csv``).
``"puttock-thwaite"``
    Eq. 2.
``"johnson"``
    Eq. 4; option ``c`` (1 default, 0.72, 0.572, or any number).
``"kunz"``
    F = 0.175 E* L d; option ``c``.
``"palmgren"``, ``"iso16281"``
    Steel-only empirical formulas (per contact).
``"universal"``
    The BEM-tabulated universal curve (:mod:`linecontact.universal` holds the curve,
    ``tables/universal_curve.csv`` its data); the default model, :data:`DEFAULT_MODEL`.

Examples
--------
>>> m = get_model("li-popov", 5e-3, 10e-3, 115.38e9)
>>> m.label
'Li-Popov (Table 1 spline)'
>>> f"{m.depth(1e3) * 1e6:.2f} um", f"{m.stiffness_at_force(1e3):.3g} N/m"
('3.05 um', '3.57e+08 N/m')
"""
from __future__ import annotations

import abc
import math
import sys
from importlib import import_module

import numpy as np

from . import classical as _c
from ._numerics import blockwise, out
from .accuracy import MODEL_ACCURACY, model_accuracy
from .lipopov import (coefficient_set, lipopov_contact_radius, lipopov_depth,
                      lipopov_force, lipopov_profile, lipopov_stiffness,
                      lipopov_stiffness_at_force)
from .tables import available_tables
from .universal import DEPTH_OVER_RADIUS, TABLE as _UNIVERSAL_TABLE, universal_curve
from .errors import OutOfRangeError, UnknownKeywordError, UnknownNameError
from .checks import check_flag, check_interval, check_positive, check_scaled, document

__all__ = [
    "ContactModel",
    "scales_are_normal",
    "MODELS",
    "DEFAULT_MODEL",
    "SLICE_MODELS",
    "DEFAULT_SLICE_MODEL",
    "register",
    "get_model",
    "available_models",
    "standard_models",
    "LiPopovModel",
    "PuttockThwaiteModel",
    "JohnsonModel",
    "KunzModel",
    "PalmgrenModel",
    "ISO16281Model",
    "UniversalModel",
]

#: Registry: key -> model class. Filled by :func:`register`.
MODELS: dict = {}

#: Models defined in other modules of this package (key -> module), imported the first
#: time one of them is asked for by key, so that a one-case calculation does not pay
#: for their import. A test checks that each module registers its keys.
DEFINED_IN = {
    "profiled-roller": "linecontact.roller.laws",
    "iso16281-slicing": "linecontact.roller.laws",
}

#: Model used by the top-level one-liners and the CLI unless told otherwise.
DEFAULT_MODEL = "universal"
#: Models that solve a profiled, tilted roller by slices; each one's solver of a
#: contact comes from :func:`linecontact.roller.solvers.slice_solver`.
SLICE_MODELS = ("profiled-roller", "iso16281-slicing")
#: Model used for a profiled or tilted roller unless told otherwise (coupled slices).
DEFAULT_SLICE_MODEL = "profiled-roller"


def register(cls):
    """Class decorator: add a :class:`ContactModel` subclass to :data:`MODELS`.

    Parameters
    ----------
    cls : type
        A :class:`ContactModel` subclass with a non-empty ``key``.

    Returns
    -------
    type
        `cls`, unchanged (so it works as a decorator).

    Examples
    --------
    >>> "li-popov" in MODELS and MODELS["li-popov"] is LiPopovModel
    True
    >>> register(int)
    Traceback (most recent call last):
    ...
    TypeError: <class 'int'> is not a ContactModel subclass
    """
    if not (isinstance(cls, type) and issubclass(cls, ContactModel)):
        raise TypeError(f"{cls!r} is not a ContactModel subclass")
    if not cls.key:
        raise TypeError(f"{cls.__name__} has no registry key")
    MODELS[cls.key] = cls
    return cls


def _scalar(name, value, unit):
    v = check_positive(name, value, unit)
    if v.ndim:
        raise OutOfRangeError(name, f"an array of shape {v.shape}",
                              f"a single number in (0, inf) {unit}",
                              hint="build one model per cylinder; evaluations are "
                                   "vectorised over depth and force")
    return float(v)


#: What :func:`scales_are_normal` requires, for error messages.
SCALES_VALID = (f"L^2, L^3, L^2/R and E* L^3/R in [{sys.float_info.min:.3g}, "
                f"{sys.float_info.max:.3g}] (the models' length and force scales)")
SCALES_HINT = "a scale of the models overflows or underflows"


def scales_are_normal(radius, length, estar):
    """Whether the self-similar scales of a cylinder are normal doubles.

    Every model works in the scales of the self-similar variables (docs/theory.md,
    section 'Self-similarity'): depth L^2/R (d~ = d R/L^2) and force E* L^3/R. Finite
    R, L and E* can still give a scale (or the power L^2, L^3 on the way) that overflows
    to inf or underflows to zero; such a cylinder is refused once, here, for every model
    (and by the command line before any model is built), rather than as an overflow
    error or a silent 0 in one of them.

    Parameters
    ----------
    radius : float or ndarray
        Radius R (the effective radius across the axis), R > 0 [m].
    length : float or ndarray
        Length L, L > 0 [m].
    estar : float or ndarray
        Effective modulus E*, E* > 0 [Pa].

    Returns
    -------
    bool or ndarray of bool
        True where L^2, L^3, L^2/R and E* L^3/R all lie in the normal doubles [-].

    Notes
    -----
    Valid range: the normal doubles, [2.23e-308, 1.8e+308].

    Examples
    --------
    >>> bool(scales_are_normal(5e-3, 10e-3, 115.38e9)), bool(scales_are_normal(5e-3, 1e300, 1e11))
    (True, False)

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017] (the
       dimensionless variables of Eq. 9).
    """
    L = np.asarray(length, dtype=float)
    R = np.asarray(radius, dtype=float)
    E = np.asarray(estar, dtype=float)
    tiny, huge = sys.float_info.min, sys.float_info.max
    with np.errstate(all="ignore"):
        scales = (L**2, L**3, L**2 / R, E * L**3 / R)
        ok = np.logical_and.reduce([(x >= tiny) & (x <= huge) for x in scales])
    return ok if ok.ndim else bool(ok)


class ContactModel(abc.ABC):
    """Base class: a normal-contact law for one rigid cylinder on an elastic half-space.

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Eq. 3 of Li & Popov 2017), 0 < E* < inf [Pa].
    **options
        Model-specific (see the subclass).

    Subclasses set :attr:`key` and implement :meth:`force`, :meth:`depth`,
    :meth:`stiffness`, :attr:`label` and :attr:`provenance`; the rest have
    defaults in terms of those.

    Notes
    -----
    R, L and E* are checked at construction: single numbers, 0 < R, L, E* < inf (an
    array raises: one model per cylinder). The range of depth and force is the
    subclass's, checked on every evaluation.

    Examples
    --------
    Every model answers the same questions; a subclass implements the law:

    >>> m = get_model("puttock-thwaite", 5e-3, 10e-3, 115.38e9)
    >>> isinstance(m, ContactModel), f"{m.length_over_radius:g}"
    (True, '2')
    """

    #: Registry key.
    key: str = ""

    def __init_subclass__(cls, **kwargs):
        """Every model's constructor refuses an unknown keyword (``cc=`` for Johnson's
        ``c``) with one line listing the valid ones (:class:`UnknownNameError`), not
        Python's bare TypeError."""
        super().__init_subclass__(**kwargs)
        init = cls.__dict__.get("__init__")
        if init is None or getattr(init, "_keywords_checked", False):
            return
        import functools
        import inspect

        params = inspect.signature(init).parameters
        if any(p.kind is p.VAR_KEYWORD for p in params.values()):
            return
        names = [n for n in params if n != "self"]

        @functools.wraps(init)
        def checked(*args, **options):     # self in args: a keyword 'self' is unknown too
            for name in options:
                if name not in names:
                    raise UnknownKeywordError(cls.__name__, name, names)
            return init(*args, **options)

        checked._keywords_checked = True
        cls.__init__ = checked

    def __init__(self, /, radius, length, estar, **options):   # a keyword 'self' is unknown
        if options:
            raise UnknownKeywordError(type(self).__name__, sorted(options)[0],
                                      ["radius", "length", "estar"])
        self.radius = _scalar("radius", radius, "m")
        self.length = _scalar("length", length, "m")
        self.estar = _scalar("estar", estar, "Pa")
        if not scales_are_normal(self.radius, self.length, self.estar):
            raise OutOfRangeError("length", self.length, SCALES_VALID, unit="m",
                                  hint=SCALES_HINT)

    # ---- description ---------------------------------------------------------------
    @property
    @abc.abstractmethod
    def label(self) -> str:
        """Human-readable name including options, e.g. ``'Johnson (c = 0.72)'``."""

    @property
    @abc.abstractmethod
    def provenance(self) -> dict:
        """Where the model comes from: table metadata or the equation reference."""

    @property
    def length_over_radius(self):
        """L/R [-]."""
        return self.length / self.radius

    #: Column tag of this model in tables/model_accuracy.csv (``F_err_<tag>``), or None
    #: where the accuracy study does not cover it (an option value it did not run).
    accuracy_tag = None

    @property
    def measured_error(self):
        """The measured error of this model against the BEM at this cylinder's L/R.

        One line of text: the range of the signed relative error of F(d) and k(d)
        over the depths of the accuracy study (d/R 1e-6 ... 0.15), at the study's L/R
        rows that bracket this cylinder's, read from tables/model_accuracy.csv
        (``python -m tools.build_tables accuracy``); or why there is none. None for a
        model the study does not cover (``accuracy_tag`` None).
        """
        if self.accuracy_tag is None:
            return None
        return _measured_error(self.accuracy_tag, self.length_over_radius)

    def _with_measured_error(self, prov):
        text = self.measured_error
        if text is not None:
            prov["measured_error"] = text
        return prov

    def check_applicable(self):
        """Raise :class:`OutOfRangeError` if the model does not apply to this cylinder."""

    def check_starts_at_zero(self):
        """Raise :class:`~linecontact.errors.CombinationError` unless F(d) starts at
        d = 0 (:attr:`first_contact_depth`), as the tangential and viscoelastic laws
        built on F(d) take it."""
        d0 = self.first_contact_depth
        if d0 != 0.0:
            from .errors import CombinationError

            raise CombinationError({"model": self.label, "first_contact_depth": d0},
                                   "the law's force starts at a nonzero depth (a tilted "
                                   "roller); use linecontact.contact.Contact, which takes "
                                   "the law in the approach from first contact",
                                   unit={"first_contact_depth": "m"})

    def __repr__(self):
        return (f"<{type(self).__name__} {self.label}: R = {self.radius:g} m, "
                f"L = {self.length:g} m, E* = {self.estar:g} Pa>")

    # ---- the contact law -----------------------------------------------------------
    @abc.abstractmethod
    def force(self, depth):
        """Normal force F(d) [N] at depth d [m]."""

    @abc.abstractmethod
    def depth(self, force):
        """Depth d(F) [m] under force F [N]."""

    @abc.abstractmethod
    def stiffness(self, depth):
        """Contact stiffness k = dF/dd [N/m] at depth d [m]."""

    def stiffness_at_force(self, force):
        """Contact stiffness k = dF/dd [N/m] at force F [N]."""
        return self.stiffness(self.depth(force))

    def contact_radius(self, depth):
        """MDR contact half-length a = k / (2 E*) [m] at depth d [m]."""
        return out(np.asarray(self.stiffness(depth)) / (2 * self.estar))

    #: Depth at which the law's force starts [m]: 0 for a cylinder, negative for a
    #: tilted roller whose depth is that of its centre. The laws built on F(d) with
    #: F(0) = 0 (tangential, viscoelastic) refuse a law that starts elsewhere.
    first_contact_depth = 0.0

    #: Why a model without an MDR profile has none (the end of the NotImplementedError
    #: message of :meth:`profile`); each such model states its own reason.
    no_profile_reason = "its force law is not derived from an equivalent MDR profile"

    def profile(self, x):
        """Equivalent MDR profile g(x) [m] at x >= 0 [m]."""
        raise NotImplementedError(f"{self.label} has no MDR profile "
                                  f"({self.no_profile_reason})")

    @classmethod
    def evaluate_many(cls, radius, length, estar, *, force=None, depth=None):
        """The contact state of many cylinders at once: one radius, length, E* and
        force (or depth) per element, without a model object per cylinder.

        A model whose law is a function of self-similar variables (docs/theory.md,
        section 'Self-similarity') overrides this; the default returns None (not
        available: build one model per cylinder).

        Parameters
        ----------
        radius, length : ndarray
            R, L per element, > 0 [m].
        estar : ndarray
            E* per element, > 0 [Pa].
        force, depth : ndarray, optional
            Exactly one: F [N] or d [m] per element.

        Returns
        -------
        tuple or None
            (dict as :meth:`evaluate` returns, ok): ok (bool array) marks the
            elements inside the model's range, whose values equal those of
            ``cls(R_i, L_i, E_i).evaluate(...)`` element by element; the others hold
            NaN (build their model to get its message).

        Notes
        -----
        Valid for the default model options only.

        Examples
        --------
        >>> JohnsonModel.evaluate_many([5e-3], [1e-2], [1e11], force=[1e3]) is None
        True

        References
        ----------
        .. [1] Li & Popov (2017) [li-popov-2017], Eq. 8 (the self-similar variables).
        """
        return None

    def evaluate(self, *, force=None, depth=None):
        """The contact state at given forces OR depths, in one vectorised call.

        With `force` F: d = depth(F), and k = stiffness_at_force(F) where the model
        has its own (a closed form in F), else stiffness(d) (no second inversion of
        F). With `depth` d: F = force(d), and k = stiffness(d), or
        stiffness_at_force(F) for a model whose class sets
        ``stiffness_explicit_in_force = True`` (a law written as d(F), Johnson's Eq. 4:
        no depth -> force -> stiffness detour). Both: the MDR contact half-length
        a = k / (2 E*) (docs/theory.md, section 'MDR': the MDR spring bed of modulus
        E* over |x| <= a has stiffness 2 E* a).

        Parameters
        ----------
        force : array_like, optional
            Normal force F > 0 [N] (or a pint Quantity of force).
        depth : array_like, optional
            Indentation depth d > 0 [m] (or a pint Quantity of length).

        Returns
        -------
        dict
            ``force`` [N], ``depth`` [m], ``stiffness`` [N/m], ``contact_radius`` [m]:
            float arrays of the input's shape (floats for a scalar input).

        Raises
        ------
        TypeError
            Neither or both of `force` and `depth` given.
        OutOfRangeError
            An input outside the model's range (the first offending element named).

        Notes
        -----
        Valid wherever the model's force/depth/stiffness are (see the subclass): it
        adds no approximation.

        Examples
        --------
        >>> m = get_model("johnson", 5e-3, 10e-3, 115.38e9)
        >>> r = m.evaluate(force=[500.0, 1000.0])
        >>> [f"{d * 1e6:.3f}" for d in r["depth"]]
        ['1.501', '2.812']
        >>> bool(r["stiffness"][1] == m.stiffness_at_force(1000.0))
        True

        References
        ----------
        .. [1] Li & Popov (2017) [li-popov-2017].
        """
        if (force is None) == (depth is None):
            raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                                  "exactly one of force, depth", where="evaluate()")
        own = type(self).stiffness_at_force is not ContactModel.stiffness_at_force
        if force is not None:
            F = check_positive("force", force, "N")
            d = np.asarray(self.depth(F), dtype=float)
            k = self.stiffness_at_force(F) if own else self.stiffness(d)
        else:
            d = check_positive("depth", depth, "m")
            F = np.asarray(self.force(d), dtype=float)
            k = (self.stiffness_at_force(F)
                 if own and getattr(self, "stiffness_explicit_in_force", False)
                 else self.stiffness(d))
        k = np.asarray(k, dtype=float)
        a = k / (2 * self.estar)
        return {"force": out(F), "depth": out(d),
                "stiffness": out(k), "contact_radius": out(a)}


# --------------------------------------------------------------------------------------
@register
class LiPopovModel(ContactModel):
    """Li & Popov (2017) MDR model, Eq. 7 with coefficients chosen by name.

    Option ``coefficients``: ``"published"`` (Table 1 spline, 0.1 <= L/R <= 6, the
    default), ``"eq11"`` (alpha = pi/2, beta = 0.4573, L/R >= 5) or the name NAME of a
    table ``tables/lipopov_NAME.csv``. Table 1 and Eq. 11 differ where both apply
    (5 <= L/R <= 6); the model never switches between them (see
    :mod:`linecontact.lipopov`). Option ``extrapolate=True`` uses the set outside its
    L/R range on request (Eq. 11 constants as they are, a table's end rows held); the
    label then says "extrapolated".

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    coefficients : str, optional
        ``"published"`` (default), ``"eq11"`` or a table name (see above).
    extrapolate : bool, optional
        Use the set outside its L/R range on request (default False).

    Notes
    -----
    Valid for L/R inside the coefficient set's range (0.1 <= L/R <= 6 for
    ``"published"``, L/R >= 5 for ``"eq11"``), depths 0 < d < beta L^2/R and forces
    0 < F < 2 alpha beta E* L^3/R (the supremum of the profile of Eq. 7). L/R is checked
    on every evaluation, or up front by :meth:`check_applicable`.

    Examples
    --------
    >>> m = LiPopovModel(5e-3, 10e-3, 115.38e9)
    >>> m.label, f"{m.depth(1e3) * 1e6:.3f} um"
    ('Li-Popov (Table 1 spline)', '3.055 um')

    Eq. 11 is given for L/R >= 5; at L/R = 2 it is refused unless asked for:

    >>> LiPopovModel(5e-3, 10e-3, 115.38e9, coefficients="eq11").depth(1e3)
    Traceback (most recent call last):
    ...
    linecontact.errors.OutOfRangeError: L/R = 2 is outside the valid range [5, inf); ...
    >>> m = LiPopovModel(5e-3, 10e-3, 115.38e9, coefficients="eq11", extrapolate=True)
    >>> m.label, f"{m.depth(1e3) * 1e6:.3f} um"
    ('Li-Popov (Eq. 11, extrapolated to L/R = 2)', '3.147 um')

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 7, 9,
       11 and Table 1.
    .. [2] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact
       Mechanics and Friction, Springer (2015).
    .. [3] docs/theory.md, section 'MDR'.
    """

    key = "li-popov"

    def __init__(self, radius, length, estar, coefficients="published", extrapolate=False):
        super().__init__(radius, length, estar)
        self.coefficients = coefficients
        self.extrapolate = check_flag("extrapolate", extrapolate)
        self._set = coefficient_set(coefficients)

    @property
    def extrapolated(self):
        """True if L/R is outside the coefficient set's range (only with extrapolate)."""
        return not bool(self._set.valid.contains(self.length_over_radius))

    @property
    def label(self):
        if self.extrapolate and self.extrapolated:
            return (f"Li-Popov ({self._set.label}, extrapolated to "
                    f"L/R = {self.length_over_radius:.3g})")
        return f"Li-Popov ({self._set.label})"

    @property
    def provenance(self):
        prov = {"model": self.label,
                "equation": "Li & Popov 2017, Eq. 7 (profile), Eq. 9 (dimensionless); "
                            "F, d, k in closed form by the MDR",
                "coefficients": self._set.name}
        prov.update(self._set.provenance)
        if self.extrapolate and self.extrapolated:
            prov["extrapolated"] = (f"L/R = {self.length_over_radius:.6g} is outside "
                                    f"{self._set.valid}; used on request")
        return self._with_measured_error(prov)

    @property
    def accuracy_tag(self):
        return f"lp_{self.coefficients}" if isinstance(self.coefficients, str) else None

    @property
    def measured_error(self):
        text = super().measured_error
        if text is not None and self.extrapolated and not self.extrapolate:
            text = (f"not applicable at L/R = {self.length_over_radius:.3g} (outside "
                    f"{self._set.valid}); extrapolated on request it measures " + text)
        return text

    @property
    def alpha_beta(self):
        """(alpha, beta) of Eq. 9 for this L/R (raises if L/R is outside the set)."""
        a, b = self._set(self.length_over_radius, extrapolate=self.extrapolate)
        return float(a), float(b)

    def check_applicable(self):
        self.alpha_beta

    def _ab(self):
        a, b = self.alpha_beta
        return dict(alpha=a, beta=b)

    def force(self, depth):
        return lipopov_force(depth, self.radius, self.length, self.estar, **self._ab())

    def depth(self, force):
        return lipopov_depth(force, self.radius, self.length, self.estar, **self._ab())

    def stiffness(self, depth):
        return lipopov_stiffness(depth, self.radius, self.length, self.estar, **self._ab())

    def stiffness_at_force(self, force):
        return lipopov_stiffness_at_force(force, self.radius, self.length, self.estar,
                                          **self._ab())

    def contact_radius(self, depth):
        return lipopov_contact_radius(depth, self.radius, self.length, **self._ab())

    def profile(self, x):
        return lipopov_profile(x, self.radius, self.length, **self._ab())


@register
class PuttockThwaiteModel(ContactModel):
    """Puttock & Thwaite (= Lundberg 1939), Li & Popov 2017 Eq. 2.

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].

    Notes
    -----
    Valid for 0 < d < L^2/R and 0 < F < pi E* L^3/R, where Eq. 2 increases; any L/R.

    Examples
    --------
    >>> m = PuttockThwaiteModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.2f} um"
    '3.36 um'

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 2.
    .. [2] M. J. Puttock, E. G. Thwaite, Elastic compression of spheres and cylinders at
       point and line contact, National Standards Laboratory Technical Paper 25, CSIRO,
       Melbourne (1969).
    .. [3] G. Lundberg, "Elastische Beruehrung zweier Halbraeume", Forschung auf dem
       Gebiete des Ingenieurwesens 10 (1939) 201-211.
    """

    key = "puttock-thwaite"
    label = "Puttock-Thwaite"
    accuracy_tag = "eq2"

    @property
    def provenance(self):
        return self._with_measured_error({"model": self.label,
                "equation": "Li & Popov 2017, Eq. 2 (Puttock & Thwaite; Lundberg 1939); "
                            "stiffness: derivative of Eq. 2 (the printed Eq. 13 is "
                            "inverted)"})

    def force(self, depth):
        return _c.puttock_thwaite_force(depth, self.radius, self.length, self.estar)

    def depth(self, force):
        return _c.puttock_thwaite_depth(force, self.radius, self.length, self.estar)

    def stiffness(self, depth):
        return _c.puttock_thwaite_stiffness_at_depth(depth, self.radius, self.length,
                                                     self.estar)

    def stiffness_at_force(self, force):
        return _c.puttock_thwaite_stiffness(force, self.radius, self.length, self.estar)

    def profile(self, x):
        return _c.puttock_thwaite_profile(x, self.radius, self.length)


@register
class JohnsonModel(ContactModel):
    """Johnson-type law, Li & Popov 2017 Eq. 4, with constant c (option, default 1).

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    c : float or str, optional
        The constant of Eq. 4 (default 1, Johnson 1985; 0.72, 0.572 or any number) [-].

    Notes
    -----
    Valid for 0 < F < 4 pi E* L R exp(-(1 + c)) and 0 < d < 4 R exp(-(1 + c)), where
    Eq. 4 increases; any L/R.

    Examples
    --------
    >>> m = JohnsonModel(5e-3, 10e-3, 115.38e9, c=0.72)
    >>> m.label, f"{m.depth(1e3) * 1e6:.2f} um"
    ('Johnson (c = 0.72)', '2.89 um')

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017], Eq. 4.
    .. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985).
    """

    key = "johnson"
    #: Eq. 4 is written as d(F): evaluate(depth=...) takes k from F, not from d
    stiffness_explicit_in_force = True

    def __init__(self, radius, length, estar, c=1.0):
        super().__init__(radius, length, estar)
        self.c = _c.johnson_constant(c)

    @property
    def label(self):
        return f"Johnson (c = {self.c:g})"

    @property
    def provenance(self):
        who = "Johnson 1985" if self.c == 1.0 else (
            "other authors cited by Li & Popov" if self.c in (0.72, 0.572)
            else "user-given constant")
        return self._with_measured_error(
            {"model": self.label,
             "equation": f"Li & Popov 2017, Eq. 4 with c = {self.c:g} ({who})"})

    @property
    def accuracy_tag(self):
        return "johnson_c" + f"{self.c:g}".replace(".", "p")

    def force(self, depth):
        return _c.johnson_force(depth, self.radius, self.length, self.estar, c=self.c)

    def depth(self, force):
        return _c.johnson_depth(force, self.radius, self.length, self.estar, c=self.c)

    def stiffness(self, depth):
        return self.stiffness_at_force(self.force(depth))

    def stiffness_at_force(self, force):
        return _c.johnson_stiffness(force, self.radius, self.length, self.estar, c=self.c)

    def profile(self, x):
        beta = _c.johnson_equivalent_beta(self.radius, self.length, self.c)
        return lipopov_profile(x, self.radius, self.length, alpha=math.pi / 2, beta=beta)


@register
class KunzModel(ContactModel):
    """Kunz & de Maria's linear law F = c E* L d (option c, default 0.175).

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].
    c : float, optional
        Coefficient of F = c E* L d, 0 < c < inf (default 0.175) [-].

    Notes
    -----
    Valid for 0 < d < inf and 0 < F < inf (a linear law: constant k = c E* L); no
    radius dependence.

    Examples
    --------
    >>> m = KunzModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.2f} um", f"{m.stiffness(1e-6):.4g} N/m"
    ('4.95 um', '2.019e+08 N/m')

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017].
    .. [2] Kunz & de Maria (2002), experiments on parallel cylinders, as cited by Li &
       Popov (2017) [1].
    """

    key = "kunz"
    no_profile_reason = "an empirical force-depth law"

    def __init__(self, radius, length, estar, c=_c.KUNZ_C):
        super().__init__(radius, length, estar)
        self.c = _scalar("c", c, "")

    @property
    def label(self):
        return f"Kunz (c = {self.c:g})"

    @property
    def provenance(self):
        return self._with_measured_error(
            {"model": self.label,
             "equation": "Kunz & de Maria 2002 (experiment, parallel cylinders), "
                         "F = c E* L d, as cited by Li & Popov 2017"})

    @property
    def accuracy_tag(self):
        return "kunz" if self.c == _c.KUNZ_C else None

    def force(self, depth):
        return _c.kunz_force(depth, self.length, self.estar, self.c)

    def depth(self, force):
        return _c.kunz_depth(force, self.length, self.estar, self.c)

    def stiffness(self, depth):
        d = check_positive("depth", depth, "m")
        return out(np.full(d.shape, self.c * self.estar * self.length))

    def stiffness_at_force(self, force):
        F = check_positive("force", force, "N")
        return out(np.full(F.shape, self.c * self.estar * self.length))


class _SteelModel(ContactModel):
    no_profile_reason = "an empirical force-depth law"
    _depth_fn = None
    _force_fn = None
    _source = ""

    @property
    def provenance(self):
        return self._with_measured_error(
            {"model": self.label, "equation": self._source,
             "validity": f"steel on steel only: {_c.STEEL_ESTAR_RANGE.describe()}"})

    def check_applicable(self):
        _c.STEEL_ESTAR_RANGE.check(self.estar, hint=_c.STEEL_HINT)

    def force(self, depth):
        return type(self)._force_fn(depth, self.length, self.estar)

    def depth(self, force):
        return type(self)._depth_fn(force, self.length, self.estar)

    def stiffness(self, depth):
        # F = C d^(1/0.9)  =>  k = F / (0.9 d); d checked (and a pint Quantity converted
        # to SI) before it enters the quotient
        d = check_positive("depth", depth, "m")
        return out(np.asarray(self.force(d)) / (0.9 * d))

    def stiffness_at_force(self, force):
        F = check_positive("force", force, "N")
        return out(F / (0.9 * np.asarray(self.depth(F))))


@register
@document(STEEL=_c.STEEL_ESTAR_RANGE)
class PalmgrenModel(_SteelModel):
    """Palmgren's empirical roller-raceway formula (one contact, steel only).

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].

    Notes
    -----
    Steel on steel only, E* within 10 % of 115.38 GPa:
    %(STEEL)s
    (E* is used for nothing else). Any 0 < F < inf and 0 < d < inf; k = F/(0.9 d),
    the derivative of the power law d ~ F^0.9.

    Examples
    --------
    >>> f"{PalmgrenModel(5e-3, 10e-3, 115.38e9).depth(1e3) * 1e6:.2f} um"
    '3.05 um'

    References
    ----------
    .. [1] A. Palmgren, Ball and Roller Bearing Engineering, SKF, Philadelphia (1959).
    """

    key = "palmgren"
    label = "Palmgren"
    accuracy_tag = "palmgren"
    _depth_fn = staticmethod(_c.palmgren_depth)
    _force_fn = staticmethod(_c.palmgren_force)
    _source = "Palmgren (1959): d [mm] = 3.84e-5 F[N]^0.9 / L[mm]^0.8, one contact"


@register
@document(STEEL=_c.STEEL_ESTAR_RANGE)
class ISO16281Model(_SteelModel):
    """ISO 16281 per-contact roller deflection (steel only).

    Parameters
    ----------
    radius : float
        Cylinder radius R, 0 < R < inf [m].
    length : float
        Cylinder length L, 0 < L < inf [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3), 0 < E* < inf [Pa].

    Notes
    -----
    Steel on steel only, E* within 10 % of 115.38 GPa:
    %(STEEL)s
    (E* is used for nothing else). Any 0 < F < inf and 0 < d < inf; k = F/(0.9 d),
    the derivative of the power law d ~ F^0.9.

    Examples
    --------
    >>> f"{ISO16281Model(5e-3, 10e-3, 115.38e9).depth(1e3) * 1e6:.2f} um"
    '3.15 um'

    References
    ----------
    .. [1] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the
       modified reference rating life for universally loaded rolling bearings.
    """

    key = "iso16281"
    label = "ISO 16281"
    accuracy_tag = "iso16281"
    _depth_fn = staticmethod(_c.iso16281_depth)
    _force_fn = staticmethod(_c.iso16281_force)
    _source = ("ISO 16281:2025: d [mm] = 3.97e-5 F[N]^0.9 / L[mm]^0.8 per contact "
               "(whole roller Q = 35948 L^(8/9) delta^(10/9), two contacts)")


#: The smallest normal double: a dimensionless depth or force below it is refused by
#: the universal curve (a subnormal has lost precision, checks.check_interval).
_TINY = float(np.finfo(float).tiny)


@register
@document(DR=DEPTH_OVER_RADIUS)
class UniversalModel(ContactModel):
    r"""The BEM universal curve for one cylinder (the default model).

    .. math::

        F = \frac{E^* L^3}{R}\Psi\!\left(\frac{dR}{L^2}\right),\quad
        k = E^* L\,\Psi'\!\left(\frac{dR}{L^2}\right),\quad
        a = \frac{k}{2E^*},\quad g(x) = \frac{L^2}{R}\Phi\!\left(\frac{x}{L}\right)

    Parameters
    ----------
    radius : float
        Cylinder radius R [m].
    length : float
        Cylinder length L [m].
    estar : float
        Effective modulus E* (Li & Popov 2017, Eq. 3) [Pa].
    table : str, optional
        Name of the table in tables/ (default ``"universal_curve"``); a missing table
        raises FileNotFoundError naming the file.
    extrapolate : bool, optional
        Accept depths beyond %(DR)s, up to the table's end (default False).

    Notes
    -----
    The curve :math:`\Psi` and its inverses are
    :class:`linecontact.universal.UniversalCurve` (the theory: docs/theory.md, sections 'Self-similarity' and 'BEM').
    Valid for any L/R and for 0 < d <= min(d~_max L^2/R, 0.15 R): d~_max is the
    table's largest dimensionless depth (30 for the shipped table), and %(DR)s is the
    range over which the accuracy study compared the models, within which the parabolic
    gap y^2/(2R) stands in for the circle (it needs d << R). Beyond it a depth is
    refused unless ``extrapolate=True``. Below the table's smallest depth the
    small-depth asymptote continues the curve (see the module docstring). Accuracy: the
    table header's ``accuracy`` line (BEM discretisation) plus the parabolic
    approximation.

    Examples
    --------
    Steel on steel (E* = 115.4 GPa), R = 5 mm, L = 10 mm, F = 1 kN (a value of the
    shipped table; the Li-Popov form gives 3.055 um with Table 1, 3.147 um with Eq. 11,
    Eq. 2 gives 3.363 um):

    >>> m = UniversalModel(5e-3, 10e-3, 115.38e9)
    >>> f"{m.depth(1e3) * 1e6:.3f} um", f"{m.stiffness_at_force(1e3) / 1e6:.1f} N/um"
    ('3.154 um', '347.9 N/um')
    >>> bool(abs(m.force(m.depth(1e3)) / 1e3 - 1) < 1e-12)
    True

    References
    ----------
    .. [1] Li & Popov (2017) [li-popov-2017].
    """

    key = "universal"
    label = "Universal curve (BEM)"

    def __init__(self, radius, length, estar, table=_UNIVERSAL_TABLE, extrapolate=False):
        super().__init__(radius, length, estar)
        self.table_name = table
        self.extrapolate = check_flag("extrapolate", extrapolate)
        self.curve = universal_curve(table)

    @property
    def provenance(self):
        meta = dict(self.curve.table.meta)
        meta["model"] = self.label
        meta["table"] = str(self.curve.table.path.name)
        return meta

    # scales
    @property
    def _dscale(self):
        return self.length ** 2 / self.radius

    @property
    def _fscale(self):
        return self.estar * self.length ** 3 / self.radius

    @property
    def _radius_limited(self):
        """True when d <= 0.15 R, not the table's end, bounds the depth."""
        return (not self.extrapolate
                and DEPTH_OVER_RADIUS.high * self.radius < self.curve.d_max * self._dscale)

    @property
    def depth_limit(self):
        """Largest accepted depth [m]: the table's end d~_max L^2/R, and (unless
        ``extrapolate``) 0.15 R."""
        if self._radius_limited:
            return DEPTH_OVER_RADIUS.high * self.radius
        return self.curve.d_max * self._dscale

    def _psi_end(self):
        """Psi at :attr:`depth_limit`, remembered for the current geometry (every d(F)
        call needs it twice; a spline evaluation with its range check each time)."""
        key = (self.radius, self.length, self.extrapolate, self.curve)
        if getattr(self, "_psi_end_key", None) != key:
            # min: d_max L^2/R / (L^2/R) may round one ulp above d_max (R = 0.5 mm,
            # L = 1 um), which the curve would refuse
            self._psi_end_value = float(self.curve.psi(
                min(self.depth_limit / self._dscale, self.curve.d_max)))
            self._psi_end_key = key
        return self._psi_end_value

    @property
    def force_limit(self):
        """Force at :attr:`depth_limit` [N]."""
        return self._psi_end() * self._fscale

    def _limit_hint(self):
        if self._radius_limited:
            return (f"d/R <= {DEPTH_OVER_RADIUS.high:g}: the parabolic gap y^2/(2R) stands "
                    "in for the circle only for d << R (extrapolate=True accepts depths up "
                    f"to the table's end, d R/L^2 = {self.curve.d_max:g})")
        # the table's end in d/R is set by the geometry: d/R = d~_max (L/R)^2
        lr = self.length / self.radius
        full = (DEPTH_OVER_RADIUS.high / self.curve.d_max) ** 0.5
        text = f"the universal table ends at d R/L^2 = {self.curve.d_max:g}"
        if lr >= full:
            return text
        return (f"{text}; the cause is the geometry: L/R = {lr:.4g} puts the table's end "
                f"at d/R = {self.curve.d_max:g} (L/R)^2 = {self.curve.d_max * lr * lr:.3g} "
                f"(the table covers d/R up to {DEPTH_OVER_RADIUS.high:g} for "
                f"L/R >= {full:.3g})")

    def _checked_depth(self, depth):
        """depth [m] checked against (0, depth_limit]."""
        d = check_interval("depth", depth, 0.0, self.depth_limit, low_open=True,
                           unit="m", hint=self._limit_hint())
        return check_scaled("depth", d, self._dscale, "depth d R/L^2", "m")

    def _checked_force(self, force):
        """force [N] checked against (0, force_limit]."""
        F = check_interval("force", force, 0.0, self.force_limit, low_open=True,
                           unit="N", hint=self._limit_hint())
        return check_scaled("force", F, self._fscale, "force Psi = F R/(E* L^3)", "N")

    def _dt(self, d):
        """d~ of checked depths d [m]: d <= depth_limit, but d/scale may still round
        above d_max at the end."""
        return np.minimum(d / self._dscale, self.curve.d_max)

    def _psi_of_force(self, F):
        """Psi of checked forces F [N]: F <= force_limit, but F/scale may still round
        above Psi at depth_limit at the end."""
        return np.minimum(F / self._fscale, self._psi_end())

    def force(self, depth):
        """F(d) [N]; depth [m]."""
        d = self._checked_depth(depth)
        curve, fscale = self.curve, self._fscale
        if d.ndim and d.size and self._dt(d.min()) >= curve.d_min:
            # all on the table: _dt and the curve's psi, fused in blocks
            def chain(db):
                psi = curve.on_table_psi(self._dt(db))
                psi *= fscale
                return psi

            return out(blockwise(chain, d))
        return out(curve.psi(self._dt(d)) * fscale)

    def depth(self, force):
        """d(F) [m]; force [N]."""
        F = self._checked_force(force)
        curve, dscale, limit = self.curve, self._dscale, self.depth_limit
        if F.ndim and F.size and F.min() / self._fscale >= curve.psi_min:
            # all on the table: the steps below, fused in blocks (cache-resident)
            def chain(fb):
                d = curve.on_table_depth(self._psi_of_force(fb))
                d *= dscale
                return np.minimum(d, limit, out=d)

            return out(blockwise(chain, F))
        d = curve.depth_of_psi(self._psi_of_force(F)) * dscale
        return out(np.minimum(d, limit))   # rounding at the closed end only

    def stiffness(self, depth):
        """k(d) = dF/dd [N/m]; depth [m]."""
        return out(self.curve.dpsi(self._dt(self._checked_depth(depth))) * self.estar
                   * self.length)

    @classmethod
    def evaluate_many(cls, radius, length, estar, *, force=None, depth=None):
        """:meth:`ContactModel.evaluate_many`: the universal curve in the self-similar
        variables of each element, the same operations as one model per cylinder
        (so equal values), and the same range (d <= min(d~_max L^2/R, 0.15 R))."""
        if (force is None) == (depth is None):
            raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                                  "exactly one of force, depth", where="evaluate_many()")
        curve = universal_curve(_UNIVERSAL_TABLE)
        R, L, E = (np.asarray(a, dtype=float) for a in (radius, length, estar))
        given = np.asarray(force if force is not None else depth, dtype=float)
        nan = np.full(given.shape, np.nan)
        try:
            return cls._evaluate_many(curve, R, L, E, given, nan, force is not None)
        except OutOfRangeError:   # an end value rounded outside the table: per cylinder
            return None

    @staticmethod
    def _evaluate_many(curve, R, L, E, given, nan, by_force):
        with np.errstate(all="ignore"):
            ok = (np.isfinite(given) & (given > 0) & (R > 0) & (L > 0) & (E > 0)
                  & np.isfinite(R) & np.isfinite(L) & np.isfinite(E)
                  & scales_are_normal(R, L, E))
            if not ok.any():
                return {k: nan for k in ("force", "depth", "stiffness",
                                         "contact_radius")}, ok
            R, L, E, x = R[ok], L[ok], E[ok], given[ok]
            # the powers as one model computes them (Python's float power: numpy's
            # array power may differ in the last bit), so that the values are equal
            lengths = L.tolist()
            dscale = np.array([v ** 2 for v in lengths]) / R
            fscale = E * np.array([v ** 3 for v in lengths]) / R
            limited = DEPTH_OVER_RADIUS.high * R < curve.d_max * dscale
            dlim = np.where(limited, DEPTH_OVER_RADIUS.high * R, curve.d_max * dscale)
            # clipped to d_max as one model does (UniversalModel._dt: d_max L^2/R
            # divided by L^2/R may round one ulp above it)
            dmax = curve.d_max
            psi_end = curve.psi(np.minimum(dlim / dscale, dmax))
            if by_force:
                # Psi = F/scale below the smallest normal double (F = 1e-301 N on a
                # steel roller) is refused by the curve, as by one model: such an
                # element is left to its model's message, not the whole call to None
                inside = (x <= psi_end * fscale) & (x / fscale >= _TINY)
                F = x
                d = curve.depth_of_psi(np.where(inside, np.minimum(F / fscale, psi_end),
                                                psi_end)) * dscale
                d = np.minimum(d, dlim)
            else:
                inside = (x <= dlim) & (x / dscale >= _TINY)   # as Psi above, d~
                d = x
                F = curve.psi(np.minimum(np.where(inside, d, dlim) / dscale, dmax)) * fscale
            k = curve.dpsi(np.minimum(np.where(inside, d, dlim) / dscale, dmax)) * E * L
            a = k / (2 * E)
        ok[ok] = inside
        res = {}
        for name, v in (("force", F), ("depth", d), ("stiffness", k),
                        ("contact_radius", a)):
            full = nan.copy()
            full[ok] = v[inside]
            res[name] = full
        return res, ok

    def profile(self, x):
        """MDR profile g(x) [m] for 0 <= x <= the MDR radius at the table's end [m]."""
        xv = np.asarray(x, dtype=float)
        if np.any(~np.isfinite(xv)) or np.any(xv < 0):
            bad = float(xv[~(np.isfinite(xv) & (xv >= 0))].flat[0]) if xv.ndim else float(xv)
            raise OutOfRangeError("x", bad, "[0, inf) m", unit="m")
        try:
            return out(self.curve.depth_of_x(xv / self.length) * self._dscale)
        except OutOfRangeError as exc:
            raise OutOfRangeError("x", float(exc.value) * self.length,
                                  f"[0, {self.curve.x_max * self.length:.6g}] m", unit="m",
                                  hint=exc.hint) from None


# --------------------------------------------------------------------------------------
ACCURACY_TABLE = MODEL_ACCURACY
_NOT_APPLICABLE, _NO_ANSWER = 98.0, 99.0   # flags of tables/model_accuracy.csv


def _measured_error(tag, length_over_radius):
    """Text: range of the measured F and k errors of model `tag` at the study's L/R
    rows bracketing `length_over_radius` (see :attr:`ContactModel.measured_error`)."""
    table = model_accuracy()
    if table is None:
        return (f"not measured: tables/{ACCURACY_TABLE}.csv is missing "
                "(python -m tools.build_tables accuracy)")
    cols = table.columns
    if f"F_err_{tag}" not in cols:
        return f"not measured: tables/{ACCURACY_TABLE}.csv has no column F_err_{tag}"
    grid = np.unique(cols["L_over_R"])
    q = length_over_radius
    if not grid[0] * (1 - 1e-9) <= q <= grid[-1] * (1 + 1e-9):
        return (f"not measured at L/R = {q:.3g}: the accuracy study covers "
                f"L/R {grid[0]:g} to {grid[-1]:g}")
    lo = grid[grid <= q * (1 + 1e-9)].max()
    hi = grid[grid >= q * (1 - 1e-9)].min()
    rows = (cols["L_over_R"] == lo) | (cols["L_over_R"] == hi)
    eF, ek = cols[f"F_err_{tag}"][rows], cols[f"k_err_{tag}"][rows]
    valid = eF < _NOT_APPLICABLE
    where = f"L/R = {lo:g}" + (f" and {hi:g}" if hi != lo else "")
    if not valid.any():
        return f"not measured: the model does not apply (or has no answer) at {where}"
    d = cols["d_over_R"][rows][valid]

    def rng(e):
        return f"{e.min() * 100:+.2g} % to {e.max() * 100:+.2g} %"

    text = (f"against the BEM at {where}, d/R {d.min():.2g} to {d.max():.2g}: "
            f"F {rng(eF[valid])}, k {rng(ek[valid])}")
    if np.any(eF == _NO_ANSWER):
        text += "; no answer at the other depths"
    return text + f" (tables/{ACCURACY_TABLE}.csv)"


def available_models():
    """Registered model keys, sorted.

    Returns
    -------
    list of str
        The keys of :data:`MODELS` [-].

    Examples
    --------
    >>> {"universal", "li-popov", "johnson", "palmgren"} <= set(available_models())
    True
    """
    return sorted(set(MODELS) | set(DEFINED_IN))


def get_model(key, radius, length, estar, **options):
    """Build the model registered under `key` for one cylinder.

    Parameters
    ----------
    key : str
        Registry key (see :data:`MODELS`) [-].
    radius, length : float
        R, L [m].
    estar : float
        E* [Pa].
    **options
        Passed to the model, e.g. ``coefficients="eq11"`` or ``c=0.72``.

    Returns
    -------
    ContactModel

    Raises
    ------
    UnknownNameError
        Unknown key (the message lists the valid ones).
    OutOfRangeError
        Bad R, L, E*.
    FileNotFoundError
        The model's table is missing (the message names the file).

    Notes
    -----
    Valid for 0 < R, L, E* < inf (checked at construction); whether a model applies
    to that cylinder (L/R in its table, steel E*) is checked when it is evaluated.

    Examples
    --------
    >>> get_model("johnson", 5e-3, 10e-3, 115.38e9, c=0.572).label
    'Johnson (c = 0.572)'
    >>> get_model("hertz", 5e-3, 10e-3, 115.38e9)
    Traceback (most recent call last):
    ...
    linecontact.errors.UnknownNameError: model = 'hertz' is not a known name; valid: ...
    """
    if key not in MODELS and key in DEFINED_IN:
        import_module(DEFINED_IN[key])
    if key not in MODELS:
        raise UnknownNameError("model", key, available_models())
    return MODELS[key](radius, length, estar, **options)


def standard_models(radius, length, estar):
    """The CLI's row set for one cylinder, in display order.

    Universal curve (the best estimate, :data:`DEFAULT_MODEL`), Li-Popov Table 1 spline,
    Li-Popov Eq. 11, Li-Popov regenerated (only if ``tables/lipopov_regenerated.csv``
    exists: an optional coefficient set), Puttock-Thwaite, Johnson c = 1, 0.72, 0.572,
    Kunz, Palmgren, ISO 16281.

    Models are built even if they do not apply to this cylinder (L/R out of a table's
    range, non-steel E*); their evaluations then raise
    :class:`~linecontact.errors.OutOfRangeError`, which the caller reports per row.
    A missing universal table is an error (FileNotFoundError naming the file), never a
    silently shorter row set.

    Parameters
    ----------
    radius, length : float
        R, L [m].
    estar : float
        E* [Pa].

    Returns
    -------
    list of ContactModel

    Notes
    -----
    Valid for 0 < R, L, E* < inf (checked at construction); whether a model applies
    to that cylinder (L/R in its table, steel E*) is checked when it is evaluated.

    Examples
    --------
    >>> rows = standard_models(5e-3, 10e-3, 115.38e9)
    >>> [m.label for m in rows][:5]  # with the shipped tables
    ['Universal curve (BEM)', 'Li-Popov (Table 1 spline)', 'Li-Popov (Eq. 11)', 'Li-Popov (regenerated table)', 'Puttock-Thwaite']
    """
    R = _scalar("radius", radius, "m")
    L = _scalar("length", length, "m")
    E = _scalar("estar", estar, "Pa")
    rows = [UniversalModel(R, L, E),
            LiPopovModel(R, L, E, coefficients="published"),
            LiPopovModel(R, L, E, coefficients="eq11")]
    if "lipopov_regenerated" in available_tables("lipopov_"):
        rows.append(LiPopovModel(R, L, E, coefficients="regenerated"))
    rows.append(PuttockThwaiteModel(R, L, E))
    rows.extend(JohnsonModel(R, L, E, c=c) for c in (1.0, 0.72, 0.572))
    rows.append(KunzModel(R, L, E))
    rows.append(PalmgrenModel(R, L, E))
    rows.append(ISO16281Model(R, L, E))
    return rows
