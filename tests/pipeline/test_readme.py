"""The README's promises that a test can hold it to: its first lines are the two commands, and every
number it states about the results is the committed file's (study/results/table1/summary.json)."""
import json
import re
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
README = (REPO / "README.md").read_text()
SUMMARY = json.loads((REPO / "study" / "results" / "table1" / "summary.json").read_text())
HEADLINE = re.compile(r"of (\d+) published cells, (\d+) have a\s+measured front and (\d+) are reproduced "
                      r"\(within (\d+) %.*?median \|deviation\| ([\d.]+) %", re.S)


def section(title):
    """The text of a `## title` section, up to the next one."""
    start = README.index(f"## {title}\n")
    end = README.find("\n## ", start + 1)
    return README[start:end if end > 0 else None]


def test_the_readme_opens_with_the_two_commands():
    assert README.splitlines()[:6] == [
        "# slidewave", "", "```bash",
        "bash scripts/study.sh     # installs what is missing (Debian packages), builds, runs the default study",
        "bash scripts/test.sh      # installs what is missing, builds, runs every test (what CI runs)", "```"]


def test_the_quoted_table1_counts_are_the_committed_ones():
    found = HEADLINE.search(section("How sure is the table"))
    assert found, "the README's Table-1 sentence changed: keep it parseable here or drop its numbers"
    total, measured, reproduced, tolerance, median = found.groups()
    assert int(total) == SUMMARY["cells_total"]
    assert int(measured) == SUMMARY["cells_compared"]
    assert int(reproduced) == SUMMARY["reproduced"]
    assert int(tolerance) == round(100 * SUMMARY["tolerance"])
    assert median == f"{100 * SUMMARY['median_abs_deviation']:.1f}"


def test_no_other_number_about_the_results():
    """Outside code spans, mesh labels (H/64) and the name Table 1, the section states only the numbers
    checked above."""
    text = re.sub(r"`[^`]*`|H/\d+|Table[ -]1", "", section("How sure is the table"))
    numbers = re.findall(r"\d+(?:\.\d+)?", text)
    found = HEADLINE.search(text)
    assert sorted(numbers) == sorted(found.groups())
