#!/usr/bin/python3
"""The few lines scripts/study.sh ends with: what a sweep holds and where its report is.

    study/scripts/study_summary.py --sweep quick [--results results] [--snakemake-log LOG]

Prints the runs of the sweep (the rows of its all_metrics.csv; the runs live in results/runs/, shared
between sweeps; and how many of them this Snakemake call made, from its log's job listing), the published Table-1 cells the sweep ran and how many it reproduces (the aggregate's
table1.csv and summary.json: nothing is recomputed), and the path of the sweep's report. A file the
sweep should have and lacks is an error (exit 2), so a broken study never ends on a clean summary.
"""
from __future__ import annotations

import argparse
import csv
import json
import re
import sys
from pathlib import Path


def runs_made(log: Path | None) -> int | None:
    """simulate jobs that the Snakemake call of this log ran (None without a log)."""
    if log is None or not log.is_file():
        return None
    return len(re.findall(r"^(?:local)?rule simulate:", log.read_text(errors="replace"), re.M))


def summary_lines(sweep: str, results: Path, log: Path | None) -> list[str]:
    table_dir = results / sweep / "table"
    table, summary, report = table_dir / "table1.csv", table_dir / "summary.json", results / sweep / "report.html"
    runs = table_dir / "all_metrics.csv"
    for path in (table, summary, runs, report):
        if not path.is_file():
            raise FileNotFoundError(f"{path} is missing: the study did not finish")
    with open(runs, newline="") as stream:
        n_runs = sum(1 for _ in csv.DictReader(stream))
    made = runs_made(log)
    made_text = ("" if made is None else " (all made now)" if made == n_runs else
                 " (all up to date)" if made == 0 else f" ({made} made now, the others up to date)")
    lines = [f"runs:    {n_runs} in {results / 'runs'}/ (listed in {runs}){made_text}"]
    tolerance = json.loads(summary.read_text())["tolerance"]
    with open(table, newline="") as stream:
        rows = [r for r in csv.DictReader(stream) if (r.get("category") or "").strip()]
    reproduced = sum(r.get("reproduced") == "true" for r in rows)
    measured = sum(bool((r.get("celerity") or "").strip()) for r in rows)
    lines.append(f"Table 1: {len(rows)} published cells run, {measured} with a measured celerity, {reproduced} "
                 f"reproduced (within {tolerance:.0%} with the published sign, regime and outcome): {table}")
    lines.append(f"report:  {report.resolve()}")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sweep", required=True, help="the sweep (e.g. quick)")
    parser.add_argument("--results", type=Path, default=Path("results"), help="results folder (default: results)")
    parser.add_argument("--snakemake-log", type=Path, help="the output of the Snakemake call (runs made now)")
    args = parser.parse_args(argv)
    try:
        print("\n".join(summary_lines(args.sweep, args.results, args.snakemake_log)))
    except (OSError, ValueError, KeyError) as err:
        print(f"study_summary.py: error: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
