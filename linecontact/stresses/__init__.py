r"""Subsurface stresses below a line contact and along a profiled roller (plane strain).

McEwen's closed forms give the plane-strain field below a Hertz strip with a sliding
traction (:mod:`~linecontact.stresses.strip`), checked against a numerical integration
of the Flamant and Cerruti line loads to 1e-13 (tests/test_stresses.py); the maximum
shear (Tresca), von Mises stress and orthogonal shear are the measures reported
(:mod:`~linecontact.stresses.measures`). Along a roller solved by slices
(:mod:`linecontact.roller`) each slice is a strip scaled by its half-width b_k and peak
pressure :math:`p_{0,k} = 2q_k/(\pi b_k)`, so the maxima of a whole roller cost
microseconds. Where the load varies along the roller (a crown, a relief, a tilt) the
strips are up to 5 % low, and the worst of each measure gets a 3D correction from
Love's uniformly loaded rectangles (:mod:`~linecontact.stresses.love`,
:mod:`~linecontact.stresses.search`); its error against a 3D boundary-element field,
measured in tables/stress_accuracy.csv, is stated in each result
(:mod:`~linecontact.stresses.accuracy`). The case-hardening check compares the stress
envelope against depth with the allowable of a hardness profile
(:mod:`~linecontact.stresses.hardening`). See docs/stresses.md.

Modules: :mod:`~linecontact.stresses.strip` (McEwen's strip: its field and maxima),
:mod:`~linecontact.stresses.measures` (Tresca, von Mises, orthogonal shear),
:mod:`~linecontact.stresses.love` (Love's rectangles and their corner sums, in numpy and
the optional C extension), :mod:`~linecontact.stresses.search` (the 3D correction's
worst point), :mod:`~linecontact.stresses.accuracy` (the measured error each result
states), :mod:`~linecontact.stresses.results` (:class:`SubsurfaceStresses`),
:mod:`~linecontact.stresses.along_roller` (:func:`line_contact_stresses`,
:func:`roller_stresses`), :mod:`~linecontact.stresses.hardening` (the case-hardening
check), :mod:`~linecontact.stresses.raceways` (:func:`raceway_stresses`: a whole
roller's two contacts, the worse and the case check over both). Every public name is importable from :mod:`linecontact.stresses` itself.

References
----------
.. [1] E. McEwen, "Stresses in elastic cylinders in contact along a generatrix",
   Phil. Mag. 40 (1949) 454-459.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
.. [3] G. Lundberg, A. Palmgren, "Dynamic capacity of rolling bearings", Acta
   Polytechnica, Mech. Eng. Ser. 1 (1947) no. 3.
.. [4] E. J. Pavlina, C. J. Van Tyne, "Correlation of yield strength and tensile
   strength with hardness for steels", J. Materials Engineering and Performance 17
   (2008) 888-893.
.. [5] ISO 2639:2002, Steels - Determination and verification of the depth of
   carburized and hardened cases (effective case depth at 550 HV).
.. [6] A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on
   part of the boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
"""
from __future__ import annotations

from .accuracy import reaches_end, stress_accuracy  # noqa: F401 (stress_accuracy: the calculator's)
from .along_roller import EDGE_LOADED_STRESS, line_contact_stresses, roller_stresses
from .hardening import CaseCheck, HardnessProfile, case_check, yield_strength_from_hardness
from .love import rectangle_stresses
from .measures import MEASURES, stress_measures
from .raceways import RacewayCaseCheck, RacewayStresses, noted_case_check, raceway_stresses
from .results import SubsurfaceStresses
from .strip import StripMaxima, StripStresses, strip_maxima, strip_stresses

__all__ = [
    "MEASURES",
    "StripStresses",
    "strip_stresses",
    "StripMaxima",
    "strip_maxima",
    "rectangle_stresses",
    "stress_measures",
    "reaches_end",
    "SubsurfaceStresses",
    "line_contact_stresses",
    "roller_stresses",
    "HardnessProfile",
    "yield_strength_from_hardness",
    "CaseCheck",
    "case_check",
    "EDGE_LOADED_STRESS",
    "raceway_stresses",
    "RacewayStresses",
    "RacewayCaseCheck",
    "noted_case_check",
]
