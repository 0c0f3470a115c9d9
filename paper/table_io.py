"""Shared by the scripts of paper/: reading the study's CSV tables, labels, LABEL=PATH arguments.
Files are written by the project's one atomic writer, `analysis.core.atomic.write_file`."""

from __future__ import annotations

# The paper scripts read the study's tables with the analysis package's reader, and report its error.
from analysis.core.errors import InputError  # noqa: F401
from analysis.core.table_csv import read_table as read_rows  # noqa: F401
from analysis.metrics.regime import outcome_label


#: A category, regime or end reason as text (one definition: analysis.metrics.regime).
label = outcome_label


def latex_number(text: str) -> str:
    """A formatted number as LaTeX math text: '3.8e-14' -> '3.8\\times10^{-14}', '1e-05' -> '10^{-5}'."""
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    power = f"10^{{{int(exponent)}}}"
    if float(mantissa) == 1:
        return power
    return ("-" + power) if float(mantissa) == -1 else f"{mantissa}\\times{power}"


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
