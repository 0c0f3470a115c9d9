"""analysis.metrics.pulses.major_pulses on synthetic opening maps with a known number of major pulses."""

import math

import numpy as np
import pytest

from analysis.metrics import pulses

PERIOD, N, C = 100.0, 200, 0.8
X = np.arange(N) * PERIOD / N
T = np.arange(0.0, 200.0, 2.0)


def bump(x0, amplitude, t, width=2.0, celerity=C):
    """Gaussian opening of a pulse moving at celerity from x0, shape (n_t, n_x)."""
    centre = (x0 + celerity * t)[:, None]
    d = (X[None, :] - centre + 0.5 * PERIOD) % PERIOD - 0.5 * PERIOD
    return amplitude * np.exp(-(d / width) ** 2)


def test_one_strong_pulse_and_weak_secondaries_count_one():
    u = bump(10.0, 5e-3, T) + bump(40.0, 1e-3, T) + bump(70.0, 1.5e-3, T)
    result = pulses.major_pulses(X, T, u, 2.5e-4, C)
    assert result.count == 1 and result.spacing == pytest.approx(PERIOD)
    assert result.strengths == (1.0,) and 0.2 < result.next_strength < 0.5


def test_two_equal_pulses_half_a_period_apart():
    u = bump(10.0, 5e-3, T) + bump(60.0, 5e-3, T) + bump(35.0, 8e-4, T)
    result = pulses.major_pulses(X, T, u, 2.5e-4, C)
    assert result.count == 2 and result.spacing == pytest.approx(PERIOD / 2, abs=PERIOD / N)
    assert min(result.strengths) > 0.95


def test_a_strong_pulse_that_arrests_early_is_not_major():
    # As strong as the survivor while it lives, but only for the first 30 s of 200 s.
    short = bump(50.0, 5e-3, T) * (T < 30.0)[:, None]
    result = pulses.major_pulses(X, T, bump(0.0, 5e-3, T) + short, 2.5e-4, C)
    assert result.count == 1


def test_nothing_above_threshold_and_bad_input():
    result = pulses.major_pulses(X, T, np.zeros((T.size, N)), 2.5e-4, C)
    assert result.count == 0 and math.isnan(result.spacing)
    with pytest.raises(ValueError):
        pulses.major_pulses(X, T, np.zeros((T.size, N)), 0.0, C)
    with pytest.raises(ValueError):
        pulses.major_pulses(X, T, np.zeros((T.size, N)), 1e-4, math.nan)


def test_moving_frame_piles_up_a_steady_pulse():
    # A pulse moving at c sits still in the frame moving at c: A is the profile times the duration
    # (c = 3 nodes per output interval, so that no interpolation blurs it).
    c = 3 * (PERIOD / N) / (T[1] - T[0])
    u = bump(30.0, 1e-3, T, celerity=c)
    accumulated = pulses.accumulated_in_moving_frame(X, T, u, 1e-6, c)
    frozen = bump(30.0, 1e-3, np.zeros(1))[0]
    dt = T[1] - T[0]
    assert accumulated == pytest.approx(np.where(frozen > 1e-6, frozen, 0.0) * dt * T.size, rel=1e-12, abs=1e-15)


def test_a_spike_narrower_than_a_pulse_is_no_major_pulse():
    # Opening at one node only, moving with the frame: above the fraction at a single node, which
    # slipping_mask's minimum width drops (seen on an H/32 run at nu = 0, f = 1.15, dt c_s = 1 m).
    u = np.zeros((T.size, N))
    u[:, 0] = 5e-3
    result = pulses.major_pulses(X, T, u, 2.5e-4, 0.0)
    assert result.count == 0 and math.isnan(result.spacing)
