#!/usr/bin/env bash
# The default sweep (scripts/sweep/Snakefile): bakes the built-in Earth at
# several table sizes, validates each and plots error against bake time into
# out/sweep/error_vs_time.png, on this machine's cores. Extra arguments go to
# snakemake, e.g.
#   bash scripts/sweep.sh --config factors=[0.5,1] queries=quick
# It builds skybake if needed but installs nothing: run scripts/setup.sh once
# first (it installs the Debian packages, snakemake among them). On a Slurm
# cluster, see scripts/sweep/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ ! -f build/CMakeCache.txt ]] || ! command -v snakemake > /dev/null; then
  echo "sweep.sh: no build/ or no snakemake: run 'bash scripts/setup.sh' first (installs and builds)" >&2
  exit 2
fi
cmake --build build --target skybake -j "$(nproc)" > /dev/null
snakemake -s scripts/sweep/Snakefile --cores "$(nproc)" "$@"
echo "sweep: sweep.csv and error_vs_time.png in out/sweep/ (or the --config out=DIR given)"
