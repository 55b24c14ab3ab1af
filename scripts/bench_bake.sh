#!/usr/bin/env bash
# Benchmark: the whole `skybake bake` process, as a user waits for it
# (start-up, stages, file written), for three bakes:
#   - the built-in Earth at the default sizes;
#   - the same at Bruneton's sizes (scattering 32 x 128 x 32 x 8) and 4 orders;
#   - the colour preset (data_formats/presets/earth_colour.toml: 16
#     wavelengths integrated into CIE X, Y, Z, four passes of the order loop).
# Each runs REPETITIONS times (default 5), the three in turn; printed per
# bake: the median wall seconds of the whole process with the min and max,
# the median CPU seconds and peak memory (GNU time), the file size, and the
# median seconds of each stage from the bake's report (`skybake bake`
# writes it beside the file), and the GPU upload `skybake info` states for
# the file. Build first (scripts/setup.sh).
#
# Usage: scripts/bench_bake.sh [REPETITIONS] [THREADS] [SKYBAKE]
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions=${1:-5}
threads=${2:-$(nproc)}
skybake=${3:-build/baker/skybake}
python=/usr/bin/python3  # Debian's, for the JSON reports
presets=$PWD/data_formats/presets
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sed -e 's/^scattering = { r = .*/scattering = { r = 32, mu = 128, mu_s = 32, nu = 8 }/' -e 's/^orders = .*/orders = 4/' \
  -e 's/^name = .*/name = "earth_bruneton_sizes"/' "$presets/earth.toml" >"$work/bruneton.toml"
names=(default bruneton_sizes_4_orders colour)
configs=("" "$work/bruneton.toml" "$presets/earth_colour.toml")

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $threads threads"
for ((i = 0; i < repetitions; ++i)); do
  for b in "${!names[@]}"; do
    out="$work/${names[b]}.exr"
    # GNU time: wall seconds, CPU seconds, peak resident KiB.
    /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$skybake" bake ${configs[b]:+"${configs[b]}"} -o "$out" \
      --threads "$threads" >/dev/null 2>&1
    read -r wall user sys kib <"$work/time"
    echo "$wall $(echo "$user + $sys" | bc -l) $kib $(stat -c %s "$out")" >>"$work/${names[b]}.runs"
    cp "${out%.exr}.report.json" "$work/${names[b]}.$i.json"
  done
done
for name in "${names[@]}"; do
  "$skybake" info "$work/$name.exr" | grep '^GPU upload:' >"$work/$name.gpu"
done

"$python" - "$work" "$repetitions" "${names[@]}" <<'EOF'
import json, statistics, sys
work, repetitions, names = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
for name in names:
    runs = [list(map(float, line.split())) for line in open(f"{work}/{name}.runs")]
    wall = [r[0] for r in runs]
    print(f"{name}: whole process median {statistics.median(wall):.2f} s (min {min(wall):.2f}, max {max(wall):.2f}, "
          f"{len(wall)} runs), CPU {statistics.median(r[1] for r in runs):.1f} s, "
          f"peak memory {statistics.median(r[2] for r in runs) / 1024:.0f} MiB, file {runs[0][3] / 2**20:.1f} MiB")
    stages = {}
    for i in range(repetitions):
        report = json.load(open(f"{work}/{name}.{i}.json"))["bake"]
        stages.setdefault("stages (all)", []).append(report["wall_seconds"])
        for stage, seconds in report.get("stage_seconds", {}).items():
            stages.setdefault(stage, []).append(seconds)
    print("  " + ", ".join(f"{stage} {statistics.median(s):.2f} s" for stage, s in stages.items()))
    print("  " + open(f"{work}/{name}.gpu").read().strip())
EOF
