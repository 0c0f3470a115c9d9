"""The frictional force ratio T/N: its minimum, inversion, and frictional drops.

Inversion: min T/N < 0 (the frictional force points the other way: the interface has moved ahead
of the top), on the raw series. Frictional drops are found on the series smoothed by a centred
moving average over `smooth_time` (the solver's T/N chatters from step to step by up to ~0.1; a
drop lasts several shear transits H/c_s): a *drop* starts at a peak after which T/N falls by at
least `min_drop`, and bottoms out at the lowest value before T/N recovers by `min_drop` above it.
Times and values are those of the smoothed series. `analysis.metrics.measure` uses min_drop = 0.1 f and
smooth_time = 2 H / c_s (the shear round trip, at which the layer rings between drops).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FrictionalDrop:
    """t_start (s) and T_over_N_start: the peak the drop falls from (its last time, on a plateau);
    t_bottom (s) and T_over_N_bottom: its lowest point; complete: whether T/N recovered after it
    (else the series ended during the drop)."""

    t_start: float
    T_over_N_start: float
    t_bottom: float
    T_over_N_bottom: float
    complete: bool


def bridge_undefined(t: np.ndarray, ratio: np.ndarray) -> np.ndarray:
    """T/N with its undefined samples (NaN: the whole interface open, N = 0) bridged linearly in time
    from the defined neighbours, so that minima and drops are measured on the defined values only.

    Returns the input unchanged when every sample is defined, all-NaN when none is.
    """
    defined = np.isfinite(ratio)
    if defined.all() or not defined.any():
        return ratio
    return np.interp(t, t[defined], ratio[defined])


def minimum_ratio(t: np.ndarray, ratio: np.ndarray) -> tuple[float, float]:
    """(min T/N, time of the minimum in s); (nan, nan) for an empty series."""
    ratio = np.asarray(ratio, dtype=float)
    if ratio.size == 0:
        return math.nan, math.nan
    k = int(np.argmin(ratio))
    return float(ratio[k]), float(np.asarray(t)[k])


def smooth(t: np.ndarray, values: np.ndarray, smooth_time: float) -> np.ndarray:
    """Centred moving average over about smooth_time (s) of a uniformly sampled series (the ends
    repeat the first and last values); unchanged when smooth_time covers less than 2 samples."""
    values = np.asarray(values, dtype=float)
    if values.size < 2:
        return values
    width = int(round(smooth_time / float(np.median(np.diff(t)))))
    if width < 2:
        return values
    from scipy.ndimage import uniform_filter1d

    return uniform_filter1d(values, size=width, mode="nearest")


def frictional_drops(t: np.ndarray, ratio: np.ndarray, min_drop: float,
                     smooth_time: float = 0.0) -> list[FrictionalDrop]:
    """Frictional drops of a T/N series.

    Parameters
    ----------
    t
        Times (s), increasing, uniformly spaced.
    ratio
        T/N (-).
    min_drop
        Smallest fall from a peak that counts as a drop, also the rise that ends it (-), > 0.
    smooth_time
        Width of the moving average applied first (s); 0 = none.
    """
    if not min_drop > 0:
        raise ValueError(f"min_drop must be > 0 (got {min_drop})")
    t = np.asarray(t, dtype=float)
    ratio = smooth(t, ratio, smooth_time)
    drops: list[FrictionalDrop] = []
    level = 1e-6 * min_drop  # values this close are equal (a plateau, rounding of the average)
    peak_k, bottom_k, falling = 0, 0, False
    for k in range(ratio.size):
        r = ratio[k]
        if not falling:
            if r >= ratio[peak_k] - level:
                peak_k = k
            elif r < ratio[peak_k] - min_drop:
                falling, bottom_k = True, k
        else:
            if r < ratio[bottom_k]:
                bottom_k = k
            elif r > ratio[bottom_k] + min_drop:
                drops.append(FrictionalDrop(t[peak_k], ratio[peak_k], t[bottom_k], ratio[bottom_k], True))
                falling, peak_k = False, k
    if falling:
        drops.append(FrictionalDrop(t[peak_k], ratio[peak_k], t[bottom_k], ratio[bottom_k], False))
    return drops
