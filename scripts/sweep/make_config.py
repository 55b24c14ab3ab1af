#!/usr/bin/env python3
"""Writes a copy of a skybake config with its table sizes scaled.

Usage: make_config.py BASE.toml FACTOR OUT.toml
Every size is multiplied by FACTOR and rounded (scattering mu kept even, every
size at least 2, mu at least 4) and the name gets the suffix _x<FACTOR>. Sizes
the base leaves out get data_formats/CONFIG.md's defaults first, so they are
scaled too. The config is read and written as TOML (tomllib, or the tomli
package before Python 3.11, and tomli_w), so any valid spelling works
(`{r=8, mu=32}` as well as `{ r = 8, mu = 32 }`); the values of the rest of
the config are copied unchanged, its comments are not.
"""
import sys

try:
    import tomllib
except ModuleNotFoundError:  # Python before 3.11: the same parser as a package
    import tomli as tomllib

import tomli_w

# The defaults of data_formats/CONFIG.md, used for sizes the base leaves out.
DEFAULT_RESOLUTION = {
    "transmittance": [256, 64],
    "irradiance": [64, 16],
    "scattering": {"r": 32, "mu": 128, "mu_s": 41, "nu": 16},
}
# The smallest sizes the baker accepts: every axis needs two samples to
# interpolate, and the view zenith (mu) two per half (above and below the
# horizon), kept even so that the horizon falls between samples.
MIN_SIZE = 2
MIN_MU = 4


def scaled(value, factor, minimum=MIN_SIZE, even=False):
    s = max(minimum, round(value * factor))
    if even and s % 2:
        s += 1
    return s


def scale_config(config, factor):
    """The config (a dict as tomllib reads it) with its sizes and name scaled."""
    resolution = config.setdefault("resolution", {})
    for key in ("transmittance", "irradiance"):
        pair = resolution.get(key, DEFAULT_RESOLUTION[key])
        resolution[key] = [scaled(int(v), factor) for v in pair]
    scattering = {**DEFAULT_RESOLUTION["scattering"], **resolution.get("scattering", {})}
    resolution["scattering"] = {
        axis: scaled(int(v), factor, MIN_MU if axis == "mu" else MIN_SIZE, even=axis == "mu")
        for axis, v in scattering.items()
    }
    if "name" in config:
        config["name"] = f"{config['name']}_x{factor:g}"
    return config


def main():
    base, factor, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    with open(base, "rb") as f:
        config = tomllib.load(f)
    with open(out, "wb") as f:
        tomli_w.dump(scale_config(config, factor), f)


if __name__ == "__main__":
    main()
