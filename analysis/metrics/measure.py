"""One run -> its metrics (the `metrics.json` of docs/contracts.md section 3).

`measure_run` is a pure function of a loaded run (`analysis.core.io.RunData`) and the measurement
settings; `analysis/README.md` explains every key. Values that cannot be measured are None
(JSON null), never a guess. The solver's constants (c_s, c_l, p0, dt, the onset estimate, the
opening threshold) are read from the run, never recomputed.

f = 0 (no friction): T = 0, so T/N is 0 up to round-off; there is nothing to drop and nothing to
invert: no frictional drops, `inversion` false (a round-off T/N of -1e-17 is not an inversion).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from analysis.fronts import celerity as cel
from analysis.fronts import default_rule
from analysis.fronts import rules
from analysis.metrics import dissipation, energy, inversion, opening, pulses, regime, validity
from analysis.theory import elastic, flutter
from analysis.core.errors import InputError
from analysis.core.io import RunData
from analysis.fronts.edges import slipping_mask
from analysis.fronts.tracking import EdgeTrack, find_edges

#: Version of the measurement definitions, written into every metrics file (analysis/README.md
#: says what each version changed).
ANALYSIS_VERSION = "4"

#: Run parameters copied into the metrics: key -> (config group, config key).
PARAMETERS = {
    "E": ("material", "E"), "nu": ("material", "nu"), "rho": ("material", "rho"),
    "H": ("geometry", "H"), "lambda_over_H": ("geometry", "lambda_over_H"),
    "elements_per_H": ("mesh", "elements_per_H"), "integration": ("mesh", "integration"),
    "mass": ("mesh", "mass"), "Uy_over_H": ("loading", "Uy_over_H"),
    "preshear_ratio": ("loading", "preshear_ratio"), "V0_over_cs": ("loading", "V0_over_cs"),
    "f": ("friction", "f"), "regularization": ("friction", "regularization"),
    "pc_length": ("friction", "pc_length"), "pc_velocity": ("friction", "pc_velocity"),
    "hht_alpha": ("time", "hht_alpha"), "contact_weighting": ("time", "contact_weighting"),
    "stop_after_opening": ("time", "stop_after_opening"),
    "perturbation_amplitude": ("perturbation", "amplitude"), "seed": ("perturbation", "seed"),
    "interface_stride": ("output", "interface_stride"),
}


@dataclass(frozen=True)
class Settings:
    """Measurement settings (all documented in analysis/README.md).

    threshold_rel: slip-velocity threshold / V0 (the opening threshold is the run's own, the one
    that drives the solver's `stop_after_opening`);
    window_length, major_duration: in seconds of the paper's time unit (E = 1000 Pa,
    rho = 1000 kg/m^3), scaled for each run by its own unit sqrt(rho / E) (`time_unit_ratio`), so
    that runs similar to the paper's up to rho or E are measured over the similar window;
    min_speed_rel: slowest front / c_s;
    onset_rel: slip velocity / V0 that marks the first slip; drop_rel: smallest frictional drop / f;
    sensitivity_threshold_factor: the threshold of the sensitivity re-measurement / threshold;
    first_window_length: the window of the `first_100s` rule (s, paper's unit, scaled as the others).
    """

    threshold_rel: float = cel.DEFAULT_THRESHOLD_REL
    window_length: float = cel.DEFAULT_WINDOW_LENGTH
    major_duration: float = cel.DEFAULT_MAJOR_DURATION
    min_speed_rel: float = 0.1
    onset_rel: float = 0.1
    drop_rel: float = 0.1
    sensitivity_threshold_factor: float = 10.0
    first_window_length: float = rules.DEFAULT_FIRST_WINDOW_LENGTH

    def check(self) -> None:
        """ValueError naming every setting out of range."""
        problems = [f"{name} = {getattr(self, name)} must be > 0" for name in
                    ("threshold_rel", "window_length", "major_duration",
                     "min_speed_rel", "onset_rel", "drop_rel", "sensitivity_threshold_factor",
                     "first_window_length")
                    if not getattr(self, name) > 0]
        if problems:
            raise ValueError("; ".join(problems))


#: E (Pa) and rho (kg/m^3) of the paper: the time unit in which the windows are given.
PAPER_E, PAPER_RHO = 1000.0, 1000.0


def time_unit_ratio(E: float, rho: float) -> float:
    """sqrt(rho / E) of a run over the paper's: every time of the problem scales with it (c_s and
    c_l go as sqrt(E / rho), and dt = dt_times_cs / c_s follows), so a window of 200 s in the paper
    is 200 s times this ratio in the run."""
    return math.sqrt((rho / PAPER_RHO) / (E / PAPER_E))


def _parameters(run: RunData) -> dict[str, Any]:
    """The PARAMETERS from the resolved config (which holds every key), then dt, dt_times_cs, t_end."""
    out: dict[str, Any] = {}
    for key, (group, name) in PARAMETERS.items():
        section = run.config.get(group)
        if not isinstance(section, dict) or name not in section:
            raise InputError(f"{run.path}: the resolved config lacks '{group}.{name}' "
                             "(malformed run file)")
        out[key] = section[name]
    out["dt"] = run.attr("dt")
    # The time step in the study's unit (a point parameter, study/sweeps.py), from the dt actually used.
    out["dt_times_cs"] = round(run.attr("dt") * run.attr("c_s"), 9)
    out["t_end"] = run.attr("t_end")
    return out


def _onset_time(t: np.ndarray, v: np.ndarray, state: np.ndarray, speed: float) -> float:
    """First output time (s) at which a node is in the slip state with slip velocity > speed."""
    slipping = ((state == 2) & (v > speed)).any(axis=1)
    frames = np.flatnonzero(slipping)
    return float(t[frames[0]]) if frames.size else math.nan


def _fronts_at(tracks: list[EdgeTrack], time: float) -> np.ndarray:
    positions = []
    for track in tracks:
        k = np.flatnonzero(np.isclose(track.t, time, rtol=0, atol=1e-9 * max(1.0, abs(time))))
        if k.size:
            positions.append(track.position[k[0]])
    return np.array(positions)


def measure_run(run: RunData, settings: Settings | None = None) -> dict[str, Any]:
    """Metrics of one run.

    Parameters
    ----------
    run
        A loaded run (analysis.core.io.load_run).
    settings
        Measurement settings; None = the documented defaults.

    Returns
    -------
    dict
        JSON-ready metrics (floats, ints, bools, strings, None, lists); see analysis/README.md.
    """
    settings = settings or Settings()
    settings.check()
    parameters = _parameters(run)
    # A run that blew up is measured on its finite part (validity.finite_part).
    run = validity.finite_part(run)
    interface, series = run.interface, run.global_series
    E, rho, H, f = (run.attr(k) for k in ("E", "rho", "H", "f"))
    c_s, c_l, V0, p0 = (run.attr(k) for k in ("c_s", "c_l", "V0", "p0"))
    x, t, v = interface.x, interface.t, interface.slip_velocity
    sampled = validity.sampling(t, H, c_s)

    # 1. Onset of slip.
    onset_time = _onset_time(t, v, interface.state, settings.onset_rel * V0)

    # 2. Slip fronts (threshold method) and the localization of the first major front.
    threshold = settings.threshold_rel * V0
    min_speed = settings.min_speed_rel * c_s
    front_map = find_edges(x, t, v, threshold)
    unit = time_unit_ratio(E, rho)
    window_length, major_duration = settings.window_length * unit, settings.major_duration * unit
    kw = dict(min_speed=min_speed, window_length=window_length, major_duration=major_duration)
    result = cel.celerity_from_fronts(front_map, **kw)

    # 3. Opening, above the solver's threshold (the one of stop_after_opening).
    open_threshold = run.attr("opening_threshold")
    opened = opening.summarize_opening(x, t, interface.opening, open_threshold)

    # 4. Every measurement rule of docs/measurement-rule.md; `celerity` is the default rule's, for
    # every run (nan with its reason where it is undefined), and so are its diagnostics; the
    # threshold sensitivity is the default rule at a higher threshold.
    rule_kw = dict(slip_threshold=threshold, opening_threshold=open_threshold,
                   first_opening_time=opened.t_first,
                   first_window_length=settings.first_window_length * unit, **kw)
    by_rule = rules.measure_rules(x, t, v, interface.opening, front_map, result, **rule_kw)
    default = by_rule[rules.DEFAULT_RULE]
    c_p = default.celerity
    high_threshold = threshold * settings.sensitivity_threshold_factor
    high_map = find_edges(x, t, v, high_threshold)
    high = rules.measure_rules(x, t, v, interface.opening, high_map,
                               cel.celerity_from_fronts(high_map, **kw),
                               **{**rule_kw, "slip_threshold": high_threshold},
                               names=(rules.DEFAULT_RULE,))[rules.DEFAULT_RULE]
    count_all, spacing_all = pulses.pulse_train(default.fronts, front_map.grid.period)
    celerity_keys = default_rule.celerity_metrics(
        by_rule, high, x=x, t=t, v=v, c_s=c_s, output_interval=front_map.output_interval,
        pulse_spacing=spacing_all if math.isfinite(spacing_all) else front_map.grid.period,
        window_length=window_length)

    # Where the first opening sits relative to the major fronts of the celerity's direction.
    behind = inside_slip = None
    c_direction = default_rule.direction(default)
    if opened.opened:
        k = int(np.flatnonzero(t == opened.t_first)[0])
        i = int(np.argmin(np.abs(x - opened.x_first)))
        inside_slip = bool(slipping_mask(v[k], threshold)[i])
        same_direction = [track for track, d in result.major if d == c_direction != 0]
        behind = opening.distance_behind_front(opened.x_first,
                                               _fronts_at(same_direction, opened.t_first),
                                               c_direction, front_map.grid.period)

    # 5. T/N: minimum, inversion, frictional drops.
    ratio = inversion.bridge_undefined(series.t, series.T_over_N)
    min_ratio, t_min_ratio = inversion.minimum_ratio(series.t, ratio)
    # Averaged over a shear round trip 2H/c_s: after a drop the layer rings at that period and its
    # harmonics (long run at nu=0.2, f=1.5: 77.6 s = 2.0 H/c_s), which a shorter average leaves as
    # spurious drops of ~0.2.
    # Without friction (f = 0) T/N is round-off: no drop, no inversion (module docstring).
    drops = (inversion.frictional_drops(series.t, ratio, settings.drop_rel * f, smooth_time=2 * H / c_s)
             if f > 0 else [])
    first = drops[0] if drops else None
    later_starts = [d.T_over_N_start for d in drops[1:]]

    # 6. Pulse train, regime, category, energy.
    # Major pulses weighed by what they open over their life; on the slip velocity if never open.
    major, major_field = pulses.MajorPulses(0, math.nan), None
    if math.isfinite(c_p):
        major_field = "opening" if opened.opened else "slip_velocity"
        major = (pulses.major_pulses(x, t, interface.opening, open_threshold, c_p) if opened.opened
                 else pulses.major_pulses(x, t, v, threshold, c_p))

    # 7. Frictional dissipation per unit slip: during opening, and from the onset to the opening.
    window = dict(t_global=series.t, dissipation=series.dissipation_friction,
                  work=series.work_external, elastic=series.energy_elastic, t_interface=t,
                  slip=interface.slip, normal_force=p0 * front_map.grid.period)
    t_last = float(t[-1])
    during = dissipation.window_dissipation(t0=opened.t_first, t1=t_last, **window)
    before = dissipation.window_dissipation(
        t0=onset_time, t1=opened.t_first if opened.opened else t_last, **window)
    spacing_theory = elastic.pulse_spacing(c_p, c_s, H)
    inverted = bool(min_ratio < 0) and f > 0
    balance_error, residual_max = energy.energy_balance_error(
        series.energy_kinetic, series.energy_elastic, series.work_external,
        series.dissipation_friction, series.energy_balance_residual)
    unphysical = validity.non_physical_reason(run, opened.max_opening)

    metrics: dict[str, Any] = {
        "source": run.path,
        "analysis_version": ANALYSIS_VERSION,
        "slidewave_version": run.attrs.get("slidewave_version"),
        "git_commit": run.attrs.get("git_commit"),
        "complete": run.complete,
        "end_reason": run.end_reason,
        "non_physical": unphysical is not None,
        "non_physical_reason": unphysical,
        "sampling_too_coarse": sampled.too_coarse,
        "output_frames_per_round_trip": sampled.frames_per_round_trip,
        **parameters,
        "c_s": c_s, "c_l": c_l, "sqrt2_c_s": math.sqrt(2.0) * c_s, "p0": p0, "V0": V0,
        "lambda": front_map.grid.period, "dx": front_map.grid.dx,
        "output_interval": front_map.output_interval,
        "slip_threshold": threshold, "threshold_rel": settings.threshold_rel,
        "window_length": window_length, "major_duration": major_duration,
        "onset_time": onset_time,
        "onset_time_estimate": run.attr("t_onset_estimate"),
        **celerity_keys,
        "localization_time": result.t_localized,
        **rules.rule_metrics(by_rule),
        "regime": regime.regime(c_p, c_s, c_l),
        "below_sqrt2_cs": regime.below_sqrt2_cs(c_p, c_s),
        "intersonic_below_sqrt2_cs": regime.intersonic_below_sqrt2_cs(c_p, c_s),
        "opening": opened.opened,
        "max_opening": opened.max_opening,
        "max_opening_time": opened.t_max,
        "opening_threshold": open_threshold,
        "first_opening_time": opened.t_first,
        "first_opening_x": opened.x_first,
        "opening_delay_after_localization": opened.t_first - result.t_localized,
        "opening_behind_front": behind,
        "opening_inside_slip": inside_slip,
        "open_fraction_max": opened.open_fraction_max,
        "min_T_over_N": min_ratio,
        "min_T_over_N_time": t_min_ratio,
        "inversion": inverted,
        "n_drops": len(drops),
        "first_drop_start_time": first.t_start if first else math.nan,
        "first_drop_start_T_over_N": first.T_over_N_start if first else math.nan,
        "first_drop_bottom_time": first.t_bottom if first else math.nan,
        "first_drop_bottom_T_over_N": first.T_over_N_bottom if first else math.nan,
        "later_drops_start_T_over_N": later_starts,
        "later_drops_start_T_over_N_median": (float(np.median(later_starts)) if later_starts
                                              else math.nan),
        "n_complete_drops": sum(d.complete for d in drops),
        "first_drop_start_after_onset": (first.t_start - onset_time) if first else math.nan,
        "first_drop_duration": (first.t_bottom - first.t_start) if first else math.nan,
        "inside_flutter_wedge": flutter.inside_wedge(run.attr("nu"), f),
        "category": regime.category(slipped=front_map.n_slipping_frames > 0,
                                    has_front=front_map.n_edge_frames > 0, opened=opened.opened,
                                    celerity=c_p, c_s=c_s, c_l=c_l, inversion=inverted,
                                    non_physical=unphysical is not None,
                                    sampling_too_coarse=sampled.too_coarse),
        "pulse_count": major.count if major_field else None,
        "pulse_spacing": major.spacing,
        "pulse_count_field": major_field,
        "pulse_major_strengths": list(major.strengths),
        "pulse_next_strength": major.next_strength,
        "pulse_count_all": count_all,
        "pulse_spacing_all": spacing_all,
        "pulse_spacing_theory": spacing_theory,
        "pulse_spacing_theory_over_H": spacing_theory / H,
        "pulse_count_theory": pulses.expected_pulse_count(front_map.grid.period, spacing_theory),
        "dissipative_friction_opening": during.mu_diss,
        "friction_work_ratio_opening": during.work_fraction,
        "friction_energy_share_opening": during.energy_share,
        "dissipative_friction_before_opening": before.mu_diss,
        "friction_work_ratio_before_opening": before.work_fraction,
        "dissipation_window_opening": [during.t0, during.t1],
        "dissipation_window_before_opening": [before.t0, before.t1],
        "energy_balance_error": balance_error,
        "energy_balance_residual_max": residual_max,
        "contact_residual_max": float(np.max(series.contact_residual)),
        "contact_iterations_max": int(np.max(series.contact_iterations)),
    }
    return json_ready(metrics)


def json_ready(value: Any) -> Any:
    """Recursively: numpy scalars -> Python, nan/inf -> None, tuples -> lists."""
    if isinstance(value, dict):
        return {str(k): json_ready(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [json_ready(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value
