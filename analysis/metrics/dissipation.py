"""Frictional dissipation per unit of interface slip: how much friction the sliding mode costs.

The paper calls the opening-wave mode one of "marginal frictional dissipation". Its measure here
is the *dissipative friction coefficient* over a time window [t0, t1]:

    mu_diss = (D(t1) - D(t0)) / (N0 (ubar(t1) - ubar(t0))),

D the solver's cumulative frictional dissipation (J/m, /global/dissipation_friction), N0 = p0 lambda
the total preload normal force (N/m) and ubar the mean over the interface nodes of the slip u_x
(m, /interface/slip). The dissipation rate is sum_i tau_i v_i h; for uniform Coulomb sliding
tau = f p0 on every node, so mu_diss = f exactly. Where the interface advances by opening (u_x
moves while the node carries no traction) or slips under a traction below f p0, mu_diss < f; an
interface that moves without any friction work has mu_diss = 0. The ratio (D(t1) - D(t0)) /
(W(t1) - W(t0)), W the external work (J/m), is the share of the input work that friction burns;
during a frictional drop friction is fed by the released elastic energy and W barely moves (or
falls, when T/N inverts), so this ratio can exceed 1 or be undefined (nan for dW <= 0). The
energy share dD / (dW - dE_el), E_el the elastic energy, relates the dissipation to all the energy
made available to the motion (work plus released elastic energy; the rest goes to waves, normal
impacts and HHT damping); nan when that is <= 0.

N0 rather than the instantaneous N: the mean normal force stays at p0 lambda up to inertial
fluctuations, and N0 keeps the uniform-sliding value exact. D and W are per step, the slip every
interface_stride steps: D and W are interpolated at the interface output times (which are step
times, so the interpolation is exact).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class WindowDissipation:
    """Over [t0, t1] (s, interface output times): mu_diss (-), work_fraction = dD/dW (-),
    energy_share = dD / (dW - dE_el) (-), and the increments dD (J/m), dW (J/m), d_slip = mean
    slip increment (m); nan when undefined."""

    mu_diss: float
    work_fraction: float
    energy_share: float
    dissipation: float
    work: float
    mean_slip: float
    t0: float = math.nan
    t1: float = math.nan


NAN_WINDOW = WindowDissipation(math.nan, math.nan, math.nan, math.nan, math.nan, math.nan)


def window_dissipation(t_global: np.ndarray, dissipation: np.ndarray, work: np.ndarray,
                       elastic: np.ndarray, t_interface: np.ndarray, slip: np.ndarray, normal_force: float,
                       t0: float, t1: float) -> WindowDissipation:
    """Dissipative friction coefficient and dissipated share of the work over a window.

    Parameters
    ----------
    t_global, dissipation, work, elastic
        Global series: times (s), cumulative frictional dissipation (J/m), external work (J/m),
        elastic energy (J/m).
    t_interface, slip
        Interface output times (s) and slip u_x (m), shape (n_out, n_c).
    normal_force
        N0 = p0 lambda (N/m), > 0.
    t0, t1
        Window (s); it snaps to the interface output times nearest to t0 and t1.

    Returns
    -------
    WindowDissipation
        NAN_WINDOW when a bound is nan or the snapped window is empty; mu_diss nan when the mean
        slip does not grow, work_fraction when the work does not, energy_share when dW - dE_el
        <= 0.
    """
    if not normal_force > 0:
        raise ValueError(f"normal_force must be > 0 (got {normal_force})")
    if not (math.isfinite(t0) and math.isfinite(t1)):
        return NAN_WINDOW
    t_interface = np.asarray(t_interface, dtype=float)
    k0 = int(np.argmin(np.abs(t_interface - t0)))
    k1 = int(np.argmin(np.abs(t_interface - t1)))
    if k1 <= k0:
        return NAN_WINDOW
    a, b = t_interface[k0], t_interface[k1]
    mean_slip = np.asarray(slip, dtype=float).mean(axis=1)
    d_slip = float(mean_slip[k1] - mean_slip[k0])
    d_dissipation = float(np.interp(b, t_global, dissipation) - np.interp(a, t_global, dissipation))
    d_work = float(np.interp(b, t_global, work) - np.interp(a, t_global, work))
    supplied = d_work - float(np.interp(b, t_global, elastic) - np.interp(a, t_global, elastic))
    fraction = d_dissipation / d_work if d_work > 0 else math.nan
    share = d_dissipation / supplied if supplied > 0 else math.nan
    mu_diss = d_dissipation / (normal_force * d_slip) if d_slip > 0 else math.nan
    return WindowDissipation(mu_diss, fraction, share, d_dissipation, d_work, d_slip, a, b)
