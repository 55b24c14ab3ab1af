"""job_resources.py: cluster requests from skybake's estimates (pytest; the
CTest sweep_make_config runs it with SKYBAKE_BINARY set)."""
import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import job_resources as jr  # noqa: E402

SKYBAKE = os.environ.get("SKYBAKE_BINARY", "build/baker/skybake")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
BASE = os.path.join(ROOT, "data_formats", "presets", "earth.toml")


def test_requests_cover_the_estimate_with_margins():
    estimate = {"peak_table_bytes": 1000 * 2**20, "file_table_bytes": 400 * 2**20, "estimated_core_seconds": 3600.0}
    bake = jr.bake_resources(estimate, threads=4)
    assert bake["mem_mb"] == 1250 + jr.PROCESS_OVERHEAD_MB
    assert bake["runtime"] == 60  # 3600 core-s x 4 / 4 threads = 60 min
    # Short jobs still ask for the minimum.
    assert jr.bake_resources({**estimate, "estimated_core_seconds": 1.0}, 8)["runtime"] == jr.MIN_RUNTIME_MIN
    assert jr.validate_mem_mb(estimate) == 500 + jr.PROCESS_OVERHEAD_MB


@pytest.mark.skipif(not os.path.exists(SKYBAKE), reason="skybake not built")
def test_estimate_before_the_config_exists_is_the_estimate_of_the_written_config(tmp_path):
    # Snakemake may ask for a bake's resources before make_config.py has
    # written its config: the estimate from the base and factor must be the
    # estimate of the config it then writes.
    config = tmp_path / "earth_x0.75.toml"
    planned = jr.bake_estimate(SKYBAKE, str(config), BASE, "0.75")
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "sweep", "make_config.py"), BASE, "0.75",
                    str(config)], check=True)
    written = jr.bake_estimate(SKYBAKE, str(config), BASE, "0.75")
    for key in ("peak_table_bytes", "file_table_bytes", "estimated_core_seconds", "scattering_size"):
        assert planned[key] == written[key]
    # Larger tables ask for more.
    larger = jr.bake_estimate(SKYBAKE, str(tmp_path / "none.toml"), BASE, "1.5")
    assert larger["peak_table_bytes"] > written["peak_table_bytes"]
