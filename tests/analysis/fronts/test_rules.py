"""analysis.fronts.rules on synthetic interface maps with known fronts (docs/measurement-rule.md)."""

import json
import math

import pytest

from analysis.core.io import load_run
from analysis.fronts import celerity as cel
from analysis.fronts import rules
from analysis.fronts.tracking import find_edges
from analysis.metrics import opening
from analysis.metrics.measure import measure_run
from synthetic_run import OPENING_THRESHOLD_REL, UY_OVER_H, H, Pulse, Scenario, build_fields, paper_case, wave_speeds

OPENING_THRESHOLD = OPENING_THRESHOLD_REL * abs(UY_OVER_H) * H


def measure_all(scenario):
    """Every rule on a scenario's maps, with analysis.metrics.measure's settings (10 V0, 0.1 c_s)."""
    d = build_fields(scenario)
    c_s = wave_speeds(scenario.nu)[0]
    threshold = 10 * d["V0"]
    front_map = find_edges(d["x"], d["t"], d["v"], threshold)
    localization = cel.celerity_from_fronts(front_map, min_speed=0.1 * c_s)
    opened = opening.summarize_opening(d["x"], d["t"], d["u_y"], OPENING_THRESHOLD)
    results = rules.measure_rules(d["x"], d["t"], d["v"], d["u_y"], front_map, localization,
                                  slip_threshold=threshold, opening_threshold=OPENING_THRESHOLD,
                                  first_opening_time=opened.t_first, min_speed=0.1 * c_s)
    return results, localization, opened, d


def precursor_then_opening_pulse():
    """nu = 0: a strong precursor near c_l (1 m/s) from 800 s that dies at 910 s and never opens,
    then a weaker, slower pulse (0.8 m/s) from 905 s that opens from 960 s on."""
    return Scenario(nu=0.0, f=1.1, t_stop=1400.0, pulses=[
        Pulse(celerity=0.98, x_front=10.0, t_start=800.0, t_end=910.0, amplitude=3e-3),
        Pulse(celerity=0.80, x_front=35.0, t_start=905.0, amplitude=1.2e-3, opening=0.01,
              opening_start=960.0)])


def test_precursor_is_localization_and_the_opening_pulse_is_opening_pulse():
    results, localization, opened, d = measure_all(precursor_then_opening_pulse())
    assert results["localization"].celerity == localization.celerity  # the first rule, unchanged
    assert results["localization"].celerity == pytest.approx(0.98, rel=5e-3)
    pulse = results["opening_pulse"]
    assert pulse.reason == "ok"
    assert pulse.celerity == pytest.approx(0.80, rel=5e-3)
    # The window starts at the pulse's localization (first output at or after 905 s).
    assert pulse.window[0] == pytest.approx(d["t"][d["t"] >= 905.0][0])
    assert results["opening_pulse_from_opening"].celerity == pytest.approx(0.80, rel=5e-3)
    # The geometric check, on the opening map, sees the same pulse.
    assert results["opening_front"].celerity == pytest.approx(0.80, rel=5e-3)
    assert results["opening_front"].window[0] == pytest.approx(opened.t_first)


def test_opening_pulse_from_opening_starts_at_the_first_opening():
    results, _, opened, d = measure_all(precursor_then_opening_pulse())
    first_open = d["t"][d["t"] >= 960.0][0]
    assert opened.t_first == pytest.approx(first_open)
    window = results["opening_pulse_from_opening"].window
    assert window[0] == pytest.approx(first_open)
    assert window[1] - window[0] == pytest.approx(rules.cel.DEFAULT_WINDOW_LENGTH, abs=d["t"][1] - d["t"][0])


def test_pulse_opening_time_is_when_the_run_bounded_by_the_front_opens():
    _, localization, _, d = measure_all(precursor_then_opening_pulse())
    from analysis.fronts.edges import PeriodicGrid
    grid = PeriodicGrid.from_nodes(d["x"])
    times = {round(track.start): rules.pulse_opening_time(track, d["t"], d["v"], d["u_y"],
                                                          10 * d["V0"], OPENING_THRESHOLD, grid)
             for track, _ in localization.major}
    precursor = [t for start, t in times.items() if start < 850]
    opening_pulse = [t for start, t in times.items() if start >= 900]
    assert precursor and all(math.isnan(t) for t in precursor)
    assert opening_pulse and opening_pulse[0] == pytest.approx(d["t"][d["t"] >= 960.0][0])


@pytest.mark.parametrize("celerity", [0.9, -0.9])
def test_deceleration_has_the_sign_and_size_of_the_slowing(celerity):
    # |c| falls linearly from 0.9 by 5e-4 m/s^2: over a window of length T the least-squares slope
    # of each half is the speed at its middle, so the deceleration is -a (T/2) / c(T/2).
    a = 5e-4
    results, _, _, _ = measure_all(Scenario(pulses=[Pulse(celerity, deceleration=a)]))
    r = results["localization"]
    span = r.window[1] - r.window[0]
    expected = -a * span / 2 / (abs(celerity) - a * span / 2)
    assert expected == pytest.approx(-0.06, abs=0.01)
    assert r.deceleration == pytest.approx(expected, rel=0.1)


def test_a_steady_front_does_not_decelerate():
    results, _, _, _ = measure_all(Scenario(pulses=[Pulse(0.882)]))
    assert abs(results["localization"].deceleration) < 5e-3


def test_late_window_ends_at_the_last_output():
    results, _, _, d = measure_all(paper_case(t_stop=2000.0))  # the pulse lives to the end
    late = results["late"]
    assert late.reason == "ok"
    assert late.window[1] == pytest.approx(d["t"][-1])
    assert late.window[0] >= d["t"][-1] - rules.cel.DEFAULT_WINDOW_LENGTH - 1e-9
    assert late.celerity == pytest.approx(0.882, rel=5e-3)


def test_first_100s_fits_the_strongest_front_over_its_first_100_s():
    results, _, _, d = measure_all(precursor_then_opening_pulse())
    first = results["first_100s"]
    assert first.celerity == pytest.approx(0.98, rel=5e-3)  # the precursor is the stronger
    assert first.window[1] - first.window[0] <= rules.DEFAULT_FIRST_WINDOW_LENGTH + 1e-9


def test_opening_free_run_has_no_opening_rules_with_a_reason():
    results, _, opened, _ = measure_all(Scenario(pulses=[Pulse(0.882)]))
    assert not opened.opened
    for name in ("opening_pulse", "opening_pulse_from_opening", "opening_front"):
        assert math.isnan(results[name].celerity) and results[name].reason == "no_opening"
        assert results[name].window is None
    assert results["localization"].reason == "ok"


def test_opening_outside_every_major_pulse_is_no_opening_pulse():
    # The interface opens only under a short-lived pulse (not major: < 100 s), which runs 20 m
    # behind the major one and never touches it.
    scenario = Scenario(pulses=[Pulse(0.882),
                                Pulse(0.882, x_front=25.0, t_start=900.0, t_end=950.0, opening=0.01,
                                      opening_start=910.0)])
    results, _, opened, _ = measure_all(scenario)
    assert opened.opened
    assert results["opening_pulse"].reason == "no_opening_pulse"
    assert math.isnan(results["opening_pulse"].celerity)


def test_every_metrics_file_carries_every_rule(run_file):
    metrics = measure_run(load_run(run_file(paper_case())))
    assert metrics["celerity_rule_default"] == "opening_pulse" == rules.DEFAULT_RULE
    for name in rules.RULES:
        for suffix in ("", "_window", "_deceleration", "_reason"):
            assert f"celerity_rule_{name}{suffix}" in metrics
    assert metrics["celerity"] == metrics["celerity_rule_opening_pulse"]
    assert metrics["celerity_window"] == metrics["celerity_rule_opening_pulse_window"]
    # The paper case's pulse is the one that opens: opening_pulse coincides with localization.
    assert metrics["celerity_rule_localization"] == metrics["celerity"]
    assert metrics["celerity_rule_opening_pulse_from_opening"] == pytest.approx(0.882, rel=5e-3)
    json.dumps(metrics, allow_nan=False)


# ---------------------------------------------------------------------------------------------
# analysis score-rules


def rule_metrics_file(tmp_path, name, nu, f, by_rule, **changes):
    """A metrics file of a (nu, f) cell with the given rule celerities (others undefined)."""
    c_s, c_l = wave_speeds(nu)
    metrics = {"nu": nu, "f": f, "celerity": by_rule.get("opening_pulse"), "c_s": c_s, "c_l": c_l,
               "opening": True, "complete": True, "non_physical": False,
               "sampling_too_coarse": False, "celerity_rule_default": "opening_pulse"}
    for rule in rules.RULES:
        metrics[f"celerity_rule_{rule}"] = by_rule.get(rule)
        metrics[f"celerity_rule_{rule}_reason"] = "ok" if rule in by_rule else "empty_window"
    metrics.update(changes)
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(metrics))
    return path


def run_cli(*args):
    import subprocess
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[3]
    return subprocess.run([sys.executable, "-m", "analysis", *map(str, args)], cwd=root,
                          capture_output=True, text=True, timeout=120)


def scored(tmp_path, files, tolerance=0.05):
    from analysis.tables.aggregate import load_metrics
    from analysis.tables.reference import read_reference
    from analysis.tables.rule_scores import rule_scores
    scores = rule_scores([load_metrics(p) for p in files], read_reference(), tolerance)
    return {s["rule"]: s for s in scores}


def test_score_rules_counts_sign_regime_tolerance_per_rule(tmp_path):
    files = [
        # nu = 0.2, f = 1.5 (published 0.882): within 5 % under localization, 10 % low under late.
        rule_metrics_file(tmp_path, "a", 0.2, 1.5, {"localization": 0.90, "late": 0.79,
                                                     "opening_pulse": 0.88}),
        # nu = 0.45, f = 1 (published -2.523, supersonic): wrong sign (regime from |c|: supersonic)
        # under localization; right sign but intersonic (|c| < c_l = 1.95) under opening_pulse.
        rule_metrics_file(tmp_path, "b", 0.45, 1.0, {"localization": 2.5, "opening_pulse": -1.5}),
        # nu = 0, f = 1.5 (published 0.982): within under both, but the run never opens.
        rule_metrics_file(tmp_path, "c", 0.0, 1.5, {"localization": 0.98, "opening_pulse": 0.98},
                          opening=False),
    ]
    s = scored(tmp_path, files)
    assert s["opening_pulse"]["default"] and not s["localization"]["default"]
    loc, pulse, late = s["localization"], s["opening_pulse"], s["late"]
    assert (loc["cells_published"], loc["cells_measured"], loc["cells_excluded"]) == (38, 2, 36)
    assert (loc["sign_matches"], loc["regime_matches"], loc["within_tolerance"], loc["reproduced"]) == (1, 2, 1, 1)
    assert (pulse["sign_matches"], pulse["regime_matches"], pulse["within_tolerance"], pulse["reproduced"]) == (2, 1, 1, 1)
    assert (late["cells_measured"], late["within_tolerance"], late["reproduced"]) == (1, 0, 0)
    assert late["median_abs_deviation"] == pytest.approx(abs(0.79 - 0.882) / 0.882)
    assert s["first_100s"]["cells_measured"] == 0 and s["first_100s"]["median_abs_deviation"] is None


@pytest.mark.parametrize("flag", [dict(non_physical=True), dict(sampling_too_coarse=True),
                                  dict(complete=False), dict(opening=False)])
def test_score_rules_flagged_runs_are_not_reproduced_under_any_rule(tmp_path, flag):
    good = {rule: 0.882 for rule in rules.RULES}
    s = scored(tmp_path, [rule_metrics_file(tmp_path, "a", 0.2, 1.5, good, **flag)])
    assert all(score["reproduced"] == 0 and score["cells_measured"] == 0 for score in s.values())
    s = scored(tmp_path, [rule_metrics_file(tmp_path, "a", 0.2, 1.5, good)])
    assert all(score["reproduced"] == 1 for score in s.values())


def test_score_rules_command_prints_and_writes_csv(tmp_path):
    files = [rule_metrics_file(tmp_path, "a", 0.2, 1.5, {"opening_pulse": 0.90, "late": 0.79})]
    out = tmp_path / "out" / "scores.csv"
    result = run_cli("score-rules", *files, "--tolerance", "0.05", "--out", out)
    assert result.returncode == 0, result.stderr
    assert "opening_pulse *" in result.stdout and "localization *" not in result.stdout
    lines = out.read_text().splitlines()
    assert lines[0].startswith("rule,default,cells_published,cells_measured")
    assert [line.split(",")[0] for line in lines[1:]] == list(rules.RULES)
    assert lines[2].split(",")[1:9] == ["true", "38", "1", "37", "1", "1", "1", "1"]
    assert lines[1].split(",")[1:4] == ["false", "38", "0"]
    assert [p.name for p in out.parent.iterdir()] == ["scores.csv"]  # no temporary left


def test_score_rules_writes_the_report_table_with_the_default_marked(tmp_path):
    files = [rule_metrics_file(tmp_path, "a", 0.2, 1.5, {"opening_pulse": 0.90, "late": 0.79}),
             rule_metrics_file(tmp_path, "b", 0.45, 1.0, {"opening_pulse": -2.40, "localization": 2.5})]
    out = tmp_path / "table"
    result = run_cli("score-rules", *files, "--tolerance", "0.05", "-o", out)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in out.iterdir()) == ["rule_scores.csv", "rule_scores.md", "rule_scores.tex"]
    from analysis.core.table_csv import read_table
    rows = {r["rule"]: r for r in read_table(out / "rule_scores.csv", ("rule", "default", "reproduced"))}
    assert [r["default"] for r in rows.values()] == [rule == "opening_pulse" for rule in rules.RULES]
    # opening_pulse: 0.90 vs 0.882 (+2.0 %) and -2.40 vs -2.523 (-4.9 %): both within 5 %.
    assert rows["opening_pulse"]["reproduced"] == 2
    assert rows["opening_pulse"]["median_abs_deviation"] == pytest.approx(
        0.5 * ((0.90 - 0.882) / 0.882 + (2.523 - 2.40) / 2.523), rel=1e-5)
    tex = (out / "rule_scores.tex").read_text()
    marked = [line for line in tex.splitlines() if "(default)" in line]
    assert len(marked) == 1 and marked[0].startswith(r"\texttt{opening\_pulse} (default)")
    # measured, excluded, sign, regime, within, reproduced, median |dev| (%) of the default rule.
    assert marked[0].split(" & ")[1:] == ["2", "36", "2", "2", "2", "2", r"3.5 \\"]
    assert tex.count(r"\\") == len(rules.RULES) + 1 and r"\bottomrule" in tex
    md = (out / "rule_scores.md").read_text()
    assert md.count("(default)") == 1 and "| opening_pulse (default) | 38 | 2 | 36 | 2 | 2 | 2 | 2 | 3.5 |" in md


def test_score_rules_refuses_metrics_without_rules_and_writes_nothing(tmp_path):
    old = tmp_path / "old.json"
    old.write_text(json.dumps({"nu": 0.2, "f": 1.5, "celerity": 0.88}))
    out = tmp_path / "scores.csv"
    result = run_cli("score-rules", old, "--out", out)
    assert result.returncode == 2
    assert "old.json" in result.stderr and "celerity_rule_localization" in result.stderr
    assert "Traceback" not in result.stderr and not out.exists()
    files = [rule_metrics_file(tmp_path, n, 0.2, 1.5, {"opening_pulse": 0.9}) for n in "ab"]
    result = run_cli("score-rules", *files, "--out", out)
    assert result.returncode == 2 and "two metrics for the cell" in result.stderr
    assert not out.exists()
    result = run_cli("score-rules", files[0], "--tolerance", "-1")
    assert result.returncode == 2 and "--tolerance" in result.stderr


def test_opening_pulse_is_the_strongest_front_whose_pulse_opens_not_the_first():
    # A weak pulse near c_l opens first (900 s); the strong, slower pulse behind it opens later.
    # lambda = 4 H: the faster pulse laps the slower one only after t_stop.
    scenario = Scenario(nu=0.0, f=1.1, lambda_over_H=4.0, t_stop=1300.0, pulses=[
        Pulse(celerity=0.98, x_front=10.0, t_start=800.0, amplitude=0.6e-3, opening=0.01,
              opening_start=900.0),
        Pulse(celerity=0.80, x_front=35.0, t_start=950.0, amplitude=3e-3, opening=0.01,
              opening_start=1000.0)])
    results, _, opened, d = measure_all(scenario)
    assert opened.t_first == pytest.approx(d["t"][d["t"] >= 900.0][0])
    pulse = results["opening_pulse"]
    assert pulse.celerity == pytest.approx(0.80, rel=5e-3)
    assert pulse.window[0] == pytest.approx(d["t"][d["t"] >= 950.0][0])
    assert results["opening_pulse_from_opening"].window[0] == pytest.approx(d["t"][d["t"] >= 1000.0][0])
