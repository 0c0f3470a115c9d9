#!/usr/bin/env bash
# README command 1: set up, build, and run the default study (the `quick` sweep: a few H/32 points
# covering every category, then its table and figures). Results in results/, figures in results/figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
export USER=${USER:-$(id -un)}
snakemake -c"$(nproc)" quick
