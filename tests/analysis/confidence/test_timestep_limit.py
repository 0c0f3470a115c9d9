"""analysis/confidence/timestep_limit.py: seed statistics per dt, every status of the dt -> 0 rule on
hand-made sequences, Adams' speed, the summary sentences, and the CLI."""

import csv
import json
import math

import pytest

from analysis import cli
from analysis.confidence import timestep_limit
from analysis.tables.reference import ReferenceCell
from analysis.theory import elastic, supersonic

REFERENCE = [ReferenceCell(0.45, 1.0, -2.523), ReferenceCell(0.49, 0.8, -5.253), ReferenceCell(0.2, 1.5, 0.882)]


def run(nu, f, dt, seed, celerity, reason="ok", n=64.0):
    return {"nu": nu, "f": f, "dt_times_cs": dt, "seed": float(seed), "celerity": celerity,
            "celerity_reason": reason, "elements_per_H": n}


def cell(nu, f, means, spread):
    """Runs at dt 0.5 ... 0.0625 with two seeds at mean +- spread/2."""
    return [run(nu, f, dt, seed, m + sign * spread / 2)
            for dt, m in zip((0.5, 0.25, 0.125, 0.0625), means) for seed, sign in ((1, -1), (2, 1))]


def statuses(runs):
    rows = timestep_limit.dt_rows(timestep_limit.unique_runs([runs]), {c.key: c.celerity for c in REFERENCE})
    return {(c["nu"], c["f"]): c for c in timestep_limit.cell_rows(rows, 0.05)}


def test_adams_celerity_is_minus_the_trace_speed():
    c_s = elastic.wave_speeds(0.45)[0]
    assert timestep_limit.adams_celerity(0.45, 1.0) == pytest.approx(-supersonic.supersonic_trace_speed(0.45, 1.0, c_s))
    assert timestep_limit.adams_celerity(0.45, 1.0) == pytest.approx(-2.245, abs=1e-3)


def test_seed_statistics_per_time_step_and_only_backward_published_cells():
    runs = cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02) + [run(0.2, 1.5, 0.5, 1, 0.8)]
    rows = timestep_limit.dt_rows(runs, {c.key: c.celerity for c in REFERENCE})
    assert [r["dt_times_cs"] for r in rows] == [0.5, 0.25, 0.125, 0.0625]
    first = rows[0]
    assert first["mean"] == pytest.approx(-2.66) and first["range"] == pytest.approx(0.02)
    assert (first["min"], first["max"]) == (pytest.approx(-2.67), pytest.approx(-2.65))
    assert first["dev_published"] == pytest.approx((-2.66 + 2.523) / 2.523)


def test_converging_sequence_gets_the_richardson_limit():
    c = statuses(cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02))[(0.45, 1.0)]
    assert c["status"] == "converging"
    assert c["d_prev"] == pytest.approx(0.10) and c["d_last"] == pytest.approx(0.05)
    assert c["value"] == pytest.approx(-2.20)  # r = 0.5: -2.25 + 0.05


def test_a_time_step_whose_runs_all_left_the_model_is_no_sample():
    runs = cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02)
    for r in runs:  # the smallest step's runs created energy: no front is measured on them
        if r["dt_times_cs"] == 0.0625:
            r.update(non_physical=True, celerity=math.nan, celerity_reason="no_major_front")
    rows = timestep_limit.dt_rows(runs, {c.key: c.celerity for c in REFERENCE})
    assert (rows[-1]["n_runs"], rows[-1]["n_backward"], rows[-1]["n_non_physical"]) == (0, 0, 2)
    assert rows[0]["n_non_physical"] == 0
    cells = timestep_limit.cell_rows(rows, 0.05)
    assert cells[0]["status"] == "left the model" and cells[0]["non_physical_dt"] == [0.0625]
    summary = timestep_limit.summarize(cells, {c.key: c.celerity for c in REFERENCE}, 0.05)
    assert summary["status_counts"]["left the model"] == 1
    assert "c_s = 0.0625$\\,m left the model" in summary["limit_sentence"]
    # A step where the physical runs show no backward front is another regime, whatever a smaller one does.
    for r in runs:
        if r["dt_times_cs"] == 0.125:
            r.update(celerity=0.8)
    assert statuses(runs)[(0.45, 1.0)]["status"] == "another regime"
    assert "0/0 (2 non-physical)" in timestep_limit.markdown(rows, [], {"limit_sentence": "", "theory_sentence": ""})


def test_differences_below_the_seed_spread_settle():
    c = statuses(cell(0.45, 1.0, (-2.66, -2.30, -2.32, -2.31), 0.05))[(0.45, 1.0)]
    assert c["status"] == "within seed spread" and c["value"] == pytest.approx(-2.31)
    assert c["value_halfwidth"] == pytest.approx(0.025)


@pytest.mark.parametrize("means", [(-2.66, -2.25, -2.50, -2.20), (-2.66, -2.60, -2.50, -2.30)])
def test_turning_or_growing_differences_do_not_converge(means):
    assert statuses(cell(0.45, 1.0, means, 0.01))[(0.45, 1.0)]["status"] == "not converging"


def test_shrinking_inside_the_seed_spread_is_only_within_the_spread():
    # d = 0.10 then 0.05, but the seeds spread 0.12 at the smallest dt: no Richardson limit.
    c = statuses(cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.12))[(0.45, 1.0)]
    assert c["status"] == "within seed spread" and c["value"] == pytest.approx(-2.25)


def test_forward_fronts_at_a_small_step_are_another_regime():
    runs = cell(0.49, 0.8, (-5.7, -4.6, -4.8, -4.9), 0.01)
    for r in runs:
        if r["dt_times_cs"] == 0.125:
            r["celerity"] = 2.1
    assert statuses(runs)[(0.49, 0.8)]["status"] == "another regime"


def test_a_run_in_two_tables_counts_once_and_meshes_must_not_mix():
    runs = cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02)
    rows = timestep_limit.dt_rows(timestep_limit.unique_runs([runs, runs[:2]]), {REFERENCE[0].key: -2.523})
    assert rows[0]["n_runs"] == 2
    with pytest.raises(timestep_limit.InputError, match="several meshes"):
        timestep_limit.dt_rows(runs + [run(0.45, 1.0, 0.5, 1, -2.6, n=32.0)], {REFERENCE[0].key: -2.523})


def test_summary_sentences_follow_the_counts():
    cells = list(statuses(cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02)
                          + cell(0.49, 0.8, (-5.7, -4.6, -5.2, -4.5), 0.01)).values())
    summary = timestep_limit.summarize(cells, {c.key: c.celerity for c in REFERENCE}, 0.05)
    assert summary["cells_settled"] == 1 and "in 1 of the 2 cells only" in summary["limit_sentence"]
    assert summary["ours_follow_theory"] == 1  # -2.20 vs -2.245: 2 %
    assert summary["published_backward_cells"] == 2 and summary["published_follow_theory"] == 0


def test_cli_writes_every_file_or_none(tmp_path, capsys):
    table = tmp_path / "m.csv"
    runs = cell(0.45, 1.0, (-2.66, -2.40, -2.30, -2.25), 0.02)
    with open(table, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(runs[0]))
        writer.writeheader()
        writer.writerows(runs)
    reference = tmp_path / "ref.csv"
    reference.write_text("nu,f,celerity_m_per_s\n0.45,1.0,-2.523\n0.2,1.5,0.882\n")
    out = tmp_path / "out"
    assert cli.main(["timestep-limit", str(table), "--reference", str(reference), "-o", str(out)]) == 0
    assert json.loads((out / "timestep_limit_summary.json").read_text())["status_counts"]["converging"] == 1
    assert len(list(out.iterdir())) == 5
    reference.write_text("nu,f,celerity_m_per_s\n0.2,1.5,0.882\n")
    bad = tmp_path / "bad"
    assert cli.main(["timestep-limit", str(table), "--reference", str(reference), "-o", str(bad)]) == 2
    assert "no run of a cell published with a backward celerity" in capsys.readouterr().err
    assert not bad.exists()
    assert math.isfinite(timestep_limit.adams_celerity(0.49, 0.8))
