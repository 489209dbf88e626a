r"""The three stress measures: maximum shear (Tresca), von Mises, orthogonal shear.

Measures: the maximum shear (Tresca) :math:`(\sigma_1 - \sigma_3)/2` over the three
principal stresses, the von Mises stress
:math:`\sqrt{\tfrac12[(\sigma_1-\sigma_2)^2 + (\sigma_2-\sigma_3)^2 +
(\sigma_3-\sigma_1)^2]}`, and the orthogonal shear :math:`|\tau_{yz}|` (its amplitude
under rolling; Lundberg & Palmgren 1947).

The measures of the plane-strain strip are the properties of
:class:`~linecontact.stresses.strip.StripStresses`; :func:`stress_measures` takes
the six components of a 3D stress state.

References
----------
.. [1] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
.. [2] G. Lundberg, A. Palmgren, "Dynamic capacity of rolling bearings", Acta
   Polytechnica, Mech. Eng. Ser. 1 (1947) no. 3.
"""
from __future__ import annotations

import numpy as np

__all__ = ["MEASURES", "stress_measures"]

#: the three stress measures, in the order they are reported
MEASURES = ("tresca", "von_mises", "orthogonal_shear")


def stress_measures(sigma_x, sigma_y, sigma_z, tau_xy, tau_xz, tau_yz):
    r"""Tresca (maximum) shear, von Mises stress and orthogonal shear of 3D stress states.

    .. math::

        \tau_{\max} = \frac{\sigma_1 - \sigma_3}{2},\qquad
        \sigma_{vM} = \sqrt{\tfrac12[(\sigma_x - \sigma_y)^2 + (\sigma_y - \sigma_z)^2
        + (\sigma_z - \sigma_x)^2] + 3(\tau_{xy}^2 + \tau_{xz}^2 + \tau_{yz}^2)},
        \qquad \tau_{orth} = |\tau_{yz}|

    with :math:`\sigma_1 \ge \sigma_2 \ge \sigma_3` the principal stresses (x along
    the roller axis, y across the contact, z into the body); the one home of these
    measures for the runtime's 3D correction and the 3D reference field (tools/bem).

    Parameters
    ----------
    sigma_x, sigma_y, sigma_z : array_like
        Normal stresses [Pa].
    tau_xy, tau_xz, tau_yz : array_like
        Shear stresses [Pa].

    Returns
    -------
    dict
        ``tresca``, ``von_mises``, ``orthogonal_shear`` arrays of the broadcast
        shape [Pa].

    Notes
    -----
    Valid for any finite stresses, -inf < sigma, tau < inf.

    Examples
    --------
    Uniaxial tension of 100 MPa: maximum shear 50 MPa, von Mises 100 MPa.

    >>> m = stress_measures(100e6, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> f"{float(m['tresca']) / 1e6:.1f} {float(m['von_mises']) / 1e6:.1f}"
    '50.0 100.0'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), sections 4.2 and 7.2.
    """
    sx, sy, sz, txy, txz, tyz = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (sigma_x, sigma_y, sigma_z, tau_xy,
                                                tau_xz, tau_yz)))
    return {name: _measure_3d(name, sx, sy, sz, txy, txz, tyz) for name in MEASURES}


def _measure_3d(name, sx, sy, sz, txy, txz, tyz):
    """One of :data:`MEASURES` of broadcast 3D stress components (stress_measures)."""
    if name == "tresca":
        T = np.empty(np.shape(sx) + (3, 3))
        T[..., 0, 0], T[..., 1, 1], T[..., 2, 2] = sx, sy, sz
        T[..., 0, 1] = T[..., 1, 0] = txy
        T[..., 0, 2] = T[..., 2, 0] = txz
        T[..., 1, 2] = T[..., 2, 1] = tyz
        ev = np.linalg.eigvalsh(T)
        return 0.5 * (ev[..., -1] - ev[..., 0])
    if name == "von_mises":
        return np.sqrt(np.maximum(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2)
                                  + 3 * (txy ** 2 + txz ** 2 + tyz ** 2), 0.0))
    return np.abs(tyz)
