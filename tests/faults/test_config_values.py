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

SUBSTRATE = '{"substrate": {"E": %r, "nu": %r, "rho": %r, "H": %r}}'

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
    # issue 24 item 8: the substrate group (all four keys or none; a whole number of elements)
    "substrate_E_zero": (SUBSTRATE % (0, 0.2, 1000, 25), ["substrate.E", "E > 0"]),
    "substrate_E_negative": (SUBSTRATE % (-1e3, 0.2, 1000, 25), ["substrate.E", "E > 0"]),
    "substrate_nu_half": (SUBSTRATE % (1e3, 0.5, 1000, 25), ["substrate.nu", "0 <= nu < 0.5"]),
    "substrate_nu_negative": (SUBSTRATE % (1e3, -0.1, 1000, 25), ["substrate.nu", "0 <= nu < 0.5"]),
    "substrate_rho_zero": (SUBSTRATE % (1e3, 0.2, 0, 25), ["substrate.rho", "rho > 0"]),
    "substrate_H_zero": (SUBSTRATE % (1e3, 0.2, 1000, 0), ["substrate.H", "H > 0"]),
    "substrate_H_fraction": (SUBSTRATE % (1e3, 0.2, 1000, 10.1), ["substrate.H", "whole number of elements"]),
    "substrate_H_one_element": (SUBSTRATE % (1e3, 0.2, 1000, 25.0 / 32), ["substrate.H", "[2, 65536]"]),
    "substrate_E_alone": ('{"substrate": {"E": 1000}}', ["substrate.nu", "substrate.rho", "substrate.H",
                                                        "together"]),
    "substrate_unknown_key": ('{"substrate": {"E": 1000, "nu": 0.2, "rho": 1000, "H": 25, "G": 1}}',
                              ["substrate.G", "unknown key"]),
    # issue 24 item 5: the single-mode seed of the checks against interface-wave theory
    "mode_seed_amplitude_zero": ('{"mode_seed": {"amplitude_over_H": 0}}',
                                 ["mode_seed.amplitude_over_H", "0 < amplitude_over_H <= 0.01"]),
    "mode_seed_amplitude_large": ('{"mode_seed": {"amplitude_over_H": 0.5}}',
                                  ["mode_seed.amplitude_over_H", "0 < amplitude_over_H <= 0.01"]),
    "mode_seed_mode_zero": ('{"mode_seed": {"amplitude_over_H": 1e-6, "mode": 0}}',
                            ["mode_seed.mode", "[1, 65536]"]),
    # 64 elements a period at the default H/32, lambda 2H: at most 16 wavelengths of four elements
    "mode_seed_mode_too_short": ('{"mode_seed": {"amplitude_over_H": 1e-6, "mode": 17}}',
                                 ["mode_seed.mode", "[1, 16]", "four elements"]),
    "mode_seed_mode_alone": ('{"mode_seed": {"mode": 2}}', ["mode_seed.amplitude_over_H", "missing"]),
    "mode_seed_start_alone": ('{"mode_seed": {"start": "sliding"}}', ["mode_seed.amplitude_over_H", "missing"]),
    "mode_seed_start_bad": ('{"mode_seed": {"amplitude_over_H": 1e-6, "start": "moving"}}',
                            ["mode_seed.start", "rest|sliding"]),
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


def test_a_whole_substrate_is_accepted_and_resolved(solver, tmp_path):
    config = tmp_path / "config.json"
    config.write_text(SUBSTRATE % (3000.0, 0.3, 2000.0, 12.5))
    result = invoke(solver, tmp_path, "check", config)
    assert result.returncode == 0, result.stderr
    assert '"substrate"' in result.stdout and '"E": 3000.0' in result.stdout


def test_no_substrate_leaves_the_resolved_config_without_the_group(solver, tmp_path):
    config = tmp_path / "config.json"
    config.write_text("{}")
    result = invoke(solver, tmp_path, "check", config)
    assert result.returncode == 0, result.stderr
    assert '"substrate"' not in result.stdout
