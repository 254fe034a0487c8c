#!/bin/sh
# check_step_diff.sh COMPILED:RUNTIME[:TOLERANCE]... - runs each pair of
# step_diff builds (tests/embedded/step_diff.c: the core compiled for a
# scene, and the run-time core with the same scene as data). Without a
# TOLERANCE the outputs must be equal byte for byte: the same status and
# state hash after one step from each of 3000 states and every 1000 steps of
# a 20 000-step run. With one (a scene whose compiled core leaves friction
# out: the run-time core solves its contacts with tangential rows of mu = 0,
# another sequence of operations) each step from the 3000 states must end
# with the same status and the same contacts active, and every value of the
# state within TOLERANCE times that value's largest magnitude over the
# states; the run's statuses must agree.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for pair in "$@"; do
    compiled=${pair%%:*} rest=${pair#*:}
    runtime=${rest%%:*} tolerance=
    [ "$rest" != "$runtime" ] && tolerance=${rest#*:}
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
    if [ "$contacts" -le 500 ] || [ "$pairs" -le 50 ]; then
        echo "FAIL step_diff $name: too few states with contacts ($mix) to compare"; failed=1; continue
    fi
    if [ -z "$tolerance" ]; then
        if cmp -s "$tmp/c" "$tmp/r"; then
            echo "ok   step_diff $name: compiled and run-time steps equal bit for bit ($(grep -c '^state' "$tmp/c") states: one, two, more contacts $mix; $(grep -c '^run' "$tmp/c") run hashes)"
        else
            echo "FAIL step_diff $name: the compiled and the run-time step differ ($contacts states with contacts):"
            diff "$tmp/c" "$tmp/r" | head -n 4
            failed=1
        fi
        continue
    fi
    # value by value: field 9 on of a state line (after its hash)
    if verdict=$(paste -d '|' "$tmp/c" "$tmp/r" | awk -F'|' -v tol="$tolerance" '
        { nc = split($1, c, " "); nr = split($2, r, " ") }
        c[1] != r[1] || c[2] != r[2] || nc != nr { print "line " NR ": the outputs do not line up"; bad = 1; exit }
        c[1] == "run" && c[4] != r[4] { print "run step " c[2] ": status " c[4] " against " r[4]; bad = 1; exit }
        c[1] == "state" {
            if (c[4] != r[4] || c[6] != r[6]) { print "state " c[2] ": status/active " c[4] "/" c[6] " against " r[4] "/" r[6]; bad = 1; exit }
            ++states
            for (i = 9; i <= nc; ++i) {
                x = c[i] + 0; y = r[i] + 0
                d = x - y; if (d < 0) d = -d
                if (x < 0) x = -x
                if (x > scale[i]) scale[i] = x
                if (d > diff[i]) { diff[i] = d; where[i] = c[2] }
                if (d > 0 && !(c[2] in differ)) { differ[c[2]] = 1; ++n_differ }
            }
            if (nc > last) last = nc
        }
        END {
            if (bad) exit 1
            worst = 0
            for (i = 9; i <= last; ++i) if (scale[i] > 0 && diff[i] / scale[i] > worst) { worst = diff[i] / scale[i]; at = where[i] }
            printf "%d states, %d differ, the largest by %.2g of its value'"'"'s scale (state %s)", states, n_differ, worst, at
            exit !(worst <= tol)
        }'); then
        echo "ok   step_diff $name: compiled (no friction) and run-time (mu = 0) steps agree within $tolerance of scale: $verdict; same statuses and contacts (one, two, more $mix)"
    else
        echo "FAIL step_diff $name: beyond $tolerance of scale: $verdict"
        failed=1
    fi
done
exit $failed
