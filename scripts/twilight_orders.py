"""How far bakes are from a reference bake, sun band by sun band.

    PYTHONPATH=build/python /usr/bin/python3 scripts/twilight_orders.py REFERENCE.exr BAKE.exr [BAKE.exr ...]

Typically REFERENCE is the same config baked with many orders (`skybake bake
--orders 12`) and each BAKE with fewer, so the figures are the error of the
orders left out and of the tail that stands in for them (docs/MEASUREMENTS.md,
"Orders"). The grid: cameras at 0, 1, 10 and 30 km; 25 suns from 10 to 107.9
deg zenith; views at zenith angles 0, 30, 60, 80, 88, 90 and 120 deg toward,
across and away from the sun. Printed per band (day < 80, low sun 80 to 90,
civil to 96, nautical to 102, astronomical to 108 deg): the RMS and mean
relative difference of the sky radiance, per channel.
"""
import sys

import numpy as np

import skybake

BANDS = {"day": (0, 80), "low_sun": (80, 90), "civil": (90, 96), "nautical": (96, 102), "astronomical": (102, 108)}
SUN_ZENITHS_DEG = [10, 40, 70, 80, 85, 88, 90.5, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105,
                   106, 107, 107.9]
ALTITUDES_M = [0, 1000, 10000, 30000]
VIEW_ZENITHS_DEG = [0, 30, 60, 80, 88, 90, 120]
VIEW_AZIMUTHS_DEG = [0, 90, 180]


def direction(zenith_deg, azimuth_deg):
    t, p = np.radians(zenith_deg), np.radians(azimuth_deg)
    return np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])


def main(reference_path, bake_paths):
    reference = skybake.Sky(reference_path)
    bottom_m = reference.atmosphere["bottom_radius_m"]
    rows = [(a, s, vz, va) for a in ALTITUDES_M for s in SUN_ZENITHS_DEG for vz in VIEW_ZENITHS_DEG
            for va in VIEW_AZIMUTHS_DEG]
    camera = np.array([[0.0, 0.0, bottom_m + a] for a, _, _, _ in rows])
    sun = np.array([direction(s, 0.0) for _, s, _, _ in rows])
    view = np.array([direction(vz, va) for _, _, vz, va in rows])
    sun_zenith = np.array([s for _, s, _, _ in rows])
    expected = np.asarray(reference.sky_radiance(camera, view, sun)[0], float)
    channels = reference.channels
    for path in bake_paths:
        got = np.asarray(skybake.Sky(path).sky_radiance(camera, view, sun)[0], float)
        print(f"{path} against {reference_path} ({', '.join(map(str, channels))}), sky radiance, %:")
        for band, (lo, hi) in BANDS.items():
            m = (sun_zenith >= lo) & (sun_zenith < hi) & (expected[:, 0] > 0)
            relative = got[m] / expected[m] - 1.0
            rms = " / ".join(f"{100 * np.sqrt(np.mean(relative[:, c] ** 2)):.2f}" for c in range(len(channels)))
            mean = " / ".join(f"{100 * np.mean(relative[:, c]):+.2f}" for c in range(len(channels)))
            print(f"  {band:13s} rms {rms}   mean {mean}   ({m.sum()} views)")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
