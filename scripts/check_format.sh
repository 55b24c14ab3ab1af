#!/usr/bin/env bash
# Fails when a C++ file of the project differs from what clang-format makes
# of it (.clang-format at the top level), naming each such file.
# Usage: check_format.sh SOURCE_DIR
set -euo pipefail
cd "$1"
format=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$format" ] || { echo "check_format: clang-format is not installed: run scripts/setup.sh" >&2; exit 1; }
if [ -d .git ]; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h')
else
  mapfile -t files < <(find baker runtime data_formats tests scripts -name '*.cpp' -o -name '*.h')
fi
unformatted=()
for f in "${files[@]}"; do
  "$format" --dry-run -Werror "$f" >/dev/null 2>&1 || unformatted+=("$f")
done
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "check_format: these files do not follow .clang-format (fix: clang-format -i FILE):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files follow .clang-format"
