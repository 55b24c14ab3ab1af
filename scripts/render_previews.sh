#!/usr/bin/env bash
# Renders the README's preview images of the built-in Earth into
# docs/images/: a camera on the ground looking toward the sun (90 deg field
# of view) at five sun angles, and a lat-long environment map.
# Usage: scripts/render_previews.sh [BAKE.exr]   (default: bakes out/earth.exr first)
set -euo pipefail
cd "$(dirname "$0")/.."
skybake=build/baker/skybake
bake=${1:-out/earth.exr}
if [ ! -f "$bake" ]; then
  mkdir -p "$(dirname "$bake")"
  "$skybake" bake -o "$bake"
fi
mkdir -p docs/images
# sun zenith (deg) and exposure: twilight needs a longer exposure, as a camera would.
for setting in 0:10 60:10 85:10 90:30 95:300; do
  zenith=${setting%%:*}
  exposure=${setting##*:}
  "$skybake" render "$bake" --altitude-m 0 --sun-zenith-deg "$zenith" --projection perspective \
    --fov-deg 90 --view-elevation-deg 20 --size 320x200 --exposure "$exposure" \
    -o "docs/images/earth_sun_zenith_${zenith}.png"
done
"$skybake" render "$bake" --altitude-m 0 --sun-zenith-deg 70 --projection latlong --size 512x256 --exposure 10 \
  -o docs/images/earth_latlong_sun_zenith_70.png
echo "previews written to docs/images/"
