"""Cluster job resources for the sweep's rules, from skybake's own estimates.

The Snakefile's `resources:` call these when a job is about to be scheduled.
Memory comes from `skybake bake CONFIG --estimate` (the table memory at the
bake's peak, the same figure the bake checks against the machine before it
allocates); time from its core-seconds estimate, or from
`skybake reference ... --estimate` (the queries the reference cache still
lacks, times the measured cost of a path). Both estimates were measured on
one 2-core machine (docs/MEASUREMENTS.md, "Job resources"); the margins
below cover slower or busier cluster nodes.
"""
import functools
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import tomllib
except ModuleNotFoundError:  # Python before 3.11: the same parser as a package
    import tomli as tomllib

import tomli_w

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_config import scale_config  # noqa: E402

# Memory beyond the tables: the program, OpenEXR's buffers while writing the
# file, the reference solver's working set (measured peaks stay under it).
PROCESS_OVERHEAD_MB = 512
# Table memory is estimated exactly; the margin covers the allocator's
# rounding and fragmentation.
MEMORY_MARGIN = 1.25
# A node may be several times slower than the measuring machine (older cores,
# other jobs on its memory bus) and a job killed at its limit loses its work
# since the last checkpoint: time limits ask for this many times the estimate.
TIME_MARGIN = 4.0
# Slurm schedules in minutes; shorter requests only add scheduling noise.
MIN_RUNTIME_MIN = 5


@functools.lru_cache(maxsize=None)
def _run_estimate(command):
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def _estimate(command, fresh=False):
    """An estimate's JSON, asked once per command line (Snakemake evaluates
    each resource of each job separately), or asked again if `fresh`: what
    the reference cache lacks changes as pieces finish."""
    if fresh:
        _run_estimate.cache_clear()
    return _run_estimate(tuple(command))


def _minutes(core_seconds, threads):
    return max(MIN_RUNTIME_MIN, math.ceil(core_seconds * TIME_MARGIN / max(threads, 1) / 60.0))


def bake_estimate(skybake, config, base=None, factor=None):
    """`skybake bake --estimate` of `config`, or, before that file exists (when
    Snakemake plans the whole workflow), of `base` scaled by `factor` as
    make_config.py will write it."""
    if os.path.exists(config) or base is None:
        return _estimate([skybake, "bake", config, "--estimate"])
    with open(base, "rb") as f:
        scaled = scale_config(tomllib.load(f), float(factor))
    with tempfile.NamedTemporaryFile("wb", suffix=".toml") as f:
        tomli_w.dump(scaled, f)
        f.flush()
        return _estimate([skybake, "bake", f.name, "--estimate"])


def bake_resources(estimate, threads):
    """mem_mb and runtime (minutes) for baking: the peak of its tables."""
    return {
        "mem_mb": math.ceil(estimate["peak_table_bytes"] * MEMORY_MARGIN / 2**20) + PROCESS_OVERHEAD_MB,
        "runtime": _minutes(estimate["estimated_core_seconds"], threads),
    }


def reference_estimate(skybake, source, queries, samples, piece="1/1", cache_args=(), fresh=False):
    return _estimate([skybake, "reference", source, "--queries", queries, "--reference-samples", str(samples),
                      "--piece", piece, "--estimate", *cache_args], fresh)


def reference_resources(estimate, threads):
    """mem_mb and runtime for computing what the cache lacks of a reference piece."""
    return {"mem_mb": PROCESS_OVERHEAD_MB, "runtime": _minutes(estimate["estimated_core_seconds"], threads)}


def validate_mem_mb(bake):
    """Validating holds the bake's tables."""
    return math.ceil(bake["file_table_bytes"] * MEMORY_MARGIN / 2**20) + PROCESS_OVERHEAD_MB


def validate_runtime(bake, reference, threads):
    """The bake's lookups, and the reference the cache still lacks (normally
    none by then: the pieces ran first), which the job computes itself."""
    return _minutes(bake["estimated_core_seconds"] + reference["estimated_core_seconds"], threads)
