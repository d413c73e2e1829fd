#!/usr/bin/env bash
# Submits a sharded sweep and its merge in one go: a job array of N shards
# (sweep.sbatch), then the merge (merge.sbatch) once every task succeeded.
#
#   scripts/slurm/submit.sh N PARTS_DIR OUT COMMAND ARGS...
#
# Extra sbatch options go in SBATCH_OPTS (e.g. "--cpus-per-task=8
# --time=2:00:00 --account=abc123"). Prints the two job ids.
set -euo pipefail
if [ $# -lt 4 ]; then
    echo "usage: submit.sh N PARTS_DIR OUT COMMAND ARGS..." >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
n=$1
parts=$(mkdir -p "$2" && cd "$2" && pwd)
out=$3
shift 3
# shellcheck disable=SC2086
array=$(sbatch --parsable ${SBATCH_OPTS:-} --array="1-$n" --chdir="$PWD" \
    --output="$parts/slurm-%A_%a.out" "$here/sweep.sbatch" "$parts" "$@")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_OPTS:-} --dependency="afterok:$array" --chdir="$PWD" \
    --output="$parts/slurm-merge-%j.out" "$here/merge.sbatch" "$parts" "$out")
merge=${merge%%;*}
echo "$array $merge"
