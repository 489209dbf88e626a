r"""The radial bearing's solvers: :class:`RadialRollerBearing` (the load distribution
over the rollers, the ring's equilibrium and stiffness: under a law, tabulated slices, or
tilted rollers) and :class:`BearingSolution`; the method is the package docstring's,
:mod:`linecontact.bearing`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._numerics import serial_blas
from ..models import DEFAULT_SLICE_MODEL, SLICE_MODELS
from ..profiles import TILT_RANGE
from ..raceway import Raceways, effective_radii, roller_between_raceways
from ..errors import CombinationError, OutOfRangeError, UnknownNameError
from ..checks import check_interval, check_positive
from .interpolant import _Law
from .ratings import (_fits, _rollers, basic_rating_life, dynamic_load_rating,
                      reference_rating_life)

__all__ = [
    "RadialRollerBearing",
    "BearingSolution",
    "load_zone_integral",
    "GRID_POINTS",
    "PROFILED_POINTS",
]

#: Points of the roller-law grid of a straight roller under a law [-].
GRID_POINTS = 160
#: Tabulated loads of a profiled roller (coupled slices) [-].
PROFILED_POINTS = 14
#: Laminae for the rating life of a roller under a law (uniform line load) [-].
LAMINAE = 20
#: Upper bound of any roller load in units of F_r for Z >= 3: one roller at
#: |psi| <= pi/Z alone carries at most F_r/cos(pi/Z) <= 2 F_r.
_TOP = 2.05


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
    t, w = np.polynomial.legendre.leggauss(400)
    t = 0.5 * (t + 1.0)
    w = 0.5 * w
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


def _worst_of(fields):
    """The largest value of each stress measure over named contacts' stress results
    (name -> SubsurfaceStresses): {"worst": {measure: {value, depth, x, contact}},
    "notes": [...]}; a measure whose maximum is not converged in some contact (an
    edge-loaded one) carries "withheld": the reason (its value is the slice width's)."""
    from ..stresses import MEASURES

    worst = {}
    for m in MEASURES:
        name, st = max(fields.items(), key=lambda kv: kv[1].worst[m]["value"])
        w = st.worst[m]
        worst[m] = {"value": float(w["value"]), "depth": float(w["z"]),
                    "x": float(w["x"]), "contact": name}
        held = [n for n, f in fields.items() if m in getattr(f, "withheld", {})]
        if held:
            worst[m]["withheld"] = (" and ".join(held) + " contact: "
                                    + fields[held[0]].withheld[m])
    notes = []
    for name, st in fields.items():
        notes.extend(f"stress ({name} contact): {t}" for t in st.notes)
    held = sorted(m for m in MEASURES if "withheld" in worst[m])
    if held:
        notes.append("stress maxima not reported (" + ", ".join(held) + "): "
                     + worst[held[0]]["withheld"])
    return {"worst": worst, "notes": notes}


def _contact_stresses(si, so, poisson, rollers=(None, None)):
    """Subsurface stress maxima of one roller's two slice contacts
    (:func:`linecontact.stresses.roller_stresses`, no traction); `rollers`: each
    contact's (radius, length, estar, profile), so that the measured error is quoted
    only inside the measured range."""
    from ..stresses import roller_stresses

    return _worst_of({"inner": roller_stresses(si, poisson=poisson, roller=rollers[0]),
                      "outer": roller_stresses(so, poisson=poisson, roller=rollers[1])})


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
        Largest relative error of the tabulated roller law used for the roller loads
        (0 after the exact polish of a law) [-].
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

    def to_dict(self):
        """The solution as plain Python (lists for arrays), SI units."""
        out = {}
        for k, v in self.__dict__.items():
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
        Number of rollers Z, 3 <= Z [-].
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
        Slices of the slice model, 10 <= n <= 1000 (ISO slicing: n >= 30) [-]
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

    Notes
    -----
    Valid for Z >= 3, 0 < D < d_m, |P_d| < D, within the contact law's range (its
    depth and L/R ranges; the universal curve to d <= 0.15 R). Centrifugal forces,
    ring deformation and roller skew are not modelled.

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
                 azimuth0=0.0, rating=None, rotating="inner", poisson=0.3):
        from ..models import available_models
        from ..profiles import StraightProfile, as_profile

        self.rollers = _rollers(rollers)
        self.pitch_diameter = float(check_positive("pitch_diameter", pitch_diameter, "m"))
        self.roller_diameter = float(check_positive("roller_diameter", roller_diameter,
                                                    "m"))
        _fits(self.pitch_diameter, self.roller_diameter)
        self.length = float(check_positive("length", length, "m"))
        D = self.roller_diameter
        self.clearance = float(check_interval(
            "clearance", clearance, -D, D, low_open=True, high_open=True, unit="m",
            hint="the clearance must be smaller than the roller diameter"))
        self.estar = float(check_positive("estar", estar, "Pa"))
        if n_slices is not None:
            n_slices = int(check_interval("n_slices", n_slices, 10, 1000))
        self.azimuth0 = float(check_interval("azimuth0", azimuth0, -math.pi, math.pi,
                                             unit="rad"))
        if rotating not in ("inner", "outer"):
            raise UnknownNameError("rotating", rotating, ["inner", "outer"])
        self.rotating = rotating
        self.poisson = float(check_interval("poisson", poisson, 0.0, 0.5))
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
        """(solve at depth, solve at force) of the inner and the outer contact."""
        out = []
        for c in self._solvers():
            out.append((lambda d, c=c: c.at_depth(d, 0.0),
                        lambda F, c=c: c.at_force(F, 0.0)))
        return out

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
    def solve(self, radial_load, moment=None, misalignment=None):
        r"""Solve the bearing under a radial load F_r, and a tilting moment M or a given
        misalignment theta (:class:`BearingSolution`).

        .. math::

            F_r = \sum_j Q_j\cos\psi_j, \qquad M = \sum_j M_j\cos\psi_j, \qquad
            \delta_j(x) = (\delta_r + \theta x)\cos\psi_j - P_d/2

        Parameters
        ----------
        radial_load : float
            Radial load F_r, 0 < F_r < inf [N] (zero or less lifts every roller).
        moment : float, optional
            Tilting moment M on the inner ring about the axis normal to the load plane,
            |M| < inf [N m]: the ring tilt theta is solved with delta_r (2 DOF).
        misalignment : float, optional
            Given tilt theta of the inner ring against the outer ring in the load
            plane, |theta| < 0.1 [rad] (positive: the rings close at +x on the loaded
            side): delta_r is solved at this tilt (1 DOF) and the moment it needs is
            reported. At most one of `moment` and `misalignment`.

        Returns
        -------
        BearingSolution

        Raises
        ------
        CombinationError
            Both `moment` and `misalignment`; either with a straight-cylinder law named
            as the model (a law has no tilt: use ``model="profiled-roller"``).
        OutOfRangeError
            A load that lifts every roller, or one beyond the contact law's range.

        Notes
        -----
        Valid for 0 < F_r < inf within the contact law's range. With a moment or a
        misalignment each roller is solved by slices (the bearing's slice model; for a
        straight roller with no model named, ``"profiled-roller"``) and is free to
        tilt between its rings, docs/bearings.md.

        Examples
        --------
        >>> s = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3).solve(10e3)
        >>> f"{s.roller_loads @ np.cos(s.azimuth) / 10e3:.12f}"
        '1.000000000000'
        """
        F = float(check_interval(
            "radial_load", radial_load, 0.0, np.inf, low_open=True, high_open=True,
            unit="N", hint="a radial load of zero or less lifts every roller"))
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
            stress = self._law_stresses(float(np.max(Q)))
        else:
            (dr, Q, k, approach, x, qi, qo, pp, law_error, label, K,
             worst) = self._solve_sliced(F)
            stress = _contact_stresses(*worst, self.poisson, self._stress_rollers())
            if not math.isfinite(pp):
                notes.append("peak pressure not reported: the most loaded roller is "
                             "edge loaded (a singular pressure on a half-space)")
        eps = 0.5 * (1 - self.clearance / (2 * dr)) if dr > 0 else math.inf
        zone = math.acos(max(-1.0, min(1.0, self.clearance / (2 * dr)))) if dr > 0 \
            else math.pi
        if self.clearance < 0 and np.all(Q > 0):
            zone = math.pi
        life16281 = reference_rating_life(self.rating, self.pitch_diameter,
                                          self.roller_diameter, qi, qo, self.rotating)
        notes.extend(stress["notes"])
        Z = self.rollers
        return BearingSolution(
            radial_load=F, displacement=float(dr), azimuth=self.azimuth.copy(),
            approach=approach, roller_loads=Q, roller_stiffness=k, stiffness=K,
            max_roller_load=float(np.max(Q)), load_zone=float(zone), epsilon=float(eps),
            peak_pressure=float(pp), slice_x=x, slice_loads_inner=qi,
            slice_loads_outer=qo, rating=self.rating,
            life_iso281=basic_rating_life(self.rating, F),
            life_iso16281=life16281, law_error=float(law_error), model=label,
            notes=tuple(notes), moment=0.0, tilt=0.0, roller_moments=np.zeros(Z),
            roller_tilts=np.zeros(Z), roller_misalignment=np.zeros(Z),
            stress=stress["worst"])

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

    def _stress_rollers(self):
        """The inner and the outer contact as equivalent rollers on a flat (effective
        radius, length, E*, profile) for the stress table's range check."""
        from types import SimpleNamespace

        radii = effective_radii(self.roller_diameter / 2, self.raceways.inner,
                                self.raceways.outer)
        return tuple(SimpleNamespace(radius=R, length=self.length, estar=self.estar,
                                     profile=self.profile) for R in radii)

    def _law_stresses(self, Q):
        """Subsurface stresses of the most loaded roller under a law: the plane-strain
        Hertz strip of each contact at the mean line load Q/L."""
        from ..stresses import line_contact_stresses

        R_in, R_out = effective_radii(self.roller_diameter / 2, self.raceways.inner,
                                      self.raceways.outer)
        return _worst_of({name: line_contact_stresses(Q, R, self.length, self.estar,
                                                      poisson=self.poisson)
                          for name, R in (("inner", R_in), ("outer", R_out))})

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
        stress = _contact_stresses(si, so, self.poisson, self._stress_rollers())
        notes.extend(stress["notes"])
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
            roller_misalignment=th * c, stress=stress["worst"])

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
            ddr = (e + float(np.sum(kk * c[on] * r))) / float(np.sum(kk * c[on] ** 2))
            dQ = kk * (c[on] * ddr - r)
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
        curve), the two in series at equal load, inverted like a law."""
        est, law0, dr0, s0 = self._universal_start(F)
        Qmax0 = float(np.max(law0.force(est._approach(dr0))[0]))
        lo, hi = 1e-3 * Qmax0, 1.6 * Qmax0
        (dep_i, force_i), (dep_o, force_o) = self._contacts()
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
        k = 1.0 / (1.0 / np.array([r.stiffness for r in ti]) + 1.0 / k_out)
        law = _Law(Fi, delta, k)
        dr = self._equilibrium(law, F)
        approach = self._approach(dr)
        Q, kj = law.force(approach)
        inner = _Law(Fi, np.array([r.depth for r in ti]),
                     np.array([r.stiffness for r in ti]))
        L = self.length
        n_lam = self.n_slices
        x = (np.arange(n_lam) + 0.5) / n_lam * L - L / 2
        qi = np.zeros((self.rollers, n_lam))
        qo = np.zeros_like(qi)
        pp = -math.inf
        K = np.zeros((2, 2))
        c = np.cos(self.azimuth)
        # each loaded roller's two contacts solved at their tabulated depths (the load
        # then differs from Q_j by the table's interpolation error, law_error: the
        # lamina loads are scaled to Q_j); rollers of equal load (+psi and -psi) solved
        # once. The 2x2 stiffness: each roller's two contacts in series as 2x2
        # matrices, (K_in^-1 + K_out^-1)^-1 (the roller free to tilt), summed with
        # cos^2 psi_j (docs/bearings.md).
        done = {}
        for j in np.flatnonzero(Q > 0):
            key = float(f"{Q[j]:.12e}")
            if key not in done:
                ri = dep_i(float(inner.delta_of(Q[j])))
                ro = dep_o(float(outer.delta_of(Q[j])))
                Ki, Ko = (np.asarray(r.stiffness_matrix) for r in (ri, ro))
                done[key] = (_laminae(ri, L, n_lam) * Q[j] / ri.force,
                             _laminae(ro, L, n_lam) * Q[j] / ro.force,
                             max(ri.p_max if ri.p_max is not None else math.nan,
                                 ro.p_max if ro.p_max is not None else math.nan),
                             Ki @ np.linalg.solve(Ki + Ko, Ko), (ri, ro))
            qi[j], qo[j], p, kser, pair = done[key]
            K += c[j] ** 2 * kser
            if Q[j] == np.max(Q):
                pp, worst = p, pair
        jm = int(np.argmax(Q))
        law_error = self._table_error(law, (force_i, force_o), Fi, Q[jm])
        label = f"{self.model} ({ti[0].method}, {ti[0].n_slices} slices)"
        return dr, Q, kj, approach, x, qi, qo, pp, law_error, label, K, worst

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

    @staticmethod
    def _table_error(law, solvers, Fi, Qmax):
        """Relative error of the interpolated delta(Q) at the geometric midpoint of the
        table interval holding the largest roller load (one extra pair of slice
        solves): the interpolant's error is largest between the nodes."""
        i = int(np.clip(np.searchsorted(Fi, Qmax) - 1, 0, len(Fi) - 2))
        Fm = math.sqrt(Fi[i] * Fi[i + 1])
        si, so = solvers[0](Fm), solvers[1](Fm)
        return abs(float(law.delta_of(Fm)) / (si.depth + so.depth) - 1.0)
