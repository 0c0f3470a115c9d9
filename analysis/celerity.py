"""Slip-front celerity from the interface slip-velocity map (paper, section "Pulse celerity").

Two independent estimates on the same time window:

1. **Threshold fronts** (the paper's method). A node slips when its slip velocity exceeds a threshold
   (`threshold`, m/s; `analysis.measure` uses 10 V0). In every output frame the slipping set is
   cleaned (slipping runs narrower than `min_width_nodes` nodes are dropped, stick gaps narrower than
   `fill_gap_nodes` are filled) and its edges are located to sub-grid precision by linear
   interpolation of the slip velocity between the two nodes that straddle the threshold. A *right*
   edge ends a slipping run towards +x, a *left* edge towards -x. Edges of each kind are linked from
   frame to frame into tracks (nearest edge to the track's predicted position, periodic distance,
   positions unwrapped across x = lambda). A track is a *slip front* when its edge moves outward
   from the slipping run at at least `min_speed`: a right edge moving in +x or a left edge moving in
   -x (a right edge moving in -x is the healing tail of a backward pulse, not a front).
   A front is *major* when it is followed for at least `major_duration` (default 100 s) and found
   in at least 80 % of the frames it spans (a track that bridges every other frame may be an
   alias, or noise strung together).

   Window rule: a major pulse is *localized* at the first output time at which a major front is
   detected, t_loc = the earliest start of a major front. The celerity window is
   [t_loc, t_loc + window_length] (default 200 s, as in the paper), clipped to the data; a different
   start (e.g. the first opening) can be given. The celerity is the common slope of front position
   against time of the fitted fronts in the window (least squares, one intercept per front),
   signed: + = +x = the sliding direction. The *strongest* front in the
   window (median peak slip velocity of the slipping run behind it) sets the direction; major fronts
   of that direction at least half as strong join the fit (a train of pulses); weaker ones are
   secondary pulses, left out.

2. **Space-time cross-correlation.** Rows of the slip-velocity map in the same window (mean
   removed, normalized) are cross-correlated with the rows m frames later (circular correlation
   over the period, summed over all row pairs). The peak is located to sub-grid precision by
   maximizing the Fourier (trigonometric) interpolant of the correlation. The lag doubles
   (m = 1, 2, 4, ...) up to half the window; at m = 1 the peak nearest to zero shift is taken, at
   larger lags the peak nearest to the shift predicted by the estimate so far, which unwraps the
   displacement across the period. The celerity is the least-squares slope (through the origin) of
   displacement against lag time.

Both assume that a pulse moves less than half the distance to the next pulse (lambda / 2 for one
pulse) between two output frames: |c| dt_out < spacing / 2 (dt_out = interface output interval).
At H/32 (dx = 0.78 m), lambda = 50 m and dt_out = 4 dt = 3.45 s (nu = 0.49) that holds up to
|c| = 7.2 m/s. Beyond it the direction is ambiguous (aliasing): `CelerityResult.frame_shift`
reports |c| dt_out so the caller can check.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

#: Slip-velocity threshold relative to the top velocity V0 (dimensionless); analysis.measure default.
DEFAULT_THRESHOLD_REL = 10.0
#: Length of the celerity window (s), as in the paper.
DEFAULT_WINDOW_LENGTH = 200.0
#: A front followed at least this long (s) belongs to a major pulse.
DEFAULT_MAJOR_DURATION = 100.0
#: Slipping runs narrower than this many nodes are noise, not pulses.
DEFAULT_MIN_WIDTH_NODES = 2
#: Stick gaps narrower than this many nodes inside a slipping run are filled.
DEFAULT_FILL_GAP_NODES = 2
#: A track survives this many output frames without a matching edge.
DEFAULT_MAX_GAP_FRAMES = 3
#: Fronts weaker (median peak slip velocity of their run) than this fraction of the strongest front
#: in the window belong to secondary pulses.
DEFAULT_MIN_RELATIVE_STRENGTH = 0.5
#: A major front is found in at least this fraction of the output frames it spans.
DEFAULT_MIN_COVERAGE = 0.8
#: Fewest points of a track (and of a track inside the window) used in a fit.
DEFAULT_MIN_POINTS = 5


@dataclass(frozen=True)
class PeriodicGrid:
    """Uniform periodic grid of the interface nodes: first node x0 (m), spacing dx (m), n nodes,
    period = n dx (m)."""

    x0: float
    dx: float
    n: int

    @property
    def period(self) -> float:
        return self.n * self.dx

    @classmethod
    def from_nodes(cls, x: np.ndarray) -> "PeriodicGrid":
        """Grid of node positions x (m) that are uniformly spaced (node x0 + n dx is node x0)."""
        x = np.asarray(x, dtype=float)
        if x.ndim != 1 or x.size < 3:
            raise ValueError("x must be 1-D with at least 3 nodes")
        steps = np.diff(x)
        dx = float(np.mean(steps))
        if dx <= 0 or np.max(np.abs(steps - dx)) > 1e-6 * dx:
            raise ValueError("interface nodes are not uniformly spaced")
        return cls(x0=float(x[0]), dx=dx, n=int(x.size))

    def wrap_difference(self, d: np.ndarray | float) -> np.ndarray | float:
        """Periodic difference mapped to [-period/2, period/2) (m)."""
        p = self.period
        return (np.asarray(d) + 0.5 * p) % p - 0.5 * p


@dataclass(frozen=True)
class EdgeTrack:
    """One edge of the slipping set followed in time.

    kind is "right" (the slipping run ends towards +x) or "left"; t (s); position (m, unwrapped
    across the period, so that it grows without bound for a pulse that keeps going); intensity
    (m/s): the peak slip velocity of the slipping run the edge bounds, at each point.
    """

    kind: str
    t: np.ndarray
    position: np.ndarray
    intensity: np.ndarray

    @property
    def start(self) -> float:
        return float(self.t[0])

    @property
    def end(self) -> float:
        return float(self.t[-1])

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0])

    @property
    def speed(self) -> float:
        """Least-squares slope of position against time (m/s); nan for fewer than 2 points."""
        if self.t.size < 2:
            return math.nan
        return float(np.polyfit(self.t, self.position, 1)[0])

    def coverage(self, output_interval: float) -> float:
        """Fraction of the output frames between the track's ends in which its edge was found (-).

        A track that bridges every other frame may be an alias (a fast front seen every 2 dt_out
        can appear to move the other way), so major fronts need a high coverage.
        """
        n_frames = round(self.duration / output_interval) + 1
        return self.t.size / n_frames

    def front_direction(self, min_speed: float) -> int:
        """+1 (front moving in +x), -1 (in -x) or 0 (not a front: too slow, or a healing edge)."""
        speed = self.speed
        if not math.isfinite(speed) or abs(speed) < min_speed:
            return 0
        if self.kind == "right" and speed > 0:
            return 1
        if self.kind == "left" and speed < 0:
            return -1
        return 0

    @property
    def strength(self) -> float:
        """Median intensity (m/s): how strong the pulse behind this edge is."""
        return float(np.median(self.intensity)) if self.intensity.size else math.nan

    def within(self, t0: float, t1: float) -> "EdgeTrack":
        keep = (self.t >= t0) & (self.t <= t1)
        return EdgeTrack(self.kind, self.t[keep], self.position[keep], self.intensity[keep])


@dataclass(frozen=True)
class CelerityResult:
    """Threshold-front celerity and how it was obtained.

    celerity (m/s, signed, nan when undefined) with `reason` = "ok" or why it is undefined:
    "no_slip" (the threshold is never exceeded), "uniform_slip" (slipping set never has an edge),
    "no_major_front" (edges, but no front followed for major_duration), "empty_window" (no major
    front in the requested window). window = (first, last) time of the fitted points (s);
    nominal_window = the rule's [start, start + window_length] (s); t_localized (s); direction
    (+1/-1/0); stderr (m/s) and r2 of the pooled fit; rms residual (m); n_fronts, n_points used;
    n_counter_fronts = strong major fronts in the window moving the other way; n_secondary_fronts
    = major fronts in the window left out as weaker than min_relative_strength of the strongest
    (either way); frame_shift = |c| dt_out (m); drift = (c over the second half of the window -
    c over the first half) / |c| (a steady pulse has |drift| << 1); fronts = the fitted tracks
    restricted to the window.
    """

    celerity: float
    reason: str
    window: tuple[float, float] | None = None
    nominal_window: tuple[float, float] | None = None
    t_localized: float = math.nan
    direction: int = 0
    stderr: float = math.nan
    r2: float = math.nan
    rms: float = math.nan
    n_fronts: int = 0
    n_points: int = 0
    n_counter_fronts: int = 0
    n_secondary_fronts: int = 0
    frame_shift: float = math.nan
    drift: float = math.nan
    fronts: tuple[EdgeTrack, ...] = field(default=(), repr=False)


@dataclass(frozen=True)
class XcorrResult:
    """Cross-correlation celerity (m/s, nan when undefined), the normalized correlation peak at the
    longest lag used (1 = the pattern moved rigidly), that lag (s) and the number of rows."""

    celerity: float
    peak_correlation: float = math.nan
    max_lag_time: float = math.nan
    n_rows: int = 0


# --------------------------------------------------------------------------------------------------
# Slipping set and its edges in one frame


def _runs(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Periodic runs of True: (start indices, lengths). Empty when mask is all False or all True."""
    previous = np.roll(mask, 1)
    starts = np.flatnonzero(mask & ~previous)
    ends = np.flatnonzero(~mask & previous)
    if starts.size == 0:
        return starts, starts
    if ends[0] < starts[0]:
        ends = np.roll(ends, -1)
    return starts, (ends - starts) % mask.size


def _clear_short_runs(mask: np.ndarray, value: bool, min_length: int) -> np.ndarray:
    """Sets runs of `value` shorter than min_length to `not value` (periodically)."""
    target = mask if value else ~mask
    starts, lengths = _runs(target)
    out = mask.copy()
    n = mask.size
    for start, length in zip(starts, lengths):
        if length < min_length:
            out[(start + np.arange(length)) % n] = not value
    return out


def slipping_mask(v: np.ndarray, threshold: float, min_width_nodes: int = DEFAULT_MIN_WIDTH_NODES,
                  fill_gap_nodes: int = DEFAULT_FILL_GAP_NODES) -> np.ndarray:
    """Nodes of one frame that belong to a slip pulse.

    Parameters
    ----------
    v
        Slip velocity of the nodes (m/s), + = +x.
    threshold
        Slip velocity above which a node slips (m/s).
    min_width_nodes, fill_gap_nodes
        Slipping runs with fewer nodes are dropped first; then stick gaps with fewer nodes are
        filled.

    Returns
    -------
    Boolean mask, True where slipping.
    """
    mask = np.asarray(v) > threshold
    if min_width_nodes > 1:
        mask = _clear_short_runs(mask, True, min_width_nodes)
    if fill_gap_nodes > 1:
        mask = _clear_short_runs(mask, False, fill_gap_nodes)
    return mask


def edge_positions(v: np.ndarray, mask: np.ndarray, threshold: float,
                   grid: PeriodicGrid) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Edges of the slipping runs of a mask: (left positions, right positions, run peaks).

    Positions in m, in [x0, x0 + period); each edge lies between the last stick node and the first
    slipping node, where the linear interpolant of v crosses the threshold (clipped to that
    element). Run k has left edge left[k], right edge right[k] and peak slip velocity peaks[k] (m/s).
    """
    n = grid.n
    starts, lengths = _runs(mask)
    if starts.size == 0:
        empty = np.empty(0)
        return empty, empty, empty
    peaks = np.array([v[(start + np.arange(length)) % n].max() for start, length in zip(starts, lengths)])
    inside_left = starts                      # first slipping node
    outside_left = (starts - 1) % n           # stick node before it
    inside_right = (starts + lengths - 1) % n  # last slipping node
    outside_right = (starts + lengths) % n    # stick node after it

    def crossing(inside: np.ndarray, outside: np.ndarray) -> np.ndarray:
        v_in, v_out = v[inside], v[outside]
        span = v_in - v_out
        with np.errstate(divide="ignore", invalid="ignore"):
            frac = np.where(span > 0, (v_in - threshold) / span, 0.5)
        return np.clip(frac, 0.0, 1.0)

    # Left edge: from the stick node (index i-1) towards the slipping node i.
    left = outside_left + 1.0 - crossing(inside_left, outside_left)
    # Right edge: from the slipping node towards the stick node after it.
    right = inside_right + crossing(inside_right, outside_right)
    return grid.x0 + (left % n) * grid.dx, grid.x0 + (right % n) * grid.dx, peaks


# --------------------------------------------------------------------------------------------------
# Tracks


class _OpenTrack:
    __slots__ = ("t", "p", "peak", "misses")

    def __init__(self, t: float, p: float, peak: float):
        self.t, self.p, self.peak, self.misses = [t], [p], [peak], 0

    def velocity(self) -> float | None:
        if len(self.t) < 2:
            return None
        tt, pp = np.array(self.t[-4:]), np.array(self.p[-4:])
        return float(np.polyfit(tt, pp, 1)[0])


def track_edges(t: np.ndarray, edges: list[np.ndarray], peaks: list[np.ndarray], kind: str,
                grid: PeriodicGrid,
                max_gap_frames: int = DEFAULT_MAX_GAP_FRAMES,
                min_points: int = DEFAULT_MIN_POINTS) -> list[EdgeTrack]:
    """Link the edges of one kind from frame to frame into tracks.

    A track with a velocity (two points or more) predicts its position at the next frame and takes
    the nearest edge within max(4 dx, a quarter of its predicted step); a new track takes the nearest edge
    within half a period. Established tracks choose first, nearest first. A track ends after
    max_gap_frames frames without an edge. Positions are unwrapped across the period.

    Parameters
    ----------
    t
        Output times (s), increasing.
    edges
        Per frame, the wrapped positions (m) of the edges of this kind.
    peaks
        Per frame, the peak slip velocity (m/s) of the run each edge bounds.
    kind
        "left" or "right", stored in the tracks.
    grid
        The interface grid.
    max_gap_frames, min_points
        Gap tolerance; tracks with fewer points are dropped.
    """
    open_tracks: list[_OpenTrack] = []
    closed: list[_OpenTrack] = []
    half = 0.5 * grid.period
    tol_min = 4.0 * grid.dx
    for tk, positions, intensity in zip(t, edges, peaks):
        candidates = []
        for i, track in enumerate(open_tracks):
            velocity = track.velocity()
            elapsed = tk - track.t[-1]
            if velocity is None:
                predicted, tolerance, priority = track.p[-1], half, 1
            else:
                predicted = track.p[-1] + velocity * elapsed
                tolerance, priority = max(tol_min, 0.25 * abs(velocity) * elapsed), 0
            if positions.size:
                d = grid.wrap_difference(positions - predicted)
                for j in np.flatnonzero(np.abs(d) <= tolerance):
                    candidates.append((priority, abs(float(d[j])), i, int(j), predicted + float(d[j])))
        candidates.sort()
        track_used, edge_used = set(), set()
        for _, _, i, j, unwrapped in candidates:
            if i in track_used or j in edge_used:
                continue
            track_used.add(i)
            edge_used.add(j)
            open_tracks[i].t.append(float(tk))
            open_tracks[i].p.append(unwrapped)
            open_tracks[i].peak.append(float(intensity[j]))
            open_tracks[i].misses = 0
        still_open = []
        for i, track in enumerate(open_tracks):
            if i not in track_used:
                track.misses += 1
            (closed if track.misses > max_gap_frames else still_open).append(track)
        open_tracks = still_open
        for j in range(positions.size):
            if j not in edge_used:
                open_tracks.append(_OpenTrack(float(tk), float(positions[j]), float(intensity[j])))
    closed.extend(open_tracks)
    return [EdgeTrack(kind, np.array(tr.t), np.array(tr.p), np.array(tr.peak)) for tr in closed
            if len(tr.t) >= min_points]


@dataclass(frozen=True)
class FrontMap:
    """Edges of the slipping set over a whole run: `tracks` (all tracks of at least min_points),
    `n_slipping_frames` (frames with a non-empty slipping set), `n_edge_frames` (frames whose
    slipping set has edges, i.e. is neither empty nor the whole interface), `output_interval`
    (median spacing of the output times, s) and the grid."""

    tracks: tuple[EdgeTrack, ...]
    n_slipping_frames: int
    n_edge_frames: int
    output_interval: float
    grid: PeriodicGrid


def find_edges(x: np.ndarray, t: np.ndarray, v: np.ndarray, threshold: float, *,
               min_width_nodes: int = DEFAULT_MIN_WIDTH_NODES,
               fill_gap_nodes: int = DEFAULT_FILL_GAP_NODES,
               max_gap_frames: int = DEFAULT_MAX_GAP_FRAMES,
               min_points: int = DEFAULT_MIN_POINTS) -> FrontMap:
    """Threshold the slip-velocity map and follow the edges of the slipping set.

    Parameters
    ----------
    x
        Node positions (m), uniform, periodic (n_c).
    t
        Output times (s), increasing (n_out).
    v
        Slip velocity (m/s), shape (n_out, n_c), + = +x.
    threshold
        Slip velocity above which a node slips (m/s), > 0.
    min_width_nodes, fill_gap_nodes, max_gap_frames, min_points
        See `slipping_mask` and `track_edges`.
    """
    if not threshold > 0:
        raise ValueError(f"threshold must be > 0 (got {threshold})")
    grid = PeriodicGrid.from_nodes(x)
    t = np.asarray(t, dtype=float)
    v = np.asarray(v, dtype=float)
    left_edges, right_edges, run_peaks = [], [], []
    n_slipping = n_edges = 0
    for row in v:
        mask = slipping_mask(row, threshold, min_width_nodes, fill_gap_nodes)
        n_slipping += bool(mask.any())
        left, right, peaks = edge_positions(row, mask, threshold, grid)
        n_edges += bool(left.size)
        left_edges.append(left)
        right_edges.append(right)
        run_peaks.append(peaks)
    tracks = (track_edges(t, left_edges, run_peaks, "left", grid, max_gap_frames, min_points)
              + track_edges(t, right_edges, run_peaks, "right", grid, max_gap_frames, min_points))
    interval = float(np.median(np.diff(t))) if t.size > 1 else math.nan
    return FrontMap(tuple(tracks), n_slipping, n_edges, interval, grid)


# --------------------------------------------------------------------------------------------------
# Celerity from the fronts


def pooled_slope(tracks: list[EdgeTrack]) -> tuple[float, float, float, float, int]:
    """Common slope of several position-time tracks, one intercept each (least squares).

    Returns (slope m/s, standard error m/s, r2, rms residual m, n points).
    """
    sxx = sxy = syy = 0.0
    n_points = 0
    for track in tracks:
        tc = track.t - track.t.mean()
        pc = track.position - track.position.mean()
        sxx += float(tc @ tc)
        sxy += float(tc @ pc)
        syy += float(pc @ pc)
        n_points += track.t.size
    if sxx <= 0:
        return math.nan, math.nan, math.nan, math.nan, n_points
    slope = sxy / sxx
    ss_res = max(syy - slope * sxy, 0.0)
    dof = n_points - len(tracks) - 1
    stderr = math.sqrt(ss_res / dof / sxx) if dof > 0 else math.nan
    r2 = 1.0 - ss_res / syy if syy > 0 else math.nan
    return slope, stderr, r2, math.sqrt(ss_res / n_points), n_points


def major_fronts(front_map: FrontMap, *, min_speed: float,
                 major_duration: float = DEFAULT_MAJOR_DURATION,
                 min_coverage: float = DEFAULT_MIN_COVERAGE) -> list[tuple[EdgeTrack, int]]:
    """(track, direction) of the fronts of major pulses: fronts (EdgeTrack.front_direction != 0)
    followed at least major_duration (s) with a coverage of at least min_coverage."""
    out = []
    for track in front_map.tracks:
        if track.duration < major_duration:
            continue
        if track.coverage(front_map.output_interval) < min_coverage:
            continue
        direction = track.front_direction(min_speed)
        if direction:
            out.append((track, direction))
    return out


def celerity_from_fronts(front_map: FrontMap, *, min_speed: float,
                         window_length: float = DEFAULT_WINDOW_LENGTH,
                         window_start: float | None = None,
                         major_duration: float = DEFAULT_MAJOR_DURATION,
                         min_relative_strength: float = DEFAULT_MIN_RELATIVE_STRENGTH,
                         min_points: int = DEFAULT_MIN_POINTS) -> CelerityResult:
    """Celerity of the major slip fronts over the window rule of the module docstring.

    Parameters
    ----------
    front_map
        From `find_edges`.
    min_speed
        Slowest edge speed (m/s) that counts as a moving front (analysis.measure: 0.1 c_s).
    window_length
        Window length (s).
    window_start
        Start of the window (s); None = the localization time t_loc.
    major_duration
        A front followed at least this long (s) is major.
    min_relative_strength
        Fronts weaker than this fraction of the strongest one in the window are secondary pulses
        and stay out of the fit.
    min_points
        Fewest points of a front inside the window for it to enter the fit.
    """
    if front_map.n_slipping_frames == 0:
        return CelerityResult(math.nan, "no_slip")
    if front_map.n_edge_frames == 0:
        return CelerityResult(math.nan, "uniform_slip")
    major = major_fronts(front_map, min_speed=min_speed, major_duration=major_duration)
    if not major:
        return CelerityResult(math.nan, "no_major_front")
    t_loc = min(track.start for track, _ in major)
    start = t_loc if window_start is None else float(window_start)
    nominal = (start, start + window_length)
    inside = [(track.within(*nominal), direction) for track, direction in major]
    inside = [(track, direction) for track, direction in inside if track.t.size >= min_points]
    if not inside:
        return CelerityResult(math.nan, "empty_window", nominal_window=nominal, t_localized=t_loc)
    # The strongest front in the window sets the direction; fronts of comparable strength going
    # the same way join the fit (a train of pulses), weaker ones are secondary pulses.
    strongest = max(track.strength for track, _ in inside)
    direction = max(inside, key=lambda item: item[0].strength)[1]
    strong = [(track, d) for track, d in inside if track.strength >= min_relative_strength * strongest]
    fronts = [track for track, d in strong if d == direction]
    slope, stderr, r2, rms, n_points = pooled_slope(fronts)
    t0 = min(track.start for track in fronts)
    t1 = max(track.end for track in fronts)
    middle = 0.5 * (t0 + t1)
    halves = [[part for part in (track.within(a, b) for track in fronts) if part.t.size >= 3]
              for a, b in ((t0, middle), (middle, t1))]
    first, second = (pooled_slope(half)[0] if half else math.nan for half in halves)
    drift = (second - first) / abs(slope) if slope else math.nan
    return CelerityResult(
        celerity=slope, reason="ok", window=(t0, t1), nominal_window=nominal, t_localized=t_loc,
        direction=direction, stderr=stderr, r2=r2, rms=rms, n_fronts=len(fronts),
        n_points=n_points, n_counter_fronts=len(strong) - len(fronts),
        n_secondary_fronts=len(inside) - len(strong),
        frame_shift=abs(slope) * front_map.output_interval, drift=drift, fronts=tuple(fronts))


# --------------------------------------------------------------------------------------------------
# Cross-correlation estimate


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
