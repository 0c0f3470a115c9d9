"""Resources of one `slidewave run` job for a scheduler, estimated from mesh size and simulated time.

The constants are measured, not written here: study/resources.json, fitted by
`/usr/bin/python3 -m study.fit_resources results/runs` from the Snakemake benchmark files of a
campaign (study/fit_resources.py says how). The model:

    seconds = setup_s + n_steps * ms_per_step_h32 (n / 32)^mesh_exponent (lambda_over_H / 2)^period_exponent / 1000
    memory  = base_mb + mb_per_element * n^2 lambda_over_H          (n = elements_per_H)

with n_steps = t_end / dt, dt = dt_times_cs / c_s: the cap of the run; a run that stops after the
interface opens makes fewer steps, which is not known before it runs. Asked from a scheduler:
TIME_MARGIN x the estimate plus 5 minutes (a shared node may be loaded, the contact iterations vary
from point to point), and MEMORY_MARGIN x the memory estimate plus MEMORY_FLOOR_MB.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from analysis.theory import elastic
from study.run_length import shear_wave_speed

CONSTANTS_FILE = Path(__file__).with_name("resources.json")
TIME_MARGIN = 3.0
MEMORY_MARGIN = 1.5
MEMORY_FLOOR_MB = 100


def load_constants(path: Path | str = CONSTANTS_FILE) -> dict:
    """{'time': {...}, 'memory': {...}, 'fitted_from': {...}} of a constants file."""
    return json.loads(Path(path).read_text())


CONSTANTS = load_constants()


def seconds(elements_per_H: int, lambda_over_H: float, steps: int, constants: dict = CONSTANTS) -> float:
    """Estimated wall time (s) of a run of `steps` time steps on one core."""
    time = constants["time"]
    ms = (time["ms_per_step_h32"] * (elements_per_H / 32.0) ** time["mesh_exponent"]
          * (lambda_over_H / 2.0) ** time["period_exponent"])
    return time["setup_s"] + steps * ms / 1000.0


def memory_mb(elements_per_H: int, lambda_over_H: float, constants: dict = CONSTANTS) -> float:
    """Estimated peak memory (MB) of a run."""
    memory = constants["memory"]
    return memory["base_mb"] + memory["mb_per_element"] * elements_per_H ** 2 * lambda_over_H


def n_steps(*, E: float, nu: float, rho: float, t_end: float, dt_times_cs: float = 0.5,
            dt: float | None = None) -> int:
    """Number of stage-3 steps to reach t_end."""
    step = elastic.time_step(shear_wave_speed(E, nu, rho), dt_times_cs, dt)
    return elastic.n_steps(t_end, step)


def estimate(*, elements_per_H: int, lambda_over_H: float, steps: int, constants: dict = CONSTANTS) -> dict:
    """Scheduler resources of one run: {'runtime': minutes, 'mem_mb': MB, 'estimate_s': seconds}."""
    wall = seconds(elements_per_H, lambda_over_H, steps, constants)
    memory = memory_mb(elements_per_H, lambda_over_H, constants)
    return {"runtime": math.ceil(5 + TIME_MARGIN * wall / 60.0),
            "mem_mb": math.ceil(MEMORY_FLOOR_MB + MEMORY_MARGIN * memory),
            "estimate_s": wall}
