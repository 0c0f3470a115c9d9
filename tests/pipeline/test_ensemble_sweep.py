"""Seeds (and any point key) swept like nu and f: the `table1_ensemble` sweep, its names, and that
the names of the runs the study already has did not change (a changed name reruns a run)."""

import csv
import re

import pytest

from study import run_store, sweeps

from .conftest import REPO

PUBLISHED = REPO / "study" / "results"


def test_ensemble_sweep_is_every_published_cell_times_eight_seeds(study_config):
    points = sweeps.sweep_points(study_config, "table1_ensemble", REPO)
    assert len(points) == 38 * 8
    assert sorted({p["seed"] for p in points.values()}) == list(range(1, 9))
    assert {p["elements_per_H"] for p in points.values()} == {64}
    # `all` builds it through the paper's envelope (test_wiring), not as a sweep of `study`
    assert study_config["paper"]["envelope"]["ensemble"] == "table1_ensemble"


def test_seed_one_is_the_ci_run_and_other_seeds_spell_their_seed(study_config):
    ensemble = sweeps.sweep_points(study_config, "table1_ensemble", REPO)
    ci = sweeps.sweep_points(study_config, "table1_ci", REPO)
    seed1 = {name for name, p in ensemble.items() if p["seed"] == 1}
    assert seed1 == set(ci)
    for name, point in ensemble.items():
        assert name.endswith(f"_seed{point['seed']}") == (point["seed"] != 1)


def test_any_point_key_can_be_a_grid_list(study_config):
    config = {**study_config, "sweeps": {"s": {"points": [{"nu": 0.2, "f": 1.5}],
                                               "grid": {"seed": [1, 7], "integration": ["reduced", "full"]}}}}
    names = list(sweeps.sweep_points(config, "s"))
    assert names == ["nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced",
                     "nu0.20_f1.50_v1e-05_L2_n64_rho1000_full",
                     "nu0.20_f1.50_v1e-05_L2_n64_rho1000_reduced_seed7",
                     "nu0.20_f1.50_v1e-05_L2_n64_rho1000_full_seed7"]


@pytest.mark.parametrize("sweep", sorted(p.name for p in PUBLISHED.iterdir()
                                         if (p / "all_metrics.csv").exists() and p.name != "study"))
def test_published_runs_keep_their_names(study_config, sweep):
    """Every run of study/results/<sweep>/all_metrics.csv is still a point of that sweep, by name: its folder
    results/runs/<point>-<digest of its config.json> (study/run_store.py) names the point."""
    with open(PUBLISHED / sweep / "all_metrics.csv", newline="") as stream:
        folders = [row["metrics_file"].split("/")[-2] for row in csv.DictReader(stream)]
    assert all(re.fullmatch(run_store.RUN_ID_PATTERN, folder) for folder in folders), folders
    published = {folder.rsplit("-", 1)[0] for folder in folders}
    assert published == set(sweeps.sweep_points(study_config, sweep, REPO))
