#!/usr/bin/python3
"""Self-contained HTML summary of a study: Table 1 published vs regenerated, figures, provenance.

    study/scripts/report.py --manifest MANIFEST_JSON --out results/report.html

Snakemake's own `--report` needs internet in 7.21; this page needs nothing but the files the
manifest names (built by study/rules/report.smk):

    {"title": str, "tolerance": 0.05,
     "sections": [{"sweep": str, "description": str, "table": table1.csv of `analysis aggregate`,
                   "cells": [[nu, f], ...] (the sweep's points), "comparison": comparison.txt or null,
                   "figures": [PNG, ...], "runs": [{"name": str, "dir": results/<sweep>/<point>}, ...]},
                  ...]}

Figures are embedded as base64 PNG under a caption that says what they show (CAPTIONS, by the
figure's kind), for which run, and the script that drew it; wide figures (more than twice as wide as
high) take the page width, others half of it; a figure whose PNG carries its legend's counts (the
PNG's Description, JSON with a "legend" key: figures/phase_diagram.py) gets them as its `data-legend`
attribute, and each Table-1 row its cell and whether the category matches, so that a test can set
the two side by side. The Table 1 block appears only for sweeps that compare with the published
Table 1 (product `comparison`); its row colours are explained above it. The runs table has a fixed
layout at the page width (long run names wrap), so that it needs no horizontal scroll; other wide
tables scroll on a wide screen and wrap in print and on a narrow screen (under 60em).
Nothing is computed here: deviations, signs, regimes, categories and the celerity's window
sensitivity are the aggregate's columns or metrics.json keys, wall time and memory Snakemake's
benchmark of `simulate`; categories read as analysis.metrics.regime.CATEGORY_LABELS says.
"""

from __future__ import annotations

import argparse
import base64
import csv
import datetime
import html
import json
import math
import platform
import subprocess
import sys
from pathlib import Path

import analysis
from analysis.metrics.regime import category_label

#: metrics.json keys shown per run, when present, and their column headings.
RUN_KEYS = {"category": "category", "regime": "regime", "onset_time": "slip onset (s)",
            "min_T_over_N": "min T/N", "max_opening": "max opening (m)", "pulse_count": "major pulses",
            "energy_balance_error": "energy residual", "end_reason": "run ended by"}
#: Text columns of the runs table (left-aligned, may wrap).
TEXT_KEYS = ("category", "regime", "end_reason")

#: What a figure shows, by the start of its file name (figure_files in study/rules/common.smk).
CAPTIONS = {
    "spacetime_slip_velocity": "Slip velocity on the interface in space and time, with the slopes of c_l, c_s and the measured c_p",
    "spacetime_opening": "Opening of the interface in space and time, with the slopes of c_l, c_s and the measured c_p",
    "spacetime_state": "Stick, slip and open zones of the interface in space and time",
    "snapshots": "Material velocity in the deformed layer, slip velocity and opening along the interface at successive times",
    "phase_diagram": "Categories of the runs in the (nu, f) plane with the flutter wedge of steady sliding, and the "
                     "paper's Table-1 cells (arrow: direction of the published opening wave; not-equal sign: our "
                     "category differs)",
    "celerity_vs_nu": "Slip-front celerity against nu, regenerated (filled) and published (open), one colour and "
                      "marker per f, with c_s, sqrt(2) c_s and c_l",
    "deviation_map": "Deviation of the regenerated celerity from the published one for each published cell (framed: reproduced; crossed: another category than published)",
    "tn_curves": "Global friction ratio T/N against time",
    "tn_aligned": "T/N against the time since the start of each run's first frictional drop (x: the run stopped during the drop)",
    "pulse_spacing": "Number and spacing of the major slip pulses against lambda/H, with the Mach-wave spacing",
    "convergence": "Celerity, minimum T/N and maximum opening against the swept parameter",
    "contrast_phase_diagram": "Categories of the runs over (material contrast E_s/E, f) per nu, with c_p/c_s, over the "
                              "unstable ranges of steady sliding from the bimaterial theory",
}

CSS = """
body { font-family: sans-serif; max-width: 75em; margin: 1em auto; padding: 0 1em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.15em 0.5em; text-align: right; }
th { background: #f0f0f0; } td.l, th.l { text-align: left; }
tr.bad td { background: #fde0dc; } tr.far td { background: #fff4cc; }
figure { display: inline-block; margin: 0.5em 0; width: 49%; vertical-align: top; }
figure.wide { width: 100%; }
figure img { max-width: 100%; } figcaption { font-size: 0.85em; color: #444; }
div.scroll { max-width: 100%; overflow-x: auto; }
table.runs { table-layout: fixed; width: 100%; font-size: 0.8em; }
table.runs th, table.runs td { overflow-wrap: break-word; white-space: normal; padding: 0.1em 0.3em; }
table.runs th:first-child, table.runs td:first-child { width: 17%; overflow-wrap: anywhere; }
span.key { padding: 0 0.4em; border: 1px solid #ccc; }
@media print, (max-width: 60em) { div.scroll { overflow: visible; } table { font-size: 0.7em; }
  th, td { white-space: normal; padding: 0.1em 0.25em; } td.l { overflow-wrap: anywhere; } }
pre { background: #f7f7f7; padding: 0.5em; overflow-x: auto; font-size: 0.85em; }
"""


def _number(text: str) -> float:
    """A CSV cell as float; empty or NA -> nan (Snakemake's benchmark writes NA for what it could not
    sample, e.g. the memory of a run that ended before its first sample)."""
    text = (text or "").strip()
    return float(text) if text and text != "NA" else math.nan


def read_csv(path: str) -> list[dict]:
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def read_json(path: Path) -> dict:
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {}


def read_benchmark(path: Path) -> dict:
    """Snakemake benchmark TSV (first row): wall seconds `s` and `max_rss` (MB)."""
    try:
        rows = list(csv.DictReader(path.open(), delimiter="\t"))
    except OSError:
        return {}
    return rows[0] if rows else {}


def fmt(value, digits: int = 4) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.{digits}g}"
    return html.escape(str(value))


def png_size(path: str) -> tuple[int, int]:
    """(width, height) in pixels from a PNG's header (IHDR)."""
    with open(path, "rb") as stream:
        header = stream.read(24)
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def png_description(path: str) -> str | None:
    """The text of a PNG's Description chunk (tEXt), if it has one."""
    data = Path(path).read_bytes()
    at = 8  # after the signature: length, type, data, CRC per chunk
    while at + 8 <= len(data):
        length, kind = int.from_bytes(data[at:at + 4], "big"), data[at + 4:at + 8]
        if kind == b"tEXt":
            key, _, text = data[at + 8:at + 8 + length].partition(b"\0")
            if key == b"Description":
                return text.decode("latin-1")
        if kind == b"IEND":
            break
        at += 12 + length
    return None


def celerity_text(values: dict) -> str:
    """c_p (m/s) +- its change with the measurement window, and 'unsteady' when the fronts were."""
    c = values.get("celerity")
    c = _number(c) if isinstance(c, str) else c
    if not isinstance(c, (int, float)) or not math.isfinite(c):
        return ""
    sensitivity = values.get("celerity_window_sensitivity")
    sensitivity = _number(sensitivity) if isinstance(sensitivity, str) else sensitivity
    text = f"{c:.4g}"
    if isinstance(sensitivity, (int, float)) and math.isfinite(sensitivity):
        text += f" &plusmn; {abs(sensitivity * c):.2g}"
    return text + (" (unsteady)" if values.get("celerity_quality") == "unsteady" else "")


def comparison_rows(table_path: str, cells: list[list[float]]) -> list[dict]:
    """Rows of the aggregate's table1.csv (published cells) that this sweep ran."""
    ran = {(round(nu, 6), round(f, 6)) for nu, f in cells}
    return [row for row in read_csv(table_path)
            if (round(_number(row["nu"]), 6), round(_number(row["f"]), 6)) in ran]


def table_html(rows: list[dict], tolerance: float) -> str:
    """Published vs regenerated celerity, from the aggregate's columns (nothing recomputed)."""
    if not rows:
        return "<p>No published cell among this sweep's points.</p>"
    reproduced = sum(r.get("reproduced") == "true" for r in rows)
    within = sum(r.get("within_tol") == "true" for r in rows)
    measured = sum(bool((r.get("celerity") or "").strip()) for r in rows)
    wrong = sum(r.get("sign_match") == "false" for r in rows)
    other = sum(r.get("category_match") == "false" for r in rows)
    out = [f"<p>{len(rows)} published cells run, {measured} with a measured celerity: {reproduced} "
           f"reproduced (within {tolerance:.0%} with the published sign, regime and outcome), {within} within "
           f"{tolerance:.0%} whatever their outcome, {wrong} with the wrong sign, {other} with another "
           "outcome than the published opening wave.</p>",
           "<p>Row colours: <span class='key' style='background:#fde0dc'>red</span> the sign or the "
           "outcome differs from the published one, or no celerity was measured; "
           "<span class='key' style='background:#fff4cc'>yellow</span> the published sign and outcome but "
           f"not reproduced (deviation over {tolerance:.0%} or another regime); no colour: reproduced.</p>",
           "<div class=scroll><table class=table1><tr><th>nu</th><th>f</th><th>published c_p (m/s)</th>"
           "<th>regenerated c_p (m/s) &plusmn; window</th><th>deviation</th><th class=l>regime (published)</th>"
           "<th class=l>category (published)</th><th>min T/N</th></tr>"]
    for r in rows:
        deviation = _number(r.get("deviation_rel", ""))
        css = ("bad" if r.get("sign_match") == "false" or r.get("category_match") == "false"
               or not (r.get("celerity") or "").strip() else
               "far" if r.get("reproduced") != "true" else "")
        dev = "" if math.isnan(deviation) else f"{100 * deviation:+.1f} %"
        category = html.escape(category_label(r.get("category") or ""))
        if r.get("category_match") == "false":
            category += f" ({html.escape(category_label(r.get('published_category') or ''))})"
        match = "true" if r.get("category_match") == "true" else "false"
        out.append(f"<tr class='{css}' data-cell='{fmt(r['nu'])},{fmt(r['f'])}' data-category-match='{match}' "
                   f"data-published='{fmt(_number(r['published']))}'><td>{fmt(r['nu'])}</td><td>{fmt(r['f'])}</td>"
                   f"<td>{fmt(_number(r['published']))}</td><td>{celerity_text(r)}</td>"
                   f"<td>{dev}</td><td class=l>{fmt(r.get('regime'))} ({fmt(r.get('published_regime'))})</td>"
                   f"<td class=l>{category}</td><td>{fmt(_number(r.get('min_T_over_N', '')), 3)}</td></tr>")
    out.append("</table></div>")
    return "\n".join(out)


def figure_caption(stem: str) -> str:
    """What the figure shows (CAPTIONS) and for which run (the rest of its name)."""
    kind = next((k for k in sorted(CAPTIONS, key=len, reverse=True) if stem.startswith(k)), None)
    if kind is None:
        return stem
    run = stem[len(kind):].lstrip("_")
    return CAPTIONS[kind] + (f", run {run}" if run else "") + "."


def figure_html(path: str) -> str:
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    stem = Path(path).stem
    script = "figures/" + ("snapshots" if stem.startswith("snapshots_") else
                           "spacetime" if stem.startswith("spacetime_") else stem) + ".py"
    width, height = png_size(path)
    css = " class=wide" if width > 2 * height else ""
    try:
        legend = json.loads(png_description(path) or "{}").get("legend")
    except ValueError:
        legend = None
    if legend is not None:
        css += f" data-legend='{html.escape(json.dumps(legend), quote=True)}'"
    return (f"<figure{css}><img alt='{html.escape(stem)}' src='data:image/png;base64,{data}'>"
            f"<figcaption>{html.escape(figure_caption(stem))} Drawn by {script} "
            f"(<code>{html.escape(path)}</code>).</figcaption></figure>")


def stop_after_opening(metrics: dict, time_config: dict) -> str:
    """The configured stop after the first opening, for a run that opened; a run that never opened
    ran to its end time, so the setting did not act."""
    if metrics.get("opening") is not True:
        return "never opened"
    return fmt(time_config.get("stop_after_opening"))


def runs_html(runs: list[dict]) -> str:
    out = ["<div class=scroll><table class=runs><tr><th class=l>run</th><th>c_p (m/s) &plusmn; window</th>"
           + "".join(f"<th{' class=l' if k in TEXT_KEYS else ''}>{heading}</th>" for k, heading in RUN_KEYS.items())
           + "<th>end time (s)</th><th>stop after opening (s)</th><th>wall (s)</th><th>memory (MB)</th></tr>"]
    total = 0.0
    for run in runs:
        directory = Path(run["dir"])
        metrics = read_json(directory / "metrics.json")
        config = read_json(directory / "config.json").get("time", {})
        bench = read_benchmark(directory / "logs" / "simulate.benchmark.tsv")
        wall = _number(bench.get("s", ""))
        total += wall if math.isfinite(wall) else 0.0
        values = {**metrics, "category": category_label(metrics["category"]) if "category" in metrics else None}
        cells = "".join(f"<td{' class=l' if k in TEXT_KEYS else ''}>{fmt(values.get(k))}</td>" for k in RUN_KEYS)
        out.append(f"<tr><td class=l>{html.escape(run['name'])}</td><td>{celerity_text(metrics)}</td>{cells}<td>{fmt(config.get('t_end'), 6)}</td>"
                   f"<td>{stop_after_opening(metrics, config)}</td><td>{fmt(wall)}</td>"
                   f"<td>{fmt(_number(bench.get('max_rss', '')))}</td></tr>")
    out.append("</table></div>")
    out.append("<p>Energy residual: the energy balance error relative to the energy that flowed through "
               "the run; with hht_alpha &gt; 0 it is the algorithmic dissipation of HHT (measured term by "
               "term against the residual in the reproduction report, section &ldquo;What the energy residual "
               "is&rdquo;, which <code>snakemake -c2 all</code> builds as paper/reproduction.pdf; "
               "docs/energy-balance.md). "
               "Wall time and memory: Snakemake's benchmark of the solver.</p>")
    out.insert(0, f"<p>{len(runs)} runs, {total:.0f} s of solver wall time in all.</p>")
    return "\n".join(out)


def provenance_html(runs: list[dict]) -> str:
    """Project version, pipeline commit and what wrote the runs (solver version and commit as the metrics report them)."""
    root = Path(__file__).resolve().parents[2]
    try:
        commit = subprocess.run(["git", "-C", str(root), "describe", "--always", "--dirty"],
                                capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown (not a git checkout)"
    writers = set()
    for run in runs:
        metrics = read_json(Path(run["dir"]) / "metrics.json")
        writers.add(tuple(str(metrics.get(k, "?")) for k in ("slidewave_version", "git_commit")))
    items = [f"generated {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M UTC}",
             f"slidewave {html.escape(analysis.__version__)} (analysis), pipeline commit {html.escape(commit)}",
             f"Python {platform.python_version()} on {html.escape(platform.node())}"]
    items += [f"runs written by slidewave {html.escape(v)} (commit {html.escape(c)})" for v, c in sorted(writers)]
    return "<ul>" + "".join(f"<li>{item}</li>" for item in items) + "</ul>"


def render(manifest: dict) -> str:
    tolerance = manifest.get("tolerance", 0.05)
    all_runs = [run for section in manifest["sections"] for run in section["runs"]]
    body = [f"<h1>{html.escape(manifest['title'])}</h1>", provenance_html(all_runs)]
    for section in manifest["sections"]:
        body.append(f"<h2>Sweep <code>{html.escape(section['sweep'])}</code></h2>")
        if section.get("description"):
            body.append(f"<p>{html.escape(section['description'])}</p>")
        if section.get("comparison"):  # a sweep that covers the published Table 1
            body.append("<h3>Table 1: published vs regenerated</h3>")
            body.append(table_html(comparison_rows(section["table"], section["cells"]), tolerance))
            text = Path(section["comparison"]).read_text()
            body.append(f"<details><summary>analysis compare</summary><pre>{html.escape(text)}</pre></details>")
        if section.get("figures"):
            body.append("<h3>Figures</h3>" + "".join(figure_html(p) for p in section["figures"]))
        body.append("<h3>Runs</h3>" + runs_html(section["runs"]))
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(manifest['title'])}"
            f"</title><style>{CSS}</style></head><body>{''.join(body)}</body></html>\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--manifest", required=True, help="JSON text (see the module docstring)")
    parser.add_argument("--out", required=True, type=Path, help="HTML file to write")
    args = parser.parse_args(argv)
    page = render(json.loads(args.manifest))
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(page)
    return 0


if __name__ == "__main__":
    sys.exit(main())
