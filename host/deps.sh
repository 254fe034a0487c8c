#!/bin/sh
# deps.sh PACKAGE... - make sure the Debian packages a make target needs are
# installed: installs the missing ones with apt-get when run as root, else
# stops with the exact command to run. Silent when everything is there.
missing=""
if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "deps.sh: not a Debian system; make sure these are installed: $*" >&2
    exit 0
fi
# one dpkg-query for all of them (it reads dpkg's database once: a call per
# package cost 30 ms each, and make test asks some 140 times); a package it
# does not know gets no line, so it is missing too
installed=$(dpkg-query -W -f='${Package} ${Status}\n' "$@" 2>/dev/null | awk '/ ok installed$/ { print $1 }')
for package in "$@"; do
    printf '%s\n' "$installed" | grep -qxF -- "$package" || missing="$missing $package"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "deps.sh: installing:$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q >&2 || exit 1
    apt-get install -y -q --no-install-recommends -o DPkg::Lock::Timeout=600 $missing >&2 || exit 1
    exit 0
fi
echo "deps.sh: missing packages:$missing" >&2
echo "run:  sudo apt-get install -y$missing" >&2
exit 1
