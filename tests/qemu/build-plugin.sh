#!/bin/sh
# build-plugin.sh - build build/cm/libinsncount.so, the QEMU instruction-count plugin.
#
# Debian's qemu-system-arm accepts -plugin but ships no plugin header, so the header comes from
# the qemu *source package* of the machine's own Debian release: a private apt configuration
# (deb-src twins of the system's Debian sources; lists and caches under build/cm/qemu-src/apt.PID,
# the system's apt state is not touched) runs `apt-get source --download-only qemu`, and only
# include/qemu/qemu-plugin.h is extracted to build/cm/qemu-src/qemu-plugin.h. The ~24 MB of
# downloads are deleted afterwards; nothing of QEMU's source goes into the repository.
#
# Idempotent: does nothing when the library is newer than its source and the header.
# Needs: apt-get, network access to the Debian archive (first run only), xz, host gcc.
# Env: CM_BUILD (default <repo>/build/cm), HOSTCC (default gcc).
# Exit status: 0 = library ready, 1 = it could not be built (the reason is printed).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${CM_BUILD:-$root/build/cm}
# Absolute: apt resolves relative Dir:: paths against /etc/apt.
if ! mkdir -p "$out" || ! out=$(cd "$out" && pwd); then echo "build-plugin: cannot create $out" >&2; exit 1; fi
src=$here/insn-plugin/insncount.c
hdir=$out/qemu-src
hdr=$hdir/qemu-plugin.h
lib=$out/libinsncount.so
hostcc=${HOSTCC:-gcc}

apt=
fail() {
    [ -z "$apt" ] || rm -rf "$apt"
    echo "build-plugin: $*" >&2
    echo "build-plugin: instruction counting (count.sh) is unavailable; building and running" \
         "images (run.sh) does not need it." >&2
    exit 1
}

newer() { [ -n "$(find "$1" -prune -newer "$2" 2>/dev/null)" ]; }   # POSIX sh has no -nt
if [ -f "$lib" ] && [ -f "$hdr" ] && newer "$lib" "$src" && newer "$lib" "$hdr"; then
    exit 0
fi

if [ ! -f "$hdr" ]; then
    command -v apt-get >/dev/null 2>&1 ||
        fail "no apt-get here: put include/qemu/qemu-plugin.h of QEMU $(qemu-system-arm --version 2>/dev/null | sed -n '1s/.*version \([0-9.]*\).*/\1/p') at $hdr"
    command -v xz >/dev/null 2>&1 || fail "xz is missing (apt-get install xz-utils)"
    apt=$hdir/apt.$$   # per process, like the .tmp files: parallel runs (make -j) cannot collide
    rm -rf "$apt"
    mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/sources.list.d" "$apt/dl" ||
        fail "cannot create $apt"
    : > "$apt/none.list"
    # deb-src twins of the Debian entries of the system's sources (deb822 and one-line styles).
    # Third-party repositories are left out: most have no deb-src and would only add errors.
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        awk 'BEGIN { RS = ""; ORS = "\n\n" }
             /(^|\n)Types:[^\n]*(^|[ \t])deb([ \t]|\n|$)/ && /(^|\n)URIs:[^\n]*debian/ {
                 sub(/(^|\n)Types:[^\n]*/, "\nTypes: deb-src"); sub(/^\n/, ""); print }' \
            "$f" >> "$apt/sources.list.d/twin.sources"
    done
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [ -f "$f" ] || continue
        sed -n 's/^[[:space:]]*deb[[:space:]]\(.*debian.*\)/deb-src \1/p' "$f" >> "$apt/sources.list.d/twin.list"
    done
    [ -s "$apt/sources.list.d/twin.sources" ] || [ -s "$apt/sources.list.d/twin.list" ] ||
        fail "no Debian archive entry in /etc/apt/sources.list{,.d} to derive a deb-src source from"
    set -- -o "Dir::Etc::SourceList=$apt/none.list" -o "Dir::Etc::SourceParts=$apt/sources.list.d" \
           -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache" -o Acquire::Retries=2
    [ "$(id -u)" = 0 ] && set -- "$@" -o APT::Sandbox::User=root  # root-owned private dirs
    echo "build-plugin: fetching qemu-plugin.h from the Debian qemu source package (~24 MB, once)"
    # update may report errors for single entries; what matters is whether the source comes.
    timeout 600 apt-get "$@" -q=2 update
    (cd "$apt/dl" && timeout 900 apt-get "$@" -q=2 source --download-only qemu) ||
        fail "could not download the qemu source package from the Debian archive (network access? deb-src entries in $apt/sources.list.d?)"
    for orig in "$apt"/dl/qemu_*.orig.tar.*; do break; done
    [ -f "$orig" ] || fail "apt-get source left no qemu_*.orig.tar.* in $apt/dl"
    # GNU tar (Debian's): -O extracts to stdout, the compression is detected.
    tar -xf "$orig" -O --wildcards '*/include/qemu/qemu-plugin.h' > "$hdr.$$" 2>/dev/null
    if [ ! -s "$hdr.$$" ]; then rm -f "$hdr.$$"; fail "no include/qemu/qemu-plugin.h in $orig"; fi
    mv "$hdr.$$" "$hdr"
    basename "$orig" > "$hdir/SOURCE"
    rm -rf "$apt"
    # The plugin API is only guaranteed within one QEMU release: warn on a mismatch.
    want=$(qemu-system-arm --version 2>/dev/null | sed -n '1s/.*version \([0-9]*\.[0-9]*\).*/\1/p')
    got=$(sed -n 's/^qemu_\([0-9]*\.[0-9]*\).*/\1/p' "$hdir/SOURCE")
    [ -z "$want" ] || [ "$want" = "$got" ] ||
        echo "build-plugin: warning: header from QEMU $got, qemu-system-arm is $want" >&2
fi

command -v "$hostcc" >/dev/null 2>&1 || fail "no host C compiler '$hostcc' (apt-get install gcc)"
"$hostcc" -std=gnu99 -O2 -Wall -Wextra -Werror -shared -fPIC -I"$hdir" -o "$lib.$$" "$src" ||
    { rm -f "$lib.$$"; fail "compiling $src failed"; }
mv "$lib.$$" "$lib"
echo "build-plugin: built $lib"
