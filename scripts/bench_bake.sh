#!/usr/bin/env bash
# Benchmark: median of N (default 3) default Earth bakes on all cores, with
# per-stage times. Usage: scripts/bench_bake.sh [REPETITIONS] [extra benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-3}
shift || true
bash scripts/setup.sh
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
build/scripts/benchmarks/bench_bake --benchmark_repetitions="$repetitions" \
  --benchmark_report_aggregates_only=true "$@"
