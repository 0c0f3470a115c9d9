#!/usr/bin/env bash
# The step-cost table of docs/performance.md: every case in its own process (so that peak_MB
# is that case's), one line per case, for H/32 ... H/256 at lambda = 2H and H/64 at lambda = 4H, 6H.
#   bench/step_table.sh [--solver spectral|cholmod] [--threads N] [BUILD_DIR]
# Columns: those of build/bench/slidewave_bench_step (ms per step by phase, step/slv = one step over one
# K_eff solve, the machine-independent figure; sweeps = Gauss–Seidel sweeps per step).  A timed program,
# not a test: run it on a quiet machine.
set -euo pipefail
solver=spectral
threads=1
build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --solver) solver="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
    *) build="$1"; shift ;;
  esac
done
bench="$build/bench/slidewave_bench_step"
[ -x "$bench" ] || { echo "error: $bench not found (build first: bash scripts/build.sh)" >&2; exit 2; }

echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), solver $solver, $threads thread(s)"
header_done=0
# n lambda t_end: H/256 runs a shorter stage 3 (one step costs ~8x an H/128 one).
for case in "32 2 1000" "64 2 1000" "128 2 1000" "256 2 300" "64 4 1000" "64 6 1000"; do
  read -r n lambda t_end <<< "$case"
  out=$("$bench" --n "$n" --lambda "$lambda" --t-end "$t_end" --solver "$solver" --threads "$threads")
  if [ $header_done -eq 0 ]; then
    echo "$out" | grep -E '^ +H/h'
    header_done=1
  fi
  echo "$out" | grep -E '^ +[0-9]+ +[0-9.]+ '
done
