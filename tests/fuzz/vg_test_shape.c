/* vg_test_shape.c - tests/test_shape.c for valgrind (tests/fuzz/vg_subset.h).
 * The case left out (60 s of the program's 61 s under valgrind) checks
 * twenty modes against their closed form through the code that the
 * five-mode case runs with five (gcov: no line of core/ or host/lib that the
 * kept cases do not reach). */
static const char *const vg_too_long[] = {
    "test_twenty_modes_match_closed_form",
};
#include "vg_subset.h"
#include "../test_shape.c"
