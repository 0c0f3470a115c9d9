"""One project version: CMakeLists.txt's project(VERSION) is what the solver writes into run.h5,
what the Python package reports (analysis.__version__, read by pyproject.toml) and what
CITATION.cff and CHANGELOG.md name."""
import re
import tomllib
from pathlib import Path

import yaml

import analysis

ROOT = Path(__file__).resolve().parents[2]


def cmake_version():
    return re.search(r"project\(\s*slidewave\s+VERSION\s+([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


def test_the_python_package_reads_the_cmake_version():
    assert analysis.__version__ == cmake_version()
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "version" in pyproject["project"]["dynamic"]
    assert pyproject["tool"]["setuptools"]["dynamic"]["version"] == {"attr": "analysis.__version__"}


def test_citation_and_changelog_name_the_version():
    assert str(yaml.safe_load((ROOT / "CITATION.cff").read_text())["version"]) == cmake_version()
    assert f"## {cmake_version()} " in (ROOT / "CHANGELOG.md").read_text()


def test_changelog_records_the_format_versions_the_code_writes():
    from analysis.core.io import FORMAT_VERSION
    from analysis.metrics.measure import ANALYSIS_VERSION

    changelog = (ROOT / "CHANGELOG.md").read_text()
    assert f"- **{FORMAT_VERSION}**" in changelog.split("`format_version`", 2)[2]
    assert f"- **{ANALYSIS_VERSION}**" in changelog.split("### metrics.json", 1)[1]
