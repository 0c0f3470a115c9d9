"""How often a study run writes the interface: the output stride rule of docs/output-sampling.md.

The analysis follows slip fronts from frame to frame, which fails when a front moves a large part of
the period between two frames (at nu = 0.49 a backward supersonic front at stride 4 moves 0.4 lambda
and its tracks break up). The study therefore writes the interface so that a front at the fastest
speed the theory admits for the point,

    v_max = max(c_l, c_Adams(nu, f) [, c_l of the substrate]),

moves at most a quarter of the period per frame:

    stride = min(4, max(1, floor(lambda / (4 v_max dt)))).

4, the solver's default, is the ceiling, and a stride of 4 is left out of config.json.
"""

from __future__ import annotations

import math

from analysis.fronts.sampling_limit import frame_shift_fraction
from analysis.theory import elastic
from analysis.theory.supersonic import supersonic_trace_speed

#: The solver's `output.interface_stride` default (docs/contracts.md), the rule's ceiling.
SOLVER_DEFAULT_STRIDE = 4
#: Largest shift of a front at v_max between two interface frames, as a fraction of the period.
MAX_SHIFT_PER_FRAME = 0.25


def fastest_front_speed(*, E: float, nu: float, rho: float, f: float, substrate: dict | None = None) -> float:
    """v_max (m/s): the layer's c_l, Adams' backward trace speed on the rigid flat (none at nu = 0) and,
    on a substrate ({E, nu, rho, ...}), the substrate's c_l, whichever is largest."""
    c_s = elastic.shear_wave_speed(E, nu, rho)
    speeds = [elastic.longitudinal_wave_speed(E, nu, rho), supersonic_trace_speed(nu, f, c_s) or 0.0]
    if substrate is not None:
        speeds.append(elastic.longitudinal_wave_speed(substrate["E"], substrate["nu"], substrate["rho"]))
    return max(speeds)


def interface_stride(*, E: float, nu: float, rho: float, f: float, H: float, lambda_over_H: float,
                     dt_times_cs: float, substrate: dict | None = None) -> int:
    """Steps between two interface frames (module docstring), in [1, SOLVER_DEFAULT_STRIDE]: the frame shift of
    the analysis's sampling limit (`frame_shift_fraction`), per step, for a front at v_max."""
    dt = elastic.time_step(elastic.shear_wave_speed(E, nu, rho), dt_times_cs)
    v_max = fastest_front_speed(E=E, nu=nu, rho=rho, f=f, substrate=substrate)
    shift_per_step = frame_shift_fraction(v_max, dt, lambda_over_H * H)
    return min(SOLVER_DEFAULT_STRIDE, max(1, math.floor(MAX_SHIFT_PER_FRAME / shift_per_step)))
