#!/bin/bash
# A single-node Slurm cluster on this machine, private to one folder: for
# trying vslam-batch --slurm without a cluster, and for its test.
#
#   scripts/slurm_local_cluster.sh start DIR   install Debian's slurm-wlm,
#       slurmdbd, munge and mariadb-server if missing (root), then start in
#       DIR a munge daemon, a MariaDB server, slurmdbd (so sacct works),
#       slurmctld and one slurmd with this machine's CPUs; waits until the
#       node is idle. Then: export SLURM_CONF=DIR/slurm.conf
#   scripts/slurm_local_cluster.sh stop DIR    stop them all
#
# Everything (keys, sockets, databases, logs) lives in DIR; the daemons
# listen on free ports of 127.0.0.1 only; the system's own munge or Slurm
# (if any) are not touched. Runs as root (Slurm's daemons run jobs as
# their users).
set -euo pipefail

MODE="${1:-}"
DIR="${2:-}"
[[ ("$MODE" == start || "$MODE" == stop) && -n "$DIR" ]] || {
  sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'
  exit 1
}
PACKAGES=(slurm-wlm slurmdbd munge mariadb-server)

die() { echo "[slurm-local] error: $*" >&2; exit 1; }

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [[ ${#missing[@]} -eq 0 ]] && return
  echo "[slurm-local] installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y --no-install-recommends "${missing[@]}" > "$DIR/apt.log" 2>&1 ||
    { apt-get update >> "$DIR/apt.log" 2>&1 &&
      apt-get install -y --no-install-recommends "${missing[@]}" >> "$DIR/apt.log" 2>&1; } ||
    die "could not install ${missing[*]} (see $DIR/apt.log)"
}

# A TCP port of 127.0.0.1 nothing listens on, at or above $1.
free_port() {
  local p=$1
  while (exec 3<> "/dev/tcp/127.0.0.1/$p") 2> /dev/null; do p=$((p + 1)); done
  echo "$p"
}

# Waits up to $2 seconds for the command $1 to succeed.
wait_for() {
  local i
  for ((i = 0; i < $2 * 4; i++)); do
    timeout 10 bash -c "$1" > /dev/null 2>&1 && return 0
    sleep 0.25
  done
  return 1
}

# Slurm's clients reach munge only at its default socket: a munged already
# serving it (the system's) is used; otherwise one is started there with a
# key of this cluster's own, and stopped with it.
start_munge() {
  if munge -n > /dev/null 2>&1; then
    echo "[slurm-local] using the munge daemon already running"
    return
  fi
  mungekey --create --keyfile="$DIR/munge/munge.key" --force > /dev/null 2>&1 ||
    dd if=/dev/urandom of="$DIR/munge/munge.key" bs=1024 count=1 2> /dev/null
  chmod 600 "$DIR/munge/munge.key"
  mkdir -p /run/munge
  /usr/sbin/munged --force --key-file="$DIR/munge/munge.key" --pid-file="$DIR/munge/munged.pid" \
    --log-file="$DIR/log/munged.log" --seed-file="$DIR/munge/munged.seed"
  wait_for "munge -n" 10 || die "munged did not start ($DIR/log/munged.log)"
}

start_mariadb() {
  mariadb-install-db --datadir="$DIR/db" --user=root --auth-root-authentication-method=normal \
    > "$DIR/log/mariadb-install.log" 2>&1 || die "mariadb-install-db failed ($DIR/log/mariadb-install.log)"
  (mariadbd --datadir="$DIR/db" --user=root --socket="$DIR/db/mysqld.sock" --port="$DB_PORT" \
    --bind-address=127.0.0.1 --pid-file="$DIR/db/mariadbd.pid" --log-error="$DIR/log/mariadb.log" \
    > /dev/null 2>&1 &)
  wait_for "mariadb --socket='$DIR/db/mysqld.sock' -uroot -e 'select 1'" 60 ||
    die "MariaDB did not start ($DIR/log/mariadb.log)"
  mariadb --socket="$DIR/db/mysqld.sock" -uroot -e \
    "CREATE USER 'slurm'@'127.0.0.1' IDENTIFIED BY 'slurm'; GRANT ALL ON slurm_acct_db.* TO 'slurm'@'127.0.0.1';"
}

write_configs() {
  local node mem
  node="$(hostname -s)"
  mem=$(($(awk '/MemTotal/ {print int($2 / 1024)}' /proc/meminfo) * 9 / 10))
  cat > "$DIR/slurm.conf" << EOF
ClusterName=vslamlocal
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
AuthType=auth/munge
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/affinity
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
JobAcctGatherType=jobacct_gather/linux
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=127.0.0.1
AccountingStoragePort=$DBD_PORT
MpiDefault=none
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
  cat > "$DIR/slurmdbd.conf" << EOF
AuthType=auth/munge
DbdHost=localhost
DbdAddr=127.0.0.1
DbdPort=$DBD_PORT
SlurmUser=root
PidFile=$DIR/slurmdbd.pid
LogFile=$DIR/log/slurmdbd.log
StorageType=accounting_storage/mysql
StorageHost=127.0.0.1
StoragePort=$DB_PORT
StorageUser=slurm
StoragePass=slurm
StorageLoc=slurm_acct_db
EOF
  chmod 600 "$DIR/slurmdbd.conf"
}

start() {
  [[ $EUID -eq 0 ]] || die "needs root (Slurm's daemons run jobs as their users)"
  [[ ! -e "$DIR/slurm.conf" ]] || die "$DIR already holds a cluster (stop it first)"
  mkdir -p "$DIR"/{munge,state,spool,log}
  DIR="$(cd "$DIR" && pwd)"
  install_packages
  DB_PORT=$(free_port 16810)
  DBD_PORT=$(free_port $((DB_PORT + 1)))
  CTLD_PORT=$(free_port $((DBD_PORT + 1)))
  SLURMD_PORT=$(free_port $((CTLD_PORT + 1)))
  write_configs
  export SLURM_CONF="$DIR/slurm.conf"
  start_munge
  start_mariadb
  slurmdbd || die "slurmdbd did not start ($DIR/log/slurmdbd.log)"
  wait_for "sacctmgr -n list cluster" 30 || die "slurmdbd does not answer ($DIR/log/slurmdbd.log)"
  sacctmgr -i add cluster vslamlocal > /dev/null 2>&1 || true
  slurmctld -f "$SLURM_CONF" || die "slurmctld did not start ($DIR/log/slurmctld.log)"
  slurmd -f "$SLURM_CONF" -N "$(hostname -s)" || die "slurmd did not start ($DIR/log/slurmd.log)"
  wait_for "sinfo -h -o %t | grep -qx idle" 60 || die "the node is not idle: $(sinfo 2>&1) ($DIR/log/)"
  echo "[slurm-local] cluster up in $DIR: $(sinfo -h -o '%P %D node(s), %c CPUs, %m MiB, %t')"
  echo "[slurm-local] use it with: export SLURM_CONF=$SLURM_CONF"
}

# Sends SIGTERM to the process in pid file $1 and waits for it to end.
stop_pid() {
  [[ -s "$1" ]] || return 0
  local pid
  pid=$(cat "$1")
  kill "$pid" 2> /dev/null || return 0
  wait_for "! kill -0 $pid" 20 || kill -9 "$pid" 2> /dev/null || true
}

stop() {
  DIR="$(cd "$DIR" && pwd)"
  [[ -e "$DIR/slurm.conf" ]] || die "no cluster in $DIR"
  export SLURM_CONF="$DIR/slurm.conf"
  scancel --user=root --quiet 2> /dev/null || true
  stop_pid "$DIR/slurmd.pid"
  stop_pid "$DIR/slurmctld.pid"
  stop_pid "$DIR/slurmdbd.pid"
  stop_pid "$DIR/db/mariadbd.pid"
  stop_pid "$DIR/munge/munged.pid"
  mv "$DIR/slurm.conf" "$DIR/slurm.conf.stopped"
  echo "[slurm-local] cluster in $DIR stopped"
}

"$MODE"
