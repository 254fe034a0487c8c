#!/bin/sh
# bench.sh - the host's speed: steps per second of the fig6 scenes (five modes and
# one mode) in float and double, this tree against an earlier commit (BENCH_BASELINE,
# default 2326ca8: 0.7.0, before the step's redesign), and the sweeps of Fig. 1b.
# Writes docs/performance.md. Run through `make bench`.
#
# The comparison is paired: for each scene and precision the two builds' complete 60 s
# runs (`beamslider run configs/SCENE.ini`, the run-time-scene path) alternate, this
# tree's then the baseline's, RUNS times, one process at a time pinned to one core, and
# each run's CPU time (user + sys of the child, from the shell's `times`) is taken; the
# speed-up is the median over the pairs of baseline CPU / this CPU, with the range of
# the pairs. Pairing keeps the ratio meaningful when the machine's speed drifts (it is
# shared); the absolute rates beside it are for orientation only and name the machine
# and its load. Env: RUNS (5), BENCH_BASELINE, OUT (docs/performance.md).
set -eu
RUNS=${RUNS:-5}
BENCH_BASELINE=${BENCH_BASELINE:-2326ca8}
OUT=${OUT:-docs/performance.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# the page's stamp (host/reports/provenance.sh): the builds measured, the sources of
# build/*/beamslider and the flags they were compiled with
. host/reports/provenance.sh
stamp=$(provenance_stamp "make bench$( [ "$BENCH_BASELINE" = 2326ca8 ] || printf ' BENCH_BASELINE=%s' "$BENCH_BASELINE")" host)
. host/reports/baseline_tree.sh
baseline=$(git rev-parse --short "$(baseline_tree "$BENCH_BASELINE")")

field() { # field NAME < json-line
    sed -n "s/.*\"$1\":\"\{0,1\}\([^,\"}]*\).*/\1/p"
}
median() { # median of the numbers on stdin
    sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
# children_cpu FILE: the CPU seconds (user + sys) of this shell's finished children so
# far, into FILE (the builtin `times` in this shell: a command substitution would ask
# a subshell, whose children are others)
children_cpu() {
    times > "$TMP/times"
    tail -n 1 "$TMP/times" | awk '{ t = 0; for (i = 1; i <= 2; ++i) { split($i, p, "m"); sub("s", "", p[2]); t += p[1] * 60 + p[2] }
        printf "%.3f\n", t }' > "$1"
}
# cpu_run BIN SCENE JSON: one run pinned to core 0 (unpinned where taskset cannot);
# its CPU seconds into $TMP/cpu
cpu_run() {
    children_cpu "$TMP/before"
    taskset -c 0 "$1" run "configs/$2.ini" > "$3" 2>/dev/null || "$1" run "configs/$2.ini" > "$3"
    children_cpu "$TMP/after"
    awk 'NR == FNR { a = $1; next } { printf "%.3f\n", $1 - a }' "$TMP/before" "$TMP/after" > "$TMP/cpu"
}
load=$(cut -d' ' -f1-3 /proc/loadavg)

rows="" ratio_rows=""
for scene in fig6 fig6_1mode; do
    for real in double float; do
        : > "$TMP/pairs"
        i=0
        while [ "$i" -lt "$RUNS" ]; do
            cpu_run "build/$real/beamslider" "$scene" "$TMP/this.json"
            this=$(cat "$TMP/cpu")
            cpu_run "build/baseline/src/build/$real/beamslider" "$scene" "$TMP/base.json"
            base=$(cat "$TMP/cpu")
            echo "$this $base $(field steps < "$TMP/this.json") $(field steps < "$TMP/base.json")" >> "$TMP/pairs"
            i=$((i + 1))
        done
        # per pair: speed-up (steps per CPU second, this over baseline: both runs have
        # the same number of steps), and each build's steps per CPU second
        awk '{ print ($2 / $4) / ($1 / $3) }' "$TMP/pairs" > "$TMP/ratios"
        ratio=$(median < "$TMP/ratios")
        low=$(sort -g "$TMP/ratios" | head -n 1) high=$(sort -g "$TMP/ratios" | tail -n 1)
        this_rate=$(awk '{ print $3 / $1 }' "$TMP/pairs" | median)
        base_rate=$(awk '{ print $4 / $2 }' "$TMP/pairs" | median)
        steps=$(field steps < "$TMP/this.json")
        sweeps=$(field mean_pgs_iters < "$TMP/this.json")
        unconverged=$(field unconverged_steps < "$TMP/this.json")
        target=$([ "$scene" = fig6 ] && echo 1 || echo 3)
        met=$(awk -v r="$this_rate" -v t="$target" 'BEGIN { print (r >= t * 1e6 ? "yes" : "**no**") }')
        rows="$rows| $scene | $real | $(awk -v r="$this_rate" 'BEGIN { printf "%.2f", r / 1e6 }') | $target | $met | \
$(awk -v s="$steps" -v r="$this_rate" 'BEGIN { printf "%.2f", s / r }') | $sweeps | $unconverged |
"
        ratio_rows="$ratio_rows| $scene | $real | $(awk -v r="$base_rate" 'BEGIN { printf "%.2f", r / 1e6 }') | \
$(awk -v r="$this_rate" 'BEGIN { printf "%.2f", r / 1e6 }') | **$(awk -v r="$ratio" 'BEGIN { printf "%.2f", r }')** | \
$(awk -v a="$low" -v b="$high" 'BEGIN { printf "%.2f-%.2f", a, b }') |
"
        echo "bench: $scene $real: $this_rate steps per CPU second, $ratio x $baseline's (median of $RUNS pairs)" >&2
        [ "$scene:$real" != fig6:double ] || fig6_ratio=$ratio
    done
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

# The two full sweeps of Fig. 1b (fig6, five modes, double), up and down in
# parallel as `make figures` runs them: median wall time of RUNS.
: > "$TMP/sweeps"
i=0
while [ "$i" -lt "$RUNS" ]; do
    start=$(date +%s.%N)
    build/double/beamslider sweep configs/fig6.ini --dir up --out "$TMP/up.csv" > "$TMP/up.json" &
    build/double/beamslider sweep configs/fig6.ini --dir down --out "$TMP/down.csv" > "$TMP/down.json" &
    wait
    awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f\n", b - a }' >> "$TMP/sweeps"
    i=$((i + 1))
done
sweep_time=$(median < "$TMP/sweeps")
sweep_steps=$(( $(field steps < "$TMP/up.json") + $(field steps < "$TMP/down.json") ))
echo "bench: two sweeps: median $sweep_time s over $RUNS runs" >&2

# Python (issue 29): one sim.step(50000) call against the library's own run loop
# (scene.run) on fig6's 1 s, in one process, turns alternating, CPU time; medians
# (host/python/examples/step_overhead.py), pinned to one core like the runs above
python_rows=""
if [ -d build/python/lib ]; then
    for real in double float32; do
        PYTHONPATH=build/python/lib PYTHONDONTWRITEBYTECODE=1 taskset -c 0 /usr/bin/python3 \
            host/python/examples/step_overhead.py "$RUNS" "$real" > "$TMP/py-$real"
        python_rows="$python_rows$(awk -v real="$real" '$1 == "run" || $1 == "batch" || $1 == "single" { rate[$1] = $2; pct[$1] = $4 }
            END { printf "| %s | %.3g | %.3g | %.0f %% | %.1f %% |\n", real, rate["run"] / 1e6, rate["batch"] / 1e6, pct["batch"], pct["single"] }' "$TMP/py-$real")
"
    done
    echo "bench: Python done" >&2
fi
python_met=$(printf '%s' "$python_rows" | awk -F'|' 'NF > 5 { gsub(/[ %]/, "", $5); if ($5 + 0 < 90) bad = 1; n++ } END { print (n > 0 && !bad ? "met" : "**not met**") }')

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
compiler=$(${CC:-cc} --version | head -n 1)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- core host port 2>/dev/null || commit="$commit with uncommitted changes to the measured sources"
fig6_met=$(awk -v r="$fig6_ratio" 'BEGIN { print (r >= 2 ? "met" : "**not met**") }')

cat > "$OUT" <<EOF
# Performance

$stamp

Produced by \`make bench\` (host/reports/bench.sh) on $(date -u +%Y-%m-%d), commit $commit, against
commit $baseline (\`BENCH_BASELINE\`: 0.7.0, before the step's redesign of 0.8.0).
Machine: $cpu, $(nproc) cores, shared (load average $load at the start, $load_after at the end of
the paired runs); compiler: $compiler; the core at \`${PROVENANCE_CORE_OPT:-?}\`, the rest at \`-O2\`
(0.7.0: everything at \`-O2\`).$(case " ${PROVENANCE_CORE_OPT:-} " in *" -flto "*) printf '%s\n%s' " With -flto the core's files are linked into the program as one" "unit (the Makefile's CORE_LTO: its stages inlined across files; results unchanged)." ;; esac)

## This tree against the baseline

Complete 60 s runs (\`beamslider run configs/SCENE.ini\`: 3 000 000 steps at dt = 2e-5 s, the
scene loaded at run time) of both builds in turn, this tree's then the baseline's, $RUNS pairs
per row, one process at a time pinned to one core. Each run's CPU time (user + sys) gives its
steps per CPU second; the speed-up is the median over the pairs of this tree's rate over the
baseline's, and the range is the lowest and highest pair's. Each pair runs the same scene in
the same precision, but the two builds follow different trajectories (0.8.0 changed the
rounding of the step: docs/baseline.md for what that does to the physics, nothing), so the
ratio includes the difference in how many steps each run spends in contact.

| scene | precision | baseline: Msteps per CPU s (median) | this tree | speed-up (median of pairs) | range of pairs |
|---|---|---|---|---|---|
$ratio_rows
The redesign's host target (issue 27): fig6 in double at least 2x the baseline's steps per
second: **$(awk -v r="$fig6_ratio" 'BEGIN { printf "%.2fx", r }')**, $fig6_met.
Where the instructions went, and what is left: docs/design.md 4, "What a step reads, and in
which form", and docs/embedded.md, "Where the cycles go" (the same code on a Cortex-M4F).

## Steps per second

This tree's runs above: the median steps per CPU second (one core), against the targets of
the project's first speed issue (at least 1 million steps/s with five modes and 3 million with
one mode, so that the 60 s signature move takes under 3 s). An absolute figure depends on
the machine and its load (above); the ratios do not.

| scene | precision | Msteps per CPU s (median) | target | met | CPU s for 60 s | mean sweeps per contact step | unconverged steps |
|---|---|---|---|---|---|---|---|
$rows
A whole run is measured, so the figure depends on the trajectory: a step with two corners in
contact costs about twice a free step. The float and the double run of a scene follow
different trajectories (the dynamics are chaotic, docs/accuracy.md) and so spend different
numbers of steps in contact; the gap between the two precisions of one scene is mostly that,
not the cost of the arithmetic.

The authors' MATLAB code, run under Octave, does about 230 steps/s on this kind of machine
according to the issue that set these targets; it is not in this repository and that figure
is not re-measured here.

## From Python

The Python package (docs/python.md) stepping fig6's 1 s (50 000 steps) in one
\`sim.step(50000)\` call, against the library's own run loop (\`scene.run\`, the C
code the CLI runs) in the same process: $RUNS turns of each alternating, CPU time,
medians, pinned to one core (host/python/examples/step_overhead.py). The last
column is 50 000 calls of \`sim.step(1)\`: what a call from Python costs.

| precision | library's loop: Msteps per CPU s | one sim.step call | batch / library | 50 000 single steps / library |
|---|---|---|---|---|
$python_rows
Target (issue 29): batch stepping at least 90 % of the library's steps per second:
$python_met.

## The sweeps of Fig. 1b

Both PCS sweeps of fig6 (five modes, double; 101 points of 100 + 25 excitation periods
each, $sweep_steps steps together), up and down run in parallel on the two cores as
\`make figures\` runs them: median **$sweep_time s** of wall time over $RUNS runs (target: under
10 s; wall time, so the machine's load enters).
EOF
echo "bench: wrote $OUT" >&2
