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

from .checks import check_interval
from .errors import CombinationError

__all__ = ["SHARE_TOLERANCE", "DutyCycle", "revolution_shares", "duty_cycle_life"]

#: Relative tolerance on the sum of the shares being 1 (rounding of given fractions) [-].
SHARE_TOLERANCE = 1e-6


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
    this rule (check it statically, :mod:`linecontact.static`).

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
