#!/bin/sh
# check_configs.sh BEAMSLIDER - every checked-in compile-time scene header
# configs/NAME.h must be exactly what `beamslider gen configs/NAME.ini` prints
# now (else: run `make configs`).
bin=$1
stale=0
count=0
for header in configs/*.h; do
    scene=${header%.h}.ini
    count=$((count + 1))
    if ! "$bin" gen "$scene" | cmp -s - "$header"; then
        echo "check_configs: FAIL: $header is stale or has no $scene (run: make configs)"
        stale=1
    fi
done
[ "$count" -gt 0 ] || { echo "check_configs: FAIL: no configs/*.h"; exit 1; }
[ "$stale" -eq 0 ] && echo "check_configs: ok: $count headers match their scene files"
exit $stale
