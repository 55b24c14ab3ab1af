#!/usr/bin/env bash
# Sanitizer runs. By default (what scripts/test.sh runs) the tests labelled
# sanitizer_fast under AddressSanitizer and UndefinedBehaviorSanitizer (the
# asan preset: every report fails its test): the readers of untrusted input,
# the runtime lookups, the command line's exit statuses and concurrent
# lookups. Then the runtime's concurrent lookups under ThreadSanitizer (the
# tsan preset). With --all, every test but those labelled no_sanitizer
# (tests/CMakeLists.txt says why each is), the baker's own suite included:
# about fifteen minutes on two cores.
# Usage: test_sanitizers.sh [--all]
set -euo pipefail
cd "$(dirname "$0")/.."
asan_presets=asan-fast
case "${1:-}" in
  "") ;;
  --all) asan_presets=asan ;;
  *) echo "usage: $0 [--all]" >&2; exit 2 ;;
esac
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1
cmake --preset asan >/dev/null
cmake --build --preset "$asan_presets" -j"$(nproc)"
ctest --preset "$asan_presets" -j"$(nproc)"
cmake --preset tsan >/dev/null
cmake --build --preset tsan -j"$(nproc)"
build-tsan/concurrent_lookups_test tests/fuzz/corpus/bake_file/tiny_earth_version3.exr
