#!/bin/sh
# check_cli.sh - the bs-reference command line: output formats equal to
# `beamslider run` (headers taken from host/lib/run/run.c), the transducer's
# columns and summary, --base-accel (a replayed harmonic equals the scene's;
# bad files are refused naming file and line), JSON keys, exit codes.
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

# run: CSV headers identical to host/lib/run/run.c's
"$bin" run configs/fig6.ini --t-end 0.02 --out "$tmp/steps.csv" --every 10 --periods "$tmp/periods.csv" >"$tmp/json" 2>"$tmp/err"
status=$?
[ $status -eq 0 ] && pass "run exits 0" || fail "run exits 0" "status $status: $(cat "$tmp/err")"
want_steps=$(sed -n 's/^const char run_csv_header\[\] = "\(.*\)\\n";$/\1/p' host/lib/run/run.c)
want_periods=$(sed -n 's/^const char run_periods_header\[\] = "\(.*\)\\n";$/\1/p' host/lib/run/run.c)
[ -n "$want_steps" ] && [ "$(head -n 1 "$tmp/steps.csv")" = "$want_steps" ] \
    && pass "steps CSV header = host/lib/run/run.c's" || fail "steps CSV header = host/lib/run/run.c's" "$(head -n 1 "$tmp/steps.csv") vs $want_steps"
[ -n "$want_periods" ] && [ "$(head -n 1 "$tmp/periods.csv")" = "$want_periods" ] \
    && pass "periods CSV header = host/lib/run/run.c's" || fail "periods CSV header = host/lib/run/run.c's" "$(head -n 1 "$tmp/periods.csv") vs $want_periods"
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

# transducer (docs/model.md 11): columns v, p, v_s and the harvested energy
printf '[scene]\nbase = %s/configs/fig6.ini\nname = fig6_resistor\n[transducer]\nload = resistor\n' "$(pwd)" >"$tmp/res.ini"
"$bin" run "$tmp/res.ini" --t-end 0.02 --out "$tmp/res.csv" --every 10 >"$tmp/json" 2>"$tmp/err"
[ "$(head -n 1 "$tmp/res.csv")" = "t,w_sensor,s,z_r,beta,contacts,pgs_iters,pgs_residual,v,p,v_s" ] \
    && grep -q '"load":"resistor"' "$tmp/json" && grep -q '"energy_load_j":' "$tmp/json" \
    && pass "resistor: CSV columns v,p,v_s and energy_load_j in the summary" \
    || fail "resistor: CSV columns v,p,v_s and energy_load_j in the summary" "$(head -n 1 "$tmp/res.csv"; cat "$tmp/json" "$tmp/err")"

# --base-accel: the harmonic's step means (docs/model.md 10: -a cos(W t_M) sin(W dt/2)/(W dt/2)) replayed
awk 'BEGIN { pi = atan2(0, -1); f = 124; a = 14; dt = 2e-5; x = pi * f * dt
             print "# fig6 excitation, mean per step, m/s^2"
             for (n = 0; n < 1000; n++) printf "%.17g\n", -a * sin(x) / x * cos(2 * pi * f * (n + 0.5) * dt) }' >"$tmp/accel.txt"
"$bin" run configs/fig6.ini --t-end 0.02 --out "$tmp/scene.csv" --every 1 >/dev/null 2>&1
"$bin" run configs/fig6.ini --t-end 0.02 --out "$tmp/replay.csv" --every 1 --base-accel "$tmp/accel.txt" >"$tmp/json" 2>"$tmp/err"
if [ $? -eq 0 ] && grep -q '"excitation":"replay"' "$tmp/json" && awk -F, 'FNR == 1 { next } NR == FNR { w[FNR] = $2; next }
        { d = $2 - w[FNR]; if (d < 0) d = -d; if (d > m) m = d; n++ } END { exit !(n == 1001 && m <= 1e-15) }' "$tmp/scene.csv" "$tmp/replay.csv"; then
    pass "--base-accel: the replayed harmonic gives the scene's run (|dw| <= 1e-15 m)"
else
    fail "--base-accel: the replayed harmonic gives the scene's run" "$(cat "$tmp/json" "$tmp/err")"
fi
"$bin" run configs/fig6.ini --t-end 0.021 --base-accel "$tmp/accel.txt" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "accel.txt:1001:.*1000 values.*1050" "$tmp/err" \
    && pass "--base-accel: too few values: exit 2, file, line and counts" || fail "--base-accel: too few values" "$(cat "$tmp/err")"
printf '1.0\n# comment\n2.5x\n' >"$tmp/bad.txt"
"$bin" run configs/fig6.ini --t-end 0.00004 --base-accel "$tmp/bad.txt" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "bad.txt:3: '2.5x'" "$tmp/err" \
    && pass "--base-accel: a bad number: exit 2 naming file and line" || fail "--base-accel: a bad number" "$(cat "$tmp/err")"
printf '1.0\nnan\n' >"$tmp/nan.txt"
"$bin" run configs/fig6.ini --t-end 0.00004 --base-accel "$tmp/nan.txt" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "nan.txt:2:" "$tmp/err" \
    && pass "--base-accel: NaN: exit 2 naming file and line" || fail "--base-accel: NaN" "$(cat "$tmp/err")"

echo "bs-reference CLI: $passed passed, $failed failed"
[ $failed -eq 0 ]
