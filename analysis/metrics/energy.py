"""Energy balance of a run, from the solver's global series.

The solver writes residual(t) = (E_kin + E_el + D_fric + W_normal)(t) - (E_kin + E_el)(0) - W_ext(t)
(J/m), W_normal being the work of the normal contact forces (energy lost at closing contacts;
docs/contracts.md section 2).
The error is max |residual| relative to the energy that flowed in the run: the largest of
max |W_ext|, max |E_el(t) - E_el(0)|, max E_kin and max D_fric (the stored preload energy E_el(0)
would make any error look small, so it is not the scale).

The energy created is max over t of E_kin + E_el - (E_kin + E_el)(0) - W_ext, relative to the same scale.
Every other term of the model takes energy out: Coulomb friction opposes the slip, the unilateral contact
only pushes, HHT-alpha damps. The top's work is the only source, so the created energy of the continuous
problem is 0 (at t = 0) and a discrete run that creates energy has left it (docs/physics-notes.md,
section 8).
"""

from __future__ import annotations

import math

import numpy as np


def energy_balance_error(energy_kinetic: np.ndarray, energy_elastic: np.ndarray,
                         work_external: np.ndarray, dissipation_friction: np.ndarray,
                         residual: np.ndarray) -> tuple[float, float]:
    """(relative error, max |residual| in J/m); the relative error is nan when no energy flowed.

    Parameters
    ----------
    energy_kinetic, energy_elastic, work_external, dissipation_friction, residual
        Global series (J/m per unit depth), same length, from t = 0.
    """
    residual_max = float(np.max(np.abs(residual))) if np.size(residual) else math.nan
    scale = energy_scale(energy_kinetic, energy_elastic, work_external, dissipation_friction)
    if not scale > 0:
        return math.nan, residual_max
    return residual_max / scale, residual_max


def energy_scale(energy_kinetic: np.ndarray, energy_elastic: np.ndarray, work_external: np.ndarray,
                 dissipation_friction: np.ndarray) -> float:
    """The energy that flowed in the run (J/m): the largest of max |W_ext|, max |E_el(t) - E_el(0)|,
    max E_kin and max D_fric."""
    return max(float(np.max(np.abs(work_external))), float(np.max(np.abs(energy_elastic - energy_elastic[0]))),
               float(np.max(energy_kinetic)), float(np.max(dissipation_friction)))


def energy_created(energy_kinetic: np.ndarray, energy_elastic: np.ndarray, work_external: np.ndarray,
                   dissipation_friction: np.ndarray) -> float:
    """max over t of E_kin + E_el - (E_kin + E_el)(0) - W_ext, relative to the energy that flowed
    (>= 0: t = 0 gives 0); nan when no energy flowed. Global series (J/m) from t = 0."""
    scale = energy_scale(energy_kinetic, energy_elastic, work_external, dissipation_friction)
    if not scale > 0:
        return math.nan
    total = energy_kinetic + energy_elastic
    return float(np.max(total - total[0] - work_external)) / scale
