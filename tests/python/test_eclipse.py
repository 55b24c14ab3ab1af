"""Solar eclipses from Python: the moon argument of the lookups against the
command line's eclipse queries (skybake validate --queries eclipse: sky rays
and rays to points), and a moon far from the sun leaving the plain lookups'
values bit for bit.

Run by CTest (python_module), with the environment test_skybake.py names.
"""
import csv
import os
import subprocess

import numpy as np
import pytest

import skybake

BINARY = os.environ["SKYBAKE_BINARY"]
BAKE = os.environ["SKYBAKE_TEST_BAKE"]


@pytest.fixture(scope="module")
def sky():
    return skybake.Sky(BAKE)


def direction(zenith_deg, azimuth_deg):
    t, p = np.radians(zenith_deg), np.radians(azimuth_deg)
    return np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])


def query_moon(camera, sun, separation_deg, radius_deg):
    """validate's eclipse query frame: the moon turned from the sun toward +y."""
    s = np.radians(separation_deg)
    moon_dir = sun * np.cos(s) + np.array([0.0, 1.0, 0.0]) * np.sin(s)
    return skybake.moon_seen_from(camera, moon_dir / np.linalg.norm(moon_dir), np.radians(radius_deg))


def test_sky_radiance_and_radiance_to_point_with_a_moon_are_the_command_lines(sky, tmp_path):
    details = tmp_path / "eclipse.csv"
    subprocess.run([BINARY, "validate", BAKE, "--queries", "eclipse", "--reference-samples", "0", "--no-cache",
                    "--details", str(details)], check=True, capture_output=True)
    bottom = sky.atmosphere["bottom_radius_m"]
    compared = 0
    to_points = 0
    with open(details) as f:
        for row in csv.DictReader(f):
            if row["kind"] != "radiance" or float(row["view_zenith_deg"]) > 90.0:
                continue  # sky rays: receivedRadiance is skyRadiance there
            camera = np.array([0.0, 0.0, bottom + float(row["altitude_m"])])
            sun = direction(float(row["sun_zenith_deg"]), 0.0)
            view = direction(float(row["view_zenith_deg"]), float(row["view_azimuth_deg"]))
            moon = query_moon(camera, sun, float(row["moon_separation_deg"]), float(row["moon_angular_radius_deg"]))
            distance_m = float(row["distance_m"])
            if distance_m > 0.0:
                radiance, _ = sky.radiance_to_point(camera, camera + view * distance_m, sun, moon=moon)
                to_points += 1
            else:
                radiance, _ = sky.sky_radiance(camera, view, sun, moon=moon)
            for c, nm in enumerate(sky.wavelengths_nm):
                expected = float(row[f"bake_{nm:g}"])
                # The details print 6 significant digits.
                assert radiance[c] == pytest.approx(expected, rel=1e-5, abs=1e-30), (row, nm)
            compared += 1
    assert compared >= 60
    assert to_points >= 40


def test_a_far_moon_changes_nothing_and_totality_is_dark(sky):
    bottom = sky.atmosphere["bottom_radius_m"]
    camera = np.array([0.0, 0.0, bottom])
    sun = direction(50.0, 0.0)
    views = np.stack([direction(z, a) for z, a in [(0, 0), (60, 90), (85, 180)]])
    plain, plain_t = sky.sky_radiance(camera, views, sun)
    far, far_t = sky.sky_radiance(camera, views, sun, moon=query_moon(camera, sun, 5.0, 0.28))
    np.testing.assert_array_equal(far, plain)
    np.testing.assert_array_equal(far_t, plain_t)
    total = query_moon(camera, sun, 0.0, 0.28)
    dark, _ = sky.sky_radiance(camera, views[0], sun, moon=total)
    # Totality's zenith: 1e-5 to 1e-2 of the day sky's, never black.
    assert np.all(dark > 1e-5 * plain[0]) and np.all(dark < 1e-2 * plain[0])
    sun_e, sky_e = sky.irradiance(camera, [0.0, 0.0, 1.0], sun, moon=total)
    assert np.all(sun_e == 0.0)
    assert np.all(sky_e > 0.0)
    with pytest.raises(skybake.BadInput):
        sky.sky_radiance(camera, views[0], sun, shadow_length_m=100.0, moon=total)
    with pytest.raises(skybake.BadInput):
        sky.radiance_to_point(camera, camera + 1000.0 * views[1], sun, shadow_length_m=100.0, moon=total)


def test_radiance_to_point_with_a_moon(sky):
    bottom = sky.atmosphere["bottom_radius_m"]
    camera = np.array([0.0, 0.0, bottom + 500.0])
    sun = direction(50.0, 0.0)
    points = camera + np.stack([d * 20e3 for d in (direction(80.0, 30.0), direction(60.0, 180.0))])
    plain, plain_t = sky.radiance_to_point(camera, points, sun)
    # A far moon: the plain values bit for bit; the rows one C++ call each.
    far, far_t = sky.radiance_to_point(camera, points, sun, moon=query_moon(camera, sun, 5.0, 0.28))
    np.testing.assert_array_equal(far, plain)
    np.testing.assert_array_equal(far_t, plain_t)
    # Totality: the transmittance unchanged, the air between far darker.
    dark, dark_t = sky.radiance_to_point(camera, points, sun, moon=query_moon(camera, sun, 0.0, 0.28))
    np.testing.assert_array_equal(dark_t, plain_t)
    assert np.all(dark < 0.1 * plain) and np.all(dark >= 0.0)
