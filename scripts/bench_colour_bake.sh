#!/usr/bin/env bash
# Benchmark: the colour bake of data_formats/presets/earth_colour.toml (16
# wavelengths integrated into CIE X, Y, Z: four passes of the order loop)
# against a 3-wavelength bake of the same atmosphere (the same config on
# 440, 550 and 680 nm, stored as wavelengths), at the default sizes, timed
# as a user feels them: the whole `skybake bake` process. The two alternate,
# REPETITIONS (default 3) times each, and the medians and file sizes are
# printed. Build first (scripts/setup.sh, or cmake --build build --target
# skybake).
#
# Usage: scripts/bench_colour_bake.sh [REPETITIONS] [THREADS] [SKYBAKE]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-3}
threads=${2:-$(nproc)}
skybake=${3:-build/baker/skybake}
presets=$PWD/data_formats/presets
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The 3-wavelength bake: the colour preset's spectra read at 440, 550 and
# 680 nm, one channel each (its spectrum files found from the presets folder).
sed -e 's/^wavelengths_nm = .*/wavelengths_nm = [440.0, 550.0, 680.0]/' -e '/^store = "cie_xyz"/d' \
  -e "s|_csv = \"|_csv = \"$presets/|g" -e 's/^name = .*/name = "earth_colour_3_wavelengths"/' \
  "$presets/earth_colour.toml" >"$work/three.toml"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $threads threads"
seconds() {  # wall seconds of one bake
  local start end
  start=$(date +%s.%N)
  "$skybake" bake "$1" -o "$2" --threads "$threads" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
colour_times=()
three_times=()
for ((i = 0; i < repetitions; ++i)); do
  colour_times+=("$(seconds "$presets/earth_colour.toml" "$work/colour.exr")")
  three_times+=("$(seconds "$work/three.toml" "$work/three.exr")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
colour=$(median "${colour_times[@]}")
three=$(median "${three_times[@]}")
printf 'colour bake (16 wavelengths -> XYZ): median %.2f s of %s: %s\n' "$colour" "$repetitions" "${colour_times[*]}"
printf '3-wavelength bake:                   median %.2f s of %s: %s\n' "$three" "$repetitions" "${three_times[*]}"
printf 'ratio: %.2f\n' "$(echo "$colour / $three" | bc -l)"
echo "files: colour $(stat -c %s "$work/colour.exr") bytes, 3 wavelengths $(stat -c %s "$work/three.exr") bytes"
