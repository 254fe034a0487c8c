#!/bin/sh
# run_fuzz.sh BINARY SECONDS WORK_CORPUS SEEDS ARTIFACTS [LIBFUZZER-OPTION...]
#
# One bounded libFuzzer run (tests/robustness.mk: make fuzz, fuzz-short,
# fuzz-minute, fuzz-long). SECONDS bounds the fuzzing time (0: no bound; then
# give -runs=N); options after ARTIFACTS are passed on (-runs, -dict).
# New inputs go to WORK_CORPUS (kept between runs), the committed SEEDS are
# only read; a crash, leak or timeout is saved under ARTIFACTS. Prints one
# line: executions, time, rate, coverage (libFuzzer's "cov": instrumented
# edges reached; "ft": features), corpus size; with FUZZ_SHOW_RULES=1 also the
# target's own report at exit (fuzz_api: which of restore's rules decided);
# on failure the end of the log and the command that reproduces it. Exit
# status 1 on any finding.
bin=$1
seconds=$2
work=$3
seeds=$4
artifacts=$5
shift 5
name=$(basename "$bin")
mkdir -p "$work" "$artifacts" || exit 1
log=$artifacts/$name.log

# The targets that read files write each input to a file in $TMPDIR: on a
# tmpfs that is no disk I/O (5000 executions of fuzz_map: 6 s, against 42 s
# on the shared machine's ext4).
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then
    TMPDIR=/dev/shm
    export TMPDIR
fi

start=$(date +%s)
"$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$artifacts/$name-" "$@" "$work" "$seeds" >"$log" 2>&1
status=$?
elapsed=$(($(date +%s) - start))

runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
cov=$(printf '%s\n' "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
ft=$(printf '%s\n' "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')
corp=$(printf '%s\n' "$last" | sed -n 's/.* corp: \([0-9]*\).*/\1/p')
rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
if [ "$status" -ne 0 ]; then
    tail -n 40 "$log"
    crash=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -n 1)
    echo "FAIL - $name: exit status $status after ${runs:-?} executions; log: $log"
    [ -n "$crash" ] && echo "       reproduce: $bin $crash"
    exit 1
fi
echo "ok   - $name: ${runs:-?} executions in $elapsed s (${rate:-?}/s), cov ${cov:-?} edges, ft ${ft:-?}, corpus ${corp:-?} inputs, no crash, leak or timeout"
[ "${FUZZ_SHOW_RULES:-0}" = 1 ] && grep '^fuzz_api: restore rule' "$log"
exit 0
