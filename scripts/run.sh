#!/usr/bin/env bash
# The main job: set up, build, bake the built-in Earth into out/earth.exr and
# render a preview of its sky (out/earth_preview.png: camera on the ground
# looking toward a sun 80 degrees from the zenith).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tool
mkdir -p out
build/baker/skybake bake -o out/earth.exr
build/baker/skybake render out/earth.exr --altitude-m 0 --sun-zenith-deg 80 --projection perspective \
  --view-elevation-deg 20 -o out/earth_preview.png
build/baker/skybake info out/earth.exr | head -n 14
echo "preview: out/earth_preview.png"
