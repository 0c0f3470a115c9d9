#!/usr/bin/python3
"""A LaTeX table of chosen per-run metrics from one or more sweeps (the report's sweep tables).

    paper/make_sweep_table.py 'v* = 1 m/s=results/regularized_fast/table/all_metrics.csv' ... \\
        --columns elements_per_H celerity category min_T_over_N end_reason -o generated/regularized.tex

Each input is LABEL=all_metrics.csv (one row per run, written by `python3 -m analysis aggregate`);
with more than one input each input's rows follow a heading row with its label. Rows keep the input order and, within
an input, are sorted by the listed parameter columns (COLUMNS entries of kind 'param'). Column
headings and number formats come from COLUMNS, so that every table of the report spells a quantity
the same way; an empty or non-finite value prints as a dash, a missing column is an error. Only
selection and formatting happen here: every number, derived ones included (celerity_over_cs,
first_drop_start_after_onset, first_drop_duration), comes from the inputs.

Incomplete measurements are marked, never shown as results: a value of the first frictional drop
(DROP_COLUMNS) from a run that stopped before T/N recovered (derived column first_drop_complete
false) carries (s), and every value of a run that did not complete (complete false) carries (i);
a note under the table says what the marks mean. A heading with '|' is set on two lines.
"""

from __future__ import annotations

import argparse
import math
import sys

from analysis.core.atomic import write_file
from table_io import InputError, label, labelled_paths, latex_number, read_rows

#: column -> (heading, kind, format): kind 'param' sorts rows; format is a str.format spec or
#: 'text' / 'yesno' / 'label' (underscores become spaces).
COLUMNS = {
    "nu": (r"$\nu$", "param", "{:.2f}"),
    "f": (r"$f$", "param", "{:.2f}"),
    "V0_over_cs": (r"$V_0/c_s$", "param", "{:.0e}"),
    "pc_velocity": (r"$v^*$ (m/s)", "param", "{:g}"),
    "lambda_over_H": (r"$\lambda/H$", "param", "{:g}"),
    "elements_per_H": (r"$H/h$", "param", "{:.0f}"),
    "rho": (r"$\rho$ (kg/m$^3$)", "param", "{:g}"),
    "dt_times_cs": (r"$\Delta t\,c_s$ (m)", "param", "{:g}"),
    "seed": ("seed", "param", "{:.0f}"),
    "celerity": (r"$c_p$ (m/s)", "value", "{:.3f}"),
    "celerity_over_cs": (r"$c_p/c_s$", "value", "{:.3f}"),
    "regime": ("regime", "value", "label"),
    "category": ("category", "value", "label"),
    "opening": ("opening", "value", "yesno"),
    "inversion": ("inversion", "value", "yesno"),
    "max_opening": (r"max|$u_y$ (m)", "value", "{:.2g}"),
    "min_T_over_N": (r"min $T/N$", "value", "{:.2f}"),
    "onset_time": (r"onset (s)", "value", "{:.0f}"),
    "localization_time": (r"localized|(s)", "value", "{:.0f}"),
    "first_opening_time": (r"first|opening (s)", "value", "{:.0f}"),
    "first_drop_start_after_onset": (r"drop after|onset (s)", "value", "{:.0f}"),
    "first_drop_duration": (r"drop|duration (s)", "value", "{:.0f}"),
    "first_drop_start_T_over_N": (r"$T/N$ at|drop start", "value", "{:.2f}"),
    "first_drop_bottom_T_over_N": (r"$T/N$ at|drop bottom", "value", "{:.2f}"),
    "n_drops": ("drops", "value", "{:.0f}"),
    "later_drops_start_T_over_N_median": (r"later drops|start at $T/N$", "value", "{:.2f}"),
    "pulse_count": ("major pulses", "value", "{:.0f}"),
    "pulse_count_all": ("all fronts", "value", "{:.0f}"),
    "pulse_spacing": (r"spacing $l$ (m)", "value", "{:.1f}"),
    "pulse_spacing_theory": (r"$2H\sqrt{c_p^2/c_s^2-1}$ (m)", "value", "{:.1f}"),
    "friction_work_ratio_opening": (r"$\Delta D_f/\Delta W$ opening", "value", "{:.2f}"),
    "dissipative_friction_opening": (r"$\mu_{\rm diss}$ opening", "value", "{:.2f}"),
    "dissipative_friction_before_opening": (r"$\mu_{\rm diss}$ before", "value", "{:.2f}"),
    "end_reason": ("run|ended by", "value", "label"),
}
#: Values of the first frictional drop: unfinished when the run stopped during it.
DROP_COLUMNS = ("first_drop_duration", "first_drop_bottom_T_over_N", "min_T_over_N")
NOTES = {"(s)": "the run stopped during the first drop (before $T/N$ recovered): the value reached then",
         "(i)": "the run did not complete"}


def cell(value, fmt: str) -> str:
    if isinstance(value, bool):
        return "yes" if value else "no"
    if value in ("", None) or (isinstance(value, float) and not math.isfinite(value)):
        return "--"
    if fmt == "label":
        return label(value)
    if fmt in ("text", "yesno"):
        return str(value).replace("_", r"\_")
    if not isinstance(value, float):
        return "--"
    return f"${latex_number(fmt.format(value))}$"


def heading(text: str) -> str:
    """A column heading; '|' breaks it into two centred lines."""
    if "|" not in text:
        return text
    return r"\begin{tabular}[b]{@{}c@{}}" + text.replace("|", r"\\") + r"\end{tabular}"


def marks(row: dict, column: str) -> str:
    """The NOTES marks of one value (see the module docstring)."""
    out = ""
    if column in DROP_COLUMNS and row.get("first_drop_complete") is False:
        out += "(s)"
    if row.get("complete") is False:
        out += "(i)"
    return out


def read(path: str, columns: list[str]) -> list[dict]:
    """The rows of one all_metrics.csv; InputError when it lacks a column of the table (derived columns
    such as celerity_over_cs come from `analysis aggregate`: rerun it for an older table)."""
    needed = list(columns) + ["complete"]
    if any(c in DROP_COLUMNS for c in columns):
        needed.append("first_drop_complete")
    return read_rows(path, needed)


def table(sets: list[tuple[str, list[dict]]], columns: list[str]) -> str:
    labelled = len(sets) > 1
    params = [c for c in columns if COLUMNS[c][1] == "param"]
    lines = [r"\begin{tabular}{" + "r" * len(columns) + "}", r"\toprule",
             " & ".join(heading(COLUMNS[c][0]) for c in columns) + r" \\"]
    used = set()
    for set_label, rows in sets:
        lines.append(r"\midrule")
        if labelled:  # a heading row per input, so that the label takes no column
            lines.append(rf"\multicolumn{{{len(columns)}}}{{l}}{{\emph{{{set_label}}}}} \\")
        rows = sorted(rows, key=lambda r: tuple(r.get(p) if isinstance(r.get(p), float) else math.inf
                                                for p in params))
        for r in rows:
            cells = []
            for c in columns:
                mark = marks(r, c) if cell(r.get(c), COLUMNS[c][2]) != "--" else ""
                used.update(m for m in NOTES if m in mark)
                cells.append(cell(r.get(c), COLUMNS[c][2]) + (rf"\textsuperscript{{{mark}}}" if mark else ""))
            lines.append(" & ".join(cells) + r" \\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    if used:  # below the tabular, wrapped at the text width
        lines.append(r"\par\smallskip{\footnotesize " + "; ".join(f"{m}: {NOTES[m]}" for m in sorted(used)) + r".\par}")
    lines.append("")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("inputs", nargs="+", metavar="LABEL=ALL_METRICS_CSV")
    parser.add_argument("--columns", nargs="+", required=True, choices=sorted(COLUMNS), metavar="COLUMN",
                        help=f"columns, in order; one of: {', '.join(COLUMNS)}")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args(argv)
    try:
        sets = [(label, read(path, args.columns)) for label, path in labelled_paths(args.inputs, "ALL_METRICS_CSV")]
    except (ValueError, InputError) as error:
        print(f"make_sweep_table.py: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:
        print(f"make_sweep_table.py: error: {error.filename}: cannot read ({error.strerror})", file=sys.stderr)
        return 2
    write_file(args.output, table(sets, args.columns))
    return 0


if __name__ == "__main__":
    sys.exit(main())
