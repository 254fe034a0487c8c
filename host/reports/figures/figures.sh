#!/bin/sh
# figures.sh - `make figures`: the PCS sweeps and free runs of the papers'
# figures, their PNGs in docs/figures/ and the numbers in docs/validation.md
# section 7 (between <!-- figures-table --> and <!-- figures-scenarios -->
# markers). Run from the repository root through `make figures`.
#
# Every simulation is an independent, deterministic job (one process, one
# core); JOBS of them run at a time (default: all cores), so the results do
# not depend on JOBS. CSVs go to build/figures/.
#
# Knobs: BIN (the beamslider binary), JOBS, DATA (CSV folder), FIG (PNG
# folder), DOC (the validation page), RUNS=0 (reuse the CSVs of the last run:
# only plots and tables).
set -eu
BIN=${BIN:-build/double/beamslider}
JOBS=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)}
RUNS=${RUNS:-1}
DATA=${DATA:-build/figures}
FIG=${FIG:-docs/figures}
DOC=${DOC:-docs/validation.md}
HERE=host/reports/figures
SCENARIOS="fig6 fig7 fig8 fig9 fig12a fig12b"
# fig8's ensemble: ENSEMBLE starts s0 + k ENSEMBLE_STEP (k = 0 is the scene's own run,
# the one run_fig8.png draws), since one run of a chaotic scene may not be typical
ENSEMBLE=8
ENSEMBLE_STEP=1e-5
export BIN DATA

for marker in figures-table figures-scenarios; do
    if ! grep -q "<!-- $marker -->" "$DOC" || ! grep -q "<!-- /$marker -->" "$DOC"; then
        echo "figures: $DOC has no <!-- $marker --> ... <!-- /$marker --> pair" >&2
        exit 1
    fi
done
mkdir -p "$DATA" "$FIG"
# the section's and the figures' stamp (host/reports/provenance.sh; with RUNS=0 it is
# the current build's, whatever made the CSVs reused)
. host/reports/provenance.sh
stamp=$(provenance_stamp "make figures")

# ensemble_s0 K -> s0 of start K of fig8's ensemble (the scene's s0 + K ENSEMBLE_STEP)
ensemble_s0() {
    awk -v s0="$(sed -n 's/^s0 *= *\([0-9.]*\).*/\1/p' configs/fig8.ini)" -v k="$1" -v step="$ENSEMBLE_STEP" \
        'BEGIN { printf "%.5f", s0 + k * step }'
}

# ---------------------------------------------------------------------------
# 1. Simulations: NAME ARGS... per line, the longest first. The sweeps use
# the defaults of docs/model.md 6: s from 0 to 0.5 in steps of 0.005, 100 periods
# held and 25 recorded per point; the fig6 sweeps also trace s = 0.3 (Fig. 2).
{
    for dir in up down; do
        echo "fig6_$dir sweep configs/fig6.ini --dir $dir --out $DATA/fig6_$dir.csv" \
             "--trace $DATA/fig6_${dir}_trace.csv --trace-at 0.3 --trace-periods 5"
    done
    for scene in fig7 fig8 fig12a fig12b fig9 fig6 fig6_1mode; do
        echo "${scene}_run run configs/$scene.ini --periods $DATA/${scene}_periods.csv"
    done
    k=1
    while [ "$k" -lt "$ENSEMBLE" ]; do
        echo "fig8_e${k}_run run configs/fig8.ini --s0 $(ensemble_s0 "$k") --periods $DATA/fig8_e${k}_periods.csv"
        k=$((k + 1))
    done
    for dir in up down; do
        echo "fig6_1mode_$dir sweep configs/fig6_1mode.ini --dir $dir --out $DATA/fig6_1mode_$dir.csv"
    done
} > "$DATA/jobs.txt"
if [ "$RUNS" != 0 ]; then
    echo "figures: $(wc -l < "$DATA/jobs.txt") simulations, $JOBS at a time" >&2
    start=$(date +%s)
    # shellcheck disable=SC2016
    if ! xargs -P "$JOBS" -L 1 sh -c '
            name=$1; shift
            if "$BIN" "$@" > "$DATA/$name.json" 2> "$DATA/$name.err"; then
                echo "figures: $name: $(sed -n "s/.*\"wall_s\":\([^,]*\).*/\1/p" "$DATA/$name.json") s" >&2
            else
                echo "figures: $name failed: $BIN $*" >&2
                cat "$DATA/$name.err" >&2
                exit 1
            fi' job < "$DATA/jobs.txt"; then
        echo "figures: a simulation failed" >&2
        exit 1
    fi
    echo "figures: simulations done in $(($(date +%s) - start)) s wall" >&2
fi

# ---------------------------------------------------------------------------
# 2. Numbers: 1 s averages, then shell assignments SCENE_key='value'.
for scene in $SCENARIOS fig6_1mode; do
    awk -F, -f "$HERE/smooth.awk" "$DATA/${scene}_periods.csv" > "$DATA/${scene}_smooth.csv"
done
: > "$DATA/numbers.sh"
for scene in fig6 fig6_1mode; do
    awk -F, -v prefix="${scene}_b" -f "$HERE/branches.awk" "$DATA/${scene}_up.csv" "$DATA/${scene}_down.csv" \
        "$DATA/${scene}_periods.csv" "$DATA/${scene}_smooth.csv" >> "$DATA/numbers.sh"
done
for scene in $SCENARIOS; do
    s0=$(sed -n 's/.*"s0":\([^,]*\).*/\1/p' "$DATA/${scene}_run.json")
    awk -F, -v prefix="$scene" -v s0="$s0" -f "$HERE/scenario.awk" "$DATA/${scene}_periods.csv" \
        "$DATA/${scene}_smooth.csv" >> "$DATA/numbers.sh"
    echo "${scene}_s0='$s0'" >> "$DATA/numbers.sh"
done
# the ensemble: start k's numbers under the prefix fig8_eK (fig8_e0: the scene's run)
k=0
echo "fig8_ensemble='$ENSEMBLE'" >> "$DATA/numbers.sh"
echo "fig8_ensemble_step='$ENSEMBLE_STEP'" >> "$DATA/numbers.sh"
while [ "$k" -lt "$ENSEMBLE" ]; do
    if [ "$k" -eq 0 ]; then
        periods=$DATA/fig8_periods.csv
        s0=$(sed -n 's/.*"s0":\([^,]*\).*/\1/p' "$DATA/fig8_run.json")
    else
        periods=$DATA/fig8_e${k}_periods.csv
        s0=$(ensemble_s0 "$k")
    fi
    awk -F, -f "$HERE/smooth.awk" "$periods" > "$DATA/fig8_e${k}_smooth.csv"
    awk -F, -v prefix="fig8_e$k" -v s0="$s0" -f "$HERE/scenario.awk" "$periods" "$DATA/fig8_e${k}_smooth.csv" >> "$DATA/numbers.sh"
    echo "fig8_e${k}_s0='$s0'" >> "$DATA/numbers.sh"
    k=$((k + 1))
done
. "$DATA/numbers.sh"
get() { eval "printf '%s' \"\${$1}\""; }                                # get VARIABLE
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }  # lt A B: A < B
rows() { echo $(($(wc -l < "$1") - 1)); }

# ---------------------------------------------------------------------------
# 3. Figures.
gp() { # gp SCRIPT ASSIGNMENTS
    gnuplot -e "$2" "$HERE/$1"
}
ini() { # ini SCENE KEY: a number from the scene file itself
    sed -n "s/^$2 *= *\([0-9.]*\).*/\1/p" "configs/$1.ini"
}
gp fig1b.gp "up='$DATA/fig6_up.csv'; down='$DATA/fig6_down.csv'; smooth='$DATA/fig6_smooth.csv';
    ends=$(rows "$DATA/fig6_smooth.csv"); out='$FIG/fig1b.png';
    ttl='Fig. 1b, fig6 (five modes, f_{ex} = $(ini fig6 frequency) Hz, a = $(ini fig6 acceleration) m/s^2): PCS branches and the free slider'"
gp fig1b_pair.gp "up1='$DATA/fig6_up.csv'; down1='$DATA/fig6_down.csv'; smooth1='$DATA/fig6_smooth.csv';
    ends1=$(rows "$DATA/fig6_smooth.csv"); ttl1='fig6: five modes';
    up2='$DATA/fig6_1mode_up.csv'; down2='$DATA/fig6_1mode_down.csv'; smooth2='$DATA/fig6_1mode_smooth.csv';
    ends2=$(rows "$DATA/fig6_1mode_smooth.csv"); ttl2='fig6\\_1mode: the lowest mode only (the seed paper''s model)';
    out='$FIG/fig1b_modes.png'"
gp fig1c.gp "up='$DATA/fig6_up.csv'; down='$DATA/fig6_down.csv'; smin=$fig6_b_s_min; smax=$fig6_b_s_max;
    out='$FIG/fig1c.png'; ttl='Fig. 1c, fig6: averaged slider velocity on the PCS model (25 recorded periods per point)'"
# Fig. 2b is the low branch at s = 0.3, 2c the high one: whichever sweep has
# the smaller amplitude there is on the low branch.
if lt "$fig6_b_up_amp_3" "$fig6_b_down_amp_3"; then low=up high=down; else low=down high=up; fi
gp fig2.gp "trace='$DATA/fig6_${low}_trace.csv'; out='$FIG/fig2b.png';
    ttl='Fig. 2b, fig6, PCS at s = 0.3 on the low branch (sweep $low, amplitude $(get fig6_b_${low}_amp_3) h)'"
gp fig2.gp "trace='$DATA/fig6_${high}_trace.csv'; out='$FIG/fig2c.png';
    ttl='Fig. 2c, fig6, PCS at s = 0.3 on the high branch (sweep $high, amplitude $(get fig6_b_${high}_amp_3) h)'"
for scene in $SCENARIOS; do
    description=$(sed -n 's/^description *= *//p' "configs/$scene.ini")
    gp scenario.gp "periods='$DATA/${scene}_periods.csv'; smooth='$DATA/${scene}_smooth.csv';
        out='$FIG/run_$scene.png';
        ttl='$scene: f_{ex} = $(ini $scene frequency) Hz, a = $(ini $scene acceleration) m/s^2, s_0 = $(get ${scene}_s0) ($description)'"
done
# fig8's ensemble: every start's 1 s averages, the scene's own start (run_fig8.png) bold
ensemble_files=
k=0
while [ "$k" -lt "$ENSEMBLE" ]; do ensemble_files="$ensemble_files $DATA/fig8_e${k}_smooth.csv"; k=$((k + 1)); done
gp ensemble.gp "files='${ensemble_files# }'; out='$FIG/run_fig8_ensemble.png';
    ttl='fig8 from $ENSEMBLE starts s_0 = $fig8_s0 + k $ENSEMBLE_STEP (k = 0..$((ENSEMBLE - 1))); bold: s_0 = $fig8_s0, the run of run\\_fig8.png'"
provenance_figures "$stamp" "$FIG"/fig1b.png "$FIG"/fig1b_modes.png "$FIG"/fig1c.png "$FIG"/fig2b.png "$FIG"/fig2c.png
for scene in $SCENARIOS; do provenance_figures "$stamp" "$FIG/run_$scene.png"; done
provenance_figures "$stamp" "$FIG/run_fig8_ensemble.png"
echo "figures: wrote $FIG/*.png" >&2

# ---------------------------------------------------------------------------
# 4. Tables for docs/validation.md (host/reports/figures/tables.awk: criteria, verdicts).
{ printf '%s\n' "$stamp"; provenance_text "$stamp"; echo; } > "$DATA/table.md"
awk -v part=table -f "$HERE/tables.awk" "$DATA/numbers.sh" >> "$DATA/table.md"
awk -v part=scenarios -f "$HERE/tables.awk" "$DATA/numbers.sh" > "$DATA/scenarios.md"
awk -v table="$DATA/table.md" -v scenarios="$DATA/scenarios.md" '
    function copy(file,    line) { while ((getline line < file) > 0) print line; close(file) }
    /<!-- figures-table -->/ { print; copy(table); skip = 1; next }
    /<!-- figures-scenarios -->/ { print; copy(scenarios); skip = 1; next }
    /<!-- \/figures-(table|scenarios) -->/ { skip = 0 }
    !skip { print }' "$DOC" > "$DATA/doc.md"
cp "$DATA/doc.md" "$DOC"
echo "figures: updated $DOC" >&2
