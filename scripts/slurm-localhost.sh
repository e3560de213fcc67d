#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for trying `raintrace render --backend slurm` and for
# the Slurm tests (render/slurm_render_test.cpp). What it makes lives in DIR: the
# configuration, state, logs and the daemons' PIDs; its munge key and the sockets go into a
# short folder of their own (Unix socket paths have a length limit), named in DIR/sockets and
# removed by `stop`. It touches neither /etc/slurm nor the system's munge, and it picks free
# ports, so it runs beside another cluster on the same machine.
#
#   scripts/slurm-localhost.sh start DIR   start munged, slurmctld and slurmd; wait until the
#                                          node is idle; print the SLURM_CONF line to use
#   scripts/slurm-localhost.sh stop DIR    stop exactly the daemons `start DIR` started
#
# Then, in the shell that submits:   export SLURM_CONF=DIR/slurm.conf
#
# DIR must be reachable by the users munge and slurm, whose daemons keep their files there (a
# folder in /tmp is; one inside a private home folder is not).
#
# Needs root (slurmd runs each job as the user who submitted it) and the Debian packages
# slurmctld, slurmd, slurm-client and munge (scripts/install-deps.sh --test installs them).
# No systemd and no cgroups needed: processes are tracked by /proc (proctrack/linuxproc) and
# there is no accounting database, so per-task results come from `scontrol show job`.
# A real cluster also needs DIR and the rendered folder on a filesystem every node mounts.
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
action=$1
dir=$(realpath -m "$2")

stop_daemons() {
  [[ -f $dir/pids ]] || return 0
  # Newest first (slurmd, slurmctld, then munged), and wait for each to be gone.
  local pid
  for pid in $(tac "$dir/pids"); do kill "$pid" 2>/dev/null || true; done
  for pid in $(cat "$dir/pids"); do
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  done
  rm -f "$dir/pids"
  # The sockets' folder (see below).
  if [[ -f $dir/sockets ]]; then rm -rf "$(cat "$dir/sockets")"; rm -f "$dir/sockets"; fi
}

case $action in
  stop) stop_daemons; exit 0 ;;
  start) ;;
  *) usage ;;
esac

[[ $(id -u) == 0 ]] || { echo "slurm-localhost: start needs root" >&2; exit 1; }
for program in munged mungekey slurmctld slurmd sinfo; do
  command -v "$program" >/dev/null || {
    echo "slurm-localhost: $program is missing (scripts/install-deps.sh --test installs Slurm)" >&2
    exit 1
  }
done
[[ -f $dir/pids ]] && { echo "slurm-localhost: already started in $dir (stop it first)" >&2; exit 1; }

# A port nothing listens on: a random one that refuses a connection (bash's /dev/tcp).
free_port() {
  local port
  while true; do
    port=$((20000 + RANDOM % 40000))
    [[ $port != "${1:-}" ]] || continue
    (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || { echo "$port"; return; }
  done
}

mkdir -p "$dir"
chmod 0755 "$dir"
for user in munge slurm; do
  setpriv --reuid="$user" --regid="$user" --init-groups test -x "$dir" || {
    echo "slurm-localhost: user $user cannot reach $dir; use a folder it can (e.g. in /tmp)" >&2
    exit 1
  }
done
: >"$dir/pids"
trap 'echo "slurm-localhost: start failed; logs in $dir" >&2; stop_daemons' ERR

# Unix sockets (munge's, slurmd's per job step) cannot have paths longer than 107 bytes: they
# live in a short folder of their own, whatever DIR is; DIR/sockets names it for `stop`.
sockets=$(mktemp -d -t rt-slurm.XXXXXX)
chmod 0755 "$sockets"
echo "$sockets" >"$dir/sockets"

# munge: its own key and socket. munged refuses a key that others could write or read and a
# socket folder that not everyone may enter (slurm and submitting users talk to the socket).
munge_dir=$sockets/munge
install -d -o munge -g munge -m 0755 "$munge_dir"
[[ -s $munge_dir/munge.key ]] || mungekey --create --keyfile="$munge_dir/munge.key"
chown munge:munge "$munge_dir/munge.key"
chmod 0400 "$munge_dir/munge.key"
socket=$munge_dir/munge.socket
setpriv --reuid=munge --regid=munge --init-groups \
  munged --foreground --socket="$socket" --key-file="$munge_dir/munge.key" \
  --pid-file="$munge_dir/munged.pid" --log-file="$munge_dir/munged.log" \
  --seed-file="$munge_dir/munged.seed" >"$dir/munged.log" 2>&1 &
echo $! >>"$dir/pids"
for _ in $(seq 100); do [[ -S $socket ]] && break; sleep 0.1; done
munge --socket="$socket" -n | unmunge --socket="$socket" >/dev/null

# Slurm: state and logs in DIR, owned by the slurm user that slurmctld runs as.
install -d -o slurm -g slurm -m 0755 "$dir/state" "$dir/log"
install -d -m 0755 "$sockets/spool"
ctld_port=$(free_port)
slurmd_port=$(free_port "$ctld_port")
memory_mb=$(awk '/MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
cat >"$dir/slurm.conf" <<CONF
# Written by scripts/slurm-localhost.sh: a one-node cluster for tests.
ClusterName=raintrace-local
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=slurm
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$sockets/spool
SlurmctldPidFile=$dir/state/slurmctld.pid
SlurmdPidFile=$sockets/spool/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory_mb State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >/dev/null 2>&1 &
echo $! >>"$dir/pids"
slurmd -D -N localhost -f "$SLURM_CONF" >/dev/null 2>&1 &
echo $! >>"$dir/pids"

for _ in $(seq 300); do
  [[ $(sinfo -h -o %t 2>/dev/null) == idle ]] && break
  sleep 0.2
done
if [[ $(sinfo -h -o %t 2>/dev/null) != idle ]]; then
  echo "slurm-localhost: the node did not become idle; see $dir/log/" >&2
  stop_daemons
  exit 1
fi
trap - ERR
echo "slurm-localhost: cluster up (partition main). Use it with:"
echo "  export SLURM_CONF=$SLURM_CONF"
echo "Stop it with: $0 stop $dir"
