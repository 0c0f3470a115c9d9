"""The interface output stride of the study's runs (study/output_sampling.py, docs/output-sampling.md)."""

import json
import subprocess

import pytest

from analysis.fronts.sampling_limit import frame_shift_fraction
from analysis.theory import elastic
from analysis.theory.supersonic import supersonic_trace_speed
from study import sweeps
from study.make_run_config import run_config
from study.output_sampling import MAX_SHIFT_PER_FRAME, SOLVER_DEFAULT_STRIDE, fastest_front_speed, interface_stride

from .test_study_config import spec

PAPER = {"E": 1000.0, "rho": 1000.0, "H": 25.0, "lambda_over_H": 2.0, "dt_times_cs": 0.5}


def shift_per_frame(stride, *, nu, f, E=1000.0, rho=1000.0, H=25.0, lambda_over_H=2.0, dt_times_cs=0.5,
                    substrate=None):
    """Distance a front at v_max moves between two frames, in periods (the analysis's frame shift)."""
    dt = dt_times_cs / elastic.shear_wave_speed(E, nu, rho)
    v_max = fastest_front_speed(E=E, nu=nu, rho=rho, f=f, substrate=substrate)
    return frame_shift_fraction(v_max, stride * dt, lambda_over_H * H)


@pytest.mark.parametrize("nu", [0.0, 0.2, 0.45, 0.49])
@pytest.mark.parametrize("f", [0.5, 1.05, 1.5, 2.0])
@pytest.mark.parametrize("lambda_over_H,dt_times_cs", [(2.0, 0.5), (1.0, 0.5), (6.0, 0.5), (2.0, 0.25), (2.0, 1.0)])
def test_the_stride_is_the_largest_up_to_4_that_keeps_a_front_at_v_max_within_a_quarter_period(
        nu, f, lambda_over_H, dt_times_cs):
    case = {**PAPER, "nu": nu, "f": f, "lambda_over_H": lambda_over_H, "dt_times_cs": dt_times_cs}
    stride = interface_stride(**case)
    shift = {key: case[key] for key in ("nu", "f", "lambda_over_H", "dt_times_cs")}
    assert 1 <= stride <= SOLVER_DEFAULT_STRIDE
    assert stride == 1 or shift_per_frame(stride, **shift) <= MAX_SHIFT_PER_FRAME
    assert stride == SOLVER_DEFAULT_STRIDE or shift_per_frame(stride + 1, **shift) > MAX_SHIFT_PER_FRAME


def test_only_nu_049_departs_from_the_solver_default_at_the_papers_period():
    """The table of docs/output-sampling.md."""
    strides = {(nu, f): interface_stride(**PAPER, nu=nu, f=f)
               for nu in (0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.49) for f in (0.5, 0.8, 1.05, 1.2, 1.5, 2.0)}
    assert {key: s for key, s in strides.items() if s != 4} == {
        (0.49, 0.5): 3, (0.49, 0.8): 2, (0.49, 1.05): 2, (0.49, 1.2): 2, (0.49, 1.5): 2, (0.49, 2.0): 1}


def test_v_max_is_adams_speed_where_it_exists_else_c_l_and_a_stiffer_substrate_raises_it():
    c_s, _, c_l = elastic.wave_speeds(0.49)
    assert fastest_front_speed(E=1000.0, nu=0.49, rho=1000.0, f=1.05) == supersonic_trace_speed(0.49, 1.05, c_s)
    assert supersonic_trace_speed(0.49, 1.05, c_s) > c_l
    assert fastest_front_speed(E=1000.0, nu=0.0, rho=1000.0, f=1.5) == elastic.wave_speeds(0.0)[2]
    substrate = {"E": 25000.0, "nu": 0.2, "rho": 1000.0, "H": 25.0}
    assert fastest_front_speed(E=1000.0, nu=0.2, rho=1000.0, f=1.5, substrate=substrate) == pytest.approx(
        elastic.longitudinal_wave_speed(25000.0, 0.2, 1000.0))
    # On a 25x stiffer substrate a stride of 4 would let a front at its c_l move 0.28 of the period.
    assert interface_stride(**PAPER, nu=0.2, f=1.5) == 4
    assert interface_stride(**PAPER, nu=0.2, f=1.5, substrate=substrate) == 3


def test_the_run_config_writes_the_stride_only_where_the_rule_departs_from_the_default(study_config):
    points = sweeps.sweep_points(study_config, "table1")
    configs = {(p["nu"], p["f"]): run_config(spec(study_config, "table1", name)) for name, p in points.items()}
    assert configs[(0.49, 1.05)]["output"] == {"interface_stride": 2}
    assert configs[(0.49, 2.0)]["output"] == {"interface_stride": 1}
    assert "output" not in configs[(0.2, 1.5)] and "output" not in configs[(0.45, 1.05)]


def test_a_sweep_that_sets_the_stride_keeps_its_own(study_config):
    (name,) = [n for n, p in sweeps.sweep_points(study_config, "table1").items() if (p["nu"], p["f"]) == (0.49, 1.05)]
    entry = spec(study_config, "table1", name)
    config = run_config({**entry, "solver": {"output": {"interface_stride": 16}}})
    assert config["output"] == {"interface_stride": 16}


def test_the_ceiling_is_the_solvers_own_default(study_config, tmp_path):
    """A stride left out of config.json must mean the rule's ceiling: the solver resolves it to 4."""
    from .conftest import solver_or_skip

    (name,) = [n for n, p in sweeps.sweep_points(study_config, "table1").items() if (p["nu"], p["f"]) == (0.2, 1.5)]
    path = tmp_path / "config.json"
    path.write_text(json.dumps(run_config(spec(study_config, "table1", name))))
    result = subprocess.run([str(solver_or_skip()), "check", str(path)], capture_output=True, text=True, check=True)
    resolved = json.loads(result.stdout[result.stdout.index("{"):])
    assert resolved["output"]["interface_stride"] == SOLVER_DEFAULT_STRIDE
