/* vg_test_sim.c - tests/test_sim.c for valgrind (tests/fuzz/vg_subset.h).
 * Under valgrind the whole program takes about 150 s, most of it the
 * 30e6-step phase test. The two left out step a rigid beam in free flight,
 * step after step: code every other case runs. */
static const char *const vg_too_long[] = {
    "test_excitation_phase_is_exact_after_long_runs", /* 3e7 steps */
    "test_slow_drift_is_not_lost_to_rounding",        /* 1e6 steps */
};
#include "vg_subset.h"
#include "../test_sim.c"
