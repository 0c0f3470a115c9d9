"""The JSON summaries the report's macro generators read (make_how_sure.py, make_how_sure_limits.py):
read one, take one key, each failure an InputError that names the file."""

import json

from analysis.core.errors import InputError


def read(path):
    """The parsed JSON of path."""
    try:
        with open(path) as stream:
            return json.load(stream)
    except (OSError, json.JSONDecodeError) as err:
        raise InputError(f"{path}: cannot read ({err})") from None


def get(data, key, path):
    """data[key], or an InputError naming path and key."""
    if key not in data:
        raise InputError(f"{path}: no key '{key}'")
    return data[key]
