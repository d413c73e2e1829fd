#!/usr/bin/env bash
# A real, one-node Slurm on this machine, to test the sharded sweep scripts:
# installs Debian's slurm-wlm and munge where missing, with slurmdbd and
# mariadb-server for the accounting that sacct reads (as root; otherwise it
# says "skipped: …" and exits 0), starts munged, MariaDB, slurmdbd,
# slurmctld and slurmd with minimal configurations in a temporary directory,
# submits a small sharded map and a suite on a row of buildings, each as a
# job array (submit.sh: sweep.sbatch, then merge.sbatch after it), waits
# with squeue, shows the jobs with sacct, and checks that each merge equals
# the unsharded output but for its timing field. Exits 0 only then.
# Every daemon it started is stopped by its PID and the temporary directory
# removed, whatever happens.
#
#   scripts/slurm/test-local.sh            # builds target/release/pounding
#   POUNDING=/path/to/pounding scripts/slurm/test-local.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
started=$(date +%s)
skip() {
    echo "skipped: $*"
    exit 0
}
say() { echo "test-local: $*"; }

# slurmd launches the jobs, which needs root here (as it does on a cluster).
[ "$(id -u)" = 0 ] || skip "a local Slurm needs root (slurm-wlm, munge, slurmd); run it as root"

# The binary.
if [ -z "${POUNDING:-}" ]; then
    (cd "$repo" && cargo build --release --quiet --bin pounding)
    POUNDING="${CARGO_TARGET_DIR:-$repo/target}/release/pounding"
fi
if [ ! -x "$POUNDING" ]; then
    echo "test-local: FAILED: no pounding binary at $POUNDING" >&2
    exit 1
fi
POUNDING=$(cd "$(dirname "$POUNDING")" && pwd)/$(basename "$POUNDING")
export POUNDING

# The packages.
sbin() { PATH="$PATH:/usr/sbin:/sbin" command -v "$1" >/dev/null 2>&1; }
missing=()
for tool in slurmctld slurmd sbatch squeue sacct scontrol; do
    sbin "$tool" || { missing+=(slurm-wlm); break; }
done
sbin munged || missing+=(munge)
# The accounting database, for sacct: slurmdbd on a MariaDB of our own.
sbin slurmdbd || missing+=(slurmdbd)
{ sbin mariadbd && sbin mariadb-install-db; } || missing+=(mariadb-server)
if [ ${#missing[@]} -gt 0 ]; then
    command -v apt-get >/dev/null || skip "${missing[*]} not installed, and there is no apt-get"
    say "installing ${missing[*]}"
    # No service may start from the packages' scripts: the daemons here are ours.
    policy=/usr/sbin/policy-rc.d
    own_policy=
    if [ ! -e "$policy" ]; then
        printf '#!/bin/sh\nexit 101\n' >"$policy" && chmod +x "$policy" && own_policy=1
    fi
    install() { DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null; }
    ok=1
    install 2>/dev/null || { apt-get update -q >/dev/null 2>&1 && install; } || ok=
    [ -n "$own_policy" ] && rm -f "$policy"
    [ -n "$ok" ] || skip "apt-get could not install ${missing[*]}"
fi
export PATH="$PATH:/usr/sbin:/sbin"

tmp=$(mktemp -d /tmp/pounding-slurm.XXXXXX)
chmod 755 "$tmp"
pids=()
cleanup() {
    local status=$?
    trap '' INT TERM HUP
    # Every daemon started here, by its PID, last started first.
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
        kill "${pids[i]}" 2>/dev/null || true
    done
    for pid in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    done
    rm -rf "$tmp"
    say "$(($(date +%s) - started)) s in all"
    exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP
fail() {
    echo "test-local: FAILED: $*" >&2
    for log in "$tmp"/*.log; do
        [ -f "$log" ] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
    done
    exit 1
}

# Free TCP ports for the two daemons.
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
pick_port() {
    local p
    for _ in $(seq 100); do
        p=$((20000 + RANDOM % 20000))
        if port_free "$p" && [ "$p" != "${1:-}" ]; then echo "$p"; return; fi
    done
    fail "no free port"
}
ctld_port=$(pick_port)
slurmd_port=$(pick_port "$ctld_port")
dbd_port=$(pick_port "$ctld_port")
db_port=$(pick_port "$dbd_port")

# munged, on a socket and key of its own.
mkdir -m 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$tmp/munge/munge.key"
socket="$tmp/munge/munge.socket"
munged --foreground --force --socket="$socket" --key-file="$tmp/munge/munge.key" \
    --pid-file="$tmp/munge/munged.pid" --seed-file="$tmp/munge/munged.seed" \
    --log-file="$tmp/munged.log" >/dev/null 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || fail "munged did not start"

host=$(hostname -s)
cpus=$(nproc)
export SLURM_CONF="$tmp/slurm.conf"

# MariaDB in the temporary directory, then slurmdbd on it.
mkdir -p "$tmp/db"
mariadb-install-db --no-defaults --datadir="$tmp/db" --user=root \
    --auth-root-authentication-method=normal --skip-test-db >"$tmp/mariadb-install.log" 2>&1 ||
    fail "mariadb-install-db failed"
mariadbd --no-defaults --datadir="$tmp/db" --socket="$tmp/db/mariadb.sock" --port="$db_port" \
    --bind-address=127.0.0.1 --user=root --skip-grant-tables --pid-file="$tmp/db/mariadb.pid" \
    --log-error="$tmp/mariadb.log" >/dev/null 2>&1 &
pids+=($!)
for _ in $(seq 100); do port_free "$db_port" || break; sleep 0.2; done
port_free "$db_port" && fail "MariaDB did not start"
cat >"$tmp/slurmdbd.conf" <<CONF
AuthType=auth/munge
AuthInfo=socket=$socket
DbdHost=$host
DbdAddr=127.0.0.1
DbdPort=$dbd_port
SlurmUser=root
StorageType=accounting_storage/mysql
StorageHost=127.0.0.1
StoragePort=$db_port
StorageUser=root
StorageLoc=slurm_acct_db
PidFile=$tmp/slurmdbd.pid
LogFile=$tmp/slurmdbd.log
CONF
chmod 600 "$tmp/slurmdbd.conf"
slurmdbd -D >"$tmp/slurmdbd.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do port_free "$dbd_port" || break; sleep 0.2; done
port_free "$dbd_port" && fail "slurmdbd did not start"
mkdir -p "$tmp/state" "$tmp/spool"
cat >"$SLURM_CONF" <<CONF
ClusterName=pounding-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=127.0.0.1
AccountingStoragePort=$dbd_port
AccountingStoragePass=$socket
JobCompType=jobcomp/filetxt
JobCompLoc=$tmp/jobcomp.txt
MinJobAge=3600
NodeName=localnode NodeHostname=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=localnode Default=YES MaxTime=INFINITE State=UP
CONF

# The cluster in the accounting database, before slurmctld registers with it.
timeout 20 sacctmgr -i add cluster pounding-test >/dev/null 2>&1 || true
slurmctld -D -c -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N localnode >"$tmp/slurmd.out" 2>&1 &
pids+=($!)
up=
deadline=$((SECONDS + 60))
while [ $SECONDS -lt $deadline ]; do
    if [ "$(timeout 5 sinfo -h -n localnode -o %t 2>/dev/null)" = idle ]; then up=1; break; fi
    kill -0 "${pids[-2]}" 2>/dev/null || fail "slurmctld stopped"
    sleep 0.3
done
[ -n "$up" ] || fail "the node did not come up ($(timeout 5 sinfo -h -o '%n %t' 2>&1 | head -1))"
say "munged, MariaDB, slurmdbd, slurmctld and slurmd up after $(($(date +%s) - started)) s"

untimed() { sed -E 's/"elapsed_ms":[0-9.e+-]+/"elapsed_ms":T/' "$1"; }

# Runs COMMAND ARGS... unsharded here and as a job array of N shards there
# (submit.sh), waits for the array and its merge, shows them with sacct and
# checks that the merge equals the unsharded output but for its timing.
#   sharded_equals NAME N COMMAND ARGS...
sharded_equals() {
    local name=$1 n=$2
    shift 2
    local work="$tmp/work-$name"
    mkdir -p "$work"
    cd "$work"
    "$POUNDING" "$@" >unsharded.json
    local array merge
    read -r array merge < <(timeout 30 "$here/submit.sh" "$n" "$work/parts" "$work/merged.json" "$@")
    [ -n "${merge:-}" ] || fail "$name: sbatch did not take the jobs"
    say "$name: submitted job array $array ($n shards) and merge job $merge"
    local done_= queued
    local deadline=$((SECONDS + 180))
    while [ $SECONDS -lt $deadline ]; do
        queued=$(timeout 5 squeue -h -j "$array,$merge" -o %i 2>/dev/null) || queued=unknown
        if [ -z "$queued" ]; then done_=1; break; fi
        sleep 0.3
    done
    [ -n "$done_" ] || fail "$name: the jobs did not finish within 3 minutes"
    echo "sacct:"
    # The accounting database takes the jobs' ends a moment after squeue drops them.
    local lines=
    for _ in $(seq 20); do
        lines=$(timeout 10 sacct -j "$array,$merge" -X -P --format=JobID,JobName,State,ExitCode,Start,End,Elapsed 2>/dev/null) || lines=
        [ "$(grep -c COMPLETED <<<"$lines")" -ge $((n + 1)) ] && break
        sleep 0.5
    done
    if [ -n "$lines" ]; then
        echo "$lines"
    else
        # Without a slurmdbd there is no accounting database: Slurm's own job
        # completion log holds the same facts.
        echo "(no accounting database; Slurm's job completion log instead)"
        awk '{ o = ""; for (i = 1; i <= NF; i++) if ($i ~ /^(JobId|Name|JobState|StartTime|EndTime|ExitCode)=/) o = o " " $i; print substr(o, 2) }' \
            "$tmp/jobcomp.txt" 2>/dev/null || true
    fi
    [ -f merged.json ] || fail "$name: the merge job wrote nothing ($(cat "$work"/parts/slurm-merge-*.out 2>/dev/null))"
    if ! diff <(untimed unsharded.json) <(untimed merged.json) >/dev/null; then
        fail "$name: the merged output differs from the unsharded one"
    fi
    say "OK: the merge of $n shards run by Slurm equals the unsharded $name ($(wc -c <merged.json) bytes)"
}

# A small map, and a suite on a row of buildings (each record's row runs in
# the parts).
sharded_equals map 3 map --x omega1=0.2:2.4:0.1 --y mu=1:4:0.5 --format json
sharded_equals row-suite 2 suite --buildings block-and-frame --suite synthetic:6@2 --level 0.3g --format json
