r"""Subsurface stresses below a line contact and along a profiled roller (plane strain).

A Hertz strip |y| <= b carries the pressure :math:`p(y) = p_0\sqrt{1 - y^2/b^2}` and a
sliding traction :math:`q(y) = \mu\, p(y)` in +y (the rolling direction, acting on the
body below). With depth z >= 0 into the body (McEwen 1949; Johnson 1985, section 4.2
for the pressure, section 7.2 for the traction)

.. math::

    m^2 = \tfrac12\left[\sqrt{(b^2 - y^2 + z^2)^2 + 4y^2z^2} + (b^2 - y^2 + z^2)\right],
    \quad
    n^2 = \tfrac12\left[\sqrt{(b^2 - y^2 + z^2)^2 + 4y^2z^2} - (b^2 - y^2 + z^2)\right],

m, n >= 0 with sign(n) = sign(y), :math:`D = m^2 + n^2`, the pressure gives

.. math::

    \sigma_y = -\frac{p_0}{b}\left[m\left(1 + \frac{z^2 + n^2}{D}\right) - 2z\right],\quad
    \sigma_z = -\frac{p_0}{b}\, m\left(1 - \frac{z^2 + n^2}{D}\right),\quad
    \tau_{yz} = -\frac{p_0}{b}\, n\,\frac{m^2 - z^2}{D},

and the traction (:math:`q_0 = \mu p_0`)

.. math::

    \sigma_y = \frac{q_0}{b}\left[n\left(2 - \frac{z^2 - m^2}{D}\right) - 2y\right],\quad
    \sigma_z = \frac{q_0}{b}\, n\,\frac{z^2 - m^2}{D},\quad
    \tau_{yz} = -\frac{q_0}{b}\left[m\left(1 + \frac{z^2 + n^2}{D}\right) - 2z\right],

and in plane strain :math:`\sigma_x = \nu(\sigma_y + \sigma_z)` (x along the roller).
Compression is negative. Printings of these formulas differ in their signs; every
component and sign here was checked against a direct numerical integration of the
Flamant (normal) and 2D Cerruti (tangential) line-load solutions (Johnson 1985,
Eqs. 2.15 and 2.19) to 1e-13 (tests/test_stresses.py).

Measures: the maximum shear (Tresca) :math:`(\sigma_1 - \sigma_3)/2` over the three
principal stresses, the von Mises stress
:math:`\sqrt{\tfrac12[(\sigma_1-\sigma_2)^2 + (\sigma_2-\sigma_3)^2 +
(\sigma_3-\sigma_1)^2]}`, and the orthogonal shear :math:`|\tau_{yz}|` (its amplitude
under rolling; Lundberg & Palmgren 1947).

Along a roller: a straight or profiled roller solved by coupled slices
(:mod:`linecontact.roller`) is a row of strips; slice k carries the line load q_k over
the half-width b_k, so :math:`p_{0,k} = 2q_k/(\pi b_k)` and its field is the strip
field scaled by p_{0,k} and b_k. The field is self-similar: the maxima are computed once
per (mu, nu) on the unit strip (a grid search refined by a bounded optimiser) and
scaled per slice, so the stresses of a whole roller cost microseconds. Where the load
varies along the roller (a crown, a relief, a tilt) the field is three-dimensional and
the strips are up to 5 % low; the worst of each measure therefore gets a 3D
correction: below the worst slices, McEwen's strip of the slice plus the 3D field of
the difference between the slices' Hertz pressures and that strip extended to
infinity, from Love's uniformly loaded rectangles (:func:`rectangle_stresses`;
Love 1929) on a grid of 24 cells across and one cell per slice along (one per slice
and across beyond 8 b). Its error against a 3D field (Love's and Cerruti's rectangles
below a 3D boundary-element pressure, tools/bem/stress.py) is measured in
tables/stress_accuracy.csv (tools/studies/stress_study.py) and stated in each
result's ``error`` and notes.

Case-hardening check: the stress envelope against depth (the largest over y at each
depth, since rolling sweeps every y past a material point) over the local allowable of
a hardness profile (:class:`HardnessProfile`), with the yield strength of steel from
its Vickers hardness by the correlation of Pavlina & Van Tyne (2008),
:math:`\sigma_{Y} = 2.876\,HV - 90.7` MPa; the allowable is sigma_Y for von Mises and
sigma_Y/2 for Tresca (the yield criteria themselves). See docs/stresses.md.

Modules: :mod:`~linecontact.stresses.strip` (McEwen's strip: its field and maxima),
:mod:`~linecontact.stresses.measures` (Tresca, von Mises, orthogonal shear),
:mod:`~linecontact.stresses.love` (Love's rectangles and their corner sums, in numpy and
the optional C extension), :mod:`~linecontact.stresses.search` (the 3D correction's
worst point), :mod:`~linecontact.stresses.accuracy` (the measured error each result
states), :mod:`~linecontact.stresses.results` (:class:`SubsurfaceStresses`),
:mod:`~linecontact.stresses.along_roller` (:func:`line_contact_stresses`,
:func:`roller_stresses`), :mod:`~linecontact.stresses.hardening` (the case-hardening
check). Every public name is importable from :mod:`linecontact.stresses` itself.

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
from .along_roller import line_contact_stresses, roller_stresses
from .hardening import CaseCheck, HardnessProfile, case_check, yield_strength_from_hardness
from .love import rectangle_stresses
from .measures import MEASURES, stress_measures
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
]
