"""The CSV tables of the analysis (table1.csv, all_metrics.csv, ensemble.csv, ...): one writer that
`analysis.tables.aggregate`, `ensemble` and `envelope` use, and for the figures and the paper one parser of
a cell and one reader that checks the columns a caller needs."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path
from typing import Any

from analysis.core.errors import InputError


def format_cell(value: Any, fmt: str = ".6g") -> str:
    """A value as a cell: None and non-finite floats -> '', bools -> true/false, floats by fmt."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "" if not math.isfinite(value) else format(value, fmt)
    return str(value)


def csv_text(columns: list[str] | tuple[str, ...], rows: list[dict[str, Any]], fmt: str = ".6g") -> str:
    """The rows (dicts; a missing key is an empty cell) as CSV text with the given columns."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(columns)
    for row in rows:
        writer.writerow([format_cell(row.get(c), fmt) for c in columns])
    return out.getvalue()


def parse_cell(text: str | None) -> Any:
    """A cell as written by aggregate: '' (and nan, na, none, null) -> nan, true/false -> bool, a
    number -> float, anything else -> the text."""
    text = (text or "").strip()
    low = text.lower()
    if low in ("", "nan", "na", "none", "null"):
        return math.nan
    if low in ("true", "false"):
        return low == "true"
    try:
        return float(text)
    except ValueError:
        return text


def read_table(path: str | Path, required: tuple[str, ...] | list[str] = ()) -> list[dict[str, Any]]:
    """The rows of a CSV table as dicts of parsed cells.

    Raises InputError naming the file when it cannot be read or lacks a required column.
    """
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            rows = [{k: parse_cell(v) for k, v in row.items() if k} for row in reader]
            columns = reader.fieldnames or []
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    missing = [c for c in required if c not in columns]
    if missing:
        raise InputError(f"{path}: missing required column(s) {', '.join(missing)} "
                         f"(has: {', '.join(columns) or 'none'})")
    return rows


def parse_table(text: str) -> list[dict[str, Any]]:
    """The rows of CSV text as `read_table` returns them (a table exactly as a reader will see it)."""
    return [{k: parse_cell(v) for k, v in row.items() if k} for row in csv.DictReader(io.StringIO(text))]
