/* support.c - shared helpers of the CMocka tests. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "support.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

static uint64_t gaussian_state = 1;

void support_long_only(void)
{
    const char *flag = getenv("BS_TEST_LONG");
    if (!flag || !*flag)
        skip();
}

void support_gaussian_seed(uint64_t seed)
{
    gaussian_state = seed;
}

double support_gaussian(void)
{
    double u[2];
    int i;
    for (i = 0; i < 2; ++i) {
        gaussian_state ^= gaussian_state >> 12;
        gaussian_state ^= gaussian_state << 25;
        gaussian_state ^= gaussian_state >> 27;
        u[i] = ((double)((gaussian_state * UINT64_C(2685821657736338717)) >> 11) + 0.5) / 9007199254740992.0;
    }
    return sqrt(-2.0 * log(u[0])) * cos(6.283185307179586 * u[1]);
}

int support_tmp_dir(char *dir, size_t size, const char *name)
{
    const int n = snprintf(dir, size, "/tmp/%s.XXXXXX", name);
    return n > 0 && (size_t)n < size && mkdtemp(dir) ? 0 : -1;
}

int support_tmp_dir_remove(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    char path[1024];
    int status = 0;

    if (!d)
        return -1;
    while ((entry = readdir(d)) != NULL) {
        if (!strcmp(entry->d_name, ".") || !strcmp(entry->d_name, ".."))
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, entry->d_name);
        if (unlink(path) != 0)
            status = -1;
    }
    closedir(d);
    return rmdir(dir) == 0 ? status : -1;
}
