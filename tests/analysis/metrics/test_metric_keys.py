"""The metric keys are declared once, per family (analysis.metrics.measure.FAMILIES), and the
README's "Metric keys" table lists exactly those keys, in their order."""
import re
from pathlib import Path

from analysis.fronts import default_rule, rules
from analysis.metrics.measure import FAMILIES, METRIC_KEYS

README = Path(__file__).resolve().parents[3] / "analysis" / "README.md"


def readme_table():
    """[(family, [keys])] of the README's "Metric keys" table, `<name>` expanded over RULES."""
    section = README.read_text().split("## Metric keys", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 2 or cells[0] in ("family", "---"):
            continue
        keys = []
        for key in re.findall(r"`([^`]+)`", cells[1]):
            keys += [key.replace("<name>", name) for name in rules.RULES] if "<name>" in key else [key]
        rows.append((cells[0], keys))
    return rows


def test_the_readme_lists_exactly_the_declared_keys_per_family():
    table = readme_table()
    assert [name for name, _ in table] == [f.name for f in FAMILIES]
    for (name, keys), family in zip(table, FAMILIES):
        assert sorted(keys) == sorted(family.keys), name
    assert sorted(k for _, keys in table for k in keys) == sorted(METRIC_KEYS)


def test_every_key_is_declared_once():
    assert len(METRIC_KEYS) == len(set(METRIC_KEYS))
    assert set(default_rule.CELERITY_KEYS) <= set(METRIC_KEYS) and set(rules.RULE_METRIC_KEYS) <= set(METRIC_KEYS)


def test_measure_run_writes_the_declared_keys_in_order(run_file):
    from synthetic_run import paper_case

    from analysis.core.io import load_run
    from analysis.metrics.measure import measure_run

    metrics = measure_run(load_run(run_file(paper_case())))
    assert tuple(metrics) == METRIC_KEYS
    assert metrics["first_drop_complete"] is (metrics["n_complete_drops"] >= 1)
    assert metrics["first_drop_duration"] == metrics["first_drop_bottom_time"] - metrics["first_drop_start_time"]
