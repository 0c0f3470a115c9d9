#!/usr/bin/env bash
# The reproduction report built from the committed tables of study/results alone, without any run:
# the same numbers, tables and verdicts as the committed paper/reproduction.pdf; the figures drawn
# from the runs are framed notes (`snakemake -c2 all` draws them). Nothing of the checkout changes.
#   bash scripts/report_from_committed.sh [FOLDER]     (default: results/from_committed)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
folder="$(realpath -m "${1:-$repo/results/from_committed}")"
export USER=${USER:-$(id -un)}  # snakemake reads it
mkdir -p "$folder"
snakemake -c1 -q -s "$repo/Snakefile" --directory "$folder" --config from_committed=true -- paper
echo "report from the committed tables: $folder/paper/reproduction.pdf"
