#!/bin/sh
# twin_ceiling_maps.sh - does the fig8 ceiling lack the plant's friction in its
# response maps? The section of docs/twin.md between <!-- twin-ceiling-maps -->
# and <!-- /twin-ceiling-maps --> (an OUT without them is refused; a new OUT is
# written whole). Run through `make twin-ceiling-maps` (about
# 15 minutes on 2 cores for 12 plants).
#
# The ceiling of `make twin-report` is told the plant's mu and e_N on the
# running twin (--friction, --restitution), but its response maps, which turn
# the lock-in's measurement into s, are designed with the scene's values. Here
# each fig8 plant of twin_report.sh (the same draws, seed = plant number) is run
# once more with CEILING_MAPS=1: a third commissioned twin whose scene holds the
# plant's mu and e_N, so that its maps are designed with them too. Printed per
# plant and pooled after 5 s: the fraction of time with |s_twin - s_plant| <=
# 0.005 for the commissioned twin, the ceiling and the ceiling with the maps.
#
#   PLANTS=12 (default) OUT=docs/twin.md JOBS=$(nproc)
#   TWIN_REPORT_DIR=DIR keeps the plants' files (TWIN_REPORT_REUSE=1: not run again;
#   TWIN_REPORT_SIGNALS=1: their signals kept, and only their twins run again where
#   they are, twin_report.sh)
set -eu
OUT=${OUT:-docs/twin.md}
PLANTS=${PLANTS:-12}
JOBS=${JOBS:-$(nproc)}
. host/reports/twin_rows.sh
work_dir
. host/reports/provenance.sh
stamp=$(provenance_stamp "make twin-ceiling-maps$( [ "$PLANTS" = 12 ] || printf ' PLANTS=%s' "$PLANTS")")

run_plants fig8 "$TMP" maps CEILING_MAPS=1

rows="" k=1 better=0 worse=0
while [ "$k" -le "$PLANTS" ]; do
    dm=$(cut -d' ' -f3 "$TMP/fig8_$k.draw")
    c=$(within "$TMP/fig8_$k.comm") e=$(within "$TMP/fig8_$k.ceil") m=$(within "$TMP/fig8_$k.maps")
    if awk -v a="$m" -v b="$e" 'BEGIN { exit !(a > b + 0.01) }'; then better=$((better + 1)); fi
    if awk -v a="$m" -v b="$e" 'BEGIN { exit !(a < b - 0.01) }'; then worse=$((worse + 1)); fi
    be=$(branches "$TMP/fig8_$k.ceil" | cut -d' ' -f2) bm=$(branches "$TMP/fig8_$k.maps" | cut -d' ' -f2)
    rows="$rows| $k | $(awk -v d="$dm" 'BEGIN { printf "%+.0f %%", 100 * d }') | $c | $e | $m | $be | $bm |
"
    k=$((k + 1))
done
pooled() { # pooled SUFFIX: over every plant's rows
    k=1 files=""
    while [ "$k" -le "$PLANTS" ]; do files="$files $TMP/fig8_$k.$1"; k=$((k + 1)); done
    # shellcheck disable=SC2086
    within $files
}
pc=$(pooled comm) pe=$(pooled ceil) pm=$(pooled maps)

cat > "$TMP/section.md" <<EOF
$stamp

### The ceiling with its maps designed at the plant's friction (fig8)

Is it the response maps that keep the fig8 ceiling below the commissioned twin? The ceiling above
is told the plant's mu and e_N on the running twin, but its maps are the scene's. Here each of the
first $PLANTS fig8 plants (the draws of the report) runs a third commissioned twin whose scene
holds the plant's mu and e_N, so that its maps are designed with them as well
(host/reports/twin_ceiling_maps.sh). Fraction of the time after 5 s
with |s_twin - s_plant| <= 0.005, and on the high branch (measured amplitude above 0.7 h) the
mean of the measured s (s_hat + s_error) less the plant's, for the ceiling and with the maps:

| plant | mu against the scene's | commissioned | ceiling (told mu, e_N) | ceiling, maps at the plant's mu, e_N | measured s - s_plant on the high branch: ceiling | maps at the plant's |
|---|---|---|---|---|---|---|
${rows}| pooled | | $pc | $pe | $pm | | |

The maps designed at the plant's friction and restitution do better than the ceiling by more than a
point on $better of $PLANTS plants and worse on $worse.
EOF
. host/reports/section.sh
write_section "$OUT" twin-ceiling-maps "$TMP/section.md" || { trap - EXIT; exit 1; }
echo "twin_ceiling_maps: wrote $OUT" >&2
