"""analysis/confidence/timeline.py: the slip-velocity maximum from a synthetic run, event statistics per set
against hand-computed values, the table's layout, and the CLI's errors."""

import json
import math

import numpy as np
import pytest

from analysis import cli
from analysis.confidence import timeline
from synthetic_run import Pulse, paper_case


def test_slip_velocity_maximum_is_the_time_of_the_largest_value_anywhere():
    t = np.array([0.0, 1.0, 2.0, 3.0])
    v = np.array([[0.0, 0.1], [0.2, -0.5], [0.4, 0.3], [np.nan, 0.0]])
    assert timeline.slip_velocity_max_time(t, v) == 1.0  # |-0.5| is the largest
    assert timeline.slip_velocity_max_time(t[:0], v[:0]) is None


def write_run_folder(run_file, tmp_path, name, seed, n, **events):
    folder = tmp_path / name
    folder.mkdir()
    # A pulse that decays from 900 s on: its largest slip velocity is at its start.
    run_file(paper_case(pulses=[Pulse(celerity=0.882, t_start=900.0, decay_time=50.0)]), name=f"{name}/run.h5")
    metrics = {"nu": 0.2, "f": 1.5, "elements_per_H": n, "seed": seed, "onset_time": 740.0,
               "localization_time": 900.0, "first_opening_time": math.nan, **events}
    (folder / "metrics.json").write_text(json.dumps(metrics))
    return folder


def test_run_events_read_metrics_and_the_run(run_file, tmp_path):
    folder = write_run_folder(run_file, tmp_path, "a", 1, 64, first_drop_start_time=850.0)
    row = timeline.run_events(folder)
    assert row["onset_time"] == 740.0 and row["first_drop_start_time"] == 850.0
    assert row["first_opening_time"] is None and row["min_T_over_N_time"] is None
    assert 900.0 <= row["slip_velocity_max_time"] <= 910.0


def rows(seed, n, **events):
    base = {"run": f"r{seed}", "nu": 0.2, "f": 1.5, "elements_per_H": n, "seed": seed}
    return {**base, **{key: events.get(key) for key in timeline.EVENTS}}


def test_statistics_per_set_and_difference_to_the_paper():
    seeds = [rows(1, 64, onset_time=740.0, localization_time=900.0),
             rows(2, 64, onset_time=750.0, localization_time=920.0),
             rows(3, 64, onset_time=745.0)]
    summary = timeline.summarize({"seeds": seeds})
    onset = summary["sets"]["seeds"]["events"]["onset_time"]
    assert (onset["n"], onset["mean"], onset["min"], onset["max"]) == (3, 745.0, 740.0, 750.0)
    assert onset["mean_minus_paper"] == pytest.approx(745.0 - 787.0)
    loc = summary["sets"]["seeds"]["events"]["localization_time"]
    assert loc["n"] == 2 and loc["mean"] == 910.0
    assert summary["sets"]["seeds"]["events"]["first_opening_time"]["mean"] is None


def test_table_gives_statistics_for_seeds_and_one_column_per_mesh():
    sets = {"seeds": [rows(1, 64, onset_time=740.0), rows(2, 64, onset_time=750.0)],
            "meshes": [rows(1, 128, onset_time=760.0), rows(1, 32, onset_time=730.0)]}
    text = timeline.latex(sets, timeline.summarize(sets))
    head = next(line for line in text.splitlines() if line.startswith("event"))
    assert head.index("$H/32$") < head.index("$H/128$")
    assert "first slip & 787 & 745 [740, 750] & 730 & 760" in text


def test_runs_of_two_cells_are_refused():
    other = dict(rows(2, 64), nu=0.3)
    with pytest.raises(timeline.InputError, match="several cells"):
        timeline.summarize({"seeds": [rows(1, 64), other]})


def test_cli_names_a_missing_metrics_file_and_writes_nothing(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    out = tmp_path / "out"
    assert cli.main(["timeline", "--set", "seeds", str(tmp_path / "empty"), "-o", str(out)]) == 2
    assert "metrics.json: cannot read" in capsys.readouterr().err and not out.exists()
