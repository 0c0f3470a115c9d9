# Sweep tables, comparison with the published Table 1, the CI reference check, the rule scores, the
# flutter wedge. What is committed of them: publish.smk. The confidence studies (paper/how_sure.tex)
# are in ensemble.smk (seeds, method envelope) and limits.smk (mesh and time-step limits, timeline).

localrules: aggregate, compare, reference_check, flutter, rule_scores


def aggregated_points(sweep):
    """{name: (sweep of the run, point)} that `aggregate` reads: a sweep's own points, or for `study`
    the whole study in one table (what paper/ quotes): every distinct run of the `study` sweeps made
    with the default run settings (`study_points`)."""
    if sweep == "study":
        return study_points()
    return {name: (sweep, point) for name, point in points(sweep).items()}


def aggregate_select(wildcards):
    """--select of Table 1: one run per cell, at the sweep's highlight (the study's: the defaults)."""
    highlight = None if wildcards.sweep == "study" else sweep_spec(wildcards.sweep).get("highlight")
    return table_select({name: point for name, (_, point) in aggregated_points(wildcards.sweep).items()},
                        highlight)


rule aggregate:
    """`python3 -m analysis aggregate`, run by the Snakemake process itself (study/in_process.py): one
    sweep's metrics (or the study's, `aggregated_points`) -> Table 1 (csv/md/tex), summary, all metrics."""
    input:
        metrics=lambda wc: [f"{run_dir(sweep, name)}/metrics.json"
                            for name, (sweep, _) in aggregated_points(wc.sweep).items()],
        reference=repo_path(config["reference"]["table"]),
    output: table_files("{sweep}")
    params:
        directory="results/{sweep}/table",
        tolerance=config["reference"]["tolerance"],
        select=aggregate_select,
    log: "results/{sweep}/logs/aggregate.log"
    run:
        in_process.aggregate(list(input.metrics), input.reference, params.tolerance, params.select,
                             params.directory, log[0])


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
        "status=0; {PYTHON:q} -m analysis compare {input.table:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} --min-within 0 > {output:q} 2> {log:q} || status=$?;"
        " echo \"compare exit status: $status\" >> {output:q}"


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
    return [word for cell in known for word in ("--known-mismatch", cell)]


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
        "{PYTHON:q} -m analysis compare {input.table:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} --min-within {params.min_within:q} --ratchet {params.known:q} > {log:q} 2>&1"
        " && cp {log:q} {output:q}"


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
        "{PYTHON:q} -m analysis score-rules {input.metrics:q} --reference {input.reference:q}"
        " --tolerance {params.tolerance:q} {params.select:q} -o {params.directory:q} > {log:q} 2>&1"


rule flutter:
    """Flutter wedge of steady sliding on a rigid flat (Martins et al. 1995), from analysis.theory.flutter."""
    output: "results/theory/flutter.txt"
    params: nu=[f"{nu:.6g}" for nu in flutter_nu()]
    log: "results/theory/logs/flutter.log"
    shell: "{PYTHON:q} -m analysis flutter-boundary --nu {params.nu:q} > {output:q} 2> {log:q}"


def contrast_theory_points(sweep):
    """[--point NU CONTRAST F ...] of a sweep's distinct (nu, contrast, f); 'rigid' for the rigid flat."""
    cells = []
    for p in points(sweep).values():
        contrast = p.get(study_sweeps.CONTRAST)
        cell = (p["nu"], "rigid" if contrast is None else repr(float(contrast)), p["f"])
        if cell not in cells:
            cells.append(cell)
    return [word for nu, contrast, f in cells for word in ("--point", repr(nu), contrast, repr(f))]


rule contrast_theory:
    """The bimaterial theory at a contrast sweep's points (analysis/theory/contrast_theory.py): the onset f
    of each family of growing modes and the most unstable mode; ~55 s of CPU for `contrast` (~100 s before the
    root finders computed q once per s and sampled the contour edges in one call; the same numbers)."""
    output: "results/{sweep}/theory/contrast_theory.csv"
    # Early, beside the runs: it needs none of them, and left to the end (the greedy scheduler takes the
    # many runs first) its 1.7 min were the last thing `all` waited for.
    priority: 50
    params:
        points=lambda wc: contrast_theory_points(wc.sweep),
        E=config["model"]["E"],
    log: "results/{sweep}/logs/contrast_theory.log"
    shell: "{PYTHON:q} -m analysis contrast-theory {params.points:q} --E {params.E:q} -o {output:q} > {log:q} 2>&1"
