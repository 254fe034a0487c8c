/* vg_short_maps.h - for a valgrind copy of a test program that designs
 * response maps (tests/fuzz/vg_subset.h): its designs record each map point
 * over 40 excitation periods instead of OBSERVER_DEFAULT_MAP_RECORD (200).
 * The record's length sets how often map_point's loop turns, not which code
 * runs, and at 200 periods the designs made vg_test_observer and
 * vg_test_friction 2.7 and 3 times as long under valgrind (432 s and 375 s
 * against 145 s and 139 s). Include it before the test program's source. */
#ifndef VG_SHORT_MAPS_H
#define VG_SHORT_MAPS_H

#include "observer_design.h"

static observer_design_options vg_design_defaults(double noise)
{
    observer_design_options o = observer_design_defaults(noise);
    o.map_record = 40;
    return o;
}
#define observer_design_defaults vg_design_defaults

#endif
