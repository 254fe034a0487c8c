#!/bin/sh
# profile.sh PROFILE ELF - per-function instruction counts from a count.sh profile.
#
# PROFILE is the file the counting plugin writes with CM_PROFILE=profile=PROFILE[,first=K,last=L]
# (insn-plugin/insncount.c); ELF the image it profiled. Prints
#     brackets N worst B W          as the profile's first line (N brackets, the costliest B: W)
#     FUNCTION TOTAL WORST          one line per function, costliest in bracket B first
# TOTAL = instructions in the function's own code over the N brackets, WORST = in bracket B.
# A profile taken with CM_CYCLES=1 adds a fourth column, CYCLES: the function's estimated
# Cortex-M4 cycles over the N brackets, base + P x branches taken + W x reads of the code
# region (P = CM_REFILL, default 3; W = CM_WAIT, default 5: the pessimistic estimate).
# Inlined code counts in the function it was inlined into, or in the outermost function of
# CM_INLINE_NAMES it came from (inline_names.sh); addresses in no sized symbol (veneers,
# padding) count as "(unknown)", outside the code region as "(outside)".
set -eu
[ $# -eq 2 ] || { echo "usage: $0 PROFILE ELF" >&2; exit 2; }
[ -f "$1" ] || { echo "profile.sh: no such profile: $1" >&2; exit 2; }
[ -f "$2" ] || { echo "profile.sh: no such image: $2" >&2; exit 2; }
symbols=$(mktemp)
inlined=$(mktemp)
trap 'rm -f "$symbols" "$inlined"' EXIT
sh "$(dirname "$0")/inline_names.sh" "$1" "$2" > "$inlined"
# function symbols with a size: "ADDRESS SIZE NAME", by address
"${CM_NM:-arm-none-eabi-nm}" -n -S "$2" | awk 'NF == 4 && $3 ~ /^[tTwW]$/ { print $1, $2, $4 }' > "$symbols"
head -n 1 "$1"
awk '
    function hex(text,    i, value) { # mawk has no strtonum
        value = 0
        for (i = 1; i <= length(text); ++i)
            value = value * 16 + index("0123456789abcdef", tolower(substr(text, i, 1))) - 1
        return value
    }
    FNR == 1 { ++file } # first the map of inline_names.sh, then the names, then the profile
    file == 1 { inlined_in[$1] = $2; next }
    file == 2 { ++n; start[n] = hex($1); stop[n] = start[n] + hex($2); name[n] = $3; next }
    FNR == 1 { next }
    {
        address = hex($1); function_name = "(unknown)"
        if ($1 == "ffffffff") function_name = "(outside)"
        else if ($1 in inlined_in) function_name = inlined_in[$1]
        else {
            low = 1; high = n # last symbol starting at or below address
            while (low < high) { mid = int((low + high + 1) / 2); if (start[mid] <= address) low = mid; else high = mid - 1 }
            if (n && start[low] <= address && address < stop[low]) function_name = name[low]
        }
        total[function_name] += $2; worst[function_name] += $3
        if (NF == 6) { cycles[function_name] += $2 * $4 + refill * $5 + wait * $6; with_cycles = 1 }
    }
    END {
        for (f in total)
            if (with_cycles) printf "%s %.0f %.0f %.0f\n", f, total[f], worst[f], cycles[f]
            else printf "%s %.0f %.0f\n", f, total[f], worst[f]
    }' refill="${CM_REFILL:-3}" wait="${CM_WAIT:-5}" "$inlined" "$symbols" "$1" | sort -k3,3nr -k2,2nr
