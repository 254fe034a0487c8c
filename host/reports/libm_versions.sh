# libm_versions.sh - sourced: libm_versions prints which versions of the C
# library's sin, cos, exp, sinh and cosh run here. glibc on x86-64 takes
# versions compiled with fused multiply-add where the CPU has FMA and AVX2
# (unless GLIBC_TUNABLES masks them), whose results differ from the others'
# in the last bit (docs/design.md 11): "fma" or "no-fma" there, elsewhere the
# machine's name (uname -m).
libm_versions() {
    [ "$(uname -m)" = x86_64 ] || { uname -m; return; }
    case ${GLIBC_TUNABLES:-} in *-FMA*|*-AVX2*) echo no-fma; return ;; esac
    if grep -qw fma /proc/cpuinfo && grep -qw avx2 /proc/cpuinfo; then echo fma; else echo no-fma; fi
}
