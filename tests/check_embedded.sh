#!/bin/sh
# check_embedded.sh TARGET:ELF:HOST_BINARY... - runs each firmware image under
# QEMU (port/cortex-m/run.sh) and its host twin, and requires the same output
# line for line: the same states, bit for bit, on target and host. A CPU fault
# (status 99), a hang (124) or any other failure of either side fails. Env:
# CHECK_EMBEDDED_TIMEOUT, seconds per QEMU run (default 120).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
passed=0
for pair in "$@"; do
    target=${pair%%:*}
    rest=${pair#*:}
    elf=${rest%%:*}
    host=${rest#*:}
    name=$(basename "$elf" .elf)
    sh port/cortex-m/run.sh "$elf" "$target" "${CHECK_EMBEDDED_TIMEOUT:-120}" > "$tmp/target.out" 2> "$tmp/target.err"
    status=$?
    if [ "$status" -ne 0 ]; then
        echo "FAIL $target $name: exit status $status under QEMU: $(tail -n 2 "$tmp/target.err" | tr '\n' ' ')"
        failed=$((failed + 1))
        continue
    fi
    if ! "$host" > "$tmp/host.out"; then
        echo "FAIL $target $name: the host twin $host failed"
        failed=$((failed + 1))
        continue
    fi
    if ! cmp -s "$tmp/target.out" "$tmp/host.out"; then
        echo "FAIL $target $name: target and host differ:"
        diff "$tmp/target.out" "$tmp/host.out" | head -n 6
        failed=$((failed + 1))
        continue
    fi
    echo "ok   $target $name: $(wc -l < "$tmp/target.out") lines identical to the host, $(tail -n 1 "$tmp/target.out")"
    passed=$((passed + 1))
done
echo "check_embedded: $passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
