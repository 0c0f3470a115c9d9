"""analysis.metrics.measure end to end on synthetic run files: metrics and categories with known answers."""

import json
import math

import pytest

from analysis.core.io import load_run
from analysis.fronts import rules
from analysis.metrics.measure import Settings, measure_run
from synthetic_run import Pulse, Scenario, paper_case, ratio_knots, wave_speeds

CONTRACT_KEYS = ("onset_time", "celerity", "celerity_window", "regime", "opening", "max_opening",
                 "min_T_over_N", "inversion", "category", "pulse_count", "pulse_spacing",
                 "energy_balance_error", "nu", "f", "V0_over_cs", "lambda_over_H", "elements_per_H",
                 "rho", "integration")


def measure(run_file, scenario, **settings):
    return measure_run(load_run(run_file(scenario)), Settings(**settings))


def test_paper_case(run_file):
    m = measure(run_file, paper_case())
    for key in CONTRACT_KEYS:
        assert key in m, key
    json.dumps(m, allow_nan=False)  # JSON-ready: no nan, no numpy types
    assert m["celerity"] == pytest.approx(0.882, rel=5e-3)
    assert m["celerity_xcorr"] == pytest.approx(0.882, rel=5e-3)
    assert m["celerity_agreement"] < 5e-3 and m["celerity_quality"] == "ok"
    assert m["celerity_window"][0] == pytest.approx(800.0, abs=4.0)
    assert m["celerity_window"][1] - m["celerity_window"][0] == pytest.approx(200.0, abs=4.0)
    assert m["regime"] == "intersonic" and m["below_sqrt2_cs"] is True
    assert m["intersonic_below_sqrt2_cs"] is True  # c_s = 0.645 <= 0.882 < sqrt(2) c_s = 0.913
    assert m["pulse_spacing_theory_over_H"] == pytest.approx(m["pulse_spacing_theory"] / 25.0)
    assert m["pulse_spacing_theory_over_H"] == pytest.approx(2 * math.sqrt((0.882 / m["c_s"]) ** 2 - 1),
                                                             rel=1e-2)
    assert m["category"] == "intersonic_opening_inversion"
    # Onset: the first output with slip (synthetic onset at 740 s), vs the quasi-static estimate.
    assert 740.0 <= m["onset_time"] < 740.0 + 4 * m["dt"]
    assert m["onset_time_estimate"] == pytest.approx(774.6, abs=0.1)
    # Opening: 1 cm in the middle of the pulse (5 m behind the half-amplitude point) from 880 s.
    assert m["opening"] is True and m["max_opening"] == pytest.approx(0.01, rel=1e-3)
    assert 880.0 <= m["first_opening_time"] < 880.0 + 4 * m["dt"]
    assert m["opening_inside_slip"] is True
    assert 4.0 < m["opening_behind_front"] < 9.0
    assert m["opening_threshold"] == pytest.approx(2.5e-4)
    # T/N knots: 1.425 -> 1.5 at 740 s, held to 850 s, down to -0.2 at 1000 s.
    assert m["min_T_over_N"] == pytest.approx(-0.2, abs=1e-3) and m["inversion"] is True
    assert m["min_T_over_N_time"] == pytest.approx(1000.0, abs=1.0)
    # Drops are found on T/N smoothed over 2H / c_s = 77.5 s, which moves a V-shaped bottom by up to
    # half that towards the gentler side.
    assert m["n_drops"] == 1 and m["first_drop_start_T_over_N"] == pytest.approx(1.5)
    assert m["first_drop_bottom_time"] == pytest.approx(1000.0, abs=25.0 / m["c_s"])
    # The bottom of the smoothed V: the 2H/c_s moving average of the scenario's piecewise-linear
    # T/N, computed here independently by quadrature (the chatter averages out).
    import numpy as np
    kt, kr = zip(*ratio_knots(paper_case()))
    width = 2 * 25.0 / m["c_s"]
    smoothed = [np.interp(np.linspace(t - width / 2, t + width / 2, 2001), kt, kr).mean()
                for t in np.arange(850.0, 1200.0, 1.0)]
    assert m["first_drop_bottom_T_over_N"] == pytest.approx(min(smoothed), abs=0.01)
    # One pulse in lambda = 2H; theory l = 2H sqrt(c^2/c_s^2 - 1) = 46.6 m -> 1 pulse.
    assert m["pulse_count"] == 1 and m["pulse_spacing"] == pytest.approx(50.0)
    assert m["pulse_count_field"] == "opening" and m["pulse_count_all"] == 1
    # One drop: no later drop to take a median of; the synthetic dissipation is 0.5 W_ext.
    assert m["later_drops_start_T_over_N_median"] is None and m["n_complete_drops"] == 1
    assert m["friction_work_ratio_opening"] == pytest.approx(0.5, rel=1e-6)
    assert m["dissipation_window_opening"][0] == m["first_opening_time"]
    assert m["pulse_spacing_theory"] == pytest.approx(46.6, abs=0.3) and m["pulse_count_theory"] == 1
    assert m["energy_balance_error"] == pytest.approx(1e-4, rel=1e-3)
    assert m["nu"] == 0.2 and m["f"] == 1.5 and m["elements_per_H"] == 32 and m["rho"] == 1000.0
    assert m["integration"] == "reduced" and m["V0_over_cs"] == 1e-5 and m["lambda_over_H"] == 2.0


@pytest.mark.parametrize("scenario, category, celerity", [
    (paper_case(), "intersonic_opening_inversion", 0.882),
    (paper_case(ratio_knots=[(0, 1.425), (740, 1.5), (900, 0.4), (1500, 1.0)]), "intersonic_opening", 0.882),
    (Scenario(pulses=[Pulse(0.85)]), "no_opening", None),  # fronts, but no opening pulse
    (Scenario(nu=0.49, f=0.5, pulses=[Pulse(-5.25, opening=0.02, opening_start=850.0)]),
     "supersonic_backward_opening", -5.25),
    (Scenario(nu=0.45, f=1.0, pulses=[Pulse(-2.523, opening=0.02, opening_start=850.0)]),
     "supersonic_backward_opening", -2.523),
    (Scenario(nu=0.0, f=2.0, pulses=[Pulse(1.213, opening=0.02, opening_start=850.0)]),
     "supersonic_forward_opening", 1.213),
    (Scenario(nu=0.45, f=1.0, pulses=[Pulse(-0.7, opening=0.02, opening_start=850.0)]),
     "intersonic_backward_opening", -0.7),
    (Scenario(pulses=[Pulse(0.5, opening=0.02, opening_start=850.0)]), "subsonic_forward_opening", 0.5),
    (Scenario(uniform_level=50.0, t_pulses=5000.0), "uniform_slip", None),
    (Scenario(uniform_level=0.0, t_onset=5000.0, t_pulses=5000.0), "no_slip", None),
])
def test_categories(run_file, scenario, category, celerity):
    m = measure(run_file, scenario)
    assert m["category"] == category
    if celerity is None:
        assert m["celerity"] is None and m["regime"] is None and m["celerity_window"] is None
    else:
        assert m["celerity"] == pytest.approx(celerity, rel=5e-3)


def test_regime_of_the_measured_celerity(run_file):
    c_s, c_l = wave_speeds(0.45)
    m = measure(run_file, Scenario(nu=0.45, f=1.0, pulses=[Pulse(-2.523, opening=0.02, opening_start=850.0)]))
    assert abs(m["celerity"]) > c_l and m["regime"] == "supersonic" and m["below_sqrt2_cs"] is False
    assert m["c_s"] == pytest.approx(c_s) and m["c_l"] == pytest.approx(c_l)


def test_two_pulses_in_lambda_4H(run_file):
    opens = dict(opening=0.01, opening_start=850.0)
    m = measure(run_file, Scenario(lambda_over_H=4.0, pulses=[Pulse(0.88, x_front=10.0, **opens),
                                                              Pulse(0.88, x_front=55.0, **opens)]))
    assert m["pulse_count"] == 2 and m["pulse_count_field"] == "opening"
    assert m["pulse_spacing"] == pytest.approx(50.0, abs=5.1)  # gaps of 45 and 55 m
    assert m["pulse_count_all"] == 2
    assert m["celerity_n_fronts"] == 2 and m["celerity"] == pytest.approx(0.88, rel=5e-3)


def test_later_drops(run_file):
    # Stick-slip: drops from 1.5, then from 1.02 and 0.99, each held 120 s (longer than the 2H/c_s
    # average); a 0.1 step chatter on top.
    knots = [(0, 1.425), (680, 1.5), (800, 1.5), (900, -0.1), (1020, -0.1), (1100, 1.02), (1220, 1.02),
             (1260, 0.3), (1380, 0.3), (1450, 0.99), (1570, 0.99), (1610, 0.2), (1800, 0.5)]
    scenario = paper_case(ratio_knots=knots, t_end=1800.0, ratio_chatter=0.1)
    m = measure(run_file, scenario)
    assert m["n_drops"] == 3
    assert m["later_drops_start_T_over_N"] == pytest.approx([1.02, 0.99], abs=3e-3)
    assert m["later_drops_start_T_over_N_median"] == pytest.approx(1.005, abs=3e-3)
    assert m["n_complete_drops"] == 3  # the last one recovers from 0.2 to 0.5 > 0.1 f
    assert m["first_drop_bottom_T_over_N"] == pytest.approx(-0.1, abs=3e-3)
    assert m["min_T_over_N"] == pytest.approx(-0.2, abs=3e-3)  # raw: with the chatter


def test_settings_change_the_measurement(run_file):
    path = run_file(Scenario(pulses=[Pulse(0.882, t_end=880.0, opening=0.01, opening_start=820.0)]))
    run = load_run(path)
    assert measure_run(run)["celerity"] is None  # lives 80 s < major_duration 100 s
    assert measure_run(run, Settings(major_duration=60.0))["celerity"] == pytest.approx(0.882, rel=5e-3)
    # A threshold above the pulse amplitude (3e-3 m/s = 465 V0) sees no slip.
    m = measure_run(run, Settings(threshold_rel=1000.0))
    assert m["celerity_reason"] == "no_slip" and m["slip_threshold"] == pytest.approx(1000 * m["V0"])
    with pytest.raises(ValueError, match="window_length"):
        measure_run(run, Settings(window_length=0.0))


def test_window_sensitivity_is_reported(run_file):
    # Pulse speeds up from 0.85 to 0.90 m/s when the interface opens at 950 s.
    early = Pulse(0.85, t_end=950.0)
    late = Pulse(0.90, x_front=10.0 + 0.85 * 150.0, t_start=950.0 + 1e-9, opening=0.01,
                 opening_start=950.0)
    m = measure(run_file, Scenario(pulses=[early, late], t_stop=1300.0))
    assert m["celerity_opening_window"] == pytest.approx(0.90, rel=5e-3)
    assert m["celerity_window_sensitivity"] == pytest.approx(m["celerity_opening_window"] / m["celerity"] - 1)
    assert math.isfinite(m["celerity_drift"]) and m["celerity_drift"] > 0.02


def test_windows_are_in_the_paper_time_unit():
    """Every time of the problem scales with sqrt(rho / E): the 200 s window of the paper (E = 1000 Pa,
    rho = 1000 kg/m^3) is 2 s at rho = 0.1 and 100 s at E = 4000 Pa."""
    from analysis.metrics.measure import time_unit_ratio

    assert time_unit_ratio(1000.0, 1000.0) == 1.0
    assert time_unit_ratio(1000.0, 0.1) == pytest.approx(0.01)
    assert time_unit_ratio(4000.0, 1000.0) == pytest.approx(0.5)


def test_the_paper_window_is_200_s(run_file):
    m = measure(run_file, paper_case())
    assert m["window_length"] == 200.0 and m["major_duration"] == 100.0


def _edit(path, **setup):
    import h5py

    with h5py.File(path, "a") as file:
        for key, value in setup.items():
            file["setup"].attrs[key] = value
    return path


def test_the_solver_constants_are_read_not_recomputed(run_file):
    # A threshold above the 1 cm opening: the run's own value decides, so no opening.
    path = _edit(run_file(paper_case()), opening_threshold=0.02, t_onset_estimate=123.0)
    m = measure_run(load_run(path))
    assert m["opening_threshold"] == 0.02 and m["opening"] is False and m["max_opening"] > 0.009
    assert m["onset_time_estimate"] == 123.0


def test_a_config_without_a_parameter_is_an_input_error(run_file):
    from analysis.core.errors import InputError
    from synthetic_run import default_config

    config = default_config(paper_case())
    del config["friction"]["pc_velocity"]
    with pytest.raises(InputError, match="lacks 'friction.pc_velocity'"):
        measure(run_file, paper_case(config_text=json.dumps(config)))


def test_outcome_of_the_run_is_carried(run_file):
    m = measure(run_file, paper_case(complete=0, end_reason="contact_not_converged"))
    assert m["complete"] is False and m["end_reason"] == "contact_not_converged"
    assert m["category"] == "intersonic_opening_inversion" and m["non_physical"] is False
    m = measure(run_file, paper_case())
    assert m["complete"] is True and m["end_reason"] == "t_end"


def test_without_friction_nothing_drops_or_inverts(run_file):
    # f = 0: T = 0; T/N is round-off around 0 (here +-1e-17 chatter, some of it negative).
    m = measure(run_file, paper_case(f=0.0, ratio_knots=[(0.0, 0.0), (1500.0, 0.0)],
                                     ratio_chatter=1e-17))
    assert m["min_T_over_N"] < 0
    assert m["n_drops"] == 0 and m["inversion"] is False and m["first_drop_start_time"] is None
    assert m["category"] == "intersonic_opening"
    assert m["celerity"] == pytest.approx(0.882, rel=5e-3)


def test_an_opening_larger_than_the_layer_is_non_physical(run_file):
    scenario = Scenario(pulses=[Pulse(0.882, opening=30.0, opening_start=880.0)],
                        complete=0, end_reason="contact_not_converged")
    m = measure(run_file, scenario)
    assert m["non_physical"] is True and m["category"] == "non_physical"
    assert m["non_physical_reason"].startswith("opening_above_H: max opening 30")
    assert m["max_opening"] == pytest.approx(30.0, rel=1e-3)  # the number stays visible
    # ... but not as a celerity: the pulse's fit is kept (window, fronts), its celerity is no measurement.
    assert m["celerity"] is None and m["celerity_reason"] == "non_physical"
    assert m["celerity_rule_opening_pulse_reason"] == "non_physical" and m["celerity_window"] is not None
    assert m["regime"] is None and m["pulse_count"] is None


def test_a_run_that_blew_up_is_non_physical_and_measured_before_the_blow_up(run_file):
    import h5py
    import numpy as np

    path = run_file(paper_case(complete=0, end_reason="contact_not_converged"))
    with h5py.File(path, "a") as file:
        t = file["/interface/t"][()]
        opening = file["/interface/opening"][()]
        opening[t >= 1400.0, 3] = np.inf
        file["/interface/opening"][...] = opening
        tg = file["/global/t"][()]
        work = file["/global/work_external"][()]
        work[tg >= 1420.0] = np.nan
        file["/global/work_external"][...] = work
    m = measure_run(load_run(path))
    assert m["category"] == "non_physical"
    assert m["non_physical_reason"] == "non_finite: /interface/opening, /global/work_external"
    assert m["max_opening"] < 1.0
    # Measured on the finite part, the pulse would give 0.882 m/s; a run that left the model has no celerity.
    assert m["celerity"] is None and m["celerity_reason"] == "non_physical"
    assert all(m[f"celerity_rule_{name}"] is None for name in rules.RULES)
    assert m["celerity_rule_localization_reason"] == "non_physical"


@pytest.mark.parametrize("stride, coarse", [(19, False), (21, True), (60, True)])
def test_sampling_too_coarse_is_its_own_category(run_file, stride, coarse):
    # 2H / (c_s dt_out) frames per shear round trip with dt_out = stride * 0.5 m / c_s: 100 / stride.
    m = measure(run_file, paper_case(interface_stride=stride))
    assert m["output_frames_per_round_trip"] == pytest.approx(100.0 / stride)
    assert m["sampling_too_coarse"] is coarse
    assert (m["category"] == "sampling_too_coarse") is coarse


def test_derived_metrics_figures_and_paper_need(run_file):
    m = measure(run_file, paper_case())
    assert m["celerity_over_cs"] == pytest.approx(m["celerity"] / m["c_s"], rel=1e-15)
    assert m["first_drop_start_after_onset"] == pytest.approx(m["first_drop_start_time"] - m["onset_time"])
    assert m["first_drop_duration"] == pytest.approx(m["first_drop_bottom_time"] - m["first_drop_start_time"])
    # nu = 0.2: the wedge is 1 < f < 6.19 (analysis.theory.flutter); nu = 0 has none.
    assert m["inside_flutter_wedge"] is True
    assert measure(run_file, paper_case(f=0.8))["inside_flutter_wedge"] is False
    assert measure(run_file, paper_case(nu=0.0))["inside_flutter_wedge"] is False
