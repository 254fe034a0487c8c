#!/bin/sh
# check_step_diff.sh COMPILED:RUNTIME... - runs each pair of step_diff builds
# (tests/embedded/step_diff.c: the core compiled for a scene, and the
# run-time core with the same scene as data) and requires equal outputs, byte
# for byte: the same status and state hash after one step from each of 3000
# states and every 1000 steps of a 20 000-step run.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for pair in "$@"; do
    compiled=${pair%%:*} runtime=${pair#*:}
    name=$(basename "$compiled" .compiled)
    if ! "$compiled" > "$tmp/c" || ! "$runtime" > "$tmp/r"; then
        echo "FAIL step_diff $name: a build failed to run"; failed=1; continue
    fi
    # states by contacts active after the step: one, two, three or more
    mix=$(awk 'function bits(h,    v, i, c) { v = 0; for (i = 1; i <= length(h); ++i) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
                                               for (c = 0; v; v = int(v / 2)) c += v % 2; return c }
               $1 == "state" { c = bits($6); n[c > 3 ? 3 : c]++ }
               END { printf "%d %d %d", n[1], n[2], n[3] }' "$tmp/c")
    contacts=$(echo "$mix" | awk '{ print $1 + $2 + $3 }')
    pairs=$(echo "$mix" | awk '{ print $2 }')
    if cmp -s "$tmp/c" "$tmp/r" && [ "$contacts" -gt 500 ] && [ "$pairs" -gt 50 ]; then
        echo "ok   step_diff $name: compiled and run-time steps equal bit for bit ($(grep -c '^state' "$tmp/c") states: one, two, more contacts $mix; $(grep -c '^run' "$tmp/c") run hashes)"
    else
        echo "FAIL step_diff $name: the compiled and the run-time step differ ($contacts states with contacts):"
        diff "$tmp/c" "$tmp/r" | head -n 4
        failed=1
    fi
done
exit $failed
