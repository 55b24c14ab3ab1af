"""The error of a bake by camera altitude, from `skybake validate --details`.

    build/baker/skybake validate BAKE.exr --details details.csv
    /usr/bin/python3 scripts/error_by_altitude.py details.csv

For the day (sun zenith below 80 deg) and low-sun (80 to 90 deg) bands, the
views above the horizontal and those below it, each camera altitude: the
mean and RMS of the relative error bake / reference - 1 per channel, in
percent, and the reference's own noise (RMS of its relative standard
error), over the values validate compares (reference at least 1e-5
W m^-2 sr^-1 nm^-1). A mean far from 0 beside a small noise is the bake's
bias (docs/ERROR_VS_TIME.md, "The frontier"). Rays to points are left out.
"""
import collections
import csv
import sys

import numpy as np

# validate's threshold for the day and low-sun bands: smaller values are
# not compared (their relative error says nothing).
SMALLEST_COMPARED = 1e-5


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    channels = [k[len("bake_"):] for k in rows[0] if k.startswith("bake_") and k[len("bake_")].isdigit()]
    errors = collections.defaultdict(lambda: {c: [] for c in channels})
    noise = collections.defaultdict(lambda: {c: [] for c in channels})
    for r in rows:
        if r["kind"] != "radiance" or float(r["distance_m"]) > 0.0:
            continue
        sun_zenith = float(r["sun_zenith_deg"])
        band = "day" if sun_zenith < 80.0 else "low_sun" if sun_zenith < 90.0 else None
        if band is None:
            continue
        half = "above" if float(r["view_zenith_deg"]) < 90.0 else "below"
        key = (band, half, float(r["altitude_m"]))
        for c in channels:
            reference = float(r["reference_" + c])
            if reference < SMALLEST_COMPARED:
                continue
            errors[key][c].append(float(r["bake_" + c]) / reference - 1.0)
            noise[key][c].append(float(r["reference_error_" + c]) / reference)
    print("band     views  altitude_m  " + "  ".join(f"{c} nm mean / rms (ref)" for c in channels))
    for key in sorted(errors):
        cells = []
        for c in channels:
            e, n = np.array(errors[key][c]), np.array(noise[key][c])
            cells.append(f"{100 * e.mean():+6.2f} / {100 * np.sqrt((e ** 2).mean()):5.2f} ({100 * np.sqrt((n ** 2).mean()):4.2f})"
                         if e.size else "          -          ")
        band, half, altitude = key
        print(f"{band:8s} {half:5s}  {altitude:10.0f}  " + "  ".join(cells))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
