#!/usr/bin/python3
"""Write generated/numbers.tex: every number the report quotes, as LaTeX macros.

    paper/make_numbers.py summary.json all_metrics.csv --table1 table1.csv -o paper/generated/numbers.tex
    paper/make_numbers.py -o paper/generated/numbers.tex        # placeholders only

Inputs (each optional; a macro whose input is absent expands to \\notavailable):
- summary.json from `python3 -m analysis aggregate`: the Table 1 comparison. Keys read (first
  alias found wins; fractions unless the key ends in `_percent`): cells_compared,
  cells_within_tolerance, tolerance, sign_matches, regime_matches, median_abs_deviation,
  max_abs_deviation (aliases in SUMMARY_KEYS). An optional `setup` object overrides the set-up
  constants (E, rho, H, Uy_over_H, preshear_ratio, hht_alpha, dt_times_cs) when all_metrics.csv
  lacks them; last resort: the solver's documented defaults (docs/contracts.md), the paper's.
- all_metrics.csv from `analysis aggregate`: one row per run. The "grid" rows are those at the
  reference V0/c_s, lambda/H and rho (1e-5, 2, 1000) with the most frequent mesh and integration
  among them; the category counts describe them. The sweeps (shear rate, period, density, mesh)
  are the rows at nu = 0.2, f = 1.5 that differ from the reference in that one parameter only
  (one run per value: the first listed).
- table1.csv (--table1): the published celerity of the reference cell.
- flutter.txt (--flutter, `python3 -m analysis flutter-boundary`: lines 'nu f_lower f_upper'):
  where the grid's opening runs sit against the flutter wedge of steady sliding.

Only selection and formatting happen here; every measured value comes from the inputs.
"""
import argparse
import csv
import json
import math
import os
import statistics
import sys
from collections import Counter

REFERENCE = dict(nu=0.2, f=1.5, V0_over_cs=1e-5, lambda_over_H=2.0, rho=1000.0, dt_times_cs=0.5)
SETUP_DEFAULTS = dict(E=1000.0, rho=1000.0, H=25.0, Uy_over_H=-0.001, preshear_ratio=0.95,
                      hht_alpha=0.1, dt_times_cs=0.5)
SUMMARY_KEYS = {  # macro: (aliases, kind); kind 'count' or 'fraction'
    "cellsTotal": (("cells_total",), "count"),
    "cellsMissing": (("cells_missing",), "count"),
    "cellsCompared": (("cells_compared", "n_compared", "compared"), "count"),
    "cellsWithin": (("cells_within_tolerance", "within_tolerance", "cells_within", "n_within"),
                    "count"),
    "tolerancePercent": (("tolerance", "tolerance_percent"), "fraction"),
    "signMatches": (("sign_matches", "sign_agreement", "cells_sign_ok", "n_sign_ok"), "count"),
    "regimeMatches": (("regime_matches", "regime_agreement", "cells_regime_ok", "n_regime_ok"),
                      "count"),
    "medianDeviationPercent": (("median_abs_deviation", "median_deviation",
                                "median_abs_deviation_percent"), "fraction"),
    "maxDeviationPercent": (("max_abs_deviation", "max_deviation", "max_abs_deviation_percent"),
                            "fraction"),
}
CATEGORIES = {
    "nNoOpening": "no_opening",
    "nIntersonicOpening": "intersonic_opening",
    "nIntersonicOpeningInversion": "intersonic_opening_inversion",
    "nSupersonicBackward": "supersonic_backward_opening",
}


class InputError(Exception):
    pass


# ---------------------------------------------------------------- formatting

def num(value, digits=3, decimals=None):
    """A number for text or math: '\\ensuremath{-0.31}', '\\ensuremath{1.2\\times10^{-4}}';
    `decimals` fixes the digits after the point (celerities: 3, as in the paper's Table 1)."""
    if value is None or not isinstance(value, (int, float)) or not math.isfinite(value):
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


def listing(pairs, unit=""):
    """'a at x, b at y' from [(value_text, at_text)]."""
    if not pairs:
        return None
    return ", ".join(f"{v}{unit} ({a})" for v, a in pairs)


# ---------------------------------------------------------------- inputs

def read_summary(path):
    try:
        with open(path) as stream:
            data = json.load(stream)
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    except json.JSONDecodeError as err:
        raise InputError(f"{path}: not valid JSON ({err})") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: expected a JSON object")
    return data


def parse(text):
    text = (text or "").strip()
    if text.lower() in ("", "nan", "none", "null"):
        return math.nan
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return float(text)
    except ValueError:
        return text


def read_rows(path, required):
    try:
        with open(path, newline="") as stream:
            reader = csv.DictReader(stream)
            rows = [{k: parse(v) for k, v in row.items() if k} for row in reader]
            columns = reader.fieldnames or []
    except OSError as err:
        raise InputError(f"{path}: cannot read ({err.strerror})") from None
    missing = [c for c in required if c not in columns]
    if missing:
        raise InputError(f"{path}: missing required column(s) {', '.join(missing)}")
    return rows


def close(a, b):
    return isinstance(a, float) and isinstance(b, float) and math.isclose(a, b, rel_tol=1e-6)


def matches(row, **wanted):
    return all(close(row.get(k), v) for k, v in wanted.items() if k in row)


# ---------------------------------------------------------------- macros

def summary_macros(summary):
    macros = {}
    for macro, (aliases, kind) in SUMMARY_KEYS.items():
        key = next((k for k in aliases if k in summary), None)
        value = summary.get(key) if key else None
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if kind == "fraction" and not key.endswith("_percent"):
                value = 100.0 * value
            macros[macro] = num(value, 3 if kind == "fraction" else 6)
        else:
            macros[macro] = None
    return macros


def setup_macros(summary, rows):
    """Set-up constants: the most common value among the runs where all_metrics.csv has the
    column (the metrics carry dt_times_cs), else summary.json's `setup`, else the documented default."""
    setup = dict(SETUP_DEFAULTS)
    setup.update({k: v for k, v in (summary or {}).get("setup", {}).items() if k in setup})
    for key in setup:
        values = Counter(r[key] for r in rows if isinstance(r.get(key), float)
                         and math.isfinite(r[key]))
        if values:
            setup[key] = values.most_common(1)[0][0]
    return {"youngModulus": num(setup["E"]), "density": num(setup["rho"]),
            "layerHeight": num(setup["H"]), "preloadRatio": num(setup["Uy_over_H"]),
            "preshearRatio": num(setup["preshear_ratio"]), "hhtAlpha": num(setup["hht_alpha"]),
            "hhtAlphaClassic": num(-setup["hht_alpha"]), "dtTimesCs": num(setup["dt_times_cs"]),
            "referenceNu": num(REFERENCE["nu"]), "referenceF": num(REFERENCE["f"]),
            "referenceVzero": num(REFERENCE["V0_over_cs"]),
            "referencePeriod": num(REFERENCE["lambda_over_H"])}


def grid_rows(rows):
    """(grid, mesh, integration): the rows of the (nu, f) grid, i.e. at the reference values of
    every other parameter, with the most frequent mesh and integration among them (a column a
    table lacks, e.g. the mesh of the published table1.csv, selects nothing)."""
    ref = {k: v for k, v in REFERENCE.items() if k not in ("nu", "f")}
    grid = [r for r in rows if matches(r, **ref)]
    meshes = Counter(r.get("elements_per_H") for r in grid)
    mesh = meshes.most_common(1)[0][0] if meshes else None
    if mesh is not None:
        grid = [r for r in grid if close(r.get("elements_per_H"), mesh)]
    variants = Counter(r.get("integration") for r in grid)
    integration = variants.most_common(1)[0][0] if variants else None
    if integration is not None:
        grid = [r for r in grid if r.get("integration") == integration]
    return grid, mesh, integration


def finite_values(rows, key):
    return [r[key] for r in rows if isinstance(r.get(key), float) and math.isfinite(r[key])]


def metrics_macros(rows, E):
    m = {}
    grid, mesh, integration = grid_rows(rows)
    m["nRuns"] = num(len(rows))
    m["nGridPoints"] = num(len({(r["nu"], r["f"]) for r in grid}))
    m["gridMesh"] = num(mesh) if isinstance(mesh, float) else None
    m["nuValues"] = ", ".join(num(v) for v in sorted({r["nu"] for r in grid})) or None
    m["fValues"] = ", ".join(num(v) for v in sorted({r["f"] for r in grid})) or None
    counts = Counter(r["category"] for r in grid)
    for macro, category in CATEGORIES.items():
        m[macro] = num(counts.get(category, 0)) if grid else None
    others = {c: n for c, n in counts.items() if c not in CATEGORIES.values()}
    m["nOtherCategory"] = num(sum(others.values())) if grid else None
    m["otherCategories"] = (", ".join(f"{str(c).replace('_', ' ')} ({n})"
                                      for c, n in sorted(others.items())) or "none") if grid else None
    m["nOpening"] = num(sum(r.get("opening") is True for r in grid)) if grid else None
    m["nInversion"] = num(sum(r.get("inversion") is True for r in grid)) if grid else None

    # c_s < c_p < sqrt(2) c_s among the forward (intersonic) opening waves of the grid.
    forward = [r for r in grid if str(r["category"]).startswith("intersonic_opening")]
    def c_s(r):
        if isinstance(r.get("c_s"), float) and math.isfinite(r["c_s"]):
            return r["c_s"]
        return math.sqrt(E / (2 * (1 + r["nu"]) * r.get("rho", 1000.0)))
    below = [r for r in forward if c_s(r) < r["celerity"] < math.sqrt(2) * c_s(r)]
    m["nForwardOpening"] = num(len(forward)) if grid else None
    m["nForwardBelowSqrtTwo"] = num(len(below)) if grid else None

    def cell(nu, f):
        hits = [r for r in grid if close(r["nu"], nu) and close(r["f"], f)]
        return hits[0] if hits else None
    reference = cell(REFERENCE["nu"], REFERENCE["f"])
    m["celerityReference"] = num(reference["celerity"], decimals=3) if reference else None
    m["minTNReference"] = num(reference["min_T_over_N"], 2) if reference else None
    m["categoryReference"] = (str(reference["category"]).replace("_", " ") if reference else None)
    corner = cell(0.0, 2.0)
    m["celerityNuZeroFTwo"] = num(corner["celerity"], decimals=3) if corner else None
    m["regimeNuZeroFTwo"] = str(corner["regime"]) if corner else None

    # One-parameter sweeps around the reference point.
    def sweep(param, value, decimals=3):
        base = dict(REFERENCE, elements_per_H=mesh)
        base.pop(param, None)
        chosen = {}  # one run per value of the parameter (the first listed)
        for r in rows:
            if (matches(r, **{k: v for k, v in base.items() if v is not None})
                    and r.get("integration", integration) == integration
                    and isinstance(r.get(param), float)):
                chosen.setdefault(r[param], r)
        pairs = [(num(value(r), decimals=decimals), num(p)) for p, r in sorted(chosen.items())]
        pairs = [(v, a) for v, a in pairs if v and a]
        return pairs if len(pairs) > 1 else []
    period = sweep("lambda_over_H", lambda r: r["pulse_count"], decimals=0)
    m["periodRatios"] = ", ".join(a for _, a in period) or None
    m["pulseCountsPeriod"] = ", ".join(v for v, _ in period) or None
    m["minTNShearRate"] = listing(sweep("V0_over_cs", lambda r: r["min_T_over_N"], 2))
    m["celerityShearRate"] = listing(sweep("V0_over_cs", lambda r: r["celerity"]))
    m["celerityOverCsDensity"] = listing(sweep("rho", lambda r: r["celerity"] / c_s(r)))
    m["celerityMesh"] = listing(sweep("elements_per_H", lambda r: r["celerity"]))
    m["celerityTimestep"] = listing(sweep("dt_times_cs", lambda r: r["celerity"]))
    # Frictional dissipation per unit mean slip (mu_diss, = f for uniform Coulomb sliding) over the
    # grid's opening runs: while the interface slides by opening waves, and before they open.
    opened = [dict(r, **{k: r[k] / r["f"] for k in ("dissipative_friction_opening",
                                                     "dissipative_friction_before_opening")
                         if isinstance(r.get(k), float) and r["f"] > 0})
              for r in grid if r.get("opening") is True]
    def median(key):
        values = finite_values(opened, key)
        return statistics.median(values) if values else None
    m["medianMuDissOpeningOverF"] = num(median("dissipative_friction_opening"), 2)
    m["medianMuDissBeforeOverF"] = num(median("dissipative_friction_before_opening"), 2)
    m["nMuDissRuns"] = num(len(finite_values(opened, "dissipative_friction_opening"))) if grid else None
    m["medianFrictionEnergyShareOpening"] = num(median("friction_energy_share_opening"), 2)
    errors = [abs(e) for e in finite_values(rows, "energy_balance_error")]
    m["maxEnergyError"] = num(max(errors), 2) if errors else None
    return m


def read_flutter(path):
    """[(nu, f_lower, f_upper)] of the flutter boundary (nan: no wedge at that nu)."""
    try:
        with open(path) as stream:
            lines = [line.split() for line in stream if line.strip() and not line.startswith("#")]
        return [tuple(float(x) for x in fields[:3]) for fields in lines]
    except (OSError, ValueError, IndexError) as err:
        raise InputError(f"{path}: not a flutter boundary 'nu f_lower f_upper' ({err})") from None


def inside_wedge(boundary, nu, f):
    """True when (nu, f) lies strictly inside the flutter wedge, bounds interpolated linearly in nu;
    None when nu is outside the tabulated range."""
    below = [b for b in boundary if b[0] <= nu + 1e-12]
    above = [b for b in boundary if b[0] >= nu - 1e-12]
    if not below or not above:
        return None
    a, b = below[-1], above[0]
    w = 0.0 if b[0] == a[0] else (nu - a[0]) / (b[0] - a[0])
    lower, upper = ((1 - w) * a[k] + w * b[k] if math.isfinite(a[k]) and math.isfinite(b[k])
                    else (b[k] if w > 0.5 else a[k]) for k in (1, 2))
    return math.isfinite(lower) and lower < f < upper  # False for upper = nan


def wedge_macros(rows, boundary):
    """Counts of the grid runs inside/outside the flutter wedge, with and without opening."""
    grid, _, _ = grid_rows(rows)
    names = ("nInsideWedge", "nOpeningInsideWedge", "nOutsideWedge", "nOpeningOutsideWedge")
    if not grid or not boundary:
        return {k: None for k in names}
    inside = [r for r in grid if inside_wedge(boundary, r["nu"], r["f"])]
    outside = [r for r in grid if inside_wedge(boundary, r["nu"], r["f"]) is False]
    return dict(zip(names, (num(len(inside)), num(sum(r.get("opening") is True for r in inside)),
                            num(len(outside)), num(sum(r.get("opening") is True for r in outside)))))


def direction_switch_macros(rows, column="celerity", prefix="switch"):
    """For nu = 0.45 and 0.49: the largest f of the grid with a backward front and the smallest
    larger f with a forward one (the paper: back to +x at higher f); `column` = published for the
    paper's own values (table1.csv)."""
    grid = [r for r in grid_rows(rows)[0] if isinstance(r.get(column), float) and math.isfinite(r[column])]
    macros = {}
    for nu, name in ((0.45, prefix + "FNuFortyFive"), (0.49, prefix + "FNuFortyNine")):
        cells = sorted((r["f"], r[column]) for r in grid if close(r["nu"], nu))
        backward = [f for f, c in cells if c < 0]
        forward = [f for f, c in cells if c > 0 and backward and f > max(backward)]
        macros[name] = (f"{num(max(backward))}--{num(min(forward))}" if backward and forward else None)
    return macros


def published_macros(rows):
    hit = [r for r in rows if close(r["nu"], REFERENCE["nu"]) and close(r["f"], REFERENCE["f"])]
    value = hit[0]["published"] if hit else None
    return {"publishedReference": num(value, decimals=3) if isinstance(value, float) else None}


def all_macros(summary_path=None, metrics_path=None, table1_path=None, E=1000.0, flutter_path=None):
    summary = read_summary(summary_path) if summary_path else None
    rows = read_rows(metrics_path, ("nu", "f", "category", "celerity", "regime",
                                    "min_T_over_N")) if metrics_path else []
    macros = setup_macros(summary, rows)
    macros.update(summary_macros(summary or {}))
    if summary is None:
        macros.update({k: None for k in SUMMARY_KEYS})
    macros.update(metrics_macros(rows, E) if rows else
                  {k: None for k in metrics_macros([], E)})
    table = read_rows(table1_path, ("nu", "f", "published")) if table1_path else []
    macros.update(published_macros(table))
    macros.update(wedge_macros(rows, read_flutter(flutter_path) if flutter_path else []))
    macros.update(direction_switch_macros(rows))
    macros.update(direction_switch_macros(table, "published", "publishedSwitch"))
    return macros


def render(macros, sources):
    lines = ["% Generated by paper/make_numbers.py from: " + (", ".join(sources) or "nothing"),
             "% Do not edit: rerun the script (or `snakemake paper`).",
             "\\providecommand{\\notavailable}{\\textit{n/a}}"]
    for name, value in macros.items():
        lines.append(f"\\newcommand{{\\{name}}}{{{value if value is not None else chr(92) + 'notavailable'}}}")
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("summary", nargs="?", help="summary.json of the Table 1 comparison")
    parser.add_argument("metrics", nargs="?", help="all_metrics.csv, one row per run")
    parser.add_argument("--table1", help="table1.csv (for the published value of the reference cell)")
    parser.add_argument("--flutter", help="flutter.txt, the flutter boundary 'nu f_lower f_upper' per line")
    parser.add_argument("--E", type=float, default=1000.0, help="Young's modulus when no c_s column")
    parser.add_argument("-o", "--output", required=True, help="numbers.tex to write")
    args = parser.parse_args(argv)
    try:
        macros = all_macros(args.summary, args.metrics, args.table1, args.E, args.flutter)
    except InputError as err:
        print(f"make_numbers.py: error: {err}", file=sys.stderr)
        return 2
    sources = [p for p in (args.summary, args.metrics, args.table1, args.flutter) if p]
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w") as stream:
        stream.write(render(macros, sources))
    return 0


if __name__ == "__main__":
    sys.exit(main())
