#!/usr/bin/python3
"""Space-time map of an interface field (paper Fig. 2a,b and Fig. 4c-f).

    figures/spacetime.py RUN.h5 --field slip_velocity --metrics metrics.json --out fig2a
    figures/spacetime.py RUN.h5 --field opening --tmin 600 --tmax 1200 --out fig2b
    figures/spacetime.py RUN.h5 --field state --out fig4c

x is horizontal, t vertical. Lines of slope 1/c for c_l and c_s (root attributes of the run) and
for the measured front celerity c_p (metrics.json key `celerity`, when given) start together at
the left edge (right edge for c_p < 0) and cross the period once, so their slopes can be compared
with the fronts in the map; their legend sits below the map, off the data. `state`: stick black, slip orange, open cyan. Without --tmin the map
starts a little before the slip onset of metrics.json (`onset_time`), else at t = 0. The colour
scale of slip velocity and opening tops at the 99.5th percentile of |value| (--vmax to set it);
a field with a significant negative part (back-slip) gets a diverging scale centred on zero.
"""
import argparse

import numpy as np
from matplotlib import patheffects
from matplotlib.colors import BoundaryNorm, ListedColormap

import _style
from _data import open_run, read_json

FIELDS = {
    "slip_velocity": ("slip velocity $\\dot u_x$", "m/s", 1.0),
    "opening": ("opening $u_y$", "mm", 1e3),
    "state": ("contact state", "", 1.0),
}
STATE_COLORS = ["#33c6e8", "black", "#ff9f1c"]  # 0 open, 1 stick, 2 slip
STATE_NAMES = ["open", "stick", "slip"]
MAX_ROWS = 4000  # more output rows than this are drawn every k-th row


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="run.h5 (a format analysis.core.io reads, docs/contracts.md section 2)")
    parser.add_argument("--field", required=True, choices=sorted(FIELDS))
    parser.add_argument("--metrics", help="metrics.json of the run (draws c_p from 'celerity')")
    parser.add_argument("--tmin", type=float, help="first time shown (s)")
    parser.add_argument("--tmax", type=float, help="last time shown (s)")
    parser.add_argument("--vmax", type=float, help="colour scale maximum, in the colourbar's unit")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def color_scale(values, vmax):
    """(vmin, vmax, clipped): a robust top (99.5th percentile of |values|) unless --vmax is given,
    symmetric when the field has a significant negative part."""
    magnitude = np.abs(values[np.isfinite(values)])
    top = vmax if vmax is not None else float(np.percentile(magnitude, 99.5)) if magnitude.size else 0
    top = top or float(magnitude.max(initial=0.0)) or 1.0
    signed = np.nanmin(values) < -0.05 * top
    return (-top if signed else 0.0), top, bool(magnitude.max(initial=0.0) > top)


def draw_field(ax, fig, x, t, values, field, vmax):
    """The map; returns True when its background is light (the slope lines are then drawn dark)."""
    name, unit, factor = FIELDS[field]
    h = x[1] - x[0] if len(x) > 1 else 1.0
    dt = t[1] - t[0] if len(t) > 1 else 1.0
    step = max(1, int(np.ceil(len(t) / MAX_ROWS)))
    # Node-centred cells; the node at x = 0 is also the one at x = lambda, so repeat it there.
    values = np.concatenate([values[::step], values[::step, :1]], axis=1)
    extent = (x[0] - h / 2, x[-1] + 3 * h / 2, t[0] - dt / 2, t[::step][-1] + step * dt / 2)
    common = dict(origin="lower", aspect="auto", extent=extent, interpolation="nearest")
    light = False
    if field == "state":
        image = ax.imshow(values, cmap=ListedColormap(STATE_COLORS),
                          norm=BoundaryNorm([-0.5, 0.5, 1.5, 2.5], 3), **common)
        bar = fig.colorbar(image, ax=ax, ticks=[0, 1, 2], fraction=0.05)
        bar.ax.set_yticklabels(STATE_NAMES)
        bar.set_label("contact state")
    else:
        values = values * factor
        low, top, clipped = color_scale(values, vmax)
        light = low < 0
        image = ax.imshow(values, cmap="RdBu_r" if light else "viridis", vmin=low, vmax=top,
                          **common)
        bar = fig.colorbar(image, ax=ax, extend=("both" if light else "max") if clipped else
                           "neither")
        bar.set_label(f"{name} ({unit})" + (", colour scale clipped" if clipped else ""))
    if step > 1:
        ax.text(1.0, -0.08, f"every {step}th output row drawn", transform=ax.transAxes,
                ha="right", va="top", fontsize=7, color="gray")
    return light


def draw_speeds(ax, speeds, x0, x1, t_anchor, light):
    """Lines t = t_anchor + |x - x_start| / |c| over one period, named in a legend."""
    ink, halo = ("black", "white") if light else ("white", "black")
    outline = [patheffects.withStroke(linewidth=3.2, foreground=halo)]
    for label, c, style in speeds:
        start, end = (x0, x1) if c > 0 else (x1, x0)
        ax.plot([start, end], [t_anchor, t_anchor + (x1 - x0) / abs(c)], color=ink, lw=1.5,
                ls=style, path_effects=outline, label=f"{label} = {c:+.3f} m/s")
    # Below the axes, never over the fronts it names; its face matches the map so that the line
    # handles (ink and halo) read as they do on the map.
    legend = ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=len(speeds),
                       title="slopes $dt/dx = 1/c$", fontsize=7, columnspacing=1.0, handlelength=2.2,
                       facecolor="white" if light else "0.55", labelcolor=ink, framealpha=1.0)
    legend.get_title().set_color(ink)
    legend.get_title().set_fontsize(8)


def default_window(metrics, t_first, t_last):
    """Without --tmin: from a little before the slip onset of metrics.json (onset_time) if known."""
    onset = metrics.get("onset_time")
    if isinstance(onset, (int, float)) and np.isfinite(onset) and t_first < onset < t_last:
        return max(t_first, onset - 0.1 * (t_last - onset))
    return None


def main(argv=None):
    # 1. Parse options and read the run.
    args = parse_args(argv)
    metrics = read_json(args.metrics) if args.metrics else {}
    run = open_run(args.run)
    tmin = args.tmin
    if tmin is None:
        t_all = run.interface(args.field)[1]
        tmin = default_window(metrics, t_all[0], t_all[-1])
    x, t, values = run.interface(args.field, tmin, args.tmax)
    c_s, c_l, lam = run.attr("c_s"), run.attr("c_l"), run.attr("lambda")
    run_label = _style.run_label(run)

    # 2. The map.
    # Printed at half the text width (3.2 in): at this size its 9 pt text prints at ~6 pt.
    fig, ax = _style.plt.subplots(figsize=(4.4, 4.2))
    light = draw_field(ax, fig, x, t, values, args.field, args.vmax)
    ax.set_xlim(0.0, lam)
    ax.set_ylim(t[0], t[-1])
    ax.set_xlabel("position along the interface $x$ (m)")
    ax.set_ylabel("time $t$ (s)  [$t$ = 0: start of the dynamic stage]")

    # 3. Wave-speed slopes: c_p from the metrics, c_s and c_l in the same direction.
    c_p = metrics.get("celerity")
    c_p = float(c_p) if c_p is not None and np.isfinite(float(c_p)) and float(c_p) != 0 else None
    sign = np.sign(c_p) if c_p is not None else 1.0
    speeds = [("$c_l$", sign * c_l, ":"), ("$c_s$", sign * c_s, "--")]
    if c_p is not None:
        speeds.append(("$c_p$", c_p, "-"))
    window = metrics.get("celerity_window")
    t_anchor = t[0] + 0.05 * (t[-1] - t[0])
    if isinstance(window, (list, tuple)) and len(window) == 2 and t[0] <= window[0] < t[-1]:
        t_anchor = float(window[0])
    draw_speeds(ax, speeds, 0.0, lam, t_anchor, light)

    title = f"{FIELDS[args.field][0].capitalize()} on the interface\n{run_label}"
    if c_p is not None:
        title += f"\nmeasured front celerity $c_p$ = {c_p:.3f} m/s ({metrics.get('regime', '')})"
    ax.set_title(title)
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
