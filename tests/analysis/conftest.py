"""Fixtures of the analysis tests: `run_file`, which writes a synthetic run.h5 (see
tests/support/synthetic_run.py; tests/support is on the path through pyproject.toml)."""

import pytest

from synthetic_run import write_run


@pytest.fixture
def run_file(tmp_path):
    """Function scenario, name='run.h5' -> path of the written synthetic run file."""

    def make(scenario, name="run.h5"):
        path = tmp_path / name
        write_run(path, scenario)
        return path

    return make
