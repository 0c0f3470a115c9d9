"""analysis.aggregate: what the tables say about runs that did not complete, and the columns the
paper and figures read instead of computing them."""

import math

from analysis import aggregate as agg
from analysis.reference import ReferenceCell

REFERENCE = [ReferenceCell(nu=0.2, f=1.5, celerity=2.0),
             ReferenceCell(nu=0.0, f=1.5, celerity=1.0)]


def metrics(nu, f, celerity, **extra):
    return {"nu": nu, "f": f, "celerity": celerity, "category": "intersonic_opening", "regime": "intersonic",
            "opening": True, "inversion": False, "min_T_over_N": 0.5, "run_complete": True,
            "end_reason": "stop_after_opening", **extra}


def test_a_run_that_did_not_complete_shows_its_end_reason_in_every_table():
    runs = [metrics(0.2, 1.5, 2.1, run_complete=False, end_reason="contact_not_converged"),
            metrics(0.0, 1.5, 1.0)]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    csv_rows = files["table1.csv"].splitlines()
    assert csv_rows[0].split(",")[-1] == "end_reason"
    assert csv_rows[1].endswith(",contact_not_converged") and csv_rows[2].endswith(",")
    assert "(run ended: contact_not_converged)" in files["table1.md"]
    assert files["table1.md"].count("run ended") == 1
    assert r"run did not complete: contact\_not\_converged" in files["table1.tex"]


def test_complete_runs_leave_end_reason_empty_and_the_latex_without_a_note():
    runs = [metrics(0.2, 1.5, 2.1), metrics(0.0, 1.5, 1.0, end_reason="t_end")]
    files, _ = agg.aggregate(runs, runs, REFERENCE, 0.05)
    assert all(line.endswith(",") for line in files["table1.csv"].splitlines()[1:])
    assert "did not complete" not in files["table1.tex"] and "run ended" not in files["table1.md"]
