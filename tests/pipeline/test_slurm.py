"""The `ci` sweep through SLURM, with each cluster profile of study/profiles/, on a single-node SLURM
started on this machine by scripts/slurm/local_slurm.sh (started here if none answers, and then
stopped again). Outside the default run: `pytest -m slurm tests/pipeline/test_slurm.py`."""

import os
import re
import subprocess

import pytest

from .conftest import REPO, snakemake, solver_or_skip

SCRIPT = REPO / "scripts" / "slurm" / "local_slurm.sh"
SLURM_DIR = os.environ.get("SLIDEWAVE_SLURM_DIR", "/tmp/slidewave-slurm")
CONF = os.path.join(SLURM_DIR, "slurm.conf")
POINTS = ("nu0.20_f1.50_v1e-05_L2_n16_rho1000_reduced", "nu0.20_f0.80_v1e-05_L2_n16_rho1000_reduced")


def slurm_answers(env):
    return subprocess.run(["sinfo", "-h", "-o", "%t"], env=env, capture_output=True, text=True).returncode == 0


@pytest.fixture(scope="module")
def slurm_env():
    env = {**os.environ, "SLURM_CONF": os.environ.get("SLURM_CONF", CONF),
           "USER": os.environ.get("USER") or subprocess.run(["id", "-un"], capture_output=True, text=True).stdout.strip()}
    started = False
    if not (os.path.exists(env["SLURM_CONF"]) and slurm_answers(env)):
        subprocess.run([str(SCRIPT), "start"], check=True, env={**env, "SLURM_CONF": CONF})
        env["SLURM_CONF"], started = CONF, True
    yield env
    if started:
        subprocess.run([str(SCRIPT), "stop"], check=True, env=env)


@pytest.mark.slurm
@pytest.mark.parametrize("profile", ["slurm", "slurm-sbatch"])
def test_ci_sweep_through_slurm(tmp_path, slurm_env, profile):
    solver = solver_or_skip()
    work = tmp_path / "work"
    env = {**slurm_env, "SLIDEWAVE_BIN": str(solver), "CI": "true"}
    result = snakemake(work, "--profile", str(REPO / "study" / "profiles" / profile), "ci", env=env, timeout=1800)
    log = result.stdout + result.stderr

    # Every simulate and figure job went through sbatch; measure and aggregate ran in the submitting
    # Snakemake (study/in_process.py).
    # --slurm: "... submitted with SLURM jobid 7"; --cluster: "Submitted job 3 with external jobid '7'."
    submitted = re.findall(r"(?:with SLURM jobid |with external jobid ')(\d+)", log)
    assert len(submitted) == 2 + 1, log[-3000:]
    for job in submitted:
        state = subprocess.run(["scontrol", "show", "job", "-o", job], env=env, capture_output=True, text=True).stdout
        assert "JobState=COMPLETED" in state, state
    for point in POINTS:
        assert len(list((work / "results" / "runs").glob(f"{point}-*/metrics.json"))) == 1
    assert (work / "results" / "ci" / "table" / "table1.csv").is_file()
    assert (work / "results" / "ci" / "figures" / f"spacetime_state_{POINTS[0]}.png").is_file()
