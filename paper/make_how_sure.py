#!/usr/bin/python3
"""generated/how_sure_numbers.tex: the numbers of paper/how_sure.tex, from the ensemble summary
(`python3 -m analysis ensemble`) and the envelope summary (`python3 -m analysis envelope`).

    paper/make_how_sure.py --ensemble ensemble_summary.json --envelope envelope_summary.json -o OUT.tex
        [--finer-ensemble ensemble_summary.json --finer-mesh 128]

The optional finer ensemble (the same cells at a finer mesh, config paper.envelope.finer_ensemble)
gives the same macros with the stem `ensFiner` instead of `ens`, and \\ensFinerMesh.
Every macro is a number of those files, formatted; a missing key or an unknown group is an error
that names the file. Deviations are printed in per cent with their sign.
"""
import argparse
import sys

from analysis.core.atomic import write_file
from numbers_tex import render
from summary_json import get, read
from analysis.core.errors import InputError

#: analysis.confidence.ensemble's systematic groups -> the macro stem of each.
GROUP_STEMS = {"supersonic backward": "Supersonic", "nu 0-0.1, f 1.1-1.2": "LowNu",
               "nu 0.1-0.2, f >= 1.5": "HighF", "the rest": "Rest"}
#: analysis.confidence.envelope's factors -> macro stem.
FACTOR_STEMS = {"seed": "Seed", "mesh": "Mesh", "time step": "TimeStep", "integration": "Integration",
                "contact weighting": "Contact"}



def pct(value, signed=True):
    if value is None:
        return "--"
    return f"{100 * value:+.1f}" if signed else f"{100 * value:.1f}"



def seeds_range(low, high):
    """'8' when every cell has 8 seeds, '3--8' otherwise."""
    return f"{low}" if low == high else f"{low}--{high}"


def ensemble_macros(summary, path, prefix="ens"):
    macros = {
        f"{prefix}TolerancePercent": f"{100 * get(summary, 'tolerance', path):g}",
        f"{prefix}Cells": get(summary, "published_cells", path),
        f"{prefix}Runs": get(summary, "runs", path),
        f"{prefix}RunsWithFront": get(summary, "runs_with_front", path),
        f"{prefix}RunsOpposite": get(summary, "runs_opposite", path),
        f"{prefix}SeedsRange": seeds_range(get(summary, "seeds_per_cell_min", path),
                                           get(summary, "seeds_per_cell_max", path)),
        f"{prefix}WithinSeedOne": get(summary, "within_tol_seed1", path),
        f"{prefix}WithinMean": get(summary, "within_tol_mean", path),
        f"{prefix}FullAgreement": get(summary, "cells_full_agreement", path),
        f"{prefix}SpreadMedian": pct(get(summary, "spread_rel_median", path), signed=False),
    }
    groups = get(summary, "groups", path)
    unknown = [name for name in groups if name not in GROUP_STEMS]
    if unknown:
        raise InputError(f"{path}: unknown group '{unknown[0]}' (known: {', '.join(GROUP_STEMS)})")
    for name, group in groups.items():
        stem = prefix + GROUP_STEMS[name]
        macros.update({
            f"{stem}Cells": group["cells"],
            f"{stem}MeanDev": pct(group["deviation_mean_rel_mean"]),
            f"{stem}MinDev": pct(group["deviation_mean_rel_min"]),
            f"{stem}MaxDev": pct(group["deviation_mean_rel_max"]),
            f"{stem}SeedOneDev": pct(group["deviation_seed1_rel_mean"]),
            f"{stem}Spread": pct(group["spread_rel_median"], signed=False),
            f"{stem}WithinSeedOne": group["within_tol_seed1"],
            f"{stem}WithinMean": group["within_tol_mean"],
        })
    return macros


def envelope_macros(summary, path):
    macros = {f"env{status.capitalize()}": get(summary, status, path)
              for status in ("within", "inside", "outside", "unmeasured")}
    macros["envCells"] = get(summary, "cells", path)
    top = get(summary, "top_factor_counts", path)
    groups = get(summary, "groups", path)
    for name in list(top) + [f for g in groups.values() for f in get(g, "median_abs_shift", path)]:
        if name not in FACTOR_STEMS:
            raise InputError(f"{path}: unknown factor '{name}' (known: {', '.join(FACTOR_STEMS)})")
    unknown = [name for name in groups if name not in GROUP_STEMS]
    if unknown:
        raise InputError(f"{path}: unknown group '{unknown[0]}' (known: {', '.join(GROUP_STEMS)})")
    # Every factor and group gets its macros (0 or "--" when the study has none), so that
    # how_sure.tex builds whatever variants config `paper.envelope` lists.
    for factor, stem in FACTOR_STEMS.items():
        macros[f"envTop{stem}"] = top.get(factor, 0)
    for name, group_stem in GROUP_STEMS.items():
        counts = groups.get(name, {})
        stem = "env" + group_stem
        for status in ("within", "inside", "outside"):
            macros[f"{stem}{status.capitalize()}"] = counts.get(status, 0)
        for factor, factor_stem in FACTOR_STEMS.items():
            macros[f"{stem}Top{factor_stem}"] = counts.get("top_factor_counts", {}).get(factor, 0)
            macros[f"{stem}Shift{factor_stem}"] = pct(counts.get("median_abs_shift", {}).get(factor), signed=False)
    return macros


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ensemble", required=True, help="ensemble_summary.json")
    parser.add_argument("--envelope", required=True, help="envelope_summary.json")
    parser.add_argument("--finer-ensemble", help="ensemble_summary.json of the same cells at a finer mesh")
    parser.add_argument("--finer-mesh", type=int, help="its elements per H (with --finer-ensemble)")
    parser.add_argument("-o", "--output", required=True, help="the .tex file to write")
    args = parser.parse_args(argv)
    if (args.finer_ensemble is None) != (args.finer_mesh is None):
        parser.error("--finer-ensemble and --finer-mesh go together")
    sources = [args.ensemble, args.envelope]
    try:
        macros = {**ensemble_macros(read(args.ensemble), args.ensemble),
                  **envelope_macros(read(args.envelope), args.envelope)}
        if args.finer_ensemble:
            macros.update(ensemble_macros(read(args.finer_ensemble), args.finer_ensemble, prefix="ensFiner"))
            macros["ensFinerMesh"] = args.finer_mesh
            sources.append(args.finer_ensemble)
    except InputError as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    write_file(args.output, render(macros, sources, script="paper/make_how_sure.py"))
    print(f"{len(macros)} macros -> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
