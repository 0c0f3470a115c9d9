"""One run -> its metrics (the `metrics.json` of docs/contracts.md section 3).

`measure_run` is a pure function of a loaded run (`analysis.core.io.RunData`) and the measurement
settings. It measures what several metrics share once (`Measured`: fronts, rules, opening, drops),
then calls one function per metric family (`FAMILIES`), each declaring the keys it produces, in the
order of metrics.json and all_metrics.csv; `METRIC_KEYS` is their concatenation and
`analysis/README.md` ("Metric keys") lists exactly those keys. Values that cannot be measured are None
(JSON null), never a guess. The solver's constants (c_s, c_l, p0, dt, the onset estimate, the
opening threshold) are read from the run, never recomputed.

f = 0 (no friction): T = 0, so T/N is 0 up to round-off; there is nothing to drop and nothing to
invert: no frictional drops, `inversion` false (a round-off T/N of -1e-17 is not an inversion).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from analysis.core.io import RunData
from analysis.fronts import default_rule, rules
from analysis.fronts.edges import slipping_mask
from analysis.fronts.tracking import EdgeTrack
from analysis.metrics import dissipation, energy, opening, pulses, regime
from analysis.metrics.measured import PARAMETERS, Measured, Settings, measure, time_unit_ratio  # noqa: F401
from analysis.theory import elastic, flutter

#: Version of the measurement definitions, written into every metrics file (analysis/README.md
#: says what each version changed).
ANALYSIS_VERSION = "9"


def _fronts_at(tracks: list[EdgeTrack], time: float) -> np.ndarray:
    positions = []
    for track in tracks:
        k = np.flatnonzero(np.isclose(track.t, time, rtol=0, atol=1e-9 * max(1.0, abs(time))))
        if k.size:
            positions.append(track.position[k[0]])
    return np.array(positions)


# --------------------------------------------------------------------------------------------------
# Metric families, in the order of metrics.json; each declares its keys.


@dataclass(frozen=True)
class Family:
    """One metric family: its name, the keys it produces (in order) and the function of `Measured`."""

    name: str
    keys: tuple[str, ...]
    compute: Callable[[Measured], dict[str, Any]]


FAMILIES: list[Family] = []


def family(name: str, keys: tuple[str, ...]) -> Callable:
    """Register the decorated function as the metric family `name` producing `keys`."""
    def register(compute: Callable[[Measured], dict[str, Any]]) -> Callable:
        FAMILIES.append(Family(name, tuple(keys), compute))
        return compute
    return register


@family("provenance", ("source", "analysis_version", "slidewave_version", "git_commit", "complete",
                       "end_reason"))
def _provenance(m: Measured) -> dict[str, Any]:
    run = m.run
    return {"source": run.path, "analysis_version": ANALYSIS_VERSION,
            "slidewave_version": run.attrs.get("slidewave_version"),
            "git_commit": run.attrs.get("git_commit"), "complete": run.complete,
            "end_reason": run.end_reason}


@family("validity", ("non_physical", "non_physical_reason", "sampling_too_coarse",
                     "output_frames_per_round_trip"))
def _validity(m: Measured) -> dict[str, Any]:
    return {"non_physical": m.non_physical_reason is not None, "non_physical_reason": m.non_physical_reason,
            "sampling_too_coarse": m.sampled.too_coarse,
            "output_frames_per_round_trip": m.sampled.frames_per_round_trip}


@family("parameters", tuple(PARAMETERS) + ("dt", "dt_times_cs", "t_end"))
def _run_parameters(m: Measured) -> dict[str, Any]:
    return m.parameters


@family("substrate", ("E_substrate_over_E", "substrate_nu", "substrate_rho_over_rho", "substrate_H_over_H"))
def _substrate(m: Measured) -> dict[str, Any]:
    """The deformable substrate against the layer (docs/substrate.md), from the resolved config; None on
    the rigid flat (no `substrate` group), so that tables group runs by contrast."""
    substrate = m.run.config.get("substrate")
    if not isinstance(substrate, dict) or substrate.get("E") is None:
        return dict.fromkeys(("E_substrate_over_E", "substrate_nu", "substrate_rho_over_rho", "substrate_H_over_H"))
    layer = m.parameters
    return {"E_substrate_over_E": substrate["E"] / layer["E"], "substrate_nu": substrate["nu"],
            "substrate_rho_over_rho": substrate["rho"] / layer["rho"],
            "substrate_H_over_H": substrate["H"] / layer["H"]}


@family("constants and settings", ("c_s", "c_l", "sqrt2_c_s", "p0", "V0", "lambda", "dx", "output_interval",
                                   "slip_threshold", "threshold_rel", "window_length", "major_duration"))
def _constants(m: Measured) -> dict[str, Any]:
    grid = m.front_map.grid
    return {"c_s": m.attr("c_s"), "c_l": m.attr("c_l"), "sqrt2_c_s": math.sqrt(2.0) * m.attr("c_s"),
            "p0": m.attr("p0"), "V0": m.attr("V0"), "lambda": grid.period, "dx": grid.dx,
            "output_interval": m.front_map.output_interval, "slip_threshold": m.threshold,
            "threshold_rel": m.settings.threshold_rel, "window_length": m.window_length,
            "major_duration": m.major_duration}


@family("onset", ("onset_time", "onset_time_estimate"))
def _onset(m: Measured) -> dict[str, Any]:
    return {"onset_time": m.onset_time, "onset_time_estimate": m.attr("t_onset_estimate")}


@family("celerity", default_rule.CELERITY_KEYS + ("localization_time",) + rules.RULE_METRIC_KEYS)
def _celerity(m: Measured) -> dict[str, Any]:
    """`celerity` is the default rule's for every run (nan with its reason where undefined), and so
    are its diagnostics; then the localization and every rule."""
    interface = m.run.interface
    keys = default_rule.celerity_metrics(
        m.by_rule, m.high_threshold, x=interface.x, t=interface.t, v=interface.slip_velocity,
        c_s=m.attr("c_s"), output_interval=m.front_map.output_interval, pulse_spacing=m.train_spacing,
        window_length=m.window_length)
    return {**keys, "localization_time": m.localization.t_localized, **rules.rule_metrics(m.by_rule)}


@family("regime", ("regime", "below_sqrt2_cs", "intersonic_below_sqrt2_cs"))
def _regime(m: Measured) -> dict[str, Any]:
    c, c_s = m.celerity, m.attr("c_s")
    return {"regime": regime.regime(c, c_s, m.attr("c_l")), "below_sqrt2_cs": regime.below_sqrt2_cs(c, c_s),
            "intersonic_below_sqrt2_cs": regime.intersonic_below_sqrt2_cs(c, c_s)}


@family("opening", ("opening", "max_opening", "max_opening_time", "opening_threshold", "first_opening_time",
                    "first_opening_x", "opening_delay_after_localization", "opening_behind_front",
                    "opening_inside_slip", "open_fraction_max"))
def _opening(m: Measured) -> dict[str, Any]:
    """Also where the first opening sits relative to the major fronts of the celerity's direction."""
    opened, interface = m.opened, m.run.interface
    behind = inside_slip = None
    c_direction = default_rule.direction(m.by_rule[rules.DEFAULT_RULE])
    if opened.opened:
        k = int(np.flatnonzero(interface.t == opened.t_first)[0])
        i = int(np.argmin(np.abs(interface.x - opened.x_first)))
        inside_slip = bool(slipping_mask(interface.slip_velocity[k], m.threshold)[i])
        same_direction = [track for track, d in m.localization.major if d == c_direction != 0]
        behind = opening.distance_behind_front(opened.x_first, _fronts_at(same_direction, opened.t_first),
                                               c_direction, m.front_map.grid.period)
    return {"opening": opened.opened, "max_opening": opened.max_opening, "max_opening_time": opened.t_max,
            "opening_threshold": m.attr("opening_threshold"), "first_opening_time": opened.t_first,
            "first_opening_x": opened.x_first,
            "opening_delay_after_localization": opened.t_first - m.localization.t_localized,
            "opening_behind_front": behind, "opening_inside_slip": inside_slip,
            "open_fraction_max": opened.open_fraction_max}


@family("T/N and frictional drops", (
        "min_T_over_N", "min_T_over_N_time", "inversion", "n_drops", "first_drop_start_time",
        "first_drop_start_T_over_N", "first_drop_bottom_time", "first_drop_bottom_T_over_N",
        "later_drops_start_T_over_N", "later_drops_start_T_over_N_median", "n_complete_drops",
        "first_drop_start_after_onset", "first_drop_duration"))
def _drops(m: Measured) -> dict[str, Any]:
    first = m.drops[0] if m.drops else None
    later = [d.T_over_N_start for d in m.drops[1:]]
    nan = math.nan
    return {"min_T_over_N": m.min_ratio, "min_T_over_N_time": m.t_min_ratio, "inversion": m.inverted,
            "n_drops": len(m.drops),
            "first_drop_start_time": first.t_start if first else nan,
            "first_drop_start_T_over_N": first.T_over_N_start if first else nan,
            "first_drop_bottom_time": first.t_bottom if first else nan,
            "first_drop_bottom_T_over_N": first.T_over_N_bottom if first else nan,
            "later_drops_start_T_over_N": later,
            "later_drops_start_T_over_N_median": float(np.median(later)) if later else nan,
            "n_complete_drops": sum(d.complete for d in m.drops),
            "first_drop_start_after_onset": (first.t_start - m.onset_time) if first else nan,
            "first_drop_duration": (first.t_bottom - first.t_start) if first else nan}


@family("flutter wedge", ("inside_flutter_wedge",))
def _flutter_wedge(m: Measured) -> dict[str, Any]:
    """Exact boundary (analysis.theory.flutter); the one place the column is computed."""
    return {"inside_flutter_wedge": flutter.inside_wedge(m.attr("nu"), m.attr("f"))}


@family("category", ("category",))
def _category(m: Measured) -> dict[str, Any]:
    return {"category": regime.category(
        slipped=m.front_map.n_slipping_frames > 0, has_front=m.front_map.n_edge_frames > 0,
        opened=m.opened.opened, celerity=m.celerity, c_s=m.attr("c_s"), c_l=m.attr("c_l"),
        inversion=m.inverted, non_physical=m.non_physical_reason is not None,
        sampling_too_coarse=m.sampled.too_coarse or m.beyond_sampling_limit)}


@family("pulses", ("pulse_count", "pulse_spacing", "pulse_count_field", "pulse_major_strengths",
                   "pulse_next_strength", "pulse_count_all", "pulse_spacing_all", "pulse_spacing_theory",
                   "pulse_spacing_theory_over_H", "pulse_count_theory"))
def _pulses(m: Measured) -> dict[str, Any]:
    """Major pulses weighed by what they open over their life; on the slip velocity if never open."""
    interface, c_p, H = m.run.interface, m.celerity, m.attr("H")
    major, field = pulses.MajorPulses(0, math.nan), None
    if math.isfinite(c_p):
        field = "opening" if m.opened.opened else "slip_velocity"
        major = (pulses.major_pulses(interface.x, interface.t, interface.opening,
                                     m.attr("opening_threshold"), c_p) if m.opened.opened
                 else pulses.major_pulses(interface.x, interface.t, interface.slip_velocity, m.threshold, c_p))
    spacing_theory = elastic.pulse_spacing(c_p, m.attr("c_s"), H)
    return {"pulse_count": major.count if field else None, "pulse_spacing": major.spacing,
            "pulse_count_field": field, "pulse_major_strengths": list(major.strengths),
            "pulse_next_strength": major.next_strength, "pulse_count_all": m.count_all,
            "pulse_spacing_all": m.spacing_all, "pulse_spacing_theory": spacing_theory,
            "pulse_spacing_theory_over_H": spacing_theory / H,
            "pulse_count_theory": pulses.expected_pulse_count(m.front_map.grid.period, spacing_theory)}


@family("dissipation", ("dissipative_friction_opening", "friction_work_ratio_opening",
                        "friction_energy_share_opening", "dissipative_friction_before_opening",
                        "friction_work_ratio_before_opening", "dissipation_window_opening",
                        "dissipation_window_before_opening"))
def _dissipation(m: Measured) -> dict[str, Any]:
    """Frictional dissipation per unit slip: during opening, and from the onset to the opening."""
    series, interface, opened = m.run.global_series, m.run.interface, m.opened
    window = dict(t_global=series.t, dissipation=series.dissipation_friction, work=series.work_external,
                  elastic=series.energy_elastic, t_interface=interface.t, slip=interface.slip,
                  normal_force=m.attr("p0") * m.front_map.grid.period)
    t_last = float(interface.t[-1])
    during = dissipation.window_dissipation(t0=opened.t_first, t1=t_last, **window)
    before = dissipation.window_dissipation(t0=m.onset_time, t1=opened.t_first if opened.opened else t_last,
                                            **window)
    return {"dissipative_friction_opening": during.mu_diss, "friction_work_ratio_opening": during.work_fraction,
            "friction_energy_share_opening": during.energy_share,
            "dissipative_friction_before_opening": before.mu_diss,
            "friction_work_ratio_before_opening": before.work_fraction,
            "dissipation_window_opening": [during.t0, during.t1],
            "dissipation_window_before_opening": [before.t0, before.t1]}


@family("energy and contact", ("energy_balance_error", "energy_balance_residual_max", "contact_residual_max",
                               "contact_iterations_max", "energy_created"))
def _energy(m: Measured) -> dict[str, Any]:
    series = m.run.global_series
    error, residual_max = energy.energy_balance_error(
        series.energy_kinetic, series.energy_elastic, series.work_external, series.dissipation_friction,
        series.energy_balance_residual)
    return {"energy_balance_error": error, "energy_balance_residual_max": residual_max,
            "contact_residual_max": float(np.max(series.contact_residual)),
            "contact_iterations_max": int(np.max(series.contact_iterations)),
            "energy_created": m.energy_created}


@family("first drop complete", ("first_drop_complete",))
def _first_drop_complete(m: Measured) -> dict[str, Any]:
    """Drops are found in time order and only the last can be cut by the end of the run: False means
    the first drop's bottom, duration and min T/N are those reached when the run stopped; None
    without a drop. Last in the file (all_metrics.csv kept its column order when this moved here
    from aggregate)."""
    return {"first_drop_complete": sum(d.complete for d in m.drops) >= 1 if m.drops else None}


#: Every key of metrics.json, in order.
METRIC_KEYS = tuple(key for f in FAMILIES for key in f.keys)


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
        JSON-ready metrics (floats, ints, bools, strings, None, lists), the keys METRIC_KEYS in
        their order; see analysis/README.md.
    """
    settings = settings or Settings()
    settings.check()
    measured = measure(run, settings)
    metrics: dict[str, Any] = {}
    for f in FAMILIES:
        values = f.compute(measured)
        if tuple(values) != f.keys:
            raise RuntimeError(f"metric family {f.name!r} produced {tuple(values)}, declared {f.keys}")
        metrics.update(values)
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
