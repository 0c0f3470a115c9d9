"""The section "How sure is this table": the envelope figure, the phase diagram of an ensemble and
paper/make_how_sure.py, from tables that analysis.confidence.ensemble and analysis.confidence.envelope write for a small
made-up ensemble (three cells, three seeds, two method variants)."""
import json
import re

import pytest

from figure_support import PAPER, ROOT, assert_figure, call, command
from how_sure_inputs import write_csv, write_tables


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    folder = write_tables(tmp_path_factory.mktemp("how_sure"))
    # A finer ensemble: the same summary with two cells within and nu = 0.2, f = 1.5 at +4 %.
    finer = json.loads((folder / "ensemble_summary.json").read_text())
    finer["within_tol_mean"] = 2
    finer["groups"]["nu 0.1-0.2, f >= 1.5"]["deviation_mean_rel_mean"] = 0.04
    (folder / "finer_summary.json").write_text(json.dumps(finer))
    return folder


def test_envelope_figure(tables, tmp_path):
    assert call("envelope", tables / "envelope.csv", "--tolerance", 0.05, "--out", tmp_path / "env") == 0
    assert_figure(tmp_path / "env")


def test_envelope_figure_names_a_missing_column(tables, tmp_path):
    broken = write_csv(tmp_path / "broken.csv", [{"nu": 0.2, "f": 1.5}])
    result = command(ROOT / "figures" / "envelope.py", broken, "--tolerance", 0.05, "--out", tmp_path / "x")
    assert result.returncode != 0 and "status" in result.stderr and not (tmp_path / "x.png").exists()


def test_phase_diagram_of_an_ensemble(tables, tmp_path):
    assert call("phase_diagram", tables / "ensemble.csv", "--ensemble", "--flutter", tables / "flutter.txt",
                "--out", tmp_path / "pd") == 0
    assert_figure(tmp_path / "pd")


def test_phase_diagram_ensemble_needs_the_agreement_column(tables, tmp_path):
    result = command(ROOT / "figures" / "phase_diagram.py", tables / "all_metrics.csv", "--ensemble",
                     "--flutter", tables / "flutter.txt", "--out", tmp_path / "pd")
    assert result.returncode != 0 and "category_agreement" in result.stderr


def macros_of(path):
    return dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", path.read_text()))


def test_numbers_of_the_section(tables, tmp_path):
    out = tmp_path / "how_sure_numbers.tex"
    result = command(PAPER / "make_how_sure.py", "--ensemble", tables / "ensemble_summary.json",
                     "--envelope", tables / "envelope_summary.json", "--finer-ensemble",
                     tables / "finer_summary.json", "--finer-mesh", 128, "-o", out)
    assert result.returncode == 0, result.stderr
    macros = macros_of(out)
    assert macros["ensRuns"] == "9" and macros["ensCells"] == "3" and macros["ensSeedsRange"] == "3"
    # nu = 0.2, f = 1.5: mean 0.86 vs 0.882 -> -2.5 %, within; the others are not.
    assert macros["ensHighFMeanDev"] == "-2.5" and macros["ensWithinMean"] == "1"
    assert macros["envWithin"] == "1" and macros["envCells"] == "3"
    # The finer ensemble's numbers come from its own file, not the ensemble's.
    assert macros["ensFinerMesh"] == "128" and macros["ensFinerWithinMean"] == "2"
    assert macros["ensFinerHighFMeanDev"] == "+4.0" and macros["ensFinerRuns"] == "9"
    # every macro how_sure.tex uses is defined
    used = set(re.findall(r"\\((?:ens|env)[A-Z]\w*)", (PAPER / "how_sure.tex").read_text()))
    assert used and used <= set(macros), sorted(used - set(macros))


def test_numbers_without_a_finer_ensemble_define_none_of_its_macros(tables, tmp_path):
    out = tmp_path / "how_sure_numbers.tex"
    assert command(PAPER / "make_how_sure.py", "--ensemble", tables / "ensemble_summary.json",
                   "--envelope", tables / "envelope_summary.json", "-o", out).returncode == 0
    assert "ensWithinMean" in macros_of(out) and not any(m.startswith("ensFiner") for m in macros_of(out))


def test_finer_ensemble_needs_its_mesh(tables, tmp_path):
    result = command(PAPER / "make_how_sure.py", "--ensemble", tables / "ensemble_summary.json",
                     "--envelope", tables / "envelope_summary.json", "--finer-ensemble",
                     tables / "finer_summary.json", "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "--finer-mesh" in result.stderr and not (tmp_path / "out.tex").exists()


def test_numbers_refuse_an_unknown_group(tables, tmp_path):
    summary = json.loads((tables / "ensemble_summary.json").read_text())
    summary["groups"]["made up"] = summary["groups"]["the rest"]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(summary))
    result = command(PAPER / "make_how_sure.py", "--ensemble", bad, "--envelope", tables / "envelope_summary.json",
                     "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "made up" in result.stderr and not (tmp_path / "out.tex").exists()
