"""What the claims (analysis.tables.claims, rendered by paper/make_claims.py) share: the sweep tables each name is (TABLES) and their
reader (Tables), the verdicts, and the LaTeX formatting of numbers in a reason."""
from __future__ import annotations

import math
import os
import re
import statistics
from dataclasses import dataclass

from analysis.core.errors import InputError
from analysis.core.table_csv import read_table as read_rows
from analysis.core.table_render import latex_number


#: name -> (sweep table it is, columns it must have).
TABLES = {
    "table1": ("table1.csv of the grid at the paper's mesh",
               ("nu", "f", "celerity", "published", "deviation_rel", "sign_match", "regime_match",
                "category_match", "regime", "published_regime", "category", "celerity_window_sensitivity")),
    "grid": ("all_metrics.csv of the (nu, f) grid",
             ("nu", "f", "category", "celerity", "celerity_over_cs", "below_sqrt2_cs", "opening", "inversion",
              "dissipative_friction_opening", "dissipative_friction_before_opening", "elements_per_H")),
    "period": ("all_metrics.csv of the period sweep", ("lambda_over_H", "pulse_count")),
    "period_ensemble": ("all_metrics.csv of the period sweep over seeds", ("lambda_over_H", "seed", "pulse_count")),
    "mesh": ("all_metrics.csv of the mesh sweep", ("elements_per_H", "celerity", "category", "pulse_count")),
    "timestep": ("all_metrics.csv of the time-step sweep", ("nu", "f", "dt_times_cs", "celerity", "category")),
    "timestep_backward": ("all_metrics.csv of the backward cells at small time steps",
                          ("nu", "f", "dt_times_cs", "seed", "category")),
    "shear_rate": ("all_metrics.csv of the shear-rate sweep",
                   ("V0_over_cs", "inversion", "min_T_over_N", "first_drop_start_after_onset")),
    "density": ("all_metrics.csv of the density sweep", ("rho", "celerity_over_cs", "min_T_over_N")),
    "long": ("all_metrics.csv of the long run", ("n_drops", "later_drops_start_T_over_N_median")),
    "long_ensemble": ("all_metrics.csv of the long run over seeds",
                      ("seed", "n_drops", "later_drops_start_T_over_N_median")),
}
VERDICTS = ("reproduced", "partly", "not reproduced", "not testable here")
FORWARD_OPENING = ("intersonic_opening", "intersonic_opening_inversion")
BACKWARD_OPENING = "supersonic_backward_opening"


@dataclass
class Verdict:
    claim: str        # key in claims.json
    statement: str    # what the paper says
    verdict: str      # one of VERDICTS
    reason: str       # the numbers and why (LaTeX text)


class Missing(Exception):
    """A table a claim needs was not built: the claim is not testable here."""


# ---------------------------------------------------------------- small helpers

def finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def same(a, b) -> bool:
    return finite(a) and abs(a - b) < 1e-9


def g(value, digits=3) -> str:
    """A number as LaTeX math, `digits` significant figures ('1e-06' as 10^{-6})."""
    return f"${latex_number(f'{value:.{digits}g}'.replace('e-0', 'e-').replace('e+0', 'e'))}$" \
        if finite(value) else "--"


def pct(fraction, decimals=1) -> str:
    """A fraction in percent with fixed decimals; a tiny one with two significant figures."""
    if finite(fraction) and 0 < abs(fraction) < 0.5 * 10 ** (-decimals - 2):
        return f"{g(100 * fraction, 2)}\\,\\%"
    return f"${100 * fraction:.{decimals}f}$\\,\\%"


def tt(text: str) -> str:
    """A table name or path as LaTeX typewriter text."""
    return "\\texttt{" + text.replace("\\", "/").replace("_", "\\_").replace("%", "\\%") + "}"


def sci(value) -> str:
    """A rate such as V0/c_s as a power of ten in math ('$10^{-4}$', '$5\\times10^{-6}$')."""
    return f"${latex_number(f'{value:.0e}'.replace('e-0', 'e-'))}$" if finite(value) else "--"


def cell(r) -> str:
    return f"({r['nu']:g}, {r['f']:g})"


def spread(values) -> float:
    """(max - min) / |mean| of finite values; nan for fewer than two."""
    values = [v for v in values if finite(v)]
    if len(values) < 2 or statistics.fmean(values) == 0:
        return math.nan
    return (max(values) - min(values)) / abs(statistics.fmean(values))


def mesh_number(mesh_label: str) -> float:
    """'H/128' -> 128 (the elements per H a mesh label names)."""
    digits = re.findall(r"\d+", mesh_label)
    return float(digits[-1]) if digits else math.nan


def grade(n_good: int, n_total: int) -> str:
    """All good: reproduced; none: not reproduced; otherwise partly."""
    if n_total == 0:
        return "not testable here"
    return "reproduced" if n_good == n_total else "not reproduced" if n_good == 0 else "partly"


class Tables:
    """The sweep tables by name; `need` raises Missing for one that was not built."""

    def __init__(self, paths: dict[str, str], meshes: list[tuple[str, str]]):
        self.rows, self.missing = {}, {}
        for name, path in paths.items():
            if not os.path.exists(path):
                self.missing[name] = path
                continue
            self.rows[name] = read_rows(path, TABLES[name][1])
            if not self.rows[name]:
                raise InputError(f"{path}: no data rows")
        self.meshes, self.missing_meshes = [], []
        for mesh, path in meshes:
            if os.path.exists(path):
                self.meshes.append((mesh, read_rows(path, TABLES["table1"][1])))
            else:
                self.missing_meshes.append(f"{mesh} ({tt(path)})")

    def need(self, name: str) -> list[dict]:
        if name in self.rows:
            return self.rows[name]
        where = f" ({tt(self.missing[name])})" if name in self.missing else ""
        raise Missing(f"table {tt(name)} not built{where}")

    def optional(self, name: str) -> list[dict] | None:
        return self.rows.get(name)

    def not_built_note(self, *names: str) -> str:
        """' (table X not built)' for each optional table that is absent, for a reason's end."""
        absent = [n for n in names if n not in self.rows]
        return "".join(f" (table {tt(n)} not built)" for n in absent)
