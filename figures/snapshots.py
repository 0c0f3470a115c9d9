#!/usr/bin/python3
"""Instantaneous states of the layer at the bulk snapshots (paper Fig. 3).

    figures/snapshots.py RUN.h5 --out fig3
    figures/snapshots.py RUN.h5 --scale 150 --columns 3 --out fig3

One block per snapshot in /snapshots/NNNN: on top the magnitude of the material velocity |v| on
the deformed layer, the displacement since the first snapshot magnified by --scale (the dashed
outline is the layer at the first snapshot, i.e. before the slip if the first snapshot is taken
then); beneath it the slip velocity and the opening against the reference position x, at the
interface output time nearest to the snapshot. All blocks share their colour scale and axes; the
colour scale is logarithmic (from V0, or 1e-4 of the largest speed, up to the largest speed) so that
the slow early snapshots are not black beside the fast pulses of the later ones; the x-range covers
the whole magnified layer.
"""
import argparse
import string

import numpy as np
from matplotlib.colors import LogNorm
from matplotlib.gridspec import GridSpec
from matplotlib.patches import Rectangle

import _style
from _data import InputError, open_run


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="run.h5 with /snapshots (a format analysis.core.io reads)")
    parser.add_argument("--scale", type=float, default=150.0,
                        help="magnification of the displacement since the first snapshot")
    parser.add_argument("--columns", type=int, default=3, help="blocks per row")
    parser.add_argument("--out", required=True, help="output prefix: writes PREFIX.png, PREFIX.pdf")
    return parser.parse_args(argv)


def element_corners(coordinates, connectivity, lam):
    """(n_el, 4, 2) corner coordinates; an element that wraps across x = lambda is unwrapped."""
    corners = coordinates[connectivity].astype(float)
    x = corners[..., 0]
    wraps = (x.max(axis=1) - x.min(axis=1)) > lam / 2
    x[wraps] = np.where(x[wraps] < lam / 2, x[wraps] + lam, x[wraps])
    return corners


def draw_layer(ax, moved, speed, connectivity, norm, H, lam):
    """|v| on the deformed mesh (corners `moved`), Gouraud-shaded on two triangles per quad."""
    points = moved.reshape(-1, 2)
    base = 4 * np.arange(len(connectivity))[:, None]
    triangles = np.concatenate([base + [0, 1, 2], base + [0, 2, 3]])
    image = ax.tripcolor(points[:, 0], points[:, 1], triangles, speed[connectivity].ravel(),
                         shading="gouraud", cmap="inferno", norm=norm, rasterized=True)
    ax.add_patch(Rectangle((0, 0), lam, H, fill=False, ls="--", lw=0.8, color="0.4"))
    ax.axhline(0.0, color="0.2", lw=1.5)  # the rigid flat
    return image


def main(argv=None):
    # 1. Parse options and read snapshots and the interface rows nearest to them.
    args = parse_args(argv)
    run = open_run(args.run)
    snapshots, coordinates, connectivity = run.snapshots()
    H, lam = run.attr("H"), run.attr("lambda")
    x, t_out, slip_velocity = run.interface("slip_velocity")
    opening = run.interface("opening")[2] * 1e3  # mm
    times = np.array([s[1] for s in snapshots])
    nearest = np.abs(t_out[None, :] - times[:, None]).argmin(axis=1)
    slip_velocity, opening = slip_velocity[nearest], opening[nearest]
    label = _style.run_label(run)
    if connectivity.ndim != 2 or connectivity.shape[1] != 4:
        raise InputError(f"{args.run}: /snapshots/connectivity has shape {connectivity.shape}, "
                         "expected (n_elements, 4)")
    for name, _, displacement, velocity in snapshots:
        if displacement.shape != coordinates.shape or velocity.shape != coordinates.shape:
            raise InputError(f"{args.run}: /snapshots/{name} fields have shapes "
                             f"{displacement.shape}, {velocity.shape}; coordinates "
                             f"{coordinates.shape}")

    # 2. Shared scales: one colour scale for |v|, one y-range per profile kind.
    speeds = [np.hypot(v[:, 0], v[:, 1]) for _, _, _, v in snapshots]
    v_max = max(float(s.max()) for s in speeds) or 1.0
    v_floor = min(max(run.attr("V0"), 1e-4 * v_max), 0.1 * v_max)
    norm = LogNorm(v_floor, v_max)
    speeds = [np.maximum(s, v_floor) for s in speeds]  # below the floor: the floor's colour
    xs = np.append(x, lam)  # periodic: close the profiles at x = lambda
    close = lambda a: np.concatenate([a, a[:, :1]], axis=1)  # noqa: E731
    slip_velocity, opening = close(slip_velocity), close(opening)
    pad = lambda lo, hi: (lo - 0.05 * (hi - lo or 1), hi + 0.05 * (hi - lo or 1))  # noqa: E731
    v_lim = pad(min(0.0, slip_velocity.min()), slip_velocity.max())
    o_lim = pad(0.0, opening.max())

    # 3. Layout: blocks of (layer map, slip-velocity profile, opening profile).
    n = len(snapshots)
    columns = max(1, min(args.columns, n))
    block_rows = -(-n // columns)
    width = 2.9  # per block: printed at the text width (6.5 in), 3 blocks keep 9 pt text at ~6 pt
    map_height = max(0.8, width * 0.8 * (1.35 * H) / lam)
    heights = [map_height, 0.75, 0.75, 0.7]
    fig = _style.plt.figure(figsize=(width * columns + 0.9, sum(heights) * block_rows + 1.0))
    grid = GridSpec(4 * block_rows, columns, figure=fig, height_ratios=heights * block_rows,
                    hspace=0.12, wspace=0.28, left=0.06, right=0.9, top=1 - 0.9 / fig.get_figheight(),
                    bottom=0.5 / fig.get_figheight())
    corners = element_corners(coordinates, connectivity, lam)
    reference = snapshots[0][2]
    moved = [corners + args.scale * (s[2] - reference)[connectivity] for s in snapshots]
    # One x-range for every panel: the whole magnified layer, and profiles aligned with it.
    x_lo = min(0.0, min(float(m[..., 0].min()) for m in moved))
    x_hi = max(lam, max(float(m[..., 0].max()) for m in moved))
    x_range = (x_lo - 0.02 * lam, x_hi + 0.02 * lam)
    image = None
    for k, (_, t_snap, _, _) in enumerate(snapshots):
        r, c = divmod(k, columns)
        ax_map, ax_v, ax_o = (fig.add_subplot(grid[4 * r + i, c]) for i in range(3))
        image = draw_layer(ax_map, moved[k], speeds[k], connectivity, norm, H, lam)
        ax_map.set_xlim(x_range)
        ax_map.set_ylim(-0.15 * H, 1.2 * H)
        ax_map.set_xticklabels([])
        ax_map.set_ylabel("$y$ (m)")
        ax_map.set_title(f"({string.ascii_lowercase[k % 26]}) $t$ = {t_snap:.1f} s", loc="left")
        t_if = t_out[nearest[k]]
        ax_v.plot(xs, slip_velocity[k], color="tab:orange", lw=1.0)
        ax_v.set_ylim(v_lim)
        ax_v.set_ylabel("$\\dot u_x$ (m/s)")
        ax_map.set_title(f"profiles at {t_if:.1f} s", loc="right",
                         fontsize=7, color="0.3")
        ax_o.fill_between(xs, 0.0, opening[k], color="tab:cyan", lw=0.8, ec="tab:blue")
        ax_o.set_ylim(o_lim)
        ax_o.set_ylabel("$u_y$ (mm)")
        ax_o.set_xlabel("reference position $x$ (m)")
        for ax in (ax_v, ax_o):
            ax.set_xlim(ax_map.get_xlim())
            ax.grid(alpha=0.3)
        ax_v.set_xticklabels([])

    # 4. Colour bar and title.
    cax = fig.add_axes([0.92, 0.3, 0.013, 0.4])
    fig.colorbar(image, cax=cax, extend="min").set_label("material velocity $|\\mathbf{v}|$ (m/s)")
    fig.suptitle(f"Material velocity in the layer (displacement since $t$ = {snapshots[0][1]:.1f} s "
                 f"magnified $\\times${args.scale:g}; dashed: layer at that time), interface slip "
                 f"velocity and opening\n{label}", fontsize=9)
    _style.save(fig, args.out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
