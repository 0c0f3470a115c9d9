"""Checks of the command-line config (`--config`, `--configfile`) before the Snakefile merges it into
study/config.yaml.

The merge (Snakemake's `update_config`, as `configfile:` does it) goes key by key, descending into
every mapping of the study config; an override that puts a scalar or a list where the study config
has a mapping (`--config sweeps=null`, `--config model=[1]`) makes that merge fail with a bare
TypeError that names neither the key nor the expected type. This check names both. Every other type
or range error is the schema's (study/config.schema.yaml), reported by `config_check.schema_errors`
with the key's path.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from study.config_check import load_yaml


class ConfigOverrideError(ValueError):
    """A command-line config value whose type cannot replace the study config's value."""


def _kind(value: Any) -> str:
    if isinstance(value, Mapping):
        return "a mapping"
    if isinstance(value, list):
        return "a list"
    return f"a {type(value).__name__}"


def clashes(overrides: Mapping, study: Mapping, prefix: str = "") -> list[str]:
    """One message per key where `study` holds a mapping and `overrides` something else."""
    messages = []
    for key, value in overrides.items():
        path = f"{prefix}{key}"
        expected = study.get(key) if isinstance(study, Mapping) else None
        if not isinstance(expected, Mapping):
            continue
        if isinstance(value, Mapping):
            messages += clashes(value, expected, f"{path}.")
        else:
            example = ", ".join(list(expected)[:3])
            messages.append(f"config key `{path}` must be a mapping (keys such as {example}), got "
                            f"{_kind(value)}: {value!r}")
    return messages


def check_overrides(overrides: Mapping, study_config_path: str | Path) -> None:
    """Raises ConfigOverrideError listing every override whose type clashes with the study config."""
    if not overrides:  # nothing to check: spares parsing the study config at every Snakemake start
        return
    study = load_yaml(study_config_path)
    messages = clashes(overrides, study)
    if messages:
        raise ConfigOverrideError(
            "bad command-line config (--config/--configfile):\n  " + "\n  ".join(messages)
            + f"\n(the study config: {study_config_path}; nested values: --config 'KEY={{...}}' or a "
              "--configfile)")
