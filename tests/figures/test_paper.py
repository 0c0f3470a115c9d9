"""paper/: numbers and table generated from the study files, placeholders, and the LaTeX build
(with placeholders only, and with every figure the report expects)."""
import re
import shutil
import subprocess
import sys

import pytest

import synthetic
from figure_support import PAPER, ROOT, command
from how_sure_inputs import write_generated, write_tables
from how_sure_limits_inputs import write_generated_limits, write_limits

sys.path.insert(0, str(PAPER))
from numbers_tex import MACRO_NAMES  # noqa: E402

LATEXMK = shutil.which("latexmk")
needs_latex = pytest.mark.skipif(LATEXMK is None, reason="latexmk not installed "
                                 "(apt-get install --no-install-recommends latexmk "
                                 "texlive-latex-recommended)")


def macros(path):
    return dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*)\}", path.read_text()))


def study_tables():
    """The report's tables declared in study/config.yaml (`paper.tables`)."""
    import yaml

    config = yaml.safe_load((PAPER.parent / "study" / "config.yaml").read_text())
    return config["paper"]["tables"]


def test_every_table_of_the_report_is_declared():
    used = set(re.findall(r"\\generatedtable\{([\w]+)\}", (PAPER / "reproduction.tex").read_text()))
    assert used == set(study_tables())


def expected_figures():
    """The figures of reproduction.tex: exactly `paper.figures` of study/config.yaml (the one list;
    paper/Makefile reads it), and the synthetic jobs of figure_support draw each of them."""
    import yaml

    from figure_support import report_jobs

    names = re.findall(r"\\generatedfigure\{([\w]+)\}", (PAPER / "reproduction.tex").read_text())
    declared = yaml.safe_load((PAPER.parent / "study" / "config.yaml").read_text())["paper"]["figures"]
    assert sorted(declared) == sorted(names), "config paper.figures and reproduction.tex disagree"
    assert sorted(report_jobs(PAPER)) == sorted(names)
    return names


def numbers_args(data, **replace):
    """make_numbers.py's options as the rule `paper_numbers` passes them, on the synthetic study."""
    options = {"--summary": data / "summary.json", "--runs": data / "all_metrics.csv",
               "--grid": data / "grid_metrics.csv", "--table1": data / "table1.csv", **replace}
    args = [item for pair in options.items() for item in pair]
    args += ["--reference-cell", "0.2", "1.5"]
    for role, parameter in synthetic.ROLES.items():
        args += ["--sweep", role, parameter, data / f"sweep_{role}.csv"]
    return args


def test_numbers_from_the_study(data, tmp_path):
    out = tmp_path / "numbers.tex"
    result = command(PAPER / "make_numbers.py", *numbers_args(data), "-o", out)
    assert result.returncode == 0, result.stderr
    m = macros(out)
    assert m["cellsTotal"] == r"\ensuremath{38}"
    assert m["cellsCompared"] == r"\ensuremath{36}"
    assert m["cellsWithin"] == r"\ensuremath{21}"
    assert m["dtTimesCs"] == r"\ensuremath{0.5}"
    assert m["tolerancePercent"] == r"\ensuremath{5}"
    assert m["medianDeviationPercent"] == r"\ensuremath{4.1}"
    assert m["nGridPoints"] == r"\ensuremath{98}" and m["nRuns"] == r"\ensuremath{111}"
    assert m["publishedReference"] == r"\ensuremath{0.882}"
    assert m["pulseCountsPeriod"].count("ensuremath") == 3
    assert m["periodRatios"] == r"\ensuremath{2}, \ensuremath{4}, \ensuremath{6}"
    assert m["celerityMesh"].count("ensuremath") == 2 * 4  # H/16, 32, 64, 128: value (mesh) each
    assert m["nSupersonicBackward"] == r"\ensuremath{2}"
    assert set(m) == set(MACRO_NAMES)
    used = set(re.findall(r"\\(\w+)", (PAPER / "reproduction.tex").read_text()))
    assert "notavailable" not in "".join(m[k] for k in m if k in used)


def test_a_missing_number_is_an_error(data, tmp_path):
    # The grid lacks the derived column inside_flutter_wedge (an all_metrics.csv from before it).
    rows = (data / "grid_metrics.csv").read_text().splitlines()
    column = rows[0].split(",").index("inside_flutter_wedge")
    (tmp_path / "grid.csv").write_text("\n".join(",".join(c for i, c in enumerate(line.split(",")) if i != column)
                                                 for line in rows) + "\n")
    result = command(PAPER / "make_numbers.py", *numbers_args(data, **{"--grid": tmp_path / "grid.csv"}),
                     "-o", tmp_path / "x.tex")
    assert result.returncode == 2 and "inside_flutter_wedge" in result.stderr
    assert not (tmp_path / "x.tex").exists()
    # A sweep must give one run per value of its parameter, and at least two values.
    result = command(PAPER / "make_numbers.py", *numbers_args(data), "--sweep", "mesh", "rho",
                     data / "sweep_mesh.csv", "-o", tmp_path / "x.tex")
    assert result.returncode == 2 and "two runs with rho = 1000 at the reference cell" in result.stderr
    rows = (data / "sweep_mesh.csv").read_text().splitlines()
    (tmp_path / "one.csv").write_text("\n".join(rows[:2]) + "\n")
    result = command(PAPER / "make_numbers.py", *numbers_args(data), "--sweep", "mesh", "elements_per_H",
                     tmp_path / "one.csv", "-o", tmp_path / "x.tex")
    assert result.returncode == 2 and "sweep 'mesh' has 1 value(s) of elements_per_H" in result.stderr
    result = command(PAPER / "make_numbers.py", *numbers_args(data, **{"--summary": tmp_path / "s.json"}),
                     "-o", tmp_path / "x.tex")
    assert result.returncode == 2 and "cannot read" in result.stderr
    (tmp_path / "s.json").write_text("{}")
    result = command(PAPER / "make_numbers.py", *numbers_args(data, **{"--summary": tmp_path / "s.json"}),
                     "-o", tmp_path / "x.tex")
    assert result.returncode == 2 and "no number under 'cells_total'" in result.stderr


def test_table1(data, tmp_path):
    out = tmp_path / "table1.tex"
    assert command(PAPER / "make_table1.py", data / "table1.csv", "-o", out).returncode == 0
    text = out.read_text()
    assert text.count(r"\\") - 2 == 10  # one row per published cell (+ two header lines)
    assert r"0.2 & 1.5 & $0.882$" in text and r"\mathbf" in text
    assert r"0.49 & 2 & $0.607$ & -- & --" in text
    assert r"$\mathbf{-3.0}$$^\ddagger$ & subsonic" in text  # the regime mismatch at (0.3, 1.5)
    (tmp_path / "bad.csv").write_text("nu,f,celerity\n0.2,1.5,0.8\n")
    result = command(PAPER / "make_table1.py", tmp_path / "bad.csv", "-o", out)
    assert result.returncode == 2 and "missing required column(s) published" in result.stderr


def test_placeholders_never_overwrite(tmp_path):
    (tmp_path / "numbers.tex").write_text("real")
    result = command(PAPER / "make_placeholders.py", "--dir", tmp_path)
    assert result.returncode == 0
    assert (tmp_path / "numbers.tex").read_text() == "real"
    assert "notavailable" in (tmp_path / "table1.tex").read_text()


def build(paper):
    result = subprocess.run(["make", "-C", str(paper)], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    assert (paper / "reproduction.pdf").stat().st_size > 20_000
    log = (paper / "reproduction.log").read_text(errors="replace")
    assert "undefined" not in log.lower(), "undefined references or macros"
    return log


@needs_latex
def test_report_builds_with_placeholders(tmp_path):
    paper = tmp_path / "paper"
    shutil.copytree(PAPER, paper, ignore=shutil.ignore_patterns("generated", "*.pdf", "*.aux"))
    build(paper)
    assert (paper / "generated" / "numbers.tex").exists()


@needs_latex
def test_report_builds_with_every_figure(data, rendered, tmp_path):
    paper = tmp_path / "paper"
    shutil.copytree(PAPER, paper, ignore=shutil.ignore_patterns("generated", "*.pdf", "*.aux"))
    gen = paper / "generated"
    gen.mkdir()
    assert sorted(rendered) == sorted(expected_figures())
    for name, (status, prefix) in rendered.items():
        assert status == 0, name
        for ext in ("png", "pdf"):
            shutil.copy(f"{prefix}.{ext}", gen / f"{name}.{ext}")
    assert command(PAPER / "make_numbers.py", *numbers_args(data), "-o", gen / "numbers.tex").returncode == 0
    assert command(PAPER / "make_table1.py", data / "table1.csv",
                   "-o", gen / "table1.tex").returncode == 0
    assert subprocess.run([sys.executable, "-m", "analysis", "energy-evidence", *[str(a) for name in synthetic.ENERGY_RUNS
                           for a in (f"--{name.replace('_', '-')}", data / f"energy_{name}.h5")],
                           "-o", str(gen / "energy_evidence.json")], cwd=ROOT, capture_output=True).returncode == 0
    assert command(PAPER / "make_energy_evidence.py", gen / "energy_evidence.json",
                   "-o", gen / "energy_evidence.tex").returncode == 0
    assert command(PAPER / "make_variants.py", f"default={data / 'summary.json'}",
                   f"dt = 1 m / c_s={data / 'summary.json'}", "-o", gen / "variants.tex").returncode == 0
    assert r"$\Delta t$ = 1 m / $c_s$" in (gen / "variants.tex").read_text()  # symbols typeset
    assert command(PAPER / "make_variants.py", "no-equals-sign", "-o", gen / "bad.tex").returncode == 2
    assert not (gen / "bad.tex").exists()
    for name, table in study_tables().items():  # every table of the study config, from the synthetic study
        if table.get("resolution"):
            args = ["make_resolution_table.py", f"H/32={data / 'table1.csv'}", f"H/64={data / 'table1.csv'}",
                    "--tolerance", "0.05"]
        else:
            args = ["make_sweep_table.py", f"all={data / 'all_metrics.csv'}", "--columns", *table["columns"]]
        assert command(PAPER / args[0], *args[1:], "-o", gen / f"{name}.tex").returncode == 0, name
    # The verdicts: the synthetic grid and Table 1; every other claim says its table was not built.
    assert command(PAPER / "make_claims.py", "--claims", ROOT / "study/reference/claims.json", "--tolerance", "0.05",
                   f"--table=table1={data / 'table1.csv'}", f"--table=grid={data / 'all_metrics.csv'}",
                   "-o", gen / "claims.tex", "--conclusions", gen / "conclusions.tex",
                   "--json", gen / "claims.json").returncode == 0
    assert command(PAPER / "make_contrast.py", data / "contrast_metrics.csv", "--theory", data / "contrast_theory.csv",
                   "--text", gen / "contrast_text.tex", "--table", gen / "contrast_table.tex").returncode == 0
    write_generated(write_tables(tmp_path), gen)  # paper/how_sure.tex's inputs (tests/figures/how_sure_inputs.py)
    write_generated_limits(write_limits(tmp_path / "limits"), gen)  # its limits subsections (how_sure_limits_inputs.py)
    build(paper)
    missing = subprocess.run(["make", "-s", "-C", str(paper), "missing"], capture_output=True,
                             text=True)
    assert missing.stdout.strip() == ""
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", str(paper / "reproduction.pdf"), "-"],
                              capture_output=True, text=True).stdout
        assert "not generated yet" not in text and "n/a" not in text


def test_table1_flags_a_run_that_did_not_complete(data, tmp_path):
    lines = (data / "table1.csv").read_text().splitlines()
    header = lines[0].split(",")
    row = next(i for i, line in enumerate(lines) if line.startswith("0.2,1.5,"))
    cells = lines[row].split(",")
    cells[header.index("end_reason")] = "contact_not_converged"
    lines[row] = ",".join(cells)
    (tmp_path / "table1.csv").write_text("\n".join(lines) + "\n")
    out = tmp_path / "table1.tex"
    assert command(PAPER / "make_table1.py", tmp_path / "table1.csv", "-o", out).returncode == 0
    text = out.read_text()
    assert text.count("$^{*}$") == 2 and "run did not complete: contact not converged" in text  # mark, note
    assert command(PAPER / "make_table1.py", data / "table1.csv", "-o", out).returncode == 0
    assert "did not complete" not in out.read_text()


OVERFULL_LOG = r"""(./reproduction.tex (./generated/numbers.tex) (./generated/regularized.tex
Overfull \hbox (157.82016pt too wide) in paragraph at lines 1--19
 [][]
) (./generated/variants.tex)
Overfull \hbox (1.5pt too wide) in paragraph at lines 3--4
LaTeX Warning: Reference `tab:gone' on page 3 undefined on input line 12.
"""


def test_the_log_check_fails_on_a_box_off_the_page_an_undefined_reference_and_a_placeholder(tmp_path):
    log = tmp_path / "reproduction.log"
    log.write_text(OVERFULL_LOG)
    numbers = tmp_path / "numbers.tex"
    numbers.write_text("\\newcommand{\\cellsTotal}{\\ensuremath{38}}\n\\newcommand{\\nRuns}{\\notavailable}\n")
    result = command(PAPER / "check_latex_log.py", log, "--numbers", numbers)
    assert result.returncode == 1
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 3, result.stderr  # the 1.5 pt box is within the allowance
    assert "157.8 pt" in lines[0] and "generated/regularized.tex" in lines[0]
    assert "tab:gone" in lines[1] and "\\nRuns" in lines[2]
    log.write_text("(./reproduction.tex)\nOverfull \\hbox (2.9pt too wide) in paragraph at lines 3--4\n")
    assert command(PAPER / "check_latex_log.py", log, "--numbers", numbers).returncode == 1  # placeholder
    assert command(PAPER / "check_latex_log.py", log).returncode == 0


@needs_latex
def test_the_build_fails_on_a_table_wider_than_the_page(tmp_path):
    paper = tmp_path / "paper"
    shutil.copytree(PAPER, paper, ignore=shutil.ignore_patterns("generated", "*.pdf", "*.aux"))
    subprocess.run([sys.executable, str(paper / "make_placeholders.py"), "--dir", str(paper / "generated")],
                   check=True, capture_output=True)
    wide = "\\begin{tabular}{" + "l" * 12 + "}\n" + " & ".join(["a rather wide column"] * 12) + " \\\\\n\\end{tabular}\n"
    (paper / "generated" / "long.tex").write_text(wide)
    result = subprocess.run(["make", "-C", str(paper)], capture_output=True, text=True)
    assert result.returncode != 0
    assert "overfull box" in result.stderr and "generated/long.tex" in result.stderr
    assert not (paper / "reproduction.pdf").exists()
