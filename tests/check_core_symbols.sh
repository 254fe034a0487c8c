#!/bin/sh
# check_core_symbols.sh REAL OBJECT... - the core must reference no symbol
# outside itself but the math the port provides (no malloc, free, printf,
# abort, memset, ... in core/). The compiler's own run-time helpers of ARM
# targets without an FPU (__aeabi_fadd, ...) are part of the compiler, not of
# a C library, and are allowed. NM selects the nm (arm-none-eabi-nm for ARM).
real=$1
shift
if [ "$real" = float ]; then
    allowed="sqrtf sinf cosf sincosf"
else
    allowed="sqrt sin cos sincos"
fi
undefined=$(${NM:-nm} -u "$@" | awk 'NF == 2 && $1 == "U" { print $2 }' | sort -u)
defined=$(${NM:-nm} --defined-only "$@" | awk 'NF == 3 { print $3 }' | sort -u)
bad=""
external=""
for symbol in $undefined; do
    echo "$defined" | grep -qx "$symbol" && continue
    external="$external $symbol"
    case " $allowed " in *" $symbol "*) continue ;; esac
    case $symbol in __aeabi_*) continue ;; esac
    bad="$bad $symbol"
done
if [ -n "$bad" ]; then
    echo "check_core_symbols ($real): FAIL: core objects reference:$bad (allowed: $allowed)"
    exit 1
fi
echo "check_core_symbols ($real): ok: external references:$external"
