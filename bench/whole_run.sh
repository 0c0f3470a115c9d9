#!/usr/bin/env bash
# Whole `slidewave run`s as users and the pipeline pay them (setup, the steps, output):
# the paper's case nu = 0.2, f = 1.5, t_end = 1000 s (slip onset ~750 s, opening pulses after), default
# config, at H/64, H/128, H/256 (lambda = 2H) and H/64 at lambda = 6H. Best of REPEATS wall times, with the
# user time, peak memory and minor page faults of that run; with --before BIN also the same runs of another
# binary, alternated run by run so that both see the same load. The first line names the CPU and its widest
# vector flags; on an AVX-512 machine, a build configured with -DSLIDEWAVE_NO_AVX512=ON runs the kernels an
# AVX2-only machine runs. A timed script, not a test: run it on a quiet machine.
#   bench/whole_run.sh [--before BIN] [--repeats N] [BUILD_DIR]
set -euo pipefail
build=build
before=""
repeats=3
while [ $# -gt 0 ]; do
  case "$1" in
    --before) before="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) build="$1"; shift ;;
  esac
done
after="$build/slidewave"
[ -x "$after" ] || { echo "error: $after not found (build first: bash scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One timed run: prints "wall user peak_MB faults" (wall to the millisecond: GNU time's %e has 10 ms steps, a tenth
# of an H/64 run; user time, peak memory and minor page faults from GNU time).
timed() {
  local start end
  start=$(date +%s%N)
  /usr/bin/time -f "%U %M %R" -o "$work/time" "$1" run "$2" -o "$work/run.h5" > /dev/null 2>&1
  end=$(date +%s%N)
  awk -v ns=$((end - start)) '{printf "%.3f %s %.0f %s\n", ns / 1e9, $1, $2 / 1024, $3}' "$work/time"
}
# Best (smallest wall) of the given "wall user MB faults" lines.
best() { sort -n | head -1; }

flags=$(grep -m1 -o -w -E 'avx512f|avx2' /proc/cpuinfo | sort -u | tr '\n' ' ')
echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), widest vector ISA flags: ${flags:-none}, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-16s %10s %10s %8s %7s" case wall_s user_s peak_MB faults
[ -n "$before" ] && printf " | %10s %10s %8s %7s | %8s" before_wall before_user before_MB faults speedup
echo
for case in "64 2" "128 2" "256 2" "64 6"; do
  read -r n lambda <<< "$case"
  printf '{"material": {"nu": 0.2}, "friction": {"f": 1.5}, "mesh": {"elements_per_H": %d}, "geometry": {"lambda_over_H": %s}, "time": {"t_end": 1000}, "output": {"progress": "never"}}\n' \
    "$n" "$lambda" > "$work/config.json"
  : > "$work/after"; : > "$work/before"
  for _ in $(seq "$repeats"); do
    timed "$after" "$work/config.json" >> "$work/after"
    [ -n "$before" ] && timed "$before" "$work/config.json" >> "$work/before"
  done
  read -r wall user mb faults <<< "$(best < "$work/after")"
  printf "%-16s %10s %10s %8s %7s" "H/$n lambda ${lambda}H" "$wall" "$user" "$mb" "$faults"
  if [ -n "$before" ]; then
    read -r b_wall b_user b_mb b_faults <<< "$(best < "$work/before")"
    speedup=$(awk -v b="$b_wall" -v a="$wall" 'BEGIN { print b / a }')
    printf " | %10s %10s %8s %7s | %7.1fx" "$b_wall" "$b_user" "$b_mb" "$b_faults" "$speedup"
  fi
  echo
done
