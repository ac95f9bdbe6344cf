#!/usr/bin/env bash
# ctest `slurm_campaign` (label slurm, issue 18): a real single-node Slurm cluster (Debian's
# slurm-wlm + munge) runs a 4-task array of a short campaign through tools/slurm/submit.sh, the
# merge job chained after it joins the shards, and the merged tables must be byte-identical to
# the same campaign run in one process with --jobs 1. Starts munged (unless one already runs),
# slurmctld and slurmd with a configuration in a temporary directory, and stops exactly the
# daemons it started (by pid, never by name). Needs root (the daemons run as root here).
#   slurm_campaign_test.sh ADCS_SIM SOURCE_DIR
set -euo pipefail
sim=$1
src=$2
[ "$(id -u)" -eq 0 ] || { echo "slurm_campaign_test: needs root to start munged/slurmctld/slurmd" >&2; exit 1; }
for b in munged slurmctld slurmd sbatch sinfo scontrol; do
  command -v "$b" >/dev/null || { echo "slurm_campaign_test: $b missing: run tools/setup-deps.sh" >&2; exit 1; }
done
tmp=$(mktemp -d /tmp/adcs-slurm.XXXXXX)
started=()
cleanup() {
  for pidfile in "${started[@]}"; do
    [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
  done
  sleep 1
  rm -rf "$tmp"
}
trap cleanup EXIT

# --- munge: reuse a running munged, else start one (and stop it afterwards) ---
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge 2>/dev/null || true
  su -s /bin/sh munge -c /usr/sbin/munged
  started+=(/run/munge/munged.pid)
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
fi
munge -n | unmunge | grep -q 'STATUS: *Success' || { echo "slurm_campaign_test: munge does not work" >&2; exit 1; }

# --- a one-node cluster, every path in the temporary directory ---
host=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool"
cat > "$tmp/slurm.conf" <<CONF
ClusterName=adcstest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -f "$SLURM_CONF"
started+=("$tmp/slurmctld.pid")
slurmd -f "$SLURM_CONF"
started+=("$tmp/slurmd.pid")
for _ in $(seq 60); do
  sinfo -h -o '%t' 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 0.5
done
sinfo -h -o '%t' | grep -qE '^(idle|mix|alloc)' || { echo "slurm_campaign_test: the node never came up" >&2; cat "$tmp"/*.log >&2; exit 1; }

# --- the campaign: 4 array tasks + the chained merge job, then the same in one process ---
campaign=(rigid-rw-mrp-pd --runs 12 --seed0 3 --set duration_s=200
          --disperse 'J_kgm2=inertia(0.1, 2)' --disperse 'wheel_axes_B=axes(0.5)' --disperse 'K_Nm=rel_normal(0.1)'
          --series att_err_rad)
start=$(date +%s)
ADCS_SIM=$sim bash "$src/tools/slurm/submit.sh" --wait 4 "$tmp/slurm-out" "${campaign[@]}"
echo "slurm: array + merge done in $(( $(date +%s) - start )) s"
"$sim" montecarlo "${campaign[@]}" --jobs 1 --out "$tmp/one" > /dev/null
for f in rigid-rw-mrp-pd-montecarlo.csv rigid-rw-mrp-pd-montecarlo.json rigid-rw-mrp-pd-montecarlo-series.h5; do
  cmp "$tmp/slurm-out/$f" "$tmp/one/$f" || { echo "slurm_campaign_test: $f differs between the Slurm array and --jobs 1" >&2; exit 1; }
done
n=$(ls "$tmp/slurm-out"/rigid-rw-mrp-pd-montecarlo.shard-*-of-4.log.jsonl | wc -l)
[ "$n" -eq 4 ] || { echo "slurm_campaign_test: expected 4 shard logs, found $n" >&2; exit 1; }
echo "slurm_campaign_test: 4 shards merged = --jobs 1, byte for byte"
