#!/usr/bin/python3
"""Deviation from the published celerity against 1/N, one line per published cell, coloured by the
cell's systematic group (paper/how_sure.tex, the mesh limit).

    figures/mesh_limit.py mesh_limit.csv --tolerance 0.05 --out mesh_limit

Reads `python3 -m analysis mesh-limit`'s mesh_limit.csv (c_<N> and dev_<N> columns, deviations
relative to |published|). The Richardson limit of a cell (status `limit`) is drawn at 1/N = 0 with
an open marker joined by a dotted line; the shaded band is +- tolerance. Deviations beyond the
plotted range are clipped at its edge.
"""
import argparse
import math
import re

import numpy as np
from matplotlib.lines import Line2D

import _style
from _data import InputError, read_csv

REQUIRED = ("nu", "f", "group", "status", "dev_limit")
GROUP_COLORS = {"supersonic backward": "tab:purple", "nu 0-0.1, f 1.1-1.2": "tab:red",
                "nu 0.1-0.2, f >= 1.5": "tab:blue", "the rest": "tab:gray"}
LIMIT = 25.0  # % shown


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="mesh_limit.csv (python3 -m analysis mesh-limit)")
    parser.add_argument("--tolerance", type=float, required=True, help="relative tolerance, e.g. 0.05")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def meshes_of(row):
    return sorted(int(m.group(1)) for k in row if (m := re.fullmatch(r"dev_(\d+)", k)))


def main(argv=None):
    args = parse_args(argv)
    rows = read_csv(args.table, REQUIRED)
    if not rows:
        raise InputError(f"{args.table}: no cells")
    meshes = meshes_of(rows[0])
    if len(meshes) < 2:
        raise InputError(f"{args.table}: needs dev_<N> columns of at least two meshes")
    fig, ax = _style.plt.subplots(figsize=(6.4, 4.2))
    tol = 100 * args.tolerance
    ax.axhspan(-tol, tol, color="0.9", zorder=0)
    ax.axhline(0, color="k", lw=0.6)
    for row in rows:
        color = GROUP_COLORS.get(row["group"], "k")
        points = [(1 / n, 100 * row[f"dev_{n}"]) for n in meshes if math.isfinite(row[f"dev_{n}"])]
        if not points:
            continue
        x, y = zip(*points)
        ax.plot(x, np.clip(y, -LIMIT, LIMIT), color=color, lw=0.9, marker="o", ms=3, alpha=0.8)
        if row["status"] == "limit" and math.isfinite(row["dev_limit"]):
            y_inf = float(np.clip(100 * row["dev_limit"], -LIMIT, LIMIT))
            ax.plot([0, x[-1] if x[-1] < x[0] else min(x)], [y_inf, np.clip(points[-1][1], -LIMIT, LIMIT)],
                    color=color, ls=":", lw=0.9)
            ax.plot([0], [y_inf], color=color, marker="o", mfc="none", ms=5)
    ax.set_xticks([0] + [1 / n for n in meshes])
    ax.set_xticklabels(["0"] + [f"1/{n}" for n in meshes])
    ax.set_xlim(-0.002, 1 / min(meshes) * 1.05)
    ax.set_ylim(-LIMIT, LIMIT)
    ax.set_xlabel("$1/N$ ($h = H/N$)")
    ax.set_ylabel("deviation from the published $c_p$ (%)")
    handles = [Line2D([], [], color=c, marker="o", ms=3, label=g.replace(">=", r"$\geq$"))
               for g, c in GROUP_COLORS.items()]
    handles.append(Line2D([], [], color="k", marker="o", mfc="none", ls=":", label="Richardson limit"))
    ax.legend(handles=handles, loc="lower left", ncol=2, fontsize=7)
    ax.grid(alpha=0.3)
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
