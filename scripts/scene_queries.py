#!/usr/bin/env python3
"""Restrict validation queries to a scene's ranges, to validate a whole-domain
bake on the queries a narrowed bake answers (docs/LEAVE_OUT.md).

Usage: scene_queries.py DETAILS.csv OUT.csv --altitude-range LOW:HIGH
                        --sun-zenith-range LOW:HIGH [--points-only]
                        [--bottom-radius-m R]

DETAILS.csv is what `skybake validate BAKE --details DETAILS.csv` writes (its
radiance rows are the query set); OUT.csv gets the radiance queries whose
camera, sun and, for radiance to a point, point lie inside the ranges, in the
columns `skybake validate --queries` reads. The point's altitude follows from
the camera above the planet's pole, as in docs/QUERIES.md.
"""
import argparse
import csv
import math
import sys

QUERY_COLUMNS = ["altitude_m", "sun_zenith_deg", "view_zenith_deg", "view_azimuth_deg", "distance_m"]


def parse_range(text):
    try:
        low, high = (float(x) for x in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text}: must be LOW:HIGH")
    return low, high


def point_altitude_m(row, bottom_radius_m):
    altitude = float(row["altitude_m"])
    distance = float(row["distance_m"] or 0.0)
    if distance <= 0.0:
        return altitude
    r = bottom_radius_m + altitude
    cos_view = math.cos(math.radians(float(row["view_zenith_deg"])))
    return math.sqrt(r * r + distance * distance + 2.0 * r * distance * cos_view) - bottom_radius_m


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("details")
    p.add_argument("out")
    p.add_argument("--altitude-range", type=parse_range, required=True)
    p.add_argument("--sun-zenith-range", type=parse_range, required=True)
    p.add_argument("--points-only", action="store_true", help="keep only the rays to a point")
    p.add_argument("--bottom-radius-m", type=float, default=6360000.0)
    a = p.parse_args()
    with open(a.details, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("kind") == "radiance"]
    if not rows:
        sys.exit(f"{a.details}: no radiance rows (expected `skybake validate --details` output)")
    (alt_lo, alt_hi), (sun_lo, sun_hi) = a.altitude_range, a.sun_zenith_range

    def inside(row):
        altitudes = (float(row["altitude_m"]), point_altitude_m(row, a.bottom_radius_m))
        if a.points_only and not float(row["distance_m"] or 0.0) > 0.0:
            return False
        return all(alt_lo <= h <= alt_hi for h in altitudes) and sun_lo <= float(row["sun_zenith_deg"]) <= sun_hi

    kept = [r for r in rows if inside(r)]
    with open(a.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(QUERY_COLUMNS)
        for r in kept:
            w.writerow([r[c] or "0" for c in QUERY_COLUMNS])
    print(f"{a.out}: {len(kept)} of {len(rows)} radiance queries inside the ranges")


if __name__ == "__main__":
    main()
