#!/bin/sh
# run.sh ELF TARGET [TIMEOUT_S] - run a bare-metal image under qemu-system-arm.
#
# The guest's stdout/stderr (semihosting) are QEMU's stdout/stderr; the exit status is the
# guest's: main's return value (mod 256), 99 after a CPU fault (startup.c), 124 if the run did
# not end within TIMEOUT_S seconds (default 60; a message is printed on stderr), 2 for bad
# usage. Env: CM_QEMU (default qemu-system-arm), CM_QEMU_ARGS (extra QEMU options, e.g. a
# -plugin; used by count.sh), CM_MACHINE (another QEMU -M than the target's, e.g. microbit).
set -u
usage() { echo "usage: $0 ELF TARGET [TIMEOUT_S]   (TARGET: cortex-m4f cortex-m7 cortex-m3 cortex-m0plus)" >&2; exit 2; }
if [ $# -lt 2 ] || [ $# -gt 3 ]; then usage; fi
elf=$1
target=$2
limit=${3:-60}
qemu=${CM_QEMU:-qemu-system-arm}

# Same table as CM_MACHINE_<target> in cortex-m.mk.
case $target in
    cortex-m4f) machine=mps2-an386 ;;
    cortex-m7) machine=mps2-an500 ;;
    cortex-m3 | cortex-m0plus) machine=mps2-an385 ;;   # QEMU 7.2 has no M0+; v6-M runs on the M3
    *) echo "run.sh: unknown target '$target'" >&2; usage ;;
esac
machine=${CM_MACHINE:-$machine}
[ -f "$elf" ] || { echo "run.sh: no such image: $elf" >&2; exit 2; }
case $limit in '' | *[!0-9]*) echo "run.sh: TIMEOUT_S must be whole seconds, not '$limit'" >&2; exit 2 ;; esac

# -serial/-monitor none: the only I/O is semihosting; -no-reboot: a reset request ends the run.
# -k: if QEMU ignores SIGTERM, SIGKILL 5 s later.
# shellcheck disable=SC2086 # CM_QEMU_ARGS is a list of options
timeout -k 5 "$limit" "$qemu" -M "$machine" -display none -monitor none -serial none -no-reboot \
    -semihosting-config enable=on,target=native ${CM_QEMU_ARGS:-} -kernel "$elf"
status=$?
if [ "$status" -eq 124 ]; then
    echo "run.sh: *** timeout: $elf ($target) still running after $limit s (hang?), stopped" >&2
fi
exit "$status"
