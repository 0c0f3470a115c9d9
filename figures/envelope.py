#!/usr/bin/python3
"""Deviation of the regenerated celerity from the published one, per published cell, with the seed
bar and the method envelope (paper/how_sure.tex).

    figures/envelope.py envelope.csv --tolerance 0.05 --out envelope

Reads `python3 -m analysis envelope`'s envelope.csv (deviations already relative to |published|).
Per cell, left to right in the table's order (grouped by systematic group): a light bar over the
method envelope, a dark bar over the seeds, a dot at the ensemble mean, a cross at seed 1, the
colour giving the status (within the tolerance, published value inside the envelope, outside);
the shaded band is +- tolerance. Deviations beyond the plotted range are clipped at its edge and
their value written there.
"""
import argparse

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import _style
from _data import InputError, read_csv

REQUIRED = ("nu", "f", "group", "status", "seed1_dev", "mean_dev", "seed_min_dev", "seed_max_dev",
            "envelope_min_dev", "envelope_max_dev")
STATUS_COLORS = {"within": "tab:green", "inside": "tab:blue", "outside": "tab:red"}
LIMIT = 25.0  # % shown; beyond it, clipped and labelled


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="envelope.csv (python3 -m analysis envelope)")
    parser.add_argument("--tolerance", type=float, required=True, help="relative tolerance, e.g. 0.05")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def percent(value):
    return np.clip(100.0 * value, -LIMIT, LIMIT)


def main(argv=None):
    # 1. Read the cells.
    args = parse_args(argv)
    rows = read_csv(args.table, REQUIRED)
    if not rows:
        raise InputError(f"{args.table}: no cells")
    x = np.arange(len(rows))

    # 2. Tolerance band, envelope and seed bars, mean and seed 1.
    fig, ax = _style.plt.subplots(figsize=(11, 4.6))
    ax.axhspan(-100 * args.tolerance, 100 * args.tolerance, color="0.88", lw=0, zorder=0)
    ax.axhline(0.0, color="0.4", lw=0.8, zorder=1)
    for i, r in enumerate(rows):
        color = STATUS_COLORS.get(r["status"], "0.5")
        if np.isfinite(r["envelope_min_dev"]):
            ax.plot([i, i], [percent(r["envelope_min_dev"]), percent(r["envelope_max_dev"])],
                    color=color, alpha=0.35, lw=7, solid_capstyle="butt", zorder=2)
        if np.isfinite(r["seed_min_dev"]):
            ax.plot([i, i], [percent(r["seed_min_dev"]), percent(r["seed_max_dev"])],
                    color=color, lw=2.2, zorder=3)
        if np.isfinite(r["mean_dev"]):
            ax.plot([i], [percent(r["mean_dev"])], "o", color=color, ms=4.5, zorder=4)
        if np.isfinite(r["seed1_dev"]):
            ax.plot([i], [percent(r["seed1_dev"])], "x", color="k", ms=4, mew=0.9, zorder=5)
        for key in ("envelope_min_dev", "envelope_max_dev", "mean_dev"):
            value = r[key]
            if np.isfinite(value) and abs(100 * value) > LIMIT:
                ax.annotate(f"{100 * value:+.0f}%", (i, percent(value)), xytext=(4, -14 if value > 0 else 14),
                            textcoords="offset points", fontsize=6, rotation=90, va="center")

    # 3. Groups: separators and names.
    groups = [r["group"] for r in rows]
    starts = [i for i in range(len(rows)) if i == 0 or groups[i] != groups[i - 1]]
    for k, start in enumerate(starts):
        end = starts[k + 1] if k + 1 < len(starts) else len(rows)
        if start:
            ax.axvline(start - 0.5, color="0.3", lw=0.8, ls=":")
        ax.text((start + end - 1) / 2, -LIMIT * 0.97, str(groups[start]).replace(">=", r"$\geq$"),
                ha="center", va="bottom", fontsize=7.5, color="0.2")

    # 4. Axes and legend.
    ax.set_xticks(x)
    ax.set_xticklabels([f"{r['nu']:g} / {r['f']:.2f}" for r in rows], rotation=90, fontsize=7)
    ax.set_xlim(-0.7, len(rows) - 0.3)
    ax.set_ylim(-LIMIT * 1.02, LIMIT * 1.02)
    ax.set_xlabel(r"published cell $\nu$ / $f$")
    ax.set_ylabel("(regenerated - published) / |published| (%)")
    counts = {s: sum(r["status"] == s for r in rows) for s in STATUS_COLORS}
    handles = [Patch(color=STATUS_COLORS["within"], label=f"ensemble mean within {100 * args.tolerance:g}% ({counts['within']})"),
               Patch(color=STATUS_COLORS["inside"], label=f"published value inside the envelope ({counts['inside']})"),
               Patch(color=STATUS_COLORS["outside"], label=f"outside the envelope ({counts['outside']})"),
               Line2D([], [], color="0.3", alpha=0.35, lw=7, label="method envelope"),
               Line2D([], [], color="0.3", lw=2.2, marker="o", ms=4.5, label="seeds: range and mean"),
               Line2D([], [], color="k", ls="none", marker="x", ms=4, label="seed 1")]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    ax.set_title("Deviation from the published Table 1 per cell: seeds and method envelope")
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
