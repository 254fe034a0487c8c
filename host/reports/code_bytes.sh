#!/bin/sh
# code_bytes.sh ELF REGEX - bytes of an image's code generated from the source files whose
# path matches REGEX (an awk regular expression, e.g. '/core/').
#
# Each instruction of .text counts in the file of its innermost source line
# (arm-none-eabi-objdump -d -l), so that code inlined from a file counts in that file: an
# image linked with -flto has no object file per source (its link map names only the
# link-time partitions), and inlining moves code across files even without it. Literal
# pools count in the file of the instruction before them. Used by embedded_report.sh and
# twin_firmware_report.sh.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 ELF REGEX" >&2; exit 2; }
[ -f "$1" ] || { echo "code_bytes.sh: no such image: $1" >&2; exit 2; }
"${CM_OBJDUMP:-arm-none-eabi-objdump}" -d -l --no-show-raw-insn -j .text "$1" | awk -v pattern="$2" '
    function hex(text,    i, value) { # mawk has no strtonum
        value = 0
        for (i = 1; i <= length(text); ++i)
            value = value * 16 + index("0123456789abcdef", tolower(substr(text, i, 1))) - 1
        return value
    }
    /^\/.*:[0-9]+/ { file = $1; sub(/:[0-9]+$/, "", file); next }  # the source line of what follows
    /^[0-9a-f]+ <.*>:$/ { file = ""; next }                        # a symbol: no line until one is given
    /^ +[0-9a-f]+:\t/ {
        address = $1; sub(":", "", address); address = hex(address)
        if (counting) bytes += address - last
        last = address; counting = file ~ pattern
    }
    END { print bytes + 0 }'
