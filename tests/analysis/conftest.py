"""Fixtures of the analysis tests: the repository root on sys.path (so `import analysis` works
however pytest is started) and `run_file`, which writes a synthetic run.h5 (see synthetic_run.py)."""

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
for folder in (ROOT, HERE):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))

from synthetic_run import write_run  # noqa: E402


@pytest.fixture
def run_file(tmp_path):
    """Function scenario, name='run.h5' -> path of the written synthetic run file."""

    def make(scenario, name="run.h5"):
        path = tmp_path / name
        write_run(path, scenario)
        return path

    return make
