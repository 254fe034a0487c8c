#!/bin/sh
# twin_probe.sh ELF [EXTRA EVERY] - the mean cost of a sample of a twin firmware cost image
# (port/cortex-m/twin built with TWIN_COST=1, e.g. build/cm/cortex-m4f/twin-cost-friction-off.elf
# of tests/embedded/twin.mk on the 1 s fig6 stream, or twin-cost-fig6-ram.elf of `make
# twin-firmware-report` on the 60 s one), counted by count.sh with the cycle estimate
# (CM_CYCLES=1) and summed by twin_samples.awk as host/reports/twin_firmware_report.sh sums
# them, on one line:
#     samples N step S producer P sample T backlog W hash H est E
# S the observer step's bracket (the twin's step and the correction), P the producer's, T all the
# firmware executes per sample plus 24 cycles of SysTick entry and return (mean estimated
# Cortex-M4 cycles, pessimistic: branch refill 3, flash wait states 5); W the largest backlog in
# samples at 168 MHz (the budget of a sample 3360 cycles at dt = 2e-5 s); H and E the hashes of
# the twin's state and estimate at the end: two builds of the firmware that print the same ones
# ran the same twin. With EXTRA and EVERY, EXTRA cycles are added to every EVERY-th sample's
# cost (T and W) first: work the image did not run, e.g. the friction estimate (`make
# twin-friction-cost`: 277 cycles at most, on one sample in 16), on the same trajectory.
#     make build/cm/cortex-m4f/twin-cost-friction-off.elf build/twin/fig6-1s.stream
#     sh tests/qemu/twin_probe.sh build/cm/cortex-m4f/twin-cost-friction-off.elf
# Env: TWIN_DT (the stream's sample period, 2e-5 s), TWIN_TIMEOUT (900 s for count.sh).
set -u
[ $# -eq 1 ] || [ $# -eq 3 ] || { echo "usage: $0 ELF [EXTRA EVERY]" >&2; exit 2; }
extra=${2:-0} every=${3:-1}
case $extra in '' | *[!0-9]*) echo "twin_probe.sh: EXTRA '$extra' is not a whole number of cycles" >&2; exit 2 ;; esac
case $every in '' | 0 | *[!0-9]*) echo "twin_probe.sh: EVERY '$every' is not a positive whole number of samples" >&2; exit 2 ;; esac
here=$(dirname "$0")
sum=$(mktemp)
trap 'rm -f "$sum" "$sum.status"' EXIT
# the count streamed into the sums (the 60 s stream prints 12 million lines)
{ st=0; CM_CYCLES=1 sh "$here/count.sh" "$1" cortex-m4f "${TWIN_TIMEOUT:-900}" || st=$?
  echo "$st" > "$sum.status"; } |
    awk -v cycles=1 -v clocks=168 -v dt="${TWIN_DT:-0.00002}" -v entry=24 -v fifo=1024 \
        -v extra="$extra" -v every="$every" -v digits=1 -f "$here/twin_samples.awk" > "$sum"
if [ "$(cat "$sum.status")" != 0 ] || ! grep -q '^samples ' "$sum"; then
    echo "twin_probe.sh: count.sh failed on $1 (status $(cat "$sum.status")), or no samples counted (not a TWIN_COST image?)" >&2
    exit 1
fi
awk '{ v[$1] = $2 } END { printf "samples %s step %s producer %s sample %s backlog %s hash %s est %s\n",
    v["samples"], v["step_pess"], v["producer_pess"], v["sample"], v["backlog_168"],
    v["hash"] == "" ? "-" : v["hash"], v["est"] == "" ? "-" : v["est"] }' "$sum"
