# study/results/: the committed copy of every table the report and the README cite (CSV/JSON, no HDF5),
# with study/results/provenance.json, and the report PDF paper/reproduction.pdf; written only by
# `publish_results`. With `--config from_committed=true` under `--directory` (scripts/report_from_committed.sh)
# the report is built from that copy alone: the committed tables stand in for the runs, every table
# derived from them is recomputed, the figures drawn from runs are left out (the report says so).

def paper_sweeps():
    """Every sweep that config `paper` names (numbers, claims, tables, figures, envelope, limits)."""
    found = []

    def walk(value):
        if isinstance(value, dict):
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)
        elif isinstance(value, str) and value in config["sweeps"]:
            found.append(value)

    walk(config["paper"])
    return found


def published_sweeps():
    """The sweeps whose tables study/results/ keeps: every sweep `all` builds (the study, the merged
    `study` table, what the paper names, the backward-celerity figure's) and the CI reference check."""
    sweeps = [*config["study"], "study", *paper_sweeps(), *BACKWARD_CELERITY_SWEEPS,
              config["reference"]["check_sweep"]]
    return list(dict.fromkeys(sweeps))


SWEEP_TABLES = ("table1.csv", "summary.json", "all_metrics.csv")
ENSEMBLE_PUBLISHED = ("ensemble.csv", "ensemble_summary.json")
LIMITS_PUBLISHED = ("mesh_limit.csv", "mesh_limit_summary.json", "timestep_limit.csv", "timestep_cells.csv",
                    "timestep_limit_summary.json", "pulse_seeds.csv", "pulse_seeds_summary.json")
# Made from the runs, not from the sweep tables (or, the contrast theory, by minutes of root finding): committed
# with their renderings, and restored as they are when the report is built from the committed tables.
CONTRAST_SWEEP = config["paper"].get("contrast", {}).get("sweep")
FROM_RUNS_PUBLISHED = {
    **{f"limits/{name}": f"results/limits/{name}" for name in TIMELINE_TABLES},
    **{f"{RULE_SCORES_SWEEP}/{Path(path).name}": path for path in RULE_SCORES},
    "energy_evidence/energy_evidence.json": "results/energy_evidence/energy_evidence.json",
    **({f"{CONTRAST_SWEEP}/contrast_theory.csv": f"results/{CONTRAST_SWEEP}/theory/contrast_theory.csv"}
       if CONTRAST_SWEEP else {}),
}


def published_files():
    """{path under study/results/: the results/ file it copies}."""
    ensembles = [config["paper"].get("envelope", {}).get(key) for key in ("ensemble", "finer_ensemble")]
    files = {f"{sweep}/{name}": f"results/{sweep}/table/{name}" for sweep in published_sweeps() for name in SWEEP_TABLES}
    files.update({f"{sweep}/{name}": f"results/{sweep}/table/{name}"
                  for sweep in ensembles if sweep for name in ENSEMBLE_PUBLISHED})
    files.update({f"envelope/{name}": f"results/envelope/{name}" for name in ("envelope.csv", "envelope_summary.json")})
    files.update({f"limits/{name}": f"results/limits/{name}" for name in LIMITS_PUBLISHED})
    files.update(FROM_RUNS_PUBLISHED)
    return files


PUBLISHED = published_files()


if not FROM_COMMITTED:
    localrules: publish_file, publish_provenance, publish_results

    rule publish_file:
        """One table copied into study/results/ (the committed results)."""
        input: lambda wc: PUBLISHED[wc.path]
        output: repo_path("study/results/{path}")
        wildcard_constraints: path="|".join(re.escape(path) for path in PUBLISHED)
        log: "logs/publish/{path}.log"
        shell: "cp {input:q} {output:q} 2> {log:q}"

    rule publish_provenance:
        """study/results/provenance.json: the commit, solver version and date of the publication, and the
        SHA-256 of every committed table and of the report."""
        input:
            tables=[repo_path(f"study/results/{path}") for path in PUBLISHED],
            report=PAPER_PDF,
            solver=SOLVER,
        output: repo_path("study/results/provenance.json")
        params: root=repo_path("study/results")
        log: "logs/publish/provenance.log"
        shell:
            "{PYTHON:q} -m study.publish_provenance --root {params.root:q} --solver {input.solver:q}"
            " --report {input.report:q} -o {output:q} > {log:q} 2>&1"

    rule publish_results:
        """`snakemake -c2 all publish_results`: refresh study/results/ and the report PDF from results/ (runs
        whatever is missing). Commit study/results/ and paper/reproduction.pdf afterwards."""
        input: repo_path("study/results/provenance.json")


else:
    if Path.cwd().resolve() == REPO:
        raise ValueError("from_committed: build the report from the committed tables under --directory "
                         "(bash scripts/report_from_committed.sh): in the checkout it would replace results/ "
                         "and paper/generated/ of the runs")

    localrules: restore_committed
    RESTORED = {source: committed for committed, source in PUBLISHED.items()
                if Path(source).name in SWEEP_TABLES or committed in FROM_RUNS_PUBLISHED}

    rule restore_committed:
        """A committed table standing in for what the runs would make (from_committed)."""
        input: lambda wc: repo_path(f"study/results/{RESTORED[wc.path]}")
        output: "{path}"
        wildcard_constraints: path="|".join(re.escape(path) for path in RESTORED)
        shell: "cp {input:q} {output:q}"

    ruleorder: restore_committed > aggregate
    ruleorder: restore_committed > timeline
    ruleorder: restore_committed > rule_scores
    ruleorder: restore_committed > energy_evidence
    ruleorder: restore_committed > contrast_theory


if not FROM_COMMITTED:
    localrules: published_check

    rule published_check:
        """CI, after `all`: every committed table is what the code makes now (study/check_published.py), the
        runs' build names aside; a difference means the results moved and the campaign must be republished."""
        input: list(PUBLISHED.values())
        output: "results/published_check.txt"
        log: "logs/published_check.log"
        run:
            from study.check_published import check

            text, agree = check({repo_path(f"study/results/{committed}"): source
                                 for committed, source in PUBLISHED.items()})
            Path(log[0]).parent.mkdir(parents=True, exist_ok=True)
            Path(log[0]).write_text(text)
            if not agree:
                raise ValueError(f"{text.splitlines()[-1]}; the differences: {log[0]}")
            Path(output[0]).write_text(text)
