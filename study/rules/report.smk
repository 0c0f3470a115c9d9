# Study reports (our own HTML: Snakemake 7.21's --report needs internet) and the LaTeX paper.

REPORT_SCRIPT = repo_path("study/scripts/report.py")

localrules: sweep_report, report, paper_figure, paper_numbers, paper_table, paper, energy_evidence_config,
    paper_energy_evidence, paper_claims, energy_evidence, paper_contrast


def report_inputs(sweeps):
    """Everything a report shows: tables, comparisons, PNG figures, and each run's files."""
    files = [REPORT_SCRIPT]
    for sweep in sweeps:
        files += [f for f in sweep_products(sweep, with_report=False) if not f.endswith(".pdf")]
        for name in ("config.json", "metrics.json", "logs/simulate.benchmark.tsv"):
            files += run_files(sweep, name)
    return files


def report_manifest(title, sweeps):
    """The manifest study/scripts/report.py reads (JSON text)."""
    sections = []
    for sweep in sweeps:
        products = sweep_spec(sweep).get("products", [])
        sections.append({
            "sweep": sweep,
            "description": sweep_spec(sweep).get("description", ""),
            "table": f"results/{sweep}/table/table1.csv",
            "cells": sorted({(p["nu"], p["f"]) for p in points(sweep).values()}),
            "comparison": f"results/{sweep}/table/comparison.txt" if "comparison" in products else None,
            "figures": [f for f in figure_files(sweep) if f.endswith(".png")],
            "runs": [{"name": name, "dir": run_dir(sweep, name)} for name in points(sweep)],
        })
    return json.dumps({"title": title, "tolerance": config["reference"]["tolerance"], "sections": sections})


rule sweep_report:
    """One sweep's HTML summary (product `report`)."""
    input: lambda wc: report_inputs([wc.sweep])
    output: "results/{sweep}/report.html"
    params: manifest=lambda wc: report_manifest(f"slidewave: sweep {wc.sweep}", [wc.sweep])
    log: "results/{sweep}/logs/report.log"
    shell: "{PYTHON:q} {REPORT_SCRIPT:q} --manifest {params.manifest:q} --out {output:q} > {log:q} 2>&1"


rule report:
    """The study's HTML summary: every sweep of `study` (snakemake report)."""
    input: lambda wc: report_inputs(config["study"])
    output: "results/report.html"
    params: manifest=lambda wc: report_manifest("slidewave: reproduction of Yastrebov (2016)", config["study"])
    log: "logs/report.log"
    shell: "{PYTHON:q} {REPORT_SCRIPT:q} --manifest {params.manifest:q} --out {output:q} > {log:q} 2>&1"


PAPER_PDF = "paper/reproduction.pdf"
PAPER_SOURCES = ("reproduction.tex", "how_sure.tex")


def paper_figures():
    """paper/generated/<name>.pdf of config `paper.figures` that this build can draw: without the runs
    (from_committed), not those drawn from run.h5 (the report frames a note in their place)."""
    names = [name for name, entry in config["paper"]["figures"].items()
             if not (FROM_COMMITTED and entry["figure"].startswith(figure_kinds.FROM_RUNS))]
    return [f"paper/generated/{name}.pdf" for name in names]


if Path.cwd().resolve() != REPO:
    localrules: paper_source

    rule paper_source:
        """Under --directory: a LaTeX source of the report copied beside its generated files."""
        input: repo_path("paper/{name}")
        output: "paper/{name}"
        wildcard_constraints: name="|".join(re.escape(name) for name in PAPER_SOURCES)
        shell: "cp {input:q} {output:q}"


def paper_figure_source(wildcards):
    """The results PDF that paper/generated/<name>.pdf copies (config `paper.figures`)."""
    entry = config["paper"]["figures"][wildcards.name]
    stem = entry["figure"]
    if "match" in entry:
        stem += "_" + study_sweeps.find_point(points(entry["sweep"]), entry["match"], f"paper.figures.{wildcards.name}")
    return f"results/{entry['sweep']}/figures/{stem}.pdf"


rule paper_figure:
    """A figure of the paper: a copy of the sweep's figure under the name reproduction.tex uses."""
    input: paper_figure_source
    output: "paper/generated/{name}.pdf"
    wildcard_constraints: name="|".join(config["paper"]["figures"]) or "no-figure"
    log: "logs/paper_figure_{name}.log"
    shell: "cp {input:q} {output:q} 2> {log:q}"


def numbers_spec():
    """config `paper.numbers`: the grid sweep and {role: sweep} of paper/make_numbers.py."""
    spec = config["paper"].get("numbers")
    if not spec:
        raise ValueError("paper.numbers: the paper needs its `grid` sweep and `sweeps` (study/config.yaml)")
    return spec


def swept_parameter(sweep):
    """The one point parameter besides nu and f that a sweep varies."""
    keys = [key for key in study_sweeps.varying_keys(points(sweep)) if key not in ("nu", "f")]
    if len(keys) != 1:
        raise ValueError(f"sweeps.{sweep}: paper.numbers needs a sweep of exactly one parameter besides "
                         f"nu and f, found {keys}")
    return keys[0]


rule paper_numbers:
    """Every number the paper quotes (paper/make_numbers.py) and its Table 1 (paper/make_table1.py),
    from the sweeps named in config `paper.numbers`, read at the `defaults` nu and f."""
    input:
        numbers_script=repo_path("paper/make_numbers.py"),
        table_script=repo_path("paper/make_table1.py"),
        summary="results/study/table/summary.json",
        runs="results/study/table/all_metrics.csv",
        table="results/study/table/table1.csv",
        grid=lambda wc: f"results/{numbers_spec()['grid']}/table/all_metrics.csv",
        sweeps=lambda wc: [f"results/{sweep}/table/all_metrics.csv" for sweep in numbers_spec()["sweeps"].values()],
        meshes=lambda wc: [f"results/{sweep}/table/table1.csv" for sweep in numbers_spec().get("meshes", {}).values()],
    output:
        numbers="paper/generated/numbers.tex",
        table="paper/generated/table1.tex",
    params:
        cell=[config['defaults']['nu'], config['defaults']['f']],
        sweeps=lambda wc: [word for role, sweep in numbers_spec()["sweeps"].items() for word in
                           ("--sweep", role, swept_parameter(sweep), f"results/{sweep}/table/all_metrics.csv")],
        meshes=lambda wc: [f"--other-mesh={label}=results/{sweep}/table/table1.csv"
                           for label, sweep in numbers_spec().get("meshes", {}).items()],
    log: "logs/paper_numbers.log"
    shell:
        "({PYTHON:q} {input.numbers_script:q} --summary {input.summary:q} --runs {input.runs:q} --grid {input.grid:q}"
        " --table1 {input.table:q} --reference-cell {params.cell:q} {params.sweeps:q} -o {output.numbers:q}"
        " && {PYTHON:q} {input.table_script:q} {input.table:q} {params.meshes:q} -o {output.table:q}) > {log:q} 2>&1"


rule paper_variants:
    """The method-variant table of the reproduction report (paper/make_variants.py), config `paper.variants`."""
    input:
        script=repo_path("paper/make_variants.py"),
        summaries=[f"results/{sweep}/table/summary.json" for sweep in config["paper"]["variants"].values()],
    output: "paper/generated/variants.tex"
    params:
        pairs=[f"{label}=results/{sweep}/table/summary.json" for label, sweep in config["paper"]["variants"].items()]
    log: "logs/paper_variants.log"
    shell: "{PYTHON:q} {input.script:q} {params.pairs:q} -o {output:q} > {log:q} 2>&1"


def claim_tables():
    """{table name: results file} of config `paper.claims` (make_claims.py's --table), the sweeps that
    exist; `table1` is a table1.csv, the others all_metrics.csv. An undeclared sweep is left out, and
    make_claims.py says which claims it leaves untestable."""
    tables = {}
    for name, sweep in config["paper"].get("claims", {}).items():
        if sweep == "study" or sweep in config["sweeps"]:
            tables[name] = f"results/{sweep}/table/{'table1.csv' if name == 'table1' else 'all_metrics.csv'}"
    return tables


rule paper_claims:
    """The verdict on each claim of the paper (study/reference/claims.json) and the report's
    Conclusions drawn from them (paper/make_claims.py)."""
    input:
        script=repo_path("paper/make_claims.py"),
        rules=[repo_path("analysis/tables/claims.py"), repo_path("analysis/tables/claim_support.py")],  # the verdicts make_claims.py renders
        claims=repo_path("study/reference/claims.json"),
        tables=lambda wc: list(claim_tables().values()),
        meshes=lambda wc: [f"results/{sweep}/table/table1.csv" for sweep in numbers_spec().get("meshes", {}).values()],
    output:
        table="paper/generated/claims.tex",
        conclusions="paper/generated/conclusions.tex",
        verdicts="paper/generated/claims.json",
    params:
        tolerance=config["reference"]["tolerance"],
        tables=lambda wc: [f"--table={name}={path}" for name, path in claim_tables().items()],
        meshes=lambda wc: [f"--mesh-table={label}=results/{sweep}/table/table1.csv"
                           for label, sweep in numbers_spec().get("meshes", {}).items()],
    log: "logs/paper_claims.log"
    shell:
        "{PYTHON:q} {input.script:q} --claims {input.claims:q} --tolerance {params.tolerance:q} {params.tables:q}"
        " {params.meshes:q} -o {output.table:q} --conclusions {output.conclusions:q} --json {output.verdicts:q}"
        " > {log:q} 2>&1"


CONTRAST_FILES = ["paper/generated/contrast_text.tex", "paper/generated/contrast_table.tex"]


rule paper_contrast:
    """"Beyond the paper: a deformable substrate": its sentences and table from the contrast sweep's runs and
    the bimaterial theory at its points (paper/make_contrast.py), config `paper.contrast`."""
    input:
        script=repo_path("paper/make_contrast.py"),
        metrics=lambda wc: f"results/{config['paper']['contrast']['sweep']}/table/all_metrics.csv",
        theory=lambda wc: f"results/{config['paper']['contrast']['sweep']}/theory/contrast_theory.csv",
    output: CONTRAST_FILES
    log: "logs/paper_contrast.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.metrics:q} --theory {input.theory:q} --text {output[0]:q}"
        " --table {output[1]:q} > {log:q} 2>&1"


ENERGY_RUNS = ("alpha_zero", "alpha", "alpha_end")  # the options of `analysis energy-evidence`


def energy_evidence_config(name):
    """Solver config of one energy-evidence run: config `paper.energy_evidence`, the run's keys over `base`."""
    def merged(base, over):
        out = dict(base)
        for key, value in over.items():
            out[key] = merged(out.get(key, {}), value) if isinstance(value, dict) else value
        return out
    spec = config["paper"]["energy_evidence"]
    return merged(spec["base"], spec["runs"][name])


rule energy_evidence_config:
    """The solver configuration of one run of config `paper.energy_evidence`."""
    output: "results/energy_evidence/{name}.json"
    wildcard_constraints: name="|".join(ENERGY_RUNS)
    params: text=lambda wc: json.dumps(energy_evidence_config(wc.name), sort_keys=True)
    shell: "printf '%s\\n' {params.text:q} > {output:q}"


rule energy_evidence_run:
    """`slidewave run` of one energy-evidence run (H/32, a few seconds)."""
    input:
        config="results/energy_evidence/{name}.json",
        solver=SOLVER,
    output: "results/energy_evidence/{name}.h5"
    wildcard_constraints: name="|".join(ENERGY_RUNS)
    log: "results/energy_evidence/logs/{name}.log"
    threads: 1
    resources: mem_mb=1000, runtime=10
    shell: "{input.solver:q} run {input.config:q} -o {output:q} --threads 1 > {log:q} 2>&1"


rule energy_evidence:
    """`python3 -m analysis energy-evidence`: the energy-balance residual of the three runs, at alpha = 0
    and against the HHT dissipation measured term by term at the study's alpha (a committed table)."""
    input: expand("results/energy_evidence/{name}.h5", name=ENERGY_RUNS)
    output: "results/energy_evidence/energy_evidence.json"
    params: runs=lambda wc, input: [w for name, path in zip(ENERGY_RUNS, input) for w in (f"--{name.replace('_', '-')}", path)]
    log: "results/energy_evidence/logs/energy_evidence.log"
    shell: "{PYTHON:q} -m analysis energy-evidence {params.runs:q} -o {output:q} > {log:q} 2>&1"


rule paper_energy_evidence:
    """The energy-balance evidence of the report: paper/make_energy_evidence.py formats the JSON."""
    input:
        script=repo_path("paper/make_energy_evidence.py"),
        evidence="results/energy_evidence/energy_evidence.json",
    output: "paper/generated/energy_evidence.tex"
    log: "logs/paper_energy_evidence.log"
    shell: "{PYTHON:q} {input.script:q} {input.evidence:q} -o {output:q} > {log:q} 2>&1"


def paper_table_job(name):
    """How `paper/generated/<name>.tex` is made (config `paper.tables`): the script, the table file
    each sweep contributes, the script's options, and the [(label, sweep)] sets."""
    spec = config["paper"]["tables"][name]
    if spec["resolution"]:
        return dict(script=repo_path("paper/make_resolution_table.py"), table="table1.csv",
                    options=["--tolerance", config['reference']['tolerance']], sets=list(spec["sets"].items()))
    if not spec.get("columns"):
        raise ValueError(f"paper.tables.{name}: a sweep table needs `columns`")
    return dict(script=repo_path("paper/make_sweep_table.py"), table="all_metrics.csv",
                options=["--columns", *spec["columns"]], sets=list(spec["sets"].items()))


rule paper_table:
    """A table of the report: per-run metrics of sweeps, or the published cells at several meshes."""
    input:
        script=lambda wc: paper_table_job(wc.name)["script"],
        tables=lambda wc: [f"results/{sweep}/table/{paper_table_job(wc.name)['table']}"
                           for _, sweep in paper_table_job(wc.name)["sets"]],
    output: "paper/generated/{name}.tex"
    wildcard_constraints: name="|".join(config["paper"]["tables"]) or "no-table"
    params:
        sets=lambda wc, input: [f"{label}={path}" for (label, _), path in
                                zip(paper_table_job(wc.name)["sets"], input.tables)],
        options=lambda wc: paper_table_job(wc.name)["options"],
    log: "logs/paper_table_{name}.log"
    shell: "{PYTHON:q} {input.script:q} {params.sets:q} {params.options:q} -o {output:q} > {log:q} 2>&1"


rule paper:
    """The LaTeX reproduction report (paper/reproduction.tex): every number, table and figure from
    generated files; under --directory from a copy of its sources there. Fails (and
    leaves no PDF) on content wider than the text, an undefined reference or a placeholder number
    of numbers.tex or energy_evidence.tex (paper/check_latex_log.py)."""
    input:
        tex=[f"paper/{name}" for name in PAPER_SOURCES],
        check=repo_path("paper/check_latex_log.py"),
        numbers="paper/generated/numbers.tex",
        table="paper/generated/table1.tex",
        variants="paper/generated/variants.tex",
        energy="paper/generated/energy_evidence.tex",
        claims="paper/generated/claims.tex",
        conclusions="paper/generated/conclusions.tex",
        figures=paper_figures(),
        tables=expand("paper/generated/{name}.tex", name=config["paper"]["tables"]),
        how_sure=HOW_SURE_FILES if config["paper"].get("envelope") else [],  # study/rules/ensemble.smk
        how_sure_limits=HOW_SURE_LIMITS_FILES if config["paper"].get("limits") else [],  # study/rules/limits.smk
        contrast=CONTRAST_FILES if config["paper"].get("contrast") else [],
    output: PAPER_PDF
    log: "logs/paper.log"
    shell:
        "(latexmk -pdf -interaction=nonstopmode -halt-on-error -file-line-error -cd paper/reproduction.tex"
        " && {PYTHON:q} {input.check:q} paper/reproduction.log --numbers {input.numbers:q} --numbers {input.energy:q})"
        " > {log:q} 2>&1"
