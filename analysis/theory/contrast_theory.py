"""The theory of steady sliding placed over the points of a contrast sweep (a layer on a substrate of
E_s = contrast E, the layer's nu and density; study/README.md), one row per (nu, contrast, f).

Per (nu, contrast): the onset f of each family of growing modes (`instability_threshold`, forward: the
slip direction of the more compliant body, backward: Adams' wave made growing by the substrate; 0 with a
generalized Rayleigh wave, inf when none grows up to f = 10) and the generalized Rayleigh speed. Per f:
the most unstable mode (`bimaterial_regime`): its family, phase speed and growth rate per unit k.
The rigid flat (contrast None) takes the flutter wedge of `analysis.theory.flutter`: the forward
onset is its lower bound f = 1, `f_upper` its upper bound, no backward family (Adams' wave is neutral);
the most unstable mode is not computed there (empty cells).

Speeds in units of the layer's c_s (+ = +x, the layer's slip direction). A threshold costs up to ~12 s
(a near-rigid substrate, E_s/E = 1000): thresholds are computed once per (nu, contrast).
"""

from __future__ import annotations

import math

from analysis.theory import flutter
from analysis.theory.bimaterial_stability import bimaterial_regime, instability_threshold
from analysis.theory.interface_wave import ElasticSolid

COLUMNS = ("nu", "E_substrate_over_E", "f", "c_gR_over_cs1", "f_threshold", "f_threshold_forward",
           "f_threshold_backward", "f_upper", "unstable", "family", "phase_speed_over_cs1",
           "growth_rate_per_k_over_cs1", "forward_phase_speed_over_cs1", "backward_phase_speed_over_cs1")


def _thresholds(nu: float, contrast: float | None, E: float, rho: float) -> dict:
    if contrast is None:
        lower, upper = flutter.flutter_boundary(nu)
        forward = lower if math.isfinite(lower) else math.inf
        return {"c_gR_over_cs1": None, "f_threshold": forward, "f_threshold_forward": forward,
                "f_threshold_backward": math.inf, "f_upper": upper if math.isfinite(lower) else None}
    layer, substrate = ElasticSolid(E, nu, rho), ElasticSolid(E * contrast, nu, rho)
    forward = instability_threshold(layer, substrate, family="forward")
    backward = instability_threshold(layer, substrate, family="backward")
    regime = bimaterial_regime(E, nu, rho, E * contrast, nu, rho, 1.0)
    return {"c_gR_over_cs1": regime["c_gR_over_cs1"], "f_threshold": min(forward, backward),
            "f_threshold_forward": forward, "f_threshold_backward": backward, "f_upper": None}


def _mode(nu: float, contrast: float | None, f: float, E: float, rho: float) -> dict:
    if contrast is None:
        return {"unstable": flutter.inside_wedge(nu, f)}
    regime = bimaterial_regime(E, nu, rho, E * contrast, nu, rho, f)
    c_s = ElasticSolid(E, nu, rho).c_s

    def over_cs(speed):
        return None if speed is None else speed / c_s

    return {"unstable": regime["unstable"], "family": regime["family"],
            "phase_speed_over_cs1": regime["phase_speed_over_cs1"],
            "growth_rate_per_k_over_cs1": regime["growth_rate_per_k_over_cs1"],
            "forward_phase_speed_over_cs1": over_cs(regime["forward_phase_speed"]),
            "backward_phase_speed_over_cs1": over_cs(regime["backward_phase_speed"])}


def contrast_theory_rows(points: list[tuple[float, float | None, float]], E: float = 1000.0,
                         rho: float = 1000.0) -> list[dict]:
    """One row (COLUMNS) per (nu, contrast, f) of `points`, in their order; contrast None: the rigid flat.

    Raises ValueError for nu outside [0, 0.5), a contrast <= 0 or f <= 0.
    """
    thresholds: dict[tuple[float, float | None], dict] = {}
    rows = []
    for nu, contrast, f in points:
        if not 0.0 <= nu < 0.5:
            raise ValueError(f"nu = {nu} outside the allowed range [0, 0.5)")
        if contrast is not None and not 0.0 < contrast < math.inf:
            raise ValueError(f"contrast = {contrast} outside the allowed range (0, inf)")
        if not 0.0 < f < math.inf:
            raise ValueError(f"f = {f} outside the allowed range (0, inf)")
        key = (nu, contrast)
        if key not in thresholds:
            thresholds[key] = _thresholds(nu, contrast, E, rho)
        rows.append({"nu": nu, "E_substrate_over_E": contrast, "f": f, **thresholds[key],
                     **_mode(nu, contrast, f, E, rho)})
    return rows
