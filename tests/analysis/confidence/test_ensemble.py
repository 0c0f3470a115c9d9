"""analysis/confidence/ensemble.py: grouping by seed, per-cell statistics against hand-computed values, groups,
the CLI's outputs and errors."""

import csv
import json
import math
import statistics

import pytest

from analysis import cli
from analysis.confidence import ensemble
from analysis.core.errors import InputError
from analysis.tables.reference import ReferenceCell

REFERENCE = [ReferenceCell(0.2, 1.5, 1.0), ReferenceCell(0.45, 1.0, -2.5), ReferenceCell(0.0, 1.1, 0.86)]


def run(nu, f, seed, celerity, category="intersonic_opening_inversion", reason="ok", n=64):
    return {"nu": nu, "f": f, "seed": float(seed), "celerity": celerity, "celerity_reason": reason,
            "category": category, "elements_per_H": float(n), "integration": "reduced"}


def test_statistics_of_one_cell_against_hand_computed_values():
    runs = [run(0.2, 1.5, 1, 0.96), run(0.2, 1.5, 2, 1.00), run(0.2, 1.5, 3, 1.10),
            run(0.2, 1.5, 4, math.nan, category="opening_without_front", reason="no_major_front")]
    row = ensemble.cell_statistics(runs, REFERENCE[0], tolerance=0.05)
    assert row["n_runs"] == 4 and row["n_front"] == 3
    assert row["celerity_mean"] == pytest.approx((0.96 + 1.00 + 1.10) / 3)
    assert row["celerity_std"] == pytest.approx(statistics.stdev([0.96, 1.00, 1.10]))
    assert (row["celerity_min"], row["celerity_max"]) == (0.96, 1.10)
    assert row["celerity_seed1"] == 0.96
    assert row["majority_category"] == "intersonic_opening_inversion"
    assert row["category_agreement"] == pytest.approx(0.75)
    assert row["deviation_seed1_rel"] == pytest.approx(-0.04) and row["within_tol_seed1"] is True
    assert row["deviation_mean_rel"] == pytest.approx(0.02) and row["within_tol_mean"] is True
    assert row["spread_rel"] == pytest.approx(row["celerity_std"])
    assert row["group"] == "nu 0.1-0.2, f >= 1.5"


def test_deviation_is_relative_to_the_magnitude_of_a_backward_celerity():
    runs = [run(0.45, 1.0, 1, -2.75, "supersonic_backward_opening"),
            run(0.45, 1.0, 2, -2.25, "supersonic_backward_opening")]
    row = ensemble.cell_statistics(runs, REFERENCE[1], tolerance=0.05)
    assert row["deviation_seed1_rel"] == pytest.approx(-0.1)  # faster backward: more negative
    assert row["deviation_mean_rel"] == pytest.approx(0.0)
    assert row["within_tol_seed1"] is False and row["within_tol_mean"] is True
    assert row["group"] == "supersonic backward"


def test_a_front_against_the_published_direction_is_counted_not_averaged():
    # nu = 0.45, f = 1.2 at H/128: two seeds backward, one forward (another wave).
    runs = [run(0.45, 1.0, 1, -2.6, "supersonic_backward_opening"), run(0.45, 1.0, 2, 0.75),
            run(0.45, 1.0, 3, -2.4, "supersonic_backward_opening")]
    row = ensemble.cell_statistics(runs, REFERENCE[1], tolerance=0.05)
    assert row["n_front"] == 2 and row["n_opposite"] == 1
    assert row["celerity_mean"] == pytest.approx(-2.5) and row["celerity_max"] == -2.4
    assert row["within_tol_mean"] is True


def test_a_cell_where_most_seeds_run_the_other_way_is_never_within():
    runs = [run(0.45, 1.0, 1, 0.7), run(0.45, 1.0, 2, 0.75),
            run(0.45, 1.0, 3, -2.5, "supersonic_backward_opening")]
    row = ensemble.cell_statistics(runs, REFERENCE[1], tolerance=0.05)
    assert row["celerity_mean"] == -2.5 and row["deviation_mean_rel"] == 0.0
    assert row["n_opposite"] == 2 and row["within_tol_mean"] is False


def test_an_unpublished_cell_takes_the_direction_of_most_fronts_and_a_tie_the_lowest_seed():
    most = [run(0.3, 0.7, 1, -2.0), run(0.3, 0.7, 2, 0.6), run(0.3, 0.7, 3, 0.8)]
    row = ensemble.cell_statistics(most, None, tolerance=0.05)
    assert row["celerity_mean"] == pytest.approx(0.7) and row["n_opposite"] == 1
    tie = [run(0.3, 0.7, 2, 0.6), run(0.3, 0.7, 1, -2.0)]
    row = ensemble.cell_statistics(tie, None, tolerance=0.05)
    assert row["celerity_mean"] == -2.0 and row["n_opposite"] == 1


def test_a_cell_without_any_front_has_no_celerity_statistics():
    runs = [run(0.0, 1.1, s, math.nan, "no_opening", "no_major_front") for s in (1, 2)]
    row = ensemble.cell_statistics(runs, REFERENCE[2], tolerance=0.05)
    assert row["n_front"] == 0 and row["celerity_mean"] is None and row["deviation_mean_rel"] is None
    assert row["within_tol_mean"] is None and row["category_agreement"] == 1.0
    assert row["group"] == "nu 0-0.1, f 1.1-1.2"


def test_runs_are_grouped_by_every_parameter_but_the_seed():
    rows = [run(0.2, 1.5, 1, 1.0), run(0.2, 1.5, 2, 1.0), run(0.2, 1.5, 1, 1.0, n=32)]
    groups = ensemble.group_runs(rows)
    assert sorted(len(g) for g in groups) == [1, 2]


def test_a_seed_twice_in_one_cell_is_an_error():
    with pytest.raises(InputError, match="seed 1 appears 2 times"):
        ensemble.group_runs([run(0.2, 1.5, 1, 1.0), run(0.2, 1.5, 1, 1.0)])


def test_groups_of_the_published_cells():
    assert ensemble.group_of(ReferenceCell(0.1, 1.2, 0.9)) == "nu 0-0.1, f 1.1-1.2"
    assert ensemble.group_of(ReferenceCell(0.1, 1.8, 0.9)) == "nu 0.1-0.2, f >= 1.5"
    assert ensemble.group_of(ReferenceCell(0.3, 1.5, 0.9)) == "the rest"
    assert ensemble.group_of(ReferenceCell(0.49, 0.5, -5.25)) == "supersonic backward"
    assert ensemble.group_of(None) == "unpublished"


def test_summary_counts_and_group_means():
    rows = ensemble.ensemble_rows(
        [run(0.2, 1.5, 1, 1.00), run(0.2, 1.5, 2, 1.20),                # seed 1 within, mean +10 %
         run(0.45, 1.0, 1, -2.75, "supersonic_backward_opening"),       # seed 1 -10 %, mean -5 %
         run(0.45, 1.0, 2, -2.50, "supersonic_backward_opening")],
        REFERENCE, tolerance=0.05)
    summary = ensemble.summarize(rows, 0.05)
    assert summary["within_tol_seed1"] == 1 and summary["within_tol_mean"] == 1
    assert summary["runs"] == 4 and summary["cells"] == 2
    group = summary["groups"]["supersonic backward"]
    assert group["cells"] == 1 and group["deviation_mean_rel_mean"] == pytest.approx(-0.05)
    assert summary["groups"]["nu 0.1-0.2, f >= 1.5"]["deviation_mean_rel_mean"] == pytest.approx(0.1)


def test_cli_writes_every_table(tmp_path):
    metrics = tmp_path / "all_metrics.csv"
    rows = [run(0.2, 1.5, s, c) for s, c in ((1, 1.0), (2, 1.02), (3, 0.98))]
    with open(metrics, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    reference = tmp_path / "ref.csv"
    reference.write_text("nu,f,celerity_m_per_s\n0.2,1.5,1.0\n")
    out = tmp_path / "out"
    assert cli.main(["ensemble", str(metrics), "--reference", str(reference), "-o", str(out)]) == 0
    table = list(csv.DictReader(open(out / "ensemble.csv")))
    assert len(table) == 1 and float(table[0]["celerity_mean"]) == pytest.approx(1.0)
    assert table[0]["n_front"] == "3" and table[0]["within_tol_mean"] == "true"
    assert json.loads((out / "ensemble_summary.json").read_text())["within_tol_mean"] == 1
    assert r"\toprule" in (out / "ensemble.tex").read_text()
    assert "0.2 | 1.50" in (out / "ensemble.md").read_text()


def test_cli_names_a_missing_column_and_writes_nothing(tmp_path, capsys):
    metrics = tmp_path / "all_metrics.csv"
    metrics.write_text("nu,f,celerity\n0.2,1.5,1.0\n")
    out = tmp_path / "out"
    assert cli.main(["ensemble", str(metrics), "-o", str(out)]) == 2
    assert "seed" in capsys.readouterr().err and not out.exists()
