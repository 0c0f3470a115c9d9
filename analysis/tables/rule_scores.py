"""Table 1 scored under every celerity rule (docs/measurement-rule.md), side by side.

For each rule of `analysis.fronts.rules.RULES` and each published cell: the run's celerity under
that rule (`celerity_rule_<name>` of its metrics file), its sign, its regime (from the run's own
c_s and c_l) and its deviation (c - published) / |published|. A run counts under no rule when it
is not an opening run (`opening` false: the paper lists only runs "which result in opening waves")
or is flagged (`non_physical`, `sampling_too_coarse`, or not `complete`): its cell is *excluded*,
i.e. not reproduced, whatever its number. A cell is *reproduced* under a rule when it is measured
(not excluded, a celerity under the rule) in the right sign, in the right regime and within the
tolerance.
"""

from __future__ import annotations

import math
from typing import Any

from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_render import Column
from analysis.fronts.rules import RULES
from analysis.metrics.regime import regime
from analysis.tables.reference import ReferenceCell, metrics_by_cell

#: Columns of the score table (one row per rule).
SCORE_COLUMNS = ("rule", "default", "cells_published", "cells_measured", "cells_excluded",
                 "sign_matches", "regime_matches", "within_tolerance", "reproduced",
                 "median_abs_deviation", "tolerance")


def exclusion(metrics: dict[str, Any]) -> str | None:
    """Why a run counts under no rule ("not_opening", "non_physical", "sampling_too_coarse",
    "incomplete", ";"-joined), or None when it counts."""
    reasons = [name for name, bad in (
        ("not_opening", not metrics.get("opening")),
        ("non_physical", bool(metrics.get("non_physical"))),
        ("sampling_too_coarse", bool(metrics.get("sampling_too_coarse"))),
        ("incomplete", not metrics.get("complete")),
    ) if bad]
    return ";".join(reasons) or None


def _by_cell(metrics: list[dict[str, Any]]) -> dict[tuple[float, float], dict[str, Any]]:
    """Metrics keyed by (nu, f); InputError for two files on one cell or a file without the rules."""
    for m in metrics:
        missing = [f"celerity_rule_{name}" for name in RULES if f"celerity_rule_{name}" not in m]
        if missing or "celerity_rule_default" not in m:
            raise InputError(f"{m.get('metrics_file')}: metrics lack the measurement rules "
                             f"({', '.join(missing) or 'celerity_rule_default'}); measure the run "
                             "again with this analysis (python3 -m analysis measure)")
    return metrics_by_cell(metrics)


def cell_scores(metrics: list[dict[str, Any]], reference: list[ReferenceCell],
                tolerance: float) -> list[dict[str, Any]]:
    """One row per (rule, published cell): rule, nu, f, published, celerity (None when not
    measured), deviation_rel, sign_match, regime_match, within_tol, reproduced, excluded (the
    exclusion reason, "missing" without a metrics file, else None), reason (the rule's)."""
    by_cell = _by_cell(metrics)
    rows = []
    for rule in RULES:
        for cell in reference:
            m = by_cell.get(cell.key)
            row: dict[str, Any] = dict(rule=rule, nu=cell.nu, f=cell.f, published=cell.celerity,
                                       celerity=None, deviation_rel=None, sign_match=None,
                                       regime_match=None, within_tol=None, reproduced=False,
                                       excluded="missing" if m is None else exclusion(m),
                                       reason=None if m is None else m.get(f"celerity_rule_{rule}_reason"))
            c = None if m is None else m.get(f"celerity_rule_{rule}")
            if row["excluded"] is None and c is not None and math.isfinite(c):
                deviation = (c - cell.celerity) / abs(cell.celerity)
                sign = (c > 0) == (cell.celerity > 0)
                same_regime = regime(c, m["c_s"], m["c_l"]) == cell.regime
                within = abs(deviation) <= tolerance
                row.update(celerity=c, deviation_rel=deviation, sign_match=sign,
                           regime_match=same_regime, within_tol=within,
                           reproduced=sign and same_regime and within)
            rows.append(row)
    return rows


def rule_scores(metrics: list[dict[str, Any]], reference: list[ReferenceCell],
                tolerance: float) -> list[dict[str, Any]]:
    """One row per rule (SCORE_COLUMNS): counts over the published cells and the median
    |deviation| of the measured ones (None when none is measured)."""
    if not tolerance > 0:
        raise InputError(f"--tolerance {tolerance} must be > 0")
    cells = cell_scores(metrics, reference, tolerance)
    defaults = {m["celerity_rule_default"] for m in metrics}
    scores = []
    for rule in RULES:
        rows = [r for r in cells if r["rule"] == rule]
        measured = [r for r in rows if r["celerity"] is not None]
        deviations = sorted(abs(r["deviation_rel"]) for r in measured)
        median = (0.5 * (deviations[(len(deviations) - 1) // 2] + deviations[len(deviations) // 2])
                  if deviations else None)
        scores.append(dict(
            rule=rule, default=rule in defaults, cells_published=len(rows),
            cells_measured=len(measured),
            cells_excluded=sum(r["excluded"] is not None for r in rows),
            sign_matches=sum(bool(r["sign_match"]) for r in measured),
            regime_matches=sum(bool(r["regime_match"]) for r in measured),
            within_tolerance=sum(bool(r["within_tol"]) for r in measured),
            reproduced=sum(r["reproduced"] for r in measured),
            median_abs_deviation=median, tolerance=tolerance))
    return scores


def scores_text(scores: list[dict[str, Any]]) -> str:
    """The score table as aligned text (one line per rule, * = the default rule)."""
    header = (f"{'rule':28s} {'published':>9s} {'measured':>8s} {'excluded':>8s} {'sign':>5s} "
              f"{'regime':>6s} {'within':>6s} {'reproduced':>10s} {'median|dev|':>11s}")
    lines = [header]
    for s in scores:
        median = "-" if s["median_abs_deviation"] is None else f"{100 * s['median_abs_deviation']:.1f} %"
        lines.append(f"{s['rule'] + (' *' if s['default'] else ''):28s} {s['cells_published']:9d} "
                     f"{s['cells_measured']:8d} {s['cells_excluded']:8d} {s['sign_matches']:5d} "
                     f"{s['regime_matches']:6d} {s['within_tolerance']:6d} {s['reproduced']:10d} "
                     f"{median:>11s}")
    tolerance = scores[0]["tolerance"] if scores else math.nan
    lines.append(f"(* default rule; within = |deviation| <= {tolerance:g}; reproduced = right sign, "
                 "regime and within; excluded = no metrics, not opening, or flagged)")
    return "\n".join(lines) + "\n"


def scores_csv(scores: list[dict[str, Any]]) -> str:
    """The score table as CSV (SCORE_COLUMNS; booleans true/false, None empty)."""
    def cell(value: Any) -> str:
        if value is None:
            return ""
        if isinstance(value, bool):
            return "true" if value else "false"
        if isinstance(value, float):
            return format(value, ".6g")
        return str(value)

    lines = [",".join(SCORE_COLUMNS)]
    lines += [",".join(cell(s[c]) for c in SCORE_COLUMNS) for s in scores]
    return "\n".join(lines) + "\n"


#: The files `score-rules -o DIR` writes, together or not at all.
SCORE_FILES = ("rule_scores.csv", "rule_scores.md", "rule_scores.tex")


def _rule_label(score: dict[str, Any]) -> str:
    return score["rule"] + (" (default)" if score["default"] else "")


def _percent(value: float | None) -> str:
    return "--" if value is None else f"{100 * value:.1f}"


def columns(scores: list[dict[str, Any]]) -> list[Column]:
    """The columns of the score table (one row per rule, the default rule marked)."""
    tolerance = scores[0]["tolerance"] if scores else math.nan
    published = scores[0]["cells_published"] if scores else 0

    def count(key: str):
        return lambda s: str(s[key])

    return [
        Column("rule", _rule_label, f"rule (of {published} published cells)",
               lambda s: r"\texttt{" + s["rule"].replace("_", r"\_") + "}" + (" (default)" if s["default"] else ""), "l"),
        Column("published", count("cells_published")),
        Column("measured", count("cells_measured"), "measured", count("cells_measured")),
        Column("excluded", count("cells_excluded"), "excluded", count("cells_excluded")),
        Column("right sign", count("sign_matches"), "sign", count("sign_matches")),
        Column("right regime", count("regime_matches"), "regime", count("regime_matches")),
        Column(f"within {100 * tolerance:g} %", count("within_tolerance"), f"within {100 * tolerance:g}\\,\\%",
               count("within_tolerance")),
        Column("reproduced", count("reproduced"), "reproduced", count("reproduced")),
        Column("median abs. deviation (%)", lambda s: _percent(s["median_abs_deviation"]),
               r"median $|$dev.$|$ (\%)", lambda s: _percent(s["median_abs_deviation"])),
    ]


def scores_markdown(scores: list[dict[str, Any]]) -> str:
    """The score table as Markdown."""
    return table_render.markdown(columns(scores), scores, (
        "Reproduced = measured in the right sign and regime and within the tolerance; excluded = "
        "no metrics, not an opening run, or flagged (docs/measurement-rule.md, analysis/README.md)."), aligned=True)


def scores_latex(scores: list[dict[str, Any]]) -> str:
    """The score table as a booktabs tabular."""
    return table_render.latex(columns(scores), scores, "score-rules -o DIR")


def score_files(scores: list[dict[str, Any]]) -> dict[str, str]:
    """Every output text of `score-rules -o DIR` by file name (SCORE_FILES)."""
    return dict(zip(SCORE_FILES, (scores_csv(scores), scores_markdown(scores), scores_latex(scores))))
