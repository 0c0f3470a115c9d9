#!/usr/bin/python3
"""Slip-front celerity against Poisson's ratio, one colour and marker per friction coefficient
(paper Fig. 4b).

    figures/celerity_vs_nu.py table1.csv --out fig4b

Reads the columns nu, f, celerity (regenerated, m/s, signed: + = sliding direction) and published
(the paper's Table 1, m/s) of table1.csv; empty cells are skipped. Each f has its own pair of
colour (the qualitative tab palette of the other figures) and marker shape, named in the legend
(a sequential colour map made the 14 f values of Table 1 near-identical shades). Filled marker:
regenerated; open marker: published; a thin line joins the two values of one cell. The upper panel shows the
fronts running in the sliding direction, the lower one those running against it (mirrored wave
speeds -c_s, -sqrt2 c_s, -c_l). The wave-speed curves are analysis.theory.elastic's, for the paper's E and
rho (1000 Pa, 1000 kg/m^3; --E, --rho).
"""
import argparse
import math

import numpy as np
from matplotlib.lines import Line2D

import _style
from _data import InputError, read_csv, select
from analysis.theory import elastic

REQUIRED = ("nu", "f", "celerity", "published")
# The qualitative palette of the other figures (convergence.py, pulse_spacing.py), then the rest of
# tab10; every f also gets its own marker, so that colours repeating after ten stay apart.
PALETTE = ["tab:red", "tab:blue", "tab:green", "tab:purple", "tab:orange", "tab:brown", "tab:olive",
           "tab:cyan", "tab:pink", "tab:gray"]
MARKERS = ["o", "s", "D", "^", "v", "P", "X", "h", "<", ">", "p", "*", "d", "8"]


def styles_of(fs):
    """{f: (colour, marker)}: distinct pairs, neighbouring f values in different colours."""
    return {f: (PALETTE[i % len(PALETTE)], MARKERS[i % len(MARKERS)]) for i, f in enumerate(sorted(fs))}


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="table1.csv with nu, f, celerity, published")
    parser.add_argument("--E", type=float, default=elastic.TABLE1_E, help="Young's modulus of the theory curves (Pa)")
    parser.add_argument("--rho", type=float, default=elastic.TABLE1_RHO, help="density of the theory curves (kg/m^3)")
    parser.add_argument("--where", nargs="*", default=[], metavar="COLUMN=VALUE",
                        help="keep only the rows with these values")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def finite(value):
    return isinstance(value, float) and math.isfinite(value)


def main(argv=None):
    # 1. Parse options and read the table.
    args = parse_args(argv)
    rows = select(read_csv(args.table, REQUIRED), args.where, args.table)
    for r in rows:
        for column in ("celerity", "published"):
            if not (finite(r[column]) or (isinstance(r[column], float) and math.isnan(r[column]))):
                raise InputError(f"{args.table}: column '{column}' holds '{r[column]}' "
                                 f"(nu={r['nu']}, f={r['f']}); expected a number or empty")
    rows = [r for r in rows if finite(r["celerity"]) or finite(r["published"])]
    if not rows:
        raise InputError(f"{args.table}: no row with a regenerated or published celerity")
    fs = sorted({r["f"] for r in rows})
    style_of = styles_of(fs)

    # 2. Two panels: c_p > 0 above, c_p < 0 below; the theory mirrored in the lower one.
    # Printed at 0.7 of the text width (4.5 in): 9 pt text prints at ~6.5 pt.
    fig, (up, down) = _style.plt.subplots(2, 1, figsize=(5.4, 5.4), sharex=True,
                                          gridspec_kw=dict(height_ratios=[3, 2], hspace=0.08))
    nu = np.linspace(0.0, max(0.495, max(r["nu"] for r in rows)), 300)
    c_s, sqrt2_c_s, c_l = np.array([elastic.wave_speeds(x, args.E, args.rho) for x in nu]).T
    for key, values in {"c_l": c_l, "c_s": c_s, "sqrt2_c_s": sqrt2_c_s}.items():
        style = dict(_style.THEORY_STYLE[key])
        up.plot(nu, values, lw=1.2, **style)
        style["label"] = "$-$" + style["label"]
        down.plot(nu, -values, lw=1.2, **style)

    # 3. Data: published open, regenerated filled, joined per cell.
    for r in rows:
        color, marker = style_of[r["f"]]
        both = finite(r["celerity"]) and finite(r["published"])
        for ax in (up, down):
            if both:
                ax.plot([r["nu"]] * 2, [r["published"], r["celerity"]], color=color, lw=0.8,
                        alpha=0.7)
            if finite(r["published"]):
                ax.plot(r["nu"], r["published"], marker, mfc="none", mec=color, ms=7.5, mew=1.2)
            if finite(r["celerity"]):
                ax.plot(r["nu"], r["celerity"], marker, color=color, ms=4.5)

    # 4. Limits from the data, legends, colour bar.
    values = [v for r in rows for v in (r["celerity"], r["published"]) if finite(v)]
    positive = [v for v in values if v > 0] or [1.0]
    negative = [v for v in values if v < 0] or [-1.0]
    up.set_ylim(min(0.5, 0.95 * min(positive)), max(1.5, 1.05 * max(positive)))
    down.set_ylim(min(-1.5, 1.1 * min(negative)), 0.0)
    up.set_ylabel("$c_p$ > 0: sliding direction (m/s)")
    down.set_ylabel("$c_p$ < 0: against sliding (m/s)")
    down.set_xlabel("Poisson's ratio $\\nu$ (-)")
    down.set_xlim(-0.02, nu[-1] + 0.01)
    markers = [Line2D([], [], ls="none", marker="o", color="0.3", ms=4.5, label="regenerated (filled)"),
               Line2D([], [], ls="none", marker="o", mfc="none", mec="0.3", ms=7,
                      label="published, Yastrebov 2016 (open)")]
    up.legend(handles=up.get_legend_handles_labels()[0] + markers, loc="upper left", ncol=2,
              fontsize=8, framealpha=0.9)
    down.legend(loc="lower left", fontsize=8, ncol=3, framealpha=0.9)
    for ax in (up, down):
        ax.grid(alpha=0.25)
    per_f = [Line2D([], [], ls="none", marker=style_of[f][1], color=style_of[f][0], ms=5.5, label=f"{f:g}")
             for f in fs]
    fig.legend(handles=per_f, title="friction\ncoefficient $f$", loc="center left",
               bbox_to_anchor=(0.91, 0.5), fontsize=8, title_fontsize=8, frameon=False, labelspacing=0.6)
    n_both = sum(finite(r["celerity"]) and finite(r["published"]) for r in rows)
    shared = _style.common_label(rows, skip=("nu", "f"))
    up.set_title(f"Slip-front celerity $c_p$: {n_both} cells with both values; wave speeds for "
                 f"$E$ = {args.E:g} Pa, $\\rho$ = {args.rho:g} kg/m$^3$"
                 + (f"\n{shared}" if shared else ""))
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
