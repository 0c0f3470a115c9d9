# One new point in one command, without editing study/config.yaml:
#
#   snakemake -c2 explore --config 'point={nu: 0.25, f: 1.6}'
#   snakemake -c2 explore --config 'point={nu: 0.45, f: 1.5, E_substrate_over_E: 3, elements_per_H: 32}'
#
# The point (checked by the schema's `point`: key names and ranges) takes every other parameter from
# `defaults` (the study's default mesh and shear rate). It becomes the sweep `explore`, so the usual
# rules run it (simulate, measure, aggregate, space-time maps, T/N); this file adds the
# point's place against the phase diagram and a one-page summary, results/explore/summary.html.
# Included after the sweep targets of the Snakefile: `explore` is a target of its own.

from snakemake.exceptions import WorkflowError

EXPLORE = "explore"
EXPLORE_FIELDS = ["state", "slip_velocity", "opening"]

if config.get("point") is not None:
    config["sweeps"][EXPLORE] = {
        "description": "one point given on the command line (snakemake explore --config 'point={...}')",
        "points": [config["point"]],
        "products": ["spacetime", "tn_curves"],
        "maps": {"fields": EXPLORE_FIELDS},
    }
    # The point passed the schema; its combination with `defaults` may still not be a mesh.
    exit_on_errors(reference_errors(config, REPO))


def explore_point_name():
    if EXPLORE not in config["sweeps"]:
        raise WorkflowError("snakemake explore needs the point: --config 'point={nu: 0.25, f: 1.6}' "
                            "(keys nu, f, V0_over_cs, lambda_over_H, elements_per_H, rho, integration, seed, "
                            "dt_times_cs, E_substrate_over_E; the rest from `defaults` in study/config.yaml)")
    (name,) = points(EXPLORE)
    return name


def explore_files():
    explore_point_name()  # the message when --config point=... is missing
    return sweep_products(EXPLORE, with_report=False) + ["results/explore/summary.html"]


rule explore_phase:
    """The explored point's category against the published Table-1 cells and the flutter wedge."""
    input:
        script=figure_script("explore_phase"),
        metrics=lambda wc: f"{run_dir(EXPLORE, explore_point_name())}/metrics.json",
        reference=repo_path(config["reference"]["table"]),
        flutter="results/theory/flutter.txt",
    output: multiext("results/explore/figures/explore_phase", *FIGURE_EXTS)
    params: prefix="results/explore/figures/explore_phase"
    log: "results/explore/logs/explore_phase.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.metrics:q} --reference {input.reference:q} --flutter {input.flutter:q}"
        " --out {params.prefix:q} > {log:q} 2>&1"


rule explore_summary:
    """One page: the point, its metrics, its place in the phase diagram, T/N and the space-time maps."""
    input:
        script=repo_path("study/scripts/explore_summary.py"),
        metrics=lambda wc: f"{run_dir(EXPLORE, explore_point_name())}/metrics.json",
        phase="results/explore/figures/explore_phase.png",
        tn="results/explore/figures/tn_curves.png",
        maps=lambda wc: [f"results/explore/figures/spacetime_{field}_{explore_point_name()}.png"
                         for field in EXPLORE_FIELDS],
    output: "results/explore/summary.html"
    log: "results/explore/logs/summary.log"
    shell:
        "{PYTHON:q} {input.script:q} --metrics {input.metrics:q} --figures {input.phase:q} {input.tn:q} {input.maps:q}"
        " --out {output:q} > {log:q} 2>&1"
