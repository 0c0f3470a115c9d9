# Sweep tables, comparison with the published Table 1, the CI reference check, and theory.

localrules: aggregate, aggregate_study, compare, reference_check, flutter, publish_table, publish_results,
    ensemble_table, envelope, paper_how_sure, rule_scores


ruleorder: aggregate_study > aggregate


rule aggregate:
    """`python3 -m analysis aggregate`: one sweep's metrics -> Table 1 (csv/md/tex), summary, all metrics
    (with the columns derived for tables and figures, e.g. inside_flutter_wedge)."""
    input:
        metrics=lambda wc: run_files(wc.sweep, "metrics.json"),
        reference=repo_path(config["reference"]["table"]),
        flutter="results/theory/flutter.txt",
    output: table_files("{sweep}")
    params:
        directory="results/{sweep}/table",
        tolerance=config["reference"]["tolerance"],
        select=lambda wc: table_select(points(wc.sweep), sweep_spec(wc.sweep).get("highlight")),
    log: "results/{sweep}/logs/aggregate.log"
    shell:
        "{PYTHON} -m analysis aggregate {input.metrics} --reference {input.reference} --flutter {input.flutter}"
        " --tolerance {params.tolerance} {params.select} -o {params.directory} > {log} 2>&1"


rule aggregate_study:
    """The whole study in one table (what paper/ quotes): every distinct run of the `study` sweeps
    made with the default run settings; Table 1 from the runs at the default parameters."""
    input:
        metrics=lambda wc: [f"{run_dir(sweep, name)}/metrics.json" for name, (sweep, _) in study_points().items()],
        reference=repo_path(config["reference"]["table"]),
        flutter="results/theory/flutter.txt",
    output: table_files("study")
    params:
        directory="results/study/table",
        tolerance=config["reference"]["tolerance"],
        select=lambda wc: table_select({name: point for name, (_, point) in study_points().items()}),
    log: "results/study/logs/aggregate.log"
    shell:
        "{PYTHON} -m analysis aggregate {input.metrics} --reference {input.reference} --flutter {input.flutter}"
        " --tolerance {params.tolerance} {params.select} -o {params.directory} > {log} 2>&1"


rule compare:
    """Regenerated vs published celerities. The verdict is recorded, not enforced: `all` must reach
    the report whatever the fidelity; `reference_check` is the gate."""
    input:
        table="results/{sweep}/table/table1.csv",
        reference=repo_path(config["reference"]["table"]),
    output: "results/{sweep}/table/comparison.txt"
    params: tolerance=config["reference"]["tolerance"]
    log: "results/{sweep}/logs/compare.log"
    shell:
        "status=0; {PYTHON} -m analysis compare {input.table} --reference {input.reference}"
        " --tolerance {params.tolerance} --min-within 0 > {output} 2> {log} || status=$?;"
        " echo \"compare exit status: $status\" >> {output}"


def ratchet_min_within(wildcards, input):
    """The ratchet's minimum count of cells within tolerance; its resolution must be the check sweep's."""
    with open(input.ratchet) as stream:
        ratchet = json.load(stream)
    resolutions = {p["elements_per_H"] for p in points(config["reference"]["check_sweep"]).values()}
    if resolutions != {ratchet["resolution"]}:
        raise ValueError(f"{input.ratchet} is for H/{ratchet['resolution']}, the check sweep runs "
                         f"H/{sorted(resolutions)}")
    return int(ratchet["min_cells_within_5pct"])


def ratchet_known_mismatches(wildcards, input):
    """--known-mismatch options for the cells whose wrong sign or regime the ratchet file records."""
    with open(input.ratchet) as stream:
        known = json.load(stream).get("known_mismatches", {})
    return " ".join(f"--known-mismatch '{cell}'" for cell in known)


rule reference_check:
    """CI gate: Table 1 regenerated at the check sweep's resolution (H/64) must keep every published sign and regime and at least the
    ratchet's count of cells within tolerance (study/reference/ratchet.json; raise it, never lower it)."""
    input:
        table=f"results/{config['reference']['check_sweep']}/table/table1.csv",
        reference=repo_path(config["reference"]["table"]),
        ratchet=repo_path(config["reference"]["ratchet"]),
    output: f"results/{config['reference']['check_sweep']}/reference_check.txt"
    params:
        tolerance=config["reference"]["tolerance"],
        min_within=ratchet_min_within,
        known=ratchet_known_mismatches,
    log: f"results/{config['reference']['check_sweep']}/logs/reference_check.log"
    shell:
        "{PYTHON} -m analysis compare {input.table} --reference {input.reference}"
        " --tolerance {params.tolerance} --min-within {params.min_within} --ratchet {params.known} > {log} 2>&1"
        " && cp {log} {output}"


def rule_score_points():
    """(sweep, {name: point}) of the rule scores: the published cells at H/64 with the default seed,
    i.e. the runs of the check sweep, taken from the ensemble sweep when the paper has one (its
    seed-1 runs are the same points, so `all` runs nothing twice)."""
    sweep = config["paper"].get("envelope", {}).get("ensemble") or config["reference"]["check_sweep"]
    seed = config["defaults"]["seed"]
    return sweep, {name: p for name, p in points(sweep).items() if p.get("seed", seed) == seed}


RULE_SCORES_SWEEP, RULE_SCORES_POINTS = rule_score_points()
RULE_SCORES = [f"results/{RULE_SCORES_SWEEP}/table/rule_scores.{ext}" for ext in ("csv", "md", "tex")]


rule rule_scores:
    """`python3 -m analysis score-rules`: Table 1 scored under every celerity rule of
    docs/measurement-rule.md, side by side (the default rule marked), on the published cells at
    H/64 with the default seed (`rule_score_points`)."""
    input:
        metrics=run_files(RULE_SCORES_SWEEP, "metrics.json", names=list(RULE_SCORES_POINTS)),
        reference=repo_path(config["reference"]["table"]),
    output: RULE_SCORES
    params:
        directory=f"results/{RULE_SCORES_SWEEP}/table",
        tolerance=config["reference"]["tolerance"],
        select=table_select(RULE_SCORES_POINTS),
    log: f"results/{RULE_SCORES_SWEEP}/logs/rule_scores.log"
    shell:
        "{PYTHON} -m analysis score-rules {input.metrics} --reference {input.reference}"
        " --tolerance {params.tolerance} {params.select} -o {params.directory} > {log} 2>&1"


rule flutter:
    """Flutter wedge of steady sliding on a rigid flat (Martins et al. 1995), from analysis.theory.flutter."""
    output: "results/theory/flutter.txt"
    params: nu=" ".join(f"{nu:.6g}" for nu in flutter_nu())
    log: "results/theory/logs/flutter.log"
    shell: "{PYTHON} -m analysis flutter-boundary --nu {params.nu} > {output} 2> {log}"


# study/results/: the committed copy of the study's small tables (no HDF5), written only by this rule.
PUBLISHED_TABLES = ("table1.csv", "summary.json", "all_metrics.csv")


def published_sweeps():
    """The sweeps whose tables study/results/ keeps: the paper's study, its merged table, the CI
    reference check and the method variants, each once."""
    sweeps = [*config["study"], "study", config["reference"]["check_sweep"], *config["paper"]["variants"].values()]
    return list(dict.fromkeys(sweeps))


rule publish_table:
    """One table of a sweep copied into study/results/<sweep>/ (the committed results)."""
    input: "results/{sweep}/table/{name}"
    output: repo_path("study/results/{sweep}/{name}")
    wildcard_constraints: name="|".join(re.escape(n) for n in PUBLISHED_TABLES)
    log: "results/{sweep}/logs/publish_{name}.log"
    shell: "cp {input} {output} 2> {log}"


rule publish_results:
    """`snakemake publish_results`: refresh study/results/ from results/ (runs whatever is missing:
    the whole study, the variants and the CI sweep). Commit study/results/ afterwards."""
    input: [repo_path(f"study/results/{sweep}/{name}") for sweep in published_sweeps() for name in PUBLISHED_TABLES]


# --------------------------------------------------------------------------------------------------
# How sure is Table 1 (paper/how_sure.tex): seed ensembles and the method envelope.

ENSEMBLE_TABLES = ("ensemble.csv", "ensemble.md", "ensemble.tex", "ensemble_summary.json")
ENVELOPE_TABLES = ("envelope.csv", "envelope.md", "envelope.tex", "envelope_summary.json")


def ensemble_files(sweep):
    """Product `ensemble`: the per-cell statistics over seeds and the phase diagram with agreement."""
    return [f"results/{sweep}/table/{name}" for name in ENSEMBLE_TABLES] + figure(sweep, "phase_diagram_ensemble")


def envelope_spec(wildcards, input):
    """config `paper.envelope` as analysis/confidence/envelope.py's --spec: each variant's tables as files."""
    variants = []
    for entry in config["paper"]["envelope"]["variants"]:
        variant = {k: v for k, v in entry.items() if k not in ("sweep", "base")}
        variant["table"] = f"results/{entry['sweep']}/table/all_metrics.csv"
        variant["base"] = f"results/{entry['base']}/table/all_metrics.csv"
        variants.append(variant)
    return shlex.quote(json.dumps({"variants": variants}))


def envelope_tables():
    """The all_metrics.csv of every sweep the envelope's variants read."""
    entries = config["paper"]["envelope"]["variants"]
    sweeps = dict.fromkeys(s for e in entries for s in (e["sweep"], e["base"]))
    return [f"results/{sweep}/table/all_metrics.csv" for sweep in sweeps]


rule ensemble_table:
    """`python3 -m analysis ensemble`: runs that differ only by seed -> per-cell statistics."""
    input:
        metrics="results/{sweep}/table/all_metrics.csv",
        reference=repo_path(config["reference"]["table"]),
    output: [f"results/{{sweep}}/table/{name}" for name in ENSEMBLE_TABLES]
    params:
        directory="results/{sweep}/table",
        tolerance=config["reference"]["tolerance"],
    log: "results/{sweep}/logs/ensemble.log"
    shell:
        "{PYTHON} -m analysis ensemble {input.metrics} --reference {input.reference}"
        " --tolerance {params.tolerance} -o {params.directory} > {log} 2>&1"


rule fig_phase_diagram_ensemble:
    """The phase diagram of an ensemble: majority category per cell, its agreement over the seeds."""
    input:
        script=repo_path("figures/phase_diagram.py"),
        ensemble="results/{sweep}/table/ensemble.csv",
        flutter="results/theory/flutter.txt",
    output: multiext("results/{sweep}/figures/phase_diagram_ensemble", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/phase_diagram_ensemble"
    log: "results/{sweep}/logs/fig_phase_diagram_ensemble.log"
    shell:
        "{PYTHON} {input.script} {input.ensemble} --ensemble --flutter {input.flutter}"
        " --out {params.prefix} > {log} 2>&1"


rule envelope:
    """`python3 -m analysis envelope`: the method envelope of every published cell (config
    `paper.envelope`: the ensemble sweep and the variants)."""
    input:
        ensemble=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/table/ensemble.csv",
        tables=envelope_tables() if config["paper"].get("envelope") else [],
    output: [f"results/envelope/{name}" for name in ENVELOPE_TABLES]
    params:
        spec=envelope_spec,
        tolerance=config["reference"]["tolerance"],
    log: "results/envelope/logs/envelope.log"
    shell:
        "{PYTHON} -m analysis envelope --ensemble {input.ensemble} --spec {params.spec}"
        " --tolerance {params.tolerance} -o results/envelope > {log} 2>&1"


rule fig_envelope:
    """Deviation from the published celerity per cell: seed bar, method envelope, status."""
    input:
        script=repo_path("figures/envelope.py"),
        table="results/envelope/envelope.csv",
    output: multiext("results/envelope/envelope", *FIGURE_EXTS)
    params:
        tolerance=config["reference"]["tolerance"],
    log: "results/envelope/logs/fig_envelope.log"
    shell:
        "{PYTHON} {input.script} {input.table} --tolerance {params.tolerance}"
        " --out results/envelope/envelope > {log} 2>&1"


def finer_ensemble():
    """config paper.envelope.finer_ensemble: (sweep, its one mesh H/h) or None."""
    sweep = config["paper"].get("envelope", {}).get("finer_ensemble")
    if sweep is None:
        return None
    meshes = {point["elements_per_H"] for point in points(sweep).values()}
    if len(meshes) != 1:
        raise ValueError(f"paper.envelope.finer_ensemble: sweep {sweep} has meshes {sorted(meshes)}, needs one")
    return sweep, meshes.pop()


def finer_ensemble_option(wildcards, input):
    if not input.finer:
        return ""
    return f"--finer-ensemble {input.finer} --finer-mesh {finer_ensemble()[1]}"


HOW_SURE_FILES = ["paper/generated/how_sure_numbers.tex", "paper/generated/ensemble.tex",
                  "paper/generated/envelope.tex", "paper/generated/envelope.pdf",
                  "paper/generated/phase_diagram_ensemble.pdf",
                  "paper/generated/rule_scores.tex"]


rule paper_how_sure:
    """The generated inputs of paper/how_sure.tex: its numbers (paper/make_how_sure.py), the
    ensemble and envelope tables, the envelope figure and the ensemble's phase diagram. Through
    the paper, `all` runs the ensemble sweeps (and the finer one) and the variant sweeps. The rule
    scores: rule `rule_scores`."""
    input:
        script="paper/make_how_sure.py",
        ensemble=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/table/ensemble_summary.json",
        ensemble_table=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/table/ensemble.tex",
        envelope="results/envelope/envelope_summary.json",
        envelope_table="results/envelope/envelope.tex",
        figure="results/envelope/envelope.pdf",
        phase_diagram=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/figures/phase_diagram_ensemble.pdf",
        rule_scores=RULE_SCORES[2],
        finer=[f"results/{finer_ensemble()[0]}/table/ensemble_summary.json"] if finer_ensemble() else [],
    output: HOW_SURE_FILES
    params: finer=finer_ensemble_option
    log: "logs/paper_how_sure.log"
    shell:
        "({PYTHON} {input.script} --ensemble {input.ensemble} --envelope {input.envelope} {params.finer}"
        " -o paper/generated/how_sure_numbers.tex"
        " && cp {input.ensemble_table} paper/generated/ensemble.tex"
        " && cp {input.envelope_table} paper/generated/envelope.tex"
        " && cp {input.figure} paper/generated/envelope.pdf"
        " && cp {input.phase_diagram} paper/generated/phase_diagram_ensemble.pdf"
        " && cp {input.rule_scores} paper/generated/rule_scores.tex) > {log} 2>&1"


# --------------------------------------------------------------------------------------------------
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
    return " ".join(f"--set {shlex.quote(label)} " + " ".join(timeline_runs(label))
                    for label in LIMITS["timeline"]["sets"])


rule mesh_limit:
    """`python3 -m analysis mesh-limit`: every published cell against 1/N, its Richardson limit
    (docs/mesh-limit.md) and the verdict on whether the published values sit at it."""
    input:
        tables=[metrics_table(sweep) for sweep in LIMITS.get("meshes", {}).values()],
        reference=repo_path(config["reference"]["table"]),
    output: [f"results/limits/{name}" for name in MESH_LIMIT_TABLES]
    params:
        meshes=" ".join(f"--mesh {n}={metrics_table(sweep)}" for n, sweep in LIMITS.get("meshes", {}).items()),
        tolerance=config["reference"]["tolerance"],
    log: "results/limits/logs/mesh_limit.log"
    shell:
        "{PYTHON} -m analysis mesh-limit {params.meshes} --reference {input.reference}"
        " --tolerance {params.tolerance} -o results/limits > {log} 2>&1"


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
        "{PYTHON} -m analysis timestep-limit {input.tables} --reference {input.reference}"
        " --tolerance {params.tolerance} -o results/limits > {log} 2>&1"


rule timeline:
    """`python3 -m analysis timeline`: the Fig. 3 events of the timeline cell across seeds and meshes."""
    input:
        metrics=lambda wc: [f"{d}/metrics.json" for label in LIMITS["timeline"]["sets"] for d in timeline_runs(label)],
        runs=lambda wc: [f"{d}/run.h5" for label in LIMITS["timeline"]["sets"] for d in timeline_runs(label)],
    output: [f"results/limits/{name}" for name in TIMELINE_TABLES]
    params: sets=timeline_set_options
    log: "results/limits/logs/timeline.log"
    shell: "{PYTHON} -m analysis timeline {params.sets} -o results/limits > {log} 2>&1"


rule pulse_seeds:
    """`python3 -m analysis pulse-seeds`: major-pulse counts per lambda/H across seeds, later drops."""
    input: [metrics_table(sweep) for sweep in LIMITS.get("pulses", [])]
    output: [f"results/limits/{name}" for name in PULSE_SEEDS_TABLES]
    params: cell=lambda wc: f"{LIMITS['timeline']['cell']['nu']} {LIMITS['timeline']['cell']['f']}"
    log: "results/limits/logs/pulse_seeds.log"
    shell: "{PYTHON} -m analysis pulse-seeds {input} --cell {params.cell} -o results/limits > {log} 2>&1"


rule fig_mesh_limit:
    """Deviation from the published celerity against 1/N, one line per cell, by group."""
    input:
        script=repo_path("figures/mesh_limit.py"),
        table="results/limits/mesh_limit.csv",
    output: multiext("results/limits/mesh_limit", *FIGURE_EXTS)
    params: tolerance=config["reference"]["tolerance"]
    log: "results/limits/logs/fig_mesh_limit.log"
    shell:
        "{PYTHON} {input.script} {input.table} --tolerance {params.tolerance}"
        " --out results/limits/mesh_limit > {log} 2>&1"


rule fig_timestep_backward:
    """The backward cells' celerity against dt c_s: seed mean and range, Adams, published."""
    input:
        script=repo_path("figures/timestep_backward.py"),
        table="results/limits/timestep_limit.csv",
    output: multiext("results/limits/timestep_backward", *FIGURE_EXTS)
    log: "results/limits/logs/fig_timestep_backward.log"
    shell: "{PYTHON} {input.script} {input.table} --out results/limits/timestep_backward > {log} 2>&1"


BACKWARD_CELERITY_SWEEPS = ("table1_h32", "variant_seed2", "table1", "table1_h128", "timestep", "variant_dt1",
                            "timestep_backward")


rule fig_backward_celerity:
    """Backward supersonic celerity against f: Adams' steady wave, the paper, our series (mesh, dt)."""
    input:
        script=repo_path("figures/backward_celerity.py"),
        reference=repo_path(config["reference"]["table"]),
        tables=[metrics_table(sweep) for sweep in BACKWARD_CELERITY_SWEEPS],
    output: multiext("results/limits/backward_celerity", *FIGURE_EXTS)
    params: tables=" ".join(f"--table {sweep}={metrics_table(sweep)}" for sweep in BACKWARD_CELERITY_SWEEPS)
    log: "results/limits/logs/fig_backward_celerity.log"
    shell:
        "{PYTHON} {input.script} {params.tables} --reference {input.reference}"
        " --out results/limits > {log} 2>&1"


HOW_SURE_LIMITS_FILES = ["paper/generated/how_sure_limits.tex", "paper/generated/mesh_limit.tex",
                         "paper/generated/timestep_limit.tex", "paper/generated/timeline.tex",
                         "paper/generated/pulse_seeds.tex", "paper/generated/mesh_limit.pdf",
                         "paper/generated/timestep_backward.pdf", "paper/generated/backward_celerity.pdf"]


rule paper_how_sure_limits:
    """The generated inputs of the limits subsections of paper/how_sure.tex: their numbers and
    sentences (paper/make_how_sure_limits.py), tables and figures."""
    input:
        script="paper/make_how_sure_limits.py",
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
        "({PYTHON} {input.script} --mesh {input.mesh} --timestep {input.timestep}"
        " --timeline {input.timeline} --pulses {input.pulses} -o paper/generated/how_sure_limits.tex"
        " && cp {input.tables} {input.figures} paper/generated/) > {log} 2>&1"
