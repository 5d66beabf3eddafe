#!/bin/bash
# SPDX-License-Identifier: MIT
# Submits a Lamina batch to Slurm as a job array of TASKS tasks (lamina-batch.sbatch beside this
# file) and a merge job that starts when every task has succeeded (afterok) and joins the parts
# into OUT.csv, OUT.jsonl and OUT.summary.json, exactly what one machine would have written.
# Prints the two job ids ("ARRAY_ID MERGE_ID").
#
#   submit.sh SPEC.json OUT TASKS [CPUS_PER_TASK] [-- BATCH OPTIONS...]
#
# e.g. submit.sh worlds/batch/spin_to_zero.json results/spin 16 8
set -euo pipefail
usage="usage: $0 SPEC.json OUT TASKS [CPUS_PER_TASK] [-- BATCH OPTIONS...]"
spec=${1:?$usage} out=${2:?$usage} tasks=${3:?$usage}
cpus=1
shift 3
if [[ $# -gt 0 && $1 != -- ]]; then cpus=$1; shift; fi
[[ ${1:-} == -- ]] && shift
[[ $tasks =~ ^[1-9][0-9]*$ ]] || { echo "$0: TASKS must be a positive integer, not '$tasks'" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
lamina=${LAMINA_HEADLESS:-lamina-headless}
log=${out}-slurm
array=$(sbatch --parsable --array="0-$((tasks - 1))" --cpus-per-task="$cpus" \
  --output="$log-%A_%a.log" "$here/lamina-batch.sbatch" "$spec" "$out" "$@")
array=${array%%;*}
parts=()
for ((k = 0; k < tasks; ++k)); do parts+=("$out.part-$k-of-$tasks.jsonl"); done
merge=$(sbatch --parsable --job-name=lamina-merge --dependency="afterok:$array" \
  --output="$log-%j-merge.log" --wrap "$(printf '%q ' "$lamina" batch merge "${parts[@]}" --out "$out")")
echo "${array} ${merge%%;*}"
