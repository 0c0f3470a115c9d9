"""analysis.metrics.inversion, opening, pulses, regime, energy on hand-built inputs."""

import math

import numpy as np
import pytest

from analysis.fronts.tracking import EdgeTrack
from analysis.metrics import energy, inversion, opening, pulses, regime


def test_drops_with_hysteresis():
    t = np.arange(12.0)
    ratio = np.array([1.0, 1.5, 1.45, 1.5, 0.2, -0.3, -0.25, 0.5, 1.0, 0.95, 0.3, 0.35])
    drops = inversion.frictional_drops(t, ratio, min_drop=0.15)
    # The 0.05 ripples (1.5 -> 1.45, -0.3 -> -0.25) are not drops; a drop starts at the last time
    # of its peak; the last drop never recovers.
    assert [(d.t_start, d.t_bottom, d.complete) for d in drops] == [(3.0, 5.0, True), (8.0, 10.0, False)]
    assert drops[0].T_over_N_bottom == -0.3 and drops[1].T_over_N_start == 1.0
    assert inversion.minimum_ratio(t, ratio) == (-0.3, 5.0)
    with pytest.raises(ValueError):
        inversion.frictional_drops(t, ratio, 0.0)


def test_no_drop_in_a_monotone_series():
    t = np.linspace(0, 10, 50)
    assert inversion.frictional_drops(t, 1.0 + 0.01 * t, 0.1) == []


def test_opening_summary_and_distance_behind_front():
    x = np.arange(10.0)
    t = np.array([0.0, 1.0, 2.0])
    u = np.full((3, 10), 1e-13)
    u[1, 4] = 3e-4
    u[2, 5] = 2e-2
    s = opening.summarize_opening(x, t, u, 2.5e-4)
    assert s.opened and s.t_first == 1.0 and s.x_first == 4.0
    assert s.max_opening == 2e-2 and s.t_max == 2.0 and s.open_fraction_max == 0.1
    closed = opening.summarize_opening(x, t, np.full((3, 10), 1e-13), 2.5e-5)
    assert not closed.opened and math.isnan(closed.t_first)
    # Front at 12 (period 10, i.e. at 2) moving +x, opening at 9: 3 m behind it.
    assert opening.distance_behind_front(9.0, np.array([12.0]), 1, 10.0) == pytest.approx(3.0)
    assert opening.distance_behind_front(9.0, np.array([12.0]), -1, 10.0) == pytest.approx(7.0)
    assert math.isnan(opening.distance_behind_front(9.0, np.array([]), 1, 10.0))


def test_pulse_train():
    t = np.arange(5.0)
    ones = np.ones(5)
    fronts = [EdgeTrack("right", t, 1.0 + t, ones), EdgeTrack("right", t, 31.0 + t, ones),
              EdgeTrack("right", t[:2], 61.0 + t[:2], ones[:2])]
    count, spacing = pulses.pulse_train(fronts, 90.0)
    assert count == 2  # three fronts at two times, two at three
    assert spacing == pytest.approx(30.0)  # gaps: 30, 30, 30 (x2) and 30, 60 (x3)
    assert pulses.pulse_train([], 50.0)[0] == 0
    assert pulses.expected_pulse_count(100.0, 46.0) == 2 and pulses.expected_pulse_count(50.0, 80.0) == 1
    assert pulses.expected_pulse_count(50.0, math.nan) is None


def test_regime_boundaries():
    assert regime.regime(0.5, 0.6, 1.0) == "subsonic"
    assert regime.regime(-0.7, 0.6, 1.0) == "intersonic"
    assert regime.regime(-1.1, 0.6, 1.0) == "supersonic"
    assert regime.regime(math.nan, 0.6, 1.0) is None
    assert regime.below_sqrt2_cs(0.84, 0.6) is True and regime.below_sqrt2_cs(-0.86, 0.6) is False


def test_category_names_are_declared():
    seen = set()
    for opened in (False, True):
        for slipped, has_front in ((False, False), (True, False), (True, True)):
            for c in (math.nan, 0.5, -0.5, 0.8, -0.8, 1.5, -1.5):
                for inverted in (False, True):
                    seen.add(regime.category(slipped=slipped, has_front=has_front, opened=opened,
                                             celerity=c, c_s=0.6, c_l=1.0, inversion=inverted))
    kw = dict(slipped=True, has_front=True, opened=True, celerity=0.8, c_s=0.6, c_l=1.0, inversion=True)
    seen.add(regime.category(**kw, sampling_too_coarse=True))
    seen.add(regime.category(**kw, non_physical=True))
    # A non-physical state wins over everything, coarse sampling over what the map shows.
    assert regime.category(**kw, non_physical=True, sampling_too_coarse=True) == "non_physical"
    assert regime.category(**kw, sampling_too_coarse=True) == "sampling_too_coarse"
    assert seen == set(regime.CATEGORIES)


def test_intersonic_below_sqrt2_cs():
    assert regime.intersonic_below_sqrt2_cs(0.7, 0.6) is True
    assert regime.intersonic_below_sqrt2_cs(-0.7, 0.6) is True
    assert regime.intersonic_below_sqrt2_cs(0.5, 0.6) is False   # subsonic
    assert regime.intersonic_below_sqrt2_cs(0.9, 0.6) is False   # above sqrt(2) c_s = 0.849
    assert regime.intersonic_below_sqrt2_cs(math.nan, 0.6) is None


def test_energy_balance_error():
    t = np.linspace(0.0, 100.0, 101)
    work = 2.0 * t
    residual = np.zeros_like(t)
    residual[50] = -0.4
    error, residual_max = energy.energy_balance_error(0.1 * t, 50.0 + 1.5 * t, work, 0.4 * t, residual)
    assert residual_max == 0.4 and error == pytest.approx(0.4 / 200.0)
    zero = np.zeros(5)
    assert math.isnan(energy.energy_balance_error(zero, zero + 3.0, zero, zero, zero)[0])


def test_energy_created_is_what_the_layer_holds_beyond_its_start_and_the_work_done_on_it():
    t = np.linspace(0.0, 100.0, 101)
    work = 2.0 * t
    # Dissipative: E_kin + E_el grows by 1.6 t of the 2 t put in, so nothing is created.
    assert energy.energy_created(0.1 * t, 50.0 + 1.5 * t, work, 0.4 * t) == 0.0
    # A step at t = 60 holds 30 J/m more than the start and the work: 30 of the 200 J/m that flowed.
    kinetic = 0.1 * t + np.where(t >= 60.0, 30.0 + 0.4 * t, 0.0)
    assert energy.energy_created(kinetic, 50.0 + 1.5 * t, work, 0.4 * t) == pytest.approx(30.0 / 200.0, rel=1e-12)
    zero = np.zeros(5)
    assert math.isnan(energy.energy_created(zero, zero + 3.0, zero, zero))


def test_drops_are_found_on_the_smoothed_series():
    t = np.arange(0.0, 1000.0, 0.5)
    # As in a run: T/N rises from 0.95 f to f, holds, drops; the solver's step-to-step chatter on top.
    ratio = (np.interp(t, [0, 100, 300, 600, 1000], [1.425, 1.5, 1.5, -0.3, 0.4])
             + 0.1 * (-1.0) ** np.arange(t.size))
    assert len(inversion.frictional_drops(t, ratio, 0.15)) > 10  # the chatter alone
    drops = inversion.frictional_drops(t, ratio, 0.15, smooth_time=20.0)
    assert len(drops) == 1
    assert drops[0].t_start == pytest.approx(300.0, abs=10.0) and drops[0].t_bottom == pytest.approx(600.0, abs=10.0)
    assert drops[0].T_over_N_start == pytest.approx(1.5, abs=1e-3)


def test_undefined_T_over_N_is_bridged_from_its_neighbours():
    from analysis.metrics import inversion

    t = np.arange(5.0)
    ratio = np.array([1.0, 0.5, np.nan, -0.5, 0.0])
    bridged = inversion.bridge_undefined(t, ratio)
    assert bridged[2] == pytest.approx(0.0) and np.isfinite(bridged).all()
    assert inversion.minimum_ratio(t, bridged) == (-0.5, 3.0)


def test_category_labels_name_every_key_they_rename_and_say_uniform_sliding_for_no_slip():
    from analysis.metrics import regime as regime_module

    assert set(regime_module.CATEGORY_LABELS) <= set(regime_module.CATEGORIES)
    assert regime_module.category_label("no_slip") == "uniform sliding"
    assert regime_module.category_label("supersonic_backward_opening") == "supersonic backward opening"
