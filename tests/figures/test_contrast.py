"""The contrast sweep's figure (figures/contrast_phase_diagram.py) and the report's section
(paper/make_contrast.py), from the tiny synthetic sweep of contrast_inputs.py."""
import json

from PIL import Image

from contrast_inputs import write_contrast
from figure_support import PAPER, call, command


def test_the_figure_builds_with_one_marker_per_run(tmp_path):
    metrics, theory = write_contrast(tmp_path)
    assert call("contrast_phase_diagram", metrics, "--theory", theory, "--out", tmp_path / "fig") == 0
    assert (tmp_path / "fig.pdf").stat().st_size > 5_000
    legend = json.loads(Image.open(tmp_path / "fig.png").info["Description"])["legend"]
    assert legend["categories"] == {"no_opening": 4, "intersonic_opening_inversion": 3, "no_slip": 4,
                                    "intersonic_backward_opening": 1}


def test_the_figure_refuses_a_repeated_point_and_a_missing_theory_row(tmp_path):
    metrics, theory = write_contrast(tmp_path)
    lines = metrics.read_text().splitlines()
    (tmp_path / "twice.csv").write_text("\n".join(lines + lines[1:2]) + "\n")
    result = command(PAPER.parent / "figures" / "contrast_phase_diagram.py", tmp_path / "twice.csv",
                     "--theory", theory, "--out", tmp_path / "fig")
    assert result.returncode == 2 and "more than once" in result.stderr
    (tmp_path / "theory.csv").write_text("\n".join(theory.read_text().splitlines()[:3]) + "\n")
    result = command(PAPER.parent / "figures" / "contrast_phase_diagram.py", metrics,
                     "--theory", tmp_path / "theory.csv", "--out", tmp_path / "fig")
    assert result.returncode == 2 and "no row for nu = 0.2, contrast 3" in result.stderr


def test_the_sections_numbers_come_from_the_table(tmp_path):
    metrics, theory = write_contrast(tmp_path)
    text, table = tmp_path / "text.tex", tmp_path / "table.tex"
    result = command(PAPER / "make_contrast.py", metrics, "--theory", theory, "--text", text, "--table", table)
    assert result.returncode == 0, result.stderr
    words = text.read_text()
    assert "At $\\nu = 0.2$ the interface opens with $E_s/E$ = rigid and 3 from $f = 1.5$; $E_s/E$ = 1 at no $f$." in words
    assert "steady sliding) in 2 runs, on $E_s/E$ = 1." in words
    assert "Backward opening waves (against it), $c_p/c_s$: $-3.01$ on 3 ($f = 1.5$)." in words
    assert "$+1.08$ on 3 ($f = 1.5$)" in words and "Backward opening waves (against it): none." in words
    assert words.count("$T/N$ inverts in 2 runs, 2 of them among the 2 that open") == 2
    assert "opening goes with instability of steady sliding in 6 of 6 runs." in words
    # |1.08 / 1.144 - 1| = 6 %, |-3.01 / -3.362 - 1| = 10 %: the growing mode that runs the same way.
    assert "by 6\\,\\% (median of 1 run)" in words and "by 10\\,\\% (median of 1 run)" in words
    assert "3: $0.665$ / $3.31$; 1: $\\infty$ / $\\infty$" in words
    rows = table.read_text()
    assert "0.2 & rigid & F & $+1.33$$^{*}$ & $1$ & -- \\\\" in rows
    assert "0.45 & 3 & F & $-3.01$$^{*}$ & $0.917$ & $0.719$ \\\\" in rows
    assert "0.45 & 1 & S & S & $\\infty$ & $\\infty$ \\\\" in rows


def test_the_section_names_what_disagrees_with_the_theory(tmp_path):
    metrics, theory = write_contrast(tmp_path)
    text = metrics.read_text().replace("0.2,0.5,3,32,no_opening,,false", "0.2,0.5,3,32,no_opening,,true")
    (tmp_path / "opened.csv").write_text(text)
    assert command(PAPER / "make_contrast.py", tmp_path / "opened.csv", "--theory", theory, "--text",
                   tmp_path / "text.tex", "--table", tmp_path / "table.tex").returncode == 0
    assert ("in 5 of 6 runs; not in (3, $f = 0.5$: stable in theory, opens)."
            in (tmp_path / "text.tex").read_text())
    result = command(PAPER / "make_contrast.py", metrics, "--theory", tmp_path / "missing.csv", "--text",
                     tmp_path / "t.tex", "--table", tmp_path / "u.tex")
    assert result.returncode == 2 and "missing.csv" in result.stderr and not (tmp_path / "t.tex").exists()
