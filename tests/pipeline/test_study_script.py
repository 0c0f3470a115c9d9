"""README command 1 (scripts/study.sh) prints one screen: a line per stage, then what the study holds
and where its report is; a failing stage shows the tail of its log and the log's path. Run in a copy
of the script's layout with stand-ins for setup, build and Snakemake (no packages, no runs)."""
import os
import shutil
import stat
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SCREEN_LINES = 24

TABLE1 = """nu,f,celerity,published,category,reproduced
0.2,1.5,0.85,0.882,intersonic_opening_inversion,true
0.45,1,-2.68,-2.523,supersonic_backward_opening,false
0.3,1.5,,0.774,,
"""

FAKE_SNAKEMAKE = """#!/bin/sh
# Stands in for Snakemake: a long job listing, then the quick sweep's files.
i=0
while [ $i -lt 300 ]; do echo "rule measure: input: a very long list of files $i"; i=$((i+1)); done
for p in a b; do echo "rule simulate:"; done
mkdir -p results/quick/table
printf 'metrics_file\nresults/runs/a/metrics.json\nresults/runs/b/metrics.json\n' > results/quick/table/all_metrics.csv
cat "$FAKE_TABLE1" > results/quick/table/table1.csv
echo '{"tolerance": 0.05}' > results/quick/table/summary.json
echo '<html></html>' > results/quick/report.html
echo "28 of 28 steps (100%) done"
[ -z "$FAIL" ] || { echo "Error in rule fig_spacetime: exit 1" >&2; exit 1; }
"""


def layout(tmp_path):
    """A checkout-shaped folder with the real study.sh and study_summary.py, stand-in stages."""
    root = tmp_path / "repo"
    (root / "scripts").mkdir(parents=True)
    (root / "study" / "scripts").mkdir(parents=True)
    shutil.copy(REPO / "scripts" / "study.sh", root / "scripts" / "study.sh")
    shutil.copy(REPO / "study" / "scripts" / "study_summary.py", root / "study" / "scripts" / "study_summary.py")
    for name in ("setup", "build"):
        (root / "scripts" / f"{name}.sh").write_text(
            f"for i in $(seq 200); do echo '{name}: a line of apt or compiler output'; done\n")
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake = bin_dir / "snakemake"
    fake.write_text(FAKE_SNAKEMAKE)
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    (tmp_path / "table1.csv").write_text(TABLE1)
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", FAKE_TABLE1=str(tmp_path / "table1.csv"))
    return root, env


def test_one_screen_ending_with_the_summary_and_the_report(tmp_path):
    root, env = layout(tmp_path)
    result = subprocess.run(["bash", "scripts/study.sh"], cwd=root, env=env, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) <= SCREEN_LINES, result.stdout
    assert [line.split()[0] for line in lines[:3]] == ["setup", "build", "study"]
    assert "28 jobs" in lines[2] and "logs/study/snakemake.log" in lines[2]
    text = result.stdout
    assert "runs:    2 in results/runs/ (listed in results/quick/table/all_metrics.csv) (all made now)" in text
    assert "Table 1: 2 published cells run, 2 with a measured celerity, 1 reproduced (within 5%" in text
    assert f"report:  {root / 'results' / 'quick' / 'report.html'}" in text
    assert lines[-1].startswith("time:")
    assert "a line of apt" in (root / "logs" / "study" / "setup.log").read_text()  # kept, not shown


def test_a_failing_stage_shows_the_tail_of_its_log(tmp_path):
    root, env = layout(tmp_path)
    result = subprocess.run(["bash", "scripts/study.sh"], cwd=root, env=dict(env, FAIL="1"),
                            capture_output=True, text=True)
    assert result.returncode == 1
    assert "study   FAILED (exit 1)" in result.stdout
    assert "Error in rule fig_spacetime" in result.stdout and "full log: logs/study/snakemake.log" in result.stdout
    assert "report:" not in result.stdout
    assert len(result.stdout.splitlines()) <= 3 + 40 + 2  # stage lines, the 40-line tail, its frame
