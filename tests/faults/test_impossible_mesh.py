"""Meshes too large for the machine, and signals during the setup (issue 21 item 7): `check` and `run`
print a memory estimate; `run` refuses a mesh whose estimate exceeds the available memory (exit 2,
estimate and available memory in the message, no file); SIGTERM during the setup of a large mesh ends
the run at once (exit 3) with no file left.

Every run here is started under an address-space limit (RLIMIT_AS), so that the available memory is the
same on every machine and a solver that does not refuse (b773bb5) fails fast instead of filling the
machine. On b773bb5 there was no estimate, H/1024 at lambda 6H grew past 5 GB before failing, SIGTERM in
the setup was acted on only after it, and a kill there left an unreadable 96-byte partial file.
"""

import json
import resource
import subprocess
import time

import pytest

from solver_runs import solver_or_skip

GIB = 1024 ** 3


def limited(gib):
    """preexec_fn: at most `gib` GiB of address space for the solver."""
    return lambda: resource.setrlimit(resource.RLIMIT_AS, (gib * GIB, gib * GIB))


def write(folder, config):
    path = folder / "config.json"
    path.write_text(json.dumps(config))
    return path


@pytest.mark.parametrize("mesh,geometry", [({"elements_per_H": 1024}, {"lambda_over_H": 6}),
                                           ({"elements_per_H": 4096}, {"lambda_over_H": 50})],
                         ids=["H1024_lambda6", "H4096_lambda50"])
def test_a_mesh_that_cannot_fit_is_refused(tmp_path, mesh, geometry):
    config = write(tmp_path, {"mesh": mesh, "geometry": geometry})
    result = subprocess.run([str(solver_or_skip()), "run", str(config), "-o", str(tmp_path / "run.h5")],
                            capture_output=True, text=True, timeout=120, preexec_fn=limited(4))
    assert result.returncode == 2, result.stderr[-2000:]
    assert "needs about" in result.stderr and "GiB" in result.stderr and "available" in result.stderr, result.stderr
    assert "address-space limit" in result.stderr, result.stderr
    assert "mesh.elements_per_H" in result.stderr, result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["config.json"], "nothing written"


def test_check_prints_the_estimate(tmp_path):
    config = write(tmp_path, {"mesh": {"elements_per_H": 1024}, "geometry": {"lambda_over_H": 6}})
    result = subprocess.run([str(solver_or_skip()), "check", str(config)], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["mesh"]["elements_per_H"] == 1024, "stdout stays the resolved config"
    assert "memory estimate" in result.stderr and "Delassus" in result.stderr, result.stderr


def start_a_long_setup(tmp_path):
    """A run of H/256 at lambda 6H (about 1.1 GiB and several seconds of setup: the dense LDLT of a
    3072 x 3072 W), one second into its setup."""
    config = write(tmp_path, {"mesh": {"elements_per_H": 256}, "geometry": {"lambda_over_H": 6},
                              "time": {"t_end": 5.0}, "output": {"progress": "never"}})
    process = subprocess.Popen([str(solver_or_skip()), "run", str(config), "-o", str(tmp_path / "run.h5")],
                               stderr=subprocess.PIPE, text=True, preexec_fn=limited(6))
    time.sleep(1.0)
    assert process.poll() is None, "the run ended within a second"
    return process


def test_sigterm_during_the_setup_ends_the_run_at_once(tmp_path):
    process = start_a_long_setup(tmp_path)
    assert not (tmp_path / "run.partial.h5").exists(), "the setup took under a second: use a larger mesh"
    sent = time.monotonic()
    process.terminate()
    _, stderr = process.communicate(timeout=120)
    latency = time.monotonic() - sent
    print(f"SIGTERM during the setup: exit after {latency:.3f} s")
    assert process.returncode == 3, stderr
    assert "interrupted during the setup" in stderr, stderr
    assert latency < 10, f"{latency:.1f} s"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["config.json"], "no file, not even the lock"


def test_sigkill_during_the_setup_leaves_no_partial_file(tmp_path):
    process = start_a_long_setup(tmp_path)
    process.kill()
    process.communicate(timeout=120)
    # The lock file stays after kill -9 (unlocked; it names the killed run), nothing else.
    assert sorted(p.name for p in tmp_path.iterdir()) in (["config.json"], ["config.json", "run.h5.lock"])
