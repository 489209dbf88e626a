r"""Static load rating and static safety of radial roller bearings (ISO 76).

The basic static radial load rating of a radial roller bearing

.. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
          i\,Z\,L_{we}\,D_{we}\cos\alpha \quad [\mathrm{N,\ mm}]

(:func:`static_load_rating`) is the load under which the most heavily loaded roller's
contact reaches a Hertz pressure of 4000 MPa (for contact angle 0, with the
zero-clearance Stribeck factor Q_max = 5 F_r / (i Z cos alpha) and steel's modulus:
docs/bearing_life.md checks the 44 against it). Against the static equivalent load
:math:`P_{0r}` (:func:`static_equivalent_load`) the static safety factor is
:math:`s_0 = C_{0r}/P_{0r}` (:func:`static_safety_factor`); from a computed peak
pressure, where a profile or misalignment makes the load distribution differ from the
rating's assumptions (edge stresses included), the stress-based safety
:math:`s_0 = (4000\ \mathrm{MPa}/p_{max})^2` (:func:`pressure_safety_factor`): line
contact, p ~ sqrt(Q).

References
----------
.. [1] ISO 76:2006, Rolling bearings - Static load ratings, as published in bearing
   catalogues (e.g. SKF, Rolling bearings, PUB BU/P1 17000, 2018, "Static load
   ratings"; Schaeffler, Technical Pocket Guide STT, 2014).
.. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Essential Concepts, chapter on static load rating (the 4000 MPa contact
   stress for roller bearings and the permanent deformation 1e-4 D it produces).
"""
from __future__ import annotations

import math

import numpy as np

from ._numerics import out
from .checks import check_interval, check_positive
from .errors import OutOfRangeError

__all__ = [
    "PERMISSIBLE_PRESSURE",
    "static_load_rating",
    "static_equivalent_load",
    "static_safety_factor",
    "pressure_safety_factor",
]

#: Contact pressure of roller bearings at the static load rating (ISO 76) [Pa].
PERMISSIBLE_PRESSURE = 4000e6
#: ISO 76's factor for radial roller bearings: 44 N/mm^2 [Pa].
_C0_FACTOR = 44e6


def static_load_rating(rollers, pitch_diameter, roller_diameter, length, rows=1,
                       contact_angle=0.0):
    r"""Basic static radial load rating C0r of a radial roller bearing (ISO 76).

    .. math:: C_{0r} = 44\left(1 - \frac{D_{we}\cos\alpha}{D_{pw}}\right)
              i\,Z\,L_{we}\,D_{we}\cos\alpha

    with the 44 in N/mm^2 and lengths in mm (here in SI: 44e6 Pa times lengths in m,
    the same number).

    Parameters
    ----------
    rollers : int
        Number of rollers per row Z >= 1 [-].
    pitch_diameter : float
        Pitch diameter D_pw > D_we cos(alpha) [m].
    roller_diameter : float
        Roller diameter D_we, 0 < D_we < inf [m].
    length : float
        Effective roller length L_we, 0 < L_we < inf [m].
    rows : int, optional
        Number of rows i >= 1 (default 1) [-].
    contact_angle : float, optional
        Nominal contact angle alpha (0 for cylindrical and needle roller bearings,
        default), 0 <= alpha < pi/2 [rad].

    Returns
    -------
    float
        C0r [N].

    Notes
    -----
    Valid for the ranges above. The rating corresponds to 4000 MPa at the centre of
    the most heavily loaded roller contact (a permanent deformation of about 1e-4 of
    the roller diameter); a maker's catalogue C0 may differ (profile, design).

    Examples
    --------
    14 rollers 11 mm x 11 mm on d_m = 70 mm:

    >>> f"{static_load_rating(14, 70e-3, 11e-3, 11e-3) / 1e3:.2f} kN"
    '62.82 kN'

    References
    ----------
    .. [1] ISO 76:2006, basic static radial load rating of radial roller bearings, as
       published in catalogues.
    """
    Z = check_interval("rollers", rollers, 1, 1e5)
    i = check_interval("rows", rows, 1, 100)
    for name, v in (("rollers", Z), ("rows", i)):
        if float(v) != int(v):
            raise OutOfRangeError(name, float(v), "a whole number >= 1")
    Dpw = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    Dwe = float(check_positive("roller_diameter", roller_diameter, "m"))
    Lwe = float(check_positive("length", length, "m"))
    a = float(check_interval("contact_angle", contact_angle, 0.0, math.pi / 2,
                             high_open=True, unit="rad"))
    Dc = Dwe * math.cos(a)
    if not Dc < Dpw:
        raise OutOfRangeError("pitch_diameter", Dpw, f"({Dc:.6g}, inf) m", unit="m",
                              hint="the pitch diameter must exceed D_we cos(alpha)")
    return _C0_FACTOR * (1.0 - Dc / Dpw) * int(i) * int(Z) * Lwe * Dc


def static_equivalent_load(radial_load):
    r"""Static equivalent radial load P0r of a radial roller bearing with alpha = 0.

    .. math:: P_{0r} = F_r

    Parameters
    ----------
    radial_load : float or array_like
        Radial load F_r (the largest that acts, shocks included),
        0 <= F_r < inf [N].

    Returns
    -------
    float or ndarray
        P0r [N].

    Notes
    -----
    ISO 76 for radial roller bearings with contact angle 0, which carry radial load
    only by their raceways (an axial load on the flanges of NJ or NUP bearings is
    checked by the flange contacts, :mod:`linecontact.flanges`, not by P0r).

    Examples
    --------
    >>> static_equivalent_load(20e3)
    20000.0

    References
    ----------
    .. [1] ISO 76:2006, static equivalent radial load, as published in catalogues.
    """
    return out(check_interval("radial_load", radial_load, 0.0, np.inf, high_open=True,
                              unit="N"))


def static_safety_factor(static_rating, static_load):
    r"""Static safety factor s0 = C0 / P0 (ISO 76).

    .. math:: s_0 = \frac{C_{0r}}{P_{0r}}

    Parameters
    ----------
    static_rating : float or array_like
        Basic static load rating C0r, 0 < C0r < inf [N].
    static_load : float or array_like
        Static equivalent load P0r, 0 <= P0r < inf [N].

    Returns
    -------
    float or ndarray
        s0 [-] (inf for no load).

    Notes
    -----
    Catalogues ask for s0 of about 1 to 4 for roller bearings depending on the
    demands on quiet running and on shock loads.

    Examples
    --------
    >>> f"{static_safety_factor(62.82e3, 20e3):.3f}"
    '3.141'

    References
    ----------
    .. [1] ISO 76:2006, static safety factor, as published in catalogues.
    """
    C0 = check_positive("static_rating", static_rating, "N")
    P0 = check_interval("static_load", static_load, 0.0, np.inf, high_open=True, unit="N")
    with np.errstate(divide="ignore"):
        return out(np.where(P0 > 0.0, C0 / np.where(P0 > 0.0, P0, 1.0), np.inf))


def pressure_safety_factor(peak_pressure, permissible_pressure=PERMISSIBLE_PRESSURE):
    r"""Stress-based static safety of a line contact from its computed peak pressure.

    .. math:: s_0 = \left(\frac{p_{perm}}{p_{max}}\right)^2, \qquad
              p_{perm} = 4000\ \mathrm{MPa}

    Parameters
    ----------
    peak_pressure : float or array_like
        Largest contact pressure p_max of the most loaded contact (edge stresses
        included), 0 <= p_max < inf [Pa].
    permissible_pressure : float, optional
        Pressure at the static load rating, 0 < p_perm < inf (default 4000 MPa, roller
        bearings) [Pa].

    Returns
    -------
    float or ndarray
        s0 [-] (inf where p_max = 0): the factor by which the load could grow before
        p_max reaches p_perm.

    Notes
    -----
    In a line contact the peak pressure grows as the square root of the load
    (Hertz: p0 = sqrt(w' E* / (pi R))), so the load safety is the square of the
    pressure ratio; with a uniformly loaded roller it equals C0r/P0r wherever the
    rating's load distribution holds. Under a profile or misalignment, p ~ sqrt(Q)
    holds only approximately (the contact length changes with the load); the factor
    is then the pressure ratio squared as defined, not an exact load margin.

    Examples
    --------
    >>> f"{pressure_safety_factor(2000e6):.2f}"
    '4.00'

    References
    ----------
    .. [1] ISO 76:2006 (4000 MPa for roller bearings), as published in catalogues.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter on static load rating.
    """
    p = check_interval("peak_pressure", peak_pressure, 0.0, np.inf, high_open=True,
                       unit="Pa")
    pp = check_positive("permissible_pressure", permissible_pressure, "Pa")
    with np.errstate(divide="ignore"):
        return out(np.where(p > 0.0, (pp / np.where(p > 0.0, p, 1.0)) ** 2, np.inf))
