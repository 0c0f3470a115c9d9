"""Closed-form quantities of the model: wave speeds, preload, time step, onset time (on the rigid flat
and on a deformable substrate), pulse spacing.

Plane strain, linear isotropic elasticity (Young's modulus E, Poisson's ratio nu, density rho);
the paper is Yastrebov 2016 (Tribol. Lett. 62:1). The flutter boundary lives in `analysis.theory.flutter`.

This is the one Python home of the formulas needed *before* a run exists (planning a study: run
length, resources; the published cells of Table 1). Once a run exists its constants are read from
the run (`/setup`: c_s, c_l, p0, dt, t_onset_estimate, opening_threshold), never recomputed;
tests/analysis/test_theory.py checks that these formulas give what the solver writes.
"""

from __future__ import annotations

import math

#: E (Pa) and rho (kg/m^3) of the paper's Table 1.
TABLE1_E = 1000.0
TABLE1_RHO = 1000.0


def shear_modulus(E: float, nu: float) -> float:
    """Shear modulus G = E / (2 (1 + nu)) (Pa)."""
    return E / (2.0 * (1.0 + nu))


def shear_wave_speed(E: float, nu: float, rho: float) -> float:
    """Shear wave speed c_s = sqrt(E / (2 (1 + nu) rho)) (m/s)."""
    return math.sqrt(E / (2.0 * (1.0 + nu) * rho))


def longitudinal_wave_speed(E: float, nu: float, rho: float) -> float:
    """Plane-strain longitudinal wave speed c_l = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)) (m/s).

    Requires 0 <= nu < 1/2.
    """
    if not 0.0 <= nu < 0.5:
        raise ValueError(f"nu = {nu} outside [0, 0.5)")
    return math.sqrt(E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu) * rho))


def wave_speeds(nu: float, E: float = TABLE1_E, rho: float = TABLE1_RHO) -> tuple[float, float, float]:
    """(c_s, sqrt(2) c_s, c_l) in m/s: the last three rows of the paper's Table 1 (E = 1000 Pa,
    rho = 1000 kg/m^3 by default). sqrt(2) c_s is the speed below which an intersonic front favours
    opening (Liu & Freund / the paper's section "Pulse celerity")."""
    c_s = shear_wave_speed(E, nu, rho)
    return c_s, math.sqrt(2.0) * c_s, longitudinal_wave_speed(E, nu, rho)


def preload_pressure(Uy: float, E: float, nu: float, H: float) -> float:
    """Contact pressure of the stage-1 preload, p0 = -Uy E (1 - nu) / (H (1 + nu)(1 - 2 nu)) (Pa).

    Uniaxial strain of a layer of height H (m) whose top is displaced by Uy (m, < 0 in compression);
    compression positive.
    """
    return -Uy * E * (1.0 - nu) / (H * (1.0 + nu) * (1.0 - 2.0 * nu))


def time_step(c_s: float, dt_times_cs: float, dt: float | None = None) -> float:
    """Time step (s): `time.dt` when given, else dt_times_cs / c_s (dt_times_cs in m: the distance a
    shear wave travels in one step)."""
    return dt if dt is not None else dt_times_cs / c_s


def n_steps(t_end: float, dt: float) -> int:
    """Stage-3 time steps to reach t_end (s) with the step dt (s): ceil(t_end / dt - 1e-9), the
    solver's count (solver/config/run_config.cpp), so that an exact multiple up to round-off is not
    one step more. The one step count of the Python side (scheduler estimates, tests)."""
    return math.ceil(t_end / dt - 1e-9)


def onset_time_estimate(*, f: float, preshear_ratio: float, p0: float, H: float, E: float,
                        nu: float, V0: float) -> float:
    """Quasi-static time (s) for T/N to grow from preshear_ratio f to f with the top moving at V0.

    The shear stress grows at G V0 / H, so the top must move delta_u = (1 - preshear_ratio) f p0 H / G
    (m), G = E / (2 (1 + nu)); t = delta_u / V0. The real first slip lands on a stair of the shear-wave
    staircase near this time (round trip 2 H / c_s).
    """
    delta_u = (1.0 - preshear_ratio) * f * p0 * H / shear_modulus(E, nu)
    return delta_u / V0


def p_wave_modulus(E: float, nu: float) -> float:
    """Plane-strain (uniaxial strain) modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) (Pa)."""
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))


def pair_onset_time_estimate(*, f: float, preshear_ratio: float, Uy: float, H: float, E: float, nu: float,
                             V0: float, H_s: float, E_s: float, nu_s: float) -> tuple[float, float]:
    """(t_onset (s), p0 (Pa)) of a layer (H, E, nu) on a deformable substrate (H_s, E_s, nu_s) whose
    bottom is held (docs/substrate.md): the quasi-static onset of `onset_time_estimate` for the pair.

    Both bodies are loaded in series through the interface, each in uniform strain. Stage 1: the top's
    displacement Uy (< 0) is shared by the two uniaxial strains under one pressure p0,

        -Uy = p0 (H / M + H_s / M_s)   ->   p0 = -Uy / (H / M + H_s / M_s),   M = p_wave_modulus;

    stage 3: the interface shear stress tau is shared by the two shear strains, so the top moves
    tau (H / G + H_s / G_s) to carry it, and T/N grows from preshear_ratio f to f after

        t_onset = (1 - preshear_ratio) f p0 (H / G + H_s / G_s) / V0.

    Against the rigid flat (H_s / M_s = H_s / G_s = 0) the pressure drops by 1 + (H_s M) / (H M_s) and
    the displacement per unit stress grows by 1 + (H_s G) / (H G_s); with the layer's nu and thickness
    (the study's contrast sweep) the two factors are equal, 1 + E / E_s, and t_onset is the rigid
    flat's (p0 is lower by that factor).
    """
    normal = H / p_wave_modulus(E, nu) + H_s / p_wave_modulus(E_s, nu_s)
    shear = H / shear_modulus(E, nu) + H_s / shear_modulus(E_s, nu_s)
    p0 = -Uy / normal
    return (1.0 - preshear_ratio) * f * p0 * shear / V0, p0


def pulse_spacing(c_p: float, c_s: float, H: float) -> float:
    """Spacing of a pulse train, l = 2 H sqrt(c_p^2 / c_s^2 - 1) (m).

    The shear Mach cone of a pulse at |c_p| > c_s, reflected at the top, returns to the interface a
    distance l behind it (paper, section "Pulse period"). nan for |c_p| <= c_s or nan c_p.
    """
    if not math.isfinite(c_p) or abs(c_p) <= c_s:
        return math.nan
    return 2.0 * H * math.sqrt(c_p * c_p / (c_s * c_s) - 1.0)
