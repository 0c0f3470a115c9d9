"""A damaged checkpoint or partial file is never resumed (issue 21 items 2 and 9a): a flipped byte in
a checkpoint dataset, an edited step counter, or a partial-file chunk that fails its Fletcher32
checksum make `slidewave run --resume` start from the beginning, say why on stderr (the real reason,
not a stale errno), and end with the datasets of an uninterrupted run.

On b773bb5 the flipped byte and the edited counter resumed into wrong data marked complete, and the
checksum failure was reported as "No such file or directory".
"""

import json
import os
import subprocess

import h5py
import pytest

from solver_runs import solver_or_skip
from test_kill_resume import assert_same_datasets

# H/16, 6455 steps (about a second); stopped at step 3000 by the test hook (docs/contracts.md section 2).
CONFIG = {"mesh": {"elements_per_H": 16}, "time": {"t_end": 300.0, "dt_times_cs": 0.03},
          "output": {"interface_stride": 3, "snapshot_times": [0, 100, 250], "progress": "never",
                     "checkpoint_interval": 0}}
STOP_AT = 3000
FINAL_FILES = ["RUN.h5", "RUN.interface.xdmf", "RUN.xdmf", "run.json"]


def run(folder, *extra, env=None):
    config = folder / "run.json"
    config.write_text(json.dumps(CONFIG))
    return subprocess.run([str(solver_or_skip()), "run", str(config), "-o", str(folder / "RUN.h5"), *extra],
                          capture_output=True, text=True, timeout=600, env={**os.environ, **(env or {})})


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    folder = tmp_path_factory.mktemp("reference")
    result = run(folder)
    assert result.returncode == 0, result.stderr
    return folder / "RUN.h5"


@pytest.fixture
def stopped(tmp_path):
    """A run stopped by SIGTERM after step STOP_AT: RUN.partial.h5 and RUN.checkpoint.h5 in tmp_path."""
    result = run(tmp_path, env={"SLIDEWAVE_TEST_SIGNAL_AT_STEP": str(STOP_AT)})
    assert result.returncode == 3, result.stderr
    return tmp_path


def flip_byte(path, dataset, at=100):
    """Inverts one byte inside the stored data of a contiguous dataset, behind HDF5's back."""
    with h5py.File(path, "r") as f:
        offset = f[dataset].id.get_offset()
    assert offset is not None, f"{dataset} is not contiguous"
    with open(path, "r+b") as raw:
        raw.seek(offset + at)
        byte = raw.read(1)[0]
        raw.seek(offset + at)
        raw.write(bytes([byte ^ 0x01]))


def resume_starts_over(folder, reference, *words):
    result = run(folder, "--resume")
    assert result.returncode == 0, result.stderr
    assert "cannot resume" in result.stderr and "starting over" in result.stderr, result.stderr
    assert "resuming from step" not in result.stderr, result.stderr
    for word in words:
        assert word in result.stderr, result.stderr
    assert "No such file or directory" not in result.stderr, result.stderr
    with h5py.File(folder / "RUN.h5", "r") as f:
        assert int(f.attrs["complete"]) == 1 and int(f.attrs["n_steps_done"]) == 6455
    assert_same_datasets(folder / "RUN.h5", reference)
    assert sorted(p.name for p in folder.iterdir()) == FINAL_FILES


def test_an_intact_checkpoint_resumes(stopped, reference):
    result = run(stopped, "--resume")
    assert result.returncode == 0, result.stderr
    assert f"resuming from step {STOP_AT}" in result.stderr, result.stderr
    assert_same_datasets(stopped / "RUN.h5", reference)


@pytest.mark.parametrize("dataset,at", [("reals/v", 100), ("reals/u", 8 * 77 + 3), ("integers/contact", 5),
                                        ("stream/digests", 9)])
def test_a_flipped_byte_in_the_checkpoint_starts_over(stopped, reference, dataset, at):
    flip_byte(stopped / "RUN.checkpoint.h5", dataset, at)
    resume_starts_over(stopped, reference, "RUN.checkpoint.h5", "damaged")


def test_an_edited_step_counter_starts_over(stopped, reference):
    with h5py.File(stopped / "RUN.checkpoint.h5", "r+") as f:
        f["integers/counters"][0] = 99999999
    resume_starts_over(stopped, reference, "RUN.checkpoint.h5", "damaged")


def test_a_partial_chunk_failing_its_checksum_says_so(stopped, reference):
    with h5py.File(stopped / "RUN.partial.h5", "r") as f:
        chunk = f["global/T"].id.get_chunk_info(0)
    with open(stopped / "RUN.partial.h5", "r+b") as raw:
        raw.seek(chunk.byte_offset + 800)
        byte = raw.read(1)[0]
        raw.seek(chunk.byte_offset + 800)
        raw.write(bytes([byte ^ 0xFF]))
    resume_starts_over(stopped, reference, "/global/T", "Fletcher32 checksum")
