"""ISO 16281 slicing of a profiled, tilted roller: uncoupled nonlinear slice springs
with the misalignment term, for comparison with the coupled-slice model.

References
----------
ISO 16281:2025 (formerly ISO/TS 16281:2008), Rolling bearings - Methods for calculating the modified reference
rating life for universally loaded rolling bearings (slicing method).
"""
from __future__ import annotations

import math

import numpy as np

from ..checks import check_interval, check_positive
from ..errors import OutOfRangeError
from ..profiles import as_profile, is_free_tilt, roller_drop
from .slices import N_SLICES, TILT_RANGE
from .solution import RollerSolution, contact_extent, peak_pressure

__all__ = ["iso_slicing", "ISO_MIN_SLICES"]

#: ISO 16281 asks for at least 30 slices: the method's fewest and its default count
#: (linecontact.roller.solvers.DEFAULT_SLICES).
ISO_MIN_SLICES = 30


def _iso_state(P, x, L, E, n, d, th):
    from ..classical import iso16281_force
    delta = d + x * math.tan(th) - P
    on = delta > 0
    Q = np.zeros_like(delta)
    if np.any(on):
        Q[on] = iso16281_force(delta[on], L, E) / n
    k = np.zeros_like(delta)
    k[on] = (10.0 / 9.0) * Q[on] / delta[on]       # dQ_k/d(delta_k)
    sec2 = 1.0 / math.cos(th) ** 2
    K = np.array([[k.sum(), (k * x).sum() * sec2],
                  [(k * x).sum(), (k * x * x).sum() * sec2]])
    return Q, float(Q.sum()), float((Q * x).sum()), K


def iso_slicing(radius, length, estar, profile=None, *, depth=None, force=None, tilt=0.0,
                n_slices=ISO_MIN_SLICES):
    """ISO 16281 slicing: uncoupled nonlinear slice springs with the misalignment term.

    .. math::

        Q_k = \\frac{c}{n}\\,\\delta_k^{10/9},\\qquad
        \\delta_k = d + x_k\\tan\\theta - P(x_k) \\;(> 0),\\qquad
        F = \\sum_k Q_k,\\quad M = \\sum_k Q_k x_k

    where c reproduces the standard's one-contact formula
    d [mm] = 3.97e-5 F[N]^0.9 / L[mm]^0.8 for a straight roller
    (:func:`linecontact.classical.iso16281_force`, the same constant), so uniform
    deflection gives the whole-roller formula exactly.

    Parameters
    ----------
    radius : float
        Radius across the axis R [m] (only for the Hertz half-width and pressure of
        each slice, b = sqrt(4 R q/(pi E*)), p = 2q/(pi b)).
    length : float
        Roller length L [m].
    estar : float
        Effective modulus E* [Pa]; steel only (the constant is empirical).
    profile : Profile or str or None
        Profile drop (None: straight) [-].
    depth, force : float
        Exactly one: depth d [m] or force F [N].
    tilt : float or str
        Tilt theta [rad] (sign as the coupled model: positive loads +x; default 0,
        aligned), or ``"free"`` for zero moment at the force or depth given.
    n_slices : int
        n >= 30 as the standard asks [-] (default 30).

    Returns
    -------
    RollerSolution
        With method ``"ISO 16281 slicing"``; ``p_max`` is the largest slice pressure
        (the method has no edge peak; ``edge_loaded`` still says if an end is loaded).

    Raises
    ------
    OutOfRangeError
        Non-steel E*, n < 30, no contact, bad input.

    Notes
    -----
    Valid for steel on steel (E* within 10 % of 115.38 GPa), |theta| < 0.1 rad. The
    slices do not interact: no edge peaks, and a crowned roller's deflection differs
    from exact Hertz (measured in tests/test_roller.py). The tilt sign follows this
    module (positive theta brings the +x end closer); the standard writes the
    misalignment term with its own sign convention.

    Examples
    --------
    A straight steel roller: uniform deflection, so the whole-roller formula
    (3.153 um at 1 kN, L = 10 mm):

    >>> s = iso_slicing(5e-3, 10e-3, 115.38e9, force=1e3)
    >>> f"{s.depth * 1e6:.3f} um"
    '3.153 um'

    References
    ----------
    ISO 16281:2025 (slicing method); Palmgren (1959).
    """
    from ..classical import STEEL_ESTAR_RANGE, STEEL_HINT
    R = float(check_positive("radius", radius, "m"))
    L = float(check_positive("length", length, "m"))
    E = float(check_positive("estar", estar, "Pa"))
    STEEL_ESTAR_RANGE.check(E, hint=STEEL_HINT)
    n = check_interval("n_slices", n_slices, ISO_MIN_SLICES, N_SLICES.high,
                       hint="ISO 16281 asks for at least 30 slices").item()
    n = int(n)
    prof = as_profile(profile, R, L, E)
    w = L / n
    x = -L / 2 + w * (np.arange(n) + 0.5)
    P = roller_drop(prof, L, x)
    if (depth is None) == (force is None):
        raise OutOfRangeError("depth", "both" if depth is not None else "neither",
                              "exactly one of depth, force")

    def d_first(th):
        return float(np.min(P - x * math.tan(th)))

    free = is_free_tilt(tilt)

    def zero_moment(moment, what, value, unit):
        """The tilt at which moment(theta) vanishes (M increases with theta)."""
        from scipy.optimize import brentq

        m0 = moment(0.0)
        if m0 == 0.0:
            return 0.0
        step = -math.copysign(1e-6, m0)          # bracket the root
        while moment(step) * m0 > 0:
            step *= 4
            if abs(step) >= TILT_RANGE.high:
                raise OutOfRangeError(what, value, "a load with a zero-moment tilt "
                                      "below 0.1 rad", unit=unit)
        return brentq(moment, min(0.0, step), max(0.0, step), xtol=1e-15, rtol=1e-13,
                      maxiter=200)

    if depth is not None:
        def depth_checked(th):
            d0 = d_first(th)
            return check_interval("depth", depth, d0, np.inf, low_open=True,
                                  high_open=True, unit="m",
                                  hint=f"no contact at or below {d0:.6g} m").item()

        th = (zero_moment(lambda t: _iso_state(P, x, L, E, n, depth_checked(t), t)[2],
                          "depth", float(depth), "m") if free
              else TILT_RANGE.check(tilt).item())
        d = depth_checked(th)
    else:
        from scipy.optimize import brentq
        F0 = float(check_positive("force", force, "N"))

        def depth_at(th):
            d0 = d_first(th)
            hi = 1e-9 * L
            while _iso_state(P, x, L, E, n, d0 + hi, th)[1] < F0:
                hi *= 4
            return brentq(lambda e: _iso_state(P, x, L, E, n, d0 + e, th)[1] - F0,
                          0.0, hi, xtol=1e-15 * L, rtol=1e-14, maxiter=200) + d0

        th = (zero_moment(lambda t: _iso_state(P, x, L, E, n, depth_at(t), t)[2],
                          "force", F0, "N") if free else TILT_RANGE.check(tilt).item())
        d = depth_at(th)
    Q, F, M, K = _iso_state(P, x, L, E, n, d, th)
    q = Q / w
    b = np.sqrt(4 * R * q / (math.pi * E))
    p = np.where(q > 0, 2 * q / (math.pi * np.where(b > 0, b, 1.0)), 0.0)
    start, stop, lo_edge, hi_edge = contact_extent(x, Q, w, L)
    edge = {(True, True): "both", (True, False): "-x", (False, True): "+x"}.get(
        (lo_edge, hi_edge))
    pm, xm = peak_pressure(x, p)
    msg = ("largest slice pressure of uncoupled 2D Hertz slices (ISO 16281); the "
           "method has no edge peak")
    if edge is not None:
        msg += f"; the contact reaches the roller end ({edge}), where the true pressure " \
               "is singular"
    return RollerSolution(
        depth=float(d), tilt=float(th), force=F, moment=M, stiffness=float(K[0, 0]),
        tilt_stiffness=float(K[1, 1]), stiffness_matrix=K, x=x, q=q, half_width=b,
        width=np.full(n, w),
        pressure=p, p_max=pm, x_at_p_max=xm, contact_start=start, contact_end=stop,
        contact_length=stop - start, edge_loaded=edge is not None, edge=edge,
        message=msg, method="ISO 16281 slicing", n_slices=n)
