"""Regime of a slip front and the category of a run for the phase diagram (paper Fig. 4a).

Regime from |c_p|: subsonic (|c_p| < c_s), intersonic (c_s <= |c_p| <= c_l), supersonic
(|c_p| > c_l). The category's front is the opening pulse: direction and regime of a run that
opens come from `celerity`, the default measurement rule `opening_pulse` (the major slip pulse
that opens, docs/measurement-rule.md), never from another front of the run. Categories, from
what a run shows:

- ``no_slip``: the interface never slips (above the threshold);
- ``uniform_slip``: it slips, never in localized pulses, and never opens;
- ``no_opening``: slip fronts (the slipping set has edges; in practice the localization rule
  finds a persistent major front), no opening (the paper's open circles); such a run has no
  `celerity` (the opening pulse is undefined), its fronts are in ``celerity_rule_localization``;
- ``intersonic_opening``: opening, front intersonic in the sliding direction (+x) (squares);
- ``intersonic_opening_inversion``: the same with T/N < 0 at some time (double squares);
- ``supersonic_backward_opening``: opening, front supersonic against the sliding direction
  (diamonds; inversion is reported separately);
- the honest others: ``supersonic_forward_opening`` (e.g. the paper's nu = 0, f = 2),
  ``intersonic_backward_opening``, ``subsonic_forward_opening``, ``subsonic_backward_opening``,
  and ``opening_without_front`` (opens, but without an opening pulse: no major slip front whose
  slipping run opens, hence no `celerity`);
- ``non_physical``: the run reached a state outside the model (non-finite values, an opening
  larger than H; `analysis.metrics.validity`), whatever it shows otherwise;
- ``sampling_too_coarse``: the interface output is too sparse to see fronts (fewer than
  `validity.MIN_FRAMES_PER_ROUND_TRIP` frames per shear round trip 2H/c_s): "no slip" or "no
  opening" from such a run would mean nothing; or too sparse for its opening pulse, which moves
  more than half a pulse spacing per frame (`celerity_reason` ``beyond_sampling_limit``,
  `analysis.fronts.sampling_limit`).

Neither of the last two enters Table 1.
"""

from __future__ import annotations

import math

CATEGORIES = (
    "no_slip", "uniform_slip", "no_opening", "intersonic_opening", "intersonic_opening_inversion",
    "supersonic_backward_opening", "supersonic_forward_opening", "intersonic_backward_opening",
    "subsonic_forward_opening", "subsonic_backward_opening", "opening_without_front",
    "non_physical", "sampling_too_coarse",
)

#: How a category reads in tables, figures and reports (the key stays in metrics.json). `no_slip`
#: means the slip velocity never exceeds the slip threshold: the interface slides uniformly with
#: the top (e.g. nu = 0.3, f = 0.5), it does not stick; `uniform_slip` slips above the threshold
#: without ever localizing.
CATEGORY_LABELS = {
    "no_slip": "uniform sliding",
    "uniform_slip": "uniform slip, no front",
    "intersonic_opening_inversion": "intersonic opening, inversion",
}


def category_label(key: str) -> str:
    """A category key as text: CATEGORY_LABELS, else the key with spaces for underscores."""
    return CATEGORY_LABELS.get(key, str(key).replace("_", " "))


#: How an end reason reads in the tables.
END_REASON_LABELS = {
    "stop_after_opening": "after opening",
    "t_end": "end time",
    "contact_not_converged": "contact not converged",
}


def outcome_label(value) -> str:
    """A category, regime or end reason as text: END_REASON_LABELS, else category_label."""
    return END_REASON_LABELS.get(str(value)) or category_label(str(value))


def regime(celerity: float, c_s: float, c_l: float) -> str | None:
    """'subsonic', 'intersonic' or 'supersonic' from |celerity| (m/s); None if nan."""
    if celerity is None or not math.isfinite(celerity):
        return None
    speed = abs(celerity)
    if speed < c_s:
        return "subsonic"
    if speed <= c_l:
        return "intersonic"
    return "supersonic"


def below_sqrt2_cs(celerity: float, c_s: float) -> bool | None:
    """|celerity| < sqrt(2) c_s (the speed range favourable to opening); None if nan."""
    if celerity is None or not math.isfinite(celerity):
        return None
    return abs(celerity) < math.sqrt(2.0) * c_s


def intersonic_below_sqrt2_cs(celerity: float, c_s: float) -> bool | None:
    """c_s <= |celerity| < sqrt(2) c_s: intersonic and in the range favourable to opening; None if
    nan."""
    if celerity is None or not math.isfinite(celerity):
        return None
    return c_s <= abs(celerity) < math.sqrt(2.0) * c_s


def category(*, slipped: bool, has_front: bool, opened: bool, celerity: float, c_s: float,
             c_l: float, inversion: bool, non_physical: bool = False,
             sampling_too_coarse: bool = False) -> str:
    """Phase-diagram category (see the module docstring).

    Parameters
    ----------
    slipped
        The slip velocity exceeded the threshold somewhere at some time.
    has_front
        The slipping set had edges (was localized) at some time.
    opened
        The opening exceeded its threshold.
    celerity
        Signed celerity of the opening pulse (m/s; the metrics' `celerity`), nan if undefined.
    c_s, c_l
        Wave speeds (m/s).
    inversion
        min T/N < 0.
    non_physical, sampling_too_coarse
        The run left the model / its output cannot show fronts: these win, in this order.
    """
    if non_physical:
        return "non_physical"
    if sampling_too_coarse:
        return "sampling_too_coarse"
    if not opened:
        if not slipped:
            return "no_slip"
        return "no_opening" if has_front else "uniform_slip"
    speed_regime = regime(celerity, c_s, c_l)
    if speed_regime is None:
        return "opening_without_front"
    direction = "forward" if celerity > 0 else "backward"
    if speed_regime == "intersonic" and direction == "forward":
        return "intersonic_opening_inversion" if inversion else "intersonic_opening"
    return f"{speed_regime}_{direction}_opening"
