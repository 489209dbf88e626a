r"""Profiled and tilted rollers on a flat: coupled slices with Hertz strips (runtime model).

A rigid roller (radius R across its axis, length L, axis x, |x| <= L/2) with a profile
drop P(x) (:mod:`linecontact.profiles`) and a tilt theta is pressed by a depth d into an
elastic half-space of effective modulus E*; the gap is

.. math:: h(x, y) = \frac{y^2}{2R} + P(x) - \theta x .

On a raceway, R is the effective radius across the axis (1/R = 1/R_roller + 1/R_race,
the race radius negative for an outer ring) and the profile drops of both bodies add.

Method (coupled slices)
-----------------------
The roller is cut into n slices of widths w_k centred at x_k (spanning the rigid
overlap interval, graded towards its ends where the pressure varies fastest:
:class:`ProfiledRoller`'s ``grading``). Slice k carries a line
load q_k spread across y as a Hertz (semi-elliptical) strip of half-width b_k,

.. math:: p(x, y) = \frac{2 q_k}{\pi b_k}\sqrt{1 - y^2/b_k^2},
          \qquad |x - x_k| < w/2,

and the two unknowns (q_k, b_k) of each loaded slice satisfy two conditions on its
centre line, with the surface displacement u of the whole pressure field (Boussinesq,
:math:`u = (\pi E^*)^{-1}\iint p/r\,dA`):

.. math::

    u(x_k, 0) = d + \theta x_k - P(x_k), \qquad
    \frac{\partial^2 u}{\partial y^2}(x_k, 0) = -\frac{1}{R}.

The influence of strip i on slice k is exact for the semi-elliptical strip, not a
point-load approximation:

.. math::

    u(x_k, 0) = \sum_i \frac{q_i}{\pi E^*}\left[a(\tau^+_{ki}) - a(\tau^-_{ki})\right],
    \qquad a(\tau) = \frac{4}{\pi}\int_0^1 \sqrt{1 - s^2}\,
                     \operatorname{asinh}\frac{\tau}{s}\,ds,

    \frac{\partial^2 u}{\partial y^2}(x_k, 0) = \sum_i \frac{q_i}{\pi E^* b_i^2}
    \left[\hat p(\tau^+_{ki}) - \hat p(\tau^-_{ki}) - 4\delta_{ki}\right],

with :math:`\tau^\pm_{ki} = (x_k - x_i \pm w_i/2)/b_i` and :math:`\hat p` the y-average
over the strip of the curvature of :math:`\int dx'/r` (module function
:func:`strip_influence`). The term :math:`-4\delta_{ki}` is the 2D Hertz curvature of the
strip's own (infinite) line contact, :math:`-4q/(\pi E^* b^2) = -1/R` in plane strain
(Johnson 1985, section 4.3); the rest corrects it for the strip's finite length and
adds the neighbours. For a circular crown this discretises the exact Hertz solution
(whose cross-sections are semi-ellipses), so it converges to it as w -> 0; with the
curvature condition replaced by the 2D relation :math:`b_k^2 = 4Rq_k/(\pi E^*)` it
would be the classical slice model with influence coefficients (Reusner 1977; de Mul,
Kalker & Fredriksson 1986; Teutsch & Sauer 2004; Fujiwara & Kawase 2006), which
converges to a contact off exact Hertz by 0.4-0.9 % in p0, 0.4-1.1 % in b and 0.07-0.2 %
in the approach for the crowns of the tests (measured with this code; 2D instead of 3D
curvature of the cross-sections).

The complementarity conditions (q_k >= 0, no interpenetration where q_k = 0) are solved
by Newton's method on (q_k, q_k/b_k^2) with an active set; with the force (and zero
moment) imposed, d (and theta) join the same Newton iteration (a bordered system), and
the stiffness matrix is the implicit derivative of the converged equations (at a
force, of the state the last Newton step started from: within about 3e-7 relative).

Accuracy (measured, tests/test_roller.py and docs/profiled_rollers.md; at the default
50 slices graded 0.8, tools/benchmarks/bench_roller_default_slices.py ``--exact``):
circular crown against exact Hertz within 0.02 % in approach, p0 and stiffness,
0.08 % in b and 0.26 % in the contact half-length, converging at second order in the
slice width; a straight roller within 0.26 % of the universal curve for d R/L^2 <=
4e-3 (0.53 % for a short, deeply pressed roller, L/R = 0.2 at d R/L^2 = 0.04),
approaching it from below (the end singularity).

Edge loading: on a half-space the pressure at a sharp roller end touched by the contact
is singular (a rigid flat-ended punch, Johnson 1985 section 5.6); the per-slice peak
there grows without bound as the slices are refined. The solution then reports
``edge_loaded = True`` and ``p_max = None`` with a message, never a grid-dependent
number. Where the profile's drop is infinite at the ends (ISO 16281, Lundberg) the
contact stays microns inside them and the pressure stays finite: the overlap
interval's end is located between the last grid point and the end, and where the peak
is still unresolved the end slices are refined until it settles (within 0.83 % of a
3D BEM on 8192 cells along the axis in the worst case measured; docs/
profiled_rollers.md, "Slice convergence").

Measured range: ``tables/roller_accuracy.csv`` (tools/studies/roller_study.py) maps this
model's error against a 3D boundary-element solution over L/D, the mean line load
q/(E* D) (D = 2R), the tilt, the tilt's drop over the approach and the profile; its
header states that range as data (``covered_*`` fields) and the largest errors inside it
(``runtime_error_*``). Every coupled-slice solution carries a note (``notes``) that
states those errors when the case lies inside the range, or names the quantity outside
it (read once, on the first solve).

Modules
-------
``kernel``     the strip influence functions (:func:`strip_influence`)
``slices``     the slice equations, their Newton / active-set solver, the stiffness matrix
``_cengine``   the same kernels, linearisation and Newton-step arithmetic in C (the
               extension ``linecontact._ckernels``, built at install where a C compiler
               exists; ``ProfiledRoller(engine=...)``: ``"c"``, the default's choice
               there; :mod:`linecontact._engine`, docs/profiled_rollers.md, "Engines")
``_layout``    the geometry and spline table as the C engine reads them
``coverage``   the note on where a case lies against tables/roller_accuracy.csv
``solution``   :class:`RollerSolution`, contact extent and peak pressure off the slices
``model``      :class:`ProfiledRoller`, :func:`roller_contact` (depth, force, free tilt)
``iso``        :func:`iso_slicing` (ISO 16281, uncoupled slices)
``laws``       :class:`ProfiledRollerModel`, :class:`ISOSlicingModel` (registered laws)
``solvers``    :func:`~linecontact.roller.solvers.slice_solver`: the one factory from a
               slice model's name to a contact's solver, with the default slice counts

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   3.2 (Boussinesq), 4.2 (Hertz), 4.3 (line contact), 5.6 (end effects).
.. [2] H. Reusner, "Druckflaechenbelastung und Oberflaechenverschiebung im
   Waelzkontakt von Rotationskoerpern", Dissertation, Karlsruhe (1977).
.. [3] J. M. de Mul, J. J. Kalker, B. Fredriksson, "The contact between arbitrarily
   curved bodies of finite dimensions", J. Tribology 108 (1986) 140-148.
.. [4] R. Teutsch, B. Sauer, "An alternative slicing technique to consider pressure
   concentrations in non-Hertzian line contacts", J. Tribology 126 (2004) 436-442.
.. [5] H. Fujiwara, T. Kawase, "Logarithmic profiles of rollers in roller bearings and
   optimization of the profiles", Proc. JSME C 72 (2006) 3022-3029.
.. [6] ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified
   reference rating life for universally loaded rolling bearings (slicing method).
"""
from __future__ import annotations

from .iso import ISO_MIN_SLICES, iso_slicing
from .kernel import strip_influence
from .laws import ISOSlicingModel, ProfiledRollerModel
from .model import ProfiledRoller, roller_contact
from .slices import N_SLICES, TILT_RANGE, ConvergenceError
from .solution import RollerSolution

__all__ = [
    "RollerSolution",
    "ProfiledRoller",
    "roller_contact",
    "iso_slicing",
    "ProfiledRollerModel",
    "ISOSlicingModel",
    "strip_influence",
    "ConvergenceError",
    "N_SLICES",
    "ISO_MIN_SLICES",
    "TILT_RANGE",
]
