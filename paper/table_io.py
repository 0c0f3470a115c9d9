"""Shared by the scripts of paper/: reading the study's CSV tables, labels, LABEL=PATH arguments.
Files are written by the project's one atomic writer, `analysis.core.atomic.write_file`."""

from __future__ import annotations

# The paper scripts read the study's tables with the analysis package's reader, and report its error.
from analysis.core.errors import InputError  # noqa: F401
from analysis.core.table_csv import read_table as read_rows  # noqa: F401
from analysis.core.table_render import latex_number  # noqa: F401
from analysis.metrics.regime import outcome_label


#: A category, regime or end reason as text (one definition: analysis.metrics.regime).
label = outcome_label


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
