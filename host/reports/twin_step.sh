#!/bin/sh
# twin_step.sh - is it the twin's step that keeps the fig8 ceiling low? The
# section of docs/twin.md between <!-- twin-step --> and <!-- /twin-step -->
# (an OUT without them is refused; a new OUT is written whole). Run through
# `make twin-step` (about 35 minutes on 2 cores).
#
# 1. The slider's climb on the high branch against friction: fig8 (nominal
#    otherwise) at mu = MUS, 120 s, run by the independent reference at
#    dt = 5e-6 s and by the core (double) at dt = 2e-5 s (the scenes'), at
#    2e-5 s prewarped and at 1e-5 s. The climb speed is ds/dt from s = 0.26 to s = 0.30 while the
#    beam is on the high branch (amplitude of w(4L/7), half its peak-to-peak
#    over 0.1 s, above 0.4 h throughout: at s = 0.26 it is near the 0.7 h of
#    the twin report's branch test), averaged over the climbs of the run.
# 2. The twin report's first PLANTS fig8 plants (the same draws, seed = plant
#    number) closed-loop with the twin's step (and the plant's outer step and
#    the signals' sample period) at 2e-5 s and at 1e-5 s (twin_report.sh
#    --plant, TWIN_DT); commissioning is the same at both. Fraction of the
#    time after 5 s with |s_twin - s_plant| <= 0.005 for the commissioned
#    twin, the ceiling (told mu, e_N) and the estimating twin; per plant, the
#    ceiling on each branch (twin_rows.sh's branches).
#
#   PLANTS=12 MUS="0.18 0.20 0.22 0.24 0.25" OUT=docs/twin.md JOBS=$(nproc)
#   TWIN_REPORT_DIR=DIR keeps the files (DIR/dt2e-5, DIR/dt1e-5, DIR/climb);
#   TWIN_REPORT_REUSE=1: the plants already there are not run again;
#   TWIN_REPORT_SIGNALS=1: their signals kept, and only their twins run again
#   where they are (twin_report.sh)
set -eu
OUT=${OUT:-docs/twin.md}
PLANTS=${PLANTS:-12}
MUS=${MUS:-0.18 0.20 0.22 0.24 0.25}
JOBS=${JOBS:-$(nproc)}
REF=${REF:-build/bs-reference}
BIN=${BIN:-build/double/beamslider}
. host/reports/twin_rows.sh
work_dir
. host/reports/provenance.sh
stamp=$(provenance_stamp "make twin-step$( [ "$PLANTS" = 12 ] || printf ' PLANTS=%s' "$PLANTS")")
start=$(date +%s)

# ---- 1. climb speeds --------------------------------------------------------------
mkdir -p "$TMP/climb"
for mu in $MUS; do
    printf '[scene]\nbase = %s/configs/fig8.ini\n[contact]\nfriction = %s\n' "$(pwd)" "$mu" > "$TMP/climb/mu$mu.ini"
    echo "$REF run $TMP/climb/mu$mu.ini --substeps 4 --t-end 120 --every 50 --out $TMP/climb/ref_$mu.csv"
    echo "$BIN run $TMP/climb/mu$mu.ini --every 50 --out $TMP/climb/dt2e-5_$mu.csv"
    echo "$BIN run $TMP/climb/mu$mu.ini --set numerics.prewarp=on --every 50 --out $TMP/climb/prewarp_$mu.csv"
    echo "$BIN run $TMP/climb/mu$mu.ini --set numerics.dt=1e-5 --every 100 --out $TMP/climb/dt1e-5_$mu.csv"
done | while read -r line; do
    out=${line##* }
    if [ "${TWIN_REPORT_REUSE:-0}" != 1 ] || [ ! -s "$out" ]; then echo "$line > /dev/null"; fi
done > "$TMP/climb/commands"
[ ! -s "$TMP/climb/commands" ] || xargs -P "$JOBS" -I CMD sh -c CMD < "$TMP/climb/commands"

# climb FILE: "speed climbs" (rows t,w_sensor,s,... every 1 ms): per 0.1 s window s
# and the amplitude; a climb is counted from the first window at s >= 0.26 to the
# first at s >= 0.30 with the amplitude above 0.4 h all along, once per stay on the
# high branch (the count re-armed by a window below 0.4 h)
climb() {
    awk -F, 'NR > 1 { k = int($1 * 10); if (k != last) { if (n) print s, (hi - lo) / 2; last = k; hi = $2; lo = $2; n = 0 }
                      if ($2 > hi) hi = $2; if ($2 < lo) lo = $2; s = $3; n++ }' "$1" |
        awk 'BEGIN { t0 = -2 } $2 <= 4e-4 { t0 = -1; next }
             t0 == -1 && $1 >= 0.26 && $1 < 0.30 { t0 = NR; s0 = $1 }
             t0 >= 0 && $1 >= 0.30 { v += ($1 - s0) / ((NR - t0) * 0.1); c++; t0 = -2 }
             END { if (c) printf "%.5f %d", v / c, c; else printf "- 0" }'
}
climb_rows=""
for mu in $MUS; do
    set -- $(climb "$TMP/climb/ref_$mu.csv") $(climb "$TMP/climb/dt2e-5_$mu.csv") \
        $(climb "$TMP/climb/prewarp_$mu.csv") $(climb "$TMP/climb/dt1e-5_$mu.csv")
    climb_rows="$climb_rows$(awk -v mu="$mu" -v r="$1" -v rc="$2" -v a="$3" -v ac="$4" -v p="$5" -v pc="$6" \
        -v b="$7" -v bc="$8" 'BEGIN {
        printf "| %s | %s (%d) | %s (%d) | %s | %s (%d) | %s | %s (%d) | %s |", mu, r, rc, a, ac, against(a, r), p, pc,
               against(p, r), b, bc, against(b, r) }
        function against(x, y) { return (x > 0 && y > 0) ? sprintf("%+.0f %%", 100 * (x / y - 1)) : "-" }')
"
done

# ---- 2. the twin at both steps -----------------------------------------------------
for dt in 2e-5 1e-5; do
    run_plants fig8 "$TMP/dt$dt" mu TWIN_DT="$dt"
done

pooled() { # pooled DT SUFFIX: over every plant's rows
    k=1 files=""
    while [ "$k" -le "$PLANTS" ]; do files="$files $TMP/dt$1/fig8_$k.$2"; k=$((k + 1)); done
    # shellcheck disable=SC2086
    within $files
}
rows="" bias_rows="" k=1 below_20=0 below_10=0
while [ "$k" -le "$PLANTS" ]; do
    dm=$(cut -d' ' -f3 "$TMP/dt2e-5/fig8_$k.draw")
    row="| $k | $(awk -v d="$dm" 'BEGIN { printf "%+.0f %%", 100 * d }') |"
    for dt in 2e-5 1e-5; do
        e=$(within "$TMP/dt$dt/fig8_$k.ceil") m=$(within "$TMP/dt$dt/fig8_$k.mu")
        row="$row $(within "$TMP/dt$dt/fig8_$k.comm") | $e | $m |"
        if awk -v a="$m" -v b="$e" 'BEGIN { exit !(a < b - 0.03) }'; then
            if [ "$dt" = 2e-5 ]; then below_20=$((below_20 + 1)); else below_10=$((below_10 + 1)); fi
        fi
    done
    rows="$rows$row
"
    set -- $(branches "$TMP/dt2e-5/fig8_$k.ceil") $(branches "$TMP/dt1e-5/fig8_$k.ceil")
    bias_rows="$bias_rows| $k | $(cut -d' ' -f9 "$TMP/dt2e-5/fig8_$k.draw" | awk '{ printf "%.3f", $1 }') | $1 | $3 | $4 | $2 | $6 |
"
    k=$((k + 1))
done
pooled_row="| pooled | | $(pooled 2e-5 comm) | $(pooled 2e-5 ceil) | $(pooled 2e-5 mu) | $(pooled 1e-5 comm) | $(pooled 1e-5 ceil) | $(pooled 1e-5 mu) |"
wall=$(($(date +%s) - start))

cat > "$TMP/section.md" <<EOF
$stamp

### The twin's step under friction (fig8)

Is it the twin's step that keeps the fig8 ceiling low? Generated by \`make twin-step\`
(host/reports/twin_step.sh; $wall s of wall time with $JOBS jobs$( [ "${TWIN_REPORT_REUSE:-0}" != 1 ] || printf ' for what this run computed: the runs already in its directory were reused')).

**The climb on the high branch.** fig8 with only its friction changed, 120 s: the speed at
which the slider climbs from s = 0.26 to 0.30 on the high branch (amplitude above 0.4 h; ds/dt [1/s], averaged over
the run's climbs, their number in brackets), by the independent reference at dt = 5e-6 s and
by the core (double) at the scenes' dt = 2e-5 s, at 2e-5 s with the prewarped frequencies
(\`[numerics] prewarp = on\`, docs/design.md 4) and at 1e-5 s:

| mu | reference, 5e-6 s | core, 2e-5 s | against the reference | 2e-5 s, prewarped | against the reference | core, 1e-5 s | against the reference |
|---|---|---|---|---|---|---|---|
${climb_rows}
**The twin at both steps.** The first $PLANTS fig8 plants of the twin report (the same draws),
closed loop with the twin's step, the plant's outer step and the measured signals' sample
period at 2e-5 s and at 1e-5 s (\`TWIN_DT\` of twin_report.sh; the plant's inner step stays
5e-6 s, commissioning is the same). Fraction of the time after 5 s with
|s_twin - s_plant| <= 0.005:

| plant | mu against the scene's | commissioned, 2e-5 s | ceiling, 2e-5 s | estimating, 2e-5 s | commissioned, 1e-5 s | ceiling, 1e-5 s | estimating, 1e-5 s |
|---|---|---|---|---|---|---|---|
${rows}${pooled_row}

Plants on which the estimating twin is more than 3 points below its ceiling: $below_20 of $PLANTS
at 2e-5 s, $below_10 at 1e-5 s.

**The branches in closed loop.** Per plant, for the ceiling at 2e-5 s: the share of the time
after 5 s with the measured amplitude above 0.7 h (the high branch), the fraction of it within
0.005 of the plant's s, the same on the low branch (amplitude below 0.25 h), and on the high
branch the mean of the measured s (s_hat + s_error) less the plant's, at both steps:

| plant | mu | high branch, share of the time | within 0.005 there | within 0.005 on the low branch | measured s - s_plant on the high branch, 2e-5 s | 1e-5 s |
|---|---|---|---|---|---|---|
${bias_rows}
EOF
. host/reports/section.sh
write_section "$OUT" twin-step "$TMP/section.md" || { trap - EXIT; exit 1; }
echo "twin_step: wrote $OUT" >&2
