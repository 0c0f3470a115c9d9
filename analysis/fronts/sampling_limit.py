"""The sampling limit of a fitted celerity: what the interface frames can tell apart.

Fronts are tracked from frame to frame of the interface output, dt_out apart, on a periodic train of
pulses `spacing` apart (the period for one pulse). A front that moves by s = |c| dt_out between two
frames looks, in those frames, exactly like one that moves by s - spacing (the other way) or by
s + spacing: the same aliasing as a sampled wave above its Nyquist frequency. Only below half the
spacing is the nearest edge in the next frame the same front. A fit whose slope says the front moved
further than that contradicts the frame-to-frame linking it was made from (edges that appear and
vanish as the interface lets go at once, joined into one track): it is not a measured celerity, in
any table, and is undefined with the reason `beyond_sampling_limit`.

`default_rule.ALIASING_FRACTION` (0.4) flags the fits that come close to the limit; they stay
measured. The study keeps its fronts far below it: it writes the interface so that a front at the
fastest speed the theory admits moves at most a quarter of the period per frame (study/output_sampling.py,
docs/output-sampling.md); written every 4 steps, the backward supersonic fronts at nu = 0.49 sat at
0.39-0.46 of the spacing, and their tracks broke up. The case that made this rule: a run of the time-step study (nu
0.45, f 1, dt c_s = 0.0625, seed 2) whose "front" moved 1.07 spacings per frame (-125 m/s, 213 c_s).
"""

from __future__ import annotations

import math
from analysis.fronts.rules import RuleResult

#: |c| dt_out / spacing above this is beyond what the frames can resolve (the Nyquist limit).
SAMPLING_LIMIT = 0.5
#: The reason of a celerity beyond that limit.
BEYOND_SAMPLING_LIMIT = "beyond_sampling_limit"


def frame_shift_fraction(celerity: float, output_interval: float, spacing: float) -> float:
    """|c| dt_out / spacing: how far a front moves between two frames, in pulse spacings."""
    return abs(celerity) * output_interval / spacing


def within_sampling_limit(result: RuleResult, output_interval: float, spacing: float) -> RuleResult:
    """`result` itself, or, when its fit moves by more than SAMPLING_LIMIT of the spacing per frame,
    the same fit (fronts and window kept, for the diagnostics) with an undefined celerity."""
    if result.reason != "ok" or not math.isfinite(result.celerity):
        return result
    if frame_shift_fraction(result.celerity, output_interval, spacing) <= SAMPLING_LIMIT:
        return result
    return result.undefined(BEYOND_SAMPLING_LIMIT)
