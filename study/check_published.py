"""Checks that what `snakemake all` regenerated is what study/results/ holds: every published table against
its committed copy, value by value.

Run by the rule `published_check` (study/rules/publish.smk), which knows each committed file's source in
results/. The same build makes the same bits (docs/performance.md, determinism), so the
values must be equal, not close: a difference means the code moved the results since they were published
and the campaign must be republished (`snakemake -c2 all publish_results`). Aside: the run-provenance columns
(`slidewave_version`, `git_commit`: they name the build, which a later commit changes without moving a
result).
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

PROVENANCE_COLUMNS = frozenset({"slidewave_version", "git_commit"})
SHOWN_PER_FILE = 5


def csv_differences(committed: Path, regenerated: Path) -> list[str]:
    with committed.open(newline="") as a, regenerated.open(newline="") as b:
        rows_a, rows_b = list(csv.DictReader(a)), list(csv.DictReader(b))
    columns_a = list(rows_a[0]) if rows_a else []
    columns_b = list(rows_b[0]) if rows_b else []
    if columns_a != columns_b:
        return [f"columns differ: {sorted(set(columns_a) ^ set(columns_b))}"]
    if len(rows_a) != len(rows_b):
        return [f"{len(rows_a)} rows committed, {len(rows_b)} regenerated"]
    found = []
    for number, (row_a, row_b) in enumerate(zip(rows_a, rows_b), start=1):
        for column in columns_a:
            if column not in PROVENANCE_COLUMNS and row_a[column] != row_b[column]:
                found.append(f"row {number} {column}: {row_a[column]} -> {row_b[column]}")
    return found


def json_differences(committed: Path, regenerated: Path) -> list[str]:
    found: list[str] = []

    def walk(a, b, where: str) -> None:
        if isinstance(a, dict) and isinstance(b, dict):
            for key in sorted(set(a) | set(b)):
                if key in PROVENANCE_COLUMNS:
                    continue
                if key not in a or key not in b:
                    found.append(f"{where}/{key}: only {'regenerated' if key in b else 'committed'}")
                else:
                    walk(a[key], b[key], f"{where}/{key}")
        elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
            for index, (x, y) in enumerate(zip(a, b)):
                walk(x, y, f"{where}[{index}]")
        elif a != b:
            found.append(f"{where or '/'}: {a!r} -> {b!r}")

    walk(json.loads(committed.read_text()), json.loads(regenerated.read_text()), "")
    return found


def differences(committed: Path, regenerated: Path) -> list[str]:
    if not committed.exists():
        return ["not committed (publish it)"]
    if committed.suffix == ".csv":
        return csv_differences(committed, regenerated)
    if committed.suffix == ".json":
        return json_differences(committed, regenerated)
    return [] if committed.read_bytes() == regenerated.read_bytes() else ["bytes differ"]


def check(pairs: dict[str, str]) -> tuple[str, bool]:
    """The report (a line per committed file, its first differences, the verdict) and whether all agree.
    pairs: {committed file: the regenerated file it was copied from}."""
    lines, failed = [], 0
    for committed, regenerated in sorted(pairs.items()):
        found = differences(Path(committed), Path(regenerated))
        failed += bool(found)
        lines.append(f"DIFFERS {committed} ({len(found)} differences)" if found else f"same {committed}")
        lines += [f"    {line}" for line in found[:SHOWN_PER_FILE]]
    if failed:
        verdict = (f"published check: FAIL: {failed} of {len(pairs)} committed tables differ from what the code"
                   " makes now: republish (snakemake -c2 all publish_results)")
    else:
        verdict = f"published check: PASS: the {len(pairs)} committed tables are what the code makes"
    return "\n".join([*lines, verdict]) + "\n", not failed
