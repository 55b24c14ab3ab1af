#!/usr/bin/env bash
# skybake render --backend gl equals --backend cpu: the same view rendered
# both ways as spectral EXR (--channels spectral: what each backend computes;
# the sun disk and the colour conversion are the same CPU code for both, and
# linear sRGB's small components, differences of large terms, would make
# relative differences meaningless), compared per pixel and channel over values above
# 1e-5 W m^-2 sr^-1 nm^-1 (skybake_gl_image_compare): RMS relative
# difference <= 0.5 %, max <= 2 %. Why that tolerance: float against double
# arithmetic (gl_lookup_parity_test.cpp explains the budget), the GLSL
# interpolating from texelFetch with the CPU's weights. A bad --backend is
# refused with exit status 2 naming the option.
# Usage: render_parity_test.sh SKYBAKE COMPARE BAKE_DIR WORK_DIR
set -u
skybake=$1
compare=$2
bakes=$3
work=$4
mkdir -p "$work"
passed=0
failed=0
case_() {
  local name=$1 bake=$2
  shift 2
  if ! "$skybake" render "$bakes/$bake" "$@" --channels spectral -o "$work/$name.cpu.exr" 2>"$work/$name.log" ||
    ! "$skybake" render "$bakes/$bake" "$@" --channels spectral --backend gl -o "$work/$name.gl.exr" \
      2>>"$work/$name.log"; then
    echo "gl_render_parity: $name: render failed: $(cat "$work/$name.log")"
    failed=$((failed + 1))
    return
  fi
  local result
  if result=$("$compare" "$work/$name.cpu.exr" "$work/$name.gl.exr" 0.005 0.02); then
    echo "gl_render_parity: $name: $result"
    passed=$((passed + 1))
  else
    echo "gl_render_parity: $name FAILED: $result"
    failed=$((failed + 1))
  fi
}
case_ ground_sun30 gl_earth.exr --altitude-m 0 --sun-zenith-deg 30 --size 128x128
case_ ground_sun85 gl_earth.exr --altitude-m 0 --sun-zenith-deg 85 --size 128x128
case_ ground_sun95 gl_earth.exr --altitude-m 0 --sun-zenith-deg 95 --size 128x128
case_ camera_30km gl_earth.exr --altitude-m 30000 --sun-zenith-deg 60 --projection latlong --size 128x64
# From 400 km the horizon lies 19.8 deg below the horizontal.
case_ orbit_limb gl_earth.exr --altitude-m 400000 --sun-zenith-deg 70 --projection perspective --fov-deg 40 \
  --view-elevation-deg -19.8 --view-azimuth-deg 30 --size 128x96
case_ scene_narrowed gl_scene.exr --altitude-m 1000 --sun-zenith-deg 60 --projection latlong --size 128x64
# Its suns end at 80 deg: by day past them (the tables at their last sun)
# and below the horizon.
case_ scene_past_its_suns gl_scene.exr --altitude-m 1000 --sun-zenith-deg 85 --projection latlong --size 128x64
case_ scene_sun_below gl_scene.exr --altitude-m 1000 --sun-zenith-deg 100 --projection latlong --size 128x64
case_ latlong_no_sun gl_earth.exr --altitude-m 0 --sun-zenith-deg 40 --projection latlong --size 128x64 --no-sun
# Solar eclipses, small images (a ground pixel sums 48 eclipsed sky
# directions): totality from the umbra's centre on the ground, where most of
# the sky lies below the 1e-5 floor and the horizon's glow is compared; a
# partial eclipse from 10 km with the lit ground.
case_ eclipse_total gl_earth.exr --altitude-m 0 --sun-zenith-deg 50 --moon 0,40,0.28 --size 32x32
case_ eclipse_partial_latlong gl_earth.exr --altitude-m 10000 --sun-zenith-deg 50 --moon 0,40.25,0.28 \
  --projection latlong --size 32x16

"$skybake" render "$bakes/gl_earth.exr" --altitude-m 0 --sun-zenith-deg 30 --backend vulkan -o "$work/x.png" \
  2>"$work/bad.log"
status=$?
if [ "$status" -eq 2 ] && grep -q -- "--backend = vulkan" "$work/bad.log"; then
  passed=$((passed + 1))
else
  echo "gl_render_parity: --backend vulkan exited $status: $(cat "$work/bad.log")"
  failed=$((failed + 1))
fi
echo "gl_render_parity: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
