"""study/check_published.py: the committed tables against the regenerated ones, value by value, the runs'
build names aside."""

import json

from study.check_published import check


def write_csv(path, rows):
    path.write_text("\n".join(",".join(row) for row in rows) + "\n")


def test_equal_tables_pass_and_build_names_are_aside(tmp_path):
    committed, regenerated = tmp_path / "committed.csv", tmp_path / "regenerated.csv"
    write_csv(committed, [["nu", "celerity", "git_commit"], ["0.2", "1.33", "aaaa"]])
    write_csv(regenerated, [["nu", "celerity", "git_commit"], ["0.2", "1.33", "bbbb"]])
    summary = tmp_path / "summary.json"
    summary.write_text(json.dumps({"within_tolerance": 19, "cells": ["nu=0.2 f=1"]}))
    text, agree = check({str(committed): str(regenerated), str(summary): str(summary)})
    assert agree, text
    assert text.splitlines()[-1].startswith("published check: PASS")


def test_a_moved_value_fails_and_is_named(tmp_path):
    committed, regenerated = tmp_path / "committed.csv", tmp_path / "regenerated.csv"
    write_csv(committed, [["nu", "celerity"], ["0.2", "1.33"], ["0.3", "1.29"]])
    write_csv(regenerated, [["nu", "celerity"], ["0.2", "1.33"], ["0.3", "1.2900000001"]])
    text, agree = check({str(committed): str(regenerated)})
    assert not agree
    assert "row 2 celerity: 1.29 -> 1.2900000001" in text
    assert "republish" in text.splitlines()[-1]


def test_json_rows_and_missing_files_fail(tmp_path):
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    a.write_text(json.dumps({"within_tolerance": 19, "missing_cells": ["nu=0 f=1.1"]}))
    b.write_text(json.dumps({"within_tolerance": 20, "missing_cells": ["nu=0 f=1.1"]}))
    text, agree = check({str(a): str(b)})
    assert not agree and "/within_tolerance: 19 -> 20" in text
    c, d = tmp_path / "c.csv", tmp_path / "d.csv"
    write_csv(c, [["nu"], ["0.2"]])
    write_csv(d, [["nu"], ["0.2"], ["0.3"]])
    assert "1 rows committed, 2 regenerated" in check({str(c): str(d)})[0]
    text, agree = check({str(tmp_path / "never_published.csv"): str(d)})
    assert not agree and "not committed" in text
