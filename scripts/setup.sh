#!/usr/bin/env bash
# Installs the Debian 12 packages skybake builds with, then configures and
# builds it in build/ (Release). Safe to run again: installs only what is
# missing and rebuilds only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config
  libopenexr-dev libopenimageio-dev libglm-dev libcli11-dev
  libtomlplusplus-dev nlohmann-json3-dev libfmt-dev
  googletest libgtest-dev libbenchmark-dev
  # The fuzz targets (tests/fuzz) build with Clang: libFuzzer is in
  # libclang-rt, and the Clang build configures OpenMP through libomp.
  clang libclang-rt-14-dev libomp-dev
  # tests/CMakeLists.txt's format_check: the code follows .clang-format.
  clang-format
  # GNU time: tests/cli/lookup_memory_test.sh measures peak memory with it.
  time
  python3 python3-numpy python3-matplotlib snakemake
  # The Python module (baker/python) and its tests.
  pybind11-dev python3-dev python3-pytest
  python3-tomli-w python3-pytest  # scripts/sweep/make_config.py writes TOML; its test runs under pytest
  # tests/slurm: the sweep through a one-node Slurm cluster the test starts
  # (and stops) itself; sbatch, scontrol and sinfo are in slurm-client.
  slurmctld slurmd slurm-client munge
  # The GL backend (runtime/gl, skybake render --backend gl): libepoxy loads
  # the GL functions, libegl-dev and libgl-dev give EGL and desktop GL to
  # link, libgles-dev the ES headers, libegl-mesa0 Mesa's EGL (its
  # surfaceless platform), libgl1-mesa-dri the llvmpipe renderer for
  # machines without a GPU.
  libepoxy-dev libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  # tests/gl/glsl_spirv_test.sh: the GLSL compiles to SPIR-V (glslangValidator)
  # and translates to HLSL and MSL (spirv-cross).
  glslang-tools spirv-cross
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "skybake setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset release >/dev/null
cmake --build build -j"$(nproc)"
