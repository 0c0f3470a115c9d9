#!/usr/bin/env bash
# README command 1: set up, build, and run the default study (the `quick` sweep: four H/32 points
# across the regimes, then its table, figures and report in results/quick/).
# One line per stage; each stage's full output goes to logs/study/<stage>.log. On failure the tail of
# that log is printed with its path. Ends with what the study holds and where its report is.
set -euo pipefail
cd "$(dirname "$0")/.."
LOGS=logs/study
SWEEP=quick
mkdir -p "$LOGS"
started=$(date +%s)

fail() {  # stage, log, exit code
  echo "FAILED (exit $3)"
  echo "---- last 40 lines of $2:"
  tail -n 40 "$2"
  echo "---- full log: $2"
  exit "$3"
}

stage() {  # name, log, command...: run quietly, print one line
  local name=$1 log=$2 t0 rc=0
  shift 2
  t0=$(date +%s)
  printf '%-7s ' "$name"
  "$@" > "$log" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || fail "$name" "$log" "$rc"
  echo "done in $(( $(date +%s) - t0 )) s (log $log)"
}

stage setup "$LOGS/setup.log" bash scripts/setup.sh
stage build "$LOGS/build.log" bash scripts/build.sh
export USER=${USER:-$(id -un)}

# Snakemake's job listing goes to the log; on a terminal its progress ("12 of 28 steps") is shown on
# one line while it runs.
log="$LOGS/snakemake.log"
printf '%-7s ' study
t0=$(date +%s)
snakemake -c"$(nproc)" "$SWEEP" > "$log" 2>&1 &
pid=$!
if [ -t 1 ]; then
  while kill -0 "$pid" 2> /dev/null; do
    progress=$(grep -o '[0-9]* of [0-9]* steps ([0-9]*%) done' "$log" | tail -n 1 || true)
    printf '\r%-7s %s' study "${progress:-planning}"
    sleep 2
  done
  printf '\r%-7s ' study
fi
rc=0
wait "$pid" || rc=$?
[ "$rc" -eq 0 ] || fail study "$log" "$rc"
jobs=$(grep -o '[0-9]* of [0-9]* steps (100%) done' "$log" | tail -n 1 | cut -d' ' -f1 || true)
if [ -n "$jobs" ]; then what="$jobs jobs"; else what="nothing to do, all up to date"; fi
echo "done in $(( $(date +%s) - t0 )) s: $what (log $log)          "

echo
"${SLIDEWAVE_PYTHON:-/usr/bin/python3}" study/scripts/study_summary.py --sweep "$SWEEP" --snakemake-log "$log" || exit $?
echo "time:    $(( $(date +%s) - started )) s in all"
