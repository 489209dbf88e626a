r"""The radial bearing's solvers: :class:`RadialRollerBearing` (the load distribution
over the rollers, the ring's equilibrium and stiffness: under a law, tabulated slices, or
tilted rollers) and :class:`BearingSolution`; the method is the package docstring's,
:mod:`linecontact.bearing`.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from .._numerics import serial_blas
from ..models import DEFAULT_SLICE_MODEL, SLICE_MODELS
from ..profiles import TILT_RANGE
from ..raceway import (Raceways, _contacts_solution, _in_series, effective_radii,
                       roller_between_raceways)
from ..errors import CombinationError, OutOfRangeError, UnknownNameError
from ..checks import Interval, check_interval, check_positive
from .interpolant import _Law
from .lubrication import (_ALPHA_HINT, _DENSITY_HINT, _VISCOSITY_HINT, DEFAULT_FILM_FORMULA,
                          DENSITY, FILM_FORMULAS, KINEMATIC_VISCOSITY, PRESSURE_VISCOSITY)
from .ratings import (_fits, _rollers, basic_rating_life, dynamic_load_rating,
                      reference_rating_life, static_load_rating)

__all__ = [
    "RadialRollerBearing",
    "BearingSolution",
    "load_zone_integral",
    "GRID_POINTS",
    "PROFILED_POINTS",
    "MAX_SLICES",
    "SLICE_COUNT",
]

#: Points of the roller-law grid of a straight roller under a law [-].
GRID_POINTS = 160
#: Tabulated loads of a profiled roller (coupled slices) [-].
PROFILED_POINTS = 14
#: Most slices per roller of a bearing [-]. The bearing solves each contact at
#: PROFILED_POINTS depths, so its cost grows with the slice solver's (about n^3):
#: measured for a 14-roller ISO-profiled bearing (d_m 65 mm, D 11 mm, L 12 mm) at
#: 10 kN on 2 shared CPU cores: 50 slices 0.3-0.5 s, 100 0.4-0.6 s, 200 2-3.5 s, 400
#: 24-44 s (and numpy's overflow warning from the solver's matmul), 1000 beyond 5 min;
#: at 200 the displacement is within 5e-7 and the most loaded roller within 1.3e-6 of
#: 400 slices' (50: 6.5e-5 and 1.4e-5), so more slices buy nothing measurable.
MAX_SLICES = 200
#: The slice counts a bearing accepts (an integer in it) [-].
SLICE_COUNT = Interval("n_slices", 10, MAX_SLICES, False, False, "")
#: Laminae for the rating life of a roller under a law (uniform line load) [-].
LAMINAE = 20
#: Upper bound of any roller load in units of F_r for Z >= 3: one roller at
#: |psi| <= pi/Z alone carries at most F_r/cos(pi/Z) <= 2 F_r.
_TOP = 2.05


@functools.lru_cache(maxsize=1)
def _load_zone_rule():
    """The load-zone integral's 400-point Gauss-Legendre rule on [0, 1], computed on
    first use and kept (numpy's leggauss solves a 400 x 400 eigenproblem: tens of ms
    per call, over a second on a loaded machine)."""
    t, w = np.polynomial.legendre.leggauss(400)
    t, w = 0.5 * (t + 1.0), 0.5 * w
    t.flags.writeable = w.flags.writeable = False      # shared by every call
    return t, w


def load_zone_integral(epsilon, exponent=10 / 9):
    r"""Stribeck's radial load-zone integral J_r(epsilon) (Harris and Kotzalas 2007).

    .. math::

        J_r(\varepsilon) = \frac{1}{2\pi}\int_{-\psi_l}^{\psi_l}
        \left[1 - \frac{1 - \cos\psi}{2\varepsilon}\right]^n\cos\psi\,d\psi,
        \qquad \cos\psi_l = 1 - 2\varepsilon \ (\varepsilon \le 1)

    Parameters
    ----------
    epsilon : float
        Load-zone parameter eps = (1 - P_d/(2 delta_r))/2, 0 < eps <= 1 [-] (0.5: zero
        clearance, half the bearing loaded).
    exponent : float, optional
        Load-deflection exponent n of Q = K delta^n, 1 <= n <= 2 [-] (10/9 for line
        contact, default).

    Returns
    -------
    float
        J_r [-]; Q_max = F_r / (Z J_r) for many rollers.

    Notes
    -----
    Valid for 0 < eps <= 1, 1 <= n <= 2 (load zone at most the full circle). Computed
    by Gauss-Legendre quadrature in u = (1 - cos psi)/(2 eps) with the endpoint
    singularity removed (400 points; relative error < 1e-8, 1e-12 for eps <= 0.5).

    Examples
    --------
    >>> f"{load_zone_integral(0.5):.4f}", f"{1 / load_zone_integral(0.5):.3f}"
    ('0.2448', '4.085')

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007), the
       load-distribution integral J_r(epsilon).
    """
    eps = float(check_interval("epsilon", epsilon, 0.0, 1.0, low_open=True))
    n = float(check_interval("exponent", exponent, 1.0, 2.0))
    # psi = arccos(1 - 2 eps t^2)... substitute cos psi = 1 - 2 eps s, s in [0, 1]:
    # dpsi = 2 eps ds / sin psi; sin psi = sqrt(4 eps s (1 - eps s)); s = t^2 removes
    # the 1/sqrt(s) singularity: ds = 2 t dt.
    t, w = _load_zone_rule()
    s = t * t
    cos = 1.0 - 2.0 * eps * s
    integrand = (1.0 - s) ** n * cos * 2.0 * eps * 2.0 * t / np.sqrt(
        4.0 * eps * s * (1.0 - eps * s))
    return float(2.0 * np.sum(w * integrand) / (2.0 * math.pi))


def _laminae(sol, length, n):
    """Lamina loads [N] of a slice solution on n equal laminae over the roller length:
    the slices' cumulative load (each slice's q_k w spread evenly over its width)
    interpolated at the lamina boundaries, so that the total load is kept."""
    x = np.asarray(sol.x, dtype=float)
    q = np.asarray(sol.q, dtype=float)
    if getattr(sol, "width", None) is not None:      # the slices' own (graded) widths
        w = np.asarray(sol.width, dtype=float)
    else:
        w = np.full(x.shape, float(x[1] - x[0]) if len(x) > 1 else length)
    edges = np.concatenate([x - w / 2, [x[-1] + w[-1] / 2]])
    cum = np.concatenate([[0.0], np.cumsum(q * w)])
    return np.diff(np.interp(np.linspace(-length / 2, length / 2, n + 1), edges, cum))


def _one_roller(sol, i):
    """Roller i of a :class:`~linecontact.raceway.RacewaySolution` solved for several
    loads under a law (its per-load entries taken at i): that roller's own solve."""
    from dataclasses import fields, replace

    per_load = {f.name: getattr(sol, f.name) for f in fields(sol)}
    return replace(sol, **{k: float(v[i]) for k, v in per_load.items()
                           if isinstance(v, np.ndarray) and v.ndim == 1})


def _ring_step(c, w, k, r, e):
    """One Newton step of the ring equilibrium on (Q_j, delta_r), the rollers' law
    linearised: delta(Q_j + dQ_j) = (delta_r + d delta_r) c_j - P_d/2 and
    sum w_j (Q_j + dQ_j) c_j = F_r, for the residuals r_j = delta(Q_j) - (delta_r c_j -
    P_d/2), e = F_r - sum w_j Q_j c_j (c_j = cos psi_j, w_j rollers alike, k_j =
    dQ/d delta): (d delta_r, dQ_j)."""
    ddr = (e + float(np.sum(w * k * c * r))) / float(np.sum(w * k * c ** 2))
    return ddr, k * (c * ddr - r)


@dataclass(frozen=True)
class BearingSolution:
    """The loaded bearing: roller loads, ring displacement, load zone, stiffness, life.

    Returned by :meth:`RadialRollerBearing.solve`; not built by hand.

    Parameters
    ----------
    radial_load : float
        Applied radial load F_r [N].
    displacement : float
        Radial displacement delta_r of the inner ring along the load [m].
    azimuth : ndarray
        Roller azimuths psi_j from the load line [rad].
    approach : ndarray
        Ring approach delta_j at each roller (negative: a gap) [m].
    roller_loads : ndarray
        Q_j of each roller (0 when unloaded) [N].
    roller_stiffness : ndarray
        dQ/d delta of each roller (0 when unloaded) [N/m].
    stiffness : ndarray
        Bearing stiffness matrix: [[K_rr]] = dF_r/d delta_r [N/m] under a law; under a
        slice model the 2x2 d(F_r, M)/d(delta_r, theta), [[K_rr, K_rt], [K_tr, K_tt]]
        [N/m, N/rad; N, N m/rad].
    max_roller_load : float
        Largest Q_j [N].
    load_zone : float
        Load-zone half angle psi_l, where delta_j = 0 (pi: every roller loaded) [rad].
    epsilon : float
        Load-zone parameter (1 - P_d/(2 delta_r))/2 [-].
    peak_pressure : float
        Peak contact pressure at the most loaded roller, the larger of its two contacts
        (Hertz p0 of the strip for a law; the slice model's peak for a profiled roller,
        nan where edge loaded) [Pa].
    slice_x : ndarray
        Lamina centres along the roller [m].
    slice_loads_inner, slice_loads_outer : ndarray
        Lamina loads of each roller's inner and outer contact, shape (Z, n_s) [N].
    rating : float
        Basic dynamic load rating C_r used for the lives [N].
    life_iso281 : float
        ISO 281 basic rating life (C_r/F_r)^(10/3) [-] (10^6 revolutions).
    life_iso16281 : float
        ISO 16281 basic reference rating life L10r [-] (10^6 revolutions).
    law_error : float
        Largest relative error of the roller law at the roller loads, |delta(Q_j) -
        delta_j| / delta(Q_j) [-]: after the exact polish of the tabulated law, 0 for
        a law (exact to round-off) and the polish's remaining residual for a slice
        model (below 1e-9: the slice solves converge to 1e-10 in force); 0 under a
        tilt (each roller solved exactly).
    model : str
        The contact law or slice model.
    notes : tuple of str
        What the user should know about this solution.
    moment : float
        Tilting moment M = sum M_j cos psi_j on the inner ring (the applied one, or the
        one a given misalignment needs) [N m].
    tilt : float
        Tilt theta of the inner ring against the outer ring in the load plane [rad].
    roller_moments : ndarray
        Moment M_j of each roller's inner-contact load about the roller's centre [N m].
    roller_tilts : ndarray
        Each roller's tilt against the inner ring (free: its moments balance) [rad].
    roller_misalignment : ndarray
        The rings' relative tilt at each roller, theta cos psi_j [rad].
    stress : dict
        Subsurface stress maxima at the most loaded roller, worst of its two contacts,
        per measure (``"tresca"``, ``"von_mises"``, ``"orthogonal_shear"``): value [Pa],
        depth [m], x along the roller [m], contact (:mod:`linecontact.stresses`, no
        traction); and ``withheld``, the reason, where an edge-loaded contact makes the
        maximum a slice-width number (not converged: report "-").
    clearance : float
        Operating radial clearance the load distribution used: the given one after the
        fits and the ring temperature difference (:mod:`linecontact.bearing.fits`) [m].
    clearance_changes : dict or None
        With fits or a temperature difference: the clearance before mounting
        (``"unmounted"``) and its changes ``"inner_fit"``, ``"outer_fit"``,
        ``"thermal"`` (negative: the clearance shrinks) [m].
    static_rating : float
        Basic static load rating C0r (ISO 76, or the one given) [N].
    static_load : float
        Static equivalent load P0r = F_r (ISO 76, contact angle 0) [N].
    static_safety : float
        s0 = C0r/P0r [-].
    pressure_safety : float
        Stress-based static safety (4000 MPa/p_max)^2 from :attr:`peak_pressure`,
        edge stresses included (nan where the peak is not reported) [-].
    roller_damage : ndarray
        Share of the bearing's ISO 16281 damage taken at each roller's position,
        summing to 1 (:func:`linecontact.bearing.ratings.roller_damage_shares`) [-].
    speed : float or None
        Speed of the inner ring against the outer ring [rad/s] (None: not given).
    entrainment_speed : float or None
        Mean rolling speed u of both contacts in pure rolling [m/s].
    film_minimum_inner, film_minimum_outer : ndarray or None
        Minimum EHL film h_min of each roller's inner and outer contact on each lamina
        (:attr:`slice_x`), shape (Z, n_s), by :attr:`film_formula`; inf where the
        lamina carries no load [m].
    film_central_inner, film_central_outer : ndarray or None
        Central EHL film h_c, Pan & Hamrock (1989), shape (Z, n_s); inf where unloaded
        [m].
    film_ratio_inner, film_ratio_outer : ndarray or None
        Film ratio Lambda of each roller's inner and outer contact, its smallest over
        the laminae (inf: unloaded) [-].
    film_ratio : float or None
        The smallest Lambda of the bearing [-].
    film_formula : str or None
        The minimum-film formula used (:data:`linecontact.bearing.lubrication.FILM_FORMULAS`).
    rated_viscosity : float or None
        nu1 of ISO 281 at the speed and pitch diameter [m^2/s].
    kappa : float or None
        Viscosity ratio nu/nu1 [-].
    fatigue_load_limit : float or None
        C_u used for a_ISO [N].
    reliability_factor : float or None
        a1 [-].
    life_modification : float or None
        a_ISO at P = F_r [-].
    life_modified : float or None
        L_nm = a1 a_ISO L10 (ISO 281) [-] (10^6 revolutions).
    reference_load : float or None
        Dynamic equivalent reference load P_ref = C_r L10r^(-3/10) [N].
    life_modification_reference : float or None
        a_ISO at P_ref [-].
    life_modified_reference : float or None
        ISO 16281's modified reference rating life L_nmr = a1 a_ISO(P_ref) L10r [-]
        (10^6 revolutions).
    axial_load : float or None
        Axial load F_a on the flanges [N].
    flange_forces : ndarray or None
        Axial force F_a,j each roller passes between its flanges, summing to F_a [N].
    flange_normal_forces : ndarray or None
        Normal force F_a,j / cos(theta) of each of the roller's two flange contacts [N].
    flange_pressure_inner, flange_pressure_outer : ndarray or None
        Hertz peak pressure of each roller's inner-ring and outer-ring flange contact
        [Pa].
    flange_rim_margin : ndarray or None
        Smaller distance of the two contact ellipses to their flange rims (negative:
        over the rim) [m].
    flange_couple : ndarray or None
        Couple F_a,j tan(theta)(2 R_e - l) of each roller's two flange forces [N m].
    flange_load_offset : ndarray or None
        Shift M/(2 Q_j) of each raceway contact's load centre along the roller that
        balances the couple (0 where unloaded); beyond L/6 a rigid roller's line load
        would lift at one end [m].
    roller : RacewaySolution
        The most loaded roller between its raceways at its load
        (:class:`~linecontact.raceway.RacewaySolution`): the exact solve its approach,
        tilt, moment, peak pressure and stresses come from, the same solve as
        :func:`~linecontact.raceway.roller_between_raceways` at Q_max (free to tilt,
        the rings misaligned by theta cos psi_j at its azimuth). Not in
        :meth:`to_dict`.
    roller_stresses : RacewayStresses
        The subsurface stresses of that roller's two contacts, ``"inner"`` and
        ``"outer"`` (:class:`~linecontact.stresses.RacewayStresses`, a mapping to each
        one's :class:`~linecontact.stresses.SubsurfaceStresses`, no traction): the
        fields `stress` summarises; its ``case_check`` is the case check over both.
        Not in :meth:`to_dict`.

    Notes
    -----
    Valid as the bearing it comes from (:class:`RadialRollerBearing`).

    Examples
    --------
    >>> s = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3).solve(10e3)
    >>> f"{s.max_roller_load / 1e3:.3f} kN, K = {s.stiffness[0, 0] / 1e6:.0f} N/um"
    '2.914 kN, K = 715 N/um'
    """

    radial_load: float
    displacement: float
    azimuth: np.ndarray
    approach: np.ndarray
    roller_loads: np.ndarray
    roller_stiffness: np.ndarray
    stiffness: np.ndarray
    max_roller_load: float
    load_zone: float
    epsilon: float
    peak_pressure: float
    slice_x: np.ndarray
    slice_loads_inner: np.ndarray
    slice_loads_outer: np.ndarray
    rating: float
    life_iso281: float
    life_iso16281: float
    law_error: float
    model: str
    notes: tuple = field(default_factory=tuple)
    moment: float = 0.0
    tilt: float = 0.0
    roller_moments: np.ndarray = None
    roller_tilts: np.ndarray = None
    roller_misalignment: np.ndarray = None
    stress: dict = None
    clearance: float = None
    clearance_changes: dict = None
    static_rating: float = None
    static_load: float = None
    static_safety: float = None
    pressure_safety: float = None
    roller_damage: np.ndarray = None
    speed: float = None
    entrainment_speed: float = None
    film_minimum_inner: np.ndarray = None
    film_minimum_outer: np.ndarray = None
    film_central_inner: np.ndarray = None
    film_central_outer: np.ndarray = None
    film_ratio_inner: np.ndarray = None
    film_ratio_outer: np.ndarray = None
    film_ratio: float = None
    film_formula: str = None
    rated_viscosity: float = None
    kappa: float = None
    fatigue_load_limit: float = None
    reliability_factor: float = None
    life_modification: float = None
    life_modified: float = None
    reference_load: float = None
    life_modification_reference: float = None
    life_modified_reference: float = None
    axial_load: float = None
    flange_forces: np.ndarray = None
    flange_normal_forces: np.ndarray = None
    flange_pressure_inner: np.ndarray = None
    flange_pressure_outer: np.ndarray = None
    flange_rim_margin: np.ndarray = None
    flange_couple: np.ndarray = None
    flange_load_offset: np.ndarray = None
    roller: object = None
    roller_stresses: object = None

    def to_dict(self):
        """The solution as plain Python (lists for arrays), SI units (the solve objects
        `roller` and `roller_stresses` left out)."""
        out = {}
        for k, v in self.__dict__.items():
            if k in ("roller", "roller_stresses"):
                continue
            if isinstance(v, np.ndarray):
                v = v.tolist()
            elif isinstance(v, tuple):
                v = list(v)
            out[k] = v
        return out


class RadialRollerBearing:
    r"""A radial cylindrical or needle roller bearing: geometry, material, contact law.

    Parameters
    ----------
    rollers : int
        Number of rollers Z, 3 <= Z, that fit on the pitch circle without overlapping
        (d_m sin(pi/Z) > D; :func:`~linecontact.bearing.ratings.max_rollers`) [-].
    pitch_diameter : float
        Pitch diameter d_m > D [m].
    roller_diameter : float
        Roller diameter D, 0 < D < d_m [m].
    length : float
        Effective roller length L, 0 < L < inf [m].
    clearance : float, optional
        Radial internal clearance P_d = d_o - d_i - 2 D, -D < P_d < D [m] (default 0;
        negative: preload).
    estar : float, optional
        Effective modulus E* of roller and rings (Li & Popov 2017, Eq. 3), 0 < E* < inf
        [Pa] (default 115.38 GPa, steel on steel).
    model : str or None, optional
        Contact law of each contact (a key of
        :func:`linecontact.models.available_models`): None gives ``"universal"`` for a
        straight roller and ``"profiled-roller"`` (coupled slices) for a profiled one;
        ``"iso16281"`` is the ISO/TS 16281 spring.
    profile : str or Profile or None, optional
        The rollers' axial profile (:mod:`linecontact.profiles`); None: straight.
    n_slices : int, optional
        Slices of the slice model, an integer 10 <= n <= MAX_SLICES = 200 (ISO
        slicing: n >= 30; converged long before, see MAX_SLICES) [-]
        (default None: the model's, as in every other door,
        :func:`linecontact.roller.solvers.default_n_slices`: 50 coupled slices, 30 ISO
        slicing; the laminae of the rating life of a sliced roller are as many).
    azimuth0 : float, optional
        Azimuth psi_0 of the first roller from the load line, |psi_0| <= pi [rad]
        (default 0: a roller under the load).
    rating : float or None, optional
        Basic dynamic load rating C_r, 0 < C_r < inf [N] (default: ISO 281 from the
        geometry, :func:`dynamic_load_rating`).
    rotating : str, optional
        The ring rotating against the load, ``"inner"`` (default) or ``"outer"``.
    poisson : float, optional
        Poisson's ratio of the rings for the von Mises stress, 0 <= nu <= 0.5 [-]
        (default 0.3, steel; the Tresca and orthogonal shear do not depend on it).
    viscosity : float, optional
        Kinematic viscosity nu of the lubricant at the operating temperature,
        0 < nu < inf [m^2/s]: with a speed (:meth:`solve`), kappa = nu/nu1.
    density : float, optional
        Density rho of the lubricant, 0 < rho < inf [kg/m^3]: the film's dynamic
        viscosity eta0 = rho nu (with `pressure_viscosity`).
    pressure_viscosity : float, optional
        Pressure-viscosity coefficient alpha of the lubricant, 0 < alpha <= 1e-7 [1/Pa]:
        with `viscosity`, `density` and a speed, the EHL film of every contact.
    roughness_roller, roughness_raceway : float, optional
        RMS roughness Rq of the rollers and of the raceways, 0 <= Rq < inf [m]: the
        film ratio Lambda (both, with the film inputs).
    film_formula : str, optional
        Minimum-film formula, ``"pan-hamrock"`` (default) or ``"dowson-higginson"``
        (:data:`linecontact.bearing.lubrication.FILM_FORMULAS`); the central film is
        Pan & Hamrock's.
    contamination : float, optional
        Contamination factor e_C, 0 <= e_C <= 1 [-]: with `viscosity`, the modified
        lives L_nm (ISO 281) and L_nmr (ISO 16281).
    reliability : float, optional
        Reliability of the modified lives, 0.9 <= R <= 0.9995 [-] (default 0.9,
        a1 = 1; with `contamination`).
    fatigue_load_limit : float, optional
        Fatigue load limit C_u, 0 < C_u < inf [N] (default: ISO 281's estimate from
        C0r, :func:`linecontact.bearing.ratings.fatigue_load_limit`; with
        `contamination`).
    static_rating : float, optional
        Basic static load rating C0r, 0 < C0r < inf [N] (default: ISO 76 from the
        geometry, :func:`linecontact.bearing.ratings.static_load_rating`).
    shaft_interference : float, optional
        Effective diametral interference of the inner ring on the shaft,
        0 <= I < inf [m] (with `bore`): the inner raceway grows (Lame).
    bore : float, optional
        Bore d of the inner ring (the shaft seat), 0 < d < d_m - D [m].
    shaft_bore : float, optional
        Bore of a hollow shaft, 0 <= d_s < d (default 0: solid) [m].
    housing_interference : float, optional
        Effective diametral interference of the outer ring in the housing,
        0 <= I < inf [m] (with `outside_diameter`): the outer raceway shrinks.
    outside_diameter : float, optional
        Outside diameter of the outer ring (the housing seat), d_m + D + P_d < D_o <
        inf [m].
    housing_diameter : float, optional
        Outside diameter of the housing, D_o < D_h <= inf (default inf: massive) [m].
    ring_modulus : float, optional
        Young's modulus of the rings, the shaft and the housing for the fits,
        0 < E < inf (default 2 E* (1 - nu^2) from `estar` and `poisson`: rollers and
        rings of one material) [Pa].
    temperature_difference : float, optional
        Temperature of the inner ring above the outer ring's, the rollers at their
        mean, -inf < dT < inf [K]: the clearance changes by -12e-6/K dT d_m (steel).
    end_radius : float, optional
        Radius R_e of the rollers' spherical ends, 0 < R_e < inf [m]; with
        `flange_angle` and the flange heights, the flanges of an NJ / NUP bearing that
        carry an axial load (:meth:`solve`'s `axial_load`).
    flange_angle : float, optional
        Inclination theta of the flange faces to the radial plane, 0 < theta < pi/4
        [rad].
    inner_flange_height, outer_flange_height : float, optional
        Heights of the inner and the outer ring's flanges above their raceways,
        0 < h < D/2 [m].
    overall_length : float, optional
        The rollers' overall length l between their end vertices, 0 < l < inf
        (default: `length`) [m].
    end_chamfer : float, optional
        Radial extent of the roller's corner beyond which its end is not spherical,
        0 <= c < D/2 (default 0) [m].
    axial_share : str, optional
        How the rollers share the axial load: ``"proportional"`` to their radial loads
        (default) or ``"equal"`` (:func:`linecontact.bearing.flanges.axial_load_shares`).

    Notes
    -----
    Valid for 3 <= Z <= max_rollers(d_m, D), 0 < D < d_m, |P_d| < D, within the
    contact law's range (its
    depth and L/R ranges; the universal curve to d <= 0.15 R). Centrifugal forces,
    ring deformation and roller skew are not modelled. The fits take the rings, the
    shaft and the housing of one material, E = 2 E* (1 - nu^2) from `estar` and
    `poisson` (210 GPa for the defaults) unless `ring_modulus` is given, Poisson's
    ratio `poisson`, each ring a cylinder from bore to raceway;
    the load distribution uses the operating clearance (:attr:`clearance`; the given
    one is :attr:`internal_clearance`). Each input group is all or nothing: an input
    that a missing partner would leave unused is refused (docs/bearing_life.md).

    Examples
    --------
    Stribeck's zero-clearance result with the ISO spring law (Z Q_max/F_r -> 1/J_r(0.5)
    = 4.085 for many rollers):

    >>> b = RadialRollerBearing(40, 200e-3, 10e-3, 10e-3, model="iso16281")
    >>> s = b.solve(20e3)
    >>> f"{40 * s.max_roller_load / 20e3:.3f}", f"{s.load_zone:.4f} rad"
    ('4.085', '1.5708 rad')

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007).
    .. [2] ISO 16281:2025, Rolling bearings - Methods for calculating the modified
       reference rating life for universally loaded rolling bearings.
    """

    def __init__(self, rollers, pitch_diameter, roller_diameter, length, clearance=0.0,
                 *, estar=115.38e9, model=None, profile=None, n_slices=None,
                 azimuth0=0.0, rating=None, rotating="inner", poisson=0.3,
                 viscosity=None, density=None, pressure_viscosity=None,
                 roughness_roller=None, roughness_raceway=None,
                 film_formula=DEFAULT_FILM_FORMULA, contamination=None, reliability=None,
                 fatigue_load_limit=None, static_rating=None, shaft_interference=None,
                 bore=None, shaft_bore=None, housing_interference=None,
                 outside_diameter=None, housing_diameter=None, ring_modulus=None,
                 temperature_difference=None, end_radius=None, flange_angle=None,
                 inner_flange_height=None, outer_flange_height=None,
                 overall_length=None, end_chamfer=None, axial_share="proportional"):
        from ..models import available_models
        from ..profiles import StraightProfile, as_profile

        self.rollers = _rollers(rollers)
        self.pitch_diameter = float(check_positive("pitch_diameter", pitch_diameter, "m"))
        self.roller_diameter = float(check_positive("roller_diameter", roller_diameter,
                                                    "m"))
        _fits(self.pitch_diameter, self.roller_diameter, self.rollers)
        self.length = float(check_positive("length", length, "m"))
        D = self.roller_diameter
        self.clearance = float(check_interval(
            "clearance", clearance, -D, D, low_open=True, high_open=True, unit="m",
            hint="the clearance must be smaller than the roller diameter"))
        self.estar = float(check_positive("estar", estar, "Pa"))
        if n_slices is not None:
            n = check_interval("n_slices", n_slices, 10, MAX_SLICES,
                               hint="more slices change no result measurably and cost "
                                    "minutes (MAX_SLICES)").item()
            if n != int(n):
                raise OutOfRangeError("n_slices", n, f"[10, {MAX_SLICES}], an integer",
                                      hint="a slice count is never rounded")
            n_slices = int(n)
        self.azimuth0 = float(check_interval("azimuth0", azimuth0, -math.pi, math.pi,
                                             unit="rad"))
        if rotating not in ("inner", "outer"):
            raise UnknownNameError("rotating", rotating, ["inner", "outer"])
        self.rotating = rotating
        self.poisson = float(check_interval("poisson", poisson, 0.0, 0.5))
        self.internal_clearance = self.clearance
        self.clearance_changes = self._mounting(
            shaft_interference, bore, shaft_bore, housing_interference,
            outside_diameter, housing_diameter, temperature_difference, ring_modulus)
        self.lubricant = self._lubricant(viscosity, density, pressure_viscosity,
                                         roughness_roller, roughness_raceway,
                                         film_formula, contamination, reliability,
                                         fatigue_load_limit)
        self.flanges = self._flange_geometry(end_radius, flange_angle,
                                             inner_flange_height, outer_flange_height,
                                             overall_length, end_chamfer, axial_share)
        self._model_named = model is not None
        R1 = D / 2
        self.profile = as_profile(profile, R1, self.length, self.estar)
        straight = isinstance(self.profile, StraightProfile)
        if model is None:
            model = "universal" if straight else DEFAULT_SLICE_MODEL
        if model not in available_models():
            raise UnknownNameError("model", model, available_models())
        if not straight and model not in SLICE_MODELS:
            raise CombinationError({"model": model, "profile": self.profile.label},
                                   "a straight-cylinder law has no profile; use "
                                   "model='profiled-roller' (coupled slices)")
        self.model = model
        self.sliced = model in SLICE_MODELS
        # the slice count of the slice model solving the rollers (a law's tilted twin:
        # the default slice model's)
        from ..roller.solvers import default_n_slices

        self.n_slices = (default_n_slices(model if self.sliced else DEFAULT_SLICE_MODEL)
                         if n_slices is None else n_slices)
        # raceways: the inner one at (d_m - D)/2; the outer one leaves P_d/2 per side
        self.raceways = Raceways(inner=(self.pitch_diameter - D) / 2,
                                 outer=(self.pitch_diameter + D) / 2 + self.clearance / 2,
                                 fit_tolerance=0.4999)
        self.rating = (dynamic_load_rating(self.rollers, self.pitch_diameter, D,
                                           self.length) if rating is None
                       else float(check_positive("rating", rating, "N")))
        self.azimuth = (self.azimuth0 + 2 * math.pi * np.arange(self.rollers)
                        / self.rollers)
        self.azimuth = (self.azimuth + math.pi) % (2 * math.pi) - math.pi
        self.static_rating = (
            static_load_rating(self.rollers, self.pitch_diameter, D, self.length)
            if static_rating is None
            else float(check_positive("static_rating", static_rating, "N")))
        if self.lubricant and self.lubricant["contamination"] is not None:
            from .ratings import fatigue_load_limit as _cu

            given = self.lubricant["fatigue_load_limit"]
            self.lubricant["fatigue_load_limit"] = (
                float(_cu(self.static_rating, self.pitch_diameter)) if given is None
                else float(check_positive("fatigue_load_limit", given, "N")))

    # -- mounting, lubricant, flanges (the inputs beyond the load distribution) -----
    @staticmethod
    def _needs(given, partners, reason, values=None):
        """Refuse an input group given in part: when any input of `given` (name ->
        value) is not None, every name of `partners` must be given in `values`
        (default `given`)."""
        values = given if values is None else values
        named = {k: v for k, v in given.items() if v is not None}
        missing = [k for k in partners if values.get(k) is None]
        if named and missing:
            raise CombinationError({**named, **{k: None for k in missing}}, reason)

    def _mounting(self, shaft_interference, bore, shaft_bore, housing_interference,
                  outside_diameter, housing_diameter, temperature_difference,
                  ring_modulus=None):
        """The operating clearance from the fits (Lame) and the rings' temperature
        difference, set as self.clearance; returns the changes (None: none given)."""
        from .fits import (inner_raceway_expansion, operating_clearance,
                           outer_raceway_contraction, thermal_clearance_change)

        shaft = {"shaft_interference": shaft_interference, "bore": bore,
                 "shaft_bore": shaft_bore}
        housing = {"housing_interference": housing_interference,
                   "outside_diameter": outside_diameter,
                   "housing_diameter": housing_diameter}
        self._needs(shaft, ("shaft_interference", "bore"), "an inner-ring fit needs "
                    "the interference and the ring's bore")
        self._needs(housing, ("housing_interference", "outside_diameter"), "an "
                    "outer-ring fit needs the interference and the ring's outside "
                    "diameter")
        if ring_modulus is not None and shaft_interference is None \
                and housing_interference is None:
            raise CombinationError({"ring_modulus": ring_modulus,
                                    "shaft_interference": None,
                                    "housing_interference": None},
                                   "the rings' modulus is used by a fit only")
        if (shaft_interference is None and housing_interference is None
                and temperature_difference is None):
            return None
        dm, D, Pd = self.pitch_diameter, self.roller_diameter, self.clearance
        E = (2.0 * self.estar * (1.0 - self.poisson ** 2) if ring_modulus is None
             else float(check_positive("ring_modulus", ring_modulus, "Pa")))
        nu = self.poisson
        d_in, d_out = dm - D, dm + D + Pd          # raceway diameters
        grow = shrink = heat = 0.0
        if shaft_interference is not None:
            d = float(check_interval("bore", bore, 0.0, d_in, low_open=True,
                                     high_open=True, unit="m",
                                     hint="the bore lies inside the inner raceway "
                                          "(d_m - D)"))
            ds = 0.0 if shaft_bore is None else float(check_interval(
                "shaft_bore", shaft_bore, 0.0, d, high_open=True, unit="m",
                hint="a hollow shaft's bore is smaller than the ring's bore"))
            grow = float(inner_raceway_expansion(shaft_interference, d, d_in, E, nu,
                                                 shaft_bore=ds))
        if housing_interference is not None:
            Do = float(check_interval("outside_diameter", outside_diameter, d_out,
                                      np.inf, low_open=True, high_open=True, unit="m",
                                      hint="the outer ring's outside lies beyond its "
                                           "raceway (d_m + D + P_d)"))
            Dh = np.inf if housing_diameter is None else float(check_interval(
                "housing_diameter", housing_diameter, Do, np.inf, low_open=True,
                unit="m", hint="the housing's outside lies beyond the ring's"))
            shrink = float(outer_raceway_contraction(housing_interference, Do, d_out,
                                                     E, nu, housing_diameter=Dh))
        if temperature_difference is not None:
            heat = float(thermal_clearance_change(d_in, d_out, D,
                                                  temperature_difference, 0.0))
        op = float(operating_clearance(Pd, grow, shrink, heat))
        self.clearance = float(check_interval(
            "operating clearance", op, -D, D, low_open=True, high_open=True, unit="m",
            hint="the fits and temperatures leave a clearance beyond the roller "
                 "diameter"))
        return {"unmounted": Pd, "inner_fit": 0.0 - grow, "outer_fit": 0.0 - shrink,
                "thermal": heat}

    def _lubricant(self, viscosity, density, pressure_viscosity, roughness_roller,
                   roughness_raceway, film_formula, contamination, reliability,
                   fatigue_load_limit):
        """The lubricant, surfaces and life-modification inputs, checked (None: none
        given)."""
        given = {"viscosity": viscosity, "density": density,
                 "pressure_viscosity": pressure_viscosity,
                 "roughness_roller": roughness_roller,
                 "roughness_raceway": roughness_raceway,
                 "contamination": contamination, "reliability": reliability,
                 "fatigue_load_limit": fatigue_load_limit}
        if film_formula not in FILM_FORMULAS:
            raise UnknownNameError("film_formula", film_formula, list(FILM_FORMULAS))
        film = ("viscosity", "density", "pressure_viscosity")
        self._needs({k: given[k] for k in film[1:]}, film, "the EHL film needs the "
                    "viscosity, the density (eta0 = rho nu) and the pressure-viscosity "
                    "coefficient", given)
        self._needs({k: given[k] for k in ("roughness_roller", "roughness_raceway")},
                    film + ("roughness_roller", "roughness_raceway"), "the film ratio "
                    "needs both roughnesses and the film inputs", given)
        self._needs({"contamination": contamination}, ("viscosity",), "the modified "
                    "life needs the viscosity ratio kappa: give the viscosity", given)
        self._needs({"reliability": reliability,
                     "fatigue_load_limit": fatigue_load_limit}, ("contamination",),
                    "the modified life (a1, C_u) needs the contamination factor", given)
        if film_formula != DEFAULT_FILM_FORMULA and pressure_viscosity is None:
            raise CombinationError({"film_formula": film_formula,
                                    "pressure_viscosity": None},
                                   "a film formula needs the film inputs")
        if all(v is None for v in given.values()):
            return None
        lub = {"film_formula": film_formula, "fatigue_load_limit": fatigue_load_limit}
        for name, interval, hint in (("viscosity", KINEMATIC_VISCOSITY, _VISCOSITY_HINT),
                                     ("density", DENSITY, _DENSITY_HINT)):
            v = given[name]
            lub[name] = None if v is None else float(interval.check(v, hint=hint))
        lub["pressure_viscosity"] = None if pressure_viscosity is None else float(
            PRESSURE_VISCOSITY.check(pressure_viscosity, hint=_ALPHA_HINT))
        for name in ("roughness_roller", "roughness_raceway"):
            v = given[name]
            lub[name] = None if v is None else float(check_interval(
                name, v, 0.0, np.inf, high_open=True, unit="m"))
        lub["contamination"] = None if contamination is None else float(
            check_interval("contamination", contamination, 0.0, 1.0))
        lub["reliability"] = 0.9 if reliability is None else float(
            check_interval("reliability", reliability, 0.9, 0.9995))
        return lub

    def _flange_geometry(self, end_radius, flange_angle, inner_flange_height,
                         outer_flange_height, overall_length, end_chamfer, axial_share):
        """The flanges of an NJ / NUP bearing, checked once by a zero-force flange
        contact (the contact point on both flange faces); None: none given."""
        from .flanges import SHARE_RULES, flange_contacts

        geo = {"end_radius": end_radius, "flange_angle": flange_angle,
               "inner_flange_height": inner_flange_height,
               "outer_flange_height": outer_flange_height}
        extra = {"overall_length": overall_length, "end_chamfer": end_chamfer}
        self._needs({**geo, **extra}, tuple(geo), "the flanges need the roller end "
                    "radius, the flange angle and both flange heights")
        if axial_share not in SHARE_RULES:
            raise UnknownNameError("axial_share", axial_share, SHARE_RULES)
        if end_radius is None:
            return None
        geo["roller_length"] = self.length if overall_length is None else overall_length
        geo["end_chamfer"] = 0.0 if end_chamfer is None else end_chamfer
        flange_contacts(0.0, self.roller_diameter, geo["roller_length"],
                        self.pitch_diameter, geo["end_radius"], geo["flange_angle"],
                        self.estar, geo["inner_flange_height"],
                        geo["outer_flange_height"], geo["end_chamfer"])
        geo["rule"] = axial_share
        return geo

    def _extras(self, sol, speed, axial_load):
        """The solution with what the load distribution implies: static safety, the
        damage per roller, and, where their inputs are given, the operating clearance's
        origin, the film, kappa, the modified lives and the flange contacts."""
        from dataclasses import replace

        from .ratings import (life_modification_factor, modified_rating_life,
                              modified_reference_rating_life, pressure_safety_factor,
                              reliability_factor, roller_damage_shares,
                              static_equivalent_load, static_safety_factor)

        F = sol.radial_load
        P0 = float(static_equivalent_load(F))
        pp = sol.peak_pressure
        f = dict(clearance=self.clearance, clearance_changes=self.clearance_changes,
                 static_rating=self.static_rating, static_load=P0,
                 static_safety=float(static_safety_factor(self.static_rating, P0)),
                 pressure_safety=(float(pressure_safety_factor(pp))
                                  if math.isfinite(pp) else math.nan),
                 roller_damage=roller_damage_shares(
                     self.rating, self.pitch_diameter, self.roller_diameter,
                     sol.slice_loads_inner, sol.slice_loads_outer, self.rotating))
        notes = list(sol.notes)
        lub = self.lubricant
        if speed is not None:
            f.update(self._film(sol, speed))
            if lub is not None and lub["contamination"] is not None:
                ec, cu = lub["contamination"], lub["fatigue_load_limit"]
                a1 = float(reliability_factor(lub["reliability"]))
                a = float(life_modification_factor(f["kappa"], ec, cu, F))
                ref = modified_reference_rating_life(
                    self.rating, self.pitch_diameter, self.roller_diameter,
                    sol.slice_loads_inner, sol.slice_loads_outer, f["kappa"], ec, cu,
                    lub["reliability"], self.rotating)
                f.update(fatigue_load_limit=cu, reliability_factor=a1,
                         life_modification=a,
                         life_modified=float(modified_rating_life(sol.life_iso281, a,
                                                                  a1)),
                         reference_load=ref.reference_load,
                         life_modification_reference=ref.life_modification,
                         life_modified_reference=ref.life)
        if axial_load is not None:
            f.update(self._flange_solution(sol, axial_load, notes))
        f["notes"] = tuple(notes)
        return replace(sol, **f)

    def _film(self, sol, speed):
        """Entrainment speed; with the lubricant, nu1 and kappa; with the film inputs,
        each lamina's minimum and central film and each contact's Lambda."""
        from .lubrication import (central_film_pan_hamrock, entrainment_speed,
                                  film_ratio, minimum_film_thickness, rated_viscosity)

        w = abs(speed)
        f = dict(speed=float(speed),
                 entrainment_speed=float(entrainment_speed(speed, self.pitch_diameter,
                                                           self.roller_diameter)))
        lub = self.lubricant
        if lub is None or lub["viscosity"] is None:
            return f
        if not w > 0:
            raise OutOfRangeError("speed", speed, "a nonzero speed [rad/s]", unit="rad/s",
                                  hint="the film and kappa need the rings to turn")
        nu1 = float(rated_viscosity(w, self.pitch_diameter))
        f.update(rated_viscosity=nu1, kappa=lub["viscosity"] / nu1)
        if lub["pressure_viscosity"] is None:
            return f
        eta = lub["density"] * lub["viscosity"]
        alpha = lub["pressure_viscosity"]
        width = self.length / sol.slice_loads_inner.shape[1]
        u = f["entrainment_speed"]
        radii = effective_radii(self.roller_diameter / 2, self.raceways.inner,
                                self.raceways.outer)
        for name, R, q in (("inner", radii[0], sol.slice_loads_inner),
                           ("outer", radii[1], sol.slice_loads_outer)):
            line = np.asarray(q, dtype=float) / width
            hmin = np.asarray(minimum_film_thickness(u, R, line, self.estar, eta, alpha,
                                                     formula=lub["film_formula"]))
            f[f"film_minimum_{name}"] = hmin
            f[f"film_central_{name}"] = np.asarray(central_film_pan_hamrock(
                u, R, line, self.estar, eta, alpha))
            if lub["roughness_roller"] is not None:
                lam = np.asarray(film_ratio(hmin, lub["roughness_roller"],
                                            lub["roughness_raceway"]))
                f[f"film_ratio_{name}"] = lam.min(axis=1)
        f["film_formula"] = lub["film_formula"]
        if "film_ratio_inner" in f:
            f["film_ratio"] = float(min(f["film_ratio_inner"].min(),
                                        f["film_ratio_outer"].min()))
        return f

    def _flange_solution(self, sol, axial_load, notes):
        """Each roller's share of the axial load and its two flange contacts
        (uncoupled: from the radial load distribution, which the flange couple does not
        change)."""
        from .flanges import axial_load_shares, flange_contacts

        g = self.flanges
        Fa = float(check_interval("axial_load", axial_load, 0.0, np.inf,
                                  high_open=True, unit="N"))
        if g is None:
            raise CombinationError({"axial_load": Fa, "end_radius": None},
                                   "an axial load needs the flanges (end_radius, "
                                   "flange_angle, inner_flange_height, "
                                   "outer_flange_height)")
        Q = sol.roller_loads
        Faj = axial_load_shares(Fa, Q, g["rule"])
        c = flange_contacts(Faj, self.roller_diameter, g["roller_length"],
                            self.pitch_diameter, g["end_radius"], g["flange_angle"],
                            self.estar, g["inner_flange_height"],
                            g["outer_flange_height"], g["end_chamfer"])
        M = np.asarray(c.tilting_moment, dtype=float)
        offset = np.divide(np.abs(M), 2.0 * Q, out=np.zeros_like(M), where=Q > 0)
        margin = np.minimum(c.inner_rim_margin, c.outer_rim_margin)
        if np.any(offset > self.length / 6):
            notes.append("flange couple: rollers "
                         f"{np.flatnonzero(offset > self.length / 6).tolist()} need "
                         "their raceway loads shifted beyond L/6: their line loads "
                         "lift at one end")
        if np.any(margin < 0):
            notes.append("flange contact ellipses run over the flange rim at rollers "
                         f"{np.flatnonzero(margin < 0).tolist()} (Hertz does not hold)")
        notes.append("flanges: the couple of the flange forces is not fed back into "
                     "the rollers' tilt (the radial load distribution is the "
                     "flange-free one)")
        return dict(axial_load=Fa, flange_forces=np.asarray(Faj, dtype=float),
                    flange_normal_forces=np.asarray(c.normal_force, dtype=float),
                    flange_pressure_inner=np.asarray(c.inner_p0, dtype=float),
                    flange_pressure_outer=np.asarray(c.outer_p0, dtype=float),
                    flange_rim_margin=np.asarray(margin, dtype=float),
                    flange_couple=M, flange_load_offset=offset)

    # -- the roller law -----------------------------------------------------------
    def _law_grid(self, F):
        """delta(Q), k(Q) of a straight roller under a law on a geometric load grid."""
        R1 = self.roller_diameter / 2
        top = _TOP * F
        last = None
        for _ in range(30):
            Q = top * np.logspace(-9, 0, GRID_POINTS)
            try:
                s = roller_between_raceways(R1, self.length, self.estar, self.raceways,
                                            force=Q, model=self.model)
                return Q, np.asarray(s.deflection), np.asarray(s.stiffness), s
            except OutOfRangeError as exc:  # the law's range ends below 2 F_r
                last = exc
                top *= 0.7
        raise last

    def _exact(self, Q):
        R1 = self.roller_diameter / 2
        s = roller_between_raceways(R1, self.length, self.estar, self.raceways,
                                    force=Q, model=self.model)
        return np.asarray(s.deflection), np.asarray(s.stiffness), s

    def _contacts(self):
        """The aligned solves at depth of the inner and the outer contact."""
        return [lambda d, c=c: c.at_depth(d, 0.0) for c in self._solvers()]

    def _solvers(self):
        """The slice solvers of the inner and the outer contact of one roller (fresh:
        each keeps its own warm start), from the factory every door uses
        (:func:`linecontact.roller.solvers.slice_solver`), as
        :func:`~linecontact.raceway.roller_between_raceways` builds them."""
        from ..roller.solvers import slice_solver

        R1 = self.roller_diameter / 2
        return [slice_solver(self.model, R, self.length, self.estar, self.profile,
                             n_slices=self.n_slices)
                for R in effective_radii(R1, self.raceways.inner, self.raceways.outer)]

    @staticmethod
    def _depth_table(at_depth, d_lo, d_top, F_top):
        """One contact at PROFILED_POINTS depths from d_lo up to a depth carrying at
        least F_top (d_top, raised by 1.5 until it does)."""
        top = at_depth(d_top)
        for _ in range(40):
            if top.force >= F_top:
                break
            d_top *= 1.5
            top = at_depth(d_top)
        d = np.geomspace(min(d_lo, d_top / 10), d_top, PROFILED_POINTS)
        return [at_depth(x) for x in d[:-1]] + [top]

    # -- the solve ----------------------------------------------------------------
    def _approach(self, dr):
        """delta_j = delta_r cos psi_j - P_d/2; |delta_j| below 1e-12 of the terms (a
        roller at the load-zone edge, cos psi rounded) is the edge itself, 0."""
        c = np.cos(self.azimuth)
        a = dr * c - self.clearance / 2
        a[np.abs(a) <= 1e-12 * (abs(dr) + abs(self.clearance))] = 0.0
        return a

    def _ring(self, law, dr):
        approach = self._approach(dr)
        Q, k = law.force(approach)
        c = np.cos(self.azimuth)
        return float(np.sum(Q * c)), float(np.sum(k * c * c)), approach, Q, k

    def _equilibrium(self, law, F):
        lo = max(self.clearance / 2, 0.0)
        hi = law.dtop + self.clearance / 2
        f_hi = self._ring(law, hi)[0] - F
        if f_hi < 0:
            raise OutOfRangeError("radial_load", F, "a load the contact law reaches",
                                  unit="N", hint="the most loaded roller would leave the "
                                  "law's range")
        dr = 0.5 * (lo + hi) if lo > 0 else law.delta_of(4.08 * F / self.rollers) + \
            self.clearance / 2
        dr = float(min(max(dr, lo), hi))
        for _ in range(200):
            g, dg, *_ = self._ring(law, dr)
            g -= F
            if abs(g) <= 1e-14 * F:
                break
            if g > 0:
                hi = dr
            else:
                lo = dr
            new = dr - g / dg if dg > 0 else 0.5 * (lo + hi)
            dr = new if lo < new < hi else 0.5 * (lo + hi)
            if hi - lo <= 1e-15 * hi:
                break
        return dr

    @serial_blas
    def solve(self, radial_load, moment=None, misalignment=None, *, speed=None,
              axial_load=None):
        r"""Solve the bearing under a radial load F_r, and a tilting moment M or a given
        misalignment theta (:class:`BearingSolution`); at a speed, and with an axial
        load on the flanges.

        .. math::

            F_r = \sum_j Q_j\cos\psi_j, \qquad M = \sum_j M_j\cos\psi_j, \qquad
            \delta_j(x) = (\delta_r + \theta x)\cos\psi_j - P_d/2

        Parameters
        ----------
        radial_load : float or array_like
            Radial load F_r, 0 < F_r < inf [N] (zero or less lifts every roller); an
            array gives an object array of solutions of its shape, one per load.
        moment : float, optional
            Tilting moment M on the inner ring about the axis normal to the load plane,
            |M| < inf [N m]: the ring tilt theta is solved with delta_r (2 DOF).
        misalignment : float, optional
            Given tilt theta of the inner ring against the outer ring in the load
            plane, |theta| < 0.1 [rad] (positive: the rings close at +x on the loaded
            side): delta_r is solved at this tilt (1 DOF) and the moment it needs is
            reported. At most one of `moment` and `misalignment`.
        speed : float, optional
            Speed of the inner ring against the outer ring, -inf < omega < inf [rad/s]
            (nonzero with a lubricant): the entrainment speed, and with the bearing's
            lubricant kappa, the film and the modified lives.
        axial_load : float, optional
            Axial load F_a carried by the flanges, 0 <= F_a < inf [N] (needs the
            bearing's flange geometry): each roller's flange forces, their Hertz
            stresses and couple.

        Returns
        -------
        BearingSolution or ndarray of BearingSolution

        Raises
        ------
        CombinationError
            Both `moment` and `misalignment`; either with a straight-cylinder law named
            as the model (a law has no tilt: use ``model="profiled-roller"``).
        OutOfRangeError
            A load that lifts every roller, or one beyond the contact law's range; a
            preload (clearance < 0) that alone presses the rollers beyond it, named as
            the clearance.

        Notes
        -----
        Valid for 0 < F_r < inf within the contact law's range. With a moment or a
        misalignment each roller is solved by slices (the bearing's slice model; for a
        straight roller with no model named, ``"profiled-roller"``) and is free to
        tilt between its rings, docs/bearings.md. The film, lives, static safety and
        flange contacts follow from the load distribution (docs/bearing_life.md);
        the flange couple is not fed back into it (the rollers' radial loads and tilts
        are the flange-free ones; the solution reports the load shift that would
        balance the couple).

        Examples
        --------
        >>> s = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3).solve(10e3)
        >>> f"{s.roller_loads @ np.cos(s.azimuth) / 10e3:.12f}"
        '1.000000000000'
        """
        if not isinstance(radial_load, str) and np.ndim(radial_load) > 0:
            loads = check_interval(
                "radial_load", radial_load, 0.0, np.inf, low_open=True, high_open=True,
                unit="N", hint="a radial load of zero or less lifts every roller")
            out = np.empty(np.shape(loads), dtype=object)
            for idx, f in np.ndenumerate(loads):
                out[idx] = self.solve(float(f), moment, misalignment, speed=speed,
                                      axial_load=axial_load)
            return out
        try:
            return self._solve(radial_load, moment, misalignment, speed, axial_load)
        except OutOfRangeError as exc:
            top = getattr(exc, "top", None)
            if top is None or not -self.clearance / 2 >= top:
                raise
            given = getattr(self, "internal_clearance", self.clearance)
            fitted = ("" if given == self.clearance else
                      f" (the operating clearance after the fits: {self.clearance:.3g} m)")
            raise OutOfRangeError(
                "clearance", given,
                f"(-{2 * top:.3g}, {self.roller_diameter:.3g}) m at F_r = "
                f"{float(radial_load):.6g} N{fitted}", unit="m",
                hint=f"a preload presses every roller by -P_d/2 = "
                     f"{-self.clearance / 2 * 1e6:.4g} um before any load, beyond the "
                     f"roller's range at this load ({top * 1e6:.4g} um); preloads are "
                     "a few micrometres") from None

    def _solve(self, radial_load, moment, misalignment, speed, axial_load,
               at_rest=False):
        """:meth:`solve` of one radial load; `at_rest`: a duty cycle's case at
        standstill (:func:`linecontact.bearing.spectrum.solve_spectrum`), solved
        without the film, kappa and the modified lives, which need the rings to turn
        (it takes no revolutions, so no fatigue damage)."""
        F = float(check_interval(
            "radial_load", radial_load, 0.0, np.inf, low_open=True, high_open=True,
            unit="N", hint="a radial load of zero or less lifts every roller"))
        if at_rest:
            speed = None
        elif speed is not None:
            speed = float(check_interval("speed", speed, -np.inf, np.inf, low_open=True,
                                         high_open=True, unit="rad/s"))
        elif self.lubricant is not None:
            raise CombinationError({"speed": None, "viscosity": self.lubricant[
                "viscosity"]}, "the lubricant's film and kappa need the inner ring's "
                "speed: give solve(..., speed=)")
        sol = self._extras(self._solve_load(F, moment, misalignment), speed, axial_load)
        if at_rest:
            from dataclasses import replace

            sol = replace(sol, speed=0.0, entrainment_speed=0.0, notes=sol.notes + (
                "at standstill: no film, kappa or modified life (they need the rings "
                "to turn); no revolutions, so no fatigue damage in the duty cycle",))
        return sol

    def _solve_load(self, F, moment, misalignment):
        """The load distribution under F_r and a moment or misalignment."""
        if moment is not None and misalignment is not None:
            raise CombinationError({"moment": moment, "misalignment": misalignment},
                                   "give a tilting moment or a misalignment, not both "
                                   "(the moment a misalignment needs is an output)")
        if moment is not None or misalignment is not None:
            for name, v, unit in (("moment", moment, "N m"),
                                  ("misalignment", misalignment, "rad")):
                if v is not None and not isinstance(v, str) and np.ndim(v) != 0:
                    raise OutOfRangeError(name, v, f"one number [{unit}]",
                                          hint="one bearing load case per solve")
            M = None if moment is None else float(check_interval(
                "moment", moment, -np.inf, np.inf, low_open=True, high_open=True,
                unit="N m"))
            th = None if misalignment is None else TILT_RANGE.check(
                misalignment, name="misalignment").item()
            return self._tilt_model(moment, misalignment)._tilted_solution(F, M, th)
        notes = []
        if not self.sliced:
            Qg, dg, kg, _ = self._law_grid(F)
            law = _Law(Qg, dg, kg)
            dr = self._equilibrium(law, F)
            dr, Q, k, approach, sol = self._polish(law, dr, F)
            law_error = 0.0
            pp = (max(float(np.max(sol.peak_pressure_inner)),
                      float(np.max(sol.peak_pressure_outer))) if sol is not None
                  else math.nan)
            n_s = LAMINAE
            x = (np.arange(n_s) + 0.5) / n_s * self.length - self.length / 2
            qi = np.outer(Q, np.full(n_s, 1.0 / n_s))
            qo = qi.copy()
            label = sol.model if sol is not None else self.model
            c = np.cos(self.azimuth)
            K = np.array([[float(np.sum(k * c * c))]])
            roller = _one_roller(sol, int(np.argmax(np.asarray(sol.force))))
            Mj, tj = np.zeros(self.rollers), np.zeros(self.rollers)
        else:
            (dr, Q, k, approach, x, qi, qo, pp, law_error, label, K, roller, Mj, tj,
             more) = self._solve_sliced(F)
            notes.extend(more)
            if not math.isfinite(pp):
                notes.append("peak pressure not reported: the most loaded roller is "
                             "edge loaded (a singular pressure on a half-space)")
        fields = self._roller_stresses(roller)
        eps = 0.5 * (1 - self.clearance / (2 * dr)) if dr > 0 else math.inf
        zone = math.acos(max(-1.0, min(1.0, self.clearance / (2 * dr)))) if dr > 0 \
            else math.pi
        if self.clearance < 0 and np.all(Q > 0):
            zone = math.pi
        life16281 = reference_rating_life(self.rating, self.pitch_diameter,
                                          self.roller_diameter, qi, qo, self.rotating)
        notes.extend(fields.notes)
        Z = self.rollers
        return BearingSolution(
            radial_load=F, displacement=float(dr), azimuth=self.azimuth.copy(),
            approach=approach, roller_loads=Q, roller_stiffness=k, stiffness=K,
            max_roller_load=float(np.max(Q)), load_zone=float(zone), epsilon=float(eps),
            peak_pressure=float(pp), slice_x=x, slice_loads_inner=qi,
            slice_loads_outer=qo, rating=self.rating,
            life_iso281=basic_rating_life(self.rating, F),
            life_iso16281=life16281, law_error=float(law_error), model=label,
            notes=tuple(notes), moment=0.0, tilt=0.0, roller_moments=Mj,
            roller_tilts=tj, roller_misalignment=np.zeros(Z),
            stress=fields.worst, roller=roller, roller_stresses=fields)

    def _tilt_model(self, moment, misalignment):
        """This bearing if its model solves tilted rollers by slices; else, with no
        model named, its twin under ``"profiled-roller"``; a law named is refused."""
        if self.sliced:
            return self
        if self._model_named:
            given = ({"moment": moment} if moment is not None else
                     {"misalignment": misalignment})
            raise CombinationError(
                {"model": self.model, **given},
                "a straight-cylinder law has no tilt; a tilting moment or misalignment "
                "needs a slice model, model='profiled-roller' or 'iso16281-slicing'")
        return RadialRollerBearing(
            self.rollers, self.pitch_diameter, self.roller_diameter, self.length,
            self.clearance, estar=self.estar, model="profiled-roller",
            profile=self.profile, n_slices=self.n_slices, azimuth0=self.azimuth0,
            rating=self.rating, rotating=self.rotating, poisson=self.poisson)

    def _roller_stresses(self, roller):
        """Subsurface stresses of one roller's two contacts (`roller`: its
        :class:`~linecontact.raceway.RacewaySolution`), no traction, with the rings'
        Poisson's ratio: :func:`linecontact.stresses.raceway_stresses` (each contact's,
        the worse per measure and the case check over both)."""
        from ..stresses import raceway_stresses

        return raceway_stresses(roller, self.length, self.estar, self.profile,
                                poisson=self.poisson)

    def _tilted_load_zone(self, dr, th, first, points=721):
        """Half the azimuth range where a roller would be loaded,
        e(psi) = delta_r cos psi - P_d/2 - 2 d_0(theta cos psi / 2) > 0, on a grid of
        `points` over [0, pi] with the crossings interpolated linearly (for theta = 0
        the aligned psi_l = arccos(P_d/(2 delta_r)); a large tilt can load both
        sides: their extents add) [rad]."""
        psi = np.linspace(0.0, math.pi, points)
        cp = np.cos(psi)
        e = dr * cp - self.clearance / 2 - 2 * np.array([first(0.5 * th * x) for x in cp])
        a, b = e[:-1], e[1:]
        h = psi[1] - psi[0]
        both = (a > 0) & (b > 0)
        cross = (a > 0) != (b > 0)
        part = np.where(cross, np.maximum(a, b) / np.where(cross, np.abs(a - b), 1.0), 0.0)
        return float(h * (np.sum(both) + np.sum(part)))

    def _tilted_solution(self, F, M, theta):
        dr, th, c, inverse, sols, K, kser, first = self._solve_tilted(F, M, theta)
        Z = self.rollers
        L = self.length
        n_lam = self.n_slices
        Q, Mj, tj, kj = (np.zeros(Z) for _ in range(4))
        qi = np.zeros((Z, n_lam))
        qo = np.zeros_like(qi)
        pp, edge = -math.inf, []
        for j in range(Z):
            g = inverse[j]
            if sols[g] is None:
                continue
            si, so = sols[g]
            Q[j], Mj[j], tj[j], kj[j] = si.force, si.moment, si.tilt, kser[g][0, 0]
            qi[j] = _laminae(si, L, n_lam)
            qo[j] = _laminae(so, L, n_lam)
            for s in (si, so):
                if s.p_max is None:
                    edge.append(j)
                else:
                    pp = max(pp, float(s.p_max))
        notes = []
        if edge:
            pp = math.nan
            notes.append("peak pressure not reported: rollers "
                         f"{sorted(set(edge))} are edge loaded (a singular pressure on "
                         "a half-space); their end laminae, and so L10r, depend on the "
                         "slice width (not converged)")
        jm = int(np.argmax(Q))
        si, so = sols[inverse[jm]]
        R_in, R_out = effective_radii(self.roller_diameter / 2, self.raceways.inner,
                                      self.raceways.outer)
        roller = _contacts_solution(self.model, si, so, R_in, R_out,
                                    float(th * c[jm]), True,
                                    self.raceways.check_fit(self.roller_diameter / 2))
        fields = self._roller_stresses(roller)
        notes.extend(fields.notes)
        approach = dr * c - self.clearance / 2
        zone = self._tilted_load_zone(dr, th, first)
        eps = 0.5 * (1 - self.clearance / (2 * dr)) if dr > 0 else math.inf
        life = reference_rating_life(self.rating, self.pitch_diameter,
                                     self.roller_diameter, qi, qo, self.rotating)
        x = (np.arange(n_lam) + 0.5) / n_lam * L - L / 2
        label = f"{self.model} ({si.method}, {si.n_slices} slices), rollers free to tilt"
        return BearingSolution(
            radial_load=F, displacement=float(dr), azimuth=self.azimuth.copy(),
            approach=approach, roller_loads=Q, roller_stiffness=kj, stiffness=K,
            max_roller_load=float(np.max(Q)), load_zone=zone, epsilon=float(eps),
            peak_pressure=float(pp), slice_x=x, slice_loads_inner=qi,
            slice_loads_outer=qo, rating=self.rating,
            life_iso281=basic_rating_life(self.rating, F), life_iso16281=life,
            law_error=0.0, model=label, notes=tuple(notes),
            moment=float(Mj @ c), tilt=float(th), roller_moments=Mj, roller_tilts=tj,
            roller_misalignment=th * c, stress=fields.worst, roller=roller,
            roller_stresses=fields)

    def _polish(self, law, dr, F):
        """Newton on (Q_j loaded, delta_r) with the exact law (the grid's interpolation
        error removed); the equilibrium row is linear, so the loads sum to F_r to
        round-off after every step."""
        c = np.cos(self.azimuth)
        Q, k = law.force(self._approach(dr))
        on = Q > 0
        sol = None
        for _ in range(20):
            d, kk, sol = self._exact(Q[on])
            r = d - (dr * c[on] - self.clearance / 2)
            e = F - float(np.sum(Q[on] * c[on]))
            ddr, dQ = _ring_step(c[on], 1.0, kk, r, e)
            step = 1.0
            neg = Q[on] + dQ <= 0
            if np.any(neg):  # a roller leaves the load zone: drop it and start again
                idx = np.flatnonzero(on)[neg]
                on[idx] = False
                Q[idx] = 0.0
                k[idx] = 0.0
                continue
            Q[on] = Q[on] + step * dQ
            dr = dr + step * ddr
            k[on] = kk
            if np.max(np.abs(r)) <= 1e-13 * max(float(np.max(d)), 1e-300) and \
                    abs(ddr) <= 1e-13 * abs(dr):
                break
        d, kk, sol = self._exact(Q[on])
        k[on] = kk
        return dr, Q, k, self._approach(dr), sol

    def _roller(self, Q):
        """One roller between the bearing's raceways at load Q [N], aligned rings,
        free to tilt: :func:`~linecontact.raceway.roller_between_raceways` with the
        bearing's model, profile and slices (the per-roller reference)."""
        if not self.sliced:
            return roller_between_raceways(self.roller_diameter / 2, self.length,
                                           self.estar, self.raceways, force=Q,
                                           model=self.model)
        return roller_between_raceways(self.roller_diameter / 2, self.length,
                                       self.estar, self.raceways, force=Q,
                                       model=self.model, profile=self.profile,
                                       tilt="free", n_slices=self.n_slices)

    def _polish_rollers(self, law, dr, F, tol=1e-9):
        """Newton on (Q_j of the loaded rollers, delta_r) with each roller solved
        exactly between its raceways (:meth:`_roller`, the per-roller reference), from
        the tabulated law's equilibrium delta_r; rollers of equal cos psi (+psi and
        -psi) solved once. Stops when every loaded roller's deflection meets its ring
        approach to `tol` relative (the slice solves converge to 1e-10 in force) and
        the loads balance F_r to round-off; a roller that leaves the load zone is
        dropped, one the ring reaches joins it.

        Returns (delta_r, Q_g, k_g, solutions_g, residual, groups of the rollers,
        cos psi_g, rollers per group), per group of equal cos psi; solutions_g None
        where unloaded; residual: the largest relative |delta(Q_g) - delta_g|."""
        c = np.cos(self.azimuth)
        _, first, inverse = np.unique(np.round(c, 12), return_index=True,
                                      return_inverse=True)
        cg = c[first]
        w = np.bincount(inverse).astype(float)
        P = self.clearance / 2
        edge = 1e-12 * (abs(dr) + abs(self.clearance))   # as _approach: 0 below
        a = dr * cg - P
        Q = law.force(np.where(np.abs(a) <= edge, 0.0, a))[0]
        on = Q > 0
        k = np.zeros_like(Q)
        sols = [None] * len(cg)
        worst = math.inf
        for it in range(31):
            idx = np.flatnonzero(on)
            for g in idx:
                if sols[g] is None or sols[g].force != Q[g]:
                    sols[g] = self._roller(float(Q[g]))
            d = np.array([sols[g].deflection for g in idx])
            k[idx] = [sols[g].stiffness for g in idx]
            r = d - (dr * cg[idx] - P)
            e = F - float(np.sum(w[idx] * Q[idx] * cg[idx]))
            worst = float(np.max(np.abs(r) / d))
            enter = ~on & (dr * cg - P > 1e-12 * (abs(dr) + abs(self.clearance)))
            if it == 30 or (not np.any(enter) and worst <= tol and abs(e) <= 1e-12 * F):
                break
            if np.any(enter):  # the ring reaches an unloaded roller: load it
                on |= enter
                Q[enter] = law.force(dr * cg[enter] - P)[0]
                continue
            ddr, dQ = _ring_step(cg[idx], w[idx], k[idx], r, e)
            neg = Q[idx] + dQ <= 0
            if np.any(neg):  # a roller leaves the load zone: drop it and start again
                for g in idx[neg]:
                    on[g], Q[g], k[g], sols[g] = False, 0.0, 0.0, None
                continue
            Q[idx] += dQ
            dr += ddr
        return dr, Q, k, sols, worst, inverse, cg, w

    def _universal_start(self, F):
        """The same bearing with the universal-curve law (a straight roller) at the
        radial load F: the bearing, its roller law, its delta_r and the law grid's
        fourth output (the straight roller's contacts), the start of the profiled and
        tilted solves."""
        est = RadialRollerBearing(self.rollers, self.pitch_diameter,
                                  self.roller_diameter, self.length, self.clearance,
                                  estar=self.estar, azimuth0=self.azimuth0,
                                  rating=self.rating)
        Qg0, dg0, kg0, s0 = est._law_grid(F)
        law0 = _Law(Qg0, dg0, kg0)
        return est, law0, est._equilibrium(law0, F), s0

    def _solve_sliced(self, F):
        """Profiled rollers: each contact's coupled-slice solution tabulated over the
        depths the bearing needs (the load range first estimated with the universal
        curve), the two in series at equal load, inverted like a law; the ring
        equilibrium on that table polished with exact solves of the loaded rollers
        (:meth:`_polish_rollers`), whose solves give every per-roller output."""
        est, law0, dr0, s0 = self._universal_start(F)
        Qmax0 = float(np.max(law0.force(est._approach(dr0))[0]))
        lo, hi = 1e-3 * Qmax0, 1.6 * Qmax0
        dep_i, dep_o = self._contacts()
        lnQ0 = law0.lnQ
        tables = []
        for dep, straight in ((dep_i, s0.depth_inner), (dep_o, s0.depth_outer)):
            ds = np.exp(np.interp(np.log([lo, hi]), lnQ0, np.log(straight)))
            # the outer table reaches at least the inner table's largest load
            top = max(hi, tables[0][-1].force) if tables else hi
            tables.append(self._depth_table(dep, ds[0], ds[1], top))
        ti, to = tables
        Fi = np.array([r.force for r in ti])
        Fo = np.array([r.force for r in to])
        if not (np.all(np.diff(Fi) > 0) and np.all(np.diff(Fo) > 0)):
            raise OutOfRangeError("profile", self.profile.label, "a roller whose load "
                                  "grows with its depth")
        outer = _Law(Fo, np.array([r.depth for r in to]),
                     np.array([r.stiffness for r in to]))
        # the outer contact at the inner table's loads (Hermite in ln F, exact slopes)
        d_out = outer.delta_of(Fi)
        k_out = outer.force(d_out)[1]
        delta = np.array([r.depth for r in ti]) + d_out
        k = _in_series(np.array([r.stiffness for r in ti]), k_out)
        law = _Law(Fi, delta, k)
        dr = self._equilibrium(law, F)
        # the tabulated equilibrium polished with exact solves of the loaded rollers:
        # every roller's load, approach, tilt, moment and contacts are those of
        # roller_between_raceways at its load
        dr, Qg, kg, sols, residual, inverse, cg, w = self._polish_rollers(law, dr, F)
        L, n_lam = self.length, self.n_slices
        x = (np.arange(n_lam) + 0.5) / n_lam * L - L / 2
        qi = np.zeros((len(cg), n_lam))
        qo = np.zeros_like(qi)
        Mg, tg = np.zeros(len(cg)), np.zeros(len(cg))
        K = np.zeros((2, 2))
        # the 2x2 stiffness: each roller's two contacts in series as 2x2 matrices,
        # (K_in^-1 + K_out^-1)^-1 (the roller free to tilt), summed with cos^2 psi_j
        # (docs/bearings.md)
        for g, sol in enumerate(sols):
            if sol is None:
                continue
            qi[g] = _laminae(sol.inner, L, n_lam)
            qo[g] = _laminae(sol.outer, L, n_lam)
            Mg[g], tg[g] = sol.moment_inner, sol.tilt
            Ki, Ko = (np.asarray(c.stiffness_matrix) for c in (sol.inner, sol.outer))
            K += w[g] * cg[g] ** 2 * (Ki @ np.linalg.solve(Ki + Ko, Ko))
        Q = Qg[inverse]
        roller = sols[inverse[int(np.argmax(Q))]]
        p_in, p_out = roller.peak_pressure_inner, roller.peak_pressure_outer
        pp = (math.nan if p_in is None or p_out is None      # edge loaded: not reported
              else max(float(p_in), float(p_out)))
        notes = []
        if residual > 1e-9:
            notes.append(f"the exact polish of the roller loads stopped at a relative "
                         f"residual of {residual:.2g} (30 Newton steps)")
        label = f"{self.model} ({roller.inner.method}, {roller.inner.n_slices} slices)"
        return (dr, Q, kg[inverse], self._approach(dr), x, qi[inverse], qo[inverse],
                pp, residual, label, K, roller, Mg[inverse], tg[inverse], notes)

    # -- tilting moment and misalignment -----------------------------------------
    def _contact_pair(self):
        """(at_depth(d, t) -> RollerSolution, first_contact_depth(t)) factories of the
        inner and the outer contact of one roller (fresh solvers: each keeps its own
        warm start)."""
        inner, outer = self._solvers()
        # the first contact: the same for both (the profile and the slices), here the
        # outer contact's (ISO slicing: on its slice centres, x_k tan theta)
        return [inner.at_depth, outer.at_depth], outer.first_contact_depth

    def _solve_tilted(self, F, M, theta):
        r"""Ring displacement and tilt (M given) or displacement at a given tilt, every
        roller free to tilt between its two slice contacts; one Newton iteration on
        all unknowns at once (each roller's inner depth and tilt, delta_r and theta),
        its linear system reduced roller by roller to the ring's 2x2 (or 1x1) system.

        Roller j at azimuth psi_j sees the ring approach delta_r c_j - P_d/2 at its
        centre and the ring misalignment phi_j = theta c_j (c_j = cos psi_j); with its
        tilt t against the inner ring, the inner contact is at (d_i, t) and the outer at
        (delta_j - d_i, phi_j - t); the roller balances force and moment,
        F_in = F_out, M_in = M_out, and passes Q_j = F_in, M_j = M_in to the rings:
        F_r = sum Q_j c_j, M = sum M_j c_j.
        """
        given_tilt = M is None
        c = np.cos(self.azimuth)
        # rollers of equal cos psi (+psi and -psi) have the same state: solve once
        key = np.round(c, 12)
        groups, inverse = np.unique(key, return_inverse=True)
        weight = np.bincount(inverse).astype(float)
        cg = groups.astype(float)
        n = len(cg)
        pairs = [None] * n
        first = None
        # start: delta_r of the aligned universal-curve bearing
        _, _, dr, _ = self._universal_start(F)
        th = 0.0 if not given_tilt else theta
        L = self.length
        u = np.full((n, 2), np.nan)      # (d_inner, roller tilt) of each group
        sols = [None] * n
        ks = [None] * n
        tol_F = 1e-11 * F
        tol_M = 1e-11 * F * L
        K = None
        for _ in range(80):
            delta = dr * cg - self.clearance / 2
            phi = th * cg
            if first is None:
                pairs[0], first = self._contact_pair()
            R_F, R_M = F, (M if not given_tilt else 0.0)
            Kg = np.zeros((2, 2))
            rhs = np.zeros(2)
            local = []
            worst = 0.0
            for g in range(n):
                e = delta[g] - 2 * first(0.5 * phi[g])
                if e <= 0:
                    u[g] = np.nan
                    sols[g] = None
                    local.append(None)
                    continue
                if pairs[g] is None:
                    pairs[g] = self._contact_pair()[0]
                if not np.isfinite(u[g, 0]):
                    u[g] = (first(0.5 * phi[g]) + 0.5 * e, 0.5 * phi[g])
                di, t = u[g]
                do = delta[g] - di
                # keep both contacts touching: back to the even split if not
                if not (di > first(t) and do > first(phi[g] - t)):
                    u[g] = (first(0.5 * phi[g]) + 0.5 * e, 0.5 * phi[g])
                    di, t = u[g]
                    do = delta[g] - di
                si = pairs[g][0](di, t)
                so = pairs[g][1](do, phi[g] - t)
                sols[g] = (si, so)
                Ki = np.asarray(si.stiffness_matrix)
                Ko = np.asarray(so.stiffness_matrix)
                r = np.array([si.force - so.force, si.moment - so.moment])
                worst = max(worst, abs(r[0]) / max(si.force, 1e-300),
                            abs(r[1]) / (max(si.force, 1e-300) * L))
                A = Ki + Ko
                # pinv: a straight roller under ISO slicing may touch with one slice
                # per contact, both at one end (K of rank 1)
                Ainv = np.linalg.pinv(A)
                kser = Ki @ Ainv @ Ko          # (Ki^-1 + Ko^-1)^-1
                y0 = Ki @ Ainv @ r             # dy = -y0 + kser dv
                R_F -= weight[g] * cg[g] * si.force
                R_M -= weight[g] * cg[g] * si.moment
                Kg += weight[g] * cg[g] ** 2 * kser
                ks[g] = kser
                rhs += weight[g] * cg[g] * y0
                local.append((Ainv, Ko, r))
            K = Kg
            if not np.any(np.isfinite(u[:, 0])):
                raise OutOfRangeError("radial_load", F, "a load that keeps a roller "
                                      "loaded", unit="N", hint="every roller is lifted")
            done = (abs(R_F) <= tol_F and worst <= 1e-10
                    and (given_tilt or abs(R_M) <= tol_M + 1e-11 * abs(M)))
            if done:
                break
            if given_tilt:
                dV = np.array([(R_F + rhs[0]) / Kg[0, 0], 0.0])
            else:
                dV = np.linalg.lstsq(Kg, np.array([R_F, R_M]) + rhs, rcond=None)[0]
            # safeguards: delta_r at least halves towards the clearance, the ring tilt
            # moves by at most a tenth of the tilt range per step
            top = max(self.clearance / 2, 0.0)
            if dr + dV[0] <= top:
                dV[0] = 0.5 * (top - dr) if dr > top else 0.5 * abs(dr) + 1e-12
            dV[1] = float(np.clip(dV[1], -0.01, 0.01))
            for g in range(n):
                if local[g] is None:
                    continue
                Ainv, Ko, r = local[g]
                du = -Ainv @ (r - Ko @ (cg[g] * dV))
                du[1] = float(np.clip(du[1], -0.01, 0.01))
                u[g] = u[g] + du
            dr += dV[0]
            th += dV[1]
            # a solved ring tilt beyond 0.05 rad: the moment is beyond the rollers'
            # capacity (a given misalignment stays as given, up to its range)
            if not given_tilt and not abs(th) < 0.05:
                break
        else:
            th = math.nan
        if not (given_tilt and math.isfinite(th)) and not abs(th) < 0.05:
            name, value, unit = (("misalignment", theta, "rad") if given_tilt else
                                 ("moment", M, "N m"))
            raise OutOfRangeError(
                name, value, "a load the rollers carry at ring tilts below 0.05 rad",
                unit=unit, hint=f"with F_r = {F:g} N no ring equilibrium was found in 80 "
                "Newton steps (the rollers' tilt against a ring must stay below 0.1 "
                "rad; a moment near the rollers' capacity, about F_r L/2, edge loads "
                "them)")
        return dr, th, c, inverse, sols, K, ks, first
