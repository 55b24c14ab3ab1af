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
# shellcheck source=expect_status.sh
source "$(dirname "${BASH_SOURCE[0]}")/expect_status.sh"

expect_status 0 "bake" -- --help
expect_status 0 "--precision" -- bake --help
# --version names the program's version (the top-level CMakeLists.txt's) and the bake formats it handles.
version=$(sed -n 's/^project(skybake VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
expect_status 0 "skybake $version (writes bake file format 10, reads formats 2 to 10)" -- --version
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
sed 's/^orders = 3/orders = 3\nstored_fraction_bits = 30/' "$small" >"$work/bad_bits.toml"
expect_status 2 "bad_bits.toml:" -- bake "$work/bad_bits.toml" -o "$work/x.exr"
grep -qF "bake.stored_fraction_bits = 30: must be in [10, 23]" "$work/stderr" ||
  fail "bad stored_fraction_bits message: $(cat "$work/stderr")"

# --target-error checks the bake it chose on the quick set's day sky and
# says whether the target is met, in the terminal and in the sidecar
# (few reference paths, no shared cache: the check's plumbing, not its
# figures, which docs/LEAVE_OUT.md gives at 32768 paths).
SKYBAKE_CACHE_DIR="$work/cache" expect_status 0 "--target-error 2%: " -- bake "$small" -o "$work/target.exr" \
  --target-error 2% --reference-samples 256 --orders 3
grep -qE -- "--target-error 2%: (met|NOT met, [0-9.]+ points over, even) at [0-9.]+x the default sizes: day sky radiance [0-9.]+ % RMS" \
  "$work/stderr" || fail "--target-error did not say whether its check met the target: $(cat "$work/stderr")"
/usr/bin/python3 - "$work/target.report.json" <<'PY' || fail "--target-error wrote no check to the sidecar"
import json, sys
choice = json.load(open(sys.argv[1]))["size_choice"]
check = choice["check"]
assert check["checked"] and check["day_queries"] > 0 and check["reference_paths"] == 256, check
assert choice["met"] == (check["day_sky_radiance_rms_percent"] <= 2.0), choice
PY
expect_status 2 "--reference-samples = 256: sets the paths of --target-error's check" -- \
  bake "$small" -o "$work/x.exr" --reference-samples 256

# --max-file-size: the config's sizes, then the sweep's smaller ones, until
# the written file fits (the built-in Earth's 22.6 MiB does not fit 12 MiB,
# its 0.75x does; 2 orders keep it quick); a budget nothing fits is refused
# and leaves no file.
expect_status 0 "trying 0.75x the default sizes" -- bake -o "$work/budget.exr" --orders 2 --max-file-size 12MiB
[ "$(stat -c %s "$work/budget.exr")" -le $((12 * 1048576)) ] || fail "--max-file-size 12MiB wrote a larger file"
grep -q '"file_size_budget"' "$work/budget.report.json" || fail "--max-file-size wrote no budget to the sidecar"
expect_status 2 "--max-file-size = 1KB: at the config's sizes the file is" -- \
  bake "$small" -o "$work/tiny.exr" --max-file-size 1KB
[ -e "$work/tiny.exr" ] && fail "a bake over its --max-file-size left a file"

# A good bake, then a failing one aimed at the same path: the first survives.
expect_status 0 "baked 'small_earth'" -- bake "$small" -o "$work/good.exr" --threads 1 --reproducible
sum_before=$(sha256sum <"$work/good.exr")
expect_status 2 "phase_g" -- bake "$work/bad_g.toml" -o "$work/good.exr"
[ "$(sha256sum <"$work/good.exr")" = "$sum_before" ] || fail "a failed bake changed an existing file"
ls -A "$work" | grep -q 'tmp-' && fail "a temporary file was left behind"

# Same config, 1 and 2 threads: byte-identical files.
expect_status 0 "" -- bake "$small" -o "$work/two.exr" --threads 2 --reproducible
cmp -s "$work/good.exr" "$work/two.exr" || fail "bakes with 1 and 2 threads differ"

expect_status 0 "" -- info "$work/good.exr"
grep -q "small_earth" "$work/stdout" || fail "info does not name the atmosphere"
grep -q "8 r x 32 mu x 8 mu_s x 4 nu" "$work/stdout" || fail "info does not give the sizes"
grep -qF "keep 16 of 23 fraction bits" "$work/stdout" || fail "info does not give the stored precision"
printf 'not an exr' >"$work/garbage.exr"
expect_status 2 "garbage.exr" -- info "$work/garbage.exr"
expect_status 2 "missing.exr" -- info "$work/missing.exr"

# lookup radiance: output columns, values, and CSV errors with line and column.
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n0,30,0,0,0\n1000,60,80,90,5000\n' >"$work/q.csv"
expect_status 0 "" -- lookup radiance "$work/good.exr" --queries "$work/q.csv" -o "$work/r.csv"
head -n1 "$work/r.csv" | grep -qx 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,radiance_680,radiance_550,radiance_440,transmittance_680,transmittance_550,transmittance_440' \
  || fail "lookup radiance header: $(head -n1 "$work/r.csv")"
[ "$(wc -l <"$work/r.csv")" -eq 3 ] || fail "lookup radiance: expected 2 rows"
awk -F, 'NR > 1 { for (i = 6; i <= 11; ++i) if (!($i > 0)) exit 1 }' "$work/r.csv" || fail "lookup radiance: non-positive values: $(cat "$work/r.csv")"
# An empty cell of the optional distance_m is a view ray, as 0 is: the same
# values as the first row above (a spreadsheet leaves unused cells empty).
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n0,30,0,0,\n' >"$work/empty_cell.csv"
expect_status 0 "" -- lookup radiance "$work/good.exr" --queries "$work/empty_cell.csv" -o "$work/empty_cell_r.csv"
[ "$(sed -n 2p "$work/empty_cell_r.csv" | cut -d, -f6-)" = "$(sed -n 2p "$work/r.csv" | cut -d, -f6-)" ] \
  || fail "an empty distance_m reads other than 0: $(cat "$work/empty_cell_r.csv")"
# A camera below the ground is on the ground at any depth: altitude -6.5e6 m
# (more than the planet's radius, which would put it under the opposite
# pole) reads what altitude 0 reads, in lookups and renders alike.
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n0,30,60,0,0\n-6.5e6,30,60,0,0\n-1e12,30,60,0,0\n' >"$work/deep.csv"
expect_status 0 "" -- lookup radiance "$work/good.exr" --queries "$work/deep.csv" -o "$work/deep_r.csv"
[ "$(cut -d, -f6- "$work/deep_r.csv" | sed -n 2,4p | sort -u | wc -l)" -eq 1 ] || fail "a deep camera differs from one on the ground: $(cat "$work/deep_r.csv")"
for altitude in 0 -6.5e6 -1e12; do
  expect_status 0 "" -- render "$work/good.exr" --altitude-m "$altitude" --sun-zenith-deg 80 --size 32x16 -o "$work/deep_$altitude.png"
done
for altitude in -6.5e6 -1e12; do
  cmp -s "$work/deep_0.png" "$work/deep_$altitude.png" || fail "a render at $altitude m differs from one on the ground"
done
# A colour bake: info says X, Y, Z and the wavelengths integrated, lookup
# labels its columns X, Y, Z, render refuses spectral channels.
cat >"$work/colour.toml" <<'EOF'
name = "small_colour"
[channels]
wavelengths_nm = { min_nm = 400, max_nm = 700, count = 5 }
store = "cie_xyz"
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
[sun]
irradiance = { wavelengths_nm = [400, 700], values = [1.8, 1.5] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[resolution]
transmittance = [32, 8]
irradiance = [8, 4]
scattering = { r = 4, mu = 16, mu_s = 4, nu = 4 }
[bake]
orders = 2
EOF
expect_status 0 "baked 'small_colour'" -- bake "$work/colour.toml" -o "$work/colour.exr" --threads 1
expect_status 0 "" -- info "$work/colour.exr"
grep -q "^channels: *X Y Z" "$work/stdout" || fail "info of a colour bake: $(cat "$work/stdout")"
grep -q "^integrated: *5 wavelengths: 400 nm  475 nm  550 nm  625 nm  700 nm" "$work/stdout" \
  || fail "info of a colour bake does not list its wavelengths: $(cat "$work/stdout")"
expect_status 0 "" -- lookup radiance "$work/colour.exr" --queries "$work/q.csv" -o "$work/colour.csv"
head -n1 "$work/colour.csv" | grep -qx 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,radiance_X,radiance_Y,radiance_Z,transmittance_X,transmittance_Y,transmittance_Z' \
  || fail "lookup radiance header of a colour bake: $(head -n1 "$work/colour.csv")"
expect_status 2 "is a colour bake" -- render "$work/colour.exr" -o "$work/colour_spectral.exr" --altitude-m 10 \
  --sun-zenith-deg 40 --size 8x8 --channels spectral
[ -e "$work/colour_spectral.exr" ] && fail "a refused render left an image"
expect_status 0 "" -- render "$work/colour.exr" -o "$work/colour.png" --altitude-m 10 --sun-zenith-deg 40 --size 8x8
expect_status 2 "add --colour-config CONFIG.toml" -- validate "$work/colour.exr"

printf 'altitude_m,sun_zenith_deg,view_zenith_deg\n0,30,0\n' >"$work/missing.csv"
expect_status 2 "missing column 'view_azimuth_deg'" -- lookup radiance "$work/good.exr" --queries "$work/missing.csv" -o "$work/bad.csv"
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n0,30,0,0\n0,thirty,0,0\n' >"$work/text.csv"
expect_status 2 "text.csv:3:2 (sun_zenith_deg): 'thirty' is not a finite number" -- lookup radiance "$work/good.exr" --queries "$work/text.csv" -o "$work/bad.csv"
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n0,30,190,0\n' >"$work/range.csv"
expect_status 2 "range.csv:2:3 (view_zenith_deg): 190 is out of range" -- lookup radiance "$work/good.exr" --queries "$work/range.csv" -o "$work/bad.csv"
[ -e "$work/bad.csv" ] && fail "a failed lookup left an output file"

printf 'altitude_m,sun_zenith_deg\n0,0\n0,60\n5000,95\n' >"$work/e.csv"
expect_status 0 "" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/e_out.csv"
head -n1 "$work/e_out.csv" | grep -q 'sky_irradiance_440,sun_irradiance_680' || fail "lookup irradiance header: $(head -n1 "$work/e_out.csv")"
awk -F, 'NR == 2 { if (!($3 > 0 && $6 > $3)) exit 1 }' "$work/e_out.csv" || fail "lookup irradiance: noon sun should outshine the sky: $(sed -n 2p "$work/e_out.csv")"

# Query files as common tools write them read as the plain file does: R's
# write.csv (quoted names, a leading unnamed row-name column, CRLF as on
# Windows) and numpy.savetxt(delimiter=',', header=...) ("# " header).
printf 'altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg\n0,30,60,0\n1500.5,85,90,180\n' >"$work/plain.csv"
printf '"","altitude_m","sun_zenith_deg","view_zenith_deg","view_azimuth_deg"\r\n"1",0,30,60,0\r\n"2",1500.5,85,90,180\r\n' >"$work/r_write.csv"
printf '%s\n' '# altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg' \
  '0.000000000000000000e+00,3.000000000000000000e+01,6.000000000000000000e+01,0.000000000000000000e+00' \
  '1.500500000000000000e+03,8.500000000000000000e+01,9.000000000000000000e+01,1.800000000000000000e+02' >"$work/numpy.csv"
expect_status 0 "" -- lookup radiance "$work/good.exr" --queries "$work/plain.csv" -o "$work/plain_out.csv"
for f in r_write numpy; do
  expect_status 0 "" -- lookup radiance "$work/good.exr" --queries "$work/$f.csv" -o "$work/${f}_out.csv"
  # Same header and the same looked-up values (columns 5 on; the query
  # columns repeat each file's own spelling of the numbers).
  cmp -s <(cut -d, -f5- "$work/plain_out.csv") <(cut -d, -f5- "$work/${f}_out.csv") \
    || fail "lookup radiance of $f.csv differs from the plain file's: $(cat "$work/${f}_out.csv")"
done
printf '"","altitude_m","sun_zenith_deg","view_zenith_deg","view_azimuth_deg"\r\n"1",0,"thirty",60,0\r\n' >"$work/r_bad.csv"
expect_status 2 "r_bad.csv:2:3 (sun_zenith_deg): 'thirty' is not a finite number" -- lookup radiance "$work/good.exr" --queries "$work/r_bad.csv" -o "$work/bad.csv"
printf 'altitude_m,sun_zenith_deg\n"0,30\n' >"$work/unclosed.csv"
expect_status 2 "unclosed.csv:2:1: quoted cell has no closing quote" -- lookup irradiance "$work/good.exr" --queries "$work/unclosed.csv" -o "$work/bad.csv"
[ -e "$work/bad.csv" ] && fail "a failed lookup left an output file"

# render: PNG and EXR; a bad extension or size is refused.
expect_status 0 "" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --projection fisheye --size 32x32 -o "$work/sky.png"
[ -s "$work/sky.png" ] || fail "render wrote no PNG"
expect_status 0 "" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 50 --moon 0,40,0.28 --projection fisheye --size 32x32 -o "$work/eclipse.png"
[ -s "$work/eclipse.png" ] || fail "render --moon wrote no PNG"
expect_status 0 "" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --projection latlong --size 64x32 -o "$work/sky.exr"
expect_status 2 "sky.exr" -- info "$work/sky.exr"
expect_status 2 ".png" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --projection fisheye -o "$work/sky.jpg"
expect_status 2 "--size" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --size 0x10 -o "$work/s2.png"
expect_status 2 "--sun-zenith-deg" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg nan -o "$work/s3.png"
expect_status 0 "" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --projection latlong --size 64x32 --channels spectral --no-sun -o "$work/spectral.exr"
expect_status 2 "--channels = spectral: needs an .exr output" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --channels spectral -o "$work/s4.png"
expect_status 2 "--channels" -- render "$work/good.exr" --altitude-m 0 --sun-zenith-deg 60 --channels xyz -o "$work/s5.exr"

# validate: a quick query set with few paths (the figures are noisy; this
# checks the command, its outputs and the report sidecar, not accuracy).
expect_status 0 "sky_radiance" -- validate "$work/good.exr" --queries quick --reference-samples 64 --no-cache --json "$work/v.json"
grep -q '"errors"' "$work/v.json" || fail "validate --json wrote no errors"
# Every band per camera altitude too (the quick set's cameras are at 0 and
# 10 km), in the table and the JSON: each group's counts add up to the row of
# every camera, and a mean of signed errors is at most their RMS.
grep -q "^sky_radiance       day          10 km " "$work/stdout" || fail "validate printed no camera-altitude rows: $(cat "$work/stdout")"
/usr/bin/python3 - "$work/v.json" <<'PY' || fail "validate --json has no consistent camera-altitude rows"
import json, sys
j = json.load(open(sys.argv[1]))
every = {(r["quantity"], r["band"]): r for r in j["errors"]}
groups = {}
for r in j["errors_by_camera_altitude"]:
    groups.setdefault((r["quantity"], r["band"]), []).append(r)
assert sorted(r["camera_altitude_m"][0] for r in groups[("sky_radiance", "day")]) == [0.0, 10000.0], groups
assert ("transmittance", "all") not in groups, "transmittance is not split by camera"
for key, rows in groups.items():
    for c, total in enumerate(every[key]["channels"]):
        assert sum(r["channels"][c]["count"] for r in rows) == total["count"], key
        for r in rows:
            s = r["channels"][c]
            assert abs(s["mean"]) <= s["rms"] + 1e-15, (key, s)
PY
grep -q '"validation"' "$work/good.report.json" || fail "validate did not add to the report sidecar"
expect_status 2 "missing column" -- validate "$work/good.exr" --queries "$work/missing.csv" --no-cache
# Off a terminal (stderr to a file, as in a log), a reference run of a few
# seconds shows it is alive: lines with its percentage and time while it
# runs, not only the final one.
expect_status 0 "reference" -- validate "$work/good.exr" --queries quick --reference-samples 6144 --no-cache --threads 2
progress_lines=$(grep -cE '^reference +[0-9]+% \([0-9]+/[0-9]+\) after +[0-9.]+ s' "$work/stderr")
[ "$progress_lines" -ge 2 ] || fail "validate logged $progress_lines progress lines before its last: $(cat "$work/stderr")"
grep -q $'\r' "$work/stderr" && fail "validate drew a terminal bar into a file"

expect_status 2 "--reference-samples" -- validate "$work/good.exr" --reference-samples -1
# Eclipses: 0 paths give the reference's single scattering alone (fast), and
# the details name each query's moon.
expect_status 0 "query set 'eclipse'" -- validate "$work/good.exr" --queries eclipse --reference-samples 0 --no-cache --details "$work/eclipse.csv"
grep -q "^radiance,0,50,0,0,0,0,0.28," "$work/eclipse.csv" || fail "validate --details lacks the total eclipse's zenith row"
grep -q "^radiance,0,50,85,0,5000,0,0.28," "$work/eclipse.csv" || fail "validate --details lacks the total eclipse's ray to a point 5 km away"
grep -q "radiance_to_point" "$work/stdout" || fail "validate --queries eclipse reports no radiance_to_point"
# A row may give both a distance and a moon: in totality at the umbra's
# centre the 5 km toward the sun lie in the umbra, so the bake's radiance to
# the point is the plain one's multiple scattering times F (about 3e-3),
# and the reference's single scattering (0 paths) nothing; the same row
# without the moon is the plain day.
printf '%s\n' altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,moon_separation_deg,moon_angular_radius_deg \
  0,50,85,0,5000,0,0.28 0,50,85,0,5000,0,0 >"$work/eclipse_point.csv"
expect_status 0 "radiance_to_point" -- validate "$work/good.exr" --queries "$work/eclipse_point.csv" --reference-samples 0 --no-cache --details "$work/eclipse_point_details.csv"
/usr/bin/python3 - "$work/eclipse_point_details.csv" <<'PY' || fail "validate gave a ray to a point in totality no eclipse"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2, rows
total, plain = rows
for key in total:
    if key.startswith("bake_"):
        assert 0 < float(total[key]) < 0.01 * float(plain[key]), (key, total[key], plain[key])
    if key.startswith("reference_") and not key.startswith("reference_error"):
        assert float(total[key]) < 1e-6 * float(plain[key]), (key, total[key], plain[key])
PY

# validate --colour-config: the colour table, its JSON and CSV columns, and a
# second run served from the colour cache; refused for a config whose
# per-wavelength lists cannot be read at other wavelengths and for a config
# that is not the bake's, before any reference is computed.
spectral="$source_dir/tests/cli/small_earth_spectral.toml"
expect_status 0 "baked 'small_earth_spectral'" -- bake "$spectral" -o "$work/spectral.exr"
colour_cache="$work/colour_cache"
expect_status 0 "CIEDE2000 median/p95/max" -- validate "$work/spectral.exr" --queries quick --reference-samples 64 --cache-dir "$colour_cache" --colour-config "$spectral" --json "$work/c.json" --details "$work/c.csv"
/usr/bin/python3 - "$work/c.json" "$work/c.csv" <<'PY' || fail "validate --colour-config wrote no colour figures"
import csv, json, math, sys
colour = json.load(open(sys.argv[1]))["colour"]
assert len(colour["reference_wavelengths_nm"]) == 41, colour["reference_wavelengths_nm"]
rows = {(r["quantity"], r["band"]): r for r in colour["errors"]}
day = rows[("sky_radiance", "day")]
assert day["count"] > 0, day
for key in ("luminance_rms", "ciede2000_median", "ciede2000_p95", "reference_ciede2000_median"):
    assert math.isfinite(day[key]) and day[key] >= 0, (key, day)
assert ("sky_irradiance", "day") in rows, rows.keys()
details = list(csv.DictReader(open(sys.argv[2])))
assert all(math.isfinite(float(r["ciede2000"])) for r in details), details[0]
PY
expect_status 0 "(54 from the cache, 0 computed" -- validate "$work/spectral.exr" --queries quick --reference-samples 64 --cache-dir "$colour_cache" --colour-config "$spectral"
[ "$(grep -c '54 from the cache, 0 computed' "$work/stdout")" -eq 2 ] || fail "the colour reference was not served from its cache: $(cat "$work/stdout")"
expect_status 2 "sun.irradiance = [1.474, 1.8504, 1.91198]: a list of one value per wavelength cannot be read at other wavelengths" -- validate "$work/good.exr" --queries quick --reference-samples 64 --no-cache --colour-config "$small"
grep -q "reference" "$work/stderr" && fail "validate computed a reference before refusing the colour config"
sed -e "s|\.\./\.\./data_formats|$source_dir/data_formats|" -e 's/phase_g = 0.8/phase_g = 0.7/' "$spectral" >"$work/other_spectral.toml"
expect_status 2 "is not the bake's" -- validate "$work/spectral.exr" --queries quick --reference-samples 64 --no-cache --colour-config "$work/other_spectral.toml"

# A colour bake against the colour reference: its X, Y, Z channel by
# channel and its colour table; refused with a config that is not its own or
# not a colour bake's. compare --colour puts it beside its atmosphere on 3 and
# 4 wavelengths and its spectral bake of its 5 wavelengths.
colour_config="$source_dir/tests/cli/small_earth_colour.toml"
expect_status 0 "baked 'small_earth_colour'" -- bake "$colour_config" -o "$work/small_colour.exr"
expect_status 0 "Y rms/p95/max %" -- validate "$work/small_colour.exr" --queries quick --reference-samples 64 --cache-dir "$colour_cache" --colour-config "$colour_config" --json "$work/cc.json" --details "$work/cc.csv"
/usr/bin/python3 - "$work/cc.json" "$work/cc.csv" <<'PY' || fail "validate of a colour bake wrote no X, Y, Z figures"
import csv, json, math, sys
j = json.load(open(sys.argv[1]))
assert j["channels"] == ["X", "Y", "Z"], j["channels"]
rows = {(r["quantity"], r["band"]): r for r in j["errors"]}
day = rows[("sky_radiance", "day")]
assert all(c["count"] > 0 and math.isfinite(c["rms"]) for c in day["channels"]), day
assert not any(r["quantity"] == "transmittance" for r in j["errors"]), "a colour reference has no transmittance"
colour = {(r["quantity"], r["band"]): r for r in j["colour"]["errors"]}
assert colour[("sky_radiance", "day")]["count"] > 0, colour
header = next(csv.reader(open(sys.argv[2])))
assert header.count("bake_Y") == 1 and "bake_400" not in header, header
PY
expect_status 2 "not a colour bake's config" -- validate "$work/small_colour.exr" --queries quick --reference-samples 64 --no-cache --colour-config "$spectral"
sed -e "s|\.\./\.\./data_formats|$source_dir/data_formats|" -e 's/phase_g = 0.8/phase_g = 0.7/' "$colour_config" >"$work/other_colour.toml"
expect_status 2 "is not the colour bake's" -- validate "$work/small_colour.exr" --queries quick --reference-samples 64 --no-cache --colour-config "$work/other_colour.toml"
expect_status 0 "colour: 5 wavelengths to CIE XYZ" -- compare "$colour_config" --colour --queries quick --reference-samples 64 --cache-dir "$colour_cache" --json "$work/compare_colour.json"
/usr/bin/python3 - "$work/compare_colour.json" <<'PY' || fail "compare --colour did not compare four bakes"
import json, sys
methods = json.load(open(sys.argv[1]))["methods"]
assert [m["method"].split(" ")[0] for m in methods] == ["3", "4", "colour:", "spectral:"], [m["method"] for m in methods]
assert all(m["precompute_seconds"] > 0 and m["memory_bytes"] > 0 and m["seconds_per_ray"] > 0 for m in methods), methods
# The same table sizes: the bytes per channel are the same for every bake
# (3, 4, 3 and 5 channels), so the spectral bake's count both lane groups'.
per_channel = [m["memory_bytes"] / c for m, c in zip(methods, (3, 4, 3, 5))]
assert len(set(per_channel)) == 1, per_channel
spectral_day = {(r["quantity"], r["band"]): r for r in methods[3]["errors"]}[("sky_radiance", "day")]
assert spectral_day["count"] > 0 and spectral_day["ciede2000_median"] >= 0, spectral_day
PY
grep -qF "spectral: 5 wavelengths, 2 lane groups" "$work/stdout" || fail "compare --colour printed no spectral bake: $(cat "$work/stdout")"
expect_status 2 "--resolutions does not apply" -- compare "$colour_config" --colour --resolutions 1
expect_status 2 "needs a colour bake's config" -- compare "$spectral" --colour

# reference: two pieces into one cache, then validate finds every query there
# and computes none; --estimate counts what the cache lacks.
rcache="$work/rcache"
expect_status 0 '"to_compute": 54' -- reference "$work/good.exr" --queries quick --reference-samples 64 --cache-dir "$rcache" --estimate
expect_status 0 "piece 1 of 2" -- reference "$work/good.exr" --queries quick --reference-samples 64 --piece 1/2 --cache-dir "$rcache"
expect_status 0 "piece 2 of 2" -- reference "$small" --queries quick --reference-samples 64 --piece 2/2 --cache-dir "$rcache"
expect_status 0 '"to_compute": 0' -- reference --queries quick --reference-samples 64 --cache-dir "$rcache" --estimate
expect_status 0 "(54 from the cache, 0 computed" -- validate "$work/good.exr" --queries quick --reference-samples 64 --cache-dir "$rcache"
expect_status 2 "--piece = 3/2: must be K/N" -- reference --piece 3/2 --queries quick
expect_status 2 "--piece = 1: must be K/N" -- reference --piece 1 --queries quick
# bake --estimate: the resources, and no bake.
expect_status 0 '"peak_table_bytes"' -- bake "$small" --estimate
expect_status 2 "-o,--output is required" -- bake "$small"

# compare: every method on a quick query set (CI's reduced run).
expect_status 0 "" -- compare "$small" --queries quick --reference-samples 64 --resolutions 1 --no-cache --json "$work/c.json"
for method in "ray-marched single scattering" "closed-form flat single scattering" "Hillaire 2020" "skybake 8x32x8x4"; do
  grep -q "$method" "$work/stdout" || fail "compare lacks '$method': $(cat "$work/stdout")"
done
grep -q '"seconds_per_ray"' "$work/c.json" || fail "compare --json lacks timings"
expect_status 2 "--resolutions" -- compare "$small" --resolutions 0
# A CSV with rays the comparators cannot answer (a moon, a point) compares
# the rest and says what it left out.
printf '%s\n' altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,moon_separation_deg,moon_angular_radius_deg \
  0,50,0,0,0,0,0 0,50,60,90,0,0,0 0,50,0,0,0,0,0.28 0,50,85,0,5000,0,0 >"$work/mixed.csv"
expect_status 0 "left out (skybake validate compares them): 1 eclipse queries (a moon; the comparators have no moon), 1 rays to points" -- compare "$small" --queries "$work/mixed.csv" --reference-samples 4 --resolutions 1 --no-cache --json "$work/mixed.json"
grep -q "compare on 'mixed.csv' (2 sky and ground rays" "$work/stdout" || fail "compare did not compare the two plain rays: $(cat "$work/stdout")"

# stress: one quick case with JSON output; an unknown case is bad input.
expect_status 0 "PASS" -- stress --quick --case mars --json "$work/stress.json"
grep -q '"all_passed": true' "$work/stress.json" || fail "stress --json lacks all_passed"
expect_status 2 "no such stress case" -- stress --case no_such_case

# A sidecar that repeats another bake's report (a bake killed between its two
# renames leaves the new report beside the old bake) is not used as this
# bake's: validate starts it anew from the file's own report.
"$skybake" bake "$small" -o "$work/two.exr" --orders 2 --reproducible 2>/dev/null
"$skybake" bake "$small" -o "$work/three.exr" --orders 3 --reproducible 2>/dev/null
cp "$work/three.report.json" "$work/two.report.json"
expect_status 0 "described another bake" -- validate "$work/two.exr" --queries quick --reference-samples 4 --no-cache
/usr/bin/python3 - "$work/two.report.json" <<'PY' || fail "validate kept another bake's report in the sidecar"
import json, sys
report = json.load(open(sys.argv[1]))
sys.exit(0 if len(report["bake"]["orders"]) == 2 and "validation" in report else 1)
PY

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all command-line checks passed"
