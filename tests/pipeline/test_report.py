"""study/scripts/report.py on hand-made inputs: the table shows the sweep's published cells with the
aggregate's deviations and flags (only for a sweep that compares with Table 1), the figures are
embedded under real captions, the runs carry c_p with its uncertainty, labels and provenance, wide
tables scroll."""

import importlib.util
import html
import json
import struct
import zlib

from .conftest import REPO

spec = importlib.util.spec_from_file_location("report", REPO / "study" / "scripts" / "report.py")
report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report)

TABLE = """nu,f,celerity,published,deviation_rel,regime,published_regime,sign_match,regime_match,within_tol,category,opening,inversion,min_T_over_N,published_category,category_match,reproduced,celerity_quality,celerity_window_sensitivity,end_reason
0.2,1.5,0.8488,0.882,-0.03764,intersonic,intersonic,true,true,true,intersonic_opening_inversion,true,true,-0.532,intersonic_opening,true,true,unsteady,-0.065,
0.45,1,-2.6805,-2.523,0.06243,supersonic,supersonic,true,true,false,supersonic_backward_opening,true,true,-0.496,supersonic_backward_opening,true,false,ok,0.01,
0.45,0.9,-2.60264,-2.506,-0.0385634,supersonic,supersonic,true,true,true,no_opening,false,false,0.843,supersonic_backward_opening,false,false,ok,,
0,1.5,,0.982,,,intersonic,,,,,,,,intersonic_opening,,,,,
"""


def png(width, height, description=None):
    """A blank RGB PNG of the given size, with a Description text chunk when given."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\0" + b"\xff" * 3 * width for _ in range(height))
    text = chunk(b"tEXt", b"Description\0" + description.encode("latin-1")) if description else b""
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + text + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def make_run(folder, metrics, max_rss="28.27"):
    (folder / "logs").mkdir(parents=True)
    (folder / "metrics.json").write_text(json.dumps({"slidewave_version": "0.1.0", "git_commit": "abc123",
                                                     "end_reason": "stop_after_opening", **metrics}))
    (folder / "config.json").write_text(json.dumps({"time": {"t_end": 3098.4, "stop_after_opening": 580.9}}))
    (folder / "logs" / "simulate.benchmark.tsv").write_text(f"s\th:m:s\tmax_rss\n3.71\t0:00:03\t{max_rss}\n")


def test_report_page(tmp_path):
    (tmp_path / "table1.csv").write_text(TABLE)
    (tmp_path / "comparison.txt").write_text("compare: PASS\n")
    legend = {"published": {"published_forward": 1, "published_backward": 2, "differs": 1}}
    (tmp_path / "phase_diagram.png").write_bytes(png(4, 3, json.dumps({"legend": legend})))
    (tmp_path / "convergence.png").write_bytes(png(30, 10))
    run = tmp_path / "nu0.20_f1.50"
    make_run(run, {"category": "intersonic_opening_inversion", "celerity": 0.8488, "opening": True,
                   "celerity_window_sensitivity": -0.065, "celerity_quality": "unsteady"})
    slow = tmp_path / "nu0.30_f0.50"
    # A run too short for Snakemake to sample its memory: the benchmark file says NA.
    make_run(slow, {"category": "no_slip", "celerity": None}, max_rss="NA")
    manifest = {"title": "test", "tolerance": 0.05, "sections": [
        {"sweep": "table1", "description": "the grid", "table": str(tmp_path / "table1.csv"),
         "cells": [[0.2, 1.5], [0.45, 1.0], [0.45, 0.9]], "comparison": str(tmp_path / "comparison.txt"),
         "figures": [str(tmp_path / "phase_diagram.png")], "runs": [{"name": "nu0.20_f1.50", "dir": str(run)}]},
        {"sweep": "mesh", "description": "one cell, several meshes", "table": str(tmp_path / "table1.csv"),
         "cells": [[0.2, 1.5]], "comparison": None, "figures": [str(tmp_path / "convergence.png")],
         "runs": [{"name": "nu0.30_f0.50", "dir": str(slow)}]}]}
    page = report.render(manifest)
    assert page.count("Table 1: published vs regenerated") == 1  # only the sweep with `comparison`
    assert ("3 published cells run, 3 with a measured celerity: 1 reproduced (within 5% with the published "
            "sign, regime and outcome), 2 within 5% whatever their outcome, 0 with the wrong sign, 1 with "
            "another outcome") in page
    assert "no opening (supersonic backward opening)" in page  # the category mismatch, with the published one
    assert "-3.8 %" in page and "+6.2 %" in page and "0.982" not in page  # (0, 1.5) was not run here
    assert "0.8488 &plusmn; 0.055 (unsteady)" in page  # c_p with its window uncertainty, in both tables
    assert page.count("0.8488 &plusmn; 0.055 (unsteady)") == 2
    assert "uniform sliding" in page and "no_slip" not in page
    assert "Categories of the runs in the (nu, f) plane" in page and "figures/phase_diagram.py" in page
    assert "<figure class=wide>" in page and page.count("<figure data-legend=") == 1  # the 3:1 convergence plot is wide
    assert page.count("<div class=scroll><table class=table1>") == 1
    assert page.count("<div class=scroll><table class=runs>") == 2
    assert "Row colours:" in page  # the red and yellow rows are explained
    assert "data-cell='0.45,0.9' data-category-match='false' data-published='-2.506'" in page
    assert f"data-legend='{html.escape(json.dumps(legend), quote=True)}'" in page  # the PNG's legend counts
    # The stop after opening is the run's setting only for a run that opened.
    assert page.count("<td>580.9</td>") == 1 and page.count("<td>never opened</td>") == 1
    assert "stop_after_opening" in page and "3.71" in page and "slidewave 0.1.0 (commit abc123)" in page
