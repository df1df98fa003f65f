#!/usr/bin/env bash
# A real single-node Slurm cluster on this machine (Debian's slurmctld, slurmd, munge),
# and the sweep's claims tested on it: a sharded campaign submitted as a job array,
# merged, equals the unsharded table byte for byte; a shard cancelled mid-run and
# resubmitted (--resume) completes the same table. Needs root (it starts the daemons);
# `.ci/run` calls it. Usage: examples/slurm/cluster-test.sh [TESTRIG_BINARY]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
testrig=$(realpath "${1:-$root/target/release/testrig}")
work=$(mktemp -d /tmp/testrig-slurm.XXXXXX)
host=$(hostname -s)
say() { printf '== slurm: %s\n' "$*"; }

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    say "installing slurmctld, slurmd, slurm-client and munge (Debian)"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurmctld slurmd slurm-client munge >/dev/null
fi

running() { # whether a live (not zombie) process of that name exists
    ps -C "$1" -o stat= 2>/dev/null | grep -qv '^Z'
}

passed=0
cleanup() { # the daemons stopped, then (after a pass) the work folder removed
    scancel --user=root >/dev/null 2>&1 || true
    for daemon in slurmd slurmctld munged; do
        [ -f "$work/$daemon.pid" ] && kill "$(cat "$work/$daemon.pid")" 2>/dev/null || true
    done
    for _ in $(seq 50); do
        running slurmctld || running slurmd || break
        sleep 0.1
    done
    if [ "$passed" = 1 ]; then rm -rf "$work"; else echo "logs kept in $work"; fi
}
trap cleanup EXIT

if running slurmctld || running slurmd; then
    say "a slurmctld or slurmd is already running on this machine: stop it first"
    exit 1
fi

say "munge"
mkdir -p "$work/munge" /run/munge
chmod 0700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 0400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket=/run/munge/munge.socket.2 \
    --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge/seed"

say "slurm.conf for $host"
mkdir -p "$work/state" "$work/spool" /etc/slurm
cpus=$(nproc)
cat > /etc/slurm/slurm.conf <<CONF
ClusterName=testrig
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SchedulerType=sched/backfill
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
printf "CgroupPlugin=autodetect\nIgnoreSystemd=yes\n" > /etc/slurm/cgroup.conf
slurmctld
slurmd
for _ in $(seq 60); do
    sinfo -h -o %T 2>/dev/null | grep -Eq '^(idle|mixed|allocated)' && break
    sleep 1
done
sinfo

# A shortened campaign: 12 cases, 4 shards.
sweep="$root/scenarios/thesis-campaign.toml"
cat > "$work/small.toml" <<TOML
$(sed -e 's/^rpm = .*/rpm = [500, 800, 1100, 1300]/' -e 's/^settle_s = .*/settle_s = 10/' \
      -e 's/^measure_s = .*/measure_s = 12/' "$sweep")
TOML
sweep="$work/small.toml"

cases_in() { # folder: finished case files
    local n=0
    if [ -d "$1" ]; then n=$(find "$1" -name '*.json' | wc -l); fi
    echo "$n"
}

wait_for() { # job id: until it has left the queue
    for _ in $(seq 600); do
        [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && return 0
        sleep 1
    done
    say "job $1 did not finish"; return 1
}

say "unsharded reference"
"$testrig" sweep "$sweep" --out "$work/all" >/dev/null

say "job array of 4 shards"
job=$(sbatch --parsable --array=0-3 --chdir="$work" "$here/campaign.sbatch" "$sweep" "$work/array" "$testrig")
wait_for "$job"
"$testrig" merge "$work"/array/shard-* --out "$work/array/merged"
cmp "$work/all/cases.csv" "$work/array/merged/cases.csv"
say "merged job array = unsharded table (byte for byte)"

say "a shard cancelled mid-run, then resubmitted with --resume"
# Longer cases (10 min settling each, about a second of work) so that the cancel lands
# between the shard's first and last case.
sed -e 's/^settle_s = .*/settle_s = 600/' "$sweep" > "$work/long.toml"
"$testrig" sweep "$work/long.toml" --shard 1/4 --out "$work/long-reference" >/dev/null
job=$(sbatch --parsable --array=1 --chdir="$work" "$here/campaign.sbatch" "$work/long.toml" "$work/cancel" "$testrig" 4)
for _ in $(seq 600); do
    [ "$(cases_in "$work/cancel/shard-1/cases")" -ge 1 ] && break
    sleep 0.1
done
scancel "$job"
wait_for "$job"
before=$(cases_in "$work/cancel/shard-1/cases")
say "cancelled with $before of 3 cases finished"
[ "$before" -lt 3 ] || { say "the shard finished before the cancel: nothing was tested"; exit 1; }
job=$(sbatch --parsable --array=1 --chdir="$work" "$here/campaign.sbatch" "$work/long.toml" "$work/cancel" "$testrig" 4)
wait_for "$job"
cat "$work"/slurm-"$job"_1.out
cmp "$work/long-reference/cases.csv" "$work/cancel/shard-1/cases.csv"
say "the resumed shard equals the uninterrupted one (byte for byte)"
say "passed"
passed=1
