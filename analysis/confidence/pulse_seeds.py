"""Major-pulse count per period lambda/H across seeds, and the T/N at which later drops start.

    python3 -m analysis pulse-seeds A.csv [B.csv ...] [--cell 0.2 1.5] -o DIR

reads ``all_metrics.csv`` tables (sweeps ``period_ensemble``, ``period``, ``table1_ensemble``, ``long``,
...), keeps the runs of one (nu, f) cell, each run (lambda/H, mesh, seed, run length) once, and per
(lambda/H, mesh): the seeds, the major-pulse counts (`pulse_count`, analysis/metrics/pulses.py) with their
histogram, the count the measured celerity predicts (`pulse_count_theory`: lambda over the spacing
2H sqrt(c_p^2/c_s^2 - 1)), how often the two agree, and the strength of the strongest non-major
pulse (`pulse_next_strength`: near the 0.5 cut the count is a close call). Later drops: over every run
with a drop after the first (`later_drops_start_T_over_N_median`; runs that stop after the first
opening have none), the T/N at which they start. Writes, together or not at all, ``pulse_seeds.csv``,
``.md``, ``.tex`` and ``pulse_seeds_summary.json``.
"""

from __future__ import annotations

import json
import math
import statistics
from collections import Counter
from typing import Any

from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_csv import csv_text
from analysis.core.table_render import Column
from analysis.tables.reference import cell_key

REQUIRED = ("nu", "f", "seed", "lambda_over_H", "elements_per_H", "pulse_count", "pulse_count_theory",
            "pulse_next_strength", "later_drops_start_T_over_N_median", "end_reason")
#: The paper's major-pulse counts per lambda/H (nu = 0.2, f = 1.5).
PAPER_COUNTS = {2.0: 1, 4.0: 2, 6.0: 3}
PAPER_LATER_DROP_T_OVER_N = 1.0
COLUMNS = ("lambda_over_H", "elements_per_H", "run_length", "seeds", "counts", "count_mode", "count_mean", "count_min",
           "count_max", "paper_count", "runs_at_paper_count", "theory_counts", "runs_count_equals_theory",
           "next_strength_median")


def _finite(v: Any) -> float | None:
    return float(v) if isinstance(v, float) and math.isfinite(v) else None


def unique_runs(tables: list[list[dict[str, Any]]], cell: tuple[float, float]) -> list[dict[str, Any]]:
    seen, out = set(), []
    for rows in tables:
        for row in rows:
            if cell_key(row["nu"], row["f"]) != cell:
                continue
            key = (row["lambda_over_H"], row["elements_per_H"], row["seed"], row["end_reason"])
            if key not in seen:
                seen.add(key)
                out.append(row)
    return out


def _length(run: dict[str, Any]) -> str:
    """'first event' for a run that stops after the first opening, else 'long'."""
    return "first event" if run["end_reason"] == "stop_after_opening" else "long"


def count_rows(runs: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """One row per (lambda/H, mesh, run length) over the runs that have a major-pulse count."""
    groups: dict[tuple, list[dict[str, Any]]] = {}
    for r in runs:
        if _finite(r["pulse_count"]) is not None:
            groups.setdefault((r["lambda_over_H"], r["elements_per_H"], _length(r)), []).append(r)
    out = []
    for (lam, n, length), members in sorted(groups.items()):
        counts = [int(r["pulse_count"]) for r in members]
        theory = [int(r["pulse_count_theory"]) if _finite(r["pulse_count_theory"]) is not None else None
                  for r in members]
        histogram = Counter(counts)
        paper = PAPER_COUNTS.get(lam)
        strengths = [s for s in (_finite(r["pulse_next_strength"]) for r in members) if s is not None]
        out.append({
            "lambda_over_H": lam, "elements_per_H": n, "run_length": length,
            "seeds": " ".join(f"{r['seed']:g}" for r in members),
            "counts": " ".join(str(c) for c in counts),
            "count_mode": max(histogram.items(), key=lambda item: (item[1], -item[0]))[0],
            "count_mean": statistics.fmean(counts), "count_min": min(counts), "count_max": max(counts),
            "paper_count": paper,
            "runs_at_paper_count": None if paper is None else sum(c == paper for c in counts),
            "n_runs": len(members),
            "theory_counts": " ".join("" if t is None else str(t) for t in theory),
            "runs_count_equals_theory": sum(c == t for c, t in zip(counts, theory)),
            "next_strength_median": statistics.median(strengths) if strengths else None,
        })
    return out


def later_drops(runs: list[dict[str, Any]]) -> dict[str, Any]:
    values = [(r, v) for r in runs if (v := _finite(r["later_drops_start_T_over_N_median"])) is not None]
    t = [v for _, v in values]
    return {"runs_with_later_drops": len(values), "runs": len(runs),
            "runs_stopped_after_opening": sum(r["end_reason"] == "stop_after_opening" for r in runs),
            "mean": statistics.fmean(t) if t else None, "min": min(t, default=None), "max": max(t, default=None),
            "paper": PAPER_LATER_DROP_T_OVER_N,
            "which": [{"lambda_over_H": r["lambda_over_H"], "elements_per_H": r["elements_per_H"],
                       "seed": r["seed"], "T_over_N": v} for r, v in values]}


def summarize(rows: list[dict[str, Any]], drops: dict[str, Any], cell: tuple[float, float]) -> dict[str, Any]:
    runs = sum(r["n_runs"] for r in rows)
    equal = sum(r["runs_count_equals_theory"] for r in rows)
    at_paper = [r for r in rows if r["paper_count"] is not None and r["run_length"] == "first event"]
    sentence = (f"Over {runs} runs the major-pulse count equals the count the measured celerity predicts "
                f"(spacing $2H\\sqrt{{c_p^2/c_s^2 - 1}}$) in {equal}, and the paper's count in "
                f"{sum(r['runs_at_paper_count'] for r in at_paper)} of the {sum(r['n_runs'] for r in at_paper)} "
                "runs at its periods that stop after the first event.")
    if drops["runs_with_later_drops"]:
        later = (f"Later drops start at $T/N$ = {drops['mean']:.2f} (range {drops['min']:.2f}--{drops['max']:.2f}) "
                 f"in the {drops['runs_with_later_drops']} runs that have one; the paper: "
                 f"$\\approx {drops['paper']:g}$.")
    else:
        later = "No run has a later drop."
    if drops["runs_stopped_after_opening"]:
        later += (f" {drops['runs_stopped_after_opening']} of the {drops['runs']} runs stop after the first "
                  "opening and cannot show one.")
    return {"nu": cell[0], "f": cell[1], "paper_counts": {f"{lam:g}": n for lam, n in PAPER_COUNTS.items()},
            "by_period": rows, "later_drops": drops, "runs": runs,
            "runs_count_equals_theory": equal, "count_sentence": sentence, "later_sentence": later}


def _or_dash(value, fmt="", dash="--"):
    return dash if value is None else format(value, fmt)


#: The columns of pulse_seeds.md and pulse_seeds.tex.
COLUMNS_SHOWN = (
    Column("lambda/H", lambda r: f"{r['lambda_over_H']:g}", r"$\lambda/H$", lambda r: f"{r['lambda_over_H']:g}"),
    Column("H/h", lambda r: f"{r['elements_per_H']:g}", "$H/h$",
           lambda r: f"{r['elements_per_H']:g}" + ("" if r["run_length"] == "first event" else " (long)")),
    Column("run", lambda r: f"{r['run_length']}"),
    Column("seeds", lambda r: f"{r['seeds']}"),
    Column("counts", lambda r: f"{r['counts']}", "counts over the seeds", lambda r: r["counts"], "l"),
    Column("mode", lambda r: f"{r['count_mode']}", "mode", lambda r: str(r["count_mode"])),
    Column("paper", lambda r: _or_dash(r["paper_count"], dash=""), "paper",
           lambda r: _or_dash(r["paper_count"])),
    Column("predicted", lambda r: f"{r['theory_counts']}", "predicted by $c_p$", lambda r: r["theory_counts"], "l"),
    Column("= predicted", lambda r: f"{r['runs_count_equals_theory']}/{r['n_runs']}", "count $=$ predicted",
           lambda r: f"{r['runs_count_equals_theory']}/{r['n_runs']}"),
    Column("next strength", lambda r: _or_dash(r["next_strength_median"], ".2f", ""), "next strength",
           lambda r: _or_dash(r["next_strength_median"], ".2f")),
)


def latex(rows: list[dict[str, Any]]) -> str:
    return table_render.latex(COLUMNS_SHOWN, rows, "pulse-seeds")


def markdown(rows, summary) -> str:
    text = summary["count_sentence"] + " " + summary["later_sentence"]
    return table_render.markdown(COLUMNS_SHOWN, rows, text.replace("$", "").replace("\\approx ", "~"))


def pulse_files(tables, cell) -> dict[str, str]:
    runs = unique_runs(tables, cell)
    if not runs:
        raise InputError(f"no run of the cell nu={cell[0]:g} f={cell[1]:g} in the tables")
    rows = count_rows(runs)
    summary = summarize(rows, later_drops(runs), cell)
    return {"pulse_seeds.csv": csv_text(COLUMNS + ("n_runs",), rows), "pulse_seeds.md": markdown(rows, summary),
            "pulse_seeds.tex": latex(rows), "pulse_seeds_summary.json": json.dumps(summary, indent=2) + "\n"}
