"""`celerity` is the default measurement rule `opening_pulse` for every run (docs/measurement-rule.md),
its diagnostics describe that rule's fit, and the category follows the opening pulse."""

import json
import math

import pytest

from analysis.core.io import load_run
from analysis.fronts import rules
from analysis.metrics.measure import ANALYSIS_VERSION, measure_run
from synthetic_run import Pulse, Scenario, wave_speeds
from test_rules import precursor_then_opening_pulse

#: Every diagnostic of `celerity` that describes the default rule's fit.
DIAGNOSTICS = ("celerity_over_cs", "celerity_window", "celerity_window_start", "celerity_window_end",
               "celerity_stderr", "celerity_r2", "celerity_rms", "celerity_drift",
               "celerity_frame_shift", "celerity_aliasing_risk", "celerity_quality", "celerity_xcorr",
               "celerity_xcorr_peak", "celerity_agreement", "celerity_opening_window",
               "celerity_window_sensitivity", "celerity_high_threshold",
               "celerity_threshold_sensitivity")


def measure(run_file, scenario):
    return measure_run(load_run(run_file(scenario)))


def test_the_default_rule_is_opening_pulse():
    assert rules.DEFAULT_RULE == "opening_pulse" and int(ANALYSIS_VERSION) >= 4  # since version 4


def test_celerity_is_the_opening_pulse_not_the_precursor(run_file):
    # nu = 0: a strong precursor near c_l (0.98 m/s) localizes first and never opens; the pulse
    # that opens runs at 0.80 m/s (c_s = 0.707, c_l = 1).
    m = measure(run_file, precursor_then_opening_pulse())
    assert m["celerity_rule_default"] == "opening_pulse"
    assert m["celerity"] == m["celerity_rule_opening_pulse"] == pytest.approx(0.80, rel=5e-3)
    assert m["celerity_rule_localization"] == pytest.approx(0.98, rel=5e-3)
    assert m["celerity_window"] == m["celerity_rule_opening_pulse_window"]
    assert m["celerity_window_start"] == m["celerity_window"][0] >= 905.0
    # Every diagnostic is the opening pulse's: one front, xcorr over its window, the same pulse
    # from its opening, the same rule at 10x the threshold.
    assert m["celerity_n_fronts"] == 1 and m["celerity_n_counter_fronts"] == 0
    assert m["celerity_xcorr"] == pytest.approx(0.80, rel=5e-3) and m["celerity_quality"] == "ok"
    assert m["celerity_opening_window"] == m["celerity_rule_opening_pulse_from_opening"]
    assert m["celerity_window_sensitivity"] == pytest.approx(m["celerity_opening_window"] / m["celerity"] - 1)
    assert m["celerity_high_threshold"] == pytest.approx(0.80, rel=5e-3)
    assert m["celerity_over_cs"] == pytest.approx(0.80 / wave_speeds(0.0)[0], rel=5e-3)
    # Regime, category and everything derived from c come from the opening pulse.
    assert m["regime"] == "intersonic" and m["category"].startswith("intersonic_opening")
    assert m["pulse_spacing_theory"] == pytest.approx(
        2 * 25.0 * math.sqrt((m["celerity"] / m["c_s"]) ** 2 - 1), rel=1e-9)


def test_a_run_that_never_opens_has_no_celerity_and_is_no_opening(run_file):
    m = measure(run_file, Scenario(pulses=[Pulse(0.85)]))
    assert m["opening"] is False and m["category"] == "no_opening"
    assert m["celerity"] is None and m["celerity_reason"] == "no_opening"
    # No other rule stands in: every diagnostic of the default is undefined too ...
    assert all(m[key] is None for key in DIAGNOSTICS), [k for k in DIAGNOSTICS if m[k] is not None]
    assert m["celerity_n_fronts"] == 0 and m["regime"] is None and m["pulse_count"] is None
    # ... while the run's major front is still measured under its own rule's name.
    assert m["celerity_rule_localization"] == pytest.approx(0.85, rel=5e-3)
    assert m["celerity_rule_localization_reason"] == "ok"
    json.dumps(m, allow_nan=False)


def test_a_run_that_opens_without_an_opening_pulse_is_opening_without_front(run_file):
    # The major pulse never opens; a short pulse 15 m ahead opens and dies within 50 s.
    m = measure(run_file, Scenario(pulses=[
        Pulse(0.882), Pulse(0.882, x_front=25.0, t_start=900.0, t_end=950.0, opening=0.01,
                            opening_start=910.0)]))
    assert m["opening"] is True and m["celerity_rule_localization"] == pytest.approx(0.882, rel=5e-3)
    assert m["celerity"] is None and m["celerity_reason"] == "no_opening_pulse"
    assert m["category"] == "opening_without_front" and m["regime"] is None


def test_metrics_carry_complete_once(run_file):
    m = measure(run_file, Scenario(pulses=[Pulse(0.85)]))
    assert m["complete"] is True and "run_complete" not in m


def test_the_category_follows_the_opening_pulse_not_a_supersonic_precursor(run_file):
    # nu = 0 (c_l = 1 m/s): a precursor at 1.05 m/s (supersonic) localizes first and never opens;
    # the pulse that opens runs at 0.80 m/s (intersonic).
    scenario = precursor_then_opening_pulse()
    scenario.pulses[0].celerity = 1.05
    m = measure(run_file, scenario)
    assert m["celerity_rule_localization"] == pytest.approx(1.05, rel=5e-3)
    assert m["celerity_rule_localization"] > m["c_l"]
    assert m["celerity"] == pytest.approx(0.80, rel=5e-3) and m["regime"] == "intersonic"
    assert m["category"] in ("intersonic_opening", "intersonic_opening_inversion")
