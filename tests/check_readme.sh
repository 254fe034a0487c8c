#!/bin/sh
# check_readme.sh - every command README.md shows in its ```sh blocks, run as a
# newcomer runs it: from a fresh copy of the tree (the files a clone has, no build/
# but build/beamslider, the double CLI `make` builds), in the README's order, each
# exiting 0; and the example JSON of `make run` is what `make run` prints now (the
# same keys in the same order, the same values but wall_s, steps_per_s and revision).
# Part of `make test` (make docs-test; after test-one has built the CLI) without
# the commands that design an observer (twin, twin-gains: 3-9 CPU-s each, about
# 18 CPU-s together on an Intel Xeon @ 2.8 GHz), which it names as skipped;
# with --long (make readme-long, part of `make test-long`) every command.
#
# How each command is run (a command the rules below do not name is run as it is):
#   make run          the beamslider command its recipe runs (the Makefile's `run:`;
#                     the build `make` does is test-one's), its JSON compared
#   make test         not run (it cannot run itself)
#   make TARGET=...   a dry run (make -n) in the copy: the goal and the knobs are
#                     accepted; make test builds and runs such images (embedded-test)
#   make install, export PKG_CONFIG_PATH, cc ... app.c, ./app
#                     the library example: tests/check_consumer.sh builds and runs it
#                     from the installed tree (make consumer-test), not duplicated here
#   sbatch ...        Slurm: tests/slurm (make test-long, as root)
#   a synopsis        (a line with [--option ...]): every --option it names is in
#                     that command's --help
#   sensor | ...      the live stream from a file: cat measured.csv | ...
# and, so that the runs take milliseconds, with the words of the command kept:
#   run               --t-end 0.02 appended (none of the README's runs sets one)
#   sweep             --from 0.29 --to 0.3 --step 0.01 --hold 1 --record 1 appended
#   map               the README's map is the operating map of `make maps` (1530
#                     runs of 120 s, README "Reports"): each --vary keeps its first
#                     two values and --set run.t_end=0.002 is appended
#   twin-plant        --t-end 0.05 appended
long=0
[ "${1:-}" = --long ] && long=1
. tests/check_lib.sh
check_setup tests/check_readme.sh build/double/beamslider

# designs_observer COMMAND: true when COMMAND runs the observer's design
designs_observer() {
    case $1 in
    "build/beamslider twin "* | "build/beamslider twin-gains "* | "sensor | build/beamslider twin "*) return 0 ;;
    esac
    return 1
}

# the copy: what a clone holds (tracked files and new ones not ignored), no build/
clone=$tmp/clone
mkdir -p "$clone/build"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files --cached --others --exclude-standard | tar -cf - -T - 2>/dev/null | (cd "$clone" && tar -xf -)
else
    tar -cf - --exclude=./build . | (cd "$clone" && tar -xf -)
fi
cp build/double/beamslider "$clone/build/beamslider"

# README's shell commands, one per line: continuation lines joined (a trailing
# backslash, or an indented line of a synopsis), comments removed
awk '/^```sh$/ { block = 1; next }
     /^```/ { if (block && cmd != "") print cmd; block = 0; cmd = ""; next }
     !block { next }
     { line = $0; sub(/[ \t]+#.*$/, "", line) }
     cmd != "" && (joined || line ~ /^[ \t]/) { sub(/^[ \t]+/, " ", line); cmd = cmd line }
     cmd != "" && !(joined || $0 ~ /^[ \t]/) { print cmd; cmd = line }
     cmd == "" { cmd = line }
     { joined = sub(/[ \t]*\\$/, "", cmd) }' README.md > "$tmp/commands"
count=$(wc -l < "$tmp/commands")
if [ "$count" -ge 20 ]; then pass "README.md shows $count commands"; else fail "README.md shows $count commands (expected 20 or more)" "$(cat "$tmp/commands")"; fi

# run NAME COMMAND: COMMAND in the copy must exit 0
run() {
    (cd "$clone" && sh -c "$2" < /dev/null) > "$tmp/out" 2> "$tmp/err"
    check_status "$1" 0 $? "$tmp/err"
}
# json_fields FILE -> "key value" per field of a one-line JSON object (an object
# inside it is one value)
json_fields() {
    awk '{ s = $0; sub(/^[^{]*\{/, "", s); sub(/\}[^}]*$/, "", s)
           depth = 0; field = ""
           for (i = 1; i <= length(s); ++i) {
               c = substr(s, i, 1)
               if (c == "{") depth++
               if (c == "}") depth--
               if (c == "," && depth == 0) { out(field); field = ""; continue }
               field = field c
           }
           out(field) }
         function out(f,   k) { k = f; sub(/:.*/, "", k); gsub(/"/, "", k); sub(/^[^:]*:/, "", f); print k, f }' "$1"
}

while IFS= read -r command; do
    if [ "$long" = 0 ] && designs_observer "$command"; then
        echo "skip - $command (designs an observer: make readme-long, part of make test-long)"
        continue
    fi
    case $command in
    "make test")
        echo "skip - $command (it cannot run itself)" ;;
    "make run")
        wrapped=$(sed -n '/^run:/,/^[^\t]/p' Makefile | sed -n 's/^\t\(\$(BUILD)\/beamslider run .*\)/\1/p' | sed 's/\$(BUILD)/build/g')
        if [ -z "$wrapped" ]; then
            fail "make run: the Makefile's run: recipe runs beamslider" "$(sed -n '/^run:/,/^[^\t]/p' Makefile)"
            continue
        fi
        run "make run ($wrapped)" "$wrapped"
        tail -n 1 "$tmp/out" > "$tmp/run.json"
        check "make run writes build/fig6.csv" test -s "$clone/build/fig6.csv"
        awk '/^```json$/ { getline; print; exit }' README.md > "$tmp/readme.json"
        json_fields "$tmp/readme.json" | grep -Ev '^(wall_s|steps_per_s|revision) ' > "$tmp/readme.fields"
        json_fields "$tmp/run.json" | grep -Ev '^(wall_s|steps_per_s|revision) ' > "$tmp/run.fields"
        if [ -s "$tmp/run.fields" ] && cmp -s "$tmp/readme.fields" "$tmp/run.fields"; then
            pass "README.md's example JSON is what make run prints (keys and values but wall_s, steps_per_s, revision)"
        else
            fail "README.md's example JSON is what make run prints (keys and values but wall_s, steps_per_s, revision)" \
                "README: $(cat "$tmp/readme.json")
now:    $(cat "$tmp/run.json")
differ (< README, > now): $(diff "$tmp/readme.fields" "$tmp/run.fields" | grep '^[<>]' | tr '\n' ';')"
        fi ;;
    "make install "* | "export PKG_CONFIG_PATH="* | "cc "*app.c* | "./app "*)
        echo "skip - $command (the library example: tests/check_consumer.sh, make consumer-test)" ;;
    "make "*)
        # shellcheck disable=SC2086
        (cd "$clone" && make -n ${command#make } < /dev/null) > "$tmp/out" 2> "$tmp/err"
        check_status "$command (dry run: make -n)" 0 $? "$tmp/err" ;;
    "sbatch "*)
        echo "skip - $command (Slurm: tests/slurm, make test-long)" ;;
    *" [--"*)
        sub=$(printf '%s\n' "$command" | awk '{ print $2 }')
        "$clone/build/beamslider" "$sub" --help > "$tmp/help" 2>&1 < /dev/null
        missing=$(printf '%s\n' "$command" | grep -o -- '--[a-z][a-z-]*' | sort -u | while read -r option; do
            grep -q -e "$option" "$tmp/help" || printf '%s ' "$option"; done)
        if [ -z "$missing" ]; then pass "synopsis of $sub: its options are in beamslider $sub --help"
        else fail "synopsis of $sub: its options are in beamslider $sub --help" "not in the help: $missing"; fi ;;
    "sensor | "*)
        run "$command (sensor: cat measured.csv)" "cat measured.csv | ${command#sensor | }" ;;
    "build/beamslider run "*)
        run "$command (--t-end 0.02)" "$command --t-end 0.02" ;;
    "build/beamslider sweep "*)
        run "$command (5 points)" "$command --from 0.29 --to 0.3 --step 0.01 --hold 1 --record 1" ;;
    "build/beamslider map "*)
        small=$(printf '%s\n' "$command" | awk '{ for (i = 1; i <= NF; ++i) if ($(i - 1) == "--vary" && split($i, r, /[=:]/) == 4)
            $i = sprintf("%s=%s,%s", r[1], r[2], r[2] + r[4]); print }')
        run "$command (first two values of each --vary, 2 ms runs)" "$small --set run.t_end=0.002"
        check "map made the folders of --out" test -s "$clone/build/maps/f_a/map.csv" ;;
    "build/beamslider map-plot "*)
        if command -v gnuplot >/dev/null 2>&1; then run "$command" "$command"
        else echo "skip - $command (needs gnuplot: make maps installs gnuplot-nox)"; fi ;;
    "build/beamslider twin-plant "*)
        run "$command (--t-end 0.05)" "$command --t-end 0.05" ;;
    *)
        run "$command" "$command" ;;
    esac
done < "$tmp/commands"

echo "check_readme: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
