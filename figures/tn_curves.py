#!/usr/bin/python3
"""Ratio of tangential to normal interface force T/N against time (paper Fig. 2c,d).

    figures/tn_curves.py v1e-6.h5 v1e-5.h5 v1e-4.h5 --labels 1e-6 1e-5 1e-4 --highlight 1 --out fig2c
    figures/tn_curves.py long.h5 --out fig2d

Reads /global/t and /global/T_over_N of each run. With several runs the highlighted one (index
into the list, default 0) is red and the others gray; a single run is drawn in red. Horizontal
references: T/N = f (the local friction coefficient) and T/N = 0 (below it the frictional force is
inverted). Labels default to the parameters in which the runs differ (else the folder names);
the title carries those they share.
"""
import argparse
import os
import re

import numpy as np

import _style
from _data import InputError, open_run


# The pipeline's legend texts (study.sweeps.label: 'V0/c_s=1e-06', 'nu=0.20 f=1.50') as mathtext.
_PAIR = re.compile(r"(nu|f|V0/c_s|lambda/H|H/h|rho|seed|dt c_s)=(\S+)")
_SYMBOLS = {"nu": "$\\nu$", "f": "$f$", "V0/c_s": "$V_0/c_s$", "lambda/H": "$\\lambda/H$", "H/h": "$H/h$",
            "rho": "$\\rho$", "seed": "seed", "dt c_s": "$\\Delta t\\, c_s$"}


def pretty(label):
    """'V0/c_s=1e-06' -> '$V_0/c_s$ = $10^{-6}$'; text that is not such pairs is kept."""
    pairs = _PAIR.findall(label)
    if not pairs or _PAIR.sub("", label).strip():
        return label
    parts = []
    for key, text in pairs:
        try:
            value = _style.sci(float(text))
        except ValueError:
            value = text
        parts.append(f"{_SYMBOLS[key]} = {value}")
    return ", ".join(parts)


def _legend_bottom(fig, ax, legend):
    """The lower edge of a legend in data units of the y-axis."""
    fig.canvas.draw()
    return ax.transData.inverted().transform(legend.get_window_extent())[0][1]


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="run.h5 files (a format analysis.core.io reads)")
    parser.add_argument("--labels", nargs="+", help="one legend label per run")
    parser.add_argument("--highlight", type=int, default=0, help="index of the run drawn in red")
    parser.add_argument("--tmin", type=float, help="first time shown (s)")
    parser.add_argument("--tmax", type=float, help="last time shown (s)")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    # 1. Parse options and read every run's global series.
    args = parse_args(argv)
    if args.labels and len(args.labels) != len(args.runs):
        raise InputError(f"--labels has {len(args.labels)} entries for {len(args.runs)} runs")
    if not 0 <= args.highlight < len(args.runs):
        raise InputError(f"--highlight {args.highlight} is not an index into the "
                         f"{len(args.runs)} runs")
    curves = []
    for path in args.runs:
        run = open_run(path)
        curves.append(dict(t=run.series("t"), ratio=run.series("T_over_N"), f=run.attr("f"),
                           parts=_style.run_parts(run), name=os.path.basename(
                               os.path.dirname(os.path.abspath(path))) or path))

    # 2. What all runs share goes to the title; what differs names the curves.
    keys = list(curves[0]["parts"])
    shared = [k for k in keys if all(c["parts"].get(k) == curves[0]["parts"][k] for c in curves)]
    differing = [k for k in dict.fromkeys(k for c in curves for k in c["parts"]) if k not in shared]
    if args.labels:
        labels = [pretty(label) for label in args.labels]
    elif differing:
        labels = [", ".join(c["parts"][k] for k in differing if k in c["parts"]) for c in curves]
    else:
        labels = [c["name"] for c in curves]
    shared = ", ".join(curves[0]["parts"][k] for k in shared)

    # 3. Draw: gray first, the highlighted run on top in red.
    # Printed at half the text width (3.2 in): at this size its 9 pt text prints at ~6 pt.
    fig, ax = _style.plt.subplots(figsize=(4.6, 3.4))
    grays = np.linspace(0.25, 0.7, max(1, len(curves) - 1))
    others = [i for i in range(len(curves)) if i != args.highlight]
    for shade, i in zip(grays, others):
        ax.plot(curves[i]["t"], curves[i]["ratio"], color=str(shade), lw=0.9, label=labels[i])
    top = curves[args.highlight]
    ax.plot(top["t"], top["ratio"], color="tab:red", lw=1.4, label=labels[args.highlight],
            zorder=3)
    for f in sorted({c["f"] for c in curves}):
        ax.axhline(f, color="black", ls="--", lw=0.8)
        ax.annotate(f"local friction coefficient $f$ = {f:g}", (0.01, f), xytext=(0, 2),
                    xycoords=("axes fraction", "data"), textcoords="offset points", fontsize=7)
    ax.axhline(0.0, color="black", lw=0.6)
    tmin = args.tmin if args.tmin is not None else min(c["t"][0] for c in curves)
    tmax = args.tmax if args.tmax is not None else max(c["t"][-1] for c in curves)
    ax.set_xlim(tmin, tmax)
    ax.set_xlabel("time $t$ (s)  [$t$ = 0: start of the dynamic stage]")
    ax.set_ylabel("frictional force ratio $T/N$ (-)")
    ax.set_title(f"Global frictional force ratio $T/N$\n{shared}")
    if len(curves) > 1:  # where it covers the fewest curve points, if that is above T/N = 0
        legend = ax.legend(loc="best", framealpha=0.9, fontsize=7)
        bottom = _legend_bottom(fig, ax, legend)
        if bottom < 0.0:  # it would hide the inversion T/N < 0: beside the axes instead
            legend.remove()
            ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False, fontsize=7)
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
