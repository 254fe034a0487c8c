/* vg_short_maps.h - for a valgrind copy of a test program that designs
 * response maps (tests/fuzz/vg_subset.h). Include it before the test
 * program's source.
 *
 * Its designs record each map point over 40 excitation periods instead of
 * OBSERVER_DEFAULT_MAP_RECORD (200). The record's length sets how often
 * map_point's loop turns, not which code runs, and at 200 periods the designs
 * made vg_test_observer and vg_test_friction 2.7 and 3 times as long under
 * valgrind (432 s and 375 s against 145 s and 139 s).
 *
 * And its designs can be read back instead of made again: with
 * VG_GAINS_SAVE=PREFIX (not empty) the program writes the gains of its n-th
 * design to PREFIX.n, with VG_GAINS_LOAD=PREFIX it reads them from there
 * (failing the design if the file is missing or short). robustness-valgrind runs each
 * such program natively with the first, then under valgrind with the second:
 * the same binary on the same inputs, so the same gains bit for bit, without
 * the millions of steps of the maps' sweeps under memcheck (about half of
 * either program's time there). observer_design's own code runs under
 * valgrind in test_host_api, whose designs make maps at 10 kHz. */
#ifndef VG_SHORT_MAPS_H
#define VG_SHORT_MAPS_H

#include <stdio.h>
#include <stdlib.h>
#include "observer_design.h"

static observer_design_options vg_design_defaults(double noise)
{
    observer_design_options o = observer_design_defaults(noise);
    o.map_record = 40;
    return o;
}
#define observer_design_defaults vg_design_defaults

/* The gains of design number `count` through PREFIX.count: 0, or -1 with
 * the reason in err. */
static int vg_gains_file(const char *prefix, int count, int save, bs_observer_gains *gains, char *err,
                         size_t err_size)
{
    char path[1024];
    FILE *f;
    int ok;
    snprintf(path, sizeof path, "%s.%d", prefix, count);
    if (!(f = fopen(path, save ? "wb" : "rb"))) {
        snprintf(err, err_size, "vg_short_maps: cannot open %.180s", path);
        return -1;
    }
    ok = save ? fwrite(gains, sizeof *gains, 1, f) == 1 : fread(gains, sizeof *gains, 1, f) == 1;
    if (fclose(f) != 0)
        ok = 0;
    if (!ok)
        snprintf(err, err_size, "vg_short_maps: cannot %s %.180s", save ? "write" : "read", path);
    return ok ? 0 : -1;
}

static int vg_observer_design(const scene_file *file, const scene_model *model, const bs_scene *scene,
                              const observer_design_options *options, bs_observer_gains *gains, char *err,
                              size_t err_size)
{
    static int designs;
    const char *load = getenv("VG_GAINS_LOAD"), *save = getenv("VG_GAINS_SAVE");
    const int count = ++designs;
    if (load && *load)
        return vg_gains_file(load, count, 0, gains, err, err_size);
    if (observer_design(file, model, scene, options, gains, err, err_size) != 0)
        return -1;
    return save && *save ? vg_gains_file(save, count, 1, gains, err, err_size) : 0;
}
#define observer_design vg_observer_design

#endif
