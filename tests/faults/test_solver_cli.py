"""Faults at the solver's command line (issue 11 items 1-4, 6, 7): exit codes, output paths,
absurd step counts, progress into a closed pipe, the recorded config bytes, interruption.

Self-contained (no conftest): the solver is $SLIDEWAVE_BIN or <repo>/build/slidewave; a missing binary
is a failure, not a skip. Each test asserts the exit code, what is (not) left on disk and that the
message names the cause. Run as root, permission bits do not stop writes, so the unwritable-folder
cases use a read-only or special filesystem (/sys) and a file posing as a folder.
"""

import json
import os
import signal
import subprocess
import time
from pathlib import Path

import h5py
import pytest

REPO = Path(__file__).resolve().parents[2]
SOLVER = Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))

# A run of a few hundredths of a second, and one of a few seconds (for faults injected mid-run: the
# solver reports progress once per wall-clock second).
TINY = {"mesh": {"elements_per_H": 4}, "time": {"t_end": 60.0}, "output": {"progress": "never"}}
# (H/64 to 4000 s at dt c_s = 0.1: ~3.2 s on one core of the 2-vCPU test machine, and it completes; H/16 to
# 2500 s took 1.3 s once the slip phase stepped in wavenumbers, too close to the 1 s the tests wait before
# they act, and long runs at small dt may end with contact_not_converged, plain stepping too.)
SECONDS = {"mesh": {"elements_per_H": 64}, "time": {"t_end": 4000.0, "dt_times_cs": 0.1},
           "output": {"progress": "never"}}


@pytest.fixture(scope="module")
def solver():
    assert SOLVER.is_file() and os.access(SOLVER, os.X_OK), \
        f"no solver binary at {SOLVER}: build it (scripts/build.sh) or set SLIDEWAVE_BIN"
    return str(SOLVER)


def write_config(folder: Path, config: dict, name: str = "config.json") -> Path:
    path = folder / name
    path.write_text(json.dumps(config))
    return path


def run(solver, *args, **kwargs):
    return subprocess.run([solver, *map(str, args)], capture_output=True, text=True, timeout=600, **kwargs)


def files_in(folder: Path) -> set:
    return {p.name for p in folder.iterdir()}


def text(value) -> str:
    """An HDF5 string attribute (h5py gives fixed-length strings as bytes)."""
    return value.decode() if isinstance(value, bytes) else str(value)


def root_attributes(path: Path) -> dict:
    with h5py.File(path, "r") as f:
        return {"complete": int(f.attrs["complete"]), "end_reason": text(f.attrs["end_reason"])}


# ---- exit codes ------------------------------------------------------------------------------

def test_complete_run_exits_0_with_a_complete_file(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    result = run(solver, "run", config, "-o", tmp_path / "run.h5")
    assert result.returncode == 0, result.stderr
    assert int(root_attributes(tmp_path / "run.h5")["complete"]) == 1


@pytest.mark.parametrize("args", [["run"], ["run", "CONFIG"], ["bogus"], ["run", "CONFIG", "-o", "x.h5", "--threads"],
                                  ["keys", "--json", "--markdown"], []])
def test_usage_errors_exit_2(solver, tmp_path, args):
    config = write_config(tmp_path, TINY)
    result = run(solver, *[config if a == "CONFIG" else a for a in args], cwd=tmp_path)
    assert result.returncode == 2, (args, result.stderr)
    assert files_in(tmp_path) == {"config.json"}


def test_version_and_help_exit_0(solver):
    assert run(solver, "--version").returncode == 0
    assert run(solver, "--help").returncode == 0


def test_threads_override_is_validated_and_recorded(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    bad = run(solver, "run", config, "-o", tmp_path / "run.h5", "--threads", "0")
    assert bad.returncode == 2 and "numerics.threads" in bad.stderr, bad.stderr
    assert files_in(tmp_path) == {"config.json"}
    good = run(solver, "run", config, "-o", tmp_path / "run.h5", "--threads", "2")
    assert good.returncode == 0, good.stderr
    with h5py.File(tmp_path / "run.h5", "r") as f:
        resolved = json.loads(text(f.attrs["config"]))
    assert resolved["numerics"]["threads"] == 2
    assert resolved["numerics"]["linear_solver"] == "spectral"


def test_write_error_exits_4_naming_the_file_and_leaves_nothing(solver, tmp_path):
    """A full disk, simulated with a file-size limit (writes fail with EFBIG once SIGXFSZ is ignored)."""
    import resource

    def limit_file_size():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (20000, 20000))

    config = write_config(tmp_path, TINY)
    result = subprocess.run([solver, "run", str(config), "-o", str(tmp_path / "run.h5")], capture_output=True,
                            text=True, timeout=600, preexec_fn=limit_file_size)
    assert result.returncode == 4, result.stderr
    assert "run.partial.h5" in result.stderr and "File too large" in result.stderr, result.stderr
    assert files_in(tmp_path) == {"config.json"}


# ---- item 3: step counts that would overflow or never end ------------------------------------

OVERFLOW = {
    "t_end_1e12": {"time": {"t_end": 1e12}},
    "rho_1e-300": {"material": {"rho": 1e-300}},
    "dt_times_cs_1e-7_H16": {"mesh": {"elements_per_H": 16}, "time": {"t_end": 1500.0, "dt_times_cs": 1e-7}},
    # the study's V0_over_cs = 1e-12 point: t_end = its onset estimate (5e9 m / c_s) + 60 transits
    "V0_over_cs_1e-12": {"loading": {"V0_over_cs": 1e-12}, "time": {"t_end": 7.75e9}},
}


@pytest.mark.parametrize("name", sorted(OVERFLOW))
def test_overflowing_step_count_exits_2_naming_the_count(solver, tmp_path, name):
    config = write_config(tmp_path, OVERFLOW[name])
    result = run(solver, "run", config, "-o", tmp_path / "run.h5")
    assert result.returncode == 2, result.stderr
    assert "time.max_steps = 20000000" in result.stderr and " steps, over " in result.stderr, result.stderr
    assert files_in(tmp_path) == {"config.json"}
    assert run(solver, "check", config).returncode == 2


# ---- item 4: output paths --------------------------------------------------------------------

def test_output_onto_the_config_exits_2_and_keeps_the_config(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    before = config.read_bytes()
    result = run(solver, "run", config, "-o", config)
    assert result.returncode == 2
    assert "input file" in result.stderr, result.stderr
    assert config.read_bytes() == before
    assert files_in(tmp_path) == {"config.json"}


@pytest.mark.parametrize("config_name", ["run.xdmf", "run.interface.xdmf", "run.partial.h5"])
def test_output_whose_sidecar_or_partial_file_is_the_config_exits_2(solver, tmp_path, config_name):
    config = write_config(tmp_path, TINY, name=config_name)
    before = config.read_bytes()
    result = run(solver, "run", config, "-o", tmp_path / "run.h5")
    assert result.returncode == 2
    assert "input file" in result.stderr, result.stderr
    assert config.read_bytes() == before and files_in(tmp_path) == {config_name}


@pytest.mark.parametrize("name", ["run.xdmf", "RUN.XDMF", "run.interface.xdmf"])
def test_output_named_like_the_xdmf_sidecar_exits_2(solver, tmp_path, name):
    config = write_config(tmp_path, {**TINY, "output": {"progress": "never", "snapshot_times": [0.0]}})
    result = run(solver, "run", config, "-o", tmp_path / name)
    assert result.returncode == 2
    assert "XDMF" in result.stderr, result.stderr
    assert files_in(tmp_path) == {"config.json"}


def test_missing_output_folder_exits_2_with_the_reason(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    result = run(solver, "run", config, "-o", tmp_path / "missing" / "run.h5")
    assert result.returncode == 2
    assert "No such file or directory" in result.stderr and "missing" in result.stderr, result.stderr
    assert files_in(tmp_path) == {"config.json"}


def test_file_as_output_folder_exits_2_with_the_reason(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    before = config.read_bytes()
    result = run(solver, "run", config, "-o", config / "run.h5")
    assert result.returncode == 2
    assert "Not a directory" in result.stderr, result.stderr
    assert config.read_bytes() == before and files_in(tmp_path) == {"config.json"}


def test_output_folder_is_a_folder_exits_2(solver, tmp_path):
    config = write_config(tmp_path, TINY)
    (tmp_path / "out.h5").mkdir()
    result = run(solver, "run", config, "-o", tmp_path / "out.h5")
    assert result.returncode == 2 and "is a folder" in result.stderr, result.stderr


def unwritable_folder(tmp_path: Path) -> Path:
    """A folder this process cannot create files in: a mode-0500 folder for a normal user; as root
    (which ignores permission bits) /sys, a read-only or special filesystem."""
    if os.geteuid() != 0:
        folder = tmp_path / "read_only"
        folder.mkdir(mode=0o500)
        return folder
    folder = Path("/sys")
    probe = folder / f"slidewave_probe_{os.getpid()}"
    try:
        probe.open("x").close()
    except OSError:
        return folder
    probe.unlink()
    pytest.fail("running as root and /sys is writable: no unwritable folder to test with")


def test_unwritable_output_folder_exits_2_before_the_run(solver, tmp_path):
    config = write_config(tmp_path, SECONDS)
    folder = unwritable_folder(tmp_path)
    before = set(os.listdir(folder))
    started = time.monotonic()
    result = run(solver, "run", config, "-o", folder / "run.h5")
    assert result.returncode == 2
    assert "cannot create a file in folder" in result.stderr, result.stderr
    assert any(reason in result.stderr for reason in ("Permission denied", "Read-only file system")), result.stderr
    assert time.monotonic() - started < 1.0, "the path must be checked before the run, not after"
    assert set(os.listdir(folder)) == before


# ---- item 6: progress never kills the run ----------------------------------------------------

def test_progress_into_a_closed_pipe_does_not_stop_the_run(solver, tmp_path):
    config = write_config(tmp_path, {**SECONDS, "output": {"progress": "always"}})
    output = tmp_path / "run.h5"
    shell = f"'{solver}' run '{config}' -o '{output}' 2>&1 | head -c 10; exit ${{PIPESTATUS[0]}}"
    result = subprocess.run(["bash", "-c", shell], capture_output=True, text=True, timeout=600)
    assert len(result.stdout) == 10, result.stdout
    assert result.returncode == 0, "the solver's exit status through the closed pipe"
    attributes = root_attributes(output)
    assert int(attributes["complete"]) == 1 and attributes["end_reason"] == "t_end"
    with h5py.File(output, "r") as f:
        assert int(f.attrs["n_steps_done"]) > 100, "a run long enough to report progress after head exited"


# ---- item 7: the recorded config is the parsed one -------------------------------------------

def test_config_edited_during_the_run_is_recorded_as_parsed(solver, tmp_path):
    config = write_config(tmp_path, SECONDS)
    parsed = config.read_bytes()
    process = subprocess.Popen([solver, "run", str(config), "-o", str(tmp_path / "run.h5")],
                               stderr=subprocess.PIPE, text=True)
    time.sleep(0.5)
    assert process.poll() is None, "the run ended before the config was edited: make SECONDS longer"
    config.write_text(json.dumps({"material": {"nu": 0.3}}))
    _, stderr = process.communicate(timeout=600)
    assert process.returncode == 0, stderr
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert text(f["setup"].attrs["config_input"]).encode() == parsed
        assert json.loads(text(f.attrs["config"]))["material"]["nu"] == 0.2


# ---- item 1/2: an interrupted run never replaces or poses as RUN.h5 ---------------------------

@pytest.mark.parametrize("signal_number", [signal.SIGTERM, signal.SIGINT])
def test_interrupted_run_exits_3_and_leaves_the_complete_file_alone(solver, tmp_path, signal_number):
    tiny = write_config(tmp_path, TINY, name="tiny.json")
    output = tmp_path / "run.h5"
    assert run(solver, "run", tiny, "-o", output).returncode == 0
    complete_bytes = output.read_bytes()
    config = write_config(tmp_path, SECONDS)
    process = subprocess.Popen([solver, "run", str(config), "-o", str(output)], stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    assert process.poll() is None, "the run ended before the signal: make SECONDS longer"
    process.send_signal(signal_number)
    _, stderr = process.communicate(timeout=600)
    assert process.returncode == 3, stderr
    assert "interrupted" in stderr and "run.partial.h5" in stderr, stderr
    assert output.read_bytes() == complete_bytes, "the complete RUN.h5 was touched"
    attributes = root_attributes(tmp_path / "run.partial.h5")
    assert int(attributes["complete"]) == 0 and attributes["end_reason"] == "interrupted"
    assert files_in(tmp_path) == {"tiny.json", "config.json", "run.h5", "run.interface.xdmf", "run.partial.h5",
                                  "run.partial.interface.xdmf", "run.checkpoint.h5"}


@pytest.mark.parametrize("group, key, value, instead", [
    ("numerics", "linear_solver", "circulant", "spectral"),
    ("contact", "all_stick", "iterate", "exact all-stick solution"),
])
def test_retired_choice_exits_2_saying_what_the_solver_does_instead(solver, tmp_path, group, key, value, instead):
    """A config written for an older solver path is refused, not silently run on another path."""
    config = write_config(tmp_path, {**TINY, group: {key: value}})
    for command in (["check", config], ["run", config, "-o", tmp_path / "run.h5"]):
        result = run(solver, *command)
        assert result.returncode == 2, result.stderr
        assert f"{group}.{key}" in result.stderr and "retired" in result.stderr and instead in result.stderr
    assert files_in(tmp_path) == {"config.json"}


@pytest.mark.parametrize("changes, advised", [
    ({"time": {"dt_times_cs": 0.25}}, True),  # H/32: c_s dt / h = 0.32, where long runs created energy
    ({}, False),  # the default dt c_s = 0.5 m: 0.64
    ({"time": {"dt_times_cs": 0.25}, "friction": {"regularization": "prakash_clifton"}}, False),
    ({"time": {"dt_times_cs": 0.25}, "friction": {"f": 0.0}}, False),
    ({"time": {"dt_times_cs": 0.25}, "mesh": {"mass": "redistributed"}}, False),  # what cures it
])
def test_a_small_courant_number_is_advised_against_not_refused(solver, tmp_path, changes, advised):
    config = {"mesh": {"elements_per_H": 32}, "output": {"progress": "never"}}
    for group, values in changes.items():
        config.setdefault(group, {}).update(values)
    result = run(solver, "check", write_config(tmp_path, config))
    assert result.returncode == 0, result.stderr
    assert ("advice: the time step is small for the mesh (c_s dt / h = 0.32 < 0.5)" in result.stderr) == advised
    if advised:
        assert "time.dt_times_cs >= 0.391 m" in result.stderr and "prakash_clifton" in result.stderr
        assert "mesh.mass = \"redistributed\"" in result.stderr
