"""Ensembles: runs that differ only by the perturbation seed, summarized per published cell.

    python3 -m analysis ensemble all_metrics.csv --reference table1_celerity.csv -o DIR

reads the aggregate's ``all_metrics.csv`` of a sweep (one row per run) and writes, together or not
at all:

- ``ensemble.csv``: one row per cell (runs equal in every ``CELL_KEYS`` column), ``ENSEMBLE_COLUMNS``:
  the celerity's mean, sample standard deviation, min and max over the runs with a celerity
  (``celerity_reason`` ok: the default rule found the major pulse that opens, its persistent
  front; a run that does not open has none) in the cell's direction (``cell_direction``: one wave
  per cell, docs/measurement-rule.md), ``n_front`` of ``n_runs``, ``n_opposite`` the fronts
  running the other way (another wave, not averaged; the mean is within tolerance only when
  ``n_front`` > ``n_opposite``), the majority
  category and ``category_agreement`` (fraction of the runs in it), the run of the default seed
  (``celerity_seed1``), and against the published value: ``deviation_mean_rel`` =
  (mean - published) / |published|, ``deviation_seed1_rel``, ``spread_rel`` = std / |published|,
  ``within_tol_mean``, ``within_tol_seed1`` and the cell's ``group`` (``SYSTEMATIC_GROUPS``);
- ``ensemble.md``, ``ensemble.tex`` (booktabs), and ``ensemble_summary.json``: per group the count
  of cells, the mean and range of ``deviation_mean_rel`` and the median ``spread_rel``; the counts
  of cells within tolerance for the default seed and for the ensemble mean.

Cells that are not published keep empty published-value columns and the group ``unpublished``.
"""

from __future__ import annotations

import json
import math
import statistics
from collections import Counter
from typing import Any

from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_render import Column
from analysis.tables.reference import ReferenceCell, cell_key

#: Columns that define a cell: every run parameter but the seed.
CELL_KEYS = ("nu", "f", "V0_over_cs", "lambda_over_H", "elements_per_H", "rho", "integration",
             "dt_times_cs", "contact_weighting", "regularization", "pc_length", "pc_velocity")
DEFAULT_SEED = 1
ENSEMBLE_COLUMNS = ("nu", "f", "elements_per_H", "group", "n_runs", "n_front", "n_opposite", "celerity_mean",
                    "celerity_std", "celerity_min", "celerity_max", "celerity_seed1",
                    "majority_category", "category_agreement", "published", "deviation_mean_rel",
                    "deviation_seed1_rel", "spread_rel", "within_tol_mean", "within_tol_seed1")
REQUIRED = ("nu", "f", "seed", "celerity", "celerity_reason", "category")

#: The systematic groups of the campaign's deviations (issue 14), first match wins: name, test on
#: a published cell (nu, f, published celerity).
SYSTEMATIC_GROUPS = (
    ("supersonic backward", lambda nu, f, c: c < 0),
    ("nu 0-0.1, f 1.1-1.2", lambda nu, f, c: nu <= 0.1 + 1e-9 and 1.1 - 1e-9 <= f <= 1.2 + 1e-9),
    ("nu 0.1-0.2, f >= 1.5", lambda nu, f, c: 0.1 - 1e-9 <= nu <= 0.2 + 1e-9 and f >= 1.5 - 1e-9),
    ("the rest", lambda nu, f, c: True),
)


def group_of(cell: ReferenceCell | None) -> str:
    """The systematic group of a published cell; 'unpublished' for None."""
    if cell is None:
        return "unpublished"
    return next(name for name, test in SYSTEMATIC_GROUPS if test(cell.nu, cell.f, cell.celerity))


def _key_value(value: Any) -> Any:
    return round(value, 9) if isinstance(value, float) and math.isfinite(value) else repr(value)


def group_runs(rows: list[dict[str, Any]]) -> list[list[dict[str, Any]]]:
    """Runs grouped by cell (equal CELL_KEYS present in the rows), in first-seen order; InputError
    when a seed appears twice in a cell (two sweeps' copies of one run: pass one sweep)."""
    groups: dict[tuple, list[dict[str, Any]]] = {}
    for row in rows:
        key = tuple(_key_value(row.get(k)) for k in CELL_KEYS)
        groups.setdefault(key, []).append(row)
    for runs in groups.values():
        seeds = Counter(r["seed"] for r in runs)
        repeated = [s for s, n in seeds.items() if n > 1]
        if repeated:
            raise InputError(f"cell nu={runs[0]['nu']:g} f={runs[0]['f']:g}: seed {repeated[0]:g} "
                             f"appears {seeds[repeated[0]]} times")
    return list(groups.values())


def _has_front(row: dict[str, Any]) -> bool:
    c = row["celerity"]
    return row["celerity_reason"] == "ok" and isinstance(c, float) and math.isfinite(c)


def cell_direction(fronts: list[float], published: ReferenceCell | None) -> float:
    """+1 or -1: the published direction, else the direction of most fronts (a tie: the first
    front's, runs being in seed order). One wave per cell (docs/measurement-rule.md)."""
    if published is not None:
        return math.copysign(1.0, published.celerity)
    forward = sum(c > 0 for c in fronts)
    if 2 * forward != len(fronts):
        return 1.0 if 2 * forward > len(fronts) else -1.0
    return math.copysign(1.0, fronts[0])


def cell_statistics(runs: list[dict[str, Any]], published: ReferenceCell | None,
                    tolerance: float) -> dict[str, Any]:
    """One ENSEMBLE_COLUMNS row for the runs of one cell (None where undefined)."""
    runs = sorted(runs, key=lambda r: r["seed"])
    all_fronts = [r["celerity"] for r in runs if _has_front(r)]
    direction = cell_direction(all_fronts, published) if all_fronts else 1.0
    fronts = [c for c in all_fronts if c * direction > 0]
    categories = Counter(r["category"] for r in runs)
    majority, count = max(categories.items(), key=lambda item: (item[1], str(item[0])))
    seed1 = [r for r in runs if r["seed"] == DEFAULT_SEED]
    c_seed1 = seed1[0]["celerity"] if seed1 and _has_front(seed1[0]) else None
    first = runs[0]
    row: dict[str, Any] = {column: None for column in ENSEMBLE_COLUMNS}
    row.update(nu=first["nu"], f=first["f"], elements_per_H=first.get("elements_per_H"),
               group=group_of(published), n_runs=len(runs), n_front=len(fronts),
               n_opposite=len(all_fronts) - len(fronts),
               celerity_seed1=c_seed1, majority_category=majority,
               category_agreement=count / len(runs))
    if fronts:
        row.update(celerity_mean=statistics.fmean(fronts), celerity_min=min(fronts),
                   celerity_max=max(fronts),
                   celerity_std=statistics.stdev(fronts) if len(fronts) > 1 else None)
    if published is not None:
        scale = abs(published.celerity)
        row["published"] = published.celerity
        if row["celerity_mean"] is not None:
            row["deviation_mean_rel"] = (row["celerity_mean"] - published.celerity) / scale
            # Most seeds producing the other wave is a category mismatch, never within.
            row["within_tol_mean"] = (abs(row["deviation_mean_rel"]) <= tolerance
                                      and row["n_front"] > row["n_opposite"])
        if c_seed1 is not None:
            row["deviation_seed1_rel"] = (c_seed1 - published.celerity) / scale
            row["within_tol_seed1"] = abs(row["deviation_seed1_rel"]) <= tolerance
        if row["celerity_std"] is not None:
            row["spread_rel"] = row["celerity_std"] / scale
    return row


def ensemble_rows(rows: list[dict[str, Any]], reference: list[ReferenceCell],
                  tolerance: float) -> list[dict[str, Any]]:
    """One row per cell: published cells in reference order first, then the others."""
    if not tolerance > 0:
        raise InputError(f"tolerance must be > 0 (got {tolerance})")
    published = {cell.key: cell for cell in reference}
    order = {cell.key: i for i, cell in enumerate(reference)}
    out = [cell_statistics(runs, published.get(cell_key(runs[0]["nu"], runs[0]["f"])), tolerance)
           for runs in group_runs(rows)]
    return sorted(out, key=lambda r: (order.get(cell_key(r["nu"], r["f"]), len(order)),
                                      r["nu"], r["f"], str(r["elements_per_H"])))


def _median(values: list[float]) -> float | None:
    return statistics.median(values) if values else None


def summarize(rows: list[dict[str, Any]], tolerance: float) -> dict[str, Any]:
    """Per systematic group and overall: counts within tolerance, mean deviation, spread."""
    published = [r for r in rows if r["published"] is not None]
    groups = {}
    for name, _ in SYSTEMATIC_GROUPS:
        members = [r for r in published if r["group"] == name]
        deviations = [r["deviation_mean_rel"] for r in members if r["deviation_mean_rel"] is not None]
        seed1 = [r["deviation_seed1_rel"] for r in members if r["deviation_seed1_rel"] is not None]
        groups[name] = {
            "cells": len(members),
            "cells_with_mean": len(deviations),
            "deviation_mean_rel_mean": statistics.fmean(deviations) if deviations else None,
            "deviation_mean_rel_min": min(deviations, default=None),
            "deviation_mean_rel_max": max(deviations, default=None),
            "deviation_seed1_rel_mean": statistics.fmean(seed1) if seed1 else None,
            "spread_rel_median": _median([r["spread_rel"] for r in members if r["spread_rel"] is not None]),
            "within_tol_seed1": sum(bool(r["within_tol_seed1"]) for r in members),
            "within_tol_mean": sum(bool(r["within_tol_mean"]) for r in members),
        }
    return {
        "tolerance": tolerance,
        "cells": len(rows),
        "published_cells": len(published),
        "runs": sum(r["n_runs"] for r in rows),
        "runs_with_front": sum(r["n_front"] + r["n_opposite"] for r in rows),
        "runs_opposite": sum(r["n_opposite"] for r in rows),
        "seeds_per_cell_min": min((r["n_runs"] for r in rows), default=0),
        "seeds_per_cell_max": max((r["n_runs"] for r in rows), default=0),
        "within_tol_seed1": sum(bool(r["within_tol_seed1"]) for r in published),
        "within_tol_mean": sum(bool(r["within_tol_mean"]) for r in published),
        "cells_full_agreement": sum(r["category_agreement"] == 1.0 for r in rows),
        "spread_rel_median": _median([r["spread_rel"] for r in published if r["spread_rel"] is not None]),
        "groups": groups,
    }


# --------------------------------------------------------------------------------------------------
# Formatting


def _pct(value: float | None, fmt: str = "+.1f") -> str:
    return "" if value is None else f"{100 * value:{fmt}}"


def _num(value: float | None, fmt: str = ".3f") -> str:
    return "" if value is None else f"{value:{fmt}}"


def _fronts(row: dict[str, Any]) -> str:
    """'n_front/n_runs', and the fronts running the other way when there are any."""
    text = f"{row['n_front']}/{row['n_runs']}"
    return text + (f" ({row['n_opposite']} opp.)" if row["n_opposite"] else "")


def _tex(value: float | None, fmt: str = ".3f") -> str:
    return "--" if value is None else f"${value:{fmt}}$"


def _dev(value: float | None) -> str:
    return _pct(value) + ("%" if value is not None else "")


#: The columns of ensemble.md and ensemble.tex (celerities in m/s, deviations in %).
TABLE = (
    Column("nu", lambda r: f"{r['nu']:g}", r"$\nu$", lambda r: f"{r['nu']:g}"),
    Column("f", lambda r: f"{r['f']:.2f}", "$f$", lambda r: f"{r['f']:.2f}"),
    Column("group", lambda r: r["group"]),
    Column("published", lambda r: _num(r["published"]), "published", lambda r: f"${r['published']:.3f}$"),
    Column("seed 1", lambda r: _num(r["celerity_seed1"]), "seed 1", lambda r: _tex(r["celerity_seed1"])),
    Column("mean", lambda r: _num(r["celerity_mean"]), "mean", lambda r: _tex(r["celerity_mean"])),
    Column("std", lambda r: _num(r["celerity_std"]), "std", lambda r: _tex(r["celerity_std"])),
    Column("min", lambda r: _num(r["celerity_min"])),
    Column("max", lambda r: _num(r["celerity_max"]), "[min, max]",
           lambda r: "" if r["celerity_min"] is None else f"[${r['celerity_min']:.3f}$, ${r['celerity_max']:.3f}$]"),
    Column("fronts", _fronts, "fronts", _fronts),
    Column("majority category", lambda r: str(r["majority_category"])),
    Column("agreement", lambda r: f"{r['category_agreement']:.2f}", "agreement",
           lambda r: f"${r['category_agreement']:.2f}$"),
    Column("dev. seed 1", lambda r: _dev(r["deviation_seed1_rel"])),
    Column("dev. mean", lambda r: _dev(r["deviation_mean_rel"]), r"dev.\ mean (\%)",
           lambda r: "" if r["deviation_mean_rel"] is None else f"${100 * r['deviation_mean_rel']:+.1f}$"),
)


def ensemble_markdown(rows: list[dict[str, Any]], summary: dict[str, Any]) -> str:
    n = summary["published_cells"]
    return table_render.markdown(TABLE, rows, (
        f"within {100 * summary['tolerance']:g}%: {summary['within_tol_seed1']}/{n} (seed 1), "
        f"{summary['within_tol_mean']}/{n} (ensemble mean); {summary['runs_with_front']}/"
        f"{summary['runs']} runs with a celerity (an opening pulse), {summary['runs_opposite']} "
        "of them against their cell's direction (not averaged)"))


def ensemble_latex(rows: list[dict[str, Any]]) -> str:
    """Booktabs tabular of the published cells by systematic group: celerities in m/s, deviations in %."""
    return table_render.latex(TABLE, [r for r in rows if r["published"] is not None], "ensemble",
                              group=lambda r: r["group"], heading=lambda g: g.replace(">=", r"$\geq$"))


def ensemble_files(rows: list[dict[str, Any]], reference: list[ReferenceCell],
                   tolerance: float) -> dict[str, str]:
    """Every output text by file name."""
    from analysis.core.table_csv import csv_text

    table = ensemble_rows(rows, reference, tolerance)
    summary = summarize(table, tolerance)
    return {
        "ensemble.csv": csv_text(ENSEMBLE_COLUMNS, table),
        "ensemble.md": ensemble_markdown(table, summary),
        "ensemble.tex": ensemble_latex(table),
        "ensemble_summary.json": json.dumps(summary, indent=2) + "\n",
    }
