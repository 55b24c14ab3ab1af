#!/usr/bin/env bash
# Every command in the sh code blocks of the given documents (README.md,
# docs/LEAVE_OUT.md), run in order as a newcomer would run them from the
# repository's root, so that the documents' commands work as written. Bakes
# run at small table sizes: the built-in Earth is tests/cli/small_earth.toml
# (the same atmosphere at tiny sizes) and each preset a copy of itself with
# the same small [resolution]; validate computes its reference with few
# paths and no cache. A few commands are covered by tests of their own or
# are not tests at all; each is named below with the reason, and a line
# that matches no rule fails. (data_formats/CONFIG.md has no commands; its
# TOML examples are tests/doc_config_examples_test.py's.)
# Usage: doc_commands_test.sh SKYBAKE_BINARY SOURCE_DIR DOCUMENT...
set -u
skybake=$1
source_dir=$2
shift 2
documents=("$@")
[ "${#documents[@]}" -ge 1 ] || { echo "doc_commands: no documents given"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
fail() { echo "doc_commands: FAIL: $*"; failed=$((failed + 1)); }

# The tree a command sees: build/baker/skybake, the presets at small sizes,
# the scripts, the example query file, and out/earth.exr as run.sh
# leaves it.
mkdir -p "$work/build/baker" "$work/data_formats" "$work/out"
ln -s "$skybake" "$work/build/baker/skybake"
cp -r "$source_dir/data_formats/presets" "$work/data_formats/presets"
mkdir -p "$work/data_formats/queries"
cp "$source_dir/data_formats/queries/example.csv" "$work/data_formats/queries/example.csv"
small_resolution=$(sed -n '/^\[resolution\]/,/^$/p' "$source_dir/tests/cli/small_earth.toml")
for preset in "$work"/data_formats/presets/*.toml; do
  # The preset's own [resolution] table, if any, out; the small one in.
  awk '/^\[/ {skip = ($0 == "[resolution]")} !skip' "$preset" >"$preset.tmp"
  printf '\n%s\n' "$small_resolution" >>"$preset.tmp"
  mv "$preset.tmp" "$preset"
done
"$skybake" bake "$source_dir/tests/cli/small_earth.toml" -o "$work/out/earth.exr" >/dev/null 2>&1 ||
  { echo "doc_commands: cannot bake the small Earth"; exit 1; }

# The command lines of each document's sh blocks, comments stripped; each
# document must have some (a document whose blocks lost their sh tag would
# otherwise pass untested).
commands=()
for document in "${documents[@]}"; do
  mapfile -t found < <(awk '/^```sh$/ {inside = 1; next} /^```/ {inside = 0} inside' "$source_dir/$document" |
    sed -e 's/[[:space:]]\+#.*$//' -e '/^[[:space:]]*$/d')
  [ "${#found[@]}" -ge 3 ] || { echo "doc_commands: only ${#found[@]} commands found in $document"; exit 1; }
  commands+=("${found[@]}")
done

for line in "${commands[@]}"; do
  read -ra words <<<"$line"
  case "$line" in
    "bash scripts/run.sh" | "bash scripts/test.sh")
      # The README's two commands: test.sh is this suite (CI runs it), and
      # run.sh installs packages; its bake and preview are the steps below.
      bash -n "$source_dir/${words[1]}" || fail "$line: does not parse"
      continue ;;
    "bash scripts/bench_"*)
      # Benchmarks time the machine; they are run by hand, not in tests.
      bash -n "$source_dir/${words[1]}" || fail "$line: does not parse"
      continue ;;
    "bash scripts/setup.sh" | "bash scripts/setup.sh --tool")
      # What run.sh and test.sh run first (this suite's build is setup.sh's).
      bash -n "$source_dir/${words[1]}" || fail "$line: does not parse"
      continue ;;
    "cmake --preset tool && cmake --build build --target skybake")
      # setup.sh --tool's build; configuring it here would reconfigure the
      # build this suite runs in, so the preset is checked to exist.
      (cd "$source_dir" && cmake --list-presets | grep -q '"tool"') || fail "$line: no tool preset"
      continue ;;
    "/usr/bin/python3 -m venv --system-site-packages ~/skybake-env" | "~/skybake-env/bin/"*)
      # CTest's python_pip_install makes a virtual environment the same way,
      # installs with the same pip command and runs the example in it.
      continue ;;
    "PYTHONPATH=build/python /usr/bin/python3 scripts/examples/aerosol_sky.py"*)
      # CTest's example_aerosol_sky runs this script at tiny sizes.
      [ -f "$source_dir/scripts/examples/aerosol_sky.py" ] || fail "$line: no such script"
      continue ;;
    "/usr/bin/python3 scripts/scene_queries.py "*)
      # A script of the repository, run from the root.
      words[1]="$source_dir/${words[1]}" ;;
    "build/baker/skybake bake -o "*)
      # The built-in Earth, at small sizes.
      words=("${words[0]}" bake "$source_dir/tests/cli/small_earth.toml" "${words[@]:2}") ;;
    "build/baker/skybake bake data_formats/presets/"*) ;;
    "build/baker/skybake view "*)
      # A server that runs until Ctrl-C: started here without a browser on
      # a free port, its page fetched, then stopped as Ctrl-C stops it.
      (cd "$work" && exec "${words[@]}" --no-open --port 0 >"$work/view_stdout" 2>"$work/stderr") &
      view_pid=$!
      for _ in $(seq 600); do grep -q ' at http' "$work/view_stdout" 2>/dev/null && break; sleep 0.1; done
      url=$(sed -n 's/.* at \(http[^ ]*\) .*/\1/p' "$work/view_stdout")
      page_ok=0
      [ -n "$url" ] && /usr/bin/python3 -c "import sys, urllib.request; sys.exit(0 if b'skybake view' in urllib.request.urlopen(sys.argv[1]).read() else 1)" "$url" && page_ok=1
      kill -INT "$view_pid"
      wait "$view_pid"
      status=$?
      if [ "$page_ok" -eq 1 ] && [ "$status" -eq 0 ]; then
        passed=$((passed + 1))
      else
        fail "$line: page fetched: $page_ok, exit $status: $(tail -3 "$work/stderr")"
      fi
      continue ;;
    "build/baker/skybake validate "*)
      words+=(--reference-samples 64 --no-cache) ;;
    "build/baker/skybake "*) ;;
    *)
      fail "'$line' matches no rule of this test; add one"
      continue ;;
  esac
  if (cd "$work" && "${words[@]}" >"$work/stdout" 2>"$work/stderr"); then
    passed=$((passed + 1))
  else
    fail "$line: exit $?: $(tail -3 "$work/stderr")"
  fi
done

echo "doc_commands: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
