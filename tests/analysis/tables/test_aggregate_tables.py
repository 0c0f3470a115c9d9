"""analysis.tables.aggregate: what the tables say about runs that did not complete, and that
all_metrics.csv carries the metrics as measured (the paper and figures read them instead of
computing them)."""

import math

import pytest

from analysis.tables import aggregate as agg
from analysis.tables.reference import ReferenceCell

REFERENCE = [ReferenceCell(nu=0.2, f=1.5, celerity=2.0),
             ReferenceCell(nu=0.0, f=1.5, celerity=1.0)]


def metrics(nu, f, celerity, **extra):
    return {"nu": nu, "f": f, "celerity": celerity, "category": "intersonic_opening", "regime": "intersonic",
            "opening": True, "inversion": False, "min_T_over_N": 0.5, "complete": True,
            "end_reason": "stop_after_opening", **extra}


def test_a_run_that_did_not_complete_shows_its_end_reason_in_every_table():
    runs = [metrics(0.2, 1.5, 2.1, complete=False, end_reason="contact_not_converged"),
            metrics(0.0, 1.5, 1.0)]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    csv_rows = files["table1.csv"].splitlines()
    assert csv_rows[0].split(",")[-1] == "end_reason"
    assert csv_rows[1].endswith(",contact_not_converged") and csv_rows[2].endswith(",")
    assert "(run ended: contact_not_converged)" in files["table1.md"]
    assert files["table1.md"].count("run ended") == 1
    assert "run did not complete: contact not converged" in files["table1.tex"]


def test_complete_runs_leave_end_reason_empty_and_the_latex_without_a_note():
    runs = [metrics(0.2, 1.5, 2.1), metrics(0.0, 1.5, 1.0, end_reason="t_end")]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    assert all(line.endswith(",") for line in files["table1.csv"].splitlines()[1:])
    assert "did not complete" not in files["table1.tex"] and "run ended" not in files["table1.md"]


def test_all_metrics_csv_carries_every_metric_as_measured():
    # A run's derived quantities are metrics of analysis.metrics.measure: aggregate only aggregates.
    runs = [metrics(0.2, 1.6, 0.9, c_s=0.6, celerity_over_cs=1.5, inside_flutter_wedge=True)]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    header, row = files["all_metrics.csv"].splitlines()
    values = dict(zip(header.split(","), row.split(",")))
    assert values["celerity_over_cs"] == "1.5" and values["inside_flutter_wedge"] == "true"
    assert header.split(",") == ["metrics_file", *runs[0]]


def test_the_tables_read_back_as_written(tmp_path):
    """analysis.core.table_csv (the reader of figures/ and paper/) on aggregate's own output."""
    from analysis.core.errors import InputError
    from analysis.core.table_csv import read_table

    runs = [metrics(0.2, 1.5, 2.1, complete=False, end_reason="contact_not_converged", c_s=0.7)]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    (tmp_path / "table1.csv").write_text(files["table1.csv"])
    rows = read_table(tmp_path / "table1.csv", ("nu", "celerity", "within_tol", "end_reason"))
    assert rows[0]["celerity"] == 2.1 and rows[0]["within_tol"] is False
    assert rows[0]["end_reason"] == "contact_not_converged" and math.isnan(rows[1]["celerity"])
    with pytest.raises(InputError, match="missing required column.s. no_such_column"):
        read_table(tmp_path / "table1.csv", ("no_such_column",))


def test_a_cell_whose_run_shows_another_outcome_is_marked_and_never_reproduced():
    # Both within 5 % with the published sign and regime (intersonic: c_s = 0.645, c_l = 1.054 m/s at
    # nu = 0.2); the first run never opened.
    reference = [ReferenceCell(nu=0.2, f=1.5, celerity=0.9), ReferenceCell(nu=0.2, f=1.1, celerity=0.85)]
    runs = [metrics(0.2, 1.5, 0.91, category="no_opening", opening=False),
            metrics(0.2, 1.1, 0.86, category="intersonic_opening_inversion")]
    files, summary = agg.aggregate(runs, runs, reference, 0.05)
    rows = agg.table1_rows(runs, reference, 0.05)
    assert [r["published_category"] for r in rows] == ["intersonic_opening", "intersonic_opening"]
    assert [r["within_tol"] for r in rows] == [True, True]
    assert [r["category_match"] for r in rows] == [False, True]
    assert [r["reproduced"] for r in rows] == [False, True]
    assert summary["within_tolerance"] == 2 and summary["category_matches"] == 1 and summary["reproduced"] == 1
    assert summary["category_mismatches"] == ["nu=0.2 f=1.5"]
    assert "no_opening (published: intersonic_opening)" in files["table1.md"]


@pytest.mark.parametrize("celerity, category, published", [
    (-2.6, "supersonic_backward_opening", "supersonic_backward_opening"),
    (1.2, "supersonic_forward_opening", "supersonic_forward_opening"),  # nu = 0: c_l = 1.0 m/s
])
def test_the_published_category_follows_the_sign_and_regime_of_the_published_celerity(celerity, category, published):
    cell = ReferenceCell(nu=0.0, f=2.0, celerity=celerity)
    assert agg.published_category(cell) == published
    assert agg.category_matches(category, published)
    assert not agg.category_matches("opening_without_front", published)

