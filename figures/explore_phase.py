#!/usr/bin/python3
"""One explored point placed in the (nu, f) plane against the published cells (paper Fig. 4a).

    figures/explore_phase.py metrics.json --reference table1_celerity.csv --flutter flutter.txt --out P

Background: the cells of the paper's Table 1 (celerity > 0: opening waves in the sliding direction,
< 0: against it; the paper's grid cells not in the table are drawn as small dots) and the flutter
wedge of steady sliding (theory, `flutter.txt`). Foreground: the explored run, with the marker of
its category (the styles of figures/phase_diagram.py) and its category and celerity written beside.
"""
import argparse

import numpy as np

import _style
from _data import InputError, read_csv, read_flutter, read_json
from phase_diagram import styles_for

PAPER_NU = (0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.49)
PAPER_F = (0.5, 0.8, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2, 1.3, 1.4, 1.5, 1.8, 2.0)


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="metrics.json of the explored run")
    parser.add_argument("--reference", required=True, help="published Table 1: nu, f, celerity_m_per_s")
    parser.add_argument("--flutter", required=True, help="flutter.txt: lines 'nu f_lower f_upper'")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    # 1. The run, the published cells, the wedge.
    args = parse_args(argv)
    metrics = read_json(args.metrics)
    missing = [k for k in ("nu", "f", "category") if k not in metrics]
    if missing:
        raise InputError(f"{args.metrics}: no {', '.join(missing)}")
    published = read_csv(args.reference, ("nu", "f", "celerity_m_per_s"))
    flutter = read_flutter(args.flutter)
    nu, f, category = float(metrics["nu"]), float(metrics["f"]), str(metrics["category"])
    f_lo, f_hi = min(PAPER_F + (f,)) - 0.1, max(PAPER_F + (f,)) + 0.1

    # 2. Wedge and published cells.
    fig, ax = _style.plt.subplots(figsize=(7.4, 4.8))
    nu_w, lower, upper = flutter.T
    upper_drawn = np.where(np.isposinf(upper), f_hi + 10.0, upper)
    ax.fill_between(nu_w, lower, upper_drawn, where=np.isfinite(lower), color="0.88", lw=0, zorder=0)
    ax.plot(nu_w, lower, "k-.", lw=1.0, zorder=1, label="flutter wedge of steady sliding (theory)")
    ax.plot(nu_w, upper_drawn, "k-.", lw=1.0, zorder=1)
    listed = {(r["nu"], r["f"]) for r in published}
    grid = [(n, g) for n in PAPER_NU for g in PAPER_F if (n, g) not in listed]
    ax.plot(*zip(*grid), ls="none", marker=".", color="0.6", ms=4, label="paper grid, not in Table 1")
    for sign, marker, label in ((1, "s", "Table 1: opening wave in the sliding direction"),
                                (-1, "D", "Table 1: opening wave against the sliding direction")):
        cells = [(r["nu"], r["f"]) for r in published if np.sign(r["celerity_m_per_s"]) == sign]
        ax.plot(*zip(*cells), ls="none", marker=marker, mfc="none", mec="0.45", ms=7, label=label)

    # 3. The explored point, with its category's marker, and a note beside it.
    name, layers = styles_for({category})[category]
    for k, layer in enumerate(layers):
        ax.plot([nu], [f], ls="none", zorder=5, **{**layer, "ms": layer.get("ms", 7) * 1.5},
                label=f"this run: {name}" if k == len(layers) - 1 else None)
    celerity = metrics.get("celerity")
    c_s = metrics.get("c_s")
    note = category.replace("_", " ")
    if celerity is not None and c_s:
        note += f"\n$c_p$ = {celerity:.3g} m/s = {celerity / c_s:.3g} $c_s$"
    ax.annotate(note, (nu, f), xytext=(12, 12), textcoords="offset points", fontsize=9,
                bbox=dict(boxstyle="round", fc="white", ec="0.5"), zorder=6)

    # 4. Axes.
    ax.set_xlim(min(PAPER_NU + (nu,)) - 0.03, max(PAPER_NU + (nu,)) + 0.05)
    ax.set_ylim(f_lo, f_hi)
    ax.grid(alpha=0.25)
    ax.set_xlabel("Poisson's ratio $\\nu$ (-)")
    ax.set_ylabel("Coulomb friction coefficient $f$ (-)")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False, fontsize=8, labelspacing=0.9)
    ax.set_title(f"Explored point $\\nu$ = {nu:g}, $f$ = {f:g} against the published cells")
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
