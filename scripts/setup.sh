#!/usr/bin/env bash
# Installs the Debian 12 packages skybake builds with, then configures and
# builds it in build/ (Release). Safe to run again: installs only what is
# missing and rebuilds only what changed.
#
#   bash scripts/setup.sh --tool   the skybake command and the runtime library
#                                  only (what scripts/run.sh needs): the
#                                  compiler, CMake and 8 libraries' -dev
#                                  packages
#   bash scripts/setup.sh          everything: also the GL backend, the Python
#                                  module, the tests, benchmarks and fuzzers,
#                                  and what the tests run (Slurm, Snakemake,
#                                  Clang, the GLSL compilers)
set -euo pipefail
cd "$(dirname "$0")/.."

mode=all
case "${1:-}" in
  --tool) mode=tool ;;
  "") ;;
  *) echo "usage: scripts/setup.sh [--tool]" >&2; exit 2 ;;
esac

# The command and the runtime library: a C++20 compiler, CMake, and the
# libraries CMakeLists.txt requires.
tool_packages=(
  build-essential cmake pkg-config
  libopenexr-dev libopenimageio-dev libglm-dev libcli11-dev
  libtomlplusplus-dev nlohmann-json3-dev libfmt-dev
  # skybake export --format web gzips the tables; skybake view serves its
  # page with cpp-httplib.
  zlib1g-dev libcpp-httplib-dev
)
# The rest of the build and the test suite.
test_packages=(
  googletest libgtest-dev libbenchmark-dev
  # The fuzz targets (tests/fuzz) build with Clang: libFuzzer is in
  # libclang-rt, and the Clang build configures OpenMP through libomp.
  clang libclang-rt-14-dev libomp-dev
  # tests/CMakeLists.txt's format_check: the code follows .clang-format.
  clang-format
  # GNU time: tests/cli/lookup_memory_test.sh measures peak memory with it.
  time
  python3 python3-numpy python3-matplotlib snakemake
  # The Python module (baker/python) and its tests; python3-venv, pip,
  # setuptools and wheel for tests/python/pip_install_test.sh, which installs
  # it with pip, and OpenImageIO's Python module to read skybake render's EXR.
  pybind11-dev python3-dev python3-pytest python3-venv python3-pip python3-wheel python3-setuptools
  python3-openimageio
  python3-tomli-w python3-yaml  # scripts/sweep: make_config.py writes TOML; test_profiles.py reads the profiles
  # tests/slurm: the sweep through a one-node Slurm cluster the test starts
  # (and stops) itself; sbatch, scontrol and sinfo are in slurm-client.
  slurmctld slurmd slurm-client munge
  # The GL backend (runtime/gl, skybake render --backend gl): libepoxy loads
  # the GL functions, libegl-dev and libgl-dev give EGL and desktop GL to
  # link, libopengl-dev libglvnd's libOpenGL (CMake's FindOpenGL makes its
  # OpenGL::EGL target only beside it), libgles-dev the ES headers,
  # libegl-mesa0 Mesa's EGL (its surfaceless platform), libgl1-mesa-dri the
  # llvmpipe renderer for machines without a GPU.
  libepoxy-dev libegl-dev libgl-dev libopengl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  # tests/gl/glsl_spirv_test.sh: the GLSL compiles to SPIR-V (glslangValidator)
  # and translates to HLSL and MSL (spirv-cross).
  glslang-tools spirv-cross
  # tests/browser: skybake view and the web export in Chromium, driven by
  # Selenium, its WebGL2 on llvmpipe in an Xvfb display the test starts.
  chromium chromium-driver python3-selenium xvfb
)

packages=("${tool_packages[@]}")
[ "$mode" = all ] && packages+=("${test_packages[@]}")

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

if [ "$mode" = tool ]; then
  # The tool preset turns the tests and benchmarks off; only the command (and
  # the runtime library it links) is built, even where the GL or Python
  # packages happen to be installed.
  cmake --preset tool >/dev/null
  cmake --build build -j"$(nproc)" --target skybake
else
  cmake --preset release >/dev/null
  cmake --build build -j"$(nproc)"
fi
