"""One-page HTML summary of an explored point (`snakemake explore`, study/rules/explore.smk).

    python3 study/scripts/explore_summary.py --metrics results/explore/<point>/metrics.json \
        --figures phase.png tn.png maps... --out results/explore/summary.html

The point's parameters and outcome from its metrics.json (the measurements the analysis made; an
incomplete run or a missing measurement says so), then the figures, embedded as PNG so that the
page travels alone. On screen the maps take half the width each; printed, the page fits one A4
landscape sheet.
"""

from __future__ import annotations

import argparse
import base64
import html
import json
import math
import sys
from pathlib import Path

#: (metrics.json key, label, unit) shown in the table, in order.
ROWS = (
    ("category", "category", ""),
    ("celerity", "slip-front celerity c_p", "m/s"),
    ("celerity_quality", "celerity quality", ""),
    ("onset_time", "slip onset", "s"),
    ("first_opening_time", "first opening", "s"),
    ("max_opening", "max opening u_y", "m"),
    ("min_T_over_N", "min T/N", ""),
    ("first_drop_bottom_T_over_N", "T/N at the bottom of the first drop", ""),
    ("pulse_count", "pulses per period", ""),
    ("end_reason", "end of the run", ""),
)
PARAMETERS = ("nu", "f", "V0_over_cs", "lambda_over_H", "elements_per_H", "rho", "integration",
              "dt_times_cs", "seed")

CSS = """
@page { size: A4 landscape; margin: 8mm; }
body { font-family: sans-serif; margin: 0.5em 1em; color: #222; font-size: 12px; }
h1 { font-size: 16px; margin: 0.2em 0; } p { margin: 0.2em 0; }
.top { display: flex; gap: 1em; align-items: flex-start; }
table { border-collapse: collapse; } td, th { border: 1px solid #ccc; padding: 0.1em 0.4em; }
th { text-align: left; background: #f0f0f0; font-weight: normal; }
.figures { display: flex; flex-wrap: wrap; gap: 0.4em; }
.figures img { width: 49%; } .top img { height: 330px; }
@media print { .figures img { width: 24%; } .top img { height: 250px; } }
.warn { background: #fde0dc; padding: 0.2em 0.4em; }
"""


def fmt(value, unit: str = "") -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "not measured"
    if isinstance(value, float):
        text = f"{value:.4g}"
    else:
        text = str(value).replace("_", " ")
    return f"{text} {unit}".strip()


def image(path: str) -> str:
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    return f"<img alt='{html.escape(Path(path).stem)}' src='data:image/png;base64,{data}'>"


def render(metrics: dict, figures: list[str]) -> str:
    point = ", ".join(f"{k} = {metrics[k]:g}" if isinstance(metrics.get(k), float) else f"{k} = {metrics[k]}"
                      for k in PARAMETERS if k in metrics)
    rows = "".join(f"<tr><th>{html.escape(label)}</th><td>{html.escape(fmt(metrics.get(key), unit))}</td></tr>"
                   for key, label, unit in ROWS)
    c_s = metrics.get("c_s")
    if metrics.get("celerity") is not None and c_s:
        rows += f"<tr><th>c_p / c_s</th><td>{metrics['celerity'] / c_s:.4g}</td></tr>"
    warning = ""
    if not metrics.get("complete", True):
        warning = (f"<p class='warn'>The run did not complete ({html.escape(str(metrics.get('end_reason')))}):"
                   " its measurements cover only the simulated time.</p>")
    phase, *rest = figures
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>slidewave explore: "
            f"{html.escape(point)}</title><style>{CSS}</style></head><body>"
            f"<h1>slidewave explore: {html.escape(point)}</h1>"
            f"<p>From {html.escape(str(metrics.get('source', '')))} (solver {html.escape(str(metrics.get('slidewave_version')))},"
            f" commit {html.escape(str(metrics.get('git_commit')))}).</p>{warning}"
            f"<div class='top'><table>{rows}</table>{image(phase)}</div>"
            f"<div class='figures'>{''.join(image(p) for p in rest)}</div></body></html>\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--metrics", required=True, help="metrics.json of the explored run")
    parser.add_argument("--figures", nargs="+", required=True,
                        help="PNG figures: the phase-diagram placement first, then the others")
    parser.add_argument("--out", required=True, type=Path, help="summary.html to write")
    args = parser.parse_args(argv)
    try:
        metrics = json.loads(Path(args.metrics).read_text())
        page = render(metrics, args.figures)
    except (OSError, json.JSONDecodeError) as err:
        print(f"explore_summary.py: error: {err}", file=sys.stderr)
        return 2
    temporary = args.out.with_suffix(".tmp")
    temporary.write_text(page)
    temporary.replace(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
