"""Resources of one `slidewave run` job for a scheduler, estimated from mesh size and simulated time.

The constants are measured, not written here: study/resources.json, fitted by
`/usr/bin/python3 -m study.fit_resources results/runs` from the Snakemake benchmark files of a
campaign (study/fit_resources.py says how). The model has the two phases of a run apart: before the
slip onset every node sticks and the solver steps the linear problem in wavenumbers
(docs/stick-phase.md), several times cheaper per step than after it and growing more slowly with the
mesh; after it a step is the layer's work plus the Gauss–Seidel contact solve, whose share grows fast
with the mesh (more nodes, more sweeps: 0.07 ms of a 0.30 ms step at H/64, 0.41 of 1.47 ms at H/128 in
the step bench, most of a step at H/256). One power law for all fitted none of them (an H/128 run at 4.5
times its fit):

    seconds = setup_s + (n_stick ms_stick + (n_steps - n_stick) (ms_slip + ms_contact)) / 1000
    ms_slip    = ms_per_step_h32         (n / 32)^mesh_exponent         (lambda_over_H / 2)^period_exponent
    ms_contact = contact_ms_per_step_h32 (n / 32)^contact_mesh_exponent (lambda_over_H / 2)^period_exponent
    ms_stick   = stick_ms_per_step_h32   (n / 32)^stick_mesh_exponent   (lambda_over_H / 2)^stick_period_exponent
    memory  = base_mb + mb_per_element * n^2 lambda_over_H          (n = elements_per_H)

with n_steps = t_end / dt, dt = dt_times_cs / c_s: the cap of the run (a run that stops after the
interface opens makes fewer steps, which is not known before it runs), and n_stick the steps up to
the quasi-static onset estimate (study/run_length.py, eq. 1), at most n_steps, where the solver has
a stick phase (`has_stick_phase`: not on a substrate, not with Prakash–Clifton's regularization), else
0. Asked from a scheduler: TIME_MARGIN x the estimate plus 5 minutes (a shared node may be loaded, the
contact iterations vary from point to point), and MEMORY_MARGIN x the memory estimate plus MEMORY_FLOOR_MB.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

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


def _ms_per_step(time: dict, prefix: str, elements_per_H: int, lambda_over_H: float) -> float:
    """ms per step of one part: '' the layer's after the onset, 'contact_' the contact solve's after it,
    'stick_' a step before it (the contact solve's period exponent is the layer's)."""
    period_exponent = time.get(f"{prefix}period_exponent", time["period_exponent"])
    return (time[f"{prefix}ms_per_step_h32"] * (elements_per_H / 32.0) ** time[f"{prefix}mesh_exponent"]
            * (lambda_over_H / 2.0) ** period_exponent)


def seconds(elements_per_H: int, lambda_over_H: float, steps: int, constants: dict = CONSTANTS, *,
            stick_steps: int = 0) -> float:
    """Estimated wall time (s) of a run of `steps` time steps, the first `stick_steps` of them before the
    slip onset, on one core. Numbers or numpy arrays (study/fit_resources.py fits this same formula over
    a campaign's runs at once)."""
    time = constants["time"]
    stick = np.minimum(stick_steps, steps)
    slip = _ms_per_step(time, "", elements_per_H, lambda_over_H) + _ms_per_step(time, "contact_", elements_per_H,
                                                                                 lambda_over_H)
    return time["setup_s"] + (stick * _ms_per_step(time, "stick_", elements_per_H, lambda_over_H)
                              + (steps - stick) * slip) / 1000.0


def memory_mb(elements_per_H: int, lambda_over_H: float, constants: dict = CONSTANTS) -> float:
    """Estimated peak memory (MB) of a run."""
    memory = constants["memory"]
    return memory["base_mb"] + memory["mb_per_element"] * elements_per_H ** 2 * lambda_over_H


def has_stick_phase(config: dict) -> bool:
    """Whether the solver steps a run's phase before the onset in wavenumbers (its stick_phase_applies,
    model/stick_phase/stick_phase_run.hpp): on the rigid flat, under plain Coulomb friction with f > 0.
    Otherwise those steps are slip steps as far as their cost goes. `config`: the run's config.json."""
    friction = config.get("friction", {})
    return (not config.get("substrate") and friction.get("f", 1.0) > 0
            and friction.get("regularization", "none") in (None, "none"))


def n_steps(*, E: float, nu: float, rho: float, t_end: float, dt_times_cs: float = 0.5,
            dt: float | None = None) -> int:
    """Number of stage-3 steps to reach t_end."""
    step = elastic.time_step(shear_wave_speed(E, nu, rho), dt_times_cs, dt)
    return elastic.n_steps(t_end, step)


def estimate(*, elements_per_H: int, lambda_over_H: float, steps: int, stick_steps: int = 0,
             constants: dict = CONSTANTS) -> dict:
    """Scheduler resources of one run: {'runtime': minutes, 'mem_mb': MB, 'estimate_s': seconds}."""
    wall = seconds(elements_per_H, lambda_over_H, steps, constants, stick_steps=stick_steps)
    memory = memory_mb(elements_per_H, lambda_over_H, constants)
    return {"runtime": math.ceil(5 + TIME_MARGIN * wall / 60.0),
            "mem_mb": math.ceil(MEMORY_FLOOR_MB + MEMORY_MARGIN * memory),
            "estimate_s": wall}
