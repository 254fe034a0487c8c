#!/bin/sh
# check_cli.sh - the beamslider command line: output formats, exit codes and
# error messages (0 ok, 1 the work failed, 2 bad usage or input; host/cli/cli.h).
#
# usage, from the repository root:  sh tests/check_cli.sh PATH/TO/beamslider
# Prints one line per check and a summary; exits 1 if any check failed.

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_cli.sh "$bin"

# ---- modes: the five natural frequencies of docs/model.md 8 (Hz, as rounded there)
"$bin" modes configs/fig6.ini >"$tmp/modes.out" 2>"$tmp/modes.err"
check_status "modes configs/fig6.ini exits 0" 0 $? "$tmp/modes.err"
if report=$(awk '
    BEGIN { split("260.28 719.01 1412.3 2339.0 3500.1", want, " ") }
    $1 ~ /^[0-9]+$/ && NF >= 2 { ++n; got[$1 + 0] = $2 }
    END {
        if (n != 5) { printf "%d mode lines, expected 5\n", n; exit 1 }
        for (k = 1; k <= 5; ++k) {
            d = got[k] - want[k]
            if (d < 0) d = -d
            if (!(d <= 1e-4 * want[k])) { printf "mode %d: %s Hz, expected %s Hz\n", k, got[k], want[k]; bad = 1 }
        }
        exit bad
    }' "$tmp/modes.out"); then
    pass "modes: f_1..f_5 = 260.28, 719.01, 1412.3, 2339.0, 3500.1 Hz (relative 1e-4)"
else
    fail "modes: f_1..f_5 = 260.28, 719.01, 1412.3, 2339.0, 3500.1 Hz (relative 1e-4)" "$report"
fi

# ---- run: CSV and JSON summary
csv="$tmp/fig6.csv"
"$bin" run configs/fig6.ini --t-end 0.2 --out "$csv" --every 10 >"$tmp/run.json" 2>"$tmp/run.err"
check_status "run fig6 --t-end 0.2 --every 10 exits 0" 0 $? "$tmp/run.err"
if [ -f "$csv" ]; then pass "run writes the --out file"; else fail "run writes the --out file"; fi
touch "$csv"
header=$(head -n 1 "$csv")
if [ "$header" = "t,w_sensor,s,z_c,beta,contacts,pgs_iters,pgs_residual" ]; then
    pass "CSV header"
else
    fail "CSV header" "got: $header"
fi
rows=$(($(wc -l <"$csv") - 1))
if [ "$rows" -eq 1001 ]; then
    pass "CSV has 1001 data rows (steps 0, 10, ..., 10000)"
else
    fail "CSV has 1001 data rows (steps 0, 10, ..., 10000)" "got $rows"
fi
if report=$(awk -F, 'NF != 8 { printf "line %d has %d fields\n", NR, NF; ++bad } END { exit NR < 2 || bad > 0 }' "$csv"); then
    pass "every CSV line has 8 fields"
else
    fail "every CSV line has 8 fields" "$report"
fi
# row i is step 10 i of dt = 2e-5 s: t = i * 2e-4 s
if report=$(awk -F, 'NR > 1 { want = (NR - 2) * 2e-4; d = $1 - want; if (d < 0) d = -d
                               if (!(d <= 1e-9)) { printf "line %d: t = %s, expected %.6f\n", NR, $1, want; ++bad } }
                     END { exit NR < 2 || bad > 0 }' "$csv"); then
    pass "CSV times are 0, 2e-4, ..., 0.2 s"
else
    fail "CSV times are 0, 2e-4, ..., 0.2 s" "$(printf '%s\n' "$report" | head -n 3)"
fi
json_lines=$(wc -l <"$tmp/run.json")
if [ "$json_lines" -eq 1 ] && grep -q '^{.*}$' "$tmp/run.json"; then
    pass "stdout is one line of JSON"
else
    fail "stdout is one line of JSON" "$(head -c 400 "$tmp/run.json")"
fi
missing=
for key in t_end steps s_final amp_final_h wall_s steps_per_s max_pgs_iters unconverged_steps; do
    grep -q "\"$key\":" "$tmp/run.json" || missing="$missing $key"
done
if [ -z "$missing" ]; then pass "JSON summary has its keys"; else fail "JSON summary has its keys" "missing:$missing"; fi
if grep -q '"steps":10000[,}]' "$tmp/run.json"; then
    pass "JSON steps = 10000"
else
    fail "JSON steps = 10000" "$(cat "$tmp/run.json")"
fi

# ---- the summary escapes the scene name (it comes from the file name when
# [scene] name is not set, and a file name may hold quotes and backslashes)
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
printf '[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n[run]\ns0 = 0.3\nt_end = 0.001\n' \
    >"$tmp/q\"b\\c.ini"
"$bin" run "$tmp/q\"b\\c.ini" >"$tmp/name.json" 2>"$tmp/name.err"
check_status "run of a scene whose file name holds a quote and a backslash exits 0" 0 $? "$tmp/name.err"
check_has "the summary escapes the quote and the backslash of the name" "$tmp/name.json" '{"scene":"q\"b\\c","model"'

# ---- bad usage: exit 2 and a message on stderr
"$bin" run configs/fig6.ini --bogus 1 >"$tmp/o" 2>"$tmp/e"
check_status "unknown option exits 2" 2 $? "$tmp/e"
check_has "unknown option is named on stderr" "$tmp/e" "--bogus"
"$bin" run configs/fig6.ini --t-end >"$tmp/o" 2>"$tmp/e"
check_status "option without a value exits 2" 2 $? "$tmp/e"
check_has "option without a value is named on stderr" "$tmp/e" "--t-end"
"$bin" frobnicate >"$tmp/o" 2>"$tmp/e"
check_status "unknown command exits 2" 2 $? "$tmp/e"
check "unknown command prints a message on stderr" test -s "$tmp/e"

# ---- bad scene: exit 2, file:line named, no output file
cp configs/mssp2023.ini "$tmp/mssp2023.ini"
cat >"$tmp/bad.ini" <<'EOF'
[scene]
base = mssp2023.ini
[excitation]
frequency = 124
acceleration = 14
[contact]
restitution = 1.5
[run]
s0 = 0.3
t_end = 0.2
EOF
"$bin" run "$tmp/bad.ini" --out "$tmp/bad.csv" >"$tmp/o" 2>"$tmp/e"
check_status "out-of-range scene value exits 2" 2 $? "$tmp/e"
check_has "bad scene message names file:line" "$tmp/e" "$tmp/bad.ini:7:"
check_has "bad scene message names [contact] restitution" "$tmp/e" "[contact] restitution"
if [ -e "$tmp/bad.csv" ]; then fail "bad scene creates no --out file"; else pass "bad scene creates no --out file"; fi

# ---- dt above the explicit limit: exit 2, no output file
"$bin" run configs/fig6.ini --dt 1e-4 --out "$tmp/dt.csv" >"$tmp/o" 2>"$tmp/e"
check_status "--dt 1e-4 exits 2" 2 $? "$tmp/e"
check_has "--dt 1e-4 message mentions the explicit limit" "$tmp/e" "explicit limit"
check_has "--dt 1e-4 message names the option" "$tmp/e" "--dt"
if [ -e "$tmp/dt.csv" ]; then fail "--dt 1e-4 creates no --out file"; else pass "--dt 1e-4 creates no --out file"; fi

# ---- output that cannot be written: exit 1 and a message
"$bin" run configs/fig6.ini --t-end 0.01 --out "$tmp/no/such/dir/x.csv" >"$tmp/o" 2>"$tmp/e"
check_status "--out into a missing folder exits 1" 1 $? "$tmp/e"
check_has "--out into a missing folder names the file" "$tmp/e" "$tmp/no/such/dir/x.csv"
if [ -c /dev/full ]; then
    "$bin" run configs/fig6.ini --t-end 0.2 --out /dev/full >"$tmp/o" 2>"$tmp/e"
    check_status "--out /dev/full exits 1" 1 $? "$tmp/e"
    check_has "--out /dev/full message names the file" "$tmp/e" "/dev/full"
    # past the "beamslider: error:" prefix every message has
    if sed 's/^beamslider: error: //' "$tmp/e" | grep -q -i -e failed -e error; then
        pass "--out /dev/full message says failed/error"
    else
        fail "--out /dev/full message says failed/error" "$(cat "$tmp/e")"
    fi
else
    echo "skip - --out /dev/full (no /dev/full here)"
fi

# ---- gen prints text from the scene file as escaped string literals only:
# a description that would close a comment and inject code, quotes, a
# backslash and trigraph question marks come back as they were written
cat > "$tmp/evil.ini" <<EOF
[scene]
base = $(pwd)/configs/fig6_1mode.ini
name = evil"na\me??/
description = */ int injected = 1; /* "quoted" ??= back\slash
EOF
if "$bin" gen "$tmp/evil.ini" > "$tmp/evil.h" 2>"$tmp/e"; then
    pass "gen of a scene with hostile text exits 0"
else
    fail "gen of a scene with hostile text exits 0" "$(cat "$tmp/e")"
fi
cat > "$tmp/evil.c" <<'EOF'
#include <stdio.h>
#include "beamslider.h"
#include "evil.h"
int main(void) { printf("%s\n%s\n", BS_SCENE_NAME, BS_SCENE_DESCRIPTION); return bs_compiled_scene.n_modes != 1; }
EOF
if ${CC:-cc} -std=c99 -Wall -Wextra -Werror -I"$(dirname "$bin")/include" -Icore/include -I"$tmp" \
       -o "$tmp/evil" "$tmp/evil.c" 2>"$tmp/e" && "$tmp/evil" > "$tmp/o"; then
    pass "the header of a scene with hostile text compiles and holds its scene"
else
    fail "the header of a scene with hostile text compiles and holds its scene" "$(cat "$tmp/e")"
fi
printf '%s\n%s\n' 'evil"na\me??/' '*/ int injected = 1; /* "quoted" ??= back\slash' > "$tmp/want"
if cmp -s "$tmp/o" "$tmp/want"; then
    pass "name and description come back unchanged from the header"
else
    fail "name and description come back unchanged from the header" "$(cat "$tmp/o")"
fi

# ---- version and field reference
"$bin" --version >"$tmp/o" 2>"$tmp/e"
check_status "--version exits 0" 0 $? "$tmp/e"
check_has "--version names the version" "$tmp/o" "beamslider $(sed -n 's/^#define BS_VERSION_STRING "\(.*\)"/\1/p' core/include/beamslider.h) (revision "
"$bin" fields extra >"$tmp/o" 2>"$tmp/e"
check_status "fields with an argument exits 2" 2 $? "$tmp/e"

echo "check_cli: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
