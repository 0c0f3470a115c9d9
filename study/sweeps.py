"""Run points of the study: expansion of a sweep declaration, readable names, look-ups.

A point is a dict of the swept parameters (POINT_KEYS). A sweep's points are

    for each entry p of `points` (+ rows of `points_from_csv`; default one empty entry)
      for each combination g of the `grid` lists (cartesian product, declared order)
        point = config.defaults | sweep.fixed | p | g

Pure functions of the validated study config (study/config.schema.yaml); no Snakemake here.
"""

from __future__ import annotations

import csv
import itertools
import math
import re
from pathlib import Path

#: Swept parameters, in the order they appear in a point's name.
POINT_KEYS = ("nu", "f", "V0_over_cs", "lambda_over_H", "elements_per_H", "rho", "integration", "seed",
              "dt_times_cs", "E_substrate_over_E")

#: The material contrast of a deformable substrate (docs/substrate.md), E_substrate / E; absent or None:
#: the paper's rigid flat (study/make_run_config.py writes no `substrate` group, the run is the same).
CONTRAST = "E_substrate_over_E"

#: Values left out of the name because every point of the paper has them (dt = 0.5 m / c_s: the
#: paper's time step).
IMPLICIT = {"seed": 1, "dt_times_cs": 0.5}


_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def typed_numbers(value):
    """`value` with every string that spells a number turned into that number, recursively.

    `--config` hands nested values over as strings, and YAML 1.1 reads 1e-5 as a string; both
    would fail the schema. Integers stay integers ("32" -> 32), the rest become floats.
    """
    if isinstance(value, dict):
        return {key: typed_numbers(item) for key, item in value.items()}
    if isinstance(value, list):
        return [typed_numbers(item) for item in value]
    if isinstance(value, str) and _NUMBER.match(value.strip()):
        text = value.strip()
        return int(text) if re.fullmatch(r"[+-]?\d+", text) else float(text)
    return value


def _decimal(x: float) -> str:
    """Two decimals (0.20, 1.50), more only when the value needs them (1.125)."""
    text = f"{x:.2f}"
    return text if float(text) == x else f"{x:.6g}"


def point_name(point: dict) -> str:
    """Directory name that spells the point's parameters, e.g.
    ``nu0.20_f1.50_v1e-05_L2_n32_rho1000_reduced`` (``..._Es3`` on a substrate 3 times stiffer)."""
    name = (f"nu{_decimal(point['nu'])}_f{_decimal(point['f'])}_v{point['V0_over_cs']:g}"
            f"_L{point['lambda_over_H']:g}_n{point['elements_per_H']}_rho{point['rho']:g}"
            f"_{point['integration']}")
    if point.get("seed", IMPLICIT["seed"]) != IMPLICIT["seed"]:
        name += f"_seed{point['seed']}"
    if point.get("dt_times_cs", IMPLICIT["dt_times_cs"]) != IMPLICIT["dt_times_cs"]:
        name += f"_dt{point['dt_times_cs']:g}"
    if point.get(CONTRAST) is not None:
        name += f"_Es{point[CONTRAST]:g}"
    return name


def _csv_value(key: str, text: str):
    """A CSV cell as the point parameter's type; ValueError when it does not spell one."""
    if key == "integration":
        return text
    if key == CONTRAST and text.strip() in ("", "null", "None"):
        return None  # the rigid flat
    return int(text) if key in ("elements_per_H", "seed") else float(text)


def _csv_points(path: Path) -> list[dict]:
    """Rows of a CSV as points, keeping only columns that are point parameters (e.g. nu, f).

    Each value is checked like a point of the config (study/config.schema.yaml): a row is as good as
    a line of config, and its values become run names and words of commands.

    Raises
    ------
    ValueError
        A value the schema refuses, naming the file, row (line of the file) and column.
    """
    from study.config_check import load_schema, value_error

    schema = load_schema()
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    points = []
    for line, row in enumerate(rows, start=2):
        point = {}
        for key, text in row.items():
            if key not in POINT_KEYS:
                continue
            try:
                point[key] = _csv_value(key, text)
                problem = value_error(point[key], schema["definitions"][key], schema)
            except (TypeError, ValueError):
                problem = value_error(text, schema["definitions"][key], schema)
            if problem:
                raise ValueError(f"{path}, row {line}, column {key}: {text!r} is not allowed; allowed: {problem}")
        points.append(point)
    return points


def sweep_points(config: dict, sweep: str, root: Path | str = ".") -> dict[str, dict]:
    """Points of one sweep, keyed by name, in declaration order.

    Raises
    ------
    KeyError
        The sweep is not declared.
    ValueError
        Two entries give the same point, or lambda_over_H * elements_per_H is not an integer.
    """
    spec = config["sweeps"][sweep]
    base = {**config["defaults"], **spec.get("fixed", {})}
    entries = list(spec.get("points", []))
    if "points_from_csv" in spec:
        entries += _csv_points(Path(root) / spec["points_from_csv"])
    if not entries:
        entries = [{}]
    grid = spec.get("grid", {})
    combos = [dict(zip(grid, values)) for values in itertools.product(*grid.values())]
    points: dict[str, dict] = {}
    for entry in entries:
        for combo in combos:
            point = {key: value for key, value in {**base, **entry, **combo}.items() if key in POINT_KEYS}
            n_x = point["lambda_over_H"] * point["elements_per_H"]
            if abs(n_x - round(n_x)) > 1e-9:
                raise ValueError(f"sweep {sweep}: lambda_over_H * elements_per_H = {n_x} is not an integer")
            name = point_name(point)
            if name in points:
                raise ValueError(f"sweep {sweep}: point {name} is declared twice")
            points[name] = point
    return points


def matches(point: dict, match: dict) -> bool:
    """True when every key of `match` equals the point's value (floats to 1e-9 relative; None, the
    rigid flat's contrast, equals only None or an absent key)."""
    for key, wanted in match.items():
        value = point.get(key) if key == CONTRAST else point[key]
        if wanted is None or value is None:
            if wanted is not value:
                return False
        elif isinstance(wanted, str) or isinstance(value, str):
            if value != wanted:
                return False
        elif not math.isclose(value, wanted, rel_tol=1e-9, abs_tol=1e-12):
            return False
    return True


def find_points(points: dict[str, dict], match: dict) -> list[str]:
    """Names of the points that match, in order."""
    return [name for name, point in points.items() if matches(point, match)]


def find_point(points: dict[str, dict], match: dict, what: str = "") -> str:
    """Name of the single matching point; ValueError if none or several match."""
    found = find_points(points, match)
    if len(found) != 1:
        raise ValueError(f"{what}: {match} matches {len(found)} points, expected exactly one")
    return found[0]


def varying_keys(points: dict[str, dict]) -> list[str]:
    """Point parameters that take more than one value across the points, in POINT_KEYS order."""
    return [key for key in POINT_KEYS
            if len({repr(point.get(key)) for point in points.values()}) > 1]


def label(point: dict, keys: list[str]) -> str:
    """Short legend text, e.g. 'V0/c_s=1e-05' or 'nu=0.20 f=1.50'."""
    symbols = {"nu": "nu", "f": "f", "V0_over_cs": "V0/c_s", "lambda_over_H": "lambda/H",
               "elements_per_H": "H/h", "rho": "rho", "integration": "", "seed": "seed",
               "dt_times_cs": "dt c_s", CONTRAST: "E_s/E"}
    parts = []
    for key in keys:
        value = point.get(key)
        if key == CONTRAST and value is None:
            parts.append("rigid flat")
            continue
        text = _decimal(value) if key in ("nu", "f") else (value if isinstance(value, str) else f"{value:g}")
        parts.append(f"{symbols[key]}={text}" if symbols[key] else str(text))
    return " ".join(parts) if parts else point_name(point)
