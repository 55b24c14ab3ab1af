#!/usr/bin/env bash
# Bad input, everywhere a user can give it: command-line values, query CSVs,
# bake files, output paths and sizes beyond the machine's memory. Each check
# asserts the message, exit status 2 and, where something is written, that a
# pre-existing output is byte-identical afterwards and no temporary file is
# left. docs/STABILITY.md ("Bad input") lists the kinds.
# Usage: bad_input_test.sh SKYBAKE_BINARY SOURCE_DIR
set -u
skybake=$1
source_dir=$2
small="$source_dir/tests/cli/small_earth.toml"
work=$(mktemp -d)
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# run ARGS...: skybake ARGS, stdout to $work/stdout and stderr to
# $work/stderr. With file_limit_kib set, under that file-size limit (ulimit
# -f): writes past it fail with EFBIG, as on a full disk; its messages then
# go through a pipe, which the limit does not cover. With memory_limit_kib
# set, under that address-space limit (ulimit -v): a machine that small,
# whatever this one has.
run() {
  if [ -n "${file_limit_kib:-}" ]; then
    : >"$work/stdout"
    (ulimit -f "$file_limit_kib" && exec "$skybake" "$@" 2>&1 >/dev/null) | cat >"$work/stderr"
    return "${PIPESTATUS[0]}"
  fi
  if [ -n "${memory_limit_kib:-}" ]; then
    (ulimit -v "$memory_limit_kib" && exec "$skybake" "$@" >"$work/stdout" 2>"$work/stderr")
    return
  fi
  "$skybake" "$@" >"$work/stdout" 2>"$work/stderr"
}

# refused FRAGMENT -- ARGS...: skybake ARGS exits 2 and its stderr holds
# "skybake: error: " and FRAGMENT.
refused() {
  local fragment=$1; shift 2
  run "$@"
  local got=$?
  if [ "$got" -ne 2 ]; then fail "skybake $* exited $got, expected 2: $(cat "$work/stderr")"; return; fi
  grep -qF -- "skybake: error: " "$work/stderr" || fail "skybake $*: no 'skybake: error:' line: $(cat "$work/stderr")"
  grep -qF -- "$fragment" "$work/stderr" || fail "skybake $*: stderr lacks '$fragment': $(cat "$work/stderr")"
}

# kept FILE FRAGMENT -- ARGS...: like refused, and FILE (which must exist)
# is byte-identical afterwards and no temporary file is left beside it.
kept() {
  local file=$1 fragment=$2; shift 3
  local before
  before=$(sha256sum <"$file")
  refused "$fragment" -- "$@"
  [ "$(sha256sum <"$file")" = "$before" ] || fail "skybake $*: changed the existing $file"
  if ls -A "$(dirname "$file")" | grep -q -- '\.tmp-'; then
    fail "skybake $*: left a temporary file: $(ls -A "$(dirname "$file")" | grep -- '\.tmp-')"
    rm -f "$(dirname "$file")"/.*.tmp-*
  fi
}

# A small good bake and outputs of every kind to aim failing runs at.
"$skybake" bake "$small" -o "$work/good.exr" --threads 2 --reproducible 2>"$work/stderr" \
  || { echo "FAIL: the small bake failed: $(cat "$work/stderr")"; exit 1; }
printf 'earlier output\n' >"$work/existing.csv"
cp "$work/existing.csv" "$work/existing.png"

# --- Command-line values: every numeric option, with the option, the value
# and the reason in the message. One shared check serves every option
# (baker/cli/option_checks.h), so the full set of bad values goes through one
# option of each kind and the others get the values CLI11 alone would let by
# (nan, which passes its Range) or misreport. Each run costs ~0.3 s of
# dynamic loading, so the set is kept small.
bake=(bake "$small" -o "$work/never.exr")
for v in 0 -1 2.5 nan inf 1e9 abc ''; do
  refused "--threads = $v: must be a whole number in [1, 4096]" -- "${bake[@]}" --threads "$v"
done
for v in -3 1e3 99999999999999999999; do
  refused "--orders = $v: must be 'auto' or a whole number in [1, 1000]" -- "${bake[@]}" --orders "$v"
done
for v in 0 nan -inf 1e-12; do
  refused "--order-tolerance = $v: must be a finite number in [1e-09, 0.5]" -- "${bake[@]}" --orders auto --order-tolerance "$v"
done
refused "--outputs = ground_irradiance: must include sky_radiance" -- "${bake[@]}" --outputs ground_irradiance
refused "--outputs: clouds not in {sky_radiance,radiance_to_points,ground_irradiance}" -- "${bake[@]}" --outputs sky_radiance,clouds
for v in 0-2000 2000 :5 nan:1 0:inf; do
  refused "--altitude-range = $v: must be LOW:HIGH, two finite numbers" -- "${bake[@]}" --altitude-range "$v"
done
for v in 0 -1 abc 3x 5MiBs 1e30GiB; do
  refused "--max-file-size = $v: must be a size such as 8MiB, 20MB or 5000000 (bytes)" -- "${bake[@]}" --max-file-size "$v"
done
refused "--max-file-size = 5MiB: cannot be combined with --target-error" -- "${bake[@]}" --max-file-size 5MiB --target-error 1%
refused "--max-file-size = 5MiB: cannot be combined with --estimate" -- bake "$small" --estimate --max-file-size 5MiB
refused "--reference-samples = 64: sets the paths of --target-error's check" -- bake "$small" --estimate --reference-samples 64
for v in 0 -1 100 abc nan%; do
  refused "--target-error = $v: must be a percentage in (0, 100), such as 0.5% or 0.5" -- "${bake[@]}" --target-error "$v"
done
refused '--target-error = "": an empty value: give one, or leave the option out' -- "${bake[@]}" --target-error ''
refused "--target-error = 0.3%: below what the sweep reached (0.35 % at 1x the default sizes" -- "${bake[@]}" --target-error 0.3%
refused "scene.altitude_range_m = [2000, 0]: the low end must be below the high end" -- "${bake[@]}" --altitude-range 2000:0
refused "scene.sun_zenith_range_deg[1] = 150: must be <= sun.max_zenith_deg (102)" -- "${bake[@]}" --sun-zenith-range 0:150
[ -e "$work/never.exr" ] && fail "a refused bake wrote its output"

render=(render "$work/none.exr" -o "$work/never.png")
view=(--altitude-m 0 --sun-zenith-deg 30)
refused "--altitude-m = -1e30: must be a finite number in [-1e+12, 1e+12]" -- "${render[@]}" --sun-zenith-deg 30 --altitude-m -1e30
refused "--altitude-m = nan: must be a finite number in [-1e+12, 1e+12]" -- "${render[@]}" --sun-zenith-deg 30 --altitude-m nan
refused "--sun-zenith-deg = nan: must be a finite number in [0, 180]" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg nan
refused "--sun-zenith-deg = -inf: must be a finite number in [0, 180]" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg -inf
refused "--moon = 0,40: must be AZIMUTH,ELEVATION,ANGULAR_RADIUS" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg 50 --moon 0,40
refused "--moon = 0,40,nan:" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg 50 --moon 0,40,nan
refused "the angular radius must be in (0, 5] degrees" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg 50 --moon 0,40,0
# The gl backend draws eclipses too, and refuses a bad moon as the cpu one does.
refused "--moon = 0,40: must be AZIMUTH,ELEVATION,ANGULAR_RADIUS" -- "${render[@]}" --altitude-m 0 --sun-zenith-deg 50 --moon 0,40 --backend gl
refused "--sun-azimuth-deg = nan: must be a finite number in [-360, 360]" -- "${render[@]}" "${view[@]}" --sun-azimuth-deg nan
refused "--view-azimuth-deg = 1e300: must be a finite number in [-360, 360]" -- "${render[@]}" "${view[@]}" --view-azimuth-deg 1e300
refused "--view-elevation-deg = nan: must be a finite number in [-90, 90]" -- "${render[@]}" "${view[@]}" --view-elevation-deg nan
refused "--fov-deg = 0: must be a finite number in [1, 360]" -- "${render[@]}" "${view[@]}" --fov-deg 0
refused "--exposure = 0: must be a finite number in (0, 1e+30]" -- "${render[@]}" "${view[@]}" --exposure 0
refused "--exposure = nan: must be a finite number in (0, 1e+30]" -- "${render[@]}" "${view[@]}" --exposure nan
refused "--size = -5x5: each side must be in [1, 16384]" -- "${render[@]}" "${view[@]}" --size -5x5
refused "--size = 99999999999x3: each side must be in [1, 16384]" -- "${render[@]}" "${view[@]}" --size 99999999999x3
refused "--size = nanxnan: must be WIDTHxHEIGHT" -- "${render[@]}" "${view[@]}" --size nanxnan

refused "--reference-samples = nan: must be a whole number in [0, 100000000]" -- validate "$work/none.exr" --reference-samples nan
refused "--reference-samples = -5: must be a whole number in [1, 100000000]" -- compare "$small" --reference-samples -5
refused "the comparators have no moon" -- compare "$small" --queries eclipse --reference-samples 4 --no-cache
refused "--threads = 0: must be a whole number in [1, 4096]" -- validate "$work/none.exr" --threads 0
refused "--threads = nan: must be a whole number in [1, 4096]" -- stress --threads nan
for v in 0 nan inf; do
  refused "--resolutions = $v: must be a finite number in [0.05, 8]" -- compare "$small" --resolutions "1,$v"
done

# --- Config files: config_test.cpp checks every key; here the keys of
# automatic orders through the command line, and an existing bake kept.
cp "$work/good.exr" "$work/kept.exr"
config_with() { sed "s/^orders = 3/$1/" "$small" >"$work/c.toml"; }
config_with 'orders = "auto"\norder_tolerance = nan'
kept "$work/kept.exr" "c.toml:39: bake.order_tolerance = nan: must be finite" -- bake "$work/c.toml" -o "$work/kept.exr"
config_with 'orders = "auto"\nmax_orders = 1'
kept "$work/kept.exr" "c.toml: bake.max_orders = 1: must be in [2, 1000]" -- bake "$work/c.toml" -o "$work/kept.exr"
config_with 'orders = 3\ntail_estimate = "yes"'
kept "$work/kept.exr" "c.toml:39: bake.tail_estimate = 'yes': must be true or false" -- bake "$work/c.toml" -o "$work/kept.exr"
config_with 'orders = "many"'
kept "$work/kept.exr" "c.toml:38: bake.orders = 'many': must be a whole number or \"auto\"" -- bake "$work/c.toml" -o "$work/kept.exr"
# A colour bake's wavelengths must span the colour-matching functions: an
# end short of them would bake a grey sky (data_formats/config/atmosphere_parameters.h).
colour_with() {
  sed -e "s|^wavelengths_nm = .*|wavelengths_nm = $1|" -e "s|\.\./\.\./|$source_dir/|" \
    "$source_dir/tests/cli/small_earth_colour.toml" >"$work/c.toml"
}
colour_with '{ min_nm = 700, max_nm = 780, count = 3 }'
kept "$work/kept.exr" "c.toml: channels.wavelengths_nm = 700 to 780 nm: a colour bake (channels.store = \"cie_xyz\") needs wavelengths from 420 nm or shorter to 640 nm or longer" -- bake "$work/c.toml" -o "$work/kept.exr"
colour_with '[550]'
kept "$work/kept.exr" "c.toml: channels.wavelengths_nm = 550 nm (one wavelength): a colour bake" -- bake "$work/c.toml" -o "$work/kept.exr"
# Numbers whose products overflow the float tables: the bake used to exit 0,
# replace the good file and write one its own reader refused. Repeated
# wavelengths shared one channel of the file.
sed '18s/5.802e-6/3e38/' "$small" >"$work/huge_rayleigh.toml"
kept "$work/kept.exr" "huge_rayleigh.toml: rayleigh.scattering[0] = 3e+38: the optical depth along the longest ray" -- bake "$work/huge_rayleigh.toml" -o "$work/kept.exr"
sed '13s/1.474/3e38/' "$small" >"$work/huge_sun.toml"
kept "$work/kept.exr" "huge_sun.toml: sun.irradiance[0] = 3e+38: must be <= 1e+15" -- bake "$work/huge_sun.toml" -o "$work/kept.exr"
sed '5s/680.0, 550.0/680.0, 680.0/' "$small" >"$work/twice_680.toml"
kept "$work/kept.exr" "twice_680.toml: channels.wavelengths_nm[1] = 680: repeats channels.wavelengths_nm[0]" -- bake "$work/twice_680.toml" -o "$work/kept.exr"
# More wavelengths than one file holds are refused, not truncated; a spectrum
# file's bad line is named with the key that reads it.
sed '5s/.*/wavelengths_nm = { min_nm = 380, max_nm = 780, count = 16 }/' "$small" >"$work/wide.toml"
kept "$work/kept.exr" "wide.toml:5: channels.wavelengths_nm = { count = 16, max_nm = 780, min_nm = 380 }: 16 wavelengths, but a wavelength bake holds at most 4: store them all with channels.store = \"spectral\"" -- bake "$work/wide.toml" -o "$work/kept.exr"
printf 'wavelength_nm,irradiance\n400,1\n500,2\n450,3\n' >"$work/unsorted.csv"
sed '13s/.*/irradiance = { spectrum_csv = "unsorted.csv" }/' "$small" >"$work/unsorted_sun.toml"
kept "$work/kept.exr" "unsorted_sun.toml:13: sun.irradiance.spectrum_csv: $work/unsorted.csv:4: wavelength 450 nm: is below line 3's 500 nm" -- bake "$work/unsorted_sun.toml" -o "$work/kept.exr"
# A key nested 50000 levels deep (100 kB) overflowed the TOML parser's stack
# (exit 139); it is refused before parsing.
{ cat "$small"; printf 'a'; for _ in $(seq 50000); do printf '.a'; done; printf ' = 1\n'; } >"$work/deep.toml"
kept "$work/kept.exr" "deep.toml:40:" -- bake "$work/deep.toml" -o "$work/kept.exr"
grep -qF "nested more than 32 levels deep" "$work/stderr" || fail "deep nesting message: $(cat "$work/stderr")"

# --- Query CSVs (lookup radiance|irradiance, validate --queries): the file,
# line and column, and the reason; an earlier output stays as it was.
header='altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg'
radiance() { kept "$work/existing.csv" "$1" -- lookup radiance "$work/good.exr" --queries "$work/q.csv" -o "$work/existing.csv"; }
printf '' >"$work/q.csv"
radiance "q.csv: no header row: the file is empty"
printf '%s\n' "$header" >"$work/q.csv"
radiance "q.csv: no query rows after the header (line 1)"
kept "$work/existing.csv" "q.csv: no query rows after the header (line 1)" -- validate "$work/good.exr" --queries "$work/q.csv" --no-cache --json "$work/existing.csv"
printf '# comment\naltitude_m,sun_zenith_deg,view_zenith_deg\n0,30,0\n' >"$work/q.csv"
radiance "q.csv:2: missing column 'view_azimuth_deg' (the header has: altitude_m, sun_zenith_deg, view_zenith_deg)"
printf '%s\n0,30,0,0\n0,thirty,0,0\n' "$header" >"$work/q.csv"
radiance "q.csv:3:2 (sun_zenith_deg): 'thirty' is not a finite number"
printf '%s\n0,30,nan,0\n' "$header" >"$work/q.csv"
radiance "q.csv:2:3 (view_zenith_deg): 'nan' is not a finite number"
kept "$work/existing.csv" "q.csv:2:3 (view_zenith_deg): 'nan' is not a finite number" -- validate "$work/good.exr" --queries "$work/q.csv" --no-cache --json "$work/existing.csv"
# validate --colour-config: a config whose per-wavelength lists cannot be
# read at other wavelengths, and one that does not exist; the key or file is
# named, the earlier output kept.
kept "$work/existing.csv" "small_earth.toml:13: sun.irradiance = [1.474, 1.8504, 1.91198]: a list of one value per wavelength cannot be read at other wavelengths" -- validate "$work/good.exr" --queries quick --no-cache --colour-config "$small" --json "$work/existing.csv"
kept "$work/existing.csv" "none.toml: no such config file" -- validate "$work/good.exr" --queries quick --no-cache --colour-config "$work/none.toml" --json "$work/existing.csv"
printf '%s\n0,30,0,-inf\n' "$header" >"$work/q.csv"
radiance "q.csv:2:4 (view_azimuth_deg): '-inf' is not a finite number"
printf '%s\n0,30,0,0\n0,30,,0\n' "$header" >"$work/q.csv"
radiance "q.csv:3:3 (view_zenith_deg): '' is not a finite number"
printf '%s\n1e13,30,0,0\n' "$header" >"$work/q.csv"
radiance "q.csv:2:1 (altitude_m): 1e13 is out of range [-1e+12, 1e+12]"
printf '%s\n0,30,0\n' "$header" >"$work/q.csv"
radiance "q.csv:2:4: 3 cells, the header (line 1) has 4 columns"
printf '%s\n0,30,0,0,7\n' "$header" >"$work/q.csv"
radiance "q.csv:2:5: 5 cells, the header (line 1) has 4 columns"
printf 'altitude_m,sun_zenith_deg,altitude_m\n' >"$work/q.csv"
radiance "q.csv:1:3: column 'altitude_m' appears twice (also column 1)"
{ printf '%s\n' "$header"; head -c 70000 /dev/zero | tr '\0' '0'; printf '\n'; } >"$work/q.csv"
radiance "q.csv:2: line longer than 65536 bytes: not a query CSV"
radiance_missing() { kept "$work/existing.csv" "$1" -- lookup radiance "$work/good.exr" --queries "$2" -o "$work/existing.csv"; }
radiance_missing "no_such.csv: cannot open query file: No such file or directory" "$work/no_such.csv"
radiance_missing "is a directory, not a query file" "$work"
# A bake narrowed to a scene's ranges refuses lookups outside them (they
# would be clamped), naming the cell, the bake and the range.
# (The orders iterate at the small sizes too, to keep this quick; the
# altitude texels are given, so that the range is not widened to the whole
# axis's next texel.)
{ cat "$small"; printf '\n[resolution.iteration]\nr = 8\nmu = 32\nmu_s = 8\nnu = 4\n[resolution.scene]\nr = 8\n'; } >"$work/narrow.toml"
"$skybake" bake "$work/narrow.toml" -o "$work/narrow.exr" --threads 2 --altitude-range 0:2000 --sun-zenith-range 0:90 \
  2>"$work/stderr" || fail "the narrowed bake failed: $(cat "$work/stderr")"
narrow() { kept "$work/existing.csv" "$1" -- lookup radiance "$work/narrow.exr" --queries "$work/q.csv" -o "$work/existing.csv"; }
printf '%s\n1000,30,0,0\n5000,30,0,0\n' "$header" >"$work/q.csv"
narrow "q.csv:3:1 (altitude_m): 5000 m is outside the altitudes $work/narrow.exr covers (0 to 2000 m, its scene.altitude_range_m)"
printf '%s\n1000,100,0,0\n' "$header" >"$work/q.csv"
narrow "q.csv:2:2 (sun_zenith_deg): 100 deg is outside the sun angles $work/narrow.exr covers (0 to"
printf '%s,distance_m\n0,30,80,0,50000\n' "$header" >"$work/q.csv"
narrow "q.csv:2:5 (distance_m): 50000 m away puts the point at altitude 8.87e+03 m, which is outside the altitudes"
# A bake of every altitude and sun says what is really wrong: a point below
# the ground (not a scene range it lacks). It refuses no sun and no camera
# (tests/runtime/night_sky_test.cpp).
whole() { kept "$work/existing.csv" "$1" -- lookup radiance "$work/good.exr" --queries "$work/q.csv" -o "$work/existing.csv"; }
printf '%s,distance_m\n0,30,95,0,3000\n' "$header" >"$work/q.csv"
whole "q.csv:2:5 (distance_m): 3000 m away puts the point at altitude -261 m, which is below the ground"
printf 'altitude_m,sun_zenith_deg\n0,190\n' >"$work/e.csv"
kept "$work/existing.csv" "e.csv:2:2 (sun_zenith_deg): 190 is out of range [0, 180]" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/existing.csv"

# --- Bake files given as input (info, lookup, render, validate): truncated,
# bit-flipped, a format version this skybake does not read, a part missing.
# Each message names the file; the reader's unit tests
# (tests/data_formats/bake_file_corrupt_test.cpp) cover the cases in depth.
corrupt="python3 $source_dir/tests/cli/corrupt_bake.py"
bytes=$(stat -c %s "$work/good.exr")
head -c 1000 "$work/good.exr" >"$work/cut_header.exr"
head -c $((bytes / 2)) "$work/good.exr" >"$work/cut_pixels.exr"
$corrupt "$work/good.exr" "$work/v99.exr" version 99
$corrupt "$work/good.exr" "$work/no_part.exr" rename optical_depth optical_deptX
$corrupt "$work/good.exr" "$work/flipped.exr" flip 0.6
printf 'altitude_m,sun_zenith_deg\n0,30\n' >"$work/e.csv"
printf 'not an exr' >"$work/text.exr"
lookup_e=(--queries "$work/e.csv" -o "$work/existing.csv")
render_v=(--altitude-m 0 --sun-zenith-deg 30 -o "$work/existing.png")
validate_q=(--queries quick --reference-samples 4 --no-cache --json "$work/existing.csv")
refused "cut_header.exr: not a readable skybake bake file: OpenEXR header: " -- info "$work/cut_header.exr"
kept "$work/existing.csv" "cut_header.exr: not a readable skybake bake file: OpenEXR header: " -- lookup irradiance "$work/cut_header.exr" "${lookup_e[@]}"
# info reads the headers alone (whole in this file) and prints them; every
# verb that reads the tables refuses it.
kept "$work/existing.csv" "cut_pixels.exr: not a readable skybake bake file: " -- lookup irradiance "$work/cut_pixels.exr" "${lookup_e[@]}"
kept "$work/existing.csv" "cut_pixels.exr: not a readable skybake bake file: " -- validate "$work/cut_pixels.exr" "${validate_q[@]}"
for command in info "lookup irradiance" render validate; do
  case $command in
    info) extra=(); out=$work/existing.csv ;;
    lookup*) extra=("${lookup_e[@]}"); out=$work/existing.csv ;;
    render) extra=("${render_v[@]}"); out=$work/existing.png ;;
    validate) extra=("${validate_q[@]}"); out=$work/existing.csv ;;
  esac
  # shellcheck disable=SC2086 # "lookup irradiance" is two words
  kept "$out" "v99.exr: format version 99 is not understood by this skybake (it reads versions 2 to 10)" -- $command "$work/v99.exr" "${extra[@]}"
  kept "$out" "no_part.exr: part 'optical_depth' is missing" -- $command "$work/no_part.exr" "${extra[@]}"
done
kept "$work/existing.png" "flipped.exr: not a readable skybake bake file: " -- render "$work/flipped.exr" "${render_v[@]}"
# A bake report whose numbers are text is refused naming the key (it ended in
# "internal error", exit 1).
"$skybake" bake "$small" -o "$work/timed.exr" --threads 2 2>/dev/null
$corrupt "$work/timed.exr" "$work/bad_report.exr" replace $'"threads": 2,\n ' $'"threads":"2",\n'
refused 'bad_report.exr [skybake:bake_report]: threads = "2": must be a number' -- info "$work/bad_report.exr"
# Names holding terminal escape sequences are printed escaped, by bake and info.
sed 's/^name = .*/name = "red\\u001b[31mtext"/' "$small" >"$work/escape.toml"
"$skybake" bake "$work/escape.toml" -o "$work/escape.exr" --reproducible >"$work/stdout" 2>"$work/stderr"
"$skybake" info "$work/escape.exr" >>"$work/stdout" 2>>"$work/stderr"
if grep -q $'\x1b' "$work/stdout" "$work/stderr"; then fail "a name's escape sequence was printed raw"; fi
grep -qF 'red\x1b[31mtext' "$work/stderr" || fail "bake does not print the escaped name: $(cat "$work/stderr")"
grep -qF 'atmosphere:    red\x1b[31mtext' "$work/stdout" || fail "info does not print the escaped name: $(head -5 "$work/stdout")"
refused "text.exr: not a readable skybake bake file" -- info "$work/text.exr"
refused "no_such.exr: no such bake file" -- info "$work/no_such.exr"
refused ": is a directory, not a bake file" -- info "$work"

# --- Output paths, for every command that writes: a missing directory, a
# path that is a directory, a directory that is a file, a directory without
# write permission and a full disk. Each is refused before any work where it
# can be known in advance; an existing output is never replaced by a partial
# one and no temporary file is left.
mkdir "$work/out" "$work/out/taken.exr" "$work/out/taken.json"
cp "$work/good.exr" "$work/out/old.exr"
cp "$work/existing.csv" "$work/out/old.json"
cp "$work/existing.csv" "$work/out/old.csv"
cp "$work/existing.png" "$work/out/old.png"
"$skybake" bake "$small" -o "$work/out/old.exr" --reproducible 2>/dev/null  # with its report sidecar
quick=(--queries quick --reference-samples 4 --no-cache)
stress_one=(stress --quick --case no_atmosphere)
compare_one=(compare "$small" "${quick[@]}" --resolutions 0.5)
refused "no/x.exr: output directory $work/no does not exist" -- bake "$small" -o "$work/no/x.exr"
refused "no/x.csv: output directory $work/no does not exist" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/no/x.csv"
refused "no/x.png: output directory $work/no does not exist" -- render "$work/good.exr" "${view[@]}" -o "$work/no/x.png"
refused "no/x.json: output directory $work/no does not exist" -- validate "$work/good.exr" "${quick[@]}" --json "$work/no/x.json"
refused "no/x.csv: output directory $work/no does not exist" -- validate "$work/good.exr" "${quick[@]}" --details "$work/no/x.csv"
refused "no/x.json: output directory $work/no does not exist" -- "${compare_one[@]}" --json "$work/no/x.json"
refused "no/x.json: output directory $work/no does not exist" -- "${stress_one[@]}" --json "$work/no/x.json"
refused "existing.csv/x.exr: $work/existing.csv is not a directory" -- bake "$small" -o "$work/existing.csv/x.exr"
# A special file is refused before the work and stays what it was (the
# rename replaced /dev/null itself with a regular file, as root); a name too
# long for its temporary file is refused before the work too.
mkfifo "$work/out/pipe.exr"
refused "pipe.exr: is a named pipe, not a regular file" -- bake "$small" -o "$work/out/pipe.exr"
[ -p "$work/out/pipe.exr" ] || fail "bake -o a named pipe replaced it"
rm -f "$work/out/pipe.exr"
long_name=$(printf 'n%.0s' $(seq 250)).exr
refused "the file name is too long" -- bake "$small" -o "$work/out/$long_name"
kept "$work/good.exr" "good.exr: is also an input ($work/good.exr); the output would replace it" -- render "$work/good.exr" "${view[@]}" -o "$work/good.exr"
kept "$work/e.csv" "e.csv: is also an input ($work/e.csv); the output would replace it" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/e.csv"
cp "$small" "$work/config.exr"
kept "$work/config.exr" "config.exr: is also an input ($work/config.exr); the output would replace it" -- bake "$work/config.exr" -o "$work/config.exr"
refused "existing.csv: the reference cache directory is a file" -- validate "$work/good.exr" --queries quick --cache-dir "$work/existing.csv"
refused "taken.exr: is a directory; the output needs a file name" -- bake "$small" -o "$work/out/taken.exr"
refused "taken.json: is a directory; the output needs a file name" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/out/taken.json"
refused "taken.exr: is a directory; the output needs a file name" -- render "$work/good.exr" "${view[@]}" -o "$work/out/taken.exr"
refused "taken.json: is a directory; the output needs a file name" -- validate "$work/good.exr" "${quick[@]}" --json "$work/out/taken.json"
refused "taken.json: is a directory; the output needs a file name" -- "${compare_one[@]}" --json "$work/out/taken.json"
refused "taken.json: is a directory; the output needs a file name" -- "${stress_one[@]}" --json "$work/out/taken.json"
# The report sidecar beside a bake (taken.exr -> taken.report.json).
mkdir "$work/out/side.report.json"
cp "$work/good.exr" "$work/out/side.exr"
kept "$work/out/side.exr" "side.report.json: is a directory; the output needs a file name" -- bake "$small" -o "$work/out/side.exr"
if [ "$(id -u)" -eq 0 ]; then
  echo "skipped: the write-permission checks (running as root, which directory permissions do not restrict)"
else
  chmod 555 "$work/out"
  kept "$work/out/old.exr" "old.exr: cannot create files in $work/out: Permission denied" -- bake "$small" -o "$work/out/old.exr"
  kept "$work/out/old.csv" "old.csv: cannot create files in $work/out: Permission denied" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/out/old.csv"
  kept "$work/out/old.png" "old.png: cannot create files in $work/out: Permission denied" -- render "$work/good.exr" "${view[@]}" -o "$work/out/old.png"
  kept "$work/out/old.report.json" "old.report.json: cannot create files in $work/out: Permission denied" -- validate "$work/out/old.exr" "${quick[@]}"
  chmod 755 "$work/out"
fi
# A full disk, as a file-size limit: the write fails part-way.
file_limit_kib=64 kept "$work/out/old.exr" "old.exr: cannot write: Failed to write pixel data to image file \"$work/out/.old.tmp-" -- bake "$small" -o "$work/out/old.exr"
grep -qF "File too large" "$work/stderr" || fail "full disk: the bake's message lacks the reason: $(cat "$work/stderr")"
file_limit_kib=0 kept "$work/out/old.csv" "old.csv: cannot write: File too large" -- lookup irradiance "$work/good.exr" --queries "$work/e.csv" -o "$work/out/old.csv"
file_limit_kib=1 kept "$work/out/old.png" "old.png: cannot write: File too large" -- render "$work/good.exr" "${view[@]}" --size 64x64 -o "$work/out/old.png"
file_limit_kib=1 kept "$work/out/old.png" "old.exr: cannot write: File too large" -- render "$work/good.exr" "${view[@]}" --size 64x64 -o "$work/out/old.exr"
file_limit_kib=1 kept "$work/out/old.json" "old.json: cannot write: File too large" -- validate "$work/good.exr" "${quick[@]}" --json "$work/out/old.json"
file_limit_kib=1 kept "$work/out/old.report.json" "old.report.json: cannot write: File too large" -- validate "$work/out/old.exr" "${quick[@]}"
file_limit_kib=1 kept "$work/out/old.json" "old.json: cannot write: File too large" -- "${compare_one[@]}" --json "$work/out/old.json"
file_limit_kib=1 kept "$work/out/old.json" "old.json: cannot write: File too large" -- "${stress_one[@]}" --json "$work/out/old.json"
(ulimit -f 0 && exec "$skybake" lookup irradiance "$work/good.exr" --queries "$work/e.csv" 2>&1 >"$work/out/stdout.csv") \
  | cat >"$work/stderr"
[ "${PIPESTATUS[0]}" -eq 2 ] || fail "lookup to a full standard output did not exit 2"
grep -qF "skybake: error: standard output: cannot write: File too large" "$work/stderr" \
  || fail "lookup to a full standard output: $(cat "$work/stderr")"
[ "$(ls -A "$work/out" | grep -c -- '\.tmp-')" -eq 0 ] || fail "temporary files left in $work/out: $(ls -A "$work/out")"

# --- Sizes beyond the machine's memory: refused before anything is
# allocated, with the estimate and what is available. A 3.8 GiB address-space
# limit stands in for a small machine (an allocation past it would fail with
# "out of memory", exit 1, so exit 2 shows the check came first).
sed 's/^scattering = {.*/scattering = { r = 512, mu = 1024, mu_s = 256, nu = 2 }/' "$small" >"$work/huge.toml"
small_machine=3900000
memory_limit_kib=$small_machine kept "$work/out/old.exr" "huge.toml: resolution.scattering = 512 x 1024 x 256 x 2: the bake (2 tables of 4.0 GiB, 3 of 2.0 GiB and the orders' radiance, 4.0 GiB, alive at once and the scattering density's 3.3 GiB kernel) needs about 21.3 GiB; this process may allocate" -- bake "$work/huge.toml" -o "$work/out/old.exr"
grep -qF "(address-space limit, ulimit -v)" "$work/stderr" || fail "the memory refusal does not say which limit: $(cat "$work/stderr")"
# The comparison's 2.2 GiB fit in the small machine's limit: a smaller one.
memory_limit_kib=1500000 kept "$work/out/old.json" "small_earth.toml: --resolutions = 1,8: the comparison (every bake kept to the end) needs about 2.2 GiB; this process may allocate" -- compare "$small" --resolutions 1,8 --json "$work/out/old.json"
memory_limit_kib=$small_machine kept "$work/out/old.png" "--size = 16384x16384: the image needs about 12.8 GiB; this process may allocate" -- render "$work/good.exr" "${view[@]}" --size 16384x16384 -o "$work/out/old.png"
# Sizes whose products overflow are refused by the config check before any
# product is formed in an int (and the estimate saturates; see
# tests/baker/bake_memory_estimate_test.cpp).
sed 's/^scattering = {.*/scattering = { r = 1024, mu = 1024, mu_s = 1024, nu = 1024 }/' "$small" >"$work/overflow.toml"
kept "$work/out/old.exr" "overflow.toml: resolution.scattering = 1099511627776 texels: more than 268435456 texels per table" -- bake "$work/overflow.toml" -o "$work/out/old.exr"

# --- Files a config names, and configs that are not files. An output is
# never one of the inputs: the spectrum CSV a config reads is kept.
printf 'wavelength_nm,irradiance\n300,1.5\n900,1.5\n' >"$work/sun.csv"
sed '13s/.*/irradiance = { spectrum_csv = "sun.csv" }/' "$small" >"$work/csv_sun.toml"
kept "$work/sun.csv" "sun.csv: is also an input ($work/sun.csv); the output would replace it" -- bake "$work/csv_sun.toml" -o "$work/sun.csv"
# A device never ends, a named pipe blocks its reader, a huge file is not a
# config: each refused by what it is, before it is read (in bounded time:
# the run has a timeout of its own in CTest).
kept "$work/kept.exr" "/dev/zero: is a character device, not a config file" -- bake /dev/zero -o "$work/kept.exr"
mkfifo "$work/fifo.toml"
kept "$work/kept.exr" "fifo.toml: is a named pipe, not a config file" -- bake "$work/fifo.toml" -o "$work/kept.exr"
kept "$work/kept.exr" "$work: is a directory, not a config file" -- bake "$work" -o "$work/kept.exr"
truncate -s 512M "$work/big.toml"
kept "$work/kept.exr" "big.toml: 536870912 bytes, larger than a config file can be (16 MiB)" -- bake "$work/big.toml" -o "$work/kept.exr"
rm -f "$work/big.toml"
refused "/dev/zero: is a character device, not a bake file" -- info /dev/zero
# Spectrum cells are quoted escaped and shortened; a value no float holds is
# refused naming the file and line, not as an infinite config value.
printf 'wavelength_nm,irradiance\n300,1\0005\n900,2\n' >"$work/nul.csv"
sed '13s/.*/irradiance = { spectrum_csv = "nul.csv" }/' "$small" >"$work/nul_sun.toml"
kept "$work/kept.exr" "nul_sun.toml:13: sun.irradiance.spectrum_csv: $work/nul.csv:2: value 1\x005: must be a finite number" -- bake "$work/nul_sun.toml" -o "$work/kept.exr"
{ printf 'wavelength_nm,irradiance\n300,'; head -c 60000000 /dev/zero | tr '\0' '7'; printf '\n900,2\n'; } >"$work/long.csv"
sed '13s/.*/irradiance = { spectrum_csv = "long.csv" }/' "$small" >"$work/long_sun.toml"
kept "$work/kept.exr" "long.csv:2: value $(printf '%080d' 0 | tr 0 7)... (60000000 bytes): must be a finite number" -- bake "$work/long_sun.toml" -o "$work/kept.exr"
[ "$(wc -c <"$work/stderr")" -lt 1000 ] || fail "a 60 MB cell was echoed: $(wc -c <"$work/stderr") bytes of message"
rm -f "$work/long.csv"
printf 'wavelength_nm,irradiance\n300,1e300\n900,2\n' >"$work/e300.csv"
sed '13s/.*/irradiance = { spectrum_csv = "e300.csv" }/' "$small" >"$work/e300_sun.toml"
kept "$work/kept.exr" "e300_sun.toml:13: sun.irradiance.spectrum_csv: $work/e300.csv:2: value 1e300: beyond the 3.40282e+38 a table's float holds" -- bake "$work/e300_sun.toml" -o "$work/kept.exr"
# An empty option value is refused, not read as the option left out.
refused '--moon = "": an empty value: give one, or leave the option out' -- render "$work/good.exr" "${view[@]}" --moon "" -o "$work/never.png"
refused '--piece = "": an empty value: give one, or leave the option out' -- reference --piece ""
[ -e "$work/never.png" ] && fail "a refused render wrote its output"

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all bad-input checks passed"
