#!/usr/bin/python3
"""Phase diagram of the sliding regimes over (material contrast, f), one panel per nu.

    figures/contrast_phase_diagram.py all_metrics.csv --theory theory.csv --out contrast_phase_diagram

A layer on a deformable substrate of E_s = contrast E (the layer's nu, density and thickness; the
contrast sweep, study/README.md). Columns: the rigid flat (runs without E_substrate_over_E), then the
contrasts from the stiffest substrate to the most compliant. One marker per run from its `category`,
in the vocabulary and colours of figures/phase_diagram.py (other categories get markers of their own,
named in the legend), with the measured celerity c_p / c_s written beside it (+: the layer's sliding
direction). The theory (`python3 -m analysis contrast-theory`, analysis/theory/contrast_theory.py) is
laid under the markers column by column: shaded grey above the onset of the forward family (the flutter
mode on a stiff substrate; on the rigid flat the flutter wedge, up to its upper bound), hatched red above
the onset of the backward family (Adams' wave made growing by the substrate); "stable" where no mode
grows (identical bodies). An onset below the plotted f range fills the column from its bottom. Each
(nu, contrast, f) must appear once. The category counts are written as JSON into the PNG's Description.
"""
import argparse
import json
import math
from collections import Counter

from matplotlib.legend_handler import HandlerTuple
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import _style
from _data import InputError, read_csv
from phase_diagram import styles_for

REQUIRED = ("nu", "f", "E_substrate_over_E", "category", "celerity_over_cs")
THEORY_REQUIRED = ("nu", "E_substrate_over_E", "f_threshold_forward", "f_threshold_backward", "f_upper")
FORWARD = dict(color="0.8", alpha=0.7, lw=0, zorder=0)
BACKWARD = dict(facecolor="none", edgecolor="tab:red", hatch="////", lw=0, alpha=0.45, zorder=0)
HALF = 0.42  # half-width of a column's theory band


def contrast_of(row):
    """The row's contrast, None on the rigid flat (an empty cell reads as nan)."""
    value = row["E_substrate_over_E"]
    return None if not isinstance(value, float) or math.isnan(value) else value


def column_label(contrast):
    if contrast is None:
        return "rigid"
    if contrast < 1 and abs(1 / contrast - round(1 / contrast)) < 1e-6:
        return f"1/{round(1 / contrast)}"
    return f"{contrast:g}"


def column_order(contrasts):
    """Rigid flat first, then from the stiffest substrate down."""
    return ([None] if None in contrasts else []) + sorted((c for c in contrasts if c is not None), reverse=True)


def same(a, b):
    return (a is None and b is None) or (a is not None and b is not None and math.isclose(a, b, rel_tol=1e-6))


def theory_of(theory, nu, contrast, path):
    for row in theory:
        if math.isclose(row["nu"], nu, rel_tol=1e-9) and same(contrast_of(row), contrast):
            return row
    raise InputError(f"{path}: no row for nu = {nu:g}, contrast {column_label(contrast)}")


def finite(value):
    return isinstance(value, float) and math.isfinite(value)


def draw_theory(ax, x, row, f_lo, f_hi):
    """The column's unstable ranges: grey above the forward onset (to f_upper on the rigid flat), red
    hatching above the backward onset; 'stable' when neither family grows."""
    forward, backward, upper = row["f_threshold_forward"], row["f_threshold_backward"], row["f_upper"]
    top = upper if finite(upper) else f_hi
    if finite(forward) and forward < f_hi:
        ax.fill_between([x - HALF, x + HALF], max(forward, f_lo), min(top, f_hi), **FORWARD)
        if forward > f_lo:
            ax.plot([x - HALF, x + HALF], [forward, forward], "k-", lw=1.1, zorder=1)
    if finite(backward) and backward < f_hi:
        ax.fill_between([x - HALF, x + HALF], max(backward, f_lo), f_hi, **BACKWARD)
        if backward > f_lo:
            ax.plot([x - HALF, x + HALF], [backward, backward], color="tab:red", ls="--", lw=1.1, zorder=1)
    if not finite(forward) and not finite(backward):
        ax.text(x, f_hi - 0.05, "stable", ha="center", va="top", fontsize=7, color="0.3")


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="all_metrics.csv of the contrast sweep (one row per run)")
    parser.add_argument("--theory", required=True, help="CSV of `python3 -m analysis contrast-theory`")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    # 1. The runs and the theory; one run per (nu, contrast, f).
    args = parse_args(argv)
    rows = read_csv(args.metrics, REQUIRED)
    theory = read_csv(args.theory, THEORY_REQUIRED)
    keys = Counter((r["nu"], column_label(contrast_of(r)), r["f"]) for r in rows)
    repeated = [k for k, n in keys.items() if n > 1]
    if repeated:
        nu, contrast, f = repeated[0]
        raise InputError(f"{args.metrics}: {len(repeated)} (nu, contrast, f) point(s) appear more than once "
                         f"(e.g. nu={nu:g}, contrast {contrast}, f={f:g})")
    nus = sorted({r["nu"] for r in rows})
    columns = column_order({contrast_of(r) for r in rows})
    fs = sorted({r["f"] for r in rows})
    f_lo, f_hi = min(fs) - 0.3, max(fs) + 0.3
    styles = styles_for({r["category"] for r in rows})
    if "no_slip" in styles:  # on a substrate: steady sliding, no node above the front threshold
        styles["no_slip"] = ("no front: steady sliding (no node slips\nfaster than the threshold, 10 $V_0$)",
                             styles["no_slip"][1])

    # 2. One panel per nu: theory bands under the run markers, the celerity beside each.
    fig, axes = _style.plt.subplots(1, len(nus), figsize=(3.3 * len(nus), 3.6), sharey=True, squeeze=False)
    for ax, nu in zip(axes[0], nus):
        for x, contrast in enumerate(columns):
            draw_theory(ax, x, theory_of(theory, nu, contrast, args.theory), f_lo, f_hi)
        for r in (r for r in rows if r["nu"] == nu):
            x = columns.index(contrast_of(r))
            for layer in styles[r["category"]][1]:
                ax.plot([x], [r["f"]], ls="none", zorder=3, **layer)
            if finite(r["celerity_over_cs"]):
                ax.annotate(f"{r['celerity_over_cs']:+.2f}", (x, r["f"]), xytext=(0, -10),
                            textcoords="offset points", ha="center", fontsize=6, zorder=4)
        ax.set_xticks(range(len(columns)))
        ax.set_xticklabels([column_label(c) for c in columns])
        ax.set_xlim(-0.5, len(columns) - 0.5)
        ax.set_ylim(f_lo, f_hi)
        ax.set_yticks(fs)
        ax.tick_params(axis="both", labelsize=8)
        ax.set_title(f"$\\nu$ = {nu:g}")
        ax.set_xlabel("$E_s / E$ (substrate / layer)")
    axes[0][0].set_ylabel("Coulomb friction coefficient $f$ (-)")

    # 3. Legend: categories with counts, then the theory.
    counts = Counter(r["category"] for r in rows)
    handles, labels = [], []
    for category, (label, layers) in styles.items():
        if counts[category]:
            handles.append(tuple(Line2D([], [], ls="none", **layer) for layer in layers))
            labels.append(f"{label} ({counts[category]})")
    handles += [Patch(**FORWARD), Patch(**BACKWARD)]
    labels += ["theory: forward mode grows (flutter;\nrigid flat: the flutter wedge)",
               "theory: backward mode grows"]
    fig.legend(handles, labels, handler_map={tuple: HandlerTuple(ndivide=1)}, loc="upper center",
               bbox_to_anchor=(0.5, 0.0), ncol=2, frameon=False, fontsize=7)
    shared = _style.common_label(rows, skip=("nu", "f", "E_substrate_over_E"))
    fig.suptitle("Sliding regimes on a deformable substrate (numbers: $c_p / c_s$)"
                 + (f"\n{shared}" if shared else ""), fontsize=9, y=1.0 + 0.05 * bool(shared))
    _style.save(fig, args.out, description=json.dumps({"legend": {"categories": dict(counts)}}))
    return 0


if __name__ == "__main__":
    _style.cli(main)
