#!/usr/bin/python3
"""Animation of one run from its bulk snapshots (the paper's supplemental movie).

    figures/movie.py RUN.h5 --out movie.mp4
    figures/movie.py RUN.h5 --out movie.mp4 --fps 12 --tmin 700 --tmax 1300 --scale 200

One frame per bulk snapshot (/snapshots/NNNN) in [--tmin, --tmax]. Top: slip velocity and opening
of the interface at the output time nearest to the frame. Middle: the deformed layer coloured by
the material speed |v| (log scale, fixed over the movie); the displacement since the first frame
is magnified by --scale (default: so that the largest magnified displacement is 0.15 H; the factor
is printed on the frame and on stderr). Bottom: T/N against time with a marker at the frame time.
The time stamp gives t in s, in shear transit times t_s = H/c_s, and in t_s after the
quasi-static onset estimate (t_onset_estimate).

MP4 (H.264) through matplotlib's FFMpegWriter; when ffmpeg is missing a GIF is written instead,
next to the requested path with the suffix .gif, and stderr says so. A progress bar on stderr.
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np
from matplotlib import animation
from matplotlib.colors import LogNorm
from matplotlib.gridspec import GridSpec

import _style
from _data import InputError, open_run
from _movie_frames import layer_grid, progress

DISPLAY_FRACTION_OF_H = 0.15  # the default magnification shows the largest displacement at 0.15 H


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="run.h5 with /snapshots (output.snapshot_times in its config)")
    parser.add_argument("--out", required=True, help="movie file (.mp4; .gif forces the GIF writer)")
    parser.add_argument("--fps", type=float, default=12.0, help="frames per second (> 0)")
    parser.add_argument("--tmin", type=float, default=None, help="first frame time (s)")
    parser.add_argument("--tmax", type=float, default=None, help="last frame time (s)")
    parser.add_argument("--scale", type=float, default=None,
                        help="magnification of the displacement since the first frame (> 0)")
    parser.add_argument("--dpi", type=int, default=100, help="pixels per inch of the 8 x 8 in frame")
    args = parser.parse_args(argv)
    if not args.fps > 0:
        parser.error(f"--fps {args.fps:g}: must be > 0")
    if args.scale is not None and not args.scale > 0:
        parser.error(f"--scale {args.scale:g}: must be > 0")
    if not 20 <= args.dpi <= 400:
        parser.error(f"--dpi {args.dpi}: allowed 20 ... 400")
    return args


def choose_writer(out, fps):
    """(writer, path): FFMpegWriter for .mp4, or the GIF fallback when ffmpeg is missing."""
    out = Path(out)
    if out.suffix.lower() != ".gif" and animation.FFMpegWriter.isAvailable():
        return animation.FFMpegWriter(fps=fps, codec="libx264", bitrate=-1,
                                      extra_args=["-pix_fmt", "yuv420p", "-crf", "23"]), out
    gif = out.with_suffix(".gif")
    if out.suffix.lower() != ".gif":
        print(f"movie.py: ffmpeg not found: writing the GIF {gif} instead of {out}", file=sys.stderr)
    return animation.PillowWriter(fps=fps), gif


def main(argv=None):
    # 1. Options, the run, the frames in the requested time range.
    args = parse_args(argv)
    run = open_run(args.run)
    H, lam, c_s = run.attr("H"), run.attr("lambda"), run.attr("c_s")
    t_s, t_onset = H / c_s, run.attr("t_onset_estimate")
    snapshots, coordinates, connectivity = run.snapshots()
    frames = [s for s in snapshots if (args.tmin is None or s[1] >= args.tmin)
              and (args.tmax is None or s[1] <= args.tmax)]
    if len(frames) < 2:
        raise InputError(f"{args.run}: {len(frames)} bulk snapshot(s) in [{args.tmin}, {args.tmax}] s; "
                         f"a movie needs at least 2 (snapshots span {snapshots[0][1]:g} ... "
                         f"{snapshots[-1][1]:g} s)")
    nodes = layer_grid(coordinates)
    x_if, t_if, slip_velocity = run.interface("slip_velocity")
    opening = run.interface("opening")[2] * 1e3  # mm
    t_global, tn = run.series("t"), run.series("T_over_N")

    # 2. Scales fixed over the movie: magnification, speed colours, profile and T/N ranges.
    reference = frames[0][2]
    largest = max(float(np.abs(d - reference).max()) for _, _, d, _ in frames)
    scale = args.scale or (DISPLAY_FRACTION_OF_H * H / largest if largest > 0 else 1.0)
    print(f"movie.py: {len(frames)} frames, {frames[0][1]:.1f} ... {frames[-1][1]:.1f} s, displacement "
          f"since the first frame magnified x{scale:.4g}", file=sys.stderr)
    speeds = [np.hypot(v[:, 0], v[:, 1]) for _, _, _, v in frames]
    v_max = max(float(s.max()) for s in speeds)
    v_floor = max(float(run.attr("V0")), v_max * 1e-4) if v_max > 0 else 1.0
    norm = LogNorm(vmin=v_floor, vmax=max(v_max, 10 * v_floor))
    rows = np.abs(t_if[None, :] - np.array([f[1] for f in frames])[:, None]).argmin(axis=1)
    xs = np.append(x_if, lam)  # periodic: close the profiles at x = lambda
    closed = lambda a: np.concatenate([a, a[:, :1]], axis=1)  # noqa: E731
    sv, op = closed(slip_velocity[rows]), closed(opening[rows])
    pad = lambda lo, hi: (lo - 0.05 * (hi - lo or 1), hi + 0.05 * (hi - lo or 1))  # noqa: E731
    t_lo, t_hi = frames[0][1] - 0.05 * (frames[-1][1] - frames[0][1]), frames[-1][1] + 0.05 * (
        frames[-1][1] - frames[0][1])
    in_window = (t_global >= t_lo) & (t_global <= t_hi) & np.isfinite(tn)

    # 3. Layout: profiles above the layer, T/N at the bottom; a constant frame size for the encoder
    # (_style's "tight" bounding box would change the size from frame to frame).
    _style.plt.rcParams["savefig.bbox"] = "standard"
    fig = _style.plt.figure(figsize=(8.0, 8.0), dpi=args.dpi)
    grid = GridSpec(4, 2, figure=fig, height_ratios=[0.7, 0.7, 4.0, 1.0], width_ratios=[1, 0.025],
                    hspace=0.5, wspace=0.04, left=0.1, right=0.9, top=0.91, bottom=0.07)
    ax_v, ax_o, ax_map, ax_tn = (fig.add_subplot(grid[i, 0]) for i in range(4))
    cax = fig.add_subplot(grid[2, 1])
    line_v, = ax_v.plot(xs, sv[0], color="tab:orange", lw=1.2)
    ax_v.set_ylim(pad(min(0.0, sv.min()), sv.max()))
    ax_v.set_ylabel("slip velocity\n$\\dot u_x$ (m/s)")
    line_o, = ax_o.plot(xs, op[0], color="tab:blue", lw=1.2)
    ax_o.set_ylim(pad(0.0, op.max()))
    ax_o.set_ylabel("opening\n$u_y$ (mm)")
    for ax in (ax_v, ax_o):
        ax.set_xlim(0, lam)
        ax.grid(alpha=0.3)
    ax_o.set_xlabel("reference position $x$ (m)")
    ax_map.set_xlim(-0.05 * lam, 1.05 * lam)
    ax_map.set_ylim(-0.05 * H, 1.12 * H)
    ax_map.set_aspect("equal")  # the layer's true shape
    ax_map.axhline(0.0, color="0.2", lw=1.5)  # the rigid flat
    ax_map.set_ylabel("$y$ (m)")
    ax_map.text(0.0, 1.02, f"material speed $|\\mathbf{{v}}|$; displacement since $t$ = {frames[0][1]:.1f} s "
                f"magnified $\\times${scale:.3g}", fontsize=9, transform=ax_map.transAxes)
    ax_tn.plot(t_global[in_window], tn[in_window], color="0.2", lw=1.0)
    marker, = ax_tn.plot([], [], "o", color="tab:red", ms=6)
    ax_tn.set_xlim(t_lo, t_hi)
    ax_tn.set_xlabel("time $t$ (s)")
    ax_tn.set_ylabel("$T/N$")
    ax_tn.grid(alpha=0.3)
    stamp = fig.text(0.03, 0.945, "", fontsize=10, family="monospace")
    fig.text(0.97, 0.975, _style.run_label(run), fontsize=8, ha="right")
    mesh = None

    # 4. Frames.
    writer, path = choose_writer(args.out, args.fps)
    path.parent.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    with writer.saving(fig, str(path), args.dpi):
        for k, (_, t, displacement, _) in enumerate(frames):
            moved = coordinates + scale * (displacement - reference)
            if mesh is not None:
                mesh.remove()
            mesh = ax_map.pcolormesh(moved[nodes, 0], moved[nodes, 1], speeds[k][nodes], shading="gouraud",
                                     cmap="inferno", norm=norm, rasterized=True)
            if k == 0:
                fig.colorbar(mesh, cax=cax, extend="min").set_label("$|\\mathbf{v}|$ (m/s)")
            line_v.set_ydata(sv[k])
            line_o.set_ydata(op[k])
            ax_v.set_title(f"interface at $t$ = {t_if[rows[k]]:.1f} s", fontsize=8, loc="right", color="0.3")
            marker.set_data([t], [np.interp(t, t_global, tn)])
            stamp.set_text(f"t = {t:7.1f} s = {t / t_s:5.2f} t_s   (onset est. + {(t - t_onset) / t_s:5.2f} t_s)")
            writer.grab_frame()
            progress(k + 1, len(frames), started)
    _style.plt.close(fig)
    size = path.stat().st_size
    print(f"movie.py: wrote {path} ({size / 1e6:.2f} MB, {len(frames)} frames at {args.fps:g} fps, "
          f"{time.monotonic() - started:.1f} s)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    _style.cli(main)
