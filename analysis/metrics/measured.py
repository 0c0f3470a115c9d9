"""What the metric families of `measure` share: the measurement `Settings`, the run parameters
copied into the metrics, and `Measured`, the fronts, rules, opening and drops of one run measured
once (`measure`). The solver's constants are read from the run, never recomputed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from analysis.core.errors import InputError
from analysis.core.io import RunData
from analysis.fronts import celerity as cel
from analysis.fronts import rules
from analysis.fronts.sampling_limit import BEYOND_SAMPLING_LIMIT, within_sampling_limit
from analysis.fronts.tracking import FrontMap, find_edges
from analysis.metrics import energy, inversion, opening, pulses, validity

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


@dataclass(frozen=True)
class Measured:
    """What several metric families share, measured once per run (`measure`)."""

    run: RunData
    settings: Settings
    parameters: dict[str, Any]
    sampled: validity.Sampling
    onset_time: float
    threshold: float
    window_length: float
    major_duration: float
    front_map: FrontMap
    localization: cel.CelerityResult
    opened: opening.OpeningSummary
    by_rule: dict[str, rules.RuleResult]
    high_threshold: rules.RuleResult
    count_all: float
    spacing_all: float
    drops: list[inversion.FrictionalDrop]
    min_ratio: float
    t_min_ratio: float
    energy_created: float  # energy.energy_created of the measured part of the run
    non_physical_reason: str | None

    @property
    def celerity(self) -> float:
        """c_p, the default rule's celerity (m/s; nan where undefined)."""
        return self.by_rule[rules.DEFAULT_RULE].celerity

    @property
    def train_spacing(self) -> float:
        """Gap between neighbouring pulses of the default rule's train (m; the period for one pulse)."""
        return _train_spacing(self.spacing_all, self.front_map)

    @property
    def beyond_sampling_limit(self) -> bool:
        """The opening pulse moves too far per frame to be measured (analysis.fronts.sampling_limit)."""
        return self.by_rule[rules.DEFAULT_RULE].reason == BEYOND_SAMPLING_LIMIT

    @property
    def inverted(self) -> bool:
        return bool(self.min_ratio < 0) and self.run.attr("f") > 0

    def attr(self, key: str) -> Any:
        return self.run.attr(key)


def _train_spacing(spacing_all: float, front_map: FrontMap) -> float:
    return spacing_all if math.isfinite(spacing_all) else front_map.grid.period


def measure(run: RunData, settings: Settings) -> Measured:
    """The shared measurements of one run (a run that blew up: of its finite part)."""
    parameters = _parameters(run)
    run = validity.finite_part(run)
    interface, series = run.interface, run.global_series
    E, rho, H, f = (run.attr(k) for k in ("E", "rho", "H", "f"))
    c_s, V0 = run.attr("c_s"), run.attr("V0")
    x, t, v = interface.x, interface.t, interface.slip_velocity

    # 1. Onset of slip; slip fronts (threshold method) and the localization of the first major front.
    onset_time = _onset_time(t, v, interface.state, settings.onset_rel * V0)
    threshold = settings.threshold_rel * V0
    front_map = find_edges(x, t, v, threshold)
    unit = time_unit_ratio(E, rho)
    window_length, major_duration = settings.window_length * unit, settings.major_duration * unit
    kw = dict(min_speed=settings.min_speed_rel * c_s, window_length=window_length,
              major_duration=major_duration)
    localization = cel.celerity_from_fronts(front_map, **kw)

    # 2. Opening, above the solver's threshold (the one of stop_after_opening).
    open_threshold = run.attr("opening_threshold")
    opened = opening.summarize_opening(x, t, interface.opening, open_threshold)

    # 3. Every measurement rule of docs/measurement-rule.md; the threshold sensitivity is the
    # default rule at a higher threshold.
    rule_kw = dict(slip_threshold=threshold, opening_threshold=open_threshold,
                   first_opening_time=opened.t_first,
                   first_window_length=settings.first_window_length * unit, **kw)
    by_rule = rules.measure_rules(x, t, v, interface.opening, front_map, localization, **rule_kw)
    high = threshold * settings.sensitivity_threshold_factor
    high_map = find_edges(x, t, v, high)
    high_threshold = rules.measure_rules(x, t, v, interface.opening, high_map,
                                         cel.celerity_from_fronts(high_map, **kw),
                                         **{**rule_kw, "slip_threshold": high},
                                         names=(rules.DEFAULT_RULE,))[rules.DEFAULT_RULE]
    count_all, spacing_all = pulses.pulse_train(by_rule[rules.DEFAULT_RULE].fronts, front_map.grid.period)
    # A fit that moves more than half a pulse spacing per frame is aliasing, not a celerity.
    spacing = _train_spacing(spacing_all, front_map)
    by_rule = {name: within_sampling_limit(result, front_map.output_interval, spacing)
               for name, result in by_rule.items()}
    high_threshold = within_sampling_limit(high_threshold, front_map.output_interval, spacing)

    # 4. T/N: minimum and frictional drops, averaged over a shear round trip 2H/c_s: after a drop
    # the layer rings at that period and its harmonics (long run at nu=0.2, f=1.5: 77.6 s =
    # 2.0 H/c_s), which a shorter average leaves as spurious drops of ~0.2. Without friction
    # (f = 0) T/N is round-off: no drop, no inversion (module docstring).
    ratio = inversion.bridge_undefined(series.t, series.T_over_N)
    min_ratio, t_min_ratio = inversion.minimum_ratio(series.t, ratio)
    drops = (inversion.frictional_drops(series.t, ratio, settings.drop_rel * f, smooth_time=2 * H / c_s)
             if f > 0 else [])
    created = energy.energy_created(series.energy_kinetic, series.energy_elastic, series.work_external,
                                    series.dissipation_friction)
    non_physical_reason = validity.non_physical_reason(run, opened.max_opening, created)
    if non_physical_reason is not None:  # a state outside the model: no rule measured the model
        by_rule = {name: validity.without_celerity(result) for name, result in by_rule.items()}
        high_threshold = validity.without_celerity(high_threshold)
    return Measured(run=run, settings=settings, parameters=parameters,
                    sampled=validity.sampling(t, H, c_s), onset_time=onset_time, threshold=threshold,
                    window_length=window_length, major_duration=major_duration, front_map=front_map,
                    localization=localization, opened=opened, by_rule=by_rule,
                    high_threshold=high_threshold, count_all=count_all, spacing_all=spacing_all,
                    drops=drops, min_ratio=min_ratio, t_min_ratio=t_min_ratio, energy_created=created,
                    non_physical_reason=non_physical_reason)
