"""YAML 1.1 reads 1e-5 (no decimal point) and 1.0e5 (no exponent sign) as strings: the Snakefile
passes the study config through study.sweeps.typed_numbers before the schema, so they mean the
numbers they spell, in study/config.yaml and on the command line; what is not a number stays a
string, and the schema then rejects it naming the key."""

import pytest
import yaml
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

from study.sweeps import sweep_points, typed_numbers

from .conftest import REPO, job_counts, snakemake

SCHEMA = str(REPO / "study" / "config.schema.yaml")


@pytest.mark.parametrize("text, number", [("1e-5", 1e-5), ("1E-5", 1e-5), ("-2e3", -2000.0), ("1.0e5", 1e5),
                                          (".5", 0.5), ("32", 32), ("+7", 7)])
def test_yaml_strings_that_spell_numbers_become_those_numbers(text, number):
    loaded = yaml.safe_load(f"x: {text}")["x"]
    value = typed_numbers({"x": loaded})["x"]
    assert value == number and type(value) is type(number)


@pytest.mark.parametrize("text", ["reduced", "1e-5x", "e5", "1e", "", "nan", "1_000"])
def test_other_strings_stay_strings(text):
    assert typed_numbers({"x": text}) == {"x": text}


def test_booleans_nulls_and_nesting_are_kept():
    config = {"a": [True, None, "1e-5", {"b": "2"}], "c": 1.5}
    assert typed_numbers(config) == {"a": [True, None, 1e-5, {"b": 2}], "c": 1.5}


def test_a_study_written_with_1e_minus_5_validates_and_means_it():
    config = typed_numbers(yaml.safe_load("""
defaults: {V0_over_cs: 1e-5}
sweeps:
  rates: {grid: {V0_over_cs: [1e-6, 5e-6]}}
"""))
    validate(config, SCHEMA)
    names = list(sweep_points(config, "rates"))
    assert config["defaults"]["V0_over_cs"] == 1e-5
    assert [n.split("_")[2] for n in names] == ["v1e-06", "v5e-06"]


def test_a_non_number_is_rejected_naming_the_key():
    config = typed_numbers(yaml.safe_load("defaults: {V0_over_cs: 1e-5x}\nsweeps: {s: {}}"))
    with pytest.raises(WorkflowError, match="V0_over_cs"):
        validate(config, SCHEMA)


def test_command_line_1e_minus_5_reaches_the_run(tmp_path):
    result = snakemake(tmp_path, "-n", "-c1", "explore", "--config",
                       "point={nu: 0.25, f: 1.6, V0_over_cs: 1e-6}")
    assert "nu0.25_f1.60_v1e-06_" in result.stdout
    assert job_counts(result.stdout)["simulate"] == 1
