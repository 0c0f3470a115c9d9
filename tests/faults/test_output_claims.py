"""What a run may write and remove (issue 21 items 1 and 4): one run per output (a second one is refused
with exit 2 naming the lock and the first run, which ends with its own, readable RUN.h5); the lock never
outlives its run (kill -9 included); a config file that the run would overwrite or remove under one of
its names is refused up front; and a run removes only files it created, never a user's file that merely
looks like a temporary.

On b773bb5 the second run truncated the first one's partial file, the config named RUN.checkpoint.h5
was deleted, and every "RUN.h5.tmp.*" file was removed by a glob.
"""

import json
import os
import subprocess
import time

import h5py
import pytest

from solver_runs import solver_or_skip

TINY = {"mesh": {"elements_per_H": 8}, "time": {"t_end": 60.0}, "output": {"progress": "never"}}
# A few seconds of stepping, so that a second run starts while the first one writes.
# (H/64 to 4000 s at dt c_s = 0.1: ~3.2 s on one core of the 2-vCPU test machine, and it completes; H/16 to
# 2500 s took 1.3 s once the slip phase stepped in wavenumbers, too close to the 1 s the tests wait before
# they act, and long runs at small dt may end with contact_not_converged, plain stepping too.)
SECONDS = {"mesh": {"elements_per_H": 64}, "time": {"t_end": 4000.0, "dt_times_cs": 0.1},
           "output": {"progress": "never"}}


def command(config, output, *extra):
    return [str(solver_or_skip()), "run", str(config), "-o", str(output), *extra]


def run(config, output, *extra, env=None):
    return subprocess.run(command(config, output, *extra), capture_output=True, text=True, timeout=600,
                          env={**os.environ, **(env or {})})


def write(folder, config, name="config.json"):
    path = folder / name
    path.write_text(json.dumps(config))
    return path


def readable_and_complete(path):
    with h5py.File(path, "r") as f:
        return int(f.attrs["complete"]) == 1 and f["global/t"].shape[0] == int(f.attrs["n_steps_done"]) + 1


# ---- item 1: two runs on one output ---------------------------------------------------------

def test_a_second_run_into_the_same_output_is_refused(tmp_path):
    config = write(tmp_path, SECONDS)
    first = subprocess.Popen(command(config, tmp_path / "run.h5"), stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not (tmp_path / "run.partial.h5").exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert first.poll() is None, "the first run ended before the second started: make SECONDS longer"
    second = run(config, tmp_path / "run.h5")
    _, first_stderr = first.communicate(timeout=600)
    assert second.returncode == 2, second.stderr
    assert "run.h5.lock" in second.stderr and f"pid {first.pid} " in second.stderr, second.stderr
    assert first.returncode == 0, first_stderr
    assert readable_and_complete(tmp_path / "run.h5")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["config.json", "run.h5", "run.interface.xdmf"]


def test_the_lock_of_a_killed_run_blocks_nothing_and_its_temporaries_go(tmp_path):
    config = write(tmp_path, TINY)
    killed = run(config, tmp_path / "run.h5", env={"SLIDEWAVE_TEST_SIGNAL_AT_STEP": "50", "SLIDEWAVE_TEST_SIGNAL": "KILL"})
    assert killed.returncode == -9, killed.stderr
    holder = (tmp_path / "run.h5.lock").read_text()
    killed_id = holder.split()[1]
    assert holder.startswith("run ") and len(killed_id) == 16, holder
    leftover = tmp_path / f"run.checkpoint.h5.tmp.{killed_id}"  # as if killed while writing a checkpoint
    leftover.write_bytes(b"half a checkpoint")
    users = ["run.h5.tmp.keepme", "run.partial.h5.tmp.1234", "run.xdmf.tmp", "run.checkpoint.h5.tmp.0123456789abcdef"]
    for name in users:
        (tmp_path / name).write_text("a user's file")

    result = run(config, tmp_path / "run.h5")
    assert result.returncode == 0, result.stderr
    assert readable_and_complete(tmp_path / "run.h5")
    assert not leftover.exists(), "the killed run's temporary, named with its run id, is removed"
    for name in users:
        assert (tmp_path / name).read_text() == "a user's file", name
    assert not (tmp_path / "run.h5.lock").exists(), "a run that ends removes its lock file"


# ---- item 4: inputs under the run's own names ------------------------------------------------

@pytest.mark.parametrize("name", ["run.checkpoint.h5", "run.h5.lock", "run.partial.interface.xdmf"])
@pytest.mark.parametrize("resume", [False, True], ids=["fresh", "resume"])
def test_a_config_under_a_name_the_run_writes_is_refused_and_kept(tmp_path, name, resume):
    config = write(tmp_path, TINY, name=name)
    before = config.read_bytes()
    result = run(config, tmp_path / "run.h5", *(["--resume"] if resume else []))
    assert result.returncode == 2, result.stderr
    assert name in result.stderr and "input file" in result.stderr, result.stderr
    assert config.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_user_files_named_like_temporaries_survive_runs_and_resumes(tmp_path):
    users = ["run.h5.tmp.keepme", "run.partial.h5.tmp.99", "run.checkpoint.h5.tmp.1", "run.xdmf.tmp",
             "run.interface.xdmf.tmp", "run.partial.xdmf.tmp"]
    for name in users:
        (tmp_path / name).write_text("a user's file")
    config = write(tmp_path, TINY)
    stopped = run(config, tmp_path / "run.h5", env={"SLIDEWAVE_TEST_SIGNAL_AT_STEP": "40"})
    assert stopped.returncode == 3, stopped.stderr
    resumed = run(config, tmp_path / "run.h5", "--resume")
    assert resumed.returncode == 0 and "resuming from step 40" in resumed.stderr, resumed.stderr
    again = run(config, tmp_path / "run.h5")
    assert again.returncode == 0, again.stderr
    for name in users:
        assert (tmp_path / name).read_text() == "a user's file", name
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        users + ["config.json", "run.h5", "run.interface.xdmf"])
