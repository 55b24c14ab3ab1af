#!/usr/bin/env bash
# A small sweep through Slurm: starts a one-node Slurm cluster of its own
# (munged, slurmctld and slurmd from Debian, configured in a temporary
# directory through SLURM_CONF, on ports of its own), runs the sweep with
# `snakemake --profile scripts/sweep/slurm`, runs the same sweep locally, and
# checks that both collected the same figures. Every daemon it started is
# stopped by its PID at the end, whatever happens.
#
# Usage: slurm_sweep_test.sh SKYBAKE SOURCE_DIR
set -euo pipefail
skybake=$(realpath "$1")
source_dir=$(realpath "$2")
for program in munged mungekey slurmctld slurmd sbatch scontrol sinfo snakemake; do
  command -v "$program" > /dev/null || { echo "slurm_sweep_test: $program not found (scripts/setup.sh installs it)"; exit 1; }
done

work=$(mktemp -d /tmp/skybake-slurm.XXXXXX)
# munged requires every directory above its socket to be searchable by all.
chmod 755 "$work"
pids=()
stop_daemons() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2> /dev/null || true
  done
  if [[ $status -ne 0 ]]; then
    for log in "$work"/log/*.log; do echo "== $log"; tail -n 30 "$log"; done
  fi
  rm -rf "$work"
  exit "$status"
}
trap stop_daemons EXIT

# Ports nothing else listens on, chosen by the kernel.
free_port() { /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
ctld_port=$(free_port)
slurmd_port=$(free_port)
while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done

mkdir -p "$work"/{munge,log,state,spool,repo}
chmod 755 "$work/munge"
mungekey --create --keyfile "$work/munge/munge.key"
chmod 600 "$work/munge/munge.key"
munged --foreground --socket "$work/munge/socket" --key-file "$work/munge/munge.key" \
  --pid-file "$work/munge/munged.pid" --seed-file "$work/munge/seed" --log-file "$work/log/munged.log" &
pids+=($!)

node=$(hostname -s)
cpus=$(nproc)
# Memory the node offers jobs: what is available now, less a reserve for the
# daemons and this test's local sweep.
memory_mb=$(( $(awk '/MemAvailable/ {print int($2 / 1024)}' /proc/meminfo) - 2048 ))
export SLURM_CONF="$work/slurm.conf"
# Snakemake's Slurm executor reads the user name from the environment.
export USER=${USER:-$(id -un)}
cat > "$SLURM_CONF" << EOF
ClusterName=skybake-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
SlurmdTimeout=300
InactiveLimit=0
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -i > "$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D > "$work/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  if sinfo -h -o '%t' 2> /dev/null | grep -q '^idle'; then break; fi
  sleep 1
done
sinfo -h -o '%t' | grep -q '^idle' || { echo "slurm_sweep_test: the node never became idle"; sinfo || true; exit 1; }

# The sweep runs in a copy of the workflow's scripts, so its outputs stay in
# the temporary directory.
cp -r "$source_dir/scripts" "$source_dir/data_formats" "$work/repo/"
cd "$work/repo"
# Two sizes, the quick query set, few paths: the figures are not the point,
# their equality is. Two reference pieces, so the validate jobs wait for two
# jobs that share one cache.
sweep_config=(factors=[0.25,0.5] queries=quick reference_samples=256 reference_pieces=2 threads=1
  "skybake=$skybake")
start=$(date +%s)
# Status once a second, not the profile's default of every 30 s: the jobs
# here take seconds.
snakemake -s scripts/sweep/Snakefile --profile scripts/sweep/slurm --latency-wait 5 --max-status-checks-per-second 1 \
  --config "${sweep_config[@]}" out=out/slurm cache_dir="$work/cache_slurm" > "$work/log/snakemake_slurm.log" 2>&1 ||
  { echo "slurm_sweep_test: the Slurm sweep failed"; tail -n 60 "$work/log/snakemake_slurm.log"; exit 1; }
echo "slurm_sweep_test: the Slurm sweep took $(( $(date +%s) - start )) s"
# Its jobs really went through Slurm, one per bake, piece and validation
# (the config and plot rules are local), as both sides saw them.
submitted=$(grep -c "has been submitted with SLURM jobid" "$work/log/snakemake_slurm.log" || true)
completed=$(grep -c "JobId=[0-9]* done" "$work/log/slurmctld.log" || true)
if [[ $submitted -ne 6 || $completed -ne 6 ]]; then
  echo "slurm_sweep_test: $submitted jobs submitted, $completed completed by slurmctld; expected 6"
  exit 1
fi

snakemake -s scripts/sweep/Snakefile --cores 2 --config "${sweep_config[@]}" out=out/local \
  cache_dir="$work/cache_local" > "$work/log/snakemake_local.log" 2>&1 ||
  { echo "slurm_sweep_test: the local sweep failed"; tail -n 60 "$work/log/snakemake_local.log"; exit 1; }

# The same figures, bake by bake. Bake times and thread counts differ, and
# so do the file sizes, by the few bytes of the header's bake report (times,
# threads, memory).
/usr/bin/python3 - out/slurm/sweep.csv out/local/sweep.csv << 'EOF'
import csv
import sys

def figures(path):
    with open(path, newline="") as f:
        rows = {r["bake"]: r for r in csv.DictReader(f)}
    return {bake: {k: v for k, v in r.items() if k not in ("bake_seconds", "threads", "file_mib")} for bake, r in rows.items()}

slurm, local = figures(sys.argv[1]), figures(sys.argv[2])
if slurm != local or len(slurm) != 2:
    sys.exit(f"slurm_sweep_test: the collected figures differ:\nslurm {slurm}\nlocal {local}")
print(f"slurm_sweep_test: {len(slurm)} bakes, the same figures through Slurm and locally")
EOF
