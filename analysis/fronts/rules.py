"""The celerity measurement rules of docs/measurement-rule.md, measured side by side.

Each rule picks a window and the fronts to fit; the fit is the pooled slope of `analysis.fronts.celerity`
(one intercept per front). Times are in the run's own unit (the caller scales the paper's 200 s
and 100 s, `analysis.metrics.measure.time_unit_ratio`).

- `localization`: the first rule of the analysis (`celerity` until analysis version 4),
  `celerity_from_fronts` unchanged.
- `opening_pulse`: the major front whose pulse opens. A major front's pulse *opens* when, in one
  of the output frames in which the front is tracked (its whole life, from its localization = its
  start), a node of the slipping run bounded by that front has u_y above the run's opening
  threshold. The life is not cut at `window_length`: the paper's pulses open "after a certain
  propagation distance", and at H/32 they open 100-330 s after their localization (nu = 0.2,
  f = 1.5: 102 s; nu = 0, f = 1.5: 328 s; nu = 0.45, f = 1: 249 s). Of the major fronts whose
  pulse opens, the strongest (`EdgeTrack.strength`, median peak slip velocity over its life) is
  the major pulse (ties: the one that opens first). Not the first to open: at nu = 0, f = 1.1
  (H/32) a precursor front near c_l bounds a slipping run that reaches back over the growing
  pulse, so its run opens first (1465 s), though its strength is a fifth of that of the pulse
  that localizes behind it at 1578 s. Window: `window_length` from that front's start; fitted:
  that front plus the major fronts of its direction at least `min_relative_strength` as strong as
  it in the window (a train of pulses).
- `opening_pulse_from_opening`: the same front and fit, the window starting at the first frame in
  which its pulse opens.
- `opening_front`: front tracking (`analysis.fronts.tracking`) on the opening map, u_y above the opening
  threshold, `window_length` from the run's first opening; fitted as `localization` fits the slip
  fronts. The "geometric" check of the paper.
- `first_100s`: the strongest major slip front (median peak slip velocity over its first
  `first_window_length`) alone, over its first `first_window_length` (100 s).
- `late`: the `localization` fit on the `window_length` ending at the last interface output.

Each rule gives a celerity (m/s, signed, nan when undefined), the window (first, last time of the
fitted points, s), a reason ("ok" or why undefined) and the deceleration over its window:
(slope over the second half - slope over the first half) / slope over the whole window, which is
negative when the front slows down (|c| falls), whatever its direction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from analysis.fronts import celerity as cel
from analysis.fronts.edges import PeriodicGrid, slipping_mask
from analysis.fronts.tracking import DEFAULT_MIN_POINTS, EdgeTrack, FrontMap, find_edges

#: The rules, in the order of docs/measurement-rule.md.
RULES = ("localization", "opening_pulse", "opening_pulse_from_opening", "opening_front",
         "first_100s", "late")
#: The rule whose celerity is `celerity`, for every run (docs/measurement-rule.md decides).
DEFAULT_RULE = "opening_pulse"
#: The default's window sensitivity: the same pulse measured from its opening (S3 of the argument).
WINDOW_SENSITIVITY_RULE = "opening_pulse_from_opening"
#: Window of `first_100s` (s, paper's unit).
DEFAULT_FIRST_WINDOW_LENGTH = 100.0


@dataclass(frozen=True)
class RuleResult:
    """celerity (m/s, nan when undefined); reason ("ok" or why undefined); window = (first, last)
    time of the fitted points (s); deceleration (-, see the module docstring); fronts fitted;
    n_counter_fronts = major fronts in the window moving the other way, at least as strong as
    those that join the fit; n_secondary_fronts = major fronts in the window left out as weaker."""

    celerity: float
    reason: str
    window: tuple[float, float] | None = None
    deceleration: float = math.nan
    fronts: tuple[EdgeTrack, ...] = field(default=(), repr=False)
    n_counter_fronts: int = 0
    n_secondary_fronts: int = 0

    def undefined(self, reason: str) -> "RuleResult":
        """The same fit (fronts and window kept, for the diagnostics) with an undefined celerity and `reason`."""
        return replace(self, celerity=math.nan, reason=reason, deceleration=math.nan)


def deceleration(fronts: list[EdgeTrack] | tuple[EdgeTrack, ...], slope: float) -> float:
    """(pooled slope over the second half - over the first half) / slope (-); the halves split
    the span of the fitted points; nan when a half has no front of 3 points or more."""
    if not fronts or not math.isfinite(slope) or slope == 0:
        return math.nan
    t0 = min(track.start for track in fronts)
    t1 = max(track.end for track in fronts)
    middle = 0.5 * (t0 + t1)
    slopes = []
    for a, b in ((t0, middle), (middle, t1)):
        half = [part for part in (track.within(a, b) for track in fronts) if part.t.size >= 3]
        if not half:
            return math.nan
        slopes.append(cel.pooled_slope(half)[0])
    return (slopes[1] - slopes[0]) / slope


def _fit(fronts: list[EdgeTrack], n_counter_fronts: int = 0, n_secondary_fronts: int = 0) -> RuleResult:
    slope = cel.pooled_slope(fronts)[0]
    window = (min(track.start for track in fronts), max(track.end for track in fronts))
    return RuleResult(slope, "ok", window, deceleration(fronts, slope), tuple(fronts),
                      n_counter_fronts, n_secondary_fronts)


def from_celerity_result(result: cel.CelerityResult) -> RuleResult:
    """A `celerity_from_fronts` result as a rule result (same celerity and window)."""
    if result.reason != "ok":
        return RuleResult(math.nan, result.reason)
    return RuleResult(result.celerity, "ok", result.window,
                      deceleration(result.fronts, result.celerity), result.fronts,
                      result.n_counter_fronts, result.n_secondary_fronts)


def anchored_fit(anchor: EdgeTrack, direction: int, major: tuple[tuple[EdgeTrack, int], ...],
                 start: float, length: float,
                 min_relative_strength: float = cel.DEFAULT_MIN_RELATIVE_STRENGTH,
                 min_points: int = DEFAULT_MIN_POINTS) -> RuleResult:
    """Fit of `anchor` over [start, start + length] together with the major fronts of its
    direction at least min_relative_strength as strong as it there (a train of pulses)."""
    first = anchor.within(start, start + length)
    if first.t.size < min_points:
        return RuleResult(math.nan, "empty_window")
    fronts, counter, secondary = [first], 0, 0
    for track, d in major:
        if track is anchor:
            continue
        part = track.within(start, start + length)
        if part.t.size < min_points:
            continue
        if part.strength < min_relative_strength * first.strength:
            secondary += 1
        elif d == direction:
            fronts.append(part)
        else:
            counter += 1
    return _fit(fronts, counter, secondary)


def _run_nodes(mask: np.ndarray, grid: PeriodicGrid, kind: str, position: float) -> np.ndarray:
    """Node indices of the slipping run of `mask` bounded by the edge of `kind` at `position` (m,
    any periodic image); empty when no slipping node is next to it."""
    n = grid.n
    s = ((position - grid.x0) % grid.period) / grid.dx
    # The edge lies between the last stick node and the first slipping node (analysis.fronts.edges).
    guesses = (math.floor(s), math.ceil(s)) if kind == "right" else (math.ceil(s), math.floor(s))
    inside = next((i % n for i in guesses if mask[i % n]), None)
    if inside is None:
        return np.empty(0, dtype=int)
    if mask.all():
        return np.arange(n)
    lo, hi = inside, inside
    while mask[(lo - 1) % n]:
        lo -= 1
    while mask[(hi + 1) % n]:
        hi += 1
    return np.arange(lo, hi + 1) % n


def pulse_opening_time(track: EdgeTrack, t: np.ndarray, v: np.ndarray, u_y: np.ndarray,
                       slip_threshold: float, opening_threshold: float, grid: PeriodicGrid,
                       lifetime: float = math.inf) -> float:
    """First time (s) at which the slipping run bounded by `track` holds a node with u_y above
    opening_threshold, among the track's points at most `lifetime` (s) after its start (default:
    all of them); nan if never.

    t, v, u_y: output times (s), slip velocity (m/s) and opening (m) maps, shape (n_out, n_c).
    """
    for time, position in zip(track.t, track.position):
        if time > track.start + lifetime:
            break
        k = int(np.searchsorted(t, time))
        if k >= t.size or not math.isclose(t[k], time, rel_tol=0, abs_tol=1e-9 * max(1.0, abs(time))):
            continue
        if not (u_y[k] > opening_threshold).any():
            continue
        nodes = _run_nodes(slipping_mask(v[k], slip_threshold), grid, track.kind, position)
        if nodes.size and (u_y[k, nodes] > opening_threshold).any():
            return float(time)
    return math.nan


def measure_rules(x: np.ndarray, t: np.ndarray, v: np.ndarray, u_y: np.ndarray,
                  front_map: FrontMap, localization: cel.CelerityResult, *,
                  slip_threshold: float, opening_threshold: float, first_opening_time: float,
                  min_speed: float, window_length: float = cel.DEFAULT_WINDOW_LENGTH,
                  major_duration: float = cel.DEFAULT_MAJOR_DURATION,
                  first_window_length: float = DEFAULT_FIRST_WINDOW_LENGTH,
                  names: tuple[str, ...] = RULES) -> dict[str, RuleResult]:
    """The rules `names` (default: every rule of RULES) on one run -> {rule: RuleResult}.

    Parameters
    ----------
    x, t, v, u_y
        Node positions (m), output times (s), slip velocity (m/s) and opening (m) maps.
    front_map, localization
        The slip-front map (`find_edges` at slip_threshold) and `celerity_from_fronts` on it with
        the same min_speed, window_length and major_duration (the `localization` rule).
    slip_threshold, opening_threshold
        Slip-velocity (m/s) and opening (m) thresholds.
    first_opening_time
        First output time with u_y above opening_threshold (s); nan when the run never opens.
    min_speed, window_length, major_duration
        As in `celerity_from_fronts` (m/s, s, s).
    first_window_length
        Window of `first_100s` (s).
    names
        The rules to measure (a subset of RULES; `opening_pulse` and `opening_pulse_from_opening`
        come together); the others are skipped, e.g. for a re-measurement at another threshold.
    """
    unknown = sorted(set(names) - set(RULES))
    if unknown:
        raise ValueError(f"unknown rule(s) {', '.join(unknown)}; the rules are {', '.join(RULES)}")
    kw = dict(min_speed=min_speed, window_length=window_length, major_duration=major_duration)
    out = {"localization": from_celerity_result(localization)}
    major = localization.major
    opened = math.isfinite(first_opening_time)
    if {"opening_pulse", "opening_pulse_from_opening"} & set(names):
        out.update(_opening_pulse_rules(t, v, u_y, front_map, localization, opened,
                                        slip_threshold, opening_threshold, window_length))

    # The opening front, on the opening map.
    if "opening_front" in names and opened:
        open_map = find_edges(x, t, u_y, opening_threshold)
        out["opening_front"] = from_celerity_result(
            cel.celerity_from_fronts(open_map, window_start=first_opening_time, **kw))
    elif "opening_front" in names:
        out["opening_front"] = RuleResult(math.nan, "no_opening")

    # The strongest major front over its first 100 s, alone.
    if "first_100s" in names:
        firsts = [(track.within(track.start, track.start + first_window_length), direction)
                  for track, direction in major]
        firsts = [(part, d) for part, d in firsts if part.t.size >= DEFAULT_MIN_POINTS]
        if firsts:
            out["first_100s"] = _fit([max(firsts, key=lambda item: item[0].strength)[0]])
        else:
            out["first_100s"] = RuleResult(math.nan, localization.reason if not major else "empty_window")

    # A late window, ending at the last output.
    if "late" in names:
        out["late"] = from_celerity_result(
            cel.celerity_from_fronts(front_map, window_start=float(t[-1]) - window_length, **kw))
    return {name: out[name] for name in RULES if name in names}


def _opening_pulse_rules(t: np.ndarray, v: np.ndarray, u_y: np.ndarray, front_map: FrontMap,
                         localization: cel.CelerityResult, opened: bool, slip_threshold: float,
                         opening_threshold: float, window_length: float) -> dict[str, RuleResult]:
    """`opening_pulse` and `opening_pulse_from_opening` (arguments as in `measure_rules`)."""
    out = {}
    major = localization.major
    # The major pulse that opens (the strongest front whose run opens), and when.
    if localization.reason in ("no_slip", "uniform_slip", "no_major_front"):
        pulse_reason = localization.reason
    elif not opened:
        pulse_reason = "no_opening"
    else:
        pulse_reason = "no_opening_pulse"
    opening_pulses = []
    if opened:
        for track, direction in major:
            t_open = pulse_opening_time(track, t, v, u_y, slip_threshold, opening_threshold,
                                        front_map.grid)
            if math.isfinite(t_open):
                opening_pulses.append((-track.strength, t_open, id(track), t_open, track, direction))
    if opening_pulses:
        *_, t_open, anchor, direction = min(opening_pulses, key=lambda item: item[:3])
        out["opening_pulse"] = anchored_fit(anchor, direction, major, anchor.start, window_length)
        out["opening_pulse_from_opening"] = anchored_fit(anchor, direction, major, t_open, window_length)
    else:
        out["opening_pulse"] = out["opening_pulse_from_opening"] = RuleResult(math.nan, pulse_reason)
    return out


#: The keys `rule_metrics` returns, in its order.
RULE_METRIC_KEYS = ("celerity_rule_default",) + tuple(
    f"celerity_rule_{name}{suffix}" for name in RULES for suffix in ("", "_window", "_deceleration", "_reason"))


def rule_metrics(results: dict[str, RuleResult], default_rule: str = DEFAULT_RULE) -> dict:
    """Metrics keys of the rules: celerity_rule_<name>, _window, _deceleration, _reason, and
    celerity_rule_default."""
    metrics: dict = {"celerity_rule_default": default_rule}
    for name in RULES:
        r = results[name]
        metrics[f"celerity_rule_{name}"] = r.celerity
        metrics[f"celerity_rule_{name}_window"] = list(r.window) if r.window else None
        metrics[f"celerity_rule_{name}_deceleration"] = r.deceleration
        metrics[f"celerity_rule_{name}_reason"] = r.reason
    return metrics
