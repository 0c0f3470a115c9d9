#!/usr/bin/python3
"""Does a solver change move Table 1? Cell by cell, the Table-1 grid after the change against the same grid
before it, in units of the seed spread of the published cells' ensemble.

A change that solves the same discrete problem another way (to round-off, to the contact tolerance, or with
another realization of the seeded perturbation) cannot reproduce a run bit for bit
after slip onset (the problem is chaotic there), so the question is whether it moves a celerity by more
than the perturbation seed already does. Prints, for every published cell, the celerity before and after,
their difference and that difference over the ensemble's seed standard deviation; then, over the whole
grid, how many cells keep their category (and, for those that do not, how far the seeds agree there), the
largest relative change, and the published cells within 5 % before and after.

Usage (from the study's folder, with `table1` and `table1_ensemble` built after the change; the committed
table of before):
    bench/table1_shift.py study/results/table1/all_metrics.csv results/table1/table/all_metrics.csv \
        results/table1_ensemble/table/ensemble.csv
"""
import argparse
import csv
import math
import statistics
import sys

TOLERANCE = 0.05  # the reference check's "within" (study/reference/ratchet.json)


def by_cell(path):
    """Rows of a CSV keyed by (nu, f), rounded so that 0.1 and 0.10000000001 are one cell."""
    with open(path, newline="") as stream:
        return {(round(float(r["nu"]), 6), round(float(r["f"]), 6)): r for r in csv.DictReader(stream)}


def number(text):
    return float(text) if text not in ("", None) else math.nan


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("default_metrics", help="all_metrics.csv of the grid before the change")
    parser.add_argument("fast_metrics", help="all_metrics.csv of the same grid after it")
    parser.add_argument("ensemble", help="ensemble.csv of the published cells (seed spread, published value)")
    args = parser.parse_args(argv)
    default, fast, ensemble = by_cell(args.default_metrics), by_cell(args.fast_metrics), by_cell(args.ensemble)
    missing = sorted(set(default) ^ set(fast))
    if missing:
        print(f"error: the two sweeps differ in their cells: {missing}", file=sys.stderr)
        return 2

    print(f"{'nu':>5} {'f':>5} {'published':>10} {'before':>10} {'after':>10} {'diff':>10} {'seed_std':>9} {'diff/std':>8}")
    ratios, within = [], {"default": 0, "fast": 0}
    for cell in sorted(ensemble):
        if cell not in default:
            continue
        published, std = number(ensemble[cell]["published"]), number(ensemble[cell]["celerity_std"])
        c_default, c_fast = number(default[cell]["celerity"]), number(fast[cell]["celerity"])
        diff = c_fast - c_default
        ratio = abs(diff) / std if std > 0 else math.nan
        if not math.isnan(ratio):
            ratios.append(ratio)
        for name, c in (("default", c_default), ("fast", c_fast)):
            within[name] += abs(c - published) <= TOLERANCE * abs(published)
        print(f"{cell[0]:5.2f} {cell[1]:5.2f} {published:10.4f} {c_default:10.4f} {c_fast:10.4f} {diff:+10.2e} "
              f"{std:9.2e} {ratio:8.3f}")

    changed = [c for c in sorted(default) if default[c]["category"] != fast[c]["category"]]
    same_category = len(default) - len(changed)
    celerities = [(number(default[c]["celerity"]), number(fast[c]["celerity"])) for c in default]
    changes = [abs(c_fast - c_default) / abs(c_default) for c_default, c_fast in celerities
               if c_default and not math.isnan(c_default) and not math.isnan(c_fast)]
    print()
    print(f"published cells compared: {len(ratios)}; |after - before| / seed std: median {statistics.median(ratios):.3f}, "
          f"max {max(ratios):.3f}; cells above 1: {sum(r > 1 for r in ratios)}")
    print(f"published cells within {TOLERANCE:.0%}: before {within['default']}, after {within['fast']}")
    print(f"whole grid: {len(default)} cells, same category {same_category}; relative celerity change "
          f"median {statistics.median(changes):.2e}, max {max(changes):.2e} over {len(changes)} measured cells")
    for c in changed:
        seeds = ensemble.get(c)
        agreement = f"seeds agree on {float(seeds['category_agreement']):.0%} ({seeds['majority_category']})" if seeds else "no ensemble"
        print(f"  category changed at nu {c[0]:g}, f {c[1]:g}: {default[c]['category']} -> {fast[c]['category']}; {agreement}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
