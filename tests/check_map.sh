#!/bin/sh
# check_map.sh - beamslider map, map-merge and --set on the command line
# (docs/maps.md): the same tables whatever the number of workers or shards,
# resume after a kill -9, refusal of another map's folder and of bad input
# (exit 2, nothing written), and fig6's outcome class (the papers' six
# scenarios are tests/check_scenarios.sh, in make test-long). Small maps of
# short runs, so that make test stays quick.
#
# usage, from the repository root:  sh tests/check_map.sh PATH/TO/beamslider

bin=${1:-}
. "$(dirname "$0")/check_lib.sh"
check_setup tests/check_map.sh "$bin"

# A small map: 3 frequencies x 2 levels x 2 repeats = 12 cases of 0.2 s.
small() { # small DIR [OPTIONS...]
    dir=$1
    shift
    "$bin" map configs/fig6.ini --set run.t_end=0.2 --vary excitation.frequency=120:124:2 \
        --vary excitation.acceleration=10,14 --repeat 2 "$@" --out "$dir"
}
# listing DIR: every file with its checksum (to see that nothing changed)
listing() { (cd "$1" && find . -type f | sort | xargs cksum); }

# ---- --set on run: checked like the file, echoed in the summary
"$bin" run configs/fig6.ini --set excitation.frequency=1.1e2 --set run.t_end=0.01 >"$tmp/o" 2>"$tmp/e"
check_status "run --set exits 0" 0 $? "$tmp/e"
check_has "the summary echoes the fields set" "$tmp/o" '"set":{"excitation.frequency":110,"run.t_end":0.01}'
check_has "the summary has the scene's hashes" "$tmp/o" '"fields_hash":"'
"$bin" run configs/fig6.ini --set excitation.frequency=abc >"$tmp/o" 2>"$tmp/e"
check_status "run --set with a bad value exits 2" 2 $? "$tmp/e"
check_has "a bad --set value is named as a file line would be" "$tmp/e" \
    "--set excitation.frequency=abc: [excitation] frequency = abc: not a number; allowed: a finite number in (0, inf) Hz"
"$bin" run configs/fig6.ini --set excitation.freq=1 >"$tmp/o" 2>"$tmp/e"
check_status "run --set of an unknown field exits 2" 2 $? "$tmp/e"
check_has "an unknown --set field is named" "$tmp/e" "--set excitation.freq=1: unknown field [excitation] freq"
"$bin" sweep configs/fig6.ini --dir up --out "$tmp/sweep.csv" --from 0.29 --to 0.3 --step 0.01 --hold 1 \
    --record 1 --set contact.friction=0.3 >"$tmp/o" 2>"$tmp/e"
check_status "sweep --set exits 0" 0 $? "$tmp/e"
check_has "the sweep summary echoes the fields set" "$tmp/o" '"set":{"contact.friction":0.3}'

# ---- the same tables with one worker, two workers, and three shards
small "$tmp/one" --jobs 1 >"$tmp/one.json" 2>"$tmp/e"
check_status "map --jobs 1 exits 0" 0 $? "$tmp/e"
check_has "map's summary says it is complete" "$tmp/one.json" '"complete":true'
check_has "map's summary counts the cases" "$tmp/one.json" '"cases":12,'
rows=$(($(wc -l <"$tmp/one/runs.csv") - 1))
if [ "$rows" -eq 12 ]; then pass "runs.csv has a row per case"; else fail "runs.csv has a row per case" "$rows rows"; fi
rows=$(($(wc -l <"$tmp/one/map.csv") - 1))
if [ "$rows" -eq 6 ]; then pass "map.csv has a row per grid point"; else fail "map.csv has a row per grid point" "$rows rows"; fi
small "$tmp/two" --jobs 2 >"$tmp/o" 2>"$tmp/e"
check_status "map --jobs 2 exits 0" 0 $? "$tmp/e"
check "--jobs 2 gives the same runs.csv as --jobs 1" cmp -s "$tmp/one/runs.csv" "$tmp/two/runs.csv"
check "--jobs 2 gives the same map.csv as --jobs 1" cmp -s "$tmp/one/map.csv" "$tmp/two/map.csv"
for i in 1 2 3; do # started together: they race to make the folder and its identity
    small "$tmp/shards" --jobs 1 --shard "$i/3" >"$tmp/shard$i.json" 2>"$tmp/shard$i.err" &
done
wait
check "three shards at once all exit 0" test -z "$(cat "$tmp"/shard*.err)"
check_has "a shard runs its share" "$tmp/shard2.json" '"shard":"2/3","shard_cases":4,'
"$bin" map-merge "$tmp/shards" >"$tmp/o" 2>"$tmp/e"
check_status "map-merge of the shards exits 0" 0 $? "$tmp/e"
check "three shards merge into the same runs.csv" cmp -s "$tmp/one/runs.csv" "$tmp/shards/runs.csv"
check "three shards merge into the same map.csv" cmp -s "$tmp/one/map.csv" "$tmp/shards/map.csv"
files=$(ls "$tmp/shards" | grep -c '^runs-.*\.csv$')
if [ "$files" -eq 3 ]; then pass "each shard appends to a file of its own"; else fail "each shard appends to a file of its own" "$files files"; fi

# ---- resume: the same command again skips what is done
small "$tmp/one" --jobs 2 >"$tmp/o" 2>"$tmp/e"
check_status "map again in a finished folder exits 0" 0 $? "$tmp/e"
check_has "map again runs nothing" "$tmp/o" '"skipped":12,"run":0,'

# ---- kill -9 mid-map, a torn last line, then resume: the same table
long="map configs/fig6.ini --set run.t_end=3 --vary excitation.frequency=118:129:1 --repeat 2 --jobs 2"
# shellcheck disable=SC2086
"$bin" $long --out "$tmp/whole" >"$tmp/o" 2>"$tmp/e"
check_status "the uninterrupted map exits 0" 0 $? "$tmp/e"
# shellcheck disable=SC2086
"$bin" $long --out "$tmp/killed" >"$tmp/o" 2>"$tmp/e" & # $! is the map itself
map_pid=$!
rows=0
for attempt in $(seq 1 200); do
    rows=$(cat "$tmp"/killed/runs-*.csv 2>/dev/null | grep -c -v '^case,')
    [ "$rows" -ge 4 ] && break
    sleep 0.05
done
kill -9 "$map_pid" 2>/dev/null
wait "$map_pid" 2>/dev/null
sleep 0.3 # the worker threads die with the process
rows=$(cat "$tmp"/killed/runs-*.csv | grep -c -v '^case,')
if [ "$rows" -ge 4 ] && [ "$rows" -lt 24 ]; then
    pass "kill -9 stopped the map midway ($rows of 24 cases done)"
else
    fail "kill -9 stopped the map midway" "$rows of 24 cases done"
fi
check "no merged table after the kill" test ! -e "$tmp/killed/runs.csv"
file=$(ls "$tmp"/killed/runs-*.csv | head -n 1)
printf '23,11,1,129,0.30001,ok,signat' >>"$file" # a row torn by the kill
# shellcheck disable=SC2086
"$bin" $long --out "$tmp/killed" >"$tmp/o" 2>"$tmp/e"
check_status "the map resumed after the kill exits 0" 0 $? "$tmp/e"
check_has "the resumed map skips the cases done" "$tmp/o" "\"skipped\":$rows,"
check_has "the resumed map ignores the torn line" "$tmp/o" '"torn_lines":1,'
check "the resumed map gives the uninterrupted one's runs.csv" cmp -s "$tmp/whole/runs.csv" "$tmp/killed/runs.csv"
check "the resumed map gives the uninterrupted one's map.csv" cmp -s "$tmp/whole/map.csv" "$tmp/killed/map.csv"

# ---- another map in the folder, bad input: exit 2, nothing written or lost
listing "$tmp/one" >"$tmp/before"
"$bin" map configs/fig6.ini --set run.t_end=0.2 --vary excitation.frequency=120:124:2 \
    --vary excitation.acceleration=10,14 --repeat 3 --out "$tmp/one" >"$tmp/o" 2>"$tmp/e"
check_status "a map with other repeats in the folder exits 2" 2 $? "$tmp/e"
check_has "it says what differs" "$tmp/e" "holds another map: its repeats (--repeat) is 2, this command's 3"
small "$tmp/one" --set contact.friction=0.3 >"$tmp/o" 2>"$tmp/e"
check_status "a map of another scene in the folder exits 2" 2 $? "$tmp/e"
check_has "it names the scene" "$tmp/e" "its scene (hash of its fields after --set)"
"$bin" map configs/fig6.ini --set run.t_end=0.2 --vary excitation.frequency=120:126:2 \
    --vary excitation.acceleration=10,14 --repeat 2 --out "$tmp/one" >"$tmp/o" 2>"$tmp/e"
check_status "a map with other values in the folder exits 2" 2 $? "$tmp/e"
check_has "it names the values" "$tmp/e" "the values of excitation.frequency differ: 3 values 120 .. 124 there, 4 values 120 .. 126"
listing "$tmp/one" >"$tmp/after"
check "the refused commands changed nothing in the folder" cmp -s "$tmp/before" "$tmp/after"
mkdir "$tmp/other" && echo x >"$tmp/other/notes.txt"
small "$tmp/other" >"$tmp/o" 2>"$tmp/e"
check_status "a folder with other files exits 2" 2 $? "$tmp/e"
check "... and is left as it was" test "$(ls "$tmp/other")" = notes.txt
bad() { # bad DESCRIPTION MESSAGE OPTIONS...: exit 2, MESSAGE, no folder
    description=$1
    message=$2
    shift 2
    "$bin" map configs/fig6.ini --set run.t_end=0.2 "$@" --out "$tmp/bad" >"$tmp/o" 2>"$tmp/e"
    check_status "$description exits 2" 2 $? "$tmp/e"
    check_has "$description: the message" "$tmp/e" "$message"
    check "$description: no folder made" test ! -e "$tmp/bad"
}
bad "an unknown --vary field" "--vary excitation.freq=1,2: unknown field excitation.freq" --vary excitation.freq=1,2
bad "an unknown --set field" "--set slider.colour=red: unknown field [slider] colour" --set slider.colour=red \
    --vary excitation.frequency=1,2
bad "an empty range" "empty range" --vary excitation.frequency=120:120:1
bad "an inverted range" "inverted range: FROM 130 is above TO 120" --vary excitation.frequency=130:120:1
bad "a shard index out of range" "--shard 5/4: shard index out of range; allowed: 1 to 4" \
    --vary excitation.frequency=120,124 --shard 5/4
bad "a value out of range" "[excitation] frequency = 0: out of range" --vary excitation.frequency=0,120
bad "a start outside the clamps" "cannot run" --vary run.s0=0.01,0.3
# counts from the input are checked before anything is allocated or checked
bad "a grid of more points than a map may have" \
    "--vary excitation.acceleration=1:1000:1: 1e+07 grid points with the fields varied before it, more than a map may have (at most 1000000 cases" \
    --vary excitation.frequency=1:10000:1 --vary excitation.acceleration=1:1000:1
bad "more cases than a map may have" "--repeat 1000: 100000 grid points times 1000 repeats, more than a map may have" \
    --vary excitation.frequency=1:100000:1 --repeat 1000
bad "a range of 1e300 / 1e-300 values" "inf values, at most 100000 a field" --vary excitation.frequency=1:1e300:1e-300

# ---- a large map shows its progress within seconds (on a terminal, as run
# does): 3000 grid points take some 15 s to check before the first case runs
if command -v script >/dev/null 2>&1; then
    cat >"$tmp/large.sh" <<EOF
exec "$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")" map "$(pwd)/configs/fig6.ini" --set run.t_end=0.01 \
    --vary excitation.frequency=100:399:1 --vary excitation.acceleration=1:10:1 --out "$tmp/large"
EOF
    timeout 10 script -qefc "sh '$tmp/large.sh'" "$tmp/large.tty" >/dev/null 2>&1 &
    large_pid=$!
    for attempt in $(seq 1 40); do # 2 s
        grep -q 'checking the cases' "$tmp/large.tty" 2>/dev/null && break
        sleep 0.05
    done
    kill "$large_pid" 2>/dev/null
    wait "$large_pid" 2>/dev/null
    check_has "a large map shows its progress within 2 s" "$tmp/large.tty" "map: checking the cases' scenes ["
else
    echo "check_map: the progress of a large map not checked: no script(1) for a terminal"
fi
"$bin" map-merge "$tmp/none" >"$tmp/o" 2>"$tmp/e"
check_status "map-merge of a folder without a map exits 2" 2 $? "$tmp/e"

# ---- a scene with a transducer: its harvested power in the tables
"$bin" map configs/fig6.ini --set transducer.load=resistor --set run.t_end=0.2 --vary excitation.frequency=120,124 \
    --vary excitation.acceleration=10,14 --jobs 2 --out "$tmp/power" >"$tmp/o" 2>"$tmp/e"
check_status "a map with a transducer exits 0" 0 $? "$tmp/e"
if report=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
                     !($c["power_w"] > 0 && $c["energy_j"] > 0) { print "case " $1 ": " $c["power_w"] ", " $c["energy_j"]; bad = 1 }
                     END { exit bad || NR != 5 }' "$tmp/power/runs.csv"); then
    pass "with a transducer every run has its power and energy"
else
    fail "with a transducer every run has its power and energy" "$report"
fi
check "without one they are nan" test "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "power_w") k = i }
    { print $k }' "$tmp/one/runs.csv" | sort -u | tr '\n' ' ')" = "nan power_w "

# ---- heatmaps (gnuplot: Debian's gnuplot-nox, which make maps installs)
if command -v gnuplot >/dev/null 2>&1; then
    "$bin" map-plot "$tmp/one" --mark 122,12,here --out "$tmp/plot" >"$tmp/o" 2>"$tmp/e"
    check_status "map-plot exits 0" 0 $? "$tmp/e"
    for figure in outcome agreement s_settled s_spread amp_h; do
        check "map-plot draws $figure" test -s "$tmp/plot_$figure.png"
    done
    check "map-plot draws no power figure without a transducer" test ! -e "$tmp/plot_power.png"
    check_has "map-plot's titles name the settled window the 0.2 s runs had" "$tmp/plot.gp" "mean s over the last 0.2 s"
    check "map-plot's titles never claim 10 s of 0.2 s runs" sh -c "! grep -q 'last 10 s' '$tmp/plot.gp'"
    "$bin" map-plot "$tmp/power" --out "$tmp/plot_t" >"$tmp/o" 2>"$tmp/e"
    check_status "map-plot of a map with a transducer exits 0" 0 $? "$tmp/e"
    check "... and draws its power" test -s "$tmp/plot_t_power.png"
    check_has "map-plot's grid has the six cells" "$tmp/plot.dat" "2 1 "
else
    echo "check_map: map-plot not checked: gnuplot is not installed (apt-get install gnuplot-nox)"
fi
"$bin" map-plot "$tmp/one" --mark 150,12,far --out "$tmp/plot" >"$tmp/o" 2>"$tmp/e"
check_status "map-plot with a mark off the map exits 2" 2 $? "$tmp/e"
# a table cut short or edited is refused with its line, and nothing drawn
damaged() { # damaged DESCRIPTION MESSAGE SED-SCRIPT|cut: map-plot of one's table so changed
    rm -rf "$tmp/damaged" "$tmp"/dplot*
    cp -r "$tmp/one" "$tmp/damaged"
    if [ "$3" = cut ]; then
        head -c -9 "$tmp/one/map.csv" >"$tmp/damaged/map.csv"
    else
        sed -i "$3" "$tmp/damaged/map.csv"
    fi
    "$bin" map-plot "$tmp/damaged" --out "$tmp/dplot" >"$tmp/o" 2>"$tmp/e"
    check_status "map-plot of a table $1 exits 2" 2 $? "$tmp/e"
    check_has "... naming the file and line" "$tmp/e" "$2"
    check "... and writes nothing" test -z "$(ls "$tmp" | grep '^dplot')"
}
damaged "cut mid-line" "map.csv:7: the last line is cut short" cut
damaged "without its last row" "map.csv: 1 of the map's 6 grid points have no row" '$d'
damaged "with a row twice" "map.csv:4: expected the row of grid point 2" '3p'
damaged "with a garbage row" "map.csv:3: 2 columns, the header has 25" '3s/.*/1,garbage/'
damaged "with a column cut off" "map.csv:2: 24 columns, the header has 25" '2s/,[^,]*$//'
damaged "with a column more" "map.csv:2: 26 columns, the header has 25" '2s/$/,1/'
damaged "with a number out of its range" "map.csv:3: column agreement is not a fraction in [0, 1]" '3s/,other,1,/,other,2,/'
damaged "with a number edited" "map.csv:2: column s_settled_mean is not a number" '2s/,\(0\.[0-9]*\),/,`touch PWNED`,/'
damaged "with another class" "map.csv:2: the outcome is not a class name" '2s/,other,/,another,/'
damaged "with other values" "map.csv:2: expected excitation.frequency = 120" '2s/^0,120,/0,121,/'
damaged "with another header" "map.csv:1: not the header of this map's table" '1s/^point/points/'
"$bin" map-plot "$tmp/whole" --out "$tmp/plot" >"$tmp/o" 2>"$tmp/e"
check_status "map-plot of a map of one varied field exits 2" 2 $? "$tmp/e"
check_has "... saying it needs two" "$tmp/e" "two different varied fields"

# ---- the outcome class of fig6 from its own start: the papers' signature move
# (a smoke of the classification; all six scenarios, 3 starts each, are
# tests/check_scenarios.sh in `make test-long`)
if [ -z "${ASAN_OPTIONS:-}" ]; then
    "$bin" map configs/fig6.ini --jobs 1 --out "$tmp/scene_fig6" >"$tmp/o" 2>"$tmp/e"
    got=$(tail -n 1 "$tmp/scene_fig6/map.csv" 2>/dev/null | cut -d, -f3)
    if [ "$got" = signature ]; then pass "fig6: signature"; else fail "fig6: signature" "got ${got:-nothing}; $(cat "$tmp/e")"; fi
fi

echo "check_map: $passed passed, $failed failed ($bin)"
[ "$failed" -eq 0 ]
