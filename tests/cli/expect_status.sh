# The command-line tests' checks, sourced by them. The sourcing script sets
# $skybake (the binary) and $work (a scratch folder) first, and reads
# $failures and $passed at its end.
failures=0
passed=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_status STATUS MESSAGE_FRAGMENT -- ARGS...: runs skybake, checks the
# exit status and that its output (stderr or stdout) contains the fragment.
expect_status() {
  local want=$1 fragment=$2; shift 3
  local got
  "$skybake" "$@" >"$work/stdout" 2>"$work/stderr"
  got=$?
  if [ "$got" -ne "$want" ]; then
    fail "skybake $* exited $got, expected $want: $(cat "$work/stderr")"
  elif [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/stderr" "$work/stdout"; then
    fail "skybake $*: output lacks '$fragment': $(cat "$work/stderr")"
  else
    passed=$((passed + 1))
  fi
}
