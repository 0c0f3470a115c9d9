"""Many metrics files -> the regenerated Table 1 beside the published one, and a table of all metrics.

Outputs (all written together or not at all):

- ``table1.csv``: one row per published cell, columns ``TABLE1_COLUMNS``. celerity and everything
  derived from it are empty when no metrics file is given for the cell or its celerity is undefined.
  deviation_rel = (celerity - published) / |published|; within_tol = |deviation_rel| <= tolerance;
  sign_match, regime_match compare with the published celerity and its regime (from c_s, c_l of
  Table 1's material). published_category is the category the published cell implies (every cell of
  the paper's Table 1 is an opening wave: ``<regime>_<direction>_opening``, ``intersonic_opening``
  for a forward intersonic one, inversion not distinguished); category_match compares the run's
  category with it (``intersonic_opening_inversion`` counts as ``intersonic_opening``); reproduced =
  within_tol and sign_match and regime_match and category_match: a cell whose run shows another
  outcome (no opening, no front) is never counted as reproduced, however close its celerity.
  celerity_quality and celerity_window_sensitivity are the run's (its c_p's uncertainty). end_reason is filled only for a run that did not complete (e.g.
  ``contact_not_converged``): such a row is shown, and flagged, never passed off as a complete run.
- ``table1.md``; ``table1.tex``: Table 1 as the report shows it (``analysis.tables.table1_tex``, the
  one LaTeX renderer of it; paper/make_table1.py adds the sign flips at other meshes).
- ``summary.json``: cells_total, cells_compared, cells_missing, within_tolerance, sign_matches,
  regime_matches, category_matches, reproduced, median_abs_deviation, max_abs_deviation, tolerance,
  missing_cells, category_mismatches (the compared cells whose category differs, "nu=N f=F").
- ``all_metrics.csv``: one row per metrics file, every scalar key as `measure` wrote it (a run's
  derived quantities, e.g. ``first_drop_duration`` or ``inside_flutter_wedge``, are metrics of
  ``analysis.metrics.measure``: an aggregate only aggregates), so that ``paper/`` and ``figures/``
  only select and format.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Iterable

from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.json_file import read_json_object
from analysis.core.table_csv import csv_text, format_cell, parse_table
from analysis.core.table_render import Column
from analysis.tables import table1_tex
from analysis.tables.reference import ReferenceCell, metrics_by_cell

TABLE1_COLUMNS = ("nu", "f", "celerity", "published", "deviation_rel", "regime", "published_regime",
                  "sign_match", "regime_match", "within_tol", "category", "opening", "inversion",
                  "min_T_over_N", "published_category", "category_match", "reproduced",
                  "celerity_quality", "celerity_window_sensitivity", "end_reason")
DEFAULT_TOLERANCE = 0.05


# --------------------------------------------------------------------------------------------------
# Inputs


def _number(value: Any) -> float:
    """A metrics value as float; None -> nan."""
    if value is None:
        return math.nan
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(value)
    return float(value)


def load_metrics(path: str | Path) -> dict[str, Any]:
    """One metrics.json; InputError unless it is a JSON object with numeric nu, f and a celerity key
    (number or null)."""
    metrics = read_json_object(path)
    missing = [key for key in ("nu", "f", "celerity") if key not in metrics]
    if missing:
        raise InputError(f"{path}: metrics lack key(s) {', '.join(missing)}")
    try:
        nu, f = _number(metrics["nu"]), _number(metrics["f"])
        _number(metrics["celerity"])
    except TypeError as err:
        raise InputError(f"{path}: nu, f and celerity must be numbers (celerity may be null), "
                         f"got {err.args[0]!r}") from None
    if not (math.isfinite(nu) and math.isfinite(f)):
        raise InputError(f"{path}: nu and f must be finite")
    metrics.setdefault("metrics_file", str(path))
    return metrics


def parse_selection(conditions: Iterable[str]) -> list[tuple[str, str]]:
    """'key=value' strings -> pairs; InputError for a malformed one."""
    pairs = []
    for condition in conditions:
        key, sep, value = condition.partition("=")
        if not sep or not key.strip():
            raise InputError(f"--select expects key=value, got '{condition}'")
        pairs.append((key.strip(), value.strip()))
    return pairs


def _matches(value: Any, wanted: str) -> bool:
    if isinstance(value, bool):
        return str(value).lower() == wanted.lower()
    if isinstance(value, (int, float)):
        try:
            return math.isclose(float(value), float(wanted), rel_tol=1e-9, abs_tol=1e-12)
        except ValueError:
            return False
    return str(value) == wanted


def select(metrics: list[dict[str, Any]], conditions: list[tuple[str, str]]) -> list[dict[str, Any]]:
    """Metrics whose every `key` equals `value` (numbers compared as numbers)."""
    return [m for m in metrics if all(k in m and _matches(m[k], w) for k, w in conditions)]


# --------------------------------------------------------------------------------------------------
# Table 1


def published_category(cell: ReferenceCell) -> str:
    """The category a published cell implies: every cell of the paper's Table 1 is an opening wave
    (the paper's Fig. 4a), in the direction of its celerity's sign and its regime."""
    direction = "forward" if cell.celerity > 0 else "backward"
    if cell.regime == "intersonic" and direction == "forward":
        return "intersonic_opening"
    return f"{cell.regime}_{direction}_opening"


def category_matches(category: Any, published: str) -> bool:
    """The run's category is the published one (with or without inversion of T/N)."""
    return isinstance(category, str) and category.removesuffix("_inversion") == published


def incomplete_reason(metrics: dict[str, Any]) -> str | None:
    """The end_reason of a run that did not complete (`complete` false), else None."""
    if metrics.get("complete", True) is not False:
        return None
    return str(metrics.get("end_reason") or "incomplete")


def table1_rows(metrics: list[dict[str, Any]], reference: list[ReferenceCell],
                tolerance: float = DEFAULT_TOLERANCE) -> list[dict[str, Any]]:
    """One row per published cell (reference order), values as Python objects (None = empty).

    InputError when two metrics files fall on the same published cell (select one with --select).
    """
    by_cell = metrics_by_cell(metrics)
    rows = []
    for cell in reference:
        m = by_cell.get(cell.key)
        row: dict[str, Any] = {column: None for column in TABLE1_COLUMNS}
        row.update(nu=cell.nu, f=cell.f, published=cell.celerity, published_regime=cell.regime,
                   published_category=published_category(cell))
        if m is not None:
            row.update(category=m.get("category"), opening=m.get("opening"),
                       inversion=m.get("inversion"), min_T_over_N=m.get("min_T_over_N"),
                       regime=m.get("regime"), end_reason=incomplete_reason(m),
                       category_match=category_matches(m.get("category"), row["published_category"]),
                       celerity_quality=m.get("celerity_quality"),
                       celerity_window_sensitivity=m.get("celerity_window_sensitivity"))
            c = _number(m["celerity"])
            if math.isfinite(c):
                deviation = (c - cell.celerity) / abs(cell.celerity)
                row.update(celerity=c, deviation_rel=deviation,
                           sign_match=(c > 0) == (cell.celerity > 0),
                           regime_match=m.get("regime") == cell.regime,
                           within_tol=abs(deviation) <= tolerance)
                row["reproduced"] = bool(row["within_tol"] and row["sign_match"] and row["regime_match"]
                                         and row["category_match"])
        rows.append(row)
    return rows


def summarize(rows: list[dict[str, Any]], tolerance: float) -> dict[str, Any]:
    """The summary of table1_rows (see the module docstring)."""
    compared = [r for r in rows if r["celerity"] is not None]
    deviations = sorted(abs(r["deviation_rel"]) for r in compared)
    median = (math.nan if not deviations else
              0.5 * (deviations[(len(deviations) - 1) // 2] + deviations[len(deviations) // 2]))
    return {
        "cells_total": len(rows),
        "cells_compared": len(compared),
        "cells_missing": len(rows) - len(compared),
        "within_tolerance": sum(bool(r["within_tol"]) for r in compared),
        "sign_matches": sum(bool(r["sign_match"]) for r in compared),
        "regime_matches": sum(bool(r["regime_match"]) for r in compared),
        "category_matches": sum(bool(r["category_match"]) for r in compared),
        "reproduced": sum(bool(r["reproduced"]) for r in compared),
        "median_abs_deviation": median if deviations else None,
        "max_abs_deviation": deviations[-1] if deviations else None,
        "tolerance": tolerance,
        "missing_cells": [f"nu={r['nu']:g} f={r['f']:g}" for r in rows if r["celerity"] is None],
        "category_mismatches": [f"nu={r['nu']:g} f={r['f']:g}" for r in compared if not r["category_match"]],
    }


def summary_line(summary: dict[str, Any]) -> str:
    """One line for the terminal and the log."""
    n = summary["cells_compared"]
    median = summary["median_abs_deviation"]
    return (f"table1: {n}/{summary['cells_total']} cells measured, {summary['within_tolerance']}/{n} "
            f"within {100 * summary['tolerance']:g}%, signs {summary['sign_matches']}/{n}, "
            f"regimes {summary['regime_matches']}/{n}, categories {summary['category_matches']}/{n}, "
            f"reproduced {summary['reproduced']}/{n}, median |deviation| "
            + ("n/a" if median is None else f"{100 * median:.1f}%"))


# --------------------------------------------------------------------------------------------------
# Formatting


def table1csv_text(rows: list[dict[str, Any]]) -> str:
    return csv_text(TABLE1_COLUMNS, rows)


def _regenerated_category(r: dict[str, Any]) -> str:
    return ((r["category"] or "") + (f" (run ended: {r['end_reason']})" if r["end_reason"] else "")
            + (f" (published: {r['published_category']})" if r["category_match"] is False else ""))


#: The columns of table1.md.
TABLE1_MD = (
    Column("nu", lambda r: f"{r['nu']:g}"), Column("f", lambda r: f"{r['f']:.2f}"),
    Column("published (m/s)", lambda r: f"{r['published']:.3f}"),
    Column("regenerated (m/s)", lambda r: "missing" if r["celerity"] is None else f"{r['celerity']:.3f}"),
    Column("deviation", lambda r: "" if r["celerity"] is None else
           f"{100 * r['deviation_rel']:+.1f}%" + ("" if r["sign_match"] else " (sign)")),
    Column("regime (pub.)", lambda r: r["published_regime"] or ""), Column("regime", lambda r: r["regime"] or ""),
    Column("category", _regenerated_category), Column("min T/N", lambda r: format_cell(r["min_T_over_N"], ".3f")),
)


def table1_markdown(rows: list[dict[str, Any]], summary: dict[str, Any]) -> str:
    return table_render.markdown(TABLE1_MD, rows, summary_line(summary))


def all_metricscsv_text(metrics: list[dict[str, Any]]) -> str:
    """One row per metrics dict, every scalar key (first-seen order, metrics_file first)."""
    columns = ["metrics_file"]
    for m in metrics:
        for key, value in m.items():
            if key not in columns and (value is None or isinstance(value, (bool, int, float, str))):
                columns.append(key)
    return csv_text(columns, metrics, fmt=".10g")


def aggregate(metrics: list[dict[str, Any]], table_metrics: list[dict[str, Any]],
              reference: list[ReferenceCell], tolerance: float) -> tuple[dict[str, str], dict[str, Any]]:
    """All output texts by file name, and the summary.

    Parameters
    ----------
    metrics
        Every metrics dict given (all_metrics.csv).
    table_metrics
        Those that enter Table 1 (after --select).
    reference
        The published cells.
    tolerance
        Relative tolerance of within_tol.
    """
    if not tolerance > 0:
        raise InputError(f"tolerance must be > 0 (got {tolerance})")
    rows = table1_rows(table_metrics, reference, tolerance)
    summary = summarize(rows, tolerance)
    files = {
        "table1.csv": table1csv_text(rows),
        "table1.md": table1_markdown(rows, summary),
        # The one Table-1 LaTeX (analysis/tables/table1_tex.py), from the table as readers see it.
        "table1.tex": table1_tex.render(parse_table(table1csv_text(rows))),
        "summary.json": json.dumps(summary, indent=2) + "\n",
        "all_metrics.csv": all_metricscsv_text(metrics),
    }
    return files, summary
