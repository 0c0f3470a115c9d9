"""The section "How sure is this table": the envelope figure, the phase diagram of an ensemble and
paper/make_how_sure.py, from tables that analysis.ensemble and analysis.envelope write for a small
made-up ensemble (three cells, three seeds, two method variants)."""
import json
import re

import pytest

from figure_support import PAPER, ROOT, assert_figure, call, command
from how_sure_inputs import write_csv, write_tables


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    return write_tables(tmp_path_factory.mktemp("how_sure"))


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


def test_numbers_of_the_section(tables, tmp_path):
    out = tmp_path / "how_sure_numbers.tex"
    result = command(PAPER / "make_how_sure.py", "--ensemble", tables / "ensemble_summary.json",
                     "--envelope", tables / "envelope_summary.json", "-o", out)
    assert result.returncode == 0, result.stderr
    macros = dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", out.read_text()))
    assert macros["ensRuns"] == "9" and macros["ensCells"] == "3" and macros["ensSeedsMax"] == "3"
    # nu = 0.2, f = 1.5: mean 0.86 vs 0.882 -> -2.5 %, within; the others are not.
    assert macros["ensHighFMeanDev"] == "-2.5" and macros["ensWithinMean"] == "1"
    assert macros["envWithin"] == "1" and macros["envCells"] == "3"
    # every macro how_sure.tex uses is defined
    used = set(re.findall(r"\\((?:ens|env)[A-Z]\w*)", (PAPER / "how_sure.tex").read_text()))
    assert used and used <= set(macros), sorted(used - set(macros))


def test_numbers_refuse_an_unknown_group(tables, tmp_path):
    summary = json.loads((tables / "ensemble_summary.json").read_text())
    summary["groups"]["made up"] = summary["groups"]["the rest"]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(summary))
    result = command(PAPER / "make_how_sure.py", "--ensemble", bad, "--envelope", tables / "envelope_summary.json",
                     "-o", tmp_path / "out.tex")
    assert result.returncode == 2 and "made up" in result.stderr and not (tmp_path / "out.tex").exists()
