"""Reading a JSON object from a file (metrics, summaries, manifests): the one reader of the package's
JSON inputs, every failure an InputError that names the file."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from analysis.core.errors import InputError


def read_json_object(path: str | Path) -> dict[str, Any]:
    """The JSON object in `path`; InputError if the file cannot be read, is not JSON or not an object."""
    try:
        with open(path) as stream:
            data = json.load(stream)
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    except json.JSONDecodeError as err:
        raise InputError(f"{path}: not valid JSON ({err})") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: expected a JSON object")
    return data
