#!/bin/sh
# check_sweep.sh - `beamslider sweep`: CSV format, grid order, determinism,
# the trace, exit codes and messages (0 ok, 1 the work failed, 2 bad usage
# or input; host/cli/cli.h).
#
# usage, from the repository root:  sh host/reports/figures/check_sweep.sh PATH/TO/beamslider
# Prints one line per check and a summary; exits 1 if any check failed.

bin=${1:-}
. "$(dirname "$0")/../../../tests/check_lib.sh"
check_setup host/reports/figures/check_sweep.sh "$bin"

small="--from 0.2 --to 0.3 --step 0.05 --hold 2 --record 3"

# ---- a small sweep each way
for dir in up down; do
    # shellcheck disable=SC2086
    "$bin" sweep configs/fig6.ini --dir $dir $small --out "$tmp/$dir.csv" >"$tmp/$dir.json" 2>"$tmp/$dir.err"
    check_status "sweep --dir $dir exits 0" 0 $? "$tmp/$dir.err"
    touch "$tmp/$dir.csv"
done
header=$(head -n 1 "$tmp/up.csv")
if [ "$header" = "s,amp_h,v_mean,mean_sweeps,max_sweeps,unconverged_steps,contact_steps,steps" ]; then
    pass "CSV header"
else
    fail "CSV header" "got: $header"
fi
s_up=$(awk -F, 'NR > 1 { printf "%s ", $1 }' "$tmp/up.csv")
s_down=$(awk -F, 'NR > 1 { printf "%s ", $1 }' "$tmp/down.csv")
if [ "$s_up" = "0.200000 0.250000 0.300000 " ] && [ "$s_down" = "0.300000 0.250000 0.200000 " ]; then
    pass "grid points in sweep order (up: 0.2 0.25 0.3, down: 0.3 0.25 0.2)"
else
    fail "grid points in sweep order (up: 0.2 0.25 0.3, down: 0.3 0.25 0.2)" "up: $s_up; down: $s_down"
fi
if report=$(awk -F, 'NF != 8 { printf "line %d has %d fields\n", NR, NF; ++bad }
                     NR > 1 && !($2 > 0 && $8 >= 5 * 400 && $8 <= 5 * 404) { printf "line %d: %s\n", NR, $0; ++bad }
                     END { exit NR != 4 || bad > 0 }' "$tmp/up.csv"); then
    pass "every row has 8 fields, amp_h > 0 and the steps of 5 periods of 124 Hz at dt 2e-5 s"
else
    fail "every row has 8 fields, amp_h > 0 and the steps of 5 periods of 124 Hz at dt 2e-5 s" "$report"
fi
steps=$(awk -F, 'NR > 1 { n += $8 } END { print n }' "$tmp/up.csv")
if grep -q "\"steps\":$steps," "$tmp/up.json" && grep -q '"status":"ok"' "$tmp/up.json" \
    && grep -q '"points":3,' "$tmp/up.json" && [ "$(wc -l <"$tmp/up.json")" -eq 1 ]; then
    pass "stdout is one line of JSON: status ok, 3 points, steps = sum of the CSV's steps"
else
    fail "stdout is one line of JSON: status ok, 3 points, steps = sum of the CSV's steps" "$(cat "$tmp/up.json")"
fi
# shellcheck disable=SC2086
"$bin" sweep configs/fig6.ini --dir up $small --out "$tmp/again.csv" >/dev/null 2>&1
if cmp -s "$tmp/up.csv" "$tmp/again.csv"; then pass "a re-run gives the same CSV"; else fail "a re-run gives the same CSV"; fi

# ---- the trace: one period at s = 0.25 from its first recorded period on
# shellcheck disable=SC2086
"$bin" sweep configs/fig6.ini --dir up $small --out "$tmp/t.csv" --trace "$tmp/trace.csv" --trace-at 0.25 \
    --trace-periods 1 >"$tmp/o" 2>"$tmp/e"
check_status "sweep --trace exits 0" 0 $? "$tmp/e"
touch "$tmp/trace.csv"
if cmp -s "$tmp/up.csv" "$tmp/t.csv"; then pass "tracing does not change the sweep"; else fail "tracing does not change the sweep"; fi
if report=$(awk -F, 'NR == 1 { if ($0 != "period,t,w_h,beta,alpha,rel_rot,contacts") { print "header: " $0; bad = 1 }; next }
                     NF != 7 { printf "line %d has %d fields\n", NR, NF; bad = 1 }
                     { d = $6 - ($4 + $5); if (d * d > 1e-16) { printf "line %d: rel_rot != beta + alpha\n", NR; bad = 1 } }
                     END { if (!(NR >= 402 && NR <= 406 && $1 >= 1 && $1 < 1.01)) { printf "%d lines, last period %s\n", NR, $1; bad = 1 }
                           exit bad }' "$tmp/trace.csv"); then
    pass "trace: header, one excitation period of rows (period 0 to 1), rel_rot = beta + alpha"
else
    fail "trace: header, one excitation period of rows (period 0 to 1), rel_rot = beta + alpha" "$report"
fi

# ---- bad usage: exit 2, a message naming the problem, no output file
bad() { # bad DESCRIPTION EXPECTED_TEXT ARGS...
    description=$1
    text=$2
    shift 2
    rm -f "$tmp/bad.csv"
    "$bin" sweep "$@" >"$tmp/o" 2>"$tmp/e"
    check_status "$description exits 2" 2 $? "$tmp/e"
    check_has "$description: message" "$tmp/e" "$text"
    if [ -e "$tmp/bad.csv" ]; then fail "$description: no output file"; fi
}
out="--out $tmp/bad.csv"
# shellcheck disable=SC2086
{
    bad "no scene" "needs a scene file"
    bad "no --dir" "--dir up or --dir down" configs/fig6.ini $out
    bad "--dir sideways" "--dir sideways" configs/fig6.ini --dir sideways $out
    bad "no --out" "--out FILE.csv" configs/fig6.ini --dir up
    bad "--from above --to" "--from must be below --to" configs/fig6.ini --dir up --from 0.4 --to 0.3 $out
    bad "--to 1.5" "--to 1.5" configs/fig6.ini --dir up --to 1.5 $out
    bad "--step not dividing the range" "--step 0.003" configs/fig6.ini --dir up --step 0.003 $out
    bad "--step 0" "--step 0" configs/fig6.ini --dir up --step 0 $out
    bad "--hold -1" "--hold -1" configs/fig6.ini --dir up --hold -1 $out
    bad "--record 0" "--record 0" configs/fig6.ini --dir up --record 0 $out
    bad "--record x" "--record x" configs/fig6.ini --dir up --record x $out
    bad "option without a value" "--hold" configs/fig6.ini --dir up $out --hold
    bad "unknown option" "--bogus" configs/fig6.ini --dir up --bogus 1 $out
    bad "--trace without --trace-at" "--trace-at" configs/fig6.ini --dir up $out --trace "$tmp/bad.csv"
    bad "--trace-at off the grid" "not a grid point" configs/fig6.ini --dir up $out --trace "$tmp/bad.csv" \
        --trace-at 0.3001
    bad "--trace-periods beyond --record" "--trace-periods 30" configs/fig6.ini --dir up $out \
        --trace "$tmp/bad.csv" --trace-at 0.3 --trace-periods 30
    bad "--dt beyond the explicit limit" "--dt" configs/fig6.ini --dir up --dt 1e-4 $out
    bad "missing scene file" "$tmp/none.ini" "$tmp/none.ini" --dir up $out
}

# ---- output that cannot be written: exit 1 and a message naming the file
"$bin" sweep configs/fig6.ini --dir up $small --out "$tmp/no/such/dir/x.csv" >"$tmp/o" 2>"$tmp/e"
check_status "--out into a missing folder exits 1" 1 $? "$tmp/e"
check_has "--out into a missing folder names the file" "$tmp/e" "$tmp/no/such/dir/x.csv"
if [ -c /dev/full ]; then
    # shellcheck disable=SC2086
    "$bin" sweep configs/fig6.ini --dir up $small --out /dev/full >"$tmp/o" 2>"$tmp/e"
    check_status "--out /dev/full exits 1" 1 $? "$tmp/e"
    check_has "--out /dev/full message names the file" "$tmp/e" "/dev/full"
    check_has "--out /dev/full message says it failed" "$tmp/e" "failed"
else
    echo "skip - --out /dev/full (no /dev/full here)"
fi

echo "check_sweep: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
