"""analysis.core.io.load_run: reads the contract, rejects unknown, old and malformed files."""

import json

import h5py
import numpy as np
import pytest

from analysis.core.io import InputError, load_run
from synthetic_run import Scenario, corrupt_stored_chunk, paper_case, store_with_filters


def test_reads_a_contract_file(run_file):
    path = run_file(paper_case())
    run = load_run(path)
    assert run.attrs["format_version"] == 2
    assert run.complete and run.end_reason == "t_end" and run.non_finite == ()
    assert run.setup["opening_threshold"] == pytest.approx(2.5e-4)
    assert run.attr("c_s") == run.setup["c_s"] and run.attr("n_steps_done") > 0
    assert '"friction"' in run.config_input
    assert run.config["friction"]["f"] == 1.5
    n_out, n_c = run.interface.slip_velocity.shape
    assert n_c == 64 and run.interface.x.size == 64 and run.interface.t.size == n_out
    assert run.interface.state.dtype == np.int8
    assert run.global_series.T_over_N[0] == pytest.approx(0.95 * 1.5)
    assert run.attr("lambda") == 50.0


@pytest.mark.parametrize("version, message", [
    (0, "format_version 0 is not supported"),
    (1, "format_version 1 is an older run-file format .*rerun the solver"),
    (4, "format_version 4 is not supported"),
    (3, "/setup attribute.*missing: substrate_E"),  # format 3 (a substrate) without its constants
    ("2", "expected the integer 2"),
    (1.5, "expected the integer 2"),
])
def test_rejects_other_format_versions(run_file, version, message):
    path = run_file(Scenario(format_version=version))
    with pytest.raises(InputError, match=message):
        load_run(path)


def test_reads_a_substrate_run_of_format_3(run_file):
    import h5py
    path = run_file(Scenario(format_version=3))
    constants = {"substrate_E": 3e3, "substrate_nu": 0.3, "substrate_rho": 2e3, "substrate_H": 25.0,
                 "substrate_c_s": 0.76, "substrate_c_l": 1.42, "substrate_return_time": 35.2}
    with h5py.File(path, "r+") as file:
        for name, value in constants.items():
            file["setup"].attrs[name] = value
    run = load_run(path)
    assert run.has_substrate
    assert run.attr("substrate_E") == 3e3 and run.attr("substrate_return_time") == 35.2


def test_a_rigid_flat_run_has_no_substrate(run_file):
    assert not load_run(run_file(Scenario())).has_substrate


def test_rejects_file_without_format_version(run_file):
    path = run_file(Scenario(drop_attributes=("format_version",)))
    with pytest.raises(InputError, match="no 'format_version'"):
        load_run(path)


def test_version_is_checked_before_anything_else(tmp_path):
    path = tmp_path / "old.h5"
    with h5py.File(path, "w") as file:
        file.attrs["format_version"] = 0  # and nothing else
    with pytest.raises(InputError, match="format_version 0"):
        load_run(path)


@pytest.mark.parametrize("scenario, message", [
    (Scenario(drop_attributes=("end_reason", "config")), "root attribute.* missing: config, end_reason"),
    (Scenario(drop_attributes=("c_s", "opening_threshold")),
     "/setup attribute.* missing: c_s, opening_threshold"),
    (Scenario(drop_attributes=("config_input",)), "/setup attribute.* missing: config_input"),
    (Scenario(drop_datasets=("/interface/opening",)), "'/interface/opening' is missing"),
    (Scenario(drop_datasets=("/global/energy_balance_residual",)), "energy_balance_residual' is missing"),
    (Scenario(creator="someone else"), "creator is 'someone else'"),
    (Scenario(config_text="{not json"), "'config' is not valid JSON"),
])
def test_rejects_malformed_files(run_file, scenario, message):
    with pytest.raises(InputError, match=message):
        load_run(run_file(scenario))


def test_rejects_inconsistent_shapes_and_values(run_file):
    path = run_file(paper_case())
    with h5py.File(path, "a") as file:
        del file["/interface/slip"]
        file["/interface/slip"] = np.zeros((3, 64))
    with pytest.raises(InputError, match=r"/interface/slip has shape \(3, 64\)"):
        load_run(path)
    path = run_file(paper_case(), name="nan.h5")
    with h5py.File(path, "a") as file:
        file["/global/T_over_N"][5] = np.nan
    with pytest.raises(InputError, match="NaN where N != 0"):
        load_run(path)
    with h5py.File(path, "a") as file:  # the whole interface open: N = 0, T/N undefined, accepted
        file["/global/N"][5] = 0.0
    assert np.isnan(load_run(path).global_series.T_over_N[5])
    with h5py.File(path, "a") as file:
        file["/global/T"][5] = np.inf
    with pytest.raises(InputError, match="non-finite"):
        load_run(path)
    path = run_file(paper_case(), name="period.h5")
    with h5py.File(path, "a") as file:
        file["setup"].attrs["lambda"] = 60.0
    with pytest.raises(InputError, match="lambda"):
        load_run(path)


def test_rejects_non_hdf5_and_missing_files(tmp_path):
    text = tmp_path / "run.h5"
    text.write_text(json.dumps({"format_version": 1}))
    with pytest.raises(InputError, match="not a readable HDF5 file"):
        load_run(text)
    with pytest.raises(InputError, match="no such file"):
        load_run(tmp_path / "absent.h5")


def test_config_input_must_be_an_attribute_not_a_dataset(run_file):
    path = run_file(Scenario(drop_attributes=("config_input",)))
    with h5py.File(path, "a") as file:
        file.create_dataset("/setup/config_input", data="{}")  # the old fixture's form
    with pytest.raises(InputError, match="missing: config_input"):
        load_run(path)


def test_non_finite_values_are_kept_for_an_incomplete_run_only(run_file):
    path = run_file(paper_case(complete=0, end_reason="contact_not_converged"))
    with h5py.File(path, "a") as file:
        file["/interface/opening"][-3:, 5] = np.inf
        file["/global/T"][-1] = np.nan
    run = load_run(path)
    assert run.non_finite == ("/interface/opening", "/global/T")
    with h5py.File(path, "a") as file:
        file.attrs["complete"] = 1
    with pytest.raises(InputError, match="'/interface/opening' holds non-finite values"):
        load_run(path)


def test_a_checksum_failure_names_the_file_and_the_dataset(run_file):
    path = run_file(paper_case())
    store_with_filters(path, "/interface/slip", fletcher32=True)
    assert load_run(path).interface.slip.shape[1] == 64  # intact, with its checksum: reads
    corrupt_stored_chunk(path, "/interface/slip")
    with pytest.raises(InputError, match=rf"{path}: dataset '/interface/slip' is corrupt: its HDF5 "
                                         "checksum does not match"):
        load_run(path)
