"""Pipeline smoke test: the tiny `ci` sweep (H/16, short) for real, through the solver, the analysis,
the table and one figure, in a scratch directory. Needs the built solver (skipped otherwise, a
failure under CI=true)."""

import csv
import json

from .conftest import job_counts, snakemake, solver_or_skip

POINT = "nu0.20_f1.50_v1e-05_L2_n16_rho1000_reduced"


def test_ci_sweep_end_to_end(tmp_path):
    solver = solver_or_skip()
    work = tmp_path / "work"
    snakemake(work, "-c2", "ci", env={"SLIDEWAVE_BIN": str(solver)})

    (run,) = (work / "results" / "runs").glob(f"{POINT}-*")  # the run's folder (study/run_store.py)
    config = json.loads((run / "config.json").read_text())
    assert config["mesh"]["elements_per_H"] == 16 and config["time"]["stop_after_opening"] > 0
    assert (run / "run.h5").stat().st_size > 0
    metrics = json.loads((run / "metrics.json").read_text())
    assert metrics["nu"] == 0.2 and metrics["f"] == 1.5 and metrics["elements_per_H"] == 16
    assert (run / "logs" / "simulate.benchmark.tsv").is_file()

    table = work / "results" / "ci" / "table"
    with open(table / "table1.csv") as stream:
        rows = {(float(r["nu"]), float(r["f"])): r for r in csv.DictReader(stream)}
    assert rows[(0.2, 1.5)]["published"]  # the published cell is in the table, measured or not
    with open(table / "all_metrics.csv") as stream:
        assert len(list(csv.DictReader(stream))) == 2
    for ext in ("png", "pdf"):
        figure = work / "results" / "ci" / "figures" / f"spacetime_state_{POINT}.{ext}"
        assert figure.stat().st_size > 10_000

    # Done means done: a second call has nothing to run.
    again = snakemake(work, "-n", "ci", env={"SLIDEWAVE_BIN": str(solver)})
    assert job_counts(again.stdout) == {} and "Nothing to be done" in again.stdout + again.stderr
