"""analysis.fronts.celerity on synthetic slip-velocity maps with known front speeds (no files)."""

import math

import numpy as np
import pytest

from analysis.fronts import celerity as cel
from analysis.fronts import edges, tracking, xcorr
from synthetic_run import Pulse, Scenario, build_fields, wave_speeds


def measure_map(scenario, **kw):
    d = build_fields(scenario)
    c_s = wave_speeds(scenario.nu)[0]
    front_map = tracking.find_edges(d["x"], d["t"], d["v"], 10 * d["V0"])
    result = cel.celerity_from_fronts(front_map, min_speed=0.1 * c_s, **kw)
    by_xcorr = (xcorr.celerity_by_xcorr(d["x"], d["t"], d["v"], result.window)
                if result.window else xcorr.XcorrResult(math.nan))
    return result, by_xcorr, d


# ---------------------------------------------------------------------------------------------
# One frame


def test_slipping_mask_drops_specks_and_fills_gaps():
    v = np.zeros(20)
    v[3] = 1.0                      # one-node speck: dropped
    v[8:15] = 1.0
    v[11] = 0.0                     # one-node gap inside a pulse: filled
    v[18:] = 1.0
    v[0] = 1.0                      # run 18, 19, 0 wraps across the period
    mask = edges.slipping_mask(v, 0.5)
    assert not mask[3]
    assert mask[8:15].all()
    assert mask[[18, 19, 0]].all() and not mask[1]


def test_edges_are_located_between_nodes_by_linear_interpolation():
    grid = edges.PeriodicGrid(x0=0.0, dx=0.5, n=16)
    v = np.zeros(16)
    v[5:9] = 1.0
    v[4] = 0.25       # left edge: threshold 0.5 is crossed 1/3 of the way from node 4 to node 5
    v[9] = 0.4        # right edge: crossed 5/6 of the way from node 8 to node 9
    mask = edges.slipping_mask(v, 0.5)
    left, right, peaks = edges.edge_positions(v, mask, 0.5, grid)
    assert left == pytest.approx([0.5 * (4 + 1 / 3)])
    assert right == pytest.approx([0.5 * (8 + 5 / 6)])
    assert peaks == pytest.approx([1.0])


def test_edges_across_the_periodic_boundary():
    grid = edges.PeriodicGrid(x0=0.0, dx=1.0, n=10)
    v = np.zeros(10)
    v[[8, 9, 0, 1]] = [1.0, 2.0, 3.0, 1.0]
    left, right, peaks = edges.edge_positions(v, edges.slipping_mask(v, 0.5), 0.5, grid)
    assert left == pytest.approx([7.5]) and right == pytest.approx([1.5]) and peaks == pytest.approx([3.0])


def test_uniform_and_empty_frames_have_no_edges():
    grid = edges.PeriodicGrid(x0=0.0, dx=1.0, n=10)
    for v in (np.ones(10), np.zeros(10)):
        left, right, peaks = edges.edge_positions(v, edges.slipping_mask(v, 0.5), 0.5, grid)
        assert left.size == right.size == peaks.size == 0


def test_grid_rejects_non_uniform_nodes():
    with pytest.raises(ValueError, match="uniformly"):
        edges.PeriodicGrid.from_nodes(np.array([0.0, 1.0, 2.5, 3.0]))


# ---------------------------------------------------------------------------------------------
# Celerity of synthetic pulses: both estimates within 0.5 %


CASES = {
    "forward intersonic": (Scenario(pulses=[Pulse(0.882)]), 0.882),
    "backward intersonic": (Scenario(nu=0.45, f=1.0, pulses=[Pulse(-0.7)]), -0.7),
    "backward supersonic nu=0.45": (Scenario(nu=0.45, f=0.95, pulses=[Pulse(-2.523)]), -2.523),
    "backward supersonic nu=0.49": (Scenario(nu=0.49, f=0.5, pulses=[Pulse(-5.25, x_front=30)]), -5.25),
    "backward supersonic 6 m/s": (Scenario(nu=0.49, f=0.8, pulses=[Pulse(-6.0, x_front=30)]), -6.0),
    "forward supersonic": (Scenario(nu=0.0, f=2.0, pulses=[Pulse(1.213)]), 1.213),
    "wraps across x = lambda": (Scenario(pulses=[Pulse(0.9, x_front=49.5)]), 0.9),
    "wraps across x = 0": (Scenario(pulses=[Pulse(-0.8, x_front=0.3, length=6.0)]), -0.8),
    "two pulses, lambda = 4H": (Scenario(lambda_over_H=4.0, pulses=[
        Pulse(0.88, x_front=10.0), Pulse(0.88, x_front=60.0, amplitude=2.5e-3)]), 0.88),
    "three pulses, lambda = 6H": (Scenario(lambda_over_H=6.0, pulses=[
        Pulse(0.9, x_front=x) for x in (5.0, 55.0, 105.0)]), 0.9),
    "noise 1 %": (Scenario(pulses=[Pulse(0.882)], noise=3e-5, seed=1), 0.882),
    "noise 2 %": (Scenario(pulses=[Pulse(0.882)], noise=6e-5, seed=3), 0.882),
    "noise 1 %, supersonic": (Scenario(nu=0.49, f=0.5, pulses=[Pulse(-5.25)], noise=3e-5, seed=2), -5.25),
    "a secondary pulse dies": (Scenario(pulses=[
        Pulse(0.882, x_front=10.0),
        Pulse(0.7, x_front=35.0, amplitude=1.5e-3, decay_time=10.0, deceleration=0.005)]), 0.882),
    "a weaker, slower pulse lives on": (Scenario(pulses=[
        Pulse(0.882, x_front=10.0), Pulse(0.84, x_front=35.0, amplitude=1e-3, t_end=960.0)]), 0.882),
    "a slower pulse dies, counter-propagating": (Scenario(pulses=[
        Pulse(0.85, x_front=10.0), Pulse(-0.7, x_front=40.0, amplitude=1e-3, t_end=860.0)]), 0.85),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_celerity_within_half_a_percent(name):
    scenario, true_celerity = CASES[name]
    result, by_xcorr, _ = measure_map(scenario)
    assert result.reason == "ok"
    assert result.celerity == pytest.approx(true_celerity, rel=5e-3)
    assert by_xcorr.celerity == pytest.approx(true_celerity, rel=5e-3)
    assert result.direction == (1 if true_celerity > 0 else -1)
    assert result.r2 > 0.999


def test_weaker_pulses_are_secondary():
    scenario, _ = CASES["a weaker, slower pulse lives on"]
    result, _, _ = measure_map(scenario)
    assert result.n_fronts == 1 and result.n_secondary_fronts == 1
    result, _, _ = measure_map(scenario, min_relative_strength=0.2)  # both in the fit
    assert result.n_fronts == 2 and result.celerity < 0.875


def test_window_starts_when_the_major_pulse_is_localized():
    scenario = Scenario(pulses=[Pulse(0.882, t_start=812.0)], t_pulses=812.0)
    result, _, d = measure_map(scenario)
    dt_out = d["t"][1] - d["t"][0]
    assert 812.0 <= result.t_localized < 812.0 + dt_out
    assert result.nominal_window == pytest.approx((result.t_localized, result.t_localized + 200.0))
    assert result.window[0] == result.t_localized
    assert result.window[1] == pytest.approx(result.t_localized + 200.0, abs=dt_out)


def test_window_is_clipped_when_the_pulse_stops():
    scenario = Scenario(pulses=[Pulse(0.882)], t_stop=950.0)
    result, _, _ = measure_map(scenario)
    assert result.window[1] < 950.0 and result.window[1] - result.window[0] > 140.0
    assert result.celerity == pytest.approx(0.882, rel=5e-3)


def test_short_lived_pulses_are_not_major():
    scenario = Scenario(pulses=[Pulse(0.882, t_end=860.0)])
    result, _, _ = measure_map(scenario)
    assert result.reason == "no_major_front" and math.isnan(result.celerity)
    result, _, _ = measure_map(scenario, major_duration=40.0)
    assert result.celerity == pytest.approx(0.882, rel=5e-3)


def test_window_start_can_be_given():
    # The pulse accelerates from 0.8 to 0.9 m/s at t = 1000 s; a window from 1000 s sees 0.9.
    early = Pulse(0.8, t_end=1000.0)
    late = Pulse(0.9, x_front=10.0 + 0.8 * 200.0, t_start=1000.0 + 1e-9)
    result, _, _ = measure_map(Scenario(pulses=[early, late], t_end=1400.0, t_stop=1400.0),
                               window_start=1000.0)
    assert result.celerity == pytest.approx(0.9, rel=5e-3)


@pytest.mark.parametrize("scenario, reason", [
    (Scenario(uniform_level=50.0, t_pulses=5000.0, noise=5e-6), "uniform_slip"),
    (Scenario(uniform_level=0.0), "no_slip"),
])
def test_no_front_gives_nan(scenario, reason):
    result, by_xcorr, _ = measure_map(scenario)
    assert result.reason == reason
    assert math.isnan(result.celerity) and result.window is None and math.isnan(by_xcorr.celerity)


def test_noise_alone_makes_no_major_front():
    # Noise at 0.9 of the threshold everywhere: spurious edges, but no front to follow.
    scenario = Scenario(uniform_level=0.0, noise=5.8e-5, seed=4)
    result, _, _ = measure_map(scenario)
    assert result.reason == "no_major_front"


@pytest.mark.parametrize("seed", [2, 3])
def test_noise_above_the_threshold_gives_nan_or_the_right_answer(seed):
    # nu = 0.49: threshold 10 V0 = 5.8e-5 m/s, below the noise; aliases must not pass as fronts.
    scenario = Scenario(nu=0.49, f=0.5, pulses=[Pulse(-5.25)], noise=6e-5, seed=seed)
    result, _, _ = measure_map(scenario)
    assert math.isnan(result.celerity) or result.celerity == pytest.approx(-5.25, rel=5e-3)


def test_xcorr_of_a_rigidly_moving_pattern():
    # A smooth periodic pattern moved by exactly c t: the correlation peak is 1.
    x = np.arange(64) * 0.78125
    t = np.arange(80) * 3.1
    c = -1.7
    v = np.exp(np.cos(2 * np.pi * (x[None, :] - c * t[:, None]) / 50.0) * 2.0)
    result = xcorr.celerity_by_xcorr(x, t, v, (t[0], t[-1]))
    assert result.celerity == pytest.approx(c, rel=1e-4)
    assert result.peak_correlation == pytest.approx(1.0, abs=1e-3)


def test_pooled_slope_of_parallel_tracks():
    t = np.linspace(0.0, 100.0, 21)
    ones = np.ones_like(t)
    tracks = [tracking.EdgeTrack("right", t, 3.0 + 0.5 * t, ones), tracking.EdgeTrack("right", t, -40.0 + 0.5 * t, ones)]
    slope, stderr, r2, rms, n = cel.pooled_slope(tracks)
    assert slope == pytest.approx(0.5, rel=1e-12) and r2 == pytest.approx(1.0) and n == 42
    assert rms == pytest.approx(0.0, abs=1e-9)
