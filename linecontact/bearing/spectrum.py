r"""Life over a duty cycle: the Palmgren-Miner rule of linear damage accumulation.

A load spectrum of cases i, each with its life :math:`L_i` (any of the rating lives, in
10^6 revolutions) and its share of revolutions :math:`u_i` (:math:`\sum u_i = 1`),
has the combined life

.. math:: \frac{1}{L} = \sum_i \frac{u_i}{L_i}

and case i takes the fraction :math:`(u_i/L_i)\,L` of the damage. Shares of time
:math:`t_i` at speeds :math:`n_i` become shares of revolutions
:math:`u_i = t_i n_i / \sum_j t_j n_j` (:func:`revolution_shares`).

References
----------
.. [1] A. Palmgren, "Die Lebensdauer von Kugellagern", Z. VDI 68 (1924) 339-341.
.. [2] M. A. Miner, "Cumulative damage in fatigue", J. Applied Mechanics 12 (1945)
   A159-A164.
.. [3] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press
   (2007): Essential Concepts, chapter 11 (life under variable load).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..checks import check_interval
from ..errors import CombinationError

__all__ = ["SHARE_TOLERANCE", "LIFE_KINDS", "DutyCycle", "revolution_shares", "duty_cycle_life",
           "LoadCase", "SpectrumSolution", "solve_spectrum"]

#: Relative tolerance on the sum of the shares being 1 (rounding of given fractions) [-].
SHARE_TOLERANCE = 1e-6
#: The lives a bearing solution carries, by name -> its attribute of
#: :class:`linecontact.bearing.BearingSolution`, combined by :func:`solve_spectrum`.
LIFE_KINDS = {"iso281": "life_iso281", "iso16281": "life_iso16281",
              "modified": "life_modified", "modified_reference": "life_modified_reference"}


def _shares(name, shares):
    s = check_interval(name, shares, 0.0, 1.0)
    if s.ndim != 1 or s.size == 0:
        raise CombinationError({name: f"shape {s.shape}"},
                               "give one share per load case (a 1-D sequence)")
    total = float(s.sum())
    if abs(total - 1.0) > SHARE_TOLERANCE:
        raise CombinationError({name: f"sum {total:.9g}"},
                               "the shares must sum to 1 (fractions, not percent)")
    return s


def revolution_shares(time_shares, speeds):
    r"""Shares of revolutions of load cases from their shares of time and speeds.

    .. math:: u_i = \frac{t_i\,n_i}{\sum_j t_j\,n_j}

    Parameters
    ----------
    time_shares : array_like
        Fractions of time t_i of the cases, 0 <= t_i <= 1, summing to 1 [-].
    speeds : array_like
        Speeds n_i of the cases (the rotating ring against the other),
        0 <= n_i < inf, not all zero where t_i > 0 [rad/s].

    Returns
    -------
    ndarray
        u_i [-], summing to 1.

    Notes
    -----
    A case at standstill (n_i = 0) takes no revolutions and so no fatigue damage in
    this rule (check it statically, :func:`linecontact.bearing.ratings.static_safety_factor`).

    Examples
    --------
    >>> revolution_shares([0.5, 0.5], [100.0, 300.0])
    array([0.25, 0.75])

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 11.
    """
    t = _shares("time_shares", time_shares)
    n = check_interval("speeds", speeds, 0.0, np.inf, high_open=True, unit="rad/s")
    if n.shape != t.shape:
        raise CombinationError({"time_shares": f"shape {t.shape}",
                                "speeds": f"shape {n.shape}"},
                               "give one speed per load case")
    w = t * n
    if not w.sum() > 0.0:
        raise CombinationError({"time_shares": t.tolist(), "speeds": n.tolist()},
                               "no case turns: no revolutions to share")
    return w / w.sum()


@dataclass(frozen=True)
class DutyCycle:
    """A duty cycle's combined life and how its cases share the revolutions and damage.

    Returned by :func:`duty_cycle_life`.

    .. math:: \\frac{1}{L} = \\sum_i \\frac{u_i}{L_i}, \\qquad
              d_i = \\frac{u_i L}{L_i}

    Parameters
    ----------
    life : float
        Combined life L [-] in 10^6 revolutions (inf if no case damages).
    revolution_shares : ndarray
        u_i of each case [-].
    damage_shares : ndarray
        d_i, the fraction of the damage each case takes (summing to 1) [-].
    seconds : float or None
        The combined life in seconds of the duty cycle (given speeds), else None [s].

    Notes
    -----
    0 < L <= inf; 0 <= u_i, d_i <= 1.

    Examples
    --------
    >>> d = duty_cycle_life([100.0, 400.0], [0.5, 0.5])
    >>> d.life, [round(float(x), 12) for x in d.damage_shares]
    (160.0, [0.8, 0.2])

    References
    ----------
    M. A. Miner (1945); A. Palmgren (1924).
    """

    life: float
    revolution_shares: np.ndarray
    damage_shares: np.ndarray
    seconds: float | None = None


def duty_cycle_life(lives, shares, speeds=None):
    r"""Combined life of a load spectrum by the Palmgren-Miner rule.

    .. math:: L = \left(\sum_i \frac{u_i}{L_i}\right)^{-1}

    with u_i the shares of revolutions (given, or from shares of time and speeds by
    :func:`revolution_shares`).

    Parameters
    ----------
    lives : array_like
        Life L_i of each case at its load (L10, L_nm, L10r, ...: one kind for all),
        0 < L_i <= inf [-] in 10^6 revolutions.
    shares : array_like
        Shares of the cases, 0 <= share <= 1, summing to 1: of revolutions, or of
        time when `speeds` is given [-].
    speeds : array_like, optional
        Speed of each case; given, `shares` are shares of time,
        0 <= n_i < inf [rad/s].

    Returns
    -------
    DutyCycle
        The combined life [10^6 revolutions], the shares of revolutions and of
        damage, and (with speeds) the life in seconds.

    Notes
    -----
    Linear damage accumulation, independent of the order of the cases; each case's
    life computed as if it acted alone. With speeds the life in seconds is
    L 10^6 2 pi / sum(t_i n_i).

    Examples
    --------
    Two cases, 30 % of revolutions at L1 = 200 and 70 % at L2 = 1000:

    >>> f"{duty_cycle_life([200.0, 1000.0], [0.3, 0.7]).life:.2f}"
    '454.55'
    >>> d = duty_cycle_life([200.0, 1000.0], [0.5, 0.5], speeds=[100.0, 300.0])
    >>> f"{d.life:.1f}, {d.seconds / 3600:.0f} h"
    '500.0, 4363 h'

    References
    ----------
    .. [1] A. Palmgren, Z. VDI 68 (1924) 339-341; M. A. Miner, J. Applied Mechanics
       12 (1945) A159-A164.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 11.
    """
    L = check_interval("lives", lives, 0.0, np.inf, low_open=True)
    if speeds is None:
        u = _shares("shares", shares)
        seconds = None
    else:
        u = revolution_shares(shares, speeds)
    if L.shape != u.shape:
        raise CombinationError({"lives": f"shape {L.shape}", "shares": f"shape {u.shape}"},
                               "give one life per load case")
    rate = u / L
    total = float(rate.sum())
    life = math.inf if total == 0.0 else 1.0 / total
    damage = rate / total if total > 0.0 else np.zeros_like(rate)
    if speeds is not None:
        mean = float(np.sum(np.asarray(shares, dtype=float)
                            * np.asarray(speeds, dtype=float)))
        seconds = life * 1e6 * 2.0 * math.pi / mean
    return DutyCycle(life=life, revolution_shares=u, damage_shares=damage,
                     seconds=seconds)


@dataclass(frozen=True)
class LoadCase:
    """One load case of a duty cycle: its share, loads and speed.

    Parameters
    ----------
    share : float
        Share of the case, of time or of revolutions (:func:`solve_spectrum`'s
        `shares`), 0 <= share <= 1 [-].
    radial_load : float
        Radial load F_r, 0 < F_r < inf [N].
    speed : float, optional
        Speed of the inner ring against the outer ring, -inf < omega < inf [rad/s]
        (needed for shares of time, and for a bearing with a lubricant).
    moment : float, optional
        Tilting moment on the inner ring, |M| < inf [N m].
    misalignment : float, optional
        Tilt of the inner ring against the outer ring, |theta| < 0.1 [rad].
    axial_load : float, optional
        Axial load on the flanges, 0 <= F_a < inf [N].

    Notes
    -----
    Each input as in :meth:`linecontact.bearing.RadialRollerBearing.solve`, which
    checks it.

    Examples
    --------
    >>> LoadCase(0.8, 10e3, speed=157.08).radial_load
    10000.0
    """

    share: float
    radial_load: float
    speed: float = None
    moment: float = None
    misalignment: float = None
    axial_load: float = None


@dataclass(frozen=True)
class SpectrumSolution:
    """A bearing over a duty cycle: each case's solution, life and damage, and the
    combined lives (Palmgren-Miner).

    Returned by :func:`solve_spectrum`.

    .. math:: \\frac{1}{L} = \\sum_i \\frac{u_i}{L_i}, \\qquad d_i = \\frac{u_i L}{L_i}

    Parameters
    ----------
    cases : tuple of LoadCase
        The load cases as given.
    solutions : tuple of BearingSolution
        Each case's solution.
    revolution_shares : ndarray
        u_i of each case [-].
    lives : dict
        Life kind (:data:`LIFE_KINDS`) -> each case's life L_i [-] (10^6
        revolutions); only the kinds every turning case has (nan for a case at
        standstill that has none: its modified lives need the rings to turn).
    damage : dict
        Life kind -> each case's share d_i of the damage, summing to 1 [-].
    life : dict
        Life kind -> the combined life L [-] (10^6 revolutions).
    hours : dict or None
        Life kind -> the combined life in hours of the cycle (shares of time with
        speeds) [h]; None for shares of revolutions.

    Notes
    -----
    0 < L <= inf; 0 <= u_i, d_i <= 1.

    Examples
    --------
    >>> from linecontact.bearing import RadialRollerBearing
    >>> r = solve_spectrum(RadialRollerBearing(14, 70e-3, 11e-3, 11e-3),
    ...                    [LoadCase(0.5, 10e3), LoadCase(0.5, 20e3)],
    ...                    shares="revolutions")
    >>> f"{r.life['iso281']:.1f}", [round(float(d), 3) for d in r.damage["iso281"]]
    ('69.8', [0.09, 0.91])

    References
    ----------
    M. A. Miner (1945); A. Palmgren (1924).
    """

    cases: tuple
    solutions: tuple
    revolution_shares: np.ndarray
    lives: dict
    damage: dict
    life: dict
    hours: dict = None


def solve_spectrum(bearing, cases, shares="time"):
    r"""A bearing over a load spectrum: each case solved, its lives and damage, and the
    combined lives by the Palmgren-Miner rule.

    .. math::

        L = \left(\sum_i \frac{u_i}{L_i}\right)^{-1}, \qquad
        u_i = \frac{t_i n_i}{\sum_j t_j n_j}\ (\text{shares of time})

    Parameters
    ----------
    bearing : RadialRollerBearing
        The bearing (:class:`linecontact.bearing.RadialRollerBearing`), its
        lubricant, fits and flanges included.
    cases : sequence of LoadCase or dict
        The load cases (a dict: :class:`LoadCase`'s fields by name), at least one.
    shares : str, optional
        ``"time"`` (default: every case needs its speed) or ``"revolutions"``: what
        the cases' shares are.

    Returns
    -------
    SpectrumSolution
        Per case: the solution, the shares of revolutions, each life kind's life and
        damage; the combined life of each kind every case has (ISO 281 L10, ISO 16281
        L10r, and with a lubricant and e_C the modified L_nm and L_nmr), in hours too
        for shares of time.

    Raises
    ------
    CombinationError
        Shares of time without a speed in every case, or shares that do not sum to 1.

    Notes
    -----
    Each case solved as if it acted alone (:meth:`RadialRollerBearing.solve`), linear
    damage accumulation (:func:`duty_cycle_life`), independent of the cases' order.
    A case at standstill (shares of time, speed 0) takes no revolutions and no
    damage; it is solved for its load distribution and static safety, without the
    film, kappa and modified lives (nan in `lives`), which need the rings to turn.
    Speeds only convert shares of time and give the film and kappa; a case's
    direction of rotation does not matter to the lives.

    Examples
    --------
    Two cases at equal revolutions: L = 2 / (1/L1 + 1/L2).

    >>> from linecontact.bearing import RadialRollerBearing
    >>> b = RadialRollerBearing(14, 70e-3, 11e-3, 11e-3)
    >>> r = solve_spectrum(b, [dict(share=0.5, radial_load=10e3),
    ...                        dict(share=0.5, radial_load=20e3)], shares="revolutions")
    >>> L1, L2 = r.lives["iso16281"]
    >>> f"{r.life['iso16281'] / (2 / (1 / L1 + 1 / L2)):.12f}"
    '1.000000000000'

    References
    ----------
    .. [1] A. Palmgren, Z. VDI 68 (1924) 339-341; M. A. Miner, J. Applied Mechanics
       12 (1945) A159-A164.
    .. [2] T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis, 5th ed. (2007),
       Essential Concepts, chapter 11.
    """
    from ..errors import UnknownNameError

    if shares not in ("time", "revolutions"):
        raise UnknownNameError("shares", shares, ["time", "revolutions"])
    cases = tuple(c if isinstance(c, LoadCase) else LoadCase(**c) for c in cases)
    if not cases:
        raise CombinationError({"cases": 0}, "give at least one load case")
    share = np.array([c.share for c in cases], dtype=float)
    speeds = None
    if shares == "time":
        missing = [i for i, c in enumerate(cases) if c.speed is None]
        if missing:
            raise CombinationError({"shares": "time", "speed": f"missing in cases "
                                    f"{missing}"}, "shares of time need each case's "
                                   "speed (or give shares='revolutions')")
        speeds = np.abs(np.array([c.speed for c in cases], dtype=float))
    # a case at standstill (shares of time, speed 0) takes no revolutions: solved
    # without the film, kappa and modified lives (undefined without rotation), it
    # enters the combination with no damage
    at_rest = [speeds is not None and speeds[i] == 0.0 for i in range(len(cases))]
    sols = tuple(bearing.solve(c.radial_load, c.moment, c.misalignment, speed=c.speed,
                               axial_load=c.axial_load) if not rest else
                 bearing._solve(c.radial_load, c.moment, c.misalignment, None,
                                c.axial_load, at_rest=True)
                 for c, rest in zip(cases, at_rest))
    lives, damage, life, hours = {}, {}, {}, ({} if speeds is not None else None)
    u = None
    for kind, attr in LIFE_KINDS.items():
        Li = [getattr(s, attr) for s in sols]
        if any(v is None and not rest for v, rest in zip(Li, at_rest)):
            continue
        Li = [math.inf if v is None else v for v in Li]
        d = duty_cycle_life(Li, share, speeds)
        u = d.revolution_shares
        lives[kind] = np.array([math.nan if v is None else v for v in
                                (getattr(s, attr) for s in sols)], dtype=float)
        damage[kind] = d.damage_shares
        life[kind] = d.life
        if hours is not None:
            hours[kind] = d.seconds / 3600.0
    return SpectrumSolution(cases=cases, solutions=sols, revolution_shares=u,
                            lives=lives, damage=damage, life=life, hours=hours)
