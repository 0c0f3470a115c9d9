"""Checks of the study config, one line per problem naming the key (or file, row and column) and the
allowed values, all problems at once.

Snakemake's `validate` reports only the first schema violation, as a dump of the schema with a
traceback line; a value that passes the schema but names nothing (a `study` entry that is not a
sweep) or a row of a `points_from_csv` file (which the schema never sees) surfaced later as a
traceback from a rule's input function. The Snakefile runs `schema_errors` and, once `validate`
has filled the defaults, `reference_errors`, and stops with `exit_on_errors` before it builds
anything.
"""

from __future__ import annotations

import copy
import functools
import math
import os
import sys
from pathlib import Path
from typing import Any

import jsonschema
import yaml

SCHEMA_PATH = Path(__file__).with_name("config.schema.yaml")


def load_schema(path: str | Path = SCHEMA_PATH) -> dict:
    """The schema (a copy: callers may change it). Parsed once per process: every `points_from_csv`
    sweep checks its rows against it, and the Snakefile is parsed at the start of every Snakemake call."""
    return load_yaml(path)


def load_yaml(path: str | Path) -> dict:
    """A YAML file (a copy: callers may change it), parsed once per process by libyaml. The Snakefile
    reads the study config and the schema with it instead of `configfile:` and `validate`, whose
    pure-Python parser takes ~0.15 s of CPU for each at every start of Snakemake."""
    return copy.deepcopy(_parsed_yaml(str(path)))


@functools.lru_cache(maxsize=None)
def _parsed_yaml(path: str) -> dict:
    with open(path) as stream:
        return yaml.load(stream, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)) or {}


def fill_defaults(config: dict, schema: dict) -> None:
    """Sets in `config` every `default` of the schema that applies, as Snakemake's `validate(config,
    schema)` does (a validator whose `properties` sets the defaults first), and raises
    jsonschema.ValidationError if the result violates the schema."""
    base = jsonschema.validators.validator_for(schema)
    check_properties = base.VALIDATORS["properties"]

    def properties_with_defaults(validator, properties, instance, sub):
        for name, subschema in properties.items():
            if "default" in subschema:
                instance.setdefault(name, subschema["default"])
        yield from check_properties(validator, properties, instance, sub)

    jsonschema.validators.extend(base, {"properties": properties_with_defaults})(schema).validate(config)


def _resolve(sub: dict, schema: dict) -> dict:
    """`sub` with its `$ref` / single `allOf` replaced by the definition it names."""
    while True:
        if "$ref" in sub:
            sub = schema["definitions"][sub["$ref"].rsplit("/", 1)[1]]
        elif len(sub.get("allOf", [])) == 1:
            sub = sub["allOf"][0]
        else:
            return sub


def allowed(sub: dict, schema: dict) -> str:
    """What the subschema admits, in words: "one of a, b", "a number in [0, 10]", ..."""
    sub = _resolve(sub, schema)
    if "enum" in sub:
        return "one of " + ", ".join(map(str, sub["enum"]))
    kind = sub.get("type")
    if kind in ("number", "integer"):
        spell = str if kind == "integer" else "{:g}".format
        low = (f"({spell(sub['exclusiveMinimum'])}" if "exclusiveMinimum" in sub else
               f"[{spell(sub['minimum'])}" if "minimum" in sub else "(-inf")
        high = (f"{spell(sub['exclusiveMaximum'])})" if "exclusiveMaximum" in sub else
                f"{spell(sub['maximum'])}]" if "maximum" in sub else "inf)")
        return f"{'an integer' if kind == 'integer' else 'a number'} in {low}, {high}"
    if kind == "string" and "pattern" in sub:
        return f"a string matching {sub['pattern']}"
    if kind == "object" and sub.get("additionalProperties") is False:
        return "a mapping with keys among " + ", ".join(sub.get("properties", {}))
    if kind == "object" and "propertyNames" in sub:
        return "a mapping whose keys are " + allowed(sub["propertyNames"], schema)
    return f"{kind}" if isinstance(kind, str) else f"see {SCHEMA_PATH.name}"


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _key(path) -> str:
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text or "(top level)"


def schema_errors(config: dict, schema: dict) -> list[str]:
    """One line per violation of the schema."""
    validator = jsonschema.Draft7Validator(schema)
    messages = []
    for error in sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.absolute_path))):
        messages.append(f"config key `{_key(error.absolute_path)}` = {_short(error.instance)}: "
                        f"{error.message if len(error.message) <= 120 else error.validator + ' failed'}; "
                        f"allowed: {allowed(error.schema, schema)}")
    return messages


def value_error(value: Any, sub: dict, schema: dict) -> str | None:
    """None when `value` satisfies the subschema and is finite, else what is allowed."""
    finite = not isinstance(value, float) or math.isfinite(value)
    valid = jsonschema.Draft7Validator({**sub, "definitions": schema["definitions"]}).is_valid(value)
    return None if finite and valid else allowed(sub, schema)


def reference_errors(config: dict, root: str | Path) -> list[str]:
    """On the validated config (defaults filled): `study` entries that name no sweep, and the sweeps
    whose points cannot be expanded (a bad `points_from_csv` row, a duplicate point, ...)."""
    from study.sweeps import sweep_points

    sweeps = config["sweeps"]
    messages = [f"config key `study[{index}]` = {_short(name)}: not a declared sweep; allowed: {', '.join(sweeps)}"
                for index, name in enumerate(config["study"]) if name not in sweeps]
    for name in sweeps:
        try:
            sweep_points(config, name, root)
        except (ValueError, OSError) as err:
            messages.append(f"config key `sweeps.{name}`: {err}")
    return messages


def exit_on_errors(messages: list[str]) -> None:
    """Print the messages, one line each, and end the process with exit code 1.

    For the Snakefile: Snakemake prints any exception raised there with a traceback line, and
    nothing has been started yet (no lock, no log, no job), so ending the process here is clean.
    """
    if not messages:
        return
    sys.stderr.write("".join(f"error: {message}\n" for message in messages))
    sys.stderr.flush()
    sys.stdout.flush()
    os._exit(1)
