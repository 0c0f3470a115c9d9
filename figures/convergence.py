#!/usr/bin/python3
"""Celerity, minimum T/N and maximum opening against one numerical or loading parameter.

    figures/convergence.py all_metrics.csv --param elements_per_H --out convergence_mesh
    figures/convergence.py all_metrics.csv --param rho --out convergence_density
    figures/convergence.py all_metrics.csv --param V0_over_cs --out convergence_shear_rate

Runs that agree on every other run parameter (nu, f, V0_over_cs, lambda_over_H, elements_per_H,
rho, integration, where present) form one line; lines with fewer than two values of the parameter
are left out. The celerity is shown as c_p/c_s (column celerity_over_cs, which `analysis aggregate`
derives), comparable when rho changes c_s. Reference lines at c_p/c_s = 1 and sqrt 2.
"""
import argparse
import math

import _style
from _data import InputError, read_csv, select

PARAMS = {  # axis label, x scale, title
    "elements_per_H": ("elements per layer height $H/h$ (-)", "log2", "Mesh convergence"),
    "rho": ("density $\\rho$ (kg/m$^3$), $\\Delta t \\propto \\sqrt{\\rho}$", "log",
            "Invariance with the density (time step scaled with $\\sqrt{\\rho}$)"),
    "V0_over_cs": ("top shear velocity $V_0/c_s$ (-)", "log", "Dependence on the shear rate"),
    "dt_times_cs": ("time step $\\Delta t\\, c_s$ (m)", "log2", "Dependence on the time step"),
}
REQUIRED = ("nu", "f", "celerity_over_cs", "min_T_over_N", "max_opening")
RUN_PARAMETERS = ("nu", "f", "V0_over_cs", "lambda_over_H", "elements_per_H", "rho", "integration", "dt_times_cs")
COLORS = ["tab:red", "tab:blue", "tab:green", "tab:purple", "tab:orange", "tab:brown", "tab:olive"]


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("metrics", help="all_metrics.csv (one row per run)")
    parser.add_argument("--param", required=True, choices=sorted(PARAMS))
    parser.add_argument("--where", nargs="*", default=[], metavar="COLUMN=VALUE",
                        help="keep only the rows with these values")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def line_label(key, fixed):
    parts = []
    for column, value in zip(fixed, key):
        text = _style.sci(value) if isinstance(value, float) else str(value)
        text += " kg/m$^3$" if column == "rho" else ""
        parts.append(f"{_style.COLUMN_LABELS[column]} = {text}")
    return ", ".join(parts)


def at_least_span(ax, relative):
    """Widen a linear y-range to +-relative of its middle: nearly equal values (the point of a
    convergence plot) then get readable ticks instead of an offset and a row of equal labels."""
    lo, hi = ax.get_ylim()
    middle, half = (lo + hi) / 2, (hi - lo) / 2
    half = max(half, relative * abs(middle))
    if half > 0:
        ax.set_ylim(middle - half, middle + half)
    ax.ticklabel_format(axis="y", style="plain", useOffset=False)


def main(argv=None):
    # 1. Parse options, read the runs, group them into lines along the parameter.
    args = parse_args(argv)
    rows = select(read_csv(args.metrics, REQUIRED + (args.param,)), args.where, args.metrics)
    fixed = [c for c in RUN_PARAMETERS if c != args.param and c in rows[0]]
    lines = {}
    for r in rows:
        lines.setdefault(tuple(r[c] for c in fixed), []).append(r)
    lines = {k: sorted(v, key=lambda r: r[args.param]) for k, v in lines.items()
             if len({r[args.param] for r in v}) > 1}
    if not lines:
        raise InputError(f"{args.metrics}: no set of runs differs only in '{args.param}' "
                         f"(the other run parameters: {', '.join(fixed)}); nothing to plot")
    # Parameters shared by every line go to the title, the rest to the legend.
    shared = [i for i, c in enumerate(fixed) if len({k[i] for k in lines}) == 1]
    varying = [i for i in range(len(fixed)) if i not in shared]

    # 2. Three panels.
    # Printed at the text width (6.5 in): 9 pt text prints at ~7 pt.
    fig, axes = _style.plt.subplots(1, 3, figsize=(8.4, 3.3))
    panels = [("celerity", "front celerity $c_p/c_s$ (-)"),
              ("min_T_over_N", "minimum $T/N$ (-)"),
              ("max_opening", "maximum opening $u_y$ (mm)")]
    for k, (key, runs) in enumerate(sorted(lines.items(), key=lambda item: str(item[0]))):
        color = COLORS[k % len(COLORS)]
        label = line_label([key[i] for i in varying], [fixed[i] for i in varying]) or None
        x = [r[args.param] for r in runs]
        axes[0].plot(x, [r["celerity_over_cs"] for r in runs], "o-", color=color, label=label)
        axes[1].plot(x, [r["min_T_over_N"] for r in runs], "o-", color=color, label=label)
        axes[2].plot(x, [1e3 * r["max_opening"] for r in runs], "o-", color=color, label=label)
    for level, text in ((1.0, "$c_s$"), (math.sqrt(2.0), "$\\sqrt{2}\\,c_s$")):
        axes[0].axhline(level, color="0.5", ls=":", lw=0.9)
        axes[0].annotate(text, (1.0, level), xycoords=("axes fraction", "data"), fontsize=7,
                         xytext=(-2, 2), textcoords="offset points", ha="right", color="0.4")
    axes[1].axhline(0.0, color="0.5", lw=0.8)
    openings = [r["max_opening"] for runs in lines.values() for r in runs]
    # Within a decade a log axis labels its ticks with rounded, identical numbers: linear then.
    log_opening = all(isinstance(v, float) and v > 0 for v in openings) and max(openings) > 10 * min(openings)
    if log_opening:
        axes[2].set_yscale("log")
    for ax in axes[:2] if log_opening else axes:
        at_least_span(ax, relative=0.05)

    # 3. Axes and title.
    name, scale, heading = PARAMS[args.param]
    values = sorted({r[args.param] for runs in lines.values() for r in runs})
    for ax, (_, ylabel) in zip(axes, panels):
        if scale == "log2":
            ax.set_xscale("log", base=2)
            ax.set_xticks(values)
            ax.set_xticklabels([f"{v:g}" for v in values])
            ax.minorticks_off()
        else:
            ax.set_xscale("log")
        ax.set_xlabel(name)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.25)
    if varying:
        axes[0].legend(fontsize=7)
    title = ", ".join(line_label([key[i]], [fixed[i]]) for i in shared
                      for key in [next(iter(lines))])
    fig.suptitle(f"{heading}: {len(lines)} series of runs" + (f"\n{title}" if title else ""),
                 fontsize=9)
    fig.tight_layout()
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
