"""analysis.theory against the paper's Table 1 and closed forms."""

import math

import pytest

from analysis import theory

# Last three rows of the paper's Table 1 (E = 1000 Pa, rho = 1000 kg/m^3).
TABLE1_SPEEDS = {
    0.0: (0.707, 1.000, 1.000), 0.1: (0.674, 0.953, 1.011), 0.2: (0.645, 0.913, 1.054),
    0.3: (0.620, 0.877, 1.160), 0.4: (0.598, 0.845, 1.464), 0.45: (0.587, 0.830, 1.948),
    0.49: (0.579, 0.819, 4.137),
}


@pytest.mark.parametrize("nu", sorted(TABLE1_SPEEDS))
def test_wave_speeds_reproduce_table1_to_three_decimals(nu):
    c_s, sqrt2_c_s, c_l = theory.wave_speeds(nu)
    assert (round(c_s, 3), round(sqrt2_c_s, 3), round(c_l, 3)) == TABLE1_SPEEDS[nu]


def test_wave_speed_closed_forms():
    # nu = 0: c_s = sqrt(E/(2 rho)), c_l = sqrt(E/rho); nu = 1/3: c_l = 2 c_s.
    assert theory.shear_wave_speed(2.0, 0.0, 1.0) == pytest.approx(1.0, rel=1e-15)
    assert theory.longitudinal_wave_speed(2.0, 0.0, 1.0) == pytest.approx(math.sqrt(2.0), rel=1e-15)
    assert (theory.longitudinal_wave_speed(7.0, 1 / 3, 3.0)
            == pytest.approx(2.0 * theory.shear_wave_speed(7.0, 1 / 3, 3.0), rel=1e-14))
    with pytest.raises(ValueError):
        theory.longitudinal_wave_speed(1.0, 0.5, 1.0)


def test_preload_pressure():
    # nu = 0: uniaxial strain is uniaxial stress, p0 = -Uy E / H.
    assert theory.preload_pressure(-0.025, 1000.0, 0.0, 25.0) == pytest.approx(1.0, rel=1e-15)
    # Paper's default at nu = 0.2: 1000 * 1e-3 * 0.8 / (1.2 * 0.6) = 1.1111 Pa; equals rho c_l^2 eps.
    p0 = theory.preload_pressure(-0.025, 1000.0, 0.2, 25.0)
    assert p0 == pytest.approx(10.0 / 9.0, rel=1e-14)
    assert p0 == pytest.approx(1000.0 * theory.longitudinal_wave_speed(1000.0, 0.2, 1000.0) ** 2 * 1e-3,
                               rel=1e-14)


def test_onset_time_estimate():
    # nu = 0.2, f = 1.5: delta_u = 0.05 * 1.5 * (10/9) * 25 / (1000/2.4) = 0.005 m; V0 = 1e-5 c_s.
    c_s = theory.shear_wave_speed(1000.0, 0.2, 1000.0)
    t = theory.onset_time_estimate(f=1.5, preshear_ratio=0.95, p0=10.0 / 9.0, H=25.0, E=1000.0,
                                   nu=0.2, V0=1e-5 * c_s)
    assert t == pytest.approx(0.005 / (1e-5 * c_s), rel=1e-12)
    assert 770.0 < t < 780.0  # the physics notes: first slip near 740 s, on a stair before this


def test_pulse_spacing():
    c_s = 0.645
    assert theory.pulse_spacing(math.sqrt(2) * c_s, c_s, 25.0) == pytest.approx(50.0, rel=1e-12)
    assert theory.pulse_spacing(-math.sqrt(5) * c_s, c_s, 25.0) == pytest.approx(100.0, rel=1e-12)
    assert math.isnan(theory.pulse_spacing(0.9 * c_s, c_s, 25.0))
    assert math.isnan(theory.pulse_spacing(math.nan, c_s, 25.0))
