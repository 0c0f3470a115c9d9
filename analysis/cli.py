"""Command line: `/usr/bin/python3 -m analysis COMMAND ...`, the one entry of every analysis command:
measure, aggregate, compare, score-rules, energy-evidence, flutter-boundary, bimaterial, contrast-theory,
interface-mode, and
the confidence studies ensemble, envelope, mesh-limit, timestep-limit, timeline, pulse-seeds
(analysis/confidence/commands.py).

Exit codes: 0 success; 1 `compare` found cells out of tolerance or of the wrong sign, or compared
none; 2 bad input (the message on stderr names the file and the problem; no output file is
written), among them a run that was interrupted (`measure` without `--allow-incomplete`) and an
output path that is one of the inputs.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from analysis.core.errors import InputError

EXIT_FAILED_CHECK = 1
EXIT_BAD_INPUT = 2


def _refuse_input_as_output(output: Path, inputs: list[Path]) -> None:
    """InputError when the output path is one of the inputs (same path or same file), before
    anything is written: `measure X -o X` would replace the run with its metrics."""
    for source in inputs:
        same = Path(os.path.abspath(output)) == Path(os.path.abspath(source))
        if not same and output.exists() and source.exists():
            same = os.path.samefile(output, source)
        if same:
            raise InputError(f"{output}: the output is the input file {source}; choose another "
                             "output path (nothing was written)")


def measure_file(run_path: Path, output: Path, *, threshold_rel: float | None = None,
                 window_length: float | None = None, major_duration: float | None = None,
                 allow_incomplete: bool = False) -> str:
    """`measure`: one run.h5 -> metrics JSON; returns the line the command prints. Also called by
    the pipeline inside the Snakemake process (study/in_process.py)."""
    from analysis.core.atomic import write_file
    from analysis.core.io import load_run
    from analysis.metrics.measure import Settings, measure_run

    _refuse_input_as_output(output, [run_path])
    given = {"threshold_rel": threshold_rel, "window_length": window_length, "major_duration": major_duration}
    settings = Settings(**{key: value for key, value in given.items() if value is not None})
    try:
        settings.check()
    except ValueError as err:
        raise InputError(str(err)) from None
    run = load_run(run_path)
    # An interrupted run stopped for a reason that has nothing to do with the physics; its
    # metrics would look like a result (a contact failure is a physical outcome, measured).
    if run.end_reason == "interrupted" and not allow_incomplete:
        raise InputError(f"{run_path}: the run was interrupted (end_reason 'interrupted', "
                         "complete = 0): its metrics would not be a result; resume or rerun it, "
                         "or pass --allow-incomplete to measure it anyway")
    metrics = measure_run(run, settings)
    write_file(output, json.dumps(metrics, indent=2, allow_nan=False) + "\n")
    c, xc = metrics["celerity"], metrics["celerity_xcorr"]
    return (f"{run_path}: celerity "
            + ("undefined (" + metrics["celerity_reason"] + ")" if c is None else
               f"{c:+.4f} m/s (cross-correlation {xc if xc is None else format(xc, '+.4f')})")
            + f", regime {metrics['regime']}, category {metrics['category']}, "
            f"min T/N {metrics['min_T_over_N']:.3f}"
            + ("" if metrics["complete"] else f", INCOMPLETE ({metrics['end_reason']})")
            + f" -> {output}")


def _measure(args: argparse.Namespace) -> int:
    print(measure_file(args.run, args.output, threshold_rel=args.threshold, window_length=args.window,
                       major_duration=args.major_duration, allow_incomplete=args.allow_incomplete))
    return 0


def aggregate_files(metrics_paths: list[Path], reference_path: Path, output: Path, tolerance: float,
                    select: list[str] = ()) -> str:
    """`aggregate`: metrics files -> the tables in folder `output`; returns the line the command
    prints. Also called by the pipeline inside the Snakemake process (study/in_process.py)."""
    from analysis.core.atomic import write_files
    from analysis.tables import aggregate as agg
    from analysis.tables.reference import read_reference

    reference = read_reference(reference_path)
    _refuse_input_as_output(output, list(metrics_paths) + [reference_path])
    metrics = [agg.load_metrics(path) for path in metrics_paths]
    table_metrics = agg.select(metrics, agg.parse_selection(list(select)))
    files, summary = agg.aggregate(metrics, table_metrics, reference, tolerance)
    write_files({output / name: text for name, text in files.items()})
    return agg.summary_line(summary) + f" -> {output}"


def _aggregate(args: argparse.Namespace) -> int:
    print(aggregate_files(args.metrics, args.reference, args.output, args.tolerance, args.select))
    return 0


def _compare(args: argparse.Namespace) -> int:
    from analysis.tables.compare import compare, read_table
    from analysis.tables.reference import read_reference

    reference = read_reference(args.reference)
    result = compare(read_table(args.table), reference, args.tolerance,
                     args.min_within, ratchet=args.ratchet,
                     known_mismatches=tuple(args.known_mismatch or ()))
    for note in result.notes:
        print(note)
    for failure in result.failures:
        print(failure)
    print(result.summary())
    return 0 if result.passed else EXIT_FAILED_CHECK


def _score_rules(args: argparse.Namespace) -> int:
    from analysis.core.atomic import write_files
    from analysis.tables import aggregate as agg
    from analysis.tables.reference import read_reference
    from analysis.tables.rule_scores import SCORE_FILES, rule_scores, score_files, scores_csv, scores_text

    reference = read_reference(args.reference)
    outputs = {}
    if args.out_dir is not None:
        outputs.update({args.out_dir / name: None for name in SCORE_FILES})
    if args.out is not None:
        outputs[args.out] = None
    for output in outputs:
        _refuse_input_as_output(output, list(args.metrics) + [args.reference])
    metrics = agg.select([agg.load_metrics(path) for path in args.metrics],
                         agg.parse_selection(args.select))
    scores = rule_scores(metrics, reference, args.tolerance)
    print(scores_text(scores), end="")
    if args.out_dir is not None:
        outputs.update({args.out_dir / name: text for name, text in score_files(scores).items()})
    if args.out is not None:
        outputs[args.out] = scores_csv(scores)
    if outputs:
        write_files(outputs)
        print(f"-> {', '.join(str(path) for path in outputs)}")
    return 0


def _energy_evidence(args: argparse.Namespace) -> int:
    from analysis.core.atomic import write_file
    from analysis.metrics.energy_evidence import ROLES, energy_evidence

    paths = {role: getattr(args, role) for role, *_ in ROLES}
    _refuse_input_as_output(args.output, list(paths.values()))
    evidence, case = energy_evidence({role: str(path) for role, path in paths.items()})
    document = {"case": case, "runs": evidence, "inputs": {role: str(path) for role, path in paths.items()}}
    write_file(args.output, json.dumps(document, indent=2, allow_nan=False) + "\n")
    print(f"energy evidence of {', '.join(str(path) for path in paths.values())} -> {args.output}")
    return 0


def _flutter_boundary(args: argparse.Namespace) -> int:
    try:
        from analysis.theory.flutter import flutter_boundary
    except ImportError as err:
        raise InputError(f"the flutter-boundary theory (analysis/theory/flutter.py) is not available: {err}") from None
    for nu in args.nu:
        if not 0.0 <= nu < 0.5:
            raise InputError(f"--nu {nu} outside [0, 0.5)")
    for nu in args.nu:
        lower, upper = flutter_boundary(nu)
        print(f"{nu:g} {lower:.6g} {upper:.6g}")
    return 0


def _bimaterial(args: argparse.Namespace) -> int:
    from analysis.theory.bimaterial_stability import bimaterial_regime, instability_threshold
    from analysis.theory.interface_wave import ElasticSolid

    nu_substrate = args.nu if args.nu_substrate is None else args.nu_substrate
    values = [("--E", args.E), ("--rho", args.rho), ("--rho-ratio", args.rho_ratio)]
    values += [("--E-ratio", ratio) for ratio in args.E_ratio]
    for key, value in values:
        if not (value > 0.0 and value < float("inf")):
            raise InputError(f"{key} {value} outside (0, inf)")
    for key, value in (("--nu", args.nu), ("--nu-substrate", nu_substrate)):
        if not 0.0 <= value < 0.5:
            raise InputError(f"{key} {value} outside [0, 0.5)")
    for f in args.f:
        if not (f > 0.0 and f < float("inf")):
            raise InputError(f"--f {f} outside (0, inf)")
    layer = ElasticSolid(args.E, args.nu, args.rho)
    print(f"layer E {layer.E:g} Pa nu {layer.nu:g} rho {layer.rho:g} kg/m^3 c_s1 {layer.c_s:.6g} m/s; "
          "speeds and growth rates per unit wavenumber in units of c_s1; + = +x = the layer's slip direction")
    for ratio in args.E_ratio:
        substrate = ElasticSolid(args.E * ratio, nu_substrate, args.rho * args.rho_ratio)
        print(f"E_ratio {ratio:g} substrate E {substrate.E:g} Pa nu {substrate.nu:g} rho {substrate.rho:g} "
              f"kg/m^3 c_s2/c_s1 {substrate.c_s / layer.c_s:.6g}")
        for f in args.f:
            regime = bimaterial_regime(layer.E, layer.nu, layer.rho, substrate.E, substrate.nu,
                                       substrate.rho, f)
            if f == args.f[0]:
                c_gr = regime["c_gR_over_cs1"]
                print("c_gR " + ("none" if c_gr is None else f"{c_gr:.6f}"))
            if regime["unstable"]:
                print(f"f {f:g} unstable growth_per_k {regime['growth_rate_per_k_over_cs1']:.6f} "
                      f"phase_speed {regime['phase_speed_over_cs1']:+.6f} direction {regime['direction']} "
                      f"family {regime['family']} n_growing {regime['n_growing']}")
            else:
                print(f"f {f:g} stable")
        if args.threshold:
            onsets = [instability_threshold(layer, substrate, family=family)
                      for family in (None, "forward", "backward")]
            print("f_threshold {:.6g} forward {:.6g} backward {:.6g}".format(*onsets))
    return 0


def _contrast_theory(args: argparse.Namespace) -> int:
    from analysis.core.atomic import write_file
    from analysis.core.table_csv import csv_text
    from analysis.theory.contrast_theory import COLUMNS, contrast_theory_rows

    points = []
    for nu, contrast, f in args.point:
        try:
            points.append((float(nu), None if contrast == "rigid" else float(contrast), float(f)))
        except ValueError:
            raise InputError(f"--point {nu} {contrast} {f}: expected NU CONTRAST F, numbers (CONTRAST may be "
                             "'rigid')") from None
    try:
        rows = contrast_theory_rows(points, E=args.E, rho=args.rho)
    except ValueError as err:
        raise InputError(f"--point: {err}") from None
    write_file(args.output, csv_text(COLUMNS, rows))
    print(f"theory of {len(rows)} points -> {args.output}")
    return 0


def _interface_mode(args: argparse.Namespace) -> int:
    from analysis.core.io import load_run
    from analysis.metrics.interface_mode import interface_wave_speed, mode_growth

    run = load_run(args.run)
    field = args.field or ("slip" if run.attr("f") == 0.0 else "slip_velocity")
    if run.attr("f") == 0.0:
        result = interface_wave_speed(run, args.mode, field, args.start, args.end)
    else:
        result = mode_growth(run, args.mode, field, args.start, args.end)
    result = {"run": str(args.run), "mode": args.mode, "field": field, **result}
    print(json.dumps(result, indent=2, allow_nan=False))
    return 0


def build_parser() -> argparse.ArgumentParser:
    from analysis.fronts.celerity import DEFAULT_MAJOR_DURATION, DEFAULT_THRESHOLD_REL, DEFAULT_WINDOW_LENGTH

    parser = argparse.ArgumentParser(prog="python3 -m analysis",
                                     description="Measure slidewave runs and compare with the paper.")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = commands.add_parser("measure", help="one run.h5 -> metrics.json")
    p.add_argument("run", type=Path, help="run file (format_version 2, or 3 with a substrate)")
    p.add_argument("-o", "--output", type=Path, required=True, help="metrics JSON to write")
    p.add_argument("--threshold", type=float, default=DEFAULT_THRESHOLD_REL,
                   help="slip-velocity threshold relative to V0 (default %(default)g)")
    p.add_argument("--allow-incomplete", action="store_true",
                   help="also measure a run that was interrupted (its metrics say so: complete, "
                        "end_reason); a contact failure is always measured")
    p.add_argument("--window", type=float, default=DEFAULT_WINDOW_LENGTH,
                   help="celerity window length in s (default %(default)g)")
    p.add_argument("--major-duration", type=float, default=DEFAULT_MAJOR_DURATION,
                   help="a front followed this long (s) is major (default %(default)g)")
    p.set_defaults(handler=_measure)

    p = commands.add_parser("aggregate", help="metrics files -> Table 1 (CSV, Markdown, LaTeX), summary")
    p.add_argument("metrics", type=Path, nargs="+", help="metrics JSON files")
    p.add_argument("-o", "--output", type=Path, required=True, help="output folder")
    _reference_options(p)
    p.add_argument("--select", action="append", default=[], metavar="KEY=VALUE",
                   help="only metrics with this value enter Table 1 (repeatable), e.g. elements_per_H=32")
    p.set_defaults(handler=_aggregate)

    p = commands.add_parser("compare", help="check a table1.csv against the published celerities")
    p.add_argument("table", type=Path, help="table with columns nu, f, celerity")
    _reference_options(p)
    p.add_argument("--min-within", type=int, default=0,
                   help="fail when fewer cells are within tolerance (default %(default)s)")
    p.add_argument("--ratchet", action="store_true",
                   help="CI gate: out-of-tolerance cells are notes; wrong sign or regime, or fewer than "
                        "--min-within cells within tolerance, fail")
    p.add_argument("--known-mismatch", action="append", metavar='"nu=N f=F"',
                   help="a cell whose wrong sign or regime is recorded (with its explanation) in the "
                        "ratchet file; reported, not failed (repeatable)")
    p.set_defaults(handler=_compare)

    p = commands.add_parser("score-rules",
                            help="Table 1 scored under every celerity rule (docs/measurement-rule.md)")
    p.add_argument("metrics", type=Path, nargs="+", help="metrics JSON files, one per published cell")
    _reference_options(p)
    p.add_argument("--select", action="append", default=[], metavar="KEY=VALUE",
                   help="only metrics with this value are scored (repeatable), e.g. elements_per_H=64")
    p.add_argument("--out", type=Path, help="also write the scores as CSV (one row per rule)")
    p.add_argument("-o", "--out-dir", type=Path,
                   help="also write DIR/rule_scores.csv, .md and .tex (the report's table)")
    p.set_defaults(handler=_score_rules)

    p = commands.add_parser("energy-evidence",
                            help="three runs with output.energy_decomposition = hht -> the energy-balance "
                                 "evidence of the report (JSON; analysis/metrics/energy_evidence.py)")
    from analysis.metrics.energy_evidence import ROLES
    for role, zero, weighting in ROLES:
        p.add_argument(f"--{role.replace('_', '-')}", dest=role, type=Path, required=True, metavar="RUN_H5",
                       help="run with hht_alpha = 0" if zero else f"run with hht_alpha > 0, {weighting} weighting")
    p.add_argument("-o", "--output", type=Path, required=True, help="JSON to write")
    p.set_defaults(handler=_energy_evidence)

    p = commands.add_parser("flutter-boundary",
                            help="print 'nu f_lower f_upper' of the flutter wedge, one line per nu")
    p.add_argument("--nu", type=float, nargs="+", required=True, help="Poisson's ratios")
    p.set_defaults(handler=_flutter_boundary)

    p = commands.add_parser("bimaterial",
                            help="generalized Rayleigh speed and the most unstable mode of steady sliding "
                                 "of the layer on a deformable substrate (analysis/theory/bimaterial_stability.py)")
    p.add_argument("--E-ratio", type=float, nargs="+", required=True,
                   help="E_substrate / E_layer (one block of output per value)")
    p.add_argument("--nu", type=float, required=True, help="Poisson's ratio of the layer")
    p.add_argument("--nu-substrate", type=float, help="Poisson's ratio of the substrate (default: --nu)")
    p.add_argument("--rho-ratio", type=float, default=1.0, help="rho_substrate / rho_layer (default %(default)g)")
    p.add_argument("--f", type=float, nargs="+", required=True, help="Coulomb coefficients")
    p.add_argument("--E", type=float, default=1000.0, help="E of the layer, Pa (default %(default)g)")
    p.add_argument("--rho", type=float, default=1000.0, help="rho of the layer, kg/m^3 (default %(default)g)")
    p.add_argument("--threshold", action="store_true",
                   help="also print the smallest f with a growing mode (0 with a generalized Rayleigh wave), "
                        "of any family, forward and backward (docs/bimaterial-theory.md)")
    p.set_defaults(handler=_bimaterial)

    p = commands.add_parser("contrast-theory",
                            help="the bimaterial theory at the points of a contrast sweep: onsets of each family "
                                 "and the most unstable mode, CSV (analysis/theory/contrast_theory.py)")
    p.add_argument("--point", nargs=3, action="append", required=True, metavar=("NU", "CONTRAST", "F"),
                   help="nu, E_substrate / E ('rigid': the rigid flat) and f of one point (repeatable)")
    p.add_argument("--E", type=float, default=1000.0, help="E of the layer, Pa (default %(default)g)")
    p.add_argument("--rho", type=float, default=1000.0, help="rho of the layer and the substrate, kg/m^3 "
                                                             "(default %(default)g)")
    p.add_argument("-o", "--output", type=Path, required=True, help="CSV to write")
    p.set_defaults(handler=_contrast_theory)

    p = commands.add_parser("interface-mode",
                            help="one wavenumber of a run with a substrate against interface-wave theory: the "
                                 "interface-wave speed (f = 0) or the growth rate and phase speed of steady "
                                 "sliding (f > 0); JSON on stdout (analysis/metrics/interface_mode.py)")
    p.add_argument("run", type=Path, help="run file with a substrate (format_version 3), seeded by `mode_seed`")
    p.add_argument("--mode", type=int, default=1, help="wavelengths in the period (default %(default)s)")
    p.add_argument("--field", default=None,
                   help="interface field (default slip at f = 0, slip_velocity otherwise)")
    p.add_argument("--start", type=float, default=None, help="window start (s, default the first output)")
    p.add_argument("--end", type=float, default=None, help="window end (s, default the last output)")
    p.set_defaults(handler=_interface_mode)

    from analysis.confidence.commands import add_commands
    add_commands(commands, _reference_options)
    return parser



def _reference_options(p: argparse.ArgumentParser) -> None:
    """--reference and --tolerance, the same for every command that scores against Table 1."""
    from analysis.tables.aggregate import DEFAULT_TOLERANCE
    from analysis.tables.reference import DEFAULT_REFERENCE

    p.add_argument("--reference", type=Path, default=DEFAULT_REFERENCE,
                   help="published celerities (default %(default)s)")
    p.add_argument("--tolerance", type=float, default=DEFAULT_TOLERANCE,
                   help="relative tolerance of a cell's deviation (default %(default)g)")

def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.handler(args)
    except InputError as err:
        print(f"error: {err}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as err:
        # The file that failed: the one the OS names, else the command's output.
        where = err.filename or getattr(args, "output", None) or "?"
        print(f"error: {where}: {err.strerror or err}", file=sys.stderr)
        return EXIT_BAD_INPUT
