r"""Axial load on the flanges of NJ and NUP cylindrical roller bearings.

An axial load F_a on a bearing with flanges (ribs) on both rings passes, roller by
roller, from the flange of one ring into one end of the roller and out of its other end
into the flange of the other ring: each loaded roller j carries an axial force
:math:`F_{a,j}` with :math:`\sum_j F_{a,j} = F_a` (:func:`axial_load_shares`).

Geometry (one plane through the bearing axis and the roller axis, x along the roller
axis, r radially outward): the roller ends are spherical, radius :math:`R_e`, centred
on the roller axis; the flange faces are inclined by the angle :math:`\theta` to the
radial plane (opening away from the roller). A sphere touches an inclined plane where
the sphere's normal is the plane's, so each end touches its flange at

.. math:: e = R_e\sin\theta

from the roller axis (towards the ring of that flange), at the height
:math:`D/2 - e` above the raceway, which must lie on the flange face. The normal force
of each contact, :math:`N = F_{a,j}/\cos\theta`, passes through its end's sphere centre;
the two contacts' forces are equal and opposite, a couple

.. math:: M = F_{a,j}\tan\theta\,(2R_e - l)

(l the roller's overall length between its end vertices) that tilts the roller in the
axial plane: for :math:`2R_e > l` it turns the inner-flange end towards the inner
raceway and the outer-flange end towards the outer raceway, and the raceway line
loads must shift along the roller to balance it (:func:`flange_contacts`).

Each contact is a Hertz point contact (:func:`linecontact.hertz.hertz_contact`) of the
end sphere with the flange face, whose curvature along the circumference
(:math:`\pm\sin\theta/\rho`, :math:`\rho` the contact's distance from the bearing axis)
is convex on the inner ring's flange and concave on the outer ring's.

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Advanced Concepts, chapter 1 (cylindrical roller bearings under combined
   radial and axial load; roller end-flange contact).
.. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007):
   Essential Concepts, chapter 6 (contact stress and deformation: roller end-flange
   contact stress).
.. [3] C. L. Karna, "Performance characteristics at the rib roller end contact in
   tapered roller bearings", ASLE Transactions 17 (1974) (the rib reaction and the
   Hertz stress of the spherical roller end on the rib, for tapered roller bearings).
.. [4] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), section
   4.2 (Hertz point contact).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._numerics import out
from ..checks import check_interval, check_positive
from ..errors import CombinationError, UnknownNameError
from ..hertz import hertz_contact

__all__ = ["SHARE_RULES", "axial_load_shares", "FlangeContacts", "flange_contacts"]

#: How the axial load is shared among the rollers (see :func:`axial_load_shares`).
SHARE_RULES = ("proportional", "equal")


def axial_load_shares(axial_load, roller_loads, rule="proportional"):
    r"""Axial force of each roller's flange contacts, summing to the bearing's axial load.

    .. math::

        F_{a,j} = F_a\,\frac{Q_j}{\sum_k Q_k}\ (\text{proportional}), \qquad
        F_{a,j} = \frac{F_a}{n_{loaded}}\ (Q_j > 0;\ \text{equal})

    Parameters
    ----------
    axial_load : float
        Axial load F_a of the bearing, 0 <= F_a < inf [N].
    roller_loads : array_like
        Radial roller loads Q_j of the load distribution, 0 <= Q_j < inf [N].
    rule : str, optional
        ``"proportional"`` (default) or ``"equal"`` (:data:`SHARE_RULES`).

    Returns
    -------
    ndarray
        F_a,j [N], one per roller, zero for the unloaded ones; they sum to F_a.

    Raises
    ------
    CombinationError
        An axial load with no radially loaded roller: the flange couple of each
        roller must be balanced by its raceway loads, so in this model only loaded
        rollers carry axial load.

    Notes
    -----
    A modelling assumption, not a result: each roller's flange couple
    (:func:`flange_contacts`) is reacted by its raceway contacts, whose capacity for
    it grows with the roller's load, hence the default share in proportion to Q_j
    (Harris & Kotzalas 2007 solve the rollers' tilt equilibrium instead);
    ``"equal"`` is the bound of stiff, evenly seated rollers.

    Examples
    --------
    >>> axial_load_shares(3000.0, [4000.0, 2000.0, 0.0, 2000.0])
    array([1500.,  750.,    0.,  750.])
    >>> axial_load_shares(3000.0, [4000.0, 2000.0, 0.0, 2000.0], rule="equal")
    array([1000., 1000.,    0., 1000.])

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Advanced Concepts, chapter 1.
    """
    Fa = float(check_interval("axial_load", axial_load, 0.0, np.inf, high_open=True,
                              unit="N"))
    Q = check_interval("roller_loads", roller_loads, 0.0, np.inf, high_open=True,
                       unit="N")
    if Q.ndim != 1:
        raise CombinationError({"roller_loads": f"shape {Q.shape}"},
                               "give one radial load per roller (a 1-D sequence)")
    if rule not in SHARE_RULES:
        raise UnknownNameError("rule", rule, SHARE_RULES)
    loaded = Q > 0.0
    if Fa == 0.0:
        return np.zeros(Q.shape)
    if not loaded.any():
        raise CombinationError({"axial_load": Fa, "roller_loads": "all 0"},
                               "no roller is loaded radially, so none can balance its "
                               "flange couple: give a radial load", unit=None)
    weight = Q if rule == "proportional" else loaded.astype(float)
    return Fa * weight / weight.sum()


@dataclass(frozen=True)
class FlangeContacts:
    """Roller end / flange contacts of every roller: forces, Hertz stress, tilting couple.

    Returned by :func:`flange_contacts`; arrays have one entry per roller (0 where the
    roller carries no axial force).

    .. math:: N = \\frac{F_a}{\\cos\\theta}, \\qquad e = R_e\\sin\\theta, \\qquad
              M = F_a\\tan\\theta\\,(2R_e - l)

    Parameters
    ----------
    axial_force : ndarray
        Axial force F_a,j of each roller [N].
    normal_force : ndarray
        Normal force N of each of its two flange contacts [N].
    radial_force : ndarray
        Radial component F_a,j tan(theta) of each contact force [N].
    offset : float
        Distance e of the contact points from the roller axis [m].
    height : float
        Height D/2 - e of the contact points above the raceway [m].
    inner_p0, outer_p0 : ndarray
        Peak Hertz pressure of the inner and the outer ring's flange contact [Pa].
    inner_semi_axes, outer_semi_axes : tuple of ndarray
        (radial, circumferential) semi-axes of the contact ellipses [m].
    inner_rim_margin, outer_rim_margin : ndarray
        Distance from the ellipse's outer edge to the flange rim (flange height minus
        contact height minus radial semi-axis) [m]; negative: the ellipse runs over
        the rim, an edge contact that Hertz does not describe.
    tilting_moment : ndarray
        The couple M of the two flange forces on each roller [N m].

    Notes
    -----
    See :func:`flange_contacts`; 0 < theta < pi/4.

    Examples
    --------
    >>> c = flange_contacts([500.0], 11e-3, 11e-3, 70e-3, 60e-3, math.radians(3),
    ...                     115.4e9, 3.2e-3, 3.2e-3)
    >>> float(c.normal_force[0] * math.cos(math.radians(3)))
    500.0

    References
    ----------
    T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis (2007); K. L. Johnson,
    Contact Mechanics (1985), section 4.2.
    """

    axial_force: np.ndarray
    normal_force: np.ndarray
    radial_force: np.ndarray
    offset: float
    height: float
    inner_p0: np.ndarray
    outer_p0: np.ndarray
    inner_semi_axes: tuple
    outer_semi_axes: tuple
    inner_rim_margin: np.ndarray
    outer_rim_margin: np.ndarray
    tilting_moment: np.ndarray


def _hertz(N, rx, ry, estar):
    """Hertz contacts of the nonzero forces N (array), zeros elsewhere: p0, and the
    semi-axes along x (radial) and y (circumferential)."""
    p0, ax, ay = (np.zeros(N.shape) for _ in range(3))
    on = N > 0.0
    if on.any():
        h = hertz_contact(N[on], rx, ry, estar)
        p0[on] = h.p0
        a, b = np.asarray(h.a), np.asarray(h.b)
        ax[on], ay[on] = (b, a) if h.swapped else (a, b)
    return p0, ax, ay


def flange_contacts(axial_force, roller_diameter, roller_length, pitch_diameter,
                    end_radius, flange_angle, estar, inner_flange_height,
                    outer_flange_height, end_chamfer=0.0):
    r"""Forces, Hertz stresses and tilting couple of each roller's two flange contacts.

    .. math::

        N = \frac{F_{a,j}}{\cos\theta}, \qquad e = R_e\sin\theta, \qquad
        M = F_{a,j}\tan\theta\,(2R_e - l),

        \frac{1}{R_x} = \frac{1}{R_e}, \qquad
        \frac{1}{R_y} = \frac{1}{R_e} \pm \frac{\sin\theta}{d_m/2 \mp e}

    (upper signs: the inner ring's flange, convex along the circumference; lower:
    the outer ring's, concave), and the Hertz contact of N on (R_x, R_y)
    (:func:`linecontact.hertz.hertz_contact`).

    Parameters
    ----------
    axial_force : float or array_like
        Axial force F_a,j of each roller (:func:`axial_load_shares`),
        0 <= F_a,j < inf [N].
    roller_diameter : float
        Roller diameter D, 0 < D < inf [m].
    roller_length : float
        Overall roller length l between the vertices of its spherical ends,
        0 < l < inf [m].
    pitch_diameter : float
        Pitch diameter d_m > D [m].
    end_radius : float
        Radius R_e of the spherical roller ends (centred on the roller axis),
        0 < R_e < inf [m].
    flange_angle : float
        Inclination theta of the flange faces to the radial plane,
        0 < theta < pi/4 [rad].
    estar : float
        Effective modulus E* of roller and flange, 0 < E* < inf [Pa].
    inner_flange_height : float
        Height of the inner ring's flange above its raceway, 0 < h_i < D/2 [m].
    outer_flange_height : float
        Height of the outer ring's flange above its raceway, 0 < h_o < D/2 [m].
    end_chamfer : float, optional
        Radial extent of the roller's corner (chamfer) beyond which its end is not
        spherical, 0 <= c < D/2 (default 0) [m].

    Returns
    -------
    FlangeContacts
        Per roller: axial, normal and radial forces, p0 and semi-axes of both flange
        contacts, the margin of each ellipse to its flange rim, and the couple M.

    Raises
    ------
    CombinationError
        The contact point (height D/2 - e) misses a flange face (above its rim or on
        the roller's chamfer): the end would touch the rim, not modelled.

    Notes
    -----
    Rigid-body statics of the roller between two flanges, frictionless flange
    contacts (the sliding friction there adds a skewing moment, not computed),
    Hertz point contacts (ellipse inside the flange face: check the rim margins),
    roller axis parallel to the bearing axis. Both flanges have the same angle. The
    forces sum per roller to F_a,j along the axis; :func:`axial_load_shares` makes
    the rollers' sum the bearing's F_a.

    Examples
    --------
    D = l = 11 mm, d_m = 70 mm, R_e = 60 mm, theta = 3 deg, flanges 3.2 mm high, steel,
    500 N on one roller:

    >>> c = flange_contacts(500.0, 11e-3, 11e-3, 70e-3, 60e-3, math.radians(3),
    ...                     115.4e9, 3.2e-3, 3.2e-3)
    >>> f"h {c.height * 1e3:.3f} mm, p0 {float(c.inner_p0) / 1e6:.0f} MPa, " \
    ...     f"M {float(c.tilting_moment):.3f} N m"
    'h 2.360 mm, p0 733 MPa, M 2.856 N m'

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Advanced Concepts, chapter 1.
    .. [2] K. L. Johnson, Contact Mechanics (1985), section 4.2.
    """
    Fa = check_interval("axial_force", axial_force, 0.0, np.inf, high_open=True,
                        unit="N")
    D = float(check_positive("roller_diameter", roller_diameter, "m"))
    l = float(check_positive("roller_length", roller_length, "m"))
    dm = float(check_interval("pitch_diameter", pitch_diameter, D, np.inf,
                              low_open=True, high_open=True, unit="m"))
    Re = float(check_positive("end_radius", end_radius, "m"))
    th = float(check_interval("flange_angle", flange_angle, 0.0, math.pi / 4,
                              low_open=True, high_open=True, unit="rad"))
    E = float(check_positive("estar", estar, "Pa"))
    hi = float(check_interval("inner_flange_height", inner_flange_height, 0.0, D / 2,
                              low_open=True, high_open=True, unit="m"))
    ho = float(check_interval("outer_flange_height", outer_flange_height, 0.0, D / 2,
                              low_open=True, high_open=True, unit="m"))
    c = float(check_interval("end_chamfer", end_chamfer, 0.0, D / 2, high_open=True,
                             unit="m"))
    e = Re * math.sin(th)
    height = D / 2 - e
    for name, h in (("inner_flange_height", hi), ("outer_flange_height", ho)):
        if not c <= height <= h:
            raise CombinationError(
                {"end_radius": Re, "flange_angle": th, name: h, "end_chamfer": c},
                f"the end touches its flange at {height:.6g} m above the raceway "
                f"(D/2 - R_e sin(theta)), outside the flange face [{c:.6g}, {h:.6g}] m "
                "between the roller's chamfer and the flange rim")
    N = Fa / math.cos(th)
    s = math.sin(th)
    ri = 1.0 / (1.0 / Re + s / (dm / 2 - e))
    ro = 1.0 / (1.0 / Re - s / (dm / 2 + e))
    pi_, axi, ayi = _hertz(np.atleast_1d(N), Re, ri, E)
    po_, axo, ayo = _hertz(np.atleast_1d(N), Re, ro, E)
    shape = np.shape(Fa)
    r = lambda x: out(np.reshape(x, shape))   # noqa: E731
    on = np.atleast_1d(N) > 0.0
    return FlangeContacts(
        axial_force=out(Fa), normal_force=out(N), radial_force=out(Fa * math.tan(th)),
        offset=e, height=height,
        inner_p0=r(pi_), outer_p0=r(po_),
        inner_semi_axes=(r(axi), r(ayi)), outer_semi_axes=(r(axo), r(ayo)),
        inner_rim_margin=r(np.where(on, hi - height - axi, hi - height)),
        outer_rim_margin=r(np.where(on, ho - height - axo, ho - height)),
        tilting_moment=out(Fa * math.tan(th) * (2.0 * Re - l)))
