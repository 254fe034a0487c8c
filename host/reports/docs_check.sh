#!/bin/sh
# docs_check.sh [FILE...] - `make docs-check` (part of `make test`): do the report
# pages of docs/ still describe the code? Each report writes a provenance stamp into
# the page or section it generates, and each figure has a line in
# docs/figures/PROVENANCE (host/reports/provenance.sh: the format). For every stamp
# this compares what was recorded with what the current tree gives:
#   version        BS_VERSION_STRING of core/include/beamslider.h
#   golden_*       the state hash of `build/REAL/beamslider run SCENE --t-end T`,
#                  double and float (20 000 steps of fig6: ~10 ms each, run once)
#   sources        (pages of measured cost) the hash of the set's files now
#   toolchain      (with sources) the compiler's first --version line and the flags
#                  make passes (PROVENANCE_*; not compared when run by hand, or with
#                  DOCS_CHECK_TOOLCHAIN=0, or when that compiler is not installed:
#                  a notice says so)
#   file           (figures) the PNG's hash: the figure is the one its line describes
# and fails, naming the page, the section, what differs (recorded and now) and the
# command that regenerates it. The revision is the reader's: a commit after the
# report moves it without changing anything measured, so it is not compared.
#
# Without arguments: every page of REQUIRED must hold a stamp of each of its
# commands (a page of results without one fails), every other page of docs/ that
# holds stamps is checked too, and every docs/figures/*.png must have its line.
# With FILE arguments (tests/check_docs_check.sh): those files only, each of which
# must hold at least one stamp (a PROVENANCE file: its figures beside it).
# Environment: PROVENANCE_BUILD (build), the folder of build/REAL/beamslider.
set -u
. host/reports/provenance.sh

# The pages of results and the commands that write them (one row per generated
# page or section): PAGE|COMMAND|SET, SET the sources set of a page of measured cost
# (its stamp must carry sources= and toolchain=). Add a row with a new report.
REQUIRED='docs/performance.md|make bench|host
docs/embedded.md|make embedded-report|embedded
docs/embedded.md|make twin-firmware-report|twin-firmware
docs/accuracy.md|make accuracy|
docs/stability.md|make stability|
docs/validation.md|make fig6-report|
docs/validation.md|make figures|
docs/maps.md|make maps|
docs/baseline.md|make baseline-check|
docs/harvester.md|make harvester-report|
docs/twin.md|make twin-report|
docs/twin.md|make twin-ceiling-maps|
docs/twin.md|make twin-step|
docs/twin.md|make twin-fast|'
# Not checked: docs/baseline_base_frame.md, the record of one past change (0.6.0's
# base frame against 113766f), kept as it was made; docs/fields.md (make fields,
# compared with `beamslider fields` by tests/check_cli.sh).
FIGURES=docs/figures
# The commands that draw the figures of FIGURES, by name (a shell pattern): PATTERN|COMMAND
FIGURE_COMMANDS='fig*.png|make figures
run_*.png|make figures
map_*.png|make maps
harvester_*.png|make harvester-report
twin_*.png|make twin-report
work_precision.png|make accuracy
python_map.png|make python-figure'

TMP=$(mktemp -d) || exit 1
trap 'rm -rf "$TMP"' EXIT
failed=0
US=$(printf '\037')
# a stamp: the whole line (a page) or after a figure's name and hash (PROVENANCE)
STAMP_RE='^(<!-- provenance: |[^ #]+ file=[0-9a-f]* <!-- provenance: ).* -->$'

# stamps FILE... -> one record per stamp: file, line, section, command, version,
# golden_scene, golden_t_end, golden_double, golden_float, sources, toolchain,
# figure name, figure hash; separated by US (fields may be empty)
stamps() {
    awk -v us="$US" '
        FNR == 1 { heading = ""; marker = ""; fence = 0; list = FILENAME ~ /(^|\/)PROVENANCE$/ }
        /^```/ { fence = !fence }
        !list && !fence && /^#+ / { heading = $0; sub(/^#+ +/, "", heading) }
        /^<!-- [a-z0-9-]+ -->$/ { marker = $2 }
        {
            if (list ? !/^[^ #]+ file=[0-9a-f]* <!-- provenance: .* -->$/ : !/^<!-- provenance: .* -->$/) next
            at = index($0, "provenance:")
            rest = substr($0, at + 11)
            sub(/ *-->.*$/, "", rest)
            delete v
            while (length(rest)) {
                sub(/^ +/, "", rest)
                eq = index(rest, "=")
                if (!eq) break
                key = substr(rest, 1, eq - 1)
                rest = substr(rest, eq + 1)
                if (substr(rest, 1, 1) == "\"") {
                    end = index(substr(rest, 2), "\"")
                    if (!end) { v[key] = substr(rest, 2); rest = ""; break }
                    v[key] = substr(rest, 2, end - 1)
                    rest = substr(rest, end + 2)
                } else {
                    end = index(rest, " ")
                    if (!end) end = length(rest) + 1
                    v[key] = substr(rest, 1, end - 1)
                    rest = substr(rest, end)
                }
            }
            figure = ""; file = ""
            if (list) {
                figure = $1
                for (i = 2; i <= NF; ++i) if ($i ~ /^file=/) file = substr($i, 6)
                section = figure
            } else {
                section = heading == "" ? "(top)" : heading
                if (marker != "") section = section " (<!-- " marker " -->)"
            }
            print FILENAME us FNR us section us v["command"] us v["version"] us v["golden_scene"] us \
                v["golden_t_end"] us v["golden_double"] us v["golden_float"] us v["sources"] us \
                v["toolchain"] us figure us file
        }' "$@"
}

toolchain_now() { # toolchain_now SET -> the toolchain now, or nothing when it cannot be told
    [ "${DOCS_CHECK_TOOLCHAIN:-1}" != 0 ] || return 0
    case $1 in host) cc=${PROVENANCE_CC:-} ;; *) cc=${PROVENANCE_CM_CC:-} ;; esac
    [ -n "$cc" ] && command -v "$cc" >/dev/null 2>&1 || return 0
    provenance_toolchain "$1" 2>/dev/null
}

if [ $# -gt 0 ]; then
    files="$*"
    for f in "$@"; do
        if [ ! -f "$f" ]; then
            echo "docs-check: $f: no such file"
            failed=$((failed + 1))
        elif ! grep -Eq "$STAMP_RE" "$f"; then
            echo "docs-check: $f holds no provenance stamp: regenerate it with the report that writes it"
            failed=$((failed + 1))
        fi
    done
else
    files=$(grep -El "$STAMP_RE" docs/*.md 2>/dev/null | grep -v '^docs/baseline_base_frame[.]md$' | tr '\n' ' ')
    [ -f "$FIGURES/PROVENANCE" ] && files="$files $FIGURES/PROVENANCE"
fi
# shellcheck disable=SC2086
[ -z "$files" ] || stamps $files > "$TMP/stamps" 2>/dev/null
touch "$TMP/stamps"

# What the tree gives now, computed once per distinct question the stamps ask, as
# lines KIND US KEY US VALUE: the version, each run's golden hash, each set's
# sources and toolchain, each figure's hash.
{
    printf 'version%s%s%s\n' "$US" "" "$US$(provenance_version)"
    awk -F "$US" '{ print $6 " " $7 }' "$TMP/stamps" | sort -u | while read -r scene t_end; do
        printf '%s\n' "$scene $t_end" | grep -Eq '^configs/[A-Za-z0-9_]+[.]ini [0-9]+([.][0-9]+)?$' || continue
        for real in double float; do
            hash=$(provenance_golden "$real" "$scene" "$t_end" 2>&1) || hash="(none: $hash)"
            printf 'golden%s%s%s%s\n' "$US" "$real $scene $t_end" "$US" "$hash"
        done
    done
    awk -F "$US" '$10 != "" { sub(/:.*/, "", $10); print $10 }' "$TMP/stamps" | sort -u | while read -r src_set; do
        sources=$(provenance_sources "$src_set" 2>&1) || sources="(none: $sources)"
        printf 'sources%s%s%s%s\n' "$US" "$src_set" "$US" "$sources"
        printf 'toolchain%s%s%s%s\n' "$US" "$src_set" "$US" "$(toolchain_now "$src_set")"
    done
    awk -F "$US" '$12 != "" { dir = $1; sub(/[^\/]*$/, "", dir); print dir $12 }' "$TMP/stamps" | sort -u |
        while IFS= read -r png; do [ -f "$png" ] && printf '%s\n' "$png"; done | tr '\n' '\0' |
        xargs -0 -r sha256sum | awk -v us="$US" '{ print "file" us substr($0, 67) us substr($1, 1, 16) }'
} > "$TMP/now"

# Every page of results holds a stamp of each command that writes it, and every
# figure has its line (without arguments only): the lists of both for the comparison
if [ $# -eq 0 ]; then
    printf '%s\n' "$REQUIRED" > "$TMP/required"
    for png in "$FIGURES"/*.png; do [ -f "$png" ] && printf '%s\n' "$png"; done > "$TMP/pngs"
else
    : > "$TMP/required"
    : > "$TMP/pngs"
fi

# The comparison: one block per stale stamp, one line per missing one; the count last.
awk -F "$US" -v us="$US" -v build="$PROVENANCE_BUILD" -v figures="$FIGURES" -v commands="$FIGURE_COMMANDS" '
    FILENAME ~ /\/now$/ { now[$1, $2] = $3; next }
    FILENAME ~ /\/required$/ { split($0, r, "|"); nreq++; req_page[nreq] = r[1]; req_command[nreq] = r[2]; req_set[nreq] = r[3]; next }
    FILENAME ~ /\/pngs$/ { npng++; png[npng] = $0; next }
    function differs(what, recorded, now_text) {
        diffs = diffs sprintf("  %s: recorded %s, %s\n", what, recorded == "" ? "(nothing)" : recorded, now_text)
    }
    {
        file = $1; line = $2; section = $3; command = $4; version = $5; scene = $6; t_end = $7
        sources = $10; toolchain = $11; figure = $12; fhash = $13
        ++stamps
        diffs = ""
        if (command == "") differs("command", "", "every stamp names the command that regenerates it")
        if (version != now["version", ""])
            differs("version", version, "the tree is " now["version", ""] " (core/include/beamslider.h)")
        key = scene " " t_end
        if (!(("golden", "double " key) in now))
            differs("golden_scene/golden_t_end", "\047" scene "\047 \047" t_end "\047", "a scene of configs/ and a duration in seconds")
        else {
            if ($8 != now["golden", "double " key])
                differs("golden_double", $8, build "/double/beamslider run " scene " --t-end " t_end " gives " now["golden", "double " key])
            if ($9 != now["golden", "float " key])
                differs("golden_float", $9, build "/float/beamslider run " scene " --t-end " t_end " gives " now["golden", "float " key])
        }
        if (sources != "") {
            set = sources; sub(/:.*/, "", set)
            if (sources != now["sources", set])
                differs("sources", sources, "the files of the set " set " hash to " now["sources", set] " now")
            if (now["toolchain", set] == "") {
                notices = notices sprintf("docs-check: notice: %s line %d: the toolchain of the set %s is not compared (DOCS_CHECK_TOOLCHAIN=0, no PROVENANCE_* flags from make, or the compiler is not installed)\n", file, line, set)
                ++nnotices
            } else if (toolchain != now["toolchain", set])
                differs("toolchain", toolchain, "now " now["toolchain", set])
        }
        if (figure != "") {
            path = file; sub(/[^\/]*$/, "", path); path = path figure
            if (!(("file", path) in now)) differs("file", fhash, path " does not exist")
            else if (fhash != now["file", path]) differs("file", fhash, path " hashes to " now["file", path] " (replaced without its line)")
            listed[figure] = 1
        }
        if (diffs != "") {
            printf "docs-check: STALE %s line %d, section \"%s\" (%s):\n%s  regenerate it: %s\n", file, line, section,
                command == "" ? "no command" : command, diffs, command == "" ? "(the stamp names none)" : command
            ++bad
        }
        n = ++count[file]; stamp_command[file, n] = command; stamp_sources[file, n] = sources
    }
    END {
        for (i = 1; i <= nreq; ++i) {
            found = 0; nosources = 0
            for (j = 1; j <= count[req_page[i]]; ++j) {
                c = stamp_command[req_page[i], j]
                if (c != req_command[i] && index(c, req_command[i] " ") != 1) continue
                if (req_set[i] == "" || index(stamp_sources[req_page[i], j], req_set[i] ":") == 1) found = 1
                else nosources = 1
            }
            if (found) continue
            ++bad
            if (nosources)
                printf "docs-check: %s: the stamp of `%s` carries no sources=%s:... and toolchain: regenerate it: %s\n",
                    req_page[i], req_command[i], req_set[i], req_command[i]
            else
                printf "docs-check: %s holds no stamp of `%s` (a page of results must say what made it): regenerate it: %s\n",
                    req_page[i], req_command[i], req_command[i]
        }
        nrules = split(commands, rule, "\n")
        for (i = 1; i <= npng; ++i) {
            name = png[i]; sub(/.*\//, "", name)
            if (name in listed) continue
            draws = "the report that draws it (README.md, \"Reports\")"
            for (k = 1; k <= nrules; ++k) {
                split(rule[k], pc, "|"); pattern = pc[1]
                gsub(/[.]/, "[.]", pattern); gsub(/[*]/, ".*", pattern)
                if (name ~ "^" pattern "$") { draws = pc[2]; break }
            }
            printf "docs-check: %s has no line in %s/PROVENANCE: regenerate it: %s\n", png[i], figures, draws
            ++bad
        }
        printf "%s", notices
        printf "%d %d %d\n", bad, stamps, nnotices > "/dev/stderr"
    }' "$TMP/now" "$TMP/required" "$TMP/pngs" "$TMP/stamps" 2> "$TMP/counts"
read -r bad count notices < "$TMP/counts"
failed=$((failed + bad))
if [ "$failed" -gt 0 ]; then
    echo "docs-check: FAIL: $failed stale or missing stamp(s) ($count stamps read); regenerate with the commands named above"
    exit 1
fi
echo "docs-check: ok: $count stamps match the tree$([ "$notices" -eq 0 ] || echo " ($notices toolchain(s) not compared)")"
