#!/usr/bin/env bash
# CTest fixture: the GL tests' small bakes.
# Usage: make_gl_test_bakes.sh SKYBAKE_BINARY TESTS_GL_SOURCE_DIR OUT_DIR
set -euo pipefail
skybake=$1
source_dir=$2
out=$3
mkdir -p "$out"
"$skybake" bake "$source_dir/gl_earth.toml" -o "$out/gl_earth.exr" --reproducible 2>/dev/null
"$skybake" bake "$source_dir/gl_scene.toml" -o "$out/gl_scene.exr" --reproducible 2>/dev/null
"$skybake" bake "$source_dir/gl_colour.toml" -o "$out/gl_colour.exr" --reproducible 2>/dev/null
echo "GL test bakes written to $out"
