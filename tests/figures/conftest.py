"""Fixtures of the figure and paper tests: synthetic inputs (see synthetic.py) built once per
session, and every figure of the report drawn once from them."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

import synthetic  # noqa: E402
from figure_support import call, report_jobs  # noqa: E402


@pytest.fixture(scope="session")
def data(tmp_path_factory):
    """Folder with run.h5, run_v1e-06.h5, run_v0.0001.h5, all_metrics.csv, table1.csv,
    flutter.txt, metrics.json, summary.json, energy_{alpha_zero,alpha,alpha_end}.h5."""
    return synthetic.write_all(tmp_path_factory.mktemp("synthetic"))


@pytest.fixture(scope="session")
def rendered(data, tmp_path_factory):
    """Every report figure drawn once: {name: (exit status, prefix)}."""
    folder = tmp_path_factory.mktemp("generated")
    return {name: (call(script, *args, "--out", folder / name), folder / name)
            for name, (script, *args) in report_jobs(data).items()}
