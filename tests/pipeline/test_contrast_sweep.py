"""The material contrast E_substrate_over_E as a point parameter (study/sweeps.py, make_run_config.py,
config.schema.yaml): names, the solver's `substrate` group, and rigid-flat runs left as they were."""

import json

import pytest
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

from study import sweeps
from study.make_run_config import config_json_text, run_config

from .conftest import REPO

SCHEMA = str(REPO / "study" / "config.schema.yaml")
POINT = dict(nu=0.2, f=1.5, V0_over_cs=1e-5, lambda_over_H=2.0, elements_per_H=32, rho=1000.0,
             integration="reduced", seed=1, dt_times_cs=0.5)


def validated(config):
    validate(config, SCHEMA)
    return config


def spec(point, solver=None):
    config = validated({"sweeps": {"s": {}}})
    return {"point": point, "model": config["model"], "run_length": config["run_length"],
            "solver": solver or {}, "snapshot_offsets_transits": []}


def test_the_contrast_is_in_the_name_only_when_present():
    rigid = sweeps.point_name(POINT)
    assert rigid == "nu0.20_f1.50_v1e-05_L2_n32_rho1000_reduced"
    assert sweeps.point_name({**POINT, "E_substrate_over_E": None}) == rigid
    assert sweeps.point_name({**POINT, "E_substrate_over_E": 3.0}) == rigid + "_Es3"
    assert sweeps.point_name({**POINT, "E_substrate_over_E": 1 / 3}) == rigid + "_Es0.333333"
    assert sweeps.point_name({**POINT, "seed": 2, "E_substrate_over_E": 1000.0}).endswith("_seed2_Es1000")


def test_a_grid_over_the_contrast_with_the_rigid_flat():
    config = validated({"sweeps": {"s": {"fixed": {"elements_per_H": 32},
                                         "grid": {"f": [1.0], "E_substrate_over_E": [None, 10.0]}}}})
    points = sweeps.sweep_points(config, "s")
    assert list(points) == ["nu0.20_f1.00_v1e-05_L2_n32_rho1000_reduced",
                            "nu0.20_f1.00_v1e-05_L2_n32_rho1000_reduced_Es10"]
    assert sweeps.varying_keys(points) == ["E_substrate_over_E"]
    assert sweeps.find_point(points, {"E_substrate_over_E": None}) == list(points)[0]
    assert sweeps.find_point(points, {"E_substrate_over_E": 10.0}) == list(points)[1]
    assert sweeps.label(points[list(points)[0]], ["E_substrate_over_E"]) == "rigid flat"
    assert sweeps.label(points[list(points)[1]], ["E_substrate_over_E"]) == "E_s/E=10"


@pytest.mark.parametrize("bad", [0.0, -1.0, 1e13, "stiff"])
def test_bad_contrasts_are_rejected(bad):
    with pytest.raises(WorkflowError):
        validated({"sweeps": {"s": {"points": [{"E_substrate_over_E": bad}]}}})


def test_the_substrate_group_takes_the_layers_nu_rho_and_thickness():
    config = run_config(spec({**POINT, "nu": 0.45, "rho": 10.0, "E_substrate_over_E": 3.0}))
    assert config["substrate"] == {"E": 3000.0, "nu": 0.45, "rho": 10.0, "H": 25.0}
    # Equal nu and thickness: the onset (study/run_length.py eq. (1')) is the rigid flat's.
    rigid = run_config(spec({**POINT, "nu": 0.45, "rho": 10.0}))
    assert config["time"]["t_end"] == pytest.approx(rigid["time"]["t_end"], rel=1e-12)


def test_a_rigid_point_writes_the_config_of_before():
    text = config_json_text(run_config(spec(POINT)))
    assert "substrate" not in json.loads(text)
    assert config_json_text(run_config(spec({**POINT, "E_substrate_over_E": None}))) == text


def test_contrast_and_a_full_substrate_group_are_exclusive():
    solver = {"substrate": {"E": 1e4, "nu": 0.3, "rho": 1000.0, "H": 12.5}}
    # The full group alone sets the substrate and its onset (H_s / G_s in series with H / G).
    config = run_config(spec(POINT, solver))
    assert config["substrate"] == solver["substrate"]
    assert config["time"]["t_end"] != pytest.approx(run_config(spec(POINT))["time"]["t_end"], rel=1e-6)
    with pytest.raises(ValueError, match="E_substrate_over_E"):
        run_config(spec({**POINT, "E_substrate_over_E": 3.0}, solver))


def test_the_contrast_sweep_leaves_every_other_run_where_it_was(study_config):
    # Rigid points of the contrast sweep are the same runs as anywhere else, and no other sweep names a contrast.
    contrast = sweeps.sweep_points(study_config, "contrast")
    assert {p.get("E_substrate_over_E") for p in contrast.values()} == {None, 1000.0, 10.0, 3.0, 1.0, 1 / 3}
    assert {p["elements_per_H"] for p in contrast.values()} == {32}
    for sweep in study_config["sweeps"]:
        if sweep != "contrast":
            assert all("_Es" not in name for name in sweeps.sweep_points(study_config, sweep, REPO))


def test_a_contrast_in_a_points_csv(tmp_path):
    (tmp_path / "points.csv").write_text("nu,f,E_substrate_over_E\n0.2,1.0,3\n0.2,1.0,\n")
    config = validated({"sweeps": {"s": {"points_from_csv": "points.csv"}}})
    names = list(sweeps.sweep_points(config, "s", tmp_path))
    assert names[0].endswith("_Es3") and "_Es" not in names[1]
