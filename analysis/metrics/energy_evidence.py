"""What the energy-balance residual of the study's runs is (docs/energy-balance.md), measured on three
runs of the reference case made with `output.energy_decomposition = hht`: hht_alpha = 0 (trapezoidal
rule, where the balance must close) and the study's hht_alpha with each contact weighting.

For each run: the energy that flowed (J/m) and the largest |residual| relative to it
(`energy.energy_balance_error`, the measure the study reports for every run); for alpha > 0 also the
residual and the HHT dissipation at the end of the run relative to the energy that flowed, their
ratio, the largest |residual + dissipation| over the run and each term's dissipation. The paper only
formats these numbers (paper/make_energy_evidence.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from analysis.core.errors import InputError
from analysis.core.io import RunData, load_hht_dissipation, load_run
from analysis.metrics.energy import energy_balance_error

#: The runs: (role, hht_alpha must be zero, contact weighting or None: any).
ROLES = (("alpha_zero", True, None), ("alpha", False, "alpha"), ("alpha_end", False, "end"))
TERMS = ("gamma", "beta", "shift")
#: Config keys on which the three runs must agree (the same case).
CASE_KEYS = (("material", "nu"), ("friction", "f"), ("mesh", "elements_per_H"), ("loading", "V0_over_cs"),
             ("time", "t_end"), ("time", "dt_times_cs"))


@dataclass(frozen=True)
class EvidenceRun:
    run: RunData
    hht: dict[str, np.ndarray]


def read_role(path: str, alpha_zero: bool, weighting: str | None) -> EvidenceRun:
    """One run checked for its role: hht_alpha zero or not, the contact weighting, complete, with
    the HHT decomposition; InputError naming the file otherwise."""
    run = load_run(path)
    alpha = run.config["time"]["hht_alpha"]
    if (alpha == 0) != alpha_zero:
        raise InputError(f"{path}: time.hht_alpha = {alpha:g}, expected " + ("0" if alpha_zero else "> 0"))
    if weighting and run.config["time"]["contact_weighting"] != weighting:
        raise InputError(f"{path}: time.contact_weighting = {run.config['time']['contact_weighting']}, "
                         f"expected {weighting}")
    if not run.complete:
        raise InputError(f"{path}: the run is incomplete ({run.end_reason})")
    return EvidenceRun(run, load_hht_dissipation(path))


def check_same_case(runs: dict[str, EvidenceRun]) -> None:
    """InputError naming the run whose CASE_KEYS differ from the `alpha` run's."""
    case = {role: tuple(r.run.config[a][b] for a, b in CASE_KEYS) for role, r in runs.items()}
    for role, values in case.items():
        if values != case["alpha"]:
            raise InputError(f"{runs[role].run.path}: another case than {runs['alpha'].run.path} "
                             f"({', '.join(f'{a}.{b}' for a, b in CASE_KEYS)} must agree)")


def run_evidence(r: EvidenceRun, alpha_zero: bool) -> dict[str, float]:
    """flowed (J/m), residual (-); for alpha > 0 also residual_end, dissipation_end, closure and
    term_<t> (relative to flowed) and ratio = -residual_end / dissipation_end."""
    g = r.run.global_series
    relative, _ = energy_balance_error(g.energy_kinetic, g.energy_elastic, g.work_external,
                                       g.dissipation_friction, g.energy_balance_residual)
    scale = float(max(abs(g.work_external).max(), abs(g.energy_elastic - g.energy_elastic[0]).max(),
                      g.energy_kinetic.max(), g.dissipation_friction.max()))
    out = {"flowed": scale, "residual": relative}
    if alpha_zero:
        return out
    residual, dissipation = g.energy_balance_residual[-1], r.hht["dissipation_hht"][-1]
    out.update(residual_end=-residual / scale, dissipation_end=dissipation / scale,
               ratio=-residual / dissipation,
               closure=float(abs(g.energy_balance_residual + r.hht["dissipation_hht"]).max()) / scale)
    out.update({f"term_{t}": r.hht[f"dissipation_hht_{t}"][-1] / scale for t in TERMS})
    return out


def energy_evidence(paths: dict[str, str]) -> tuple[dict[str, dict[str, float]], dict[str, object]]:
    """({role: run_evidence}, the case: nu, f, elements_per_H, t_end, hht_alpha) of the runs by role."""
    runs = {role: read_role(paths[role], zero, weighting) for role, zero, weighting in ROLES}
    check_same_case(runs)
    c = runs["alpha"].run.config
    case = {"nu": c["material"]["nu"], "f": c["friction"]["f"], "elements_per_H": c["mesh"]["elements_per_H"],
            "t_end": c["time"]["t_end"], "hht_alpha": c["time"]["hht_alpha"]}
    return {role: run_evidence(runs[role], zero) for role, zero, _ in ROLES}, case
