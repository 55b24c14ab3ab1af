#!/usr/bin/python3
"""Error of a bake against the reference per eclipse case, from the CSV that
`skybake validate --queries eclipse --details FILE` writes: for each moon
(separation, angular radius), camera altitude and kind of ray (views of the
sky and the ground, or rays to points), the RMS relative error of the
radiance over the rays (values below 1e-5 W m^-2 sr^-1 nm^-1 skipped, as
validate does), and the zenith view's bake / reference ratio (views only);
for the sky irradiance queries (kind "irradiance", one per moon and
altitude), its error and its bake / reference ratio in the same columns.

Usage: /usr/bin/python3 scripts/eclipse_errors.py DETAILS.csv
"""
import csv
import math
import sys
from collections import defaultdict

SMALLEST = 1e-5


def main(path):
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if r["kind"] in ("radiance", "sky_irradiance")]
    channels = [k[len("bake_"):] for k in rows[0] if k.startswith("bake_")]
    groups = defaultdict(list)
    for r in rows:
        if r["kind"] == "sky_irradiance":
            rays = "irradiance"
        else:
            rays = "points" if float(r["distance_m"]) > 0.0 else "views"
        groups[(float(r["moon_separation_deg"]), float(r["moon_angular_radius_deg"]), float(r["altitude_m"]),
                rays)].append(r)
    print("moon_sep_deg moon_radius_deg altitude_m rays " +
          " ".join(f"rms_{c}_%" for c in channels) + " " + " ".join(f"zenith_ratio_{c}" for c in channels))
    for key in sorted(groups):
        rms = []
        zen = []
        for c in channels:
            errs = []
            for r in groups[key]:
                ref, bake = float(r[f"reference_{c}"]), float(r[f"bake_{c}"])
                if ref >= SMALLEST:
                    errs.append((bake - ref) / ref)
                if r["kind"] == "sky_irradiance" or float(r["view_zenith_deg"]) == 0.0:
                    zen.append(f"{bake / ref:.3f}" if ref > 0 else "nan")
            rms.append(f"{100 * math.sqrt(sum(e * e for e in errs) / len(errs)):.2f}" if errs else "-")
        print(f"{key[0]} {key[1]} {key[2]:.0f} {key[3]} " + " ".join(rms) + " " + " ".join(zen))


if __name__ == "__main__":
    main(sys.argv[1])
