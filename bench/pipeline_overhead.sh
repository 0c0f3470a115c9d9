#!/usr/bin/env bash
# Pipeline overhead per run (issue 25, item 6): what Snakemake and Python cost beside the solver.
# A 16-point H/64 sweep without figures (nu 0-0.3 x f 1.2-2, given with --config) is run from scratch
# by `snakemake -cCORES SWEEP` of CHECKOUT's Snakefile in a scratch folder; every solver call goes
# through /usr/bin/time, so that
#
#     overhead per run = (wall - solver CPU time / CORES) / runs
#
# is what the pipeline adds per run (scheduling, configuring, measuring, aggregating, Python start-up).
# That wall-time figure moves with the machine's load (printed); the CPU time the pipeline spends
# beside the solver (user + system of Snakemake and every process it started, less the solver's),
# per run, moves much less: both are printed. A timed script, not a test: compare checkouts side by
# side on the same machine, alternated with --repeats.
#   bench/pipeline_overhead.sh [--cores N] [--repeats N] [--solver BIN] [CHECKOUT ...]
# CHECKOUT defaults to this repository; e.g. the state before a change:
#   git archive main | tar -x -C /tmp/before && bench/pipeline_overhead.sh /tmp/before .
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cores=2 repeats=1 solver=${SLIDEWAVE_BIN:-$here/build/slidewave}
checkouts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cores) cores="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --solver) solver="$2"; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) checkouts+=("$(cd "$1" && pwd)"); shift ;;
  esac
done
[ ${#checkouts[@]} -gt 0 ] || checkouts=("$here")
[ -x "$solver" ] || { echo "error: solver $solver not found (bash scripts/build.sh, or --solver BIN)" >&2; exit 2; }
solver=$(cd "$(dirname "$solver")" && pwd)/$(basename "$solver")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sweep=bench16
points="sweeps={$sweep: {fixed: {elements_per_H: 64}, grid: {nu: [0.0, 0.1, 0.2, 0.3], f: [1.2, 1.5, 1.8, 2.0]}}}"
runs=16

# The solver seen by the pipeline: the real one under /usr/bin/time, appending "user sys" per call.
cat > "$work/timed_solver" <<EOF
#!/bin/sh
exec /usr/bin/time -a -o "$work/solver_times" -f "%U %S" "$solver" "\$@"
EOF
chmod +x "$work/timed_solver"

echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores (-c$cores), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
printf "%-32s %5s %8s %12s %14s %14s %6s\n" checkout runs wall_s solver_cpu_s overhead_s/run pipeline_cpu/run load
for ((r = 0; r < repeats; r++)); do
  for checkout in "${checkouts[@]}"; do
    rm -rf "$work/results" "$work/solver_times"
    mkdir -p "$work/results"
    load=$(cut -d' ' -f1 /proc/loadavg)
    t0=$(date +%s.%N)
    SLIDEWAVE_BIN="$work/timed_solver" /usr/bin/time -o "$work/snakemake_time" -f "%U %S" snakemake -s "$checkout/Snakefile" --directory "$work/results" -c"$cores" \
      "$sweep" --config "$points" > "$work/snakemake.log" 2>&1 || { tail -n 30 "$work/snakemake.log"; exit 1; }
    t1=$(date +%s.%N)
    calls=$(wc -l < "$work/solver_times")
    [ "$calls" -eq "$runs" ] || { echo "error: $calls solver calls, expected $runs" >&2; exit 1; }
    all_cpu=$(awk '{print $1 + $2}' "$work/snakemake_time")
    awk -v t0="$t0" -v t1="$t1" -v n="$runs" -v c="$cores" -v name="$checkout" -v load="$load" -v all="$all_cpu" \
      '{cpu += $1 + $2} END {wall = t1 - t0; printf "%-32s %5d %8.2f %12.2f %14.3f %14.3f %6s\n",
        name, n, wall, cpu, (wall - cpu / c) / n, (all - cpu) / n, load}' "$work/solver_times"
  done
done
