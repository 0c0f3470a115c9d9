"""Helpers of figures/movie.py: the layer's nodes as a structured grid, and a progress bar."""
import sys
import time

import numpy as np

from _data import InputError


def layer_grid(coordinates):
    """(n_y + 1, n_x + 1) node indices of the unwrapped layer mesh, rows bottom to top.

    The snapshot mesh is a structured grid of quadrilaterals whose column x = lambda repeats x = 0
    (docs/contracts.md section 2); as a node grid it draws with one pcolormesh per frame, much faster
    than a triangulation. Raises InputError when the coordinates are not such a grid.
    """
    def levels(values):
        spacing = np.ptp(values) or 1.0
        keys = np.round(values / spacing * 1e6).astype(np.int64)
        unique, index = np.unique(keys, return_inverse=True)
        return len(unique), index

    n_x, ix = levels(coordinates[:, 0])
    n_y, iy = levels(coordinates[:, 1])
    nodes = np.full((n_y, n_x), -1, dtype=np.int64)
    nodes[iy, ix] = np.arange(len(coordinates))
    if n_x * n_y != len(coordinates) or np.any(nodes < 0):
        raise InputError(f"the snapshot mesh ({len(coordinates)} nodes on {n_x} x {n_y} distinct x, y) "
                         "is not a structured grid")
    return nodes


def progress(done, total, started, stream=sys.stderr, width=30):
    """A bar on one line ('\\r') on a terminal; in a log, a line at every 10 % and at the end."""
    elapsed = time.monotonic() - started
    remaining = elapsed / done * (total - done) if done else 0.0
    filled = int(width * done / total)
    text = (f"[{'#' * filled}{'.' * (width - filled)}] {done}/{total} frames, {elapsed:.0f} s"
            f" (about {remaining:.0f} s left)")
    if stream.isatty():
        stream.write("\r" + text + ("\n" if done == total else ""))
    elif done == total or done * 10 // total != (done - 1) * 10 // total:
        stream.write(text + "\n")
    stream.flush()
