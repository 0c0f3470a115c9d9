"""study/fit_resources.py refits study/resources.py's constants from benchmark files: on a synthetic
campaign made from known constants, the fit finds them again and the model then predicts each run;
a campaign that cannot see an exponent leaves it as it was."""

import json
import math

import h5py
import pytest

from study import fit_resources, resources

TRUTH = {"time": {"setup_s": 0.3, "ms_per_step_h32": 0.05, "mesh_exponent": 2.3, "period_exponent": 1.6},
         "memory": {"base_mb": 20.0, "mb_per_element": 0.004}}
PRIOR = {"time": {"setup_s": 1.0, "ms_per_step_h32": 0.2, "mesh_exponent": 2.5, "period_exponent": 1.87},
         "memory": {"base_mb": 500.0, "mb_per_element": 0.03}, "fitted_from": {"runs": 0}}


def write_run(folder, n, period, steps, constants=TRUTH, noise=1.0, load=0.0):
    """A run folder as the pipeline leaves it: config.json, run.h5 (n_steps_done), the benchmark of
    a job that took `noise` times the model's time, or got `load` percent of a core (0: not sampled)."""
    (folder / "logs").mkdir(parents=True)
    (folder / "config.json").write_text(json.dumps({"mesh": {"elements_per_H": n},
                                                    "geometry": {"lambda_over_H": period}}))
    with h5py.File(folder / "run.h5", "w") as run:
        run.attrs["n_steps_done"] = steps
    wall = resources.seconds(n, period, steps, constants) * noise * (100.0 / load if load else 1.0)
    cpu = load / 100.0 * fit_resources.last_sample_time(wall)
    rss = resources.memory_mb(n, period, constants)
    (folder / "logs" / "simulate.benchmark.tsv").write_text(
        "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
        f"{wall:.6f}\t0:00:00\t{rss:.2f}\t0\t0\t0\t0\t0\t{load:.2f}\t{cpu:.6f}\n")


def campaign(root, cases, **kwargs):
    for index, (n, period, steps) in enumerate(cases):
        write_run(root / f"nu0.20_f1.50_n{n}_L{period:g}-{index:012x}", n, period, steps, **kwargs)


CASES = [(n, period, steps) for n in (16, 32, 64) for period in (2.0, 4.0) for steps in (2000, 6000)] + [
    (128, 2.0, 3000), (64, 6.0, 3000)]


def test_the_fit_finds_the_constants_of_a_synthetic_campaign(tmp_path):
    campaign(tmp_path / "runs", CASES)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    for group in ("time", "memory"):
        for key, value in TRUTH[group].items():
            assert fitted[group][key] == pytest.approx(value, rel=0.01, abs=1e-3), (group, key)
    assert fitted["fitted_from"]["runs"] == len(CASES) and fitted["fitted_from"]["meshes"] == [16, 32, 64, 128]
    # The model with the fitted constants predicts every run, and resources.estimate asks for more.
    for n, period, steps in CASES:
        predicted = resources.seconds(n, period, steps, fitted)
        assert predicted == pytest.approx(resources.seconds(n, period, steps, TRUTH), rel=0.02)
        asked = resources.estimate(elements_per_H=n, lambda_over_H=period, steps=steps, constants=fitted)
        assert asked["runtime"] * 60 > predicted and asked["mem_mb"] > resources.memory_mb(n, period, TRUTH)


def test_a_loaded_run_does_not_pull_the_fit(tmp_path):
    campaign(tmp_path / "runs", CASES)
    write_run(tmp_path / "runs" / "nu0.20_f1.50_slow-000000000000", 64, 2.0, 4000, noise=4.0)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    assert resources.seconds(64, 2.0, 4000, fitted) == pytest.approx(resources.seconds(64, 2.0, 4000, TRUTH), rel=0.1)


def test_a_campaign_on_a_loaded_machine_is_timed_by_the_share_of_a_core_each_run_got(tmp_path):
    campaign(tmp_path / "runs", [(n, period, steps) for n, period, steps in CASES
                                 if resources.seconds(n, period, steps, TRUTH) >= 1.0], load=30.0)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    for n, period, steps in CASES:
        assert resources.seconds(n, period, steps, fitted) == pytest.approx(
            resources.seconds(n, period, steps, TRUTH), rel=0.05)


def test_an_exponent_the_campaign_cannot_see_keeps_its_value(tmp_path):
    campaign(tmp_path / "runs", [(n, 2.0, steps) for n in (32, 64) for steps in (1000, 3000, 9000)])
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    assert fitted["time"]["period_exponent"] == PRIOR["time"]["period_exponent"]
    assert fitted["time"]["mesh_exponent"] == pytest.approx(TRUTH["time"]["mesh_exponent"], rel=0.01)
    assert fitted["fitted_from"]["periods"] == [2.0]


def test_too_few_runs_is_an_error_naming_the_folder(tmp_path, capsys):
    campaign(tmp_path / "runs", CASES[:2])
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(tmp_path / "out.json")]) == 2
    assert str(tmp_path / "runs") in capsys.readouterr().err and not (tmp_path / "out.json").exists()


def test_the_committed_constants_are_a_fit():
    """study/resources.json is what fit_resources writes (every constant present and positive), and
    the model grows with the mesh, the period and the steps."""
    constants = resources.load_constants()
    for group, keys in (("time", TRUTH["time"]), ("memory", TRUTH["memory"])):
        assert set(constants[group]) == set(keys) and all(v >= 0 for v in constants[group].values())
    assert constants["fitted_from"]["runs"] >= 3
    small = resources.estimate(elements_per_H=32, lambda_over_H=2.0, steps=100_000)
    large = resources.estimate(elements_per_H=128, lambda_over_H=2.0, steps=100_000)
    assert 5 <= small["runtime"] < large["runtime"] and small["mem_mb"] < large["mem_mb"]
    assert resources.seconds(64, 6.0, 1000) > resources.seconds(64, 2.0, 1000) > resources.seconds(64, 2.0, 100)
    assert not math.isnan(resources.memory_mb(64, 2.0))
