#!/bin/sh
# twin_probe.sh ELF - the mean cost of a sample of a twin firmware cost image
# (port/cortex-m/twin built with TWIN_COST=1, e.g. build/cm/cortex-m4f/twin-cost-friction-off.elf
# of tests/embedded/twin.mk, the 1 s fig6 stream), counted by count.sh with the cycle estimate
# (CM_CYCLES=1), on one line:
#     samples N step S producer P sample T hash H est E
# S the observer step's bracket (the twin's step and the correction), P the producer's, T all the
# firmware executes per sample plus 24 cycles of SysTick entry and return, as
# host/reports/twin_firmware_report.sh counts them (mean estimated Cortex-M4 cycles, pessimistic:
# branch refill 3, flash wait states 5); H and E the hashes of the twin's state and estimate at the
# end: two builds of the firmware that print the same ones ran the same twin. The marks come four
# to a sample: the producer's bracket, then the observer step's.
#     make build/cm/cortex-m4f/twin-cost-friction-off.elf build/twin/fig6-1s.stream
#     sh tests/qemu/twin_probe.sh build/cm/cortex-m4f/twin-cost-friction-off.elf
set -u
[ $# -eq 1 ] || { echo "usage: $0 ELF" >&2; exit 2; }
out=$(CM_CYCLES=1 sh "$(dirname "$0")/count.sh" "$1" cortex-m4f 600) || {
    echo "twin_probe.sh: count.sh failed on $1" >&2; exit 1; }
printf '%s\n' "$out" | awk '
    /^\[insn\] total/ { next }
    /^\[insn\] [0-9]+ cycles / { # [insn] N cycles C taken T flash F
        pessimistic = $4 + 3 * $6 + 5 * $8
        if (++marks > 1) sample += pessimistic # the first interval is the start-up
        if (marks % 4 == 2) { ++producers; producer += pessimistic }
        if (marks % 4 == 0) { ++samples; step += pessimistic; total += sample + 24; sample = 0 }
        next
    }
    /^end status/ { for (i = 2; i < NF; ++i) { if ($i == "hash") hash = $(i + 1); if ($i == "est") est = $(i + 1) } }
    END {
        if (samples == 0) { print "twin_probe.sh: no samples counted (not a TWIN_COST image?)" > "/dev/stderr"; exit 1 }
        printf "samples %d step %.1f producer %.1f sample %.1f hash %s est %s\n", samples, step / samples,
               producer / producers, total / samples, hash == "" ? "-" : hash, est == "" ? "-" : est
    }'
