"""The sky irradiance lookup against the hemisphere sum of the sky radiance
lookups of the same bake, on a horizontal surface.

    PYTHONPATH=build/python /usr/bin/python3 scripts/irradiance_against_sky.py BAKE.exr

The irradiance table holds rows 4 km apart in altitude (the default); the sum
over the sky radiance lookups has no such rows, so where the two part is
where the table's rows and their blending miss the air between them
(docs/ERROR_VS_TIME.md, "The frontier"). The sum: 256 x 256 directions,
cosine weighted (midpoints in sin^2 of the zenith angle and in azimuth),
within about 0.1 % of the table on the ground by day. Printed per case:
irradiance / sum - 1 per channel, in percent.
"""
import sys

import numpy as np

import skybake

# (camera altitude m, sun zenith deg): the day at and between the rows, and
# cameras whose own sunset falls between two rows.
CASES = [(0.0, 30.0), (1000.0, 30.0), (1000.0, 60.0), (3000.0, 30.0), (44000.0, 96.5), (56000.0, 98.0)]
RINGS = 256
AZIMUTHS = 256


def hemisphere_sum(sky, camera, sun):
    u = (np.arange(RINGS) + 0.5) / RINGS  # sin^2 of the zenith angle: cosine weighted
    sin_t, cos_t = np.sqrt(u), np.sqrt(1.0 - u)
    phi = 2.0 * np.pi * (np.arange(AZIMUTHS) + 0.5) / AZIMUTHS
    ring, azimuth = np.meshgrid(np.arange(RINGS), phi, indexing="ij")
    views = np.stack([sin_t[ring] * np.cos(azimuth), sin_t[ring] * np.sin(azimuth), cos_t[ring]], -1).reshape(-1, 3)
    radiance, _ = sky.sky_radiance(np.broadcast_to(camera, views.shape), views, np.broadcast_to(sun, views.shape))
    return np.pi * np.asarray(radiance, dtype=float).mean(axis=0)


def main(path):
    sky = skybake.Sky(path)
    bottom = sky.atmosphere["bottom_radius_m"]
    print("altitude_m  sun_zenith_deg  irradiance / hemisphere sum - 1, % (" +
          ", ".join(f"{w:g} nm" for w in sky.wavelengths_nm) + ")")
    for altitude_m, sun_zenith_deg in CASES:
        camera = np.array([0.0, 0.0, bottom + altitude_m])
        z = np.radians(sun_zenith_deg)
        sun = np.array([np.sin(z), 0.0, np.cos(z)])
        _, table = sky.irradiance(camera, [0.0, 0.0, 1.0], sun)
        ratio = np.asarray(table, dtype=float) / hemisphere_sum(sky, camera, sun) - 1.0
        print(f"{altitude_m:10.0f}  {sun_zenith_deg:14.1f}  " + "  ".join(f"{100 * x:+7.2f}" for x in ratio))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
