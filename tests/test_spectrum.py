"""Duty-cycle life by the Palmgren-Miner rule (linecontact.bearing.spectrum)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.errors import CombinationError, OutOfRangeError
from linecontact.bearing.spectrum import duty_cycle_life, revolution_shares


def test_two_case_spectrum_life():
    """L = 1 / (t1/L1 + t2/L2): 30 % of revolutions at 200, 70 % at 1000:
    1 / (0.0015 + 0.0007) = 454.545..."""
    d = duty_cycle_life([200.0, 1000.0], [0.3, 0.7])
    assert d.life == pytest.approx(1 / (0.3 / 200 + 0.7 / 1000), rel=1e-15)
    assert d.life == pytest.approx(454.5454545, rel=1e-9)
    assert d.damage_shares.sum() == pytest.approx(1.0, rel=1e-15)
    assert d.damage_shares[0] == pytest.approx(0.0015 / 0.0022, rel=1e-14)


def test_one_case_is_its_own_life_and_equal_lives_combine_to_it():
    assert duty_cycle_life([321.0], [1.0]).life == 321.0
    assert duty_cycle_life([321.0, 321.0], [0.4, 0.6]).life == pytest.approx(321.0,
                                                                            rel=1e-15)


def test_time_shares_at_speeds_become_revolution_shares():
    """u_i = t_i n_i / sum t_j n_j; equal time at 100 and 300 rad/s: 1/4 and 3/4 of the
    revolutions; the life in seconds is L 1e6 2 pi / (mean speed)."""
    u = revolution_shares([0.5, 0.5], [100.0, 300.0])
    assert u.tolist() == [0.25, 0.75]
    d = duty_cycle_life([200.0, 1000.0], [0.5, 0.5], speeds=[100.0, 300.0])
    assert d.life == pytest.approx(1 / (0.25 / 200 + 0.75 / 1000), rel=1e-15)
    assert d.seconds == pytest.approx(d.life * 1e6 * 2 * math.pi / 200.0, rel=1e-15)


def test_standstill_case_takes_no_damage():
    d = duty_cycle_life([10.0, 1000.0], [0.5, 0.5], speeds=[0.0, 100.0])
    assert d.life == pytest.approx(1000.0, rel=1e-15)
    assert d.damage_shares.tolist() == [0.0, 1.0]


def test_infinite_life_cases():
    d = duty_cycle_life([np.inf, 500.0], [0.5, 0.5])
    assert d.life == pytest.approx(1000.0, rel=1e-15)
    assert math.isinf(duty_cycle_life([np.inf], [1.0]).life)


def test_shares_must_sum_to_one():
    """Fractions summing to 1; percentages are refused, not rescaled silently."""
    with pytest.raises(OutOfRangeError, match="shares = 30"):
        duty_cycle_life([200.0, 1000.0], [30.0, 70.0])
    with pytest.raises(CombinationError, match="sum to 1"):
        duty_cycle_life([200.0, 1000.0], [0.3, 0.6])
    with pytest.raises(CombinationError, match="one life per load case"):
        duty_cycle_life([200.0], [0.3, 0.7])
