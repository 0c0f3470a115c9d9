"""The figure kinds a sweep's `products` may ask for (study/config.yaml), listed once.

A kind `k` is drawn by figures/k.py through rule `fig_k` (study/rules/figures.smk). The schema's
`products` enum and its reserved target names (study/config.schema.yaml, static JSON Schema) repeat
these names; tests/pipeline/test_study_config.py checks that they, the rules, the scripts and the
report's captions (study/scripts/report.py) agree with this list."""

#: Drawn once per sweep: results/<sweep>/figures/<kind>.png and .pdf.
PER_SWEEP = ("phase_diagram", "celerity_vs_nu", "deviation_map", "tn_curves", "tn_aligned", "pulse_spacing",
             "convergence", "contrast_phase_diagram")
#: Drawn per point: spacetime_<field>_<point> (the sweep's `maps`), snapshots_<point>.
PER_POINT = ("spacetime", "snapshots")
FIGURE_KINDS = PER_SWEEP + PER_POINT
#: Drawn from the runs' run.h5 rather than from tables: left out of the report built from the committed
#: tables (study/rules/publish.smk).
FROM_RUNS = ("tn_curves", "tn_aligned", "spacetime", "snapshots")
#: The products that are not figures: the comparison with the paper, the HTML report, the ensemble table.
OTHER_PRODUCTS = ("comparison", "report", "ensemble")
PRODUCTS = OTHER_PRODUCTS + FIGURE_KINDS
