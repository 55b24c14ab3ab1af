"""The configs skybake ships, as dicts to change and bake.

    config = skybake.presets.load("earth")
    config["mie"]["phase_g"] = 0.7
    skybake.bake(config, "earth_g07.exr")

names() lists them (the built-in Earth, Earth for deep twilight, hazy Earth,
Mars, Earth on measured spectra per wavelength or as colour); path(name) is
the TOML file; load(name) its dict in the config schema (CONFIG.md, beside
the presets in skybake's sources as data_formats/CONFIG.md). The spectrum
files a preset names (the solar spectrum, ozone's cross sections) are
installed beside it, and load() gives their absolute paths, so the dict
bakes from any directory.
"""
import pathlib as _pathlib

try:
    import tomllib as _toml
except ModuleNotFoundError:  # Python before 3.11: the same parser as a package
    import tomli as _toml

__all__ = ["names", "path", "load", "load_file"]

_HERE = _pathlib.Path(__file__).resolve().parent
# The config keys whose values are files (CONFIG.md, "Spectra").
_FILE_KEYS = ("spectrum_csv", "cross_section_csv")


def names():
    """The presets' names, sorted: "earth", "mars", ..."""
    return sorted(p.stem for p in _HERE.glob("*.toml"))


def path(name):
    """The TOML file of preset `name` (a pathlib.Path); ValueError for a name
    that is not one of names()."""
    if name not in names():
        raise ValueError(f"no preset named {name!r}; the presets are {', '.join(names())}")
    return _HERE / f"{name}.toml"


def _absolute_files(value, directory):
    if isinstance(value, dict):
        return {k: (str(directory / v) if k in _FILE_KEYS and isinstance(v, str) and not _pathlib.Path(v).is_absolute()
                    else _absolute_files(v, directory))
                for k, v in value.items()}
    if isinstance(value, list):
        return [_absolute_files(v, directory) for v in value]
    return value


def load_file(file):
    """A config file (TOML) as a dict, its spectrum files made absolute
    (relative ones are relative to the file's folder, as `skybake bake`
    reads them)."""
    file = _pathlib.Path(file)
    with open(file, "rb") as f:
        return _absolute_files(_toml.load(f), file.resolve().parent)


def load(name):
    """Preset `name` as a dict (see names())."""
    return load_file(path(name))
