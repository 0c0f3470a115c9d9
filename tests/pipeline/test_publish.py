"""What is committed of the campaign (study/rules/publish.smk): `publish_results` writes exactly the files
study/results/ holds, every one the report needs; the report builds from them without any run, and only
under --directory (dry runs; the LaTeX build itself: tests/figures/test_page_width.py)."""

import json
from pathlib import Path

from .conftest import REPO, job_counts, snakemake
from .test_wiring import DRY_ENV, jobs

COMMITTED = REPO / "study" / "results"
NOT_PUBLISHED = {"README.md", "provenance.json"}  # written by hand / by publish_provenance itself


def outputs(result, rule):
    return {fields["output"] for name, fields in jobs(result.stdout) if name == rule}


def test_publish_results_writes_exactly_the_committed_tables(tmp_path):
    result = snakemake(REPO, "-n", "--nolock", "--forceall", "publish_results", env=DRY_ENV)
    published = {str(Path(path).relative_to(COMMITTED)) for path in outputs(result, "publish_file")}
    committed = {str(path.relative_to(COMMITTED)) for path in COMMITTED.rglob("*") if path.is_file()}
    assert published == committed - NOT_PUBLISHED
    # Every kind of evidence the report cites is among them, and the report itself is rebuilt.
    for path in ("table1/table1.csv", "table1_ensemble/ensemble_summary.json", "envelope/envelope.csv",
                 "limits/mesh_limit_summary.json", "limits/timeline.tex", "energy_evidence/energy_evidence.json"):
        assert path in published, path
    counts = job_counts(result.stdout)
    assert counts["paper"] == 1 and counts["publish_provenance"] == 1


def test_the_provenance_names_every_committed_file():
    provenance = json.loads((COMMITTED / "provenance.json").read_text())
    committed = {str(path.relative_to(COMMITTED)) for path in COMMITTED.rglob("*") if path.is_file()}
    assert set(provenance["files"]) == committed - NOT_PUBLISHED
    assert provenance["uncommitted_changes"] is False and len(provenance["git_commit"]) == 40
    assert provenance["report"]["path"].endswith("reproduction.pdf") and (REPO / "paper" / "reproduction.pdf").is_file()


def test_the_report_from_the_committed_tables_runs_nothing(tmp_path):
    result = snakemake(tmp_path, "-n", "--nolock", "--config", "from_committed=true", "--", "paper")
    counts = job_counts(result.stdout)
    for rule in ("simulate", "configure", "measure", "energy_evidence_run", "build_solver", "aggregate",
                 "timeline", "rule_scores", "energy_evidence", "publish_file"):
        assert rule not in counts, rule
    assert counts["paper"] == 1 and counts["paper_source"] == 2
    restored = outputs(result, "restore_committed")
    for path in ("results/study/table/table1.csv", "results/limits/timeline.tex",
                 "results/energy_evidence/energy_evidence.json", "results/table1_ensemble/table/all_metrics.csv"):
        assert path in restored, path
    # The tables derived from the committed ones are computed again, as the runs' pipeline does.
    for rule in ("ensemble_table", "envelope", "mesh_limit", "timestep_limit", "pulse_seeds", "paper_claims"):
        assert counts[rule] >= 1, rule


def test_the_report_from_the_committed_tables_is_refused_in_the_checkout():
    result = snakemake(REPO, "-n", "--nolock", "--config", "from_committed=true", "--", "paper", check=False)
    assert result.returncode != 0 and "--directory" in result.stdout + result.stderr


def test_from_committed_must_be_true_or_false(tmp_path):
    result = snakemake(tmp_path, "-n", "--nolock", "--config", "from_committed=maybe", "--", "paper", check=False)
    assert result.returncode != 0 and "from_committed" in result.stdout + result.stderr
