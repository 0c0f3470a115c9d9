"""Faults on the analysis side (issue: trust under faults, items 1, 4, 8, 13).

Each test drives `python3 -m analysis` as a user would and asserts that nothing looking like a
result is left, that no input is destroyed, and that the message names the cause. Run files are the
synthetic ones of tests/support/synthetic_run.py (format_version 2); this file needs no conftest.
"""

import json
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
from synthetic_run import (Pulse, Scenario, corrupt_stored_chunk, paper_case,
                           store_with_filters, write_run)

REFERENCE = ROOT / "study" / "reference" / "table1_celerity.csv"


def analysis(*args):
    """(exit code, stdout, stderr) of `python3 -m analysis ARGS` from the repository root."""
    result = subprocess.run([sys.executable, "-m", "analysis", *map(str, args)], cwd=ROOT,
                            capture_output=True, text=True, timeout=300)
    assert "Traceback" not in result.stderr, result.stderr
    return result.returncode, result.stdout, result.stderr


def measured(tmp_path, scenario, *options, name="run.h5"):
    """Write a synthetic run, measure it; (exit code, metrics or None, stderr, run path)."""
    run = tmp_path / name
    write_run(run, scenario)
    out = tmp_path / (name + ".json")
    code, _, err = analysis("measure", run, "-o", out, *options)
    return code, (json.loads(out.read_text()) if out.exists() else None), err, run


# 1. Interrupted runs never look like results.

def test_an_interrupted_run_is_refused(tmp_path):
    code, metrics, err, run = measured(tmp_path, paper_case(complete=0, end_reason="interrupted"))
    assert code == 2 and metrics is None
    assert f"{run}: the run was interrupted" in err
    assert list(tmp_path.iterdir()) == [run]  # no metrics, no temporary file


def test_an_interrupted_run_is_measured_when_asked_and_says_so(tmp_path):
    code, metrics, err, _ = measured(tmp_path, paper_case(complete=0, end_reason="interrupted"),
                                     "--allow-incomplete")
    assert code == 0, err
    assert metrics["complete"] is False and metrics["end_reason"] == "interrupted"


def test_a_contact_failure_is_measured_and_flagged(tmp_path):
    code, metrics, err, _ = measured(tmp_path, paper_case(complete=0, end_reason="contact_not_converged"))
    assert code == 0, err
    assert metrics["complete"] is False and metrics["end_reason"] == "contact_not_converged"


# 4. measure X -o X destroys nothing.

def test_measure_onto_its_own_input_is_refused_before_writing(tmp_path):
    run = tmp_path / "run.h5"
    write_run(run, paper_case())
    before = run.read_bytes()
    (tmp_path / "alias.h5").symlink_to(run)
    for output in (run, tmp_path / "alias.h5"):
        code, _, err = analysis("measure", run, "-o", output)
        assert code == 2 and "the output is the input file" in err
        assert run.read_bytes() == before


# 8. Edge cases of measure.

def test_a_run_without_friction_is_measured(tmp_path):
    code, metrics, err, _ = measured(tmp_path, paper_case(f=0.0, ratio_knots=[(0.0, 0.0), (1500.0, 0.0)],
                                                          ratio_chatter=1e-17))
    assert code == 0, err
    assert metrics["n_drops"] == 0 and metrics["inversion"] is False


def test_an_opening_larger_than_the_layer_is_non_physical(tmp_path):
    scenario = Scenario(pulses=[Pulse(0.882, opening=398.0, opening_start=880.0)], complete=0,
                        end_reason="contact_not_converged")
    code, metrics, err, _ = measured(tmp_path, scenario)
    assert code == 0, err
    assert metrics["category"] == "non_physical" and metrics["non_physical"] is True
    assert "opening_above_H" in metrics["non_physical_reason"]


def test_a_run_that_blew_up_to_infinity_is_non_physical(tmp_path):
    run = tmp_path / "run.h5"
    write_run(run, paper_case(complete=0, end_reason="contact_not_converged"))
    with h5py.File(run, "a") as file:
        file["/interface/opening"][-5:, :] = np.inf
    out = tmp_path / "m.json"
    code, _, err = analysis("measure", run, "-o", out)
    assert code == 0, err
    metrics = json.loads(out.read_text())
    assert metrics["category"] == "non_physical"
    assert metrics["non_physical_reason"] == "non_finite: /interface/opening"


def test_a_run_that_created_energy_is_non_physical(tmp_path):
    # The top does 1 J/m of work; the layer ends up holding 3 J/m more than at the start: 2 J/m from nowhere.
    run = tmp_path / "run.h5"
    write_run(run, paper_case())
    with h5py.File(run, "a") as file:
        t = file["/global/t"][()]
        share = (t - t[0]) / (t[-1] - t[0])
        file["/global/work_external"][:] = share
        file["/global/energy_kinetic"][:] = 3.0 * share**2
        file["/global/energy_elastic"][:] = 5.0
        file["/global/dissipation_friction"][:] = 0.0
    out = tmp_path / "m.json"
    code, _, err = analysis("measure", run, "-o", out)
    assert code == 0, err
    metrics = json.loads(out.read_text())
    assert metrics["energy_created"] == pytest.approx(2.0 / 3.0, rel=1e-3)
    assert metrics["category"] == "non_physical" and metrics["non_physical"] is True
    assert metrics["non_physical_reason"].startswith("energy_created:")


def test_a_coarse_interface_stride_is_not_reported_as_no_slip(tmp_path):
    # The paper case opens; written every 200 steps (155 s, a third of a round trip per frame).
    code, metrics, err, _ = measured(tmp_path, paper_case(interface_stride=200))
    assert code == 0, err
    assert metrics["category"] == "sampling_too_coarse" and metrics["sampling_too_coarse"] is True


# 8. compare: nothing compared fails; --known-mismatch is validated.

def _table(tmp_path, rows):
    path = tmp_path / "table1.csv"
    path.write_text("nu,f,celerity\n" + "".join(f"{nu},{f},{c}\n" for nu, f, c in rows))
    return path


@pytest.mark.parametrize("options", [(), ("--ratchet",)])
def test_compare_with_nothing_compared_fails(tmp_path, options):
    for rows in ([], [(0.2, 1.5, "")], [(0.3, 7.0, 0.9)]):  # empty, unmeasured, unpublished cell
        code, out, _ = analysis("compare", _table(tmp_path, rows), "--reference", REFERENCE, *options)
        assert code == 1 and "FAIL" in out and "0 cells compared" in out, out


@pytest.mark.parametrize("value, message", [
    ("garbage", "expected \"nu=N f=F\""),
    ("nu=abc f=1.5", "expected \"nu=N f=F\""),
    ("nu=0.3 f=7", "no published cell nu=0.3 f=7"),
])
def test_compare_validates_known_mismatches(tmp_path, value, message):
    table = _table(tmp_path, [(0.2, 1.5, 0.88)])
    code, _, err = analysis("compare", table, "--reference", REFERENCE, "--ratchet",
                            "--known-mismatch", value)
    assert code == 2 and message in err


def test_compare_accepts_a_known_mismatch_of_a_published_cell(tmp_path):
    table = _table(tmp_path, [(0.2, 1.5, 0.88), (0.49, 1.5, 5.3)])
    code, out, err = analysis("compare", table, "--reference", REFERENCE, "--ratchet",
                              "--known-mismatch", "nu=0.49 f=1.50")
    assert code == 0, out + err
    assert "KNOWN WRONG SIGN nu=0.49 f=1.5" in out


# 13. Corruption is detected on read and reported with the file and the dataset.

@pytest.mark.parametrize("filters, words", [
    (dict(fletcher32=True), "checksum does not match"),
    (dict(compression="gzip"), "is corrupt"),
])
def test_a_corrupt_dataset_is_reported_with_file_and_dataset(tmp_path, filters, words):
    run = tmp_path / "run.h5"
    write_run(run, paper_case())
    store_with_filters(run, "/interface/slip_velocity", **filters)
    corrupt_stored_chunk(run, "/interface/slip_velocity")
    out = tmp_path / "m.json"
    code, _, err = analysis("measure", run, "-o", out)
    assert code == 2 and not out.exists()
    assert f"error: {run}: dataset '/interface/slip_velocity'" in err and words in err, err


# Issue 21 item 8: a damaged structure or an absurd declared size is an error naming the file, exit 2.

def _damage_object_header(run, name):
    """Flip the version byte of a dataset's object header (h5py then raises KeyError on opening it)."""
    with h5py.File(run, "r") as file:
        address = h5py.h5o.get_info(file[name].id).addr
    with open(run, "r+b") as stream:
        stream.seek(address)
        byte = stream.read(1)[0]
        stream.seek(address)
        stream.write(bytes([byte ^ 0xFF]))


def _declare(file, name, shape):
    """Replace a dataset by one that declares `shape` and stores nothing (chunks never written)."""
    del file[name]
    file.create_dataset(name, shape=shape, dtype="f8", chunks=(1024,) + shape[1:])


def _declare_huge_field(run):
    with h5py.File(run, "a") as file:
        _declare(file, "/interface/slip_velocity", (10**9, 16))


def _declare_huge_run(run):
    """Every interface and global dataset says 1e11 rows: consistent, and 100s of TB."""
    with h5py.File(run, "a") as file:
        n_c = file["/interface/x"].shape[0]
        for name in list(file["interface"]):
            if name != "x":
                _declare(file, f"/interface/{name}", (10**11,) if name == "t" else (10**11, n_c))
        for name in list(file["global"]):
            _declare(file, f"/global/{name}", (10**11,))


@pytest.mark.parametrize("damage, words", [
    (lambda run: _damage_object_header(run, "/interface/slip_velocity"), "damaged HDF5 structure (KeyError"),
    (_declare_huge_field, "/interface/slip_velocity has shape (1000000000, 16), expected (n_out, n_c)"),
    (_declare_huge_run, "of memory available"),
], ids=["object_header", "huge_field", "huge_run"])
def test_a_structurally_broken_run_file_is_an_error_naming_it(tmp_path, damage, words):
    run = tmp_path / "run.h5"
    write_run(run, paper_case())
    damage(run)
    out = tmp_path / "m.json"
    code, _, err = analysis("measure", run, "-o", out)
    assert code == 2 and not out.exists(), err
    assert err.startswith(f"error: {run}: ") and words in err, err
    assert len(err.strip().splitlines()) == 1, err
