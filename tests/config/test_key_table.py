"""The study schema (study/config.schema.yaml) never admits a value that the solver's key table
(`slidewave keys --json`, the source of docs/contracts.md section 1) rejects, and it refuses the points
whose step count would overflow (issue 11 item 3).

Self-contained: the solver is $SLIDEWAVE_BIN or <repo>/build/slidewave (missing: a failure, not a skip).
"""

import json
import math
import os
import subprocess
from pathlib import Path

import jsonschema
import pytest
import yaml

from analysis.theory import elastic

REPO = Path(__file__).resolve().parents[2]
SOLVER = Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))
SCHEMA = yaml.safe_load((REPO / "study" / "config.schema.yaml").read_text())

# Every study parameter that becomes a solver key (study/configure writes it there).
POINT_KEYS = {
    "nu": "material.nu", "f": "friction.f", "V0_over_cs": "loading.V0_over_cs",
    "lambda_over_H": "geometry.lambda_over_H", "elements_per_H": "mesh.elements_per_H", "rho": "material.rho",
    "integration": "mesh.integration", "seed": "perturbation.seed", "dt_times_cs": "time.dt_times_cs",
    # E_substrate / E: substrate.E = E_substrate_over_E E (study/make_run_config.py); a positive ratio, like the key.
    "E_substrate_over_E": "substrate.E",
}
MODEL_KEYS = {"E": "material.E", "H": "geometry.H", "Uy_over_H": "loading.Uy_over_H",
              "preshear_ratio": "loading.preshear_ratio"}
RUN_LENGTH_KEYS = {"t_end": "time.t_end"}
SUBSTRATE_KEYS = {"E": "substrate.E", "nu": "substrate.nu", "rho": "substrate.rho", "H": "substrate.H"}


@pytest.fixture(scope="module")
def table():
    assert SOLVER.is_file(), f"no solver binary at {SOLVER}: build it (scripts/build.sh) or set SLIDEWAVE_BIN"
    rows = json.loads(subprocess.run([str(SOLVER), "keys", "--json"], check=True, capture_output=True,
                                     text=True).stdout)
    return {f"{row['group']}.{row['name']}": row for row in rows}


def schema_properties():
    """(where, parameter, subschema, solver key) for every mapped schema property."""
    definitions = SCHEMA["definitions"]
    for name, key in POINT_KEYS.items():
        yield "definitions", name, definitions[name], key
    for name, key in MODEL_KEYS.items():
        yield "model", name, SCHEMA["properties"]["model"]["properties"][name], key
    for name, key in RUN_LENGTH_KEYS.items():
        yield "run_length", name, definitions["run_length"]["properties"][name], key
        yield "properties.run_length", name, SCHEMA["properties"]["run_length"]["properties"][name], key
    for name, key in SUBSTRATE_KEYS.items():
        yield "substrate", name, definitions["substrate"]["properties"][name], key


def lower_of(sub):
    """(value, exclusive) of the schema's lower bound, or None."""
    if "exclusiveMinimum" in sub:
        return sub["exclusiveMinimum"], True
    return (sub["minimum"], False) if "minimum" in sub else None


def upper_of(sub):
    if "exclusiveMaximum" in sub:
        return sub["exclusiveMaximum"], True
    return (sub["maximum"], False) if "maximum" in sub else None


def test_every_point_and_model_parameter_is_mapped():
    assert set(SCHEMA["definitions"]["point"]["properties"]) == set(POINT_KEYS)
    assert set(SCHEMA["properties"]["model"]["properties"]) == set(MODEL_KEYS)
    assert set(SCHEMA["definitions"]["substrate"]["properties"]) == set(SUBSTRATE_KEYS)


def test_schema_substrate_is_all_or_none():
    assert admits({"$ref": "#/definitions/solver_keys"}, {"substrate": {"E": 1e3, "nu": 0.2, "rho": 1e3, "H": 25.0}})
    assert not admits({"$ref": "#/definitions/solver_keys"}, {"substrate": {"E": 1e3}})
    assert not admits({"$ref": "#/definitions/solver_keys"}, {"substrate": {"E": 1e3, "nu": 0.5, "rho": 1e3, "H": 1.0}})


PROPERTIES = [pytest.param(*p, id=f"{p[0]}.{p[1]}") for p in schema_properties()]


@pytest.mark.parametrize("where,name,sub,key", PROPERTIES)
def test_schema_bounds_lie_inside_the_key_table(table, where, name, sub, key):
    row = table[key]
    if row["kind"] == "choice":
        assert set(sub["enum"]) <= set(row["choices"]), f"{where}.{name}: {sub['enum']} vs {row['choices']}"
        return
    if row["kind"] == "integer":
        assert sub["type"] == "integer", f"{where}.{name}: the solver key {key} is an integer"
    for side, schema_bound, table_bound, inside in (
            ("lower", lower_of(sub), row.get("minimum"), lambda s, t: s > t),
            ("upper", upper_of(sub), row.get("maximum"), lambda s, t: s < t)):
        if table_bound is None:
            continue
        assert schema_bound is not None, f"{where}.{name}: no {side} bound, the solver's {key} has {table_bound}"
        value, exclusive = schema_bound
        ok = inside(value, table_bound["value"]) or (
            value == table_bound["value"] and (exclusive or not table_bound["exclusive"]))
        assert ok, f"{where}.{name}: {side} bound {schema_bound} admits values that {key} rejects ({row['allowed']})"


@pytest.mark.parametrize("where,name,sub,key", PROPERTIES)
def test_schema_defaults_are_allowed_by_the_solver(table, where, name, sub, key):
    if sub.get("default") is None:
        return
    row, value = table[key], sub["default"]
    for bound, below in ((row.get("minimum"), True), (row.get("maximum"), False)):
        if bound:
            inside = value > bound["value"] if below else value < bound["value"]
            assert inside or (value == bound["value"] and not bound["exclusive"]), f"{where}.{name} = {value}"


# The largest integer that YAML, JSON and a float keep exact: `--config` seeds arrive as floats.
EXACT_INTEGER_MAX = 2**53 - 1


@pytest.mark.parametrize("where,name,sub,key", PROPERTIES)
def test_every_number_has_both_bounds_so_infinity_never_passes(table, where, name, sub, key):
    """Issue 21 item 6: `f: 1e999` (inf) and `seed: 1e19` were admitted (the solver's key table has no
    upper bound for them); the schema bounds every number it passes to the solver, within the table's
    bounds (test above) and, for an integer, within the exact range of a float."""
    if table[key]["kind"] == "choice":
        return
    assert lower_of(sub) is not None and upper_of(sub) is not None, f"{where}.{name}: unbounded ({key})"
    assert not admits(sub, math.inf) and not admits(sub, -math.inf)
    if sub["type"] == "integer":
        assert upper_of(sub)[0] <= EXACT_INTEGER_MAX, f"{where}.{name}: {upper_of(sub)} beyond 2^53 - 1"
        assert not admits(sub, 1e19)


def admits(subschema, value) -> bool:
    validator = jsonschema.Draft7Validator({**subschema, "definitions": SCHEMA["definitions"]})
    return validator.is_valid(value)


@pytest.mark.parametrize("name,value", [("V0_over_cs", 1.0e-12), ("rho", 1e-300), ("dt_times_cs", 1e-7)])
def test_schema_refuses_points_that_overflow_the_step_count(name, value):
    assert not admits({"$ref": "#/definitions/point"}, {name: value})
    assert admits({"$ref": "#/definitions/point"}, {name: SCHEMA["properties"]["defaults"]["properties"][name]["default"]})


def test_schema_refuses_an_absurd_run_length():
    assert not admits({"$ref": "#/definitions/run_length"}, {"t_end": 1e12})
    assert not admits({"$ref": "#/definitions/run_length"}, {"duration_transits": 1e9})
    assert admits({"$ref": "#/definitions/run_length"}, {"t_end": 20000.0})


def test_the_slowest_schema_point_at_default_settings_fits_max_steps(table):
    """V0_over_cs at its schema minimum, every other parameter at the study default: onset (eq. 1 of
    study/run_length.py) + the default duration must stay inside time.max_steps."""
    d = {k: v["default"] for k, v in SCHEMA["properties"]["defaults"]["properties"].items()}
    m = {k: v["default"] for k, v in SCHEMA["properties"]["model"]["properties"].items()}
    v0_min = lower_of(SCHEMA["definitions"]["V0_over_cs"])[0]
    nu, f = d["nu"], d["f"]
    shear_over_p0 = (1 - 2 * nu) / (2 * (1 - nu)) / -m["Uy_over_H"]  # G / p0
    onset_times_cs = (1 - m["preshear_ratio"]) * f * m["H"] / (shear_over_p0 * v0_min)  # t_onset c_s (m)
    duration = SCHEMA["properties"]["run_length"]["properties"]["duration_transits"]["default"] * m["H"]
    n_steps = elastic.n_steps(onset_times_cs + duration, d["dt_times_cs"])  # times c_s: lengths, same count
    assert n_steps <= table["time.max_steps"]["default"], n_steps
