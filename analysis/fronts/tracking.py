"""Edges of the slipping set followed from frame to frame: tracks, and the front map of a run.

Edges of each kind (see `analysis.fronts.edges`) are linked from frame to frame into tracks (nearest edge
to the track's predicted position, periodic distance, positions unwrapped across x = lambda). A
track is a *slip front* when its edge moves outward from the slipping run at at least `min_speed`:
a right edge moving in +x or a left edge moving in -x (a right edge moving in -x is the healing
tail of a backward pulse, not a front).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from analysis.fronts.edges import (DEFAULT_FILL_GAP_NODES, DEFAULT_MIN_WIDTH_NODES, PeriodicGrid,
                            edge_positions, slipping_mask)

#: A track survives this many output frames without a matching edge.
DEFAULT_MAX_GAP_FRAMES = 3
#: Fewest points of a track (and of a track inside the window) used in a fit.
DEFAULT_MIN_POINTS = 5


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


class _OpenTrack:
    __slots__ = ("t", "p", "peak", "misses")

    def __init__(self, t: float, p: float, peak: float):
        self.t, self.p, self.peak, self.misses = [t], [p], [peak], 0

    def velocity(self) -> float | None:
        """Least-squares slope of the last 4 points (m/s), None below 2 points. The centred closed form of
        the fit: called for every open track at every frame, where np.polyfit's set-up costs ~50 us."""
        if len(self.t) < 2:
            return None
        tt, pp = self.t[-4:], self.p[-4:]
        t_mean, p_mean = sum(tt) / len(tt), sum(pp) / len(pp)
        spread = sum((a - t_mean) ** 2 for a in tt)
        return sum((a - t_mean) * (b - p_mean) for a, b in zip(tt, pp)) / spread


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
    # A frame where no node exceeds the threshold (the whole stick phase) has an empty slipping set and no
    # edges: answered without cleaning its mask (the same result, at a fraction of the cost).
    any_above = (v > threshold).any(axis=1)
    empty = np.empty(0)
    for row, above in zip(v, any_above):
        if not above:
            left_edges.append(empty)
            right_edges.append(empty)
            run_peaks.append(empty)
            continue
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
