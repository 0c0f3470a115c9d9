"""Out-of-range and malformed values in a run configuration (issue 21 item 6): `check` and `run` alike
exit 2 naming the key and the allowed range, leave no file behind and never echo a huge value back.

Self-contained: the solver is $SLIDEWAVE_BIN or <repo>/build/slidewave (missing: a failure, not a skip).
"""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SOLVER = Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))

CASES = {
    # b773bb5: accepted, wrapped to -9223372036854775808
    "seed_1e19": ('{"perturbation": {"seed": 1e19}}', ["perturbation.seed", "9007199254740991"]),
    "seed_2e64": ('{"perturbation": {"seed": 18446744073709551615}}', ["perturbation.seed", "9007199254740991"]),
    # b773bb5: uncaught nlohmann out_of_range, exit 134
    "f_1e999": ('{"friction": {"f": 1e999}}', ["friction.f", "1e999", "finite"]),
    "snapshot_1e999": ('{"output": {"snapshot_times": [0, -1e999]}}', ["output.snapshot_times[1]", "-1e999"]),
    # b773bb5: the second "mesh" group replaced the first, exit 0
    "duplicate_group": ('{"mesh": {"elements_per_H": 4}, "mesh": {"integration": "full"}}', ["mesh", "twice"]),
    "duplicate_key": ('{"time": {"t_end": 60, "t_end": 70}}', ["time.t_end", "twice"]),
}


@pytest.fixture(scope="module")
def solver():
    assert SOLVER.is_file() and os.access(SOLVER, os.X_OK), \
        f"no solver binary at {SOLVER}: build it (scripts/build.sh) or set SLIDEWAVE_BIN"
    return str(SOLVER)


def invoke(solver, folder, command, config_path):
    args = [solver, command, str(config_path)] + (["-o", str(folder / "run.h5")] if command == "run" else [])
    return subprocess.run(args, capture_output=True, text=True, timeout=300, cwd=folder)


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_value_exits_2_naming_the_key(solver, tmp_path, command, case):
    text, expected = CASES[case]
    config = tmp_path / "config.json"
    config.write_text(text)
    result = invoke(solver, tmp_path, command, config)
    assert result.returncode == 2, (result.returncode, result.stderr)
    for word in expected:
        assert word in result.stderr, result.stderr
    assert {p.name for p in tmp_path.iterdir()} == {"config.json"}, "nothing written"


def test_seed_at_the_limit_is_accepted(solver, tmp_path):
    config = tmp_path / "config.json"
    config.write_text('{"perturbation": {"seed": 9007199254740991}}')
    result = invoke(solver, tmp_path, "check", config)
    assert result.returncode == 0, result.stderr
    assert '"seed": 9007199254740991' in result.stdout


@pytest.mark.parametrize("command", ["check", "run"])
def test_a_huge_value_is_not_echoed(solver, tmp_path, command):
    config = tmp_path / "config.json"
    huge = "x" * 100_000_000
    config.write_text('{"mesh": {"integration": "' + huge + '"}, "' + huge + '": 1}')
    result = invoke(solver, tmp_path, command, config)
    assert result.returncode == 2, result.stderr[:300]
    assert "mesh.integration" in result.stderr and "unknown group" in result.stderr, result.stderr[:300]
    assert len(result.stderr) < 1000, f"{len(result.stderr)} characters on stderr"
