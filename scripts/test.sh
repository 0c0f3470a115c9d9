#!/usr/bin/env bash
# README command 2: set up, build, and run every test of the default run (C++ GoogleTest through
# CTest without the `long` label, then the Python tests of analysis, figures and pipeline).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${SLIDEWAVE_PYTHON:-/usr/bin/python3}
bash scripts/setup.sh --latex
bash scripts/build.sh
ctest --test-dir build -LE long --output-on-failure -j2
"$PYTHON" -m pytest -q tests/analysis tests/figures tests/pipeline
