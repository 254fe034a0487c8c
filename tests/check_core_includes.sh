#!/bin/sh
# check_core_includes.sh - the core's include graph (docs/design.md 1):
#   - core/ includes only core headers, the port's bs_port.h, the generated
#     bs_build_config.h, the compiled scene (#include BS_SCENE_CONFIG) and the
#     freestanding <stdint.h>, <stddef.h>: nothing from host/, nothing else
#     from port/, no libc;
#   - the internal headers of core/src never include the umbrella beamslider.h;
#   - there is no include cycle.
# Run from the repository root. Exit status 1 on a violation.
set -u
cd "$(dirname "$0")/.." || exit 2
failures=0
bad() { echo "check_core_includes: FAIL: $*"; failures=$((failures + 1)); }

edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
for file in core/include/*.h core/src/*.h core/src/*.c; do
    name=${file##*/}
    sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*\(.*\)$/\1/p' "$file" | while read -r target; do
        case $target in
            '<stdint.h>' | '<stddef.h>') ;;
            '<'*) echo "BAD $file includes $target (only <stdint.h> and <stddef.h>)" ;;
            BS_SCENE_CONFIG) ;;
            '"bs_port.h"' | '"bs_build_config.h"') ;;
            '"'*'"')
                header=${target#\"}
                header=${header%\"}
                case $header in */*) echo "BAD $file includes \"$header\": a path, not a core header"; continue ;; esac
                if [ -f "core/include/$header" ] || [ -f "core/src/$header" ]; then
                    echo "EDGE $name $header"
                else
                    echo "BAD $file includes \"$header\", which is not a core header"
                fi
                case $file:$header in core/src/*.h:beamslider.h) echo "BAD $file includes the umbrella beamslider.h" ;; esac
                ;;
            *) echo "BAD $file includes $target" ;;
        esac
    done
done > "$edges"

while read -r kind rest; do
    [ "$kind" = BAD ] && bad "$rest"
done < "$edges"

# cycles: repeatedly drop files that include nothing left; what remains is on
# or upstream of a cycle
awk '$1 == "EDGE" { print $2, $3 }' "$edges" | sort -u > "$edges.graph"
cycle=$(awk '
    { from[NR] = $1; to[NR] = $2; n = NR; node[$1] = 1; node[$2] = 1 }
    END {
        do {
            removed = 0
            for (v in node) {
                out = 0
                for (i = 1; i <= n; ++i) if (alive[i] != "dead" && from[i] == v) ++out
                if (out == 0) {
                    delete node[v]; ++removed
                    for (i = 1; i <= n; ++i) if (to[i] == v) alive[i] = "dead"
                }
            }
        } while (removed > 0)
        for (v in node) printf "%s ", v
    }' "$edges.graph")
rm -f "$edges.graph"
[ -z "$cycle" ] || bad "include cycle (on it or including it): $cycle"

if [ "$failures" -gt 0 ]; then
    echo "check_core_includes: $failures violation(s)"
    exit 1
fi
echo "check_core_includes: ok: $(awk '$1 == "EDGE"' "$edges" | wc -l) includes, only core headers, bs_port.h and <stdint.h>/<stddef.h>, no cycle"
