#!/usr/bin/env bash
# Benchmark: `skybake view` as a person opening it feels it, on the
# built-in Earth at default sizes: from the page's navigation to its first
# frame (a quarter-resolution frame, then the full one) with Mesa's shader
# cache empty (the first run on a machine) and filled (every run after);
# full 1280x720 frames per second on Mesa's llvmpipe in Chromium; beside
# them `skybake render` of the same view at 1280x720 on the CPU and on
# OpenGL (whole processes). Medians of N (default 3) runs.
# Usage: scripts/bench_view.sh [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build/baker/skybake info out/earth.exr >/dev/null 2>&1 || { mkdir -p out; build/baker/skybake bake -o out/earth.exr; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
/usr/bin/python3 scripts/bench_view.py build/baker/skybake out/earth.exr "${1:-3}"
