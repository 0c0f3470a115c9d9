"""study/fit_resources.py refits study/resources.py's constants from benchmark files: on a synthetic
campaign made from known constants, the fit finds them again (the stick and slip phases apart) and the
model then predicts each run; a campaign that cannot see an exponent leaves it as it was."""

import json
import math

import h5py
import pytest

from study import fit_resources, resources

TRUTH = {"time": {"setup_s": 0.3, "ms_per_step_h32": 0.05, "mesh_exponent": 2.3, "period_exponent": 1.6,
                  "contact_ms_per_step_h32": 0.004, "contact_mesh_exponent": 4.5,
                  "stick_ms_per_step_h32": 0.012, "stick_mesh_exponent": 1.7, "stick_period_exponent": 1.2},
         "memory": {"base_mb": 20.0, "mb_per_element": 0.004}}
# A file from before the phases were modelled apart (no contact_ or stick_ keys): the fit starts from it.
PRIOR = {"time": {"setup_s": 1.0, "ms_per_step_h32": 0.2, "mesh_exponent": 2.5, "period_exponent": 1.87},
         "memory": {"base_mb": 500.0, "mb_per_element": 0.03}, "fitted_from": {"runs": 0}}
DT = 0.5  # s, the synthetic runs' step


def write_run(folder, n, period, steps, stick_fraction=0.5, constants=TRUTH, noise=1.0, load=0.0):
    """A run folder as the pipeline leaves it: config.json, run.h5 (n_steps_done, and the setup times that
    put the onset estimate after stick_fraction of the steps), the benchmark of a job that took `noise`
    times the model's time, or got `load` percent of a core (0: not sampled)."""
    (folder / "logs").mkdir(parents=True)
    (folder / "config.json").write_text(json.dumps({"mesh": {"elements_per_H": n},
                                                    "geometry": {"lambda_over_H": period}}))
    stick_steps = round(stick_fraction * steps)
    with h5py.File(folder / "run.h5", "w") as run:
        run.attrs["n_steps_done"] = steps
        setup = run.create_group("setup")
        setup.attrs.update({"dt": DT, "t_end": steps * DT, "t_onset_estimate": stick_steps * DT})
    wall = (resources.seconds(n, period, steps, constants, stick_steps=stick_steps) * noise
            * (100.0 / load if load else 1.0))
    cpu = load / 100.0 * fit_resources.last_sample_time(wall)
    rss = resources.memory_mb(n, period, constants)
    (folder / "logs" / "simulate.benchmark.tsv").write_text(
        "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
        f"{wall:.6f}\t0:00:00\t{rss:.2f}\t0\t0\t0\t0\t0\t{load:.2f}\t{cpu:.6f}\n")


def campaign(root, cases, **kwargs):
    for index, case in enumerate(cases):
        n, period = case[0], case[1]
        write_run(root / f"nu0.20_f1.50_n{n}_L{period:g}-{index:012x}", *case, **kwargs)


CASES = [(n, period, steps, fraction) for n in (16, 32, 64) for period in (2.0, 4.0) for steps in (2000, 6000)
         for fraction in (0.2, 0.8)] + [(128, 2.0, 3000, 0.7), (64, 6.0, 3000, 0.7)]


def seconds(case, constants):
    n, period, steps, fraction = case
    return resources.seconds(n, period, steps, constants, stick_steps=round(fraction * steps))


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
    for case in CASES:
        n, period, steps, fraction = case
        predicted = seconds(case, fitted)
        assert predicted == pytest.approx(seconds(case, TRUTH), rel=0.02)
        asked = resources.estimate(elements_per_H=n, lambda_over_H=period, steps=steps,
                                   stick_steps=round(fraction * steps), constants=fitted)
        assert asked["runtime"] * 60 > predicted and asked["mem_mb"] > resources.memory_mb(n, period, TRUTH)


def test_a_stick_step_and_a_slip_step_cost_what_their_phase_costs():
    """The model: a run all before the onset costs its steps at the stick phase's rate, all after it at
    the slip phase's (the layer's part and the contact solve's), and a mixed run the sum (stick steps
    beyond the run's steps count as the run's)."""
    t = TRUTH["time"]
    stick_ms = t["stick_ms_per_step_h32"] * 2 ** t["stick_mesh_exponent"] * 2 ** t["stick_period_exponent"]
    slip_ms = (t["ms_per_step_h32"] * 2 ** t["mesh_exponent"]
               + t["contact_ms_per_step_h32"] * 2 ** t["contact_mesh_exponent"]) * 2 ** t["period_exponent"]
    assert resources.seconds(64, 4.0, 1000, TRUTH, stick_steps=1000) == pytest.approx(0.3 + stick_ms)
    assert resources.seconds(64, 4.0, 1000, TRUTH, stick_steps=5000) == pytest.approx(0.3 + stick_ms)
    assert resources.seconds(64, 4.0, 1000, TRUTH) == pytest.approx(0.3 + slip_ms)
    assert resources.seconds(64, 4.0, 1000, TRUTH, stick_steps=250) == pytest.approx(
        0.3 + 0.25 * stick_ms + 0.75 * slip_ms)


def test_a_loaded_run_does_not_pull_the_fit(tmp_path):
    campaign(tmp_path / "runs", CASES)
    write_run(tmp_path / "runs" / "nu0.20_f1.50_slow-000000000000", 64, 2.0, 4000, noise=4.0)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    assert seconds((64, 2.0, 4000, 0.5), fitted) == pytest.approx(seconds((64, 2.0, 4000, 0.5), TRUTH), rel=0.1)


def test_a_campaign_on_a_loaded_machine_is_timed_by_the_share_of_a_core_each_run_got(tmp_path):
    # runs long enough to be sampled (>= 1 s), so ten times the steps
    long_cases = [(n, period, 10 * steps, fraction) for n, period, steps, fraction in CASES]
    campaign(tmp_path / "runs", long_cases, load=30.0)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(PRIOR))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    for case in long_cases:
        assert seconds(case, fitted) == pytest.approx(seconds(case, TRUTH), rel=0.05)


def test_an_exponent_the_campaign_cannot_see_keeps_its_value(tmp_path):
    # two meshes, one period: no contact term to tell from the layer's (the truth has none, the prior
    # says so), one period exponent
    truth = {**TRUTH, "time": {**TRUTH["time"], "contact_ms_per_step_h32": 0.0}}
    campaign(tmp_path / "runs", [(n, 2.0, steps, fraction) for n in (32, 64) for steps in (1000, 3000, 9000)
                                 for fraction in (0.2, 0.8)], constants=truth)
    output = tmp_path / "resources.json"
    output.write_text(json.dumps({**PRIOR, "time": {**PRIOR["time"], "contact_ms_per_step_h32": 0.0}}))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    # one period: both phases keep the prior's period exponent (a file without stick_ keys: the slip one's)
    assert fitted["time"]["period_exponent"] == PRIOR["time"]["period_exponent"]
    assert fitted["time"]["stick_period_exponent"] == PRIOR["time"]["period_exponent"]
    assert fitted["time"]["mesh_exponent"] == pytest.approx(TRUTH["time"]["mesh_exponent"], rel=0.01)
    assert fitted["time"]["stick_mesh_exponent"] == pytest.approx(TRUTH["time"]["stick_mesh_exponent"], rel=0.01)
    assert fitted["fitted_from"]["periods"] == [2.0]


def test_a_campaign_without_stick_steps_keeps_the_stick_constants(tmp_path):
    campaign(tmp_path / "runs", [(n, period, steps, 0.0) for n, period, steps, _ in CASES])
    output = tmp_path / "resources.json"
    output.write_text(json.dumps(TRUTH))
    assert fit_resources.main([str(tmp_path / "runs"), "-o", str(output)]) == 0
    fitted = json.loads(output.read_text())
    for key in ("stick_ms_per_step_h32", "stick_mesh_exponent", "stick_period_exponent"):
        assert fitted["time"][key] == TRUTH["time"][key]


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
    # the stick phase is the cheaper one (docs/stick-phase.md), at every mesh the study runs
    for n in (32, 64, 128, 256):
        assert resources.seconds(n, 2.0, 1000, stick_steps=1000) < resources.seconds(n, 2.0, 1000)
    assert not math.isnan(resources.memory_mb(64, 2.0))
