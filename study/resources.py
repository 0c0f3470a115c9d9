"""Resources of one `slidewave run`, estimated from mesh size and simulated time.

Cost per step measured on one core with reduced integration, lambda = 2H (PHYSICS-NOTES.md):
~1.4 ms at H/32 and ~9 ms at H/64, i.e. a factor 2^2.68 per halving of h. We assume the same
power of the element count when the period grows:

    ms_per_step = 1.4 (n / 32)^2.68 (lambda_over_H / 2)^1.34,   n_steps = t_end / dt,  dt = dt_times_cs / c_s.

The runtime asked from a scheduler is 3x the estimate plus 5 minutes (first slip and contact
iterations vary from point to point); memory is dominated by the sparse factor of the effective
matrix: measured max RSS ~50 MB at H/32, ~90-110 MB at H/64, ~650 MB at H/128 (lambda = 2H); we
ask 500 MB + 0.03 MB per element (1.5 GB at H/128).
"""

from __future__ import annotations

import math

from study.run_length import shear_wave_speed

MS_PER_STEP_H32 = 1.4
MESH_EXPONENT = 2.68


def ms_per_step(elements_per_H: int, lambda_over_H: float) -> float:
    """Estimated wall time of one time step (ms) on one core."""
    return (MS_PER_STEP_H32 * (elements_per_H / 32.0) ** MESH_EXPONENT
            * (lambda_over_H / 2.0) ** (MESH_EXPONENT / 2.0))


def n_steps(*, E: float, nu: float, rho: float, t_end: float, dt_times_cs: float = 0.5,
            dt: float | None = None) -> int:
    """Number of stage-3 steps to reach t_end."""
    step = dt if dt is not None else dt_times_cs / shear_wave_speed(E, nu, rho)
    return math.ceil(t_end / step * (1.0 - 1e-12))  # an exact multiple is not one step more


def estimate(*, elements_per_H: int, lambda_over_H: float, steps: int) -> dict:
    """Scheduler resources of one run: {'runtime': minutes, 'mem_mb': MB, 'estimate_s': seconds}."""
    seconds = steps * ms_per_step(elements_per_H, lambda_over_H) / 1000.0
    n_elements = elements_per_H * elements_per_H * lambda_over_H
    return {"runtime": math.ceil(5 + 3 * seconds / 60.0),
            "mem_mb": math.ceil(500 + 0.03 * n_elements),
            "estimate_s": seconds}
