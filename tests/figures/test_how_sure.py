"""The section "How sure is this table": the envelope figure, the phase diagram of an ensemble and
paper/make_how_sure.py, from tables that analysis.ensemble and analysis.envelope write for a small
made-up ensemble (three cells, three seeds, two method variants)."""
import csv
import json
import re
import sys

import pytest

from figure_support import PAPER, ROOT, assert_figure, call, command

sys.path.insert(0, str(ROOT))
from analysis import ensemble as ensemble_module  # noqa: E402
from analysis import envelope as envelope_module  # noqa: E402

REFERENCE = "nu,f,celerity_m_per_s\n0.2,1.5,0.882\n0.45,1.0,-2.523\n0.0,1.1,0.861\n"
SEEDS = {(0.2, 1.5): [0.86, 0.85, 0.87], (0.45, 1.0): [-2.68, -2.66, 1.0], (0.0, 1.1): [0.99, 1.01, 0.97]}
CATEGORY = {(0.2, 1.5): "intersonic_opening_inversion", (0.45, 1.0): "supersonic_backward_opening",
            (0.0, 1.1): "supersonic_forward_opening"}


def write_csv(path, rows):
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return path


@pytest.fixture(scope="module")
def tables(tmp_path_factory):
    folder = tmp_path_factory.mktemp("how_sure")
    (folder / "ref.csv").write_text(REFERENCE)
    runs = [{"nu": nu, "f": f, "seed": seed, "celerity": c, "celerity_reason": "ok",
             "category": CATEGORY[(nu, f)] if c * SEEDS[(nu, f)][0] > 0 else "supersonic_forward_opening",
             "elements_per_H": 64}
            for (nu, f), values in SEEDS.items() for seed, c in enumerate(values, start=1)]
    write_csv(folder / "all_metrics.csv", runs)
    assert ensemble_module.main([str(folder / "all_metrics.csv"), "--reference", str(folder / "ref.csv"),
                                 "-o", str(folder)]) == 0
    coarse = [{"nu": nu, "f": f, "celerity": values[0] * 1.08, "celerity_reason": "ok"}
              for (nu, f), values in SEEDS.items()]
    write_csv(folder / "h32.csv", coarse)
    base = [{"nu": nu, "f": f, "celerity": values[0], "celerity_reason": "ok"} for (nu, f), values in SEEDS.items()]
    write_csv(folder / "h64.csv", base)
    spec = {"variants": [{"factor": "mesh", "label": "H/32", "table": str(folder / "h32.csv"),
                          "base": str(folder / "h64.csv")}]}
    assert envelope_module.main(["--ensemble", str(folder / "ensemble.csv"), "--spec", json.dumps(spec),
                                 "-o", str(folder)]) == 0
    (folder / "flutter.txt").write_text("0 nan nan\n0.2 1.0 inf\n0.45 1.0 inf\n")
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
