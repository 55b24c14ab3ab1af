"""The compiled part of the skybake Python package for pip (pyproject.toml):
CMake builds it (baker/python/cmake_build.py)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "baker", "python"))
from cmake_build import setup_skybake  # noqa: E402

setup_skybake()
