"""Roots of an analytic function in a rectangle of the complex plane, by the argument principle.

`winding_number` counts the zeros inside a box (minus the poles) from the phase of the function
along its edges, sampled densely near given features (branch points, poles on the real axis) and
refined where the phase jumps; `isolate_roots` bisects the box until each part holds one root and
refines it by `newton_root`. Used by `analysis.theory.bimaterial_stability` for the roots of the
sliding dispersion relation (docs/bimaterial-theory.md, section 4); numbers in, numbers out.
"""

from __future__ import annotations

import math

import numpy as np


def edge_points(a: complex, b: complex, features: np.ndarray, n_base: int = 64,
                 n_cluster: int = 40) -> np.ndarray:
    """Points of the segment a -> b (a included, b not), clustered geometrically towards the point
    of the segment nearest to each feature (the origin and the branch points): Psi varies on the
    scale of the distance to them (|Psi| ~ |s|^3 far out, square roots at the branch points)."""
    length = abs(b - a)
    direction = (b - a) / length
    nearest = np.empty(len(features))
    distance = np.empty(len(features))
    for i, z in enumerate(features):
        along = ((z - a) * np.conj(direction)).real / length
        nearest[i] = min(max(along, 0.0), 1.0)
        distance[i] = abs(a + nearest[i] * (b - a) - z)
    # one geomspace for all features (it is called per edge of every contour: the same numbers as one
    # call per feature, checked, at a fraction of the calls)
    offsets = np.geomspace(np.maximum(distance, 1e-13 * length), length, n_cluster, axis=-1) / length
    t = np.unique(np.concatenate([np.linspace(0.0, 1.0, n_base, endpoint=False), (nearest[:, None] + offsets).ravel(),
                                  (nearest[:, None] - offsets).ravel(), nearest]))
    t = t[(t >= 0.0) & (t < 1.0)]
    return a + t * (b - a)


def winding_number(fun, x0: float, x1: float, y0: float, y1: float, features: np.ndarray) -> int:
    """Zeros of fun inside the rectangle (argument principle). The contour is sampled densely near
    the features (``edge_points``) and refined adaptively: segments whose phase change exceeds
    0.4 rad are halved until none is left."""
    corners = [complex(x0, y0), complex(x1, y0), complex(x1, y1), complex(x0, y1), complex(x0, y0)]
    path = np.concatenate([edge_points(a, b, features) for a, b in zip(corners[:-1], corners[1:])]
                          + [np.array([corners[0]])])
    values = fun(path)
    for _ in range(80):
        if not np.all(np.isfinite(values)) or np.any(values == 0):
            raise ArithmeticError("the dispersion function vanishes or is not finite on the contour")
        step = np.angle(values[1:] / values[:-1])
        coarse = np.flatnonzero(np.abs(step) > 0.4)
        if coarse.size == 0:
            return int(round(float(np.sum(step)) / (2.0 * math.pi)))
        if np.min(np.abs(path[coarse + 1] - path[coarse])) < 1e-15 * (x1 - x0 + y1 - y0):
            raise ArithmeticError("argument principle: a zero lies on the contour")
        middle = 0.5 * (path[coarse] + path[coarse + 1])
        path = np.insert(path, coarse + 1, middle)
        values = np.insert(values, coarse + 1, fun(middle))
    raise ArithmeticError("argument principle: contour refinement did not converge")


def newton_root(fun, s: complex, box=None, max_iterations: int = 60) -> complex | None:
    """Newton's method on fun from s; None if it stalls or leaves box (x0, x1, y0, y1) enlarged by
    half its size on every side (the root sought lies in the box)."""
    if box is not None:
        x0, x1, y0, y1 = box
        margin = 0.5 * max(x1 - x0, y1 - y0)
    step = complex(math.inf)
    for _ in range(max_iterations):
        h = 1e-7 * max(1.0, abs(s))
        values = fun(np.array([s, s + h, s - h]))
        slope = complex((values[1] - values[2]) / (2.0 * h))
        if slope == 0 or not math.isfinite(abs(slope)):
            return None
        step = complex(values[0]) / slope
        s -= step
        if box is not None and not (x0 - margin <= s.real <= x1 + margin and y0 - margin <= s.imag <= y1 + margin):
            return None
        if abs(step) <= 1e-15 * max(1.0, abs(s)):
            return s
    return s if abs(step) <= 1e-10 * max(1.0, abs(s)) else None


def isolate_roots(fun, box, n_roots: int, size_floor: float, features: np.ndarray,
             depth: int = 0) -> list[complex]:
    """Roots of fun inside box = (x0, x1, y0, y1) holding n_roots of them (bisection + Newton)."""
    if n_roots == 0:
        return []
    x0, x1, y0, y1 = box
    if n_roots == 1:
        root = newton_root(fun, complex(0.5 * (x0 + x1), 0.5 * (y0 + y1)), box)
        # a zero of fun inside the box is its only one (the count is 1); the bottom edge is strict,
        # a neutral root just below it must not be taken for the growing one
        pad = 1e-12 * max(x1 - x0, y1 - y0)
        if root is not None and x0 - pad <= root.real <= x1 + pad and y0 < root.imag <= y1 + pad:
            return [root]
    if max(x1 - x0, y1 - y0) < size_floor or depth > 200:
        centre = newton_root(fun, complex(0.5 * (x0 + x1), 0.5 * (y0 + y1))) or complex(0.5 * (x0 + x1), 0.5 * (y0 + y1))
        return [centre] * n_roots  # a multiple root (or a cluster below the floor)
    # halve the longer side; the cut is moved off the middle if a zero lies on it
    for fraction in (0.5, 0.4871, 0.5219, 0.4473):
        if x1 - x0 >= y1 - y0:
            cut = x0 + fraction * (x1 - x0)
            halves = ((x0, cut, y0, y1), (cut, x1, y0, y1))
        else:
            cut = y0 + fraction * (y1 - y0)
            halves = ((x0, x1, y0, cut), (x0, x1, cut, y1))
        try:
            counts = [winding_number(fun, *half, features) for half in halves]
        except ArithmeticError:
            continue
        if sum(counts) == n_roots:
            break
    else:
        raise ArithmeticError("root isolation failed: inconsistent zero counts")
    roots: list[complex] = []
    for half, count in zip(halves, counts):
        roots.extend(isolate_roots(fun, half, count, size_floor, features, depth + 1))
    return roots
