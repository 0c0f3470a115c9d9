"""Shared set-up of the pipeline tests: the study config, the `slurm`
marker (skipped unless selected with `-m slurm` or SLIDEWAVE_TEST_SLURM=1), and a runner for
Snakemake in a scratch directory."""

import copy
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SNAKEMAKE = os.environ.get("SLIDEWAVE_SNAKEMAKE", "/usr/bin/snakemake")
# SOLVER and solver_or_skip are re-exported to the pipeline tests.
from solver_runs import SOLVER, solver_or_skip  # noqa: F401


def pytest_configure(config):
    config.addinivalue_line("markers", "slurm: runs the pipeline through a local SLURM (start it with "
                                       "scripts/slurm/local_slurm.sh); skipped unless selected with -m slurm")


def pytest_collection_modifyitems(config, items):
    selected = "slurm" in (config.getoption("markexpr") or "") or os.environ.get("SLIDEWAVE_TEST_SLURM") == "1"
    if selected:
        return
    skip = pytest.mark.skip(reason="SLURM test: run with -m slurm (needs scripts/slurm/local_slurm.sh)")
    for item in items:
        if "slurm" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(scope="session")
def study_config():
    """study/config.yaml validated (defaults filled) exactly as the Snakefile does."""
    from study.config_check import fill_defaults, load_schema, load_yaml

    config = load_yaml(REPO / "study" / "config.yaml")
    fill_defaults(config, load_schema())
    return config


@pytest.fixture
def config(study_config):
    """A copy of the validated study config that a test may change."""
    return copy.deepcopy(study_config)


def snakemake(workdir, *args, env=None, check=True, timeout=1800, snakefile=REPO / "Snakefile"):
    """Runs the repository's Snakefile (or another checkout's) with results in `workdir`; returns the
    CompletedProcess."""
    environment = {**os.environ, **(env or {})}
    environment.setdefault("SLIDEWAVE_BIN", str(SOLVER))
    command = [SNAKEMAKE, "-s", str(snakefile), "--directory", str(workdir), *args]
    result = subprocess.run(command, capture_output=True, text=True, env=environment, timeout=timeout)
    if check and result.returncode != 0:
        raise AssertionError(f"{' '.join(command)} failed ({result.returncode}):\n"
                             f"{result.stdout[-4000:]}\n{result.stderr[-8000:]}")
    return result


def job_counts(output):
    """{rule: count} from the 'Job stats' table of a Snakemake (dry) run."""
    counts, inside = {}, False
    for line in output.splitlines():
        if line.startswith("Job stats"):
            inside, counts = True, {}
            continue
        if inside:
            parts = line.split()
            if not parts:
                if counts:
                    inside = False
                continue
            if parts[0] == "total":
                inside = False
            elif len(parts) >= 2 and parts[1].isdigit():
                counts[parts[0]] = int(parts[1])
    return counts
