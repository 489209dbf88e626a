r"""Tangential contact of any model: full stick, Cattaneo-Mindlin partial slip, fretting.

The method of dimensionality reduction (Popov & Hess 2015, chapter 4) gives every
normal-contact law F(d) a tangential companion from the normal law alone: the full-stick
stiffness :math:`k_t = (G^*/E^*)\,k_n(d)`, the Cattaneo-Mindlin partial-slip law up to
gross slip, the Masing unloading and reloading branches and the energy dissipated per
fretting cycle (:mod:`~linecontact.tangential.laws`, where the assumptions and the
cases in which they are exact are stated). For the finite cylinder, whose full-stick
stiffness depends on the direction of the shift, ``method="bem"`` takes the ratio (and
a partial-slip correction) from the boundary-element table
``tables/tangential_cylinder.csv``; docs/tangential.md gives the plain MDR's measured
error. All functions take SI units (m, N, Pa) and broadcast over numpy arrays.

Modules: :mod:`~linecontact.tangential.moduli` (G*, the shear ratio G*/E*),
:mod:`~linecontact.tangential.laws` (the laws as functions of a model),
:mod:`~linecontact.tangential.contact` (:class:`TangentialContact`: one normal state
under tangential load), :mod:`~linecontact.tangential.cylinder_table` (the finite
cylinder's BEM table and its ratios). Every public name is importable from
:mod:`linecontact.tangential` itself.

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapters 3-4.
.. [2] C. Cattaneo, Sul contatto di due corpi elastici: distribuzione locale degli
   sforzi, Rend. Accad. Naz. Lincei 27 (1938) 342-348, 434-436, 474-478.
.. [3] R. D. Mindlin, Compliance of elastic bodies in contact, J. Appl. Mech. 16
   (1949) 259-268.
.. [4] R. D. Mindlin, H. Deresiewicz, Elastic spheres in contact under varying oblique
   forces, J. Appl. Mech. 20 (1953) 327-344.
.. [5] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 7.
.. [6] L. E. Goodman, Contact stress analysis of normally loaded rough spheres, J. Appl.
   Mech. 29 (1962) 515-522.
"""
from __future__ import annotations

from .contact import TangentialContact
from .cylinder_table import (STRAIGHT_CYLINDER_MODELS, TANGENTIAL_TABLE,
                             CylinderTangentialTable, cylinder_stiffness_ratios,
                             cylinder_tangential_table)
from .laws import (FRICTION, gross_slip_shift, tangential_force, tangential_shift,
                   tangential_stiffness)
from .moduli import (SHEAR_RATIO, effective_shear_modulus, equivalent_poisson,
                     mdr_stiffness_ratio, shear_modulus, shear_ratio)

__all__ = [
    "shear_modulus",
    "effective_shear_modulus",
    "shear_ratio",
    "equivalent_poisson",
    "mdr_stiffness_ratio",
    "gross_slip_shift",
    "tangential_stiffness",
    "tangential_force",
    "tangential_shift",
    "TangentialContact",
    "CylinderTangentialTable",
    "cylinder_tangential_table",
    "cylinder_stiffness_ratios",
    "STRAIGHT_CYLINDER_MODELS",
    "TANGENTIAL_TABLE",
    "SHEAR_RATIO",
    "FRICTION",
]
