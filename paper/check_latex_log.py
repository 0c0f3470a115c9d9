#!/usr/bin/python3
"""Fail a LaTeX build whose output a reader cannot trust: content wider than the text (an overfull
box beyond a few points runs into the margin or off the page), references or citations left
undefined, or a number of generated/numbers.tex left as a placeholder (\\notavailable, which only
make_placeholders.py writes).

    paper/check_latex_log.py paper/reproduction.log [--numbers paper/generated/numbers.tex ...] [--max-overfull-pt 3]

Exit 0 when the log is clean, 1 with one line per problem otherwise (the rule `paper` and
`make -C paper` run it after latexmk, so the build fails).
"""
import argparse
import re
import sys

OVERFULL = re.compile(r"^Overfull \\[hv]box \((?P<pt>[\d.]+)pt too (?:wide|high)\) (?P<where>.*)$")
UNDEFINED = re.compile(r"^LaTeX Warning: (?:Reference|Citation) .* undefined")


def problems(log: str, max_overfull_pt: float) -> list[str]:
    """The overfull boxes wider than max_overfull_pt and the undefined references of a LaTeX log,
    each named by its input file (the last one opened before it) and line range."""
    found, current = [], "?"
    for line in log.splitlines():
        opened = re.findall(r"\(\.?/?([\w./-]+\.tex)", line)
        if opened:
            current = opened[-1]
        overfull = OVERFULL.match(line)
        if overfull and float(overfull["pt"]) > max_overfull_pt:
            found.append(f"overfull box {float(overfull['pt']):.1f} pt (> {max_overfull_pt:g} pt) "
                         f"{overfull['where']} near {current}")
        if UNDEFINED.match(line):
            found.append(line.strip())
    return found


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("log", help="the .log of the final LaTeX run")
    parser.add_argument("--numbers", action="append", default=[],
                        help="generated/numbers.tex (repeatable: any file of generated macros): none of "
                             "its macros may be \\notavailable")
    parser.add_argument("--max-overfull-pt", type=float, default=3.0)
    args = parser.parse_args(argv)
    try:
        with open(args.log, errors="replace") as stream:
            found = problems(stream.read(), args.max_overfull_pt)
        for numbers in args.numbers:
            with open(numbers) as stream:
                found += [f"{numbers}: \\{name} is a placeholder (\\notavailable)" for name in
                          re.findall(r"\\newcommand\{\\(\w+)\}\{\\notavailable\}", stream.read())]
    except OSError as err:
        print(f"check_latex_log.py: error: {err.filename}: cannot read ({err.strerror})", file=sys.stderr)
        return 2
    for problem in found:
        print(f"check_latex_log.py: {problem}", file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
