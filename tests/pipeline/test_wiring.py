"""The DAG of every target, by dry runs (no solver needed): counts of jobs per rule, the ratchet's
checks, and that a new point adds exactly its own jobs."""

import json
import re
from pathlib import PurePosixPath

import pytest
import yaml

from study.sweeps import sweep_points

from .conftest import REPO, SOLVER, job_counts, snakemake

# Dry runs execute nothing: any existing file stands in for an unbuilt solver.
DRY_ENV = {"SLIDEWAVE_BIN": str(SOLVER) if SOLVER.is_file() else "/bin/true"}


@pytest.fixture
def workdir(tmp_path):
    return tmp_path / "work"


def dry(workdir, *args, **kwargs):
    result = snakemake(workdir, "-n", "--nolock", *args, env=DRY_ENV, **kwargs)
    return result, job_counts(result.stdout)


def test_ci_target(workdir):
    _, counts = dry(workdir, "ci")
    assert counts == {"aggregate": 1, "ci": 1, "fig_spacetime": 1, "measure": 2, "simulate": 2}


def test_quick_is_the_default_target(workdir):
    _, default = dry(workdir)
    _, quick = dry(workdir, "quick")
    assert default == quick
    assert quick["simulate"] == 4 and quick["sweep_report"] == 1 and quick["fig_phase_diagram"] == 1


def jobs(output):
    """[(rule, {field: text})] of a dry run's job listing (`input:`, `output:`, `wildcards:`, ...)."""
    found = []
    for block in output.split("\n\n"):
        match = re.search(r"^(?:local)?rule (\w+):$", block, re.MULTILINE)
        if match:
            fields = dict(re.findall(r"^    (\w+): (.*)$", block, re.MULTILINE))
            found.append((match.group(1), fields))
    return found


def files(text):
    """The paths of a job's `input:` or `output:` field (comma-separated, as Snakemake prints them)."""
    return [path.strip() for path in text.split(",") if path.strip()]


def run_folders(paths):
    """The run folders (results/runs/<point>-<digest>) of some paths."""
    return {str(PurePosixPath(path).parent) for path in paths if path.startswith("results/runs/")}


def test_all_builds_every_sweep_the_report_and_the_paper(study_config):
    # In the checkout: the paper is built from paper/ (not copied under --directory).
    result, counts = dry(REPO, "all", "--forceall")
    listed = jobs(result.stdout)
    # Each run is simulated once, whatever the number of sweeps that declare it (same configuration,
    # same folder), and every sweep `all` reaches tabulates each of its points.
    simulated = [run_folders(files(fields["output"])) for rule, fields in listed if rule == "simulate"]
    assert all(len(folder) == 1 for folder in simulated)
    simulated = set().union(*simulated)
    assert len(simulated) == counts["simulate"] == counts["measure"]
    tables = {files(fields["output"])[0].split("/")[1]: run_folders(files(fields["input"]))
              for rule, fields in listed if rule == "aggregate"}
    sweeps = {sweep: folders for sweep, folders in tables.items() if sweep != "study"}
    assert {sweep: len(folders) for sweep, folders in sweeps.items()} == {
        sweep: len(sweep_points(study_config, sweep, REPO)) for sweep in sweeps}
    assert set().union(*sweeps.values()) == simulated
    # The shared runs (issue 25): table1_ci's cells are table1's and seed 1 of table1_ensemble, the
    # H/128 cells seed 1 of table1_h128_ensemble, the paper's case is in most one-parameter sweeps.
    assert sum(map(len, sweeps.values())) - len(simulated) >= 2 * 38
    # It reaches the study, the paper's method variants and the ensembles of its envelope.
    paper = study_config["paper"]
    envelope = paper.get("envelope", {})
    expected = {*study_config["study"], *paper["variants"].values(),
                *(value for key, value in envelope.items() if "ensemble" in key and isinstance(value, str))}
    assert expected <= set(sweeps)
    assert counts["aggregate"] == len(sweeps) + 1  # and the study's table
    assert counts["paper_figure"] == len(paper["figures"]) and counts["paper"] == 1 and counts["report"] == 1
    assert counts["paper_table"] == len(paper["tables"])
    # What the energy residual is: three small runs with the HHT dissipation booked, one generator.
    assert counts["energy_evidence_run"] == 3 and counts["energy_evidence"] == 1 and counts["paper_energy_evidence"] == 1
    # The verdict on each claim and the Conclusions, from sweeps the paper builds anyway (no extra run).
    assert counts["paper_claims"] == 1
    # How sure is Table 1: the seeds of the ensemble sweep, the method envelope, the section's inputs.
    # The ensemble at H/64 and the finer one (its summary only: paper.envelope.finer_ensemble).
    assert counts["ensemble_table"] == 2 and counts["fig_phase_diagram_ensemble"] == 1
    assert counts["envelope"] == 1 and counts["fig_envelope"] == 1 and counts["paper_how_sure"] == 1
    # Its limits: mesh limit, backward pulses against dt, Fig. 3 timeline, pulse counts across seeds.
    for rule in ("mesh_limit", "timestep_limit", "timeline", "pulse_seeds", "fig_mesh_limit", "fig_timestep_backward",
                 "fig_backward_celerity", "paper_how_sure_limits"):
        assert counts[rule] == 1, rule
    assert counts["fig_spacetime"] == 4 + 2 + 3 + 3 + 2 + 4 * 3 and counts["fig_convergence"] == 3 + 1 + 4


def test_a_point_of_several_sweeps_runs_once(workdir):
    """table1_ci's 38 runs are table1's published cells and seed 1 of table1_ensemble (issue 25)."""
    _, counts = dry(workdir, "table1", "table1_ensemble", "table1_ci")
    assert counts["simulate"] == counts["measure"] == 98 + 8 * 38 - 38
    _, counts = dry(workdir, "table1_h128", "table1_h128_ensemble")
    assert counts["simulate"] == 3 * 38
    # A sweep that changes the run (its length) has runs of its own at the same point.
    _, counts = dry(workdir, "long", "shear_rate")
    assert counts["simulate"] == 1 + 5


def test_one_target_per_sweep(workdir):
    _, counts = dry(workdir, "period", "mesh")  # 3 + 3 points, the paper's case (lambda 2H, H/64) in both
    assert counts["simulate"] == 5 and counts["fig_pulse_spacing"] == 1 and counts["fig_convergence"] == 1
    _, counts = dry(workdir, "phase_diagram")
    assert counts["simulate"] == 98 and counts["fig_phase_diagram"] == 1 and counts["flutter"] == 1


def test_figures_never_depend_on_solver(workdir):
    """Restyling a figure reruns the figure only: figure rules take run.h5 / tables, not the solver."""
    result, _ = dry(workdir, "figures", "--forceall")
    listed = jobs(result.stdout)
    figures = [inputs(fields) for rule, fields in listed if rule.startswith("fig_")]
    assert len(figures) > 20
    solver = DRY_ENV["SLIDEWAVE_BIN"]
    for files in figures:
        assert solver not in files and not any(f.endswith("config.json") for f in files)
    # The check can fail: each simulation lists the solver and its config among its inputs.
    simulations = [inputs(fields) for rule, fields in listed if rule == "simulate"]
    assert simulations and all(solver in files for files in simulations)


def inputs(fields):
    """The input files of a job of a dry run's listing."""
    return files(fields.get("input", ""))


def write_ratchet(directory, resolution, minimum=0):
    path = directory / "ratchet.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"min_cells_within_5pct": minimum, "resolution": resolution}))
    return path


def test_reference_check_reads_the_ratchet(workdir, tmp_path):
    ratchet = write_ratchet(tmp_path, 64, minimum=7)
    result, counts = dry(workdir, "reference_check", "-p", "--config", f"reference={{ratchet: {ratchet}}}")
    assert counts["simulate"] == 38 and counts["reference_check"] == 1
    assert "--min-within 7" in result.stdout


def test_ratchet_for_another_resolution_is_refused(workdir, tmp_path):
    ratchet = write_ratchet(tmp_path, 32)
    result = snakemake(workdir, "-n", "--nolock", "reference_check", "--config", f"reference={{ratchet: {ratchet}}}",
                       env=DRY_ENV, check=False)
    assert result.returncode != 0 and "H/32" in result.stdout + result.stderr


def test_a_new_point_runs_alone(workdir, tmp_path, study_config):
    """`--configfile` extends the study; the DAG of the extended ci sweep has one more run."""
    extra = tmp_path / "extra.yaml"
    points = study_config["sweeps"]["ci"]["points"] + [{"nu": 0.3, "f": 1.25}]
    extra.write_text(yaml.safe_dump({"sweeps": {"ci": {"points": points}}}))
    result, counts = dry(workdir, "ci", "--configfile", str(REPO / "study" / "config.yaml"), str(extra))
    assert counts["simulate"] == 3
    assert "nu0.30_f1.25_v1e-05_L2_n16_rho1000_reduced" in result.stdout


def test_command_line_points_are_typed(workdir):
    result, counts = dry(workdir, "mine", "--config", "sweeps={mine: {fixed: {elements_per_H: 32}, "
                                                      "points: [{nu: 0.3, f: 1.25}, {nu: 0.1, f: 1e-1}]}}")
    assert counts["simulate"] == 2
    assert "nu0.10_f0.10_v1e-05_L2_n32_rho1000_reduced" in result.stdout


def test_bad_config_stops_before_any_job(workdir):
    result = snakemake(workdir, "-n", "--nolock", "ci", "--config", "sweeps={ci: {points: [{nu: 0.7}]}}",
                       env=DRY_ENV, check=False)
    assert result.returncode != 0 and "0.7" in result.stdout + result.stderr


