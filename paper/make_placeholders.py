#!/usr/bin/python3
"""Fill paper/generated/ with placeholders for whatever the pipeline has not produced yet, so that
the report compiles before any run exists.

    paper/make_placeholders.py [--force] [--dir paper/generated]

Writes numbers.tex and energy_evidence.tex (every macro \\notavailable), table1.tex (an empty
table), claims.tex (the verdict table, empty) and conclusions.tex (a line saying so) when absent, or
always with --force. Figures need no placeholder: reproduction.tex draws a
framed note in place of a generated/<name>.pdf that does not exist. Existing generated files are
never touched without --force.
"""
import argparse
import os
import sys

from numbers_tex import ENERGY_MACRO_NAMES, MACRO_NAMES, render

TABLE = """% Placeholder written by paper/make_placeholders.py: run make_table1.py on table1.csv.
\\begin{tabular}{rrrrr}
\\toprule
 & & \\multicolumn{2}{c}{$c_p$ (m/s)} & deviation \\\\
\\cmidrule(lr){3-4}
$\\nu$ & $f$ & published & regenerated & (\\%) \\\\
\\midrule
\\multicolumn{5}{c}{\\notavailable{} (Table~1 not generated yet)} \\\\
\\bottomrule
\\end{tabular}
"""

CLAIMS = """% Placeholder written by paper/make_placeholders.py: run paper/make_claims.py.
\\begin{longtable}{@{}ll@{}}
\\caption{Verdict on each claim of the paper: \\notavailable{} (not generated yet).}\\label{tab:claims} \\\\
\\toprule claim of the paper & verdict \\\\ \\midrule
\\multicolumn{2}{c}{\\notavailable{} (paper/make\\_claims.py has not run)} \\\\
\\bottomrule
\\end{longtable}
"""
CONCLUSIONS = """% Placeholder written by paper/make_placeholders.py: run paper/make_claims.py.
\\notavailable{} (the conclusions are drawn from the verdicts of paper/make\\_claims.py, not generated yet).
"""


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--dir", default=os.path.join(here, "generated"),
                        help="folder of the generated files (default: paper/generated)")
    parser.add_argument("--force", action="store_true", help="overwrite existing files")
    args = parser.parse_args(argv)
    os.makedirs(args.dir, exist_ok=True)
    placeholders = {name: r"\notavailable" for name in MACRO_NAMES}
    files = {"numbers.tex": "\\providecommand{\\notavailable}{\\textit{n/a}}\n"
                            + render(placeholders, ["nothing: placeholders"]),
             "table1.tex": TABLE,
             "claims.tex": CLAIMS,
             "conclusions.tex": CONCLUSIONS,
             "energy_evidence.tex": render({name: r"\notavailable" for name in ENERGY_MACRO_NAMES},
                                           ["nothing: placeholders"], script="paper/make_energy_evidence.py")}
    for name, text in files.items():
        path = os.path.join(args.dir, name)
        if os.path.exists(path) and not args.force:
            print(f"kept {path}")
            continue
        with open(path, "w") as stream:
            stream.write(text)
        print(f"wrote placeholder {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
