"""Both documents a reviewer reads stay within the page: the paper built from the committed
study/results (scripts/report_from_committed.sh) and the
HTML report of a real sweep, rendered to PNG (pdftoppm; headless Chromium screenshots of the HTML at
1400 px and at a printed page's width). Content wider than the page leaves ink in the right margin; each check is shown
to find it on a page built to overflow."""
import json
import shutil
import subprocess
import sys

import numpy as np
import pytest
import yaml
from PIL import Image

from figure_support import ROOT

PDFTOPPM = shutil.which("pdftoppm")
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
needs_pdftoppm = pytest.mark.skipif(PDFTOPPM is None, reason="pdftoppm not installed (apt-get install poppler-utils)")
needs_latex = pytest.mark.skipif(shutil.which("latexmk") is None, reason="latexmk not installed "
                                 "(scripts/setup.sh --latex)")
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="chromium not installed (apt-get install chromium)")
DPI = 50
CONFIG = yaml.safe_load((ROOT / "study" / "config.yaml").read_text())


def run(*args, **kwargs):
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, f"{args[:2]}: {result.stdout[-2000:]}{result.stderr[-2000:]}"
    return result


def pages(pdf, folder):
    run(PDFTOPPM, "-r", DPI, "-png", pdf, folder / "page")
    return sorted(folder.glob("page-*.png"))


def margin_ink(png, margin_px):
    """Pixels with ink (darker than light grey) in the rightmost margin_px columns of an image."""
    pixels = np.asarray(Image.open(png).convert("L"))
    return int((pixels[:, -margin_px:] < 200).sum())


def paper_margin_px():
    """The part of the paper's right margin (2.3 cm) that must stay empty: all but 0.5 cm, which
    covers the 3 pt an overfull box may take (paper/check_latex_log.py)."""
    return int((2.3 - 0.5) / 2.54 * DPI)


def chromium(*args):
    return run(CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", *args, timeout=120)


# ------------------------------------------------------------------------------------------- paper

def build_from_committed(tmp_path):
    """The report built from study/results alone by scripts/report_from_committed.sh (figures drawn
    from the runs are framed notes: the runs are not committed)."""
    run("bash", ROOT / "scripts" / "report_from_committed.sh", tmp_path / "from_committed", timeout=1200)
    return tmp_path / "from_committed" / "paper" / "reproduction.pdf"


@needs_latex
@needs_pdftoppm
def test_the_paper_from_the_committed_results_stays_within_the_page(tmp_path):
    pdf = build_from_committed(tmp_path)
    images = pages(pdf, tmp_path)
    assert len(images) >= 8
    for png in images:
        assert margin_ink(png, paper_margin_px()) == 0, f"{png.name}: content in the right margin"


@needs_latex
@needs_pdftoppm
def test_the_margin_check_sees_a_table_wider_than_the_page(tmp_path):
    wide = " & ".join(["a rather wide column"] * 10)
    (tmp_path / "wide.tex").write_text(
        "\\documentclass[11pt,a4paper]{article}\\usepackage[margin=2.3cm]{geometry}\\begin{document}"
        "\\noindent\\begin{tabular}{" + "l" * 10 + "}" + wide + "\\end{tabular}\\end{document}\n")
    run("pdflatex", "-interaction=nonstopmode", "wide.tex", cwd=tmp_path)
    assert margin_ink(pages(tmp_path / "wide.pdf", tmp_path)[0], paper_margin_px()) > 0


# -------------------------------------------------------------------------------------------- HTML

def report_page(tmp_path, sweep="table1"):
    """study/scripts/report.py over a committed sweep: its Table 1 and one folder per run holding the
    run's committed metrics (the longest run names and the widest values the study has)."""
    rows = list(__import__("csv").DictReader((ROOT / "study" / "results" / sweep / "all_metrics.csv").open()))
    runs = []
    for i, row in enumerate(rows):
        folder = tmp_path / "runs" / f"{sweep}_point{i:03d}_nu{row['nu']}_f{row['f']}_elements_per_H{row['elements_per_H']}"
        folder.mkdir(parents=True)
        (folder / "metrics.json").write_text(json.dumps({k: (float(v) if v.replace(".", "", 1).replace("-", "", 1)
                                                             .replace("e", "", 1).isdigit() else v)
                                                         for k, v in row.items()}))
        runs.append({"name": folder.name, "dir": str(folder)})
    manifest = {"title": "page width", "tolerance": CONFIG["reference"]["tolerance"], "sections": [
        {"sweep": sweep, "description": "", "table": str(ROOT / "study" / "results" / sweep / "table1.csv"),
         "cells": sorted({(float(r["nu"]), float(r["f"])) for r in rows}), "comparison": str(tmp_path / "cmp.txt"),
         "figures": [], "runs": runs}]}
    (tmp_path / "cmp.txt").write_text("compare: PASS\n")
    page = tmp_path / "report.html"
    run(sys.executable, ROOT / "study" / "scripts" / "report.py", "--manifest", json.dumps(manifest), "--out", page)
    return page


def screenshots(page, folder):
    """Screenshots of an HTML page in a 1400 px window and in a 760 px one (a printed page's width:
    the report applies its print rules below 60em, so that this shows what print shows; Chromium's
    own printing clips at the page edge, where a test cannot see what was cut)."""
    shots = []
    for width in (1400, 760):
        shot = folder / f"screen{width}.png"
        chromium(f"--window-size={width},2000", f"--screenshot={shot}", page.as_uri())
        shots.append(shot)
    return shots


#: Right strips that stay blank: beside the 75em (1200 px) page centred in 1400 px; inside the
#: body's 1em padding at 760 px.
MARGIN_PX = (60, 10)


@needs_chromium
def test_the_html_report_stays_within_a_wide_and_a_print_width_window(tmp_path):
    for shot, margin in zip(screenshots(report_page(tmp_path), tmp_path), MARGIN_PX):
        assert margin_ink(shot, margin) == 0, f"{shot.name}: content beyond the page"


@needs_chromium
def test_the_html_checks_see_a_table_wider_than_the_window(tmp_path):
    page = tmp_path / "wide.html"
    cells = "".join(f"<td>column_{i}_with_a_long_unbreakable_value</td>" for i in range(12))
    page.write_text(f"<!DOCTYPE html><html><body style='max-width: 75em; margin: auto; padding: 0 1em'>"
                    f"<table border=1><tr>{cells}</tr></table></body></html>")
    for shot, margin in zip(screenshots(page, tmp_path), MARGIN_PX):
        assert margin_ink(shot, margin) > 0, shot.name
