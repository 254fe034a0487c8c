#!/bin/sh
# check_outputs.sh - text from the user in what beamslider writes (issue 26):
# scene names, descriptions, file names and options reach C headers, gnuplot
# scripts and JSON only through the one writer of each language
# (host/lib/out_c.h, out_gnuplot.h, out_json.h). Hostile names (a backquote,
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

check "nothing ran: no PWNED file" test ! -e PWNED -a ! -e "$tmp/PWNED"
echo "check_outputs: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
