r"""The whole roller between the two raceways of a radial bearing, for any contact law.

A roller (radius R1, length L) sits between an inner raceway (radius Ri, convex) and
an outer raceway (radius Ro, concave). Its two contacts are each a cylinder of the
effective radius on a half-space (Hertz's reduction of two parallel cylinders, Johnson
1985, section 4.2):

.. math::

    \frac{1}{R_{in}} = \frac{1}{R_1} + \frac{1}{R_i}, \qquad
    \frac{1}{R_{out}} = \frac{1}{R_1} - \frac{1}{R_o},

both of the roller's length and profile and the same E*. The contacts are in series:
they carry the same force F (the roller in radial equilibrium, no centrifugal force)
and the ring approach at the roller's centre is the sum of their depths,

.. math::

    \delta = d_{in}(F) + d_{out}(F), \qquad \frac{1}{k} = \frac{1}{k_{in}} +
    \frac{1}{k_{out}} .

Profiled or tilted rollers
--------------------------
With a profile, a tilt or misaligned rings, each contact is the coupled-slice model of
:mod:`linecontact.roller` (or ISO 16281 slicing). The roller's tilt theta is
measured against the inner raceway (positive when its +x end goes deeper into the inner
ring); with the outer ring misaligned by psi (positive when the rings close at +x, the
ring approach being :math:`\delta + \psi x`), the tilt of the roller against the outer
raceway is :math:`\psi - \theta`. The roller is either held at a given tilt (the moment
:math:`M = M_{in} - M_{out}` that holds it is reported) or free to tilt: then it
settles where the moments of its two contacts about its centre balance,

.. math:: M_{in}(F, \theta) = M_{out}(F, \psi - \theta),

solved by Newton's method with the exact tilt stiffness of each contact at constant
force, :math:`k_{M\theta} = K_{11} - K_{10}K_{01}/K_{00}`. The roller's tilt stiffness is
:math:`dM/d\theta = k_{M\theta,in} + k_{M\theta,out}` (force held), and with the tilt free
its radial stiffness follows from the two 2x2 stiffness matrices with the moment
balance kept (:func:`roller_between_raceways`).

Fit
---
The raceways must fit the roller: :math:`R_o - R_i = 2R_1 + c` with the radial
clearance c (or preload, c < 0) small. A pair with
:math:`|R_o - R_i - 2R_1| > \epsilon\,2R_1` (:data:`FIT_TOLERANCE` epsilon = 1 % of the
roller diameter by default, wider than the radial clearance of bearings' clearance
classes) is refused with the numbers: most often diameters typed as radii.

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 4.2
   (two cylinders with parallel axes).
.. [2] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded rolling bearings (roller between raceways,
   slicing, misalignment).
.. [3] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press (2007),
   chapter on roller-raceway deflection (contacts in series).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .models import DEFAULT_MODEL, DEFAULT_SLICE_MODEL, SLICE_MODELS
from .profiles import TILT_RANGE, is_free_tilt
from .errors import CombinationError, OutOfRangeError, UnknownNameError
from ._numerics import out
from .checks import Interval, check_positive

__all__ = [
    "Raceways",
    "RacewaySolution",
    "effective_radii",
    "effective_radius",
    "check_fit",
    "roller_between_raceways",
    "FIT_TOLERANCE",
    "SLICE_MODELS",
]

#: Default fit tolerance: |Ro - Ri - 2 R1| may be at most this fraction of 2 R1 [-].
FIT_TOLERANCE = 0.01
#: Fit tolerances accepted [-].
FIT_TOLERANCE_RANGE = Interval("fit_tolerance", 0.0, 0.5, low_open=False, high_open=True)
#: The law used for a straight, aligned roller when no model is named.
DEFAULT_STRAIGHT_MODEL = DEFAULT_MODEL


def _one_of(name, value, given):
    """The radius from a radius or a diameter (exactly one), checked > 0 [m]."""
    radius, diameter = given
    if (radius is None) == (diameter is None):
        raise CombinationError({f"{name}_radius": radius, f"{name}_diameter": diameter},
                               f"give the {name} raceway as a radius or a diameter, "
                               "exactly one")
    if radius is not None:
        return float(check_positive(f"{name}_radius", radius, "m"))
    return 0.5 * float(check_positive(f"{name}_diameter", diameter, "m"))


@dataclass(frozen=True, init=False)
class Raceways:
    """The inner (convex) and outer (concave) raceway of a radial bearing.

    Give each raceway as a radius or as a diameter (data sheets give diameters: the
    inner ring's raceway diameter and the outer ring's, e.g. d1 and D1 of a cylindrical
    roller bearing).

    Parameters
    ----------
    inner : float, optional
        Inner raceway radius Ri, 0 < Ri < inf [m].
    outer : float, optional
        Outer raceway radius Ro > roller radius [m].
    inner_diameter : float, optional
        Inner raceway diameter 2 Ri, instead of `inner` [m].
    outer_diameter : float, optional
        Outer raceway diameter 2 Ro, instead of `outer` [m].
    misalignment : float, optional
        Tilt psi of the outer ring against the inner ring in the roller's plane,
        positive when the rings close at the roller's +x end, |psi| < 0.1 [rad]
        (default 0).
    fit_tolerance : float, optional
        Largest |Ro - Ri - 2 R1| accepted, as a fraction of the roller diameter 2 R1,
        0 <= eps < 0.5 [-] (default :data:`FIT_TOLERANCE`, 1 %).

    Notes
    -----
    Valid for 0 < Ri < Ro < inf; the fit against a roller is checked by
    :meth:`check_fit` (and by every solve). Attributes ``inner``, ``outer`` are the
    radii [m].

    Examples
    --------
    >>> r = Raceways(inner_diameter=40e-3, outer_diameter=50e-3)
    >>> r.inner, r.outer
    (0.02, 0.025)
    >>> [f"{x * 1e3:.3f} mm" for x in r.effective_radii(2.5e-3)]
    ['2.222 mm', '2.778 mm']
    """

    inner: float
    outer: float
    misalignment: float
    fit_tolerance: float

    def __init__(self, inner=None, outer=None, *, inner_diameter=None,
                 outer_diameter=None, misalignment=0.0, fit_tolerance=FIT_TOLERANCE):
        Ri = _one_of("inner", inner, (inner, inner_diameter))
        Ro = _one_of("outer", outer, (outer, outer_diameter))
        if not Ro > Ri:
            raise CombinationError({"inner_radius": Ri, "outer_radius": Ro},
                                   "the outer raceway must be larger than the inner one",
                                   unit={"inner_radius": "m", "outer_radius": "m"})
        object.__setattr__(self, "inner", Ri)
        object.__setattr__(self, "outer", Ro)
        object.__setattr__(self, "misalignment",
                           TILT_RANGE.check(misalignment, name="misalignment").item())
        object.__setattr__(self, "fit_tolerance",
                           FIT_TOLERANCE_RANGE.check(fit_tolerance).item())

    def effective_radii(self, roller_radius):
        """Effective radii (R_in, R_out) of the two contacts [m]
        (:func:`effective_radii`)."""
        return effective_radii(roller_radius, self.inner, self.outer)

    def check_fit(self, roller_radius):
        """The radial clearance Ro - Ri - 2 R1 [m], or :class:`CombinationError` if the
        raceways do not fit the roller (:func:`check_fit`)."""
        return check_fit(roller_radius, self.inner, self.outer, self.fit_tolerance)


def effective_radius(roller_radius, counter_radius):
    r"""Effective radius of two parallel cylinders in line contact (Hertz's reduction).

    .. math:: \frac{1}{R} = \frac{1}{R_1} + \frac{1}{R_2}

    with R_2 > 0 for a convex counter-body (an inner raceway), R_2 < 0 for a concave one
    (an outer raceway, |R_2| > R_1) and R_2 = inf for a flat.

    Parameters
    ----------
    roller_radius : float or array_like
        Roller radius R1 [m].
    counter_radius : float or array_like
        Signed radius R2 of the counter-body [m] (negative: concave).

    Returns
    -------
    float or ndarray
        R [m], elementwise (nan where an input is nan; the inputs are not checked:
        :func:`effective_radii` is the checked door).

    Notes
    -----
    Valid for parallel axes and a contact half-width b << R (Hertz), 0 < R1 < |R2|.

    Examples
    --------
    >>> f"{effective_radius(5e-3, 20e-3) * 1e3:.4f} mm"
    '4.0000 mm'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    return 1 / (1 / roller_radius + 1 / counter_radius)


def effective_radii(roller_radius, inner_radius, outer_radius):
    r"""Effective radii of a roller's contacts with an inner and an outer raceway.

    .. math:: R_{in} = \left(\frac{1}{R_1} + \frac{1}{R_i}\right)^{-1}, \qquad
              R_{out} = \left(\frac{1}{R_1} - \frac{1}{R_o}\right)^{-1}

    Parameters
    ----------
    roller_radius : float or array_like
        Roller radius R1 [m].
    inner_radius : float or array_like
        Inner raceway radius Ri (convex) [m].
    outer_radius : float or array_like
        Outer raceway radius Ro (concave), Ro > R1 [m].

    Returns
    -------
    tuple of float or ndarray
        (R_in, R_out) [m].

    Notes
    -----
    Valid for 0 < R1 < Ro, 0 < Ri (parallel axes, b << R).

    Examples
    --------
    >>> [f"{r * 1e3:.4f}" for r in effective_radii(5e-3, 20e-3, 30e-3)]
    ['4.0000', '6.0000']

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    R1 = check_positive("roller_radius", roller_radius, "m")
    Ri = check_positive("inner_radius", inner_radius, "m")
    Ro = check_positive("outer_radius", outer_radius, "m")
    bad = ~(Ro > R1)
    if np.any(bad):
        i = np.argwhere(np.atleast_1d(bad))[0][0]
        raise CombinationError(
            {"roller_radius": float(np.atleast_1d(R1)[i] if np.ndim(R1) else R1),
             "outer_radius": float(np.atleast_1d(Ro)[i] if np.ndim(Ro) else Ro)},
            "the roller does not fit inside the outer raceway (Ro must exceed R1)",
            unit={"roller_radius": "m", "outer_radius": "m"})
    return out(effective_radius(R1, Ri)), out(effective_radius(R1, -Ro))


def check_fit(roller_radius, inner_radius, outer_radius, tolerance=FIT_TOLERANCE):
    r"""Radial clearance of a roller between two raceways, refusing a pair that does not fit.

    .. math:: c = R_o - R_i - 2R_1, \qquad |c| \le \epsilon\,2R_1

    Parameters
    ----------
    roller_radius : float
        Roller radius R1 [m].
    inner_radius : float
        Inner raceway radius Ri [m].
    outer_radius : float
        Outer raceway radius Ro [m].
    tolerance : float, optional
        epsilon, 0 <= eps < 0.5 [-] (default :data:`FIT_TOLERANCE`).

    Returns
    -------
    float
        The radial clearance c [m] (negative: preload).

    Raises
    ------
    CombinationError
        |c| > eps 2 R1, with the three radii, the difference and the tolerance, and a
        hint when the numbers look like diameters typed as radii.

    Notes
    -----
    Valid for 0 < R1, Ri, Ro < inf. The contact laws take the raceways as rigidly
    positioned: the clearance changes which rollers carry load in a bearing, not the
    contact law of one roller.

    Examples
    --------
    >>> f"{check_fit(5e-3, 20e-3, 30.01e-3) * 1e6:.0f} um"
    '10 um'
    >>> check_fit(5e-3, 40e-3, 60e-3)
    Traceback (most recent call last):
    ...
    linecontact.errors.CombinationError: roller_radius = 0.005 m, inner_radius = 0.04 m, outer_radius = 0.06 m: the raceways do not fit the roller: Ro - Ri = 0.02 m, not the roller diameter 2 R1 = 0.01 m within 1 % (the difference 0.01 m exceeds 0.0001 m); Ro - Ri = 4 R1: diameters given as radii?

    References
    ----------
    T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis (2007) (radial clearance).
    """
    R1 = float(check_positive("roller_radius", roller_radius, "m"))
    Ri = float(check_positive("inner_radius", inner_radius, "m"))
    Ro = float(check_positive("outer_radius", outer_radius, "m"))
    eps = FIT_TOLERANCE_RANGE.check(tolerance).item()
    c = Ro - Ri - 2 * R1
    if abs(c) <= eps * 2 * R1 * (1 + 1e-12):
        return c
    hint = ""
    gap = Ro - Ri
    if abs(gap - 4 * R1) <= eps * 4 * R1:
        hint = "; Ro - Ri = 4 R1: diameters given as radii?"
    elif abs(gap - R1) <= eps * R1:
        hint = "; Ro - Ri = R1: the roller's diameter given as its radius?"
    raise CombinationError(
        {"roller_radius": R1, "inner_radius": Ri, "outer_radius": Ro},
        f"the raceways do not fit the roller: Ro - Ri = {gap:.6g} m, not the roller "
        f"diameter 2 R1 = {2 * R1:.6g} m within {100 * eps:.6g} % (the difference "
        f"{abs(c):.6g} m exceeds {eps * 2 * R1:.6g} m){hint}",
        unit={"roller_radius": "m", "inner_radius": "m", "outer_radius": "m"})


@dataclass(frozen=True)
class RacewaySolution:
    """The whole roller between two raceways: load, deflection, stiffness, tilt, moment.

    Returned by :func:`roller_between_raceways`; not built by hand. Scalars, or arrays
    of the force's (deflection's) shape for a straight, aligned roller under a law.

    Parameters
    ----------
    force : float or ndarray
        Load F carried by the roller (each contact carries it) [N].
    deflection : float or ndarray
        Ring approach at the roller's centre, delta = d_in + d_out [m].
    stiffness : float or ndarray
        dF/d delta of the whole roller (the tilt held, or free with the moment balance
        kept when ``free_tilt``) [N/m].
    depth_inner, depth_outer : float or ndarray
        Depth of each contact at the roller's centre [m].
    stiffness_inner, stiffness_outer : float or ndarray
        dF/dd of each contact at fixed tilt [N/m].
    peak_pressure_inner, peak_pressure_outer : float or ndarray or None
        Peak pressure of each contact (plane-strain Hertz p0 for a straight law; the
        slice model's peak, None where it is edge loaded) [Pa].
    radius_inner, radius_outer : float
        Effective radii of the two contacts [m].
    clearance : float
        Radial clearance Ro - Ri - 2 R1 [m].
    tilt : float
        Roller tilt against the inner raceway [rad].
    misalignment : float
        Outer ring's tilt against the inner ring [rad].
    moment : float
        Moment M_in - M_out that holds the roller at its tilt (0 when free) [N m].
    moment_inner, moment_outer : float
        Moment of each contact's load about the roller's centre [N m].
    tilt_stiffness : float or None
        dM/dtheta of the roller at constant force [N m/rad] (None for a straight law).
    free_tilt : bool
        True if the tilt was solved for moment equilibrium.
    inner, outer : RollerSolution or None
        The two slice solutions (q(x), pressures, edge loading); None for a law.
    model : str
        The contact law or slice method used.
    notes : tuple of str
        Validity notes (each contact's, prefixed inner/outer).

    Notes
    -----
    Valid as the contact model used, for the fit checked by :func:`check_fit`.

    Examples
    --------
    >>> s = roller_between_raceways(5e-3, 10e-3, 115.38e9,
    ...                             Raceways(20e-3, 30e-3), force=1e3)
    >>> f"{s.deflection * 1e6:.3f} um = {s.depth_inner * 1e6:.3f} + " \\
    ...     f"{s.depth_outer * 1e6:.3f}"
    '6.320 um = 3.217 + 3.103'
    """

    force: object
    deflection: object
    stiffness: object
    depth_inner: object
    depth_outer: object
    stiffness_inner: object
    stiffness_outer: object
    peak_pressure_inner: object
    peak_pressure_outer: object
    radius_inner: float
    radius_outer: float
    clearance: float
    tilt: float = 0.0
    misalignment: float = 0.0
    moment: float = 0.0
    moment_inner: float = 0.0
    moment_outer: float = 0.0
    tilt_stiffness: object = None
    free_tilt: bool = False
    inner: object = None
    outer: object = None
    model: str = ""
    notes: tuple = field(default_factory=tuple)


def _kmt(K):
    """dM/dtheta at constant force of one contact from its 2x2 stiffness matrix."""
    return K[1, 1] - K[1, 0] * K[0, 1] / K[0, 0]


def _is_straight(profile):
    from .profiles import StraightProfile

    return isinstance(profile, StraightProfile)


def roller_between_raceways(radius, length, estar, raceways, *, force=None,
                            deflection=None, model=None, profile=None, tilt=0.0,
                            n_slices=None, **options):
    r"""Solve a whole roller between two raceways at a given load or ring approach.

    .. math::

        \delta = d_{in}(F, \theta) + d_{out}(F, \psi - \theta), \qquad
        \frac{1}{k} = \frac{1}{k_{in}} + \frac{1}{k_{out}}, \qquad
        M_{in} = M_{out}\ \text{(tilt free)}

    Parameters
    ----------
    radius : float
        Roller radius R1 (half its diameter) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* of roller and rings (the same material on both) [Pa].
    raceways : Raceways
        The two raceways (radii or diameters, ring misalignment, fit tolerance).
    force : float or array_like, optional
        Roller load F > 0 [N]; arrays for a straight, aligned roller under a law.
    deflection : float or array_like, optional
        Ring approach delta > 0 at the roller's centre, instead of `force` [m].
    model : str or None, optional
        Contact law of each contact: a key of :func:`linecontact.models.available_models`.
        None: ``"universal"`` for a straight, aligned roller, ``"profiled-roller"``
        (coupled slices) otherwise. A profile, a tilt or misaligned rings need a
        slice model (``"profiled-roller"`` or ``"iso16281-slicing"``).
    profile : Profile or str or None, optional
        The roller's axial profile (:mod:`linecontact.profiles`; a spec is read with
        the roller's own radius R1, so ``"iso16281"`` takes D = 2 R1); None: straight.
    tilt : float or str, optional
        Roller tilt against the inner raceway, |theta| < 0.1 [rad] (default 0,
        aligned); ``"free"``: the tilt at which the roller's moments balance.
    n_slices : int, optional
        Slices of a slice model [-] (default: the model's, 50 coupled, 30 ISO).
    **options
        Passed to a law (e.g. ``c=0.72`` for Johnson's).

    Returns
    -------
    RacewaySolution

    Raises
    ------
    CombinationError
        Raceways that do not fit the roller; a profile, tilt or misalignment with a
        straight-cylinder law; neither or both of force and deflection.
    UnknownNameError
        An unknown model key.
    OutOfRangeError
        A value outside its range, or outside the law's range.

    Notes
    -----
    Valid for 0 < R1 < Ro, |theta|, |psi| < 0.1 rad, b << R_in, within each law's
    range (a slice model: see :mod:`linecontact.roller`). Under a law the contacts are
    straight, aligned cylinders of the effective radii: the roller's moment is zero by
    symmetry and its tilt stiffness is not given (None; ask a slice model).

    Examples
    --------
    A crowned roller between raceways, free to tilt: aligned by symmetry, and the
    deflection is the sum of the two contacts computed one by one:

    >>> from linecontact.roller import ProfiledRoller
    >>> race = Raceways(20e-3, 30e-3)
    >>> s = roller_between_raceways(5e-3, 10e-3, 115.38e9, race, force=1e3,
    ...                             profile="circular:Rc=0.1", tilt="free", n_slices=40)
    >>> f"{s.deflection * 1e6:.3f} um, tilt {abs(s.tilt):.1g} rad"
    '22.134 um, tilt 0 rad'
    >>> d = sum(ProfiledRoller(r, 10e-3, 115.38e9, "circular:Rc=0.1", n_slices=40)
    ...         .at_force(1e3, tilt=0.0).depth for r in race.effective_radii(5e-3))
    >>> f"{d * 1e6:.3f} um"
    '22.134 um'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 4.2; ISO 16281:2025.
    """
    from .models import available_models, get_model
    from .profiles import as_profile

    R1 = float(check_positive("radius", radius, "m"))
    L = float(check_positive("length", length, "m"))
    E = float(check_positive("estar", estar, "Pa"))
    if not isinstance(raceways, Raceways):
        raise OutOfRangeError("raceways", repr(raceways), "a linecontact.raceway.Raceways")
    if (force is None) == (deflection is None):
        raise CombinationError({"force": force, "deflection": deflection},
                               "give exactly one of force and deflection")
    clearance = raceways.check_fit(R1)
    R_in, R_out = raceways.effective_radii(R1)
    free = is_free_tilt(tilt)
    th = None if free else TILT_RANGE.check(tilt).item()
    psi = raceways.misalignment
    prof = as_profile(profile, R1, L, E)
    plain = _is_straight(prof) and psi == 0.0 and (free or th == 0.0)
    if model is None:
        model = DEFAULT_STRAIGHT_MODEL if plain else DEFAULT_SLICE_MODEL
    if model not in available_models():
        raise UnknownNameError("model", model, available_models())
    if model not in SLICE_MODELS:
        if not plain:
            raise CombinationError(
                {"model": model, "profile": prof.label, "tilt": tilt,
                 "misalignment": psi},
                "a straight-cylinder law has no profile, tilt or misalignment; use "
                "model='profiled-roller' (coupled slices)")
        return _law_solution(get_model, model, R_in, R_out, L, E, force, deflection,
                             clearance, options)
    if options:
        raise CombinationError({"model": model, "options": sorted(options)},
                               "a slice model takes no law options")
    return _slice_solution(model, R_in, R_out, L, E, prof, force, deflection, th, psi,
                           n_slices, clearance)


def _law_solution(get_model, key, R_in, R_out, L, E, force, deflection, clearance,
                  options):
    """Straight, aligned roller: two laws in series, vectorised over the loads."""
    from .classical import hertz_peak_pressure

    mi = get_model(key, R_in, L, E, **options)
    mo = get_model(key, R_out, L, E, **options)
    for m in (mi, mo):
        m.check_applicable()
    if force is not None:
        F = check_positive("force", force, "N")
    else:
        F = _force_at_deflection(mi, mo, check_positive("deflection", deflection, "m"))
    ri, ro = mi.evaluate(force=F), mo.evaluate(force=F)
    di, do = np.asarray(ri["depth"]), np.asarray(ro["depth"])
    ki, ko = np.asarray(ri["stiffness"]), np.asarray(ro["stiffness"])
    return RacewaySolution(
        force=out(np.asarray(F, dtype=float)), deflection=out(di + do),
        stiffness=out(_in_series(ki, ko)), depth_inner=out(di),
        depth_outer=out(do), stiffness_inner=out(ki), stiffness_outer=out(ko),
        peak_pressure_inner=hertz_peak_pressure(F, R_in, L, E),
        peak_pressure_outer=hertz_peak_pressure(F, R_out, L, E),
        radius_inner=float(R_in), radius_outer=float(R_out), clearance=clearance,
        model=mi.label)


def _force_at_deflection(mi, mo, delta):
    """F with d_in(F) + d_out(F) = delta: Newton on ln F (delta grows with F, its
    log-slope F/(k delta) between about 0.7 and 1), bracketed."""
    delta = np.asarray(delta, dtype=float)
    flat = delta.ravel()
    res = np.empty_like(flat)
    for i, dl in enumerate(flat):
        # the 2D line contact's order of magnitude, F ~ pi E* L delta / 10
        lnF = math.log(math.pi * mi.estar * mi.length * dl / 10.0)
        lo, hi = -math.inf, math.inf
        for _ in range(100):
            F = math.exp(lnF)
            ri, ro = mi.evaluate(force=F), mo.evaluate(force=F)
            d = float(ri["depth"] + ro["depth"])
            k = _in_series(float(ri["stiffness"]), float(ro["stiffness"]))
            err = math.log(d / dl)
            if abs(err) <= 1e-13:
                break
            if err < 0:
                lo = max(lo, lnF)
            else:
                hi = min(hi, lnF)
            step = -err / (F / (k * d))
            new = lnF + step
            if not lo < new < hi:
                new = 0.5 * (lo + hi) if math.isfinite(lo) and math.isfinite(hi) else (
                    lnF + (2.0 if err < 0 else -2.0))
            lnF = new
        else:
            raise OutOfRangeError("deflection", float(dl), "a deflection the law reaches",
                                  unit="m", hint="no force found in 100 Newton steps")
        res[i] = F
    return res.reshape(delta.shape)


def _slice_solution(model, R_in, R_out, L, E, prof, force, deflection, th, psi,
                    n_slices, clearance):
    if np.ndim(force) or np.ndim(deflection):
        raise CombinationError({"model": model, "force": "an array"},
                               "a slice model solves one load at a time; loop over "
                               "the loads")
    from .roller.solvers import slice_solver

    inner = slice_solver(model, R_in, L, E, prof, n_slices=n_slices).at_force
    outer = slice_solver(model, R_out, L, E, prof, n_slices=n_slices).at_force
    free = th is None

    def at(F, t):
        si, so = inner(F, t), outer(F, psi - t)
        return si, so

    def solve_tilt(F):
        if not free:
            return at(F, th)
        t = 0.5 * psi
        lo, hi = -0.1, 0.1
        for _ in range(60):
            si, so = at(F, t)
            g = si.moment - so.moment
            dg = _kmt(si.stiffness_matrix) + _kmt(so.stiffness_matrix)
            if abs(g) <= 1e-10 * F * L:
                return si, so
            if g > 0:
                hi = min(hi, t)
            else:
                lo = max(lo, t)
            new = t - g / dg
            t = new if lo < new < hi else 0.5 * (lo + hi)
        from .roller import ConvergenceError

        raise ConvergenceError(f"no tilt balances the roller's moments at F = {F:g} N")

    if force is not None:
        F = float(check_positive("force", force, "N"))
        si, so = solve_tilt(F)
    else:
        dl = float(check_positive("deflection", deflection, "m"))
        lnF = math.log(math.pi * E * L * dl / 10.0)
        for _ in range(100):
            F = math.exp(lnF)
            si, so = solve_tilt(F)
            d = si.depth + so.depth
            k = _series_stiffness(si, so, free)
            err = math.log(d / dl) if d > 0 else -math.inf
            if abs(err) <= 1e-10:
                break
            lnF -= max(min(err / (F / (k * d)), 2.0), -2.0)
        else:
            raise OutOfRangeError("deflection", dl, "a deflection the model reaches",
                                  unit="m", hint="no force found in 100 Newton steps")
    return _contacts_solution(model, si, so, R_in, R_out, psi, free, clearance, F)


def _contacts_solution(model, si, so, R_in, R_out, misalignment, free, clearance,
                      force=None):
    """The :class:`RacewaySolution` of a roller whose two slice contacts are solved:
    `si` and `so` (:class:`~linecontact.roller.RollerSolution`, inner and outer, at the
    same load), the slice model's name, the effective radii [m], the rings'
    misalignment [rad], whether the roller is free to tilt, the clearance [m] and the
    roller load asked for [N] (None: the inner contact's). The one assembly of
    :func:`roller_between_raceways` and of a bearing's rollers
    (:mod:`linecontact.bearing`), so that both report the same numbers of one solve."""
    F = si.force if force is None else force
    psi = misalignment
    k = _series_stiffness(si, so, free)
    tks = _kmt(si.stiffness_matrix) + _kmt(so.stiffness_matrix)
    notes = tuple(f"inner: {n}" for n in si.notes) + tuple(f"outer: {n}" for n in so.notes)
    return RacewaySolution(
        force=float(F), deflection=float(si.depth + so.depth), stiffness=float(k),
        depth_inner=float(si.depth), depth_outer=float(so.depth),
        stiffness_inner=float(si.stiffness), stiffness_outer=float(so.stiffness),
        peak_pressure_inner=si.p_max, peak_pressure_outer=so.p_max,
        radius_inner=float(R_in), radius_outer=float(R_out), clearance=clearance,
        tilt=float(si.tilt), misalignment=float(psi),
        moment=0.0 if free else float(si.moment - so.moment),
        moment_inner=float(si.moment), moment_outer=float(so.moment),
        tilt_stiffness=float(tks), free_tilt=free, inner=si, outer=so,
        model=f"{model} ({si.method}, {si.n_slices} slices)", notes=notes)


def _in_series(k1, k2):
    """Stiffness of two springs in series, 1/(1/k1 + 1/k2) [N/m]: the roller's inner and
    outer contacts carry the same load and their approaches add."""
    return 1.0 / (1.0 / k1 + 1.0 / k2)


def _series_stiffness(si, so, free):
    """dF/d delta of the roller: contacts in series at fixed tilt, or with the tilt
    free (moment balance kept: dM_in = dM_out, d theta_out = -d theta_in)."""
    Ki, Ko = si.stiffness_matrix, so.stiffness_matrix
    if not free:
        return _in_series(Ki[0, 0], Ko[0, 0])
    # unknowns (dd_in, dd_out, dtheta) for dF = 1
    A = np.array([[Ki[0, 0], 0.0, Ki[0, 1]],
                  [0.0, Ko[0, 0], -Ko[0, 1]],
                  [Ki[1, 0], -Ko[1, 0], Ki[1, 1] + Ko[1, 1]]])
    dd_in, dd_out, _ = np.linalg.solve(A, [1.0, 1.0, 0.0])
    return 1.0 / (dd_in + dd_out)
