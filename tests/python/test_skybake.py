"""The Python module against the C++ runtime and the command line.

Run by CTest (python_module): SKYBAKE_BINARY names the skybake command,
SKYBAKE_TEST_BAKE a default-size Earth bake, SKYBAKE_SOURCE_DIR the
checkout; PYTHONPATH holds the build's python/ folder.
"""
import concurrent.futures
import copy
import csv
import json
import io
import os
import subprocess
import tomllib

import numpy as np
import pytest

import skybake

BINARY = os.environ["SKYBAKE_BINARY"]
BAKE = os.environ["SKYBAKE_TEST_BAKE"]
SOURCE = os.environ["SKYBAKE_SOURCE_DIR"]
SMALL_EARTH = os.path.join(SOURCE, "tests", "cli", "small_earth.toml")


@pytest.fixture(scope="module")
def sky():
    return skybake.Sky(BAKE)


def direction(zenith_deg, azimuth_deg):
    """The command line's local frame (data_formats/queries/local_frame.h)."""
    t, p = np.broadcast_arrays(np.radians(zenith_deg), np.radians(azimuth_deg))
    return np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)


# Queries in the command line's columns: altitude_m, sun_zenith_deg,
# view_zenith_deg, view_azimuth_deg, distance_m (0: the whole ray). Day,
# low sun, twilight, looking down, from orbit, and points at a distance.
QUERIES = [
    (0, 30, 0, 0, 0), (1000, 30, 60, 90, 0), (1000, 85, 89, 10, 0), (50, 95, 80, 0, 0),
    (2000, 60, 120, 45, 0), (400000, 40, 110, 0, 0), (10, 45, 80, 30, 20000), (3000, 96, 95, 180, 5000),
    # Suns below the lowest baked one (night continuation) and a camera below the ground.
    (0, 112, 0, 0, 0), (-100, 150, 90, 180, 0), (1000, 180, 0, 0, 0), (10, 110, 80, 0, 20000),
]


def cli_lookup(queries):
    text = "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n"
    text += "".join(",".join(str(v) for v in q) + "\n" for q in queries)
    out = subprocess.run([BINARY, "lookup", "radiance", BAKE, "--queries", "/dev/stdin"], input=text,
                         capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    names = [k for k in rows[0] if k.startswith("radiance_")]
    tnames = [k for k in rows[0] if k.startswith("transmittance_")]
    # %.9g round-trips a float32 exactly, so these are the C++ values themselves.
    radiance = np.array([[float(r[k]) for k in names] for r in rows], dtype=np.float32)
    transmittance = np.array([[float(r[k]) for k in tnames] for r in rows], dtype=np.float32)
    return radiance, transmittance


def test_lookups_equal_the_command_lines_bit_for_bit(sky):
    # The command line and the module call the same Sky lookups on the same
    # doubles: the float32 results must be identical, not merely close.
    expected_radiance, expected_transmittance = cli_lookup(QUERIES)
    bottom = sky.atmosphere["bottom_radius_m"]
    for q, er, et in zip(QUERIES, expected_radiance, expected_transmittance):
        altitude, sun_zenith, view_zenith, view_azimuth, distance = q
        camera = np.array([0.0, 0.0, bottom + altitude])
        view = direction(view_zenith, view_azimuth)
        sun = direction(sun_zenith, 0.0)
        if distance > 0:
            r, t = sky.radiance_to_point(camera, camera + view * distance, sun)
        else:
            r, t = sky.sky_radiance(camera, view, sun)
        np.testing.assert_array_equal(r, er, err_msg=str(q))
        np.testing.assert_array_equal(t, et, err_msg=str(q))


def test_sky_darkens_to_the_night_floor_as_the_sun_sinks_to_the_nadir(sky):
    # As the C++ runtime (tests/runtime/night_sky_test.cpp): every sun is
    # valid, brightness never rises as the sun sinks (1e-5: float rounding of
    # the sums), and at the nadir it is the night floor, 0.
    bottom = sky.atmosphere["bottom_radius_m"]
    suns = direction(np.linspace(90, 180, 361), 0.0)
    camera = [0.0, 0.0, bottom + 10.0]
    zenith, _ = sky.sky_radiance(camera, [0.0, 0.0, 1.0], suns)
    _, diffuse = sky.irradiance(camera, [0.0, 0.0, 1.0], suns)
    for values in (zenith, diffuse):
        assert np.all(np.isfinite(values)) and np.all(values >= 0)
        assert np.all(values[1:] <= values[:-1] * (1 + 1e-5))
        assert np.all(values[-1] == 0)
    assert sky.baked_ranges["sun_zenith_max_deg"] == 180.0


def test_shapes_broadcast_and_results_are_float32_per_channel(sky):
    bottom = sky.atmosphere["bottom_radius_m"]
    views = direction(np.linspace(0, 180, 7)[:, None], np.linspace(0, 360, 5)[None, :])  # (7, 5, 3)
    r, t = sky.sky_radiance([0, 0, bottom + 100], views, direction(30, 0))
    assert r.shape == (7, 5, sky.channel_count) and t.shape == r.shape
    assert r.dtype == np.float32 and t.dtype == np.float32
    assert np.all(np.isfinite(r)) and np.all(r >= 0) and np.all((t >= 0) & (t <= 1))
    # Each entry is that row's own lookup.
    one, _ = sky.sky_radiance([0, 0, bottom + 100], views[3, 2], direction(30, 0))
    np.testing.assert_array_equal(r[3, 2], one)
    sun, diffuse = sky.irradiance([[0, 0, bottom]] * 4, [0, 0, 1], direction([0, 30, 60, 89], 0))
    assert sun.shape == (4, sky.channel_count) and np.all(np.diff(sun[:, 1]) < 0)  # lower sun, less direct light
    assert np.all(diffuse > 0)
    assert sky.transmittance([0, 0, bottom + 10], [0, 0, bottom + 20000]).shape == (sky.channel_count,)
    assert sky.solar_radiance().shape == (sky.channel_count,)
    assert sky.wavelengths_nm == [680.0, 550.0, 440.0]
    assert sky.baked_ranges["sun_zenith_max_deg"] == pytest.approx(180.0)  # every sun: the night continuation
    assert sky.outputs == {"sky_radiance": True, "radiance_to_points": True, "ground_irradiance": True}


def test_many_rows_over_threads_and_many_callers_equal_one_by_one(sky):
    bottom = sky.atmosphere["bottom_radius_m"]
    rng = np.random.default_rng(7)
    views = rng.normal(size=(20000, 3))  # enough rows to be split over threads
    views /= np.linalg.norm(views, axis=-1, keepdims=True)
    camera, sun = [0, 0, bottom + 500], direction(80, 0)
    whole, _ = sky.sky_radiance(camera, views, sun)
    sample = rng.choice(len(views), 50, replace=False)
    for i in sample:
        np.testing.assert_array_equal(whole[i], sky.sky_radiance(camera, views[i], sun)[0])
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: sky.sky_radiance(camera, views, sun)[0], range(4)))
    for r in results:
        np.testing.assert_array_equal(r, whole)


def test_bad_input_raises_badinput_with_the_command_lines_message(sky, tmp_path):
    with pytest.raises(skybake.BadInput, match="no such bake file"):
        skybake.Sky(tmp_path / "missing.exr")
    garbage = tmp_path / "garbage.exr"
    garbage.write_bytes(b"not an exr" * 100)
    with pytest.raises(ValueError):
        skybake.Sky(garbage)
    with pytest.raises(skybake.BadInput, match="last axis of length 3"):
        sky.sky_radiance([0, 0, 1], [0, 1], [0, 0, 1])
    with pytest.raises(skybake.BadInput, match="broadcast"):
        sky.sky_radiance(np.zeros((2, 3)), np.zeros((3, 3)), [0, 0, 1])
    config = tomllib.load(open(SMALL_EARTH, "rb"))
    config["mie"]["phase_g"] = 1.5
    with pytest.raises(skybake.BadInput, match="mie.phase_g"):
        skybake.bake(config, tmp_path / "x.exr")
    assert not (tmp_path / "x.exr").exists()


def unchanged(path, before):
    """Whether the file at `path` still holds the bytes `before`."""
    return path.read_bytes() == before


def test_arguments_are_checked_as_the_command_line_checks_them(tmp_path):
    # Thread counts libgomp cannot start (10**5 crashed it, 10**9 aborted it),
    # negative ones, and non-ints: BadInput before anything runs.
    out = tmp_path / "o.exr"
    for threads in (100000, 10**9, 10**30, -5):
        with pytest.raises(skybake.BadInput, match=rf"threads = {threads}: must be 0 \(all cores\) or 1 to 4096"):
            skybake.bake(SMALL_EARTH, out, threads=threads)
        with pytest.raises(skybake.BadInput, match=rf"threads = {threads}: must be 0"):
            skybake.validate(BAKE, threads=threads)
    with pytest.raises(skybake.BadInput, match="threads: a float is not a thread count"):
        skybake.bake(SMALL_EARTH, out, threads=2.5)
    # orders= as --orders: "auto" or a whole number in [1, 1000].
    for orders in ("many", 0, 10**30):
        with pytest.raises(skybake.BadInput, match=rf"orders = {orders}: must be 'auto' or a whole number in \[1, 1000\]"):
            skybake.bake(SMALL_EARTH, out, orders=orders)
    with pytest.raises(skybake.BadInput, match="orders: a float is not a number of orders"):
        skybake.bake(SMALL_EARTH, out, orders=2.5)
    # A NUL in a path would cut it short for the system.
    with pytest.raises(skybake.BadInput, match="the path contains a NUL character"):
        skybake.bake(SMALL_EARTH, str(tmp_path / "o\x00.exr"))
    assert not (tmp_path / "o").exists()
    assert not out.exists()


def test_an_output_never_replaces_an_input(tmp_path):
    # Neither the config nor a spectrum file it names.
    config = tmp_path / "c.toml"
    csv_file = tmp_path / "sun.csv"
    csv_file.write_text("wavelength_nm,irradiance\n300,1.5\n900,1.5\n")
    lines = open(SMALL_EARTH).read().splitlines()
    lines[12] = 'irradiance = { spectrum_csv = "sun.csv" }'
    config.write_text("\n".join(lines) + "\n")
    for target in (config, csv_file):
        before = target.read_bytes()
        with pytest.raises(skybake.BadInput, match="is also an input"):
            skybake.bake(str(config), str(target))
        assert unchanged(target, before)


def test_config_dicts_that_cannot_be_configs_are_refused_before_they_recurse(tmp_path):
    out = tmp_path / "o.exr"
    deep = {}
    level = deep
    for _ in range(100000):
        level["x"] = {}
        level = level["x"]
    with pytest.raises(skybake.BadInput, match=r"config dict: (x\.){31}x: nested deeper than a config can be \(32 levels\)"):
        skybake.bake(deep, out)
    nested = [0.3]
    for _ in range(100000):
        nested = [nested]
    with pytest.raises(skybake.BadInput, match=r"planet\.ground_albedo(\[0\]){30}: nested deeper"):
        skybake.bake({"planet": {"ground_albedo": nested}}, out)
    itself = {"name": "loop"}
    itself["x"] = itself
    with pytest.raises(skybake.BadInput, match="config dict: x: contains itself"):
        skybake.bake(itself, out)
    config = tomllib.load(open(SMALL_EARTH, "rb"))
    config["resolution"]["scattering"]["r"] = 10**30
    with pytest.raises(skybake.BadInput, match="resolution.scattering.r: the integer 1000000000000000000000000000000 is too large"):
        skybake.bake(config, out)
    assert not out.exists()


def random_python_value(rng, depth=0):
    """Anything a script might put in a config dict, hostile values included."""
    kind = rng.integers(0, 16) if depth < 6 else rng.integers(0, 9)
    if kind == 0:
        return bool(rng.integers(0, 2))
    if kind == 1:
        return int(rng.choice([0, -1, 7, 2**31, -(2**63), 2**63, 10**30]))
    if kind == 2:
        return float(rng.choice([0.5, -3.0, 1e-300, 1e300, np.nan, np.inf, -np.inf]))
    if kind == 3:
        return rng.choice(["", "auto", "x\x00y", "\x1b[31m", "\u00e9\u2600", "z" * 100000])
    if kind == 4:
        return np.float32(rng.normal())
    if kind == 5:
        return np.array(rng.normal(size=int(rng.integers(0, 4))))
    if kind == 6:
        return np.array([["a", "b"]])
    if kind == 7:
        return rng.choice([None, b"bytes", 1j, object()])
    if kind == 8:
        return {1, 2}
    if kind in (9, 10):
        return [random_python_value(rng, depth + 1) for _ in range(int(rng.integers(0, 4)))]
    if kind == 11:
        return tuple(random_python_value(rng, depth + 1) for _ in range(int(rng.integers(0, 3))))
    keys = ["channels", "planet", "sun", "rayleigh", "mie", "resolution", "bake", "scene", "name", 3, None, ""]
    return {keys[int(rng.integers(0, len(keys)))]: random_python_value(rng, depth + 1)
            for _ in range(int(rng.integers(0, 4)))}


def test_any_config_dict_gives_a_bake_or_badinput(tmp_path):
    # The dict conversion's property test: random dicts, and the small Earth
    # with one leaf replaced by a random value (sometimes a container holding
    # itself), bake or raise BadInput; never another exception or a crash.
    rng = np.random.default_rng(42)
    small = tomllib.load(open(SMALL_EARTH, "rb"))
    small["resolution"]["scattering"] = {"r": 4, "mu": 8, "mu_s": 4, "nu": 2}
    outcomes = {"baked": 0, "refused": 0}
    for i in range(200):
        if i % 2:
            config = random_python_value(rng)
            if not isinstance(config, dict):
                config = {"x": config}
        else:
            config = copy.deepcopy(small)
            table = config[rng.choice([k for k in config if isinstance(config[k], dict)])]
            key = rng.choice(list(table))
            table[key] = random_python_value(rng)
            if i % 10 == 0:
                table[key] = [table]  # holds the table that holds it
        try:
            skybake.bake(config, tmp_path / "o.exr", orders=1, threads=1)
            outcomes["baked"] += 1
        except skybake.BadInput:
            outcomes["refused"] += 1
    assert outcomes["baked"] > 0 and outcomes["refused"] > 0, outcomes


def test_numpy_values_in_a_config_dict_bake_as_their_lists(tmp_path):
    config = tomllib.load(open(SMALL_EARTH, "rb"))
    as_numpy = tomllib.load(open(SMALL_EARTH, "rb"))
    as_numpy["channels"]["wavelengths_nm"] = np.array(config["channels"]["wavelengths_nm"])
    as_numpy["resolution"]["scattering"]["r"] = np.int64(config["resolution"]["scattering"]["r"])
    skybake.bake(config, tmp_path / "lists.exr", orders=2, reproducible=True)
    skybake.bake(as_numpy, tmp_path / "numpy.exr", orders=2, reproducible=True)
    assert (tmp_path / "lists.exr").read_bytes() == (tmp_path / "numpy.exr").read_bytes()


def test_files_that_are_not_bakes_or_configs_are_named_for_what_they_are(tmp_path):
    with pytest.raises(skybake.BadInput, match="/dev/zero: is a character device, not a bake file"):
        skybake.Sky("/dev/zero")
    with pytest.raises(skybake.BadInput, match="/dev/zero: is a character device, not a config file"):
        skybake.bake("/dev/zero", tmp_path / "o.exr")
    with pytest.raises(skybake.BadInput, match="is a directory, not a config file"):
        skybake.bake(str(tmp_path), tmp_path / "o.exr")
    fifo = tmp_path / "fifo.toml"
    os.mkfifo(fifo)
    with pytest.raises(skybake.BadInput, match="fifo.toml: is a named pipe, not a config file"):
        skybake.bake(str(fifo), tmp_path / "o.exr")


def test_lookups_keep_the_runtimes_geometry_contract(sky):
    # Huge, tiny and non-unit directions, cameras far away and deep below
    # the ground: finite results in range (runtime/README.md, "Geometry").
    rng = np.random.default_rng(20261206)
    n = 5000  # more than 4096 rows: the threaded path
    scale = 10.0 ** rng.uniform(-300, 300, size=(n, 1))
    camera = rng.normal(size=(n, 3)) * 10.0 ** rng.uniform(0, 20, size=(n, 1))
    view = rng.normal(size=(n, 3)) * scale
    sun = rng.normal(size=(n, 3)) * scale[::-1]
    radiance, transmittance = sky.sky_radiance(camera, view, sun)
    assert np.all(np.isfinite(radiance)) and np.all(radiance >= 0)
    assert np.all((transmittance >= 0) & (transmittance <= 1))
    sun_e, sky_e = sky.irradiance(camera, view, sun)
    assert np.all(np.isfinite(sun_e)) and np.all(np.isfinite(sky_e))
    # One refused row refuses the call, naming the argument and its value.
    for bad, message in ((np.nan, r"view direction = \(nan, 0, 1\): not finite"),
                         (0.0, r"view direction = \(0, 0, 0\): a direction needs a length above 0")):
        views = np.tile([0.0, 0.0, 1.0], (n, 1))
        views[1234] = [bad, 0.0, 1.0 if np.isnan(bad) else 0.0]
        with pytest.raises(skybake.BadInput, match=message):
            sky.sky_radiance(camera, views, sun)
    for radius in (10.0, np.radians(100)):
        with pytest.raises(skybake.BadInput, match=r"angular_radius_rad = .*: must be in \[0, pi/2\)"):
            skybake.moon_seen_from([0, 0, 6.4e6], [0, 0, 1], radius)


def test_a_spectral_bakes_lookups_give_every_channel_as_the_command_line(tmp_path):
    many = os.path.join(SOURCE, "tests", "cli", "small_earth_many.toml")
    bake = tmp_path / "many.exr"
    subprocess.run([BINARY, "bake", many, "-o", str(bake), "--threads", "1"], check=True, capture_output=True)
    sky = skybake.Sky(bake)
    assert sky.channel_count == 6 and len(sky.wavelengths_nm) == 6
    assert len(sky.atmosphere["sun_irradiance"]) == 6
    assert sky.luminance(np.ones(6)) > 0  # the ybar weights of all 6 wavelengths
    queries = [(0, 30, 0, 0, 0), (1000, 85, 89, 10, 0), (50, 95, 80, 0, 0), (10, 45, 80, 30, 20000)]
    text = "altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m\n"
    text += "".join(",".join(str(v) for v in q) + "\n" for q in queries)
    out = subprocess.run([BINARY, "lookup", "radiance", str(bake), "--queries", "/dev/stdin"], input=text,
                         capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    expected = np.array([[float(r[k]) for k in r if k.startswith("radiance_")] for r in rows], dtype=np.float32)
    assert expected.shape == (4, 6)
    bottom = sky.atmosphere["bottom_radius_m"]
    for q, want in zip(queries, expected):
        camera = np.array([0.0, 0.0, bottom + q[0]])
        view, sun = direction(q[2], q[3]), direction(q[1], 0.0)
        if q[4] > 0:
            got = sky.radiance_to_point(camera, camera + view * q[4], sun)[0]
        else:
            got = sky.sky_radiance(camera, view, sun)[0]
        # %.9g round-trips a float32: the same values bit for bit.
        np.testing.assert_array_equal(got, want)
    assert sky.solar_radiance().shape == (6,)


def test_bake_from_a_dict_gives_the_same_file_as_the_command_line(tmp_path):
    config = tomllib.load(open(SMALL_EARTH, "rb"))
    calls = []
    report = skybake.bake(config, tmp_path / "py.exr", threads=1, reproducible=True,
                          progress=lambda stage, fraction: calls.append((stage, fraction)))
    assert len(report["orders"]) >= 1  # one entry per computed order
    assert calls and all(0.0 <= f <= 1.0 for _, f in calls)
    assert any(f == 1.0 for _, f in calls) and any(f == 0.0 for _, f in calls)
    subprocess.run([BINARY, "bake", SMALL_EARTH, "-o", str(tmp_path / "cli.exr"), "--reproducible", "--threads", "1"],
                   check=True, capture_output=True)
    # A dict read from the file and the file itself are the same config: the
    # lookups of the two bakes agree exactly.
    a, b = skybake.Sky(tmp_path / "py.exr"), skybake.Sky(tmp_path / "cli.exr")
    bottom = a.atmosphere["bottom_radius_m"]
    views = direction(np.linspace(0, 170, 18), 20.0)
    np.testing.assert_array_equal(a.sky_radiance([0, 0, bottom + 10], views, direction(50, 0))[0],
                                  b.sky_radiance([0, 0, bottom + 10], views, direction(50, 0))[0])


def test_validate_gives_the_command_lines_figures(tmp_path):
    bake = tmp_path / "earth.exr"
    bake.write_bytes(open(BAKE, "rb").read())  # the command line writes a sidecar beside it
    settings = dict(queries="quick", reference_samples=256, no_cache=True)
    report = skybake.validate(bake, **settings)
    json_path = tmp_path / "validate.json"
    subprocess.run([BINARY, "validate", str(bake), "--queries", "quick", "--reference-samples", "256", "--no-cache",
                    "--json", str(json_path)], check=True, capture_output=True)
    expected = json.loads(json_path.read_text())
    # The reference's paths are seeded per query: the same settings give the
    # same reference and so the same error figures, to the last digit.
    assert report["errors"] == expected["errors"]
    assert report["reference_paths"] == 256 and report["wavelengths_nm"] == [680.0, 550.0, 440.0]
    with pytest.raises(skybake.BadInput):
        skybake.validate(tmp_path / "missing.exr", **settings)


QUICK_COLOUR_VALIDATION = dict(queries="quick", reference_samples=64, no_cache=True)


def bake_and_validate_with_colour(config, tmp_path):
    """Bakes CONFIG with the command line, then validates the bake with its
    colour reference from Python and from the command line (the quick set,
    64 paths): the bake, Python's report and the command line's JSON."""
    bake = tmp_path / "bake.exr"
    subprocess.run([BINARY, "bake", config, "-o", str(bake)], check=True, capture_output=True)
    report = skybake.validate(bake, colour_config=config, **QUICK_COLOUR_VALIDATION)
    json_path = tmp_path / "validate.json"
    subprocess.run([BINARY, "validate", str(bake), "--queries", "quick", "--reference-samples", "64", "--no-cache",
                    "--colour-config", config, "--json", str(json_path)], check=True, capture_output=True)
    return bake, report, json.loads(json_path.read_text())


def test_validate_gives_the_command_lines_colour_figures(tmp_path):
    config = os.path.join(SOURCE, "tests", "cli", "small_earth_spectral.toml")
    bake, report, expected = bake_and_validate_with_colour(config, tmp_path)
    # Seeded per query and wavelength group: the same figures to the last digit.
    assert report["colour"]["errors"] == expected["colour"]["errors"]
    assert "colour" not in skybake.validate(bake, **QUICK_COLOUR_VALIDATION)
    with pytest.raises(skybake.BadInput, match="sun.irradiance"):
        skybake.validate(bake, colour_config=SMALL_EARTH, **QUICK_COLOUR_VALIDATION)


def test_validate_gives_a_spectral_bakes_figures_per_wavelength(tmp_path):
    config = os.path.join(SOURCE, "tests", "cli", "small_earth_many.toml")
    bake, report, expected = bake_and_validate_with_colour(config, tmp_path)
    # Each lane group's reference is seeded per query as the command line's:
    # the same figures, every wavelength's, to the last digit.
    assert report["errors"] == expected["errors"]
    assert report["colour"]["errors"] == expected["colour"]["errors"]
    assert report["wavelengths_nm"] == [400.0, 460.0, 520.0, 580.0, 640.0, 700.0]
    assert [g["wavelengths_nm"] for g in report["lane_groups"]] == [[400.0, 460.0, 520.0, 580.0], [640.0, 700.0]]
    day = next(r for r in report["errors"] if (r["quantity"], r["band"]) == ("sky_radiance", "day"))
    assert len(day["channels"]) == 6 and all(c["count"] > 0 for c in day["channels"])


def test_a_bake_beyond_the_memory_it_may_allocate_is_refused_before_allocating(tmp_path):
    # As the command line does (docs/STABILITY.md): under a 4 GB address-space
    # limit, tables of 34 GB are refused with the estimate, not attempted.
    script = f"""
import skybake, tomllib
config = tomllib.load(open({SMALL_EARTH!r}, "rb"))
config["resolution"]["scattering"] = {{"r": 512, "mu": 1024, "mu_s": 256, "nu": 2}}
try:
    skybake.bake(config, {str(tmp_path / 'huge.exr')!r})
except skybake.BadInput as e:
    print("refused:", e)
"""
    out = subprocess.run(["bash", "-c", 'ulimit -v 4000000 && exec /usr/bin/python3 -c "$0"', script],
                         capture_output=True, text=True, timeout=60)
    assert "refused: config dict: resolution.scattering = 512 x 1024 x 256 x 2" in out.stdout, out.stdout + out.stderr
    assert "needs about" in out.stdout
    assert not (tmp_path / "huge.exr").exists()


def test_twilight_orders_script_compares_bakes_band_by_band():
    # scripts/twilight_orders.py (docs/MEASUREMENTS.md, "Orders"): a bake
    # against itself differs by nothing in every band; the one-order bake
    # beside it lacks the multiple scattering, so it reads below the
    # reference in every band (measured: by day 18 to 34 %, in astronomical
    # twilight 97 to 99 % of the light).
    single = os.path.join(os.path.dirname(BAKE), "earth_single.exr")
    script = os.path.join(SOURCE, "scripts", "twilight_orders.py")
    out = subprocess.run(["/usr/bin/python3", script, BAKE, BAKE, single], check=True, capture_output=True,
                         text=True, env=dict(os.environ)).stdout
    reports = out.split(" against ")
    assert len(reports) == 3
    bands = ["day", "low_sun", "civil", "nautical", "astronomical"]
    itself, one_order = out.split("earth_single.exr against")
    for band in bands:
        row = next(line for line in itself.splitlines() if line.strip().startswith(band + " "))
        assert "rms 0.00 / 0.00 / 0.00" in row, row
        row = next(line for line in one_order.splitlines() if line.strip().startswith(band + " "))
        means = [float(x) for x in row.split("mean")[1].split("(")[0].split("/")]
        assert all(m < -1.0 for m in means), row


def test_error_by_altitude_script_gives_the_mean_and_rms_per_altitude(tmp_path):
    # scripts/error_by_altitude.py (docs/ERROR_VS_TIME.md, "The frontier") on
    # a details CSV of known errors: at 30 km the bake reads 1 % and 3 % high
    # (mean 2, RMS sqrt(5) = 2.24), on the ground 1 % low; a reference below
    # validate's 1e-5 is left out, as are twilight suns and rays to points.
    header = ("kind,altitude_m,sun_zenith_deg,view_zenith_deg,view_azimuth_deg,distance_m,moon_separation_deg,"
              "moon_angular_radius_deg,bake_680,reference_680,reference_error_680")
    rows = ["radiance,30000,30,45,0,0,0,0,1.01e-3,1e-3,1e-6",
            "radiance,30000,60,10,90,0,0,0,1.03e-3,1e-3,1e-6",
            "radiance,30000,60,10,90,0,0,0,5e-6,1e-6,1e-9",
            "radiance,0,30,45,0,0,0,0,0.99e-3,1e-3,2e-6",
            "radiance,0,95,45,0,0,0,0,2e-3,1e-3,2e-6",
            "radiance,0,30,85,0,1000,0,0,2e-3,1e-3,2e-6"]
    details = tmp_path / "details.csv"
    details.write_text("\n".join([header] + rows) + "\n")
    script = os.path.join(SOURCE, "scripts", "error_by_altitude.py")
    out = subprocess.run(["/usr/bin/python3", script, str(details)], check=True, capture_output=True,
                         text=True).stdout
    lines = [line.split() for line in out.splitlines()[1:]]
    assert [(l[0], l[1], l[2]) for l in lines] == [("day", "above", "0"), ("day", "above", "30000")], out
    assert lines[0][3:6] == ["-1.00", "/", "1.00"], out
    assert lines[1][3:6] == ["+2.00", "/", "2.24"], out
    assert lines[1][6] == "(0.10)", out


def test_irradiance_against_sky_script_agrees_on_the_ground():
    # scripts/irradiance_against_sky.py (docs/ERROR_VS_TIME.md): on the
    # ground by day the table's sky irradiance and the hemisphere sum of the
    # sky radiance lookups agree (measured within 0.11 % on the default
    # bake: 0.3 % leaves room for the sum's midpoint rule); every case prints
    # a finite figure per channel.
    script = os.path.join(SOURCE, "scripts", "irradiance_against_sky.py")
    out = subprocess.run(["/usr/bin/python3", script, BAKE], check=True, capture_output=True, text=True,
                         env=dict(os.environ)).stdout
    rows = [line.split() for line in out.splitlines()[1:]]
    assert len(rows) == 6, out
    assert all(np.isfinite(float(x)) for row in rows for x in row[2:]), out
    ground = [float(x) for x in rows[0][2:]]
    assert rows[0][:2] == ["0", "30.0"] and all(abs(x) < 0.3 for x in ground), out


def test_irradiance_against_sky_dense_sweep_gives_every_band():
    # scripts/irradiance_against_sky.py --dense (docs/MEASUREMENTS.md, "The
    # sky irradiance across altitude"), every 10 km: a row per altitude band
    # and sun band, each a finite largest error at an altitude inside its
    # band. On the ground band by day it is the aerosol layer between the
    # table's rows: measured 5.0 % at 1.5 km on the default bake every 500
    # m; every 10 km the sweep sees only the ground itself there, where the
    # table and the extrapolated sum agree within 0.1 % (measured); 0.3 %
    # leaves room for the extrapolation.
    script = os.path.join(SOURCE, "scripts", "irradiance_against_sky.py")
    out = subprocess.run(["/usr/bin/python3", script, "--dense", BAKE, "10000"], check=True, capture_output=True,
                         text=True, env=dict(os.environ)).stdout
    rows = [line.split() for line in out.splitlines()[1:]]
    assert [(r[0], r[1]) for r in rows[:3]] == [("0-5", "day"), ("0-5", "low_sun"), ("0-5", "civil")], out
    assert len(rows) == 12, out  # every 10 km: none from 55 km to the top
    for band, _, largest, altitude_km, sun_deg, _ in rows:
        low, high = band.split("-")
        assert np.isfinite(float(largest)) and float(low) <= float(altitude_km) < float(high), out
    assert float(rows[0][2]) < 0.3, out


def test_lookups_by_angles_take_one_form_of_each_argument(sky):
    with pytest.raises(skybake.BadInput, match="give camera_m or altitude_m, not both"):
        sky.sky_radiance([0, 0, 7e6], altitude_m=0, view_zenith_deg=0, sun_zenith_deg=30)
    with pytest.raises(skybake.BadInput, match="give sun_dir or sun_zenith_deg$"):
        sky.sky_radiance(altitude_m=0, view_zenith_deg=0)
    with pytest.raises(skybake.BadInput, match="altitude_m: every value must be finite"):
        sky.sky_radiance(altitude_m=[0, np.nan], view_zenith_deg=0, sun_zenith_deg=30)
    with pytest.raises(skybake.BadInput, match="view_azimuth_deg: every value must be finite"):
        sky.sky_radiance(altitude_m=0, view_zenith_deg=0, view_azimuth_deg=np.inf, sun_zenith_deg=30)
    with pytest.raises(skybake.BadInput, match="give point_m or distance_m, not both"):
        sky.radiance_to_point(altitude_m=0, point_m=[0, 0, 7e6], distance_m=10, view_zenith_deg=0,
                              sun_zenith_deg=30)
    # Angles broadcast as the vectors do: 2 altitudes by 3 view zenith angles.
    radiance, _ = sky.sky_radiance(altitude_m=[[0.0], [1000.0]], view_zenith_deg=[0, 45, 90], sun_zenith_deg=30)
    assert radiance.shape == (2, 3, sky.channel_count)


def test_render_refuses_what_skybake_render_refuses(sky):
    for kwargs, message in ((dict(projection="perspective", fov_deg=179), "fov_deg = 179: a perspective camera"),
                            (dict(size=(0, 10)), r"size = 0x10: each side must be in \[1, 16384\]"),
                            (dict(moon=(0, 95, 0.28)), "moon = 0,95,0.28: the elevation must be in"),
                            (dict(projection="cube"), "projection = cube: must be fisheye, latlong or perspective"),
                            (dict(channels="xyz"), "channels = xyz: must be rgb or spectral"),
                            (dict(altitude_m=np.nan), "altitude_m = nan: must be a finite number")):
        arguments = dict(altitude_m=0, sun_zenith_deg=50, size=(8, 8))
        arguments.update(kwargs)
        with pytest.raises(skybake.BadInput, match=message):
            sky.render(**arguments)


def test_a_config_dicts_error_names_the_key_path_not_a_line():
    config = skybake.presets.load("earth")
    config["mie"]["typo_key"] = 1
    with pytest.raises(skybake.BadInput, match=r"^config dict: mie\.typo_key: unknown key$"):
        skybake.bake(config, "never.exr")
    config = skybake.load_config("earth")
    config["mie"]["phase_g"] = 1.5
    with pytest.raises(skybake.BadInput, match=r"^config dict: mie\.phase_g = 1\.5: must be in \(-1, 1\)"):
        skybake.bake(config, "never.exr")
