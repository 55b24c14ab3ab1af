#!/usr/bin/env bash
# A spectral bake (channels.store = "spectral") through the command line:
# baked byte-identically on 1 and 2 threads, info and lookup printing all 6
# channels, render writing them, validate and reference working lane group
# by lane group, and compare's comparators refusing it with exit status 2.
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

# validate: each lane group against its own reference, the figures of all 6
# wavelengths in the table (a group at a time), the JSON and the details;
# with --colour-config, the colour of all 6 channels together.
expect_status 0 "2 lane groups of up to 4 wavelengths, each against its own reference" -- validate "$work/two.exr" \
  --queries quick --reference-samples 64 --cache-dir "$work/cache" --json "$work/v.json" --details "$work/d.csv" \
  --colour-config "$many"
for heading in "lane group 1 of 2 (400nm to 580nm):" "lane group 2 of 2 (640nm to 700nm):" "700nm rms/p95/max %" \
  "CIEDE2000 median/p95/max"; do
  grep -qF "$heading" "$work/stdout" || fail "validate's table lacks '$heading': $(cat "$work/stdout")"
done
/usr/bin/python3 - "$work/v.json" "$work/d.csv" <<'PY' || fail "validate wrote no per-wavelength figures of the spectral bake"
import csv, json, math, sys
j = json.load(open(sys.argv[1]))
assert j["wavelengths_nm"] == [400, 460, 520, 580, 640, 700], j["wavelengths_nm"]
assert [g["wavelengths_nm"] for g in j["lane_groups"]] == [[400, 460, 520, 580], [640, 700]], j["lane_groups"]
assert all(g["reference_computed"] == 54 for g in j["lane_groups"]), j["lane_groups"]
rows = {(r["quantity"], r["band"]): r for r in j["errors"]}
for key in (("sky_radiance", "day"), ("transmittance", "all"), ("sky_irradiance", "day")):
    channels = rows[key]["channels"]
    assert len(channels) == 6 and all(c["count"] > 0 and math.isfinite(c["rms"]) for c in channels), (key, channels)
assert j["colour"]["errors"][0]["count"] > 0, j["colour"]
header = next(csv.reader(open(sys.argv[2])))
assert all(f"bake_{nm}" in header for nm in (400, 580, 640, 700)) and "ciede2000" in header, header
PY
# reference: every lane group into the cache, where validate then finds them.
expect_status 0 '"to_compute": 108' -- reference "$many" --queries quick --reference-samples 64 --cache-dir "$work/rcache" --estimate
expect_status 0 "lane group 2 of 2 (640 700 nm)" -- reference "$many" --queries quick --reference-samples 64 --cache-dir "$work/rcache"
expect_status 0 "(108 from the cache, 0 computed" -- validate "$work/two.exr" --queries quick --reference-samples 64 --cache-dir "$work/rcache"
# compare's comparators take one atmosphere of at most 4 wavelengths.
expect_status 2 "skybake compare's comparators take at most 4 wavelengths" -- compare "$many" --queries quick --no-cache

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
