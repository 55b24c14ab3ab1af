#!/usr/bin/env bash
# Set up, build, and run the whole test suite, then its fast tests under
# AddressSanitizer + UndefinedBehaviorSanitizer and concurrent lookups under
# ThreadSanitizer (scripts/test_sanitizers.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
bash scripts/test_sanitizers.sh
