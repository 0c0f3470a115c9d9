"""Whether a run can be measured at all: a non-physical state, or output sampled too coarsely.

Three ways a run can produce numbers that look like a result and are not:

- **Non-physical state.** A run that blew up (typically one that ended on `contact_not_converged`)
  can open by hundreds of metres on a 25 m layer, or hold non-finite values. The model is linear
  elasticity of a layer of height H under small strains: an opening larger than H is outside it
  whatever the cause. Such a run is `non_physical`; its metrics are kept (measured on the finite
  part of the run) so that the state stays visible, but not its celerity: the growth that ends
  outside the model starts before it is detected, so no rule's fit is a measurement of the model
  (`without_celerity`: undefined, reason `non_physical`, in every table).
- **Energy created.** Friction, the unilateral contact and HHT-alpha only take energy out; the top's
  work is the only source. A run whose E_kin + E_el exceeds its start plus that work by more than
  `ENERGY_CREATED_LIMIT` of the energy that flowed has been driven by the discrete scheme, not the
  physics: at small time steps without regularization the friction's booked work turns negative (it
  feeds the layer) and the energy grows without bound (docs/physics-notes.md, section 8). Such a run is
  `non_physical` too, whether or not it opens beyond H.
- **Sampling too coarse.** The interface fields are written every `interface_stride` steps, every
  dt_out seconds. The layer's dynamics proceeds in shear round trips 2H/c_s (the staircase of T/N,
  the spacing 2H sqrt(c_p^2/c_s^2 - 1) of a pulse train, the ringing after a frictional drop);
  a front is fitted from at least `MIN_FRAMES_PER_ROUND_TRIP` points (`tracking.DEFAULT_MIN_POINTS`).
  With fewer frames per round trip a pulse that forms, runs and opens within a few round trips can
  fall between frames, and the run comes out as `no_slip` or without a front although it opened.
  The paper's sampling (stride 4, dt = 0.5 m / c_s at H = 25 m) gives 25 frames per round trip;
  the study's coarsest (dt = 1 m / c_s) 12.5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from analysis.core.errors import InputError
from analysis.core.io import GlobalSeries, InterfaceFields, RunData
from analysis.fronts.rules import RuleResult
from analysis.fronts.tracking import DEFAULT_MIN_POINTS

#: Energy a run may create, relative to the energy that flowed (`energy.energy_created`): the continuous
#: problem creates none (the top's work is its only source), so this only absorbs the ledger's round-off
#: (1e-12) and its trapezoidal booking of W_ext; runs that create energy were measured at 0.03 to 1.95, the
#: others at 0 (H/32, H/64) or at most 5.3e-6 (H/128) (docs/physics-notes.md, section 8).
ENERGY_CREATED_LIMIT = 1e-3

#: The reason of a celerity that a non-physical run would have had.
NON_PHYSICAL = "non_physical"

#: Fewest interface output frames per shear round trip 2H/c_s (and in the whole run).
MIN_FRAMES_PER_ROUND_TRIP = DEFAULT_MIN_POINTS


@dataclass(frozen=True)
class Sampling:
    """frames_per_round_trip = 2H / (c_s dt_out) (-, nan with one frame); too_coarse (bool)."""

    frames_per_round_trip: float
    too_coarse: bool


def sampling(t: np.ndarray, H: float, c_s: float) -> Sampling:
    """Whether the interface output times t (s) resolve the layer's shear round trip 2H/c_s."""
    if t.size < 2:
        return Sampling(math.nan, True)
    dt_out = float(np.median(np.diff(t)))
    frames = 2.0 * H / (c_s * dt_out)
    return Sampling(frames, bool(frames < MIN_FRAMES_PER_ROUND_TRIP or t.size < DEFAULT_MIN_POINTS))


def non_physical_reason(run: RunData, max_opening: float, energy_created: float = 0.0) -> str | None:
    """Why the state of a run is not physical ("non_finite: ...", "opening_above_H: ...",
    "energy_created: ..."), else None.

    max_opening (m): the largest opening over the measured (finite) part of the run; energy_created:
    `energy.energy_created` of that part (nan: no energy flowed, nothing to judge).
    """
    if run.non_finite:
        return "non_finite: " + ", ".join(run.non_finite)
    H = run.attr("H")
    if max_opening > H:
        return f"opening_above_H: max opening {max_opening:.6g} m > H = {H:g} m"
    if energy_created > ENERGY_CREATED_LIMIT:
        return (f"energy_created: E_kin + E_el exceeded E(0) + W_ext by {energy_created:.3g} of the energy "
                f"that flowed (> {ENERGY_CREATED_LIMIT:g})")
    return None


def without_celerity(result: RuleResult) -> RuleResult:
    """A rule's result on a non-physical run: its fit (fronts, window) kept for the diagnostics, its
    celerity undefined with the reason NON_PHYSICAL; a result already undefined keeps its own reason."""
    if result.reason != "ok":
        return result
    return result.undefined(NON_PHYSICAL)


def _first_bad(t: np.ndarray, arrays: list[np.ndarray]) -> float:
    """First time (s) at which one of the arrays (first axis = time) holds inf or a NaN; inf if none."""
    bad = np.zeros(t.size, dtype=bool)
    for data in arrays:
        rows = ~np.isfinite(data)
        bad |= rows.reshape(t.size, -1).any(axis=1)
    return float(t[np.argmax(bad)]) if bad.any() else math.inf


def finite_part(run: RunData) -> RunData:
    """The run up to (excluding) the first time at which any interface field or global series is
    non-finite (T/N is NaN where N = 0 by definition: it does not count); the run itself when all
    is finite. InputError when nothing finite is left to measure."""
    if not run.non_finite:
        return run
    fields, series = run.interface, run.global_series
    names = [n for n in InterfaceFields.__dataclass_fields__ if n not in ("x", "t")]
    t_bad = _first_bad(fields.t, [getattr(fields, n) for n in names])
    others = [getattr(series, n) for n in GlobalSeries.__dataclass_fields__ if n not in ("t", "T_over_N")]
    ratio = series.T_over_N
    t_bad = min(t_bad, _first_bad(series.t, others + [np.where(np.isnan(ratio), 0.0, ratio)]))
    keep_out, keep_step = fields.t < t_bad, series.t < t_bad
    if not keep_out.any() or np.count_nonzero(keep_step) < 2:
        raise InputError(f"{run.path}: non-finite values from t = {t_bad:g} s leave nothing to "
                         f"measure ({', '.join(run.non_finite)})")
    interface = replace(fields, **{n: getattr(fields, n)[keep_out] for n in ("t", *names)})
    global_series = GlobalSeries(**{n: getattr(series, n)[keep_step]
                                    for n in GlobalSeries.__dataclass_fields__})
    return replace(run, interface=interface, global_series=global_series)
