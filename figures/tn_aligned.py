#!/usr/bin/python3
"""T/N against the time since the start of the first frictional drop, one curve per run (the
paper's Fig. 2c aligns its shear rates so: the drop does not depend on V0).

    figures/tn_aligned.py v1e-6.h5 v1e-5.h5 --metrics v1e-6.json v1e-5.json --labels 1e-6 1e-5 --out fig2e

Reads /global/t and /global/T_over_N of each run and, from its metrics.json, first_drop_start_time
(s; the peak the first drop falls from, `analysis.metrics.inversion`) and n_complete_drops. Time runs from
that start, in units of the shear transit time t_s = H / c_s (run attributes). A run whose first
drop was cut by the end of the run (n_complete_drops = 0) ends in a cross: its last value is not the
bottom of the drop. The highlighted run (index, default 0) is red, the others gray.
"""
import argparse
import math

import numpy as np

import _style
from _data import InputError, open_run, read_json


def main(argv=None):
    # 1. Parse options; read each run's T/N and its first drop's start.
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="run.h5 files")
    parser.add_argument("--metrics", nargs="+", required=True, help="metrics.json of each run, in order")
    parser.add_argument("--labels", nargs="+", help="one legend label per run")
    parser.add_argument("--highlight", type=int, default=0, help="index of the run drawn in red")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    args = parser.parse_args(argv)
    for option in ("metrics", "labels"):
        values = getattr(args, option)
        if values is not None and len(values) != len(args.runs):
            raise InputError(f"--{option} has {len(values)} entries for {len(args.runs)} runs")
    if not 0 <= args.highlight < len(args.runs):
        raise InputError(f"--highlight {args.highlight} is not an index into the {len(args.runs)} runs")
    curves = []
    for path, metrics_path in zip(args.runs, args.metrics):
        run, metrics = open_run(path), read_json(metrics_path)
        start = metrics.get("first_drop_start_time")
        if not isinstance(start, (int, float)) or not math.isfinite(start):
            raise InputError(f"{metrics_path}: no first_drop_start_time (the run has no frictional drop)")
        t_s = run.attr("H") / run.attr("c_s")
        curves.append(dict(t=(run.series("t") - start) / t_s, ratio=run.series("T_over_N"),
                           f=run.attr("f"), cut=metrics.get("n_complete_drops") == 0))
    labels = args.labels or [str(i) for i in range(len(curves))]

    # 2. Draw: gray first, the highlighted run on top in red; a cross where a cut drop ends.
    fig, ax = _style.plt.subplots(figsize=(3.4, 2.6))
    grays = np.linspace(0.25, 0.7, max(1, len(curves) - 1))
    order = [i for i in range(len(curves)) if i != args.highlight] + [args.highlight]
    for k, i in enumerate(order):
        c = curves[i]
        color = "tab:red" if i == args.highlight else str(grays[min(k, len(grays) - 1)])
        ax.plot(c["t"], c["ratio"], color=color, lw=1.2 if i == args.highlight else 0.8, label=labels[i])
        if c["cut"]:
            ax.plot(c["t"][-1], c["ratio"][-1], "x", color=color, ms=5)
    for f in sorted({c["f"] for c in curves}):
        ax.axhline(f, color="black", ls="--", lw=0.6)
    ax.axhline(0.0, color="black", lw=0.5)
    ax.set_xlim(-5.0, max(c["t"][-1] for c in curves))
    ax.set_xlabel("$(t - t_\\mathrm{drop})\\,c_s/H$ (-)")
    ax.set_ylabel("$T/N$ (-)")
    ax.set_title("T/N from the start of the first drop" + ("\n(x: run stopped during the drop)"
                                                           if any(c["cut"] for c in curves) else ""))
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=7, frameon=False)
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
