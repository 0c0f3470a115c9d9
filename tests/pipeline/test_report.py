"""study/scripts/report.py on hand-made inputs: the table shows the sweep's published cells with the
aggregate's deviations, the figures are embedded, the runs carry their provenance."""

import base64
import importlib.util
import json

from .conftest import REPO

spec = importlib.util.spec_from_file_location("report", REPO / "study" / "scripts" / "report.py")
report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(report)

TABLE = """nu,f,celerity,published,deviation_rel,regime,published_regime,sign_match,regime_match,within_tol,category,opening,inversion,min_T_over_N
0.2,1.5,0.8488,0.882,-0.03764,intersonic,intersonic,true,true,true,intersonic_opening_inversion,true,true,-0.532
0.45,1,-2.6805,-2.523,0.06243,supersonic,supersonic,true,true,false,supersonic_backward_opening,true,true,-0.496
0,1.5,,0.982,,,intersonic,,,,,,,
"""
PNG = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==")


def test_report_page(tmp_path):
    (tmp_path / "table1.csv").write_text(TABLE)
    (tmp_path / "phase_diagram.png").write_bytes(PNG)
    run = tmp_path / "nu0.20_f1.50"
    (run / "logs").mkdir(parents=True)
    (run / "metrics.json").write_text(json.dumps({"category": "intersonic_opening_inversion", "celerity": 0.8488,
                                                  "end_reason": "stop_after_opening", "run_complete": True,
                                                  "slidewave_version": "0.1.0", "git_commit": "abc123"}))
    (run / "config.json").write_text(json.dumps({"time": {"t_end": 3098.4, "stop_after_opening": 580.9}}))
    (run / "logs" / "simulate.benchmark.tsv").write_text("s\th:m:s\tmax_rss\n3.71\t0:00:03\t28.27\n")
    manifest = {"title": "test", "tolerance": 0.05, "sections": [{
        "sweep": "quick", "description": "one point per category", "table": str(tmp_path / "table1.csv"),
        "cells": [[0.2, 1.5], [0.45, 1.0]], "comparison": None,
        "figures": [str(tmp_path / "phase_diagram.png")],
        "runs": [{"name": "nu0.20_f1.50", "dir": str(run)}]}]}
    page = report.render(manifest)
    assert "2 published cells run, 2 with a measured celerity: 1 within 5%, 0 with the wrong sign" in page
    assert "-3.8 %" in page and "+6.2 %" in page and "0.982" not in page  # (0, 1.5) was not run here
    assert "data:image/png;base64," in page and "figures/phase_diagram.py" in page
    assert "stop_after_opening" in page and "3.71" in page and "slidewave 0.1.0 (commit abc123)" in page
