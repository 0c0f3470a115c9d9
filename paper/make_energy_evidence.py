#!/usr/bin/python3
"""Write generated/energy_evidence.tex: what the energy-balance residual of the study's runs is,
measured on the reference case (docs/energy-balance.md), as LaTeX macros.

    paper/make_energy_evidence.py --alpha-zero a0.h5 --alpha a01.h5 --alpha-end a01_end.h5 -o energy_evidence.tex

Three runs of the same case with `output.energy_decomposition = hht`: hht_alpha = 0 (trapezoidal
rule, where the balance must close), and the study's hht_alpha with each contact weighting. For each:
the energy that flowed (J/m) and the largest |residual| relative to it (analysis/metrics/energy.py, the
measure the study reports for every run), and, for alpha > 0, the residual and the HHT dissipation
measured term by term at the end of the run, their ratio, the largest |residual + dissipation| over
the run, and each term's dissipation (all relative to the energy that flowed). A run without the decomposition, with the wrong alpha or weighting, or of another case
than the others is an error (exit 2) naming the file.
"""
import argparse
import math
import sys

from analysis.metrics.energy import energy_balance_error
from analysis.core.io import load_run
from numbers_tex import ENERGY_MACRO_NAMES, render
from analysis.core.atomic import write_file
from table_io import InputError

#: The runs, as (option, macro suffix, hht_alpha must be zero, contact weighting or None: any).
ROLES = (("alpha_zero", "AlphaZero", True, None), ("alpha", "Alpha", False, "alpha"),
         ("alpha_end", "AlphaEnd", False, "end"))
TERMS = ("gamma", "beta", "shift")
CASE_KEYS = (("material", "nu"), ("friction", "f"), ("mesh", "elements_per_H"), ("loading", "V0_over_cs"),
             ("time", "t_end"), ("time", "dt_times_cs"))


def sci(value, digits=2):
    """'\\ensuremath{2.7\\times10^{-14}}', '\\ensuremath{0.274}'."""
    if not math.isfinite(value):
        raise InputError(f"non-finite value {value}")
    if value != 0 and (abs(value) < 1e-3 or abs(value) >= 1e5):
        exponent = math.floor(math.log10(abs(value)))
        mantissa = f"{value / 10 ** exponent:.{digits - 1}f}"
        return f"\\ensuremath{{{mantissa}\\times10^{{{exponent}}}}}"
    return f"\\ensuremath{{{value:.{digits + 1}g}}}"


def read(path, alpha_zero, weighting):
    """(run, {dataset: array}) of one run, checked for its role."""
    import h5py

    run = load_run(path)
    alpha = run.config["time"]["hht_alpha"]
    if (alpha == 0) != alpha_zero:
        raise InputError(f"{path}: time.hht_alpha = {alpha:g}, expected " + ("0" if alpha_zero else "> 0"))
    if weighting and run.config["time"]["contact_weighting"] != weighting:
        raise InputError(f"{path}: time.contact_weighting = {run.config['time']['contact_weighting']}, "
                         f"expected {weighting}")
    if not run.complete:
        raise InputError(f"{path}: the run is incomplete ({run.end_reason})")
    names = ["dissipation_hht"] + [f"dissipation_hht_{t}" for t in TERMS]
    with h5py.File(path, "r") as file:
        if "global/dissipation_hht" not in file:
            raise InputError(f"{path}: no /global/dissipation_hht: run it with output.energy_decomposition = hht")
        extra = {name: file[f"global/{name}"][()] for name in names}
    return run, extra


def macros_of(runs):
    """{macro: LaTeX} from {role: (run, extra datasets)}."""
    macros = {}
    first = runs[ROLES[0][0]][0]
    for role, suffix, zero, _ in ROLES:
        run, extra = runs[role]
        g = run.global_series
        relative, _ = energy_balance_error(g.energy_kinetic, g.energy_elastic, g.work_external,
                                           g.dissipation_friction, g.energy_balance_residual)
        scale = float(max(abs(g.work_external).max(), abs(g.energy_elastic - g.energy_elastic[0]).max(),
                          g.energy_kinetic.max(), g.dissipation_friction.max()))
        macros[f"energyFlowed{suffix}"] = f"\\ensuremath{{{scale:.3g}}}"
        macros[f"energyResidual{suffix}"] = sci(relative)
        if zero:
            continue
        residual, dissipation = g.energy_balance_residual[-1], extra["dissipation_hht"][-1]
        macros[f"energyResidualEnd{suffix}"] = sci(-residual / scale)
        macros[f"energyDissipationEnd{suffix}"] = sci(dissipation / scale)
        macros[f"energyRatio{suffix}"] = f"\\ensuremath{{{-residual / dissipation:.6f}}}"
        closure = float(abs(g.energy_balance_residual + extra["dissipation_hht"]).max()) / scale
        macros[f"energyClosure{suffix}"] = sci(closure)
        for term in TERMS:
            macros[f"energyTerm{term.capitalize()}{suffix}"] = sci(extra[f"dissipation_hht_{term}"][-1] / scale)
    c = first.config
    macros["energyEvidenceCase"] = (
        f"$\\nu = {c['material']['nu']:g}$, $f = {c['friction']['f']:g}$, $H/h = {c['mesh']['elements_per_H']}$, "
        f"$t_\\mathrm{{end}} = {c['time']['t_end']:g}$\\,s")
    macros["energyEvidenceAlpha"] = f"\\ensuremath{{{runs['alpha'][0].config['time']['hht_alpha']:g}}}"
    return {name: macros[name] for name in ENERGY_MACRO_NAMES}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    for role, _, zero, weighting in ROLES:
        parser.add_argument(f"--{role.replace('_', '-')}", required=True, metavar="RUN_H5",
                            help="run with hht_alpha = 0" if zero else f"run with hht_alpha > 0, {weighting} weighting")
    parser.add_argument("-o", "--output", required=True, help="energy_evidence.tex to write")
    args = parser.parse_args(argv)
    try:
        runs = {role: read(getattr(args, role), zero, weighting) for role, _, zero, weighting in ROLES}
        case = {role: tuple(run.config[a][b] for a, b in CASE_KEYS) for role, (run, _) in runs.items()}
        for role, values in case.items():
            if values != case["alpha"]:
                raise InputError(f"{getattr(args, role)}: another case than {args.alpha} "
                                 f"({', '.join(f'{a}.{b}' for a, b in CASE_KEYS)} must agree)")
        macros = macros_of(runs)
    except InputError as err:
        print(f"make_energy_evidence.py: error: {err}", file=sys.stderr)
        return 2
    write_file(args.output, render(macros, [getattr(args, role) for role, *_ in ROLES],
                                         script="paper/make_energy_evidence.py"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
