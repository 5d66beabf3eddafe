#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The seed's batch on a real one-node Slurm cluster: local_slurm.sh starts munged, slurmctld and
# slurmd (Debian's packages) in a temporary folder; docs/slurm/submit.sh submits SPEC as a 4-task
# job array and a merge job; the merged CSV and JSON Lines must equal, byte for byte, what one
# machine writes with 2 threads (wall times left out of both). The daemons are stopped by pid
# and the folder removed however the test ends.
#
#   slurm_array_test.sh BIN_DIR SOURCE_DIR SPEC
#
# When Slurm is not installed and cannot be (cmake/setup-deps.sh slurm: root or sudo and
# Debian's registry), the test says why and exits 77, which CTest reports as skipped.
# KEEP_TMP=1 keeps the folder (results, parts, job and daemon logs) for a look afterwards.
set -euo pipefail
bin=${1:?usage: $0 BIN_DIR SOURCE_DIR SPEC} source=${2:?} spec=${3:?}
here=$(cd "$(dirname "$0")" && pwd)
tasks=4

have_slurm() {
  local program
  for program in munged munge unmunge slurmctld slurmd sbatch squeue scontrol sinfo; do
    command -v "$program" > /dev/null || return 1
  done
}

if ! have_slurm; then
  echo "Slurm is not installed: installing it (cmake/setup-deps.sh slurm)"
  if ! bash "$source/cmake/setup-deps.sh" slurm || ! have_slurm; then
    echo "SKIPPED: Slurm could not be installed here (needs root or sudo and Debian's registry)"
    exit 77
  fi
fi

tmp=$(mktemp -d /tmp/lamina-slurm.XXXXXX)
chmod 0755 "$tmp"
cleanup() {
  bash "$here/local_slurm.sh" stop "$tmp/cluster" || true
  rm -rf "$tmp"
}
trap cleanup EXIT
[[ -n ${KEEP_TMP:-} ]] && trap 'bash "$here/local_slurm.sh" stop "$tmp/cluster"; echo "kept $tmp"' EXIT

# slurmctld's port and slurmd's (port + 1), free on this machine
port_free() { ! (exec 3<> "/dev/tcp/127.0.0.1/$1") 2> /dev/null; }
port=$((20000 + 2 * ($$ % 5000)))
while ! port_free "$port" || ! port_free $((port + 1)); do port=$((port + 2)); done

mkdir "$tmp/cluster"
bash "$here/local_slurm.sh" start "$tmp/cluster" "$port"
export SLURM_CONF=$tmp/cluster/slurm.conf
export LAMINA_HEADLESS=$bin/lamina-headless

"$LAMINA_HEADLESS" batch "$spec" --threads 2 --no-wall-time --quiet --out "$tmp/single" > /dev/null

read -r array merge < <(bash "$source/docs/slurm/submit.sh" "$spec" "$tmp/cluster-run" "$tasks" 1 \
  -- --no-wall-time)
echo "submitted array job $array and merge job $merge"

# waits for both jobs to leave the queue (60 s at most)
for ((i = 0; i < 300; ++i)); do
  [[ -z $(squeue -h -j "$array,$merge" 2> /dev/null) ]] && break
  sleep 0.2
done

status=0
for job in "$array" "$merge"; do
  states=$(scontrol show job "$job" | grep -o 'JobState=[A-Z_]*\|ExitCode=[0-9:]*' | sort | uniq -c)
  echo "job $job: $(echo $states)"
  if grep -qv 'JobState=COMPLETED\|ExitCode=0:0' <<< "$states"; then status=1; fi
done
expected_tasks=$(scontrol show job "$array" | grep -c 'JobState=COMPLETED' || true)
if [[ $expected_tasks -ne $tasks ]]; then
  echo "FAILED: $expected_tasks of $tasks array tasks completed"
  status=1
fi
if [[ $status -ne 0 ]]; then
  echo "FAILED: a job did not complete; its logs:"
  tail -n 20 "$tmp"/cluster-run-slurm-*.log "$tmp/cluster/log/"*.log || true
  exit 1
fi

for ext in csv jsonl; do
  if ! cmp "$tmp/single.$ext" "$tmp/cluster-run.$ext"; then
    echo "FAILED: the merged $ext differs from the single-machine run"
    diff "$tmp/single.$ext" "$tmp/cluster-run.$ext" | head -n 20
    exit 1
  fi
done
runs=$(($(wc -l < "$tmp/single.csv") - 1))
echo "PASSED: $runs runs in $tasks array tasks, merged, identical to one machine (csv and jsonl)"
