#!/usr/bin/python3
"""Rebuild the sweep tables the paper reads (results/<sweep>/table/) from the committed
study/results/<sweep>/all_metrics.csv, with the current analysis: a machine without the runs (no
HDF5, no metrics.json) can build the paper from the committed measurements.

    paper/tables_from_published.py --published study/results \\
        --reference study/reference/table1_celerity.csv --tolerance 0.05 -o results

Each row of all_metrics.csv is one run's scalar metrics; they are aggregated again by
`analysis.tables.aggregate.aggregate` (Table 1 flags), not edited. Table 1 of a sweep takes
the runs that its committed table1.csv compared (same cell, celerity and min T/N), so the selection is the one
the pipeline made. Nothing is measured here and nothing under study/results is written.
"""
import argparse
import math
import sys
from pathlib import Path

from analysis.core.errors import InputError
from analysis.core.table_csv import read_table
from analysis.tables import aggregate as agg
from analysis.tables.reference import cell_key, read_reference

def as_metrics(row):
    """A committed all_metrics.csv row as the metrics dict it was written from (nan -> None)."""
    return {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in row.items()}


def same(value, written):
    """A metric equals its value as table1.csv wrote it (6 significant digits; empty = None)."""
    if value is None or written is None or (isinstance(written, float) and math.isnan(written)):
        return value is None and (written is None or math.isnan(written))
    return math.isclose(value, written, rel_tol=1e-5)


def table_runs(runs, table_path):
    """The runs the committed table1.csv compared: one per cell, matched by cell and celerity."""
    chosen = []
    for cell in read_table(table_path, ("nu", "f", "celerity", "min_T_over_N")):
        at = [m for m in runs if cell_key(m["nu"], m["f"]) == cell_key(cell["nu"], cell["f"])]
        for key in ("celerity", "min_T_over_N"):
            if len(at) > 1:
                at = [m for m in at if same(m[key], cell[key])]
        if len(at) > 1:
            raise InputError(f"{table_path}: cell nu={cell['nu']:g} f={cell['f']:g} matches {len(at)} runs")
        chosen += at
    return chosen


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--published", type=Path, required=True, help="study/results")
    parser.add_argument("--reference", type=Path, required=True, help="the published Table 1")
    parser.add_argument("--tolerance", type=float, required=True)
    parser.add_argument("-o", "--output", type=Path, required=True, help="results folder to fill")
    args = parser.parse_args(argv)
    try:
        reference = read_reference(args.reference)
        sweeps = sorted(p.parent for p in args.published.glob("*/all_metrics.csv"))
        if not sweeps:
            raise InputError(f"{args.published}: no <sweep>/all_metrics.csv")
        for folder in sweeps:
            runs = [as_metrics(r) for r in read_table(folder / "all_metrics.csv", ("nu", "f", "celerity"))]
            files, _ = agg.aggregate(runs, table_runs(runs, folder / "table1.csv"), reference,
                                     args.tolerance)
            out = args.output / folder.name / "table"
            out.mkdir(parents=True, exist_ok=True)
            for name, text in files.items():
                (out / name).write_text(text)
            print(f"{out}: {len(runs)} runs")
    except InputError as err:
        print(f"tables_from_published.py: error: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
