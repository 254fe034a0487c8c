/* vg_test_observer.c - tests/test_observer.c for valgrind
 * (tests/fuzz/vg_subset.h). The cases left out: one, 60 % of the program's
 * time, designs gains and maps at a second frequency (the design code of
 * test_design_gives_kalman_gains_and_a_map) and runs the twin on two plants
 * for seconds of simulated time (the observer's code of the tracking cases);
 * the other (24 s under valgrind) steps the observer at forty positions of
 * the gain schedule, the code the tracking cases run as their slider moves. */
static const char *const vg_too_long[] = {
    "test_maps_at_a_moved_excitation",
    "test_beam_correction_follows_the_gain_schedule",
};
#include "vg_subset.h"
#include "vg_short_maps.h"
#include "../test_observer.c"
