"""analysis/confidence/envelope.py: the envelope, the shifts per factor, the status of a cell, against
hand-computed values; the command line."""

import csv
import json
import math

import pytest

from analysis import cli
from analysis.confidence import envelope
from analysis.core.errors import InputError


def cell(nu=0.2, f=1.5, published=1.0, lo=1.06, hi=1.10, seed1=1.06, mean=1.08, group="g"):
    return {"nu": nu, "f": f, "published": published, "celerity_min": lo, "celerity_max": hi,
            "celerity_seed1": seed1, "celerity_mean": mean, "group": group}


def variant(factor, value, base, nu=0.2, f=1.5):
    return {"factor": factor, "label": factor, "values": {(nu, f): value}, "base_values": {(nu, f): base}}


def test_published_value_inside_the_envelope_through_the_mesh():
    (row,) = envelope.envelope_rows([cell()], [variant("mesh", 0.97, 1.05), variant("time step", 1.07, 1.06)], 0.05)
    assert row["envelope_min"] == 0.97 and row["envelope_max"] == 1.10
    assert row["status"] == "inside" and row["outside_by_rel"] == 0.0
    assert row["shift_mesh"] == pytest.approx(-0.08) and row["shift_time step"] == pytest.approx(0.01)
    assert row["shift_seed"] == pytest.approx(0.04)
    assert row["top_factor"] == "mesh" and row["top_shift"] == pytest.approx(-0.08)
    assert row["mean_dev"] == pytest.approx(0.08) and row["envelope_min_dev"] == pytest.approx(-0.03)


def test_outside_the_envelope_by_the_distance_to_the_nearer_bound():
    (row,) = envelope.envelope_rows([cell()], [variant("mesh", 1.04, 1.06)], 0.05)
    assert row["status"] == "outside" and row["outside_by_rel"] == pytest.approx(0.04)
    assert row["top_factor"] == "seed"


def test_within_tolerance_is_judged_on_the_ensemble_mean():
    (row,) = envelope.envelope_rows([cell(lo=0.9, hi=1.2, mean=1.04, seed1=1.2)], [], 0.05)
    assert row["status"] == "within"
    (row,) = envelope.envelope_rows([cell(lo=1.2, hi=1.2, mean=math.nan, seed1=1.2)], [], 0.05)
    assert row["status"] == "outside" and row["mean_dev"] is None


def test_a_front_in_the_other_direction_is_counted_not_enveloped():
    backward = cell(published=-2.5, lo=-2.7, hi=-2.6, seed1=-2.7, mean=-2.65)
    (row,) = envelope.envelope_rows([backward], [variant("time step", 1.0, -2.6)], 0.05)
    assert row["sign_flips"] == 1 and row["envelope_max"] == -2.6 and row["shift_time step"] is None
    assert row["status"] == "outside" and row["outside_by_rel"] == pytest.approx(0.04)


def test_unpublished_cells_are_left_out():
    assert envelope.envelope_rows([cell(published=math.nan)], [], 0.05) == []


def test_cell_values_refuse_two_runs_on_one_cell():
    rows = [{"nu": 0.2, "f": 1.5, "celerity": 1.0, "celerity_reason": "ok", "dt_times_cs": dt}
            for dt in (0.5, 1.0)]
    with pytest.raises(InputError, match="two runs"):
        envelope.cell_values(rows, {}, "t")
    assert envelope.cell_values(rows, {"dt_times_cs": 1.0}, "t") == {(0.2, 1.5): 1.0}


def write_csv(path, rows):
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return str(path)


def test_cli(tmp_path):
    ensemble = write_csv(tmp_path / "ensemble.csv", [cell()])
    run = {"nu": 0.2, "f": 1.5, "celerity": 0.96, "celerity_reason": "ok"}
    table = write_csv(tmp_path / "v.csv", [run])
    base = write_csv(tmp_path / "b.csv", [{**run, "celerity": 1.06}])
    spec = json.dumps({"variants": [{"factor": "mesh", "label": "H/32", "table": table, "base": base}]})
    out = tmp_path / "out"
    assert cli.main(["envelope", "--ensemble", ensemble, "--spec", spec, "-o", str(out)]) == 0
    (row,) = csv.DictReader(open(out / "envelope.csv"))
    assert row["status"] == "inside" and float(row["shift_mesh"]) == pytest.approx(-0.10)
    assert json.loads((out / "envelope_summary.json").read_text())["inside"] == 1
    bad = json.dumps({"variants": [{"factor": "seed", "label": "x", "table": table, "base": base}]})
    assert cli.main(["envelope", "--ensemble", ensemble, "--spec", bad, "-o", str(tmp_path / "bad")]) == 2
    assert not (tmp_path / "bad").exists()
