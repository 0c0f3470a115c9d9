"""Slip-front celerity: the window rule and the fit (paper, section "Pulse celerity").

The slip-velocity map is thresholded (`analysis.fronts.edges`: a node slips above `threshold`, m/s;
`analysis.metrics.measure` uses 10 V0) and the edges of the slipping set are followed in time
(`analysis.fronts.tracking`). A front is *major* when it is followed for at least `major_duration`
(default 100 s) and found in at least 80 % of the frames it spans (a track that bridges every
other frame may be an alias, or noise strung together).

Window rule: a major pulse is *localized* at the first output time at which a major front is
detected, t_loc = the earliest start of a major front. The celerity window is
[t_loc, t_loc + window_length] (default 200 s, as in the paper), clipped to the data; a different
start (e.g. the first opening) can be given. The celerity is the common slope of front position
against time of the fitted fronts in the window (least squares, one intercept per front), signed:
+ = +x = the sliding direction. The *strongest* front in the window (median peak slip velocity of
the slipping run behind it) sets the direction; major fronts of that direction at least half as
strong join the fit (a train of pulses); weaker ones are secondary pulses, left out. The second,
independent estimate on the same window is `analysis.fronts.xcorr`.

Both assume that a pulse moves less than half the distance to the next pulse (lambda / 2 for one
pulse) between two output frames: |c| dt_out < spacing / 2 (dt_out = interface output interval).
At H/32 (dx = 0.78 m), lambda = 50 m and dt_out = 4 dt = 3.45 s (nu = 0.49) that holds up to
|c| = 7.2 m/s. Beyond it the direction is ambiguous (aliasing): `CelerityResult.frame_shift`
reports |c| dt_out so the caller can check.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from analysis.fronts.tracking import DEFAULT_MIN_POINTS, EdgeTrack, FrontMap

#: Slip-velocity threshold relative to the top velocity V0 (dimensionless); analysis.metrics.measure default.
DEFAULT_THRESHOLD_REL = 10.0
#: Length of the celerity window (s), as in the paper.
DEFAULT_WINDOW_LENGTH = 200.0
#: A front followed at least this long (s) belongs to a major pulse.
DEFAULT_MAJOR_DURATION = 100.0
#: Fronts weaker (median peak slip velocity of their run) than this fraction of the strongest front
#: in the window belong to secondary pulses.
DEFAULT_MIN_RELATIVE_STRENGTH = 0.5
#: A major front is found in at least this fraction of the output frames it spans.
DEFAULT_MIN_COVERAGE = 0.8


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
    restricted to the window; major = (track, direction) of every major front of the run (whole
    tracks, `major_fronts`), empty when the reason is "no_slip" or "uniform_slip".
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
    major: tuple[tuple[EdgeTrack, int], ...] = field(default=(), repr=False)

    def major_in_direction(self) -> list[EdgeTrack]:
        """The major fronts that move in the fitted direction (none when it is undefined)."""
        return [track for track, d in self.major if d == self.direction != 0]


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
        Slowest edge speed (m/s) that counts as a moving front (analysis.metrics.measure: 0.1 c_s).
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
    major = tuple(major_fronts(front_map, min_speed=min_speed, major_duration=major_duration))
    if not major:
        return CelerityResult(math.nan, "no_major_front")
    t_loc = min(track.start for track, _ in major)
    start = t_loc if window_start is None else float(window_start)
    nominal = (start, start + window_length)
    inside = [(track.within(*nominal), direction) for track, direction in major]
    inside = [(track, direction) for track, direction in inside if track.t.size >= min_points]
    if not inside:
        return CelerityResult(math.nan, "empty_window", nominal_window=nominal, t_localized=t_loc,
                              major=major)
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
        frame_shift=abs(slope) * front_map.output_interval, drift=drift, fronts=tuple(fronts),
        major=major)
