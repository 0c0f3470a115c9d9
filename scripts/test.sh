#!/usr/bin/env bash
# README command 2: set up, build, and run every test of the default run: C++ GoogleTest through CTest
# (without the `long` label), again in the sanitizer build with one short run, the Python tests of
# analysis, figures, pipeline, faults and the golden regression (tests/golden), the pipeline wiring tests
# again from a copy in a folder named `slidewave` (tests must not depend on where the checkout lives:
# `git clone` names it so), then the reference check of the regenerated Table 1 (H/64) against the
# published values (study/reference/ratchet.json).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${SLIDEWAVE_PYTHON:-/usr/bin/python3}
export USER=${USER:-$(id -un)}  # snakemake reads it
bash scripts/setup.sh --latex --test
bash scripts/build.sh
ctest --test-dir build -LE long --output-on-failure -j2
# The same tests and one short run (H/16, 300 s) in a Debug build with AddressSanitizer and
# UndefinedBehaviorSanitizer: asserts on, any finding aborts. Without the H/128 smoke runs: the H/16 to
# H/64 ones take the same code paths, and under the sanitizers these two would take minutes each.
bash scripts/build.sh --sanitize
ctest --test-dir build-sanitize -LE long -E 'H128$' --output-on-failure -j2
sanitized="$(mktemp -d)"
echo '{"mesh": {"elements_per_H": 16}, "time": {"t_end": 300}, "output": {"progress": "never"}}' > "$sanitized/config.json"
build-sanitize/slidewave run "$sanitized/config.json" -o "$sanitized/run.h5"
rm -rf "$sanitized"
"$PYTHON" -m pytest -q tests/analysis tests/figures tests/pipeline tests/faults tests/config tests/paraview tests/golden
copy="$(mktemp -d)/slidewave"
mkdir "$copy"
git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$copy"
(repo="$PWD" && cd "$copy" && SLIDEWAVE_BIN="${SLIDEWAVE_BIN:-$repo/build/slidewave}" "$PYTHON" -m pytest -q -p no:cacheprovider tests/pipeline/test_wiring.py)
rm -rf "$(dirname "$copy")"
snakemake -c"$(nproc)" reference_check
cat results/table1_ci/reference_check.txt | tail -1
