"""The commands of the confidence studies, registered on `python3 -m analysis` (analysis/cli.py):
`ensemble`, `envelope`, `mesh-limit`, `timestep-limit`, `timeline`, `pulse-seeds`.

Each handler reads its tables, calls the module's pure `*_files` function and writes the files it
returns at once (analysis/core/atomic.py); an InputError becomes exit 2 in `analysis.cli.main`.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Callable

from analysis.core.atomic import write_files
from analysis.core.errors import InputError
from analysis.core.table_csv import read_table


def _write(output: Path, files: dict[str, str]) -> None:
    write_files({output / name: text for name, text in files.items()})


def _ensemble(args: argparse.Namespace) -> int:
    from analysis.confidence.ensemble import REQUIRED, ensemble_files
    from analysis.tables.reference import read_reference

    files = ensemble_files(read_table(args.metrics, REQUIRED), read_reference(args.reference), args.tolerance)
    _write(args.output, files)
    summary = json.loads(files["ensemble_summary.json"])
    print(f"ensemble: {summary['cells']} cells, {summary['runs']} runs; within "
          f"{100 * args.tolerance:g}%: {summary['within_tol_seed1']} (seed 1), "
          f"{summary['within_tol_mean']} (mean) of {summary['published_cells']} -> {args.output}")
    return 0


def _envelope(args: argparse.Namespace) -> int:
    from analysis.confidence.envelope import STATUSES, envelope_files

    if not args.tolerance > 0:
        raise InputError(f"--tolerance must be > 0 (got {args.tolerance})")
    try:
        spec = json.loads(args.spec)
    except json.JSONDecodeError as err:
        raise InputError(f"--spec is not valid JSON ({err})") from None
    ensemble = read_table(args.ensemble, ("nu", "f", "group", "published", "celerity_mean",
                                          "celerity_min", "celerity_max", "celerity_seed1"))
    files = envelope_files(ensemble, spec, args.tolerance)
    _write(args.output, files)
    summary = json.loads(files["envelope_summary.json"])
    print("envelope: " + ", ".join(f"{summary[s]} {s}" for s in STATUSES)
          + f" of {summary['cells']} cells -> {args.output}")
    return 0


def _mesh_option(text: str) -> tuple[int, str]:
    name, sep, path = text.partition("=")
    try:
        n = int(name)
    except ValueError:
        n = 0
    if not sep or n <= 0 or not path:
        raise argparse.ArgumentTypeError(f"--mesh takes N=PATH with N > 0 elements per H (got '{text}')")
    return n, path


def _mesh_limit(args: argparse.Namespace) -> int:
    from analysis.confidence.mesh_limit import REQUIRED, mesh_limit_files
    from analysis.tables.reference import read_reference

    paths = dict(args.mesh)
    if len(paths) != len(args.mesh):
        raise InputError("--mesh: a mesh N is given twice")
    tables = {n: read_table(p, REQUIRED) for n, p in paths.items()}
    files = mesh_limit_files(tables, paths, read_reference(args.reference), args.tolerance)
    _write(args.output, files)
    print(json.loads(files["mesh_limit_summary.json"])["verdict"])
    return 0


def _timestep_limit(args: argparse.Namespace) -> int:
    from analysis.confidence.timestep_limit import REQUIRED, timestep_files
    from analysis.tables.reference import read_reference

    files = timestep_files([read_table(p, REQUIRED) for p in args.tables], read_reference(args.reference),
                           args.tolerance)
    _write(args.output, files)
    summary = json.loads(files["timestep_limit_summary.json"])
    print(summary["limit_sentence"], summary["theory_sentence"])
    return 0


def _timeline(args: argparse.Namespace) -> int:
    from analysis.confidence.timeline import run_events, timeline_files

    sets = {}
    for label, *folders in args.set:
        if not folders:
            raise InputError(f"--set {label}: no run folder")
        if label in sets:
            raise InputError(f"--set {label}: the label is given twice")
        sets[label] = [run_events(Path(folder)) for folder in folders]
    files = timeline_files(sets)
    _write(args.output, files)
    print(files["timeline.md"], end="")
    return 0


def _pulse_seeds(args: argparse.Namespace) -> int:
    from analysis.confidence.pulse_seeds import REQUIRED, pulse_files
    from analysis.tables.reference import cell_key

    files = pulse_files([read_table(p, REQUIRED) for p in args.tables], cell_key(*args.cell))
    _write(args.output, files)
    print(files["pulse_seeds.md"], end="")
    return 0


def add_commands(commands: argparse._SubParsersAction,
                 reference_options: Callable[[argparse.ArgumentParser], None]) -> None:
    """Register the six confidence commands; `reference_options` adds --reference and --tolerance."""
    from analysis.tables.aggregate import DEFAULT_TOLERANCE

    p = commands.add_parser("ensemble", help="runs that differ only by seed -> per-cell statistics "
                            "(analysis/confidence/ensemble.py)")
    p.add_argument("metrics", type=Path, help="all_metrics.csv of a sweep (python3 -m analysis aggregate)")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    reference_options(p)
    p.set_defaults(handler=_ensemble)

    p = commands.add_parser("envelope", help="the method envelope of every published cell "
                            "(analysis/confidence/envelope.py)")
    p.add_argument("--ensemble", type=Path, required=True, help="ensemble.csv (python3 -m analysis ensemble)")
    p.add_argument("--spec", required=True, help="the variants as JSON text (see analysis/confidence/envelope.py)")
    p.add_argument("--tolerance", type=float, default=DEFAULT_TOLERANCE,
                   help="relative tolerance of 'within' (default %(default)g)")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    p.set_defaults(handler=_envelope)

    p = commands.add_parser("mesh-limit", help="every published cell against 1/N and its Richardson limit "
                            "(analysis/confidence/mesh_limit.py)")
    p.add_argument("--mesh", type=_mesh_option, action="append", required=True,
                   help="N=all_metrics.csv of the published cells at H/N (repeat; at least 3)")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    reference_options(p)
    p.set_defaults(handler=_mesh_limit)

    p = commands.add_parser("timestep-limit", help="the backward cells against dt c_s "
                            "(analysis/confidence/timestep_limit.py)")
    p.add_argument("tables", type=Path, nargs="+", help="all_metrics.csv of the time-step sweeps")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    reference_options(p)
    p.set_defaults(handler=_timestep_limit)

    p = commands.add_parser("timeline", help="the Fig. 3 events across seeds and meshes "
                            "(analysis/confidence/timeline.py)")
    p.add_argument("--set", nargs="+", action="append", required=True, metavar=("LABEL", "DIR"),
                   help="a label and the run folders of one set (repeat)")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    p.set_defaults(handler=_timeline)

    p = commands.add_parser("pulse-seeds", help="major-pulse counts per lambda/H across seeds "
                            "(analysis/confidence/pulse_seeds.py)")
    p.add_argument("tables", type=Path, nargs="+", help="all_metrics.csv tables")
    p.add_argument("--cell", type=float, nargs=2, default=(0.2, 1.5), metavar=("NU", "F"))
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    p.set_defaults(handler=_pulse_seeds)
