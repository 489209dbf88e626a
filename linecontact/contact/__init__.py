r"""One roller contact described completely, its parts composed: the library's front door.

A :class:`Contact` is built from four parts and answers every question about it:

- the **roller** (:class:`Roller`): radius or diameter, length, axial profile (a crown
  radius is a circular profile), tilt (a number, 0 by default: aligned; or ``"free"``:
  moment equilibrium);
- the **counter-body**: :class:`Flat`, :class:`Convex` or :class:`Concave` (a radius or a
  diameter), or the inner and outer raceway of a radial bearing
  (:class:`~linecontact.raceway.Raceways`: the whole roller, two contacts in series);
- the **materials**: :class:`Elastic` roller and counter-body (a rigid one has an
  infinite modulus), or one of them :class:`Viscoelastic` against an elastic one, or
  simply the effective modulus ``estar``;
- the **loading**, given to the methods: a normal force or depth
  (:meth:`Contact.normal`), a tangential force or shift with a friction coefficient
  (:meth:`Contact.tangential`), a time history (:meth:`Contact.creep`,
  :meth:`Contact.relaxation_history`).

Each output is computed from that combination: a profiled roller by coupled slices
(:mod:`linecontact.roller`), a straight aligned one by a contact law
(:mod:`linecontact.models`, the universal curve by default); the tangential law of a
contact from its own normal law F(d) by the method of dimensionality reduction
(:mod:`linecontact.tangential`: :math:`k_t = (G^*/E^*)\,k_n`,
:math:`F_t(u) = \mu[F(d) - F(d - G^* u/(\mu E^*))]`); creep and relaxation from the same
law by Lee & Radok's correspondence (:mod:`linecontact.viscoelastic`); the whole roller
between raceways from its two contacts (:mod:`linecontact.raceway`). An output the
physics or the methods here do not define for a combination is refused: a result field
is None and :meth:`ContactResult.get` raises :class:`~linecontact.errors.CombinationError`
with the reason, and a combination that defines nothing is refused when the
:class:`Contact` is built or the method called. The depth of a contact is its approach
at the roller's centre (x = 0); ``approach`` is measured from first contact (they differ
for a tilted roller).

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
   Friction, Springer (2015), chapters 3-4 (tangential law from the normal law).
.. [2] E. H. Lee, J. R. M. Radok, The contact problem for viscoelastic bodies, J. Appl.
   Mech. 27 (1960) 438-444.
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   4.2 (two cylinders), 7 (tangential loading).
"""
from __future__ import annotations

from ..raceway import Raceways
from .contact import Contact
from .parts import FREE, Concave, Convex, Elastic, Flat, Roller, Viscoelastic
from .results import ContactResult, CreepResult, TangentialResult

__all__ = [
    "Roller",
    "Flat",
    "Convex",
    "Concave",
    "Raceways",
    "Elastic",
    "Viscoelastic",
    "Contact",
    "ContactResult",
    "TangentialResult",
    "CreepResult",
    "FREE",
]


# An unknown keyword names the valid ones and the close match (docs/inputs.md); the
# classes are wrapped in place, so once here covers the three modules.
