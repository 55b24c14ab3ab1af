#!/usr/bin/env bash
# The Python package installed the usual way: a fresh virtual environment,
# `pip install --no-build-isolation .` from the checkout (offline: numpy and
# setuptools are Debian's, seen through --system-site-packages), then, from
# outside the checkout, `import skybake` from the environment, the version,
# a bake of a preset with one value changed, lookups by angles against the
# vector form, Sky.render against `skybake render`
# (installed_package_check.py), and the README's example script.
#
#   pip_install_test.sh SOURCE_DIR BUILD_DIR SKYBAKE_BINARY
#
# pip builds the module in BUILD_DIR (SKYBAKE_CMAKE_BUILD_DIR,
# baker/python/cmake_build.py), where the test suite's build has already
# made it: the test checks packaging, not a second compile.
set -euo pipefail
source_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
skybake=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 -m venv --system-site-packages "$work/venv"
python="$work/venv/bin/python"
(cd "$source_dir" && SKYBAKE_CMAKE_BUILD_DIR="$build_dir" "$python" -m pip install --quiet --no-index \
  --no-build-isolation .)

cd "$work"
version=$("$python" -c "import skybake; print(skybake.__version__)")
location=$("$python" -c "import skybake; print(skybake.__file__)")
echo "pip install test: skybake $version from $location"
case "$location" in
  "$work/venv/"*) ;;
  *) echo "pip install test: skybake was imported from $location, not the virtual environment" >&2; exit 1 ;;
esac
"$python" "$source_dir/tests/python/installed_package_check.py" "$skybake"
"$python" "$source_dir/scripts/examples/aerosol_sky.py" --small -o "$work/aerosol_sky.png"
test -s "$work/aerosol_sky.png"
echo "pip install test: passed"
