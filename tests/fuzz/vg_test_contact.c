/* vg_test_contact.c - tests/test_contact.c for valgrind
 * (tests/fuzz/vg_subset.h). The case left out, nearly all the program's
 * time, compares the detection from expansions with the direct shapes at
 * 200 000 random poses: the detection and shape code every contact of the
 * other cases runs. */
static const char *const vg_too_long[] = {
    "test_detection_from_expansions_matches_direct_shapes",
};
#include "vg_subset.h"
#include "../test_contact.c"
