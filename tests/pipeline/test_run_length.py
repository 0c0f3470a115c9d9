"""study/run_length.py and study/resources.py against closed forms and our measurements
(docs/physics-notes.md, docs/performance.md)."""

import json
import math
import subprocess

import pytest

from analysis.core.io import load_run
from analysis.metrics.measure import Settings, measure_run
from study import resources
from study.run_length import onset_time_estimate, run_length, shear_wave_speed

from .conftest import solver_or_skip

PAPER = dict(E=1000.0, H=25.0, Uy_over_H=-0.001, preshear_ratio=0.95, V0_over_cs=1e-5)


def onset(nu, f, rho=1000.0, **changes):
    return onset_time_estimate(**{**PAPER, **changes}, nu=nu, f=f, rho=rho)


def test_onset_by_hand_at_the_papers_reference_point():
    # nu = 0.2: p0 = 0.001 E 0.8 / (1.2 * 0.6) = 10/9 Pa, G = 1000/2.4 Pa, c_s = sqrt(G/1000).
    p0, G = 10.0 / 9.0, 1000.0 / 2.4
    V0 = 1e-5 * math.sqrt(G / 1000.0)
    expected = 0.05 * 1.5 * p0 * 25.0 / (G * V0)
    assert onset(0.2, 1.5) == pytest.approx(expected, rel=1e-14)
    assert expected == pytest.approx(774.597, abs=1e-3)  # the solver's t_onset_estimate attribute


@pytest.mark.parametrize("nu, f, first_slip, round_trips", [
    (0.0, 1.5, 534.6, 1), (0.2, 1.5, 743.6, 1), (0.3, 1.5, 1019.1, 1), (0.45, 1.0, 2343.2, 1),
    (0.49, 2.0, 21906.3, 1.25)])  # nu = 0.49: 104 s early, 1.2 round trips
def test_onset_estimate_is_near_the_measured_first_slip(nu, f, first_slip, round_trips):
    # docs/physics-notes.md: the first slip lands on a stair of the shear-wave staircase (round trip
    # 2H/c_s); onset_time measured at H/64 (study/results/table1/all_metrics.csv).
    round_trip = 2 * 25.0 / shear_wave_speed(1000.0, nu, 1000.0)
    assert abs(onset(nu, f) - first_slip) < round_trips * round_trip


def test_onset_scales_with_f_and_inversely_with_V0_and_not_with_rho():
    assert onset(0.3, 2.0) == pytest.approx(2 * onset(0.3, 1.0), rel=1e-14)
    assert onset(0.3, 1.0, V0_over_cs=1e-6) == pytest.approx(10 * onset(0.3, 1.0), rel=1e-14)
    # V0 = 1e-5 c_s and c_s ~ rho^-1/2: the onset time scales like sqrt(rho), as dt does.
    assert onset(0.3, 1.0, rho=10.0) == pytest.approx(onset(0.3, 1.0) / 10.0, rel=1e-14)


def test_run_length_adds_transits_and_stops_after_opening():
    times = run_length(**PAPER, nu=0.2, rho=1000.0, f=1.5, duration_transits=60, stop_after_opening_transits=15)
    transit = 25.0 / shear_wave_speed(1000.0, 0.2, 1000.0)
    assert times.transit_time == pytest.approx(38.7298, abs=1e-4)
    assert times.t_end == pytest.approx(onset(0.2, 1.5) + 60 * transit, rel=1e-14)
    assert times.stop_after_opening == pytest.approx(15 * transit, rel=1e-14)
    # The cap holds the slow growth near f = 1 (nu = 0, f = 1.1 opens 1075 s after the first slip at
    # H/32, docs/physics-notes.md) plus the stop delay, with margin.
    near_one = run_length(**PAPER, nu=0.0, rho=1000.0, f=1.1, duration_transits=60, stop_after_opening_transits=15)
    assert near_one.t_end - near_one.t_onset_estimate > 1075.0 + near_one.stop_after_opening + 500.0


def test_explicit_t_end_and_no_stop():
    times = run_length(**PAPER, nu=0.2, rho=1000.0, f=1.5, duration_transits=60,
                       stop_after_opening_transits=None, t_end=20000.0)
    assert times.t_end == 20000.0 and times.stop_after_opening is None


@pytest.mark.parametrize("bad", [dict(duration_transits=0), dict(stop_after_opening_transits=-1.0),
                                 dict(t_end=0.0)])
def test_bad_lengths_are_rejected(bad):
    arguments = dict(duration_transits=60, stop_after_opening_transits=15, t_end=None)
    with pytest.raises(ValueError):
        run_length(**PAPER, nu=0.2, rho=1000.0, f=1.5, **{**arguments, **bad})


def test_step_count_does_not_depend_on_density():
    # Durations in H/c_s and dt = 0.5 m / c_s: the same number of steps whatever rho.
    counts = set()
    for rho in (0.1, 10.0, 1000.0):
        times = run_length(**PAPER, nu=0.2, rho=rho, f=1.5, duration_transits=60, stop_after_opening_transits=15)
        counts.add(resources.n_steps(E=1000.0, nu=0.2, rho=rho, t_end=times.t_end))
    assert len(counts) == 1
    (steps,) = counts
    # The onset estimate at nu = 0.2, f = 1.5 is 1000 steps exactly (774.597 s / 0.774597 s), and a
    # transit is H / (0.5 m) = 50 steps.
    assert steps == 1000 + 60 * 50


# A deformable substrate (study/run_length.py eq. (1'), analysis.theory.elastic.pair_onset_time_estimate).
def pair_length(substrate, f=2.0, nu=0.2):
    return run_length(**PAPER, nu=nu, rho=1000.0, f=f, duration_transits=8, stop_after_opening_transits=None,
                      substrate=substrate)


def test_onset_on_a_substrate_by_hand():
    # Layer nu = 0.2 on E_s = E, nu_s = 0.45, H_s = H / 2: M = 1000 0.8 / (1.2 0.6), M_s = 1000 0.55 / (1.45 0.1),
    # G = 1000 / 2.4, G_s = 1000 / 2.9. The pressure drops by 1 + (H_s / M_s) / (H / M), the top's
    # displacement per unit shear stress grows by 1 + (H_s / G_s) / (H / G).
    M, M_s, G, G_s = 1000 * 0.8 / 0.72, 1000 * 0.55 / 0.145, 1000 / 2.4, 1000 / 2.9
    normal, shear = 1 + 12.5 / M_s / (25 / M), 1 + 12.5 / G_s / (25 / G)
    substrate = {"E": 1000.0, "nu": 0.45, "rho": 1000.0, "H": 12.5}
    assert pair_length(substrate).t_onset_estimate == pytest.approx(onset(0.2, 2.0) * shear / normal, rel=1e-12)
    assert shear / normal == pytest.approx(1.3992, abs=1e-4)


@pytest.mark.parametrize("contrast", [1000.0, 10.0, 3.0, 1.0, 1 / 3])
def test_onset_with_the_layers_nu_and_thickness_is_the_rigid_flats(contrast):
    # Both compliances grow by 1 + E / E_s: the factors cancel (only p0 is lower), the study's contrast sweep.
    substrate = {"E": 1000.0 * contrast, "nu": 0.45, "rho": 1000.0, "H": 25.0}
    assert pair_length(substrate, nu=0.45).t_onset_estimate == pytest.approx(onset(0.45, 2.0), rel=1e-12)


def test_a_very_stiff_substrate_is_the_rigid_flat():
    substrate = {"E": 1e12, "nu": 0.3, "rho": 1000.0, "H": 6.25}
    assert pair_length(substrate).t_onset_estimate == pytest.approx(onset(0.2, 2.0), rel=1e-8)


def test_onset_on_a_substrate_is_near_the_measured_first_slip(tmp_path):
    # A real run at H/16 (0.2 s): 1445 s estimated, 1413 s measured (1403 s at H/32); the rigid flat's
    # 1033 s would be 27 % early. A thinner substrate of another nu exercises both compliances.
    solver = solver_or_skip()
    substrate = {"E": 1000.0, "nu": 0.45, "rho": 1000.0, "H": 12.5}
    times = pair_length(substrate)
    config = {"material": {"E": 1000.0, "nu": 0.2, "rho": 1000.0}, "geometry": {"H": 25.0, "lambda_over_H": 2.0},
              "mesh": {"elements_per_H": 16}, "friction": {"f": 2.0}, "time": {"t_end": times.t_end},
              "substrate": substrate}
    (tmp_path / "config.json").write_text(json.dumps(config))
    subprocess.run([str(solver), "run", str(tmp_path / "config.json"), "-o", str(tmp_path / "run.h5")],
                   check=True, capture_output=True, timeout=300)
    measured = measure_run(load_run(tmp_path / "run.h5"), Settings())["onset_time"]
    assert measured == pytest.approx(times.t_onset_estimate, rel=0.04)
    assert abs(measured - onset(0.2, 2.0)) > 0.25 * measured  # the rigid flat's estimate is far off
