"""What a user of the pip-installed skybake package does first, checked
(tests/python/pip_install_test.sh runs it with the virtual environment's
Python, outside the checkout):

    installed_package_check.py SKYBAKE_BINARY

- skybake.__version__ is the installed distribution's version;
- skybake.presets holds every preset, its spectrum files found from any
  directory, and a preset with one value changed bakes with that value;
- lookups by altitude and angles give the command line's `skybake lookup`
  values bit for bit, and so the vector form's (same doubles, same calls);
- Sky.render gives `skybake render`'s EXR pixels.
"""
import csv
import importlib.metadata
import io
import os
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

import skybake

BINARY = sys.argv[1]
# Small tables keep the bake to a second or two; what is checked (the
# changed value arrives, lookups and images agree with the command line
# reading the same file) does not depend on the table sizes.
SMALL_RESOLUTION = {"transmittance": [64, 16], "irradiance": [16, 8],
                    "scattering": {"r": 8, "mu": 32, "mu_s": 8, "nu": 4}}


def check(condition, message):
    if not condition:
        sys.exit(f"installed package check: {message}")


def cli_rows(command, bake, header, rows):
    text = header + "\n" + "".join(",".join(str(v) for v in row) + "\n" for row in rows)
    out = subprocess.run([BINARY, "lookup", command, bake, "--queries", "/dev/stdin"], input=text,
                         capture_output=True, text=True)
    check(out.returncode == 0, f"skybake lookup {command}: {out.stderr}")
    out = out.stdout
    return list(csv.DictReader(io.StringIO(out)))


def columns(rows, prefix):
    # %.9g round-trips a float32 exactly: these are the C++ values themselves.
    names = [k for k in rows[0] if k.startswith(prefix)]
    return np.array([[float(r[k]) for k in names] for r in rows], dtype=np.float32)


def main():
    check(skybake.__version__ == importlib.metadata.version("skybake"),
          f"__version__ {skybake.__version__} is not the distribution's {importlib.metadata.version('skybake')}")

    names = skybake.presets.names()
    for expected in ("earth", "earth_colour", "earth_hazy", "earth_spectral", "earth_twilight", "mars"):
        check(expected in names, f"preset {expected} missing from {names}")
    spectral = skybake.load_config("earth_spectral")
    sun_csv = pathlib.Path(spectral["sun"]["irradiance"]["spectrum_csv"])
    check(sun_csv.is_absolute() and sun_csv.is_file(), f"earth_spectral's solar spectrum {sun_csv} is not a file")

    with tempfile.TemporaryDirectory() as work:
        config = skybake.presets.load("earth")
        check(config["mie"]["phase_g"] != 0.7, "the test's changed value is the preset's own")
        config["mie"]["phase_g"] = 0.7
        config["resolution"] = SMALL_RESOLUTION
        bake = os.path.join(work, "earth_g07.exr")
        skybake.bake(config, bake)
        sky = skybake.Sky(bake)
        check(sky.atmosphere["mie_phase_g"] == 0.7, f"mie_phase_g {sky.atmosphere['mie_phase_g']}, not 0.7")
        check(repr(sky).startswith(f"skybake.Sky({bake!r}: 3 channels"), f"repr {sky!r}")

        # Day, low sun, twilight, looking down, from orbit, below the ground.
        queries = np.array([(0, 30, 0, 0), (1000, 30, 60, 90), (1000, 85, 89, 10), (50, 95, 80, 0),
                            (2000, 60, 120, 45), (400000, 40, 110, 0), (-100, 150, 90, 180)], dtype=float)
        altitude, sun_zenith, view_zenith, view_azimuth = queries.T
        rows = cli_rows("radiance", bake, "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg", queries)
        radiance, transmittance = sky.sky_radiance(altitude_m=altitude, view_zenith_deg=view_zenith,
                                                   view_azimuth_deg=view_azimuth, sun_zenith_deg=sun_zenith)
        np.testing.assert_array_equal(radiance, columns(rows, "radiance_"))
        np.testing.assert_array_equal(transmittance, columns(rows, "transmittance_"))
        bottom = sky.atmosphere["bottom_radius_m"]
        t, p = np.radians(view_zenith), np.radians(view_azimuth)
        views = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
        suns = np.stack([np.sin(np.radians(sun_zenith)), 0 * sun_zenith, np.cos(np.radians(sun_zenith))], axis=-1)
        cameras = np.stack([0 * altitude, 0 * altitude, bottom + np.maximum(altitude, 0.0)], axis=-1)
        vector_radiance, _ = sky.sky_radiance(cameras, views, suns)
        np.testing.assert_array_equal(radiance, vector_radiance)

        # 20 km along rays above the horizontal, 500 m along those looking
        # down (the point must stay above the ground, as the command line checks).
        distance = np.where(view_zenith < 90.0, 20000.0, 500.0)
        rows = cli_rows("radiance", bake, "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m",
                        np.column_stack([queries, distance]))
        to_point, _ = sky.radiance_to_point(altitude_m=altitude, view_zenith_deg=view_zenith,
                                            view_azimuth_deg=view_azimuth, distance_m=distance,
                                            sun_zenith_deg=sun_zenith)
        np.testing.assert_array_equal(to_point, columns(rows, "radiance_"))

        rows = cli_rows("irradiance", bake, "altitude_m,sun_zenith_deg", queries[:, :2])
        sun_irradiance, sky_irradiance = sky.irradiance(altitude_m=altitude, sun_zenith_deg=sun_zenith)
        np.testing.assert_array_equal(sun_irradiance, columns(rows, "sun_irradiance_"))
        np.testing.assert_array_equal(sky_irradiance, columns(rows, "sky_irradiance_"))

        # A sunset as a perspective view and an environment map with an
        # eclipse, small images: both renderers run the same C++ per pixel.
        for args, kwargs in ((["--projection", "perspective", "--view-elevation-deg", "5", "--size", "48x32"],
                              dict(projection="perspective", view_elevation_deg=5, size=(48, 32))),
                             (["--projection", "latlong", "--size", "64x32", "--moon", "0,40,0.28"],
                              dict(projection="latlong", size=(64, 32), moon=(0, 40, 0.28)))):
            image_path = os.path.join(work, "view.exr")
            subprocess.run([BINARY, "render", bake, "--altitude-m", "100", "--sun-zenith-deg", "50", *args,
                            "-o", image_path], check=True, capture_output=True)
            expected = oiio.ImageInput.open(image_path).read_image("float")
            image = sky.render(altitude_m=100, sun_zenith_deg=50, **kwargs)
            check(image.dtype == np.float32 and image.shape == expected.shape,
                  f"render gave {image.dtype} {image.shape}, skybake render {expected.shape}")
            np.testing.assert_array_equal(image, expected)
    print(f"installed package check: skybake {skybake.__version__} passed")


if __name__ == "__main__":
    main()
