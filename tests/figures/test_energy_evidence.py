"""paper/make_energy_evidence.py: the energy-balance evidence of the report from three runs with the
HHT dissipation booked (synthetic runs of tests/figures/synthetic.py; the solver's side is
tests/solver/hht_dissipation_test.cpp). Every macro is written from the runs; a run without the
decomposition, with the wrong alpha or weighting, or of another case is refused naming the file."""
import re
import sys

import h5py
import pytest
from figure_support import PAPER, command

import synthetic

sys.path.insert(0, str(PAPER))
from numbers_tex import ENERGY_MACRO_NAMES  # noqa: E402


def evidence(data, out, **replace):
    runs = {name: data / f"energy_{name}.h5" for name in synthetic.ENERGY_RUNS}
    runs.update(replace)
    args = [a for name, path in runs.items() for a in (f"--{name.replace('_', '-')}", path)]
    return command(PAPER / "make_energy_evidence.py", *args, "-o", out)


def macros(path):
    return dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", path.read_text()))


def test_every_macro_from_the_runs(data, tmp_path):
    result = evidence(data, tmp_path / "e.tex")
    assert result.returncode == 0, result.stderr
    m = macros(tmp_path / "e.tex")
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
    result = evidence(data, tmp_path / "e.tex", **{role: tmp_path / "wrong.h5"})
    assert result.returncode == 2 and says in result.stderr and "wrong.h5" in result.stderr, result.stderr
    assert not (tmp_path / "e.tex").exists()


def test_a_run_without_the_decomposition_is_refused(data, tmp_path):
    synthetic.write_energy_run(tmp_path / "plain.h5", 0.1, "alpha", decomposition=False)
    result = evidence(data, tmp_path / "e.tex", alpha=tmp_path / "plain.h5")
    assert result.returncode == 2
    assert "plain.h5: no /global/dissipation_hht" in result.stderr
    assert "output.energy_decomposition = hht" in result.stderr


def test_runs_of_another_case_are_refused(data, tmp_path):
    synthetic.write_energy_run(tmp_path / "other.h5", 0.1, "end")
    with h5py.File(tmp_path / "other.h5", "a") as file:
        file.attrs["config"] = file.attrs["config"].replace('"t_end": 1200.0', '"t_end": 900.0')
    result = evidence(data, tmp_path / "e.tex", alpha_end=tmp_path / "other.h5")
    assert result.returncode == 2 and "another case" in result.stderr, result.stderr
