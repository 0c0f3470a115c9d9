"""analysis.tables.aggregate and analysis.tables.compare through the command line, on a synthetic study."""

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

from analysis.cli import main
from analysis.tables.aggregate import TABLE1_COLUMNS
from synthetic_run import Pulse, Scenario, paper_case

ROOT = Path(__file__).resolve().parents[3]
REFERENCE = ROOT / "study" / "reference" / "table1_celerity.csv"


def cli(*args):
    """Run `python3 -m analysis ARGS` as a user would; returns the CompletedProcess."""
    return subprocess.run([sys.executable, "-m", "analysis", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)


def metrics_file(folder, name, nu, f, celerity, **extra):
    data = dict(nu=nu, f=f, celerity=celerity, regime="intersonic", category="intersonic_opening",
                opening=True, inversion=False, min_T_over_N=0.3, elements_per_H=32,
                later_drops_start_T_over_N=[1.0, 0.98])
    data.update(extra)
    path = folder / name
    path.write_text(json.dumps(data))
    return path


@pytest.fixture
def study(tmp_path, run_file):
    """Two measured synthetic runs and hand-written metrics for some other cells."""
    folder = tmp_path / "metrics"
    folder.mkdir()
    measured = []
    for name, scenario in (("nu0.2_f1.5", paper_case()),
                           ("nu0.49_f0.5", Scenario(nu=0.49, f=0.5, pulses=[
                               Pulse(-5.30, opening=0.02, opening_start=850.0)]))):
        out = folder / f"{name}.json"
        assert main(["measure", str(run_file(scenario, name + ".h5")), "-o", str(out)]) == 0
        measured.append(out)
    good = [metrics_file(folder, "a.json", 0.45, 1.3, 0.69),           # -2.5 %
            metrics_file(folder, "b.json", 0.1, 1.8, None),            # run without a front
            metrics_file(folder, "c.json", 0.2, 1.0, 0.7),             # not a Table 1 cell
            metrics_file(folder, "d.json", 0.2, 1.5, 0.9, elements_per_H=64)]  # mesh variant
    return folder, measured + good


def read_rows(path):
    with open(path, newline="") as stream:
        reader = csv.DictReader(stream)
        return reader.fieldnames, list(reader)


def test_aggregate_writes_table1_and_summary(tmp_path, study):
    folder, files = study
    out = tmp_path / "tables"
    result = cli("aggregate", *files, "-o", out, "--select", "elements_per_H=32")
    assert result.returncode == 0, result.stderr
    assert "table1: 3/38 cells measured, 3/3 within 5%, signs 3/3" in result.stdout
    columns, rows = read_rows(out / "table1.csv")
    assert tuple(columns) == TABLE1_COLUMNS
    assert len(rows) == 38
    cell = {(float(r["nu"]), float(r["f"])): r for r in rows}
    r = cell[(0.2, 1.5)]
    assert float(r["celerity"]) == pytest.approx(0.882, rel=5e-3) and float(r["published"]) == 0.882
    assert r["within_tol"] == "true" and r["sign_match"] == "true" and r["regime_match"] == "true"
    assert r["category"] == "intersonic_opening_inversion" and r["inversion"] == "true"
    r = cell[(0.49, 0.5)]
    assert float(r["deviation_rel"]) == pytest.approx(-0.05 / 5.25, rel=1e-2)  # (c - pub) / |pub|
    assert r["regime"] == r["published_regime"] == "supersonic"
    assert cell[(0.45, 1.3)]["deviation_rel"].startswith("-0.025")
    assert cell[(0.1, 1.8)]["celerity"] == "" and cell[(0.1, 1.8)]["category"] == "intersonic_opening"
    assert cell[(0.3, 1.5)]["celerity"] == "" and cell[(0.3, 1.5)]["published_regime"] == "intersonic"
    assert cell[(0.0, 2.0)]["published_regime"] == "supersonic"  # 1.213 > c_l = 1.0
    summary = json.loads((out / "summary.json").read_text())
    assert {k: summary[k] for k in ("cells_compared", "within_tolerance", "sign_matches",
                                    "regime_matches", "tolerance")} == {
        "cells_compared": 3, "within_tolerance": 3, "sign_matches": 3, "regime_matches": 3,
        "tolerance": 0.05}
    assert summary["median_abs_deviation"] == pytest.approx(0.05 / 5.25, rel=0.2)
    tex = (out / "table1.tex").read_text()
    # The report's Table 1 (analysis.tables.table1_tex): one row per published cell, the regenerated
    # celerity beside the published one.
    for text in (r"\toprule", r"\midrule", r"\bottomrule", "$-5.399$", "published", "regenerated"):
        assert text in tex
    assert tex.count(r"\\") == 2 + 38  # 2 header lines, one per published cell
    assert "| 0.45 | 1.30 | 0.708 | 0.690 | -2.5% |" in (out / "table1.md").read_text()
    columns, rows = read_rows(out / "all_metrics.csv")
    assert len(rows) == len(files) and columns[0] == "metrics_file"
    assert "celerity_xcorr" in columns and "later_drops_start_T_over_N" not in columns
    # compare accepts this table
    result = cli("compare", out / "table1.csv", "--reference", REFERENCE, "--tolerance", "0.05")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "PASS: 3 cells compared, 3 within 5%" in result.stdout


def test_aggregate_refuses_two_runs_for_one_cell(tmp_path, study):
    folder, files = study
    out = tmp_path / "tables"
    result = cli("aggregate", *files, "-o", out)
    assert result.returncode == 2
    assert "two metrics for the cell nu=0.2 f=1.5" in result.stderr and "--select" in result.stderr
    assert not out.exists()


def test_compare_fails_on_wrong_sign_and_tolerance(tmp_path):
    folder = tmp_path
    files = [metrics_file(folder, "a.json", 0.45, 1.0, 2.52),     # published -2.523: wrong sign
             metrics_file(folder, "b.json", 0.0, 2.0, 1.30),      # published 1.213: +7.2 %
             metrics_file(folder, "c.json", 0.2, 1.2, 0.876)]     # within
    out = tmp_path / "tables"
    assert main(["aggregate", *map(str, files), "-o", str(out)]) == 0
    result = cli("compare", out / "table1.csv", "--reference", REFERENCE)
    assert result.returncode == 1
    assert "WRONG SIGN nu=0.45 f=1: celerity 2.5200 m/s vs published -2.523 m/s" in result.stdout
    assert "OUT OF TOLERANCE nu=0 f=2" in result.stdout and "+7.2%" in result.stdout
    assert "nu=0.2 f=1.2" not in result.stdout.replace("compare:", "")
    assert "FAIL" in result.stdout
    # A wider tolerance forgives the deviation, never the sign.
    result = cli("compare", out / "table1.csv", "--reference", REFERENCE, "--tolerance", "0.1")
    assert result.returncode == 1 and "WRONG SIGN" in result.stdout and "OUT OF TOLERANCE" not in result.stdout


def test_compare_min_within(tmp_path):
    files = [metrics_file(tmp_path, "c.json", 0.2, 1.2, 0.876)]
    out = tmp_path / "tables"
    assert main(["aggregate", *map(str, files), "-o", str(out)]) == 0
    assert main(["compare", str(out / "table1.csv"), "--min-within", "1"]) == 0
    assert main(["compare", str(out / "table1.csv"), "--min-within", "2"]) == 1


def test_bad_inputs_are_named_and_write_nothing(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    out = tmp_path / "tables"
    assert main(["aggregate", str(bad), "-o", str(out)]) == 2
    assert "bad.json: not valid JSON" in capsys.readouterr().err
    assert not out.exists()
    lacking = tmp_path / "lacking.json"
    lacking.write_text(json.dumps({"nu": 0.2, "celerity": 1.0}))
    assert main(["aggregate", str(lacking), "-o", str(out)]) == 2
    assert "lack key(s) f" in capsys.readouterr().err
    table = tmp_path / "table.csv"
    table.write_text("nu,f,speed\n0.2,1.5,0.88\n")
    assert main(["compare", str(table)]) == 2
    assert "table lacks column(s) celerity" in capsys.readouterr().err
    table.write_text("nu,f,celerity\n0.2,1.5,fast\n")
    assert main(["compare", str(table)]) == 2
    assert "table.csv:2: not a number" in capsys.readouterr().err
    assert main(["compare", str(tmp_path / "absent.csv")]) == 2
    assert "cannot read table" in capsys.readouterr().err


def test_reference_copy_matches_the_paper():
    shared = ROOT.parent / "shared" / "reference" / "table1_celerity.csv"
    if shared.exists():
        assert REFERENCE.read_text() == shared.read_text()
    _, rows = read_rows(REFERENCE)
    assert len(rows) == 38
    assert {(r["nu"], r["f"]): r["celerity_m_per_s"] for r in rows}[("0.49", "1.50")] == "-5.399"


def test_table1_tex_compiles(tmp_path):
    import shutil

    if not shutil.which("pdflatex") or subprocess.run(["kpsewhich", "booktabs.sty"],
                                                      capture_output=True).returncode:
        pytest.skip("pdflatex with booktabs not installed")
    files = [metrics_file(tmp_path, "c.json", 0.2, 1.2, 0.876)]
    out = tmp_path / "tables"
    assert main(["aggregate", *map(str, files), "-o", str(out)]) == 0
    (out / "doc.tex").write_text("\\documentclass{article}\\usepackage{booktabs}\\begin{document}"
                                 "\\small\\input{table1.tex}\\end{document}\n")
    result = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"],
                            cwd=out, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stdout[-2000:]


def test_compare_ratchet_mode_fails_only_on_sign_regime_or_count():
    from analysis.tables.compare import compare
    from analysis.tables.reference import ReferenceCell

    reference = [ReferenceCell(0.2, 1.5, 0.882), ReferenceCell(0.45, 1.0, -2.523), ReferenceCell(0.0, 1.5, 0.982)]
    # 10 % off, but right sign and regime: a note in ratchet mode, a failure otherwise.
    table = {(0.2, 1.5): 0.97, (0.45, 1.0): -2.52, (0.0, 1.5): 0.98}
    strict = compare(table, reference, 0.05)
    gate = compare(table, reference, 0.05, min_within=2, ratchet=True)
    assert not strict.passed and gate.passed and len(gate.notes) == 1
    assert not compare(table, reference, 0.05, min_within=3, ratchet=True).passed  # below the ratchet
    # Right sign, wrong regime: 0.6 m/s is subsonic at nu = 0.2 (c_s = 0.645).
    wrong_regime = compare({**table, (0.2, 1.5): 0.6}, reference, 0.05, ratchet=True)
    assert not wrong_regime.passed and "WRONG REGIME" in wrong_regime.failures[0]
    wrong_sign = compare({**table, (0.45, 1.0): 2.5}, reference, 0.05, ratchet=True)
    assert not wrong_sign.passed and "WRONG SIGN" in wrong_sign.failures[0]


def test_compare_known_mismatch_is_a_note_but_a_new_one_fails():
    from analysis.tables.compare import compare
    from analysis.tables.reference import ReferenceCell

    reference = [ReferenceCell(0.49, 1.5, -5.399), ReferenceCell(0.2, 1.5, 0.882)]
    table = {(0.49, 1.5): 0.747, (0.2, 1.5): 0.88}
    gate = compare(table, reference, 0.05, ratchet=True, known_mismatches=("nu=0.49 f=1.5",))
    assert gate.passed and any(n.startswith("KNOWN WRONG SIGN") for n in gate.notes)
    new = compare({**table, (0.2, 1.5): -0.88}, reference, 0.05, ratchet=True, known_mismatches=("nu=0.49 f=1.5",))
    assert not new.passed and new.failures == [f for f in new.failures if "nu=0.2 f=1.5" in f]
