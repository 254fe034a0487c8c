/* vg_test_friction.c - tests/test_friction.c for valgrind
 * (tests/fuzz/vg_subset.h). The cases left out: one (about 30 s of the
 * program's 113 s under valgrind) runs the twin and its plant through the
 * same run() as the case that follows a plant with more friction, on the
 * scene's own friction. Of the lines of core/ and host/lib it reaches
 * (gcov), one is not reached by the kept cases: the position correction of
 * an s error above its deadband, which vg_test_observer's tracking case
 * runs. The other runs that pair twice more (a plant under a frequency
 * ramp, and steady); what only it reaches is the frequency gate's return
 * in core/src/bs_observer.c (arithmetic on the observer's own fields). */
static const char *const vg_too_long[] = {
    "test_friction_does_not_chase_noise_on_the_high_branch",
    "test_friction_holds_while_the_frequency_moves",
};
#include "vg_subset.h"
#include "vg_short_maps.h"
#include "../test_friction.c"
