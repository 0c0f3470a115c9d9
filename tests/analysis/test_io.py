"""analysis.io.load_run: reads the contract, rejects unknown, old and malformed files."""

import json

import h5py
import numpy as np
import pytest

from analysis.io import RunFormatError, load_run
from synthetic_run import Scenario, paper_case


def test_reads_a_contract_file(run_file):
    path = run_file(paper_case())
    run = load_run(path)
    assert run.attrs["format_version"] == 1
    assert run.config["friction"]["f"] == 1.5
    n_out, n_c = run.interface.slip_velocity.shape
    assert n_c == 64 and run.interface.x.size == 64 and run.interface.t.size == n_out
    assert run.interface.state.dtype == np.int8
    assert run.global_series.T_over_N[0] == pytest.approx(0.95 * 1.5)
    assert run.attr("lambda") == 50.0


@pytest.mark.parametrize("version, message", [
    (0, "format_version 0 is not supported"),
    (2, "format_version 2 is not supported"),
    ("1", "expected the integer 1"),
    (1.5, "expected the integer 1"),
])
def test_rejects_other_format_versions(run_file, version, message):
    path = run_file(Scenario(format_version=version))
    with pytest.raises(RunFormatError, match=message):
        load_run(path)


def test_rejects_file_without_format_version(run_file):
    path = run_file(Scenario(drop_attributes=("format_version",)))
    with pytest.raises(RunFormatError, match="no 'format_version'"):
        load_run(path)


def test_version_is_checked_before_anything_else(tmp_path):
    path = tmp_path / "old.h5"
    with h5py.File(path, "w") as file:
        file.attrs["format_version"] = 0  # and nothing else
    with pytest.raises(RunFormatError, match="format_version 0"):
        load_run(path)


@pytest.mark.parametrize("scenario, message", [
    (Scenario(drop_attributes=("c_s", "config")), "missing: config, c_s"),
    (Scenario(drop_datasets=("/interface/opening",)), "'/interface/opening' is missing"),
    (Scenario(drop_datasets=("/global/energy_balance_residual",)), "energy_balance_residual' is missing"),
    (Scenario(creator="someone else"), "creator is 'someone else'"),
    (Scenario(config_text="{not json"), "'config' is not valid JSON"),
])
def test_rejects_malformed_files(run_file, scenario, message):
    with pytest.raises(RunFormatError, match=message):
        load_run(run_file(scenario))


def test_rejects_inconsistent_shapes_and_values(run_file):
    path = run_file(paper_case())
    with h5py.File(path, "a") as file:
        del file["/interface/slip"]
        file["/interface/slip"] = np.zeros((3, 64))
    with pytest.raises(RunFormatError, match=r"/interface/slip has shape \(3, 64\)"):
        load_run(path)
    path = run_file(paper_case(), name="nan.h5")
    with h5py.File(path, "a") as file:
        file["/global/T_over_N"][5] = np.nan
    with pytest.raises(RunFormatError, match="NaN where N != 0"):
        load_run(path)
    with h5py.File(path, "a") as file:  # the whole interface open: N = 0, T/N undefined, accepted
        file["/global/N"][5] = 0.0
    assert np.isnan(load_run(path).global_series.T_over_N[5])
    with h5py.File(path, "a") as file:
        file["/global/T"][5] = np.inf
    with pytest.raises(RunFormatError, match="non-finite"):
        load_run(path)
    path = run_file(paper_case(), name="period.h5")
    with h5py.File(path, "a") as file:
        file.attrs["lambda"] = 60.0
    with pytest.raises(RunFormatError, match="lambda"):
        load_run(path)


def test_rejects_non_hdf5_and_missing_files(tmp_path):
    text = tmp_path / "run.h5"
    text.write_text(json.dumps({"format_version": 1}))
    with pytest.raises(RunFormatError, match="not a readable HDF5 file"):
        load_run(text)
    with pytest.raises(RunFormatError, match="no such file"):
        load_run(tmp_path / "absent.h5")
