# slidewave: regenerate the parametric study of Yastrebov (2016).
#
#   snakemake -c2                 the default study `quick` (a few minutes)
#   snakemake -c2 all             every sweep of the paper, figures, report, paper PDF
#   snakemake -c2 <sweep>         one sweep (table1, shear_rate, period, mesh, density, long,
#                                 snapshots, quick, ci, table1_ci, ...) with its table and figures
#   snakemake -c2 reference_check Table 1 at H/64 against the published values (CI)
#   snakemake -c2 movies          the animations of `movies` (results/movies/<name>/movie.mp4)
#   snakemake -c2 explore --config 'point={nu: 0.25, f: 1.6}'   one new point, its figures and summary
#
# Wiring only: the study is declared in study/config.yaml (schema study/config.schema.yaml), the
# rules live in study/rules/*.smk, the logic in study/*.py. See study/README.md.

import os
import sys

from snakemake.utils import min_version, update_config

min_version("7.21")
sys.path.insert(0, workflow.basedir)
from study.config_check import exit_on_errors, fill_defaults, load_schema, load_yaml, reference_errors, schema_errors
from study.config_overrides import check_overrides
from study.sweeps import typed_numbers

# Here `config` holds only the command line's values: check their types before they are merged.
STUDY_CONFIG = os.path.join(workflow.basedir, "study/config.yaml")
check_overrides(config, STUDY_CONFIG)
# What `configfile: STUDY_CONFIG` does (the study config under the command line's values), with the
# file parsed by libyaml (study/config_check.py: load_yaml).
workflow.configfiles.append(STUDY_CONFIG)
update_config(config, load_yaml(STUDY_CONFIG))
update_config(config, workflow.overwrite_config)
config.update(typed_numbers(config))  # --config passes nested numbers as strings
# --config passes booleans as strings too; anything but true/false stays a string that the schema refuses.
config.update({key: {"true": True, "false": False}.get(value, value) for key, value in config.items()
               if key == "from_committed" and isinstance(value, str)})
# Every problem on one line naming the key and the allowed values (study/config_check.py).
exit_on_errors(schema_errors(config, load_schema()))
fill_defaults(config, load_schema())  # what snakemake.utils.validate does, without parsing the schema again
exit_on_errors(reference_errors(config, workflow.basedir))

# Interpreter with numpy/h5py/matplotlib (Debian's), and the solver binary: none when the report is
# built from the committed tables (study/rules/publish.smk), so that nothing can plan a run.
PYTHON = os.environ.get("SLIDEWAVE_PYTHON", "/usr/bin/python3")
FROM_COMMITTED = config["from_committed"]
SOLVER = "no-solver-from-committed-tables" if FROM_COMMITTED else os.environ.get("SLIDEWAVE_BIN", "build/slidewave")

include: "study/rules/common.smk"
include: "study/rules/simulate.smk"
include: "study/rules/tables.smk"
include: "study/rules/ensemble.smk"
include: "study/rules/limits.smk"
include: "study/rules/figures.smk"
include: "study/rules/report.smk"
include: "study/rules/movies.smk"
include: "study/rules/publish.smk"


rule quick:
    """The default study: four points at H/32 across the regimes, its table, figures and report."""
    default_target: True
    input: lambda wc: sweep_products("quick")


rule all:
    """The paper: every sweep of `study`, the figures, the study report and the paper PDF."""
    input:
        lambda wc: study_files(sweep_products),
        "results/report.html",
        PAPER_PDF,


rule figures:
    """Every figure of the sweeps in `study`."""
    input: lambda wc: study_files(figure_files)


rule phase_diagram:
    """Fig. 4a: categories in (nu, f) with the flutter wedge."""
    input: figure("table1", "phase_diagram")


# One target per sweep, named like the sweep (`snakemake table1`, `snakemake ci`, ...).
for _sweep in config["sweeps"]:
    if _sweep == "quick":  # defined above, as the default target
        continue
    rule:
        name: _sweep
        input: lambda wc, sweep=_sweep: sweep_products(sweep)


rule movies:
    """One animation per entry of `movies.runs` (figures/movie.py)."""
    input: lambda wc: movie_files()


# After the sweep targets: it declares the sweep `explore` from --config point={...}.
include: "study/rules/explore.smk"


rule explore:
    """One point from the command line: metrics, space-time maps, T/N, phase diagram, summary page."""
    input: lambda wc: explore_files()
