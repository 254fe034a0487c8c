#!/bin/sh
# valgrind_cli.sh BEAMSLIDER - the command-line tool under valgrind memcheck
# (tests/robustness.mk: robustness-valgrind): a short run with both outputs,
# modes, gen, and the refusals (bad scene, bad option, /dev/full). Each must
# end with its documented exit status and no memcheck error or leak.
bin=$1
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

# vg DESCRIPTION EXPECTED-STATUS ARGS...
vg() {
    description=$1
    expected=$2
    shift 2
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible \
        --log-file="$tmp/vg.log" "$bin" "$@" >"$tmp/out" 2>"$tmp/err"
    status=$?
    if [ "$status" -eq "$expected" ] && [ ! -s "$tmp/vg.log" ]; then
        passed=$((passed + 1))
        echo "ok   - valgrind beamslider $description (exit $status)"
    else
        failed=$((failed + 1))
        echo "FAIL - valgrind beamslider $description: exit $status, expected $expected"
        cat "$tmp/vg.log" "$tmp/err"
    fi
}

cp configs/mssp2023.ini "$tmp/" || exit 1
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = nan\n' >"$tmp/bad.ini"
vg "run fig6 0.05 s with --out and --periods" 0 run configs/fig6.ini --t-end 0.05 --out "$tmp/a.csv" \
    --periods "$tmp/p.csv"
vg "run fig6 pcs 0.02 s" 0 run configs/fig6.ini --model pcs --t-end 0.02
vg "modes" 0 modes configs/fig6.ini
vg "gen" 0 gen configs/fig6_1mode.ini
vg "bad scene value" 2 run "$tmp/bad.ini"
vg "unknown option" 2 run configs/fig6.ini --bogus 1
vg "missing scene file" 2 run "$tmp/none.ini"
if [ -c /dev/full ]; then
    vg "--out /dev/full" 1 run configs/fig6.ini --t-end 0.05 --out /dev/full
fi
echo "valgrind_cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
