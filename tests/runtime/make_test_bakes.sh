#!/usr/bin/env bash
# CTest fixture: bakes the built-in Earth at its default sizes, once with all
# orders and once with single scattering only, for the runtime tests.
# Usage: make_test_bakes.sh SKYBAKE_BINARY OUT_DIR
# SKYBAKE_TEST_BAKER, when set, names the skybake that bakes instead (the
# sanitizer run's runtime tests read bakes of the ordinary build).
set -euo pipefail
skybake=${SKYBAKE_TEST_BAKER:-$1}
out=$2
mkdir -p "$out"
"$skybake" bake -o "$out/earth.exr" --reproducible 2>/dev/null
"$skybake" bake -o "$out/earth_single.exr" --orders 1 --reproducible 2>/dev/null
echo "test bakes written to $out"
