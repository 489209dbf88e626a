r"""Tangential contact of any model: full stick, Cattaneo-Mindlin partial slip, fretting.

The method of dimensionality reduction (Popov & Hess 2015, chapter 4) gives every
normal-contact law F(d) a tangential companion. The 1D springs of the MDR profile carry
a tangential stiffness :math:`G^*\,dx` besides the normal one :math:`E^*\,dx`, with

.. math::

    \frac{1}{G^*} = \frac{2-\nu_1}{4G_1} + \frac{2-\nu_2}{4G_2}, \qquad
    G_i = \frac{E_i}{2(1+\nu_i)},

and each spring sticks while :math:`G^*|u(x)| \le \mu E^*(d - g(x))`. With the shear
ratio :math:`r = G^*/E^*` and the friction coefficient :math:`\mu` this gives, from the
normal law alone (no profile needed):

- full stick: :math:`k_t = r\,k_n(d)`;
- monotonic shift u at constant normal depth d (Cattaneo 1938, Mindlin 1949):
  :math:`F_t(u) = \mu\,[F(d) - F(d - r u/\mu)]` up to gross slip at
  :math:`u^* = \mu d/r`, where :math:`F_t = \mu F(d)`; at constant normal force the
  same law holds at :math:`d = d(F)` (the normal and tangential problems are
  uncoupled, Goodman's approximation);
- unloading from :math:`(u_0, F_0)` and reloading by the Masing rule
  (Mindlin & Deresiewicz 1953): :math:`F_t = F_0 - 2 f((u_0 - u)/2)` and
  :math:`F_t = -F_0 + 2 f((u_0 + u)/2)`, f the monotonic law;
- energy dissipated per full cycle of amplitude :math:`u_0` (fretting):
  :math:`W = 8\int_0^{u_0} f(s)\,ds - 4 u_0 f(u_0)`.

Where these are exact, and where not
------------------------------------
Exact for axisymmetric contacts (a sphere gives Mindlin's and Mindlin-Deresiewicz's
results, which the tests check) under the Cattaneo-Mindlin assumptions: the normal
and tangential problems uncoupled (exact for elastically similar bodies, or with
:math:`(1-2\nu_1)/G_1 = (1-2\nu_2)/G_2`; for a rigid indenter on a compressible body it
is Goodman's approximation) and the slip parallel to the load. At :math:`\nu = 0`
(:math:`G^* = E^*`) the tangential kernel equals the normal one and the laws hold
exactly for *any* shape. For an elongated contact (a finite roller) the true full-stick
stiffness depends on the direction of the shift; ``method="bem"`` reads it from the
boundary-element table ``tables/tangential_cylinder.csv`` (across the axis, the
rolling direction, and along it), and the partial-slip law then uses that stiffness
ratio in place of :math:`G^*/E^*` (and the table's partial-slip correction, if the
table carries one). See docs/tangential.md for the measured error of the plain MDR.

All functions take SI units (m, N, Pa) and broadcast over numpy arrays.

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
