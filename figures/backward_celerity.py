#!/usr/bin/python3
"""Backward (supersonic) pulse celerity against f: Adams' steady-wave theory, the paper, our runs.

    /usr/bin/python3 figures/backward_celerity.py --out results/figures

Writes OUT/backward_celerity.{png,pdf} (one panel per nu) and OUT/backward_celerity.{csv,md}: per
(nu, f), the theory celerity -c(f) (`analysis.theory.supersonic.supersonic_trace_speed`, c_s of the paper's
E and rho), the published value (study/reference/table1_celerity.csv) and the celerity of every
committed series in study/results (mesh, time step, seed), signed as measured. The plot shows only
backward (negative) measured celerities; a positive value in the table is a pulse of another regime.

In the pipeline (rule `fig_backward_celerity`, study/rules/figures.smk) every folder's table is
given by `--table FOLDER=PATH` (results/<sweep>/table/all_metrics.csv); without it the committed
copies in --results are read, and the series of `timestep_backward` is left out (with a note) while
its table is not committed yet. Unlike the other figure scripts it evaluates the theory itself (a
root find, no run data), since there is no generated theory file to read.
"""
import argparse
import csv
import math
import os
import sys
from pathlib import Path

import numpy as np

import _style
from _data import InputError, read_csv

from analysis.theory import elastic, supersonic

ROOT = Path(__file__).resolve().parents[1]

# (column, label, folder under --results, required row values, plot style)
SERIES = [
    ("h32_dt0.5", "$H/32$, $\\Delta t\\,c_s$ = 0.5 m", "table1_h32",
     dict(elements_per_H=32, dt_times_cs=0.5, seed=1), dict(color="tab:orange", marker="^")),
    ("h32_dt0.5_seed2", "$H/32$, $\\Delta t\\,c_s$ = 0.5 m, seed 2", "variant_seed2",
     dict(elements_per_H=32, dt_times_cs=0.5, seed=2), dict(color="tab:orange", marker="v", mfc="none")),
    ("h64_dt0.5", "$H/64$, $\\Delta t\\,c_s$ = 0.5 m", "table1",
     dict(elements_per_H=64, dt_times_cs=0.5, seed=1), dict(color="tab:orange", marker="o")),
    ("h128_dt0.5", "$H/128$, $\\Delta t\\,c_s$ = 0.5 m", "table1_h128",
     dict(elements_per_H=128, dt_times_cs=0.5, seed=1), dict(color="tab:orange", marker="s")),
    ("h64_dt0.25", "$H/64$, $\\Delta t\\,c_s$ = 0.25 m", "timestep",
     dict(elements_per_H=64, dt_times_cs=0.25, seed=1), dict(color="tab:blue", marker="o")),
    ("h32_dt1", "$H/32$, $\\Delta t\\,c_s$ = 1 m", "variant_dt1",
     dict(elements_per_H=32, dt_times_cs=1.0, seed=1), dict(color="tab:green", marker="^")),
    ("h64_dt1", "$H/64$, $\\Delta t\\,c_s$ = 1 m", "timestep",
     dict(elements_per_H=64, dt_times_cs=1.0, seed=1), dict(color="tab:green", marker="o")),
    ("h64_dt0.125", "$H/64$, $\\Delta t\\,c_s$ = 0.125 m", "timestep_backward",
     dict(elements_per_H=64, dt_times_cs=0.125, seed=1), dict(color="tab:cyan", marker="o")),
    ("h64_dt0.0625", "$H/64$, $\\Delta t\\,c_s$ = 0.0625 m", "timestep_backward",
     dict(elements_per_H=64, dt_times_cs=0.0625, seed=1), dict(color="tab:purple", marker="o")),
]
#: Folders whose committed table may not exist yet (standalone use only).
OPTIONAL_FOLDERS = ("timestep_backward",)
COMMON = dict(integration="reduced", regularization="none", lambda_over_H=2, V0_over_cs=1e-5)
REQUIRED = ("nu", "f", "celerity", "integration", "regularization", "lambda_over_H", "E", "rho",
            "V0_over_cs") + tuple(SERIES[0][3])
NU_VALUES = (0.45, 0.49)
F_CURVE = np.linspace(0.3, 2.0, 171)


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--results", default=str(ROOT / "study" / "results"),
                        help="folder of the committed sweep tables (default: study/results)")
    parser.add_argument("--table", action="append", default=[], metavar="FOLDER=PATH",
                        help="the all_metrics.csv of a series' folder (repeat; overrides --results)")
    parser.add_argument("--reference", default=str(ROOT / "study" / "reference" / "table1_celerity.csv"),
                        help="published celerities (nu, f, celerity_m_per_s)")
    return parser.parse_args(argv)


def _same(value, wanted):
    if isinstance(wanted, (int, float)):
        return isinstance(value, float) and math.isclose(value, float(wanted), rel_tol=1e-9)
    if wanted == "none":  # read_csv turns the text 'none' into nan
        return isinstance(value, float) and math.isnan(value)
    return str(value) == wanted


def _matches(row, wanted):
    return all(_same(row[k], v) for k, v in wanted.items())


def table_paths(results, overrides):
    """{folder: all_metrics.csv path}: the --table overrides, else the committed copy in results;
    an optional folder without a committed table is left out."""
    paths = {}
    for text in overrides:
        folder, sep, path = text.partition("=")
        if not sep or folder not in {s[2] for s in SERIES} or not path:
            raise InputError(f"--table takes FOLDER=PATH with FOLDER one of "
                             f"{', '.join(sorted({s[2] for s in SERIES}))} (got '{text}')")
        paths[folder] = Path(path)
    for folder in {s[2] for s in SERIES} - set(paths):
        path = Path(results) / folder / "all_metrics.csv"
        if folder in OPTIONAL_FOLDERS and not path.exists() and not overrides:
            print(f"note: {path} not found: its series is left out", file=sys.stderr)
            continue
        paths[folder] = path
    return paths


def measured(paths, nu):
    """{column: {f: celerity}} of the runs at nu (E = 1000 Pa, rho = 1000 kg/m^3)."""
    out = {}
    for column, _, folder, wanted, _ in SERIES:
        if folder not in paths:
            out[column] = {}
            continue
        path = paths[folder]
        rows = read_csv(path, REQUIRED)
        picked = {}
        for row in rows:
            if not (_matches(row, dict(wanted, **COMMON, nu=nu, E=1000.0, rho=1000.0))):
                continue
            f = round(row["f"], 6)
            if f in picked:
                raise InputError(f"{path}: two runs at nu = {nu}, f = {f} for series {column}")
            picked[f] = row["celerity"]
        out[column] = picked
    return out


def published(reference, nu):
    rows = read_csv(reference, ("nu", "f", "celerity_m_per_s"))
    return {round(r["f"], 6): r["celerity_m_per_s"] for r in rows
            if math.isclose(r["nu"], nu, rel_tol=1e-9) and r["celerity_m_per_s"] < 0.0}


def theory_celerity(nu, f):
    """-c (m/s): the backward steady wave at the paper's E, rho (c_s from analysis.theory.elastic)."""
    c_s = elastic.wave_speeds(nu)[0]
    return -supersonic.supersonic_trace_speed(nu, f, c_s)


def collect(paths, reference):
    """{nu: (published {f: celerity}, measured {column: {f: celerity}})}: every input read once."""
    return {nu: (published(reference, nu), measured(paths, nu)) for nu in NU_VALUES}


def table_rows(data):
    """One row per (nu, f) where the paper or any series has a backward celerity."""
    rows = []
    for nu, (paper, ours) in data.items():
        fs = set(paper)
        for values in ours.values():
            fs |= {f for f, c in values.items() if math.isfinite(c) and c < 0.0}
        for f in sorted(fs):
            row = {"nu": nu, "f": f, "theory": theory_celerity(nu, f), "published": paper.get(f, math.nan)}
            for column, *_ in SERIES:
                row[column] = ours[column].get(f, math.nan)
            rows.append(row)
    return rows


def write_tables(rows, out):
    columns = ["nu", "f", "theory", "published"] + [s[0] for s in SERIES]
    with open(out / "backward_celerity.csv", "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(columns)
        for row in rows:
            writer.writerow([f"{row[c]:.6g}" if math.isfinite(row[c]) else "" for c in columns])

    def cell(value):
        return f"{value:.3f}" if math.isfinite(value) else ""

    heads = ["nu", "f", "theory -c", "published"] + [s[0].replace("_", " ") for s in SERIES]
    lines = ["| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    for row in rows:
        lines.append("| " + " | ".join([f"{row['nu']:g}", f"{row['f']:g}"]
                                       + [cell(row[c]) for c in columns[2:]]) + " |")
    (out / "backward_celerity.md").write_text("\n".join(lines) + "\n")


def plot(data, out):
    fig, axes = _style.plt.subplots(1, len(data), figsize=(7.0, 3.2))
    for ax, (nu, (paper, ours)) in zip(axes, data.items()):
        c_s, _, c_l = elastic.wave_speeds(nu)
        ax.plot(F_CURVE, [theory_celerity(nu, f) for f in F_CURVE], color="k", lw=1.2,
                label="steady wave (Adams 2000)")
        ax.axhline(-c_l, **dict(_style.THEORY_STYLE["c_l"], label="$-c_l$"))
        ax.plot(list(paper), list(paper.values()), ls="none", marker="*", ms=9, color="k",
                label="published (Table 1)")
        for column, label, _, _, style in SERIES:
            points = sorted((f, c) for f, c in ours[column].items() if math.isfinite(c) and c < 0.0)
            if points:
                ax.plot(*zip(*points), ls="none", ms=5, label=label, **style)
        ax.set_title(f"$\\nu$ = {nu:g} ($c_s$ = {c_s:.3f}, $c_l$ = {c_l:.3f} m/s)")
        ax.set_xlabel("coefficient of friction $f$ (-)")
        ax.set_xlim(F_CURVE[0], F_CURVE[-1])
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("backward celerity $c_p$ (m/s)")
    handles, labels = axes[0].get_legend_handles_labels()
    for handle, label in zip(*axes[1].get_legend_handles_labels()):
        if label not in labels:
            handles.append(handle)
            labels.append(label)
    fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=3, frameon=False)
    fig.suptitle("Backward supersonic pulses: $E$ = 1000 Pa, $\\rho$ = 1000 kg/m$^3$, $\\lambda = 2H$",
                 y=1.03)
    _style.save(fig, str(out / "backward_celerity"))


def main(argv=None):
    # 1. Parse options; 2. collect theory, published and measured celerities; 3. write table, plot.
    args = parse_args(argv)
    data = collect(table_paths(args.results, args.table), args.reference)  # every input is read before anything is written
    out = Path(args.out)
    os.makedirs(out, exist_ok=True)
    write_tables(table_rows(data), out)
    plot(data, out)
    return 0


if __name__ == "__main__":
    _style.cli(main)
