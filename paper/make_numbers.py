#!/usr/bin/python3
"""Write generated/numbers.tex: every number the report quotes, as LaTeX macros.

    paper/make_numbers.py --summary results/study/table/summary.json \\
        --runs results/study/table/all_metrics.csv --grid results/table1/table/all_metrics.csv \\
        --table1 results/study/table/table1.csv --reference-cell 0.2 1.5 \\
        --sweep period lambda_over_H results/period/table/all_metrics.csv ... -o numbers.tex

The pipeline (rule `paper_numbers`) passes every input by name from study/config.yaml
(`paper.numbers`): nothing here knows the study's defaults or guesses which runs form what.

- --summary: summary.json of the study's Table 1 comparison (`python3 -m analysis aggregate`).
- --runs: all_metrics.csv of the whole study (how many runs, the largest energy-balance error).
- --grid: all_metrics.csv of the (nu, f) grid sweep, one run per cell: the set-up constants (one value
  across the grid), the category counts, the flutter wedge (column inside_flutter_wedge), the forward
  waves below sqrt(2) c_s (column below_sqrt2_cs), the frictional dissipation.
- --table1: table1.csv of the study (published values).
- --reference-cell NU F: the cell the text discusses; each sweep is read at it.
- --sweep ROLE PARAMETER FILE: the one-parameter sweep that plays ROLE (SWEEP_ROLES) in the text,
  the parameter it varies, and its all_metrics.csv.

A number the text needs that the inputs lack is an error (exit 2) naming the macro and the input.
Only selection and formatting happen here; every value comes from the inputs.
"""
import argparse
import math
import statistics
import sys
from collections import Counter

from numbers_tex import MACRO_NAMES, render
from analysis.core.atomic import write_file
from analysis.core.json_file import read_json_object
from table_io import InputError, read_rows
from table_io import label as table_label

SUMMARY_KEYS = {  # macro: (summary.json key, kind); a fraction is printed in percent
    "cellsTotal": ("cells_total", "count"),
    "cellsMissing": ("cells_missing", "count"),
    "cellsCompared": ("cells_compared", "count"),
    "cellsWithin": ("within_tolerance", "count"),
    "cellsReproduced": ("reproduced", "count"),
    "categoryMatches": ("category_matches", "count"),
    "tolerancePercent": ("tolerance", "fraction"),
    "signMatches": ("sign_matches", "count"),
    "regimeMatches": ("regime_matches", "count"),
    "medianDeviationPercent": ("median_abs_deviation", "fraction"),
    "maxDeviationPercent": ("max_abs_deviation", "fraction"),
}
SETUP_KEYS = {"youngModulus": "E", "density": "rho", "layerHeight": "H", "preloadRatio": "Uy_over_H",
              "preshearRatio": "preshear_ratio", "hhtAlpha": "hht_alpha", "dtTimesCs": "dt_times_cs"}
CATEGORIES = {
    "nNoOpening": "no_opening",
    "nIntersonicOpening": "intersonic_opening",
    "nIntersonicOpeningInversion": "intersonic_opening_inversion",
    "nSupersonicBackward": "supersonic_backward_opening",
}
#: The sweeps the text discusses: role -> {macro: (column quoted at each parameter value, decimals)};
#: "-" as the column: the parameter values themselves.
SWEEP_ROLES = {
    "period": {"periodRatios": ("-", None), "pulseCountsPeriod": ("pulse_count", 0)},
    "shear_rate": {"minTNShearRate": ("min_T_over_N", 2), "celerityShearRate": ("celerity", 3)},
    "density": {"celerityOverCsDensity": ("celerity_over_cs", 3)},
    "mesh": {"celerityMesh": ("celerity", 3)},
    "timestep": {"celerityTimestep": ("celerity", 3)},
}
#: Poisson's ratios at which the text follows the backward pulses back to forward ones (the paper's).
SWITCH_NUS = {"FNuFortyFive": 0.45, "FNuFortyNine": 0.49}
GRID_COLUMNS = ("nu", "f", "category", "celerity", "celerity_over_cs", "regime", "min_T_over_N", "opening", "inversion",
                "below_sqrt2_cs", "inside_flutter_wedge", "V0_over_cs", "lambda_over_H", "elements_per_H",
                "dissipative_friction_opening", "dissipative_friction_before_opening",
                "friction_energy_share_opening", *SETUP_KEYS.values())


# ---------------------------------------------------------------- formatting

def num(value, digits=3, decimals=None):
    """A number for text or math: '\\ensuremath{-0.31}', '\\ensuremath{1.2\\times10^{-4}}';
    `decimals` fixes the digits after the point (celerities: 3, as in the paper's Table 1).
    None when the value is not a finite number."""
    if value is None or isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        return None
    if decimals is not None:
        return f"\\ensuremath{{{value:.{decimals}f}}}"
    if isinstance(value, int) or (float(value).is_integer() and abs(value) < 1e6):
        return f"\\ensuremath{{{int(value)}}}"
    if value != 0 and (abs(value) < 1e-3 or abs(value) >= 1e5):
        exponent = math.floor(math.log10(abs(value)))
        mantissa = value / 10 ** exponent
        text = f"{mantissa:.{max(digits - 1, 0)}g}"
        text = "" if text == "1" else ("-" if text == "-1" else text + r"\times")
        return f"\\ensuremath{{{text}10^{{{exponent}}}}}"
    return f"\\ensuremath{{{value:.{digits}g}}}"


def label(value):
    """A category or regime as text (table_io.LABELS: 'no_slip' -> 'uniform sliding')."""
    return table_label(value)


def cell_list(cells):
    """Summary cells 'nu=0.45 f=0.9' as '$(\\nu, f) = (0.45, 0.9)$, ...'; 'none' for none."""
    if not cells:
        return "none"
    pairs = [c.replace("nu=", "").replace(" f=", ", ") for c in cells]
    return r"$(\nu, f) = $ " + ", ".join(f"$({p})$" for p in pairs)


# ---------------------------------------------------------------- inputs

def finite(value):
    return isinstance(value, float) and math.isfinite(value)


def same(a, b):
    return finite(a) and finite(b) and math.isclose(a, b, rel_tol=1e-6)


def one_per_cell(rows, path):
    """The rows of a grid sweep keyed by (nu, f); InputError for a cell with two runs."""
    cells = {}
    for r in rows:
        if (r["nu"], r["f"]) in cells:
            raise InputError(f"{path}: two runs at nu={r['nu']:g} f={r['f']:g}; the grid has one per cell")
        cells[(r["nu"], r["f"])] = r
    return cells


def at_cell(rows, nu, f):
    return [r for r in rows if same(r["nu"], nu) and same(r["f"], f)]


# ---------------------------------------------------------------- macros

def summary_macros(summary, path):
    macros = {}
    for macro, (key, kind) in SUMMARY_KEYS.items():
        value = summary.get(key)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(f"{path}: no number under '{key}' (for \\{macro})")
        macros[macro] = num(100.0 * value if kind == "fraction" else value, 3 if kind == "fraction" else 6)
    return macros


def setup_macros(grid, path):
    """The set-up constants, each one value across the grid's runs."""
    macros = {}
    for macro, key in SETUP_KEYS.items():
        values = {r[key] for r in grid}
        if len(values) != 1:
            raise InputError(f"{path}: column {key} takes {len(values)} values across the grid "
                             f"({sorted(map(str, values))[:4]}); \\{macro} needs one")
        macros[macro] = num(values.pop())
    macros["hhtAlphaClassic"] = num(-grid[0]["hht_alpha"])
    return macros


def grid_macros(grid, reference_cell):
    m = {}
    nu, f = reference_cell
    reference = at_cell(grid, nu, f)
    if len(reference) != 1:
        raise InputError(f"the grid has {len(reference)} runs at the reference cell nu={nu:g} f={f:g}")
    reference = reference[0]
    m.update(referenceNu=num(nu), referenceF=num(f), referenceVzero=num(reference["V0_over_cs"]),
             referencePeriod=num(reference["lambda_over_H"]))
    meshes = {r["elements_per_H"] for r in grid}
    m["nGridPoints"] = num(len(grid))
    m["gridMesh"] = num(meshes.pop()) if len(meshes) == 1 else None
    m["nuValues"] = ", ".join(num(v) for v in sorted({r["nu"] for r in grid}))
    m["fValues"] = ", ".join(num(v) for v in sorted({r["f"] for r in grid}))
    counts = Counter(r["category"] for r in grid)
    for macro, category in CATEGORIES.items():
        m[macro] = num(counts.get(category, 0))
    others = {c: n for c, n in counts.items() if c not in CATEGORIES.values()}
    m["nOtherCategory"] = num(sum(others.values()))
    m["otherCategories"] = ", ".join(f"{label(c)} ({n})" for c, n in sorted(others.items())) or "none"
    m["nOpening"] = num(sum(r["opening"] is True for r in grid))
    m["nInversion"] = num(sum(r["inversion"] is True for r in grid))

    # c_s < c_p < sqrt(2) c_s among the forward opening waves (intersonic, and the sub- and
    # supersonic ones the claim excludes).
    forward = [r for r in grid if str(r["category"]).startswith("intersonic_opening")
               or str(r["category"]).endswith("_forward_opening")]
    m["nForwardOpening"] = num(len(forward))
    m["nForwardBelowSqrtTwo"] = num(sum(r["below_sqrt2_cs"] is True for r in forward))
    # Which forward waves are not below sqrt(2) c_s: count per nu and their c_p/c_s.
    above = [r for r in forward if r["below_sqrt2_cs"] is False]
    per_nu = Counter(r["nu"] for r in above)
    ratios = [r["celerity_over_cs"] for r in above if finite(r["celerity_over_cs"])]
    m["forwardAboveSqrtTwo"] = ("none" if not above else
                                ", ".join(f"{num(n)} at $\\nu = {nu:g}$" for nu, n in sorted(per_nu.items()))
                                + f" ($c_p/c_s$ from {num(min(ratios), decimals=3)} to {num(max(ratios), decimals=3)})")

    m["celerityReference"] = num(reference["celerity"], decimals=3)
    m["minTNReference"] = num(reference["min_T_over_N"], 2)
    m["categoryReference"] = label(reference["category"])
    corner = at_cell(grid, 0.0, 2.0)
    m["celerityNuZeroFTwo"] = num(corner[0]["celerity"], decimals=3) if corner else None
    m["regimeNuZeroFTwo"] = str(corner[0]["regime"]) if corner else None

    # The flutter wedge of steady sliding (inside_flutter_wedge: None where nu is off its table).
    inside = [r for r in grid if r["inside_flutter_wedge"] is True]
    outside = [r for r in grid if r["inside_flutter_wedge"] is False]
    m.update(nInsideWedge=num(len(inside)), nOpeningInsideWedge=num(sum(r["opening"] is True for r in inside)),
             nOutsideWedge=num(len(outside)), nOpeningOutsideWedge=num(sum(r["opening"] is True for r in outside)))

    # Frictional dissipation per unit mean slip (mu_diss, = f for uniform Coulomb sliding) over the
    # opening runs: while the interface slides by opening waves, and before they open.
    opened = [r for r in grid if r["opening"] is True]

    def median(key, per_f=False):
        values = [r[key] / r["f"] if per_f else r[key] for r in opened
                  if finite(r[key]) and (not per_f or r["f"] > 0)]
        return statistics.median(values) if values else None
    m["medianMuDissOpeningOverF"] = num(median("dissipative_friction_opening", per_f=True), 2)
    m["medianMuDissBeforeOverF"] = num(median("dissipative_friction_before_opening", per_f=True), 2)
    m["nMuDissRuns"] = num(sum(finite(r["dissipative_friction_opening"]) and r["f"] > 0 for r in opened))
    m["medianFrictionEnergyShareOpening"] = num(median("friction_energy_share_opening"), 2)
    m.update(direction_switch_macros(grid, "celerity", "switch"))
    return m


def direction_switch_macros(rows, column, prefix):
    """For each SWITCH_NUS: the largest f with a backward front and the smallest larger f with a
    forward one, 'f1--f2' (the paper: back to +x at higher f); None when there is no such pair."""
    macros = {}
    for name, nu in SWITCH_NUS.items():
        cells = sorted((r["f"], r[column]) for r in rows if same(r["nu"], nu) and finite(r[column]))
        backward = [f for f, c in cells if c < 0]
        forward = [f for f, c in cells if c > 0 and backward and f > max(backward)]
        macros[prefix + name] = f"{num(max(backward))}--{num(min(forward))}" if backward and forward else None
    return macros


def sweep_macros(role, parameter, rows, reference_cell, path):
    """The role's macros: 'value (parameter), ...' over the sweep's runs at the reference cell, one
    run per parameter value, in increasing order of the parameter."""
    runs = at_cell(rows, *reference_cell)
    by_value = {}
    for r in runs:
        if not finite(r.get(parameter)):
            raise InputError(f"{path}: a run at the reference cell without a value of {parameter}")
        if r[parameter] in by_value:
            raise InputError(f"{path}: two runs with {parameter} = {r[parameter]:g} at the reference cell")
        by_value[r[parameter]] = r
    if len(by_value) < 2:
        raise InputError(f"{path}: sweep '{role}' has {len(by_value)} value(s) of {parameter} at the "
                         "reference cell; the text compares at least two")
    macros = {}
    for macro, (column, decimals) in SWEEP_ROLES[role].items():
        if column == "-":
            macros[macro] = ", ".join(num(p) for p in sorted(by_value))
            continue
        if column not in rows[0]:
            raise InputError(f"{path}: no column {column} (for \\{macro})")
        values = [(num(r[column], decimals=decimals), num(p)) for p, r in sorted(by_value.items())]
        macros[macro] = (", ".join(v for v, _ in values) if role == "period"
                         else ", ".join(f"{v} ({a})" for v, a in values))
        if any(v is None for v, _ in values):
            macros[macro] = None
    return macros


def all_macros(args):
    summary = read_json_object(args.summary)
    runs = read_rows(args.runs, ("energy_balance_error",))
    grid_rows = read_rows(args.grid, GRID_COLUMNS)
    one_per_cell(grid_rows, args.grid)
    table = read_rows(args.table1, ("nu", "f", "published"))
    macros = setup_macros(grid_rows, args.grid)
    macros.update(summary_macros(summary, args.summary))
    macros["nRuns"] = num(len(runs))
    errors = [abs(r["energy_balance_error"]) for r in runs if finite(r["energy_balance_error"])]
    macros["maxEnergyError"] = num(max(errors), 2) if errors else None
    macros["medianEnergyError"] = num(statistics.median(errors), 2) if errors else None
    macros["categoryMismatchCells"] = cell_list(summary.get("category_mismatches") or [])
    macros["missingCells"] = cell_list(summary.get("missing_cells") or [])
    macros.update(grid_macros(grid_rows, args.reference_cell))
    for role, parameter, path in args.sweep:
        if role not in SWEEP_ROLES:
            raise InputError(f"--sweep {role}: unknown role (one of {', '.join(SWEEP_ROLES)})")
        macros.update(sweep_macros(role, parameter, read_rows(path, ("nu", "f", parameter)),
                                   args.reference_cell, path))
    missing_roles = [role for role in SWEEP_ROLES if role not in {s[0] for s in args.sweep}]
    if missing_roles:
        raise InputError(f"no --sweep for {', '.join(missing_roles)}")
    published = at_cell(table, *args.reference_cell)
    macros["publishedReference"] = num(published[0]["published"], decimals=3) if published else None
    macros.update(direction_switch_macros(table, "published", "publishedSwitch"))
    macros = {name: macros[name] for name in MACRO_NAMES}
    missing = [name for name, value in macros.items() if value is None]
    if missing:
        raise InputError("no value for " + ", ".join(f"\\{name}" for name in missing)
                         + f" in the inputs ({args.grid}, {args.table1}, the sweeps)")
    return macros


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--summary", required=True, help="summary.json of the study's Table 1 comparison")
    parser.add_argument("--runs", required=True, help="all_metrics.csv of the whole study")
    parser.add_argument("--grid", required=True, help="all_metrics.csv of the (nu, f) grid sweep")
    parser.add_argument("--table1", required=True, help="table1.csv of the study (published values)")
    parser.add_argument("--reference-cell", nargs=2, type=float, required=True, metavar=("NU", "F"))
    parser.add_argument("--sweep", nargs=3, action="append", default=[], metavar=("ROLE", "PARAMETER", "FILE"),
                        help=f"a one-parameter sweep of the text; ROLE: {', '.join(SWEEP_ROLES)}")
    parser.add_argument("-o", "--output", required=True, help="numbers.tex to write")
    args = parser.parse_args(argv)
    try:
        macros = all_macros(args)
    except InputError as err:
        print(f"make_numbers.py: error: {err}", file=sys.stderr)
        return 2
    sources = [args.summary, args.runs, args.grid, args.table1] + [s[2] for s in args.sweep]
    write_file(args.output, render(macros, sources))
    return 0


if __name__ == "__main__":
    sys.exit(main())
