"""study/config.yaml against its schema, and the expansion of sweeps into named run points."""

import copy
import csv
import importlib.util
import json
import re
import subprocess

import pytest
import yaml
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

from study import figure_kinds, sweeps
from study.config_check import fill_defaults, load_schema
from study.make_run_config import run_config

from .conftest import REPO

SCHEMA = str(REPO / "study" / "config.schema.yaml")


def validated(config):
    validate(config, SCHEMA)
    return config


def test_minimal_config_gets_the_papers_defaults():
    config = validated({"sweeps": {"one": {}}})
    assert config["model"] == {"E": 1000.0, "H": 25.0, "Uy_over_H": -0.001, "preshear_ratio": 0.95}
    assert config["defaults"]["elements_per_H"] == 64 and config["defaults"]["V0_over_cs"] == 1e-5
    assert config["run_length"] == {"duration_transits": 60, "stop_after_opening_transits": 15, "t_end": None}
    (name,) = sweeps.sweep_points(config, "one")
    assert name == "nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced"


@pytest.mark.parametrize("config", [{"sweeps": {"one": {}}}, "study/config.yaml"])
def test_defaults_are_filled_as_snakemakes_validate_fills_them(config):
    # The Snakefile fills them with the schema parsed once by libyaml (study/config_check.py).
    if isinstance(config, str):
        with open(REPO / config) as stream:
            config = yaml.full_load(stream)  # as Snakemake's `configfile:` reads it
    ours = copy.deepcopy(config)
    fill_defaults(ours, load_schema())
    assert ours == validated(config)


@pytest.mark.parametrize("bad", [
    {"sweeps": {"s": {"points": [{"nu": 0.5}]}}},                  # nu < 0.5
    {"sweeps": {"s": {"points": [{"f": -0.1}]}}},                  # f >= 0
    {"sweeps": {"s": {"grid": {"V0_over_cs": ["1e-5"]}}}},         # YAML reads 1e-5 as a string
    {"sweeps": {"s": {"points": [{"mu": 0.3}]}}},                  # unknown parameter
    {"sweeps": {"s": {"grid": {"elements_per_H": [32.5]}}}},       # not an integer
    {"sweeps": {"s": {"products": ["movie"]}}},                    # unknown product
    {"sweeps": {"all": {}}},                                       # a sweep may not shadow a target
    {"sweeps": {"s": {"run_length": {"duration_transits": 0}}}},
    {"sweeps": {"s": {"solver": {"materials": {}}}}},              # not a solver group
    {"sweeps": {}},
    {"run_length": {"stop_after": 3}, "sweeps": {"s": {}}},
])
def test_bad_values_are_rejected(bad):
    with pytest.raises(WorkflowError):
        validated(bad)


def test_numbers_need_a_decimal_point_in_yaml():
    assert yaml.safe_load("x: 1e-5")["x"] == "1e-5" and yaml.safe_load("x: 1.0e-5")["x"] == 1e-5


def test_sweep_sizes(study_config):
    size = {name: len(sweeps.sweep_points(study_config, name, REPO)) for name in study_config["sweeps"]}
    assert size["table1"] == 98
    assert size["shear_rate"] == 5 and size["period"] == 3 and size["mesh"] == 3 and size["density"] == 3
    assert size["table1_ci"] == 38 and size["table1_h32"] == 38
    assert 3 <= size["quick"] <= 6 and size["ci"] <= 3


@pytest.mark.parametrize("sweep, resolution", [("table1_ci", 64), ("table1_h32", 32)])
def test_reference_sweeps_hold_exactly_the_published_cells(study_config, sweep, resolution):
    points = sweeps.sweep_points(study_config, sweep, REPO)
    with open(REPO / "study" / "reference" / "table1_celerity.csv") as stream:
        published = {(float(r["nu"]), float(r["f"])) for r in csv.DictReader(stream)}
    assert {(p["nu"], p["f"]) for p in points.values()} == published
    assert {p["elements_per_H"] for p in points.values()} == {resolution}


def test_quick_and_ci_are_coarse(study_config):
    assert {p["elements_per_H"] for p in sweeps.sweep_points(study_config, "quick").values()} == {32}
    assert {p["elements_per_H"] for p in sweeps.sweep_points(study_config, "ci").values()} == {16}


def test_names_spell_the_parameters():
    point = dict(nu=0.45, f=1.125, V0_over_cs=5e-6, lambda_over_H=4.0, elements_per_H=128, rho=0.1,
                 integration="full", seed=1)
    assert sweeps.point_name(point) == "nu0.45_f1.125_v5e-06_L4_n128_rho0.1_full"
    assert sweeps.point_name({**point, "seed": 7}).endswith("_full_seed7")


def test_points_times_grid_over_fixed_and_defaults():
    config = validated({"defaults": {"nu": 0.1}, "sweeps": {"s": {
        "fixed": {"elements_per_H": 16},
        "points": [{"f": 1.0}, {"f": 2.0, "rho": 10.0}],
        "grid": {"lambda_over_H": [2.0, 4.0]}}}})
    points = list(sweeps.sweep_points(config, "s").values())
    assert [(p["f"], p["lambda_over_H"], p["rho"]) for p in points] == [
        (1.0, 2.0, 1000.0), (1.0, 4.0, 1000.0), (2.0, 2.0, 10.0), (2.0, 4.0, 10.0)]
    assert all(p["nu"] == 0.1 and p["elements_per_H"] == 16 for p in points)


def test_adding_a_point_keeps_the_other_names(study_config):
    config = json.loads(json.dumps(study_config))
    before = sweeps.sweep_points(config, "quick")
    config["sweeps"]["quick"]["points"].append({"nu": 0.3, "f": 1.25})
    after = sweeps.sweep_points(config, "quick")
    assert list(after)[:len(before)] == list(before)
    assert list(after)[-1] == "nu0.30_f1.25_v1e-05_L2_n32_rho1000_reduced"


def test_duplicates_and_fractional_periods_are_errors():
    with pytest.raises(ValueError, match="twice"):
        sweeps.sweep_points(validated({"sweeps": {"s": {"points": [{"f": 1.0}, {"f": 1.0}]}}}), "s")
    with pytest.raises(ValueError, match="integer"):
        sweeps.sweep_points(validated({"sweeps": {"s": {"points": [{"lambda_over_H": 2.01}]}}}), "s")


def test_lookups(study_config):
    points = sweeps.sweep_points(study_config, "shear_rate")
    assert sweeps.varying_keys(points) == ["V0_over_cs"]
    name = sweeps.find_point(points, {"V0_over_cs": 1e-5})
    assert list(points).index(name) == 2
    with pytest.raises(ValueError):
        sweeps.find_point(points, {"nu": 0.2})
    assert sweeps.label(points[name], ["V0_over_cs"]) == "V0/c_s=1e-05"


def spec(config, sweep, name):
    entry = config["sweeps"][sweep]
    return {"point": sweeps.sweep_points(config, sweep, REPO)[name], "model": config["model"],
            "run_length": {**config["run_length"], **entry.get("run_length", {})},
            "solver": entry.get("solver", {}),
            "snapshot_offsets_transits": entry.get("snapshot_offsets_transits", [])}


def test_run_config_of_the_snapshot_run(study_config):
    (name,) = sweeps.sweep_points(study_config, "snapshots")
    config = run_config(spec(study_config, "snapshots", name))
    times = config["output"]["snapshot_times"]
    # The paper's Fig. 3 times 787 ... 1077 s, from the onset estimate 774.6 s, then later ones.
    assert times[0] == pytest.approx(786.2, abs=1.0) and times[5] == pytest.approx(1076.7, abs=1.0)
    assert times == sorted(times) and times[-1] < config["time"]["t_end"]
    assert config["time"]["stop_after_opening"] == pytest.approx(15 * 38.7298, rel=1e-4)


def test_solver_overrides_add_keys_but_may_not_redefine_the_study(study_config):
    (name,) = sweeps.sweep_points(study_config, "long")
    entry = spec(study_config, "long", name)
    assert run_config({**entry, "solver": {"contact": {"tolerance": 1e-9}}})["contact"] == {"tolerance": 1e-9}
    assert run_config(entry)["time"] == {"t_end": 20000.0, "stop_after_opening": None, "dt_times_cs": 0.5}
    with pytest.raises(ValueError, match="friction.f"):
        run_config({**entry, "solver": {"friction": {"f": 0.3}}})


def test_the_solver_accepts_every_config_of_the_study(study_config, tmp_path):
    """Contract check: `slidewave check` (unknown keys are errors) on every point of every sweep."""
    from .conftest import solver_or_skip

    solver = solver_or_skip()
    for sweep in study_config["sweeps"]:
        for name in sweeps.sweep_points(study_config, sweep, REPO):
            path = tmp_path / f"{sweep}_{name}.json"
            path.write_text(json.dumps(run_config(spec(study_config, sweep, name))))
            result = subprocess.run([str(solver), "check", str(path)], capture_output=True, text=True)
            assert result.returncode == 0, f"{sweep}/{name}: {result.stderr}"


def test_the_time_step_is_a_point_parameter_named_only_off_the_paper_value(study_config):
    points = sweeps.sweep_points(study_config, "timestep")
    names = [name for name, point in points.items() if point["nu"] == 0.2]
    assert names == ["nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced_dt0.25",
                     "nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced",
                     "nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced_dt1"]
    assert [run_config(spec(study_config, "timestep", name))["time"]["dt_times_cs"] for name in names] == [0.25, 0.5, 1.0]


def test_the_figure_kinds_are_the_one_list(study_config):
    """study/figure_kinds.py is the list; the static schema, the rules, the scripts and the report's
    captions name the same kinds."""
    schema = yaml.safe_load(open(SCHEMA))
    products = schema["definitions"]["sweep"]["properties"]["products"]["items"]["enum"]
    assert sorted(products) == sorted(figure_kinds.PRODUCTS)
    reserved = set(schema["properties"]["sweeps"]["propertyNames"]["not"]["enum"])
    rules = set(re.findall(r"^rule (fig_\w+):", (REPO / "study" / "rules" / "figures.smk").read_text(), re.MULTILINE))
    spec = importlib.util.spec_from_file_location("report", REPO / "study" / "scripts" / "report.py")
    report = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(report)
    for kind in figure_kinds.FIGURE_KINDS:
        assert f"fig_{kind}" in rules and f"fig_{kind}" in reserved, kind
        assert (REPO / "figures" / f"{kind}.py").is_file(), kind
        assert any(stem.startswith(kind) for stem in report.CAPTIONS), kind
    assert rules == {f"fig_{kind}" for kind in figure_kinds.FIGURE_KINDS}
    # FROM_RUNS: exactly the kinds whose rule reads a run.h5 (the rest draw from tables).
    text = (REPO / "study" / "rules" / "figures.smk").read_text()
    blocks = dict(re.findall(r"^rule fig_(\w+):\n(.*?)(?=^rule |\Z)", text, re.MULTILINE | re.DOTALL))
    assert {kind for kind in figure_kinds.FIGURE_KINDS if "run.h5" in blocks[kind]} == set(figure_kinds.FROM_RUNS)
    for sweep in study_config["sweeps"].values():
        assert set(sweep.get("products", [])) <= set(figure_kinds.PRODUCTS)
