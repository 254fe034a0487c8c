/* support.c - shared helpers of the CMocka tests. */
#include "support.h"

#include <math.h>
#include <stdio.h>

void support_load(const char *path, scene_file *file, bs_scene *scene, scene_model *model)
{
    char err[1024];
    if (scene_read(path, file, scene, model, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
}

void support_build(scene_file *file, bs_scene *scene, scene_model *model)
{
    char err[1024];
    if (scene_build(file, scene, model, err, sizeof err) != 0) {
        print_error("%s\n", err);
        fail();
    }
}

void support_assert_close(const char *what, double actual, double expected, double abs_tol,
                          double rel_tol, const char *file, int line)
{
    const double tolerance = abs_tol + rel_tol * fabs(expected);
    if (!(fabs(actual - expected) <= tolerance)) {
        print_error("%s: got %.12g, expected %.12g (difference %.3g, tolerance %.3g)\n", what, actual,
                    expected, actual - expected, tolerance);
        _fail(file, line);
    }
}

bs_step_report support_report(const bs_sim *sim)
{
    bs_step_report report;
    assert_int_equal(bs_sim_get_report(sim, &report), BS_OK);
    return report;
}
