"""How far bakes are from a reference bake: sky radiance, ground rays, rays to
points and sky irradiance, sun band by sun band.

    PYTHONPATH=build/python /usr/bin/python3 scripts/bake_difference.py REFERENCE.exr BAKE.exr [BAKE.exr ...]

REFERENCE is typically the same atmosphere on finer tables, so the figures
are the error of each BAKE's texels (docs/MEASUREMENTS.md, "Sizes"). The
grid: cameras at 0, 1, 5, 10, 30 and 59 km; 25 suns from 10 to 107.9 deg
zenith; views at 13 zenith angles from 0 to 175 deg and 5 azimuths from the
sun's (0 to 180 deg). A view that meets the ground is a ground ray; rays to
points end 2, 10 and 50 km along the sky views; the sky irradiance is on a
horizontal surface at each camera. Printed per quantity and band (day < 80,
low sun 80 to 90, civil to 96, nautical to 102, astronomical to 108 deg):
the RMS and mean relative difference, per channel, in percent, of the values
the reference does not give as 0.
"""
import sys

import numpy as np

import skybake

BANDS = {"day": (0, 80), "low_sun": (80, 90), "civil": (90, 96), "nautical": (96, 102), "astronomical": (102, 108)}
SUN_ZENITHS_DEG = [10, 40, 70, 80, 85, 88, 90.5, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105,
                   106, 107, 107.9]
ALTITUDES_M = [0, 1000, 5000, 10000, 30000, 59000]
VIEW_ZENITHS_DEG = [0, 20, 40, 60, 75, 85, 88, 89.5, 92, 100, 120, 150, 175]
VIEW_AZIMUTHS_DEG = [0, 45, 90, 135, 180]
POINT_DISTANCES_M = [2000, 10000, 50000]


def direction(zenith_deg, azimuth_deg):
    t, p = np.radians(np.asarray(zenith_deg, float)), np.radians(np.asarray(azimuth_deg, float))
    return np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)


def grid(bottom_m):
    a, s, vz, va = (x.ravel() for x in np.meshgrid(ALTITUDES_M, SUN_ZENITHS_DEG, VIEW_ZENITHS_DEG,
                                                   VIEW_AZIMUTHS_DEG, indexing="ij"))
    camera = np.stack([np.zeros_like(a, float), np.zeros_like(a, float), bottom_m + a], axis=-1)
    view = direction(vz, va)
    # A view meets the ground where the ray's lowest point lies below the bottom radius, ahead of the camera.
    r = camera[:, 2]
    mu = view[:, 2]
    hits_ground = (mu < 0) & (r * r * (mu * mu - 1.0) + bottom_m * bottom_m >= 0)
    # One horizontal surface per camera and sun for the irradiance (the grid repeats them for every view).
    surfaces = (vz == VIEW_ZENITHS_DEG[0]) & (va == VIEW_AZIMUTHS_DEG[0])
    return camera, view, direction(s, 0.0), s, hits_ground, surfaces


def lookups(sky, camera, view, sun, hits_ground, surfaces):
    radiance = np.asarray(sky.sky_radiance(camera, view, sun)[0], float)
    sky_views = ~hits_ground
    points, point_suns = [], []
    for d in POINT_DISTANCES_M:
        points.append(camera[sky_views] + d * view[sky_views])
        point_suns.append(sun[sky_views])
    to_point = np.asarray(sky.radiance_to_point(np.concatenate([camera[sky_views]] * len(POINT_DISTANCES_M)),
                                                np.concatenate(points), np.concatenate(point_suns))[0], float)
    up = np.zeros_like(camera[surfaces])
    up[:, 2] = 1.0
    irradiance = np.asarray(sky.irradiance(camera[surfaces], up, sun[surfaces])[1], float)
    return radiance, to_point, irradiance


def report(name, got, expected, sun_zenith, channels):
    print(f"  {name}")
    for band, (lo, hi) in BANDS.items():
        m = (sun_zenith >= lo) & (sun_zenith < hi) & np.all(expected > 0, axis=1)
        if not m.any():
            continue
        relative = got[m] / expected[m] - 1.0
        rms = " / ".join(f"{100 * np.sqrt(np.mean(relative[:, c] ** 2)):.2f}" for c in range(len(channels)))
        mean = " / ".join(f"{100 * np.mean(relative[:, c]):+.2f}" for c in range(len(channels)))
        print(f"    {band:13s} rms {rms}   mean {mean}   ({m.sum()})")


def main(reference_path, bake_paths):
    reference = skybake.Sky(reference_path)
    camera, view, sun, sun_zenith, hits_ground, surfaces = grid(reference.atmosphere["bottom_radius_m"])
    expected = lookups(reference, camera, view, sun, hits_ground, surfaces)
    sky_views = ~hits_ground
    point_suns = np.concatenate([sun_zenith[sky_views]] * len(POINT_DISTANCES_M))
    channels = reference.channels
    for path in bake_paths:
        got = lookups(skybake.Sky(path), camera, view, sun, hits_ground, surfaces)
        print(f"{path} against {reference_path} ({', '.join(map(str, channels))}), %:")
        report("sky radiance, sky views", got[0][sky_views], expected[0][sky_views], sun_zenith[sky_views], channels)
        report("sky radiance, ground rays", got[0][hits_ground], expected[0][hits_ground], sun_zenith[hits_ground],
               channels)
        report("radiance to points", got[1], expected[1], point_suns, channels)
        report("sky irradiance", got[2], expected[2], sun_zenith[surfaces], channels)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
