r"""Shear moduli of the tangential contact: G*, the shear ratio G*/E*, and back.

With the method of dimensionality reduction the tangential springs have the
stiffness :math:`G^*\,dx` besides the normal :math:`E^*\,dx`:

.. math::

    \frac{1}{G^*} = \frac{2-\nu_1}{4G_1} + \frac{2-\nu_2}{4G_2}, \qquad
    G_i = \frac{E_i}{2(1+\nu_i)},

and the shear ratio :math:`r = G^*/E^*` lies in [2/3, 1] for Poisson ratios in
[0, 0.5] (:data:`SHEAR_RATIO`).

References
----------
.. [1] V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics
   and Friction, Springer (2015), chapters 3-4.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section 7.
"""
from __future__ import annotations

import numpy as np

from .._numerics import out
from ..checks import POISSON_RATIO, Interval, check_positive, document
from ..classical import MODULUS_OR_RIGID, effective_modulus, two_bodies

__all__ = [
    "shear_modulus",
    "effective_shear_modulus",
    "shear_ratio",
    "equivalent_poisson",
    "mdr_stiffness_ratio",
    "SHEAR_RATIO",
]

#: G*/E* for Poisson ratios in [0, 0.5]: 2(1-nu)/(2-nu) lies in [2/3, 1].
SHEAR_RATIO = Interval("gstar/estar", 2.0 / 3.0, 1.0, unit="", rtol=1e-12)


@document(E=MODULUS_OR_RIGID, NU=POISSON_RATIO)
def shear_modulus(modulus, poisson):
    r"""Shear modulus of an isotropic elastic body, :math:`G = E/(2(1+\nu))`.

    Parameters
    ----------
    modulus : float or array_like
        Young's modulus E, ``inf`` for a rigid body [Pa].
    poisson : float or array_like
        Poisson ratio nu [-].

    Returns
    -------
    float or ndarray
        G [Pa].

    Notes
    -----
    Valid for %(E)s and %(NU)s.

    Examples
    --------
    >>> f"{shear_modulus(210e9, 0.3) / 1e9:.2f} GPa"
    '80.77 GPa'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), section 2.
    """
    E = MODULUS_OR_RIGID.check(modulus, name="modulus")
    nu = POISSON_RATIO.check(poisson, name="poisson")
    return out(E / (2.0 * (1.0 + nu)))


@document(E=MODULUS_OR_RIGID, NU=POISSON_RATIO)
def effective_shear_modulus(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    r"""Effective tangential modulus G* of two bodies (Popov & Hess 2015, chapter 4).

    .. math::
        \frac{1}{G^*} = \frac{2-\nu_1}{4G_1} + \frac{2-\nu_2}{4G_2}, \qquad
        G_i = \frac{E_i}{2(1+\nu_i)}

    Parameters
    ----------
    modulus1 : float or array_like
        Young's modulus E1 of the first body [Pa].
    poisson1 : float or array_like
        Poisson ratio nu1 of the first body [-].
    modulus2 : float or array_like, optional
        Young's modulus E2 of the second body, ``inf`` (default) for a rigid body [Pa].
    poisson2 : float or array_like, optional
        Poisson ratio nu2 of the second body; required with a finite `modulus2` (as in
        :func:`linecontact.classical.effective_modulus`), ignored for a rigid one [-].

    Returns
    -------
    float or ndarray
        G* [Pa]. For a rigid second body G* = 4 G1/(2 - nu1).

    Raises
    ------
    OutOfRangeError
        A modulus or Poisson ratio outside its range, a finite `modulus2` without
        `poisson2`, or both bodies rigid.

    Notes
    -----
    Valid for %(E)s (``inf`` = rigid) and %(NU)s for each body, not both rigid.
    With :func:`linecontact.classical.effective_modulus` the ratio G*/E* lies in
    [2/3, 1]; it is 2(1-nu)/(2-nu) for a rigid indenter (0.8235 at nu = 0.3).

    Examples
    --------
    Rigid roller on steel, and steel on steel:

    >>> f"{effective_shear_modulus(210e9, 0.3) / 1e9:.2f} GPa"
    '190.05 GPa'
    >>> f"{effective_shear_modulus(210e9, 0.3, 210e9, 0.3) / 1e9:.2f} GPa"
    '95.02 GPa'

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015); R. D. Mindlin, J. Appl. Mech. 16 (1949) 259-268.
    """
    E1, nu1, E2, nu2 = two_bodies(modulus1, poisson1, modulus2, poisson2)
    compliance = (2 - nu1) * (1 + nu1) / (2 * E1) + (2 - nu2) * (1 + nu2) / (2 * E2)
    return out(1.0 / compliance)


def shear_ratio(modulus1, poisson1, modulus2=np.inf, poisson2=None):
    r"""The MDR's shear ratio G*/E* of two bodies, :math:`2(1-\nu)/(2-\nu)` if one is rigid.

    .. math::
        \frac{G^*}{E^*} = \frac{(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2}
                               {(2-\nu_1)(1+\nu_1)/(2E_1) + (2-\nu_2)(1+\nu_2)/(2E_2)}

    Parameters
    ----------
    modulus1, modulus2 : float or array_like
        Young's moduli, ``inf`` for a rigid body (not both) [Pa].
    poisson1, poisson2 : float or array_like
        Poisson ratios in [0, 0.5] [-].

    Returns
    -------
    float or ndarray
        G*/E* in [2/3, 1] [-].

    Notes
    -----
    Valid for moduli in (0, inf] Pa and Poisson ratios in [0, 0.5]. It is 1 at
    nu = 0, where the tangential problem is the normal one.

    Examples
    --------
    >>> f"{shear_ratio(210e9, 0.3):.4f}", f"{shear_ratio(210e9, 0.0):.4f}"
    ('0.8235', '1.0000')

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015).
    """
    g = effective_shear_modulus(modulus1, poisson1, modulus2, poisson2)
    e = effective_modulus(modulus1, poisson1, modulus2, poisson2)
    return out(np.asarray(g) / np.asarray(e))


def equivalent_poisson(gstar, estar):
    r"""Poisson ratio of the one-body problem with the same G*/E*: :math:`2(1-r)/(2-r)`.

    .. math::
        r = \frac{G^*}{E^*} = \frac{2(1-\nu)}{2-\nu}
        \;\Longleftrightarrow\; \nu = \frac{2(1-r)}{2-r}

    In the uncoupled (Goodman) problem two bodies act as one half-space with
    :math:`1/G = \sum 1/G_i` and :math:`1-\nu = \sum[(1-\nu_i)/G_i] / \sum 1/G_i`
    (both the normal and the tangential Boussinesq-Cerruti kernels add up that way),
    and that body has the same G*/E*. This is the Poisson ratio at which the cylinder's
    BEM table is read.

    Parameters
    ----------
    gstar : float or array_like
        Effective shear modulus G* [Pa].
    estar : float or array_like
        Effective modulus E* [Pa].

    Returns
    -------
    float or ndarray
        The equivalent Poisson ratio [-], in [0, 0.5].

    Notes
    -----
    Valid for 2/3 <= G*/E* <= 1 (Poisson ratios of both bodies in [0, 0.5]).

    Examples
    --------
    >>> f"{equivalent_poisson(shear_ratio(210e9, 0.3), 1.0):.6f}"
    '0.300000'
    >>> f"{equivalent_poisson(shear_ratio(210e9, 0.3, 70e9, 0.33), 1.0):.4f}"
    '0.3226'

    References
    ----------
    L. E. Goodman, J. Appl. Mech. 29 (1962) 515-522; K. L. Johnson, Contact
    Mechanics (1985), section 7.1.
    """
    r = _ratio(gstar, estar)
    return out(2.0 * (1.0 - r) / (2.0 - r))


@document(NU=POISSON_RATIO)
def mdr_stiffness_ratio(poisson):
    r"""The MDR's full-stick k_t/k_n = G*/E* = 2(1-nu)/(2-nu) of one elastic body.

    .. math:: \frac{k_t}{k_n} = \frac{2(1-\nu)}{2-\nu}

    Parameters
    ----------
    poisson : float or array_like
        Poisson ratio nu (or :func:`equivalent_poisson` of two bodies) [-].

    Returns
    -------
    float or ndarray
        k_t/k_n [-].

    Notes
    -----
    Valid for %(NU)s. Exact for axisymmetric contacts; for an elongated one the
    true ratio depends on the direction (see :func:`cylinder_stiffness_ratios`).

    Examples
    --------
    >>> f"{mdr_stiffness_ratio(0.3):.4f}", f"{mdr_stiffness_ratio(0.0):.4f}"
    ('0.8235', '1.0000')

    References
    ----------
    V. L. Popov, M. Hess, Method of Dimensionality Reduction in Contact Mechanics and
    Friction, Springer (2015).
    """
    nu = POISSON_RATIO.check(poisson, name="poisson")
    return out(2.0 * (1.0 - nu) / (2.0 - nu))


def _ratio(gstar, estar):
    g = check_positive("gstar", gstar, "Pa")
    e = check_positive("estar", estar, "Pa")
    return SHEAR_RATIO.check(g / e, hint="G*/E* of bodies with Poisson ratios in [0, 0.5] "
                                         "(effective_shear_modulus, effective_modulus)")
