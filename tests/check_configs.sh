#!/bin/sh
# check_configs.sh BEAMSLIDER - the generated files that are checked in must be
# current: every compile-time scene header configs/NAME.h exactly what
# `beamslider gen configs/NAME.ini` prints now (else: run `make configs`), and
# docs/fields.md what `beamslider fields` prints (else: run `make fields`).
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
if ! "$bin" fields | cmp -s - docs/fields.md; then
    echo "check_configs: FAIL: docs/fields.md is stale (run: make fields)"
    stale=1
fi
# configs/*.h are generated where glibc runs the versions of sinh, cosh and exp
# compiled with fused multiply-add (x86-64 with FMA and AVX2): on a CPU without
# them the shape fit's last bits differ (docs/design.md 11)
if [ "$stale" -ne 0 ] && [ "$(uname -m)" = x86_64 ]; then
    case ${GLIBC_TUNABLES:-} in *-FMA*|*-AVX2*) fma=masked ;; *) fma=$(grep -qw fma /proc/cpuinfo && grep -qw avx2 /proc/cpuinfo && echo yes) ;; esac
    [ "$fma" = yes ] || echo "check_configs: this CPU runs glibc's versions of libm without fused multiply-add (no FMA or AVX2, or GLIBC_TUNABLES masks them); configs/*.h were generated with the fused versions, and the shape fit's last bits differ (docs/design.md 11)"
fi
[ "$stale" -eq 0 ] && echo "check_configs: ok: $count headers match their scene files, docs/fields.md is current"
exit $stale
