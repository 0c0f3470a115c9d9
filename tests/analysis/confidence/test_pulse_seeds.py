"""analysis/confidence/pulse_seeds.py: major-pulse counts per period across seeds, the agreement with the
count the celerity predicts, the later drops, and the CLI's error for a missing cell."""

import math

import pytest

from analysis import cli
from analysis.confidence import pulse_seeds


def run(lam, seed, count, theory, later=math.nan, end="stop_after_opening", n=64.0, nu=0.2, f=1.5, strength=0.3):
    return {"nu": nu, "f": f, "seed": float(seed), "lambda_over_H": lam, "elements_per_H": n,
            "pulse_count": float(count), "pulse_count_theory": float(theory), "pulse_next_strength": strength,
            "later_drops_start_T_over_N_median": later, "end_reason": end}


def test_counts_per_period_and_agreement_with_paper_and_prediction():
    runs = [run(2.0, 1, 2, 1), run(2.0, 2, 1, 1), run(2.0, 3, 1, 1, strength=0.45),
            run(4.0, 1, 2, 3), run(4.0, 2, 3, 3), run(2.0, 1, 3, 1, later=0.65, end="t_end"),
            run(2.0, 1, 9, 9, nu=0.3)]
    rows = pulse_seeds.count_rows(pulse_seeds.unique_runs([runs, runs[:2]], (0.2, 1.5)))
    by = {(r["lambda_over_H"], r["run_length"]): r for r in rows}
    first = by[(2.0, "first event")]
    assert first["counts"] == "2 1 1" and first["count_mode"] == 1 and first["n_runs"] == 3
    assert first["count_mean"] == pytest.approx(4 / 3)
    assert first["runs_at_paper_count"] == 2 and first["runs_count_equals_theory"] == 2
    assert first["next_strength_median"] == pytest.approx(0.3)
    assert by[(4.0, "first event")]["runs_at_paper_count"] == 1
    assert by[(4.0, "first event")]["runs_count_equals_theory"] == 1
    assert by[(2.0, "long")]["counts"] == "3"


def test_mode_prefers_the_smaller_count_on_a_tie():
    rows = pulse_seeds.count_rows([run(4.0, 1, 2, 3), run(4.0, 2, 3, 3)])
    assert rows[0]["count_mode"] == 2


def test_later_drops_and_sentences():
    runs = [run(2.0, 1, 2, 1), run(2.0, 1, 3, 1, later=0.65, end="t_end"), run(4.0, 2, 2, 2, later=0.75, end="t_end")]
    drops = pulse_seeds.later_drops(runs)
    assert drops["runs_with_later_drops"] == 2 and drops["mean"] == pytest.approx(0.70)
    assert (drops["min"], drops["max"]) == (0.65, 0.75) and drops["runs_stopped_after_opening"] == 1
    summary = pulse_seeds.summarize(pulse_seeds.count_rows(runs), drops, (0.2, 1.5))
    assert "0.70 (range 0.65--0.75) in the 2 runs" in summary["later_sentence"]
    assert "1 of the 3 runs stop after the first opening" in summary["later_sentence"]
    assert "paper's count in 0 of the 1 runs" in summary["count_sentence"]
    none = pulse_seeds.summarize([], pulse_seeds.later_drops(runs[:1]), (0.2, 1.5))
    assert none["later_sentence"].startswith("No run has a later drop.")


def test_cli_names_the_missing_cell(tmp_path, capsys):
    table = tmp_path / "m.csv"
    row = run(2.0, 1, 1, 1, nu=0.3)
    table.write_text(",".join(row) + "\n" + ",".join(str(v) for v in row.values()) + "\n")
    out = tmp_path / "out"
    assert cli.main(["pulse-seeds", str(table), "-o", str(out)]) == 2
    assert "no run of the cell nu=0.2 f=1.5" in capsys.readouterr().err and not out.exists()
    assert cli.main(["pulse-seeds", str(table), "--cell", "0.3", "1.5", "-o", str(out)]) == 0
    assert (out / "pulse_seeds_summary.json").exists()
