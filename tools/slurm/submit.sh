#!/usr/bin/env bash
# Submits a Monte Carlo campaign to Slurm as a job array of SHARDS tasks and chains the merge
# job after it (--dependency=afterok: it starts only if every task succeeded; if one fails, the
# merge is cancelled, --kill-on-invalid-dep). A failed or killed task is rerun with the same
# command: `--resume` (in montecarlo.sbatch) runs only its missing runs.
#
# Usage: tools/slurm/submit.sh [--wait] SHARDS OUT_DIR TARGET [montecarlo options ...]
#   TARGET   a registered scenario name or a vehicle file (a path every node can read)
#   options  as for adcs-sim montecarlo (--runs, --seed0, --disperse, --set, --series, ...)
#   --wait   return only when the merge job has ended (its exit status)
# The adcs-sim binary is $ADCS_SIM (default: build/src/adcs-sim of this checkout); extra sbatch
# options (partition, account, time, cpus) go in $SBATCH_OPTIONS, e.g.
#   SBATCH_OPTIONS="--partition=batch --time=02:00:00 --cpus-per-task=4" tools/slurm/submit.sh 32 /scratch/mc cubesat.toml --runs 10000
# Prints "ARRAY_JOB_ID MERGE_JOB_ID".
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
wait_flag=()
if [ "${1:-}" = "--wait" ]; then wait_flag=(--wait); shift; fi
if [ $# -lt 3 ]; then
  sed -n '2,17p' "${BASH_SOURCE[0]}" >&2
  exit 2
fi
shards=$1
out=$2
shift 2
case "$shards" in ''|*[!0-9]*) echo "submit.sh: SHARDS must be a positive integer, got '$shards'" >&2; exit 2;; esac
[ "$shards" -ge 1 ] || { echo "submit.sh: SHARDS must be >= 1" >&2; exit 2; }
sim=${ADCS_SIM:-"$here/../../build/src/adcs-sim"}
[ -x "$sim" ] || { echo "submit.sh: no adcs-sim at $sim (build it, or set ADCS_SIM)" >&2; exit 2; }
sim=$(cd "$(dirname "$sim")" && pwd)/$(basename "$sim")
mkdir -p "$out"
out=$(cd "$out" && pwd)
# shellcheck disable=SC2086  # SBATCH_OPTIONS is a list of options
array=$(sbatch --parsable ${SBATCH_OPTIONS:-} --chdir="$out" --output="$out/slurm-%A_%a.out" \
  --array=0-$((shards - 1)) "$here/montecarlo.sbatch" "$sim" "$out" "$@")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable "${wait_flag[@]}" ${SBATCH_OPTIONS:-} --chdir="$out" --output="$out/slurm-merge-%j.out" \
  --dependency=afterok:"$array" --kill-on-invalid-dep=yes "$here/merge.sbatch" "$sim" "$out")
echo "$array ${merge%%;*}"
