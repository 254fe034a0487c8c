#!/usr/bin/env bash
# run_parallel.sh JOBS TARGET... - `make TARGET` for every TARGET, JOBS at a
# time, in the order given (the longest first balances the lanes best). The
# lines each one prints are prefixed with its name, so that two running side
# by side stay readable; every target runs to its end whatever the others
# do. Prints each target's status and wall time as it ends, and a summary.
# Exit status 1 if any target failed. Used by `make test-long`: its targets
# build into trees of their own, or into the double and float trees that
# the Makefile builds before starting them (no two makes build one file).
set -u
jobs=$1
shift
[ "$jobs" -ge 1 ] 2>/dev/null || { echo "run_parallel.sh: JOBS must be a positive number, not '$jobs'" >&2; exit 2; }
make=${MAKE:-make}
status_dir=$(mktemp -d)
trap 'rm -rf "$status_dir"' EXIT
start_all=$(date +%s)

run_one() { # TARGET: its lines prefixed, its status and seconds into status_dir
    local target=$1 start=$(date +%s)
    # $make unquoted: MAKE may carry words of its own (make -f FILE)
    { $make --no-print-directory "$target" 2>&1; echo $? > "$status_dir/$target.status"; } \
        | sed -u "s|^|[$target] |"
    echo $(( $(date +%s) - start )) > "$status_dir/$target.seconds"
    echo "== $target: $( [ "$(cat "$status_dir/$target.status")" = 0 ] && echo ok || echo FAILED) ($(cat "$status_dir/$target.seconds") s)"
}

running=0
for target in "$@"; do
    if [ "$running" -ge "$jobs" ]; then
        wait -n
        running=$((running - 1))
    fi
    echo "== $target: started"
    run_one "$target" &
    running=$((running + 1))
done
wait

failed=
for target in "$@"; do
    [ "$(cat "$status_dir/$target.status" 2>/dev/null || echo 1)" = 0 ] || failed="$failed $target"
done
echo "run_parallel: $# targets, $jobs at a time, $(( $(date +%s) - start_all )) s of wall time"
if [ -n "$failed" ]; then
    echo "run_parallel: FAILED:$failed"
    exit 1
fi
