#!/bin/sh
# embedded_report.sh TARGET:SCENE:REAL:SOLVE:ELF... - cost of the core on Cortex-M
# targets under QEMU, written to docs/embedded.md. Run through
# `make embedded-report` (which builds the images: tests/embedded/scene_run.c
# with -DBS_RUN_COST=1). SOLVE is "subspace" (the default core) or "sweeps"
# (built with -DBS_WITH_SUBSPACE=0: the contact solve is plain sweeps), with
# "-whole" appended for an image that runs the scene's whole run (t_end / dt
# steps) and nothing else.
#
# Per image:
#   flash   core code (.text of core/*.o) + constants (.rodata of core/*.o and
#           the scene's bs_compiled_scene), from the linker map after
#           --gc-sections, i.e. what the core and its scene add to a firmware
#   RAM     the bs_sim (the only RAM the core uses besides stack)
#   stack   the deepest stack a phase of steps used, measured by painting
#           (includes the few bytes of the calling loop)
#   instructions per step, counted exactly by QEMU's TCG plugin
#           (tests/qemu/count.sh): every step is bracketed by two marks;
#           the count includes ~10 instructions of harness (the call through
#           a volatile pointer and the marks), not subtracted. Phase "scene":
#           the scene from its start (settling, impacts, contact with one or
#           two corners); phase "tight": the worst case, all four corners and
#           the clamp stop in contact every step; "whole run": every step of
#           the scene from t = 0 to t_end (60 s of fig6: 3e6 steps), two
#           images at a time
#   where the instructions go (Cortex-M4F float, fig6 and fig6_1mode): each
#           phase is run once more with a per-address profile (count.sh with
#           CM_PROFILE) and split per function (tests/qemu/profile.sh);
#           the script stops if the profile's worst step differs from the
#           count above.
#   optimisation level: images whose SOLVE ends in "-O2" are built at -O2
#           instead of the default CM_OPT (-O3): their code size and counts
#           next to those of the same scene, target and solve at CM_OPT.
# Env: CM_OPT (the level of the other images, for the text; the Makefile passes it).
set -eu
: "${CM_OPT:?embedded_report: CM_OPT unset (run it through make embedded-report)}"
OUT=${OUT:-docs/embedded.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

specs=$*   # TARGET:SCENE:REAL:SOLVE:ELF words (no spaces); "set --" below reuses $@
sh tests/qemu/build-plugin.sh >&2

# core_sizes MAP -> "code rodata scene_rodata sim_bss" in bytes
core_sizes() {
    awk '
        function hex(text,    i, value) { # "0x1a4" -> 420 (mawk has no strtonum)
            value = 0
            for (i = 3; i <= length(text); ++i)
                value = value * 16 + index("0123456789abcdef", tolower(substr(text, i, 1))) - 1
            return value
        }
        function add(name, size, object) {
            if (object ~ /\/core\// && name ~ /^\.text/) code += size
            else if (object ~ /\/core\// && name ~ /^\.rodata/) ro += size
            else if (name == ".rodata.bs_compiled_scene") scene += size
            else if (name == ".bss.sim") sim += size
        }
        /^ \.[A-Za-z_.0-9]+$/ { pending = $1; next }
        pending != "" && NF == 3 && $1 ~ /^0x/ { add(pending, hex($2), $3); pending = ""; next }
        /^ \.[A-Za-z_.0-9]+ +0x/ && NF == 4 { add($1, hex($3), $4) }
        { pending = "" }
        END { printf "%d %d %d %d\n", code, ro, scene, sim }' "$1"
}

# step_counts OUTPUT PHASE [BUDGET] -> "steps mean worst over" from count.sh's output
# (over: steps above BUDGET instructions)
step_counts() {
    awk -v phase="$2" -v budget="${3:-0}" '
        $0 ~ "^" phase ": end" { inside = 0 }
        inside && /^\[insn\] [0-9]+$/ {
            if (++marks % 2 == 0) { n++; sum += $2; if ($2 > worst) worst = $2; if ($2 > budget) over++ }
        }
        $0 ~ "^scene " && phase == "scene" { inside = 1 }
        $0 ~ "^scene: end" && phase == "tight" { inside = 1; marks = 0 }
        END { if (n) printf "%d %.0f %d %d\n", n, sum / n, worst, over; else print "0 0 0 0" }' "$1"
}

# qemu_failed WHAT OUTPUT: says that WHAT failed, with the image's last lines other than
# counts, and stops
qemu_failed() {
    echo "embedded_report: $1 failed under QEMU:" >&2
    grep -v '^\[insn\]' "$2" | tail -n 5 >&2
    exit 1
}

# Cycles per step at dt = 2e-5 s on the boards of the real-time targets: a 168 MHz M4F
# and a 480 MHz M7
M4F_BUDGET=3360
M7_BUDGET=9600
budget() { # TARGET
    case $1 in cortex-m4f) echo $M4F_BUDGET ;; cortex-m7) echo $M7_BUDGET ;; *) echo 0 ;; esac
}

# the whole runs first, two at a time (QEMU runs one image per host thread); each
# output is ~80 MB of counts, deleted once summarised
whole=0
for spec in $specs; do
    case $spec in *-whole:*) ;; *) continue ;; esac
    whole=$((whole + 1))
    echo "embedded_report: $spec: whole run" >&2
    { status=0
      sh tests/qemu/count.sh "$(echo "$spec" | cut -d: -f5)" "${spec%%:*}" 3600 > "$TMP/whole-$whole" || status=$?
      echo $status > "$TMP/whole-$whole.status"; } &
    [ $((whole % 2)) -ne 0 ] || wait
done
wait
whole=0
for spec in $specs; do
    case $spec in *-whole:*) ;; *) continue ;; esac
    whole=$((whole + 1))
    out=$TMP/whole-$whole
    status=$(cat "$out.status")
    [ "$status" -eq 0 ] || qemu_failed "the whole run of $spec (status $status)" "$out"
    budget=$(budget "${spec%%:*}")
    set -- $(step_counts "$out" scene "$budget")
    contacts=$(sed -n 's/^scene: end .* most-contacts \([0-9]*\).*/\1/p' "$out")
    echo "$spec" | awk -F: -v counts="$1 $2 $3 $contacts $4 $budget" \
        '{ sub(/-whole$/, "", $4); print $1, $2, $3, $4, counts }' >> "$TMP/whole_summary"
    rm -f "$out"
done

rows=""
for spec in $specs; do
    case $spec in *-whole:* | *-O2:*) continue ;; esac
    target=$(echo "$spec" | cut -d: -f1)
    scene=$(echo "$spec" | cut -d: -f2)
    real=$(echo "$spec" | cut -d: -f3)
    solve=$(echo "$spec" | cut -d: -f4)
    elf=$(echo "$spec" | cut -d: -f5)
    echo "embedded_report: $target $scene $real $solve" >&2
    sh tests/qemu/count.sh "$elf" "$target" 600 > "$TMP/out" || qemu_failed "$elf" "$TMP/out"
    set -- $(core_sizes "${elf%.elf}.map")
    code=$1 ro=$2 scene_bytes=$3 sim_bytes=$4
    set -- $(step_counts "$TMP/out" scene)
    steps=$1 mean=$2 worst=$3
    set -- $(step_counts "$TMP/out" tight)
    tight_mean=$2 tight_worst=$3
    stack=$(sed -n 's/^scene: end .* stack \([0-9]*\).*/\1/p' "$TMP/out")
    tight_stack=$(sed -n 's/^tight: end .* stack \([0-9]*\).*/\1/p' "$TMP/out")
    contacts=$(sed -n 's/^scene: end .* most-contacts \([0-9]*\).*/\1/p' "$TMP/out")
    tight_contacts=$(sed -n 's/^tight: end .* most-contacts \([0-9]*\).*/\1/p' "$TMP/out")
    [ "$stack" -gt "$tight_stack" ] || stack=$tight_stack
    rows="$rows| $scene | $target | $real | $solve | $code | $((ro + scene_bytes)) | $sim_bytes | $stack | $steps | $mean | $worst ($contacts) | $tight_mean | $tight_worst ($tight_contacts) |
"
    echo "$target $scene $real $mean $worst $tight_worst $solve" >> "$TMP/summary"
    echo "$target $scene $real $solve $code $mean $worst $tight_worst" >> "$TMP/levels"
    # Cortex-M4F float, the scenes with targets: where the worst step of each phase goes
    if [ "$target" = cortex-m4f ] && [ "$real" = float ] && { [ "$scene" = fig6 ] || [ "$scene" = fig6_1mode ]; }; then
        for phase in scene tight; do
            if [ "$phase" = scene ]; then range="first=1,last=$steps" counted=$worst
            else range="first=$((steps + 1))" counted=$tight_worst; fi
            CM_PROFILE="profile=$TMP/profile,$range" sh tests/qemu/count.sh "$elf" "$target" 600 \
                > "$TMP/out" || { echo "embedded_report: profiling $elf failed" >&2; exit 1; }
            sh tests/qemu/profile.sh "$TMP/profile" "$elf" > "$TMP/functions"
            # the profile must see the same worst step as the count above
            set -- $(head -n 1 "$TMP/functions")
            [ "${5:-}" = "$counted" ] || {
                echo "embedded_report: $elf $phase: profile's worst step ${5:-?} != counted $counted" >&2
                exit 1
            }
            awk -v column="$solve $phase" 'NR > 1 { print $1, column, $3 }' "$TMP/functions" \
                >> "$TMP/by_function-$scene"
        done
    fi
done

# The -O2 images -> markdown rows: code, mean, worst and tight worst, each at -O2 and at CM_OPT
for spec in $specs; do
    case $spec in *-O2:*) ;; *) continue ;; esac
    elf=$(echo "$spec" | cut -d: -f5)
    echo "embedded_report: $spec" >&2
    sh tests/qemu/count.sh "$elf" "${spec%%:*}" 600 > "$TMP/out" || qemu_failed "$elf" "$TMP/out"
    set -- $(core_sizes "${elf%.elf}.map") $(step_counts "$TMP/out" scene) $(step_counts "$TMP/out" tight)
    code=$1 mean=$6 worst=$7 tight_worst=${11}
    echo "$spec" | awk -F: -v o2="$code $mean $worst $tight_worst" -v levels="$TMP/levels" '{
        sub(/-O2$/, "", $4)
        while ((getline line < levels) > 0) {
            split(line, f, " ")
            if (f[1] == $1 && f[2] == $2 && f[3] == $3 && f[4] == $4) twin = f[5] " " f[6] " " f[7] " " f[8]
        }
        if (twin == "") { print "embedded_report: no image at the default level for " $0 > "/dev/stderr"; exit 1 }
        split(o2, a, " "); split(twin, b, " ")
        printf "| %s | %s | %s | %d | %d | %d | %d | %d | %d | %d | %d | %.2f |\n", $2, $1, $4,
            a[1], b[1], a[2], b[2], a[3], b[3], a[4], b[4], a[4] / b[4]
    }' >> "$TMP/level_rows"
done

# Core code of the scenes that leave something out, as a share of fig6's (subspace), per level
leaner=$(awk -F'|' '{ for (i = 2; i <= 6; ++i) gsub(/ /, "", $i) }
    $4 == "subspace" { o2[$2] = $5; high[$2] = $6 }
    END {
        if (!o2["fig6"]) exit
        printf "fig6_1mode %.0f %% and fig6_frictionless %.0f %% at -O2, %.0f %% and %.0f %% at the default level",
            100 * o2["fig6_1mode"] / o2["fig6"], 100 * o2["fig6_frictionless"] / o2["fig6"],
            100 * high["fig6_1mode"] / high["fig6"], 100 * high["fig6_frictionless"] / high["fig6"]
    }' "$TMP/level_rows")

# by_function_table SCENE -> markdown rows: instructions per function in the worst step of
# each phase and solve, costliest in the sweeps build's tight phase first, then the total
by_function_table() {
    awk '
        { count[$1 SUBSEP $2 " " $3] = $4; seen[$1] = 1; total[$2 " " $3] += $4 }
        END {
            split("subspace scene,subspace tight,sweeps scene,sweeps tight", column, ",")
            for (f in seen) {
                line = "| `" f "` |"
                for (c = 1; c <= 4; ++c) line = line " " (count[f SUBSEP column[c]] + 0) " |"
                printf "%012d %s\n", count[f SUBSEP "sweeps tight"] + 0, line
            }
            line = "| **the step** |"
            for (c = 1; c <= 4; ++c) line = line " **" total[column[c]] "** |"
            printf "%012d %s\n", -1, line
        }' "$TMP/by_function-$1" | sort -r | cut -d' ' -f2-
}

# outside_solve SCENE -> "FIND SMOOTH STEP": of the sweeps build's worst tight step, the
# instructions that find the contacts (corners, the beam under them), those of the smooth
# part of the step, and the whole step
outside_solve() {
    awk '
        $2 " " $3 != "sweeps tight" { next }
        $1 == "bs_contact_detect" || $1 == "bs_shape_deflection" { find += $4 }
        $1 == "bs_sim_step" || $1 == "bs_beam_force" || $1 ~ /^bs_excitation_/ { smooth += $4 }
        { step += $4 }
        END { printf "%d %d %d\n", find, smooth, step }' "$TMP/by_function-$1"
}

# Real-time margins on the M4F (168 MHz) and M7 (480 MHz) at dt = 2e-5 s: the cycle
# budget per step over the worst instruction count of the whole run (where counted) and
# of any phase
margins=$(awk -v m4f=$M4F_BUDGET -v m7=$M7_BUDGET '
    FILENAME ~ /whole_summary$/ { whole[$1 " " $2 " " $3 " " $4] = $7; next }
    $1 == "cortex-m4f" || $1 == "cortex-m7" {
        worst = $5 > $6 ? $5 : $6
        budget = $1 == "cortex-m4f" ? m4f : m7
        run = whole[$1 " " $2 " " $3 " " $7]
        if (run != "" && run > worst) worst = run
        printf "| %s | %s | %s | %s | %.0f | %s | %s | %d | %.2f |\n", $2, $1, $3, $7, budget,
            run == "" ? "-" : run, run == "" ? "-" : sprintf("%.2f", budget / run), worst, budget / worst
    }' "$TMP/whole_summary" "$TMP/summary")
targets=$(awk '
    FILENAME ~ /whole_summary$/ { whole[$1 " " $2 " " $3 " " $4] = $7; next }
    $1 == "cortex-m4f" && ($2 == "fig6_1mode" || $2 == "fig6") {
        run = whole[$1 " " $2 " " $3 " " $7]
        worst = $5 > $6 ? $5 : $6
        if (run != "" && run > worst) worst = run
        limit = $2 == "fig6_1mode" ? 1500 : 6000
        printf "| %s | %s | %d | %s | %d | %d | %s |\n", $2, $7, $5, run == "" ? "-" : run, $6, limit,
            worst <= limit ? "yes" : "**no**"
    }' "$TMP/whole_summary" "$TMP/summary")
whole_rows=$(awk '{
        printf "| %s | %s | %s | %s | %d | %d | %d (%d) | %d | %d |\n", $2, $1, $3, $4, $5, $6, $7, $8, $10, $9
    }' "$TMP/whole_summary")

# The targets' verdict in numbers: the sweeps build's worst tight step, split
breakdown=""
for scene in fig6_1mode fig6; do
    [ -f "$TMP/by_function-$scene" ] || continue
    limit=$([ "$scene" = fig6_1mode ] && echo 1500 || echo 6000)
    set -- $(outside_solve "$scene")
    breakdown="$breakdown
### $scene

| function | subspace: worst scene step | subspace: worst tight step | sweeps: worst scene step | sweeps: worst tight step |
|---|---|---|---|---|
$(by_function_table "$scene")

In the sweeps build's worst tight step ($3 instructions; target $limit), finding the contacts
(\`bs_contact_detect\`, \`bs_shape_deflection\`: corner positions, the beam under each
corner, gaps, force directions) takes $1 and the smooth part of the step (\`bs_sim_step\`,
\`bs_beam_force\`, \`bs_excitation_*\`) $2, together $(($1 + $2)) ($(awk -v a=$(($1 + $2)) -v b=$limit 'BEGIN { printf "%.0f", 100 * a / b }') % of the target);
the contact solve and its set-up (Delassus matrix, two sweeps, the residual, the update of
the velocities) the remaining $(($3 - $1 - $2)).
"
done

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
cat > "$OUT" <<EOF
# The core on Cortex-M

Produced by \`make embedded-report\` (host/reports/embedded_report.sh) on $(date -u +%Y-%m-%d), commit $commit,
with $(arm-none-eabi-gcc --version | head -n 1) (\`$CM_OPT\`, \`-std=c99\`, no fused multiply-add) and
$(qemu-system-arm --version | head -n 1). Each image is tests/embedded/scene_run.c with the core compiled
against one scene (configs/NAME.h, \`beamslider gen\`) and the generic embedded port
(port/embedded); see the script's header for what each column measures.

**Instruction counts are not cycles.** QEMU counts executed instructions exactly and
deterministically but has no timing model: a Cortex-M4 takes 1 cycle for most integer and
single-precision instructions, 2 for loads, 14 for a division or square root, more for taken
branches and flash wait states; a Cortex-M7 may issue two per cycle. Cycles per step on silicon
will be somewhat higher than these counts on the M4F and may be lower on the M7; measure on
the board (DWT_CYCCNT) before relying on a margin below about 1.5.

| scene | target | real | contact solve | core code [B] | constants [B] | RAM: bs_sim [B] | stack [B] | steps counted | mean insn/step | worst insn/step (contacts) | tight: mean | tight: worst (contacts) |
|---|---|---|---|---|---|---|---|---|---|---|---|---|
$rows
"scene": the first steps of the scene from its start (20 000 steps
on the FPU targets, 2 000 on the M3 and M0+: settling, impacts and contact with one or two
corners). "tight": a quarter as many steps with every corner and the clamp stop in contact.
Constants are the core's read-only data and the scene (mode-shape table, modal data); the
M3 and M0+ have no FPU and compute float in software (libgcc), hence the large counts.
"contact solve": "subspace" is the default core; "sweeps" the same core built with
\`-DBS_WITH_SUBSPACE=0\`, whose contact solve is at most pgs_max_sweeps (here 2) plain
Gauss-Seidel sweeps: no Gaussian eliminations, a hard bound on the cost of a step, at the
price of steps left unconverged where two corners of one face touch (what that does to
accuracy: docs/accuracy.md, "Without the subspace step").

## Whole runs

Every step of the scene's run from t = 0 to t_end (fig6 and fig6_1mode: 60 s, 3 000 000
steps at dt = 2e-5 s: the drift to the clamp, the jump and the walk back), float, on the
boards of the real-time targets. The "scene" phase above is its first 0.4 s. The cycle
budget is clock x dt (168 MHz M4F, 480 MHz M7); the last column counts the steps whose
instructions alone exceed it.

| scene | target | real | contact solve | steps | mean insn/step | worst insn/step (contacts) | cycle budget | steps over budget |
|---|---|---|---|---|---|---|---|---|
$whole_rows

## Targets of the embedded issue (Cortex-M4F, worst case of every phase)

| scene | contact solve | worst: scene | worst: whole run | worst: tight | target | met |
|---|---|---|---|---|---|---|
$targets

## Where the instructions go (Cortex-M4F, float)

Instructions executed in each function during the worst step of each phase, for the default
core ("subspace") and the sweeps build (tests/qemu/profile.sh on a profile from the same
QEMU plugin; code inlined into a function counts there). The last row is the whole step; the
script checks that it equals the worst count of the tables above.
$breakdown
## Optimisation level

The same images built at -O2 instead of \`$CM_OPT\` (every other image of this report):
core code in bytes and instructions per step (scene: mean and worst; tight: worst). The
loops over modes and contact rows have lengths fixed by the compiled scene, which the
higher level unrolls; the last column is the tight worst step at -O2 over the default.

Core code of the scenes that leave something out, as a share of fig6's (subspace solve):
$leaner.
Where a share is above 100 %, unrolling the leaner scene's loops at the higher level adds
more code than its switches removed.

| scene | target | contact solve | code: -O2 | code: default | mean: -O2 | mean: default | worst: -O2 | worst: default | tight worst: -O2 | tight worst: default | tight worst -O2 / default |
|---|---|---|---|---|---|---|---|---|---|---|---|
$(cat "$TMP/level_rows" 2>/dev/null)

## Real-time margin at dt = 2e-5 s

Cycle budget per step (clock x dt) over the worst instruction count of the whole run (where
counted) and of any phase, the tight one included; above 1 means the step fits in real time
*if* one instruction took one cycle (see above).

| scene | board | real | contact solve | cycle budget | worst: whole run | budget / worst: whole run | worst: any phase | budget / worst: any phase |
|---|---|---|---|---|---|---|---|---|
$margins
EOF
echo "embedded_report: wrote $OUT" >&2
