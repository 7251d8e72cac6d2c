#!/usr/bin/env bash
# Runs a sharded render on a real Slurm: a one-node cluster (slurmctld + slurmd + munged) on
# this machine, started here and stopped on exit. Submits the documented array job
# (docs/examples/slurm/render-array.sh) with `sbatch --array`, waits for it, merges the parts
# and checks the merged image against the single-process render byte for byte.
#
# Usage: tests/slurm/run.sh [RTC_BINARY]   (default target/release/rtc; run from the repo root)
# Installs slurm-wlm and munge with apt-get when absent (needs root). When Slurm cannot be
# started it says so loudly; it fails only in CI (CI=true), elsewhere it exits 0 after the
# message so a developer without root is not blocked.
set -uo pipefail
cd "$(dirname "$0")/../.."
rtc=$(realpath "${1:-target/release/rtc}")
scene=scenes/five_spheres.rtc
shards=4

cannot() {
  echo "tests/slurm: CANNOT RUN SLURM HERE: $*" >&2
  if [ "${CI:-}" = "true" ]; then exit 1; fi
  echo "tests/slurm: skipped (not in CI)" >&2
  exit 0
}

[ -x "$rtc" ] || cannot "no rtc binary at $rtc (cargo build --release first)"
if ! command -v sbatch >/dev/null || ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  [ "$(id -u)" = 0 ] || cannot "slurm-wlm and munge are not installed and this is not root"
  echo "tests/slurm: installing slurm-wlm and munge" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge >/tmp/rtc-slurm-apt.log 2>&1 \
    || { apt-get update -q >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge >/tmp/rtc-slurm-apt.log 2>&1; } \
    || cannot "apt-get install slurm-wlm munge failed (see /tmp/rtc-slurm-apt.log)"
fi
[ "$(id -u)" = 0 ] || cannot "starting slurmd needs root"

work=$(mktemp -d /tmp/rtc-slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  sleep 0.5
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

# munge: a fresh key and a private socket, so a system munged (if any) is left alone.
mkdir -p "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
socket=$work/munge/munge.socket
munged --force -f --key-file="$work/munge/munge.key" --socket="$socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/seed" \
  || cannot "munged did not start (see $work/munge/munged.log)"
sleep 0.5
[ -f "$work/munge/munged.pid" ] && pids+=("$(cat "$work/munge/munged.pid")")

host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool" "$work/out"
cat >"$work/slurm.conf" <<CONF
ClusterName=rtc-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=${RTC_SLURMCTLD_PORT:-16817}
SlurmdPort=${RTC_SLURMD_PORT:-16818}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=rtc Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf

slurmctld -c -i -f "$SLURM_CONF" || cannot "slurmctld did not start (see $work/slurmctld.log)"
slurmd -f "$SLURM_CONF" || cannot "slurmd did not start (see $work/slurmd.log)"
sleep 1
for f in slurmctld.pid slurmd.pid; do [ -f "$work/$f" ] && pids+=("$(cat "$work/$f")"); done

ready=""
for _ in $(seq 1 60); do
  if sinfo -h -o '%t' 2>/dev/null | grep -qE '^(idle|mix)'; then ready=1; break; fi
  sleep 0.5
done
[ -n "$ready" ] || { tail -5 "$work/slurmctld.log" "$work/slurmd.log" >&2; cannot "the Slurm node never became idle"; }

start=$(date +%s.%N)
RTC="$rtc" sbatch --wait --array=0-$((shards - 1)) --chdir="$work" \
  --export=ALL,RTC="$rtc" "$PWD/docs/examples/slurm/render-array.sh" "$PWD/$scene" "$work/out" >"$work/sbatch.txt" \
  || { cat "$work"/rtc-shard-*.log >&2 2>/dev/null; echo "tests/slurm: the array job failed" >&2; exit 1; }
end=$(date +%s.%N)

"$rtc" merge "$work"/out/part-*.rtcpart -o "$work/merged.png" || { echo "tests/slurm: merge failed" >&2; exit 1; }
"$rtc" render "$scene" -o "$work/single.png" 2>/dev/null || { echo "tests/slurm: single render failed" >&2; exit 1; }
if cmp -s "$work/merged.png" "$work/single.png"; then
  printf 'tests/slurm: %d array tasks under Slurm %s, merged = single render byte for byte (array job %.1f s)\n' \
    "$shards" "$(sinfo -V | cut -d' ' -f2)" "$(echo "$end - $start" | bc)"
else
  echo "tests/slurm: the merged image differs from the single render" >&2
  exit 1
fi
