#!/bin/sh
# selftest.sh - build selftest.c for every Cortex-M target, run it under QEMU, check the output.
#
# Run from anywhere; works in the repository root. Per target it checks: exit status 0 and
# every expected line; the empty mark bracket counts 2 instructions; the float multiply-add
# loop costs exactly 5 instructions per iteration (+ a small constant) with an FPU and a
# plausible 20..400 in software; stack painting reads 0 for nothing and (depth+1) x frame (frame
# from selftest.su) for the nested calls; the fault variant exits 99 with "*** CPU fault"; the
# hang variant is stopped with status 124 within its 1 s limit. Also: an M4F image on the
# FPU-less AN385 faults inside startup, before newlib's semihosting set-up, and must still exit
# 99 (not 0); two counted runs give identical counts; a profile of two brackets sums to their
# counts and puts the loop's instructions in its function; probe.sh's means are those of the
# labelled brackets; twin_samples.awk's means and backlogs on a made-up count.
# If the counting plugin cannot be built (no network for the header), the count checks are
# skipped with a notice and the rest still runs. Exit status: 0 all passed, 1 otherwise.
# Env: MAKE (default make), CM_BUILD (default build/cm).
set -u
here=$(cd "$(dirname "$0")" && pwd)
cd "$here/../.." || exit 1
CM_BUILD=${CM_BUILD:-build/cm}
export CM_BUILD
targets="cortex-m4f cortex-m7 cortex-m3 cortex-m0plus"
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "  ok   $*"; }
bad() { fail=$((fail + 1)); echo "  FAIL $*"; }
check() { # check DESCRIPTION CONDITION...: the condition is a test(1) expression
    d=$1; shift
    if [ "$@" ] 2>/dev/null; then ok "$d"; else bad "$d"; fi
}
count_of() { # count_of FILE LABEL -> the "[insn] N" right before the line LABEL
    awk -v label="$2" '/^\[insn\] [0-9]+$/ { n = $2; next } $0 == label { print n; exit }' "$1"
}
cycles_of() { # cycles_of FILE LABEL FIELD -> FIELD (cycles, taken, flash) of the mark line before LABEL
    awk -v label="$2" -v field="$3" '/^\[insn\] [0-9]+ cycles/ { for (i = 3; i < NF; i += 2) v[$i] = $(i + 1); next }
        $0 == label { print v[field]; exit }' "$1"
}
has() { grep -qxF "$2" "$1"; }

for tool in arm-none-eabi-gcc arm-none-eabi-nm qemu-system-arm timeout; do
    command -v $tool >/dev/null 2>&1 || {
        echo "selftest.sh: $tool not found (apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm)" >&2
        exit 1
    }
done
echo "== build"
mkdir -p "$CM_BUILD" || exit 1
# A relative -f keeps object paths short: NAME.obj/tests/qemu/selftest.o
${MAKE:-make} --no-print-directory -f tests/qemu/selftest.mk -j2 CM_BUILD="$CM_BUILD" \
    >"$CM_BUILD/selftest-build.log" 2>&1 || {
    cat "$CM_BUILD/selftest-build.log"; echo "selftest.sh: build failed"; exit 1; }
ok "built $(echo "$targets" | wc -w) targets x {selftest, selftest-fault, selftest-hang}"
if sh "$here/build-plugin.sh"; then counting=1; else
    counting=; echo "selftest.sh: NOTICE: instruction-count checks skipped (no plugin, see above)"; fi

for t in $targets; do
    echo "== $t"
    dir=$CM_BUILD/$t
    out=$dir/selftest.out
    if [ -n "$counting" ]; then
        sh "$here/count.sh" "$dir/selftest.elf" "$t" 30 >"$out" 2>&1
    else
        sh "$here/../../port/cortex-m/run.sh" "$dir/selftest.elf" "$t" 30 >"$out" 2>&1
    fi
    check "selftest exits 0 (output: $out)" "$?" -eq 0
    missing=
    for line in "bracket empty" "bracket mul_add n=0" "bracket mul_add n=1000" "stack empty used=0" \
                "printf 3.141593 -1.500 1e+06" "selftest done"; do
        has "$out" "$line" || missing="$missing '$line'"
    done
    check "expected lines present${missing:+ (missing:$missing)}" -z "$missing"

    frame=$(awk -F '\t' '$1 ~ /:selftest_nest$/ { print $2 }' "$dir/selftest.obj/tests/qemu/selftest.su" 2>/dev/null)
    used=$(sed -n 's/^stack nest depth=9 used=\([0-9]*\)$/\1/p' "$out")
    # 10 frames of the .su size; the lowest bytes of the deepest frame may be padding.
    check "stack nest used=$used, 10 x frame $frame = $((10 * ${frame:-0}))" \
        -n "$frame" -a -n "$used" -a "${used:-0}" -le $((10 * ${frame:-0})) -a "${used:-0}" -ge $((10 * ${frame:-0} - 8))

    if [ -n "$counting" ]; then
        empty=$(count_of "$out" "bracket empty")
        n0=$(count_of "$out" "bracket mul_add n=0")
        n1000=$(count_of "$out" "bracket mul_add n=1000")
        check "empty mark bracket = ${empty:-?} instructions (expect 2)" "${empty:-x}" = 2
        if [ -n "$n0" ] && [ -n "$n1000" ]; then
            loop=$((n1000 - n0))
            case $t in
                cortex-m4f | cortex-m7)
                    check "mul_add: n=0 $n0, n=1000 $n1000 -> 5 x 1000 + $((loop - 5000)) (hardware float)" \
                        "$loop" -ge 5000 -a "$loop" -le 5004 ;;
                *)
                    check "mul_add: n=0 $n0, n=1000 $n1000 -> $((loop / 1000)).$((loop % 1000 / 100)) per iteration (software float, plausible 20..400)" \
                        "$loop" -ge 20000 -a "$loop" -le 400000 ;;
            esac
        else
            bad "mul_add counts missing from $out"
        fi
        total=$(sed -n 's/^\[insn\] total \([0-9]*\)$/\1/p' "$out")
        check "total printed at exit: ${total:-none}" -n "$total"
    fi

    sh "$here/../../port/cortex-m/run.sh" "$dir/selftest-fault.elf" "$t" 30 >"$dir/selftest-fault.out" 2>&1
    st=$?
    check "fault variant exits 99 (got $st), prints '*** CPU fault'" "$st" -eq 99 -a \
        "$(grep -c '^\*\*\* CPU fault' "$dir/selftest-fault.out")" -eq 1
    start=$(date +%s)
    sh "$here/../../port/cortex-m/run.sh" "$dir/selftest-hang.elf" "$t" 1 >"$dir/selftest-hang.out" 2>&1
    st=$?
    took=$(($(date +%s) - start))
    check "hang variant stopped with 124 (got $st) in ${took} s, message printed" "$st" -eq 124 -a \
        "$took" -le 7 -a "$(grep -c 'run.sh: \*\*\* timeout' "$dir/selftest-hang.out")" -eq 1
done

echo "== cross-checks"
# FP instructions are undefined on the AN385's M3: the fault hits in startup (newlib's
# initialise_monitor_handles) before semihosting is set up; newlib's exit would give 0 there.
CM_MACHINE=mps2-an385 sh "$here/../../port/cortex-m/run.sh" "$CM_BUILD/cortex-m4f/selftest.elf" cortex-m4f 30 >"$CM_BUILD/wrong-board.out" 2>&1
st=$?
check "M4F image on mps2-an385: early fault exits 99 (got $st)" "$st" -eq 99
if [ -n "$counting" ]; then
    sh "$here/count.sh" "$CM_BUILD/cortex-m4f/selftest.elf" cortex-m4f 30 >"$CM_BUILD/cortex-m4f/selftest.out2" 2>&1
    has "$CM_BUILD/cortex-m4f/selftest.out" "selftest done" &&
        cmp -s "$CM_BUILD/cortex-m4f/selftest.out" "$CM_BUILD/cortex-m4f/selftest.out2"
    check "counts deterministic (two cortex-m4f runs identical)" "$?" -eq 0
    # The profile mode attributes exactly the bracketed instructions: brackets 2 and 3 are
    # mul_add n=0 and n=1000; the loop itself is in selftest_mul_add.
    prof=$CM_BUILD/cortex-m4f/selftest.profile
    rm -f "$prof"
    CM_PROFILE="profile=$prof,first=2,last=3" sh "$here/count.sh" "$CM_BUILD/cortex-m4f/selftest.elf" \
        cortex-m4f 30 >"$CM_BUILD/cortex-m4f/selftest.out3" 2>&1
    n0=$(count_of "$CM_BUILD/cortex-m4f/selftest.out" "bracket mul_add n=0")
    n1000=$(count_of "$CM_BUILD/cortex-m4f/selftest.out" "bracket mul_add n=1000")
    first=$(head -n 1 "$prof" 2>/dev/null)
    sum=$(awk 'NR > 1 { sum += $2 } END { print sum + 0 }' "$prof" 2>/dev/null)
    check "profile of brackets 2-3: '$first', sum ${sum:-?} = $n0 + $n1000" \
        "$first" = "brackets 2 worst 3 $n1000" -a "${sum:-0}" -eq $((${n0:-0} + ${n1000:-0}))
    loop=$(sh "$here/profile.sh" "$prof" "$CM_BUILD/cortex-m4f/selftest.elf" 2>/dev/null |
           awk '$1 == "selftest_mul_add" { print $3 }')
    check "profile: selftest_mul_add ${loop:-?} instructions in bracket 3 (expect 5000..5010)" \
        "${loop:-0}" -ge 5000 -a "${loop:-0}" -le 5010
    # The cycle estimate (CM_CYCLES=1): loops whose cost the model fixes per iteration, and
    # data reads from the code region counted where the table is and not where it is not.
    out=$CM_BUILD/cortex-m4f/selftest.cycles
    CM_CYCLES=1 sh "$here/count.sh" "$CM_BUILD/cortex-m4f/selftest.elf" cortex-m4f 30 >"$out" 2>&1
    check "cycles: counts unchanged by the cycle estimate" \
        "$(cycles_of "$out" "bracket mul_add n=1000" cycles | wc -c)" -gt 1 -a \
        "$(sed -n 's/^\(\[insn\] [0-9]*\).*/\1/p' "$out" | cksum)" = \
        "$(sed -n 's/^\(\[insn\] [0-9]*\).*/\1/p' "$CM_BUILD/cortex-m4f/selftest.out" | cksum)"
    for loop in "mul_add 5" "div_add 18"; do
        set -- $loop
        c0=$(cycles_of "$out" "bracket $1 n=0" cycles); c1=$(cycles_of "$out" "bracket $1 n=1000" cycles)
        t0=$(cycles_of "$out" "bracket $1 n=0" taken); t1=$(cycles_of "$out" "bracket $1 n=1000" taken)
        # taken: 999 back edges, less the n = 0 bracket's branch around the loop
        check "cycles: $1 costs $(( (${c1:-0} - ${c0:-0}) )) base cycles and $(( ${t1:-0} - ${t0:-0} )) taken branches more for 1000 iterations (expect $2 x 1000 + 0..5, 998)" \
            $((${c1:-0} - ${c0:-0})) -ge $(($2 * 1000)) -a $((${c1:-0} - ${c0:-0})) -le $(($2 * 1000 + 5)) -a \
            $((${t1:-0} - ${t0:-0})) -eq 998
    done
    fl=$(cycles_of "$out" "bracket sum flash" flash); ram=$(cycles_of "$out" "bracket sum ram" flash)
    check "cycles: 64 floats from a const table = ${fl:-?} reads of the code region (expect 64..66), from RAM ${ram:-?} (expect 0..2)" \
        "${fl:-0}" -ge 64 -a "${fl:-0}" -le 66 -a "${ram:-99}" -le 2
    check "cycles: empty bracket = $(cycles_of "$out" "bracket empty" cycles) cycles, $(cycles_of "$out" "bracket empty" taken) taken (expect 2, 2)" \
        "$(cycles_of "$out" "bracket empty" cycles)" = 2 -a "$(cycles_of "$out" "bracket empty" taken)" = 2
    # probe.sh averages every second bracket (a cost-mode image's steps): here the seven
    # labelled ones, whose means are formed from their labels instead
    want=$(for label in "bracket empty" "bracket mul_add n=0" "bracket mul_add n=1000" "bracket div_add n=0" \
               "bracket div_add n=1000" "bracket sum flash" "bracket sum ram"; do
               echo "$(count_of "$CM_BUILD/cortex-m4f/selftest.out" "$label") $(cycles_of "$out" "$label" cycles)" \
                   "$(cycles_of "$out" "$label" taken) $(cycles_of "$out" "$label" flash)"
           done | awk 'NF == 4 { ++n; i += $1; p += $2 + 3 * $3 + 5 * $4 }
                       END { printf "steps %d insn %.1f pessimistic %.1f", n, n ? i / n : 0, n ? p / n : 0 }')
    got=$(sh "$here/probe.sh" "$CM_BUILD/cortex-m4f/selftest.elf" 2>/dev/null | awk '{ print $1, $2, $3, $4, $7, $8 }')
    check "probe.sh: '$got' (expect '$want': the labelled brackets)" "$got" = "$want"
fi

# twin_samples.awk (twin_probe.sh, the twin firmware report) on a made-up count: the start-up
# interval, then a sample's intervals (the loop since the last step, the producer, the loop,
# the observer step; the first sample has no loop before it) costing 150, 150 and 0 cycles
# against a budget of 100 (5 MHz x 2e-5 s): backlog 50, 100, 0, at most 1 sample; with 100
# more on every second sample 150, 250, 0: 50, 200, 100, 2 samples
samples_of() { # samples_of EXTRA EVERY -> "sample MEAN backlog W over K step S producer P"
    awk 'BEGIN { print "[insn] 9 cycles 9 taken 0 flash 0"
                 split("20 10 120 0 20 10 120 0 0 0 0", c, " ")
                 for (i = 1; i <= 11; ++i) printf "[insn] 1 cycles %d taken 0 flash 0\n", c[i]
                 print "end status 0 stack 8 s 0.5 hash ab est cd" }' |
        awk -v cycles=1 -v clocks=5 -v dt=0.00002 -v entry=0 -v fifo=1 -v extra="$1" -v every="$2" \
            -v digits=1 -f "$here/twin_samples.awk" |
        awk '{ v[$1] = $2 } END { print "sample", v["sample"], "backlog", v["backlog_5"], "over", v["over"],
                                  "step", v["step_pess"], "producer", v["producer_pess"], v["hash"], v["est"] }'
}
got=$(samples_of 0 1)
check "twin_samples.awk: '$got'" "$got" = "sample 100.0 backlog 1 over 2 step 80.0 producer 13.3 ab cd"
got=$(samples_of 100 2)
check "twin_samples.awk, 100 cycles on every second sample: '$got'" "$got" = "sample 133.3 backlog 2 over 2 step 80.0 producer 13.3 ab cd"

note=
[ -n "$counting" ] || note=" (instruction counts not checked)"
echo "selftest.sh: $pass passed, $fail failed$note"
[ "$fail" -eq 0 ]
