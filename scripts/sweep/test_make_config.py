"""make_config.py scales sizes however the base config spells its TOML.

Run: /usr/bin/python3 -m pytest scripts/sweep/test_make_config.py
(CTest: sweep_make_config), or with any Python that has tomli_w: the script
runs under the interpreter running the test. A regex-based version once
renamed a compact config (`{r=8, mu=32}`) to _x0.5 but left its sizes as
they were.
"""
import pathlib
import subprocess
import sys

try:
    import tomllib
except ModuleNotFoundError:  # Python before 3.11: the same parser as a package
    import tomli as tomllib

SCRIPT = pathlib.Path(__file__).with_name("make_config.py")
EARTH = pathlib.Path(__file__).parents[2] / "data_formats" / "presets" / "earth.toml"


def run(tmp_path, text, factor):
    base = tmp_path / "base.toml"
    base.write_text(text)
    out = tmp_path / "out.toml"
    subprocess.run([sys.executable, str(SCRIPT), str(base), str(factor), str(out)], check=True)
    with open(out, "rb") as f:
        return tomllib.load(f)


def test_compact_inline_tables_are_scaled(tmp_path):
    compact = ('name = "tiny"\n[resolution]\ntransmittance=[64,16]\nirradiance=[32,8]\n'
               "scattering = {r=8, mu=32, mu_s=16, nu=4}\n")
    got = run(tmp_path, compact, 0.5)
    assert got["name"] == "tiny_x0.5"
    assert got["resolution"]["transmittance"] == [32, 8]
    assert got["resolution"]["irradiance"] == [16, 4]
    assert got["resolution"]["scattering"] == {"r": 4, "mu": 16, "mu_s": 8, "nu": 2}


def test_minimums_and_even_mu(tmp_path):
    got = run(tmp_path, 'name = "m"\n[resolution]\nscattering={r=3,mu=6,mu_s=3,nu=3}\n', 0.5)
    s = got["resolution"]["scattering"]
    assert s["mu"] % 2 == 0 and s["mu"] >= 4
    assert min(s.values()) >= 2


def test_missing_sizes_get_defaults_scaled_and_the_rest_is_kept(tmp_path):
    got = run(tmp_path, EARTH.read_text().replace("[resolution]", "[old_resolution]"), 2)
    with open(EARTH, "rb") as f:
        earth = tomllib.load(f)
    assert got["resolution"]["scattering"] == {"r": 64, "mu": 256, "mu_s": 82, "nu": 32}
    assert got["resolution"]["transmittance"] == [512, 128]
    # Everything but the name and sizes is the base's, value for value.
    for key, value in earth.items():
        if key not in ("name", "resolution"):
            assert got[key] == value, key
