#!/bin/sh
# check_twin.sh CLI SCENE.ini CSV HOST_PACE SYSTICK_ELF - the twin firmware's checks
# (port/cortex-m/twin) beyond tests/check_embedded.sh, which compares its QEMU images with
# their host builds bit for bit:
#   1. the host build that keeps pace computes what `CLI twin SCENE.ini --measured CSV`
#      computes: s, s_sigma, amplitude, power, outliers and health every 0.1 s, character
#      for character
#      (the firmware prints them in the formats of the CLI's --out), with nothing dropped;
#   2. the SysTick build (a real interrupt as the producer) under QEMU with TWIN_ICOUNT
#      (-icount: QEMU's time is the instruction count) runs to its end with status 0 (the
#      firmware fails unless every sample was stepped or counted dropped), twice with the
#      same output (so its drops are reproducible).
# Env: TWIN_ICOUNT (QEMU options), CHECK_EMBEDDED_TIMEOUT (seconds per QEMU run, 120).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cli=$1 scene=$2 csv=$3 host=$4 elf=$5
failed=0

"$cli" twin "$scene" --measured "$csv" --out "$tmp/est.csv" --every 5000 > /dev/null &&
    "$host" > "$tmp/host.out" || { echo "FAIL twin: $cli twin or $host failed"; exit 1; }
awk -F, 'NR > 1 { print $2, $3, $4, $5, $11, $12 }' "$tmp/est.csv" > "$tmp/cli"
awk '$1 == "t" { print $4, $6, $8, $10, $12, $14 }' "$tmp/host.out" > "$tmp/firmware"
if [ ! -s "$tmp/cli" ] || ! cmp -s "$tmp/cli" "$tmp/firmware"; then
    echo "FAIL twin: the firmware and \`beamslider twin\` differ (s s_sigma amplitude power outliers health):"
    diff "$tmp/cli" "$tmp/firmware" | head -n 6
    failed=1
elif ! grep -q '^end status 0 .* dropped 0 ' "$tmp/host.out"; then
    echo "FAIL twin: $host: $(tail -n 1 "$tmp/host.out")"
    failed=1
else
    echo "ok   twin: $(wc -l < "$tmp/cli") estimates identical to \`beamslider twin\`, $(tail -n 1 "$tmp/host.out" | cut -d" " -f1-13)"
fi

for run in 1 2; do
    CM_QEMU_ARGS="${TWIN_ICOUNT:?check_twin: TWIN_ICOUNT unset}" \
        sh port/cortex-m/run.sh "$elf" cortex-m4f "${CHECK_EMBEDDED_TIMEOUT:-120}" > "$tmp/systick-$run" 2> "$tmp/err"
    status=$?
    if [ "$status" -ne 0 ]; then
        echo "FAIL twin: $elf under QEMU ($TWIN_ICOUNT): status $status: $(tail -n 2 "$tmp/err" "$tmp/systick-$run" | tr '\n' ' ')"
        failed=1
        break
    fi
done
if [ "$failed" -eq 0 ]; then
    if cmp -s "$tmp/systick-1" "$tmp/systick-2"; then
        echo "ok   twin: SysTick producer under QEMU ($TWIN_ICOUNT), twice the same: $(tail -n 1 "$tmp/systick-1" | cut -d" " -f1-19)"
    else
        echo "FAIL twin: two runs of $elf under QEMU ($TWIN_ICOUNT) differ:"
        diff "$tmp/systick-1" "$tmp/systick-2" | head -n 6
        failed=1
    fi
fi
[ "$failed" -eq 0 ]
