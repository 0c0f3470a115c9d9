"""The measure and flutter-boundary commands."""

import json
import subprocess
import sys
import types
from pathlib import Path

import pytest

from analysis import cli
from synthetic_run import Scenario, paper_case

ROOT = Path(__file__).resolve().parents[2]


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "analysis", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)


def test_measure_command(run_file, tmp_path):
    out = tmp_path / "out" / "metrics.json"
    result = run_cli("measure", run_file(paper_case()), "-o", out, "--threshold", "20")
    assert result.returncode == 0, result.stderr
    assert "celerity +0.88" in result.stdout and "intersonic_opening_inversion" in result.stdout
    metrics = json.loads(out.read_text())
    assert metrics["threshold_rel"] == 20.0
    assert metrics["celerity"] == pytest.approx(0.882, rel=5e-3)
    assert [p.name for p in out.parent.iterdir()] == ["metrics.json"]  # no temporary left


def test_measure_rejects_an_old_file_and_writes_nothing(run_file, tmp_path):
    out = tmp_path / "metrics.json"
    result = run_cli("measure", run_file(Scenario(format_version=0)), "-o", out)
    assert result.returncode == 2
    assert "format_version 0 is not supported" in result.stderr and "Traceback" not in result.stderr
    assert not out.exists()


def test_measure_rejects_bad_settings(run_file, tmp_path, capsys):
    out = tmp_path / "metrics.json"
    assert cli.main(["measure", str(run_file(paper_case())), "-o", str(out), "--window", "-5"]) == 2
    assert "window_length = -5.0 must be > 0" in capsys.readouterr().err
    assert not out.exists()


def test_flutter_boundary_command_calls_analysis_flutter(monkeypatch, capsys):
    calls = []

    def boundary(nu):
        calls.append(nu)
        return (1.0, float("inf")) if nu < 0.25 else (float("nan"), float("nan"))

    monkeypatch.setitem(sys.modules, "analysis.theory.flutter", types.SimpleNamespace(flutter_boundary=boundary))
    assert cli.main(["flutter-boundary", "--nu", "0", "0.1", "0.4"]) == 0
    assert capsys.readouterr().out.splitlines() == ["0 1 inf", "0.1 1 inf", "0.4 nan nan"]
    assert calls == [0.0, 0.1, 0.4]
    assert cli.main(["flutter-boundary", "--nu", "0.5"]) == 2
    assert "outside [0, 0.5)" in capsys.readouterr().err


def test_flutter_boundary_command_with_the_real_module():
    flutter = pytest.importorskip("analysis.theory.flutter")
    if not hasattr(flutter, "flutter_boundary"):
        pytest.skip("analysis.theory.flutter has no flutter_boundary yet")
    result = run_cli("flutter-boundary", "--nu", "0", "0.3")
    assert result.returncode == 0, result.stderr
    lines = [line.split() for line in result.stdout.splitlines()]
    assert [line[0] for line in lines] == ["0", "0.3"] and all(len(line) == 3 for line in lines)
    for line in lines:
        for token in line[1:]:
            float(token)  # numbers, inf or nan


def test_measure_refuses_an_interrupted_run_unless_asked(run_file, tmp_path):
    run = run_file(paper_case(complete=0, end_reason="interrupted"))
    out = tmp_path / "metrics.json"
    result = run_cli("measure", run, "-o", out)
    assert result.returncode == 2 and not out.exists()
    assert f"{run}: the run was interrupted" in result.stderr and "--allow-incomplete" in result.stderr
    result = run_cli("measure", run, "-o", out, "--allow-incomplete")
    assert result.returncode == 0, result.stderr
    assert "INCOMPLETE (interrupted)" in result.stdout
    metrics = json.loads(out.read_text())
    assert metrics["complete"] is False and metrics["end_reason"] == "interrupted"


def test_measure_refuses_to_write_over_its_input(run_file, tmp_path):
    run = run_file(paper_case())
    before = run.read_bytes()
    link = tmp_path / "link.h5"
    link.symlink_to(run)
    hard = tmp_path / "hard.h5"
    hard.hardlink_to(run)
    for output in (run, link, hard, tmp_path / "." / run.name):
        assert cli.main(["measure", str(run), "-o", str(output)]) == 2
    assert run.read_bytes() == before


def test_bimaterial_command_prints_the_regime_of_the_theory(capsys):
    from analysis.theory.bimaterial_stability import bimaterial_regime, instability_threshold
    from analysis.theory.interface_wave import ElasticSolid

    assert cli.main(["bimaterial", "--E-ratio", "3", "--nu", "0.2", "--nu-substrate", "0.2",
                     "--f", "0.5", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "c_gR none" in lines and "f 0.5 stable" in lines
    regime = bimaterial_regime(1000.0, 0.2, 1000.0, 3000.0, 0.2, 1000.0, 1.0)
    (line,) = [line for line in lines if line.startswith("f 1 ")]
    words = line.split()
    assert words[2] == "unstable" and words[8] == regime["direction"] and words[10] == regime["family"]
    assert float(words[4]) == pytest.approx(regime["growth_rate_per_k_over_cs1"], abs=1e-6)
    assert float(words[6]) == pytest.approx(regime["phase_speed_over_cs1"], abs=1e-6)
    # a pair with a generalized Rayleigh wave: unstable from f = 0 on (forward), backward above a threshold
    assert cli.main(["bimaterial", "--E-ratio", "1.5", "--nu", "0.2", "--f", "0.5", "--threshold"]) == 0
    lines = capsys.readouterr().out.splitlines()
    pair = ElasticSolid(1000.0, 0.2, 1000.0), ElasticSolid(1500.0, 0.2, 1000.0)
    onsets = [instability_threshold(*pair, family=family) for family in (None, "forward", "backward")]
    assert onsets[0] == onsets[1] == 0.0 and onsets[2] > 0.5
    assert lines[-1] == "f_threshold {:.6g} forward {:.6g} backward {:.6g}".format(*onsets)
    assert lines[2] == "c_gR 0.983791"
    # identical materials: the Rayleigh wave, stable
    assert cli.main(["bimaterial", "--E-ratio", "1", "--nu", "0.25", "--f", "2"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "c_gR 0.919402" in lines and "f 2 stable" in lines


@pytest.mark.parametrize("args, message", [(["--E-ratio", "0", "--nu", "0.2", "--f", "1"], "--E-ratio 0.0 outside"),
                                           (["--E-ratio", "2", "--nu", "0.5", "--f", "1"], "--nu 0.5 outside"),
                                           (["--E-ratio", "2", "--nu", "0.2", "--nu-substrate", "-0.1",
                                             "--f", "1"], "--nu-substrate -0.1 outside"),
                                           (["--E-ratio", "2", "--nu", "0.2", "--f", "-1"], "--f -1.0 outside")])
def test_bimaterial_command_rejects_bad_input(args, message, capsys):
    assert cli.main(["bimaterial", *args]) == 2
    assert message in capsys.readouterr().err
