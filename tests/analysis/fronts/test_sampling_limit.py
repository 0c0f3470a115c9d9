"""A fit that moves more than half a pulse spacing per frame is no celerity (analysis.fronts.sampling_limit)."""

import math

import pytest

from analysis.core.io import load_run
from analysis.fronts import sampling_limit
from analysis.fronts.rules import RuleResult
from analysis.fronts.sampling_limit import BEYOND_SAMPLING_LIMIT, within_sampling_limit
from analysis.metrics.measure import measure_run
from synthetic_run import paper_case

#: dt_out (s) and the spacing (m) of a run at lambda = 2H = 50 m with one pulse.
DT_OUT, SPACING = 3.45, 50.0


def fit(celerity):
    return RuleResult(celerity=celerity, reason="ok", window=(900.0, 1100.0), deceleration=0.01)


@pytest.mark.parametrize("celerity", [-5.8, -7.2, 7.2, 0.88])
def test_fronts_up_to_half_a_spacing_per_frame_are_measured(celerity):
    # -5.8 m/s: the backward supersonic fronts at nu = 0.49 move 0.40 spacings per frame; 7.2 m/s: 0.497.
    assert within_sampling_limit(fit(celerity), DT_OUT, SPACING) == fit(celerity)


@pytest.mark.parametrize("celerity", [-7.3, 7.3, -125.0])
def test_fronts_beyond_half_a_spacing_per_frame_are_undefined(celerity):
    limited = within_sampling_limit(fit(celerity), DT_OUT, SPACING)
    assert math.isnan(limited.celerity) and limited.reason == BEYOND_SAMPLING_LIMIT
    assert math.isnan(limited.deceleration)
    # The fit is kept for the diagnostics: its window and fronts.
    assert limited.window == fit(celerity).window and limited.fronts == fit(celerity).fronts


def test_undefined_fits_are_left_as_they_are():
    undefined = RuleResult(celerity=math.nan, reason="no_opening")
    assert within_sampling_limit(undefined, DT_OUT, SPACING) is undefined


def test_a_run_whose_pulse_is_beyond_the_limit_has_no_celerity(run_file, monkeypatch):
    # The paper case's pulse (0.88 m/s) moves 0.05 spacings per frame; a limit below that makes it
    # a pulse the frames cannot resolve: no celerity, with the reason, and the run's category is
    # that its sampling is too coarse (it enters no table), while the other keys stay measured.
    measured = measure_run(load_run(run_file(paper_case())))
    assert measured["celerity_reason"] == "ok" and measured["category"] != "sampling_too_coarse"
    monkeypatch.setattr(sampling_limit, "SAMPLING_LIMIT", 0.01)
    m = measure_run(load_run(run_file(paper_case())))
    assert m["celerity"] is None and m["celerity_reason"] == BEYOND_SAMPLING_LIMIT
    assert m["celerity_rule_localization"] is None
    assert m["category"] == "sampling_too_coarse" and m["regime"] is None
    assert m["sampling_too_coarse"] is False  # the run's frames per round trip are enough
    assert m["opening"] is True and m["min_T_over_N"] == measured["min_T_over_N"]
