"""Shared by the scripts of paper/: reading the study's CSV tables, LABEL=PATH arguments and atomic
writes."""

from __future__ import annotations

import csv
import math
import os
import tempfile


class InputError(Exception):
    """An input table is missing, unreadable or lacks what the paper needs."""


def parse(text):
    """A CSV cell: '' (and nan, none, null) -> nan, true/false -> bool, a number -> float, else str."""
    text = (text or "").strip()
    if text.lower() in ("", "nan", "none", "null"):
        return math.nan
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return float(text)
    except ValueError:
        return text


def read_rows(path, required):
    """Rows of a CSV table as dicts of parsed cells; InputError naming missing required columns."""
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            rows = [{k: parse(v) for k, v in row.items() if k} for row in reader]
            columns = reader.fieldnames or []
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    missing = [c for c in required if c not in columns]
    if missing:
        raise InputError(f"{path}: missing required column(s) {', '.join(missing)}")
    return rows


def labelled_paths(items: list[str], what: str) -> list[tuple[str, str]]:
    """[(label, path)] of 'LABEL=PATH' arguments; the label may contain '=', the path does not.

    Raises ValueError naming the argument that is not LABEL=PATH (`what` names PATH, e.g. SUMMARY_JSON).
    """
    pairs = []
    for item in items:
        label, sep, path = item.rpartition("=")
        if not sep:
            raise ValueError(f"{item!r} is not LABEL={what}")
        pairs.append((label, path))
    return pairs


def current_umask() -> int:
    """The process's file-mode creation mask (reading it means setting it: set it straight back)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write_atomically(path: str, text: str) -> None:
    """Write `text` to `path` through a temporary file and a rename: never a partial file.

    The file gets the mode of any other new file (0666 less the umask), not the temporary file's
    0600, which the rename would keep: colleagues sharing the project folder can read the tables.
    """
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", dir=directory, delete=False, suffix=".tmp") as out:
        try:
            out.write(text)
            os.chmod(out.name, 0o666 & ~current_umask())
        except BaseException:
            os.unlink(out.name)
            raise
    os.replace(out.name, path)
