#!/usr/bin/env bash
# skybake lookup streams its rows: its peak memory does not grow with the
# number of queries. Two million rows may take no more than 16 MiB above
# ten rows (the bake itself and the I/O buffers are the same for both; held
# in memory, two million rows took over 800 MiB).
# Usage: lookup_memory_test.sh SKYBAKE_BINARY SOURCE_DIR
set -u
skybake=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -x /usr/bin/time ] || { echo "lookup_memory_test: GNU time is not installed: run scripts/setup.sh"; exit 1; }
"$skybake" bake "$source_dir/tests/cli/small_earth.toml" -o "$work/small.exr" --reproducible 2>/dev/null ||
  { echo "lookup_memory_test: the bake failed"; exit 1; }
queries() {
  awk -v n="$1" 'BEGIN { print "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg";
    for (i = 0; i < n; i++) printf "%d,%d,%d,%d\n", i % 5000, (i * 7) % 95, (i * 13) % 180, (i * 17) % 360 }'
}
peak_kib() {  # peak resident memory of one lookup of $1 rows
  queries "$1" >"$work/q.csv"
  /usr/bin/time -f %M -o "$work/peak" "$skybake" lookup radiance "$work/small.exr" --queries "$work/q.csv" \
    -o "$work/out.csv" 2>/dev/null || { echo "lookup_memory_test: the lookup of $1 rows failed"; exit 1; }
  [ "$(wc -l <"$work/out.csv")" -eq $(($1 + 1)) ] || { echo "lookup_memory_test: $1 rows in, not $1 out"; exit 1; }
  cat "$work/peak"
}
few=$(peak_kib 10)
many=$(peak_kib 2000000)
growth=$((many - few))
echo "lookup_memory_test: peak ${few} KiB for 10 rows, ${many} KiB for 2000000 rows (+${growth} KiB)"
[ "$growth" -le 16384 ] || { echo "lookup_memory_test: memory grows with the rows"; exit 1; }
echo "1 passed, 0 failed"
