r"""Stress maxima below a line contact and along a roller solved by slices.

A straight or profiled roller solved by coupled slices
(:mod:`linecontact.roller`) is a row of strips; slice k carries the line load q_k over
the half-width b_k, so :math:`p_{0,k} = 2q_k/(\pi b_k)` and its field is the strip
field scaled by p_{0,k} and b_k. The field is self-similar: the maxima are computed once
per (mu, nu) on the unit strip (a grid search refined by a bounded optimiser) and
scaled per slice, so the stresses of a whole roller cost microseconds. Where the load
varies along the roller (a crown, a relief, a tilt) the field is three-dimensional and
the strips are up to 5 % low; the worst of each measure therefore gets a 3D
correction: below the worst slices, McEwen's strip of the slice plus the 3D field of
the difference between the slices' Hertz pressures and that strip extended to
infinity, from Love's uniformly loaded rectangles (:func:`~linecontact.stresses.love.rectangle_stresses`;
Love 1929) on a grid of 24 cells across and one cell per slice along (one per slice
and across beyond 8 b). Its error against a 3D field (Love's and Cerruti's rectangles
below a 3D boundary-element pressure, tools/bem/stress.py) is measured in
tables/stress_accuracy.csv (tools/studies/stress_study.py) and stated in each
result's ``error`` and notes.

References
----------
.. [1] E. McEwen, "Stresses in elastic cylinders in contact along a generatrix",
   Phil. Mag. 40 (1949) 454-459.
.. [2] K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), sections
   2.2-2.3 (line loads), 4.2 (Hertz strip), 7.2 (sliding).
.. [3] A. E. H. Love, "The stress produced in a semi-infinite solid by pressure on
   part of the boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .accuracy import reaches_end, stress_accuracy
from .measures import MEASURES
from .results import _assemble
from .search import _worst_3d
from .strip import _check_material, _maxima

__all__ = ["line_contact_stresses", "roller_stresses", "EDGE_LOADED_STRESS"]

#: Why the stress maxima of an edge-loaded roller are not reported: the reason, and
#: what converges instead. Measured: a misaligned 20-roller bearing (D = L = 10 mm,
#: straight, 10 kN, 1 mrad) Tresca 955, 1283, 1705 MPa at 20, 40, 80 slices; an aligned
#: straight roller R 5 mm, L 14 mm at 100 N/mm 420 to 1325 MPa from 25 to 400 slices.
EDGE_LOADED_STRESS = ("edge loaded: the contact reaches a roller end, where the pressure "
                      "on a half-space is singular, so the stress maxima grow as the "
                      "slices are refined (a slice-width number, not reported); a crown, "
                      "a logarithmic profile or an end relief with a corner radius that "
                      "keeps the contact off the ends gives converged stresses")

#: where roller_stresses' 3D search looks (its ``search``)
_SEARCHES = ("candidates", "every slice")


def line_contact_stresses(force, radius, length, estar, friction=0.0, poisson=0.3):
    r"""Stress maxima below an infinitely long (plane-strain) Hertz line contact.

    .. math:: b = \sqrt{\frac{4 F R}{\pi L E^*}}, \qquad
              p_0 = \sqrt{\frac{F E^*}{\pi L R}}

    with the maxima of :func:`strip_maxima` scaled by b and p0 (one slice at x = 0).

    Parameters
    ----------
    force : float
        Normal force F [N].
    radius : float
        Radius R across the axis (effective radius against a raceway) [m].
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa].
    friction : float, optional
        Coefficient mu of the sliding traction, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio, 0 <= nu <= 0.5 [-].

    Returns
    -------
    SubsurfaceStresses
        One slice.

    Notes
    -----
    Valid for 0 < F, R, L, E* < inf and b << R; the uniform line load F/L ignores the
    roller ends (for those use :func:`roller_stresses`).

    Examples
    --------
    >>> s = line_contact_stresses(1000.0, 5e-3, 10e-3, 115.385e9, friction=0.1)
    >>> f"{s.worst['von_mises']['value'] / 1e6:.0f} MPa"
    '485 MPa'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), Eq. 4.45 and section 7.2.
    """
    from ..classical import hertz_half_width, hertz_peak_pressure
    mu, nu = _check_material(friction, poisson)
    b = float(hertz_half_width(force, radius, length, estar))
    p0 = float(hertz_peak_pressure(force, radius, length, estar))
    return _assemble(np.zeros(1), np.array([b]), np.array([p0]), mu, nu,
                     notes=("plane-strain Hertz strip with the mean line load F/L: exact "
                            "for an infinitely long contact; the roller ends are not "
                            "modelled",))


def roller_stresses(solution, friction=0.0, poisson=0.3, roller=None, three_d=True,
                    search="candidates"):
    r"""Stress maxima along a roller solved by slices, per slice and the worst of all.

    .. math:: p_{0,k} = \frac{2 q_k}{\pi b_k},\qquad
              \tau_{\max,k} = \hat\tau(\mu, \nu)\, p_{0,k}
              \text{ at } z_k = \hat z(\mu, \nu)\, b_k

    per slice (plane strain); the worst of each measure then gets a 3D correction:
    below candidate slices (the strips' worst and two either side, p0's other peaks;
    where the contact reaches an end, slices spread over the whole roller, refined
    along it), the field is McEwen's strip of that slice plus the 3D field (Love's rectangles, :func:`rectangle_stresses`)
    of the difference between the slices' Hertz pressures and that strip extended
    to infinity, maximised over (y, z) by a zoomed grid search (docs/stresses.md).

    Parameters
    ----------
    solution : RollerSolution
        From :class:`linecontact.roller.ProfiledRoller`, :func:`~linecontact.roller.roller_contact`
        or :func:`~linecontact.roller.iso_slicing` (its ``x``, ``q``, ``half_width``).
    friction : float, optional
        Coefficient mu of the sliding traction, 0 <= mu <= 1 [-].
    poisson : float, optional
        Poisson's ratio, 0 <= nu <= 0.5 [-].
    roller : ProfiledRoller, optional
        The model that produced `solution`: with it the note also checks L/D, the
        mean line load and the profile against the measured range.
    three_d : bool, optional
        Apply the 3D correction to the worst (default; without it the worst is the
        plane-strain strips', up to 5 % low under a crown, a relief or a tilt).
    search : {"candidates", "every slice"}, optional
        Where the 3D correction's grid search looks: below the candidate slices
        (default), or below every loaded slice (a check of the candidates' choice:
        never lower, some 20-25 times the cost).

    Returns
    -------
    SubsurfaceStresses
        Per slice (plane strain) and worst (3D-corrected); ``error`` and the notes
        give the measured error against a 3D field.

    Notes
    -----
    Valid as the roller model (b << R, |theta| < 0.1 rad); the 3D correction covers the
    normal pressure (the traction's field stays the strip's); measured against a 3D
    field in tables/stress_accuracy.csv (``error``, notes). A measure whose strip
    maximum lies at the surface (mu >= 0.3) keeps the strip's value.

    Examples
    --------
    >>> from linecontact.roller import roller_contact
    >>> sol = roller_contact(5e-3, 14e-3, 115.385e9, "circular:Rc=0.5", force=4200.0)
    >>> s = roller_stresses(sol)
    >>> f"{s.worst['tresca']['value'] / 1e6:.0f} MPa (strips: {s.strip_worst['tresca']['value'] / 1e6:.0f} MPa)"
    '759 MPa (strips: 737 MPa)'

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), sections 3.2, 4.2 and 7.2; E. McEwen
    (1949); A. E. H. Love (1929).
    """
    mu, nu = _check_material(friction, poisson)
    if search not in _SEARCHES:
        raise ValueError(f"search = {search!r} is not one of {_SEARCHES}")
    x = np.asarray(solution.x, dtype=float)
    b = np.asarray(solution.half_width, dtype=float)
    q = np.asarray(solution.q, dtype=float)
    loaded = (b > 0) & (q > 0)
    p0 = np.where(loaded, 2 * q / (np.pi * np.where(loaded, b, 1.0)), 0.0)
    b = np.where(loaded, b, 0.0)
    edge = bool(getattr(solution, "edge_loaded", False))
    note, error = stress_accuracy(solution, mu, roller, three_d and x.size > 1)
    notes = [note]
    if edge:
        notes.insert(0, "edge loaded: the end slice's pressure is a singular peak on a "
                        "half-space, so the stresses below it are resolved only to the "
                        "slice width (a grid-dependent number, like the peak pressure)")
    s = _assemble(x, b, p0, mu, nu, notes, edge)
    if edge:
        s = dataclasses.replace(s, withheld={m: EDGE_LOADED_STRESS for m in MEASURES})
    if not three_d or x.size < 2 or not loaded.any():
        return dataclasses.replace(s, error=error)
    # the contact at or near an end: the worst may lie anywhere along the roller, and
    # the search scans every part of it
    wide = edge or reaches_end(solution)
    w3 = _worst_3d(x, b, p0, mu, nu, _maxima(mu, nu), wide,
                   every=search == "every slice")
    if all(v is None for v in w3.values()):
        # every measure's worst at the surface (friction >= ~0.4): nothing corrected,
        # the strips' worst as it is, and the method says so
        return dataclasses.replace(s, error=error)
    worst = {k: (s.worst[k] if w3[k] is None else w3[k]) for k in MEASURES}
    return dataclasses.replace(s, worst=worst, strip_worst=s.worst, error=error,
                               method="strip + 3D correction")
