"""Pattern celerity from the space-time cross-correlation of the slip-velocity map.

Rows of the slip-velocity map in a time window (mean removed, normalized) are cross-correlated with
the rows m frames later (circular correlation over the period, summed over all row pairs). The peak
is located to sub-grid precision by maximizing the Fourier (trigonometric) interpolant of the
correlation. The lag doubles (m = 1, 2, 4, ...) up to half the window; at m = 1 the peak nearest to
zero shift is taken, at larger lags the peak nearest to the shift predicted by the estimate so far,
which unwraps the displacement across the period. The celerity is the least-squares slope (through
the origin) of displacement against lag time. Like the threshold fronts (`analysis.fronts.celerity`) it
assumes |c| dt_out < spacing / 2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analysis.fronts.edges import PeriodicGrid


@dataclass(frozen=True)
class XcorrResult:
    """Cross-correlation celerity (m/s, nan when undefined), the normalized correlation peak at the
    longest lag used (1 = the pattern moved rigidly), that lag (s) and the number of rows."""

    celerity: float
    peak_correlation: float = math.nan
    max_lag_time: float = math.nan
    n_rows: int = 0


def _interpolated_correlation(spectrum: np.ndarray, n: int, shift: float) -> float:
    """Trigonometric interpolant of the circular correlation irfft(spectrum, n) at a real shift."""
    k = np.arange(spectrum.size)
    weights = np.full(spectrum.size, 2.0)
    weights[0] = 1.0
    imag = spectrum.imag.copy()
    if n % 2 == 0:
        weights[-1] = 1.0
        imag[-1] = 0.0
    phase = 2.0 * np.pi * k * shift / n
    return float(np.sum(weights * (spectrum.real * np.cos(phase) - imag * np.sin(phase))) / n)


def _refine_peak(spectrum: np.ndarray, n: int, shift: int) -> tuple[float, float]:
    from scipy.optimize import minimize_scalar

    result = minimize_scalar(lambda s: -_interpolated_correlation(spectrum, n, s),
                             bounds=(shift - 1.0, shift + 1.0), method="bounded",
                             options={"xatol": 1e-7})
    return float(result.x), float(-result.fun)


def celerity_by_xcorr(x: np.ndarray, t: np.ndarray, v: np.ndarray, window: tuple[float, float], *,
                      max_lag_fraction: float = 0.5, min_peak_ratio: float = 0.5) -> XcorrResult:
    """Pattern celerity from space-time cross-correlation of the slip-velocity map.

    Parameters
    ----------
    x, t, v
        Node positions (m), output times (s), slip velocity (m/s, shape (n_out, n_c)).
    window
        (t0, t1) in s: the rows used.
    max_lag_fraction
        Longest lag as a fraction of the number of rows in the window.
    min_peak_ratio
        Correlation maxima lower than this fraction of the highest one are not candidates.

    Returns
    -------
    XcorrResult
        nan celerity when the window holds fewer than 3 rows with a non-uniform slip velocity,
        or the output times are not uniformly spaced.
    """
    grid = PeriodicGrid.from_nodes(x)
    t = np.asarray(t, dtype=float)
    keep = (t >= window[0]) & (t <= window[1])
    rows, times = np.asarray(v, dtype=float)[keep], t[keep]
    if times.size < 3:
        return XcorrResult(math.nan, n_rows=int(times.size))
    steps = np.diff(times)
    dt_out = float(np.median(steps))
    if np.max(np.abs(steps - dt_out)) > 1e-3 * dt_out:
        return XcorrResult(math.nan, n_rows=int(times.size))
    centered = rows - rows.mean(axis=1, keepdims=True)
    norms = np.linalg.norm(centered, axis=1)
    valid = norms > 1e-12 * max(float(norms.max()), 1e-300)
    centered[valid] /= norms[valid, None]
    centered[~valid] = 0.0
    if np.count_nonzero(valid) < 3:
        return XcorrResult(math.nan, n_rows=int(times.size))
    spectra = np.fft.rfft(centered, axis=1)
    n = grid.n
    lags_time, shifts = [], []
    estimate, peak = None, math.nan
    lag = 1
    max_lag = max(1, int(max_lag_fraction * (times.size - 1)))
    while lag <= max_lag:
        pairs = valid[:-lag] & valid[lag:]
        if not pairs.any():
            break
        cross = np.sum(np.conj(spectra[:-lag][pairs]) * spectra[lag:][pairs], axis=0)
        corr = np.fft.irfft(cross, n)
        maxima = np.flatnonzero((corr > np.roll(corr, 1)) & (corr >= np.roll(corr, -1)))
        maxima = maxima[corr[maxima] >= min_peak_ratio * corr.max()]
        if maxima.size == 0:
            break
        predicted = 0.0 if estimate is None else estimate * lag * dt_out / grid.dx
        offsets = grid.wrap_difference((maxima - predicted) * grid.dx) / grid.dx
        best = int(np.argmin(np.abs(offsets)))
        fine, value = _refine_peak(cross, n, int(maxima[best]))
        shift = predicted + float(grid.wrap_difference((fine - predicted) * grid.dx)) / grid.dx
        lags_time.append(lag * dt_out)
        shifts.append(shift * grid.dx)
        tau, disp = np.array(lags_time), np.array(shifts)
        estimate = float(tau @ disp / (tau @ tau))
        peak = value / np.count_nonzero(pairs)
        lag *= 2
    if estimate is None:
        return XcorrResult(math.nan, n_rows=int(times.size))
    return XcorrResult(estimate, peak_correlation=peak, max_lag_time=lags_time[-1],
                       n_rows=int(times.size))
