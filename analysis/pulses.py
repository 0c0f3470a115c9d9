"""Pulse train in the localized regime: how many major pulses, how far apart, against theory.

Counted on the fitted major fronts of `analysis.celerity` (one front per pulse): at each output time
of the window, the number of fronts present and the periodic gaps between them. The paper's
relation l = 2 H sqrt(c_p^2/c_s^2 - 1) (`analysis.theory.pulse_spacing`) predicts
max(1, round(lambda / l)) pulses in a period lambda.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.celerity import EdgeTrack


def pulse_train(fronts: tuple[EdgeTrack, ...] | list[EdgeTrack], period: float) -> tuple[int, float]:
    """(pulse count, pulse spacing in m) of a set of fronts moving together.

    Parameters
    ----------
    fronts
        Front tracks of one direction, restricted to the measurement window.
    period
        Period of the interface (m).

    Returns
    -------
    count
        Median over the output times of the number of fronts present (0 without fronts).
    spacing
        Median of the periodic gaps between neighbouring fronts (m); the period for one pulse;
        nan without fronts.
    """
    if not fronts:
        return 0, math.nan
    positions: dict[float, list[float]] = {}
    for track in fronts:
        for tk, p in zip(track.t, track.position):
            positions.setdefault(float(tk), []).append(float(p) % period)
    counts, gaps = [], []
    for values in positions.values():
        counts.append(len(values))
        ordered = np.sort(values)
        gaps.extend(np.diff(np.append(ordered, ordered[0] + period)))
    return int(round(float(np.median(counts)))), float(np.median(gaps))


def expected_pulse_count(period: float, spacing: float) -> int | None:
    """max(1, round(period / spacing)) for a theoretical spacing (m); None if spacing is nan."""
    if not math.isfinite(spacing) or spacing <= 0:
        return None
    return max(1, round(period / spacing))
