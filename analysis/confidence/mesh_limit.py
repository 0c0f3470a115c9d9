"""The mesh limit of each published cell: celerity against 1/N and a Richardson limit.

    python3 -m analysis mesh-limit --mesh 32=A.csv --mesh 64=B.csv --mesh 128=C.csv [--mesh 256=D.csv]
        --reference table1_celerity.csv -o DIR

reads each mesh's ``all_metrics.csv`` (one row per run; only the default seed, seed 1, is used, so
an ensemble sweep may be passed) and writes, together or not at all, ``mesh_limit.csv``, ``.md``,
``.tex`` and ``mesh_limit_summary.json``. The rule (docs/mesh-limit.md, fixed before the outcome):
over the finest three meshes N1 < N2 < N3 with celerities c1, c2, c3 and r = (c3 - c2) / (c2 - c1),
the cell is *incomplete* (a value missing or of another sign), *not monotone* (r <= 0), *not
converging* (r >= 1), or has the limit c_inf = c3 + (c3 - c2) r / (1 - r) (Richardson with the
observed order p = -log2 r).
"""

from __future__ import annotations

import json
import math
from typing import Any

from analysis.confidence.ensemble import DEFAULT_SEED, group_of
from analysis.core import table_render
from analysis.core.errors import InputError
from analysis.core.table_csv import csv_text
from analysis.core.table_render import Column
from analysis.tables.reference import ReferenceCell, cell_key

REQUIRED = ("nu", "f", "seed", "celerity", "celerity_reason")
STATUSES = ("limit", "not monotone", "not converging", "incomplete", "fewer meshes")


def _front(row: dict[str, Any]) -> float | None:
    c = row["celerity"]
    return c if row["celerity_reason"] == "ok" and isinstance(c, float) and math.isfinite(c) else None


def celerities_by_cell(rows: list[dict[str, Any]], path: str) -> dict[tuple[float, float], float | None]:
    """{(nu, f): celerity of the seed-1 run (None: no front)}; InputError for two seed-1 runs of a cell."""
    out: dict[tuple[float, float], float | None] = {}
    for row in rows:
        if row["seed"] != DEFAULT_SEED:
            continue
        key = cell_key(row["nu"], row["f"])
        if key in out:
            raise InputError(f"{path}: two seed-{DEFAULT_SEED} runs of the cell nu={key[0]:g} f={key[1]:g}")
        out[key] = _front(row)
    return out


def richardson(values: list[float | None]) -> dict[str, Any]:
    """The rule of docs/mesh-limit.md on the finest three values (coarse to fine, each mesh twice the
    previous): status, ratio r, observed order p, limit and extrapolation step (None where undefined)."""
    out = {"status": "incomplete", "ratio": None, "order": None, "limit": None, "step": None}
    if len(values) < 3:
        return out
    c1, c2, c3 = values[-3:]
    if c1 is None or c2 is None or c3 is None or len({math.copysign(1.0, c) for c in (c1, c2, c3)}) > 1:
        return out
    if c2 == c1:
        return dict(out, status="not monotone")
    r = (c3 - c2) / (c2 - c1)
    out["ratio"] = r
    if r <= 0:
        return dict(out, status="not monotone")
    if r >= 1:
        return dict(out, status="not converging")
    limit = c3 + (c3 - c2) * r / (1 - r)
    return dict(out, status="limit", order=-math.log2(r), limit=limit, step=abs(limit - c3))


def _rel(value: float | None, published: float) -> float | None:
    return None if value is None else (value - published) / abs(published)


def cell_row(cell: ReferenceCell, meshes: list[int], by_mesh: dict[int, dict], tolerance: float) -> dict[str, Any]:
    """One row: the published value, c at every mesh, the limit and the comparisons."""
    values = [by_mesh[n].get(cell.key) for n in meshes]
    present = [(n, c) for n, c in zip(meshes, values) if cell.key in by_mesh[n]]
    fit = richardson([c for _, c in present])
    # The finest three must be consecutive halvings (32, 64, 128 or 64, 128, 256).
    finest = [n for n, _ in present[-3:]]
    if len(finest) < 3 or finest[1] != 2 * finest[0] or finest[2] != 2 * finest[1]:
        fit = dict(richardson([]), status="fewer meshes")
    row: dict[str, Any] = {"nu": cell.nu, "f": cell.f, "group": group_of(cell), "published": cell.celerity,
                           "finest_meshes": "/".join(str(n) for n, _ in present[-3:]), **fit}
    for n, c in zip(meshes, values):
        row[f"c_{n}"] = c
        row[f"dev_{n}"] = _rel(c, cell.celerity)
    row["dev_limit"] = _rel(fit["limit"], cell.celerity)
    c64 = row.get("c_64")
    row["published_closer_than_64"] = (None if fit["limit"] is None or c64 is None else
                                       abs(cell.celerity - fit["limit"]) < abs(c64 - fit["limit"]))
    for name in ("64", "128", "limit"):
        dev = row.get(f"dev_{name}")
        row[f"within_{name}"] = None if dev is None else abs(dev) <= tolerance
    return row


def summarize(rows: list[dict[str, Any]], tolerance: float) -> dict[str, Any]:
    """Counts over the cells, and the verdict of docs/mesh-limit.md."""
    with_limit = [r for r in rows if r["status"] == "limit"]
    count = lambda key, among: sum(bool(r.get(key)) for r in among)  # noqa: E731
    summary = {
        "tolerance": tolerance,
        "cells": len(rows),
        "status_counts": {s: sum(r["status"] == s for r in rows) for s in STATUSES},
        "cells_with_limit": len(with_limit),
        "cells_at_256": sum(r.get("c_256") is not None for r in rows),
        "within_64": count("within_64", rows),
        "cells_at_128": sum(r.get("c_128") is not None for r in rows),
        "within_128": count("within_128", rows),
        "within_limit": count("within_limit", with_limit),
        "within_64_of_limit_cells": count("within_64", with_limit),
        "published_closer_than_64": count("published_closer_than_64", with_limit),
    }
    converged = (summary["within_limit"] > summary["within_64_of_limit_cells"]
                 and 2 * summary["published_closer_than_64"] > len(with_limit))
    summary["published_at_limit"] = converged
    summary["verdict"] = (
        f"Of the {len(with_limit)} cells with a mesh limit, {summary['within_limit']} are within "
        f"{100 * tolerance:g}\\,\\% of the published value at the limit against "
        f"{summary['within_64_of_limit_cells']} at $H/h = 64$, and the published value is closer to the "
        f"limit than $H/h = 64$ is in {summary['published_closer_than_64']}: the published values "
        + ("sit at the converged values." if converged else "do not sit at the converged values."))
    return summary


def mesh_limit_rows(tables: dict[int, list[dict[str, Any]]], paths: dict[int, str],
                    reference: list[ReferenceCell], tolerance: float) -> list[dict[str, Any]]:
    if not tolerance > 0:
        raise InputError(f"tolerance must be > 0 (got {tolerance})")
    if len(tables) < 3:
        raise InputError(f"--mesh: at least three meshes are needed (got {sorted(tables)})")
    meshes = sorted(tables)
    by_mesh = {n: celerities_by_cell(tables[n], paths[n]) for n in meshes}
    return [cell_row(cell, meshes, by_mesh, tolerance) for cell in reference]


def _num(v: float | None, fmt: str = ".3f") -> str:
    return "--" if v is None else f"${v:{fmt}}$"


def _pct(v: float | None) -> str:
    return "--" if v is None else f"${100 * v:+.1f}$"


def _f3(v: float | None) -> str:
    return "" if v is None else f"{v:.3f}"


def _fp(v: float | None) -> str:
    return "" if v is None else f"{100 * v:+.1f}"


_STATUS_SHORT = {"limit": "limit", "not monotone": "not mon.", "not converging": "not conv.",
                 "incomplete": "incompl.", "fewer meshes": "few meshes"}


def columns(meshes: list[int]) -> list[Column]:
    """The columns of mesh_limit.md and mesh_limit.tex, one per mesh for its celerity."""
    closer = {None: "--", True: "yes", False: "no"}
    return [
        Column("nu", lambda r: f"{r['nu']:g}", r"$\nu$", lambda r: f"{r['nu']:g}"),
        Column("f", lambda r: f"{r['f']:.2f}", "$f$", lambda r: f"{r['f']:.2f}"),
        Column("group", lambda r: r["group"]),
        Column("published", lambda r: _f3(r["published"]), "published", lambda r: _num(r["published"])),
        *[Column(f"N={n}", lambda r, n=n: _f3(r.get(f"c_{n}")), f"$N{{=}}{n}$", lambda r, n=n: _num(r.get(f"c_{n}")))
          for n in meshes],
        Column("status", lambda r: r["status"], "status", lambda r: _STATUS_SHORT[r["status"]], "l"),
        Column("limit", lambda r: _f3(r["limit"]), r"$c_\infty$", lambda r: _num(r["limit"])),
        Column("order", lambda r: "" if r["order"] is None else f"{r['order']:.2f}", "$p$",
               lambda r: _num(r["order"], ".2f")),
        Column("step", lambda r: _f3(r["step"])),
        Column("dev 64 %", lambda r: _fp(r.get("dev_64")), r"dev.\ 64", lambda r: _pct(r.get("dev_64"))),
        Column("dev 128 %", lambda r: _fp(r.get("dev_128"))),
        Column("dev limit %", lambda r: _fp(r["dev_limit"]), r"dev.\ $\infty$", lambda r: _pct(r["dev_limit"])),
        Column("pub closer than 64", lambda r: "" if r["published_closer_than_64"] is None
               else str(r["published_closer_than_64"]).lower(), "closer",
               lambda r: closer[r["published_closer_than_64"]], "l"),
    ]


def latex(rows: list[dict[str, Any]], meshes: list[int]) -> str:
    return table_render.latex(columns(meshes), rows, "mesh-limit")


def markdown(rows: list[dict[str, Any]], meshes: list[int], summary: dict[str, Any]) -> str:
    return table_render.markdown(columns(meshes), rows, summary["verdict"].replace("\\,\\%", " %").replace("$", ""))


def mesh_limit_files(tables, paths, reference, tolerance) -> dict[str, str]:
    rows = mesh_limit_rows(tables, paths, reference, tolerance)
    meshes = sorted(tables)
    summary = summarize(rows, tolerance)
    summary["meshes"] = meshes
    columns = (["nu", "f", "group", "published"] + [f"c_{n}" for n in meshes] + [f"dev_{n}" for n in meshes]
               + ["finest_meshes", "status", "ratio", "order", "limit", "step", "dev_limit",
                  "published_closer_than_64", "within_64", "within_128", "within_limit"])
    return {"mesh_limit.csv": csv_text(columns, rows), "mesh_limit.md": markdown(rows, meshes, summary),
            "mesh_limit.tex": latex(rows, meshes),
            "mesh_limit_summary.json": json.dumps(summary, indent=2) + "\n"}
