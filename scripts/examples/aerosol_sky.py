#!/usr/bin/python3
"""How haze changes the sky through the day: bakes the built-in Earth
(skybake.presets.load("earth")) with 1x, 4x and 16x its aerosol (Mie)
scattering, each at two Mie asymmetries g, then plots the zenith radiance and
the horizon radiance toward the sun at 550 nm against the sun's zenith angle.

    python3 scripts/examples/aerosol_sky.py -o aerosol_sky.png   # skybake installed with pip
    PYTHONPATH=build/python /usr/bin/python3 scripts/examples/aerosol_sky.py -o aerosol_sky.png   # the build tree's

--small bakes at tiny table sizes (seconds; the test suite runs it so).
"""
import argparse
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import skybake

AEROSOL_FACTORS = [1.0, 4.0, 16.0]
MIE_G = [0.7, 0.85]
CAMERA_ALTITUDE_M = 2.0
SUN_ZENITH_DEG = np.linspace(0.0, 96.0, 97)
GREEN_NM = 550.0


def variant(base, factor, g, small):
    config = {key: (dict(value) if isinstance(value, dict) else value) for key, value in base.items()}
    config["name"] = f"earth_mie_x{factor:g}_g{g:g}"
    mie = config["mie"]
    mie["scattering"] = [v * factor for v in mie["scattering"]]
    mie["extinction"] = [v * factor for v in mie.get("extinction", mie["scattering"])]
    mie["phase_g"] = g
    if small:
        config["resolution"] = {"transmittance": [64, 16], "irradiance": [16, 8],
                                "scattering": {"r": 8, "mu": 32, "mu_s": 8, "nu": 4}}
        config["bake"] = {"orders": 3}
    return config


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-o", "--output", default="aerosol_sky.png", help="the plot (PNG)")
    parser.add_argument("--small", action="store_true", help="tiny tables: seconds instead of a minute")
    args = parser.parse_args()
    base = skybake.presets.load("earth")
    fig, (ax_zenith, ax_horizon) = plt.subplots(1, 2, figsize=(10, 4), sharex=True)
    with tempfile.TemporaryDirectory() as work:
        for factor in AEROSOL_FACTORS:
            for g in MIE_G:
                config = variant(base, factor, g, args.small)
                path = os.path.join(work, config["name"] + ".exr")
                skybake.bake(config, path)
                sky = skybake.Sky(path)
                channel = int(np.argmin(np.abs(np.array(sky.wavelengths_nm) - GREEN_NM)))
                # The sun at azimuth 0; the horizon view just above it, toward the sun.
                zenith, _ = sky.sky_radiance(altitude_m=CAMERA_ALTITUDE_M, view_zenith_deg=0.0,
                                             sun_zenith_deg=SUN_ZENITH_DEG)
                horizon, _ = sky.sky_radiance(altitude_m=CAMERA_ALTITUDE_M, view_zenith_deg=89.0,
                                              sun_zenith_deg=SUN_ZENITH_DEG)
                label = f"aerosol x{factor:g}, g = {g:g}"
                style = "-" if g == MIE_G[0] else "--"
                ax_zenith.semilogy(SUN_ZENITH_DEG, zenith[:, channel], style, label=label)
                ax_horizon.semilogy(SUN_ZENITH_DEG, horizon[:, channel], style, label=label)
                print(f"{label}: zenith {zenith[30, channel]:.4g}, horizon {horizon[30, channel]:.4g} "
                      f"W m^-2 sr^-1 nm^-1 with the sun 30 deg from the zenith", file=sys.stderr)
    for ax, title in ((ax_zenith, "zenith"), (ax_horizon, "horizon (view zenith 89 deg), toward the sun")):
        ax.set_title(f"{title}, {GREEN_NM:g} nm")
        ax.set_xlabel("sun zenith angle (deg)")
        ax.grid(True, which="both", alpha=0.3)
    ax_zenith.set_ylabel("radiance (W m$^{-2}$ sr$^{-1}$ nm$^{-1}$)")
    ax_horizon.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
