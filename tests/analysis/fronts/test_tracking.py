"""analysis.fronts.tracking: the open track's predicted velocity is the least-squares slope of its last
four points (its closed form replaced np.polyfit, which it must equal to round-off)."""

import numpy as np
import pytest

from analysis.fronts.tracking import _OpenTrack


def track_of(times, positions):
    track = _OpenTrack(times[0], positions[0], 1.0)
    track.t += list(times[1:])
    track.p += list(positions[1:])
    return track


@pytest.mark.parametrize("n_points", [2, 3, 4, 7])
def test_velocity_is_the_least_squares_slope_of_the_last_four_points(n_points):
    rng = np.random.default_rng(n_points)
    # Output times near a run's (hundreds of s, steps of ~1 s): polyfit on them is good to ~1e-11.
    times = 800.0 + np.cumsum(rng.uniform(0.5, 2.0, n_points))
    positions = 30.0 + 0.9 * (times - times[0]) + rng.normal(0.0, 0.05, n_points)
    expected = np.polyfit(times[-4:], positions[-4:], 1)[0]
    assert track_of(times, positions).velocity() == pytest.approx(expected, rel=1e-9, abs=1e-12)


def test_velocity_needs_two_points():
    assert _OpenTrack(1.0, 2.0, 1.0).velocity() is None
