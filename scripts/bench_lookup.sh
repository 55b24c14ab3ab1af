#!/usr/bin/env bash
# Benchmark: sky-radiance lookups per second on one core (scalar and batch),
# median of N (default 5) repetitions, on the built-in Earth at default sizes.
# Usage: scripts/bench_lookup.sh [REPETITIONS] [extra benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-5}
shift || true
bash scripts/setup.sh
# Re-bake when the file is missing or from a format this build does not read.
build/baker/skybake info out/earth.exr >/dev/null 2>&1 || { mkdir -p out; build/baker/skybake bake -o out/earth.exr; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
SKYBAKE_BAKE=out/earth.exr taskset -c 0 build/scripts/benchmarks/bench_lookup \
  --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true "$@"
