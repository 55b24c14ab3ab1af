#!/usr/bin/env python3
"""Tabulates and plots a sweep: error against bake time.

Usage: plot_sweep.py OUT.csv OUT.png VALIDATE_1.json [VALIDATE_2.json ...]
Each validate JSON sits beside its bake's report sidecar (NAME.report.json),
which holds the bake time and file size. The error plotted is the RMS relative
error of sky radiance, worst channel, per sun band.
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The sun bands of `skybake validate` (validation_queries.h): civil
# ("twilight"), nautical and astronomical twilight. A band a validation lacks
# (one made before the deep-twilight bands, or a query set without those
# suns) reads NaN and is left out of the plot.
BANDS = ["day", "low_sun", "twilight", "nautical", "astronomical"]


def worst_rms(validation, quantity, band):
    for row in validation["errors"]:
        if row["quantity"] == quantity and row["band"] == band:
            return max(c["rms"] for c in row["channels"])
    return float("nan")


def main():
    out_csv, out_png, inputs = sys.argv[1], sys.argv[2], sys.argv[3:]
    rows = []
    for path in inputs:
        validation = json.load(open(path))
        sidecar_path = path.replace(".validate.json", ".report.json")
        sidecar = json.load(open(sidecar_path)) if os.path.exists(sidecar_path) else {}
        bake = sidecar.get("bake", {})
        row = {
            "bake": os.path.basename(path).replace(".validate.json", ""),
            "bake_seconds": bake.get("wall_seconds", float("nan")),
            "threads": bake.get("threads", ""),
            "file_mib": sidecar.get("file_size_bytes", float("nan")) / 2**20,
        }
        for band in BANDS:
            row[f"sky_rms_{band}_percent"] = 100 * worst_rms(validation, "sky_radiance", band)
        rows.append(row)
    rows.sort(key=lambda r: r["bake_seconds"])
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for band in BANDS:
        if all(r[f"sky_rms_{band}_percent"] != r[f"sky_rms_{band}_percent"] for r in rows):
            continue  # NaN throughout: no queries in this band
        ax.plot([r["bake_seconds"] for r in rows], [r[f"sky_rms_{band}_percent"] for r in rows], "o-", label=band)
    for r in rows:
        # Beside the first band the validation has (day, in a sweep).
        finite = [r[f"sky_rms_{band}_percent"] for band in BANDS if r[f"sky_rms_{band}_percent"] > 0]
        if finite:
            ax.annotate(r["bake"], (r["bake_seconds"], finite[0]), fontsize=7, textcoords="offset points",
                        xytext=(4, 4))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("bake time (s)")
    ax.set_ylabel("sky radiance RMS relative error, worst channel (%)")
    ax.set_title("skybake: error against bake time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title="sun band")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)


if __name__ == "__main__":
    main()
