"""How `pip install .` builds the skybake Python module: setuptools hands the
extension skybake._skybake to CMake, which configures skybake (without its
tests and benchmarks) for the Python running pip and builds the
skybake_python target; the presets (data_formats/presets) are copied into
the package as skybake.presets.

Environment:
  SKYBAKE_CMAKE_BUILD_DIR  an existing, configured skybake build folder to
                           build the module in (e.g. build/ after
                           scripts/setup.sh) instead of a new one; it must be
                           configured for this Python (Python3_EXECUTABLE).
  CMAKE_BUILD_PARALLEL_LEVEL  compile jobs (default: every core).
"""
import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
PRESETS_DIR = SOURCE_DIR / "data_formats" / "presets"


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class BuildWithCMake(build_ext):
    def build_extension(self, ext):
        existing = os.environ.get("SKYBAKE_CMAKE_BUILD_DIR")
        if existing:
            build_dir = pathlib.Path(existing).resolve()
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            subprocess.run(["cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                            "-DSKYBAKE_BUILD_TESTS=OFF", "-DSKYBAKE_BUILD_BENCHMARKS=OFF",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "skybake_python", "-j", jobs], check=True)
        built = build_dir / "python" / "skybake" / ("_skybake" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            raise RuntimeError(f"{built} was not built: {build_dir} is configured for another Python than "
                               f"{sys.executable}, or pybind11 (pybind11-dev) or this Python's headers "
                               f"(python3-dev) were not found (see its CMake output)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


class BuildWithPresets(build_py):
    def run(self):
        super().run()
        presets = pathlib.Path(self.build_lib) / "skybake" / "presets"
        presets.mkdir(parents=True, exist_ok=True)
        for file in sorted(PRESETS_DIR.iterdir()):
            if file.suffix in (".toml", ".csv"):
                shutil.copyfile(file, presets / file.name)


# setuptools' own work files go under build/pip, beside (not into) the
# CMake build folder the README's commands use, and not into the sources.
PIP_WORK_DIR = SOURCE_DIR / "build" / "pip"


def setup_skybake():
    PIP_WORK_DIR.mkdir(parents=True, exist_ok=True)
    setup(ext_modules=[CMakeExtension("skybake._skybake")],
          cmdclass={"build_ext": BuildWithCMake, "build_py": BuildWithPresets},
          options={"build": {"build_base": str(PIP_WORK_DIR)}, "egg_info": {"egg_base": str(PIP_WORK_DIR)}})
