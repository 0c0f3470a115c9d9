"""analysis.metrics.dissipation: the dissipative friction coefficient on hand-built series."""

import math

import numpy as np
import pytest

from analysis.metrics import dissipation

F, P0, PERIOD, N_C = 1.5, 1.11, 50.0, 64
N0 = P0 * PERIOD
DT, STRIDE = 0.5, 4


def series(rate, dissipating=True):
    """Uniform sliding at `rate` (m/s) from t = 10 s: per-step globals, slip every STRIDE steps."""
    t_global = np.arange(0.0, 100.0 + DT / 2, DT)
    slip_mean = rate * np.maximum(t_global - 10.0, 0.0)
    dissipated = F * N0 * slip_mean if dissipating else np.zeros_like(t_global)
    work = 1.2 * dissipated + 1e-3 * t_global
    elastic = 100.0 - 0.1 * dissipated
    t_interface = t_global[::STRIDE]
    ripple = 1e-4 * np.sin(2 * np.pi * np.arange(N_C) / N_C)  # zero-mean, non-uniform slip
    slip = slip_mean[::STRIDE, None] + ripple[None, :]
    return dict(t_global=t_global, dissipation=dissipated, work=work, elastic=elastic,
                t_interface=t_interface, slip=slip, normal_force=N0)


def test_uniform_coulomb_sliding_gives_f():
    result = dissipation.window_dissipation(t0=20.0, t1=90.0, **series(1e-3))
    assert result.mu_diss == pytest.approx(F, rel=1e-12)
    assert result.t0 == 20.0 and result.t1 == 90.0
    assert result.mean_slip == pytest.approx(0.07)
    assert result.work_fraction == pytest.approx(result.dissipation / result.work)
    assert result.energy_share == pytest.approx(result.dissipation / (result.work + 0.1 * result.dissipation))


def test_window_snaps_to_interface_times():
    # 21.3 s is not an output time (every 2 s): the window snaps to 22 s on both series.
    result = dissipation.window_dissipation(t0=21.3, t1=89.1, **series(1e-3))
    assert result.t0 == 22.0 and result.t1 == 90.0 and result.mu_diss == pytest.approx(F, rel=1e-12)


def test_sliding_without_friction_work_gives_zero():
    result = dissipation.window_dissipation(t0=20.0, t1=90.0, **series(1e-3, dissipating=False))
    assert result.mu_diss == 0.0


def test_undefined_windows():
    data = series(1e-3)
    assert math.isnan(dissipation.window_dissipation(t0=math.nan, t1=90.0, **data).mu_diss)
    assert math.isnan(dissipation.window_dissipation(t0=90.0, t1=20.0, **data).mu_diss)
    # Before the onset nothing slips: no coefficient.
    assert math.isnan(dissipation.window_dissipation(t0=0.0, t1=8.0, **data).mu_diss)
    with pytest.raises(ValueError):
        dissipation.window_dissipation(t0=0.0, t1=8.0, **dict(data, normal_force=0.0))
