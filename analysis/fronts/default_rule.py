"""`celerity` and its diagnostics: the default measurement rule's fit, for every run.

The default rule (`analysis.fronts.rules.DEFAULT_RULE`, argued in docs/measurement-rule.md) gives
the celerity, its window and the fronts it fitted (`RuleResult`); every `celerity_*` diagnostic of
the metrics is computed on that fit, so that a number and its uncertainty always describe the same
fronts over the same window. Where the rule is undefined (e.g. a run that never opens) the
celerity is nan with the rule's reason, and so is every diagnostic: no other rule stands in.

- stderr, r2, rms, n_points: the pooled fit of the fitted fronts (`analysis.fronts.celerity.pooled_slope`);
- drift = (slope over the second half - over the first half) / |c|: the rule's deceleration
  (relative to the signed slope) times the sign of c;
- frame_shift = |c| dt_out, and the aliasing risk above ALIASING_FRACTION of the pulse spacing;
- xcorr over the rule's window (`analysis.fronts.xcorr`), agreement = |xcorr - c| / |c|;
- quality: `ok` or a `;`-list of the concerns below;
- window sensitivity: the same pulse measured from its opening (`WINDOW_SENSITIVITY_RULE`);
- threshold sensitivity: the default rule at a higher slip threshold (the caller measures it).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from analysis.fronts import celerity as cel
from analysis.fronts.rules import DEFAULT_RULE, WINDOW_SENSITIVITY_RULE, RuleResult
from analysis.fronts.sampling_limit import frame_shift_fraction
from analysis.fronts.xcorr import XcorrResult, celerity_by_xcorr

#: celerity_quality flags: |threshold - xcorr| / |c| above this -> "estimates_disagree";
QUALITY_AGREEMENT = 0.02
#: |drift| above this -> "unsteady";
QUALITY_DRIFT = 0.05
#: |c| dt_out above this fraction of the pulse spacing -> "aliasing_risk" (the limit, beyond which a fit is
#: no celerity, is sampling_limit.SAMPLING_LIMIT = 1/2).
ALIASING_FRACTION = 0.4


def relative(a: float, b: float) -> float:
    """(a - b) / |b|, nan when either is nan or b = 0."""
    if not (math.isfinite(a) and math.isfinite(b)) or b == 0:
        return math.nan
    return (a - b) / abs(b)


def direction(result: RuleResult) -> int:
    """+1 / -1: the sign of the rule's celerity; 0 when it is undefined."""
    return int(math.copysign(1, result.celerity)) if math.isfinite(result.celerity) else 0


#: The keys `celerity_metrics` returns, in its order (analysis/README.md, "Metric keys").
CELERITY_KEYS = (
    "celerity", "celerity_over_cs", "celerity_reason", "celerity_window", "celerity_window_start",
    "celerity_window_end", "celerity_stderr", "celerity_r2", "celerity_rms", "celerity_n_fronts",
    "celerity_n_points", "celerity_n_counter_fronts", "celerity_n_secondary_fronts", "celerity_drift",
    "celerity_frame_shift", "celerity_aliasing_risk", "celerity_quality", "celerity_xcorr",
    "celerity_xcorr_peak", "celerity_agreement", "celerity_opening_window",
    "celerity_window_sensitivity", "celerity_high_threshold", "celerity_threshold_sensitivity")


def celerity_metrics(by_rule: dict[str, RuleResult], high_threshold: RuleResult, *, x: np.ndarray,
                     t: np.ndarray, v: np.ndarray, c_s: float, output_interval: float,
                     pulse_spacing: float, window_length: float) -> dict[str, Any]:
    """The `celerity*` keys of the metrics (analysis/README.md) from the default rule's result.

    Parameters
    ----------
    by_rule
        `celerity_rules.measure_rules` of the run (every rule).
    high_threshold
        The default rule measured at the sensitivity threshold.
    x, t, v
        Node positions (m), output times (s) and slip-velocity map (m/s) (for the xcorr estimate).
    c_s
        Shear wave speed (m/s).
    output_interval
        Interface output interval dt_out (s).
    pulse_spacing
        Gap between neighbouring pulses (m; the period for one pulse): the aliasing limit.
    window_length
        The rules' window (s): a fit spanning less than half of it is a short window.
    """
    result = by_rule[DEFAULT_RULE]
    c, ok = result.celerity, result.reason == "ok"
    _, stderr, r2, rms, n_points = (cel.pooled_slope(list(result.fronts)) if ok
                                    else (math.nan,) * 4 + (0,))
    drift = result.deceleration * direction(result) if ok else math.nan
    frame_shift = abs(c) * output_interval if ok else math.nan
    xcorr = celerity_by_xcorr(x, t, v, result.window) if ok else XcorrResult(math.nan)
    agreement = abs(relative(xcorr.celerity, c))
    aliasing_risk = (bool(frame_shift_fraction(c, output_interval, pulse_spacing) > ALIASING_FRACTION)
                     if ok else None)
    quality = None
    if ok:
        concerns = [name for name, bad in (
            ("estimates_disagree", not agreement <= QUALITY_AGREEMENT),
            ("unsteady", not abs(drift) <= QUALITY_DRIFT),
            ("aliasing_risk", aliasing_risk),
            ("counter_fronts", result.n_counter_fronts > 0),
            ("short_window", result.window[1] - result.window[0] < 0.5 * window_length),
        ) if bad]
        quality = ";".join(concerns) or "ok"
    c_opening_window = by_rule[WINDOW_SENSITIVITY_RULE].celerity
    return {
        "celerity": c,
        "celerity_over_cs": c / c_s,
        "celerity_reason": result.reason,
        "celerity_window": list(result.window) if result.window else None,
        "celerity_window_start": result.window[0] if result.window else math.nan,
        "celerity_window_end": result.window[1] if result.window else math.nan,
        "celerity_stderr": stderr,
        "celerity_r2": r2,
        "celerity_rms": rms,
        "celerity_n_fronts": len(result.fronts),
        "celerity_n_points": n_points,
        "celerity_n_counter_fronts": result.n_counter_fronts,
        "celerity_n_secondary_fronts": result.n_secondary_fronts,
        "celerity_drift": drift,
        "celerity_frame_shift": frame_shift,
        "celerity_aliasing_risk": aliasing_risk,
        "celerity_quality": quality,
        "celerity_xcorr": xcorr.celerity,
        "celerity_xcorr_peak": xcorr.peak_correlation,
        "celerity_agreement": agreement,
        "celerity_opening_window": c_opening_window,
        "celerity_window_sensitivity": relative(c_opening_window, c),
        "celerity_high_threshold": high_threshold.celerity,
        "celerity_threshold_sensitivity": relative(high_threshold.celerity, c),
    }
