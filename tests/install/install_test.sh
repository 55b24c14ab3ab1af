#!/usr/bin/env bash
# Installs the build into a temporary prefix and builds two programs against
# it as a renderer would, one with find_package(skybake), one with
# pkg-config, and a third that adds the source tree with add_subdirectory.
# Each prints the zenith sky radiance of BAKE; all must print exactly what
# the installed `skybake lookup radiance` prints for the query.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR BAKE
set -euo pipefail
source_dir=$1
build_dir=$2
bake=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# Consumers that printed what skybake lookup printed.
agreed=0
agree() { agreed=$((agreed + 1)); }

prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >"$work/install.log" || {
  cat "$work/install.log"
  exit 1
}
# Everything the package puts under include/ sits under include/skybake/.
others=$(find "$prefix/include" -mindepth 1 -maxdepth 1 ! -name skybake)
[ -z "$others" ] || fail "headers outside include/skybake: $others"
for f in bin/skybake lib/cmake/skybake/skybakeConfig.cmake lib/cmake/skybake/skybakeConfigVersion.cmake \
  lib/pkgconfig/skybake.pc include/skybake/runtime/sky.h share/doc/skybake/data_formats/CONFIG.md \
  share/doc/skybake/docs/QUERIES.md share/doc/skybake/data_formats/presets/earth.toml; do
  [ -e "$prefix/$f" ] || fail "the install lacks $f"
done
# Every document the command names is installed where its --help says.
"$prefix/bin/skybake" --help | grep -q "$prefix/share/doc/skybake" ||
  fail "skybake --help does not name the installed documents' folder $prefix/share/doc/skybake"
for doc in $( (for c in bake info lookup render validate compare stress reference; do "$prefix/bin/skybake" "$c" --help; done) |
  grep -oE '(docs|data_formats)/[A-Z_]+\.md' | sort -u); do
  [ -e "$prefix/share/doc/skybake/$doc" ] || fail "skybake --help names $doc, which the install lacks"
done

altitude_m=1000
sun_zenith_deg=30
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n%s,%s,0,0\n' "$altitude_m" "$sun_zenith_deg" \
  >"$work/query.csv"
# The radiance_<nm> columns, one per channel in the bake's order.
"$prefix/bin/skybake" lookup radiance "$bake" --queries "$work/query.csv" >"$work/lookup.csv"
expected=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^radiance_/) keep[i] = 1 }
  NR == 2 { out = ""; for (i = 1; i <= NF; ++i) if (i in keep) out = out (out == "" ? "" : ",") $i; print out }' \
  "$work/lookup.csv")
echo "skybake lookup radiance: $expected"
# The installed command finds its image encoder module (lib/skybake).
"$prefix/bin/skybake" render "$bake" --altitude-m 0 --sun-zenith-deg 60 --size 16x8 -o "$work/installed.png" ||
  fail "the installed skybake cannot write an image"
[ -s "$work/installed.png" ] || fail "the installed skybake wrote no image"

# find_package(skybake)
cmake -S "$source_dir/tests/install/find_package_consumer" -B "$work/find_package" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$work/fp.log" 2>&1 &&
  cmake --build "$work/find_package" >>"$work/fp.log" 2>&1 || {
  cat "$work/fp.log"
  fail "the find_package(skybake) consumer does not build"
}
if [ -x "$work/find_package/sky_zenith" ]; then
  got=$("$work/find_package/sky_zenith" "$bake" "$altitude_m" "$sun_zenith_deg" 2>/dev/null)
  echo "find_package consumer:   $got"
  if [ "$got" = "$expected" ]; then agree; else fail "the find_package consumer printed $got, skybake lookup $expected"; fi
fi

# skybake::gl, where the build has it: the installed helper makes a context
# and uploads the tables.
if [ -e "$prefix/lib/libskybake_gl.so" ]; then
  if [ -x "$work/find_package/gl_upload" ]; then
    "$work/find_package/gl_upload" "$bake" >"$work/gl.out" 2>&1 || fail "gl_upload failed: $(cat "$work/gl.out")"
    cat "$work/gl.out"
  else
    fail "the package has libskybake_gl.so but find_package(skybake) gave no skybake::gl"
  fi
fi

# The GLSL README's example (runtime/glsl/example), where the package has
# skybake::gl: its two files are the README's code blocks, it builds against
# the package as the README shows, and it prints the zenith radiance of the
# query above (1 km, sun at 30 deg, hard-coded in it) as the lookup does, to
# 1e-3 relative: the GL parity tests' largest sky difference is 3e-4.
if [ -e "$prefix/lib/libskybake_gl.so" ]; then
  readme="$source_dir/runtime/glsl/README.md"
  for f in CMakeLists.txt:cmake sky_pixel.cpp:cpp; do
    name=${f%%:*}
    awk -v title="\`$name\`:" -v open="\`\`\`${f##*:}" \
      '$0 == title { want = 1; next } want && $0 == open { inside = 1; next } inside && $0 == "```" { exit } inside { print }' \
      "$readme" >"$work/readme_$name"
    cmp -s "$work/readme_$name" "$source_dir/runtime/glsl/example/$name" ||
      fail "runtime/glsl/README.md shows a $name other than runtime/glsl/example/$name"
  done
  cmake -S "$source_dir/runtime/glsl/example" -B "$work/glsl_example" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$work/example.log" 2>&1 &&
    cmake --build "$work/glsl_example" >>"$work/example.log" 2>&1 || {
    cat "$work/example.log"
    fail "the GLSL README's example does not build against the package"
  }
  if [ -x "$work/glsl_example/sky_pixel" ]; then
    got=$("$work/glsl_example/sky_pixel" "$bake" 2>&1) || fail "the GLSL README's example failed: $got"
    echo "GLSL README example:     $got"
    awk -v got="$got" -v want="$expected" 'BEGIN {
      n = split(got, g, ","); m = split(want, w, ",")
      if (n != m) exit 1
      for (i = 1; i <= n; ++i) { d = g[i] - w[i]; if (d < 0) d = -d; if (!(d <= 1e-3 * w[i])) exit 1 }
    }' && agree || fail "the GLSL README's example printed $got, skybake lookup $expected"
  fi
fi

# The Python module, where the build has it, imported from the prefix.
python_dir="$prefix/lib/python3/dist-packages"
if [ -d "$python_dir/skybake" ]; then
  got=$(PYTHONPATH="$python_dir" /usr/bin/python3 -c "
import sys, numpy as np, skybake
sky = skybake.Sky(sys.argv[1])
z = np.radians(float(sys.argv[3]))
r, _ = sky.sky_radiance([0, 0, sky.atmosphere['bottom_radius_m'] + float(sys.argv[2])], [0, 0, 1], [np.sin(z), 0, np.cos(z)])
print(','.join('%.9g' % v for v in r))" "$bake" "$altitude_m" "$sun_zenith_deg" 2>&1)
  echo "installed Python module:   $got"
  if [ "$got" = "$expected" ]; then agree; else fail "the installed Python module printed $got, skybake lookup $expected"; fi
fi

# pkg-config, with nothing but the compiler and what the .pc file gives.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs skybake)
libdir=$(pkg-config --variable=libdir skybake)
# shellcheck disable=SC2086
c++ -std=c++20 -O2 "$source_dir/tests/install/sky_zenith.cpp" $flags -Wl,-rpath,"$libdir" \
  -o "$work/pkg_config_sky_zenith" 2>"$work/pc.log" || {
  cat "$work/pc.log"
  fail "the pkg-config consumer does not build with: $flags"
}
if [ -x "$work/pkg_config_sky_zenith" ]; then
  got=$("$work/pkg_config_sky_zenith" "$bake" "$altitude_m" "$sun_zenith_deg" 2>/dev/null)
  echo "pkg-config consumer:     $got"
  if [ "$got" = "$expected" ]; then agree; else fail "the pkg-config consumer printed $got, skybake lookup $expected"; fi
fi

# add_subdirectory of the source tree, the runtime alone.
cmake -S "$source_dir/tests/install/subproject_consumer" -B "$work/subproject" -DCMAKE_BUILD_TYPE=Release \
  -DSKYBAKE_SOURCE_DIR="$source_dir" >"$work/sub.log" 2>&1 &&
  cmake --build "$work/subproject" -j"$(nproc)" >>"$work/sub.log" 2>&1 || {
  tail -n 40 "$work/sub.log"
  fail "the add_subdirectory consumer does not build"
}
if [ -x "$work/subproject/sky_zenith" ]; then
  got=$("$work/subproject/sky_zenith" "$bake" "$altitude_m" "$sun_zenith_deg" 2>/dev/null)
  echo "add_subdirectory consumer: $got"
  if [ "$got" = "$expected" ]; then agree; else fail "the add_subdirectory consumer printed $got, skybake lookup $expected"; fi
fi

[ -n "$expected" ] || fail "skybake lookup printed nothing"
if [ "$failures" -eq 0 ]; then echo "install test: $agreed consumers agree, 0 failed"; else exit 1; fi
