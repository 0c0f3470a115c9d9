# Figures: one rule per script of figures/, run.h5 / metrics / tables in, PREFIX.png + PREFIX.pdf out.
# Each script is an input, so restyling a figure redraws it, and never reruns a simulation.


def figure_script(name):
    return repo_path(f"figures/{name}.py")


rule fig_spacetime:
    """Fig. 2a,b and 4c-f: space-time map of slip velocity, opening or contact state."""
    input:
        script=figure_script("spacetime"),
        run=lambda wc: f"{run_dir(wc.sweep, wc.point)}/run.h5",
        metrics=lambda wc: f"{run_dir(wc.sweep, wc.point)}/metrics.json",
    output: multiext("results/{sweep}/figures/spacetime_{field}_{point}", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/spacetime_{field}_{point}"
    log: "results/{sweep}/logs/fig_spacetime_{field}_{point}.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.run:q} --field {wildcards.field:q} --metrics {input.metrics:q}"
        " --out {params.prefix:q} > {log:q} 2>&1"


rule fig_tn_curves:
    """Fig. 2c,d: T/N against time for every run of a sweep (the `highlight` point in red)."""
    input:
        script=figure_script("tn_curves"),
        runs=lambda wc: run_files(wc.sweep, "run.h5"),
    output: multiext("results/{sweep}/figures/tn_curves", *FIGURE_EXTS)
    params:
        prefix="results/{sweep}/figures/tn_curves",
        labels=lambda wc: tn_labels(wc.sweep),
        highlight=lambda wc: tn_highlight(wc.sweep),
    log: "results/{sweep}/logs/fig_tn_curves.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.runs:q} --labels {params.labels:q} {params.highlight:q}"
        " --out {params.prefix:q} > {log:q} 2>&1"


rule fig_tn_aligned:
    """Fig. 2c aligned: T/N from the start of each run's first drop (the `highlight` point in red)."""
    input:
        script=figure_script("tn_aligned"),
        runs=lambda wc: run_files(wc.sweep, "run.h5"),
        metrics=lambda wc: run_files(wc.sweep, "metrics.json"),
    output: multiext("results/{sweep}/figures/tn_aligned", *FIGURE_EXTS)
    params:
        prefix="results/{sweep}/figures/tn_aligned",
        labels=lambda wc: tn_labels(wc.sweep),
        highlight=lambda wc: tn_highlight(wc.sweep),
    log: "results/{sweep}/logs/fig_tn_aligned.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.runs:q} --metrics {input.metrics:q} --labels {params.labels:q}"
        " {params.highlight:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_snapshots:
    """Fig. 3: material velocity in the deformed layer, slip velocity and opening at the snapshot times."""
    input:
        script=figure_script("snapshots"),
        run=lambda wc: f"{run_dir(wc.sweep, wc.point)}/run.h5",
    output: multiext("results/{sweep}/figures/snapshots_{point}", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/snapshots_{point}"
    log: "results/{sweep}/logs/fig_snapshots_{point}.log"
    shell: "{PYTHON:q} {input.script:q} {input.run:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_phase_diagram:
    """Fig. 4a: category of each (nu, f) with the theoretical flutter wedge and the paper's
    classification of its Table-1 cells laid over it."""
    input:
        script=figure_script("phase_diagram"),
        metrics="results/{sweep}/table/all_metrics.csv",
        table="results/{sweep}/table/table1.csv",
        flutter="results/theory/flutter.txt",
    output: multiext("results/{sweep}/figures/phase_diagram", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/phase_diagram"
    log: "results/{sweep}/logs/fig_phase_diagram.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.metrics:q} --flutter {input.flutter:q} --published {input.table:q}"
        " --out {params.prefix:q} > {log:q} 2>&1"


rule fig_contrast_phase_diagram:
    """Beyond the paper: the category of each (contrast, f) per nu, over the bimaterial theory's unstable ranges."""
    input:
        script=figure_script("contrast_phase_diagram"),
        metrics="results/{sweep}/table/all_metrics.csv",
        theory="results/{sweep}/theory/contrast_theory.csv",
    output: multiext("results/{sweep}/figures/contrast_phase_diagram", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/contrast_phase_diagram"
    log: "results/{sweep}/logs/fig_contrast_phase_diagram.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.metrics:q} --theory {input.theory:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_celerity_vs_nu:
    """Fig. 4b: slip-front celerity against nu per f, with c_s, sqrt(2) c_s and c_l."""
    input:
        script=figure_script("celerity_vs_nu"),
        table="results/{sweep}/table/table1.csv",
    output: multiext("results/{sweep}/figures/celerity_vs_nu", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/celerity_vs_nu"
    log: "results/{sweep}/logs/fig_celerity_vs_nu.log"
    shell: "{PYTHON:q} {input.script:q} {input.table:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_deviation_map:
    """Deviation from the published celerity over (nu, f), reproduced cells and other categories marked."""
    input:
        script=figure_script("deviation_map"),
        table="results/{sweep}/table/table1.csv",
    output: multiext("results/{sweep}/figures/deviation_map", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/deviation_map"
    log: "results/{sweep}/logs/fig_deviation_map.log"
    shell: "{PYTHON:q} {input.script:q} {input.table:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_pulse_spacing:
    """Pulse spacing against lambda/H with l = 2H sqrt(c_p^2/c_s^2 - 1)."""
    input:
        script=figure_script("pulse_spacing"),
        metrics="results/{sweep}/table/all_metrics.csv",
    output: multiext("results/{sweep}/figures/pulse_spacing", *FIGURE_EXTS)
    params: prefix="results/{sweep}/figures/pulse_spacing"
    log: "results/{sweep}/logs/fig_pulse_spacing.log"
    shell: "{PYTHON:q} {input.script:q} {input.metrics:q} --out {params.prefix:q} > {log:q} 2>&1"


rule fig_convergence:
    """Metrics against the one parameter the sweep varies (mesh, density with dt, shear rate)."""
    input:
        script=figure_script("convergence"),
        metrics="results/{sweep}/table/all_metrics.csv",
    output: multiext("results/{sweep}/figures/convergence", *FIGURE_EXTS)
    params:
        prefix="results/{sweep}/figures/convergence",
        param=lambda wc: convergence_param(wc.sweep),
    log: "results/{sweep}/logs/fig_convergence.log"
    shell:
        "{PYTHON:q} {input.script:q} {input.metrics:q} --param {params.param:q} --out {params.prefix:q} > {log:q} 2>&1"
