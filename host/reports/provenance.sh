# provenance.sh - sourced by the report scripts of host/reports: the stamp each
# report writes into the page (or the section of a page) it generates, so that
# `make docs-check` (host/reports/docs_check.sh) can tell when the page no longer
# describes the code. Sourced, not run; from the repository root.
#
# The stamp is one line, an HTML comment (invisible on the rendered page):
#
#   <!-- provenance: command="make bench" version=0.8.0 revision=1d28b82ac328
#        golden_scene=configs/fig6.ini golden_t_end=0.4 golden_double=eb14c821
#        golden_float=91964252 sources=host:3f2a9c0d1e4b5a67
#        toolchain="cc (Debian 12.2.0-14) 12.2.0; CFLAGS=-O2 -g; CORE_OPT=-O3" -->
#
# (on one line). Values are a run of characters without blanks, or "quoted" (no
# double quote inside).
#   command     what regenerates the page: docs-check names it when the page is stale
#   version     BS_VERSION_STRING of core/include/beamslider.h
#   revision    the commit (git rev-parse --short=12 HEAD), "-dirty" when the sources
#               of the stamp's set (below; "results" for a page without sources=)
#               differ from it; for the reader only: docs-check does not compare it
#   golden_*    the state hashes ("hash" of the JSON summary) of
#               `beamslider run GOLDEN_SCENE --t-end GOLDEN_T_END` of the double and
#               the float build the report used: 20 000 steps of fig6, the first
#               quantity tests/test_golden.c pins. They move with every change of
#               the results, so a page whose hashes are not the current build's
#               describes other results.
#   sources     pages of measured cost only: SET:HASH, the first 16 hex digits of
#               a SHA-256 over the sorted names and contents of the files of SET
#               (provenance_files), the code whose cost the page measures
#   toolchain   with sources: the compiler's first --version line and the flags
#               the page's code was compiled with (make passes them: reports.mk)
#
# Figures (docs/figures/*.png) are listed in docs/figures/PROVENANCE, one line
# each: NAME.png file=HASH <!-- provenance: ... -->, HASH the first 16 hex digits
# of the PNG's SHA-256 (provenance_figures), so that a figure replaced without its
# line, or a line without its figure, is seen too.

PROVENANCE_SCENE=configs/fig6.ini
PROVENANCE_T_END=0.4
PROVENANCE_BUILD=${PROVENANCE_BUILD:-build}

# provenance_paths SET -> the paths (folders or globs) of a set; its files are
# those under them but the documentation (*.md) and what provenance_excluded names:
#   host           what build/*/beamslider is compiled from: the core, the host
#                  library and CLI, the host port (docs/performance.md)
#   embedded       what the Cortex-M images of the core are compiled and counted
#                  from: the core, the Cortex-M and embedded ports, the compiled
#                  scenes, the image programs and the QEMU counter (docs/embedded.md)
#   twin-firmware  the same and the twin firmware, its constants' design and its
#                  stream's packer (docs/embedded.md, "Twin firmware")
#   results        every source a result can depend on (for revision's "-dirty")
provenance_paths() {
    case $1 in
    host) echo "core host/include host/lib host/cli port/host port/bs_platform.h port/build_config.sh" ;;
    embedded) echo "core port/cortex-m port/embedded port/bs_platform.h port/build_config.sh configs/*.h tests/embedded tests/qemu" ;;
    twin-firmware) echo "$(provenance_paths embedded) host/lib/twin host/lib/io" ;;
    results) echo "core host/include host/lib host/cli port configs" ;;
    *) echo "provenance: no source set '$1' (host, embedded, twin-firmware, results)" >&2; return 1 ;;
    esac
}

# provenance_excluded SET -> an extended regular expression of the paths of SET's
# folders that are not in it
provenance_excluded() {
    case $1 in
    # the step's images link no observer code (arm-none-eabi-nm of the cost
    # images: no bs_observer_*, bs_lockin_*; no step source includes their
    # headers), so the observer's sources are the twin firmware's alone
    embedded) echo '[.]md$|^port/cortex-m/twin/|^core/src/bs_observer[.]c$|^core/src/bs_lockin[.][ch]$|^core/include/bs_observer[.]h$|^core/include/bs_lockin_layout[.]h$' ;;
    *) echo '[.]md$' ;;
    esac
}

# provenance_files SET -> the files of SET, one per line, sorted (C locale): in a
# git work tree the tracked and untracked files not ignored, else every file
provenance_files() {
    p_paths=$(provenance_paths "$1") || return 1
    p_excluded=$(provenance_excluded "$1")
    # shellcheck disable=SC2086
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        git ls-files --cached --others --exclude-standard -- $p_paths
    else
        for p_path in $p_paths; do
            [ -e "$p_path" ] && find "$p_path" -type f
        done
    fi | grep -v -E "$p_excluded" | while IFS= read -r f; do [ -f "$f" ] && printf '%s\n' "$f"; done | LC_ALL=C sort -u
}

# provenance_hash FILE -> the first 16 hex digits of its SHA-256
provenance_hash() {
    sha256sum "$1" | cut -c1-16
}

# provenance_sources SET -> SET:HASH over the names and contents of its files
provenance_sources() {
    p_files=$(provenance_files "$1") || return 1
    [ -n "$p_files" ] || { echo "provenance: the set $1 has no files" >&2; return 1; }
    printf '%s:%s\n' "$1" "$(printf '%s\n' "$p_files" | tr '\n' '\0' | xargs -0 sha256sum | sha256sum | cut -c1-16)"
}

# provenance_toolchain SET -> "compiler line; flags" of the code SET measures, from
# the PROVENANCE_* variables make exports (host/reports/reports.mk)
provenance_toolchain() {
    case $1 in
    host)
        [ -n "${PROVENANCE_CC:-}" ] && [ -n "${PROVENANCE_CFLAGS+set}" ] && [ -n "${PROVENANCE_CORE_OPT+set}" ] || {
            echo "provenance: PROVENANCE_CC, _CFLAGS, _CORE_OPT unset (run the report through make)" >&2; return 1; }
        printf '%s; CFLAGS=%s; CORE_OPT=%s\n' "$($PROVENANCE_CC --version 2>/dev/null | head -n 1)" \
            "$PROVENANCE_CFLAGS" "$PROVENANCE_CORE_OPT" ;;
    embedded | twin-firmware)
        [ -n "${PROVENANCE_CM_CC:-}" ] && [ -n "${PROVENANCE_CM_OPT+set}" ] || {
            echo "provenance: PROVENANCE_CM_CC, _CM_OPT unset (run the report through make)" >&2; return 1; }
        printf '%s; CM_OPT=%s\n' "$($PROVENANCE_CM_CC --version 2>/dev/null | head -n 1)" "$PROVENANCE_CM_OPT" ;;
    *) echo "provenance: no toolchain for the set '$1'" >&2; return 1 ;;
    esac
}

# provenance_version -> BS_VERSION_STRING of the tree
provenance_version() {
    sed -n 's/^#define BS_VERSION_STRING "\(.*\)"/\1/p' core/include/beamslider.h
}

# provenance_revision SET -> the commit, "-dirty" if SET's files differ from it
provenance_revision() {
    p_revision=$(git rev-parse --short=12 HEAD 2>/dev/null) || { echo unknown; return 0; }
    p_paths=$(provenance_paths "$1") || return 1
    # shellcheck disable=SC2086
    if ! git diff --quiet HEAD -- $p_paths 2>/dev/null \
        || [ -n "$(git ls-files --others --exclude-standard -- $p_paths 2>/dev/null)" ]; then
        p_revision=$p_revision-dirty
    fi
    echo "$p_revision"
}

# provenance_golden REAL [SCENE T_END] -> the state hash of build/REAL/beamslider's run
provenance_golden() {
    p_bin=$PROVENANCE_BUILD/$1/beamslider
    [ -x "$p_bin" ] || { echo "provenance: $p_bin not built (make REAL=$1)" >&2; return 1; }
    p_hash=$("$p_bin" run "${2:-$PROVENANCE_SCENE}" --t-end "${3:-$PROVENANCE_T_END}" 2>/dev/null \
        | sed -n 's/.*"hash":"\([0-9a-f]*\)".*/\1/p')
    [ -n "$p_hash" ] || { echo "provenance: $p_bin run ${2:-$PROVENANCE_SCENE} gave no hash" >&2; return 1; }
    echo "$p_hash"
}

# provenance_stamp COMMAND [SET] -> the stamp line; SET (host or embedded) for a
# page of measured cost. Run it before the report's runs: it fails (status 1, a
# message) when a build is missing or make did not pass the flags.
provenance_stamp() {
    p_version=$(provenance_version)
    p_revision=$(provenance_revision "${2:-results}") || return 1
    p_double=$(provenance_golden double) || return 1
    p_float=$(provenance_golden float) || return 1
    p_cost=
    if [ -n "${2:-}" ]; then
        p_sources=$(provenance_sources "$2") || return 1
        p_toolchain=$(provenance_toolchain "$2") || return 1
        p_cost=" sources=$p_sources toolchain=\"$p_toolchain\""
    fi
    printf '<!-- provenance: command="%s" version=%s revision=%s golden_scene=%s golden_t_end=%s golden_double=%s golden_float=%s%s -->\n' \
        "$1" "$p_version" "$p_revision" "$PROVENANCE_SCENE" "$PROVENANCE_T_END" "$p_double" "$p_float" "$p_cost"
}

# provenance_text STAMP -> a sentence for a page that has no line of its own
# saying what made it
provenance_text() {
    printf '%s\n' "$1" | awk '{
        for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
        match($0, /command="[^"]*"/); command = substr($0, RSTART + 9, RLENGTH - 10)
        printf "Made by `%s` with beamslider %s (revision %s; state hashes %s double, %s float).\n",
            command, v["version"], v["revision"], v["golden_double"], v["golden_float"] }'
}

# provenance_figures STAMP PNG...: each PNG's line in the PROVENANCE file of its
# folder (docs/figures/PROVENANCE), replaced or added; the lines sorted by name
provenance_figures() {
    p_stamp=$1
    shift
    for p_png in "$@"; do
        p_list=$(dirname "$p_png")/PROVENANCE
        p_name=$(basename "$p_png")
        p_line="$p_name file=$(provenance_hash "$p_png") $p_stamp"
        {
            echo "# PROVENANCE - what made each figure of this folder (host/reports/provenance.sh):"
            echo "# written by the reports, checked by make docs-check; do not edit by hand."
            { [ ! -f "$p_list" ] || awk -v name="$p_name" '!/^#/ && $1 != name' "$p_list"
              printf '%s\n' "$p_line"; } | LC_ALL=C sort
        } > "$p_list.tmp" && mv "$p_list.tmp" "$p_list" || return 1
    done
}
