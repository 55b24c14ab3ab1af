"""The Slurm profile folder scripts/sweep/slurm and what the Snakefile asks of
it: config.yaml for Snakemake 7, config.v8+.yaml for Snakemake 8 and later.

Run: /usr/bin/python3 -m pytest scripts/sweep/test_profiles.py (CTest:
sweep_profiles). Snakemake 8 is not a Debian 12 package, so its profile is
checked against the options Snakemake 8 defines; the Snakefile and the
Snakemake 7 profile run through the snakemake on PATH (Debian's 7.21).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest
import yaml

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
PROFILE = HERE / "slurm"
V7 = PROFILE / "config.yaml"
V8 = PROFILE / "config.v8+.yaml"
SKYBAKE = pathlib.Path(os.environ.get("SKYBAKE_BINARY", ROOT / "build" / "baker" / "skybake")).resolve()
SNAKEMAKE = shutil.which("snakemake")

# Long options (without their dashes) that a Snakemake 8 profile may set: a
# subset, for cluster profiles, of those that snakemake/cli.py's
# get_argument_parser defines in both Snakemake 8.0.0 and 9.25.2. A profile
# key outside it is either a typo or a Snakemake 7 option (slurm, cluster,
# cluster-config, cluster-status) that Snakemake 8 refuses. The Slurm
# plugin's own options (slurm-...) are left out: which exist depends on the
# plugin's version, and the profile sets none.
SNAKEMAKE_8_OPTIONS = {
    "apptainer-args", "apptainer-prefix", "conda-frontend", "conda-prefix", "config", "configfile",
    "default-resources", "directory", "envvars", "executor", "jobname", "jobs", "keep-going",
    "keep-incomplete", "latency-wait", "local-cores", "max-jobs-per-second", "max-status-checks-per-second",
    "nocolor", "printshellcmds", "quiet", "rerun-incomplete", "resources", "restart-times", "retries",
    "scheduler", "seconds-between-status-checks", "set-resources", "set-threads", "shared-fs-usage",
    "show-failed-logs", "software-deployment-method", "use-apptainer", "use-conda", "use-envmodules",
}
# Resources the Slurm executors turn into sbatch options: Snakemake 7's
# (snakemake/executors/slurm/slurm_submit.py) and the Snakemake 8 plugin's
# (snakemake_executor_plugin_slurm/submit_string.py) read the same names.
SLURM_RESOURCES = {"mem_mb", "mem_mb_per_cpu", "runtime", "cpus_per_task", "slurm_partition", "slurm_account",
                   "slurm_extra", "constraint", "qos", "nodes", "tasks"}
# Resources Snakemake derives or sets itself.
SNAKEMAKE_RESOURCES = {"mem_mib", "disk_mb", "disk_mib", "tmpdir", "_cores", "_nodes"}
CLUSTER_RULES = {"bake", "reference_piece", "validate"}
LOCAL_RULES = {"sized_config", "plot", "all"}


def load(path):
    with open(path) as f:
        return yaml.safe_load(f)


def profile_file(files, major):
    """The file of a profile folder Snakemake `major` reads. Snakemake 7
    reads config.yaml (snakemake/__init__.py, get_profile_file). Snakemake 8
    and later take, of the files named config.yaml or config.vN+.yaml
    (9.x also profile.yaml and profile.vN+.yaml) with N at most its major
    version, the one with the largest N (snakemake/cli.py, get_profile_dir;
    docs/executing/cli.rst, "Profiles")."""
    if major < 8:
        return "config.yaml" if "config.yaml" in files else None
    pattern = re.compile(r"(?:profile|config)(?:\.v(\d+)\+)?\.yaml")
    candidates = {}
    for name in files:
        m = pattern.fullmatch(name)
        if m and int(m.group(1) or 0) <= major:
            candidates[name] = int(m.group(1) or 0)
    return max(candidates, key=candidates.get) if candidates else None


def test_each_snakemake_reads_its_own_file():
    files = sorted(p.name for p in PROFILE.iterdir())
    assert profile_file(files, 7) == "config.yaml"
    assert profile_file(files, 8) == "config.v8+.yaml"
    assert profile_file(files, 9) == "config.v8+.yaml"
    # Snakemake 8.0's pattern was matched at the start of a name only
    # (re.match on "config(.v(?P<min_major>\d+)\+)?.yaml"): no other file in
    # the folder may look like a profile to it.
    loose = re.compile(r"config(.v(\d+)\+)?.yaml")
    assert [f for f in files if loose.match(f)] == ["config.v8+.yaml", "config.yaml"]


def test_snakemake_8_profile_uses_the_slurm_plugin_and_its_options_only():
    v8 = load(V8)
    assert v8["executor"] == "slurm"
    unknown = set(v8) - SNAKEMAKE_8_OPTIONS
    assert not unknown, f"options Snakemake 8 does not define: {sorted(unknown)}"
    assert isinstance(v8["jobs"], int) and v8["jobs"] > 0
    assert isinstance(v8["latency-wait"], int) and v8["latency-wait"] > 0
    assert isinstance(v8["retries"], int) and v8["retries"] >= 0
    assert v8["printshellcmds"] is True


def test_snakemake_7_profile_keeps_its_built_in_executor():
    v7 = load(V7)
    assert v7["slurm"] is True
    assert "executor" not in v7


def test_both_profiles_ask_the_same():
    v7, v8 = load(V7), load(V8)
    for key in ("jobs", "latency-wait", "printshellcmds", "default-resources"):
        assert v7.get(key) == v8.get(key), key
    assert v7["restart-times"] == v8["retries"]
    # Nothing else differs but the executor and the name of the restarts.
    assert set(v7) - {"slurm", "restart-times"} == set(v8) - {"executor", "retries"}


def interpreter_of(program):
    """The Python a console script runs under, from its #! line."""
    with open(program) as f:
        line = f.readline().strip()
    if not line.startswith("#!"):
        pytest.skip(f"{program} has no #! line")
    words = line[2:].split()
    if os.path.basename(words[0]) == "env":
        return shutil.which(words[-1])
    return words[0]


@pytest.fixture
def workdir(tmp_path):
    """A copy of the workflow, so Snakemake's own state (.snakemake/) and the
    outputs stay in the test's directory."""
    if SNAKEMAKE is None:
        pytest.skip("snakemake is not installed (scripts/setup.sh installs it)")
    if not SKYBAKE.exists():
        pytest.skip(f"{SKYBAKE} not built (the Snakefile asks skybake for each job's estimates)")
    shutil.copytree(HERE, tmp_path / "scripts" / "sweep",
                    ignore=shutil.ignore_patterns("__pycache__", ".pytest_cache"))
    (tmp_path / "data_formats" / "presets").mkdir(parents=True)
    shutil.copy(ROOT / "data_formats" / "presets" / "earth.toml", tmp_path / "data_formats" / "presets")
    return tmp_path


def snakemake(workdir, *args, env=None):
    result = subprocess.run([SNAKEMAKE, "-s", "scripts/sweep/Snakefile", *args], cwd=workdir, env=env,
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout + result.stderr


def planned_jobs(output):
    """(rule, resources, shell command) of each job a dry run with -p lists."""
    jobs = []
    for block in re.split(r"\n(?=\[[^\]]*\]\n)", output):
        rule = re.search(r"^(?:local)?rule (\w+):", block, re.M)
        if not rule:
            continue
        resources = re.search(r"^\s+resources: (.*)$", block, re.M)
        pairs = dict(p.split("=", 1) for p in resources.group(1).split(", ")) if resources else {}
        command = block.strip().split("\n")[-1].strip()
        jobs.append((rule.group(1), pairs, command))
    return jobs


def test_dry_run_through_the_profile(workdir):
    # The Snakemake 7 the machine has reads config.yaml; config.v8+.yaml
    # beside it must not disturb it.
    config = ["factors=[0.5,1]", f"skybake={SKYBAKE}", f"cache_dir={workdir / 'cache'}"]
    output = snakemake(workdir, "-n", "-p", "--profile", str(workdir / "scripts" / "sweep" / "slurm"),
                       "--config", *config)
    jobs = planned_jobs(output)
    assert {rule for rule, _, _ in jobs} == CLUSTER_RULES | LOCAL_RULES
    for rule, resources, _ in jobs:
        if rule not in CLUSTER_RULES:
            continue
        assert set(resources) <= SLURM_RESOURCES | SNAKEMAKE_RESOURCES, (rule, resources)
        # What sbatch gets as --mem (MB) and -t (minutes).
        assert int(resources["mem_mb"]) > 0 and int(resources["runtime"]) > 0, (rule, resources)
    # The config and plot steps run under the Python Snakemake runs under.
    python = interpreter_of(SNAKEMAKE)
    commands = {rule: command for rule, _, command in jobs}
    assert commands["sized_config"].startswith(f"{python} scripts/sweep/make_config.py ")
    assert commands["plot"].startswith(f"{python} scripts/sweep/plot_sweep.py ")


def test_python_config_names_the_interpreter(workdir):
    output = snakemake(workdir, "-n", "-p", "--cores", "1", "--config", "factors=[0.5]", f"skybake={SKYBAKE}",
                       f"cache_dir={workdir / 'cache'}", "python=/opt/site/bin/python3")
    commands = {rule: command for rule, _, command in planned_jobs(output)}
    assert commands["sized_config"].startswith("/opt/site/bin/python3 scripts/sweep/make_config.py ")
    assert commands["plot"].startswith("/opt/site/bin/python3 scripts/sweep/plot_sweep.py ")


def test_envmodules_load_only_when_asked(workdir):
    # A stand-in `module` on PATH logs what the job asks of it; a tiny bake
    # (0.1 of the default sizes) runs in a fraction of a second.
    bin_dir = workdir / "bin"
    bin_dir.mkdir()
    (bin_dir / "module").write_text('#!/bin/sh\necho "module $*" >> "$MODULE_LOG"\n')
    (bin_dir / "module").chmod(0o755)
    log = workdir / "module.log"
    env = {**os.environ, "PATH": f"{bin_dir}{os.pathsep}{os.environ['PATH']}", "MODULE_LOG": str(log)}
    bake = "out/sweep/earth_x0.1.exr"
    config = ["--config", f"skybake={SKYBAKE}", "threads=1", "envmodules=[gcc/12.2.0,openexr/3.1.5]"]
    snakemake(workdir, "--cores", "1", bake, *config, env=env)
    assert (workdir / bake).exists()
    assert not log.exists()
    snakemake(workdir, "--cores", "1", "--use-envmodules", "--force", bake, *config, env=env)
    assert log.read_text().splitlines() == ["module purge", "module load gcc/12.2.0 openexr/3.1.5"]


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
