# How sure is Table 1 (paper/how_sure.tex): seed ensembles and the method envelope, their figures and
# the generated inputs of the report's section.

localrules: ensemble_table, envelope, paper_how_sure

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
    return json.dumps({"variants": variants})


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
        "{PYTHON:q} -m analysis ensemble {input.metrics:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} -o {params.directory:q} > {log:q} 2>&1"


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
        "{PYTHON:q} {input.script:q} {input.ensemble:q} --ensemble --flutter {input.flutter:q}"
        " --out {params.prefix:q} > {log:q} 2>&1"


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
        "{PYTHON:q} -m analysis envelope --ensemble {input.ensemble:q} --spec {params.spec:q}"
        " --tolerance {params.tolerance:q} -o results/envelope > {log:q} 2>&1"


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
        "{PYTHON:q} {input.script:q} {input.table:q} --tolerance {params.tolerance:q}"
        " --out results/envelope/envelope > {log:q} 2>&1"


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
        return []
    return ["--finer-ensemble", *input.finer, "--finer-mesh", finer_ensemble()[1]]


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
        script=repo_path("paper/make_how_sure.py"),
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
        "({PYTHON:q} {input.script:q} --ensemble {input.ensemble:q} --envelope {input.envelope:q} {params.finer:q}"
        " -o paper/generated/how_sure_numbers.tex"
        " && cp {input.ensemble_table:q} paper/generated/ensemble.tex"
        " && cp {input.envelope_table:q} paper/generated/envelope.tex"
        " && cp {input.figure:q} paper/generated/envelope.pdf"
        " && cp {input.phase_diagram:q} paper/generated/phase_diagram_ensemble.pdf"
        " && cp {input.rule_scores:q} paper/generated/rule_scores.tex) > {log:q} 2>&1"
