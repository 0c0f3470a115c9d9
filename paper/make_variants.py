"""Table of method variants over the published Table-1 cells (reproduction campaign).

Usage: make_variants.py LABEL=results/<sweep>/table/summary.json ... -o generated/variants.tex

Each summary.json is what `python3 -m analysis aggregate` wrote for one variant sweep (the 38 published
cells at one resolution with one modelling choice changed). The table lists, per variant, the cells
measured, the published signs, regimes and outcomes (categories) kept, the cells reproduced (within
tolerance with the published sign, regime and outcome) and the median deviation, so that the report
quotes no hand-typed number. Labels are plain text from study/config.yaml; `dt`, `c_s` and `2x2`
are set as symbols, and the label column wraps.
"""

from __future__ import annotations

import argparse
import json
import sys

from analysis.core.atomic import write_file
from table_io import labelled_paths


SYMBOLS = {"dt": r"$\Delta t$", "c_s": r"$c_s$", "2x2": r"$2\times2$"}


def typeset(label: str) -> str:
    """A plain-text label as LaTeX: underscores escaped, then SYMBOLS set as math."""
    text = label.replace("_", r"\_")
    for plain, symbol in SYMBOLS.items():
        text = text.replace(plain.replace("_", r"\_"), symbol)
    return text


def row(label: str, summary: dict) -> str:
    median = 100 * summary["median_abs_deviation"]
    return (f"{label} & {summary['cells_compared']} & {summary['sign_matches']} & "
            f"{summary['regime_matches']} & {summary['category_matches']} & {summary['reproduced']} & "
            f"{median:.1f}\\,\\% \\\\")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("variants", nargs="+", metavar="LABEL=SUMMARY_JSON")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args(argv)
    try:
        pairs = labelled_paths(args.variants, "SUMMARY_JSON")
    except ValueError as error:
        print(f"make_variants.py: error: {error}", file=sys.stderr)
        return 2
    rows, tolerances = [], set()
    for label, path in pairs:
        try:
            with open(path) as stream:
                summary = json.load(stream)
            rows.append(row(typeset(label), summary))
            tolerances.add(summary["tolerance"])
        except (OSError, KeyError, ValueError) as error:
            print(f"make_variants.py: error: {path}: {error}", file=sys.stderr)
            return 2
    if len(tolerances) != 1:
        print(f"make_variants.py: error: the summaries were made with different tolerances {sorted(tolerances)}",
              file=sys.stderr)
        return 2
    lines = [r"\begin{tabular}{p{0.3\textwidth}rrrrrr}", r"\toprule",
             r"variant & measured & signs & regimes & outcomes & "
             rf"\begin{{tabular}}[b]{{@{{}}c@{{}}}}reproduced\\({100 * tolerances.pop():g}\,\%)\end{{tabular}} & "
             r"\begin{tabular}[b]{@{}c@{}}median\\$|$dev.$|$\end{tabular} \\",
             r"\midrule", *rows]
    lines += [r"\bottomrule", r"\end{tabular}", ""]
    write_file(args.output, "\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
