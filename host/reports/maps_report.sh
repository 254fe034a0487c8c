#!/bin/sh
# maps_report.sh - `make maps`: the operating map of the validated parameter
# set (configs/mssp2023.ini, through configs/fig6.ini with its excitation
# varied) over f_ex 90-140 Hz x a 2-20 m/s^2, 3 starts per point, 120 s each,
# its heatmaps (docs/figures/map_*.png) and the numbers of docs/maps.md
# between <!-- maps-numbers --> and <!-- /maps-numbers -->. Run from the
# repository root through `make maps`.
#
# The map is resumable: run again after an interruption, it runs only the
# cases not done. Each invocation's JSON summary is kept beside the folder
# (DIR-run-DATE.json); the wall time and cases per second reported are those
# of the invocation that ran the most cases.
#
# Knobs: BIN (the beamslider binary), DIR (the map's folder), JOBS (default:
# all cores), FIG (PNG folder), DOC (the page).
set -eu
BIN=${BIN:-build/double/beamslider}
DIR=${DIR:-build/maps/mssp2023}
JOBS=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)}
FIG=${FIG:-docs/figures}
DOC=${DOC:-docs/maps.md}
# the papers' scenarios on the map: f_ex, a, name (fig12a and fig12b share a
# point; fig12b starts at s0 = 0.4, the map at 0.3 like the others)
MARKS=${MARKS:-"124,14,fig6 104,14,fig7 126,10,fig8 124,6,fig9 106,10,fig12a/b"}
LABELS="fig6:signature fig7:trivial fig8:relaxation fig9:self_damping fig12a:trivial"
# the outcome classes in their table order (host/lib/map/outcome_classes.h, the one table)
CLASSES=$(sed -n 's/^ *X([A-Z_]*, *\([a-z_]*\),.*/\1/p' host/lib/map/outcome_classes.h | tr '\n' ' ')
[ -n "$CLASSES" ] || { echo "maps: no outcome classes in host/lib/map/outcome_classes.h" >&2; exit 1; }

if ! grep -q '<!-- maps-numbers -->' "$DOC" || ! grep -q '<!-- /maps-numbers -->' "$DOC"; then
    echo "maps: $DOC has no <!-- maps-numbers --> ... <!-- /maps-numbers --> pair" >&2
    exit 1
fi
mkdir -p "$(dirname "$DIR")" "$FIG"
# the section's and the figures' stamp (host/reports/provenance.sh)
. host/reports/provenance.sh
stamp=$(provenance_stamp "make maps")
command="$BIN map configs/fig6.ini --set run.t_end=120 --vary excitation.frequency=90:140:1 \
--vary excitation.acceleration=2:20:2 --repeat 3 --jobs $JOBS --out $DIR"
echo "maps: $command" >&2
# shellcheck disable=SC2086
$command >"$DIR-run-$(date +%Y%m%d-%H%M%S).json"

set --
for mark in $MARKS; do set -- "$@" --mark "$mark"; done
"$BIN" map-plot "$DIR" --out "$DIR-plot" --title "validated set (fig6.ini), 120 s from s0 = 0.3" "$@"
for figure in outcome agreement s_settled s_spread amp_h; do
    cp "$DIR-plot_$figure.png" "$FIG/map_$figure.png"
    provenance_figures "$stamp" "$FIG/map_$figure.png"
done

# ---- numbers
run_json=$(for f in "$DIR"-run-*.json; do
    printf '%s %s\n' "$(sed -n 's/.*"run":\([0-9]*\).*/\1/p' "$f")" "$f"; done | sort -n | tail -n 1 | cut -d' ' -f2)
field() { sed -n "s/.*\"$1\":\"\{0,1\}\([^,\"}]*\).*/\1/p" "$run_json"; }
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)
{
    echo "$stamp"
    echo "Produced by \`make maps\` (host/reports/maps_report.sh) on $(date -u +%Y-%m-%d): beamslider"
    echo "$(field version) (revision $(field revision)), $(field precision) precision."
    echo
    echo '```sh'
    echo "$command"
    echo '```'
    echo
    echo "| cases | grid points | starts per point | jobs | wall time | cases per second | machine |"
    echo "|---|---|---|---|---|---|---|"
    echo "| $(field cases) ($(field run) run by this invocation) | $(field points) | $(field repeat) | $(field jobs) |" \
        "$(awk -v w="$(field wall_s)" 'BEGIN { printf "%.0f s (%.1f min)", w, w / 60 }') | $(field cases_per_s) |" \
        "$(getconf _NPROCESSORS_ONLN) cores, $cpu |"
    echo
    echo "Grid points by the class most of their 3 starts ended in, and how many of the points"
    echo "had starts in more than one class:"
    echo
    awk -F, -v classes="$CLASSES" 'NR == 1 { next }
        { n[$5]++; total++; if ($6 + 0 < 1) split_points++ }
        END {
            printf "| class | grid points | share |\n|---|---|---|\n"
            count = split(classes, order, " ")
            for (i = 1; i <= count; i++) printf "| %s | %d | %.0f %% |\n", order[i], n[order[i]], 100 * n[order[i]] / total
            printf "| (points whose starts disagree) | %d | %.0f %% |\n", split_points, 100 * split_points / total
        }' "$DIR/map.csv"
    echo
    echo "What the runs classed *other* did (runs.csv; the rules of section 2 are not changed by this):"
    echo
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        { runs++ }
        $c["outcome"] != "other" { next }
        { other++
          if ($c["cycles"] == 1) one++
          else if ($c["cycles"] == 0 && $c["amp_h"] > 0.5) high++
          else if ($c["cycles"] == 0 && $c["amp_max_h"] < 0.25) low++
          else rest++ }
        END {
            printf "| of %d runs | runs |\n|---|---|\n", runs
            printf "| other | %d |\n", other
            printf "| ... end on the high branch without a fall (amp_h > 0.5 h, no cycle), but s did not walk one way (a retreat of 0.005 or more) nor make a signature move | %d |\n", high
            printf "| ... one cycle (a rise and a fall; two make a relaxation oscillation) | %d |\n", one
            printf "| ... never above 0.25 h, but not below 0.05 h over the last 10 s | %d |\n", low
            printf "| ... no cycle; the 1 s averaged amplitude went above 0.25 h, but the last 10 s are not above 0.5 h (between the branches at the end) | %d |\n", rest
        }' "$DIR/runs.csv"
    echo
    echo "The papers' scenarios on the map (the point's 3 starts). fig12b, fig12a's excitation from s0 = 0.4,"
    echo "is not on it: the map starts every run at 0.3 (tests/check_map.sh classifies fig12b from its own start)."
    echo
    echo "| scenario | f_ex [Hz] | a [m/s^2] | paper | map: class (agreement) | fractions $(echo $CLASSES | tr ' ' '/') | s_settled mean (sd) | amp_h mean [h] |"
    echo "|---|---|---|---|---|---|---|---|"
    for pair in $LABELS; do
        scene=${pair%%:*}
        f=$(sed -n 's/^frequency *= *\([0-9.]*\).*/\1/p' "configs/$scene.ini")
        a=$(sed -n 's/^acceleration *= *\([0-9.]*\).*/\1/p' "configs/$scene.ini")
        awk -F, -v f="$f" -v a="$a" -v scene="$scene" -v want="${pair#*:}" -v classes="$CLASSES" '
            NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; count = split(classes, order, " "); next }
            $2 == f && $3 == a {
                fractions = ""
                for (i = 1; i <= count; i++) fractions = fractions (i > 1 ? "/" : "") $c["frac_" order[i]]
                printf "| %s | %s | %s | %s | %s (%s) | %s | %s (%s) | %s |\n", scene, f, a, want,
                    $c["outcome"], $c["agreement"], fractions, $c["s_settled_mean"], $c["s_settled_sd"], $c["amp_h_mean"]
            }' "$DIR/map.csv"
    done
} >"$DIR-numbers.md"
. host/reports/section.sh
write_section "$DOC" maps-numbers "$DIR-numbers.md"
echo "maps: wrote $FIG/map_*.png and the numbers of $DOC" >&2
