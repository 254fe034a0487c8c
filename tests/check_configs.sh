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
# compiled with fused multiply-add: elsewhere the shape fit's last bits differ
if [ "$stale" -ne 0 ]; then
    . host/reports/libm_versions.sh
    here=$(libm_versions)
    [ "$here" = fma ] || echo "check_configs: configs/*.h were generated where glibc runs its versions of libm compiled with fused multiply-add (x86-64 with FMA and AVX2); this machine runs others ($here: no FMA or AVX2, GLIBC_TUNABLES masks them, or another architecture), whose last bits differ in the shape fit (docs/design.md 11)"
fi
[ "$stale" -eq 0 ] && echo "check_configs: ok: $count headers match their scene files, docs/fields.md is current"
exit $stale
