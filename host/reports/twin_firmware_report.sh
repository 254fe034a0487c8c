#!/bin/sh
# twin_firmware_report.sh CSV TARGET:SCENE:VARIANT:ELF[:DT]... - the cost of the twin
# firmware (port/cortex-m/twin) on a whole recorded plant run under QEMU, written as the
# section "Twin firmware" of docs/embedded.md (replacing it, or appended). Run through
# `make twin-firmware-report` (tests/embedded/twin.mk builds the images and the stream;
# about 10 minutes on 2 cores). CSV is the plant run the images' stream was made from
# (its last row's s_true: the plant's s at the end). DT: the image's sample period, 2e-5 s
# when not given; the fig6_fast images (the coarser step of docs/design.md 4) run on
# their own stream, whose plant run is fast-60s.csv beside CSV.
#
# Each image is the firmware built with TWIN_COST=1: the simulated clock runs the
# producer once per twin step (one sample per step, never a queue: the images measure,
# the queue is computed here), and every producer call and every observer step is
# bracketed by bs_board_mark(). VARIANT: flash (constants in flash) or ram (scene and
# gains copied to RAM, -mslow-flash-data). Per image, from tests/qemu/count.sh (Cortex-M4F
# with the cycle estimate, CM_CYCLES=1):
#   twin step   the bracket of bs_observer_step (the twin's step and the observer's
#               correction): instructions, estimated cycles optimistic (P = 1, W = 0) and
#               pessimistic (P = 3, W = 5), as docs/embedded.md, "The cycle model"
#   producer    the bracket of twin_produce (one sample into the FIFO; a block from the
#               source every TWIN_BLOCK_SAMPLES, over semihosting: its bkpt costs nothing)
#   per sample  everything the firmware executes from one twin step's end to the next
#               (producer, FIFO pop, bookkeeping, the 10 Hz report's printf), plus 24
#               cycles for the SysTick exception's entry and return (12 each, Cortex-M4
#               TRM), which the simulated clock's function call does not have
#   backlog     of samples waiting in the FIFO at clock f: the Lindley recursion
#               W = max(0, W + c_k - B), c_k the per-sample cost (pessimistic; on the M7,
#               without a cycle model, instructions), B = f x dt; largest W as ceil(W / B)
#               samples, and the first sample at which it exceeds TWIN_FIFO_SAMPLES (the
#               firmware's FIFO: from there on the overrun policy drops samples)
#   observer    the M4F fig6 flash image profiled (count.sh with CM_PROFILE, then
#               tests/qemu/classes.sh): estimated cycles per sample of the observer's own
#               code (core/src/bs_observer.c: bs_observer_*, what it inlines), of the twin's
#               step and of the rest of the firmware, each by kind of instruction
#   memory      from the image's map and symbols: code of the core and of the firmware,
#               constants (the scene, the gains), RAM of each static object, the image's
#               totals (arm-none-eabi-size; newlib's printf is most of the rest), and the
#               deepest stack of the main loop (painted; the 10 Hz printf excluded)
# Env: CM_OPT, CM_BUILD (from make), TWIN_FIFO_SAMPLES (1024), OUT (docs/embedded.md).
set -eu
: "${CM_OPT:?twin_firmware_report: CM_OPT unset (run it through make twin-firmware-report)}"
OUT=${OUT:-docs/embedded.md}
FIFO=${TWIN_FIFO_SAMPLES:-1024}
csv=$1
shift
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# the section's stamp (host/reports/provenance.sh): the sources of the images and the flags
. host/reports/provenance.sh
stamp=$(provenance_stamp "make twin-firmware-report" twin-firmware)
sh tests/qemu/build-plugin.sh >&2

DT=0.00002                      # the stream's sample period [s] (fig6)
CLOCKS="168 200 240 280 320 360 400 480" # M4F clocks of the backlog table [MHz]
ENTRY=24                        # SysTick entry + return [cycles]

val() { awk -v name="$2" '$1 == name { sub(/^[^ ]+ /, ""); print; found = 1; exit } END { if (!found) print "-" }' "$1"; }

# symbol_size ELF NAME -> bytes (0 if absent)
symbol_size() {
    arm-none-eabi-nm -S --radix=d "$1" | awk -v name="$2" '$4 == name { print $2 + 0; found = 1; exit }
        END { if (!found) print 0 }'
}
# sizes ELF -> "core_code twin_code scene gains": code generated from the core and from
# the firmware's own files (code_bytes.sh: by source line, what -flto inlines across them
# counted where it came from), constants of the scene and the gains (their symbols: the
# images are built without -fdata-sections, so the link map has no section of their own)
sizes() {
    echo "$(sh host/reports/code_bytes.sh "$1" /core/src/) $(sh host/reports/code_bytes.sh "$1" /twin/twin_)" \
        "$(symbol_size "$1" bs_compiled_scene) $(symbol_size "$1" twin_gains)"
}

n=0
for spec in "$@"; do
    n=$((n + 1))
    echo "$spec" > "$TMP/spec-$n"
done
word() { cut -d: -f"$2" "$TMP/spec-$1"; }
dt_of() { _d=$(word "$1" 5); echo "${_d:-$DT}"; } # dt_of JOB: its sample period [s]
# The twin's step inlined by -flto into the observer's sample counts as the step's
# (tests/qemu/inline_names.sh; share_rows below)
export CM_INLINE_NAMES="bs_step_measured bs_sim_step bs_sim_step_measured"
run_job() {
    j=$1 target=$(word "$1" 1) elf=$(word "$1" 4)
    echo "twin_firmware_report: $target $(word "$1" 2) $(word "$1" 3)" >&2
    if [ "$target" = cortex-m4f ]; then cycles=1 mhz=168; else cycles= mhz=480; fi
    # the five-mode twin on the M4F with its constants in flash: profiled, so that the
    # observer's share can be told from the step's (~1.5x the time)
    profile=
    [ "$target:$(word "$1" 2):$(word "$1" 3)" != cortex-m4f:fig6:flash ] || profile=profile=$TMP/job-$j.profile
    # the count streamed into its summary, "NAME VALUE" lines (tests/qemu/twin_samples.awk)
    { status=0
      CM_CYCLES=$cycles CM_PROFILE=$profile sh tests/qemu/count.sh "$elf" "$target" 3600 || status=$?
      echo "$status" > "$TMP/job-$j.status"; } |
        awk -v clocks="$CLOCKS" -v dt="$(dt_of "$1")" -v entry=$ENTRY -v fifo="$FIFO" -v cycles="${cycles:-0}" -v mhz=$mhz \
            -v logfile="$TMP/job-$j.log" -f tests/qemu/twin_samples.awk > "$TMP/job-$j.sum" || :
    [ -z "$profile" ] || [ "$(cat "$TMP/job-$j.status")" != 0 ] ||
        sh tests/qemu/classes.sh "$TMP/job-$j.profile" "$elf" > "$TMP/job-$j.classes"
}
# two lanes, the M7 (no cycle estimate: faster) with the shorter one
j=1
while [ "$j" -le "$n" ]; do echo "$j" >> "$TMP/lane-$((j % 2 + 1))"; j=$((j + 1)); done
for lane in 1 2; do
    [ -f "$TMP/lane-$lane" ] || continue
    ( while read -r j; do run_job "$j"; done < "$TMP/lane-$lane" ) &
done
wait
j=1
while [ "$j" -le "$n" ]; do
    if [ "$(cat "$TMP/job-$j.status" 2>/dev/null)" != 0 ] || [ "$(val "$TMP/job-$j.sum" status)" != 0 ]; then
        echo "twin_firmware_report: $(cat "$TMP/spec-$j") failed:" >&2
        tail -n 5 "$TMP/job-$j.log" >&2 2>/dev/null || :
        exit 1
    fi
    j=$((j + 1))
done

job() { # job TARGET SCENE VARIANT -> number
    _k=1
    while [ "$_k" -le "$n" ]; do
        [ "$(cut -d: -f1-3 "$TMP/spec-$_k")" != "$1:$2:$3" ] || { echo "$_k"; return; }
        _k=$((_k + 1))
    done
}
# The constants in RAM change the cost, not the results: the same end state
j=1
while [ "$j" -le "$n" ]; do
    if [ "$(word "$j" 3)" = ram ]; then
        twin=$(job "$(word "$j" 1)" "$(word "$j" 2)" flash)
        [ -z "$twin" ] || [ "$(val "$TMP/job-$j.sum" hash)" = "$(val "$TMP/job-$twin.sum" hash)" ] || {
            echo "twin_firmware_report: $(cat "$TMP/spec-$j") ends in another state than its flash variant" >&2
            exit 1
        }
    fi
    j=$((j + 1))
done

# --- tables ---------------------------------------------------------------------
s_plant=$(tail -n 1 "$csv" | cut -d, -f4)
cost_rows="" memory_rows="" backlog_rows=""
j=1
while [ "$j" -le "$n" ]; do
    target=$(word "$j" 1) scene=$(word "$j" 2) variant=$(word "$j" 3) elf=$(word "$j" 4) s=$TMP/job-$j.sum dt=$(dt_of "$j")
    if [ "$target" = cortex-m4f ]; then unit= mhz=168; else unit=" (insn)" mhz=480; fi
    budget=$(awk -v m=$mhz -v d="$dt" 'BEGIN { printf "%.0f", m * d * 1e6 }')
    cost_rows="$cost_rows| $scene | $target | $variant | $(val "$s" samples) | $(val "$s" step_insn) | $(val "$s" step_worst_insn) | $(val "$s" step_opt) | $(val "$s" step_worst_opt) | $(val "$s" step_pess) | $(val "$s" step_worst_pess) | $(val "$s" producer_insn) | $(val "$s" producer_pess) | $(val "$s" sample_insn) | $(val "$s" sample)$unit | $budget | $(val "$s" over) | $(val "$s" backlog_$mhz) ($(val "$s" backlog_time_$mhz)) | $(awk -v k="$(val "$s" overflow)" -v dt="$dt" 'BEGIN { if (k > 0) printf "%.3f s", k * dt; else print "never" }') | $(val "$s" s) |
"
    set -- $(sizes "$elf")
    ram_copy=$(( $(symbol_size "$elf" scene_in_ram) + $(symbol_size "$elf" gains_in_ram) ))
    set -- "$@" $(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" || $1 == ".ARM.exidx" { flash += $2 } $1 == ".data" { flash += $2; ram += $2 } $1 == ".bss" { ram += $2 } END { print flash, ram }')
    memory_rows="$memory_rows| $scene | $target | $variant | $1 | $2 | $3 | $4 | $(symbol_size "$elf" twin) | $(symbol_size "$elf" obs) | $(symbol_size "$elf" fifo) | $(symbol_size "$elf" block) | $ram_copy | $5 | $6 | $(val "$s" stack) |
"
    if [ "$target" = cortex-m4f ] && [ "$dt" = "$DT" ]; then # the clocks' budgets are for 2e-5 s
        row="| $scene | $variant |"
        for c in $CLOCKS; do row="$row $(val "$s" backlog_$c) |"; done
        backlog_rows="$backlog_rows$row
"
    fi
    j=$((j + 1))
done
# The observer's share (the profiled image): per sample, by part of the firmware and kind
# of instruction -> rows "| part | cycles | FP ops | FP cycles | load | store | control | other | insn |"
share_rows() {
    awk -v samples="$2" '
        function part_of(f) {
            sub(/[.].*/, "", f) # GCC'"'"'s clones (.constprop.0, .isra.0, .part.0) count as the function
            if (f ~ /^bs_observer_/ || f ~ /^(observe|correct_position|estimate_position|move_slider|demodulate|transfer|complex_div|angle_of|invert_map|matching_map|gains_at|correction_of|commit_correction|beyond_gate|twin_signal|twin_power|mean|add_compensated)$/) return 1
            if (f ~ /^(step|bs_sim_step|bs_sim_step_measured|bs_step_measured)$/ || f ~ /^bs_(excitation|beam|piezo|contact|pgs|shape)_/ ||
                f ~ /^(active_set_solve|residual_of|residual|pointed_mode|breach_size|next_modes?|solve_[a-z_]+)$/) return 2
            return 3
        }
        { k = part_of($1); for (c = 2; c <= 13; ++c) { v[k, c] += $c; v[0, c] += $c } }
        END {
            split("the observer'"'"'s correction (core/src/bs_observer.c)|the twin'"'"'s step|the rest within the brackets (the producer, the marks, the firmware'"'"'s own code around the step'"'"'s call)", name, "|")
            for (k = 1; k <= 3; ++k)
                printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", name[k], v[k, 8] / samples,
                    v[k, 3] / samples, v[k, 9] / samples, v[k, 10] / samples, v[k, 11] / samples, v[k, 12] / samples,
                    v[k, 13] / samples, v[k, 2] / samples
            printf "| the rest, outside the brackets (main loop, FIFO pop, bookkeeping, the simulated clock, the 10 Hz report, the stack measurement), and SysTick'"'"'s entry | %.0f | - | - | - | - | - | - | %.0f |\n",
                per_sample - v[0, 8] / samples, per_sample_insn - v[0, 2] / samples
            printf "| **per sample** | **%.0f** | | | | | | | %.0f |\n", per_sample, per_sample_insn
        }' per_sample="$3" per_sample_insn="$4" "$1"
}
clock_head="| scene | variant |" clock_rule="|---|---|"
for c in $CLOCKS; do clock_head="$clock_head $c MHz ($((c * 20)) cycles) |"; clock_rule="$clock_rule---|"; done

fig6=$TMP/job-$(job cortex-m4f fig6 flash).sum
fig6ram=$TMP/job-$(job cortex-m4f fig6 ram).sum
one=$TMP/job-$(job cortex-m4f fig6_1mode ram).sum
share_table=$(share_rows "$TMP/job-$(job cortex-m4f fig6 flash).classes" "$(val "$fig6" samples)" "$(val "$fig6" sample)" \
    "$(val "$fig6" sample_insn)") && [ "$(printf '%s\n' "$share_table" | wc -l)" -eq 5 ] || {
    echo "twin_firmware_report: the share table of the profiled image failed" >&2; exit 1; }
# share_of PART -> the part's cycles per sample (share_table's second column)
share_of() { printf '%s\n' "$share_table" | awk -F'|' -v k="$1" 'NR == k { gsub(/ /, "", $3); print $3 }'; }
# target_row TEXT LIMIT FLASH RAM -> a row, met if either value is within the limit
target_row() {
    awk -v text="$1" -v limit="$2" -v flash="$3" -v ram="$4" 'BEGIN {
        met = (flash != "-" && flash + 0 <= limit + 0) || (ram != "-" && ram + 0 <= limit + 0)
        printf "| %s | ≤ %s | %s | %s | %s |\n", text, limit, flash, ram, met ? "yes" : "**no**" }'
}
target_rows="$(target_row "fig6 twin with the observer: mean estimated cycles per sample (whole stream)" 2700 \
                  "$(val "$fig6" sample)" "$(val "$fig6ram" sample)")
$(target_row "fig6 twin: largest backlog over the whole stream, samples" "$FIFO (the FIFO)" \
                  "$(val "$fig6" backlog_168)" "$(val "$fig6ram" backlog_168)")"
# full_at SUMMARY -> when the FIFO is first full at 168 MHz
full_at() { awk -v k="$(val "$1" overflow)" -v dt=$DT 'BEGIN { printf "%.3f s", k * dt }'; }
flash_fits=$([ "$(val "$fig6" backlog_168)" -le "$FIFO" ] && echo 1 || echo 0)
ram_fits=$([ "$(val "$fig6ram" backlog_168)" -le "$FIFO" ] && echo 1 || echo 0)
case $flash_fits$ram_fits in
11) verdict="It keeps pace on the 168 MHz M4F."
    fifo_text="both within the FIFO of $FIFO samples: no sample is dropped." ;;
01) verdict="It keeps pace on the 168 MHz M4F with its constants in RAM, not in flash."
    fifo_text="within the FIFO of $FIFO samples in RAM (no sample is dropped), beyond it in flash (full at $(full_at "$fig6"))." ;;
10) verdict="It keeps pace on the 168 MHz M4F with its constants in flash, not in RAM."
    fifo_text="within the FIFO of $FIFO samples in flash (no sample is dropped), beyond it in RAM (full at $(full_at "$fig6ram"))." ;;
*)  verdict="Not in real time on the 168 MHz M4F."
    fifo_text="beyond the FIFO of $FIFO samples (full at $(full_at "$fig6") in flash)." ;;
esac
# the slowest listed clock at which a variant's largest backlog fits the FIFO
fits() {
    for c in $CLOCKS; do
        [ "$(val "$1" backlog_$c)" -gt "$FIFO" ] || { echo "$c MHz"; return; }
    done
    echo "none of the clocks listed"
}
# the coarser step's paragraph (its images, when listed)
fast_text=""
fast=$(job cortex-m4f fig6_fast flash) fastram=$(job cortex-m4f fig6_fast ram)
if [ -n "$fast" ] && [ -n "$fastram" ]; then
    fast_dt=$(dt_of "$fast")
    fast_budget=$(awk -v d="$fast_dt" 'BEGIN { printf "%.0f", 168 * d * 1e6 }')
    fast_csv=$(dirname "$csv")/fast-60s.csv
    f=$TMP/job-$fast.sum fr=$TMP/job-$fastram.sum
    if [ "$(val "$f" backlog_168)" -le "$FIFO" ] || [ "$(val "$fr" backlog_168)" -le "$FIFO" ]; then
        fast_verdict="it keeps pace on the 168 MHz M4F"
    else
        fast_verdict="it does not keep pace on the 168 MHz M4F"
    fi
    fast_text="**At the coarser step** (fig6 with dt = $fast_dt s, a stream of $(awk -v d="$fast_dt" 'BEGIN { printf "%.0f", 1 / d }') samples a second, and
prewarped modal frequencies: docs/design.md 4, \"Prewarped frequencies\", compares its slow dynamics
with the default step's and the converged model's) the same firmware, on a 60 s stream of that scene as
the plant (\`beamslider twin-plant\`, as above; the plant's s at 60 s: $(tail -n 1 "$fast_csv" | cut -d, -f4)),
takes $(val "$f" sample) estimated cycles per sample (flash) and $(val "$fr" sample) (RAM) against the
$fast_budget of a sample period at 168 MHz; $(val "$f" over) and $(val "$fr" over) of its samples are over that budget,
and the largest backlog over the stream is $(val "$f" backlog_168) samples ($(val "$f" backlog_time_168)) in flash and
$(val "$fr" backlog_168) ($(val "$fr" backlog_time_168)) in RAM: $fast_verdict.
"
fi
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- core port configs tests/embedded 2>/dev/null ||
    commit="$commit with uncommitted changes to the measured sources"

cat > "$TMP/section" <<EOF
## Twin firmware

$stamp

Produced by \`make twin-firmware-report\` (host/reports/twin_firmware_report.sh; also run by
\`make embedded-report\`) on $(date -u +%Y-%m-%d), commit $commit, with the same compiler,
\`$CM_OPT\` and QEMU as above. The firmware is port/cortex-m/twin (its README: what it does, the
producer, the overrun policy): a float twin of the compiled scene and the observer
(core/include/bs_observer.h) with the constants of \`beamslider twin-gains\`, fed one sample per
dt through a FIFO of $FIFO samples. The stream: fig6's whole 60 s run as the plant
(\`beamslider twin-plant configs/fig6.ini --snr 40 --bits 12 --seed 1\`, float build;
3 000 000 samples), read over semihosting. The fig6_1mode twin runs on the same stream (the
plant has five modes, the twin one). The images measure: one sample per twin step, never a
queue; the queue a real-time producer would build is computed from the measured costs
(Lindley recursion, script header). Cycles are the estimates of "The cycle model" above; the M7
row gives instructions, which stand in for cycles in its backlog (480 MHz, budget 9600).

**Cost per sample** at dt = 2e-5 s (fig6_fast: the coarser step below). "Twin step": the bracket around \`bs_observer_step\` (the
twin's step and the observer's correction). "Producer": the bracket around \`twin_produce\`
(the interrupt's work). "Per sample": all the firmware executes per sample (producer, FIFO,
bookkeeping, the simulated clock that stands in for the interrupt, the 10 Hz report and, in these
images only, the stack measurement after each report: a window of 4 KiB painted again, a few
cycles a sample), plus 24 cycles of SysTick entry and return. The firmware does not measure the
solve's residual, which it does not report (its README, "Start-up"). Budget: the cycles
(M7: instructions) of a sample period at 168 MHz (M7: 480 MHz). Samples over budget,
the largest backlog and the first FIFO overflow at 168 MHz (M7: 480 MHz), from the per-sample
cost (pessimistic). Last column: the twin's s at 60 s (the plant's: $s_plant; the ram variants
end in the same state as the flash ones, bit for bit, which the script checks).

| twin scene | target | constants | samples | twin step: mean insn | worst insn | mean cycles: optimistic | worst: optimistic | mean cycles: pessimistic | worst: pessimistic | producer: mean insn | producer: mean cycles (pess.) | per sample: mean insn | per sample: mean cycles (pess.) | budget | samples over budget | largest backlog [samples] | FIFO of $FIFO full at | s at 60 s |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
$cost_rows
**Targets** (issue 27; Cortex-M4F at 168 MHz, pessimistic estimate, the five-mode twin on the
fig6 stream; met when the flash or the ram variant meets it):

| target | limit | flash | ram | met |
|---|---|---|---|---|
$target_rows

**$verdict** The twin step takes $(val "$fig6" step_pess) estimated cycles per sample on average
(pessimistic, constants in flash; $(val "$fig6" step_opt) optimistic) where a sample period has 3360:
the fig6 step (its whole-run mean is in "Whole runs" above) plus the observer's correction, on a
twin that follows the plant. The whole firmware takes $(val "$fig6" sample) per sample (flash) and $(val "$fig6ram" sample)
(ram); the largest backlog over the whole stream is $(val "$fig6" backlog_168) samples ($(val "$fig6" backlog_time_168)) in flash and
$(val "$fig6ram" backlog_168) ($(val "$fig6ram" backlog_time_168)) in RAM, $fifo_text Where the
overrun policy would take over (samples dropped and counted, the twin stepped through each gap
without measurement: port/cortex-m/twin/README.md, "Overrun policy"; \`make test\` runs it at a
stated $(sed -n 's/^TWIN_OVERLOAD_CYCLES := //p' tests/embedded/twin.mk) cycles per step), the table below gives the clock that keeps the backlog within the FIFO:
the largest backlog over the whole stream against the clock of an M4-class core (the same cycle
estimate; clock x dt cycles per sample):

$clock_head
$clock_rule
$backlog_rows
The backlog fits the FIFO from $(fits "$fig6") with the five-mode twin (constants in flash),
$(fits "$fig6ram") with its constants in RAM, and from $(fits "$one") with the one-mode twin in RAM.
The one-mode twin is another model, not only a cheaper one: on the five-mode plant its s ends
$(awk -v a="$(val "$one" s)" -v b="$s_plant" 'BEGIN { d = a - b; printf "%.3f", d < 0 ? -d : d }') from the plant's, the five-mode twin's
$(awk -v a="$(val "$fig6" s)" -v b="$s_plant" 'BEGIN { d = a - b; printf "%.4f", d < 0 ? -d : d }'). A 480 MHz Cortex-M7 runs the
fig6 twin in $(val "$TMP/job-$(job cortex-m7 fig6 flash).sum" sample) instructions per sample against 9600 cycles.

$fast_text
**Where a sample's cycles go** (the five-mode twin, constants in flash, profiled over the whole
stream; tests/qemu/classes.sh): estimated cycles per sample (pessimistic), the floating-point
arithmetic executed and its cycles, and the rest by kind of instruction, as in "Where the cycles
go" above. The observer's correction is $(share_of 1) cycles per sample, the twin's step
$(share_of 2).

| part | cycles/sample | FP operations/sample | FP cycles | load cycles | store cycles | control cycles | other cycles | instructions/sample |
|---|---|---|---|---|---|---|---|---|
$share_table

**Memory** (bytes). Code: .text of the core and of the firmware's files (port/cortex-m/twin);
constants: the scene and the gains in flash; RAM: the twin (\`bs_sim\`), the observer (three
delay lines of 257 values), the FIFO ($FIFO samples of 12 bytes), the producer's block, the
copies of scene and gains in the ram variant; the image's totals include newlib (printf with
floats, semihosting), which a product replaces. Stack: the deepest use of the main loop
(the twin step and the producer, called from it; the 10 Hz printf excluded), to which an
interrupt adds its exception frame (104 bytes with the FPU's lazy context).

| twin scene | target | constants | core code | firmware code | scene | gains | twin (bs_sim) | observer | FIFO | block | scene + gains in RAM | image flash | image RAM (.data + .bss) | stack |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
$memory_rows
EOF

# Replace the section (from its heading to the next "## " or the end) or append it
awk -v section="$TMP/section" '
    /^## Twin firmware$/ { skip = 1; while ((getline line < section) > 0) print line; done = 1; next }
    skip && /^## / { skip = 0 }
    !skip { print }
    END { if (!done) { print ""; while ((getline line < section) > 0) print line } }' "$OUT" > "$TMP/page"
cp "$TMP/page" "$OUT"
echo "twin_firmware_report: wrote the section \"Twin firmware\" of $OUT" >&2
