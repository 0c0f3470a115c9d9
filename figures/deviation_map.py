#!/usr/bin/python3
"""Deviation of the regenerated slip-front celerity from the published one over the (nu, f) plane,
with the cells whose outcome differs from the paper's marked (what the paper's Fig. 4a and Table 1
show side by side, in one picture).

    figures/deviation_map.py table1.csv --out deviation_map

Reads the columns nu, f, deviation_rel, reproduced, sign_match, regime_match, category_match and
published_category of table1.csv (`python3 -m analysis aggregate`). Each published cell is a
square coloured by the deviation (%, diverging scale, clipped at +-MAX_PERCENT) and labelled with
it; a black frame marks a reproduced cell (within the tolerance with the published sign, regime and
category); a cross, a cell whose run shows another category than the published opening wave (the
published classification of every Table-1 cell); a triangle, another regime or sign; grey, a cell
without a measured front. The cells sit on the grid of the nu and f values the table has (equally
spaced, like the paper's Table 1), so that the close f values near 1 stay apart.
"""
import argparse
import math

from matplotlib.colors import TwoSlopeNorm
from matplotlib.lines import Line2D

import _style
from _data import read_csv, select

REQUIRED = ("nu", "f", "deviation_rel", "reproduced", "sign_match", "regime_match", "category_match",
            "published_category")
MAX_PERCENT = 20.0


def finite(value):
    return isinstance(value, float) and math.isfinite(value)


def main(argv=None):
    # 1. Parse options and read the table.
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="table1.csv of `python3 -m analysis aggregate`")
    parser.add_argument("--where", nargs="*", default=[], metavar="COLUMN=VALUE")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    args = parser.parse_args(argv)
    rows = select(read_csv(args.table, REQUIRED), args.where, args.table)

    # 2. One square per published cell, coloured by the deviation in %, on the grid of the values.
    nus, fs = sorted({r["nu"] for r in rows}), sorted({r["f"] for r in rows})
    fig, ax = _style.plt.subplots(figsize=(6.3, 4.6))
    cmap = _style.plt.get_cmap("RdBu_r")
    norm = TwoSlopeNorm(vcenter=0.0, vmin=-MAX_PERCENT, vmax=MAX_PERCENT)
    for r in rows:
        x, y = nus.index(r["nu"]), fs.index(r["f"])
        measured = finite(r["deviation_rel"])
        percent = 100.0 * r["deviation_rel"] if measured else math.nan
        face = cmap(norm(max(-MAX_PERCENT, min(MAX_PERCENT, percent)))) if measured else "0.85"
        edge, width = ("black", 1.6) if r["reproduced"] is True else ("0.6", 0.6)
        ax.scatter(x, y, s=330, marker="s", c=[face], edgecolors=edge, linewidths=width, zorder=2)
        if measured:
            ax.annotate(f"{percent:+.0f}", (x, y), ha="center", va="center", fontsize=6.5, zorder=4)
        if r["category_match"] is False:
            ax.scatter(x, y, s=330, marker="x", c="black", linewidths=1.0, zorder=3)
        if r["sign_match"] is False or r["regime_match"] is False:
            ax.scatter(x + 0.3, y + 0.3, s=18, marker="^", c="black", zorder=5)

    # 3. Axes, colour bar, legend.
    ax.set_xlabel("Poisson's ratio $\\nu$ (-)")
    ax.set_ylabel("friction coefficient $f$ (-)")
    ax.set_xticks(range(len(nus)), [f"{v:g}" for v in nus])
    ax.set_yticks(range(len(fs)), [f"{v:g}" for v in fs])
    ax.set_xlim(-0.6, len(nus) - 0.4)
    ax.set_ylim(-0.6, len(fs) - 0.4)
    bar = fig.colorbar(_style.plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, fraction=0.05, pad=0.02,
                       extend="both")
    bar.set_label("$(c_p - c_p^{\\mathrm{pub}})/|c_p^{\\mathrm{pub}}|$ (%)")
    handles = [Line2D([], [], ls="none", marker="s", mfc="white", mec="black", mew=1.6, ms=9, label="reproduced"),
               Line2D([], [], ls="none", marker="x", color="black", ms=8, label="other category than published"),
               Line2D([], [], ls="none", marker="^", color="black", ms=5, label="other regime or sign"),
               Line2D([], [], ls="none", marker="s", mfc="0.85", mec="0.6", ms=9, label="no measured front")]
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, fontsize=7,
              frameon=False)
    n_reproduced = sum(r["reproduced"] is True for r in rows)
    ax.set_title(f"Deviation from the published celerity: {len(rows)} published cells, "
                 f"{n_reproduced} reproduced")
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
