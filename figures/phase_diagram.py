#!/usr/bin/python3
"""Phase diagram of the sliding regimes in the (nu, f) plane (paper Fig. 4a).

    figures/phase_diagram.py all_metrics.csv --flutter flutter.txt --out fig4a
    figures/phase_diagram.py all_metrics.csv --flutter flutter.txt --where elements_per_H=64 --out fig4a
    figures/phase_diagram.py all_metrics.csv --flutter flutter.txt --published table1.csv --out fig4a
    figures/phase_diagram.py ensemble.csv --ensemble --flutter flutter.txt --out fig4a_ensemble

One marker per run from the `category` column: open circle no opening, square intersonic opening
in the sliding direction, double square the same with inversion of T/N, diamond supersonic opening
against the sliding direction; any other category gets its own marker, named in the legend. The
dash-dotted lines bound the flutter wedge read from `flutter.txt` (lines `nu f_lower f_upper`, as
printed by `python3 -m analysis flutter-boundary`; `inf` = unbounded, `nan` = no instability).
Each (nu, f) must appear once: restrict a mixed table with --where column=value. With --ensemble
the input is `python3 -m analysis ensemble`'s ensemble.csv: the marker is the cell's majority
category over its seeds, and a cell whose seeds disagree is ringed in orange with its category
agreement (fraction of the seeds in the majority category) written beside it.
With --published table1.csv (`python3 -m analysis aggregate`) the paper's classification is laid
over ours: every cell of the paper's Table 1 (an opening wave, Fig. 4a of the paper) gets an arrow
on the left of our marker in its published direction (blue, pointing right: in the sliding
direction; red, pointing left: against it; from the sign of the published celerity), and a black
"not equal" sign on the right where the run's category differs from the published one
(`category_match` false). Only published cells that were run are marked and counted: a study that
runs a few points (e.g. `quick`) says nothing about the others.
The nu axis is ticked at every swept nu and at the tenths between them. The legend's counts are
also written as JSON into the PNG's Description ({"legend": {"published_forward": n, ...}}), so that
the study report can check them against its table.
"""
import argparse
import json
from collections import Counter

import numpy as np
from matplotlib.legend_handler import HandlerTuple
from matplotlib.lines import Line2D
from matplotlib.transforms import offset_copy

import _style
from _data import InputError, read_csv, read_flutter, select

REQUIRED = ("nu", "f", "category")
ENSEMBLE_REQUIRED = ("nu", "f", "majority_category", "category_agreement", "n_runs")
RING = dict(marker="o", mfc="none", mec="tab:orange", ms=13, mew=1.4)
PUBLISHED_REQUIRED = ("nu", "f", "published", "category_match")
# Beside our marker (offsets in points, so that close f values stay apart): an arrow in the published
# direction on the left, a "not equal" sign on the right where our category differs.
PUBLISHED_MARK = {
    "forward": ("published: opening wave in the sliding direction",
                dict(marker=">", mfc="tab:blue", mec="tab:blue", ms=6)),
    "backward": ("published: opening wave against the sliding direction",
                 dict(marker="<", mfc="tab:red", mec="tab:red", ms=6)),
}
PUBLISHED_OFFSET, DIFFERS_OFFSET = -10.0, 10.0  # points
DIFFERS = dict(marker="$\\neq$", color="black", ms=8, mew=0.5)
KNOWN = {
    "no_opening": ("no opening", [dict(marker="o", mfc="white", mec="0.3", ms=7, mew=1.0)]),
    "intersonic_opening": ("intersonic opening wave, sliding direction",
                           [dict(marker="s", mfc="tab:blue", mec="tab:blue", ms=7)]),
    "intersonic_opening_inversion": (
        "intersonic opening wave with inversion of $T/N$",
        [dict(marker="s", mfc="white", mec="navy", ms=11, mew=1.2),
         dict(marker="s", mfc="navy", mec="navy", ms=5.5)]),
    "supersonic_backward_opening": ("supersonic opening wave against the sliding direction",
                                    [dict(marker="D", mfc="tab:red", mec="tab:red", ms=7)]),
}
OTHER_MARKERS = ["^", "v", "P", "X", "*", "h", "p", "d"]  # not < >: the published arrows
OTHER_COLORS = ["tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink", "tab:olive"]


def styles_for(categories):
    styles, k = dict(KNOWN), 0
    for category in sorted(categories):
        if category not in styles:
            styles[category] = (str(category).replace("_", " "), [dict(
                marker=OTHER_MARKERS[k % len(OTHER_MARKERS)], ms=8, mec="black", mew=0.5,
                mfc=OTHER_COLORS[k % len(OTHER_COLORS)])])
            k += 1
    return styles


def run_published_cells(published, rows):
    """The published cells (rows of table1.csv) that have a run among `rows`."""
    ran = {(round(r["nu"], 6), round(r["f"], 6)) for r in rows}
    return [c for c in published if (round(c["nu"], 6), round(c["f"], 6)) in ran]


def nu_ticks(nus, lo, hi):
    """Every swept nu, and the tenths in [lo, hi] not closer than 0.04 to one of them."""
    tenths = [k / 10 for k in range(int(np.ceil(lo * 10 - 1e-9)), int(np.floor(hi * 10 + 1e-9)) + 1)]
    return sorted(set(nus) | {t for t in tenths if all(abs(t - nu) >= 0.04 for nu in nus)})


def overlay_published(ax, cells):
    """Arrows and "not equal" signs of the published cells that were run; returns their legend
    handles and labels."""
    beside = {dx: offset_copy(ax.transData, fig=ax.figure, x=dx, units="points")
              for dx in (PUBLISHED_OFFSET, DIFFERS_OFFSET)}
    handles, labels, counts = [], [], {}
    for direction, (label, style) in PUBLISHED_MARK.items():
        chosen = [c for c in cells if (c["published"] > 0) == (direction == "forward")]
        counts[f"published_{direction}"] = len(chosen)
        if not chosen:
            continue
        ax.plot([c["nu"] for c in chosen], [c["f"] for c in chosen], ls="none", zorder=4,
                transform=beside[PUBLISHED_OFFSET], **style)
        handles.append(Line2D([], [], ls="none", **style))
        labels.append(f"{label} ({len(chosen)})")
    # category_match is empty (nan) when the run gave no category: that differs too.
    differs = [c for c in cells if c["category_match"] is not True]
    counts["differs"] = len(differs)
    if differs:
        ax.plot([c["nu"] for c in differs], [c["f"] for c in differs], ls="none", zorder=5,
                transform=beside[DIFFERS_OFFSET], **DIFFERS)
        handles.append(Line2D([], [], ls="none", **DIFFERS))
        labels.append(f"our category differs from the\npublished one ({len(differs)})")
    return handles, labels, counts


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="all_metrics.csv (one row per run)")
    parser.add_argument("--flutter", required=True, help="flutter.txt: lines 'nu f_lower f_upper'")
    parser.add_argument("--ensemble", action="store_true",
                        help="the input is ensemble.csv: majority category and category agreement")
    parser.add_argument("--where", nargs="*", default=[], metavar="COLUMN=VALUE",
                        help="keep only the rows with these values")
    parser.add_argument("--published", metavar="TABLE1_CSV",
                        help="table1.csv of `python3 -m analysis aggregate`: ring the paper's Table-1 "
                             "cells by published direction, mark where our category differs")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    # 1. Parse options, read the runs and the flutter boundary.
    args = parse_args(argv)
    if args.ensemble:
        rows = select(read_csv(args.metrics, ENSEMBLE_REQUIRED), args.where, args.metrics)
        rows = [{**r, "category": r["majority_category"]} for r in rows]
    else:
        rows = select(read_csv(args.metrics, REQUIRED), args.where, args.metrics)
    repeated = [k for k, n in Counter((r["nu"], r["f"]) for r in rows).items() if n > 1]
    if repeated:
        raise InputError(f"{args.metrics}: {len(repeated)} (nu, f) point(s) appear more than once "
                         f"(e.g. nu={repeated[0][0]:g}, f={repeated[0][1]:g}); select one study "
                         "with --where, e.g. --where elements_per_H=64 V0_over_cs=1e-5")
    flutter = read_flutter(args.flutter)
    styles = styles_for({r["category"] for r in rows})
    fs = sorted({r["f"] for r in rows})
    f_lo, f_hi = min(fs) - 0.1, max(fs) + 0.1

    # 2. Flutter wedge: beyond the plot where unbounded, broken where absent.
    # Printed at 0.8 of the text width (5.2 in) with its legend: 9 pt text prints at ~6 pt.
    fig, ax = _style.plt.subplots(figsize=(5.0, 4.2))
    nu_w, lower, upper = flutter.T
    upper_drawn = np.where(np.isposinf(upper), f_hi + 10.0, upper)
    ax.fill_between(nu_w, lower, upper_drawn, where=np.isfinite(lower), color="0.85", alpha=0.6,
                    lw=0, zorder=0)
    ax.plot(nu_w, lower, "k-.", lw=1.2, zorder=1)
    ax.plot(nu_w, upper_drawn, "k-.", lw=1.2, zorder=1)

    # 3. One marker per run, by category.
    handles, labels = [], []
    counts = Counter(r["category"] for r in rows)
    legend_counts = {"categories": dict(counts)}
    for category, (label, layers) in styles.items():
        chosen = [r for r in rows if r["category"] == category]
        if not chosen:
            continue
        nu = [r["nu"] for r in chosen]
        f = [r["f"] for r in chosen]
        for layer in layers:
            ax.plot(nu, f, ls="none", zorder=3, **layer)
        handles.append(tuple(Line2D([], [], ls="none", **layer) for layer in layers))
        labels.append(f"{label} ({counts[category]})")
    # 3b. Ensembles: ring and agreement where the seeds disagree.
    split = [r for r in rows if args.ensemble and r["category_agreement"] < 1.0]
    for r in split:
        ax.plot([r["nu"]], [r["f"]], ls="none", zorder=4, **RING)
        ax.annotate(f"{r['category_agreement']:.2f}", (r["nu"], r["f"]), xytext=(7, 5),
                    textcoords="offset points", fontsize=7, color="tab:orange", zorder=5)
    if args.ensemble:
        handles.append(Line2D([], [], ls="none", **RING))
        labels.append(f"seeds disagree ({len(split)} cells): fraction\nin the majority category")
    # 3c. The paper's classification: a ring per published cell, "not equal" where ours differs.
    if args.published:
        published = run_published_cells(read_csv(args.published, PUBLISHED_REQUIRED), rows)
        handles_published, labels_published, legend_counts["published"] = overlay_published(ax, published)
        handles += handles_published
        labels += labels_published
    handles.append(Line2D([], [], color="k", ls="-.", lw=1.2))
    labels.append("flutter of steady sliding (theory):\nunstable inside the shaded wedge")
    ax.legend(handles, labels, handler_map={tuple: HandlerTuple(ndivide=1)}, loc="upper left",
              bbox_to_anchor=(1.01, 1.0), frameon=False, labelspacing=1.0)

    # 4. Axes.
    nus = sorted({r["nu"] for r in rows})
    margin = 0.045 if args.published else 0.02  # room for the published marks beside the end columns
    nu_lo, nu_hi = min(nus + [nu_w.min()]), max(nus + [nu_w.max()])
    ax.set_xlim(nu_lo - margin, nu_hi + margin)
    ax.set_ylim(f_lo, f_hi)
    ax.set_xticks(nu_ticks(nus, nu_lo, nu_hi))
    ax.set_yticks(fs)
    ax.tick_params(axis="both", labelsize=8)
    ax.grid(alpha=0.25)
    ax.set_xlabel("Poisson's ratio $\\nu$ (-)")
    ax.set_ylabel("Coulomb friction coefficient $f$ (-)")
    shared = _style.common_label(rows, skip=("nu", "f"))
    what = (f"{len(rows)} cells (majority of {int(max(r['n_runs'] for r in rows))} seeds)"
            if args.ensemble else f"{len(rows)} runs")
    ax.set_title(f"Sliding regimes of {what} in the ($\\nu$, $f$) plane"
                 + (f"\n{shared}" if shared else ""))
    _style.save(fig, args.out, description=json.dumps({"legend": legend_counts}))
    return 0


if __name__ == "__main__":
    _style.cli(main)
