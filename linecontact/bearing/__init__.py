r"""Radial cylindrical and needle roller bearings: load distribution, stiffness, rating life.

Z rollers (diameter D, effective length L, any axial profile) sit at the azimuths
:math:`\psi_j = \psi_0 + 2\pi j/Z` on the pitch diameter :math:`d_m`, between an inner
raceway of radius :math:`(d_m - D)/2` (convex) and an outer raceway (concave) that
leaves the radial internal clearance :math:`P_d` (ISO 5753-1's radial internal
clearance; Harris' diametral clearance :math:`P_d = d_o - d_i - 2D`, negative for
preload). A radial displacement :math:`\delta_r` of the inner ring towards the roller at
:math:`\psi = 0` gives roller j the ring approach

.. math:: \delta_j = \delta_r\cos\psi_j - P_d/2,

and the roller carries :math:`Q_j = Q(\delta_j)` for :math:`\delta_j > 0`, 0 otherwise.
:math:`Q(\delta)` is the whole roller between its two raceways (the two contacts in
series with the same load, :func:`linecontact.raceway.roller_between_raceways`) under
any contact law of :mod:`linecontact.models` (the universal curve by default, the
ISO/TS 16281 spring ``"iso16281"`` for comparison), or the coupled-slice model of
:mod:`linecontact.roller` for a profiled roller. Equilibrium of the ring:

.. math:: F_r = \sum_j Q_j\cos\psi_j, \qquad
          K_{rr} = \frac{dF_r}{d\delta_r} = \sum_{j\,\text{loaded}} k_j\cos^2\psi_j,

with :math:`k_j = dQ/d\delta` of roller j: the radial stiffness is the exact derivative
of the equilibrium (no finite differences).

How it is solved
----------------
The roller law is evaluated once, vectorised, on a geometric grid of loads
(:data:`GRID_POINTS` points from :math:`10^{-9}F_r` to :math:`2.05F_r`, which bounds
every roller load for :math:`Z \ge 3`), giving :math:`\delta(Q)` and its slope; its
inverse :math:`Q(\delta)` is the cubic Hermite interpolant of :math:`\ln Q` against
:math:`\ln\delta` with the exact slopes :math:`d\ln Q/d\ln\delta = k\delta/Q`. Newton's
method on :math:`\delta_r`, bracketed, solves the ring equilibrium on that inverse; then
(laws) a Newton polish on the loaded rollers' loads and :math:`\delta_r` with the exact
law, :math:`\delta(Q_j) = \delta_r\cos\psi_j - P_d/2`, :math:`\sum Q_j\cos\psi_j = F_r`,
removes the interpolation error: the loads then sum to :math:`F_r` to round-off.

A profiled roller under the slice model is tabulated the same way, at
:data:`PROFILED_POINTS` depths per contact (each a coupled-slice solve), and the ring
equilibrium on that table is polished the same way with every loaded roller solved
exactly between its raceways at its load
(:func:`linecontact.raceway.roller_between_raceways`, free to tilt): each roller's load,
approach, tilt, moment and lamina loads, and the most loaded roller's peak pressure and
stresses, are those of its own exact solve (kept as :attr:`BearingSolution.roller`);
the polish's remaining residual, below 1e-9, is reported
(:attr:`BearingSolution.law_error`).

Tilting moment and misalignment
-------------------------------
A tilt theta of the inner ring in the load plane adds :math:`\theta x\cos\psi_j` to
roller j's approach along its axis x: the rings are misaligned by
:math:`\phi_j = \theta\cos\psi_j` at roller j, which is free to tilt between its two
slice contacts (force and moment balance, :mod:`linecontact.raceway`) and carries
:math:`Q_j, M_j`; the ring carries :math:`F_r = \sum Q_j\cos\psi_j`,
:math:`M = \sum M_j\cos\psi_j`. Given M, (delta_r, theta) are solved (2 DOF); given
theta, delta_r (1 DOF). One Newton iteration on all unknowns (each distinct roller's
inner depth and tilt, and the ring's) with the slice model's exact 2x2 contact
matrices; the bearing's stiffness matrix is
:math:`K = \sum_j \cos^2\psi_j\,(K_{in}^{-1} + K_{out}^{-1})^{-1}`
= d(F_r, M)/d(delta_r, theta), exact for the discrete equations (docs/bearings.md).

Stribeck's result
-----------------
For :math:`Q = K\delta^n` and the load-zone parameter
:math:`\varepsilon = \tfrac12(1 - P_d/(2\delta_r))`, the continuous load zone gives
:math:`Q_{max} = F_r/(Z J_r(\varepsilon))` (:func:`load_zone_integral`);
:math:`J_r(0.5) = 0.2448` for n = 10/9: :math:`Z Q_{max}/F_r \to 4.08` for many rollers.

Rating life
-----------
ISO 281:2007's basic dynamic load rating :math:`C_r` (:func:`dynamic_load_rating`) and
basic rating life :math:`L_{10} = (C_r/P_r)^{10/3}` (:func:`basic_rating_life`), and the
basic reference rating life of ISO 16281:2025 (which replaced ISO/TS 16281:2008; the
lamina method for roller bearings, :func:`reference_rating_life`), both in
:math:`10^6` revolutions.

References
----------
.. [1] R. Stribeck, "Kugellager fuer beliebige Belastungen", Z. VDI 45 (1901) 73-125.
.. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press (2007),
   load distribution in radially loaded bearings (the integral J_r(epsilon)).
.. [3] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life.
.. [4] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for
   calculating the modified reference rating life for universally loaded rolling
   bearings.
"""
from __future__ import annotations

from . import fits, flanges, lubrication, spectrum
from .fits import (STEEL_EXPANSION, fit_pressure, inner_raceway_expansion,
                   operating_clearance, outer_raceway_contraction,
                   thermal_clearance_change)
from .flanges import SHARE_RULES, FlangeContacts, axial_load_shares, flange_contacts
from .lubrication import (DEFAULT_FILM_FORMULA, FILM_FORMULAS, cage_speed,
                          central_film_pan_hamrock, ehl_parameters, entrainment_speed,
                          film_ratio, minimum_film_dowson_higginson,
                          minimum_film_pan_hamrock, minimum_film_thickness,
                          rated_viscosity, viscosity_ratio)
from .radial import (GRID_POINTS, MAX_SLICES, PROFILED_POINTS, SLICE_COUNT,
                     BearingSolution, RadialRollerBearing, load_zone_integral)
from .ratings import (A_ISO_CAP, KAPPA_RANGE, PERMISSIBLE_PRESSURE, RELIABILITY_FACTORS,
                      ROLLER_COUNT, ReferenceLife, basic_rating_life, dynamic_load_rating,
                      fatigue_load_limit, lamina_load_ratings, life_modification_factor,
                      max_rollers,
                      modified_rating_life, modified_reference_rating_life,
                      pressure_safety_factor, reference_equivalent_load,
                      reference_rating_life, reliability_factor, roller_damage_shares,
                      static_equivalent_load,
                      static_load_rating, static_safety_factor)
from .spectrum import (LIFE_KINDS, DutyCycle, LoadCase, SpectrumSolution, duty_cycle_life,
                       revolution_shares, solve_spectrum)

__all__ = [
    # load distribution (radial.py)
    "RadialRollerBearing",
    "BearingSolution",
    "load_zone_integral",
    "GRID_POINTS",
    "PROFILED_POINTS",
    # ratings (ratings.py): ISO 281, ISO 16281, ISO 76, life modification
    "dynamic_load_rating",
    "max_rollers",
    "ROLLER_COUNT",
    "SLICE_COUNT",
    "MAX_SLICES",
    "basic_rating_life",
    "reference_rating_life",
    "lamina_load_ratings",
    "roller_damage_shares",
    "static_load_rating",
    "static_equivalent_load",
    "static_safety_factor",
    "pressure_safety_factor",
    "PERMISSIBLE_PRESSURE",
    "life_modification_factor",
    "fatigue_load_limit",
    "reliability_factor",
    "modified_rating_life",
    "reference_equivalent_load",
    "modified_reference_rating_life",
    "ReferenceLife",
    "A_ISO_CAP",
    "KAPPA_RANGE",
    "RELIABILITY_FACTORS",
    # lubrication (lubrication.py): EHL film, kinematics, viscosity ratio
    "minimum_film_thickness",
    "minimum_film_pan_hamrock",
    "central_film_pan_hamrock",
    "minimum_film_dowson_higginson",
    "ehl_parameters",
    "film_ratio",
    "entrainment_speed",
    "cage_speed",
    "rated_viscosity",
    "viscosity_ratio",
    "DEFAULT_FILM_FORMULA",
    "FILM_FORMULAS",
    # duty cycle (spectrum.py)
    "solve_spectrum",
    "LoadCase",
    "SpectrumSolution",
    "LIFE_KINDS",
    "duty_cycle_life",
    "revolution_shares",
    "DutyCycle",
    # operating clearance (fits.py)
    "fit_pressure",
    "inner_raceway_expansion",
    "outer_raceway_contraction",
    "thermal_clearance_change",
    "operating_clearance",
    "STEEL_EXPANSION",
    # flanges of NJ / NUP bearings (flanges.py)
    "axial_load_shares",
    "flange_contacts",
    "FlangeContacts",
    "SHARE_RULES",
]


# An unknown keyword names the valid ones and the close match (docs/inputs.md); the
# classes are wrapped in place, the functions here, where users import them.
