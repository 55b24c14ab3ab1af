#!/usr/bin/env bash
# A spectral bake (channels.store = "spectral") through the command line:
# baked byte-identically on 1 and 2 threads, info and lookup printing all 6
# channels, render writing them, and the verbs that compare with the
# reference solver refusing it with exit status 2.
# Usage: spectral_cli_test.sh SKYBAKE_BINARY SOURCE_DIR
set -u
skybake=$1
source_dir=$(cd "$2" && pwd)
many="$source_dir/tests/cli/small_earth_many.toml"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=expect_status.sh
source "$(dirname "${BASH_SOURCE[0]}")/expect_status.sh"

# The number of comma-separated fields of line N of a file.
fields() { sed -n "${2}p" "$1" | awk -F, '{ print NF }'; }

expect_status 0 "baked 'small_earth_many'" -- bake "$many" -o "$work/one.exr" --threads 1 --reproducible
expect_status 0 "" -- bake "$many" -o "$work/two.exr" --threads 2 --reproducible
cmp -s "$work/one.exr" "$work/two.exr" || fail "spectral bakes with 1 and 2 threads differ"

expect_status 0 "channels:      400 nm  460 nm  520 nm  580 nm  640 nm  700 nm" -- info "$work/two.exr"
grep -qF "lane groups:   2 of at most 4 wavelengths, each baked as one pass: 400 460 520 580 nm; 640 700 nm" \
  "$work/stdout" || fail "info does not give the lane groups: $(cat "$work/stdout")"

printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n100,30,60,90,0\n100,95,80,0,5000\n' \
  >"$work/q.csv"
expect_status 0 "" -- lookup radiance "$work/two.exr" --queries "$work/q.csv" -o "$work/radiance.csv"
head -1 "$work/radiance.csv" | grep -qF "radiance_400,radiance_460,radiance_520,radiance_580,radiance_640,radiance_700,transmittance_400" ||
  fail "lookup radiance's header lacks the 6 channels: $(head -1 "$work/radiance.csv")"
for line in 1 2 3; do
  [ "$(fields "$work/radiance.csv" $line)" = 17 ] || fail "lookup radiance line $line has not 5 + 2 x 6 fields"
done
printf 'altitude_m,sun_zenith_deg\n0,30\n' >"$work/e.csv"
expect_status 0 "" -- lookup irradiance "$work/two.exr" --queries "$work/e.csv" -o "$work/irradiance.csv"
[ "$(fields "$work/irradiance.csv" 2)" = 14 ] || fail "lookup irradiance has not 2 + 2 x 6 fields"
head -1 "$work/irradiance.csv" | grep -qF "sun_irradiance_700" || fail "lookup irradiance lacks sun_irradiance_700"

expect_status 0 "" -- render "$work/two.exr" --altitude-m 0 --sun-zenith-deg 60 --projection latlong --size 32x16 \
  --channels spectral -o "$work/spectral.exr"
expect_status 0 "" -- render "$work/two.exr" --altitude-m 0 --sun-zenith-deg 60 --projection latlong --size 32x16 \
  -o "$work/rgb.png"

expect_status 2 "a spectral bake of 6 wavelengths" -- validate "$work/two.exr" --queries quick --no-cache
expect_status 2 "a spectral bake of 6 wavelengths" -- reference "$work/two.exr" --queries quick --cache-dir "$work/cache"
expect_status 2 "a spectral bake of 6 wavelengths" -- compare "$many" --queries quick --no-cache

# Config refusals: combined single Mie, and too many wavelengths for the
# default store, whose message names both stores that take them.
sed -e "s|\.\./\.\./data_formats|$source_dir/data_formats|" -e 's/^orders = 3$/orders = 3\ncombined_single_mie = true/' \
  "$many" >"$work/combined.toml"
expect_status 2 "bake.combined_single_mie = true" -- bake "$work/combined.toml" -o "$work/x.exr"
sed -e "s|\.\./\.\./data_formats|$source_dir/data_formats|" -e '/^store = "spectral"$/d' "$many" >"$work/plain.toml"
expect_status 2 'channels.store = "spectral"' -- bake "$work/plain.toml" -o "$work/x.exr"
grep -qF 'channels.store = "cie_xyz"' "$work/stderr" || fail "the message does not name cie_xyz: $(cat "$work/stderr")"
[ -e "$work/x.exr" ] && fail "a refused bake left an output file"

echo "spectral cli test: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
