"""The published slip-front celerities (paper Table 1) and what follows from them.

File: `study/reference/table1_celerity.csv`, columns `nu,f,celerity_m_per_s` (m/s, signed,
+ = sliding direction). The published regime is derived from the celerity and the wave speeds of
Table 1's material (E = 1000 Pa, rho = 1000 kg/m^3).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from analysis.core.errors import InputError
from analysis.metrics.regime import regime
from analysis.theory import elastic

#: The reference file shipped with the project.
DEFAULT_REFERENCE = Path(__file__).resolve().parents[2] / "study" / "reference" / "table1_celerity.csv"
_COLUMNS = ("nu", "f", "celerity_m_per_s")


@dataclass(frozen=True)
class ReferenceCell:
    """One published cell: nu, f, celerity (m/s) and its regime."""

    nu: float
    f: float
    celerity: float

    @property
    def key(self) -> tuple[float, float]:
        return cell_key(self.nu, self.f)

    @property
    def regime(self) -> str:
        c_s, _, c_l = elastic.wave_speeds(self.nu)
        return regime(self.celerity, c_s, c_l)


def cell_key(nu: float, f: float) -> tuple[float, float]:
    """Key of a (nu, f) cell, robust to float formatting (rounded to 1e-6)."""
    return round(float(nu), 6), round(float(f), 6)


def metrics_by_cell(metrics: list[dict[str, Any]]) -> dict[tuple[float, float], dict[str, Any]]:
    """Metrics keyed by their (nu, f) cell; InputError when two files fall on one cell."""
    by_cell: dict[tuple[float, float], dict[str, Any]] = {}
    for m in metrics:
        key = cell_key(m["nu"], m["f"])
        if key in by_cell:
            raise InputError(f"two metrics for the cell nu={key[0]:g} f={key[1]:g}: "
                             f"{by_cell[key].get('metrics_file')} and {m.get('metrics_file')}; "
                             "pass one per cell or narrow them with --select key=value")
        by_cell[key] = m
    return by_cell


def read_reference(path: str | Path = DEFAULT_REFERENCE) -> list[ReferenceCell]:
    """The published cells, in file order. InputError for a missing or malformed file."""
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            missing = [c for c in _COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                raise InputError(f"{path}: reference lacks column(s) {', '.join(missing)} "
                                 f"(expected {','.join(_COLUMNS)})")
            cells = []
            for line, row in enumerate(reader, 2):
                try:
                    cell = ReferenceCell(float(row["nu"]), float(row["f"]),
                                         float(row["celerity_m_per_s"]))
                except (TypeError, ValueError):
                    raise InputError(f"{path}:{line}: not a number in {dict(row)}") from None
                if not all(math.isfinite(v) for v in (cell.nu, cell.f, cell.celerity)):
                    raise InputError(f"{path}:{line}: non-finite value in {dict(row)}")
                cells.append(cell)
    except OSError as err:
        raise InputError(f"{path}: cannot read reference ({err.strerror})") from None
    if not cells:
        raise InputError(f"{path}: reference has no cells")
    keys = [c.key for c in cells]
    duplicates = sorted({k for k in keys if keys.count(k) > 1})
    if duplicates:
        raise InputError(f"{path}: duplicate cells {duplicates}")
    return cells
