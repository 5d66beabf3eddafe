#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A one-node Slurm cluster of its own in a folder, for tests: munged, slurmctld and slurmd from
# Debian's packages, each with its key, socket, pid, log, state and spool files in DIR, found by
# the clients through DIR/slurm.conf (SLURM_CONF). Nothing outside DIR is written, nothing is
# started by the system, and the daemons are stopped by the pids in their pid files (never by
# name, so another cluster on the machine is left alone).
#
#   local_slurm.sh start DIR [PORT]   start the three daemons; waits until the node is idle
#   local_slurm.sh stop DIR           SIGTERM the three daemons and wait for them
#   local_slurm.sh env DIR            prints `export SLURM_CONF=...` for the clients
#
# PORT (default 6817) is slurmctld's; slurmd takes PORT+1. Facts this follows (Slurm 22.05,
# munge 0.5.15): munged's socket folder must be mode 0711; without AuthInfo=socket=... every
# client looks for /run/munge; select/linear would run one array task per node at a time.
set -euo pipefail

die() { echo "local_slurm: $*" >&2; exit 1; }

start_munge() {  # DIR
  local dir=$1
  mkdir -p "$dir/munge"
  chmod 0711 "$dir/munge"
  head -c 1024 /dev/urandom > "$dir/munge/munge.key"
  chmod 0400 "$dir/munge/munge.key"
  munged --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
    --seed-file="$dir/munge/munged.seed" --force
  munge -n -S "$dir/munge/munge.socket" | unmunge -S "$dir/munge/munge.socket" > /dev/null ||
    die "munged in $dir/munge does not answer (see $dir/munge/munged.log)"
}

write_conf() {  # DIR PORT
  local dir=$1 port=$2 node
  node=$(slurmd -C | head -1 | sed -e 's/^NodeName=[^ ]*/NodeName=localhost NodeAddr=127.0.0.1/' \
    -e 's/ UpTime=.*//')
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  cat > "$dir/slurm.conf" << EOF
ClusterName=lamina-test
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MinJobAge=300
ReturnToService=2
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
$node State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
}

wait_idle() {  # DIR
  local dir=$1 state i
  for ((i = 0; i < 150; ++i)); do
    state=$(SLURM_CONF=$dir/slurm.conf sinfo -h -o %t 2> /dev/null || true)
    [[ $state == idle ]] && return 0
    sleep 0.1
  done
  die "the node did not become idle in 15 s (state '$state'; logs in $dir/log)"
}

start() {  # DIR [PORT]
  local dir port=${2:-6817}
  dir=$(cd "$1" && pwd)
  for program in munged munge unmunge slurmctld slurmd sinfo; do
    command -v "$program" > /dev/null || die "$program is not installed"
  done
  start_munge "$dir"
  write_conf "$dir" "$port"
  slurmctld -f "$dir/slurm.conf" || die "slurmctld did not start (see $dir/log/slurmctld.log)"
  slurmd -f "$dir/slurm.conf" -N localhost || die "slurmd did not start (see $dir/log/slurmd.log)"
  wait_idle "$dir"
}

stop_pid() {  # PIDFILE
  local pid i
  [[ -s $1 ]] || return 0
  pid=$(cat "$1")
  kill -TERM "$pid" 2> /dev/null || return 0
  for ((i = 0; i < 100; ++i)); do
    kill -0 "$pid" 2> /dev/null || return 0
    sleep 0.1
  done
  kill -KILL "$pid" 2> /dev/null || true
}

stop() {  # DIR
  local dir=$1
  stop_pid "$dir/slurmd.pid"
  stop_pid "$dir/slurmctld.pid"
  stop_pid "$dir/munge/munged.pid"
}

case ${1:-} in
  start) start "${2:?usage: $0 start DIR [PORT]}" "${3:-6817}" ;;
  stop) stop "${2:?usage: $0 stop DIR}" ;;
  env) echo "export SLURM_CONF=$(cd "${2:?usage: $0 env DIR}" && pwd)/slurm.conf" ;;
  *) die "usage: $0 start DIR [PORT] | stop DIR | env DIR" ;;
esac
