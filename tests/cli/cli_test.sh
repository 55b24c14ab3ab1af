#!/usr/bin/env bash
# Command-line behaviour: exit statuses, messages, atomic outputs and
# byte-identical bakes across thread counts.
# Usage: cli_test.sh SKYBAKE_BINARY SOURCE_DIR
set -u
skybake=$1
source_dir=$2
small="$source_dir/tests/cli/small_earth.toml"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_status STATUS MESSAGE_FRAGMENT -- ARGS...: runs skybake, checks the
# exit status and that stderr contains the fragment.
expect_status() {
  local want=$1 fragment=$2; shift 3
  local got
  "$skybake" "$@" >"$work/stdout" 2>"$work/stderr"
  got=$?
  if [ "$got" -ne "$want" ]; then fail "skybake $* exited $got, expected $want: $(cat "$work/stderr")"; fi
  if [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/stderr" "$work/stdout"; then
    fail "skybake $*: output lacks '$fragment': $(cat "$work/stderr")"
  fi
}

expect_status 0 "bake" -- --help
expect_status 0 "--precision" -- bake --help
expect_status 2 "" -- frobnicate
expect_status 2 "--threads" -- bake "$small" -o "$work/x.exr" --threads 0
expect_status 2 "--precision" -- bake "$small" -o "$work/x.exr" --precision double
expect_status 2 "--orders" -- bake "$small" -o "$work/x.exr" --orders -3
expect_status 2 "nope.toml" -- bake "$work/nope.toml" -o "$work/x.exr"
expect_status 2 "does not exist" -- bake "$small" -o "$work/no/such/dir/x.exr"
[ -e "$work/x.exr" ] && fail "a failed bake left an output file"

sed 's/phase_g = 0.8/phase_g = 1.2/' "$small" >"$work/bad_g.toml"
expect_status 2 "bad_g.toml:" -- bake "$work/bad_g.toml" -o "$work/x.exr"
grep -qF "mie.phase_g = 1.2: must be in (-1, 1)" "$work/stderr" || fail "bad phase_g message: $(cat "$work/stderr")"

# A good bake, then a failing one aimed at the same path: the first survives.
expect_status 0 "baked 'small_earth'" -- bake "$small" -o "$work/good.exr" --threads 1 --reproducible
sum_before=$(sha256sum <"$work/good.exr")
expect_status 2 "phase_g" -- bake "$work/bad_g.toml" -o "$work/good.exr"
[ "$(sha256sum <"$work/good.exr")" = "$sum_before" ] || fail "a failed bake changed an existing file"
ls -A "$work" | grep -q '\.tmp-' && fail "a temporary file was left behind"

# Same config, 1 and 2 threads: byte-identical files.
expect_status 0 "" -- bake "$small" -o "$work/two.exr" --threads 2 --reproducible
cmp -s "$work/good.exr" "$work/two.exr" || fail "bakes with 1 and 2 threads differ"

expect_status 0 "" -- info "$work/good.exr"
grep -q "small_earth" "$work/stdout" || fail "info does not name the atmosphere"
grep -q "8 r x 32 mu x 8 mu_s x 4 nu" "$work/stdout" || fail "info does not give the sizes"
printf 'not an exr' >"$work/garbage.exr"
expect_status 2 "garbage.exr" -- info "$work/garbage.exr"
expect_status 2 "missing.exr" -- info "$work/missing.exr"

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all command-line checks passed"
