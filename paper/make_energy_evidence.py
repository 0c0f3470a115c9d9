#!/usr/bin/python3
"""Write generated/energy_evidence.tex: what the energy-balance residual of the study's runs is,
measured on the reference case (docs/energy-balance.md), as LaTeX macros.

    paper/make_energy_evidence.py energy_evidence.json -o energy_evidence.tex

The JSON is what `python3 -m analysis energy-evidence` measured on three runs of the same case made with
`output.energy_decomposition = hht` (analysis/metrics/energy_evidence.py); this script only formats it. A
JSON without a role or a number is an error (exit 2) naming the file and the key.
"""
import argparse
import json
import math
import sys

from analysis.core.atomic import write_file
from analysis.metrics.energy_evidence import TERMS
from numbers_tex import ENERGY_MACRO_NAMES, render
from table_io import InputError

#: role -> macro suffix.
SUFFIX = {"alpha_zero": "AlphaZero", "alpha": "Alpha", "alpha_end": "AlphaEnd"}


def sci(value, digits=2):
    """'\\ensuremath{2.7\\times10^{-14}}', '\\ensuremath{0.274}'."""
    if not math.isfinite(value):
        raise InputError(f"non-finite value {value}")
    if value != 0 and (abs(value) < 1e-3 or abs(value) >= 1e5):
        exponent = math.floor(math.log10(abs(value)))
        mantissa = f"{value / 10 ** exponent:.{digits - 1}f}"
        return f"\\ensuremath{{{mantissa}\\times10^{{{exponent}}}}}"
    return f"\\ensuremath{{{value:.{digits + 1}g}}}"


def macros_of(evidence, case):
    """{macro: LaTeX} from analysis.metrics.energy_evidence's numbers: formatting only."""
    macros = {}
    for role, numbers in evidence.items():
        suffix = SUFFIX[role]
        macros[f"energyFlowed{suffix}"] = f"\\ensuremath{{{numbers['flowed']:.3g}}}"
        macros[f"energyResidual{suffix}"] = sci(numbers["residual"])
        if "ratio" not in numbers:
            continue
        macros[f"energyResidualEnd{suffix}"] = sci(numbers["residual_end"])
        macros[f"energyDissipationEnd{suffix}"] = sci(numbers["dissipation_end"])
        macros[f"energyRatio{suffix}"] = f"\\ensuremath{{{numbers['ratio']:.6f}}}"
        macros[f"energyClosure{suffix}"] = sci(numbers["closure"])
        for term in TERMS:
            macros[f"energyTerm{term.capitalize()}{suffix}"] = sci(numbers[f"term_{term}"])
    macros["energyEvidenceCase"] = (
        f"$\\nu = {case['nu']:g}$, $f = {case['f']:g}$, $H/h = {case['elements_per_H']}$, "
        f"$t_\\mathrm{{end}} = {case['t_end']:g}$\\,s")
    macros["energyEvidenceAlpha"] = f"\\ensuremath{{{case['hht_alpha']:g}}}"
    return {name: macros[name] for name in ENERGY_MACRO_NAMES}


def read_evidence(path):
    """(evidence by role, case) of an `analysis energy-evidence` JSON; InputError naming what is missing."""
    try:
        with open(path, encoding="utf-8") as file:
            document = json.load(file)
        runs, case = document["runs"], document["case"]
    except (OSError, ValueError, KeyError, TypeError) as err:
        raise InputError(f"{path}: not an energy-evidence JSON of `python3 -m analysis energy-evidence` "
                         f"({type(err).__name__}: {err})") from None
    for role in SUFFIX:
        needed = ["flowed", "residual"]
        if role != "alpha_zero":
            needed += ["residual_end", "dissipation_end", "ratio", "closure", *(f"term_{t}" for t in TERMS)]
        missing = [key for key in needed if not isinstance(runs.get(role, {}).get(key), (int, float))]
        if missing:
            raise InputError(f"{path}: runs.{role} lacks the number(s) {', '.join(missing)}")
    return runs, case


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("evidence", help="energy_evidence.json of `python3 -m analysis energy-evidence`")
    parser.add_argument("-o", "--output", required=True, help="energy_evidence.tex to write")
    args = parser.parse_args(argv)
    try:
        macros = macros_of(*read_evidence(args.evidence))
    except InputError as err:
        print(f"make_energy_evidence.py: error: {err}", file=sys.stderr)
        return 2
    write_file(args.output, render(macros, [args.evidence], script="paper/make_energy_evidence.py"))
    return 0

if __name__ == "__main__":
    sys.exit(main())
