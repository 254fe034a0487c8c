#!/bin/sh
# check_slurm.sh - host/slurm/ against a real single-node Slurm (make
# test-long, never make test): munged and slurmctld/slurmd started here, as
# root, with their own key, socket, SLURM_CONF, state and spool under
# build/slurm/, on ports of their own; a small map submitted as an array of 4
# shard tasks and the merge step after them (submit-map.sh); the merged
# tables must equal those of one `beamslider map` process. The daemons are
# stopped by their PIDs on exit. Without root, or where Debian's slurm-wlm
# and munge cannot be installed, it prints a notice and skips.
#
# usage, from the repository root:  sh tests/slurm/check_slurm.sh PATH/TO/beamslider [BUILD]
set -u
bin=${1:-}
build=${2:-build}
. tests/check_lib.sh
check_setup tests/slurm/check_slurm.sh "$bin"
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")

skip() {
    echo "check_slurm: SKIPPED: $1"
    exit 0
}
[ "$(id -u)" = 0 ] || skip "not root: a private Slurm needs root to start slurmd (make test-long as root, as CI does)"
if ! command -v slurmctld >/dev/null 2>&1 || ! command -v munged >/dev/null 2>&1; then
    sh host/deps.sh slurm-wlm munge >/dev/null 2>&1 || skip "slurm-wlm and munge could not be installed"
fi
for tool in slurmctld slurmd sbatch sinfo munged mungekey; do
    command -v "$tool" >/dev/null 2>&1 || skip "$tool not found after installing slurm-wlm and munge"
done

here=$(mkdir -p "$build" && cd "$build" && pwd)/slurm
rm -rf "$here"
mkdir -p "$here/munge" "$here/state" "$here/spool" "$here/logs"
chmod 711 "$here/munge" # munged wants its folder closed, the socket reachable
pids=""
stop_daemons() {
    for pid in $pids; do kill "$pid" 2>/dev/null; done
    for pid in $pids; do
        for i in 1 2 3 4 5 6 7 8 9 10; do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
        kill -9 "$pid" 2>/dev/null
    done
    pids=""
}
trap 'stop_daemons; rm -rf "$tmp"' EXIT
trap 'stop_daemons; rm -rf "$tmp"; exit 1' INT TERM

# ---- munge: a key and a socket of our own
mungekey --create --keyfile="$here/munge/munge.key" || skip "mungekey failed"
munged --force --foreground --socket="$here/munge/munge.socket" --key-file="$here/munge/munge.key" \
    --log-file="$here/munge/munged.log" --pid-file="$here/munge/munged.pid" \
    --seed-file="$here/munge/munged.seed" >"$here/logs/munged.out" 2>&1 &
pids="$pids $!"
for i in $(seq 1 50); do [ -S "$here/munge/munge.socket" ] && break; sleep 0.1; done
if munge -S "$here/munge/munge.socket" -n | unmunge -S "$here/munge/munge.socket" >/dev/null 2>&1; then
    pass "munged runs with its own key and socket"
else
    fail "munged runs with its own key and socket" "$(cat "$here/logs/munged.out")"
fi

# ---- slurm: one node, 2 CPUs, ports of its own
port=$((20000 + $$ % 20000))
cat >"$here/slurm.conf" <<CONF
ClusterName=beamslider
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$here/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$here/state
SlurmdSpoolDir=$here/spool
SlurmctldPidFile=$here/slurmctld.pid
SlurmdPidFile=$here/slurmd.pid
SlurmctldLogFile=$here/logs/slurmctld.log
SlurmdLogFile=$here/logs/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=localhost CPUs=2 State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
SLURM_CONF=$here/slurm.conf
export SLURM_CONF
slurmctld -D -i >"$here/logs/slurmctld.out" 2>&1 &
pids="$pids $!"
slurmd -D -N localhost >"$here/logs/slurmd.out" 2>&1 &
pids="$pids $!"
state=
for i in $(seq 1 60); do
    state=$(sinfo -h -N -o %T 2>/dev/null)
    [ "$state" = idle ] && break
    sleep 0.5
done
if [ "$state" = idle ]; then
    pass "slurmctld and slurmd run: one idle node"
else
    fail "slurmctld and slurmd run: one idle node" "sinfo: $state; $(tail -n 5 "$here/logs/slurmctld.log" "$here/logs/slurmd.log" 2>&1)"
    echo "check_slurm: $passed passed, $failed failed"
    exit 1
fi

# ---- a small map: one process, then 4 array tasks and the merge step
options="--set run.t_end=0.5 --vary excitation.frequency=118:126:2 --vary excitation.acceleration=10,14 --repeat 2"
# shellcheck disable=SC2086
"$bin" map configs/fig6.ini $options --jobs 2 --out "$tmp/single" >"$tmp/o" 2>"$tmp/e"
check_status "the single-process map exits 0" 0 $? "$tmp/e"
# shellcheck disable=SC2086
SBATCH_OPTIONS="--output=$here/logs/%x-%A_%a.out --time=10" WAIT=1 \
    sh host/slurm/submit-map.sh 4 "$bin" "$PWD/configs/fig6.ini" "$here/map" $options >"$tmp/o" 2>"$tmp/e"
check_status "the array of 4 shards and the merge step end well" 0 $? "$tmp/e"
array=$(sed -n 's/^array job \([0-9]*\),.*/\1/p' "$tmp/o")
tasks=$(ls "$here/logs" | grep -c "^beamslider-map-${array}_[1-4]\.out$")
if [ "$tasks" -eq 4 ]; then pass "4 array tasks ran"; else fail "4 array tasks ran" "$(ls "$here/logs")"; fi
shards=$(cat "$here"/logs/beamslider-map-"${array}"_*.out 2>/dev/null | grep -c '"shard":"[1-4]/4"')
if [ "$shards" -eq 4 ]; then pass "each task ran its shard i/4"; else fail "each task ran its shard i/4" "$(cat "$here"/logs/*.out)"; fi
check "the merged runs.csv equals the single process's" cmp -s "$tmp/single/runs.csv" "$here/map/runs.csv"
check "the merged map.csv equals the single process's" cmp -s "$tmp/single/map.csv" "$here/map/map.csv"

stop_daemons
left=
for name in slurmctld slurmd munged; do
    pid=$(cat "$here/$name.pid" "$here/munge/$name.pid" 2>/dev/null | head -n 1)
    [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null && left="$left $name"
done
check "the daemons are stopped" test -z "$left"
echo "check_slurm: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
