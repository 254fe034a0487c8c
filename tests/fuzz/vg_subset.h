/* vg_subset.h - a test program of tests/ for valgrind, without its longest
 * cases (tests/robustness.mk, robustness-valgrind).
 *
 * Under valgrind's ~50x slowdown a case that runs a few seconds natively
 * takes minutes. A file that includes this header first defines such
 * cases in vg_too_long (each with why it may be left out: it reaches no
 * code the kept cases do not), then includes this header and the test
 * program's source, compiled as it is: its group runs without them. Every
 * case still runs natively in `make test` (a case of support_long_only in
 * `make test-long`) and under ASan/UBSan in `make test-long`.
 */
#ifndef VG_SUBSET_H
#define VG_SUBSET_H

#include <stdio.h>
#include <string.h>
#include "support.h"

#define vg_too_long_count (sizeof vg_too_long / sizeof vg_too_long[0])

static int vg_run_group(const char *name, const struct CMUnitTest *tests, size_t count,
                        CMFixtureFunction setup, CMFixtureFunction teardown)
{
    static struct CMUnitTest kept[64];
    size_t used = 0, skipped = 0, i, j;

    if (count > sizeof kept / sizeof kept[0]) {
        printf("vg_subset: %zu tests, room for %zu\n", count, sizeof kept / sizeof kept[0]);
        return 1;
    }
    for (i = 0; i < count; ++i) {
        for (j = 0; j < vg_too_long_count && strcmp(tests[i].name, vg_too_long[j]); ++j)
            ;
        if (j < vg_too_long_count) {
            printf("[ SKIPPED  ] %s (too long under valgrind)\n", tests[i].name);
            ++skipped;
        } else {
            kept[used++] = tests[i];
        }
    }
    if (skipped != vg_too_long_count) { /* a case renamed: the list is stale */
        printf("vg_subset: %zu of %zu long tests found by name\n", skipped, vg_too_long_count);
        return 1;
    }
    return _cmocka_run_group_tests(name, kept, used, setup, teardown);
}

#undef cmocka_run_group_tests
#define cmocka_run_group_tests(group, setup, teardown) \
    vg_run_group(#group, group, sizeof(group) / sizeof((group)[0]), setup, teardown)

#endif
