/* vg_test_sim.c - tests/test_sim.c for valgrind (tests/robustness.mk).
 *
 * The same source, compiled as it is, run without the tests that take
 * millions of steps: under valgrind's ~50x slowdown the whole program takes
 * about 150 s, most of it the 30e6-step phase test. Those tests exercise no
 * code the other cases do not (a rigid beam in free flight, step after step);
 * they run natively and under ASan/UBSan in `make test`.
 */
#include <stdio.h>
#include <string.h>
#include "support.h"

static int vg_run_group(const char *name, const struct CMUnitTest *tests, size_t count,
                        CMFixtureFunction setup, CMFixtureFunction teardown);

#undef cmocka_run_group_tests
#define cmocka_run_group_tests(group, setup, teardown) \
    vg_run_group(#group, group, sizeof(group) / sizeof((group)[0]), setup, teardown)

#include "../test_sim.c"

static const char *const too_long[] = {
    "test_excitation_phase_is_exact_after_long_runs", /* 3e7 steps */
    "test_slow_drift_is_not_lost_to_rounding",        /* 1e6 steps */
};
#define TOO_LONG (sizeof too_long / sizeof too_long[0])

static int vg_run_group(const char *name, const struct CMUnitTest *tests, size_t count,
                        CMFixtureFunction setup, CMFixtureFunction teardown)
{
    static struct CMUnitTest kept[64];
    size_t used = 0, skipped = 0, i, j;

    for (i = 0; i < count && used < sizeof kept / sizeof kept[0]; ++i) {
        for (j = 0; j < TOO_LONG && strcmp(tests[i].name, too_long[j]); ++j)
            ;
        if (j < TOO_LONG) {
            printf("[ SKIPPED  ] %s (too long under valgrind)\n", tests[i].name);
            ++skipped;
        } else {
            kept[used++] = tests[i];
        }
    }
    if (skipped != TOO_LONG) /* renamed? then it runs, slowly: say so */
        printf("vg_test_sim: note: %zu of %zu long tests found by name\n", skipped, (size_t)TOO_LONG);
    return _cmocka_run_group_tests(name, kept, used, setup, teardown);
}
