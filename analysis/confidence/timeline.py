"""The Fig. 3 timeline of the nu = 0.2, f = 1.5 run: our event times across seeds and meshes.

    python3 -m analysis timeline --set "seeds, H/64" DIR... --set meshes DIR... -o DIR

Each DIR is a run folder with ``metrics.json`` and ``run.h5``. Per run, the times (s, stage-3 clock,
as the paper's) of the events of ``EVENTS``; all but one are metrics of `analysis.metrics.measure`; the
slip-velocity maximum (the time of the largest slip velocity anywhere on the interface over the
recorded run) is read from run.h5 here, since no metric holds it. Per set: the mean, min and max of
every event over its runs and, per run, its mesh and seed. Writes, together or not at all,
``timeline.csv`` (one row per run), ``timeline.md``, ``timeline.tex`` and ``timeline_summary.json``.

The paper gives no event times, only the times of the six snapshots of its Fig. 3 ("t ~ 787, 840,
890, 960, 1010, 1077 s"), whose panels show first slip, pulse localization, the opening at the
slip-velocity maximum and the drop: ``PAPER_TIMES`` pairs each event with the snapshot that shows
it; the drop's start and the T/N minimum have no single snapshot (the drop spans 960-1077 s).
"""

from __future__ import annotations

import json
import math
import statistics
from pathlib import Path
from typing import Any

import numpy as np

from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_csv import csv_text
from analysis.core.table_render import Column

#: event key -> label; the keys are metrics of analysis.metrics.measure but `slip_velocity_max_time`.
EVENTS = {
    "onset_time": "first slip",
    "localization_time": "pulse localization",
    "celerity_window_start": "celerity window starts",
    "first_opening_time": "first opening",
    "slip_velocity_max_time": "slip-velocity maximum",
    "first_drop_start_time": "frictional drop starts",
    "min_T_over_N_time": "T/N minimum",
}
PAPER_TIMES = {"onset_time": 787.0, "localization_time": 840.0, "first_opening_time": 890.0,
               "slip_velocity_max_time": 890.0}
PAPER_DROP_SNAPSHOTS = (960.0, 1010.0, 1077.0)


def _number(value: Any) -> float | None:
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) else None


def slip_velocity_max_time(t: np.ndarray, slip_velocity: np.ndarray) -> float | None:
    """Time of the largest slip velocity over the interface and the run (first if repeated)."""
    if slip_velocity.size == 0:
        return None
    peak = np.nanmax(np.abs(slip_velocity), axis=1)
    if not np.isfinite(peak).any():
        return None
    return float(t[int(np.nanargmax(peak))])


def run_events(folder: Path) -> dict[str, Any]:
    """One run's events, mesh and seed; InputError naming the file when one is unreadable."""
    from analysis.core.io import load_run

    path = folder / "metrics.json"
    try:
        metrics = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as err:
        raise InputError(f"{path}: cannot read ({err})") from None
    for key in ("nu", "f", "elements_per_H", "seed"):
        if key not in metrics:
            raise InputError(f"{path}: no key '{key}'")
    run = load_run(folder / "run.h5")
    row = {"run": str(folder), "nu": metrics["nu"], "f": metrics["f"],
           "elements_per_H": metrics["elements_per_H"], "seed": metrics["seed"]}
    for key in EVENTS:
        row[key] = (slip_velocity_max_time(run.interface.t, run.interface.slip_velocity)
                    if key == "slip_velocity_max_time" else _number(metrics.get(key)))
    return row


def set_summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """Per event: n, mean, min, max over the runs that have it; the runs' meshes and seeds."""
    out: dict[str, Any] = {"runs": len(rows), "meshes": sorted({r["elements_per_H"] for r in rows}),
                           "seeds": sorted({r["seed"] for r in rows}), "events": {}}
    for key in EVENTS:
        values = [r[key] for r in rows if r[key] is not None]
        out["events"][key] = {"n": len(values), "mean": statistics.fmean(values) if values else None,
                              "min": min(values, default=None), "max": max(values, default=None),
                              "paper": PAPER_TIMES.get(key)}
        if values and key in PAPER_TIMES:
            out["events"][key]["mean_minus_paper"] = out["events"][key]["mean"] - PAPER_TIMES[key]
    return out


def summarize(sets: dict[str, list[dict[str, Any]]]) -> dict[str, Any]:
    cells = {(r["nu"], r["f"]) for rows in sets.values() for r in rows}
    if len(cells) != 1:
        raise InputError(f"the runs are of several cells {sorted(cells)}: the timeline is of one cell")
    (nu, f), = cells
    return {"nu": nu, "f": f, "paper_times": PAPER_TIMES, "paper_drop_snapshots": list(PAPER_DROP_SNAPSHOTS),
            "sets": {label: set_summary(rows) for label, rows in sets.items()}}


def _t(v: float | None) -> str:
    return "--" if v is None else f"{v:.0f}"


def _paper_tex(event: dict[str, str]) -> str:
    paper = PAPER_TIMES.get(event["key"])
    if paper is None and event["key"] in ("first_drop_start_time", "min_T_over_N_time"):
        return f"({PAPER_DROP_SNAPSHOTS[0]:.0f}--{PAPER_DROP_SNAPSHOTS[-1]:.0f})"
    return _t(paper)


def _stats(e: dict[str, Any], with_n: bool, missing: str) -> str:
    if e["mean"] is None:
        return missing
    return f"{e['mean']:.0f} [{e['min']:.0f}, {e['max']:.0f}]" + (f" ({e['n']})" if with_n else "")


def columns(sets: dict[str, list[dict[str, Any]]], summary: dict[str, Any]) -> list[Column]:
    """Events as rows; the paper, then per set: in Markdown mean [min, max] (n); in LaTeX either
    mean [min, max] (several seeds of one mesh) or one column per run (a set of meshes)."""
    cols = [Column("event", lambda e: e["label"], "event", lambda e: e["label"], "l"),
            Column("paper", lambda e: _t(PAPER_TIMES.get(e["key"])), "paper", _paper_tex)]
    cols += [Column(f"{label}: mean [min, max] (n)",
                    lambda e, label=label: _stats(summary["sets"][label]["events"][e["key"]], True, ""))
             for label in summary["sets"]]
    for label, rows in sets.items():
        if len(summary["sets"][label]["meshes"]) == 1:
            cols.append(Column(None, None, f"{label}: mean [min, max]",
                               lambda e, label=label: _stats(summary["sets"][label]["events"][e["key"]], False, "--")))
        else:
            cols += [Column(None, None, f"$H/{r['elements_per_H']:g}$", lambda e, r=r: _t(r[e["key"]]))
                     for r in sorted(rows, key=lambda r: r["elements_per_H"])]
    return cols


def _events() -> list[dict[str, str]]:
    return [{"key": key, "label": label} for key, label in EVENTS.items()]


def latex(sets: dict[str, list[dict[str, Any]]], summary: dict[str, Any]) -> str:
    return table_render.latex(columns(sets, summary), _events(), "timeline")


def markdown(summary: dict[str, Any]) -> str:
    return table_render.markdown(columns({}, summary), _events())


def timeline_files(sets: dict[str, list[dict[str, Any]]]) -> dict[str, str]:
    summary = summarize(sets)
    rows = [dict(r, set=label) for label, members in sets.items() for r in members]
    columns = ["set", "run", "nu", "f", "elements_per_H", "seed", *EVENTS]
    return {"timeline.csv": csv_text(columns, rows), "timeline.md": markdown(summary),
            "timeline.tex": latex(sets, summary), "timeline_summary.json": json.dumps(summary, indent=2) + "\n"}
