#!/bin/sh
# check_robustness_cli.sh BEAMSLIDER - regression checks of the bad inputs
# docs/robustness.md found mishandled (tests/robustness.mk: robustness-cli):
# a NUL byte or UTF-16 text in a scene, a folder given as the scene, standard
# output that cannot be written, a start position at the edge of its range
# (host check in double, core check in bs_real), text after a section's ],
# CR-only line ends, /dev/zero or a FIFO as a scene or base, options that
# used up the base-file slots, outputs that are one file (or the scene, or
# standard output) and outputs truncated before another failed to open,
# values that overflow together. Run from the repository root.
bin=$1
passed=0
failed=0
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# expect DESCRIPTION STATUS TEXT ARGS...: exit status STATUS and TEXT on
# stderr (an empty TEXT: anything); standard output goes to $stdout
stdout=$tmp/out
limit=  # a command prefix, such as timeout 20
expect() {
    description=$1
    want=$2
    text=$3
    shift 3
    $limit "$bin" "$@" >"$stdout" 2>"$tmp/err"
    status=$?
    if [ "$status" -eq "$want" ] && { [ -z "$text" ] || grep -q -F -e "$text" "$tmp/err"; }; then
        passed=$((passed + 1))
        echo "ok   - $description"
    else
        failed=$((failed + 1))
        echo "FAIL - $description: exit $status (expected $want), stderr: $(cat "$tmp/err")"
    fi
}

if [ ! -x "$bin" ] || [ ! -f configs/fig6.ini ]; then
    echo "FAIL - usage (from the repository root): sh tests/fuzz/check_robustness_cli.sh PATH/TO/beamslider"
    exit 1
fi
cp configs/mssp2023.ini "$tmp/" || exit 1
good='[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 0.01\n'
printf "$good" >"$tmp/good.ini"

printf "$good" | sed 's/^s0 = 0.3$/s0 = 0.3\x00junk/' >"$tmp/nul.ini"
expect "a NUL byte is refused with its line" 2 "nul.ini:7: NUL byte" run "$tmp/nul.ini"
if command -v iconv >/dev/null 2>&1; then
    printf "$good" | iconv -f UTF-8 -t UTF-16 >"$tmp/utf16.ini"
    expect "a UTF-16 scene is refused as not text" 2 "utf16.ini:1: NUL byte" run "$tmp/utf16.ini"
fi
expect "a folder as the scene is a read error" 2 "cannot read scene file" run "$tmp"
if [ -c /dev/full ]; then
    stdout=/dev/full
    expect "run > /dev/full exits 1" 1 "writing standard output failed" run configs/fig6.ini --t-end 0.001
    expect "modes > /dev/full exits 1" 1 "writing standard output failed" modes configs/fig6.ini
    expect "gen > /dev/full exits 1" 1 "writing standard output failed" gen configs/fig6_1mode.ini
    stdout=$tmp/out
fi
# s0 = 0.8 is the upper end of the range the host allows for L = 0.05 m,
# B = 0.02 m (1 - B/2L, in double); in bs_real, s0 L lands above L - B/2
printf '[scene]\nbase = mssp2023.ini\n[beam]\nlength = 0.05\n[slider]\nslot_width = 0.02\n[excitation]\nfrequency = 124\nacceleration = 14\n[numerics]\ndt = 5e-6\n[run]\ns0 = 0.8\nt_end = 0.001\n' >"$tmp/edge.ini"
expect "s0 at the edge the core refuses: bad input, file:line" 2 "edge.ini:13: [run] s0" run "$tmp/edge.ini" --out "$tmp/edge.csv"
if [ -e "$tmp/edge.csv" ]; then
    failed=$((failed + 1))
    echo "FAIL - s0 at the edge creates no --out file"
else
    passed=$((passed + 1))
    echo "ok   - s0 at the edge creates no --out file"
fi
# values each in range whose product is out of range: a phase step
# f_ex dt that rounds to zero in the 2^-64 turns the phase counts (float:
# a frequency below the smallest normal float is refused first)
printf "$good" | sed 's/^frequency = 124$/frequency = 1e-160/' >"$tmp/slow.ini"
expect "a phase step that rounds to zero: blames the frequency's line" 2 \
    "slow.ini:4: the values make" run "$tmp/slow.ini"
expect "... and gives the frequency's range" 2 \
    "[excitation] frequency = 1e-160 Hz ($tmp/slow.ini:4): [5.421011e-15, " run "$tmp/slow.ini"
# a denormal thickness gave NaN frequencies, blamed on dt
printf "$good" | sed 's/^\[excitation\]$/[beam]\nthickness = 1e-320\n[excitation]/' >"$tmp/denormal.ini"
expect "a denormal thickness is blamed on the thickness" 2 "denormal.ini:4: the values make" run "$tmp/denormal.ini"
expect "more steps than a double counts exactly" 2 "[run] t_end = 1e+09 s is more than 2^53 steps" \
    run "$tmp/good.ini" --dt 1e-12 --t-end 1e9
expect "--out and --periods naming one file" 2 "--out and --periods both name" \
    run "$tmp/good.ini" --out "$tmp/same.csv" --periods "$tmp/same.csv"

# ---- outputs compared as files, opened all or none (they used to be
# compared as strings, sweep's --trace not at all, and --out was truncated
# before --periods failed to open)
# unchanged DESCRIPTION FILE: FILE still holds "keep"
unchanged() {
    if [ "$(cat "$2")" = keep ]; then
        passed=$((passed + 1)); echo "ok   - $1"
    else
        failed=$((failed + 1)); echo "FAIL - $1: $2 holds $(head -c 80 "$2")"
    fi
}
echo keep >"$tmp/keep.csv"
ln -s keep.csv "$tmp/symlink.csv"
ln "$tmp/keep.csv" "$tmp/hardlink.csv"
ln -s nowhere.csv "$tmp/dangling.csv"
mkdir "$tmp/sub"
expect "--out ./x and --periods x are one file" 2 "are the same file" \
    run "$tmp/good.ini" --out "$tmp/./keep.csv" --periods "$tmp/keep.csv"
expect "a symbolic link to --out as --periods" 2 "are the same file" \
    run "$tmp/good.ini" --out "$tmp/keep.csv" --periods "$tmp/symlink.csv"
expect "a hard link to --out as --periods" 2 "are the same file" \
    run "$tmp/good.ini" --out "$tmp/hardlink.csv" --periods "$tmp/keep.csv"
unchanged "outputs that are one file leave it untouched" "$tmp/keep.csv"
expect "two spellings of a file still to be created" 2 "are the same file" \
    run "$tmp/good.ini" --out "$tmp/new.csv" --periods "$tmp/sub/../new.csv"
expect "a dangling link to --out as --periods" 2 "are the same file" \
    run "$tmp/good.ini" --out "$tmp/nowhere.csv" --periods "$tmp/dangling.csv"
stdout=$tmp/summary.txt
expect "--out /dev/stdout when standard output is a file" 2 "is where standard output goes" \
    run "$tmp/good.ini" --out /dev/stdout
expect "--out naming the file standard output goes to" 2 "is where standard output goes" \
    run "$tmp/good.ini" --out "$tmp/summary.txt"
stdout=$tmp/out
expect "sweep --out and --trace are one file" 2 "are the same file" \
    sweep "$tmp/good.ini" --dir up --out "$tmp/keep.csv" --trace "$tmp/symlink.csv" --trace-at 0.2 \
    --from 0.2 --to 0.21 --step 0.01 --hold 1 --record 1
unchanged "sweep leaves it untouched" "$tmp/keep.csv"
expect "the scene file as --out" 2 "is the scene file" run "$tmp/good.ini" --out "$tmp/./good.ini"
expect "the base file as --periods" 2 "is the scene's base file" run "$tmp/good.ini" --periods "$tmp/mssp2023.ini"
expect "the scene file as sweep --out" 2 "is the scene file" \
    sweep "$tmp/good.ini" --dir up --out "$tmp/good.ini" --from 0.2 --to 0.21 --step 0.01
expect "a --periods that cannot be opened" 1 "cannot open $tmp/none/p.csv" \
    run "$tmp/good.ini" --out "$tmp/keep.csv" --periods "$tmp/none/p.csv"
unchanged "... leaves --out untouched" "$tmp/keep.csv"
expect "a --trace that cannot be opened" 1 "cannot open $tmp/none/t.csv" \
    sweep "$tmp/good.ini" --dir up --out "$tmp/fresh.csv" --trace "$tmp/none/t.csv" --trace-at 0.2 \
    --from 0.2 --to 0.21 --step 0.01
if [ -e "$tmp/fresh.csv" ]; then
    failed=$((failed + 1)); echo "FAIL - ... and leaves no new --out file behind"
else
    passed=$((passed + 1)); echo "ok   - ... and leaves no new --out file behind"
fi
expect "two outputs to /dev/null run" 0 "" run "$tmp/good.ini" --out /dev/null --periods /dev/null
expect "a contact-solve cap above the real-time range" 2 "allowed: an integer in [1, 100000]" \
    run "$tmp/good.ini" --pgs-iters 1000000
# text after the ] of a section line, CR-only line ends: libinih would drop
# them and the base value would run
printf "$good" | sed 's/^\[excitation\]$/[excitation] frequency = 200/' >"$tmp/after.ini"
expect "a key after [section] on its line is refused" 2 "after.ini:3: text after [excitation]" run "$tmp/after.ini"
printf "$good" | tr '\n' '\r' >"$tmp/mac.ini"
expect "CR-only line ends are refused" 2 "mac.ini:1: carriage return without a line feed" run "$tmp/mac.ini"
printf "$good" | sed 's/$/\r/' >"$tmp/crlf.ini"
expect "CRLF line ends run" 0 "" run "$tmp/crlf.ini"
# a base that never ends, a FIFO: refused at once (they used to hang; the
# timeout turns a hang into a failure where timeout exists)
if command -v timeout >/dev/null 2>&1; then limit="timeout 20"; fi
printf '[scene]\nbase = /dev/zero\n' >"$tmp/zero.ini"
expect "base = /dev/zero is refused" 2 "zero.ini:2: [scene] base = /dev/zero: cannot read /dev/zero: a character device" \
    run "$tmp/zero.ini"
if mkfifo "$tmp/fifo.ini" 2>/dev/null; then
    expect "a FIFO as the scene is refused" 2 "fifo.ini: cannot read scene file: a FIFO" run "$tmp/fifo.ini"
fi
limit=
# options used to take the slots of base files (8 in all): a chain of 7
# files and five options failed with "too many nested base files"
for i in 1 2 3 4 5; do printf '[scene]\nbase = chain%d.ini\n' $((i + 1)) >"$tmp/chain$i.ini"; done
printf '[scene]\nbase = good.ini\n' >"$tmp/chain6.ini"
expect "a chain of 7 files and five options runs" 0 "" run "$tmp/chain1.ini" --dt 2e-5 --t-end 0.001 \
    --s0 0.3 --model free --pgs-iters 2 --dt 1e-5
echo "check_robustness_cli: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
