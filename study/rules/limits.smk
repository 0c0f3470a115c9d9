# How sure is Table 1, the limits (paper/how_sure.tex, config `paper.limits`): the mesh limit of every
# published cell, the backward pulses against dt, the Fig. 3 timeline and the pulse counts across seeds.

localrules: mesh_limit, timestep_limit, timeline, pulse_seeds, paper_how_sure_limits

LIMITS = config["paper"].get("limits", {})
MESH_LIMIT_TABLES = ("mesh_limit.csv", "mesh_limit.md", "mesh_limit.tex", "mesh_limit_summary.json")
TIMESTEP_LIMIT_TABLES = ("timestep_limit.csv", "timestep_cells.csv", "timestep_limit.md", "timestep_limit.tex",
                         "timestep_limit_summary.json")
TIMELINE_TABLES = ("timeline.csv", "timeline.md", "timeline.tex", "timeline_summary.json")
PULSE_SEEDS_TABLES = ("pulse_seeds.csv", "pulse_seeds.md", "pulse_seeds.tex", "pulse_seeds_summary.json")


def metrics_table(sweep):
    return f"results/{sweep}/table/all_metrics.csv"


def timeline_runs(label):
    """The run folders of the timeline cell in the sweeps of one set (config paper.limits.timeline)."""
    cell = LIMITS["timeline"]["cell"]
    folders = [run_dir(sweep, name) for sweep in LIMITS["timeline"]["sets"][label]
               for name in study_sweeps.find_points(points(sweep), cell)]
    if not folders:
        raise ValueError(f"paper.limits.timeline.sets.{label}: no run of {cell} in {LIMITS['timeline']['sets'][label]}")
    return folders


def timeline_set_options(wildcards):
    return [word for label in LIMITS["timeline"]["sets"] for word in ("--set", label, *timeline_runs(label))]

rule mesh_limit:
    """`python3 -m analysis mesh-limit`: every published cell against 1/N, its Richardson limit
    (docs/mesh-limit.md) and the verdict on whether the published values sit at it."""
    input:
        tables=[metrics_table(sweep) for sweep in LIMITS.get("meshes", {}).values()],
        reference=repo_path(config["reference"]["table"]),
    output: [f"results/limits/{name}" for name in MESH_LIMIT_TABLES]
    params:
        meshes=[word for n, sweep in LIMITS.get("meshes", {}).items() for word in ("--mesh", f"{n}={metrics_table(sweep)}")],
        tolerance=config["reference"]["tolerance"],
    log: "results/limits/logs/mesh_limit.log"
    shell:
        "{PYTHON:q} -m analysis mesh-limit {params.meshes:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} -o results/limits > {log:q} 2>&1"


rule timestep_limit:
    """`python3 -m analysis timestep-limit`: the backward cells against dt c_s, with the seed spread
    and Adams' steady wave; does a dt -> 0 limit exist (docs/supersonic-backward.md section 6)."""
    input:
        tables=[metrics_table(sweep) for sweep in LIMITS.get("timestep", [])],
        reference=repo_path(config["reference"]["table"]),
    output: [f"results/limits/{name}" for name in TIMESTEP_LIMIT_TABLES]
    params: tolerance=config["reference"]["tolerance"]
    log: "results/limits/logs/timestep_limit.log"
    shell:
        "{PYTHON:q} -m analysis timestep-limit {input.tables:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} -o results/limits > {log:q} 2>&1"


rule timeline:
    """`python3 -m analysis timeline`: the Fig. 3 events of the timeline cell across seeds and meshes."""
    input:
        metrics=lambda wc: [f"{d}/metrics.json" for label in LIMITS["timeline"]["sets"] for d in timeline_runs(label)],
        runs=lambda wc: [f"{d}/run.h5" for label in LIMITS["timeline"]["sets"] for d in timeline_runs(label)],
    output: [f"results/limits/{name}" for name in TIMELINE_TABLES]
    params: sets=timeline_set_options
    log: "results/limits/logs/timeline.log"
    shell: "{PYTHON:q} -m analysis timeline {params.sets:q} -o results/limits > {log:q} 2>&1"


rule pulse_seeds:
    """`python3 -m analysis pulse-seeds`: major-pulse counts per lambda/H across seeds, later drops."""
    input: [metrics_table(sweep) for sweep in LIMITS.get("pulses", [])]
    output: [f"results/limits/{name}" for name in PULSE_SEEDS_TABLES]
    params: cell=lambda wc: [LIMITS['timeline']['cell']['nu'], LIMITS['timeline']['cell']['f']]
    log: "results/limits/logs/pulse_seeds.log"
    shell: "{PYTHON:q} -m analysis pulse-seeds {input:q} --cell {params.cell:q} -o results/limits > {log:q} 2>&1"


rule fig_mesh_limit:
    """Deviation from the published celerity against 1/N, one line per cell, by group."""
    input:
        script=repo_path("figures/mesh_limit.py"),
        table="results/limits/mesh_limit.csv",
    output: multiext("results/limits/mesh_limit", *FIGURE_EXTS)
    params: tolerance=config["reference"]["tolerance"]
    log: "results/limits/logs/fig_mesh_limit.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.table:q} --tolerance {params.tolerance:q}"
        " --out results/limits/mesh_limit > {log:q} 2>&1"


rule fig_timestep_backward:
    """The backward cells' celerity against dt c_s: seed mean and range, Adams, published."""
    input:
        script=repo_path("figures/timestep_backward.py"),
        table="results/limits/timestep_limit.csv",
    output: multiext("results/limits/timestep_backward", *FIGURE_EXTS)
    log: "results/limits/logs/fig_timestep_backward.log"
    shell: "{PYTHON:q} {input.script:q} {input.table:q} --out results/limits/timestep_backward > {log:q} 2>&1"


BACKWARD_CELERITY_SWEEPS = ("table1_h32", "variant_seed2", "table1", "table1_h128", "timestep", "variant_dt1",
                            "timestep_backward")


rule fig_backward_celerity:
    """Backward supersonic celerity against f: Adams' steady wave, the paper, our series (mesh, dt)."""
    input:
        script=repo_path("figures/backward_celerity.py"),
        reference=repo_path(config["reference"]["table"]),
        tables=[metrics_table(sweep) for sweep in BACKWARD_CELERITY_SWEEPS],
    output: multiext("results/limits/backward_celerity", *FIGURE_EXTS)
    params: tables=[word for sweep in BACKWARD_CELERITY_SWEEPS for word in ("--table", f"{sweep}={metrics_table(sweep)}")]
    log: "results/limits/logs/fig_backward_celerity.log"
    shell:
        "{PYTHON:q} {input.script:q} {params.tables:q} --reference {input.reference:q}"
        " --out results/limits > {log:q} 2>&1"


HOW_SURE_LIMITS_FILES = ["paper/generated/how_sure_limits.tex", "paper/generated/mesh_limit.tex",
                         "paper/generated/timestep_limit.tex", "paper/generated/timeline.tex",
                         "paper/generated/pulse_seeds.tex", "paper/generated/mesh_limit.pdf",
                         "paper/generated/timestep_backward.pdf", "paper/generated/backward_celerity.pdf"]


rule paper_how_sure_limits:
    """The generated inputs of the limits subsections of paper/how_sure.tex: their numbers and
    sentences (paper/make_how_sure_limits.py), tables and figures."""
    input:
        script=repo_path("paper/make_how_sure_limits.py"),
        mesh="results/limits/mesh_limit_summary.json",
        timestep="results/limits/timestep_limit_summary.json",
        timeline="results/limits/timeline_summary.json",
        pulses="results/limits/pulse_seeds_summary.json",
        tables=[f"results/limits/{name}" for name in ("mesh_limit.tex", "timestep_limit.tex", "timeline.tex",
                                                      "pulse_seeds.tex")],
        figures=[f"results/limits/{name}.pdf" for name in ("mesh_limit", "timestep_backward", "backward_celerity")],
    output: HOW_SURE_LIMITS_FILES
    log: "logs/paper_how_sure_limits.log"
    shell:
        "({PYTHON:q} {input.script:q} --mesh {input.mesh:q} --timestep {input.timestep:q}"
        " --timeline {input.timeline:q} --pulses {input.pulses:q} -o paper/generated/how_sure_limits.tex"
        " && cp {input.tables:q} {input.figures:q} paper/generated/) > {log:q} 2>&1"
