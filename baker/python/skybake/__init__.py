"""skybake: precomputed atmospheric scattering from Python.

    config = skybake.presets.load("earth")           # a dict: change and bake
    skybake.bake(config, "earth.exr")
    sky = skybake.Sky("earth.exr")
    radiance, transmittance = sky.sky_radiance(camera_m, view_dir, sun_dir)
    radiance, transmittance = sky.sky_radiance(altitude_m=100, view_zenith_deg=80,
                                               view_azimuth_deg=30, sun_zenith_deg=60)
    image = sky.render(altitude_m=0, sun_zenith_deg=85, projection="latlong")

Positions are metres from the planet's centre and directions unit vectors,
as arrays whose last axis has length 3; any leading shapes that numpy
broadcasts together. Instead of the vectors, the lookups also take the
command line's description (`skybake lookup`, docs/QUERIES.md): altitudes in
metres above the planet's +z pole and zenith and azimuth angles in degrees
(azimuths from +x toward +y; the sun's azimuth is 0 unless given), arrays
that broadcast as the vectors do. Results are float32 arrays of the broadcast shape plus
one axis of the bake's channels, in its channel order (`sky.channels`):
radiance in W m^-2 sr^-1 nm^-1, irradiance in W m^-2 nm^-1 (a colour bake's
X, Y, Z: W m^-2 sr^-1 and W m^-2; `sky.luminance` gives cd m^-2 of either). The values are
the C++ runtime's (runtime/sky.h) bit for bit; the GIL is released while a
lookup runs, and calls of many rows use several threads.

Bad input (a missing or corrupt file, a config value, a left-out output)
raises skybake.BadInput, a ValueError with the message the command line
prints. Geometry follows the C++ runtime's contract (runtime/README.md,
"Geometry"): a row with a non-finite value, a zero direction or a moon of
negative or non-finite radius raises BadInput for the call, naming the
argument; directions of any other length are normalised; positions beyond
1e12 m from the centre are moved in to it, and below the ground, at any
depth, onto it.
"""
import json as _json

import numpy as _np

from . import _skybake
from . import presets
from ._skybake import BadInput

__all__ = ["Sky", "BadInput", "bake", "validate", "moon_seen_from", "load_config", "presets", "__version__"]

__version__ = _skybake.__version__


def _rows(*vectors, scalars=()):
    """Broadcasts (..., 3) vectors and (...) scalars to one leading shape;
    returns that shape and each as C-contiguous float64 rows."""
    vectors = [_np.asarray(v, dtype=_np.float64) for v in vectors]
    scalars = [_np.asarray(s, dtype=_np.float64) for s in scalars]
    for v in vectors:
        if v.ndim == 0 or v.shape[-1] != 3:
            raise BadInput(f"a position or direction needs a last axis of length 3, not shape {v.shape}")
    try:
        shape = _np.broadcast_shapes(*[v.shape[:-1] for v in vectors], *[s.shape for s in scalars])
    except ValueError as e:
        raise BadInput(f"the arguments' shapes do not broadcast: {e}") from None
    n = int(_np.prod(shape, dtype=_np.int64))
    out = [_np.ascontiguousarray(_np.broadcast_to(v, shape + (3,)).reshape(n, 3)) for v in vectors]
    out += [_np.ascontiguousarray(_np.broadcast_to(s, shape).reshape(n)) for s in scalars]
    return shape, out


def _finite(name, values):
    values = _np.asarray(values, dtype=_np.float64)
    if not _np.all(_np.isfinite(values)):
        raise BadInput(f"{name}: every value must be finite")
    return values


def _by_angles(vector, vector_name, angles, angles_name):
    """Whether an argument comes in the local frame's form (an altitude, or
    angles) rather than as vectors; exactly one of the two must be given."""
    if (vector is None) == (angles is None):
        raise BadInput(f"give {vector_name} or {angles_name}" + ("" if vector is None else ", not both"))
    return angles is not None


def _directions(vector, vector_name, zenith_deg, azimuth_deg, zenith_name):
    """A direction argument given as vectors, or as zenith and azimuth angles
    (degrees) in the local frame: (..., 3) unit vectors."""
    if not _by_angles(vector, vector_name, zenith_deg, zenith_name):
        return vector
    zenith = _finite(zenith_name, zenith_deg)
    azimuth = _finite(zenith_name.replace("zenith", "azimuth"), azimuth_deg)
    zenith, azimuth = _np.broadcast_arrays(zenith, azimuth)
    flat = _skybake._directions_at_angles(zenith.reshape(-1), azimuth.reshape(-1))
    return flat.reshape(zenith.shape + (3,))


def load_config(name_or_path):
    """A config as a dict to change and pass to bake(): a preset's name
    ("earth", "mars", ...: skybake.presets.names()) or a TOML file's path.
    Spectrum files it names come back as absolute paths."""
    text = str(name_or_path)
    if text in presets.names():
        return presets.load(text)
    return presets.load_file(text)


def moon_seen_from(camera_m, direction, angular_radius_rad):
    """A solar eclipse's moon for the lookups' moon argument: (centre_m,
    radius_m) of the moon seen from camera_m in unit direction `direction`
    with angular radius angular_radius_rad, at the mean lunar distance
    (runtime/physics/moon_occluder.h, Moon::seenFrom)."""
    centre, radius = _skybake._moon_seen_from(list(map(float, camera_m)), list(map(float, direction)),
                                              float(angular_radius_rad))
    return _np.asarray(centre), radius


class Sky:
    """A bake file's lookups (skybake::Sky). Thread-safe.

    Every lookup returns float32 arrays of the arguments' broadcast leading
    shape plus one axis of the bake's channels (sky.channels): radiance in
    W m^-2 sr^-1 nm^-1, irradiance in W m^-2 nm^-1, transmittance unitless (a
    colour bake's X, Y, Z: W m^-2 sr^-1 and W m^-2)."""

    def __init__(self, path):
        self._path = str(path)
        self._sky = _skybake.Sky(self._path)
        # Where the angle form's altitudes start (the atmosphere dict is built per call).
        self._bottom_radius_m = self._sky.atmosphere["bottom_radius_m"]

    def __repr__(self):
        r = self.baked_ranges
        top = "any height" if r["altitude_max_m"] == float("inf") else f"{r['altitude_max_m']:g} m"
        return (f"skybake.Sky({self._path!r}: {self.channel_count} channels ({', '.join(self.channels)}), "
                f"{self.orders} orders, camera {r['altitude_min_m']:g} m to {top}, "
                f"sun zenith {r['sun_zenith_min_deg']:g} to {r['sun_zenith_max_deg']:g} deg)")

    @property
    def path(self):
        """The bake file this Sky was read from."""
        return self._path

    @property
    def wavelengths_nm(self):
        """The channels' wavelengths, nm (a list), or for a colour bake the
        wavelengths integrated into its X, Y, Z."""
        return list(self._sky.wavelengths_nm)

    @property
    def channel_kind(self):
        """What the channels hold: "wavelengths" (spectral radiance, W m^-2
        sr^-1 nm^-1) or "cie_xyz" (CIE 1931 X, Y, Z, W m^-2 sr^-1)."""
        return self._sky.channel_kind

    @property
    def channels(self):
        """The channels' names in channel order: "680nm", ... or "X", "Y", "Z"."""
        return list(self._sky.channel_names)

    def luminance(self, values):
        """Luminance in cd m^-2 of radiances this bake returns (illuminance in
        lx of irradiances): an array of shape (..., channels) to one of shape
        (...), float64. A colour bake's is 683 Y; a wavelength bake's goes
        through the CIE 1931 colour-matching functions as `skybake render`
        does (Sky::luminance, the same weights)."""
        values = _np.asarray(values, dtype=_np.float64)
        if values.ndim == 0 or values.shape[-1] != self.channel_count:
            raise BadInput(f"luminance needs a last axis of the bake's {self.channel_count} channels, "
                           f"not shape {values.shape}")
        return values @ _np.asarray(self._sky.luminance_weights, dtype=_np.float64)

    @property
    def channel_count(self):
        """Channels per result: the bake's wavelengths, or 3 for a colour bake."""
        return self._sky.channel_count

    @property
    def orders(self):
        """Scattering orders the bake computed."""
        return self._sky.orders

    @property
    def atmosphere(self):
        """The atmosphere the file states, a dict in SI units (radii in m,
        coefficients in m^-1, spectra as lists per channel)."""
        return self._sky.atmosphere

    @property
    def baked_ranges(self):
        """The camera altitudes (m) and sun zenith angles (deg) the tables serve.

        A bake of the whole domain serves every sun (0 to 180 deg): below
        sun.max_zenith_deg the night continuation takes over (runtime/README.md).
        """
        return self._sky.baked_ranges

    @property
    def outputs(self):
        """What the bake holds: sky_radiance, radiance_to_points, ground_irradiance."""
        return self._sky.outputs

    @property
    def bake_report(self):
        """The bake report the file carries, as a dict."""
        return _json.loads(self._sky.bake_report_json)

    def _shaped(self, shape, *results):
        c = self.channel_count
        return tuple(r.reshape(shape + (c,)) for r in results)

    def _positions(self, vector, vector_name, altitude_m):
        """A position argument given as vectors (m from the planet's centre),
        or as altitudes (m) above the local frame's +z pole."""
        if not _by_angles(vector, vector_name, altitude_m, "altitude_m"):
            return vector
        altitude = _finite("altitude_m", altitude_m)
        flat = _skybake._positions_at_altitude(self._bottom_radius_m, altitude.reshape(-1))
        return flat.reshape(altitude.shape + (3,))

    def _sun(self, sun_dir, sun_zenith_deg, sun_azimuth_deg):
        return _directions(sun_dir, "sun_dir", sun_zenith_deg, sun_azimuth_deg, "sun_zenith_deg")

    def sky_radiance(self, camera_m=None, view_dir=None, sun_dir=None, shadow_length_m=0.0, moon=None, *,
                     altitude_m=None, view_zenith_deg=None, view_azimuth_deg=0.0, sun_zenith_deg=None,
                     sun_azimuth_deg=0.0):
        """Radiance toward the camera along view rays and the transmittance to
        each ray's end (the ground's reflected light not included): a pair
        of arrays of shape (..., channels).

        camera_m (..., 3) m from the planet's centre, or altitude_m (...) m;
        view_dir (..., 3), or view_zenith_deg and view_azimuth_deg (...);
        sun_dir (..., 3), or sun_zenith_deg and sun_azimuth_deg (...);
        shadow_length_m (...): light shafts, the length of the ray in the
        shadow of terrain; moon: a solar eclipse's moon, (centre_m, radius_m)
        (see moon_seen_from; docs/ECLIPSES.md), not with a shadow length."""
        camera_m = self._positions(camera_m, "camera_m", altitude_m)
        view_dir = _directions(view_dir, "view_dir", view_zenith_deg, view_azimuth_deg, "view_zenith_deg")
        sun_dir = self._sun(sun_dir, sun_zenith_deg, sun_azimuth_deg)
        if moon is not None:
            if _np.any(_np.asarray(shadow_length_m) != 0.0):
                raise BadInput("sky_radiance: a moon and a shadow length together are not available")
            centre_m, radius_m = moon
            shape, (c, v, s, m, r) = _rows(camera_m, view_dir, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._sky_radiance_eclipse(c, v, s, m, r))
        shape, (c, v, s, d) = _rows(camera_m, view_dir, sun_dir, scalars=(shadow_length_m,))
        return self._shaped(shape, *self._sky._sky_radiance(c, v, s, d))

    def radiance_to_point(self, camera_m=None, point_m=None, sun_dir=None, shadow_length_m=0.0, moon=None, *,
                          altitude_m=None, view_zenith_deg=None, view_azimuth_deg=0.0, distance_m=None,
                          sun_zenith_deg=None, sun_azimuth_deg=0.0):
        """Aerial perspective: the radiance the air between camera and point
        adds, and the transmittance between them, (..., channels) each.

        camera_m (..., 3) or altitude_m (...); point_m (..., 3) m from the
        planet's centre, or the point distance_m (...) m from the camera
        along view_zenith_deg and view_azimuth_deg (as `skybake lookup
        radiance` with a distance_m column); sun, shadow_length_m and moon as
        in sky_radiance (a moon not with a shadow length)."""
        camera_m = self._positions(camera_m, "camera_m", altitude_m)
        if point_m is None and distance_m is not None:
            view = _directions(None, "view_dir", view_zenith_deg, view_azimuth_deg, "view_zenith_deg")
            distance = _finite("distance_m", distance_m)
            point_m = _np.asarray(camera_m, dtype=_np.float64) + view * distance[..., None]
        elif point_m is None:
            raise BadInput("give point_m, or distance_m with view_zenith_deg")
        elif distance_m is not None:
            raise BadInput("give point_m or distance_m, not both")
        sun_dir = self._sun(sun_dir, sun_zenith_deg, sun_azimuth_deg)
        if moon is not None:
            if _np.any(_np.asarray(shadow_length_m) != 0.0):
                raise BadInput("radiance_to_point: a moon and a shadow length together are not available")
            centre_m, radius_m = moon
            shape, (c, p, s, m, r) = _rows(camera_m, point_m, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._radiance_to_point_eclipse(c, p, s, m, r))
        shape, (c, p, s, d) = _rows(camera_m, point_m, sun_dir, scalars=(shadow_length_m,))
        return self._shaped(shape, *self._sky._radiance_to_point(c, p, s, d))

    def irradiance(self, point_m=None, normal=None, sun_dir=None, moon=None, *, altitude_m=None,
                   sun_zenith_deg=None, sun_azimuth_deg=0.0):
        """(sun, sky) irradiance on surfaces, (..., channels) each.

        point_m (..., 3) and a unit normal (..., 3); or altitude_m (...), a
        horizontal surface there unless a normal is given (as `skybake lookup
        irradiance`); sun and moon as in sky_radiance."""
        if normal is None and altitude_m is not None:
            normal = (0.0, 0.0, 1.0)
        if normal is None:
            raise BadInput("give normal with point_m")
        point_m = self._positions(point_m, "point_m", altitude_m)
        sun_dir = self._sun(sun_dir, sun_zenith_deg, sun_azimuth_deg)
        if moon is not None:
            centre_m, radius_m = moon
            shape, (p, n, s, m, r) = _rows(point_m, normal, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._irradiance_eclipse(p, n, s, m, r))
        shape, (p, n, s) = _rows(point_m, normal, sun_dir)
        return self._shaped(shape, *self._sky._irradiance(p, n, s))

    def transmittance(self, a_m, b_m):
        """Transmittance along segments from a_m to b_m ((..., 3) each, m
        from the planet's centre), (..., channels); 0 through the ground."""
        shape, (a, b) = _rows(a_m, b_m)
        return self._shaped(shape, self._sky._transmittance(a, b))[0]

    def solar_radiance(self):
        """The sun disk's radiance above the atmosphere, (channels,), W m^-2
        sr^-1 nm^-1."""
        return self._sky.solar_radiance()

    def render(self, altitude_m, sun_zenith_deg, sun_azimuth_deg=0.0, projection="fisheye", fov_deg=None,
               size=None, view_elevation_deg=10.0, view_azimuth_deg=None, sun_disk=True, moon=None,
               channels="rgb"):
        """The sky as an image, as `skybake render` makes it with the same
        arguments (its options without the dashes): a float32 array of shape
        (height, width, 3), rows top to bottom.

        channels "rgb": linear Rec. 709 (sRGB primaries, D65 white) in cd m^-2,
        the pixels of `skybake render -o image.exr`; "spectral": the bake's
        own channels, W m^-2 sr^-1 nm^-1, shape (height, width, channels).
        projection: "fisheye" (looking up, fov_deg the full cone, default
        180), "latlong" (an environment map: azimuth across with the sun's in
        the middle column, zenith angle down) or "perspective" (fov_deg
        horizontal, default 90, looking toward view_azimuth_deg, default the
        sun's, view_elevation_deg above the horizontal); size: (width,
        height) in pixels, default (512, 512), latlong (1024, 512); sun_disk:
        the sun disk integrated over each pixel, or left out; moon: a solar
        eclipse's moon as (azimuth_deg, elevation_deg, angular_radius_deg)
        seen from the camera (docs/ECLIPSES.md)."""
        if size is not None:
            size = tuple(int(x) for x in size)
            if len(size) != 2:
                raise BadInput(f"size = {size}: must be (width, height)")
        if moon is not None:
            moon = tuple(float(x) for x in moon)
            if len(moon) != 3:
                raise BadInput(f"moon = {moon}: must be (azimuth_deg, elevation_deg, angular_radius_deg)")
        return _skybake._render(self._sky, float(altitude_m), float(sun_zenith_deg), float(sun_azimuth_deg),
                                str(projection), None if fov_deg is None else float(fov_deg), size,
                                float(view_elevation_deg),
                                None if view_azimuth_deg is None else float(view_azimuth_deg), bool(sun_disk), moon,
                                str(channels))


def bake(config, output, threads=0, orders=None, reproducible=False, progress=None):
    """Bakes `config` (a TOML file's path, or a dict in the config schema of
    data_formats/CONFIG.md, validated with the same messages) into `output`,
    as `skybake bake` does, and returns the bake report as a dict.

    threads: OpenMP threads, an int, 0 (all cores) or 1 to 4096; orders:
    overrides bake.orders, "auto" or an int from 1 to 1000; reproducible:
    leave the run's facts (time, threads) out of the file; progress:
    progress(stage, fraction) called as each stage starts, at each tenth of
    its work and at its end; None draws the command line's bar when stderr is
    a terminal. A dict holds bool, int (64 bits), float, str, list, tuple,
    dict and numpy arrays and scalars (as their lists and numbers), nested at
    most 32 levels and never holding itself. `output` may not be the config
    or a spectrum file it names. Anything else raises BadInput."""
    return _skybake.bake(config if isinstance(config, dict) else str(config), str(output),
                         threads, orders, reproducible, progress)


def validate(bake, queries="standard", reference_samples=None, cache_dir=None, no_cache=False, threads=0,
             colour_config=None):
    """The bake's error against the independent reference solver, as
    `skybake validate --json` reports it (a dict: RMS, p95 and max relative
    error per band and channel, lookup time per ray). queries: "standard",
    "quick" or a CSV path; reference_samples: Monte Carlo paths per query
    (None: the command line's default); cache_dir: the reference cache (None:
    the command line's default); no_cache: compute afresh and keep nothing;
    colour_config: the config the bake was made from, to add the "colour"
    figures of `validate --colour-config` (luminance and CIEDE2000 per sun
    band against a reference in CIE XYZ from 41 wavelengths); threads: an
    int, 0 (all cores) or 1 to 4096."""
    kwargs = {} if reference_samples is None else {"reference_samples": int(reference_samples)}
    return _skybake.validate(str(bake), str(queries), cache_dir="" if cache_dir is None else str(cache_dir),
                             no_cache=no_cache, threads=threads,
                             colour_config="" if colour_config is None else str(colour_config), **kwargs)
