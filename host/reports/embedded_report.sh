#!/bin/sh
# embedded_report.sh TARGET:SCENE:REAL:KIND:ELF... - cost of the core on Cortex-M under
# QEMU, against the targets of the embedded issue, written to docs/embedded.md. Run
# through `make embedded-report` (tests/embedded/embedded.mk builds the images:
# tests/embedded/scene_run.c with -DBS_RUN_COST=1, every step bracketed by two marks).
#
# KIND is SOLVE[-ram][-O2|-whole]. SOLVE: "subspace" (the default core) or "sweeps"
# (built with -DBS_WITH_SUBSPACE=0). No suffix: a per-phase cost image (phases "scene",
# the scene's first steps, and "tight", every corner and the clamp stop in contact).
# -ram: the scene copied to RAM before the run and no literal pools (-mslow-flash-data),
# so that a step reads no data from flash. -O2: built at -O2 instead of CM_OPT.
# -whole: the scene's whole run (t_end / dt steps) and nothing else.
#
# Measured per image (all Cortex-M4F runs with the cycle estimate, CM_CYCLES=1):
#   flash   core code (the image's instructions whose source line is in core/:
#           code_bytes.sh) + constants (.rodata of core/*.o, none with -flto, and the
#           scene's bs_compiled_scene, from the linker map after --gc-sections)
#   RAM     the bs_sim (the only RAM the core uses besides stack), plus the scene's
#           copy in the ram variant
#   stack   the deepest stack a phase used, measured by painting (includes the few
#           bytes of the calling loop)
#   per step, from the counter's line at the second mark of each step
#           (tests/qemu/count.sh; the count includes ~10 instructions of harness: the
#           call through a volatile pointer and the marks, not subtracted):
#           instructions (exact), and on the M4F estimated cycles C + P T + W F from
#           the plugin's base cycles C, branches taken T and data reads from flash F:
#           optimistic P = 1, W = 0; pessimistic P = 3, W = 5
#   budget  clock x dt cycles per step: 3360 (168 MHz M4F), 9600 (480 MHz M7), dt 2e-5 s
#   backlog of a twin that reads one sample per dt: the Lindley recursion
#           W = max(0, W + c_k - B) over the per-step cost c_k (pessimistic cycles; on
#           the M7, which has no cycle model, instructions) with budget B; the largest
#           W as ceil(W / B) samples and W / f_clock
#   where the cycles go (M4F float fig6 and fig6_1mode): the whole runs (constants in
#           flash) are profiled as they are counted (count.sh with CM_PROFILE) and split
#           per function (tests/qemu/profile.sh); the worst steps of the cost images'
#           phases, default core and sweeps build, once more each. The script stops if a
#           profile disagrees with the counts (worst step, total pessimistic cycles).
#           The whole runs' profiles also by kind of instruction (tests/qemu/classes.sh)
#           and stage of the step (STAGE_AWK): cycles against the floating-point
#           arithmetic the step executes.
#   the ram variant must end each phase in the same state (hash) as its flash twin.
# QEMU runs two at a time (one image per host thread); a whole run's counts (~300 MB for
# 60 s) are summarised as they stream and never stored.
# Env: CM_OPT (the level of the images, for the text; the Makefile passes it), CM_BUILD,
# OUT (default docs/embedded.md).
set -eu
: "${CM_OPT:?embedded_report: CM_OPT unset (run it through make embedded-report)}"
OUT=${OUT:-docs/embedded.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# the page's stamp (host/reports/provenance.sh): the sources of the images and the flags
. host/reports/provenance.sh
stamp=$(provenance_stamp "make embedded-report" embedded)

sh tests/qemu/build-plugin.sh >&2

# Boards of the real-time targets at dt = 2e-5 s: clock [MHz] and cycles per step
M4F_MHZ=168 M4F_BUDGET=3360
M7_MHZ=480 M7_BUDGET=9600
budget() { case $1 in cortex-m4f) echo $M4F_BUDGET ;; cortex-m7) echo $M7_BUDGET ;; *) echo 0 ;; esac; }
mhz() { case $1 in cortex-m4f) echo $M4F_MHZ ;; cortex-m7) echo $M7_MHZ ;; *) echo 0 ;; esac; }
# The two estimates: branch refill P and flash wait states W per data read
OPT_REFILL=1 OPT_WAIT=0
PESS_REFILL=3 PESS_WAIT=5

# One image per job, numbered in argument order: $TMP/spec-N holds TARGET:SCENE:REAL:KIND:ELF
n=0
for spec in "$@"; do
    n=$((n + 1))
    echo "$spec" > "$TMP/spec-$n"
done
jobs=$n
word() { cut -d: -f"$2" "$TMP/spec-$1"; } # word JOB FIELD

# profiled TARGET SCENE REAL KIND: whether the image's cost is split per function
profiled() {
    [ "$1" = cortex-m4f ] && [ "$3" = float ] || return 1
    case $2:$4 in fig6:subspace-whole | fig6_1mode:subspace-whole | fig6:subspace | fig6:sweeps | \
                  fig6_1mode:subspace | fig6_1mode:sweeps) return 0 ;; esac
    return 1
}

# core_sizes ELF -> "code rodata scene_rodata sim_bss scene_copy_bss" in bytes: the code
# generated from core/ (code_bytes.sh), the rest from the link map beside the image. The
# core's .rodata (the scene check's messages, ~550 B; its numeric constants are literal
# pools, in its code) is found by its object file, which -flto does not keep: 0 there.
core_sizes() {
    code=$(sh host/reports/code_bytes.sh "$1" /core/)
    awk -f host/reports/link_map_sections.awk "${1%.elf}.map" | awk -v code="$code" '
        $3 ~ /\/core\// && $1 ~ /^\.rodata/ { ro += $2; next }
        $1 == ".rodata.bs_compiled_scene" { scene += $2; next }
        $1 == ".bss.sim" { sim += $2; next }
        $1 == ".bss.scene_in_ram" { copy += $2 }
        END { printf "%d %d %d %d %d\n", code, ro, scene, sim, copy }'
}

# The steps of one phase of count.sh's output -> "NAME VALUE" lines (read them with val):
# steps, mean_/worst_ insn, opt (optimistic cycles), pess (pessimistic cycles); over
# (steps whose cost exceeds the budget) and backlog (largest Lindley W, in cycles), the
# cost being pessimistic cycles where estimated, else instructions; sum_insn, sum_pess;
# flash and taken (mean per step); status, contacts (most at once) and stack from the
# phase's end line, and the state's hash there. Run by steps_of.
STEPS_AWK='
    other != "" && !/^\[insn\] [0-9]/ { print > other }
    $0 ~ "^" phase ": end" {
        inside = 0
        for (i = 3; i < NF; ++i) {
            if ($i == "status") status = $(i + 1)
            if ($i == "most-contacts") contacts = $(i + 1)
            if ($i == "stack") stack = $(i + 1)
            if ($i == "hash") hash = $(i + 1)
        }
    }
    inside && /^\[insn\] [0-9]+( |$)/ {
        if (++marks % 2) next            # the odd marks open a step
        ++n; insn = $2; sum_insn += insn; if (insn > worst_insn) worst_insn = insn
        cost = insn
        if (NF >= 8) {                   # "[insn] N cycles C taken T flash F"
            cycles = 1
            opt = $4 + opt_refill * $6 + opt_wait * $8
            pess = $4 + pess_refill * $6 + pess_wait * $8
            sum_opt += opt; if (opt > worst_opt) worst_opt = opt
            sum_pess += pess; if (pess > worst_pess) worst_pess = pess
            taken += $6; flash += $8
            cost = pess
        }
        if (cost > budget) ++over
        backlog += cost - budget         # Lindley: the cycles still owed when the next sample comes
        if (backlog < 0) backlog = 0
        if (backlog > worst_backlog) worst_backlog = backlog
    }
    phase == "scene" && /^scene / { inside = 1 }
    phase == "tight" && /^scene: end/ { inside = 1; marks = 0 }
    END {
        printf "steps %d\nstatus %s\ncontacts %s\nstack %s\nhash %s\n", n, status == "" ? "none" : status, contacts + 0, stack + 0, hash == "" ? "-" : hash
        if (!n) exit
        printf "mean_insn %.0f\nworst_insn %d\nsum_insn %.0f\nover %d\nbacklog %.0f\n", sum_insn / n, worst_insn, sum_insn, over, worst_backlog
        if (cycles)
            printf "mean_opt %.0f\nworst_opt %d\nmean_pess %.0f\nworst_pess %d\nsum_pess %.0f\nflash %.1f\ntaken %.1f\n",
                sum_opt / n, worst_opt, sum_pess / n, worst_pess, sum_pess, flash / n, taken / n
    }'
# steps_of PHASE BUDGET OTHER [FILE]: STEPS_AWK over FILE (or stdin); lines other than counts
# go to the file OTHER if not empty
steps_of() {
    awk -v phase="$1" -v budget="$2" -v other="$3" -v opt_refill=$OPT_REFILL -v opt_wait=$OPT_WAIT \
        -v pess_refill=$PESS_REFILL -v pess_wait=$PESS_WAIT "$STEPS_AWK" ${4:+"$4"}
}
# val FILE NAME -> the value of NAME in a STEPS_AWK summary, "-" if it has none
val() { awk -v name="$2" '$1 == name { print $2; found = 1; exit } END { if (!found) print "-" }' "$1"; }

# The functions whose code the profiles attribute to them where -flto inlined it into the
# step (tests/qemu/inline_names.sh): the stages' entry points, so that the per-function and
# per-stage tables name the stage as without link-time optimisation.
export CM_INLINE_NAMES="bs_contact_detect bs_contact_problem bs_pgs_solve bs_contact_apply bs_excitation_step_mean bs_beam_stable"

# run_job N: runs image N under QEMU; leaves $TMP/job-N.scene and .tight (summaries),
# .status (0 or why it failed), .log (the image's output other than counts) and, if
# profiled, .functions-PHASE (profile.sh's table of the phase: whole run or worst step)
run_job() {
    j=$1
    target=$(word "$j" 1) scene=$(word "$j" 2) real=$(word "$j" 3) kind=$(word "$j" 4) elf=$(word "$j" 5)
    base=$TMP/job-$j
    cycles=
    [ "$target" != cortex-m4f ] || cycles=1
    echo "embedded_report: $target $scene $real $kind" >&2
    case $kind in
        *-whole)
            # stream the counts into the summary; the profile (if any) costs ~1.5x the time
            profile=
            ! profiled "$target" "$scene" "$real" "$kind" || profile=profile=$base.profile
            { status=0
              CM_CYCLES=$cycles CM_PROFILE=$profile sh tests/qemu/count.sh "$elf" "$target" 3600 || status=$?
              echo "$status" > "$base.status"; } |
                steps_of scene "$(budget "$target")" "$base.log" > "$base.scene"
            [ "$(cat "$base.status")" -eq 0 ] || return 0
            [ -z "$profile" ] || { sh tests/qemu/profile.sh "$base.profile" "$elf" > "$base.functions-whole"
                                   sh tests/qemu/classes.sh "$base.profile" "$elf" > "$base.classes-whole"; }
            ;;
        *)
            status=0
            CM_CYCLES=$cycles sh tests/qemu/count.sh "$elf" "$target" 600 > "$base.out" || status=$?
            echo "$status" > "$base.status"
            grep -v '^\[insn\] [0-9]' "$base.out" > "$base.log" || :
            [ "$status" -eq 0 ] || return 0
            for phase in scene tight; do
                steps_of $phase "$(budget "$target")" "" "$base.out" > "$base.$phase"
            done
            rm -f "$base.out"
            profiled "$target" "$scene" "$real" "$kind" || return 0
            # the worst step of each phase, per function: a profiled run per phase
            steps=$(val "$base.scene" steps)
            for phase in scene tight; do
                if [ "$phase" = scene ]; then range="first=1,last=$steps"; else range="first=$((steps + 1))"; fi
                CM_PROFILE="profile=$base.profile-$phase,$range" sh tests/qemu/count.sh "$elf" "$target" 600 \
                    > /dev/null || { echo "profiling $phase failed" > "$base.status"; return 0; }
                sh tests/qemu/profile.sh "$base.profile-$phase" "$elf" > "$base.functions-$phase"
            done
            ;;
    esac
}

# Two lanes of jobs, each run in order in the background: the longest jobs first, each
# to the lane with less work so far (work ~ steps; a profiled whole run ~1.5x)
j=1
while [ "$j" -le "$jobs" ]; do
    steps=1
    case $(word "$j" 4) in *-whole)
        steps=$(sed -n 's/^#define BS_SCENE_STEPS \([0-9]*\)u.*/\1/p' "configs/$(word "$j" 2).h") ;;
    esac
    profiled "$(word "$j" 1)" "$(word "$j" 2)" "$(word "$j" 3)" "$(word "$j" 4)" && factor=1.5 || factor=1
    echo "$j $steps $factor"
    j=$((j + 1))
done | sort -k2,2nr | awk '{ lane = load[1] <= load[2] ? 1 : 2; load[lane] += $2 * $3; print $1 > (tmp "/lane-" lane) }' tmp="$TMP"
for lane in 1 2; do
    [ -f "$TMP/lane-$lane" ] || continue
    ( while read -r j; do run_job "$j"; done < "$TMP/lane-$lane" ) &
done
wait

# Stop on the first image that failed: its status, the last lines of its output
j=1
while [ "$j" -le "$jobs" ]; do
    base=$TMP/job-$j
    status=$(cat "$base.status" 2>/dev/null || echo "did not run")
    for phase in scene tight; do
        [ "$status" != 0 ] || [ ! -f "$base.$phase" ] || [ "$(val "$base.$phase" status)" = 0 ] ||
            [ "$(val "$base.$phase" status)" = none ] || status="$phase phase ended with status $(val "$base.$phase" status)"
    done
    if [ "$status" != 0 ]; then
        echo "embedded_report: $(cat "$TMP/spec-$j") failed under QEMU ($status):" >&2
        tail -n 5 "$base.log" >&2 2>/dev/null || :
        exit 1
    fi
    j=$((j + 1))
done

# job TARGET SCENE REAL KIND -> the job's number (empty if none)
job() {
    _k=1
    while [ "$_k" -le "$jobs" ]; do
        [ "$(cut -d: -f1-4 "$TMP/spec-$_k")" != "$1:$2:$3:$4" ] || { echo "$_k"; return; }
        _k=$((_k + 1))
    done
}
# value_of TARGET SCENE REAL KIND PHASE NAME -> one value of a job's summary ("-" if none)
value_of() {
    _j=$(job "$1" "$2" "$3" "$4")
    if [ -n "$_j" ] && [ -f "$TMP/job-$_j.$5" ]; then val "$TMP/job-$_j.$5" "$6"; else echo -; fi
}
# ceil_div A B, per_mhz A MHZ: backlog in samples (rounded up) and in microseconds
ceil_div() { awk -v a="$1" -v b="$2" 'BEGIN { q = int(a / b); if (q * b < a) ++q; print q }'; }
per_mhz() { awk -v a="$1" -v f="$2" 'BEGIN { printf "%.0f", a / f }'; }

# The ram variant must compute what the image with the constants in flash computes: the
# same hash at the end of each phase
j=1
while [ "$j" -le "$jobs" ]; do
    kind=$(word "$j" 4)
    case $kind in *-ram*) ;; *) j=$((j + 1)); continue ;; esac
    twin=$(job "$(word "$j" 1)" "$(word "$j" 2)" "$(word "$j" 3)" "$(echo "$kind" | sed 's/-ram//')")
    for phase in scene tight; do
        [ -n "$twin" ] && [ -f "$TMP/job-$j.$phase" ] || continue
        [ "$(val "$TMP/job-$j.$phase" hash)" = "$(val "$TMP/job-$twin.$phase" hash)" ] || {
            echo "embedded_report: $(cat "$TMP/spec-$j") $phase: hash $(val "$TMP/job-$j.$phase" hash)" \
                 "differs from the flash image's $(val "$TMP/job-$twin.$phase" hash)" >&2
            exit 1
        }
    done
    j=$((j + 1))
done

# --- the profiles: consistency with the counts, then tables ---------------------------
# whole-run profiles: every step profiled, the same worst step, the same total cycles
for scene in fig6 fig6_1mode; do
    j=$(job cortex-m4f $scene float subspace-whole)
    [ -n "$j" ] && [ -f "$TMP/job-$j.functions-whole" ] || continue
    set -- $(head -n 1 "$TMP/job-$j.functions-whole")
    total=$(awk 'NR > 1 { sum += $4 } END { printf "%.0f", sum }' "$TMP/job-$j.functions-whole")
    if [ "$2" != "$(val "$TMP/job-$j.scene" steps)" ] || [ "$5" != "$(val "$TMP/job-$j.scene" worst_insn)" ] ||
       [ "$total" != "$(val "$TMP/job-$j.scene" sum_pess)" ]; then
        echo "embedded_report: $scene whole-run profile ($2 steps, worst $5, $total cycles) disagrees with the counts" \
             "($(val "$TMP/job-$j.scene" steps), $(val "$TMP/job-$j.scene" worst_insn), $(val "$TMP/job-$j.scene" sum_pess))" >&2
        exit 1
    fi
done
# per-phase worst-step profiles: the same worst step as counted
j=1
while [ "$j" -le "$jobs" ]; do
    for phase in scene tight; do
        [ -f "$TMP/job-$j.functions-$phase" ] || continue
        set -- $(head -n 1 "$TMP/job-$j.functions-$phase")
        [ "${5:-}" = "$(val "$TMP/job-$j.$phase" worst_insn)" ] || {
            echo "embedded_report: $(cat "$TMP/spec-$j") $phase: profile's worst step ${5:-?} != counted $(val "$TMP/job-$j.$phase" worst_insn)" >&2
            exit 1
        }
    done
    j=$((j + 1))
done

# --- the targets (issue 27: Cortex-M4F at 168 MHz, float, dt = 2e-5 s, default core) --
# target_row KIND TEXT LIMIT OP FLASH RAM: a row; met if the flash or the ram value meets
# it (a cell may carry more after its number, "N (T µs)": the number is compared)
target_row() {
    awk -v kind="$1" -v text="$2" -v limit="$3" -v op="$4" -v flash="$5" -v ram="$6" 'BEGIN {
        met = 0
        if (flash != "-" && (op == "<" ? flash + 0 < limit + 0 : flash + 0 <= limit + 0)) met = 1
        if (ram != "-" && (op == "<" ? ram + 0 < limit + 0 : ram + 0 <= limit + 0)) met = 1
        printf "| %s | %s | %s %s | %s | %s | %s |\n", kind, text, op == "<" ? "<" : "≤", limit, flash, ram, met ? "yes" : "**no**"
    }'
}
# backlog_cell TARGET SCENE REAL KIND -> "N (M µs)"
backlog_cell() {
    b=$(value_of "$1" "$2" "$3" "$4" scene backlog)
    [ "$b" != - ] || { echo -; return; }
    echo "$(ceil_div "$b" "$(budget "$1")") ($(per_mhz "$b" "$(mhz "$1")") µs)"
}
m4f() { value_of cortex-m4f "$1" float "$2" "$3" "$4"; } # m4f SCENE KIND PHASE NAME
targets="$(target_row required "fig6: mean estimated cycles per step (whole 60 s run)" 1700 "<=" \
              "$(m4f fig6 subspace-whole scene mean_pess)" "$(m4f fig6 subspace-ram-whole scene mean_pess)")
$(target_row required "fig6: largest backlog over the whole run, samples (time)" 64 "<=" \
              "$(backlog_cell cortex-m4f fig6 float subspace-whole)" "$(backlog_cell cortex-m4f fig6 float subspace-ram-whole)")
$(target_row required "fig8: largest backlog over the whole 120 s run, samples (time)" 64 "<=" \
              "$(backlog_cell cortex-m4f fig8 float subspace-whole)" "$(backlog_cell cortex-m4f fig8 float subspace-ram-whole)")
$(target_row "aimed at" "fig6: worst step of the whole run, estimated cycles" 6000 "<=" \
              "$(m4f fig6 subspace-whole scene worst_pess)" "$(m4f fig6 subspace-ram-whole scene worst_pess)")
$(target_row "aimed at" "fig6_1mode: mean estimated cycles per step (whole run)" 1000 "<=" \
              "$(m4f fig6_1mode subspace-whole scene mean_pess)" "$(m4f fig6_1mode subspace-ram-whole scene mean_pess)")
$(target_row "aimed at" "fig6_1mode: worst step of the whole run, estimated cycles" 3000 "<=" \
              "$(m4f fig6_1mode subspace-whole scene worst_pess)" "$(m4f fig6_1mode subspace-ram-whole scene worst_pess)")
$(target_row "aimed at" "Cortex-M7, fig6 in double: worst instructions per step (whole run)" 4800 "<=" \
              "$(value_of cortex-m7 fig6 double subspace-whole scene worst_insn)" -)
$(target_row "reported" "fig6: tight case (every corner and the stop in contact), worst step, estimated cycles" 12000 "<=" \
              "$(m4f fig6 subspace tight worst_pess)" "$(m4f fig6 subspace-ram tight worst_pess)")"
targets_met=$(echo "$targets" | grep '^| required' | grep -c '| yes |$' || :)
targets_all=$(echo "$targets" | grep -c '^| required')
aimed_met=$(echo "$targets" | grep '^| aimed at' | grep -c '| yes |$' || :)
aimed_all=$(echo "$targets" | grep -c '^| aimed at')

# --- whole runs ---------------------------------------------------------------------
# rows in argument order, so that the constants-in-flash row of a scene comes first
# (host/reports/accuracy.sh reads the first M4F float row of a scene: "mean insn/step")
whole_rows=""
j=1
while [ "$j" -le "$jobs" ]; do
    case $(word "$j" 4) in *-whole) ;; *) j=$((j + 1)); continue ;; esac
    target=$(word "$j" 1) s=$TMP/job-$j.scene
    case $(word "$j" 4) in *-ram-*) variant=ram ;; *) variant=flash ;; esac
    if [ "$(val "$s" mean_pess)" = - ]; then unit=" (insn)"; else unit=; fi
    b=$(val "$s" backlog)
    whole_rows="$whole_rows| $(word "$j" 2) | $target | $(word "$j" 3) | $variant | $(val "$s" steps) | $(val "$s" mean_insn) | $(val "$s" worst_insn) | $(val "$s" mean_opt) | $(val "$s" worst_opt) | $(val "$s" mean_pess) | $(val "$s" worst_pess) | $(val "$s" flash) | $(val "$s" contacts) | $(budget "$target") | $(val "$s" over)$unit | $(ceil_div "$b" "$(budget "$target")")$unit | $(per_mhz "$b" "$(mhz "$target")")$unit |
"
    j=$((j + 1))
done

# --- the cost images ----------------------------------------------------------------
rows=""
j=1
while [ "$j" -le "$jobs" ]; do
    kind=$(word "$j" 4)
    case $kind in *-whole | *-O2) j=$((j + 1)); continue ;; esac
    base=$TMP/job-$j
    set -- $(core_sizes "$(word "$j" 5)")
    ram=$4
    [ "$5" -eq 0 ] || ram="$(($4 + $5)) ($4 + $5)"
    stack=$(val "$base.scene" stack) tight_stack=$(val "$base.tight" stack)
    [ "$stack" -gt "$tight_stack" ] || stack=$tight_stack
    build=$(echo "$kind" | sed 's/^subspace/default/; s/-ram$/, ram/')
    rows="$rows| $(word "$j" 2) | $(word "$j" 1) | $(word "$j" 3) | $build | $1 | $(($2 + $3)) | $ram | $stack | $(val "$base.scene" steps) | $(val "$base.scene" mean_insn) | $(val "$base.scene" worst_insn) ($(val "$base.scene" contacts)) | $(val "$base.tight" mean_insn) | $(val "$base.tight" worst_insn) ($(val "$base.tight" contacts)) | $(val "$base.scene" mean_pess) | $(val "$base.scene" worst_pess) | $(val "$base.tight" mean_pess) | $(val "$base.tight" worst_pess) |
"
    j=$((j + 1))
done

# The sweeps build against the default core (M4F float cost images): mean/worst
# instructions of each phase, and whether the first steps (at most two contacts, where
# both builds run the same solve) end in the same state
sweeps_scene="" sweeps_tight="" sweeps_states="the same states (equal hashes): their instruction counts there differ only by
code generation (the compiler inlines the smaller solve differently)"
for scene in fig6 fig6_1mode; do
    for phase in scene tight; do
        cell="$scene $(m4f $scene subspace $phase mean_insn)/$(m4f $scene subspace $phase worst_insn) against"
        cell="$cell $(m4f $scene sweeps $phase mean_insn)/$(m4f $scene sweeps $phase worst_insn)"
        if [ $phase = scene ]; then sweeps_scene="$sweeps_scene${sweeps_scene:+, }$cell"
        else sweeps_tight="$sweeps_tight${sweeps_tight:+, }$cell"; fi
    done
    [ "$(m4f $scene subspace scene hash)" = "$(m4f $scene sweeps scene hash)" ] ||
        sweeps_states="**different states** (the hashes differ)"
done
most_whole=$(j=1; while [ "$j" -le "$jobs" ]; do
    case $(word "$j" 4) in *-whole) val "$TMP/job-$j.scene" contacts ;; esac; j=$((j + 1)); done | sort -n | tail -n 1)

# --- where the cycles go ------------------------------------------------------------
# whole_functions SCENE -> rows: per function, pessimistic cycles and instructions per
# step (mean over the whole run), share of the cycles, instructions in the run's worst step
whole_functions() {
    j=$(job cortex-m4f "$1" float subspace-whole)
    awk -v steps="$(val "$TMP/job-$j.scene" steps)" '
        NR == 1 { next }
        { name[NR] = $1; insn[NR] = $2; worst[NR] = $3; cycles[NR] = $4; total_c += $4; total_i += $2; total_w += $3 }
        END {
            for (i = 2; i <= NR; ++i)
                printf "%015.0f | `%s` | %.1f | %.1f %% | %.1f | %d |\n", cycles[i], name[i], cycles[i] / steps,
                    100 * cycles[i] / total_c, insn[i] / steps, worst[i]
            printf "%015.0f | **the step** | **%.1f** | **100 %%** | **%.1f** | **%d** |\n", -1, total_c / steps,
                total_i / steps, total_w
        }' "$TMP/job-$j.functions-whole" | LC_ALL=C sort -r | sed 's/^[-0-9]* //'
}
# worst_functions SCENE -> rows: instructions per function in the worst step of each
# phase, default core and sweeps build, costliest in the default core's tight step first
worst_functions() {
    for kind in subspace sweeps; do
        j=$(job cortex-m4f "$1" float $kind)
        for phase in scene tight; do
            awk -v column="$kind $phase" 'NR > 1 { print $1, column, $3 }' "$TMP/job-$j.functions-$phase"
        done
    done | awk '
        { count[$1 SUBSEP $2 " " $3] = $4; seen[$1] = 1; total[$2 " " $3] += $4 }
        END {
            split("subspace scene,subspace tight,sweeps scene,sweeps tight", column, ",")
            for (f in seen) {
                line = "| `" f "` |"
                for (c = 1; c <= 4; ++c) line = line " " (count[f SUBSEP column[c]] + 0) " |"
                printf "%012d %s\n", count[f SUBSEP "subspace tight"] + 0, line
            }
            line = "| **the step** |"
            for (c = 1; c <= 4; ++c) line = line " **" total[column[c]] "** |"
            printf "%012d %s\n", -1, line
        }' | LC_ALL=C sort -r | cut -d' ' -f2-
}
# STAGE_AWK: the stage of the step a function of the images belongs to (inlined code
# counts in its caller: the names are those the M4F images keep)
STAGE_AWK='
    function stage_of(f) {
        sub(/[.].*/, "", f) # GCC'"'"'s clones (.constprop.0, .isra.0, .part.0) count as the function
        if (f ~ /^(step|bs_sim_step|bs_sim_step_measured)$/ || f ~ /^bs_(excitation|beam|piezo)_/) return 1
        if (f == "bs_contact_detect" || f ~ /^bs_shape_/) return 2
        if (f == "bs_contact_problem") return 3
        if (f ~ /^bs_pgs_/ || f ~ /^(active_set_solve|residual_of|residual|pointed_mode|breach_size|next_modes?|solve_[a-z_]+)$/) return 4
        if (f == "bs_contact_apply") return 5
        return 6
    }'
STAGE_NAMES="the smooth part (modal forces, excitation, the free positions and velocities)|finding the contacts (corner positions, the beam under each corner, gaps, rows)|the contact problem (free velocities and Delassus matrix from the rows)|the contact solve (the pair by Cramer, active-set systems, sweeps)|applying the percussions to the velocities|harness (the calling loop and the marks)"
# stage_table SCENE -> rows: per stage of the whole run's profile, cycles per step and by
# kind of instruction, the floating-point arithmetic executed, and cycles over its cycles
stage_table() {
    j=$(job cortex-m4f "$1" float subspace-whole)
    awk -v steps="$(val "$TMP/job-$j.scene" steps)" -v names="$STAGE_NAMES" "$STAGE_AWK"'
        {
            k = stage_of($1)
            for (c = 2; c <= 13; ++c) { v[k, c] += $c; v[0, c] += $c }
        }
        END {
            split(names, name, "|")
            for (k = 0; k <= 6; ++k) {
                if (k > 0 && v[k, 8] == 0) continue
                label = k ? name[k] : "**the step**"
                printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %s |\n", label,
                    v[k, 8] / steps, v[k, 3] / steps, v[k, 9] / steps, v[k, 10] / steps, v[k, 11] / steps,
                    v[k, 12] / steps, v[k, 13] / steps, v[k, 2] / steps,
                    (v[k, 9] > 0 ? sprintf("%.1f", v[k, 8] / v[k, 9]) : "-")
            }
        }' "$TMP/job-$j.classes-whole"
}
breakdown=""
for scene in fig6 fig6_1mode; do
    j=$(job cortex-m4f $scene float subspace-whole)
    [ -n "$j" ] && [ -f "$TMP/job-$j.functions-whole" ] || continue
    breakdown="$breakdown
### $scene

The whole 60 s run ($(val "$TMP/job-$j.scene" steps) steps, constants in flash): estimated cycles
(pessimistic) and instructions per step, mean over the run, and the instructions of the run's
worst step ($(val "$TMP/job-$j.scene" worst_insn) instructions), per function.

| function | cycles/step (pessimistic) | share of the cycles | insn/step | worst step of the run: insn |
|---|---|---|---|---|
$(whole_functions $scene)

The worst step of each phase of the cost images (instructions per function), default core
and sweeps build:

| function | default: worst scene step | default: worst tight step | sweeps: worst scene step | sweeps: worst tight step |
|---|---|---|---|---|
$(worst_functions $scene)

By stage of the step and kind of instruction (tests/qemu/classes.sh): estimated cycles per
step (pessimistic, mean over the whole run), the floating-point arithmetic executed (add,
subtract, multiply, divide, square root, negate, convert: what the equations ask for) and its
cycles, the cycles of the rest by kind (loads: data into registers, the return address
too; control: compares, branches, IT blocks, a float compare's flag transfer; other:
integer arithmetic and moves), and the stage's cycles over its arithmetic's cycles: the
distance to the floor.

| stage | cycles/step | FP operations/step | FP cycles | load cycles | store cycles | control cycles | other cycles | instructions/step | cycles / FP cycles |
|---|---|---|---|---|---|---|---|---|---|
$(stage_table $scene)
"
done

# --- optimisation level -------------------------------------------------------------
# The -O2 images -> rows: code, mean, worst and tight worst, each at -O2 and at CM_OPT
level_rows=""
j=1
while [ "$j" -le "$jobs" ]; do
    kind=$(word "$j" 4)
    case $kind in *-O2) ;; *) j=$((j + 1)); continue ;; esac
    solve=${kind%-O2} scene=$(word "$j" 2)
    twin=$(job cortex-m4f "$scene" float "$solve")
    [ -n "$twin" ] || { echo "embedded_report: no image at the default level for $(cat "$TMP/spec-$j")" >&2; exit 1; }
    set -- $(core_sizes "$(word "$j" 5)")
    code_o2=$1
    set -- $(core_sizes "$(word "$twin" 5)")
    level_rows="$level_rows$(awk -v scene="$scene" -v solve="$solve" -v a="$code_o2 $(val "$TMP/job-$j.scene" mean_insn) $(val "$TMP/job-$j.scene" worst_insn) $(val "$TMP/job-$j.tight" worst_insn)" \
        -v b="$1 $(val "$TMP/job-$twin.scene" mean_insn) $(val "$TMP/job-$twin.scene" worst_insn) $(val "$TMP/job-$twin.tight" worst_insn)" 'BEGIN {
        split(a, x, " "); split(b, y, " ")
        printf "| %s | cortex-m4f | %s | %d | %d | %d | %d | %d | %d | %d | %d | %.2f |\n", scene, solve == "subspace" ? "default" : solve,
            x[1], y[1], x[2], y[2], x[3], y[3], x[4], y[4], x[4] / y[4] }')
"
    j=$((j + 1))
done
# Core code of the scenes that leave something out, as a share of fig6's (default core)
leaner=$(echo "$level_rows" | awk -F'|' '{ for (i = 2; i <= 6; ++i) gsub(/ /, "", $i) }
    $4 == "default" { o2[$2] = $5; high[$2] = $6; if ($2 != "fig6") order[++n] = $2 }
    END {
        if (!o2["fig6"]) exit
        for (i = 1; i <= n; ++i)
            printf "%s%s %.0f %% at -O2 and %.0f %% at the default level", (i > 1 ? "; " : ""), order[i],
                100 * o2[order[i]] / o2["fig6"], 100 * high[order[i]] / high["fig6"]
    }')

# --- the page -----------------------------------------------------------------------
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- core port configs tests/embedded 2>/dev/null ||
    commit="$commit with uncommitted changes to the measured sources"
fig6_flash_reads=$(m4f fig6 subspace-whole scene flash)
fig6_ram_reads=$(m4f fig6 subspace-ram-whole scene flash)
# the last section, "Twin firmware", is host/reports/twin_firmware_report.sh's: kept as it is
twin_section=$(sed -n '/^## Twin firmware$/,$p' "$OUT" 2>/dev/null || :)
cat > "$OUT" <<EOF
# The core on Cortex-M

$stamp

Produced by \`make embedded-report\` (host/reports/embedded_report.sh) on $(date -u +%Y-%m-%d), commit $commit,
with $(arm-none-eabi-gcc --version | head -n 1) (\`$CM_OPT\`, \`-std=c99\`, no fused multiply-add) and
$(qemu-system-arm --version | head -n 1) with the counting plugin tests/qemu/insn-plugin (instruction
counts exact; Cortex-M4 cycles estimated, next section). Each image is tests/embedded/scene_run.c with
the core compiled against one scene (configs/NAME.h, \`beamslider gen\`) and the generic embedded
port (port/embedded); the script's header says what each column measures. Every count is per
step of the simulation and includes about 10 instructions of harness (the call through a
volatile pointer and the two marks around it).

## Targets

The targets of the step's redesign (issue 27): Cortex-M4F at 168 MHz, float, dt = 2e-5 s (a
budget of 3360 cycles per step), the default core; a Cortex-M7 at 480 MHz in double. M4F
values are the pessimistic cycle estimate (below): "flash" with the scene's constants in
flash as a firmware keeps them, "ram" with the scene copied to RAM (or CCM) at start-up and
the literal pools replaced by MOVW/MOVT (\`-mslow-flash-data\`). A target is met when either
estimate meets it. The Cortex-M7 has no public per-instruction timing: its row counts
instructions. Met: $targets_met of the $targets_all required targets, $aimed_met of the $aimed_all aimed at; the tight
case is reported beside its old target. Where the cycles go, against the arithmetic the step
executes, is the section "Where the cycles go"; the twin firmware's targets are in "Twin
firmware".

| kind | target | limit | flash | ram | met |
|---|---|---|---|---|---|
$targets

## The cycle model

The counting plugin estimates Cortex-M4 cycles from the instructions it executes
(tests/qemu/insn-plugin/insncount.c, "Cycle model"). What it counts:

- each instruction's base cycles from the Cortex-M4 Technical Reference Manual's timing
  tables: 1 for data processing, single-precision add, multiply, compare, convert and move,
  2 for a single load or store and MLA/MLS, 3 for LDRD/STRD and the FPU's multiply-accumulate,
  1 + N for a load or store multiple of N words, 14 for VDIV and VSQRT, 12 for SDIV/UDIV (the
  manual gives 2 to 12: the early exit is not modelled);
- each branch taken (a branch, or a load into the PC, after which execution does not fall
  through) costs a pipeline refill of P cycles more: P = 1 in the optimistic estimate, P = 3
  in the pessimistic one (the manual's range);
- each data read from flash costs W wait states more: W = 0 in the optimistic estimate,
  W = 5 in the pessimistic one (168 MHz on a typical flash, every read of constant data:
  the scene's modal data and shape table, literal pools, switch tables). Reads are counted
  per memory access to the code region (the first 4 MiB, where the images keep code and
  constants; RAM is elsewhere).

Left out, so the estimate is not a measurement: load and store pipelining (neighbouring
loads or stores can take 1 cycle each instead of 2: the base cycles are an upper bound
there); FPU result latencies and register dependencies; bus contention between fetches and
data reads; instruction fetch wait states (assumed hidden by the flash accelerator's cache,
the ART of an STM32F4, which holds the hot loop; a cache miss costs more); any data cache in
front of the flash (the pessimistic W is then the upper end). QEMU executes the code exactly,
so the instruction counts and the numbers C, T and F the estimate is built from are exact and
deterministic; the error is in the weights. Measure on the board (DWT_CYCCNT) before relying
on a margin of a few percent. The Cortex-M7 (dual issue, branch prediction, caches) has no
public per-instruction timing: its cycles are not estimated, and its rows give instructions
only (where a backlog needs a cost, instructions stand in for cycles, marked "(insn)").

## Whole runs

Every step of the scene's run from t = 0 to t_end (fig6 and fig6_1mode: 60 s, 3 000 000
steps: the drift to the clamp, the jump and the walk back; fig8: 120 s, 6 000 000 steps of
relaxation cycles, many jumps), default core, on the boards of the targets. Cycles are the
two estimates; "flash reads" the data reads from flash per step (mean), which the ram variant
removes (fig6: $fig6_flash_reads per step in flash, $fig6_ram_reads in ram). Steps over budget and the
largest backlog use the pessimistic estimate: the backlog is the delay of a twin that reads
one sample per dt from a FIFO (Lindley recursion, script header), in samples (rounded up) and
microseconds; it stays bounded when the mean is under the budget and the worst stretches are
short.

| scene | target | real | variant | steps | mean insn/step | worst insn/step | mean cycles: optimistic | worst cycles: optimistic | mean cycles: pessimistic | worst cycles: pessimistic | flash reads/step | most contacts | cycle budget | steps over budget | largest backlog [samples] | largest backlog [µs] |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
$whole_rows
No whole run of the sweeps build (\`-DBS_WITH_SUBSPACE=0\`): both builds solve one and two
contacts alike (core/src/bs_pgs.c: the pair exactly, by its active-set systems); the sweeps
build leaves the active-set step out only where three or more contacts are active at once,
which these runs never have (most contacts at once over all of them: $most_whole). In the cost
images' first steps (at most two contacts) the two builds reach $sweeps_states; mean/worst
instructions there, default against sweeps: $sweeps_scene. The tight phase, five contacts,
is where they differ: $sweeps_tight.

## Per image

Each cost image runs two phases. "scene": the first steps of the scene from its start
(20 000 steps on the FPU targets, 2 000 on the M3 and M0+: settling, impacts and contact with
one or two corners). "tight": a quarter as many steps with every corner and the clamp stop in
contact (the slot pushed 2 um into the beam; the contact solve's worst case). Constants are
the core's read-only data and the scene (mode-shape table, modal data), in flash; RAM is the
bs_sim, plus the scene's copy in the ram variant ("ram": \`-DBS_RUN_SCENE_IN_RAM=1
-mslow-flash-data\`, the same states as with the constants in flash, bit for bit: the
script compares the hashes, here and in the whole runs). The M3 and M0+ have no FPU and compute float
in software (libgcc), hence the large counts. "sweeps" is the core built with
\`-DBS_WITH_SUBSPACE=0\`. Cycles (pessimistic estimate) on the M4F only.

| scene | target | real | build | core code [B] | constants [B] | RAM [B] | stack [B] | steps counted | mean insn/step | worst insn/step (contacts) | tight: mean insn | tight: worst insn (contacts) | mean cycles | worst cycles | tight: mean cycles | tight: worst cycles |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
$rows
## Where the cycles go (Cortex-M4F, float)

Per function (tests/qemu/profile.sh on profiles from the same plugin; code inlined into a
function counts there). The script checks that the whole-run profile's total equals the
counted cycles and that each profile's worst step equals the counted worst step.
$breakdown
## Optimisation level

The same images built at -O2 instead of \`$CM_OPT\` (every other image of this report):
core code in bytes and instructions per step (scene: mean and worst; tight: worst). The
loops over modes and contact rows have lengths fixed by the compiled scene, which the
higher level unrolls; the last column is the tight worst step at -O2 over the default.

Core code of the scenes that leave something out, as a share of fig6's (default core):
$leaner.
Where a share is above 100 %, unrolling the leaner scene's loops at the higher level adds
more code than its switches removed.

| scene | target | build | code: -O2 | code: default | mean: -O2 | mean: default | worst: -O2 | worst: default | tight worst: -O2 | tight worst: default | tight worst -O2 / default |
|---|---|---|---|---|---|---|---|---|---|---|---|
$level_rows
EOF
[ -z "$twin_section" ] || printf '\n%s\n' "$twin_section" >> "$OUT"
echo "embedded_report: wrote $OUT" >&2
