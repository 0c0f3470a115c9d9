"""Method envelope of each published cell: how far seeds, mesh, time step and integration move the
regenerated celerity, and whether the published value lies inside that range.

    python3 -m analysis envelope --ensemble ensemble.csv --spec SPEC.json -o DIR

``ensemble.csv`` is `analysis.confidence.ensemble`'s table (one row per cell: the seeds' mean, min, max, the
default seed's run). SPEC (JSON, from config `paper.envelope`) lists the method variants::

    {"variants": [{"factor": "mesh", "label": "H/32", "table": ".../all_metrics.csv",
                   "where": {}, "base": ".../all_metrics.csv", "base_where": {}}]}

A variant's value at a cell is the celerity of its run there (``table`` rows matching ``where``,
one per cell, with a persistent front); its shift is (value - base value) / |published|, the base
being the same method with that one choice at the paper's setting. Per cell (``ENVELOPE_COLUMNS``):

- the envelope [envelope_min, envelope_max]: min and max over the seeds and every variant whose
  front runs in the published direction; a front running the other way is another category, not
  a celerity of this wave: it is counted in ``sign_flips`` and moves neither envelope nor shift;
- ``shift_<factor>``: the variant shift of largest magnitude for that factor; ``shift_seed`` =
  (max - min) / |published| over the seeds;
- ``top_factor``: the factor with the largest |shift|;
- ``status``: ``within`` (ensemble mean, or the default seed without a mean, within tolerance),
  ``inside`` (published value in the envelope), ``outside``; ``outside_by_rel``: distance from
  the published value to the nearer bound over |published| (0 unless outside).

Deviations (``*_dev``) are (celerity - published) / |published|, so the figure plots columns as they
are. Outputs: ``envelope.csv``, ``envelope.md``, ``envelope.tex``, ``envelope_summary.json``.
"""

from __future__ import annotations

import json
import math
import statistics
from typing import Any

from analysis.confidence.ensemble import SYSTEMATIC_GROUPS
from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_csv import read_table
from analysis.core.table_render import Column
from analysis.tables.reference import cell_key

BASE_COLUMNS = ("nu", "f", "group", "published", "celerity_seed1", "celerity_mean", "seed_min",
                "seed_max", "envelope_min", "envelope_max", "seed1_dev", "mean_dev", "seed_min_dev",
                "seed_max_dev", "envelope_min_dev", "envelope_max_dev", "top_factor", "top_shift",
                "status", "outside_by_rel", "sign_flips")
STATUSES = ("within", "inside", "outside")


def _finite(value: Any) -> bool:
    return isinstance(value, float) and math.isfinite(value)


def _matches(row: dict[str, Any], where: dict[str, Any]) -> bool:
    for key, wanted in where.items():
        value = row.get(key)
        if isinstance(wanted, str) or not isinstance(value, float):
            if value != wanted:
                return False
        elif not math.isclose(value, float(wanted), rel_tol=1e-9, abs_tol=1e-12):
            return False
    return True


def cell_values(rows: list[dict[str, Any]], where: dict[str, Any], what: str) -> dict[tuple, float]:
    """{(nu, f): celerity} of the rows matching `where` that have a persistent front; InputError
    when two runs fall on one cell (narrow `where`)."""
    values: dict[tuple, float] = {}
    seen: set[tuple] = set()
    for row in rows:
        if not _matches(row, where):
            continue
        key = cell_key(row["nu"], row["f"])
        if key in seen:
            raise InputError(f"{what}: two runs at nu={key[0]:g} f={key[1]:g}; narrow `where` ({where})")
        seen.add(key)
        if row.get("celerity_reason") == "ok" and _finite(row.get("celerity")):
            values[key] = row["celerity"]
    return values


def factors_of(variants: list[dict[str, Any]]) -> list[str]:
    """'seed' first, then the variants' factors in first-seen order."""
    out = ["seed"]
    for variant in variants:
        if variant["factor"] not in out:
            out.append(variant["factor"])
    return out


def envelope_rows(ensemble: list[dict[str, Any]], variants: list[dict[str, Any]],
                  tolerance: float) -> list[dict[str, Any]]:
    """One row per published cell of `ensemble`, by systematic group (ensemble.SYSTEMATIC_GROUPS),
    then f, then nu. Each variant: factor, label, values and base_values ({(nu, f): celerity})."""
    factors = factors_of(variants)
    out = []
    for cell in ensemble:
        published = cell.get("published")
        if not _finite(published):
            continue
        key, scale = cell_key(cell["nu"], cell["f"]), abs(published)
        row: dict[str, Any] = {c: None for c in BASE_COLUMNS}
        row.update({f"shift_{factor}": None for factor in factors})
        row.update(nu=cell["nu"], f=cell["f"], group=cell.get("group"), published=published)
        def same_direction(value):
            return (value > 0) == (published > 0)

        seeds = [cell[c] for c in ("celerity_min", "celerity_max") if _finite(cell.get(c))]
        inside = [c for c in seeds if same_direction(c)]
        flips = len(seeds) - len(inside)
        if _finite(cell.get("celerity_seed1")):
            row["celerity_seed1"] = cell["celerity_seed1"]
            if same_direction(cell["celerity_seed1"]):
                inside.append(cell["celerity_seed1"])
        if _finite(cell.get("celerity_mean")):
            row["celerity_mean"] = cell["celerity_mean"]
        if seeds:
            row.update(seed_min=min(seeds), seed_max=max(seeds))
            row["shift_seed"] = (max(seeds) - min(seeds)) / scale
        for variant in variants:
            value, base = variant["values"].get(key), variant["base_values"].get(key)
            if value is None:
                continue
            if not same_direction(value):
                flips += 1
                continue
            inside.append(value)
            if base is not None and same_direction(base):
                shift = (value - base) / scale
                current = row[f"shift_{variant['factor']}"]
                if current is None or abs(shift) > abs(current):
                    row[f"shift_{variant['factor']}"] = shift
        row["sign_flips"] = flips
        if inside:
            row.update(envelope_min=min(inside), envelope_max=max(inside))
        for name, value in (("seed1", row["celerity_seed1"]), ("mean", row["celerity_mean"]),
                            ("seed_min", row["seed_min"]), ("seed_max", row["seed_max"]),
                            ("envelope_min", row["envelope_min"]), ("envelope_max", row["envelope_max"])):
            row[f"{name}_dev"] = None if value is None else (value - published) / scale
        shifts = [(f, row[f"shift_{f}"]) for f in factors if row[f"shift_{f}"] is not None]
        if shifts:
            row["top_factor"], row["top_shift"] = max(shifts, key=lambda item: abs(item[1]))
        deviation = row["mean_dev"] if row["mean_dev"] is not None else row["seed1_dev"]
        if deviation is not None and abs(deviation) <= tolerance:
            row["status"], row["outside_by_rel"] = "within", 0.0
        elif inside and row["envelope_min"] <= published <= row["envelope_max"]:
            row["status"], row["outside_by_rel"] = "inside", 0.0
        elif inside:
            nearer = min((row["envelope_min"], row["envelope_max"]), key=lambda b: abs(b - published))
            row["status"], row["outside_by_rel"] = "outside", abs(nearer - published) / scale
        out.append(row)
    order = {name: i for i, (name, _) in enumerate(SYSTEMATIC_GROUPS)}
    return sorted(out, key=lambda r: (order.get(r["group"], len(order)), r["f"], r["nu"]))


def summarize(rows: list[dict[str, Any]], factors: list[str]) -> dict[str, Any]:
    """Counts per status, and how often each factor moves a cell most, overall and per systematic
    group; per group also the median |shift| of each factor over the cells where it was run."""
    groups: dict[str, dict[str, Any]] = {}
    for name in dict.fromkeys(r["group"] or "" for r in rows):
        members = [r for r in rows if (r["group"] or "") == name]
        groups[name] = {
            **{s: sum(r["status"] == s for r in members) for s in STATUSES},
            "top_factor_counts": {f: sum(r["top_factor"] == f for r in members) for f in factors},
            "median_abs_shift": {f: (statistics.median(shifts) if shifts else None)
                                 for f in factors
                                 for shifts in [[abs(r[f"shift_{f}"]) for r in members
                                                 if r[f"shift_{f}"] is not None]]},
        }
    return {
        "cells": len(rows),
        **{s: sum(r["status"] == s for r in rows) for s in STATUSES},
        "unmeasured": sum(r["status"] is None for r in rows),
        "top_factor_counts": {f: sum(r["top_factor"] == f for r in rows) for f in factors},
        "groups": groups,
    }


# --------------------------------------------------------------------------------------------------
# Formatting and command line


def _pct(value: float | None) -> str:
    return "" if value is None else f"{100 * value:+.1f}"


def _span(lo: float | None, hi: float | None, tex: bool) -> str:
    if lo is None:
        return "--" if tex else ""
    return f"[${_pct(lo)}$, ${_pct(hi)}$]" if tex else f"[{_pct(lo)}, {_pct(hi)}]"


def _tex_pct(value: float | None) -> str:
    return "--" if value is None else f"${_pct(value)}$"


def columns(factors: list[str]) -> list[Column]:
    """The columns of envelope.md (with the shift of each factor) and envelope.tex (deviations from
    the published celerity in %, the status and the factor that moves the cell most)."""
    return [
        Column("nu", lambda r: f"{r['nu']:g}", r"$\nu$", lambda r: f"{r['nu']:g}"),
        Column("f", lambda r: f"{r['f']:.2f}", "$f$", lambda r: f"{r['f']:.2f}"),
        Column("group", lambda r: r["group"] or ""),
        Column("published", lambda r: f"{r['published']:.3f}"),
        Column("dev. seed 1 (%)", lambda r: _pct(r["seed1_dev"]), "seed 1", lambda r: _tex_pct(r["seed1_dev"])),
        Column("dev. mean (%)", lambda r: _pct(r["mean_dev"]), "mean", lambda r: _tex_pct(r["mean_dev"])),
        Column("seeds (%)", lambda r: _span(r["seed_min_dev"], r["seed_max_dev"], False), "seeds",
               lambda r: _span(r["seed_min_dev"], r["seed_max_dev"], True)),
        Column("envelope (%)", lambda r: _span(r["envelope_min_dev"], r["envelope_max_dev"], False), "envelope",
               lambda r: _span(r["envelope_min_dev"], r["envelope_max_dev"], True)),
        Column("status", lambda r: r["status"] or "unmeasured", "status", lambda r: r["status"] or "--", "l"),
        Column("top factor", lambda r: r["top_factor"] or "", "moved most by",
               lambda r: "--" if r["top_factor"] is None else f"{r['top_factor']} (${_pct(r['top_shift'])}$)", "l"),
        *[Column(f"{f} (%)", lambda r, f=f: _pct(r[f"shift_{f}"])) for f in factors],
    ]


def envelope_markdown(rows: list[dict[str, Any]], factors: list[str], summary: dict[str, Any]) -> str:
    return table_render.markdown(columns(factors), rows, ", ".join(f"{summary[s]} {s}" for s in STATUSES)
                                 + f" of {summary['cells']} cells")


def envelope_latex(rows: list[dict[str, Any]]) -> str:
    """Booktabs tabular by systematic group (see `columns`)."""
    return table_render.latex(columns([]), rows, "envelope", group=lambda r: r["group"],
                              heading=lambda g: (g or "").replace(">=", r"$\geq$"))


def load_variants(spec: dict[str, Any]) -> list[dict[str, Any]]:
    """The spec's variants with their values read from the tables."""
    variants = []
    for i, entry in enumerate(spec.get("variants", [])):
        missing = [k for k in ("factor", "label", "table", "base") if k not in entry]
        if missing:
            raise InputError(f"envelope spec: variant {i} lacks {', '.join(missing)}")
        if entry["factor"] == "seed":
            raise InputError("envelope spec: the factor 'seed' is the ensemble's; name the variant otherwise")
        required = ("nu", "f", "celerity", "celerity_reason")
        values = cell_values(read_table(entry["table"], required), entry.get("where", {}), entry["table"])
        base = cell_values(read_table(entry["base"], required), entry.get("base_where", {}), entry["base"])
        variants.append({**entry, "values": values, "base_values": base})
    return variants


def envelope_files(ensemble: list[dict[str, Any]], spec: dict[str, Any], tolerance: float) -> dict[str, str]:
    from analysis.core.table_csv import csv_text

    variants = load_variants(spec)
    factors = factors_of(variants)
    rows = envelope_rows(ensemble, variants, tolerance)
    summary = {**summarize(rows, factors), "tolerance": tolerance,
               "variants": [{k: v[k] for k in ("factor", "label", "table", "base")} for v in variants]}
    return {
        "envelope.csv": csv_text(BASE_COLUMNS + tuple(f"shift_{f}" for f in factors), rows),
        "envelope.md": envelope_markdown(rows, factors, summary),
        "envelope.tex": envelope_latex(rows),
        "envelope_summary.json": json.dumps(summary, indent=2) + "\n",
    }
