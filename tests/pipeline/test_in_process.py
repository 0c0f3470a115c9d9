"""study/in_process.py: the pipeline's measure and aggregate, run inside the Snakemake process, write
the files `python3 -m analysis measure|aggregate` writes, byte for byte, and log the command's line
or its error."""

import subprocess
import sys

import pytest

from analysis.core.errors import InputError
from study import in_process
from synthetic_run import paper_case, write_run

from .conftest import REPO


def analysis(*args):
    subprocess.run([sys.executable, "-m", "analysis", *map(str, args)], cwd=REPO, check=True, capture_output=True)


def test_measure_and_aggregate_write_what_the_commands_write(tmp_path):
    run = tmp_path / "run.h5"
    write_run(run, paper_case())
    in_process.measure(str(run), str(tmp_path / "in" / "metrics.json"), str(tmp_path / "in" / "measure.log"))
    analysis("measure", run, "-o", tmp_path / "cli" / "metrics.json")
    assert (tmp_path / "in" / "metrics.json").read_bytes() == (tmp_path / "cli" / "metrics.json").read_bytes()
    assert "celerity" in (tmp_path / "in" / "measure.log").read_text()

    reference = REPO / "study" / "reference" / "table1_celerity.csv"
    metrics = str(tmp_path / "in" / "metrics.json")
    in_process.aggregate([metrics], str(reference), 0.05, ["--select", "seed=1"], str(tmp_path / "in" / "table"),
                         str(tmp_path / "in" / "aggregate.log"))
    analysis("aggregate", metrics, "--reference", reference, "--tolerance", 0.05, "--select", "seed=1",
             "-o", tmp_path / "cli" / "table")
    for table in (tmp_path / "cli" / "table").iterdir():
        assert (tmp_path / "in" / "table" / table.name).read_bytes() == table.read_bytes(), table.name


def test_a_failed_measurement_is_logged_and_raised(tmp_path):
    bad = tmp_path / "run.h5"
    bad.write_text("not HDF5")
    with pytest.raises(InputError):
        in_process.measure(str(bad), str(tmp_path / "metrics.json"), str(tmp_path / "logs" / "measure.log"))
    assert (tmp_path / "logs" / "measure.log").read_text().startswith(f"error: {bad}")
    assert not (tmp_path / "metrics.json").exists()
