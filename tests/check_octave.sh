#!/bin/sh
# check_octave.sh BEAMSLIDER MEXDIR PRECISION [short] - the Octave bridge
# (host/octave; `make test-octave`, which builds what it needs) against the CLI
# of the same precision, under octave-cli --norc --quiet:
#
#   BEAMSLIDER  build/REAL/beamslider (the CLI whose hashes are the reference)
#   MEXDIR      the folder of beamslider_mex.mex of that precision
#   short       skip the 60 s fig6 run (the other precision's pass)
#
# Checks (tests/octave/check_octave.m): beamslider_run's fig6 60 s hash is
# the one `beamslider run configs/fig6.ini` prints now (not a stored value),
# and a 2 s run at 120 Hz through 'set'; errors raised with the library's
# message (file:line, field, range); the stepping state: n steps in one call,
# in two halves through a .mat file and `clear beamslider_mex`, and measured steps, all
# the same state and the CLI's hash; a damaged state or one of another scene
# refused. Then (full pass only) every ```matlab block of docs/octave.md is
# run in order in one session, and the output of each one followed by a
# ```text block must be that text. Nothing is written into host/octave.
# shellcheck disable=SC2016 # Octave code in single quotes
set -u
. tests/check_lib.sh
check_setup "$0" "${1:-}"
cli=$1
mexdir=$(cd "${2:?usage: check_octave.sh BEAMSLIDER MEXDIR PRECISION [short]}" && pwd)
precision=${3:?usage: check_octave.sh BEAMSLIDER MEXDIR PRECISION [short]}
short_pass=${4:-}
root=$(pwd)
octave_run() {
    octave-cli --norc --quiet --no-history --eval "addpath('$root/host/octave', '$mexdir', '$root/tests/octave'); $1"
}

if ! command -v octave-cli >/dev/null 2>&1; then
    fail "octave-cli not found (Debian: apt-get install octave liboctave-dev)"
    exit 1
fi
hash_of() { sed -n 's/.*"hash":"\([0-9a-f]*\)".*/\1/p'; }
before=$(find host/octave -type f | sort | xargs cksum)

long=""
[ "$short_pass" = short ] || long=$("$cli" run configs/fig6.ini | hash_of)
short=$("$cli" run configs/fig6.ini --t-end 2 --set excitation.frequency=120 | hash_of)
if [ -z "$short" ] || { [ "$short_pass" != short ] && [ -z "$long" ]; }; then
    fail "the CLI's reference runs gave no hash"
    exit 1
fi
octave_run "check_octave('$precision', '$long', '$short', 2, '$tmp')" > "$tmp/check.out" 2>&1
status=$?
grep -E '^(ok  |FAIL) - ' "$tmp/check.out"
grep -v -E '^(ok  |FAIL) - ' "$tmp/check.out" > "$tmp/check.err"
passed=$((passed + $(grep -c '^ok   - ' "$tmp/check.out")))
failed=$((failed + $(grep -c '^FAIL - ' "$tmp/check.out")))
check_status "check_octave.m ($precision) finished" 0 "$status" "$tmp/check.err"

# docs/octave.md: its examples, run as a reader would, their printed output
if [ "$short_pass" != short ]; then
    awk -v dir="$tmp" '
        /^```matlab$/ { n++; code = 1; printf "fprintf(\"@@ %d\\n\");\n", n > (dir "/doc.m"); next }
        code && /^```$/ { code = 0; last = n; next }
        code { print > (dir "/doc.m"); next }
        /^```text$/ && last == n && n > 0 { text = 1; next }
        text && /^```$/ { text = 0; last = 0; next }
        text { print > (dir "/doc." n ".want"); next }
        /[^ ]/ { last = 0 }
        END { printf "fprintf(\"@@ end\\n\");\n" > (dir "/doc.m") }
    ' docs/octave.md
    octave_run "source('$tmp/doc.m')" > "$tmp/doc.out" 2>&1
    check_status "docs/octave.md: its examples run" 0 $? "$tmp/doc.out"
    awk -v dir="$tmp" '/^@@ / { block = $2; next } { print > (dir "/doc." block ".got") }' "$tmp/doc.out"
    examples=0
    for want in "$tmp"/doc.*.want; do
        [ -f "$want" ] || continue
        examples=$((examples + 1))
        got=${want%.want}.got
        block=${want#"$tmp"/doc.}
        [ -f "$got" ] || : > "$got"
        if cmp -s "$want" "$got"; then
            pass "docs/octave.md example ${block%.want}: prints the output it shows"
        else
            fail "docs/octave.md example ${block%.want}: prints the output it shows" "$(diff "$want" "$got")"
        fi
    done
    [ "$examples" -gt 0 ] || fail "docs/octave.md: no example with its output (a \`\`\`matlab block then \`\`\`text)"
fi

after=$(find host/octave -type f | sort | xargs cksum)
if [ "$before" = "$after" ]; then
    pass "nothing written into host/octave"
else
    fail "the tests wrote into host/octave" "$(printf '%s\n%s\n' "$before" "$after")"
fi

echo "check_octave.sh ($precision): $passed passed, $failed failed"
[ "$failed" -eq 0 ]
