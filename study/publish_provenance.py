"""study/results/provenance.json: where the committed tables and the report come from.

    python3 -m study.publish_provenance --root study/results --solver build/slidewave \
        --report paper/reproduction.pdf -o study/results/provenance.json

Records the commit the publication was made from (and whether the tree had uncommitted changes), the
solver's version line, the date, and the SHA-256 of every file under --root (provenance.json itself
aside) and of the report, so that a reader can tell which tables a PDF was built from. Each run's own
provenance (slidewave_version, git_commit, analysis_version) is a column of all_metrics.csv.
"""

from __future__ import annotations

import argparse
import datetime
import hashlib
import json
import subprocess
import sys
from pathlib import Path

from analysis.core.atomic import write_file


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def git(*args: str, cwd: Path) -> str:
    """Output of a git command in the checkout, or 'unknown' outside one."""
    try:
        return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def provenance(root: Path, solver: str, report: Path, output: Path) -> dict:
    checkout = Path(__file__).resolve().parent.parent
    version = subprocess.run([solver, "--version"], capture_output=True, text=True, check=True).stdout.strip()
    files = {str(path.relative_to(root)): sha256(path) for path in sorted(root.rglob("*"))
             if path.is_file() and path.resolve() != output.resolve() and path.name != "README.md"}
    return {
        "published_at": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "git_commit": git("rev-parse", "HEAD", cwd=checkout),
        # The code's changes; the tables and the report being published are changes by design.
        "uncommitted_changes": git("status", "--porcelain", "--", "solver", "analysis", "study", "paper", "figures",
                                   "Snakefile", ":(exclude)study/results", ":(exclude)paper/reproduction.pdf",
                                   cwd=checkout) not in ("", "unknown"),
        "solver_version": version,
        "command": "snakemake publish_results",
        "report": {"path": str(report), "sha256": sha256(report)},
        "files": files,
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, required=True, help="the committed results folder (study/results)")
    parser.add_argument("--solver", required=True, help="the slidewave binary the runs were made with")
    parser.add_argument("--report", type=Path, required=True, help="the report PDF")
    parser.add_argument("-o", "--output", type=Path, required=True, help="provenance.json to write")
    args = parser.parse_args(argv)
    document = provenance(args.root, args.solver, args.report, args.output)
    write_file(args.output, json.dumps(document, indent=2) + "\n")
    print(f"{len(document['files'])} tables and the report -> {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
