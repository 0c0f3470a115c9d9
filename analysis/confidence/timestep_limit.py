"""The backward supersonic pulses against the time step: is there a dt -> 0 limit, and is it Adams'?

    python3 -m analysis timestep-limit A.csv [B.csv ...] --reference table1_celerity.csv -o DIR

reads ``all_metrics.csv`` tables (sweeps ``timestep_backward`` and ``timestep``; a run present in
two tables, same nu, f, mesh, dt c_s and seed, is counted once, from the first) and keeps the runs
of the cells published with a backward (negative) celerity. Per cell and dt c_s: the runs, those
with a backward front, and over those the celerity's mean, min and max (the seed spread); the
theory's value -c of Adams' steady supersonic slip wave (`analysis.theory.supersonic`). A run that left the
model (`non_physical`: it created energy or opened beyond H, `analysis/metrics/validity.py`) is no sample of
the celerity: it is counted apart (`n_non_physical`), not among the runs. Writes, together or
not at all, ``timestep_limit.csv`` (one row per cell and dt), ``timestep_cells.csv`` (one per cell),
``timestep_limit.md``, ``.tex`` and ``timestep_limit_summary.json``.

The rule for a limit (docs/supersonic-backward.md, section 6; fixed before any run at dt c_s =
0.0625 or 0.125 m had finished). Over the three smallest dt c_s (each half the previous) of a cell, with
seed means m1, m2, m3 (largest dt first), the differences d_prev = m2 - m1, d_last = m3 - m2, and the
seed range S = max - min at the smallest dt:

- *another regime*: at one of those dt fewer than half of the runs have a backward front (of the runs
  that stay physical, where there are any);
- *left the model*: else, at one of those dt every run is `non_physical` (added with analysis version 8,
  when the runs at dt c_s = 0.0625 m were found to create energy: docs/physics-notes.md, section 8): the
  method cannot go to that dt, and nothing is said about a limit;
- *within seed spread*: |d_prev| <= S and |d_last| <= S: halving dt moves the mean by no more than
  the seeds scatter; the value is the mean at the smallest dt, +- S/2;
- *converging*: d_prev, d_last of one sign, |d_last| < |d_prev|, and S < |d_prev| (the shrinking is
  resolved above the seeds): the Richardson limit of `analysis.confidence.mesh_limit.richardson`;
- *not converging*: otherwise (the differences grow or turn above the seed spread).
"""

from __future__ import annotations

import json
import math
import statistics
from typing import Any

from analysis.confidence.mesh_limit import richardson
from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_csv import csv_text
from analysis.core.table_render import Column
from analysis.tables.reference import cell_key
from analysis.theory import elastic, supersonic

REQUIRED = ("nu", "f", "seed", "dt_times_cs", "elements_per_H", "celerity", "celerity_reason")
STATUSES = ("within seed spread", "converging", "not converging", "another regime", "left the model",
            "too few time steps")
RUN_COLUMNS = ("nu", "f", "dt_times_cs", "n_runs", "n_backward", "n_non_physical", "mean", "min", "max", "range",
               "theory", "published", "dev_theory", "dev_published")
CELL_COLUMNS = ("nu", "f", "published", "theory", "status", "d_prev", "d_last", "range_smallest",
                "value", "value_halfwidth", "dev_value_theory", "smallest_dt", "mean_smallest_dt",
                "dev_smallest_theory", "dev_published_theory")


def adams_celerity(nu: float, f: float) -> float:
    """-c (m/s): Adams' backward steady wave at Table 1's E and rho."""
    return -supersonic.supersonic_trace_speed(nu, f, elastic.wave_speeds(nu)[0])


def unique_runs(tables: list[list[dict[str, Any]]]) -> list[dict[str, Any]]:
    """The runs of all tables, each (nu, f, mesh, dt, seed) once (the first table wins)."""
    seen, out = set(), []
    for rows in tables:
        for row in rows:
            key = (cell_key(row["nu"], row["f"]), row["elements_per_H"], round(row["dt_times_cs"], 9), row["seed"])
            if key not in seen:
                seen.add(key)
                out.append(row)
    return out


def _backward(row: dict[str, Any]) -> float | None:
    c = row["celerity"]
    ok = row["celerity_reason"] == "ok" and isinstance(c, float) and math.isfinite(c)
    return c if ok and c < 0 else None


def dt_rows(runs: list[dict[str, Any]], published: dict) -> list[dict[str, Any]]:
    """One row per (published backward cell, dt c_s): seed statistics of the backward fronts."""
    groups: dict[tuple, list[dict[str, Any]]] = {}
    for row in runs:
        key = cell_key(row["nu"], row["f"])
        if key in published and published[key] < 0:
            groups.setdefault((key, round(row["dt_times_cs"], 9)), []).append(row)
    out = []
    for ((nu, f), dt), rows in sorted(groups.items(), key=lambda item: (item[0][0], -item[0][1])):
        meshes = {r["elements_per_H"] for r in rows}
        if len(meshes) > 1:
            raise InputError(f"cell nu={nu:g} f={f:g} dt c_s={dt:g}: runs at several meshes "
                             f"{sorted(meshes)}; pass tables of one mesh")
        physical = [r for r in rows if not r.get("non_physical")]
        fronts = [c for c in map(_backward, physical) if c is not None]
        adams = adams_celerity(nu, f)
        row = {"nu": nu, "f": f, "dt_times_cs": dt, "elements_per_H": meshes.pop(), "n_runs": len(physical),
               "n_backward": len(fronts), "n_non_physical": len(rows) - len(physical),
               "theory": adams, "published": published[(nu, f)]}
        if fronts:
            mean = statistics.fmean(fronts)
            row.update(mean=mean, min=min(fronts), max=max(fronts), range=max(fronts) - min(fronts),
                       dev_theory=(mean - adams) / abs(adams),
                       dev_published=(mean - published[(nu, f)]) / abs(published[(nu, f)]))
        out.append(row)
    return out


def cell_status(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """The rule of the module docstring on one cell's rows (largest dt first)."""
    out = {"status": "too few time steps", "d_prev": None, "d_last": None, "range_smallest": None,
           "value": None, "value_halfwidth": None}
    last = rows[-3:]
    if len(last) < 3 or any(not math.isclose(b["dt_times_cs"] * 2, a["dt_times_cs"]) for a, b in zip(last, last[1:])):
        return out
    if any(r["n_runs"] > 0 and (2 * r["n_backward"] < r["n_runs"] or r["n_backward"] == 0) for r in last):
        return dict(out, status="another regime")
    if any(r["n_runs"] == 0 for r in last):
        return dict(out, status="left the model")
    m1, m2, m3 = (r["mean"] for r in last)
    spread = last[-1]["range"]
    out.update(d_prev=m2 - m1, d_last=m3 - m2, range_smallest=spread)
    if abs(m2 - m1) <= spread and abs(m3 - m2) <= spread:
        return dict(out, status="within seed spread", value=m3, value_halfwidth=spread / 2)
    fit = richardson([m1, m2, m3])
    if fit["status"] == "limit" and spread < abs(m2 - m1):
        return dict(out, status="converging", value=fit["limit"], value_halfwidth=fit["step"])
    return dict(out, status="not converging")


def cell_rows(rows: list[dict[str, Any]], tolerance: float) -> list[dict[str, Any]]:
    cells: dict[tuple, list[dict[str, Any]]] = {}
    for row in rows:
        cells.setdefault((row["nu"], row["f"]), []).append(row)
    out = []
    for (nu, f), members in cells.items():
        members = sorted(members, key=lambda r: -r["dt_times_cs"])
        adams, published = members[0]["theory"], members[0]["published"]
        status = cell_status(members)
        value = status["value"]
        finest = [r for r in members if r.get("mean") is not None]
        smallest = finest[-1] if finest else {}
        out.append({"nu": nu, "f": f, "published": published, "theory": adams, **status,
                    "non_physical_dt": [r["dt_times_cs"] for r in members if r.get("n_non_physical")],
                    "smallest_dt": smallest.get("dt_times_cs"), "mean_smallest_dt": smallest.get("mean"),
                    "dev_smallest_theory": smallest.get("dev_theory"),
                    "dev_value_theory": None if value is None else (value - adams) / abs(adams),
                    "dev_published_theory": (published - adams) / abs(adams),
                    "value_follows_theory": None if value is None else abs(value - adams) <= tolerance * abs(adams),
                    "published_follows_theory": abs(published - adams) <= tolerance * abs(adams)})
    return out


def summarize(cells: list[dict[str, Any]], published: dict, tolerance: float) -> dict[str, Any]:
    """Counts, and the generated sentences on the limit and on Adams' speed."""
    counts = {s: sum(c["status"] == s for c in cells) for s in STATUSES}
    with_value = [c for c in cells if c["value"] is not None]
    ours = sum(bool(c["value_follows_theory"]) for c in with_value)
    smallest = [c for c in cells if c["dev_smallest_theory"] is not None]
    ours_smallest = sum(abs(c["dev_smallest_theory"]) <= tolerance for c in smallest)
    backward = {k: v for k, v in published.items() if v < 0}
    pub_follow = sum(abs(v - adams_celerity(*k)) <= tolerance * abs(adams_celerity(*k)) for k, v in backward.items())
    limited = counts["within seed spread"] + counts["converging"]
    if cells and limited == len(cells):
        limit = f"In all {len(cells)} cells the celerity settles as $\\Delta t \\to 0$: a limit exists."
    elif limited == 0:
        limit = (f"In none of the {len(cells)} cells does the celerity settle as $\\Delta t \\to 0$: "
                 "at the time steps we can afford it is not a converged quantity.")
    else:
        limit = (f"The celerity settles as $\\Delta t \\to 0$ in {limited} of the {len(cells)} cells only: "
                 "it is not a converged quantity of the method in general.")
    left = sorted({dt for c in cells for dt in c.get("non_physical_dt", [])})
    if left:
        steps = ", ".join(f"{dt:g}" for dt in left)
        limit += (f" Runs at $\\Delta t\\,c_s = {steps}$\\,m left the model (the layer gained energy that no work "
                  "put in) and are no samples.")
    tol = f"{100 * tolerance:g}\\,\\%"
    follow = (f"Within {tol} of Adams' speed: ours at the smallest time step in {ours_smallest} of "
              f"{len(smallest)} cells (the settled value in {ours} of the {len(with_value)} cells that settle), "
              f"the published values in {pub_follow} of the {len(backward)} published backward cells.")
    return {"tolerance": tolerance, "cells": len(cells), "status_counts": counts, "cells_settled": limited,
            "ours_follow_theory": ours, "ours_smallest_dt_follow_theory": ours_smallest,
            "cells_with_smallest_dt": len(smallest), "published_backward_cells": len(backward),
            "published_follow_theory": pub_follow, "limit_sentence": limit, "theory_sentence": follow}


def _n(v, fmt=".3f"):
    return "--" if v is None else f"${v:{fmt}}$"


def _f3(v) -> str:
    return "" if v is None else f"{v:.3f}"


def _backward_of_runs(r) -> str:
    """'backward/physical runs', and how many runs left the model."""
    text = f"{r['n_backward']}/{r['n_runs']}"
    return text + f" ({r['n_non_physical']} non-physical)" if r.get("n_non_physical") else text


#: The columns of the per-run-set table (timestep_limit.md, timestep_limit.tex).
RUN_TABLE = (
    Column("nu", lambda r: f"{r['nu']:g}", r"$\nu$", lambda r: f"{r['nu']:g}"),
    Column("f", lambda r: f"{r['f']:g}", "$f$", lambda r: f"{r['f']:g}"),
    Column("dt c_s", lambda r: f"{r['dt_times_cs']:g}", r"$\Delta t\,c_s$ (m)", lambda r: f"{r['dt_times_cs']:g}"),
    Column("backward/runs", _backward_of_runs, "backward", _backward_of_runs),
    *[Column(key, lambda r, key=key: _f3(r.get(key)), key, lambda r, key=key: _n(r.get(key))) for key in ("mean", "min", "max")],
    Column("Adams", lambda r: _f3(r["theory"]), "Adams", lambda r: _n(r["theory"])),
    Column("published", lambda r: _f3(r["published"]), "published", lambda r: _n(r["published"])),
    Column(None, None, r"dev.\ Adams (\%)",
           lambda r: "--" if r.get("dev_theory") is None else f"${100 * r['dev_theory']:+.1f}$"),
)
#: The columns of the per-cell table (timestep_limit.md).
CELL_TABLE = (
    Column("nu", lambda c: f"{c['nu']:g}"), Column("f", lambda c: f"{c['f']:g}"),
    Column("status", lambda c: c["status"]),
    *[Column(header, lambda c, key=key: _f3(c[key])) for header, key in (
        ("d_prev", "d_prev"), ("d_last", "d_last"), ("seed range", "range_smallest"), ("value", "value"),
        ("Adams", "theory"), ("published", "published"))],
)


def latex(rows: list[dict[str, Any]]) -> str:
    return table_render.latex(RUN_TABLE, rows, "timestep-limit", group=lambda r: (r["nu"], r["f"]))


def markdown(rows, cells, summary) -> str:
    text = summary["limit_sentence"] + " " + summary["theory_sentence"]
    return (table_render.markdown(RUN_TABLE, rows) + "\n"
            + table_render.markdown(CELL_TABLE, cells,
                                    text.replace("\\,\\%", " %").replace("$\\Delta t \\to 0$", "dt -> 0")))


def timestep_files(tables, reference, tolerance) -> dict[str, str]:
    if not tolerance > 0:
        raise InputError(f"tolerance must be > 0 (got {tolerance})")
    published = {c.key: c.celerity for c in reference}
    rows = dt_rows(unique_runs(tables), published)
    if not rows:
        raise InputError("no run of a cell published with a backward celerity in the tables")
    cells = cell_rows(rows, tolerance)
    summary = summarize(cells, published, tolerance)
    summary.update(dt_values=sorted({r["dt_times_cs"] for r in rows}), runs_per_point_max=max(r["n_runs"] for r in rows),
                   meshes=sorted({r["elements_per_H"] for r in rows}))
    return {"timestep_limit.csv": csv_text(RUN_COLUMNS, rows),
            "timestep_cells.csv": csv_text(CELL_COLUMNS + ("value_follows_theory", "published_follows_theory"), cells),
            "timestep_limit.md": markdown(rows, cells, summary), "timestep_limit.tex": latex(rows),
            "timestep_limit_summary.json": json.dumps(summary, indent=2) + "\n"}
