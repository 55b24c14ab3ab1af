"""The Python module's view of a bake's channels: their kind and names, and
luminance over numpy arrays, for a wavelength bake and a colour bake.

Run by CTest (python_module) with the environment of test_skybake.py.
"""
import os
import subprocess

import numpy as np
import pytest

import skybake

BINARY = os.environ["SKYBAKE_BINARY"]
BAKE = os.environ["SKYBAKE_TEST_BAKE"]

# The CIE 1931 2 degree ybar summed over its 5 nm table (360 to 830 nm)
# times 5 nm: Y of a flat spectrum of 1 W m^-2 sr^-1 nm^-1
# (runtime/colour/spectral_to_xyz.h, ybarIntegral_nm).
YBAR_INTEGRAL_NM = 106.857
# 683 lm/W, the luminous efficacy that defines the candela.
LUMINOUS_EFFICACY = 683.0

COLOUR_CONFIG = """
name = "small_colour"
[channels]
wavelengths_nm = { min_nm = 400, max_nm = 700, count = 6 }
store = "cie_xyz"
[planet]
bottom_radius_m = 6360000.0
top_radius_m = 6420000.0
ground_albedo = { wavelengths_nm = [400, 700], values = [0.1, 0.1] }
[sun]
irradiance = { wavelengths_nm = [400, 550, 700], values = [1.7, 1.85, 1.45] }
[rayleigh]
scattering = { at_nm = 550, value = 13.558e-6, exponent = 4 }
density = [{ exp_term = 1.0, exp_scale = -1.25e-4 }]
[mie]
scattering = { at_nm = 550, value = 3.996e-6, angstrom_exponent = 0.0 }
phase_g = 0.8
density = [{ exp_term = 1.0, exp_scale = -8.333e-4 }]
[resolution]
transmittance = [64, 16]
irradiance = [16, 8]
scattering = { r = 8, mu = 32, mu_s = 8, nu = 4 }
[bake]
orders = 2
"""


@pytest.fixture(scope="module")
def colour_sky(tmp_path_factory):
    folder = tmp_path_factory.mktemp("colour")
    config = folder / "colour.toml"
    config.write_text(COLOUR_CONFIG)
    subprocess.run([BINARY, "bake", str(config), "-o", str(folder / "colour.exr"), "--threads", "1"],
                   check=True, capture_output=True)
    return skybake.Sky(folder / "colour.exr")


def test_a_wavelength_bake_names_its_wavelengths_and_weighs_a_flat_spectrum_as_cie_does():
    sky = skybake.Sky(BAKE)
    assert sky.channel_kind == "wavelengths"
    assert sky.channels == [f"{w:g}nm".replace(".", "p") for w in sky.wavelengths_nm]
    # A flat spectrum is integrated exactly by the piecewise-linear rule
    # (end values held): 683 times the ybar integral, to float weights
    # (1e-6 relative).
    flat = np.ones((2, 5, sky.channel_count), dtype=np.float32)
    np.testing.assert_allclose(sky.luminance(flat), LUMINOUS_EFFICACY * YBAR_INTEGRAL_NM, rtol=1e-5)


def test_a_colour_bake_holds_xyz_and_its_luminance_is_683_y(colour_sky):
    assert colour_sky.channel_kind == "cie_xyz"
    assert colour_sky.channels == ["X", "Y", "Z"]
    assert colour_sky.channel_count == 3
    assert colour_sky.wavelengths_nm == pytest.approx([400, 460, 520, 580, 640, 700])
    bottom = colour_sky.atmosphere["bottom_radius_m"]
    zenith = np.radians(np.linspace(0, 85, 10))
    views = np.stack([np.sin(zenith), np.zeros_like(zenith), np.cos(zenith)], axis=-1)
    sun = [np.sin(np.radians(40)), 0.0, np.cos(np.radians(40))]
    radiance, _ = colour_sky.sky_radiance([0, 0, bottom + 10], views, sun)
    assert radiance.shape == (10, 3) and np.all(radiance > 0)
    # The same float values times the same weights: equal to double rounding.
    np.testing.assert_allclose(colour_sky.luminance(radiance), LUMINOUS_EFFICACY * radiance[:, 1].astype(np.float64),
                               rtol=1e-12)


def test_luminance_refuses_the_wrong_number_of_channels(colour_sky):
    with pytest.raises(skybake.BadInput, match="3 channels"):
        colour_sky.luminance(np.ones((4, 5)))


def test_a_colour_bake_of_wavelengths_that_miss_the_colour_matching_functions_is_refused(tmp_path):
    # 700 to 780 nm, or one wavelength, would bake a grey sky: BadInput
    # naming the key and the span it needs, and an existing output kept.
    out = tmp_path / "o.exr"
    out.write_bytes(b"kept")
    for wavelengths, value in (("{ min_nm = 700, max_nm = 780, count = 3 }", "700 to 780 nm"),
                               ("[550]", r"550 nm \(one wavelength\)")):
        config = tmp_path / "c.toml"
        # Spectra that reach the wavelengths asked for, so that the span is
        # what is refused.
        text = COLOUR_CONFIG.replace("[400, 700]", "[380, 780]").replace("[400, 550, 700]", "[380, 550, 780]")
        config.write_text(text.replace("{ min_nm = 400, max_nm = 700, count = 6 }", wavelengths))
        with pytest.raises(skybake.BadInput,
                           match=rf"c\.toml: channels\.wavelengths_nm = {value}: .* from 420 nm or shorter to 640 nm or longer"):
            skybake.bake(str(config), str(out))
        assert out.read_bytes() == b"kept"
