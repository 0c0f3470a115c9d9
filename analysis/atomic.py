"""Writing output files all-or-nothing: each file goes to a temporary name in its folder and is
renamed into place only after every file of the set has been written."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def write_files(contents: dict[Path, str]) -> None:
    """Write several text files; on any error none of them is left (old files stay as they were)."""
    temporaries: list[tuple[str, Path]] = []
    try:
        for target, text in contents.items():
            target = Path(target)
            target.parent.mkdir(parents=True, exist_ok=True)
            handle, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
            temporaries.append((name, target))
            with os.fdopen(handle, "w", newline="") as stream:
                stream.write(text)
        for name, target in temporaries:
            os.replace(name, target)
    finally:
        for name, _ in temporaries:
            if os.path.exists(name):
                os.unlink(name)


def write_file(target: str | Path, text: str) -> None:
    """Write one text file atomically."""
    write_files({Path(target): text})
