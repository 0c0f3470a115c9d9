#!/usr/bin/python3
"""Backward supersonic celerity against the time step, one panel per cell: seed mean and range,
Adams' steady slip wave and the published value (paper/how_sure.tex).

    figures/timestep_backward.py timestep_limit.csv --out timestep_backward

Reads `python3 -m analysis timestep-limit`'s timestep_limit.csv (one row per cell and dt c_s).
"""
import argparse
import math

import numpy as np

import _style
from _data import InputError, read_csv

REQUIRED = ("nu", "f", "dt_times_cs", "n_runs", "n_backward", "mean", "min", "max", "theory", "published")


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="timestep_limit.csv (python3 -m analysis timestep-limit)")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    rows = read_csv(args.table, REQUIRED)
    cells = sorted({(r["nu"], r["f"]) for r in rows})
    if not cells:
        raise InputError(f"{args.table}: no cells")
    ncol = min(len(cells), 2)
    nrow = math.ceil(len(cells) / ncol)
    fig, axes = _style.plt.subplots(nrow, ncol, figsize=(3.3 * ncol, 2.6 * nrow), squeeze=False)
    for ax, (nu, f) in zip(axes.flat, cells):
        members = sorted((r for r in rows if (r["nu"], r["f"]) == (nu, f)), key=lambda r: r["dt_times_cs"])
        dt = np.array([r["dt_times_cs"] for r in members])
        has = np.array([math.isfinite(r["mean"]) for r in members])
        mean = np.array([r["mean"] for r in members])
        lo = np.array([r["min"] for r in members])
        hi = np.array([r["max"] for r in members])
        ax.errorbar(dt[has], mean[has], yerr=[mean[has] - lo[has], hi[has] - mean[has]], color="tab:orange",
                    marker="o", ms=4, capsize=3, label="ours: seed mean, range")
        for r in members:  # where not every run has a backward front; runs that left the model apart
            non_physical = r.get("n_non_physical") or 0
            if r["n_backward"] < r["n_runs"] or non_physical:
                label = f"{r['n_backward']:g}/{r['n_runs']:g}" + (f"\n{non_physical:g} n.-p." if non_physical else "")
                ax.annotate(label, (r["dt_times_cs"], ax.get_ylim()[0]), fontsize=6, ha="center", va="bottom")
        ax.axhline(members[0]["theory"], color="k", lw=1.0, label="Adams' steady wave")
        ax.axhline(members[0]["published"], color="k", ls="--", lw=1.0, label="published")
        ax.set_xscale("log", base=2)
        ax.set_xticks(dt)
        ax.set_xticklabels([f"{v:g}" for v in dt])
        ax.set_title(f"$\\nu$ = {nu:g}, $f$ = {f:g}")
        ax.set_xlabel("$\\Delta t\\,c_s$ (m)")
        ax.set_ylabel("$c_p$ (m/s)")
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[len(cells):]:
        ax.set_visible(False)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3, frameon=False)
    fig.tight_layout()
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
