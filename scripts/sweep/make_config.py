#!/usr/bin/env python3
"""Writes a copy of a skybake config with its table sizes scaled.

Usage: make_config.py BASE.toml FACTOR OUT.toml
Every size is multiplied by FACTOR and rounded (scattering mu kept even, every
size at least 2, mu at least 4); the rest of the config is copied unchanged.
"""
import re
import sys


def scaled(value, factor, minimum=2, even=False):
    s = max(minimum, round(value * factor))
    if even and s % 2:
        s += 1
    return s


def main():
    base, factor, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    text = open(base).read()
    if not re.search(r"^\[resolution\]", text, flags=re.M):
        # The defaults of data_formats/CONFIG.md, written out so they can be scaled.
        defaults = ("\n[resolution]\ntransmittance = [256, 64]\nirradiance = [64, 16]\n"
                    "scattering = { r = 32, mu = 128, mu_s = 32, nu = 8 }\n")
        text = text.replace("\n[bake]", defaults + "\n[bake]", 1) if "\n[bake]" in text else text + defaults
    pair = r"(\s*=\s*\[)\s*(\d+)\s*,\s*(\d+)\s*\]"

    def scale_pair(m):
        return f"{m.group(1)}{m.group(2)}{scaled(int(m.group(3)), factor)}, {scaled(int(m.group(4)), factor)}]"

    text = re.sub(r"^(transmittance|irradiance)" + pair, scale_pair, text, flags=re.M)

    def scale_axis(m):
        minimum = 4 if m.group(1) == "mu" else 2
        return f"{m.group(1)} = {scaled(int(m.group(2)), factor, minimum, even=m.group(1) == 'mu')}"

    text = re.sub(r"\b(r|mu|mu_s|nu) = (\d+)", scale_axis, text)
    text = re.sub(r'^name = "(.*)"', lambda m: f'name = "{m.group(1)}_x{factor:g}"', text, flags=re.M)
    open(out, "w").write(text)


if __name__ == "__main__":
    main()
