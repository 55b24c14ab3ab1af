#!/usr/bin/env python3
"""Every ```toml example of data_formats/CONFIG.md is a working config
fragment: merged into a complete config (its keys replacing the config's),
`skybake bake CONFIG --estimate` accepts it. Examples that set [channels]
are merged into data_formats/presets/earth_colour.toml, whose quantities are
spectra that any wavelengths can read; the rest into
tests/cli/small_earth.toml. An example without a table header fails: the
reader could not tell where its keys go.

Usage: doc_config_examples_test.py SKYBAKE SOURCE_DIR
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib


def toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"no TOML form for {value!r}")


def toml_text(config):
    """Top-level keys, then one [table] per table, sub-tables inline."""
    lines = [f"{k} = {toml_value(v)}" for k, v in config.items() if not isinstance(v, dict)]
    for name, table in config.items():
        if isinstance(table, dict):
            lines.append(f"\n[{name}]")
            lines += [f"{k} = {toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


def merged(base, example):
    """The example's keys replace the base's, table by table; [channels]
    whole, since its keys are read together (store with the wavelengths)."""
    out = dict(base)
    for key, value in example.items():
        if isinstance(value, dict) and isinstance(out.get(key), dict) and key != "channels":
            out[key] = merged(out[key], value)
        else:
            out[key] = value
    return out


def main():
    skybake, source = sys.argv[1], pathlib.Path(sys.argv[2])
    text = (source / "data_formats/CONFIG.md").read_text()
    examples = re.findall(r"^```toml\n(.*?)^```", text, flags=re.S | re.M)
    if len(examples) < 5:
        print(f"doc_config_examples: only {len(examples)} TOML examples found in CONFIG.md")
        return 1
    failed = 0
    with tempfile.TemporaryDirectory() as work:
        presets = pathlib.Path(work) / "presets"
        shutil.copytree(source / "data_formats/presets", presets)
        for n, example in enumerate(examples, 1):
            first = next((line for line in example.splitlines() if line.strip()), "")
            if not first.startswith("["):
                print(f"doc_config_examples: FAIL: example {n} has no table header: {first!r}")
                failed += 1
                continue
            fragment = tomllib.loads(example)
            base_path = (presets / "earth_colour.toml" if "channels" in fragment
                         else source / "tests/cli/small_earth.toml")
            config = merged(tomllib.loads(base_path.read_text()), fragment)
            # At tiny sizes, whatever the base: the estimate only needs them valid.
            config.setdefault("resolution", {})["scattering"] = merged(
                config.get("resolution", {}).get("scattering", {}), {"r": 8, "mu": 32, "mu_s": 8, "nu": 4})
            path = presets / f"example_{n}.toml"
            path.write_text(toml_text(config))
            run = subprocess.run([skybake, "bake", str(path), "--estimate"], capture_output=True, text=True)
            if run.returncode != 0:
                print(f"doc_config_examples: FAIL: example {n} ({first}): {run.stderr.strip()}")
                failed += 1
    print(f"doc_config_examples: {len(examples) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
