#!/bin/sh
# classes.sh PROFILE ELF - where a profile's instructions and cycles go, per function and
# per kind of instruction.
#
# PROFILE as profile.sh takes it (count.sh with CM_PROFILE=..., and CM_CYCLES=1 for the
# cycle columns); ELF the image it profiled. Prints one line per function,
#     FUNCTION INSN FP LOAD STORE CONTROL OTHER  CYC CYC_FP CYC_LOAD CYC_STORE CYC_CONTROL CYC_OTHER
# totals over the profiled brackets (divide by their number for per-step figures), where
#     FP       floating-point arithmetic: vadd vsub vmul vnmul vmla vmls vfma vneg vabs vdiv
#              vsqrt vcvt (the arithmetic the step's equations ask for)
#     LOAD     ldr ldm vldr vldm pop (data brought into registers, the return address too)
#     STORE    str stm vstr vstm push vpush
#     CONTROL  branches, compares, it blocks, vmrs (a float compare's flags), cbz/cbnz
#     OTHER    integer arithmetic, moves between registers (vmov, mov), address arithmetic
# and CYC* the estimated cycles of each (profile.sh's formula, CM_REFILL and CM_WAIT as
# there; 0 without cycle columns). Inlined code counts in its caller, or in the function of
# CM_INLINE_NAMES it came from, as in profile.sh.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 PROFILE ELF" >&2; exit 2; }
[ -f "$1" ] || { echo "classes.sh: no such profile: $1" >&2; exit 2; }
[ -f "$2" ] || { echo "classes.sh: no such image: $2" >&2; exit 2; }
listing=$(mktemp)
inlined=$(mktemp)
trap 'rm -f "$listing" "$inlined"' EXIT
sh "$(dirname "$0")/inline_names.sh" "$1" "$2" > "$inlined"
# "ADDRESS FUNCTION MNEMONIC" for every instruction of the image, the address as the
# profile writes it (8 hex digits)
"${CM_OBJDUMP:-arm-none-eabi-objdump}" -d --no-show-raw-insn "$2" | awk '
    /^[0-9a-f]+ <.*>:$/ { name = $2; gsub(/[<>:]/, "", name); next }
    /^ +[0-9a-f]+:\t/ { address = $1; sub(":", "", address); while (length(address) < 8) address = "0" address
                        print address, name, $2 }' > "$listing"
awk '
    FNR == 1 { ++file } # first the map of inline_names.sh, then the names, then the profile
    file == 1 { inlined_in[$1] = $2; next }
    file == 2 { name[$1] = $2; mnemonic[$1] = $3; next }
    FNR == 1 { next }
    {
        f = ($1 in inlined_in) ? inlined_in[$1] : ($1 in name) ? name[$1] : "(unknown)"; op = ($1 in mnemonic) ? mnemonic[$1] : ""
        kind = "other"
        if (op ~ /^v(add|sub|mul|nmul|mla|mls|nmla|nmls|fma|fms|neg|abs|div|sqrt|cvt)/) kind = "fp"
        else if (op ~ /^(v?ldr|v?ldm|pop|vpop)/) kind = "load"
        else if (op ~ /^(v?str|v?stm|push|vpush)/) kind = "store"
        else if (op ~ /^(b|bl|blx|bx|cbz|cbnz|it|cmp|cmn|tst|teq|vcmp|vmrs|tbb|tbh)($|[.a-z])/) kind = "control"
        cycles = NF == 6 ? $2 * $4 + refill * $5 + wait * $6 : 0
        functions[f] = 1; insn[f, kind] += $2; cyc[f, kind] += cycles
    }
    END {
        split("fp load store control other", kinds, " ")
        for (f in functions) {
            line = f; total = 0; total_cycles = 0
            for (k = 1; k <= 5; ++k) { total += insn[f, kinds[k]]; total_cycles += cyc[f, kinds[k]] }
            line = line " " total
            for (k = 1; k <= 5; ++k) line = line " " insn[f, kinds[k]] + 0
            line = line " " total_cycles
            for (k = 1; k <= 5; ++k) line = line " " cyc[f, kinds[k]] + 0
            print line
        }
    }' refill="${CM_REFILL:-3}" wait="${CM_WAIT:-5}" "$inlined" "$listing" "$1" | sort -k8,8nr -k2,2nr
