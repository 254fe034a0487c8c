#!/bin/sh
# count.sh ELF TARGET [TIMEOUT_S] - run an image like run.sh, counting executed instructions.
#
# Output (all on stdout, in execution order): the guest's stdout and stderr, interleaved with
#     [insn] N         at each call of bs_board_mark(): N = instructions executed since the
#                      previous mark (since reset for the first one), the mark call excluded
#     [insn] total N   at the end: instructions of the whole run
# With CM_CYCLES=1 both kinds of line go on "cycles C taken T flash F": the Cortex-M4 cycle
# estimate of the same instructions, its branches taken and its data reads from the code
# region (insn-plugin/insncount.c, "Cycle model").
# plus run.sh's messages. A bracket  mark(); code; mark(); printf("label\n");  therefore shows
# as "[insn] N" directly followed by "label": N is the code's cost plus the harness overhead
# (2 for an empty bracket; see README.md). Counts are exact and deterministic.
#
# Exit status: as run.sh (the guest's status, 99 fault, 124 timeout, 2 usage), or 125 if the
# plugin cannot be built (build-plugin.sh prints why). Without bs_board_mark in the image only
# the total is printed. Env: CM_BUILD (where libinsncount.so is; default <repo>/build/cm),
# CM_NM (default arm-none-eabi-nm), CM_PROFILE (more plugin arguments, e.g.
# profile=FILE,first=K,last=L for a per-address profile of brackets K..L: see
# insn-plugin/insncount.c and profile.sh), and those of run.sh.
set -u
here=$(cd "$(dirname "$0")" && pwd)
if [ $# -lt 2 ] || [ $# -gt 3 ]; then echo "usage: $0 ELF TARGET [TIMEOUT_S]" >&2; exit 2; fi
elf=$1
[ -f "$elf" ] || { echo "count.sh: no such image: $elf" >&2; exit 2; }
CM_BUILD=${CM_BUILD:-$(cd "$here/../.." && pwd)/build/cm}
export CM_BUILD
sh "$here/build-plugin.sh" >&2 || exit 125   # its messages stay out of the counted stream
CM_BUILD=$(cd "$CM_BUILD" && pwd)

plugin=$CM_BUILD/libinsncount.so
mark=$("${CM_NM:-arm-none-eabi-nm}" "$elf" | awk '$3 == "bs_board_mark" { print $1; exit }')
if [ -n "$mark" ]; then
    plugin=$plugin,mark=0x$mark${CM_PROFILE:+,$CM_PROFILE}${CM_CYCLES:+,cycles=$CM_CYCLES}
else
    [ -z "${CM_PROFILE:-}" ] || { echo "count.sh: CM_PROFILE needs bs_board_mark in $elf" >&2; exit 2; }
    plugin=$plugin${CM_CYCLES:+,cycles=$CM_CYCLES}
    echo "count.sh: no bs_board_mark in $elf: only the total is counted" >&2
fi
# The plugin prints on stderr; merging keeps its lines in order with the guest's output (both
# are written unbuffered from QEMU's vCPU thread as the guest runs).
CM_QEMU_ARGS="-plugin $plugin" sh "$here/../../port/cortex-m/run.sh" "$elf" "$2" "${3:-60}" 2>&1
