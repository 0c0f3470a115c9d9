"""Check a regenerated Table 1 against the published celerities.

A cell is *compared* when the table gives it a celerity. It fails when its sign differs from the
published one, or when |celerity - published| / |published| exceeds the tolerance. The check also
fails when fewer than `min_within` cells are within tolerance (so that an empty table cannot pass
when something is required of it). Deviations are recomputed from the reference; the table's own
`published` and `deviation_rel` columns are not trusted.

Ratchet mode (`ratchet=True`, the CI gate of the pipeline): a cell out of tolerance is reported but is
not a failure; a wrong sign or a wrong regime (subsonic / intersonic / supersonic) is, and so is a
count of cells within tolerance below `min_within` (the ratchet in study/reference/ratchet.json).

A check that compared no cell at all (an empty table, a table of other cells) fails in either
mode: nothing was shown. A known mismatch must name a published cell as "nu=N f=F".
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

from analysis.core.errors import InputError
from analysis.metrics.regime import regime
from analysis.tables.reference import ReferenceCell, cell_key
from analysis.theory import elastic


@dataclass(frozen=True)
class Comparison:
    """Outcome: failures (one message per failing cell), counts and whether the check passed."""

    failures: list[str]
    notes: list[str]
    compared: int
    within: int
    sign_matches: int
    missing: int
    min_within: int
    tolerance: float

    @property
    def passed(self) -> bool:
        return not self.failures and self.compared > 0 and self.within >= self.min_within

    def summary(self) -> str:
        verdict = "PASS" if self.passed else "FAIL"
        nothing = " (nothing compared: no published cell has a measured celerity)" if not self.compared else ""
        return (f"compare: {verdict}{nothing}: {self.compared} cells compared, {self.within} within "
                f"{100 * self.tolerance:g}% (at least {self.min_within} required), "
                f"signs {self.sign_matches}/{self.compared}, {self.missing} published cells without "
                f"a measurement")


def read_table(path: str | Path) -> dict[tuple[float, float], float]:
    """(nu, f) -> celerity (m/s, nan when empty) of a table with columns nu, f, celerity."""
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            missing = [c for c in ("nu", "f", "celerity") if c not in (reader.fieldnames or [])]
            if missing:
                raise InputError(f"{path}: table lacks column(s) {', '.join(missing)}")
            table: dict[tuple[float, float], float] = {}
            for line, row in enumerate(reader, 2):
                try:
                    key = cell_key(float(row["nu"]), float(row["f"]))
                    text = (row["celerity"] or "").strip()
                    value = float(text) if text else math.nan
                except (TypeError, ValueError):
                    raise InputError(f"{path}:{line}: not a number in nu, f or celerity: "
                                     f"{row.get('nu')!r}, {row.get('f')!r}, {row.get('celerity')!r}") from None
                if key in table:
                    raise InputError(f"{path}:{line}: cell nu={key[0]:g} f={key[1]:g} appears twice")
                table[key] = value
    except OSError as err:
        raise InputError(f"{path}: cannot read table ({err.strerror})") from None
    return table


_CELL_NAME = re.compile(r"^nu=(\S+) f=(\S+)$")


def parse_cell_name(text: str, reference: list[ReferenceCell]) -> str:
    """The printed name "nu=N f=F" of a published cell, from a --known-mismatch value.

    InputError when the text is not of that form, holds no numbers, or names no published cell.
    """
    match = _CELL_NAME.match(text.strip())
    try:
        key = cell_key(float(match.group(1)), float(match.group(2))) if match else None
    except ValueError:
        key = None
    if key is None or not all(math.isfinite(v) for v in key):
        raise InputError(f"--known-mismatch {text!r}: expected \"nu=N f=F\" with numbers, "
                         "e.g. \"nu=0.49 f=1.5\"")
    for cell in reference:
        if cell.key == key:
            return f"nu={cell.nu:g} f={cell.f:g}"
    raise InputError(f"--known-mismatch {text!r}: no published cell nu={key[0]:g} f={key[1]:g} "
                     "in the reference")


def compare(table: dict[tuple[float, float], float], reference: list[ReferenceCell],
            tolerance: float, min_within: int = 0, ratchet: bool = False,
            known_mismatches: tuple[str, ...] = ()) -> Comparison:
    """Compare every published cell that the table measures.

    Parameters
    ----------
    table
        From read_table.
    reference
        The published cells.
    tolerance
        Relative tolerance (> 0).
    min_within
        Fewest cells that must be within tolerance (>= 0).
    ratchet
        Cells out of tolerance become notes; wrong sign or regime still fail (module docstring).
    known_mismatches
        Cells ("nu=0.49 f=1.5", as printed) whose wrong sign or regime is recorded in the ratchet
        file with its explanation: reported as KNOWN notes instead of failures, so that only a new
        mismatch fails the gate. Each must name a published cell (InputError otherwise).
    """
    if not tolerance > 0:
        raise InputError(f"--tolerance must be > 0 (got {tolerance})")
    if min_within < 0:
        raise InputError(f"--min-within must be >= 0 (got {min_within})")
    known_mismatches = tuple(parse_cell_name(text, reference) for text in known_mismatches)
    failures, notes = [], []
    compared = within = signs = missing = 0
    for cell in reference:
        c = table.get(cell.key, math.nan)
        if not math.isfinite(c):
            missing += 1
            continue
        compared += 1
        deviation = (c - cell.celerity) / abs(cell.celerity)
        name = f"nu={cell.nu:g} f={cell.f:g}"
        where = f"{name}: celerity {c:.4f} m/s vs published {cell.celerity:.3f} m/s"
        mismatches = notes if name in known_mismatches else failures
        prefix = "KNOWN " if name in known_mismatches else ""
        if (c > 0) != (cell.celerity > 0):
            mismatches.append(f"{prefix}WRONG SIGN {where}")
            continue
        signs += 1
        c_s, _, c_l = elastic.wave_speeds(cell.nu)
        if ratchet and regime(c, c_s, c_l) != cell.regime:
            mismatches.append(f"{prefix}WRONG REGIME {where} ({regime(c, c_s, c_l)} vs {cell.regime})")
            continue
        if abs(deviation) <= tolerance:
            within += 1
        else:
            (notes if ratchet else failures).append(
                f"OUT OF TOLERANCE {where} ({100 * deviation:+.1f}%, tolerance {100 * tolerance:g}%)")
    return Comparison(failures, notes, compared, within, signs, missing, min_within, tolerance)
