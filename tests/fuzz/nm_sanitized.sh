#!/bin/sh
# nm_sanitized.sh NM-ARGS... - nm without the symbols that sanitizer
# instrumentation adds to an object (__asan_*, __ubsan_*, __sanitizer_*,
# __lsan_*), and the linker's _GLOBAL_OFFSET_TABLE_, through which the
# instrumentation of position-independent objects reaches its globals.
# tests/robustness.mk passes it as NM to
# tests/check_core_symbols.sh for the ASan/UBSan build, so that the check
# still catches any other library call in core/.
nm "$@" | grep -v -E ' (__asan_|__ubsan_|__sanitizer_|__lsan_|_GLOBAL_OFFSET_TABLE_$)'
exit 0
