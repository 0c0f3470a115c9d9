"""Golden regression (tests/golden/README.md): every config of tests/golden/configs run with the built
solver gives the digests of tests/golden/digests.json, dataset by dataset; so does the paper case run
with --threads 2 and run interrupted by SIGTERM then resumed with --resume. A mismatch lists the
datasets that differ and how far they moved. Re-bless with scripts/bless_golden.sh.

Runs the solver binary (build/slidewave, or $SLIDEWAVE_BIN) in temporary folders, ~10 s in all."""

import re
import signal
import subprocess
import time

import h5py
import pytest

import golden
from solver_runs import solver_or_skip

BLESSED = golden.load()["runs"]
RESUMED = "paper_snapshots"  # the config run with --threads 2 and interrupted/resumed
wall_times = {}  # config name -> seconds of its uninterrupted run, to place the interruption


def assert_golden(name, run_file, how=""):
    lines = golden.report(name, BLESSED.get(name), run_file)
    if lines:
        pytest.fail(f"{name}{how} differs from tests/golden/digests.json ({len(lines)} entries):\n" + "\n".join(lines)
                    + "\nIf the change is intended: scripts/bless_golden.sh, and say why in the commit.",
                    pytrace=False)


def test_every_config_has_digests():
    assert golden.config_names() == sorted(BLESSED), "configs/*.json and digests.json disagree: re-bless"


def test_the_digest_skips_only_the_listed_attributes(tmp_path):
    """Two files that differ only in the excluded provenance give the same digests; a one-bit change of
    a dataset or of a result attribute does not."""
    path = tmp_path / "a.h5"
    with h5py.File(path, "w") as f:
        f.attrs["created_utc"] = "2026-01-01T00:00:00Z"
        f.attrs["config"] = '{"numerics": {"threads": 1, "linear_solver": "spectral"}}'
        f.attrs["end_reason"] = "t_end"
        f.create_dataset("global/T", data=[1.0, 2.0]).attrs["unit"] = "N/m"
    before = golden.digest(path)
    with h5py.File(path, "r+") as f:
        f.attrs["created_utc"] = "2027-01-01T00:00:00Z"
        f.attrs["config"] = '{"numerics": {"threads": 2, "linear_solver": "spectral"}}'
        f["global/T"].attrs["unit"] = "kN/m"
    assert golden.digest(path) == before
    with h5py.File(path, "r+") as f:
        f["global/T"][1] = 2.0000000000000004
    lines = golden.compare(before, golden.digest(path))
    assert len(lines) == 1 and lines[0].startswith("  /global/T: values differ"), lines
    with h5py.File(path, "r+") as f:
        f.attrs["end_reason"] = "stop_after_opening"
    assert "/@end_reason" in "".join(golden.compare(before, golden.digest(path)))


@pytest.mark.parametrize("name", golden.config_names())
def test_run_matches_its_digests(name, tmp_path):
    solver_or_skip()
    start = time.monotonic()
    run_file = golden.run_config(name, tmp_path)
    wall_times[name] = time.monotonic() - start
    assert_golden(name, run_file)


def test_two_threads_give_the_same_bits(tmp_path):
    solver_or_skip()
    assert_golden(RESUMED, golden.run_config(RESUMED, tmp_path, "--threads", "2"), " with --threads 2")


def interrupt(folder, delay):
    """Starts the run, sends SIGTERM `delay` s after RUN.partial.h5 appears; returns (exit code, stderr)."""
    output = folder / f"{RESUMED}.h5"
    partial = folder / f"{RESUMED}.partial.h5"
    process = subprocess.Popen([str(golden.solver()), "run", str(golden.CONFIGS / f"{RESUMED}.json"), "-o",
                                str(output)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=golden.solver_environment())
    while not partial.exists() and process.poll() is None:
        time.sleep(0.001)
    time.sleep(delay)
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate(timeout=300)
    return process.returncode, stderr


def test_interrupted_and_resumed_run_gives_the_golden_digests(tmp_path):
    """SIGTERM once the partial file exists (no deterministic trigger: the delay is a fraction of the
    uninterrupted run, shorter on each try), then --resume: the same digests as the golden run."""
    solver_or_skip()
    elapsed = wall_times.get(RESUMED, 0.5)
    for fraction in (0.4, 0.2, 0.05, 0.0):
        for stale in tmp_path.iterdir():
            stale.unlink()
        code, stderr = interrupt(tmp_path, fraction * elapsed)
        if code == 3:
            break
        assert code == 0, stderr
    else:
        pytest.skip("every run finished before the signal")
    assert "interrupted" in stderr, stderr
    assert (tmp_path / f"{RESUMED}.checkpoint.h5").exists()
    step = re.search(r"at step (\d+)", stderr)
    resumed = golden.run_config(RESUMED, tmp_path, "--resume")
    assert_golden(RESUMED, resumed, f" (interrupted at step {step.group(1) if step else '?'}, resumed)")
