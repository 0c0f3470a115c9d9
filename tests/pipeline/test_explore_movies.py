"""Wiring of `snakemake explore` (one point from the command line) and `snakemake movies`, as dry
runs: the jobs each target plans, and the rejection of a bad or missing point naming the key."""

import json
import re

import pytest

from .conftest import job_counts, snakemake


def test_explore_plans_one_run_its_figures_and_summary(tmp_path):
    result = snakemake(tmp_path, "-n", "-c2", "explore", "--config", "point={nu: 0.25, f: 1.6}")
    counts = job_counts(result.stdout)
    assert counts["simulate"] == counts["measure"] == 1 and "configure" not in counts
    assert counts["fig_spacetime"] == 3 and counts["fig_tn_curves"] == 1
    assert counts["explore_phase"] == counts["explore_summary"] == 1
    # The study's default mesh (H/64), the other parameters from `defaults`.
    assert re.search(r"results/runs/nu0.25_f1.60_v1e-05_L2_n64_rho1000_reduced-[0-9a-f]{12}/run.h5", result.stdout)


@pytest.mark.parametrize("point, key, words", [
    ("{nu: 0.6, f: 1.6}", "nu", "maximum of 0.5"),
    ("{nu: 0.25, f: -0.1}", "f", "minimum of 0"),
    ("{nu: 0.25, mu: 0.3}", "mu", "not allowed"),
    ("{nu: 0.25, elements_per_H: 1}", "elements_per_H", "minimum of 2"),
])
def test_a_bad_point_is_rejected_naming_the_key_and_range(tmp_path, point, key, words):
    result = snakemake(tmp_path, "-n", "-c1", "explore", "--config", f"point={point}", check=False)
    assert result.returncode != 0
    output = result.stdout + result.stderr
    assert (f"`point.{key}`" in output or f"'{key}'" in output) and words in output
    assert not (tmp_path / "results").exists()


def test_explore_without_a_point_says_how_to_give_one(tmp_path):
    result = snakemake(tmp_path, "-n", "-c1", "explore", check=False)
    assert result.returncode != 0
    assert "--config 'point={nu: 0.25, f: 1.6}'" in result.stdout + result.stderr


def test_movies_plan_one_run_and_one_movie_each(tmp_path):
    result = snakemake(tmp_path, "-n", "-c2", "movies")
    counts = job_counts(result.stdout)
    assert counts["movie_simulate"] == counts["movie_render"] == counts["movie_configure"] == 2
    assert "results/movies/paper/movie.mp4" in result.stdout
    assert "results/movies/supersonic_backward/movie.mp4" in result.stdout


def test_movie_run_requests_one_snapshot_per_frame(tmp_path):
    snakemake(tmp_path, "-c1", "results/movies/paper/config.json")
    config = json.loads((tmp_path / "results/movies/paper/config.json").read_text())
    times = config["output"]["snapshot_times"]
    assert len(times) == 141  # 0 ... 14 t_s every 0.1 t_s (study/config.yaml movies.runs.paper)
    assert config["output"]["interface_stride"] == 1
    assert config["mesh"]["elements_per_H"] == 64 and config["material"]["nu"] == 0.2
