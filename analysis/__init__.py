"""slidewave analysis: from a run's HDF5 to metrics, Table 1 and the check against the paper.

Sub-packages, each a namespace (docs/architecture.md says what may import what): `core` (run-file
reader, errors, atomic writes, CSV tables), `theory` (closed forms), `fronts` (slip fronts and the
celerity), `metrics` (one run's metrics), `tables` (a sweep's tables), `confidence` (how sure the
study is). `python3 -m analysis --help` lists the commands. `analysis.core.io` is the only module
that reads HDF5.
"""

import re
from pathlib import Path


def _version() -> str:
    """The project's one version, `project(slidewave VERSION ...)` of CMakeLists.txt (the solver
    writes the same into run.h5); an installed copy without the checkout reads its metadata."""
    cmake = Path(__file__).resolve().parents[1] / "CMakeLists.txt"
    if cmake.is_file():
        match = re.search(r"project\(\s*slidewave\s+VERSION\s+([0-9][0-9.]*)", cmake.read_text())
        if match:
            return match.group(1)
    from importlib.metadata import version
    return version("slidewave")


__version__ = _version()
