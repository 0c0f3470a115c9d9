"""Simulated time of one run, from the physics of the slip onset.

Stage 3 (the dynamic stage, clock t = 0) starts with T/N = r f, r = preshear_ratio. The top then
moves at V0, so in the quasi-static picture the interface shear stress grows at G V0 / H and reaches
the Coulomb limit f p0 at

    t_onset = (1 - r) f p0 H / (G V0),                                              (1)

    p0 = -Uy_over_H E (1 - nu) / ((1 + nu)(1 - 2 nu)),   G = E / (2 (1 + nu)),   V0 = V0_over_cs c_s.

Everything after the onset happens on the time scale of elastic waves crossing the layer, so the
durations that follow it are counted in shear transit times t_s = H / c_s (38.7 s at nu = 0.2,
rho = 1000 kg/m^3). With dt = dt_times_cs / c_s a transit is always H / dt_times_cs = 50 steps
at the default dt_times_cs = 0.5 m: the step count of a run depends neither on rho nor on E.

A run ends at

    t_end = t_onset + duration_transits t_s                                          (2)

(a cap), or earlier, stop_after_opening_transits t_s after the interface first opens (the solver's
`time.stop_after_opening`). See study/README.md for the chosen values and why.

On a deformable substrate (E_s, nu_s, H_s; docs/substrate.md) the two bodies are loaded in series:
the preload pressure is shared, p0 = -Uy / (H / M + H_s / M_s), and so is the shear stress, so the top
moves tau (H / G + H_s / G_s) to carry it:

    t_onset = (1 - r) f p0 (H / G + H_s / G_s) / V0,   M = E (1 - nu) / ((1 + nu)(1 - 2 nu))      (1')

(analysis.theory.elastic.pair_onset_time_estimate). With the substrate's nu and thickness equal to the
layer's, both compliances grow by 1 + E / E_s and (1') is (1) again: only p0 is lower.
"""

from __future__ import annotations

from dataclasses import dataclass

from analysis.theory import elastic


@dataclass(frozen=True)
class RunLength:
    """Times (s, stage-3 clock) that bound one run."""

    t_onset_estimate: float  #: quasi-static slip-onset time, eq. (1)
    transit_time: float  #: H / c_s
    t_end: float  #: end of the run, a cap when stop_after_opening is set
    stop_after_opening: float | None  #: end this long after the first opening, or None


# The formulas live in one place, analysis/theory/elastic.py (the measurement side uses the same ones).
shear_modulus = elastic.shear_modulus
shear_wave_speed = elastic.shear_wave_speed


def onset_time_estimate(*, E: float, nu: float, rho: float, H: float, f: float,
                        Uy_over_H: float, preshear_ratio: float, V0_over_cs: float) -> float:
    """Quasi-static time (s) at which T/N reaches f, eq. (1) of the module docstring."""
    return elastic.onset_time_estimate(f=f, preshear_ratio=preshear_ratio,
                                      p0=elastic.preload_pressure(Uy_over_H * H, E, nu, H), H=H, E=E, nu=nu,
                                      V0=V0_over_cs * shear_wave_speed(E, nu, rho))


def run_length(*, E: float, nu: float, rho: float, H: float, f: float, Uy_over_H: float,
               preshear_ratio: float, V0_over_cs: float, duration_transits: float,
               stop_after_opening_transits: float | None, t_end: float | None = None,
               substrate: dict | None = None) -> RunLength:
    """Run length of one point.

    Parameters
    ----------
    E, nu, rho, H, f, Uy_over_H, preshear_ratio, V0_over_cs
        The run's material, geometry, friction and loading (SI units), as in docs/contracts.md.
    duration_transits
        Cap after the onset estimate, in shear transit times H / c_s; must be > 0.
    stop_after_opening_transits
        End the run this many transit times after the first opening; None runs to the cap.
    t_end
        Explicit end time (s), overriding eq. (2) (e.g. the long stick-slip run).
    substrate
        The deformable substrate's `E`, `nu`, `H` (the solver's `substrate` group; other keys are
        ignored): the onset of eq. (1'); None: the rigid flat, eq. (1).

    Returns
    -------
    RunLength
    """
    if duration_transits <= 0:
        raise ValueError(f"duration_transits must be > 0, got {duration_transits}")
    if stop_after_opening_transits is not None and stop_after_opening_transits <= 0:
        raise ValueError(f"stop_after_opening_transits must be > 0 or None, got {stop_after_opening_transits}")
    if t_end is not None and t_end <= 0:
        raise ValueError(f"t_end must be > 0 or None, got {t_end}")
    transit = H / shear_wave_speed(E, nu, rho)
    if substrate is None:
        t_onset = onset_time_estimate(E=E, nu=nu, rho=rho, H=H, f=f, Uy_over_H=Uy_over_H,
                                      preshear_ratio=preshear_ratio, V0_over_cs=V0_over_cs)
    else:
        t_onset, _ = elastic.pair_onset_time_estimate(
            f=f, preshear_ratio=preshear_ratio, Uy=Uy_over_H * H, H=H, E=E, nu=nu,
            V0=V0_over_cs * shear_wave_speed(E, nu, rho), H_s=substrate["H"], E_s=substrate["E"],
            nu_s=substrate["nu"])
    end = t_end if t_end is not None else t_onset + duration_transits * transit
    stop = None if stop_after_opening_transits is None else stop_after_opening_transits * transit
    return RunLength(t_onset_estimate=t_onset, transit_time=transit, t_end=end, stop_after_opening=stop)
