"""Opening of the interface (u_y > 0): whether, how much, where and when it first occurs.

Threshold: the run's own `opening_threshold` (a `/setup` attribute: 1 % of the preload displacement
|Uy|, the one that drives the solver's `stop_after_opening`), i.e. 1e-5 H at the default preload
Uy = -1e-3 H (0.25 mm at H = 25 m). Closed nodes carry round-off (~1e-13 m in the solver); opening
waves open by 0.6 mm to 15 cm (all 36 opening cells of the H/32 Table-1 sweep). Between the two,
nu = 0.2, f = 0.8 shows one transient lift-off of 4e-5 m (0.16 % of |Uy|, three output frames)
during its frictional drop and no travelling opening; the 1 % criterion calls that "no opening
wave", and `max_opening` keeps the number so that the choice stays visible.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class OpeningSummary:
    """opened (bool); max_opening (m, over all nodes and outputs); t_first (s) and x_first (m):
    the first output time with u_y above the threshold and the node opened most then (nan if
    never); t_max (s): when the maximum occurs; open_fraction_max: largest fraction of the
    interface open at one output."""

    opened: bool
    max_opening: float
    t_first: float
    x_first: float
    t_max: float
    open_fraction_max: float


def summarize_opening(x: np.ndarray, t: np.ndarray, u_y: np.ndarray, threshold: float) -> OpeningSummary:
    """Opening summary of an interface opening map.

    Parameters
    ----------
    x, t
        Node positions (m), output times (s).
    u_y
        Opening (m), shape (n_out, n_c).
    threshold
        Opening threshold (m), > 0.
    """
    u_y = np.asarray(u_y, dtype=float)
    is_open = u_y > threshold
    k_max, i_max = np.unravel_index(int(np.argmax(u_y)), u_y.shape)
    frames = np.flatnonzero(is_open.any(axis=1))
    if frames.size == 0:
        t_first = x_first = math.nan
    else:
        k = int(frames[0])
        t_first, x_first = float(t[k]), float(x[int(np.argmax(u_y[k]))])
    return OpeningSummary(opened=bool(frames.size), max_opening=float(u_y[k_max, i_max]),
                          t_first=t_first, x_first=x_first, t_max=float(t[k_max]),
                          open_fraction_max=float(is_open.mean(axis=1).max()))


def distance_behind_front(x_open: float, fronts: np.ndarray, direction: int, period: float) -> float:
    """Distance (m) from the nearest slip front ahead of a point back to it, along the propagation.

    Parameters
    ----------
    x_open
        Position of the point (m), e.g. where the interface first opens.
    fronts
        Positions of the slip fronts at that time (m, any periodic image).
    direction
        Propagation direction of the fronts, +1 or -1.
    period
        Period of the interface (m).

    Returns
    -------
    Distance in [0, period) (m): 0 = at the front, small = just behind it; nan without fronts.
    """
    fronts = np.asarray(fronts, dtype=float)
    if fronts.size == 0 or direction == 0:
        return math.nan
    return float(np.min((direction * (fronts - x_open)) % period))
