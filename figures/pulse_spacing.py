#!/usr/bin/python3
"""Number and spacing of the major slip pulses against the period lambda/H (paper, "Pulse period").

    figures/pulse_spacing.py all_metrics.csv --out pulse_spacing
    figures/pulse_spacing.py all_metrics.csv --where nu=0.2 f=1.5 --out pulse_spacing

Measured (filled): pulse_count and pulse_spacing (m) of each run. Predicted (open, dashed): the
Mach-wave spacing l = 2H sqrt(c_p^2/c_s^2 - 1) from each run's measured celerity c_p, and the
pulse count it implies (metrics pulse_spacing_theory and pulse_count_theory of `analysis measure`;
undefined, not drawn, when |c_p| <= c_s). Gray lines: the spacings lambda/n a periodic layer allows.
"""
import argparse

import numpy as np

import _style
from _data import read_csv, select

REQUIRED = ("nu", "f", "lambda_over_H", "H", "pulse_count", "pulse_spacing", "pulse_spacing_theory",
            "pulse_count_theory")
COLORS = ["tab:red", "tab:blue", "tab:green", "tab:purple", "tab:orange", "tab:brown"]


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="all_metrics.csv (one row per run)")
    parser.add_argument("--where", nargs="*", default=[], metavar="COLUMN=VALUE",
                        help="keep only the rows with these values")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def main(argv=None):
    # 1. Parse options and read the runs; one group per (nu, f).
    args = parse_args(argv)
    rows = select(read_csv(args.metrics, REQUIRED), args.where, args.metrics)
    rows.sort(key=lambda r: r["lambda_over_H"])
    groups = {}
    for r in rows:
        groups.setdefault((r["nu"], r["f"]), []).append(r)

    # 2. Count (left) and spacing (right) against lambda/H.
    fig, (ax_n, ax_l) = _style.plt.subplots(1, 2, figsize=(9.0, 3.9))
    lam = np.array(sorted({r["lambda_over_H"] for r in rows}))
    span = np.linspace(0.0, lam.max() * 1.1, 100)
    most = int(max((r["pulse_count"] for r in rows if np.isfinite(r["pulse_count"])), default=1))
    for n in range(1, min(most, 8) + 2):
        ax_l.plot(span, span / n, color="0.8", lw=0.8, zorder=0,
                  label="$\\lambda/n$: spacings of $n$ equal pulses" if n == 1 else None)
        ax_l.annotate(f"$\\lambda/{n}$" if n > 1 else "$\\lambda$", (span[-1], span[-1] / n),
                      fontsize=7, color="0.5", va="center")
    for k, ((nu, f), group) in enumerate(sorted(groups.items())):
        color = COLORS[k % len(COLORS)]
        x = [r["lambda_over_H"] for r in group]
        label = f"$\\nu$ = {nu:g}, $f$ = {f:g}"
        predicted_l = np.array([r["pulse_spacing_theory"] / r["H"] for r in group])  # in units of H
        ax_n.plot(x, [r["pulse_count"] for r in group], "o", color=color, ms=7,
                  label=f"{label}: measured")
        ax_n.plot(x, [r["pulse_count_theory"] for r in group], "s--", mfc="none", color=color, ms=7,
                  lw=0.9, label="$\\lambda/l$ rounded, $l = 2H\\sqrt{c_p^2/c_s^2-1}$")
        ax_l.plot(x, [r["pulse_spacing"] / r["H"] for r in group], "o", color=color, ms=7,
                  label=f"{label}: measured")
        ax_l.plot(x, predicted_l, "s--", mfc="none", color=color, ms=7, lw=0.9,
                  label="$l/H = 2\\sqrt{c_p^2/c_s^2-1}$ from measured $c_p$")

    # 3. Axes.
    for ax in (ax_n, ax_l):
        ax.set_xlabel("period $\\lambda/H$ (-)")
        ax.set_xlim(0.0, lam.max() * 1.15)
        ax.set_xticks(lam)
        ax.grid(alpha=0.25)
        ax.legend(fontsize=7, loc="upper left")
    ax_n.set_ylim(0.0, None)
    ax_n.set_ylabel("number of major slip pulses (-)")
    ax_n.yaxis.get_major_locator().set_params(integer=True)
    ax_l.set_ylim(0.0, None)
    heights = sorted({r["H"] for r in rows})
    ax_l.set_ylabel(f"pulse spacing $l/H$ (-)   [$H$ = {', '.join(f'{h:g}' for h in heights)} m]")
    shared = _style.common_label(rows, skip=("lambda_over_H",))
    fig.suptitle("Major slip pulses in the periodic layer: count and spacing against the period"
                 + (f"\n{shared}" if shared else ""), fontsize=9)
    fig.tight_layout()
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
