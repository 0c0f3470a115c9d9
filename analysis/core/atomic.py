"""Writing output files all-or-nothing: each file goes to a temporary name in its folder and is
renamed into place only after every file of the set has been written.

The temporary file of `tempfile.mkstemp` has mode 0600, which the rename would keep; each file is
given the mode any other file gets (0666 minus the umask) before the rename, so that colleagues on
a shared project folder can read the results as they can read everything else there.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def _umask() -> int:
    """The process umask (read by setting it and setting it back: there is no pure getter)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def default_file_mode() -> int:
    """Mode of a newly created regular file under the current umask (open(2) with 0666)."""
    return 0o666 & ~_umask()


def write_files(contents: dict[Path, str]) -> None:
    """Write several text files; on any error none of them is left (old files stay as they were)."""
    temporaries: list[tuple[str, Path]] = []
    mode = default_file_mode()
    try:
        for target, text in contents.items():
            target = Path(target)
            target.parent.mkdir(parents=True, exist_ok=True)
            handle, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
            temporaries.append((name, target))
            with os.fdopen(handle, "w", newline="") as stream:
                stream.write(text)
            os.chmod(name, mode)
        for name, target in temporaries:
            os.replace(name, target)
    finally:
        for name, _ in temporaries:
            if os.path.exists(name):
                os.unlink(name)


def write_file(target: str | Path, text: str) -> None:
    """Write one text file atomically."""
    write_files({Path(target): text})
