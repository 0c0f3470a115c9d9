# Look-ups shared by the rules: the points of a sweep, each run's specification and resources, and
# the files each sweep's target builds. The logic lives in study/*.py (tested in tests/pipeline/).

import functools
import inspect
import json
import re
from pathlib import Path

REPO = Path(workflow.basedir).resolve()  # on sys.path (the Snakefile's folder)
from study import figure_kinds
from study import resources as study_resources
from study import run_store
from study import sweeps as study_sweeps
from study.make_run_config import config_json_text, run_config, run_times
from snakemake.exceptions import WorkflowError

# Scripts run as `-m study.*`, `-m analysis` and figures/*.py import from the repository root,
# also when --directory puts the results elsewhere.
os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), os.environ.get("PYTHONPATH")]))
# OpenBLAS starts a thread per core in every process that loads it, and idle each spins for ~0.1 s of system
# CPU: `slidewave run` now stops them itself (solver/main.cpp, one thread), the Python jobs (numpy) get one
# thread from this (~40 s of `all` on 2 cores before; the same bits either way). Set here, not in a rule's
# shell, so that existing runs are not rerun for a changed rule; a value in the environment wins.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

wildcard_constraints:
    sweep="[A-Za-z][A-Za-z0-9_]*",
    point="nu[^/]+",
    run=run_store.RUN_ID_PATTERN,
    field="slip_velocity|opening|state",

FIGURE_EXTS = (".png", ".pdf")
# figures/convergence.py --param accepts these point parameters.
CONVERGENCE_PARAMS = ("elements_per_H", "rho", "V0_over_cs", "dt_times_cs")


def repo_path(path):
    """A path of the study config (relative to the repository root) as an absolute path."""
    return str(REPO / path)


@functools.lru_cache(maxsize=None)
def points(sweep):
    """{name: point} of one sweep (study/sweeps.py)."""
    return study_sweeps.sweep_points(config, sweep, REPO)


def sweep_spec(sweep):
    return config["sweeps"][sweep]


def run_dir(sweep, point):
    """The folder of a sweep's point: results/runs/<point>-<digest>, shared by every sweep whose point
    resolves to the same solver configuration (`run_id`)."""
    return f"{run_store.RUNS_DIR}/{run_id(sweep, point)}"


def run_files(sweep, filename, names=None):
    """<run folder>/<filename> for the given (default: all) points of a sweep."""
    return [f"{run_dir(sweep, name)}/{filename}" for name in (names or points(sweep))]


def _deep_merge(base, extra):
    merged = dict(base)
    for key, value in extra.items():
        merged[key] = _deep_merge(merged[key], value) if isinstance(value, dict) and isinstance(merged.get(key), dict) else value
    return merged


def run_spec(sweep, point):
    """Everything study/make_run_config.py needs to write one config.json."""
    spec = sweep_spec(sweep)
    return {
        "point": points(sweep)[point],
        "model": config["model"],
        "run_length": {**config["run_length"], **spec.get("run_length", {})},
        "solver": _deep_merge(config["solver"], spec.get("solver", {})),
        "snapshot_offsets_transits": spec.get("snapshot_offsets_transits", []),
    }


# Runs are stored by what they compute (study/run_store.py): a point that several sweeps declare with
# the same configuration (table1_ci, table1's published cells and seed 1 of table1_ensemble; the
# paper's reference case in half the one-parameter sweeps) is one folder, computed once. The solver
# build is not in the name: it is an input of every run (a newer binary reruns it), so a folder holds
# the current build's run, and run.h5 records the version that wrote it.
RUN_OWNERS = {}  # run id -> (sweep, point) of the first sweep seen to declare it


@functools.lru_cache(maxsize=None)
def run_config_text(sweep, point):
    """The config.json of one point (study/make_run_config.py), as written into its run folder."""
    return config_json_text(run_config(run_spec(sweep, point)))


@functools.lru_cache(maxsize=None)
def run_id(sweep, point):
    """The name of a point's run folder: equal for equal configurations."""
    identity = run_store.run_id(point, run_config_text(sweep, point))
    RUN_OWNERS.setdefault(identity, (sweep, point))
    return identity


def run_owner(identity):
    """(sweep, point) of a run folder's name, from every declared sweep (a job of its own, e.g. on a
    cluster node, has not looked at the sweeps yet)."""
    if identity not in RUN_OWNERS:
        for sweep in config["sweeps"]:
            for point in points(sweep):
                run_id(sweep, point)
    if identity not in RUN_OWNERS:
        raise WorkflowError(f"results/runs/{identity}: no sweep of the study declares this run "
                            "(its point or its configuration changed since it was made)")
    return RUN_OWNERS[identity]


@functools.lru_cache(maxsize=None)
def run_estimate(sweep, point):
    """Scheduler resources of one run (study/resources.py), from its mesh and simulated time, the part of
    it before the slip onset estimate apart."""
    spec = run_spec(sweep, point)
    config = run_config(spec)
    p, time = spec["point"], config["time"]

    def steps_to(t):
        return study_resources.n_steps(E=spec["model"]["E"], nu=p["nu"], rho=p["rho"], t_end=t,
                                       dt_times_cs=time.get("dt_times_cs", 0.5), dt=time.get("dt"))

    stick_end = min(run_times(spec).t_onset_estimate, time["t_end"])
    stick_steps = steps_to(stick_end) if study_resources.has_stick_phase(config) else 0
    return study_resources.estimate(elements_per_H=p["elements_per_H"], lambda_over_H=p["lambda_over_H"],
                                    steps=steps_to(time["t_end"]), stick_steps=stick_steps)


def figure(sweep, stem):
    """results/<sweep>/figures/<stem>.png and .pdf."""
    return [f"results/{sweep}/figures/{stem}{ext}" for ext in FIGURE_EXTS]


def map_points(sweep):
    """Points drawn as space-time maps: those matching `maps.points` (default: all)."""
    wanted = sweep_spec(sweep).get("maps", {}).get("points")
    if wanted is None:
        return list(points(sweep))
    return [study_sweeps.find_point(points(sweep), match, f"sweeps.{sweep}.maps.points") for match in wanted]


def figure_files(sweep):
    """Every figure (PNG and PDF) that a sweep's `products` ask for."""
    spec = sweep_spec(sweep)
    files = []
    for kind in spec.get("products", []):
        if kind in figure_kinds.PER_SWEEP:
            files += figure(sweep, kind)
        elif kind == "spacetime":
            for field in spec.get("maps", {}).get("fields", ["state"]):
                for name in map_points(sweep):
                    files += figure(sweep, f"spacetime_{field}_{name}")
        elif kind == "snapshots":
            for name in points(sweep):
                files += figure(sweep, f"snapshots_{name}")
    return files


def table_files(sweep):
    """What `python3 -m analysis aggregate` writes for one sweep."""
    directory = f"results/{sweep}/table"
    return [f"{directory}/{name}" for name in
            ("table1.csv", "table1.md", "table1.tex", "summary.json", "all_metrics.csv")]


def sweep_products(sweep, with_report=True):
    """The files of one sweep's target: table, comparison, figures and report as declared."""
    products = sweep_spec(sweep).get("products", [])
    files = table_files(sweep) + figure_files(sweep)
    if "comparison" in products:
        files.append(f"results/{sweep}/table/comparison.txt")
    if "ensemble" in products:
        files += ensemble_files(sweep)  # study/rules/ensemble.smk
    if with_report and "report" in products:
        files.append(f"results/{sweep}/report.html")
    return files


def study_files(files_of):
    """files_of(sweep) for every sweep of `study` (what `all` covers), as one list."""
    return [path for sweep in config["study"] for path in files_of(sweep)]


def table_select(pts, highlight=None):
    """[`--select`, `KEY=VALUE`, ...] so that at most one run falls on each (nu, f) cell of Table 1: every
    other parameter that varies across the points takes the `highlight` point's value, else the
    study default (e.g. the shear-rate sweep's table is the V0/c_s = 1e-5 run)."""
    keys = [k for k in study_sweeps.varying_keys(pts) if k not in ("nu", "f")]
    wanted = {**config["defaults"], **(highlight or {})}
    # No default contrast: the rigid flat, whose runs' metrics carry E_substrate_over_E = None.
    return [word for k in keys for word in ("--select", f"{k}={wanted.get(k)}")]


def has_default_run_settings(sweep):
    """True when a sweep runs its points with the study-wide run length, solver keys and no snapshots, on
    the rigid flat (a sweep with a substrate contrast, `contrast`, is beyond the paper: not in its table)."""
    spec = sweep_spec(sweep)
    on_rigid_flat = all(p.get(study_sweeps.CONTRAST) is None for p in points(sweep).values())
    return (on_rigid_flat and not spec.get("snapshot_offsets_transits") and not spec.get("solver")
            and all(spec.get("run_length", {}).get(k, v) == v for k, v in config["run_length"].items()))


def study_points():
    """{name: (sweep, point)} of the `study` sweeps with default run settings, each run once (the
    first sweep that declares a point owns it; the same point elsewhere is the same computation)."""
    unique = {}
    for sweep in config["study"]:
        if has_default_run_settings(sweep):
            for name, point in points(sweep).items():
                unique.setdefault(name, (sweep, point))
    return unique


def tn_labels(sweep):
    """Legend texts of a sweep's T/N curves: the parameters that vary across it."""
    pts = points(sweep)
    keys = study_sweeps.varying_keys(pts)
    return [study_sweeps.label(p, keys) for p in pts.values()]


def tn_highlight(sweep):
    """[`--highlight`, INDEX] for the sweep's `highlight` point, or nothing."""
    match = sweep_spec(sweep).get("highlight")
    if match is None:
        return []
    name = study_sweeps.find_point(points(sweep), match, f"sweeps.{sweep}.highlight")
    return ["--highlight", list(points(sweep)).index(name)]


def convergence_param(sweep):
    """The one convergence parameter a sweep varies (other parameters, e.g. nu and f, may vary too:
    each of their combinations is one line of the plot)."""
    keys = [key for key in study_sweeps.varying_keys(points(sweep)) if key in CONVERGENCE_PARAMS]
    if len(keys) != 1:
        raise ValueError(f"sweeps.{sweep}: a convergence plot needs exactly one of {CONVERGENCE_PARAMS} "
                         f"to vary, found {keys}")
    return keys[0]


def flutter_nu():
    """Poisson's ratios at which the flutter boundary is evaluated (evenly spaced, `theory`)."""
    theory = config["theory"]
    lo, hi, n = theory["flutter_nu_min"], theory["flutter_nu_max"], theory["flutter_nu_count"]
    return [lo + i * (hi - lo) / (n - 1) for i in range(n)]


# How this process runs jobs, set here for every call of Snakemake 7 (an option it lacks is left as it
# is; study/README.md, "Pipeline overhead"):
# - the rules with `run:` (measure, aggregate: study/in_process.py) run in threads of this process,
#   with --force-use-threads (always so on a cluster node); without it, each would start a new
#   Snakemake, which parses this workflow again (~1.5 s of CPU per job);
# - jobs are chosen by the greedy scheduler unless the command line asks for --scheduler: the default
#   (ilp) starts the CBC solver, a process, each time a job ends and two or more wait, while a core
#   stays idle; its objective beyond the greedy one (which also takes the highest priority first:
#   build_solver's, then contrast_theory's), the early removal of temp() files, has nothing to weigh here;
# - pandas cannot be imported while jobs are planned and run: Snakemake 7 imports it at the start of
#   every call (~0.25 s of CPU beyond numpy, before any job starts) only to fingerprint pandas objects
#   given as params, which no rule has; other params are fingerprinted the same way without it.
#   Nothing run in this process uses it (study/in_process.py neither; figures run in processes of their own).
def _execute_options(execute):
    names = inspect.signature(execute).parameters
    scheduler_given = any(arg.split("=")[0] == "--scheduler" for arg in sys.argv)

    def execute_with_options(*args, **kwargs):
        if "force_use_threads" in names:
            kwargs["force_use_threads"] = True
        if "scheduler_type" in names and not scheduler_given:
            kwargs["scheduler_type"] = "greedy"
        without_pandas = "pandas" not in sys.modules
        if without_pandas:
            sys.modules["pandas"] = None  # `import pandas` raises ImportError
        try:
            return execute(*args, **kwargs)
        finally:
            if without_pandas and sys.modules.get("pandas", 0) is None:
                del sys.modules["pandas"]
    return execute_with_options


workflow.execute = _execute_options(workflow.execute)
