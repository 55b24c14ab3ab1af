#!/usr/bin/env bash
# Benchmark: sky-radiance rays per second of the GLSL library on OpenGL (a
# 1920x1080 pass, headless EGL: the GPU where there is one, else Mesa's
# llvmpipe on every core), beside the CPU's scalar and batch lookups on one
# core; median of N (default 5) repetitions, built-in Earth at default sizes.
# Usage: scripts/bench_gl_lookup.sh [REPETITIONS]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-5}
bash scripts/setup.sh
build/baker/skybake info out/earth.exr >/dev/null 2>&1 || { mkdir -p out; build/baker/skybake bake -o out/earth.exr; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
[ -x build/scripts/benchmarks/bench_gl_lookup ] || {
  echo "bench_gl_lookup was not built (no libepoxy or EGL; scripts/setup.sh installs them)" >&2
  exit 1
}
SKYBAKE_BAKE=out/earth.exr build/scripts/benchmarks/bench_gl_lookup \
  --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true
SKYBAKE_BAKE=out/earth.exr taskset -c 0 build/scripts/benchmarks/bench_lookup \
  --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true
