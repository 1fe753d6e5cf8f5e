#!/usr/bin/env bash
# A private single-node Slurm cluster for the tests: `start STATE` starts munged with its own key,
# socket and state in a fresh temporary folder, then slurmctld and slurmd (as root) with a
# generated slurm.conf (one node, this machine's short host name, with nproc CPUs; state and spool
# in that folder), and writes the folder to STATE; `stop STATE` stops exactly those daemons and
# removes the folder. No system service is touched. The environment a test needs to reach the
# cluster: `. FOLDER/env` (SLURM_CONF and the munge socket).
set -euo pipefail

action=${1:?usage: slurm_cluster.sh start|stop STATE-FILE}
state=${2:?usage: slurm_cluster.sh start|stop STATE-FILE}

find_program() {
  for candidate in "$(command -v "$1" 2>/dev/null || true)" "/usr/sbin/$1" "/usr/bin/$1"; do
    if [ -n "$candidate" ] && [ -x "$candidate" ]; then
      echo "$candidate"
      return 0
    fi
  done
  echo "slurm_cluster.sh: $1 not found (apt-get install slurm-wlm munge)" >&2
  return 1
}

stop_pid() {
  local file=$1
  [ -f "$file" ] || return 0
  local pid
  pid=$(cat "$file")
  if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || return 0
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  fi
}

case "$action" in
  start)
    [ "$(id -u)" -eq 0 ] || { echo "slurm_cluster.sh: slurmd needs root" >&2; exit 1; }
    if [ -f "$state" ]; then "$0" stop "$state" || true; fi
    munged=$(find_program munged)
    mungekey=$(command -v mungekey || echo /usr/sbin/mungekey)
    slurmctld=$(find_program slurmctld)
    slurmd=$(find_program slurmd)
    dir=$(mktemp -d /tmp/tactile-slurm.XXXXXX)
    chmod 755 "$dir"
    mkdir -p "$(dirname "$state")"
    echo "$dir" >"$state"
    trap '"$0" stop "$state" || true' ERR
    mkdir -p "$dir/munge" "$dir/ctld" "$dir/spool" "$dir/log"
    chmod 700 "$dir/munge"
    # munge: its own key, socket, pid and seed files.
    if [ -x "$mungekey" ]; then
      "$mungekey" --create --keyfile="$dir/munge/munge.key" >/dev/null 2>&1
    else
      dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 2>/dev/null
    fi
    chmod 400 "$dir/munge/munge.key"
    "$munged" --key-file="$dir/munge/munge.key" --socket="$dir/munge/socket" \
      --pid-file="$dir/munge/munged.pid" --seed-file="$dir/munge/seed" \
      --log-file="$dir/log/munged.log" --force
    host=$(hostname -s)
    cpus=$(nproc)
    memory=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)
    cat >"$dir/slurm.conf" <<EOF
ClusterName=tactiletest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/socket
CredType=cred/munge
SlurmctldPort=$((20000 + RANDOM % 20000))
SlurmdPort=$((40000 + RANDOM % 20000))
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool/slurmd-%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=2
MinJobAge=300
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    printf 'export SLURM_CONF=%s\n' "$dir/slurm.conf" >"$dir/env"
    export SLURM_CONF="$dir/slurm.conf"
    "$slurmctld" -i -f "$dir/slurm.conf" ||
      { cat "$dir/log/slurmctld.log" >&2 || true; "$0" stop "$state"; exit 1; }
    "$slurmd" -f "$dir/slurm.conf" ||
      { cat "$dir/log/slurmd.log" >&2 || true; "$0" stop "$state"; exit 1; }
    trap - ERR
    # Ready when the node takes jobs.
    for _ in $(seq 100); do
      if sinfo -h -N -o '%T' 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; then
        echo "Slurm $(sinfo -V | awk '{print $2}') on $host ($cpus CPUs), state in $dir"
        exit 0
      fi
      sleep 0.2
    done
    echo "slurm_cluster.sh: the node never became idle" >&2
    sinfo -N >&2 || true
    tail -n 20 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
    "$0" stop "$state" || true
    exit 1
    ;;
  stop)
    [ -f "$state" ] || exit 0
    dir=$(cat "$state")
    if [ -n "$dir" ] && [ -d "$dir" ]; then
      stop_pid "$dir/slurmd.pid"
      stop_pid "$dir/slurmctld.pid"
      stop_pid "$dir/munge/munged.pid"
      case "$dir" in /tmp/tactile-slurm.*) rm -rf "$dir" ;; esac
    fi
    rm -f "$state"
    ;;
  *)
    echo "usage: slurm_cluster.sh start|stop STATE-FILE" >&2
    exit 2
    ;;
esac
