#!/bin/sh
# friction_cost.sh OFF.elf ON.elf - the friction estimate's cost on the Cortex-M4F
# (docs/twin.md, "Friction"; issue 30 item 5): the twin firmware (port/cortex-m/twin) with
# TWIN_COST=1 on the 1 s fig6 stream, once without the estimate and once with it running at
# every update of s (every 16 samples once the observer has settled, 0.5 s) without changing
# mu (tests/embedded/twin.mk: gate open, deadband 1), so that both run the same trajectory
# and each observer step's bracket differs by the estimate alone. Counted by
# tests/qemu/count.sh with the Cortex-M4 cycle estimate (CM_CYCLES=1), pessimistic
# (P = 3, W = 5: docs/embedded.md, "The cycle model"). Prints, over the observer steps:
# the mean extra cycles per sample, and the extra cycles of the steps that run the estimate
# (mean and largest). Run through `make twin-friction-cost`.
set -eu
off=$1 on=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
steps() { # steps ELF > one line per observer step: "insn pessimistic_cycles"
    CM_CYCLES=1 sh tests/qemu/count.sh "$1" cortex-m4f 600 > "$TMP/raw" 2>&1 || {
        echo "friction_cost: $1 failed under QEMU: $(tail -n 2 "$TMP/raw" | tr '\n' ' ')" >&2; exit 1; }
    awk '/^\[insn\] total/ { next }
        /^\[insn\] [0-9]+/ { ++marks; if (marks % 4 == 0) print $2, $4 + 3 * $6 + 5 * $8 }' "$TMP/raw"
    grep '^t ' "$TMP/raw" | sed 's/ queued .*//' > "$1.reports"
}
steps "$off" > "$TMP/off"
mv "$off.reports" "$TMP/off.reports"
steps "$on" > "$TMP/on"
mv "$on.reports" "$TMP/on.reports"
# the same trajectory: the 10 Hz reports (s, s_sigma, amplitude, power, ...) alike
if ! cmp -s "$TMP/off.reports" "$TMP/on.reports" || [ ! -s "$TMP/off.reports" ]; then
    echo "friction_cost: the two images do not run the same trajectory:" >&2
    diff "$TMP/off.reports" "$TMP/on.reports" | head -n 4 >&2
    exit 1
fi
echo "the same trajectory: $(wc -l < "$TMP/off.reports") reports alike"
paste -d' ' "$TMP/off" "$TMP/on" | awk '
    { n++; di = $3 - $1; dc = $4 - $2; extra += dc; extra_insn += di
      if (dc != 0) { k++; sum += dc; if (dc > worst) worst = dc; if (di > worst_insn) worst_insn = di } }
    END {
        if (n == 0) { print "friction_cost: no observer step counted" > "/dev/stderr"; exit 1 }
        printf "observer steps %d, of which %d run the friction estimate\n", n, k
        printf "mean extra per sample: %.1f cycles (pessimistic), %.1f instructions\n", extra / n, extra_insn / n
        printf "steps that run it: %.0f extra cycles on average, %d at most (%d instructions at most)\n",
               k ? sum / k : 0, worst, worst_insn }'
