#!/bin/sh
# inline_names.sh PROFILE ELF - the function each profiled address counts in, when it was
# inlined from one of the functions named in CM_INLINE_NAMES.
#
# profile.sh and classes.sh count inlined code in the function it was inlined into. An
# image linked with -flto inlines whole stages of the step (the contact problem, the solve)
# into one symbol, and a per-stage account then needs the source's functions back. With
# CM_INLINE_NAMES="f g ..." (space-separated), every address of PROFILE whose inline chain
# (arm-none-eabi-addr2line -f -i) passes through one of them is printed as
#     ADDRESS NAME      (ADDRESS as the profile writes it, 8 hex digits)
# with NAME the outermost listed function of its chain; other addresses are not printed and
# keep their symbol's name; a first line "address name" heads the list (so that an empty
# list is still a file of one line to the scripts that read it). Without CM_INLINE_NAMES
# only that line.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 PROFILE ELF" >&2; exit 2; }
echo "address name"
[ -n "${CM_INLINE_NAMES:-}" ] || exit 0
awk 'NR > 1 && $1 != "ffffffff" { print "0x" $1 }' "$1" \
    | "${CM_ADDR2LINE:-arm-none-eabi-addr2line}" -a -f -i -e "$2" \
    | awk -v listed="$CM_INLINE_NAMES" '
        BEGIN { n = split(listed, names, " "); for (i = 1; i <= n; ++i) wanted[names[i]] = 1 }
        function flush() { if (address != "" && name != "") print address, name }
        /^0x[0-9a-f]+$/ { flush(); address = substr($0, 3); while (length(address) < 8) address = "0" address
                          name = ""; line = 0; next }
        { ++line; if (line % 2 == 1 && ($1 in wanted)) name = $1 } # callers come after: the outermost wins
        END { flush() }'
