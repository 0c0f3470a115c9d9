#!/usr/bin/env bash
# Configures and builds slidewave: Release into build/, or with --sanitize a Debug build with
# AddressSanitizer and UndefinedBehaviorSanitizer (no benchmarks) into build-sanitize/.
# Usage: scripts/build.sh [--sanitize] [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build options=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build=build-sanitize options=(-DCMAKE_BUILD_TYPE=Debug -DSLIDEWAVE_SANITIZE=ON -DSLIDEWAVE_BENCH=OFF)
fi
mkdir -p "$build"
cmake -S . -B "$build" "${options[@]}" "$@" > "$build/cmake.log" 2>&1 || { cat "$build/cmake.log"; exit 1; }
cmake --build "$build" -j"$(nproc)"
