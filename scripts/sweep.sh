#!/usr/bin/env bash
# The default sweep (scripts/sweep/Snakefile): bakes the built-in Earth at
# several table sizes, validates each and plots error against bake time into
# out/sweep/error_vs_time.png. Extra arguments go to snakemake, e.g.
#   bash scripts/sweep.sh --config factors=[0.5,1] queries=quick
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
snakemake -s scripts/sweep/Snakefile --cores "$(nproc)" "$@"
echo "sweep: out/sweep/sweep.csv, out/sweep/error_vs_time.png"
