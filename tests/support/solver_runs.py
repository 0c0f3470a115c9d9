"""The solver binary for Python tests that need real runs: where it is, skipping (a failure under
CI=true) when it or another tool is missing, and a tiny run (H/8, 60 s) with a chosen output section.

Not a test module: tests put this folder on sys.path and `import solver_runs`."""
import json
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SOLVER = Path(os.environ.get("SLIDEWAVE_BIN", REPO / "build" / "slidewave"))


def missing(message):
    """Skips the test for a missing tool; under CI=true a missing tool is a failure."""
    if os.environ.get("CI") == "true":
        pytest.fail(message)
    pytest.skip(message)


def solver_or_skip():
    """The solver binary (build/slidewave, or $SLIDEWAVE_BIN); skipped when it is not built."""
    if not (SOLVER.is_file() and os.access(SOLVER, os.X_OK)):
        missing(f"solver binary {SOLVER} not built (bash scripts/build.sh)")
    return SOLVER


def tiny_run(folder, output):
    """Runs the solver at H/8 up to 60 s in `folder` with `output` as the config's output section;
    returns the path of its run.h5."""
    solver = solver_or_skip()
    config = {"mesh": {"elements_per_H": 8}, "time": {"t_end": 60.0}, "output": output}
    (folder / "config.json").write_text(json.dumps(config))
    subprocess.run([str(solver), "run", str(folder / "config.json"), "-o", str(folder / "run.h5")],
                   check=True, capture_output=True, timeout=300)
    return folder / "run.h5"
