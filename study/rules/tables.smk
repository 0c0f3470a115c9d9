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
    """Flutter wedge of steady sliding on a rigid flat (Martins et al. 1995), from analysis.flutter."""
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
    """config `paper.envelope` as analysis/envelope.py's --spec: each variant's tables as files."""
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
    """`python3 -m analysis.ensemble`: runs that differ only by seed -> per-cell statistics."""
    input:
        metrics="results/{sweep}/table/all_metrics.csv",
        reference=repo_path(config["reference"]["table"]),
    output: [f"results/{{sweep}}/table/{name}" for name in ENSEMBLE_TABLES]
    params:
        directory="results/{sweep}/table",
        tolerance=config["reference"]["tolerance"],
    log: "results/{sweep}/logs/ensemble.log"
    shell:
        "{PYTHON} -m analysis.ensemble {input.metrics} --reference {input.reference}"
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
    """`python3 -m analysis.envelope`: the method envelope of every published cell (config
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
        "{PYTHON} -m analysis.envelope --ensemble {input.ensemble} --spec {params.spec}"
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


HOW_SURE_FILES = ["paper/generated/how_sure_numbers.tex", "paper/generated/ensemble.tex",
                  "paper/generated/envelope.tex", "paper/generated/envelope.pdf",
                  "paper/generated/phase_diagram_ensemble.pdf",
                  "paper/generated/rule_scores.tex"]


rule paper_how_sure:
    """The generated inputs of paper/how_sure.tex: its numbers (paper/make_how_sure.py), the
    ensemble and envelope tables, the envelope figure and the ensemble's phase diagram. Through
    the paper, `all` runs the ensemble sweep and the variant sweeps. The rule scores: rule `rule_scores`."""
    input:
        script="paper/make_how_sure.py",
        ensemble=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/table/ensemble_summary.json",
        ensemble_table=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/table/ensemble.tex",
        envelope="results/envelope/envelope_summary.json",
        envelope_table="results/envelope/envelope.tex",
        figure="results/envelope/envelope.pdf",
        phase_diagram=f"results/{config['paper'].get('envelope', {}).get('ensemble', 'none')}/figures/phase_diagram_ensemble.pdf",
        rule_scores=RULE_SCORES[2],
    output: HOW_SURE_FILES
    log: "logs/paper_how_sure.log"
    shell:
        "({PYTHON} {input.script} --ensemble {input.ensemble} --envelope {input.envelope}"
        " -o paper/generated/how_sure_numbers.tex"
        " && cp {input.ensemble_table} paper/generated/ensemble.tex"
        " && cp {input.envelope_table} paper/generated/envelope.tex"
        " && cp {input.figure} paper/generated/envelope.pdf"
        " && cp {input.phase_diagram} paper/generated/phase_diagram_ensemble.pdf"
        " && cp {input.rule_scores} paper/generated/rule_scores.tex) > {log} 2>&1"
