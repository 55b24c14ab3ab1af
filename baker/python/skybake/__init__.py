"""skybake: precomputed atmospheric scattering from Python.

    sky = skybake.Sky("earth.exr")
    radiance, transmittance = sky.sky_radiance(camera_m, view_dir, sun_dir)

Positions are metres from the planet's centre and directions unit vectors,
as arrays whose last axis has length 3; any leading shapes that numpy
broadcasts together. Results are float32 arrays of the broadcast shape plus
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
from ._skybake import BadInput

__all__ = ["Sky", "BadInput", "bake", "validate", "moon_seen_from"]


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


def moon_seen_from(camera_m, direction, angular_radius_rad):
    """A solar eclipse's moon for the lookups' moon argument: (centre_m,
    radius_m) of the moon seen from camera_m in unit direction `direction`
    with angular radius angular_radius_rad, at the mean lunar distance
    (runtime/physics/moon_occluder.h, Moon::seenFrom)."""
    centre, radius = _skybake._moon_seen_from(list(map(float, camera_m)), list(map(float, direction)),
                                              float(angular_radius_rad))
    return _np.asarray(centre), radius


class Sky:
    """A bake file's lookups (skybake::Sky). Thread-safe."""

    def __init__(self, path):
        self._sky = _skybake.Sky(str(path))

    @property
    def wavelengths_nm(self):
        """The channels' wavelengths, or for a colour bake the wavelengths
        integrated into its X, Y, Z."""
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
        lx of irradiances): an array whose last axis is the channels, to an
        array of the leading shape (float64). A colour bake's is 683 Y; a
        wavelength bake's goes through the CIE 1931 colour-matching functions
        as `skybake render` does (Sky::luminance, the same weights)."""
        values = _np.asarray(values, dtype=_np.float64)
        if values.ndim == 0 or values.shape[-1] != self.channel_count:
            raise BadInput(f"luminance needs a last axis of the bake's {self.channel_count} channels, "
                           f"not shape {values.shape}")
        return values @ _np.asarray(self._sky.luminance_weights, dtype=_np.float64)

    @property
    def channel_count(self):
        return self._sky.channel_count

    @property
    def orders(self):
        """Scattering orders the bake computed."""
        return self._sky.orders

    @property
    def atmosphere(self):
        """The atmosphere the file states (SI units; spectra per channel)."""
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

    def sky_radiance(self, camera_m, view_dir, sun_dir, shadow_length_m=0.0, moon=None):
        """Radiance toward the camera along view_dir and the transmittance to
        the ray's end (the ground's reflected light not included). moon: a
        solar eclipse's moon, (centre_m, radius_m) (see moon_seen_from;
        docs/ECLIPSES.md), not with a shadow length."""
        if moon is not None:
            if _np.any(_np.asarray(shadow_length_m) != 0.0):
                raise BadInput("sky_radiance: a moon and a shadow length together are not available")
            centre_m, radius_m = moon
            shape, (c, v, s, m, r) = _rows(camera_m, view_dir, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._sky_radiance_eclipse(c, v, s, m, r))
        shape, (c, v, s, d) = _rows(camera_m, view_dir, sun_dir, scalars=(shadow_length_m,))
        return self._shaped(shape, *self._sky._sky_radiance(c, v, s, d))

    def radiance_to_point(self, camera_m, point_m, sun_dir, shadow_length_m=0.0, moon=None):
        """Aerial perspective: radiance between camera and point, and the
        transmittance between them; moon as in sky_radiance, not with a
        shadow length."""
        if moon is not None:
            if _np.any(_np.asarray(shadow_length_m) != 0.0):
                raise BadInput("radiance_to_point: a moon and a shadow length together are not available")
            centre_m, radius_m = moon
            shape, (c, p, s, m, r) = _rows(camera_m, point_m, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._radiance_to_point_eclipse(c, p, s, m, r))
        shape, (c, p, s, d) = _rows(camera_m, point_m, sun_dir, scalars=(shadow_length_m,))
        return self._shaped(shape, *self._sky._radiance_to_point(c, p, s, d))

    def irradiance(self, point_m, normal, sun_dir, moon=None):
        """(sun, sky) irradiance on a surface at point_m with unit normal;
        moon as in sky_radiance."""
        if moon is not None:
            centre_m, radius_m = moon
            shape, (p, n, s, m, r) = _rows(point_m, normal, sun_dir, centre_m, scalars=(radius_m,))
            return self._shaped(shape, *self._sky._irradiance_eclipse(p, n, s, m, r))
        shape, (p, n, s) = _rows(point_m, normal, sun_dir)
        return self._shaped(shape, *self._sky._irradiance(p, n, s))

    def transmittance(self, a_m, b_m):
        """Transmittance along the segment from a_m to b_m (0 through the ground)."""
        shape, (a, b) = _rows(a_m, b_m)
        return self._shaped(shape, self._sky._transmittance(a, b))[0]

    def solar_radiance(self):
        """The sun disk's radiance above the atmosphere, per channel."""
        return self._sky.solar_radiance()


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
