"""Pulse train in the localized regime: how many major pulses, how far apart, against theory.

The paper counts *major* slip-opening pulses (lambda/H = 2, 4, 6 give 1, 2, 3): many pulses form
at localization, most of them arrest after a short life, the major ones keep going at constant
speed and open the interface. A pulse is therefore weighed by how much it opens over its whole
life, in the frame that moves with the pulses:

1. Accumulated opening A(xi) = sum over output times of u_y(xi + c_p t, t) dt_out (m s), xi the
   position in the frame moving at the measured celerity c_p (u_y periodically interpolated; values
   at or below the opening threshold count as 0). A pulse that keeps going piles up at a fixed xi;
   one that opens a little and arrests adds little.
2. The major pulses are the zones where A >= `fraction` (0.5) of its maximum (cleaned like the
   slipping set: runs narrower than 2 nodes dropped, gaps narrower than 2 nodes filled); count =
   their number, spacing = the median periodic gap between their peaks (lambda for one pulse).

Evidence (nu = 0.2, f = 1.5, H/64, lambda/H = 2, 4, 6): instantaneous rules are fragile. The peak
slip velocity and the slip rate integrated over a pulse stay within a factor 2 across the 3-8
pulses of the period while they slip, so a 0.5 cut counts nearly all of them; the number of
opening zones at least half as open as the widest, per output time, gives 2, 3, 2 at the median
and moves by one or two with the cut (0.4-0.6) and with which times are counted. A(xi) separates:
its ordered peaks are 1, 0.78 | 0.31 (lambda = 2H), 1, 0.93 | 0.34 (4H), 1, 0.84, 0.57 | 0.44
(6H), i.e. 2, 2, 3 major pulses. Limits: pulses slower or faster than c_p smear in the moving
frame (0.78 vs 0.82 m/s drift 10 m apart over the 250 s of opening); c_p must be defined.

A run that never opens has no slip-opening pulse; there the same rule runs on the slip velocity
above the slip threshold (A = slip per passage times c_p, m), and the caller says which field it
used. The previous count, the median number of fitted fronts present per output time in the
celerity window (`pulse_train`), stays as `pulse_count_all`: it counts young pulses that later
arrest. The paper's relation l = 2 H sqrt(c_p^2/c_s^2 - 1) (`analysis.theory.elastic.pulse_spacing`)
predicts max(1, round(lambda / l)) pulses in a period lambda.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analysis.fronts.edges import PeriodicGrid, slipping_mask
from analysis.fronts.tracking import EdgeTrack

#: A pulse is major when its accumulated opening reaches this fraction of the largest.
DEFAULT_MAJOR_FRACTION = 0.5


@dataclass(frozen=True)
class MajorPulses:
    """count (-, 0 when nothing exceeds the threshold) and spacing (m, nan then) of the major
    pulses; strengths: the peak of A in each major zone, relative to the largest (descending);
    next_strength: the largest relative peak of A outside the major zones (0 if none), i.e. how
    clear the cut is."""

    count: int
    spacing: float
    strengths: tuple[float, ...] = ()
    next_strength: float = math.nan


def accumulated_in_moving_frame(x: np.ndarray, t: np.ndarray, field: np.ndarray, threshold: float,
                                celerity: float) -> np.ndarray:
    """A(xi) = sum_k field(xi + c t_k, t_k) (t_k+1 - t_k) on the node grid (xi = x), values at or
    below threshold set to 0 (field unit times s).

    Parameters
    ----------
    x, t
        Node positions (m, uniform, periodic), output times (s).
    field
        Opening (m) or slip velocity (m/s), shape (n_out, n_c).
    threshold
        Values at or below it do not count.
    celerity
        Speed of the moving frame (m/s, signed).
    """
    grid = PeriodicGrid.from_nodes(x)
    t = np.asarray(t, dtype=float)
    field = np.asarray(field, dtype=float)
    weights = np.diff(t, append=t[-1] + (t[-1] - t[-2] if t.size > 1 else 1.0))
    nodes = np.arange(grid.n + 1)
    accumulated = np.zeros(grid.n)
    for tk, wk, row in zip(t, weights, field):
        row = np.where(row > threshold, row, 0.0)
        if not row.any():
            continue
        where = (np.arange(grid.n) + celerity * tk / grid.dx) % grid.n
        accumulated += wk * np.interp(where, nodes, np.append(row, row[0]))
    return accumulated


def major_pulses(x: np.ndarray, t: np.ndarray, field: np.ndarray, threshold: float,
                 celerity: float, *, fraction: float = DEFAULT_MAJOR_FRACTION) -> MajorPulses:
    """Number and spacing of the major pulses of a map (rule of the module docstring).

    Parameters
    ----------
    x, t
        Node positions (m, uniform, periodic), output times (s), >= 2.
    field
        Opening u_y (m) or slip velocity (m/s), shape (n_out, n_c).
    threshold
        Value above which a node counts (same unit as field), > 0.
    celerity
        Pulse celerity (m/s, signed, finite).
    fraction
        Major pulses reach this fraction of the largest accumulated value, in (0, 1].
    """
    if not threshold > 0:
        raise ValueError(f"threshold must be > 0 (got {threshold})")
    if not 0 < fraction <= 1:
        raise ValueError(f"fraction must be in (0, 1] (got {fraction})")
    if not math.isfinite(celerity):
        raise ValueError("celerity must be finite")
    grid = PeriodicGrid.from_nodes(x)
    accumulated = accumulated_in_moving_frame(x, t, field, threshold, celerity)
    largest = float(accumulated.max())
    if not largest > 0:
        return MajorPulses(0, math.nan)
    relative = accumulated / largest
    mask = slipping_mask(relative, fraction * (1 - 1e-12))
    if mask.all():
        return MajorPulses(1, grid.period, (1.0,), 0.0)
    if not mask.any():
        # The zones above the fraction are all narrower than a pulse (slipping_mask's minimum
        # width): spikes of the accumulated map, not pulses.
        return MajorPulses(0, math.nan)
    previous = np.roll(mask, 1)
    starts = np.flatnonzero(mask & ~previous)
    ends = np.flatnonzero(~mask & previous)
    if ends[0] < starts[0]:
        ends = np.roll(ends, -1)
    peaks, strengths = [], []
    for start, length in zip(starts, (ends - starts) % grid.n):
        zone = (start + np.arange(length)) % grid.n
        i = zone[int(np.argmax(relative[zone]))]
        peaks.append(i * grid.dx)
        strengths.append(float(relative[i]))
    # Strongest local maximum of A outside the major zones: how clear the cut is.
    maxima = (relative > np.roll(relative, 1)) & (relative >= np.roll(relative, -1)) & ~mask
    next_strength = float(relative[maxima].max()) if maxima.any() else 0.0
    ordered = np.sort(peaks)
    gaps = np.diff(np.append(ordered, ordered[0] + grid.period))
    return MajorPulses(len(peaks), float(np.median(gaps)), tuple(sorted(strengths, reverse=True)),
                       next_strength)


def pulse_train(fronts: tuple[EdgeTrack, ...] | list[EdgeTrack], period: float) -> tuple[int, float]:
    """(count, spacing in m) of all fronts moving together: the `pulse_count_all` metric.

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
