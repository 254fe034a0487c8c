#!/bin/sh
# twin_backlog.sh ELF [EXTRA EVERY] - the largest backlog of a twin firmware cost image
# (port/cortex-m/twin built with TWIN_COST=1 on the 60 s fig6 stream, e.g.
# build/cm/cortex-m4f/twin-cost-fig6-ram.elf of `make twin-firmware-report`) at 168 MHz, as
# twin_firmware_report.sh computes it: the per-sample costs (pessimistic estimated cycles, plus
# 24 of SysTick entry and return) through the Lindley recursion W = max(0, W + c_k - B),
# B = 3360 cycles (168 MHz x 2e-5 s), the largest W in samples (rounded up). With EXTRA and
# EVERY, EXTRA cycles are added to every EVERY-th sample first: the cost of work the image did
# not run, e.g. the friction estimate (`make twin-friction-cost`: 277 cycles at most, on one
# sample in 16), on the same trajectory. Prints one line:
#     samples N mean M backlog W extra EXTRA every EVERY
# Env: TWIN_BUDGET (3360), TWIN_TIMEOUT (900 s for count.sh).
set -u
[ $# -eq 1 ] || [ $# -eq 3 ] || { echo "usage: $0 ELF [EXTRA EVERY]" >&2; exit 2; }
extra=${2:-0} every=${3:-1}
case $extra in '' | *[!0-9]*) echo "twin_backlog.sh: EXTRA '$extra' is not a whole number of cycles" >&2; exit 2 ;; esac
case $every in '' | 0 | *[!0-9]*) echo "twin_backlog.sh: EVERY '$every' is not a positive whole number of samples" >&2; exit 2 ;; esac
status=$(mktemp)
trap 'rm -f "$status" "$status.line"' EXIT
# the count streamed into the recursion (the 60 s stream prints 12 million lines)
{ st=0; CM_CYCLES=1 sh tests/qemu/count.sh "$1" cortex-m4f "${TWIN_TIMEOUT:-900}" 2>&1 || st=$?
  echo "$st" > "$status"; } |
awk -v budget="${TWIN_BUDGET:-3360}" -v extra="$extra" -v every="$every" '
    /^\[insn\] total/ { next }
    /^\[insn\] [0-9]+ cycles / { # four marks a sample: the producer, then the observer step
        pessimistic = $4 + 3 * $6 + 5 * $8
        if (++marks > 1) cost += pessimistic # the first interval is the start-up
        if (marks % 4 == 0) {
            ++n; cost += 24 + (n % every == 0 ? extra : 0); sum += cost
            w += cost - budget; if (w < 0) w = 0; if (w > most) most = w
            cost = 0
        }
    }
    END {
        if (n == 0) { print "twin_backlog.sh: no samples counted (not a TWIN_COST image?)" > "/dev/stderr"; exit 1 }
        q = int(most / budget); if (q * budget < most) ++q
        printf "samples %d mean %.1f backlog %d extra %s every %s\n", n, sum / n, q, extra, every
    }' > "$status.line"
if [ "$(cat "$status")" != 0 ] || [ ! -s "$status.line" ]; then
    echo "twin_backlog.sh: count.sh failed on $1 (status $(cat "$status"))" >&2
    exit 1
fi
cat "$status.line"
