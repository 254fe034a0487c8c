#!/bin/sh
# build_config.sh OUT float|double [NAME=VALUE ...] - writes the core's generated
# build configuration header (core/include/bs_build_config.h.in) to OUT: the
# precision and, as #defines, the given switches, e.g.
#     sh port/build_config.sh build/x/bs_build_config.h float \
#         'BS_SCENE_CONFIG="configs/fig6.h"' BS_WITH_SUBSPACE=0
# OUT is replaced only when its text changes, so builds that depend on it do not
# redo work. (port/cmake fills the same template with configure_file.)
set -eu
usage() { echo "usage: build_config.sh OUT float|double [NAME=VALUE ...]" >&2; exit 2; }
[ $# -ge 2 ] || usage
out=$1
case $2 in
    float) flag=1 ;;
    double) flag=0 ;;
    *) echo "build_config.sh: precision must be float or double, not '$2'" >&2; exit 2 ;;
esac
shift 2
lines=
for define in "$@"; do
    case $define in
        [A-Z]*=*) ;;
        *) echo "build_config.sh: expected NAME=VALUE, not '$define'" >&2; exit 2 ;;
    esac
    lines="$lines#define ${define%%=*} ${define#*=}
"
done
[ -n "$lines" ] || lines="/* none */
"
template=$(dirname "$0")/../core/include/bs_build_config.h.in
mkdir -p "$(dirname "$out")"
tmp=$out.tmp.$$
while IFS= read -r line; do
    case $line in
        @BS_CONFIG_LINES@) printf '%s' "$lines" ;;
        *@BS_REAL_FLOAT@*) printf '%s\n' "$line" | sed "s/@BS_REAL_FLOAT@/$flag/" ;;
        *) printf '%s\n' "$line" ;;
    esac
done < "$template" > "$tmp"
if cmp -s "$tmp" "$out" 2>/dev/null; then rm -f "$tmp"; else mv "$tmp" "$out"; fi
