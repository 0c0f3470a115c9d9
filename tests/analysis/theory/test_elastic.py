"""analysis.theory.elastic against the paper's Table 1 and closed forms."""

import json
import math
import subprocess
from pathlib import Path

import pytest

from analysis.theory import elastic

# Last three rows of the paper's Table 1 (E = 1000 Pa, rho = 1000 kg/m^3).
TABLE1_SPEEDS = {
    0.0: (0.707, 1.000, 1.000), 0.1: (0.674, 0.953, 1.011), 0.2: (0.645, 0.913, 1.054),
    0.3: (0.620, 0.877, 1.160), 0.4: (0.598, 0.845, 1.464), 0.45: (0.587, 0.830, 1.948),
    0.49: (0.579, 0.819, 4.137),
}


@pytest.mark.parametrize("nu", sorted(TABLE1_SPEEDS))
def test_wave_speeds_reproduce_table1_to_three_decimals(nu):
    c_s, sqrt2_c_s, c_l = elastic.wave_speeds(nu)
    assert (round(c_s, 3), round(sqrt2_c_s, 3), round(c_l, 3)) == TABLE1_SPEEDS[nu]


def test_wave_speed_closed_forms():
    # nu = 0: c_s = sqrt(E/(2 rho)), c_l = sqrt(E/rho); nu = 1/3: c_l = 2 c_s.
    assert elastic.shear_wave_speed(2.0, 0.0, 1.0) == pytest.approx(1.0, rel=1e-15)
    assert elastic.longitudinal_wave_speed(2.0, 0.0, 1.0) == pytest.approx(math.sqrt(2.0), rel=1e-15)
    assert (elastic.longitudinal_wave_speed(7.0, 1 / 3, 3.0)
            == pytest.approx(2.0 * elastic.shear_wave_speed(7.0, 1 / 3, 3.0), rel=1e-14))
    with pytest.raises(ValueError):
        elastic.longitudinal_wave_speed(1.0, 0.5, 1.0)


def test_preload_pressure():
    # nu = 0: uniaxial strain is uniaxial stress, p0 = -Uy E / H.
    assert elastic.preload_pressure(-0.025, 1000.0, 0.0, 25.0) == pytest.approx(1.0, rel=1e-15)
    # Paper's default at nu = 0.2: 1000 * 1e-3 * 0.8 / (1.2 * 0.6) = 1.1111 Pa; equals rho c_l^2 eps.
    p0 = elastic.preload_pressure(-0.025, 1000.0, 0.2, 25.0)
    assert p0 == pytest.approx(10.0 / 9.0, rel=1e-14)
    assert p0 == pytest.approx(1000.0 * elastic.longitudinal_wave_speed(1000.0, 0.2, 1000.0) ** 2 * 1e-3,
                               rel=1e-14)


def test_onset_time_estimate():
    # nu = 0.2, f = 1.5: delta_u = 0.05 * 1.5 * (10/9) * 25 / (1000/2.4) = 0.005 m; V0 = 1e-5 c_s.
    c_s = elastic.shear_wave_speed(1000.0, 0.2, 1000.0)
    t = elastic.onset_time_estimate(f=1.5, preshear_ratio=0.95, p0=10.0 / 9.0, H=25.0, E=1000.0,
                                   nu=0.2, V0=1e-5 * c_s)
    assert t == pytest.approx(0.005 / (1e-5 * c_s), rel=1e-12)
    assert 770.0 < t < 780.0  # the physics notes: first slip near 740 s, on a stair before this


def test_pulse_spacing():
    c_s = 0.645
    assert elastic.pulse_spacing(math.sqrt(2) * c_s, c_s, 25.0) == pytest.approx(50.0, rel=1e-12)
    assert elastic.pulse_spacing(-math.sqrt(5) * c_s, c_s, 25.0) == pytest.approx(100.0, rel=1e-12)
    assert math.isnan(elastic.pulse_spacing(0.9 * c_s, c_s, 25.0))
    assert math.isnan(elastic.pulse_spacing(math.nan, c_s, 25.0))


# The solver writes the constants it uses; analysis.theory.elastic must give the same numbers before a run
# exists. A tiny run (H/2, a few steps) with values away from the defaults, so that a default cannot
# hide a mismatch.
SOLVER = Path(__file__).resolve().parents[3] / "build" / "slidewave"
TINY = {
    "material": {"E": 2000.0, "nu": 0.3, "rho": 900.0},
    "geometry": {"H": 10.0, "lambda_over_H": 2.0},
    "mesh": {"elements_per_H": 2},
    "loading": {"Uy_over_H": -2e-3, "preshear_ratio": 0.9, "V0_over_cs": 1e-4},
    "friction": {"f": 0.7},
    "time": {"dt_times_cs": 0.25, "t_end": 0.5},
    "output": {"progress": "never"},
}


def expected_constants(config: dict) -> dict:
    """c_s, c_l, p0, dt, t_onset_estimate of a config, from analysis.theory.elastic."""
    m, g, lo = config["material"], config["geometry"], config["loading"]
    E, nu, rho, H = m["E"], m["nu"], m["rho"], g["H"]
    c_s = elastic.shear_wave_speed(E, nu, rho)
    p0 = elastic.preload_pressure(lo["Uy_over_H"] * H, E, nu, H)
    return {
        "c_s": c_s, "c_l": elastic.longitudinal_wave_speed(E, nu, rho), "p0": p0,
        "dt": elastic.time_step(c_s, config["time"]["dt_times_cs"]),
        "t_onset_estimate": elastic.onset_time_estimate(
            f=config["friction"]["f"], preshear_ratio=lo["preshear_ratio"], p0=p0, H=H, E=E, nu=nu,
            V0=lo["V0_over_cs"] * c_s),
    }


def assert_run_agrees_with_theory(run_path, config):
    from analysis.core.io import load_run

    run = load_run(run_path)
    for name, value in expected_constants(config).items():
        # Same formulas, possibly another order of operations: agreement to round-off.
        assert run.setup[name] == pytest.approx(value, rel=1e-13, abs=0), name


@pytest.mark.skipif(not SOLVER.exists(), reason=f"no solver at {SOLVER} (build it: scripts/build.sh)")
def test_theory_agrees_with_what_the_solver_writes(tmp_path):
    config_path, run_path = tmp_path / "tiny.json", tmp_path / "tiny.h5"
    config_path.write_text(json.dumps(TINY))
    result = subprocess.run([str(SOLVER), "run", str(config_path), "-o", str(run_path)],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert_run_agrees_with_theory(run_path, TINY)
