#!/usr/bin/env bash
# The main job: set up, build, and bake the built-in Earth into out/earth.exr.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p out
build/baker/skybake bake -o out/earth.exr
build/baker/skybake info out/earth.exr | head -n 14
