#!/usr/bin/env bash
# The test suite's short fuzz run. The suite is built with GCC, and libFuzzer
# needs Clang, so this configures a Clang build of the fuzz targets of its own
# (FUZZ_BUILD_DIR, inside the main build tree), builds only them, and runs the
# targets side by side for SECONDS each. Each run writes new inputs to a fresh
# scratch corpus and only reads the committed seeds. A crash, sanitizer report,
# leak, timeout or escaped exception fails the test; the input that caused it
# is kept under FUZZ_BUILD_DIR/short_run/<target>/.
# Usage: run_short_fuzz.sh SOURCE_DIR FUZZ_BUILD_DIR [SECONDS]
set -euo pipefail
source_dir=$1
build_dir=$2
seconds=${3:-20}

# An input that takes longer than this is a hang; the seeds take milliseconds.
per_input_timeout_s=10
# libFuzzer's own default: more memory than this for one input is a finding.
rss_limit_mb=2048

fail() {
  echo "run_short_fuzz: $*" >&2
  exit 1
}

command -v clang++ >/dev/null ||
  fail "clang++ is not installed, and the fuzz targets need Clang: run scripts/setup.sh"
# clang++ alone is not enough: libFuzzer ships in libclang-rt-*-dev.
probe_dir=$(mktemp -d)
trap 'rm -rf "$probe_dir"' EXIT
printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' \
  >"$probe_dir/probe.cpp"
clang++ -fsanitize=fuzzer "$probe_dir/probe.cpp" -o "$probe_dir/probe" 2>"$probe_dir/log" ||
  fail "clang++ cannot link libFuzzer (package libclang-rt-14-dev): run scripts/setup.sh
$(cat "$probe_dir/log")"

echo "run_short_fuzz: building the fuzz targets with Clang in $build_dir"
cmake -S "$source_dir" -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DSKYBAKE_BUILD_FUZZERS=ON -DSKYBAKE_BUILD_TESTS=OFF -DSKYBAKE_BUILD_BENCHMARKS=OFF \
  >"$probe_dir/configure.log" 2>&1 || fail "configuring failed:
$(cat "$probe_dir/configure.log")"
cmake --build "$build_dir" --target fuzzers -j"$(nproc)" >"$probe_dir/build.log" 2>&1 ||
  fail "building failed:
$(tail -n 60 "$probe_dir/build.log")"

fuzz_dir="$source_dir/tests/fuzz"
# start_target NAME SEED_DIR [EXTRA_FLAGS...]: runs one target in the background.
start_target() {
  local name=$1 seeds=$2
  shift 2
  local work="$build_dir/short_run/$name"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/findings"
  "$build_dir/tests/fuzz/$name" "$work/corpus" "$seeds" "$@" \
    -max_total_time="$seconds" -timeout="$per_input_timeout_s" -rss_limit_mb="$rss_limit_mb" \
    -artifact_prefix="$work/findings/" -print_final_stats=1 >"$work/log" 2>&1 &
  pids+=($!)
  names+=("$name")
}

pids=()
names=()
start_target fuzz_bake_file "$fuzz_dir/corpus/bake_file"
# -max_len: configs as long as 128 kB, so mutations can nest keys deep enough
# to reach the nesting limit (32 levels) and far beyond it, where toml++'s
# recursion once overflowed its stack (8000 levels, 16 kB); libFuzzer's
# default takes the largest seed's length.
start_target fuzz_config "$fuzz_dir/corpus/config" -dict="$fuzz_dir/config.dict" -max_len=131072

status=0
for i in "${!pids[@]}"; do
  name=${names[$i]}
  work="$build_dir/short_run/$name"
  if wait "${pids[$i]}"; then
    echo "run_short_fuzz: $name: no findings in ${seconds} s; last status: $(grep -E '^#[0-9]+' "$work/log" | tail -n 1)"
  else
    status=1
    echo "run_short_fuzz: $name: FINDING (input kept in $work/findings/); the end of its log:" >&2
    tail -n 60 "$work/log" >&2
  fi
done
exit $status
