"""The analysis steps that the Snakemake process runs itself (rules `measure` and `aggregate`, with
`run:`), so that measuring a run costs the measurement and not a Python start-up importing numpy,
h5py and scipy (~0.3 s of CPU, more than measuring an H/64 run; study/README.md, "Pipeline
overhead"). The same functions as `python3 -m analysis measure|aggregate` (analysis/cli.py), so the
files are the same; the line the command prints goes to the job's log, and so does an error, which
then fails the job.

Snakemake runs such jobs in threads of its own process: these functions print nothing and leave
the working directory and the standard streams alone (the analysis's atomic writes read the umask by
setting it and setting it back, harmless between threads that all write with the same umask).
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable


def _logged(log: str | Path, action: Callable[[], str]) -> None:
    """Runs `action`, writing its line (or its error) to `log`."""
    log = Path(log)
    log.parent.mkdir(parents=True, exist_ok=True)
    try:
        line = action()
    except Exception as err:
        log.write_text(f"error: {err}\n")
        raise
    log.write_text(line + "\n")


def measure(run_file: str, metrics_file: str, log: str) -> None:
    """`python3 -m analysis measure RUN -o METRICS`."""
    from analysis.cli import measure_file

    _logged(log, lambda: measure_file(Path(run_file), Path(metrics_file)))


def aggregate(metrics_files: list[str], reference: str, tolerance: float, select: list[str],
              directory: str, log: str) -> None:
    """`python3 -m analysis aggregate METRICS... --reference R --tolerance T [--select K=V]... -o DIR`;
    `select` holds the command's words (`--select`, `K=V`, ...)."""
    from analysis.cli import aggregate_files

    conditions = [word for word in select if word != "--select"]
    _logged(log, lambda: aggregate_files([Path(p) for p in metrics_files], Path(reference), Path(directory),
                                         float(tolerance), conditions))
