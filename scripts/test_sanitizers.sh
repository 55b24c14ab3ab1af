#!/usr/bin/env bash
# The fast tests under AddressSanitizer and UndefinedBehaviorSanitizer (the
# asan preset: every report fails its test), and the runtime's concurrent
# lookups under ThreadSanitizer (the tsan preset). Tests that cannot run
# under a sanitizer carry the label no_sanitizer (tests/CMakeLists.txt says
# why). Run by scripts/test.sh after the ordinary suite.
set -euo pipefail
cd "$(dirname "$0")/.."
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)"
ctest --preset asan -j"$(nproc)"
cmake --preset tsan >/dev/null
cmake --build --preset tsan -j"$(nproc)"
build-tsan/concurrent_lookups_test tests/fuzz/corpus/bake_file/tiny_earth_version3.exr
