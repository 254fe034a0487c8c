#!/bin/sh
# check_cli.sh - the bs-reference command line: output formats equal to
# `beamslider run` (headers taken from host/lib/run.c), JSON keys, exit codes.
#
# usage, from the repository root:  sh tests/reference/check_cli.sh build/bs-reference
bin=${1:-}
passed=0
failed=0
pass() { passed=$((passed + 1)); echo "ok   - $1"; }
fail() { failed=$((failed + 1)); echo "FAIL - $1"; [ -n "${2:-}" ] && printf '%s\n' "$2" | sed 's/^/       /'; }

if [ -z "$bin" ] || [ ! -x "$bin" ] || [ ! -f configs/fig6.ini ]; then
    echo "FAIL - usage (from the repository root): sh tests/reference/check_cli.sh PATH/TO/bs-reference"
    exit 1
fi
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# modes: docs/model.md 8 frequencies, relative 1e-4
if "$bin" modes configs/fig6.ini >"$tmp/modes" 2>&1 && awk -F, '
    BEGIN { split("260.28 719.01 1412.3 2339.0 3500.1", want, " ") }
    $1 ~ /^[0-9]+$/ { n++; d = $3 - want[$1]; if (d < 0) d = -d; if (!(d <= 1e-4 * want[$1])) bad = 1 }
    END { exit (n != 5 || bad) }' "$tmp/modes"; then
    pass "modes: f_1..f_5 of docs/model.md 8"
else
    fail "modes: f_1..f_5 of docs/model.md 8" "$(cat "$tmp/modes")"
fi

# run: CSV headers identical to host/lib/run.c's
"$bin" run configs/fig6.ini --t-end 0.02 --out "$tmp/steps.csv" --every 10 --periods "$tmp/periods.csv" >"$tmp/json" 2>"$tmp/err"
status=$?
[ $status -eq 0 ] && pass "run exits 0" || fail "run exits 0" "status $status: $(cat "$tmp/err")"
want_steps=$(sed -n 's/^const char run_csv_header\[\] = "\(.*\)\\n";$/\1/p' host/lib/run.c)
want_periods=$(sed -n 's/^const char run_periods_header\[\] = "\(.*\)\\n";$/\1/p' host/lib/run.c)
[ -n "$want_steps" ] && [ "$(head -n 1 "$tmp/steps.csv")" = "$want_steps" ] \
    && pass "steps CSV header = host/lib/run.c's" || fail "steps CSV header = host/lib/run.c's" "$(head -n 1 "$tmp/steps.csv") vs $want_steps"
[ -n "$want_periods" ] && [ "$(head -n 1 "$tmp/periods.csv")" = "$want_periods" ] \
    && pass "periods CSV header = host/lib/run.c's" || fail "periods CSV header = host/lib/run.c's" "$(head -n 1 "$tmp/periods.csv") vs $want_periods"
rows=$(($(wc -l <"$tmp/steps.csv") - 1))
[ "$rows" -eq 101 ] && pass "steps CSV: t = 0 and every 10th of 1000 steps" || fail "steps CSV rows" "$rows rows, expected 101"
periods=$(($(wc -l <"$tmp/periods.csv") - 1))
[ "$periods" -eq 2 ] && pass "periods CSV: 2 periods of 124 Hz in 0.02 s" || fail "periods CSV rows" "$periods rows, expected 2"
for key in t_end steps s_final s_min amp_final_h wall_s max_iters; do
    grep -q "\"$key\":" "$tmp/json" || missing="$missing $key"
done
[ -z "${missing:-}" ] && pass "JSON summary keys" || fail "JSON summary keys" "missing:$missing in $(cat "$tmp/json")"

# bad input: exit 2 with a message
"$bin" run configs/fig6.ini --bogus 1 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "unknown option" "$tmp/err" && pass "unknown option: exit 2" || fail "unknown option: exit 2" "$(cat "$tmp/err")"
"$bin" run configs/fig6.ini --dt -1 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && pass "negative dt: exit 2" || fail "negative dt: exit 2" "$(cat "$tmp/err")"

echo "bs-reference CLI: $passed passed, $failed failed"
[ $failed -eq 0 ]
