"""Resources of one `slidewave run`, estimated from mesh size and simulated time.

Cost per step measured on one core with the default solver, nu = 0.2, f = 1.5
(`build/bench/slidewave_bench_step`, docs/performance.md): 0.140 ms at H/32, 0.594 ms at H/64,
4.50 ms at H/128 (lambda = 2H) and 4.64 ms at H/64 with lambda = 6H. We fit a power of the mesh
(a factor 2^2.5 per halving of h, exact at H/32 and H/128, 30 % high at H/64) and of the period
(lambda/2H)^1.87 (the measured ratio 4.64/0.594 between 6H and 2H at H/64):

    ms_per_step = 0.14 (n / 32)^2.5 (lambda_over_H / 2)^1.87,   n_steps = t_end / dt,  dt = dt_times_cs / c_s.

The runtime asked from a scheduler is 3x the estimate plus 5 minutes (first slip and contact
iterations vary from point to point, and a shared node may be loaded); memory is dominated by the
operators of the mesh: measured max RSS ~50 MB at H/32, ~90-110 MB at H/64, ~650 MB at H/128
(lambda = 2H, Snakemake benchmark files); we ask 500 MB + 0.03 MB per element (1.5 GB at H/128).
"""

from __future__ import annotations

import math

from analysis.theory import elastic
from study.run_length import shear_wave_speed

#: The measurements the model is fitted to: (elements_per_H, lambda_over_H) -> ms per step on one
#: core (docs/performance.md). A new benchmark changes this table and the fit below, not the tests,
#: which check the fit against this table (tests/pipeline/test_run_length.py).
MEASURED_MS_PER_STEP = {(32, 2.0): 0.140, (64, 2.0): 0.594, (128, 2.0): 4.50, (64, 6.0): 4.64}
#: The model may overestimate a measurement by this factor, never underestimate it (by more than 1 %).
MAX_OVERESTIMATE = 1.35

MS_PER_STEP_H32 = 0.14
MESH_EXPONENT = 2.5    # per halving of h
PERIOD_EXPONENT = 1.87


def ms_per_step(elements_per_H: int, lambda_over_H: float) -> float:
    """Estimated wall time of one time step (ms) on one core."""
    return (MS_PER_STEP_H32 * (elements_per_H / 32.0) ** MESH_EXPONENT
            * (lambda_over_H / 2.0) ** PERIOD_EXPONENT)


def n_steps(*, E: float, nu: float, rho: float, t_end: float, dt_times_cs: float = 0.5,
            dt: float | None = None) -> int:
    """Number of stage-3 steps to reach t_end."""
    step = elastic.time_step(shear_wave_speed(E, nu, rho), dt_times_cs, dt)
    return elastic.n_steps(t_end, step)


def estimate(*, elements_per_H: int, lambda_over_H: float, steps: int) -> dict:
    """Scheduler resources of one run: {'runtime': minutes, 'mem_mb': MB, 'estimate_s': seconds}."""
    seconds = steps * ms_per_step(elements_per_H, lambda_over_H) / 1000.0
    n_elements = elements_per_H * elements_per_H * lambda_over_H
    return {"runtime": math.ceil(5 + 3 * seconds / 60.0),
            "mem_mb": math.ceil(500 + 0.03 * n_elements),
            "estimate_s": seconds}
