"""The sky irradiance lookup against the hemisphere sum of the sky radiance
lookups of the same bake, on a horizontal surface.

    PYTHONPATH=build/python /usr/bin/python3 scripts/irradiance_against_sky.py BAKE.exr
    PYTHONPATH=build/python /usr/bin/python3 scripts/irradiance_against_sky.py --dense BAKE.exr [STEP_M]

The irradiance table holds 16 rows in altitude (the default; cosine spaced,
dense near the ground and the top); the sum over the sky radiance lookups
has no such rows, so where the two part is where the table's rows and
their blending miss the air between them
(docs/ERROR_VS_TIME.md, "The frontier"). The sum: 256 x 256 directions,
cosine weighted (midpoints in sin^2 of the zenith angle and in azimuth),
within about 0.1 % of the table on the ground by day. Printed per case:
irradiance / sum - 1 per channel, in percent.

--dense sweeps every altitude from the ground to the top every STEP_M
(default 500 m) and
suns from the zenith to 96 deg (every 5 deg by day, every 0.5 deg from 80
deg on), with the sums of 64 x 64 and 128 x 128 directions extrapolated to
infinitely many (2 S_128 - S_64: the midpoint sum's error near the sun's
aureole falls as 1 / n, and this is within 0.1 % of 2 S_256 - S_128 on the
default bake from the ground to 30 km and into civil twilight), and prints, per altitude band and sun band (day < 80 deg, low sun to
90, civil twilight to 96), the largest |irradiance / sum - 1| over the
channels and where it is. Sums below 1e-5 W m^-2 nm^-1 (validate's floor
for radiance, times pi) are left out. The sum carries the radiance
lookups' own error, which the reference (`skybake validate --queries` with a
CSV of altitude_m and sun_zenith_deg) does not.
"""
import sys

import numpy as np

import skybake

# (camera altitude m, sun zenith deg): the day at and between the rows, and
# cameras whose own sunset falls between two rows.
CASES = [(0.0, 30.0), (1000.0, 30.0), (1000.0, 60.0), (3000.0, 30.0), (44000.0, 96.5), (56000.0, 98.0)]
RINGS = 256
AZIMUTHS = 256
DENSE_DIRECTIONS = (64, 128)  # the two sums extrapolated
DENSE_ALTITUDE_STEP_M = 500.0
DENSE_SUNS_DEG = np.concatenate([np.arange(0.0, 80.0, 5.0), np.arange(80.0, 96.01, 0.5)])
SUN_BANDS = {"day": (0.0, 80.0), "low_sun": (80.0, 90.0), "civil": (90.0, 96.01)}
ALTITUDE_BANDS_KM = [(0, 5), (5, 20), (20, 45), (45, 55), (55, None)]
SMALLEST_COMPARED = np.pi * 1e-5


def hemisphere_sum(sky, camera, sun, rings=RINGS, azimuths=AZIMUTHS):
    u = (np.arange(rings) + 0.5) / rings  # sin^2 of the zenith angle: cosine weighted
    sin_t, cos_t = np.sqrt(u), np.sqrt(1.0 - u)
    phi = 2.0 * np.pi * (np.arange(azimuths) + 0.5) / azimuths
    ring, azimuth = np.meshgrid(np.arange(rings), phi, indexing="ij")
    views = np.stack([sin_t[ring] * np.cos(azimuth), sin_t[ring] * np.sin(azimuth), cos_t[ring]], -1).reshape(-1, 3)
    radiance, _ = sky.sky_radiance(np.broadcast_to(camera, views.shape), views, np.broadcast_to(sun, views.shape))
    return np.pi * np.asarray(radiance, dtype=float).mean(axis=0)


def table_over_sum(sky, altitude_m, sun_zenith_deg, rings=RINGS, azimuths=AZIMUTHS):
    """The table's irradiance, the hemisphere sum, per channel."""
    camera = np.array([0.0, 0.0, sky.atmosphere["bottom_radius_m"] + altitude_m])
    z = np.radians(sun_zenith_deg)
    sun = np.array([np.sin(z), 0.0, np.cos(z)])
    _, table = sky.irradiance(camera, [0.0, 0.0, 1.0], sun)
    return np.asarray(table, dtype=float), hemisphere_sum(sky, camera, sun, rings, azimuths)


def cases(path):
    sky = skybake.Sky(path)
    print("altitude_m  sun_zenith_deg  irradiance / hemisphere sum - 1, % (" +
          ", ".join(f"{w:g} nm" for w in sky.wavelengths_nm) + ")")
    for altitude_m, sun_zenith_deg in CASES:
        table, total = table_over_sum(sky, altitude_m, sun_zenith_deg)
        ratio = table / total - 1.0
        print(f"{altitude_m:10.0f}  {sun_zenith_deg:14.1f}  " + "  ".join(f"{100 * x:+7.2f}" for x in ratio))


def dense(path, step_m):
    sky = skybake.Sky(path)
    top_m = sky.atmosphere["top_radius_m"] - sky.atmosphere["bottom_radius_m"]
    altitudes = np.arange(0.0, top_m - 1.0, step_m)
    # worst[(altitude band, sun band)] = (|error|, altitude, sun, channel)
    worst = {}
    for altitude_m in altitudes:
        km = altitude_m / 1000.0
        a_band = next(b for b in ALTITUDE_BANDS_KM if km >= b[0] and (b[1] is None or km < b[1]))
        for sun in DENSE_SUNS_DEG:
            s_band = next(name for name, (lo, hi) in SUN_BANDS.items() if lo <= sun < hi)
            coarse, fine = (table_over_sum(sky, altitude_m, sun, n, n) for n in DENSE_DIRECTIONS)
            table, total = fine[0], 2.0 * fine[1] - coarse[1]
            for c in range(len(total)):
                if not total[c] >= SMALLEST_COMPARED:
                    continue
                error = abs(table[c] / total[c] - 1.0)
                key = (a_band, s_band)
                if key not in worst or error > worst[key][0]:
                    worst[key] = (error, altitude_m, sun, c)
    names = sky.channels
    print("altitude_km  sun_band  largest_%  at_altitude_km  at_sun_zenith_deg  channel")
    for a_band in ALTITUDE_BANDS_KM:
        label = f"{a_band[0]}-{a_band[1] if a_band[1] is not None else f'{top_m / 1000:g}'}"
        for s_band in SUN_BANDS:
            if (a_band, s_band) not in worst:
                continue
            error, altitude_m, sun, c = worst[(a_band, s_band)]
            print(f"{label:11s}  {s_band:8s}  {100 * error:9.2f}  {altitude_m / 1000:14.1f}  {sun:17.1f}  {names[c]}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--dense"] and len(args) in (2, 3):
        dense(args[1], float(args[2]) if len(args) == 3 else DENSE_ALTITUDE_STEP_M)
    elif len(args) == 1 and not args[0].startswith("-"):
        cases(args[0])
    else:
        sys.exit(__doc__)
