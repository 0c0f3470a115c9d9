"""Kill and resume (issue 11, items 2 and 12): a run killed with SIGKILL or stopped with SIGTERM at
several points continues with `slidewave run CONFIG -o RUN.h5 --resume` and ends with datasets byte
for byte equal to an uninterrupted run; a stopped run (exit 3) never creates or replaces RUN.h5 and
leaves RUN.partial.h5 (complete = 0, end_reason interrupted) with RUN.checkpoint.h5; a checkpoint of
another configuration is refused (exit 2) naming the key; without a checkpoint --resume starts over.

Runs the solver binary (build/slidewave, or $SLIDEWAVE_BIN: tests/support/solver_runs.py) in temporary
folders. The signals come from the solver's test hook (SLIDEWAVE_TEST_SIGNAL_AT_STEP, docs/contracts.md
section 2) at a chosen step, so that no test depends on the machine's speed (they used to sleep a
fraction of the reference run's wall time and skip when the run had already finished)."""

import json
import os
import shutil
import signal
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from solver_runs import solver_or_skip

# H/16 with a short step: 25820 steps, a few seconds of wall time; checkpoints every 0.2 s.
CONFIG = {
    "mesh": {"elements_per_H": 16},
    "friction": {"f": 1.5},
    "time": {"t_end": 1200.0, "dt_times_cs": 0.03},
    "output": {"interface_stride": 3, "snapshot_times": [0, 400, 900], "progress": "never",
               "checkpoint_interval": 0.2},
}


def solver():
    return str(solver_or_skip())


N_STEPS = 25820


def write_config(folder, config=CONFIG):
    path = Path(folder) / "run.json"
    path.write_text(json.dumps(config))
    return path


def run(config_path, output, *extra, timeout=600):
    return subprocess.run([solver(), "run", str(config_path), "-o", str(output), *extra],
                          capture_output=True, text=True, timeout=timeout)


def datasets(path):
    """Every dataset of an HDF5 file: name -> (dtype, shape, bytes)."""
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                value = obj[()]
                out[name] = (value.dtype.str, value.shape, np.asarray(value).tobytes())
        f.visititems(visit)
    return out


def assert_same_datasets(a, b):
    da, db = datasets(a), datasets(b)
    assert sorted(da) == sorted(db), "dataset names differ"
    differing = [name for name in da if da[name] != db[name]]
    assert not differing, f"datasets differ: {differing}"


def attributes(path):
    with h5py.File(path, "r") as f:
        return {key: (value.decode() if isinstance(value, bytes) else value) for key, value in f.attrs.items()}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The uninterrupted run."""
    folder = tmp_path_factory.mktemp("reference")
    result = run(write_config(folder), folder / "RUN.h5")
    assert result.returncode == 0, result.stderr
    assert attributes(folder / "RUN.h5")["complete"] == 1
    assert attributes(folder / "RUN.h5")["n_steps_done"] == N_STEPS
    assert sorted(p.name for p in folder.iterdir()) == ["RUN.h5", "RUN.interface.xdmf", "RUN.xdmf", "run.json"]
    return folder / "RUN.h5"


def start_and_signal(folder, fraction, signum):
    """Runs CONFIG into folder/RUN.h5 and has it signal itself after step fraction * N_STEPS."""
    hook = {"SLIDEWAVE_TEST_SIGNAL_AT_STEP": str(int(fraction * N_STEPS)),
            "SLIDEWAVE_TEST_SIGNAL": "KILL" if signum == signal.SIGKILL else "TERM"}
    result = subprocess.run([solver(), "run", str(write_config(folder)), "-o", str(folder / "RUN.h5")],
                            capture_output=True, text=True, timeout=600, env={**os.environ, **hook})
    return result.returncode, result.stderr


@pytest.mark.parametrize("fraction", [0.15, 0.4, 0.65])
@pytest.mark.parametrize("signum", [signal.SIGKILL, signal.SIGTERM], ids=["kill", "term"])
def test_resume_after_a_signal_is_bit_identical(tmp_path, reference, fraction, signum):
    reference_file = reference
    code, stderr = start_and_signal(tmp_path, fraction, signum)
    names = {p.name for p in tmp_path.iterdir()}
    assert "RUN.h5" not in names, "an interrupted run must not create RUN.h5"
    if signum == signal.SIGTERM:
        assert code == 3, stderr
        assert "interrupted" in stderr
        assert {"RUN.partial.h5", "RUN.checkpoint.h5"} <= names
        partial = attributes(tmp_path / "RUN.partial.h5")
        assert partial["complete"] == 0
        assert partial["end_reason"] == "interrupted"
        assert partial["n_steps_done"] == int(fraction * N_STEPS)
    else:
        assert code == -signal.SIGKILL
    had_checkpoint = (tmp_path / "RUN.checkpoint.h5").exists()

    resumed = run(tmp_path / "run.json", tmp_path / "RUN.h5", "--resume")
    assert resumed.returncode == 0, resumed.stderr
    if had_checkpoint:  # also after kill -9: the rows the checkpoint counted survive in RUN.partial.h5
        assert "resuming from step" in resumed.stderr, resumed.stderr
    assert attributes(tmp_path / "RUN.h5")["complete"] == 1
    assert_same_datasets(tmp_path / "RUN.h5", reference_file)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["RUN.h5", "RUN.interface.xdmf", "RUN.xdmf", "run.json"], \
        "checkpoint, partial file and temporaries are gone once RUN.h5 is complete"


def test_stopped_rerun_leaves_the_complete_file_untouched(tmp_path, reference):
    reference_file = reference
    shutil.copy(reference_file, tmp_path / "RUN.h5")
    before = (tmp_path / "RUN.h5").read_bytes()
    stat_before = os.stat(tmp_path / "RUN.h5")
    code, stderr = start_and_signal(tmp_path, 0.4, signal.SIGTERM)
    assert code == 3, stderr
    assert (tmp_path / "RUN.h5").read_bytes() == before
    assert os.stat(tmp_path / "RUN.h5").st_mtime_ns == stat_before.st_mtime_ns
    assert attributes(tmp_path / "RUN.partial.h5")["complete"] == 0


def test_checkpoint_of_another_configuration_is_refused(tmp_path, reference):
    code, stderr = start_and_signal(tmp_path, 0.4, signal.SIGTERM)
    assert code == 3, stderr
    changed = json.loads(json.dumps(CONFIG))
    changed["friction"]["f"] = 1.4
    partial_before = (tmp_path / "RUN.partial.h5").read_bytes()
    checkpoint_before = (tmp_path / "RUN.checkpoint.h5").read_bytes()
    refused = run(write_config(tmp_path, changed), tmp_path / "RUN.h5", "--resume")
    assert refused.returncode == 2, refused.stderr
    assert "friction.f" in refused.stderr and "1.4" in refused.stderr, refused.stderr
    assert "RUN.checkpoint.h5" in refused.stderr
    assert not (tmp_path / "RUN.h5").exists()
    assert (tmp_path / "RUN.partial.h5").read_bytes() == partial_before, "a refusal changes nothing"
    assert (tmp_path / "RUN.checkpoint.h5").read_bytes() == checkpoint_before


def test_resume_without_checkpoint_starts_over(tmp_path, reference):
    reference_file = reference
    result = run(write_config(tmp_path), tmp_path / "RUN.h5", "--resume")
    assert result.returncode == 0, result.stderr
    assert_same_datasets(tmp_path / "RUN.h5", reference_file)


def test_partial_file_without_the_checkpointed_rows_starts_over(tmp_path, reference):
    reference_file = reference
    code, stderr = start_and_signal(tmp_path, 0.5, signal.SIGTERM)
    assert code == 3, stderr
    with h5py.File(tmp_path / "RUN.partial.h5", "r+") as f:  # rows changed behind the checkpoint's back
        f["global/T"][0] = 1.0
    result = run(tmp_path / "run.json", tmp_path / "RUN.h5", "--resume")
    assert result.returncode == 0, result.stderr
    assert "cannot resume" in result.stderr and "/global/T" in result.stderr and "starting over" in result.stderr
    assert_same_datasets(tmp_path / "RUN.h5", reference_file)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["RUN.h5", "RUN.interface.xdmf", "RUN.xdmf", "run.json"]


def test_a_substrate_run_stopped_and_resumed_equals_the_uninterrupted_one(tmp_path):
    """With a deformable substrate (format 3): the checkpoint carries the substrate, and the resumed file
    (its prefix copied from RUN.partial.h5, /substrate_snapshots included) equals the uninterrupted run."""
    config = {"mesh": {"elements_per_H": 8}, "friction": {"f": 0.3}, "loading": {"V0_over_cs": 1e-3},
              "substrate": {"E": 3000.0, "nu": 0.3, "rho": 2000.0, "H": 12.5},
              "time": {"t_end": 400.0},
              "output": {"interface_stride": 3, "snapshot_times": [0, 100, 300], "progress": "never",
                         "checkpoint_interval": 0}}
    runs = {}
    for name, env in (("whole", {}), ("stopped", {"SLIDEWAVE_TEST_SIGNAL_AT_STEP": "200"})):
        folder = tmp_path / name
        folder.mkdir()
        (folder / "config.json").write_text(json.dumps(config))
        args = [solver(), "run", str(folder / "config.json"), "-o", str(folder / "run.h5")]
        result = subprocess.run(args, capture_output=True, text=True, timeout=300, env={**os.environ, **env})
        if name == "stopped":
            assert result.returncode == 3, result.stderr
            assert (folder / "run.checkpoint.h5").is_file()
            result = subprocess.run(args + ["--resume"], capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, result.stderr
        runs[name] = folder / "run.h5"

    def datasets(path):
        out = {}
        with h5py.File(path, "r") as f:
            f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
            assert f.attrs["format_version"] == 3
        return out

    whole, resumed = datasets(runs["whole"]), datasets(runs["stopped"])
    assert set(whole) == set(resumed)
    assert any(name.startswith("substrate_snapshots/0002") for name in whole)
    for name in whole:
        assert whole[name].tobytes() == resumed[name].tobytes(), name
