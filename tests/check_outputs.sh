#!/bin/sh
# check_outputs.sh - text from the user in what beamslider writes (issue 26):
# scene names, descriptions, file names and options reach C headers, gnuplot
# scripts and JSON only through the one writer of each language
# (host/lib/io/out_c.h, out_gnuplot.h, out_json.h). Hostile names (a backquote,
# an @, quotes, a line break, a comment's end, a backslash) go through gen,
# twin-gains and map-plot; the results are read by the real C compiler,
# gnuplot and a JSON parser, which must see the text as given and nothing
# run. Small scenes and short runs: a second or two in all.
#
# usage, from the repository root:  sh tests/check_outputs.sh PATH/TO/beamslider

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_outputs.sh "$bin"
include=$(dirname "$bin")/include
bin_abs=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin") # for commands run in $tmp
cc=${CC:-cc}

# The hostile name: every way out of a C comment or string, a gnuplot string
# or a JSON string the old writers left open.
name='x */ int injected = 42; /* m`touch PWNED`x @m "q" '"'s"' \ ??/ end'
hostile() { # hostile FILE [NAME]: a one-mode fig6 of 0.01 s named NAME
    cat >"$1" <<EOF
[scene]
base = $(pwd)/configs/fig6_1mode.ini
name = ${2:-$name}
description = d */ "q" \\ ??= \`touch PWNED\`
[run]
t_end = 0.01
[numerics]
dt = 1e-4
EOF
}
hostile "$tmp/hostile.ini"

# ---- C headers: gen and twin-gains
"$bin" gen "$tmp/hostile.ini" >"$tmp/scene.h" 2>"$tmp/e"
check_status "gen of a scene with a hostile name exits 0" 0 $? "$tmp/e"
cat >"$tmp/scene.c" <<'EOF'
#include <stdio.h>
#include "beamslider.h"
#include "scene.h"
static int injected = 1; /* a second definition if the header injected one */
int main(void) { printf("%s\n", BS_SCENE_NAME); return injected - 1; }
EOF
if $cc -std=c99 -Wall -Wextra -Werror -Wcomment -Wtrigraphs -I"$include" -Icore/include -I"$tmp" \
       -o "$tmp/scene" "$tmp/scene.c" 2>"$tmp/e" && "$tmp/scene" >"$tmp/o"; then
    pass "gen: the header compiles, nothing injected"
else
    fail "gen: the header compiles, nothing injected" "$(cat "$tmp/e")"
fi
printf '%s\n' "$name" >"$tmp/want"
check "gen: BS_SCENE_NAME is the name as given" cmp -s "$tmp/o" "$tmp/want"

# a name with a line break (the default name is the file's: any byte but /)
nl='
'
cp "$tmp/hostile.ini" "$tmp/line${nl}break *.ini"
sed -i '/^name = /d' "$tmp/line${nl}break *.ini"
"$bin" gen "$tmp/line${nl}break *.ini" >"$tmp/scene.h" 2>"$tmp/e"
check_status "gen of a scene whose file name has a line break exits 0" 0 $? "$tmp/e"
if $cc -std=c99 -Wall -Wextra -Werror -I"$include" -Icore/include -I"$tmp" -o "$tmp/scene" "$tmp/scene.c" \
       2>"$tmp/e" && "$tmp/scene" >"$tmp/o"; then
    pass "gen: the header of that scene compiles"
else
    fail "gen: the header of that scene compiles" "$(cat "$tmp/e")"
fi
printf 'line\nbreak *\n' >"$tmp/want"
check "gen: its BS_SCENE_NAME holds the line break" cmp -s "$tmp/o" "$tmp/want"

"$bin" twin-gains "$tmp/hostile.ini" --noise 1e-7 >"$tmp/gains.h" 2>"$tmp/e"
check_status "twin-gains of a scene with a hostile name exits 0" 0 $? "$tmp/e"
cat >"$tmp/gains.c" <<'EOF'
#include "gains.h"
static int injected = 1;
int main(void) { return injected - 1 + (bs_observer_gains_scene.n_modes != 1); }
EOF
if $cc -std=c99 -Wall -Wextra -Werror -Wcomment -Wtrigraphs -I"$include" -Icore/include -I"$tmp" \
       -o "$tmp/gains" "$tmp/gains.c" 2>"$tmp/e" && "$tmp/gains"; then
    pass "twin-gains: the header compiles, nothing injected"
else
    fail "twin-gains: the header compiles, nothing injected" "$(head -c 600 "$tmp/e")"
fi
head -n 1 "$tmp/gains.h" >"$tmp/gains.head"
check_has "twin-gains: the name is in the comment, escaped" "$tmp/gains.head" \
    '/* x *\/ int injected = 42; /\* m`touch PWNED`x @m "q" '"'s"' \134 ?\?/ end: signal deflection'
for bad in 'x */ int injected = 42; /*' 1abc int class __x '' "a${nl}b" \
    A234567890123456789012345678901234567890123456789012345678901234; do
    "$bin" twin-gains "$tmp/hostile.ini" --noise 1e-7 --name "$bad" >"$tmp/o" 2>"$tmp/e"
    status=$?
    if [ "$status" -eq 2 ] && [ ! -s "$tmp/o" ] && grep -q -e '--name .*allowed: a C identifier' -e '--name: character' "$tmp/e"; then
        pass "twin-gains --name '$bad' is refused (exit 2, nothing written)"
    else
        fail "twin-gains --name '$bad' is refused (exit 2, nothing written)" "exit $status; $(cat "$tmp/e")"
    fi
done
"$bin" twin-gains "$tmp/hostile.ini" --noise 1e-7 --name gains_fig6 >"$tmp/o" 2>"$tmp/e"
check_status "twin-gains --name gains_fig6 exits 0" 0 $? "$tmp/e"
check_has "... and declares it" "$tmp/o" "static const bs_observer_gains gains_fig6 = {"

# ---- JSON: every command's summary, read by a strict parser (one line,
# UTF-8, no NaN or Infinity), with the name as given and null for a number
# that is not finite
# json_check DESCRIPTION FILE [KEY=JSON | KEY~TEXT ...]: FILE must be one JSON
# line with those members (~: a text as given). The checks are collected and
# run by one python at the end (python starts slowly).
json_checks=0
json_check() {
    json_checks=$((json_checks + 1))
    cp "$2" "$tmp/json.$json_checks.out"
    description=$1
    shift 2
    printf '%s\0' "$description" "$@" >"$tmp/json.$json_checks.args"
}
json_run_checks() { # prints ok/FAIL lines as pass and fail do, then counts them in
    cat >"$tmp/json_check.py" <<'EOF'
import json, sys
def constant(name):
    raise ValueError("not JSON: " + name)
def check(out, pairs):
    text = open(out, "rb").read().decode("utf-8")
    lines = text.split("\n")
    if len(lines) != 2 or lines[1] != "":
        return "not one line: %r" % text[:300]
    try:
        summary = json.loads(lines[0], parse_constant=constant)
    except ValueError as e:
        return "%s: %s" % (e, text[:300])
    for pair in pairs:
        if "~" in pair and ("=" not in pair or pair.index("~") < pair.index("=")):
            key, want = pair.split("~", 1)
        else:
            key, want = pair.split("=", 1)
            want = json.loads(want)
        if key not in summary or summary[key] != want:
            return "%s: %r, expected %r" % (key, summary.get(key, "(none)"), want)
    return None
for n in range(1, int(sys.argv[2]) + 1):
    base = "%s/json.%d" % (sys.argv[1], n)
    args = open(base + ".args", "rb").read().decode("utf-8", "surrogateescape").split("\0")[:-1]
    try:
        why = check(base + ".out", args[1:])
    except UnicodeDecodeError as e:
        why = "not UTF-8: %s" % e
    print("ok   - %s" % args[0] if why is None else "FAIL - %s\n       %s" % (args[0], why))
EOF
    python3 "$tmp/json_check.py" "$tmp" "$json_checks" >"$tmp/json_report" 2>&1
    cat "$tmp/json_report"
    passed=$((passed + $(grep -c '^ok' "$tmp/json_report")))
    failed=$((failed + $(grep -c '^FAIL' "$tmp/json_report")))
    [ "$(grep -c -e '^ok' -e '^FAIL' "$tmp/json_report")" -eq "$json_checks" ] || fail "the JSON checks ran"
}


"$bin" run "$tmp/hostile.ini" >"$tmp/o" 2>"$tmp/e"
check_status "run of the hostile scene exits 0" 0 $? "$tmp/e"
json_check "run: the summary is JSON with the name as given" "$tmp/o" "scene~$name"
"$bin" sweep "$tmp/hostile.ini" --dir up --out "$tmp/sweep.csv" --from 0.29 --to 0.3 --step 0.01 --hold 1 \
    --record 1 >"$tmp/o" 2>"$tmp/e"
check_status "sweep of the hostile scene exits 0" 0 $? "$tmp/e"
json_check "sweep: the summary is JSON with the name as given" "$tmp/o" "scene~$name"
# a folder whose name holds a quote and a byte that is no UTF-8 (Latin-1)
dir="$tmp/map \"$(printf '\377')"
"$bin" map "$tmp/hostile.ini" --vary excitation.frequency=120,124 --vary excitation.acceleration=10,14 --jobs 1 \
    --out "$dir" >"$tmp/o" 2>"$tmp/e"
check_status "map of the hostile scene exits 0" 0 $? "$tmp/e"
json_check "map: the summary is JSON (the folder's byte 0xff as U+FFFD)" "$tmp/o" "scene~$name" \
    "out~$tmp/map \"$(printf '\357\277\275')" complete=true
"$bin" map-merge "$dir" >"$tmp/o" 2>"$tmp/e"
check_status "map-merge of it exits 0" 0 $? "$tmp/e"
json_check "map-merge: the summary is JSON with the name as given" "$tmp/o" "scene~$name" \
    'command="map-merge"' cases=4 complete=true
"$bin" twin-plant "$tmp/hostile.ini" --snr 40 --out "$tmp/plant.csv" >"$tmp/o" 2>"$tmp/e"
check_status "twin-plant of the hostile scene exits 0" 0 $? "$tmp/e"
json_check "twin-plant: the summary is JSON with the name as given" "$tmp/o" "plant~$name" steps=100
"$bin" twin "$tmp/hostile.ini" --measured "$tmp/plant.csv" --out "$tmp/est.csv" --score-after 100 \
    >"$tmp/o" 2>"$tmp/e"
check_status "twin on it exits 0" 0 $? "$tmp/e"
json_check "twin: the summary is JSON, nothing scored is null" "$tmp/o" "scene~$name" within=null rms_s_error=null
"$bin" twin-plant "$tmp/hostile.ini" --t-end 1e-9 --out "$tmp/plant0.csv" >"$tmp/o" 2>"$tmp/e"
if [ $? -eq 2 ]; then # a run of no step may be refused as such
    pass "twin-plant of no step is refused"
else
    json_check "twin-plant of no step: the summary is JSON, its NaN RMS null" "$tmp/o" signal_rms=null
fi
# a name with a line break in a line-based file: one line still
hostile "$tmp/twoline.ini"
cp "$tmp/twoline.ini" "$tmp/two${nl}# sample_rate = 1 Hz.ini"
sed -i '/^name = /d' "$tmp/two${nl}# sample_rate = 1 Hz.ini"
"$bin" twin-plant "$tmp/two${nl}# sample_rate = 1 Hz.ini" --out "$tmp/plant2.csv" >"$tmp/o" 2>"$tmp/e"
check_status "twin-plant of a scene named with a line break exits 0" 0 $? "$tmp/e"
check "... and forges no header line" test "$(grep -c '^# sample_rate' "$tmp/plant2.csv")" -eq 1
"$bin" modes "$tmp/two${nl}# sample_rate = 1 Hz.ini" >"$tmp/o" 2>"$tmp/e"
check_status "modes of it exits 0" 0 $? "$tmp/e"
check "... its table's first line is one line" test "$(grep -c '^# ' "$tmp/o")" -eq "$("$bin" modes "$tmp/hostile.ini" | grep -c '^# ')"

# ---- gnuplot: map-plot of that map (its name from the folder's identity),
# with a hostile --title and --mark label, in a folder named with a quote
if command -v gnuplot >/dev/null 2>&1; then
    (cd "$tmp" && "$bin_abs" map-plot "$dir" --mark '122,12,l`touch PWNED`'"'x @m" >"$tmp/o" 2>"$tmp/e")
    check_status "map-plot of the hostile map exits 0" 0 $? "$tmp/e"
    check "map-plot: it draws the outcome" test -s "$dir/plot_outcome.png"
    # gnuplot itself reads each title back: "set title X" printed as "print X"
    title_of() { # title_of SCRIPT: the first figure's title as gnuplot reads it
        grep '^set title ' "$1" | head -n 1 | sed 's/^set title /print /' >"$tmp/title.gp"
        (cd "$tmp" && gnuplot "$tmp/title.gp" 2>&1)
    }
    printf '%s\n%s\n' "$name" "outcome class: the class most starts ended in (1 start per point)" >"$tmp/want"
    title_of "$dir/plot.gp" >"$tmp/o"
    check "map-plot: gnuplot reads the title as the scene's name, as given" cmp -s "$tmp/o" "$tmp/want"
    check_has "map-plot: the label is one string" "$dir/plot.gp" "set label 1 'l\`touch PWNED\`''x @m' at "
    (cd "$tmp" && "$bin_abs" map-plot "$dir" --title "t\`touch PWNED\`'@m \$HOME \\${nl}second" --out "$tmp/t" \
        >"$tmp/o" 2>"$tmp/e")
    check_status "map-plot --title with a backquote, a quote and a line break exits 0" 0 $? "$tmp/e"
    printf '%s\n%s\n' "t\`touch PWNED\`'@m \$HOME \\?second" \
        "outcome class: the class most starts ended in (1 start per point)" >"$tmp/want"
    title_of "$tmp/t.gp" >"$tmp/o"
    check "map-plot: gnuplot reads --title as given (the line break as ?)" cmp -s "$tmp/o" "$tmp/want"
    # gnuplot away: said so, nothing written
    (cd "$tmp" && PATH=/nonexistent "$bin_abs" map-plot "$dir" --out "$tmp/nognuplot" >"$tmp/o" 2>"$tmp/e")
    check_status "map-plot without gnuplot exits 1" 1 $? "$tmp/e"
    check_has "... saying gnuplot is not installed" "$tmp/e" "gnuplot is not installed (no gnuplot on PATH"
    check "... and writes nothing" test -z "$(ls "$tmp" | grep nognuplot)"
else
    echo "check_outputs: map-plot not checked: gnuplot is not installed (apt-get install gnuplot-nox)"
fi
"$bin" map-plot "$dir" --out "$tmp/pic${nl}x" >"$tmp/o" 2>"$tmp/e"
check_status "map-plot --out with a line break exits 2" 2 $? "$tmp/e"
check "... and writes nothing" test -z "$(ls "$tmp" | grep "^pic")"
# the identity edited: a control character in the name is refused with its line
sed -i 's/^info scene = .*/info scene = x\x01y/' "$dir/map-identity.txt"
"$bin" map-plot "$dir" --out "$tmp/edited" >"$tmp/o" 2>"$tmp/e"
check_status "map-plot of an identity edited to hold a control character exits 2" 2 $? "$tmp/e"
check_has "... naming the file and line" "$tmp/e" "map-identity.txt:12: a control character"

json_run_checks
check "nothing ran: no PWNED file" test ! -e PWNED -a ! -e "$tmp/PWNED" -a ! -e "$dir/PWNED"
echo "check_outputs: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
