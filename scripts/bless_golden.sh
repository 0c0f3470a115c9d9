#!/usr/bin/env bash
# Re-blesses the golden regression (tests/golden/README.md) from the current build: reruns every config
# of tests/golden/configs (or the NAMEs given) with build/slidewave ($SLIDEWAVE_BIN), rewrites
# tests/golden/digests.json and prints which configs and datasets moved. Build first
# (scripts/build.sh); a solver source newer than the binary stops it. A commit that re-blesses says
# why the results moved. Usage: scripts/bless_golden.sh [NAME ...]
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${SLIDEWAVE_PYTHON:-/usr/bin/python3}
binary=${SLIDEWAVE_BIN:-build/slidewave}
[ -x "$binary" ] || { echo "bless_golden: $binary not built (bash scripts/build.sh)" >&2; exit 1; }
newer=$(find solver CMakeLists.txt -newer "$binary" -type f | head -3)
if [ -z "${SLIDEWAVE_BIN:-}" ] && [ -n "$newer" ]; then
  echo "bless_golden: $binary is older than $(echo $newer | tr ' ' ',')...: run bash scripts/build.sh first" >&2
  exit 1
fi
"$PYTHON" tests/golden/golden.py bless "$@"
git --no-pager diff --stat -- tests/golden/digests.json
