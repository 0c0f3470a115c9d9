"""Refit the cost model of study/resources.py from the Snakemake benchmark files of a campaign.

    /usr/bin/python3 -m study.fit_resources [RESULTS ...] [-o study/resources.json]

Every run folder under RESULTS (default `results/runs`) that holds config.json, run.h5 and
logs/simulate.benchmark.tsv is one measurement: the job's time and peak memory `max_rss`
(Snakemake's benchmark), the mesh and period (config.json), the steps the solver really made
(run.h5's `n_steps_done`: a run that stops after the opening makes fewer than its cap) and of them
the steps up to the onset estimate (run.h5's setup `t_onset_estimate`, `t_end`, `dt`: what the
scheduler estimate knows before the run). The time is
what the run takes on a core of its own: the wall time `s` times the share of a core the job got
until Snakemake's last sample of it (`cpu_time`, the CPU seconds then, over the time of that sample:
on a machine shared with other work a run may get a fraction of a core), or `s` itself for a job
too short to have been sampled. Fitted:

    wall_s = study/resources.py's seconds (setup, and the stick and slip phases' power laws apart)
    max_rss_mb = base_mb + mb_per_element * n^2 lambda_over_H

the time by least squares on log(wall) with each (mesh, period) weighing the same however many runs
it has (a campaign has hundreds of H/64 runs and a few at H/256) and a soft-L1 loss (a run slowed
by a loaded machine does not pull the fit); the two phases are told apart by the campaign's spread of
stick fractions (an onset at 11 % of a run at nu = 0, f = 0.5, at 96 % at nu = 0.49, f = 2). The memory by
least squares on the runs long enough for Snakemake to have sampled the solver (its first sample
is taken when the job starts, the next 0.5 s later: a shorter job records its shell). An exponent
that the campaign cannot see (one mesh, or one period) keeps its value in the current file. The
constants are written to OUTPUT (what study/resources.py reads), with what they were fitted from;
a table per mesh and period of measured / fitted goes to stdout. Commit the file.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

from analysis.theory import elastic
from study import resources

#: Shortest job (s) whose peak memory is the solver's, not the shell's (Snakemake samples every 0.5 s).
MIN_SAMPLED_WALL_S = 1.0
#: Snakemake 7 samples a job when it starts, every 0.5 s for 15 s, then every 30 s (snakemake/benchmark.py).
SAMPLE_INTERVAL_S, DENSE_SAMPLING_S, SPARSE_INTERVAL_S = 0.5, 15.0, 30.0


def read_benchmark(path: Path) -> dict[str, float]:
    """The first row of a Snakemake benchmark TSV as numbers (`s`, `max_rss`, ...)."""
    with open(path, newline="") as stream:
        row = next(csv.DictReader(stream, delimiter="\t"))
    return {key: float(value) for key, value in row.items() if key != "h:m:s" and value not in ("", "NA")}


def steps_done(run_file: Path) -> tuple[int, int] | None:
    """(steps, stick_steps): run.h5's `n_steps_done`, and how many of them come before the onset
    estimate (min(t_onset_estimate, t_end) / dt, the scheduler's count); None when the run does not
    record its steps."""
    import h5py

    with h5py.File(run_file, "r") as run:
        value = run.attrs.get("n_steps_done")
        setup = run["setup"].attrs if "setup" in run else {}
        times = [setup.get(key) for key in ("t_onset_estimate", "t_end", "dt")]
    if value is None:
        return None
    steps = int(value)
    if any(t is None for t in times):
        return steps, 0
    t_onset, t_end, dt = (float(t) for t in times)
    return steps, min(steps, elastic.n_steps(min(t_onset, t_end), dt))


def last_sample_time(wall: float) -> float:
    """When Snakemake last sampled a job of this wall time (s after its start)."""
    if wall < DENSE_SAMPLING_S:
        return SAMPLE_INTERVAL_S * math.floor(wall / SAMPLE_INTERVAL_S)
    return DENSE_SAMPLING_S + SPARSE_INTERVAL_S * math.floor((wall - DENSE_SAMPLING_S) / SPARSE_INTERVAL_S)


def core_seconds(record: dict[str, float]) -> float:
    """The job's time on a core of its own: wall x the share of a core it got until its last sample."""
    sampled, cpu = last_sample_time(record["s"]), record.get("cpu_time", 0.0)
    if sampled < MIN_SAMPLED_WALL_S or cpu <= 0:
        return record["s"]
    return record["s"] * min(1.0, cpu / sampled)


def measurements(roots: list[Path]) -> list[dict]:
    """One dict per run folder under `roots`: mesh, period, elements, steps, wall_s (on a core of its
    own, `core_seconds`), max_rss_mb."""
    found, seen = [], set()
    for root in roots:
        for bench in sorted(root.glob("**/logs/simulate.benchmark.tsv")):
            folder = bench.parent.parent.resolve()
            config_file, run_file = folder / "config.json", folder / "run.h5"
            if folder in seen or not config_file.is_file() or not run_file.is_file():
                continue
            seen.add(folder)
            counted = steps_done(run_file)
            if not counted or not counted[0]:
                continue
            steps, stick_steps = counted
            config = json.loads(config_file.read_text())
            if not resources.has_stick_phase(config):
                stick_steps = 0
            n, period = config["mesh"]["elements_per_H"], config["geometry"]["lambda_over_H"]
            record = read_benchmark(bench)
            found.append({"run": str(folder), "n": n, "period": period, "elements": n * n * period,
                          "steps": steps, "stick_steps": stick_steps, "wall_s": core_seconds(record),
                          "max_rss_mb": record.get("max_rss", math.nan)})
    return found


#: The time constants of study/resources.py.
TIME_KEYS = ("setup_s", "ms_per_step_h32", "mesh_exponent", "period_exponent", "contact_ms_per_step_h32",
             "contact_mesh_exponent", "stick_ms_per_step_h32", "stick_mesh_exponent", "stick_period_exponent")


def prior_time(prior: dict) -> dict:
    """The prior's time constants. A file from before the phases were modelled apart (no contact_ or
    stick_ keys) starts the contact solve at a tenth of the layer's step, growing as it does, and the
    stick step at a third of it."""
    full = dict(prior)
    full.setdefault("contact_ms_per_step_h32", prior["ms_per_step_h32"] / 10)
    full.setdefault("contact_mesh_exponent", prior["mesh_exponent"])
    full.setdefault("stick_ms_per_step_h32", prior["ms_per_step_h32"] / 3)
    full.setdefault("stick_mesh_exponent", prior["mesh_exponent"])
    full.setdefault("stick_period_exponent", prior["period_exponent"])
    return full


def fit_time(runs: list[dict], prior: dict) -> dict:
    """The time constants (TIME_KEYS) that the runs can see; the others from `prior`.

    A stick step is the layer's part of a slip step, without the contact solve and in wavenumbers
    (docs/stick-phase.md): it costs less at every mesh and period, and grows no faster with them. The fit
    keeps it so, with the stick step as a factor <= 1 on the layer's part and exponents a fraction of its (a
    campaign's stick fractions, 4-97 % of a run's steps, tell the phases apart only loosely: unconstrained,
    a fit made an H/32 stick step cost three slip steps). The contact solve's part needs three meshes or
    more to be told from the layer's; with fewer it keeps the prior's."""
    prior = prior_time(prior)
    free_mesh = len({r["n"] for r in runs}) > 1
    free_contact = len({r["n"] for r in runs}) > 2  # two power laws in the mesh need three meshes
    free_period = len({r["period"] for r in runs}) > 1
    free_stick = any(r["stick_steps"] > 0 for r in runs) and any(r["steps"] > r["stick_steps"] for r in runs)
    # (name, free, start, lower, upper); the stick step's as offsets from the layer's part
    variables = [("setup_s", True, None, 0.0, np.inf),
                 ("log_ms", True, math.log(prior["ms_per_step_h32"]), -np.inf, np.inf),
                 ("mesh_exponent", free_mesh, prior["mesh_exponent"], 0.0, 6.0),
                 ("period_exponent", free_period, prior["period_exponent"], 0.0, 6.0),
                 ("log_contact_ms", free_contact, math.log(max(prior["contact_ms_per_step_h32"], 1e-6)), -np.inf,
                  np.inf),
                 ("contact_mesh_exponent", free_contact, prior["contact_mesh_exponent"], 0.0, 8.0),
                 ("log_stick_ratio", free_stick, -1.0, -np.inf, 0.0),
                 ("stick_mesh_fraction", free_stick and free_mesh, 0.8, 0.0, 1.0),
                 ("stick_period_fraction", free_stick and free_period, 0.8, 0.0, 1.0)]
    variables = [v for v in variables if v[1]]
    n = np.array([r["n"] for r in runs], float)
    period = np.array([r["period"] for r in runs], float)
    steps = np.array([r["steps"] for r in runs], float)
    stick = np.array([r["stick_steps"] for r in runs], float)
    wall = np.array([r["wall_s"] for r in runs], float)
    group_size = {}
    for r in runs:
        group_size[(r["n"], r["period"])] = group_size.get((r["n"], r["period"]), 0) + 1
    weight = np.array([group_size[(r["n"], r["period"])] ** -0.5 for r in runs])

    def unpack(x):
        value = dict(zip((v[0] for v in variables), x))
        c = dict(prior)
        c["setup_s"] = value["setup_s"]
        c["ms_per_step_h32"] = math.exp(value["log_ms"])
        for key in ("mesh_exponent", "period_exponent", "contact_mesh_exponent"):
            c[key] = value.get(key, prior[key])
        if "log_contact_ms" in value:
            c["contact_ms_per_step_h32"] = math.exp(value["log_contact_ms"])
        if free_stick:
            c["stick_ms_per_step_h32"] = c["ms_per_step_h32"] * math.exp(value["log_stick_ratio"])
            for key, fraction in (("mesh_exponent", "stick_mesh_fraction"),
                                  ("period_exponent", "stick_period_fraction")):
                c[f"stick_{key}"] = c[key] * value[fraction] if fraction in value else prior[f"stick_{key}"]
        return c

    def residuals(x):
        model = resources.seconds(n, period, steps, {"time": unpack(x)}, stick_steps=stick)
        return weight * (np.log(model) - np.log(wall))

    start = [min(prior["setup_s"], wall.min() / 2) if v[0] == "setup_s" else v[2] for v in variables]
    solution = least_squares(residuals, start, bounds=([v[3] for v in variables], [v[4] for v in variables]),
                             loss="soft_l1", f_scale=0.1)
    fitted = unpack(solution.x)
    return {key: fitted[key] for key in TIME_KEYS}


def fit_memory(runs: list[dict], prior: dict) -> dict:
    """base_mb and mb_per_element by least squares (both >= 0) on the runs Snakemake sampled."""
    sampled = [r for r in runs if r["wall_s"] >= MIN_SAMPLED_WALL_S and math.isfinite(r["max_rss_mb"])]
    if not sampled:
        return dict(prior)
    elements = np.array([r["elements"] for r in sampled], float)
    rss = np.array([r["max_rss_mb"] for r in sampled], float)
    if len(set(elements)) > 1:
        slope, base = np.polyfit(elements, rss, 1)
        if slope < 0 or base < 0:
            slope, base = (max(slope, 0.0), float(np.mean(rss - max(slope, 0.0) * elements)))
    else:
        slope = prior["mb_per_element"]
        base = float(np.mean(rss - slope * elements))
    return {"base_mb": max(base, 0.0), "mb_per_element": slope}


def ratio_table(runs: list[dict], constants: dict) -> list[str]:
    """Median and extreme measured / fitted wall time and memory per (mesh, period)."""
    lines = [f"{'H/h':>5} {'lambda/H':>8} {'runs':>5} {'time meas/fit: median':>22} {'min':>6} {'max':>6}"
             f" {'memory meas/fit: median':>24} {'max':>6}"]
    groups: dict[tuple, list[dict]] = {}
    for r in runs:
        groups.setdefault((r["n"], r["period"]), []).append(r)
    for (n, period), group in sorted(groups.items()):
        time = [r["wall_s"] / resources.seconds(n, period, r["steps"], constants, stick_steps=r["stick_steps"])
                for r in group]
        memory = [r["max_rss_mb"] / resources.memory_mb(n, period, constants) for r in group
                  if r["wall_s"] >= MIN_SAMPLED_WALL_S and math.isfinite(r["max_rss_mb"])]
        memory_text = (f"{np.median(memory):>24.2f} {max(memory):>6.2f}" if memory else f"{'-':>24} {'-':>6}")
        lines.append(f"{n:>5} {period:>8g} {len(group):>5} {np.median(time):>22.2f} {min(time):>6.2f}"
                     f" {max(time):>6.2f} {memory_text}")
    return lines


def fit(runs: list[dict], prior: dict) -> dict:
    """The constants study/resources.py reads, with what they were fitted from."""
    constants = {"time": fit_time(runs, prior["time"]), "memory": fit_memory(runs, prior["memory"])}
    worst = max(r["wall_s"] / resources.seconds(r["n"], r["period"], r["steps"], constants,
                                                stick_steps=r["stick_steps"]) for r in runs)
    constants["fitted_from"] = {
        "runs": len(runs),
        "meshes": sorted({r["n"] for r in runs}),
        "periods": sorted({r["period"] for r in runs}),
        "memory_runs": sum(r["wall_s"] >= MIN_SAMPLED_WALL_S for r in runs),
        "max_time_measured_over_fit": round(worst, 3),
    }
    return constants


def rounded(value):
    """Constants with 4 significant digits (a readable committed file)."""
    if isinstance(value, dict):
        return {key: rounded(item) for key, item in value.items()}
    if isinstance(value, float):
        return float(f"{value:.4g}")
    return value


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", nargs="*", type=Path, default=[Path("results/runs")],
                        help="folders searched for run folders (default: results/runs)")
    parser.add_argument("-o", "--output", type=Path, default=resources.CONSTANTS_FILE,
                        help=f"constants file to write (default: {resources.CONSTANTS_FILE})")
    args = parser.parse_args(argv)
    runs = measurements(args.results)
    if len(runs) < 3:
        print(f"fit_resources: error: {len(runs)} run folders with config.json, run.h5 (n_steps_done) and "
              f"logs/simulate.benchmark.tsv under {', '.join(map(str, args.results))}; need at least 3",
              file=sys.stderr)
        return 2
    prior = resources.load_constants(args.output if args.output.is_file() else resources.CONSTANTS_FILE)
    constants = rounded(fit(runs, prior))
    args.output.write_text(json.dumps(constants, indent=2) + "\n")
    print("\n".join(ratio_table(runs, constants)))
    print(f"wrote {args.output} from {len(runs)} runs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
