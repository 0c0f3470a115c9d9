"""The slipping set of one frame of the slip-velocity map and the edges of its runs.

A node slips when its slip velocity exceeds a threshold. In every output frame the slipping set is
cleaned (slipping runs narrower than `min_width_nodes` nodes are dropped, stick gaps narrower than
`fill_gap_nodes` are filled) and its edges are located to sub-grid precision by linear interpolation
of the slip velocity between the two nodes that straddle the threshold. A *right* edge ends a
slipping run towards +x, a *left* edge towards -x. `analysis.fronts.tracking` links the edges over time.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Slipping runs narrower than this many nodes are noise, not pulses.
DEFAULT_MIN_WIDTH_NODES = 2
#: Stick gaps narrower than this many nodes inside a slipping run are filled.
DEFAULT_FILL_GAP_NODES = 2


@dataclass(frozen=True)
class PeriodicGrid:
    """Uniform periodic grid of the interface nodes: first node x0 (m), spacing dx (m), n nodes,
    period = n dx (m)."""

    x0: float
    dx: float
    n: int

    @property
    def period(self) -> float:
        return self.n * self.dx

    @classmethod
    def from_nodes(cls, x: np.ndarray) -> "PeriodicGrid":
        """Grid of node positions x (m) that are uniformly spaced (node x0 + n dx is node x0)."""
        x = np.asarray(x, dtype=float)
        if x.ndim != 1 or x.size < 3:
            raise ValueError("x must be 1-D with at least 3 nodes")
        steps = np.diff(x)
        dx = float(np.mean(steps))
        if dx <= 0 or np.max(np.abs(steps - dx)) > 1e-6 * dx:
            raise ValueError("interface nodes are not uniformly spaced")
        return cls(x0=float(x[0]), dx=dx, n=int(x.size))

    def wrap_difference(self, d: np.ndarray | float) -> np.ndarray | float:
        """Periodic difference mapped to [-period/2, period/2) (m)."""
        p = self.period
        return (np.asarray(d) + 0.5 * p) % p - 0.5 * p


def _runs(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Periodic runs of True: (start indices, lengths). Empty when mask is all False or all True."""
    previous = np.roll(mask, 1)
    starts = np.flatnonzero(mask & ~previous)
    ends = np.flatnonzero(~mask & previous)
    if starts.size == 0:
        return starts, starts
    if ends[0] < starts[0]:
        ends = np.roll(ends, -1)
    return starts, (ends - starts) % mask.size


def _clear_short_runs(mask: np.ndarray, value: bool, min_length: int) -> np.ndarray:
    """Sets runs of `value` shorter than min_length to `not value` (periodically)."""
    target = mask if value else ~mask
    starts, lengths = _runs(target)
    out = mask.copy()
    n = mask.size
    for start, length in zip(starts, lengths):
        if length < min_length:
            out[(start + np.arange(length)) % n] = not value
    return out


def slipping_mask(v: np.ndarray, threshold: float, min_width_nodes: int = DEFAULT_MIN_WIDTH_NODES,
                  fill_gap_nodes: int = DEFAULT_FILL_GAP_NODES) -> np.ndarray:
    """Nodes of one frame that belong to a slip pulse.

    Parameters
    ----------
    v
        Slip velocity of the nodes (m/s), + = +x.
    threshold
        Slip velocity above which a node slips (m/s).
    min_width_nodes, fill_gap_nodes
        Slipping runs with fewer nodes are dropped first; then stick gaps with fewer nodes are
        filled.

    Returns
    -------
    Boolean mask, True where slipping.
    """
    mask = np.asarray(v) > threshold
    if min_width_nodes > 1:
        mask = _clear_short_runs(mask, True, min_width_nodes)
    if fill_gap_nodes > 1:
        mask = _clear_short_runs(mask, False, fill_gap_nodes)
    return mask


def edge_positions(v: np.ndarray, mask: np.ndarray, threshold: float,
                   grid: PeriodicGrid) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Edges of the slipping runs of a mask: (left positions, right positions, run peaks).

    Positions in m, in [x0, x0 + period); each edge lies between the last stick node and the first
    slipping node, where the linear interpolant of v crosses the threshold (clipped to that
    element). Run k has left edge left[k], right edge right[k] and peak slip velocity peaks[k] (m/s).
    """
    n = grid.n
    starts, lengths = _runs(mask)
    if starts.size == 0:
        empty = np.empty(0)
        return empty, empty, empty
    peaks = np.array([v[(start + np.arange(length)) % n].max() for start, length in zip(starts, lengths)])
    inside_left = starts                      # first slipping node
    outside_left = (starts - 1) % n           # stick node before it
    inside_right = (starts + lengths - 1) % n  # last slipping node
    outside_right = (starts + lengths) % n    # stick node after it

    def crossing(inside: np.ndarray, outside: np.ndarray) -> np.ndarray:
        v_in, v_out = v[inside], v[outside]
        span = v_in - v_out
        with np.errstate(divide="ignore", invalid="ignore"):
            frac = np.where(span > 0, (v_in - threshold) / span, 0.5)
        return np.clip(frac, 0.0, 1.0)

    # Left edge: from the stick node (index i-1) towards the slipping node i.
    left = outside_left + 1.0 - crossing(inside_left, outside_left)
    # Right edge: from the slipping node towards the stick node after it.
    right = inside_right + crossing(inside_right, outside_right)
    return grid.x0 + (left % n) * grid.dx, grid.x0 + (right % n) * grid.dx, peaks
