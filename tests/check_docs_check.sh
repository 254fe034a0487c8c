#!/bin/sh
# check_docs_check.sh - the checker of `make docs-check` (host/reports/docs_check.sh)
# on copies of report pages: a page stamped now passes; a page whose stamp recorded
# another golden hash, other measured sources, another version or toolchain, a
# figure whose PNG is not the one its line describes, and a page with no stamp fail,
# each named with the command that regenerates it; a revision alone does not fail.
# Needs build/double/beamslider and build/float/beamslider (make docs-check-test).
# One run of the checker and one stamp: about half a CPU second.
. tests/check_lib.sh
check_setup tests/check_docs_check.sh build/double/beamslider
[ -x build/float/beamslider ] || { echo "FAIL - build/float/beamslider not built"; exit 1; }
. host/reports/provenance.sh
# the flags the stamps record and the checker compares (make passes its own)
PROVENANCE_CC=cc PROVENANCE_CFLAGS='-O2 -g' PROVENANCE_CORE_OPT=-O3
export PROVENANCE_CC PROVENANCE_CFLAGS PROVENANCE_CORE_OPT
unset DOCS_CHECK_TOOLCHAIN

# stamped PAGE STAMP > COPY: the page with its stamps removed and STAMP under its
# first heading, as the reports write it
stamped() {
    grep -v '^<!-- provenance: ' "$1" | awk -v stamp="$2" '{ print } /^# / && !done { print ""; print stamp; done = 1 }'
}
# one stamp of a page of measured cost; the others from it (fewer runs)
cost_stamp=$(provenance_stamp "make bench" host) || exit 1
stamp=$(printf '%s\n' "$cost_stamp" | sed 's/command="make bench"/command="make stability"/; s/ sources=.* -->$/ -->/')
stamped docs/performance.md "$cost_stamp" > "$tmp/performance.md"
stamped docs/stability.md "$stamp" > "$tmp/stability.md"
mkdir -p "$tmp/figures"
printf 'not a PNG, but bytes to hash\n' > "$tmp/figures/fig1b.png"
provenance_figures "$(printf '%s\n' "$stamp" | sed 's/make stability/make figures/')" "$tmp/figures/fig1b.png"

# the stale copies: one thing changed in each
sed 's/golden_double=\([0-9a-f]*\)/golden_double=0bad0bad/' "$tmp/stability.md" > "$tmp/golden.md"
sed 's/sources=host:[0-9a-f]*/sources=host:00000000deadbeef/' "$tmp/performance.md" > "$tmp/sources.md"
sed 's/ version=[^ ]*/ version=0.0.1/' "$tmp/stability.md" > "$tmp/version.md"
sed 's/toolchain="[^"]*"/toolchain="cc 1.0; CFLAGS=-O0; CORE_OPT=-O0"/' "$tmp/performance.md" > "$tmp/toolchain.md"
sed 's/ revision=[^ ]*/ revision=0123456789ab/' "$tmp/stability.md" > "$tmp/revision.md"
grep -v '^<!-- provenance: ' "$tmp/stability.md" > "$tmp/unstamped.md"
mkdir -p "$tmp/stale-figures"
cp "$tmp/figures/PROVENANCE" "$tmp/stale-figures/PROVENANCE"
printf 'another figure\n' > "$tmp/stale-figures/fig1b.png"
# one run of the checker (each costs a few tenths of a CPU second): the fresh and the stale
sh host/reports/docs_check.sh "$tmp/performance.md" "$tmp/stability.md" "$tmp/figures/PROVENANCE" \
    "$tmp/golden.md" "$tmp/sources.md" "$tmp/version.md" "$tmp/toolchain.md" \
    "$tmp/revision.md" "$tmp/unstamped.md" "$tmp/stale-figures/PROVENANCE" > "$tmp/stale.out" 2>&1
check_status "stale pages fail" 1 $? "$tmp/stale.out"
if grep -E "$tmp/(performance|stability|revision)[.]md|$tmp/figures/" "$tmp/stale.out"; then
    fail "pages and a figure stamped now pass, and so does a page whose revision alone differs" "$(cat "$tmp/stale.out")"
else
    pass "pages and a figure stamped now pass, and so does a page whose revision alone differs"
fi
check_has "a stale golden hash names the page and its section" "$tmp/stale.out" \
    "STALE $tmp/golden.md line 3, section \"Stability on stiff and extreme cases\" (make stability)"
check_has "... what differs, recorded and now" "$tmp/stale.out" \
    "golden_double: recorded 0bad0bad, build/double/beamslider run configs/fig6.ini --t-end 0.4 gives"
check_has "... and the command that regenerates it" "$tmp/stale.out" "regenerate it: make stability"
check_has "a stale sources hash names the page" "$tmp/stale.out" "STALE $tmp/sources.md line 3, section \"Performance\" (make bench)"
check_has "... and the sources that differ" "$tmp/stale.out" "sources: recorded host:00000000deadbeef, the files of the set host hash to"
check_has "... and the command" "$tmp/stale.out" "regenerate it: make bench"
check_has "another version fails" "$tmp/stale.out" "version: recorded 0.0.1, the tree is $(provenance_version)"
check_has "another toolchain fails" "$tmp/stale.out" "toolchain: recorded cc 1.0; CFLAGS=-O0; CORE_OPT=-O0, now"
check_has "a page of results with no stamp fails" "$tmp/stale.out" "$tmp/unstamped.md holds no provenance stamp"
check_has "a figure replaced without its line fails" "$tmp/stale.out" \
    "STALE $tmp/stale-figures/PROVENANCE line 3, section \"fig1b.png\" (make figures)"
check_has "... naming the figure" "$tmp/stale.out" "$tmp/stale-figures/fig1b.png hashes to"
check_has "... and the count" "$tmp/stale.out" "docs-check: FAIL: 6 stale or missing stamp(s) (9 stamps read)"

echo "check_docs_check: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
