"""Readers for the figure scripts: run.h5 (through analysis.core.io), metrics JSON, CSV tables,
flutter.txt.

Figures compute nothing: this module only opens files, checks what the figures need, and hands
arrays and rows to the plotting code. A run file is read by `analysis.core.io.load_run`, the project's
one reader, which checks `format_version` first; the bulk snapshots, which it does not read, are
read here after that check. Every problem with an input is the analysis package's `InputError`
(one error class for the whole Python side), whose message names the file and what is wrong.
"""
import json
import math

import numpy as np

from analysis.core.errors import InputError
from analysis.core.io import load_run
from analysis.core.table_csv import parse_cell, read_table

__all__ = ["InputError", "Run", "open_run", "read_csv", "read_flutter",
           "read_json", "select"]


class Run:
    """A checked run.h5: root attributes, config, interface fields, global series, snapshots."""

    def __init__(self, path):
        self._data = load_run(path)
        self.path = self._data.path
        # Root attributes and, from format 2 on, the derived constants of /setup (nu, f, c_s, H,
        # ...) that titles and labels name.
        self.attrs = {**self._data.attrs, **getattr(self._data, "setup", {})}
        self.config = self._data.config

    def attr(self, name):
        """A numeric root attribute as float."""
        return self._data.attr(name)

    def interface(self, field, tmin=None, tmax=None):
        """(x, t, values[n_t, n_c]) of /interface/<field> restricted to tmin <= t <= tmax."""
        fields = self._data.interface
        t = fields.t
        lo = 0 if tmin is None else int(np.searchsorted(t, tmin, side="left"))
        hi = len(t) if tmax is None else int(np.searchsorted(t, tmax, side="right"))
        if hi <= lo:
            raise InputError(f"{self.path}: no interface output in [{tmin}, {tmax}] s "
                             f"(output spans [{t[0]:g}, {t[-1]:g}] s)")
        return fields.x, t[lo:hi], getattr(fields, field)[lo:hi]

    def series(self, name):
        """A /global series (one value per step from t = 0)."""
        return getattr(self._data.global_series, name)

    def snapshots(self):
        """[(name, t, displacement, velocity)] sorted by t, plus coordinates and connectivity."""
        import h5py

        with h5py.File(self.path, "r") as file:
            if "/snapshots" not in file:
                raise InputError(f"{self.path}: group '/snapshots' is missing "
                                 "(no output.snapshot_times in the run config?)")
            group = file["/snapshots"]
            for name in ("coordinates", "connectivity"):
                if name not in group:
                    raise InputError(f"{self.path}: dataset '/snapshots/{name}' is missing")
            items = []
            for name, node in group.items():
                if name in ("coordinates", "connectivity"):
                    continue
                missing = [k for k in ("displacement", "velocity") if k not in node]
                if "t" not in node.attrs or missing:
                    raise InputError(f"{self.path}: /snapshots/{name} lacks "
                                     f"{', '.join(missing + ['attribute t'] * ('t' not in node.attrs))}")
                items.append((name, float(node.attrs["t"]), np.asarray(node["displacement"]),
                              np.asarray(node["velocity"])))
            coordinates = np.asarray(group["coordinates"], dtype=float)
            connectivity = np.asarray(group["connectivity"]).astype(int)
        if not items:
            raise InputError(f"{self.path}: /snapshots holds no snapshot")
        items.sort(key=lambda item: item[1])
        return items, coordinates, connectivity


def open_run(path):
    return Run(path)


def read_json(path):
    try:
        with open(path) as stream:
            return json.load(stream)
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    except json.JSONDecodeError as err:
        raise InputError(f"{path}: not valid JSON ({err})") from None


def read_csv(path, required):
    """Rows of a table of `analysis aggregate` as dicts of parsed values (analysis.core.table_csv); an
    InputError names any missing required column or a table without rows."""
    rows = read_table(path, required)
    if not rows:
        raise InputError(f"{path}: no data rows")
    return rows


def select(rows, where, path="input"):
    """Keep rows matching every 'column=value' in `where` (numbers compared as numbers)."""
    for condition in where or []:
        if "=" not in condition:
            raise InputError(f"--where expects column=value, got '{condition}'")
        key, wanted = (s.strip() for s in condition.split("=", 1))
        wanted = parse_cell(wanted)
        if rows and key not in rows[0]:
            raise InputError(f"{path}: --where column '{key}' does not exist")
        rows = [r for r in rows if _same(r[key], wanted)]
    if not rows:
        raise InputError(f"{path}: no row left after --where {' '.join(where)}")
    return rows


def _same(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
    return str(a) == str(b)


def read_flutter(path):
    """Lines 'nu f_lower f_upper' (inf/nan allowed; '#' comments and a 'nu ...' header skipped)."""
    points = []
    try:
        with open(path) as stream:
            lines = stream.readlines()
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    for number, line in enumerate(lines, 1):
        tokens = line.split("#", 1)[0].replace(",", " ").split()
        if not tokens or tokens[0].lower() == "nu":
            continue
        try:
            if len(tokens) != 3:
                raise ValueError
            points.append(tuple(float(s) for s in tokens))
        except ValueError:
            raise InputError(f"{path}:{number}: expected 'nu f_lower f_upper', got "
                             f"'{line.strip()}'") from None
    if not points:
        raise InputError(f"{path}: no 'nu f_lower f_upper' line")
    return np.array(sorted(points))
