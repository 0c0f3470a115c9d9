"""The pipeline works from a checkout whose path has a space (issue 21 item 3): every path a rule puts
into a command is shell-quoted. A copy of the tracked files in `.../my dir/slidewave`, results in
`.../my dir/work`: a dry run of the CI sweep, then one real measure and space-time figure of a
synthetic run (no solver run)."""

import re
import shutil
import subprocess

from .conftest import REPO, job_counts, snakemake

from synthetic_run import paper_case, write_run


def copy_checkout(target):
    """The tracked (and untracked, not ignored) files of the repository, as scripts/test.sh copies them."""
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=REPO,
                            check=True, capture_output=True).stdout.decode().split("\0")
    for name in filter(None, listed):
        source = REPO / name
        if source.is_file():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / name)


def test_the_pipeline_runs_from_a_checkout_path_with_a_space(tmp_path, study_config):
    checkout, work = tmp_path / "my dir" / "slidewave", tmp_path / "my dir" / "work"
    copy_checkout(checkout)
    work.mkdir()

    def run(*args):
        return snakemake(work, *args, snakefile=checkout / "Snakefile", env={"SLIDEWAVE_BIN": "/bin/false"},
                         timeout=600)

    planned = run("-n", "ci").stdout
    counts = job_counts(planned)
    assert counts["simulate"] == 2 and counts["fig_spacetime"] == 1

    from study.sweeps import sweep_points
    (name,) = [n for n, p in sweep_points(study_config, "ci", REPO).items() if p["f"] == 1.5]
    (folder,) = set(re.findall(rf"results/runs/{re.escape(name)}-[0-9a-f]+", planned))  # study/run_store.py
    run_file = work / folder / "run.h5"
    run_file.parent.mkdir(parents=True)
    write_run(run_file, paper_case())
    figure = work / "results" / "ci" / "figures" / f"spacetime_state_{name}.png"
    run("-c1", str(figure.relative_to(work)), "--allowed-rules", "measure", "fig_spacetime")
    assert figure.stat().st_size > 0 and (run_file.parent / "metrics.json").is_file()
