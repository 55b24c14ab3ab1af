#!/usr/bin/env bash
# The tree matches docs/ARCHITECTURE.md: baker/ holds nothing at its root but
# its CMakeLists.txt, data_formats/ nothing at its root but what every format
# uses and the formats' two specifications, runtime/ nothing at its root but
# the Sky API, and every folder of baker/,
# runtime/ and data_formats/ is a room the architecture page names, so a new
# file lands in a room that says what it is.
# Usage: layout_check.sh SOURCE_DIR
set -u
cd "$1"
failures=0
fail() { echo "layout_check: $*"; failures=$((failures + 1)); }

for f in baker/*; do
  [ -d "$f" ] || [ "$f" = baker/CMakeLists.txt ] || fail "$f sits in baker/'s root; put it in the room it belongs to"
done
for f in data_formats/*; do
  [ -d "$f" ] && continue
  case "${f#data_formats/}" in
    CMakeLists.txt | CONFIG.md | FORMAT.md | angles.h | atomic_file.* | error.h | input_file.* | terminal_text.* | \
      text_numbers.h) ;;
    *) fail "$f sits in data_formats/'s root; put it in the room of its format" ;;
  esac
done
for f in runtime/*; do
  [ -d "$f" ] && continue
  case "${f#runtime/}" in
    CMakeLists.txt | README.md | version.h | sky.h | sky.cpp | sky_*.cpp | sky_lookup_*.h | lookup_geometry.*) ;;
    *) fail "$f sits in runtime/'s root, which holds the Sky API; put the physics in runtime/physics/" ;;
  esac
done
for d in baker/* runtime/* data_formats/*; do
  [ -d "$d" ] || continue
  grep -qF "\`$d/\`" docs/ARCHITECTURE.md || fail "$d/ is not a room docs/ARCHITECTURE.md describes"
done
[ "$failures" -eq 0 ] && echo "layout_check: the tree matches docs/ARCHITECTURE.md"
exit $((failures > 0))
