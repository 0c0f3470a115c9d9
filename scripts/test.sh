#!/usr/bin/env bash
# README command 2: set up, build, and run every test of the default run: C++ GoogleTest through CTest
# (without the `long` label), the Python tests of analysis, figures and pipeline, then the reference
# check of the regenerated Table 1 (H/32) against the published values (study/reference/ratchet.json).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${SLIDEWAVE_PYTHON:-/usr/bin/python3}
export USER=${USER:-$(id -un)}  # snakemake reads it
bash scripts/setup.sh --latex
bash scripts/build.sh
ctest --test-dir build -LE long --output-on-failure -j2
"$PYTHON" -m pytest -q tests/analysis tests/figures tests/pipeline
snakemake -c"$(nproc)" reference_check
cat results/table1_ci/reference_check.txt | tail -1
