"""A configuration of any size runs (issue 21 item 5): over 64 KiB, HDF5's limit for an attribute in
an object header, `check` and `run` both succeed, run.h5 records the verbatim input and the resolved
configuration in full, a checkpoint of such a run resumes, and analysis/io.py reads the file.

On b773bb5 `check` passed and `run` failed with exit 4 ("cannot create attribute config_input ...
No such file or directory").
"""

import json
import os
import subprocess
from pathlib import Path

import h5py
import pytest

REPO = Path(__file__).resolve().parents[2]
from analysis.core.io import load_run
from solver_runs import solver_or_skip

BASE = {"mesh": {"elements_per_H": 8}, "time": {"t_end": 60.0}, "output": {"progress": "never"}}


def padded_text():
    """BASE with 70000 spaces of padding: the verbatim input is over 64 KiB."""
    return '{"mesh": {"elements_per_H": 8},' + " " * 70000 + '"time": {"t_end": 60.0}, "output": {"progress": "never"}}'


def many_snapshots_text():
    """9000 snapshot times (after t_end, so none is taken): the resolved configuration is over 64 KiB."""
    config = json.loads(json.dumps(BASE))
    config["output"]["snapshot_times"] = [1e6 + k for k in range(9000)]
    return json.dumps(config)


def run(*args, env=None):
    return subprocess.run([str(solver_or_skip()), *map(str, args)], capture_output=True, text=True, timeout=600,
                          env={**os.environ, **(env or {})})


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


@pytest.mark.parametrize("make", [padded_text, many_snapshots_text], ids=["whitespace", "snapshot_times"])
def test_a_config_over_64_kib_runs_and_is_recorded_in_full(tmp_path, make):
    config = tmp_path / "config.json"
    config.write_text(make())
    assert config.stat().st_size > 65536
    assert run("check", config).returncode == 0
    result = run("run", config, "-o", tmp_path / "run.h5")
    assert result.returncode == 0, result.stderr
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert text(f["setup"].attrs["config_input"]).encode() == config.read_bytes()
        assert json.loads(text(f.attrs["config"]))["output"]["snapshot_times"] == \
            json.loads(config.read_text())["output"].get("snapshot_times", [])
    run_data = load_run(tmp_path / "run.h5")
    assert run_data.complete


def test_a_run_with_a_large_config_resumes(tmp_path):
    config = tmp_path / "config.json"
    config.write_text(many_snapshots_text())
    stopped = run("run", config, "-o", tmp_path / "run.h5", env={"SLIDEWAVE_TEST_SIGNAL_AT_STEP": "30"})
    assert stopped.returncode == 3, stopped.stderr
    resumed = run("run", config, "-o", tmp_path / "run.h5", "--resume")
    assert resumed.returncode == 0, resumed.stderr
    assert "resuming from step 30" in resumed.stderr, resumed.stderr
