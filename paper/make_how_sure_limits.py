#!/usr/bin/python3
"""generated/how_sure_limits.tex: the numbers and sentences of the limits subsections of
paper/how_sure.tex (mesh limit, backward pulses against dt, Fig. 3 timeline, pulse counts), from the
summaries of analysis.confidence.mesh_limit, analysis.confidence.timestep_limit, analysis.confidence.timeline and analysis.confidence.pulse_seeds.

    paper/make_how_sure_limits.py --mesh mesh_limit_summary.json --timestep timestep_limit_summary.json
        --timeline timeline_summary.json --pulses pulse_seeds_summary.json -o OUT.tex

Every macro (prefix `lim`) is a value of those files, formatted; the sentences are written by the
analysis modules from their counts. A missing key is an error that names the file.
"""
import argparse
import sys

from analysis.core.atomic import write_file
from numbers_tex import render
from summary_json import get, read
from analysis.core.errors import InputError

#: analysis.confidence.timeline's events -> macro stem.
EVENT_STEMS = {"onset_time": "Onset", "localization_time": "Localization", "celerity_window_start": "Window",
               "first_opening_time": "Opening", "slip_velocity_max_time": "SlipMax",
               "first_drop_start_time": "Drop", "min_T_over_N_time": "MinTN"}
#: the order of a set in the timeline summary -> macro stem.
SET_STEMS = ("One", "Two", "Three")
MESH_STATUS = {"limit": "Limit", "not monotone": "NotMonotone", "not converging": "NotConverging",
               "incomplete": "Incomplete", "fewer meshes": "FewerMeshes"}
DT_STATUS = {"within seed spread": "WithinSpread", "converging": "Converging", "not converging": "NotConverging",
             "another regime": "OtherRegime", "left the model": "LeftModel", "too few time steps": "TooFew"}




def seconds(value):
    return "--" if value is None else f"{value:.0f}"


def _series(items):
    """'a', 'a and b', 'a, b and c'."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def mesh_macros(s, path):
    counts = get(s, "status_counts", path)
    macros = {"limTolerancePercent": f"{100 * get(s, 'tolerance', path):g}",
              "limMeshCells": get(s, "cells", path), "limMeshWithLimitCells": get(s, "cells_with_limit", path),
              "limMeshCellsAtTwoFiveSix": get(s, "cells_at_256", path),
              "limMeshCellsAtOneTwoEight": get(s, "cells_at_128", path),
              "limMeshWithinSixtyFour": get(s, "within_64", path),
              "limMeshWithinOneTwoEight": get(s, "within_128", path),
              "limMeshWithinLimit": get(s, "within_limit", path),
              "limMeshWithinSixtyFourOfLimitCells": get(s, "within_64_of_limit_cells", path),
              "limMeshCloser": get(s, "published_closer_than_64", path),
              "limMeshVerdict": get(s, "verdict", path),
              "limMeshList": _series([f"{n:g}" for n in get(s, "meshes", path) if n != 256])}
    for status, stem in MESH_STATUS.items():
        macros[f"limMesh{stem}"] = counts.get(status, 0)
    return macros


def timestep_macros(s, path):
    counts = get(s, "status_counts", path)
    macros = {"limDtCells": get(s, "cells", path), "limDtSettled": get(s, "cells_settled", path),
              "limDtPublishedBackward": get(s, "published_backward_cells", path),
              "limDtPublishedFollow": get(s, "published_follow_theory", path),
              "limDtOursSmallestFollow": get(s, "ours_smallest_dt_follow_theory", path),
              "limDtLimitSentence": get(s, "limit_sentence", path),
              "limDtTheorySentence": get(s, "theory_sentence", path),
              "limDtSmallest": f"{min(get(s, 'dt_values', path)):g}",
              "limDtLargest": f"{max(get(s, 'dt_values', path)):g}",
              "limDtSeedsMax": get(s, "runs_per_point_max", path),
              "limDtMeshes": ", ".join(f"{n:g}" for n in get(s, "meshes", path))}
    for status, stem in DT_STATUS.items():
        macros[f"limDt{stem}"] = counts.get(status, 0)
    return macros


def timeline_macros(s, path):
    sets = get(s, "sets", path)
    if len(sets) > len(SET_STEMS):
        raise InputError(f"{path}: {len(sets)} sets, at most {len(SET_STEMS)} have macros")
    macros = {"limTlNu": f"{get(s, 'nu', path):g}", "limTlF": f"{get(s, 'f', path):g}"}
    for stem, (label, data) in zip(SET_STEMS, sets.items()):
        macros[f"limTl{stem}Label"] = label
        macros[f"limTl{stem}Runs"] = get(data, "runs", path)
        events = get(data, "events", path)
        for key, event in EVENT_STEMS.items():
            e = get(events, key, path)
            for stat in ("mean", "min", "max"):
                macros[f"limTl{stem}{event}{stat.capitalize()}"] = seconds(e[stat])
    for key, event in EVENT_STEMS.items():
        paper = get(s, "paper_times", path).get(key)
        if paper is not None:
            macros[f"limTlPaper{event}"] = seconds(paper)
    drops = get(s, "paper_drop_snapshots", path)
    macros["limTlPaperDropFirst"], macros["limTlPaperDropLast"] = seconds(drops[0]), seconds(drops[-1])
    return macros


def pulse_macros(s, path):
    paper = get(s, "paper_counts", path)
    return {"limPulsePaperPeriods": _series([f"${lam}$" for lam in paper]),
            "limPulsePaperCounts": _series([str(n) for n in paper.values()]),
            "limPulseRuns": get(s, "runs", path),
            "limPulseEqualTheory": get(s, "runs_count_equals_theory", path),
            "limPulseCountSentence": get(s, "count_sentence", path),
            "limPulseLaterSentence": get(s, "later_sentence", path)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mesh", required=True, help="mesh_limit_summary.json")
    parser.add_argument("--timestep", required=True, help="timestep_limit_summary.json")
    parser.add_argument("--timeline", required=True, help="timeline_summary.json")
    parser.add_argument("--pulses", required=True, help="pulse_seeds_summary.json")
    parser.add_argument("-o", "--output", required=True, help="the .tex file to write")
    args = parser.parse_args(argv)
    try:
        macros = {**mesh_macros(read(args.mesh), args.mesh), **timestep_macros(read(args.timestep), args.timestep),
                  **timeline_macros(read(args.timeline), args.timeline),
                  **pulse_macros(read(args.pulses), args.pulses)}
    except InputError as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    sources = [args.mesh, args.timestep, args.timeline, args.pulses]
    write_file(args.output, render(macros, sources, script="paper/make_how_sure_limits.py"))
    print(f"{len(macros)} macros -> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
