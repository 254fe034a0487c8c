#!/bin/sh
# probe.sh ELF [TARGET] - the mean cost of a step of a cost-mode image (tests/embedded/scene_run.c
# built with -DBS_RUN_COST=1, e.g. the mid-run probes build/cm/cortex-m4f/mid-fig6-float.elf of
# tests/embedded/embedded.mk), counted by count.sh with the cycle estimate (CM_CYCLES=1), on one line:
#     steps N insn I optimistic O pessimistic P hash H
# N the steps counted, I their mean instructions, O and P their mean estimated Cortex-M4 cycles
# (branch refill P = 1 and 3, flash wait states W = 0 and 5: insn-plugin/insncount.c, "Cycle
# model"), H the state hash the image prints at its end: two builds of the step are the same
# arithmetic when H is the same. A cost-mode image brackets each step with bs_board_mark(), so
# the marks alternate: the step, then the harness up to the next step; the first mark closes what
# ran before the counted steps (BS_RUN_SKIP). TARGET defaults to cortex-m4f. The structures of
# docs/design.md 4 were measured with it:
#     make build/cm/cortex-m4f/mid-fig6-float.elf && sh tests/qemu/probe.sh build/cm/cortex-m4f/mid-fig6-float.elf
# and, for other compiler flags, the same with CM_BUILD=DIR CM_OPT='...' (a tree of its own).
set -u
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: $0 ELF [TARGET]" >&2; exit 2; }
out=$(CM_CYCLES=1 sh "$(dirname "$0")/count.sh" "$1" "${2:-cortex-m4f}") || {
    echo "probe.sh: count.sh failed on $1" >&2; exit 1; }
printf '%s\n' "$out" | awk '
    /^\[insn\] [0-9]+ cycles / {
        if (++marks % 2 == 0) { # a step: [insn] N cycles C taken T flash F
            ++steps; insn += $2; optimistic += $4 + $6; pessimistic += $4 + 3 * $6 + 5 * $8
        }
    }
    / hash / { for (i = 1; i < NF; ++i) if ($i == "hash") hash = $(i + 1) }
    END {
        if (steps == 0) { print "probe.sh: no step brackets (not a cost-mode image?)" > "/dev/stderr"; exit 1 }
        printf "steps %d insn %.1f optimistic %.1f pessimistic %.1f hash %s\n", steps, insn / steps,
               optimistic / steps, pessimistic / steps, hash == "" ? "-" : hash
    }'
