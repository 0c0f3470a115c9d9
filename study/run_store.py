"""Where a run lives: results/runs/<point>-<digest>, named by what it computes.

The digest is the first 12 hex digits of the SHA-256 of the run's config.json (its text, exactly as
the solver reads it: study/make_run_config.py), so a point that several sweeps declare with the
same resolved configuration is one folder, computed once and read by each sweep; a point whose
configuration differs (another run length, solver keys, snapshots) is another folder. The point's
name (study/sweeps.py) comes first so that a folder says what it holds.
"""

from __future__ import annotations

import hashlib

RUNS_DIR = "results/runs"
DIGEST_LENGTH = 12
#: Snakemake wildcard constraint of a run folder's name.
RUN_ID_PATTERN = "nu[^/]+-[0-9a-f]{%d}" % DIGEST_LENGTH


def run_id(point_name: str, config_text: str) -> str:
    """`<point>-<digest of config_text>`."""
    return f"{point_name}-{hashlib.sha256(config_text.encode()).hexdigest()[:DIGEST_LENGTH]}"
