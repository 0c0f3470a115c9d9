"""`python3 -m analysis energy-evidence` and paper/make_energy_evidence.py: the energy-balance evidence
of the report, measured on three runs with the HHT dissipation booked (synthetic runs of
tests/figures/synthetic.py; the solver's side is tests/solver/hht_dissipation_test.cpp) into a JSON,
which the paper only formats. Every macro comes from the runs; a run without the decomposition, with
the wrong alpha or weighting, or of another case is refused naming the file."""
import json
import os
import re
import subprocess
import sys

import h5py
import pytest
from figure_support import PAPER, ROOT, command

import synthetic

sys.path.insert(0, str(PAPER))
from numbers_tex import ENERGY_MACRO_NAMES  # noqa: E402


def evidence(data, out, **replace):
    """`analysis energy-evidence` of the synthetic runs (some replaced) -> out (JSON)."""
    runs = {name: data / f"energy_{name}.h5" for name in synthetic.ENERGY_RUNS}
    runs.update(replace)
    args = [a for name, path in runs.items() for a in (f"--{name.replace('_', '-')}", path)]
    return subprocess.run([sys.executable, "-m", "analysis", "energy-evidence", *map(str, args), "-o", str(out)],
                          capture_output=True, text=True, cwd=ROOT, env=dict(os.environ, MPLBACKEND="Agg"))


def rendered(data, tmp_path):
    """energy_evidence.tex of the synthetic runs: measured, then formatted."""
    result = evidence(data, tmp_path / "e.json")
    assert result.returncode == 0, result.stderr
    result = command(PAPER / "make_energy_evidence.py", tmp_path / "e.json", "-o", tmp_path / "e.tex")
    assert result.returncode == 0, result.stderr
    return tmp_path / "e.tex"


def macros(path):
    return dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", path.read_text()))


def test_every_macro_from_the_runs(data, tmp_path):
    m = macros(rendered(data, tmp_path))
    assert list(m) == list(ENERGY_MACRO_NAMES)
    assert "notavailable" not in "".join(m.values())
    # The synthetic runs: energy that flowed = max W = 1.2 J/m; residual = -dissipation = 0.025 W.
    assert m["energyFlowedAlpha"] == r"\ensuremath{1.2}"
    assert m["energyResidualEndAlpha"] == m["energyDissipationEndAlpha"] == r"\ensuremath{0.025}"
    assert m["energyRatioAlpha"] == r"\ensuremath{1.000000}"
    assert m["energyTermGammaAlpha"] == r"\ensuremath{0.2}"
    assert m["energyResidualAlphaZero"].startswith(r"\ensuremath{8.3\times10^{-17}")  # 1e-16 / 1.2


@pytest.mark.parametrize("role,alpha,weighting,says", [
    ("alpha_zero", 0.1, "alpha", "time.hht_alpha = 0.1, expected 0"),
    ("alpha", 0.0, "alpha", "time.hht_alpha = 0, expected > 0"),
    ("alpha_end", 0.1, "alpha", "time.contact_weighting = alpha, expected end"),
])
def test_a_run_in_the_wrong_role_is_refused(data, tmp_path, role, alpha, weighting, says):
    synthetic.write_energy_run(tmp_path / "wrong.h5", alpha, weighting)
    result = evidence(data, tmp_path / "e.json", **{role: tmp_path / "wrong.h5"})
    assert result.returncode == 2 and says in result.stderr and "wrong.h5" in result.stderr, result.stderr
    assert not (tmp_path / "e.json").exists()


def test_a_run_without_the_decomposition_is_refused(data, tmp_path):
    synthetic.write_energy_run(tmp_path / "plain.h5", 0.1, "alpha", decomposition=False)
    result = evidence(data, tmp_path / "e.json", alpha=tmp_path / "plain.h5")
    assert result.returncode == 2
    assert "plain.h5: no /global/dissipation_hht" in result.stderr
    assert "output.energy_decomposition = hht" in result.stderr


def test_runs_of_another_case_are_refused(data, tmp_path):
    synthetic.write_energy_run(tmp_path / "other.h5", 0.1, "end")
    with h5py.File(tmp_path / "other.h5", "a") as file:
        file.attrs["config"] = file.attrs["config"].replace('"t_end": 1200.0', '"t_end": 900.0')
    result = evidence(data, tmp_path / "e.json", alpha_end=tmp_path / "other.h5")
    assert result.returncode == 2 and "another case" in result.stderr, result.stderr


def test_the_json_keeps_the_case_and_the_inputs(data, tmp_path):
    assert evidence(data, tmp_path / "e.json").returncode == 0
    document = json.loads((tmp_path / "e.json").read_text())
    assert set(document["runs"]) == set(synthetic.ENERGY_RUNS) == set(document["inputs"])
    assert document["runs"]["alpha"]["flowed"] == pytest.approx(1.2, rel=1e-3)  # max W of the synthetic runs
    assert document["case"]["hht_alpha"] > 0


def test_a_json_without_a_number_is_refused_naming_it(data, tmp_path):
    assert evidence(data, tmp_path / "e.json").returncode == 0
    document = json.loads((tmp_path / "e.json").read_text())
    del document["runs"]["alpha"]["ratio"]
    (tmp_path / "e.json").write_text(json.dumps(document))
    result = command(PAPER / "make_energy_evidence.py", tmp_path / "e.json", "-o", tmp_path / "e.tex")
    assert result.returncode == 2 and "e.json" in result.stderr and "ratio" in result.stderr, result.stderr
    assert not (tmp_path / "e.tex").exists()
